//! Axis ticks for the plots. Plain Rust, tested natively.

/// A tick spacing of 1, 2 or 5 × 10^k giving about five ticks over `[0, span]` (0 for an empty
/// or non-finite span).
pub fn nice_step(span: f64) -> f64 {
    if !(span > 0.0 && span.is_finite()) {
        return 0.0;
    }
    let raw = span / 5.0;
    let magnitude = 10f64.powi(raw.log10().floor() as i32);
    [1.0, 2.0, 5.0, 10.0].iter().map(|m| m * magnitude).find(|&s| s >= raw).unwrap_or(raw)
}

/// The decades `low..=high` (as exponents of 10) to label on a log axis, every `every`-th.
pub fn decades(low: i32, high: i32, every: i32) -> Vec<i32> {
    (low..=high).filter(|e| (e - low) % every.max(1) == 0).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn steps_are_one_two_five() {
        assert_eq!(nice_step(11.66), 5.0);
        assert_eq!(nice_step(1.0), 0.2);
        assert_eq!(nice_step(40.0), 10.0);
        assert_eq!(nice_step(0.012), 0.005);
        assert_eq!(nice_step(0.0), 0.0);
        assert_eq!(nice_step(f64::NAN), 0.0);
    }

    #[test]
    fn decade_labels() {
        assert_eq!(decades(-7, 0, 2), vec![-7, -5, -3, -1]);
        assert_eq!(decades(-3, -1, 0), vec![-3, -2, -1]);
    }
}
