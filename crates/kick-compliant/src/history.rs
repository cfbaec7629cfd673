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
    pub fn fill<E>(&mut self, end: f64, inclusive: bool, mut make: impl FnMut(f64, &mut u64) -> Result<S, E>) -> Result<(), E> {
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

/// Solve with a history: `run(None)` solves without one first (the grid of
/// [`Spacing::Count`] depends on the contact's end, and every history's row
/// count is refused beyond [`kick_core::MAX_HISTORY_SAMPLES`] before a row is made),
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
    // Rows are counted before any is made, on the contact solved once
    // without sampling: every history (1D, 3D, streamed to a file or
    // collected for Python) holds at most MAX_HISTORY_SAMPLES.
    let spacing = spacing.validate()?;
    let end = end_of(&run(None)?);
    let grid = spacing.grid(end);
    grid.samples_within(end, kick_core::MAX_HISTORY_SAMPLES)?;
    let mut sampler = Sampler::new(grid, sink);
    let outcome = run(Some(&mut sampler))?;
    let samples = grid.samples_until(end_of(&outcome));
    Ok((outcome, samples))
}

#[cfg(test)]
mod tests {
    use crate::Accurate;
    use kick_core::{KickError, RecordingSolver, Scenario, Solver, Spacing, MAX_HISTORY_SAMPLES};
    use std::ops::ControlFlow;

    /// Every history's rows are counted before one is made: an interval
    /// that gives more than MAX_HISTORY_SAMPLES rows over the contact
    /// (t_c / Δ + 1, from the contact solved alone) is refused with that
    /// count, the sink never called, streamed or collected. 1e-300 s used to
    /// spin (1e297 grid points), 1e-10 s to stream 9e7 rows.
    #[test]
    fn a_history_longer_than_the_limit_is_refused_before_its_first_row() {
        let s = Scenario::baseline();
        let solver = Accurate::default();
        let contact_time = solver.solve(&s).unwrap().contact_time;
        let limit = MAX_HISTORY_SAMPLES as f64;
        for interval in [contact_time / (2.0 * limit), 1e-10, 1e-300] {
            let mut rows = 0u64;
            let result = solver.solve_streamed(&s, Spacing::Interval(interval), &mut |_| {
                rows += 1;
                ControlFlow::Continue(())
            });
            match result {
                Err(KickError::HistoryTooLong { needed, limit: l }) => {
                    let expected = (contact_time / interval).ceil() + 1.0;
                    assert!((needed - expected).abs() <= 1.0 + 1e-12 * expected, "{interval}: {needed} {expected}");
                    assert_eq!(l, MAX_HISTORY_SAMPLES as u64);
                }
                other => panic!("{interval}: {other:?}"),
            }
            assert_eq!(rows, 0, "{interval}");
            let collected = solver.solve_sampled(&s, Spacing::Interval(interval), MAX_HISTORY_SAMPLES);
            assert!(matches!(collected, Err(KickError::HistoryTooLong { .. })), "{interval}");
        }
        // At the limit it streams.
        let fits = contact_time / (limit - 2.0);
        let streamed = solver.solve_streamed(&s, Spacing::Interval(fits), &mut |_| ControlFlow::Continue(())).unwrap();
        assert!(streamed.samples <= MAX_HISTORY_SAMPLES as u64, "{}", streamed.samples);
        assert!(solver.solve_streamed(&s, Spacing::Count(MAX_HISTORY_SAMPLES + 1), &mut |_| ControlFlow::Continue(())).is_err());
    }
}
