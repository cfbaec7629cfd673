//! Parameter sweeps for the experiments: spin and speed against offset,
//! friction and approach angle, and the speed–spin trade-off.

use crate::accurate::Accurate3d;
use crate::error::Kick3dError;
use crate::model::{Kick3d, Kick3dSpec};
use kick_core::parameters::{self, ParameterDef, SetParameter, Value};
use kick_core::Scenario;
use serde::Serialize;

/// The swept quantity.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Axis {
    /// e, m
    Offset,
    /// μ
    Friction,
    /// α, degrees
    ApproachAngle,
}

impl Axis {
    /// The declared parameter swept.
    pub fn def(self) -> &'static ParameterDef {
        match self {
            Axis::Offset => &parameters::OFFSET,
            Axis::Friction => &parameters::FRICTION,
            Axis::ApproachAngle => &parameters::APPROACH_ANGLE,
        }
    }
    pub fn name(self) -> &'static str {
        self.def().name
    }
    pub fn unit(self) -> &'static str {
        self.def().unit
    }
    fn apply(self, spec: &mut Kick3dSpec, value: f64) {
        // A declared scalar of the 3D level: setting it cannot fail.
        let _ = spec.set_parameter(self.def(), Value::Number(value));
    }
}

/// One point of a sweep (SI units, angles in degrees).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SweepPoint {
    pub value: f64,
    pub speed: f64,
    pub spin_rpm: f64,
    pub launch_angle: f64,
    pub launch_azimuth: f64,
    pub contact_time: f64,
    pub slip_time: f64,
    pub peak_normal_force: f64,
    pub peak_tangential_force: f64,
    /// Share of the initial kinetic energy that ends as ball spin.
    pub spin_energy_share: f64,
}

/// Names and units of [`SweepPoint`]'s columns after `value`.
pub const COLUMNS: [(&str, &str); 9] = [
    ("speed", "m/s"),
    ("spin_rpm", "rpm"),
    ("launch_angle", "deg"),
    ("launch_azimuth", "deg"),
    ("contact_time", "s"),
    ("slip_time", "s"),
    ("peak_normal_force", "N"),
    ("peak_tangential_force", "N"),
    ("spin_energy_share", "1"),
];

impl SweepPoint {
    pub fn columns(&self) -> [f64; 9] {
        [
            self.speed,
            self.spin_rpm,
            self.launch_angle,
            self.launch_azimuth,
            self.contact_time,
            self.slip_time,
            self.peak_normal_force,
            self.peak_tangential_force,
            self.spin_energy_share,
        ]
    }
}

/// Run the accurate path at each value of `axis`, the rest from `base` and `spec`.
pub fn sweep(base: &Scenario, spec: &Kick3dSpec, axis: Axis, values: &[f64]) -> Result<Vec<SweepPoint>, Kick3dError> {
    let solver = Accurate3d::default();
    values
        .iter()
        .map(|&value| {
            let mut s = *spec;
            axis.apply(&mut s, value);
            let kick = Kick3d::new(*base, &s)?;
            let o = solver.solve(&kick)?;
            Ok(SweepPoint {
                value,
                speed: o.speed,
                spin_rpm: o.spin_rpm,
                launch_angle: o.launch_angle,
                launch_azimuth: o.launch_azimuth,
                contact_time: o.contact_time,
                slip_time: o.slip_time,
                peak_normal_force: o.peak_normal_force,
                peak_tangential_force: o.peak_tangential_force,
                spin_energy_share: o.energy.ball_spin / o.energy.kinetic_initial,
            })
        })
        .collect()
}

/// `count` evenly spaced values from `start` to `end`.
pub fn linspace(start: f64, end: f64, count: usize) -> Vec<f64> {
    match count {
        0 => Vec::new(),
        1 => vec![start],
        _ => (0..count).map(|i| start + (end - start) * i as f64 / (count - 1) as f64).collect(),
    }
}

/// The four standard experiments on Table 1's baseline: offset 0–9 cm
/// (μ = 0.5), friction 0–2 (offset 5 cm), approach angle 0–40° (offset 0,
/// μ = 0.5) and the trade-off (the offset sweep read as speed against spin).
pub fn standard() -> Result<Vec<(Axis, Vec<SweepPoint>)>, Kick3dError> {
    let base = Scenario::baseline();
    let d = Kick3dSpec::default();
    Ok(vec![
        (Axis::Offset, sweep(&base, &d, Axis::Offset, &linspace(0.0, 0.09, 10))?),
        (Axis::Friction, sweep(&base, &Kick3dSpec { offset: Some(0.05), ..d }, Axis::Friction, &linspace(0.0, 2.0, 11))?),
        (Axis::ApproachAngle, sweep(&base, &d, Axis::ApproachAngle, &linspace(0.0, 40.0, 9))?),
    ])
}
