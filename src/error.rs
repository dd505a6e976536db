//! The one error type of the crate: the argument at fault and what is wrong with it, as fields.
//!
//! Messages name arguments by their Rust names (`max_time`, `shortest_path`). A binding to
//! another language renders the same error with its own names and number formatting through
//! [`KliError::message`]; the JavaScript package passes camelCase and JavaScript's `String(x)`.

use std::fmt;

/// Why a call was refused: [`argument`](KliError::argument) names the argument at fault (an
/// element of an array as `starts[3]`), [`kind`](KliError::kind) says what is wrong.
#[derive(Debug, Clone, PartialEq)]
pub struct KliError {
    argument: String,
    kind: ErrorKind,
}

/// What a value must be, for [`ErrorKind::OutOfRange`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Requirement {
    /// Finite.
    Finite,
    /// Finite and `> 0`.
    Positive,
    /// Finite and `≥ 0`.
    NonNegative,
    /// Finite with `|x| ≤` the bound.
    AtMost(f64),
    /// Finite, from the first bound to the second.
    Between(f64, f64),
}

/// The shape of a vector argument, for messages about its components.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Shape {
    /// A quaternion `[w, x, y, z]`, scalar first.
    Quaternion,
    /// A quaternion `[x, y, z, w]`, scalar last (three.js, gl-matrix, glTF): how a binding names
    /// the components of an argument its caller laid out so.
    QuaternionXyzw,
    /// A 3-vector `[x, y, z]`.
    Vector3,
}

impl Shape {
    fn components(self) -> &'static [&'static str] {
        match self {
            Shape::Quaternion => &["w", "x", "y", "z"],
            Shape::QuaternionXyzw => &["x", "y", "z", "w"],
            Shape::Vector3 => &["x", "y", "z"],
        }
    }

    fn describe(self) -> &'static str {
        match self {
            Shape::Quaternion => "a quaternion of 4 finite numbers [w, x, y, z], not all zero",
            Shape::QuaternionXyzw => "a quaternion of 4 finite numbers [x, y, z, w], not all zero",
            Shape::Vector3 => "3 finite numbers [x, y, z], not all zero",
        }
    }
}

/// What is wrong with the argument.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum ErrorKind {
    /// Component `index` (`[w, x, y, z]` or `[x, y, z]`, from 0) is NaN or infinite.
    NotFinite { shape: Shape, index: usize, value: f64 },
    /// A quaternion or axis of zero length: it has no direction.
    ZeroLength { shape: Shape },
    /// A number outside its domain.
    OutOfRange { value: f64, requirement: Requirement },
    /// An array that must hold `expected` numbers: 4 for each `per` (a singular noun: "t value",
    /// "edge"), or, with `per` empty, one value of `expected` numbers (a quaternion, a 3-vector).
    WrongLength { expected: usize, got: usize, per: String },
    /// A name that is not one of `allowed`.
    UnknownName { got: String, allowed: &'static [&'static str] },
    /// The target is `-start` and the long way round was asked for: `q' = 0` there, an unstable
    /// equilibrium (MATH.md, "Edge cases"). `start` and `end` name the two quaternions.
    Antipodal { start: String, end: String },
    /// Algorithm 1 did not meet the tolerance by `max_time`.
    NotReached { tolerance: f64, max_time: f64, closest: f64, predicted: f64 },
    /// A step left `q` unchanged short of the tolerance, far from the target: `p` so close to `-r`
    /// (taken the long way) that `δ q'` is below the resolution of f64.
    Stalled { time: f64, distance: f64 },
    /// An integrator that works in R⁴ let `|q|` run away from 1 near `-r`, where the sphere
    /// repels off-sphere errors (`d|q|²/dt = 2 (q·r)(1 - |q|²)`, MATH.md, "Edge cases").
    LeftSphere { integrator: &'static str, time: f64, norm: f64 },
    /// The step is beyond the integrator's stability: `|q|` ran away from 1 on a path where the
    /// sphere attracts (`q·r > 0` throughout).
    Unstable { integrator: &'static str, step: f64, time: f64, norm: f64 },
    /// `max_time / step` asks for more samples than a path may hold.
    TooManySteps { steps: f64, limit: usize },
    /// A mean that is not unique: the two largest eigenvalues of the chordal mean's scatter
    /// matrix are equal to rounding (`1` and `i`: MATH.md, "Averaging rotations"), or the
    /// quaternions sum to zero. Reported, never an arbitrary pick.
    NotUnique { top: f64, second: f64 },
    /// Anything else, in words: the type checks of a language binding.
    Invalid(String),
    /// A line of a text read (a pose-graph file) that cannot be read, by its number from 1;
    /// [`ErrorKind::line`] hands the number to bindings, as a property beside the message.
    /// With the feature `sync` only, the one reader of files (built without it, no module pays
    /// for the variant's message).
    #[cfg(feature = "sync")]
    InvalidLine { line: usize, problem: String },
}

impl ErrorKind {
    /// A short stable code for the kind, e.g. `"not-finite"`: what bindings hand their callers.
    pub fn code(&self) -> &'static str {
        match self {
            ErrorKind::NotFinite { .. } => "not-finite",
            ErrorKind::ZeroLength { .. } => "zero-length",
            ErrorKind::OutOfRange { .. } => "out-of-range",
            ErrorKind::WrongLength { .. } => "wrong-length",
            ErrorKind::UnknownName { .. } => "unknown-name",
            ErrorKind::Antipodal { .. } => "antipodal",
            ErrorKind::NotReached { .. } => "not-reached",
            ErrorKind::Stalled { .. } => "stalled",
            ErrorKind::LeftSphere { .. } => "left-sphere",
            ErrorKind::Unstable { .. } => "unstable",
            ErrorKind::TooManySteps { .. } => "too-many-steps",
            ErrorKind::NotUnique { .. } => "not-unique",
            ErrorKind::Invalid(_) => "invalid",
            #[cfg(feature = "sync")]
            ErrorKind::InvalidLine { .. } => "invalid",
        }
    }

    /// The component at fault, for [`ErrorKind::NotFinite`].
    pub fn component(&self) -> Option<usize> {
        match self {
            ErrorKind::NotFinite { index, .. } => Some(*index),
            _ => None,
        }
    }

    /// The line at fault (from 1), for [`ErrorKind::InvalidLine`].
    pub fn line(&self) -> Option<usize> {
        match self {
            #[cfg(feature = "sync")]
            ErrorKind::InvalidLine { line, .. } => Some(*line),
            _ => None,
        }
    }
}

impl KliError {
    /// The error `kind` about `argument`.
    pub fn new(argument: impl Into<String>, kind: ErrorKind) -> Self {
        Self { argument: argument.into(), kind }
    }

    /// An [`ErrorKind::Invalid`] error: `argument` followed by `problem` is the message.
    pub fn invalid(argument: impl Into<String>, problem: impl Into<String>) -> Self {
        Self::new(argument, ErrorKind::Invalid(problem.into()))
    }

    /// The argument at fault, by its Rust name.
    pub fn argument(&self) -> &str {
        &self.argument
    }

    /// What is wrong with it.
    pub fn kind(&self) -> &ErrorKind {
        &self.kind
    }

    /// The same error about another argument, e.g. `starts[3]` instead of `q` in a batch call.
    pub fn renamed(self, argument: impl Into<String>) -> Self {
        Self { argument: argument.into(), ..self }
    }

    /// The message, with argument names written by `name` and numbers by `number`. It starts
    /// with the argument's name.
    pub fn message(&self, name: &dyn Fn(&str) -> String, number: &dyn Fn(f64) -> String) -> String {
        let (arg, n) = (name(&self.argument), number);
        match &self.kind {
            ErrorKind::NotFinite { shape, index, value } => {
                let component = shape.components().get(*index).copied().unwrap_or("?");
                format!(
                    "{arg} must be {}: its {component} component is {}",
                    shape.describe(),
                    n(*value)
                )
            }
            ErrorKind::ZeroLength { shape } => {
                format!("{arg} must be {}: it has zero length", shape.describe())
            }
            ErrorKind::OutOfRange { value, requirement } => {
                let requirement = match requirement {
                    Requirement::Finite => "a finite number".into(),
                    Requirement::Positive => "a finite number > 0".into(),
                    Requirement::NonNegative => "a finite number ≥ 0".into(),
                    Requirement::AtMost(bound) => {
                        format!("a finite number from -{} to {}", n(*bound), n(*bound))
                    }
                    Requirement::Between(low, high) => {
                        format!("a finite number from {} to {}", n(*low), n(*high))
                    }
                };
                format!("{arg} must be {requirement} (got {})", n(*value))
            }
            // "p must hold 4 numbers (got 3)"
            ErrorKind::WrongLength { expected, got, per } if per.is_empty() => {
                format!("{arg} must hold {expected} numbers (got {got})")
            }
            // "ends must hold 4 numbers per t value: 8 for 2 t values (got 4)"
            ErrorKind::WrongLength { expected, got, per } => {
                let count = expected / 4;
                let plural = if count == 1 { "" } else { "s" };
                format!(
                    "{arg} must hold 4 numbers per {per}: {expected} for {count} {per}{plural} (got {got})"
                )
            }
            ErrorKind::UnknownName { got, allowed } => {
                format!("{arg} must be {} (got \"{got}\")", one_of(allowed))
            }
            ErrorKind::Antipodal { start, end } => format!(
                "{} and {} are antipodal and {} is false: q' = 0 there, an unstable equilibrium, so \
                 the flow never moves and no path is determined ({0} and {1} are the same \
                 rotation; use {2}: true)",
                name(start),
                name(end),
                name("shortest_path"),
            ),
            ErrorKind::NotReached { tolerance, max_time, closest, predicted } => format!(
                "{arg} {} not reached within {} {} (closest distance {}; the closed form predicts \
                 T* = {}): raise {} or the tolerance",
                n(*tolerance),
                name("max_time"),
                n(*max_time),
                n(*closest),
                n(*predicted),
                name("max_time"),
            ),
            ErrorKind::Stalled { time, distance } => format!(
                "{arg} is false and p is so close to -r that a step does not move q (stuck at \
                 distance {} from the target at t = {}), a numerical equilibrium; use {arg}: true \
                 or a larger step",
                n(*distance),
                n(*time)
            ),
            ErrorKind::LeftSphere { integrator, time, norm } => format!(
                "{arg} {integrator} left the sphere S³ (|q| = {} at t = {}): near -r the sphere \
                 repels the rounding errors of a step taken in R⁴; use {arg} \"geodesic\", which \
                 stays on S³, or {}: true",
                n(*norm),
                n(*time),
                name("shortest_path"),
            ),
            ErrorKind::Unstable { integrator, step, time, norm } => format!(
                "{arg} {} is too large for {} {integrator}: q left the sphere S³ (|q| = {} at \
                 t = {}); use a smaller step",
                n(*step),
                name("integrator"),
                n(*norm),
                n(*time),
            ),
            ErrorKind::TooManySteps { steps, limit } => format!(
                "{arg} is too small for {}: {} / {arg} = {} steps, more than the {limit} a path \
                 may hold",
                name("max_time"),
                name("max_time"),
                n(*steps)
            ),
            ErrorKind::NotUnique { top, second } => format!(
                "{arg} have no unique mean: the largest two eigenvalues of their scatter matrix, \
                 {} and {}, are equal to rounding (the rotations are spread evenly, as 1 and i \
                 are); weights that break the tie, or the geodesic median, give one",
                n(*top),
                n(*second)
            ),
            ErrorKind::Invalid(problem) => format!("{arg} {problem}"),
            #[cfg(feature = "sync")]
            ErrorKind::InvalidLine { line, problem } => format!("{arg} line {line}: {problem}"),
        }
    }
}

/// `"a", "b" or "c"`.
fn one_of(names: &[&str]) -> String {
    let mut list = String::new();
    for (i, name) in names.iter().enumerate() {
        let separator = if i == 0 {
            ""
        } else if i + 1 == names.len() {
            " or "
        } else {
            ", "
        };
        list.push_str(separator);
        list.push('"');
        list.push_str(name);
        list.push('"');
    }
    list
}

/// Rust's way of writing a number in a message: exponent form for the very small and large.
pub fn rust_number(x: f64) -> String {
    if x != 0.0 && x.is_finite() && (x.abs() < 1e-4 || x.abs() >= 1e16) {
        format!("{x:e}")
    } else {
        format!("{x}")
    }
}

impl fmt::Display for KliError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message(&|name| name.to_owned(), &rust_number))
    }
}

impl std::error::Error for KliError {}

/// Checks that `value` meets `requirement`.
pub fn require(argument: &str, value: f64, requirement: Requirement) -> Result<f64, KliError> {
    let ok = value.is_finite()
        && match requirement {
            Requirement::Finite => true,
            Requirement::Positive => value > 0.0,
            Requirement::NonNegative => value >= 0.0,
            Requirement::AtMost(bound) => value.abs() <= bound,
            Requirement::Between(low, high) => (low..=high).contains(&value),
        };
    if ok {
        Ok(value)
    } else {
        Err(KliError::new(argument, ErrorKind::OutOfRange { value, requirement }))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn messages_start_with_the_argument_in_the_callers_names() {
        let e = KliError::new(
            "max_time",
            ErrorKind::OutOfRange { value: -1.0, requirement: Requirement::Positive },
        );
        assert_eq!(e.to_string(), "max_time must be a finite number > 0 (got -1)");
        let camel = |s: &str| if s == "max_time" { "maxTime".to_owned() } else { s.to_owned() };
        let js = e.message(&camel, &|x| format!("<{x}>"));
        assert_eq!(js, "maxTime must be a finite number > 0 (got <-1>)");
        assert_eq!((e.argument(), e.kind().code()), ("max_time", "out-of-range"));
    }

    #[test]
    fn component_errors_name_the_component() {
        let e = KliError::new(
            "r",
            ErrorKind::NotFinite { shape: Shape::Quaternion, index: 2, value: f64::NAN },
        );
        assert!(e.to_string().ends_with("its y component is NaN"), "{e}");
        assert_eq!(e.kind().component(), Some(2));
        let renamed = e.renamed("ends[4]");
        assert!(renamed.to_string().starts_with("ends[4] must be a quaternion"));
    }

    #[test]
    fn requirements() {
        assert_eq!(require("s", 3.0, Requirement::AtMost(3.0)), Ok(3.0));
        assert!(require("s", -3.5, Requirement::AtMost(3.0)).is_err());
        assert!(require("t", f64::INFINITY, Requirement::Finite).is_err());
        assert!(require("t", -0.0, Requirement::NonNegative).is_ok());
        assert!(require("step", 0.0, Requirement::Positive).is_err());
    }

    #[test]
    fn an_unknown_name_lists_the_names_allowed() {
        let message = |allowed: &'static [&'static str]| {
            KliError::new("method", ErrorKind::UnknownName { got: "mean".into(), allowed })
                .to_string()
        };
        assert_eq!(message(&["chordal"]), r#"method must be "chordal" (got "mean")"#);
        assert_eq!(message(&["a", "b"]), r#"method must be "a" or "b" (got "mean")"#);
        assert_eq!(
            message(&["a", "b", "c", "d"]),
            r#"method must be "a", "b", "c" or "d" (got "mean")"#
        );
    }

    /// As Rust's `{:?}` writes an `f64` (exponent form below 1e-4 and from 1e16), without its
    /// `.0` on whole numbers; zero and non-finite values as `{}` does.
    #[test]
    fn numbers_in_messages_switch_to_exponents_where_rust_does() {
        for (x, want) in [
            (1e-4, "0.0001"),
            (-1e-4, "-0.0001"),
            (9.99e-5, "9.99e-5"),
            (1e16, "1e16"),
            (-1e16, "-1e16"),
            (9999999999999998.0, "9999999999999998"),
            (2.5, "2.5"),
            (0.0, "0"),
            (f64::MIN_POSITIVE, "2.2250738585072014e-308"),
            (f64::NEG_INFINITY, "-inf"),
            (f64::NAN, "NaN"),
        ] {
            assert_eq!(rust_number(x), want, "{x:?}");
            if x != 0.0 && x.is_finite() && x.fract() != 0.0 {
                assert_eq!(rust_number(x), format!("{x:?}"));
            }
        }
    }
}
