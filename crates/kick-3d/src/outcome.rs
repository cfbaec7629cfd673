//! What a 3D solver returns.

use crate::model::Kick3d;
use crate::Kick3dError;
use kick_core::ContactLaw;
use parry3d_f64::math::{Rot3, Vec3};
use serde::Serialize;

/// Energy partition at separation, J (Eqs. 30–33 extended by rotation and friction).
///
/// `kinetic_initial + drive_work + gravity_work` equals `ball_translation +
/// ball_spin + foot + elastic_final + normal_damping_loss + friction_loss`;
/// the losses and works are integrated from their own power densities, so the
/// residual measures the solver, not a definition.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct EnergyPartition {
    pub kinetic_initial: f64,
    /// ½ m_b |v_b|².
    pub ball_translation: f64,
    /// ½ I_b |ω_b|².
    pub ball_spin: f64,
    /// Foot translation and rotation.
    pub foot: f64,
    /// U(δ) of the normal law plus ½ k_t |ξ|² of the tangential spring at the end.
    pub elastic_final: f64,
    /// ∫ (F_n(δ, δ̇) − F_n(δ, 0)) δ̇ dt, the normal law's loss (Eq. 25 for the
    /// paper's law; a clamped Kelvin–Voigt also loses the spring energy left
    /// when its force reaches zero).
    pub normal_damping_loss: f64,
    /// ∫ μ F_n λ dt: the Coulomb slider's loss (λ its speed; [`crate::tangential`]).
    pub friction_loss: f64,
    /// ∫ F_drive · v_f dt.
    pub drive_work: f64,
    /// Work of gravity on both bodies.
    pub gravity_work: f64,
}

impl EnergyPartition {
    /// Input − (kinetic + elastic + losses): zero up to the solver's error.
    pub fn residual(&self) -> f64 {
        self.kinetic_initial + self.drive_work + self.gravity_work
            - (self.ball_translation + self.ball_spin + self.foot + self.elastic_final + self.normal_damping_loss + self.friction_loss)
    }
    pub fn relative_residual(&self) -> f64 {
        self.residual() / (self.kinetic_initial + self.drive_work.abs() + self.gravity_work.abs())
    }
}

/// Summary of one 3D contact, SI units, world frame (x: line of motion, z: up).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Outcome3d {
    /// Ball velocity at separation, m/s.
    pub launch_velocity: [f64; 3],
    /// Ball angular velocity at separation, rad/s.
    pub spin: [f64; 3],
    /// |launch_velocity|, m/s.
    pub speed: f64,
    /// |spin| in revolutions per minute.
    pub spin_rpm: f64,
    /// Elevation of the launch velocity above the horizontal, degrees.
    pub launch_angle: f64,
    /// Horizontal direction of launch from the x axis, degrees (positive toward +y).
    pub launch_azimuth: f64,
    pub foot_velocity: [f64; 3],
    pub foot_angular_velocity: [f64; 3],
    pub contact_time: f64,
    pub peak_normal_force: f64,
    pub peak_normal_force_time: f64,
    /// sup |F_t|, N.
    pub peak_tangential_force: f64,
    pub peak_tangential_force_time: f64,
    pub max_compression: f64,
    pub max_compression_time: f64,
    /// Total time the contact points slip (the tangential force on its Coulomb cap), s.
    pub slip_time: f64,
    /// Contact impulse on the ball ∫F dt, N s (Eq. 1).
    pub impulse: [f64; 3],
    /// ∫ F_n dt, N s.
    pub normal_impulse: f64,
    /// ∫ r × F dt about the ball centre, N m s (Eq. 61 with a moving r).
    pub angular_impulse: [f64; 3],
    /// r0 × J with r0 the contact point at first touch (Eq. 61 as written).
    pub angular_impulse_fixed_point: [f64; 3],
    pub energy: EnergyPartition,
    /// Right-hand-side evaluations (0 for closed forms), or scene steps.
    pub evaluations: u64,
    pub solver: &'static str,
    /// The normal contact law.
    pub law: kick_core::LawKind,
}

impl Outcome3d {
    /// Ball angular momentum at separation, I_b ω (the ball starts without spin).
    pub fn ball_angular_momentum(&self, ball_inertia: f64) -> [f64; 3] {
        self.spin.map(|w| ball_inertia * w)
    }

    /// Fill speed, rpm and angles from the two vectors.
    pub(crate) fn derive_summary(&mut self) {
        let [vx, vy, vz] = self.launch_velocity;
        self.speed = (vx * vx + vy * vy + vz * vz).sqrt();
        let [wx, wy, wz] = self.spin;
        self.spin_rpm = (wx * wx + wy * wy + wz * wz).sqrt() * 60.0 / std::f64::consts::TAU;
        self.launch_angle = vz.atan2((vx * vx + vy * vy).sqrt()).to_degrees();
        self.launch_azimuth = vy.atan2(vx).to_degrees();
    }

    /// No NaN or infinity leaves the library.
    pub(crate) fn check_finite(self) -> Result<Self, kick_core::KickError> {
        let t = self.contact_time;
        let vectors = [
            ("launch velocity", self.launch_velocity),
            ("spin", self.spin),
            ("foot velocity", self.foot_velocity),
            ("foot angular velocity", self.foot_angular_velocity),
            ("impulse", self.impulse),
            ("angular impulse", self.angular_impulse),
        ];
        for (name, v) in vectors {
            for x in v {
                kick_core::error::finite(name, x, t)?;
            }
        }
        let scalars = [
            ("contact time", self.contact_time),
            ("peak normal force", self.peak_normal_force),
            ("peak tangential force", self.peak_tangential_force),
            ("max compression", self.max_compression),
            ("slip time", self.slip_time),
            ("energy residual", self.energy.residual()),
        ];
        for (name, x) in scalars {
            kick_core::error::finite(name, x, t)?;
        }
        Ok(self)
    }
}

/// A running maximum (value, time).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Peak {
    pub value: f64,
    pub time: f64,
}

impl Peak {
    pub fn observe(&mut self, value: f64, time: f64) {
        if value > self.value {
            *self = Peak { value, time };
        }
    }
}

/// Extremes collected along a run.
#[derive(Debug, Clone, Copy)]
pub struct Peaks {
    pub normal: Peak,
    pub tangential: Peak,
    /// (δ_max, its time)
    pub compression: (f64, f64),
    pub slip_time: f64,
}

/// Samples of a recorded run: (t, kinetic + elastic energy, damping loss, friction loss).
pub type EnergySample = (f64, f64, f64, f64);

/// Both bodies at separation, world frame, with the running integrals.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EndState {
    pub time: f64,
    pub foot_position: Vec3,
    pub foot_orientation: Rot3,
    pub foot_velocity: Vec3,
    pub foot_angular_velocity: Vec3,
    pub ball_position: Vec3,
    pub ball_velocity: Vec3,
    pub ball_angular_velocity: Vec3,
    /// Tangential spring extension ξ.
    pub spring: Vec3,
    /// δ at the end (zero up to the event's location; the ball's δ_B with a boot).
    pub compression: f64,
    /// δ_b, the boot's compression at the end (0 without a boot).
    pub boot_compression: f64,
    /// ∫ F dt and ∫ r × F dt (about the ball centre) on the ball, ∫ F_n dt.
    pub impulse: Vec3,
    pub angular_impulse: Vec3,
    pub normal_impulse: f64,
    pub normal_damping_loss: f64,
    pub friction_loss: f64,
    pub drive_work: f64,
    pub gravity_work: f64,
}

impl EndState {
    /// Kinetic energy of the foot: translation and rotation about its principal axes.
    pub fn foot_energy(&self, kick: &Kick3d) -> f64 {
        if let Some(leg) = &kick.leg {
            // ∫ F dt on the foot: the drive's less the contact's on the ball.
            let impulse = kick.drive() * self.time - self.impulse;
            return leg.foot_energy(kick.base.effective_foot_mass(), impulse, self.foot_angular_velocity, self.foot_velocity);
        }
        let [ix, iy, iz] = kick.foot_inertia;
        let w = self.foot_orientation.inverse() * self.foot_angular_velocity;
        0.5 * kick.base.effective_foot_mass() * self.foot_velocity.length_squared() + 0.5 * w.dot(w * Vec3::new(ix, iy, iz))
    }
}

/// Refuses a compression deeper than the geometry allows: the ball's radius
/// R, where the ball's centre reaches the foot's surface. Beyond it the
/// contact normal turns over and the foot passes through the ball, so no
/// law describes the contact: an error, never an outcome (every path checks
/// as it goes and [`assemble`] the peak).
pub(crate) fn within_geometry(kick: &Kick3d, compression: f64, time: f64) -> Result<(), Kick3dError> {
    if compression > kick.ball_radius {
        let (limit_name, why) = ("the ball radius R", "the ball's centre reaches the foot's surface");
        return Err(kick_core::KickError::BeyondGeometry { compression, time, limit: kick.ball_radius, limit_name, why }.into());
    }
    Ok(())
}

/// The summary at separation.
pub(crate) fn assemble(
    kick: &Kick3d,
    end: &EndState,
    peaks: Peaks,
    evaluations: u64,
    solver: &'static str,
) -> Result<Outcome3d, Kick3dError> {
    within_geometry(kick, peaks.compression.0, peaks.compression.1)?;
    let r0 = -kick.initial_normal() * kick.ball_radius;
    let fixed = r0.cross(end.impulse);
    let law = kick.law();
    let mut out = Outcome3d {
        launch_velocity: end.ball_velocity.to_array(),
        spin: end.ball_angular_velocity.to_array(),
        speed: 0.0,
        spin_rpm: 0.0,
        launch_angle: 0.0,
        launch_azimuth: 0.0,
        foot_velocity: end.foot_velocity.to_array(),
        foot_angular_velocity: end.foot_angular_velocity.to_array(),
        contact_time: end.time,
        peak_normal_force: peaks.normal.value,
        peak_normal_force_time: peaks.normal.time,
        peak_tangential_force: peaks.tangential.value,
        peak_tangential_force_time: peaks.tangential.time,
        max_compression: peaks.compression.0,
        max_compression_time: peaks.compression.1,
        slip_time: peaks.slip_time,
        impulse: end.impulse.to_array(),
        normal_impulse: end.normal_impulse,
        angular_impulse: end.angular_impulse.to_array(),
        angular_impulse_fixed_point: fixed.to_array(),
        energy: EnergyPartition {
            kinetic_initial: kick.initial_kinetic_energy(),
            ball_translation: 0.5 * kick.base.ball_mass() * end.ball_velocity.length_squared(),
            ball_spin: 0.5 * kick.ball_inertia * end.ball_angular_velocity.length_squared(),
            foot: end.foot_energy(kick),
            elastic_final: law.potential(end.compression)
                + kick.spring_energy(end.spring.length_squared())
                + kick.base.boot().map_or(0.0, |b| b.potential(end.boot_compression)),
            normal_damping_loss: end.normal_damping_loss,
            friction_loss: end.friction_loss,
            drive_work: end.drive_work,
            gravity_work: end.gravity_work,
        },
        evaluations,
        solver,
        law: law.kind(),
    };
    out.derive_summary();
    Ok(out.check_finite()?)
}

/// Names and units of [`Outcome3d::observable_values`]: every summary number
/// of a 3D kick, vectors as `_x`, `_y`, `_z` columns (world frame), the
/// energy partition as `energy_*`. Result files name their columns by these.
pub const OBSERVABLES_3D: [(&str, &str); 42] = [
    ("launch_velocity_x", "m/s"),
    ("launch_velocity_y", "m/s"),
    ("launch_velocity_z", "m/s"),
    ("spin_x", "rad/s"),
    ("spin_y", "rad/s"),
    ("spin_z", "rad/s"),
    ("speed", "m/s"),
    ("spin_rpm", "rpm"),
    ("launch_angle", "deg"),
    ("launch_azimuth", "deg"),
    ("foot_velocity_x", "m/s"),
    ("foot_velocity_y", "m/s"),
    ("foot_velocity_z", "m/s"),
    ("foot_angular_velocity_x", "rad/s"),
    ("foot_angular_velocity_y", "rad/s"),
    ("foot_angular_velocity_z", "rad/s"),
    ("impulse_x", "N s"),
    ("impulse_y", "N s"),
    ("impulse_z", "N s"),
    ("normal_impulse", "N s"),
    ("angular_impulse_x", "N m s"),
    ("angular_impulse_y", "N m s"),
    ("angular_impulse_z", "N m s"),
    ("contact_time", "s"),
    ("peak_normal_force", "N"),
    ("peak_normal_force_time", "s"),
    ("peak_tangential_force", "N"),
    ("peak_tangential_force_time", "s"),
    ("max_compression", "m"),
    ("max_compression_time", "s"),
    ("slip_time", "s"),
    ("energy_kinetic_initial", "J"),
    ("energy_ball_translation", "J"),
    ("energy_ball_spin", "J"),
    ("energy_foot", "J"),
    ("energy_elastic_final", "J"),
    ("energy_normal_damping_loss", "J"),
    ("energy_friction_loss", "J"),
    ("energy_drive_work", "J"),
    ("energy_gravity_work", "J"),
    ("energy_residual", "J"),
    ("evaluations", "1"),
];

impl Outcome3d {
    /// The values of [`OBSERVABLES_3D`], in order: the numbers of
    /// [`FIELDS_3D`] but the fixed-point angular impulse, then the evaluations.
    pub fn observable_values(&self) -> [f64; OBSERVABLES_3D.len()] {
        let mut out = [0.0; OBSERVABLES_3D.len()];
        let n = OBSERVABLES_3D.len() - 1;
        out[..n].copy_from_slice(&self.field_values()[..n]);
        out[n] = self.evaluations as f64;
        out
    }

    /// The numbers of [`FIELDS_3D`], in order: the serde fields, vectors whole.
    pub fn field_values(&self) -> [f64; FIELD_VALUES_3D] {
        let e = &self.energy;
        let mut out = [0.0; FIELD_VALUES_3D];
        let mut at = 0;
        let mut put = |part: &[f64]| {
            out[at..at + part.len()].copy_from_slice(part);
            at += part.len();
        };
        put(&self.launch_velocity);
        put(&self.spin);
        put(&[self.speed, self.spin_rpm, self.launch_angle, self.launch_azimuth]);
        put(&self.foot_velocity);
        put(&self.foot_angular_velocity);
        put(&self.impulse);
        put(&[self.normal_impulse]);
        put(&self.angular_impulse);
        put(&[
            self.contact_time,
            self.peak_normal_force,
            self.peak_normal_force_time,
            self.peak_tangential_force,
            self.peak_tangential_force_time,
            self.max_compression,
            self.max_compression_time,
            self.slip_time,
            e.kinetic_initial,
            e.ball_translation,
            e.ball_spin,
            e.foot,
            e.elastic_final,
            e.normal_damping_loss,
            e.friction_loss,
            e.drive_work,
            e.gravity_work,
            e.residual(),
        ]);
        put(&self.angular_impulse_fixed_point);
        out
    }
}

/// The numbers [`Outcome3d::field_values`] returns.
pub const FIELD_VALUES_3D: usize = 44;
const _: () = {
    let mut sum = 0;
    let mut i = 0;
    while i < FIELDS_3D.len() {
        sum += FIELDS_3D[i].1;
        i += 1;
    }
    assert!(sum == FIELD_VALUES_3D, "FIELDS_3D's widths add up to FIELD_VALUES_3D");
};

/// The outcome's serde fields as (name, width), the energy partition's as
/// `energy_*`, then `energy_residual`: every number of a kick but the
/// evaluation count, vectors whole (Python's `simulate3d_many` columns).
pub const FIELDS_3D: [(&str, usize); 30] = [
    ("launch_velocity", 3),
    ("spin", 3),
    ("speed", 1),
    ("spin_rpm", 1),
    ("launch_angle", 1),
    ("launch_azimuth", 1),
    ("foot_velocity", 3),
    ("foot_angular_velocity", 3),
    ("impulse", 3),
    ("normal_impulse", 1),
    ("angular_impulse", 3),
    ("contact_time", 1),
    ("peak_normal_force", 1),
    ("peak_normal_force_time", 1),
    ("peak_tangential_force", 1),
    ("peak_tangential_force_time", 1),
    ("max_compression", 1),
    ("max_compression_time", 1),
    ("slip_time", 1),
    ("energy_kinetic_initial", 1),
    ("energy_ball_translation", 1),
    ("energy_ball_spin", 1),
    ("energy_foot", 1),
    ("energy_elastic_final", 1),
    ("energy_normal_damping_loss", 1),
    ("energy_friction_loss", 1),
    ("energy_drive_work", 1),
    ("energy_gravity_work", 1),
    ("energy_residual", 1),
    ("angular_impulse_fixed_point", 3),
];

#[cfg(test)]
mod tests {
    use crate::{Kick3d, KickSpec, Solver3d};
    use kick_core::parameters::{SetParameter, Value};
    use kick_core::KickError;

    /// The observables are the fields (vectors as `_x`, `_y`, `_z`) in the
    /// same order, but the fixed-point angular impulse, then the evaluations:
    /// what `observable_values` copies from `field_values` relies on it.
    #[test]
    fn the_observables_are_the_fields_in_order() {
        let mut names = Vec::new();
        for (name, width) in super::FIELDS_3D {
            match width {
                1 => names.push(name.to_string()),
                _ => names.extend(["x", "y", "z"].map(|a| format!("{name}_{a}"))),
            }
        }
        assert_eq!(names.len(), super::FIELD_VALUES_3D);
        let observables: Vec<String> = super::OBSERVABLES_3D.iter().map(|(n, _)| n.to_string()).collect();
        let n = observables.len() - 1;
        assert_eq!(&names[..n], &observables[..n]);
        assert_eq!(&names[n..], ["angular_impulse_fixed_point_x", "angular_impulse_fixed_point_y", "angular_impulse_fixed_point_z"]);
        assert_eq!(observables[n], "evaluations");
        let o = Solver3d::Auto.solve(&kick(&[("offset", 0.03)])).unwrap();
        let (v, f) = (o.observable_values(), o.field_values());
        assert_eq!(
            (v[3], v[16], v[20], v[40], v[41]),
            (o.spin[0], o.impulse[0], o.angular_impulse[0], o.energy.residual(), o.evaluations as f64)
        );
        assert_eq!(&f[41..], &o.angular_impulse_fixed_point);
    }

    fn kick(values: &[(&str, f64)]) -> Kick3d {
        let mut spec = KickSpec::default();
        for &(name, x) in values {
            spec.set_named(name, Value::Number(x)).unwrap();
        }
        spec.build().unwrap()
    }

    /// A compression deeper than the ball's radius (its centre at the foot's
    /// surface) is an error naming the limit on every path, never an
    /// outcome. At 200 m/s against k = 1e4 N/m^n the undamped energy balance
    /// k δ^(n+1)/(n+1) = ½ μ V0² puts δ_max at 1.27 m, eleven radii; the
    /// paper's baseline stays well inside (δ_max ≈ 1 cm).
    #[test]
    fn compression_beyond_the_ball_radius_is_an_error() {
        let soft = kick(&[("foot_speed", 200.0), ("stiffness", 1e4)]);
        let undamped = soft.base.elastic_max_compression();
        assert!(undamped > 10.0 * soft.ball_radius, "{undamped}");
        let driven = kick(&[("offset", 0.05), ("drive_force", 1e6)]);
        for name in Solver3d::NAMES {
            let solver = Solver3d::from_name(name, crate::DEFAULT_SCENE_STEP).unwrap();
            let mut cases = vec![("soft", &soft)];
            if !matches!(name, "1d" | "auto") {
                cases.push(("driven", &driven));
            }
            for (case, kick) in cases {
                match solver.solve(kick) {
                    Err(crate::Kick3dError::Core(KickError::BeyondGeometry { compression, limit, .. })) => {
                        assert!(compression > limit && limit == kick.ball_radius, "{name} {case}: {compression} {limit}");
                    }
                    other => panic!("{name} {case}: {other:?}"),
                }
            }
            let baseline = solver.solve(&Kick3d::baseline()).unwrap();
            assert!(baseline.max_compression < 0.5 * Kick3d::baseline().ball_radius, "{name}: {}", baseline.max_compression);
        }
        let text = Solver3d::from_name("accurate", 1e-6).unwrap().solve(&soft).unwrap_err().to_string();
        assert!(text.contains("exceeds the ball radius R = 0.11 m"), "{text}");
    }
}
