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
