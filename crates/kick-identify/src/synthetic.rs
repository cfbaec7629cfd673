//! Synthetic observations: the forward model at known parameters plus seeded
//! Gaussian noise, for recovery tests and identifiability studies.

use crate::data::{Channel, HistoryData, Measurement, Observable, Observations, ScalarObservation, WeightedHistory};
use crate::model::predict;
use crate::parameter::{FitParameter, ModelPoint};
use crate::IdentifyError;
use kick_compliant::Accurate;
use kick_core::Scenario;
use rand::rngs::Xoshiro256PlusPlus;
use rand::{RngExt, SeedableRng};
use std::collections::BTreeMap;

/// Seeded standard normal deviates (Box–Muller on the generator's uniforms).
pub struct Gaussian {
    rng: Xoshiro256PlusPlus,
    spare: Option<f64>,
}

impl Gaussian {
    pub fn new(seed: u64) -> Self {
        Gaussian { rng: Xoshiro256PlusPlus::seed_from_u64(seed), spare: None }
    }

    pub fn sample(&mut self) -> f64 {
        if let Some(z) = self.spare.take() {
            return z;
        }
        // u1 in (0, 1] so ln u1 is finite.
        let u1 = 1.0 - self.rng.random::<f64>();
        let u2 = self.rng.random::<f64>();
        let r = (-2.0 * u1.ln()).sqrt();
        let (s, c) = (std::f64::consts::TAU * u2).sin_cos();
        self.spare = Some(r * s);
        r * c
    }
}

/// Noise of a plausible lab recording of the baseline kick: 20 N on a
/// ≈ 3.8 kN pulse, 0.1 mm on ≈ 28 mm, 0.05 m/s on the velocities.
pub fn lab_sigma(channels: &[Channel]) -> BTreeMap<Channel, f64> {
    channels
        .iter()
        .map(|&c| {
            let s = match c {
                Channel::Force => 20.0,
                Channel::Compression => 1e-4,
                Channel::FootVelocity | Channel::BallVelocity => 0.05,
            };
            (c, s)
        })
        .collect()
}

/// `count` equally spaced times over [0, span × the undamped contact time].
pub fn time_grid(scenario: &Scenario, count: usize, span: f64) -> Vec<f64> {
    let end = span * scenario.elastic_contact_time();
    let count = count.max(2);
    (0..count).map(|i| end * i as f64 / (count - 1) as f64).collect()
}

/// Channels of `truth` (its scenario, law and time offset) at `times`, each
/// plus N(0, sigma²) noise from `seed`.
pub fn history(
    solver: &Accurate,
    truth: &ModelPoint,
    times: Vec<f64>,
    sigma: &BTreeMap<Channel, f64>,
    seed: u64,
) -> Result<Observations, IdentifyError> {
    let channels: Vec<(Channel, Vec<f64>)> = sigma.keys().map(|&c| (c, vec![0.0; times.len()])).collect();
    let exact = WeightedHistory::new(HistoryData { times, channels }, sigma.clone())?;
    let mut observations = Observations::history(exact);
    let values = predict(solver, truth, &observations)?;
    let mut noise = Gaussian::new(seed);
    if let Some(h) = observations.history.as_mut() {
        let per_channel = h.data.times.len();
        for (k, (channel, column)) in h.data.channels.iter_mut().enumerate() {
            let s = sigma[channel];
            for (i, v) in column.iter_mut().enumerate() {
                *v = values[k * per_channel + i] + s * noise.sample();
            }
        }
    }
    Ok(observations)
}

/// Scalar observables of `truth`, each plus N(0, sigma²) noise from `seed`
/// (seed `None`: exact values).
pub fn scalars(solver: &Accurate, truth: &Scenario, sigma: &[(Observable, f64)], seed: Option<u64>) -> Result<Observations, IdentifyError> {
    let outcome = kick_core::Solver::solve(solver, truth)?;
    let mut noise = seed.map(Gaussian::new);
    let scalars = sigma
        .iter()
        .map(|&(observable, s)| ScalarObservation {
            observable,
            value: observable.value(&outcome) + noise.as_mut().map_or(0.0, |g| s * g.sample()),
            sigma: s,
        })
        .collect();
    Observations::scalars(scalars)
}

/// Measurements of `truth` at each of `conditions` (values of declared
/// parameters, as a `[[measurement]]` gives them), each observable of
/// `sigma` plus N(0, sigma²) noise from `seed` (seed `None`: exact values).
/// Named by their conditions ("speed = 6, inflation_pressure = 80000").
pub fn measurements(
    solver: &Accurate,
    truth: &ModelPoint,
    conditions: &[Vec<(FitParameter, f64)>],
    sigma: &[(Observable, f64)],
    seed: Option<u64>,
) -> Result<Observations, IdentifyError> {
    let mut noise = seed.map(Gaussian::new);
    let mut out = Vec::with_capacity(conditions.len());
    for given in conditions {
        let name: Vec<String> = given.iter().map(|(p, v)| format!("{} = {}", p.name(), kick_core::short(*v))).collect();
        let exact = Observations {
            scalars: sigma.iter().map(|&(observable, s)| ScalarObservation { observable, value: 0.0, sigma: s }).collect(),
            history: None,
            measurements: Vec::new(),
        };
        let mut m = Measurement { name: name.join(", "), conditions: given.clone(), observations: exact };
        let values = predict(solver, &m.at(truth)?, &m.observations)?;
        for (s, v) in m.observations.scalars.iter_mut().zip(values) {
            s.value = v + noise.as_mut().map_or(0.0, |g| s.sigma * g.sample());
        }
        out.push(m);
    }
    let o = Observations { scalars: Vec::new(), history: None, measurements: out };
    o.validate()?;
    Ok(o)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Mean and variance of 20 000 deviates: standard errors 0.007 and 0.01,
    /// so 5 standard errors is 0.035 / 0.05.
    #[test]
    fn gaussian_has_unit_variance() {
        let mut g = Gaussian::new(7);
        let n = 20_000;
        let xs: Vec<f64> = (0..n).map(|_| g.sample()).collect();
        let mean = xs.iter().sum::<f64>() / n as f64;
        let var = xs.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1) as f64;
        assert!(mean.abs() < 0.035, "{mean}");
        assert!((var - 1.0).abs() < 0.05, "{var}");
    }
}
