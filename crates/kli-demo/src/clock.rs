//! The time of a run that has a span (the KLI page's flow from 0 to T, the keyframes' span):
//! what such a page class keeps, and through [`Clocked`] its run contract's time.

use crate::figure::Timed;

/// A page class that keeps a [`Clock`]: its time runs at one unit a second of the page's clock.
pub(crate) trait Clocked {
    fn clock(&self) -> &Clock;
    fn clock_mut(&mut self) -> &mut Clock;
}

/// `Clocked` for a page class whose [`Clock`] is its field `clock`.
macro_rules! clocked {
    ($class:ident) => {
        impl $crate::clock::Clocked for $class {
            fn clock(&self) -> &$crate::clock::Clock {
                &self.clock
            }

            fn clock_mut(&mut self) -> &mut $crate::clock::Clock {
                &mut self.clock
            }
        }
    };
}
pub(crate) use clocked;

impl<T: Clocked> Timed for T {
    fn span(&self) -> (f64, f64) {
        self.clock().span()
    }

    fn time(&self) -> f64 {
        self.clock().time()
    }

    fn seek(&mut self, t: f64) -> bool {
        self.clock_mut().seek(t)
    }

    fn advance(&mut self, seconds: f64) -> bool {
        self.clock_mut().advance(seconds)
    }
}

/// The time of a run that has a span, `[start, end]`: the time on show, moved by `seek` and
/// `advance` (the KLI run, the keyframes' curves).
pub struct Clock {
    start: f64,
    end: f64,
    t: f64,
}

impl Clock {
    /// At `start`.
    pub fn new(start: f64, end: f64) -> Clock {
        Clock { start, end: end.max(start), t: start }
    }

    pub fn span(&self) -> (f64, f64) {
        (self.start, self.end)
    }

    pub fn time(&self) -> f64 {
        self.t
    }

    /// Moves to `t`, kept within the span (a non-finite `t` is the start). Always gets there.
    pub fn seek(&mut self, t: f64) -> bool {
        self.t = if t.is_finite() { t.max(self.start).min(self.end) } else { self.start };
        true
    }

    /// Moves on by `dt` (a non-finite or negative `dt` by nothing); true once at the end.
    pub fn advance(&mut self, dt: f64) -> bool {
        let dt = if dt.is_finite() { dt.max(0.0) } else { 0.0 };
        self.t = (self.t + dt).min(self.end);
        self.t >= self.end
    }
}
