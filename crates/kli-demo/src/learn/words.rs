//! The words the tour's views draw, in the page's language. The page gives them with its options
//! (`words`, the strings file's `canvas`: www/learn/strings/en.js, bs.js); a run given none (a
//! `<kli-figure>`, the first pictures drawn at build time) draws the English here. A template's
//! `{name}` is a value the view fills in ([`fill`]).

/// Declares [`Words`]: each word's field, its key in the strings' `canvas` (camelCase) and its
/// English.
macro_rules! words {
    ($($field:ident $key:literal $english:literal,)*) => {
        /// The words of the views (see the module).
        #[derive(Clone, Debug, PartialEq, Eq)]
        pub struct Words {
            $(pub $field: String,)*
        }

        impl Default for Words {
            fn default() -> Self {
                Words { $($field: String::from($english),)* }
            }
        }

        impl Words {
            /// The keys, as the strings file names them.
            pub const KEYS: &'static [&'static str] = &[$($key,)*];

            /// The word of `key`, to set; `None` for a key that is none of [`Words::KEYS`].
            pub fn slot(&mut self, key: &str) -> Option<&mut String> {
                match key {
                    $($key => Some(&mut self.$field),)*
                    _ => None,
                }
            }
        }
    };
}

words! {
    yaw "yaw" "yaw",
    pitch "pitch" "pitch",
    bank "bank" "bank",
    locked "locked" "yaw and bank axes coincide: gimbal lock",
    apart "apart" "yaw and bank axes {angle}° apart",
    axis "axis" "axis",
    about "about" "{angle}° about {axis}",
    diagonal "diagonal" "diagonal",
    turned_by "turnedBy" "turned by q",
    turned_by_minus "turnedByMinus" "turned by −q",
    circle "circle" "θ = {angle}°: q is {half}° round the circle",
    slerp "slerp" "s = {s}: SLERP {slerp}° along, NLERP {nlerp}° (of 60°)",
    wing "wing" "wing",
    nose "nose" "h(q): the nose",
    rolled "rolled" "rolled {angle}° about its nose",
    order "order" "R(t), the order parameter",
    pinned "pinned" "h(r), pinned",
    widest "widest" "t = {t}   widest: {angle}° from r",
    along "along" "how far along the arc: s",
    steps "steps" "‖r − qₙ‖ at each step",
    drift "drift" "| |q| − 1 |, the drift off S³",
    largest "largest" "{integrator}: largest drift {drift}",
    geodesic "geodesic" "geodesic",
    rate "rate" "|ω(t)|, the turning rate",
    parts "parts" "ω(t) in its x, y, z parts",
    chain "chain" "KLI chain, smoothness {smoothness}",
    pieces "pieces" "piecewise SLERP",
    jump "jump" "jump {jump}",
}

/// `template` with each `{name}` of `values` replaced by its value.
pub fn fill(template: &str, values: &[(&str, &str)]) -> String {
    values.iter().fold(template.to_owned(), |text, (name, value)| {
        text.replace(&format!("{{{name}}}"), value)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_key_sets_its_word_and_templates_fill() {
        let mut words = Words::default();
        for key in Words::KEYS {
            *words.slot(key).unwrap() = format!("<{key}>");
        }
        assert_eq!(words.turned_by_minus, "<turnedByMinus>");
        assert!(words.slot("nothing").is_none());
        let english = Words::default();
        assert_eq!(fill(&english.about, &[("angle", "90"), ("axis", "z")]), "90° about z");
        assert_eq!(fill(&english.apart, &[("angle", "50.0")]), "yaw and bank axes 50.0° apart");
    }
}
