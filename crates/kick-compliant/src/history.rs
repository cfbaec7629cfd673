//! Uniform time histories ([`kick_core::Spacing`]) for the 1D solvers (and,
//! with a sample type of its own, the 3D accurate path, `kick_3d::history`).
//!
//! A sample at grid time t_k is made by re-integrating from the last
//! accepted step before it to t_k with the run's own method (one step of
//! the same Runge–Kutta formula, or a few if an adaptive method rejects
//! it), so every sample carries the accuracy of an accepted step, and the
//! integration that decides the outcome never sees the grid: its steps, and
//! so the outcome, are bit-identical with and without a history.

use kick_core::{Grid, KickError, Outcome, Sample, Spacing, Streamed};
use std::ops::ControlFlow;

/// Hands grid samples (of type `S`) to a sink in time order.
pub struct Sampler<'a, S = Sample> {
    grid: Grid,
    next: u64,
    sink: &'a mut dyn FnMut(&S) -> ControlFlow<()>,
    open: bool,
    /// Right-hand-side evaluations spent on samples (not in the outcome's count).
    pub evaluations: u64,
}

impl<'a, S> Sampler<'a, S> {
    pub fn new(grid: Grid, sink: &'a mut dyn FnMut(&S) -> ControlFlow<()>) -> Self {
        Sampler { grid, next: 0, sink, open: true, evaluations: 0 }
    }

    /// Whether a grid sample is still due at or before `end` (`inclusive`)
    /// or before it: lets a caller skip preparing what [`Self::fill`] needs.
    pub fn due(&self, end: f64, inclusive: bool) -> bool {
        self.open && self.grid.admits(self.next, end, inclusive)
    }

    /// Make and hand over every grid sample up to `end` (`inclusive`) or
    /// before it, not yet handed over; `make(t, evaluations)` makes one.
    pub fn fill<E>(
        &mut self,
        end: f64,
        inclusive: bool,
        mut make: impl FnMut(f64, &mut u64) -> Result<S, E>,
    ) -> Result<(), E> {
        while self.due(end, inclusive) {
            let sample = make(self.grid.time(self.next), &mut self.evaluations)?;
            self.next += 1;
            self.open = (self.sink)(&sample).is_continue();
        }
        Ok(())
    }

    /// The separation row, the history's last.
    pub fn finish(&mut self, sample: S) {
        if self.open {
            self.open = (self.sink)(&sample).is_continue();
        }
    }
}

/// Solve with a history: `run(None)` solves without one (needed first for
/// [`Spacing::Count`], whose grid depends on the contact's end),
/// `run(Some(sampler))` with one; `end_of` reads the history's end time
/// t_end off the outcome.
pub fn stream(
    spacing: Spacing,
    sink: &mut dyn FnMut(&Sample) -> ControlFlow<()>,
    end_of: impl Fn(&Outcome) -> f64,
    run: impl FnMut(Option<&mut Sampler>) -> Result<Outcome, KickError>,
) -> Result<Streamed, KickError> {
    let (outcome, samples) = stream_any(spacing, sink, end_of, run)?;
    Ok(Streamed { outcome, samples })
}

/// [`stream`] for any sample, outcome and error type: the outcome and the
/// number of samples in the full history (grid points plus the separation row).
pub fn stream_any<S, O, E: From<KickError>>(
    spacing: Spacing,
    sink: &mut dyn FnMut(&S) -> ControlFlow<()>,
    end_of: impl Fn(&O) -> f64,
    mut run: impl FnMut(Option<&mut Sampler<S>>) -> Result<O, E>,
) -> Result<(O, u64), E> {
    let grid = match spacing.validate()? {
        Spacing::Interval(_) => spacing.grid(f64::NAN),
        Spacing::Count(_) => spacing.grid(end_of(&run(None)?)),
    };
    let mut sampler = Sampler::new(grid, sink);
    let outcome = run(Some(&mut sampler))?;
    let samples = grid.samples_until(end_of(&outcome));
    Ok((outcome, samples))
}
