//! The page's colours on canvas, each at least WCAG 2.2 AA against the white background: 4.5:1
//! for anything drawn as text (labels, ticks), 3:1 for lines and marks only. The page's CSS
//! (`www/style.css`) uses the same values.

/// The canvas background.
pub const BACKGROUND: &str = "#ffffff";
/// Text and outlines.
pub const INK: &str = "#343a40";
/// Secondary text: tick labels, captions on canvas.
pub const MUTED: &str = "#5c636a";
/// Grid lines and the sphere's graticule (decoration, no contrast needed).
pub const GRID: &str = "#dee2e6";
/// KLI's curve, point and labels.
pub const KLI: &str = "#c2410c";
/// SLERP's curve, point and labels.
pub const SLERP: &str = "#7048e8";
/// The body x-axis (nose).
pub const AXIS_X: &str = "#c92a2a";
/// The body y-axis (port wing).
pub const AXIS_Y: &str = "#237032";
/// The body z-axis (fin).
pub const AXIS_Z: &str = "#1971c2";
/// A pose graph's edges by misfit, low to high (the map on the synchronisation page): blue to
/// dark red, each darker than the one before (so the order reads in grey and to every kind of
/// colour blindness), each at least 3:1 on white.
pub const MISFIT: [&str; 5] = ["#3a86b4", "#5a5fbf", "#8e3b8e", "#a61c3c", "#7a0c0c"];

#[cfg(test)]
mod tests {
    use super::*;

    /// WCAG 2.x relative luminance of `#rrggbb`, from its definition (sRGB, linearised).
    fn luminance(hex: &str) -> f64 {
        let channel = |i: usize| {
            let c = u8::from_str_radix(&hex[1 + 2 * i..3 + 2 * i], 16).unwrap() as f64 / 255.0;
            if c <= 0.04045 { c / 12.92 } else { ((c + 0.055) / 1.055).powf(2.4) }
        };
        0.2126 * channel(0) + 0.7152 * channel(1) + 0.0722 * channel(2)
    }

    fn contrast(a: &str, b: &str) -> f64 {
        let (la, lb) = (luminance(a), luminance(b));
        (la.max(lb) + 0.05) / (la.min(lb) + 0.05)
    }

    #[test]
    fn luminance_matches_the_definition_at_known_points() {
        assert_eq!(luminance("#ffffff"), 1.0);
        assert_eq!(luminance("#000000"), 0.0);
        assert!((contrast("#ffffff", "#000000") - 21.0).abs() < 1e-12);
        // WebAIM's checker gives 4.54:1 for #767676 on white, the lightest AA grey.
        assert!((contrast("#767676", "#ffffff") - 4.54).abs() < 0.005);
    }

    #[test]
    fn the_misfit_scale_darkens_step_by_step_and_every_step_meets_3_to_1() {
        for pair in MISFIT.windows(2) {
            assert!(luminance(pair[1]) < luminance(pair[0]), "{pair:?}");
        }
        for colour in MISFIT {
            let ratio = contrast(colour, BACKGROUND);
            assert!(ratio >= 3.0, "{colour}: {ratio:.2}:1");
        }
    }

    #[test]
    fn every_colour_drawn_as_text_meets_aa_on_white() {
        for (name, colour) in [
            ("INK", INK),
            ("MUTED", MUTED),
            ("KLI", KLI),
            ("SLERP", SLERP),
            ("AXIS_X", AXIS_X),
            ("AXIS_Y", AXIS_Y),
            ("AXIS_Z", AXIS_Z),
        ] {
            let ratio = contrast(colour, BACKGROUND);
            assert!(ratio >= 4.5, "{name} {colour}: {ratio:.2}:1");
        }
    }
}
