//! Errors and numbers at the boundary: a [`KliError`] becomes a JavaScript `Error` with the
//! message in JavaScript's names and number formatting, and `argument`, `kind` and `component`
//! properties (the TypeScript interface `KliError`).

use js_sys::{Error, Reflect};
use kli::KliError;
use wasm_bindgen::JsValue;

/// What every fallible call returns; its error is the JavaScript `Error` to throw.
pub type JsResult<T> = Result<T, Thrown>;

/// A JavaScript `Error` on its way out to the caller. The one conversion from a [`KliError`]
/// (`?` makes it), and wasm-bindgen throws it.
#[derive(Debug)]
pub struct Thrown(JsValue);

impl From<KliError> for Thrown {
    // Out of line: inlined at every `?`, the conversion cost the module a kilobyte.
    #[inline(never)]
    fn from(e: KliError) -> Thrown {
        Thrown(throw(e))
    }
}

impl From<Thrown> for JsValue {
    fn from(thrown: Thrown) -> JsValue {
        thrown.0
    }
}

/// The JavaScript name of a Rust argument name: camelCase (`max_time` → `maxTime`); an element
/// such as `starts[3]` keeps its index.
pub fn js_name(rust: &str) -> String {
    // Rust names are ASCII; ASCII case mapping keeps Unicode's tables out of the module.
    let mut name = String::with_capacity(rust.len());
    let mut upper = false;
    for c in rust.chars() {
        if c == '_' {
            upper = true;
        } else {
            name.push(if upper { c.to_ascii_uppercase() } else { c });
            upper = false;
        }
    }
    name
}

/// JavaScript's `String(x)`: keeps Rust's float formatting (and its size) out of the module.
pub fn number(x: f64) -> String {
    js_sys::Number::from(x).to_string_with_radix(10).map(String::from).unwrap_or_default()
}

/// The `Error` to throw for `e`: its message in JavaScript's names and numbers, and its
/// `argument`, `kind`, `component` (a quaternion's) and `line` (a file's) as properties.
#[inline(never)]
fn throw(e: KliError) -> JsValue {
    let error = Error::new(&e.message(&js_name, &number));
    let set = |key: &str, value: JsValue| Reflect::set(&error, &key.into(), &value).is_ok();
    set("argument", js_name(e.argument()).into());
    set("kind", e.kind().code().into());
    if let Some(component) = e.kind().component() {
        set("component", (component as f64).into());
    }
    if let Some(line) = e.kind().line() {
        set("line", (line as f64).into());
    }
    error.into()
}

#[cfg(test)]
mod tests {
    use super::js_name;

    #[test]
    fn js_names_are_camel_case() {
        assert_eq!(js_name("max_time"), "maxTime");
        assert_eq!(js_name("shortest_path"), "shortestPath");
        assert_eq!(js_name("starts[3]"), "starts[3]");
        assert_eq!(js_name("p"), "p");
    }
}
