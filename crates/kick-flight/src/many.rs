//! Many flights at once: parameter columns in, one outcome or error per row
//! out, rows solved in parallel (rayon) on a bounded number of threads.
//! Front ends (Python's `kick.flight_many`) broadcast their arrays to rows
//! and turn each row's result into a status code ([`FlightError::status`]).

use crate::{solve, FlightError, FlightOutcome, FlightParameter, FlightSpec};
use kick_core::threads::{cores, max_threads};
use rayon::prelude::*;

/// Rows a worker takes at a time: large enough that rayon's bookkeeping is
/// small beside the flights (a few µs each), small enough to balance.
const MIN_ROWS_PER_TASK: usize = 64;

/// One parameter's values: `rows × components` numbers (row-major; a
/// vector's three numbers together), or just `components` numbers for the
/// same value in every row.
#[derive(Debug, Clone, Copy)]
pub struct Column<'a> {
    pub parameter: FlightParameter,
    pub values: &'a [f64],
}

/// Solve `rows` flights: row i is `base` with every column's i-th value set.
/// A row that is refused or fails has its error (its status:
/// [`FlightError::status`]); the call itself is refused only for columns
/// of the wrong length or a thread count outside 1..=[`max_threads`] (the
/// workspace's one bound). `threads`: None runs on rayon's global pool.
pub fn flight_many(
    base: &FlightSpec,
    columns: &[Column],
    rows: usize,
    threads: Option<usize>,
) -> Result<Vec<Result<FlightOutcome, FlightError>>, FlightError> {
    for c in columns {
        let width = c.parameter.components();
        if c.values.len() != width && c.values.len() != rows * width {
            return Err(FlightError::WrongLength { name: c.parameter.name(), expected: rows * width, found: c.values.len() });
        }
    }
    let row = |i: usize| -> Result<FlightOutcome, FlightError> {
        let mut spec = *base;
        for c in columns {
            let width = c.parameter.components();
            let at = if c.values.len() == width { 0 } else { i * width };
            spec.set(c.parameter, &c.values[at..at + width])?;
        }
        solve(&spec.build()?)
    };
    let run = || (0..rows).into_par_iter().with_min_len(MIN_ROWS_PER_TASK).map(row).collect();
    match threads {
        None => Ok(run()),
        Some(n) => {
            if n == 0 {
                return Err(FlightError::InvalidParameter { name: "threads", value: 0.0, requirement: "at least 1" });
            }
            if n > max_threads() {
                return Err(FlightError::TooManyThreads { requested: n, max: max_threads(), cores: cores() });
            }
            let pool = rayon::ThreadPoolBuilder::new().num_threads(n).build().map_err(|_| FlightError::InvalidParameter {
                name: "threads",
                value: n as f64,
                requirement: "a number of threads the system can start",
            })?;
            Ok(pool.install(run))
        }
    }
}

impl FlightError {
    /// What became of a row: refused (bad input) or a numerical failure
    /// (never reported as physics); a flight that lands has status
    /// `Separated` (code 0, kick-core's success code).
    pub fn status(&self) -> kick_core::Status {
        use kick_core::Status;
        match self {
            FlightError::NoLanding { .. } | FlightError::Integration { .. } | FlightError::NonFinite { .. } => Status::NumericalFailure,
            FlightError::InvalidParameter { .. }
            | FlightError::Missing { .. }
            | FlightError::OutOfRange { .. }
            | FlightError::WrongLength { .. }
            | FlightError::TooMany { .. }
            | FlightError::UnknownParameter { .. }
            | FlightError::Conflict { .. }
            | FlightError::TooManySamples { .. }
            | FlightError::TooManyThreads { .. } => Status::Refused,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every row is the flight `solve` gives for the same spec, to the bit,
    /// whatever the thread count; a bad row is refused alone; scalars broadcast.
    #[test]
    fn rows_are_single_flights() {
        let speeds = [20.0, 25.0, -1.0, 30.0];
        let spins = [0.0, 0.0, 50.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 10.0, -20.0, 30.0];
        let columns = [
            Column { parameter: FlightParameter::Speed, values: &speeds },
            Column { parameter: FlightParameter::Spin, values: &spins },
            Column { parameter: FlightParameter::LaunchAngle, values: &[18.0] },
        ];
        let base = FlightSpec { distance: Some(9.15), ..FlightSpec::default() };
        for threads in [None, Some(1), Some(2)] {
            let out = flight_many(&base, &columns, 4, threads).unwrap();
            assert_eq!(out.len(), 4);
            for (i, result) in out.iter().enumerate() {
                let spec = FlightSpec {
                    speed: Some(speeds[i]),
                    launch_angle: Some(18.0),
                    spin: Some([spins[3 * i], spins[3 * i + 1], spins[3 * i + 2]]),
                    ..base
                };
                let single = spec.build().and_then(|f| solve(&f));
                assert_eq!(result, &single, "row {i}");
            }
            assert!(matches!(&out[2], Err(e) if e.status() == kick_core::Status::Refused));
        }
    }

    #[test]
    fn bad_calls_are_refused() {
        let base = FlightSpec::from_exit_speed(25.0, 20.0);
        let short = [Column { parameter: FlightParameter::Spin, values: &[1.0, 2.0, 3.0, 4.0] }];
        assert_eq!(flight_many(&base, &short, 2, None), Err(FlightError::WrongLength { name: "spin", expected: 6, found: 4 }));
        assert!(matches!(flight_many(&base, &[], 1, Some(0)), Err(FlightError::InvalidParameter { name: "threads", .. })));
        // The workspace's one bound (kick_core::threads), as `--threads` and Python's `threads=`.
        let max = kick_core::threads::max_threads();
        assert_eq!(
            flight_many(&base, &[], 1, Some(max + 1)),
            Err(FlightError::TooManyThreads { requested: max + 1, max, cores: kick_core::threads::cores() })
        );
        assert_eq!(flight_many(&base, &[], 1, Some(max)).unwrap().len(), 1);
        assert_eq!(flight_many(&base, &[], 0, None).unwrap().len(), 0);
        // Unchanged rows: the base flight, every time.
        let out = flight_many(&base, &[], 3, Some(2)).unwrap();
        let single = solve(&base.build().unwrap());
        assert!(out.iter().all(|r| r == &single));
    }
}
