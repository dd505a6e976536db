//! The time of an endless run that moves by whole steps (the swarm, the synchronisation page's
//! flow): what such a page class says of its steps, and through [`stepped!`] its run contract's
//! time, with no end and no way back.

/// A page class whose time moves by whole steps, each costing some work (its own unit: an
/// oscillator's step, an edge's visit), each call bounded so a frame or a task stays short.
pub(crate) trait Stepped {
    /// Steps a second of the page's clock at speed 1.
    const PACE: f64;
    /// The most work one frame (`advance`) takes: past it the run slows down rather than falls
    /// behind (what the bound cuts off is not owed).
    const FRAME_WORK: f64;
    /// The most work one `seek` call (a task) takes.
    const TASK_WORK: f64;
    /// The work of one step.
    fn step_work(&self) -> f64;
    /// The run's step, in its time.
    fn dt(&self) -> f64;
    /// The run's time now.
    fn now(&self) -> f64;
    /// Steps owed to the clock: a frame's share of a step carries over to the next.
    fn owed(&mut self) -> &mut f64;
    /// `steps` (a whole number from 1 to a bound of work) steps, then one sample of the
    /// history; false if the model refused.
    fn steps(&mut self, steps: f64) -> bool;

    /// Steps a bound of `work` allows (at least one).
    fn within(&self, work: f64) -> f64 {
        (work / self.step_work()).floor().max(1.0)
    }

    /// Runs on towards `t`, at most [`Stepped::TASK_WORK`] a call; true once there.
    fn seek_steps(&mut self, t: f64) -> bool {
        let left = if t.is_finite() { ((t - self.now()) / self.dt()).round() } else { 0.0 };
        if left < 1.0 {
            return true;
        }
        let steps = left.min(self.within(Self::TASK_WORK));
        self.steps(steps) && steps >= left
    }

    /// [`Stepped::PACE`] steps a second, at most [`Stepped::FRAME_WORK`] a call.
    fn advance_steps(&mut self, seconds: f64) {
        if seconds.is_finite() && seconds > 0.0 {
            let owed = (*self.owed() + seconds * Self::PACE).min(self.within(Self::FRAME_WORK));
            *self.owed() = owed;
            let steps = owed.floor();
            if steps >= 1.0 && self.steps(steps) {
                *self.owed() -= steps;
            }
        }
    }
}

/// The run contract's time for a [`Stepped`] page class: from 0, with no end.
macro_rules! stepped {
    ($class:ident) => {
        impl $crate::figure::Timed for $class {
            fn span(&self) -> (f64, f64) {
                (0.0, f64::INFINITY)
            }

            fn time(&self) -> f64 {
                $crate::stepped::Stepped::now(self)
            }

            fn seek(&mut self, t: f64) -> bool {
                $crate::stepped::Stepped::seek_steps(self, t)
            }

            /// Never at an end.
            fn advance(&mut self, seconds: f64) -> bool {
                $crate::stepped::Stepped::advance_steps(self, seconds);
                false
            }
        }
    };
}
pub(crate) use stepped;
