//! The forward model: `Accurate` (Dop853 with located events) with the
//! scenario's own contact law, whose outputs are smooth in the parameters,
//! unlike the fixed-step method's contact time.

use crate::data::{Channel, Observations};
use crate::parameter::ModelPoint;
use crate::IdentifyError;
use kick_compliant::Accurate;
use kick_core::{ContactLaw, History, Outcome, OutsideValidity, RecordingSolver, Sample, Scenario, Solver, Spacing};
use std::ops::ControlFlow;

/// Recording interval as a fraction of the undamped contact time: the
/// cubic Hermite interpolation between recorded steps then has a relative
/// error far below any measurement noise (checked in the tests).
pub const RECORD_FRACTION: f64 = 1.0 / 400.0;

/// Model predictions at the observations, in the order of
/// [`Observations`]: scalars first, then each history channel over all
/// times, a history sample at data time t read at model time t − t0; then
/// each measurement's, the point moved to its conditions.
pub fn predict(solver: &Accurate, point: &ModelPoint, observations: &Observations) -> Result<Vec<f64>, IdentifyError> {
    let mut out = Vec::with_capacity(observations.len());
    predict_own(solver, point, observations, &mut out)?;
    for m in &observations.measurements {
        predict_own(solver, &m.at(point)?, &m.observations, &mut out)?;
    }
    if let Some(bad) = out.iter().position(|v| !v.is_finite()) {
        return Err(IdentifyError::data("model", format!("prediction {bad} is not finite")));
    }
    Ok(out)
}

/// The predictions of `observations`' own scalars and history (not its measurements) into `out`.
fn predict_own(solver: &Accurate, point: &ModelPoint, observations: &Observations, out: &mut Vec<f64>) -> Result<(), IdentifyError> {
    let scenario = &point.scenario;
    if observations.scalars.is_empty() && observations.history.is_none() {
        return Ok(());
    }
    match &observations.history {
        None => {
            let outcome = solver.solve(scenario)?;
            out.extend(observations.scalars.iter().map(|s| s.observable.value(&outcome)));
        }
        Some(history) => {
            let interval = scenario.elastic_contact_time() * RECORD_FRACTION;
            let (outcome, recorded) =
                record_until(solver, scenario, interval, history.data.times.last().copied().unwrap_or(0.0) - point.time_offset)?;
            out.extend(observations.scalars.iter().map(|s| s.observable.value(&outcome)));
            let trajectory = Trajectory::new(scenario, &outcome, recorded)?;
            for (channel, _) in &history.data.channels {
                out.extend(history.data.times.iter().map(|&t| trajectory.channel(*channel, t - point.time_offset)));
            }
        }
    }
    Ok(())
}

/// Where the model at `point` leaves its contact law's validity: the
/// observations' own contact (labelled "") and each measurement's (by its
/// name), those that have observations.
pub fn outside_validity(
    solver: &Accurate,
    point: &ModelPoint,
    observations: &Observations,
) -> Result<Vec<(String, OutsideValidity)>, IdentifyError> {
    let mut contexts = Vec::new();
    if !observations.scalars.is_empty() || observations.history.is_some() {
        contexts.push((String::new(), *point));
    }
    for m in &observations.measurements {
        contexts.push((m.name.clone(), m.at(point)?));
    }
    let mut out = Vec::new();
    for (label, at) in contexts {
        if let Err(outside) = at.check_validity(&solver.solve(&at.scenario)?)? {
            out.push((label, outside));
        }
    }
    Ok(out)
}

/// What the histories would hold with no contact in the data: zero force
/// and compression and the velocities before first touch, in [`predict`]'s
/// order; `None` for a scalar (the contact's own, whatever t0).
pub fn without_contact(solver: &Accurate, point: &ModelPoint, observations: &Observations) -> Result<Vec<Option<f64>>, IdentifyError> {
    let mut out = Vec::with_capacity(observations.len());
    without_contact_own(solver, point, observations, &mut out)?;
    for m in &observations.measurements {
        without_contact_own(solver, &m.at(point)?, &m.observations, &mut out)?;
    }
    Ok(out)
}

fn without_contact_own(
    solver: &Accurate,
    point: &ModelPoint,
    observations: &Observations,
    out: &mut Vec<Option<f64>>,
) -> Result<(), IdentifyError> {
    out.extend(observations.scalars.iter().map(|_| None));
    let Some(history) = &observations.history else { return Ok(()) };
    let scenario = &point.scenario;
    // The first sample, at first touch, holds the velocities before it.
    let (_, recorded) = record_until(solver, scenario, scenario.elastic_contact_time() * RECORD_FRACTION, 0.0)?;
    let first = recorded.samples.first().ok_or_else(|| IdentifyError::data("model", "the solver recorded no samples"))?;
    for (channel, _) in &history.data.channels {
        let value = match channel {
            Channel::Force | Channel::Compression => 0.0,
            Channel::FootVelocity => first.foot_velocity,
            Channel::BallVelocity => first.ball_velocity,
        };
        out.extend(history.data.times.iter().map(|_| Some(value)));
    }
    Ok(())
}

/// Samples `interval` apart up to model time `until` (the data's last time
/// less t0) and one past it, then no more: a trial point whose contact
/// outlasts the data (a soft, high-exponent law creeping apart for minutes)
/// costs samples only over the data's span, where the whole contact cost up
/// to `MAX_HISTORY_SAMPLES` each time (a second per residual, a fit of hours).
///
/// A history's rows are counted over the whole contact before any is made
/// (at most `MAX_HISTORY_SAMPLES`); a trial point whose contact is too long
/// for that at `interval` is recorded once more at the interval that fits
/// it (coarser: such a point lies far from the data's). It was refused with
/// "history too long: use a longer interval or fewer samples", options a
/// fit has not (`kick fit profile --spread 10`, a `kick fit data` start at
/// exponent 9).
fn record_until(solver: &Accurate, scenario: &Scenario, interval: f64, until: f64) -> Result<(Outcome, History), IdentifyError> {
    let record = |interval: f64| {
        let mut samples = Vec::new();
        let streamed = solver.solve_streamed(scenario, Spacing::Interval(interval), &mut |s: &Sample| {
            samples.push(*s);
            if s.time > until {
                ControlFlow::Break(())
            } else {
                ControlFlow::Continue(())
            }
        })?;
        Ok::<_, kick_core::KickError>((streamed.outcome, History { samples }))
    };
    match record(interval) {
        Err(kick_core::KickError::HistoryTooLong { needed, limit }) => {
            // `needed` rows at `interval` span the contact: spread them over `limit` less a margin.
            Ok(record(interval * (needed / (limit as f64 - 16.0)))?)
        }
        other => Ok(other?),
    }
}

/// A recorded contact, readable at any time: before first touch the initial
/// state, during contact cubic Hermite interpolation of positions (with
/// velocities) and velocities (with accelerations), after separation free flight.
#[derive(Debug, Clone)]
pub struct Trajectory {
    samples: Vec<Sample>,
    scenario: Scenario,
    contact_time: f64,
}

impl Trajectory {
    /// Refuses an empty history.
    pub fn new(scenario: &Scenario, outcome: &Outcome, history: History) -> Result<Trajectory, IdentifyError> {
        let mut samples: Vec<Sample> = Vec::with_capacity(history.samples.len());
        for s in history.samples {
            // Events can repeat an accepted step's time; keep one sample per time.
            if samples.last().is_none_or(|last: &Sample| s.time > last.time) {
                samples.push(s);
            }
        }
        if samples.is_empty() {
            return Err(IdentifyError::data("model", "the solver recorded no samples"));
        }
        Ok(Trajectory { samples, scenario: *scenario, contact_time: outcome.contact_time })
    }

    /// (x_f, v_f, x_b, v_b) at time t.
    pub fn state(&self, t: f64) -> [f64; 4] {
        let first = &self.samples[0];
        let last = &self.samples[self.samples.len() - 1];
        if t <= first.time {
            let dt = t - first.time;
            return [
                first.foot_position + first.foot_velocity * dt,
                first.foot_velocity,
                first.ball_position + first.ball_velocity * dt,
                first.ball_velocity,
            ];
        }
        if t >= last.time {
            let dt = t - last.time;
            // Free flight after separation; a constant drive keeps pushing the foot.
            let a = self.scenario.drive_force() / self.scenario.effective_foot_mass();
            return [
                last.foot_position + last.foot_velocity * dt + 0.5 * a * dt * dt,
                last.foot_velocity + a * dt,
                last.ball_position + last.ball_velocity * dt,
                last.ball_velocity,
            ];
        }
        let i = self.samples.partition_point(|s| s.time <= t) - 1;
        let (a, b) = (&self.samples[i], &self.samples[i + 1]);
        let h = b.time - a.time;
        let u = (t - a.time) / h;
        let (mf, mb, fd) = (self.scenario.effective_foot_mass(), self.scenario.ball_mass(), self.scenario.drive_force());
        let acc_f = |s: &Sample| (fd - s.force) / mf; // Eq. 13
        let acc_b = |s: &Sample| s.force / mb; // Eq. 14
        [
            hermite(u, h, a.foot_position, a.foot_velocity, b.foot_position, b.foot_velocity),
            hermite(u, h, a.foot_velocity, acc_f(a), b.foot_velocity, acc_f(b)),
            hermite(u, h, a.ball_position, a.ball_velocity, b.ball_position, b.ball_velocity),
            hermite(u, h, a.ball_velocity, acc_b(a), b.ball_velocity, acc_b(b)),
        ]
    }

    /// One observed channel at time t; the force is the scenario's contact
    /// law at the interpolated (δ, δ̇), zero outside [0, t_c].
    pub fn channel(&self, channel: Channel, t: f64) -> f64 {
        let [xf, vf, xb, vb] = self.state(t);
        match channel {
            Channel::Compression => (xf - xb).max(0.0),
            Channel::FootVelocity => vf,
            Channel::BallVelocity => vb,
            Channel::Force => {
                if (0.0..=self.contact_time).contains(&t) {
                    self.scenario.contact_law().contact_force((xf - xb).max(0.0), vf - vb)
                } else {
                    0.0
                }
            }
        }
    }
}

/// Cubic Hermite interpolant at fraction u of a step h, from values and slopes.
#[inline]
fn hermite(u: f64, h: f64, y0: f64, d0: f64, y1: f64, d1: f64) -> f64 {
    let u2 = u * u;
    let u3 = u2 * u;
    (2.0 * u3 - 3.0 * u2 + 1.0) * y0 + (u3 - 2.0 * u2 + u) * h * d0 + (-2.0 * u3 + 3.0 * u2) * y1 + (u3 - u2) * h * d1
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Interpolating a coarse recording agrees with the solver's own states on
    /// a 20x finer recording: the Hermite error is O(h⁴) ≈ (1/400)⁴ ≈ 4e-11
    /// of the pulse scale, so 1e-6 relative is a loose, safe bound. The force
    /// channel is the scenario's own law: under Hunt–Crossley, Eq. 20 at the
    /// same (δ, δ̇) would be off by c V0 ≈ 70% of the peak at first touch.
    #[test]
    fn interpolation_matches_a_finer_recording() {
        for law in [kick_core::LawKind::PowerLaw, kick_core::LawKind::HuntCrossleyExact, kick_core::LawKind::KelvinVoigt] {
            interpolation_matches_for(Scenario::baseline().with_law(law, Some(0.66)).unwrap());
        }
    }

    /// A trial point whose contact outlasts the data by far (this soft,
    /// high-exponent law, met by a fit of data with no contact, separates
    /// after two minutes) is recorded over the data's 6.5 ms only: one
    /// sample past them, where the whole contact took 976,000 and a second.
    /// Within the span the samples are the whole recording's.
    #[test]
    fn recording_stops_one_sample_past_the_data() {
        use kick_core::Parameter::*;
        let s = [(FootMass, 0.36203), (Stiffness, 3.4299e4), (Damping, 459.41), (Exponent, 5.3346)]
            .iter()
            .fold(Scenario::baseline(), |s, &(p, v)| s.with(p, v).unwrap());
        let solver = Accurate::default();
        let interval = s.elastic_contact_time() * RECORD_FRACTION;
        let until = 6.5e-3;
        let (o, h) = record_until(&solver, &s, interval, until).unwrap();
        assert!(o.contact_time > 120.0, "{}", o.contact_time);
        assert_eq!(h.samples.len(), (until / interval).floor() as usize + 2);
        let [.., before, past] = h.samples[..] else { panic!() };
        assert!(before.time <= until && past.time > until);
        let (_, whole) =
            solver.solve_recorded(&Scenario::baseline(), Scenario::baseline().elastic_contact_time() * RECORD_FRACTION).unwrap();
        let (_, part) =
            record_until(&solver, &Scenario::baseline(), Scenario::baseline().elastic_contact_time() * RECORD_FRACTION, 2e-3).unwrap();
        assert_eq!(whole.samples[..part.samples.len()], part.samples[..]);
        // Ten times finer the whole 2-minute contact needs ~1e7 rows, past the
        // history limit: recorded at the interval that fits it, not refused.
        let (o, h) = record_until(&solver, &s, interval / 10.0, until).unwrap();
        let needed = (o.contact_time / (interval / 10.0)).ceil() + 1.0;
        assert!(needed > kick_core::MAX_HISTORY_SAMPLES as f64, "{needed}");
        let [.., before, past] = h.samples[..] else { panic!() };
        assert!(before.time <= until && past.time > until && h.samples.len() >= 2);
    }

    fn interpolation_matches_for(s: Scenario) {
        let solver = Accurate::default();
        let tc0 = s.elastic_contact_time();
        let (o, coarse) = solver.solve_recorded(&s, tc0 * RECORD_FRACTION).unwrap();
        let (_, fine) = solver.solve_recorded(&s, tc0 * RECORD_FRACTION / 20.0).unwrap();
        let tr = Trajectory::new(&s, &o, coarse).unwrap();
        assert!(Trajectory::new(&s, &o, History::default()).is_err());
        let force_scale = o.peak_force;
        for sample in fine.samples.iter().step_by(7) {
            let t = sample.time;
            if t <= 0.0 || t >= o.contact_time {
                continue;
            }
            let f = tr.channel(Channel::Force, t);
            assert!((f - sample.force).abs() < 1e-6 * force_scale, "t={t}: {f} vs {}", sample.force);
            let d = tr.channel(Channel::Compression, t);
            assert!((d - sample.compression).abs() < 1e-6 * o.max_compression);
            let vb = tr.channel(Channel::BallVelocity, t);
            assert!((vb - sample.ball_velocity).abs() < 1e-6 * o.v_ball_out);
        }
        // After separation: free flight at the exit velocities.
        let after = o.contact_time * 1.5;
        assert_eq!(tr.channel(Channel::BallVelocity, after), o.v_ball_out);
        assert_eq!(tr.channel(Channel::Force, after), 0.0);
        assert_eq!(tr.channel(Channel::Compression, after), 0.0);
    }
}
