//! Numbers as text, by JavaScript's own formatting: Rust's float formatting would add its code
//! to the module for nothing.

pub use kli_wasm::error::number;

/// `x` with `digits` decimals, by JavaScript's `toFixed` (no float formatting in the module).
pub fn fixed(x: f64, digits: u8) -> String {
    js_sys::Number::from(x).to_fixed(digits).map(String::from).unwrap_or_default()
}

/// `x` in exponent form with `digits` decimals, by JavaScript's `toExponential`.
pub fn exponential(x: f64, digits: u8) -> String {
    js_sys::Number::from(x).to_exponential(digits).map(String::from).unwrap_or_default()
}

/// Numbers joined by `separator`, each as JavaScript writes it (the shortest text that reads back
/// as the same number): a CSV row's fields, a JSON list's items.
pub fn joined(values: &[f64], separator: &str) -> String {
    let mut text = String::with_capacity(values.len() * 20);
    for (i, &v) in values.iter().enumerate() {
        if i > 0 {
            text.push_str(separator);
        }
        text.push_str(&number(v));
    }
    text
}

/// A JSON list of numbers, `[1,0.5]`.
pub fn json_list(values: &[f64]) -> String {
    format!("[{}]", joined(values, ","))
}
