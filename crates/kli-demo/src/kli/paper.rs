//! The paper's Table 1 as printed, and how each printed number compares with the computed one
//! (MATH.md, "The paper's example": one row is a copy of the row above, and some digits are
//! truncated rather than rounded).

/// Table 1 as printed: `(t, [w, x, y, z])` to two decimals, for `p = k`, `r = ½(1 + i + j + k)`.
pub const PRINTED_TABLE_1: [(f64, [f64; 4]); 8] = [
    (0.0, [0.0, 0.0, 0.0, 1.0]),
    (0.2, [0.09, 0.09, 0.09, 0.98]),
    (0.4, [0.17, 0.17, 0.17, 0.95]),
    (0.55, [0.23, 0.23, 0.23, 0.92]),
    (0.85, [0.31, 0.31, 0.31, 0.84]),
    (1.2, [0.37, 0.37, 0.37, 0.76]),
    (1.8, [0.37, 0.37, 0.37, 0.76]),
    (11.66, [0.49, 0.49, 0.49, 0.5]),
];

/// The paper's example, `[w, x, y, z]`.
pub const PAPER_P: [f64; 4] = [0.0, 0.0, 0.0, 1.0];
pub const PAPER_R: [f64; 4] = [0.5, 0.5, 0.5, 0.5];

/// How a printed two-decimal number stands to the computed value.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Verdict {
    /// The value rounded to two decimals.
    Agrees,
    /// The value cut after two decimals (not rounded): a lesser slip.
    Truncated,
    /// Neither: a wrong number.
    Differs,
}

impl Verdict {
    pub fn name(self) -> &'static str {
        match self {
            Verdict::Agrees => "agrees",
            Verdict::Truncated => "truncated",
            Verdict::Differs => "differs",
        }
    }
}

/// The verdict on `printed` (two decimals) for the computed `value`.
pub fn verdict(printed: f64, value: f64) -> Verdict {
    // Half a unit in the last printed place, with room for the value's own rounding.
    if (printed - value).abs() <= 0.005 + 1e-9 {
        Verdict::Agrees
    } else if (printed - (value * 100.0).trunc() / 100.0).abs() < 1e-9 {
        Verdict::Truncated
    } else {
        Verdict::Differs
    }
}

/// The printed row at `t`, if Table 1 has one (`t` within 1e-9, so the measured `T = 11.66`
/// finds its row).
pub fn printed_row(t: f64) -> Option<(usize, [f64; 4])> {
    PRINTED_TABLE_1
        .iter()
        .position(|&(m, _)| (m - t).abs() < 1e-9)
        .map(|i| (i, PRINTED_TABLE_1[i].1))
}

/// The time of the row above row `index` when the two are printed the same.
pub fn repeats_row_above(index: usize) -> Option<f64> {
    let above = PRINTED_TABLE_1.get(index.checked_sub(1)?)?;
    (above.1 == PRINTED_TABLE_1.get(index)?.1).then_some(above.0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DQuat;

    /// q(t) of the closed form, written out with plain trigonometry (MATH.md): φ0 = π/3,
    /// tan(φ/2) = tan(φ0/2) e^(−t), q = [sin φ p + sin(φ0 − φ) r] / sin φ0.
    fn exact(t: f64) -> [f64; 4] {
        let phi0 = std::f64::consts::FRAC_PI_3;
        let phi = 2.0 * ((phi0 / 2.0).tan() * (-t).exp()).atan();
        let (a, b) = (phi.sin() / phi0.sin(), (phi0 - phi).sin() / phi0.sin());
        std::array::from_fn(|i| a * PAPER_P[i] + b * PAPER_R[i])
    }

    #[test]
    fn the_printed_table_against_the_closed_form() {
        let verdicts: Vec<Vec<Verdict>> = PRINTED_TABLE_1
            .iter()
            .map(|&(t, printed)| {
                let q = exact(t);
                (0..4).map(|c| verdict(printed[c], q[c])).collect()
            })
            .collect();
        use Verdict::*;
        assert_eq!(verdicts[0], [Agrees; 4]);
        // 0.9866 printed 0.98, 0.1754 printed 0.17, 0.8455 printed 0.84, 0.49999 printed 0.49:
        // cut, not rounded.
        assert_eq!(verdicts[1], [Agrees, Agrees, Agrees, Truncated]);
        assert_eq!(verdicts[2], [Truncated, Truncated, Truncated, Agrees]);
        assert_eq!(verdicts[4], [Agrees, Agrees, Agrees, Truncated]);
        assert_eq!(verdicts[7], [Truncated, Truncated, Truncated, Agrees]);
        for row in [3, 5] {
            assert_eq!(verdicts[row], [Agrees; 4], "row {row}");
        }
        // The t = 1.8 row is the t = 1.2 row again: every number wrong.
        assert_eq!(verdicts[6], [Differs; 4]);
        assert_eq!(repeats_row_above(6), Some(1.2));
        assert!((1..8).filter(|&i| i != 6).all(|i| repeats_row_above(i).is_none()));
        assert_eq!(repeats_row_above(0), None);
        assert_eq!(printed_row(11.66 + 1e-12).map(|(i, _)| i), Some(7));
        assert_eq!(printed_row(1.0), None);
        // The closed form here is the core's too.
        let core =
            kli::kli_exact(kli::from_wxyz(PAPER_P), kli::from_wxyz(PAPER_R), 1.8, true).unwrap();
        assert!(
            (core
                - DQuat::from_array([exact(1.8)[1], exact(1.8)[2], exact(1.8)[3], exact(1.8)[0]]))
            .length()
                < 1e-15
        );
    }
}
