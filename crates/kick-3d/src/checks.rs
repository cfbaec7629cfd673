//! Checks of the 3D model against the 1D solver, closed forms and
//! conservation laws, in the row shape of `kick-checks` (name, equation,
//! expected, actual, error, tolerance, passed) so `kick check` can list them.
//!
//! `error` is |actual − expected| / scale, the scale named per row; each
//! tolerance has its reason next to it.

use crate::accurate::Accurate3d;
use crate::model::{Kick3d, Kick3dSpec};
use crate::outcome::Outcome3d;
use crate::Kick3dError;
use kick_compliant::Accurate;
use kick_core::{Scenario, Solver};
use parry3d_f64::math::Vec3;

pub use kick_core::check::CheckRow;
use kick_core::check::{Scoring, ToleranceKind};

/// How each family of rows of [`checks`] is scored (the report prints it):
/// the scale of the error and the origin of the tolerance.
pub const SCORING: [Scoring; 12] = [
    Scoring {
        prefix: "3d central frictionless = 1d",
        scale: "|the 1D value|",
        tolerance: "1e-9: the same contact, so the solvers' stated accuracy",
        kind: ToleranceKind::SolverAccuracy,
    },
    Scoring {
        prefix: "3d zero offset",
        scale: "V/R, the rolling spin at the foot's speed",
        tolerance: "1e-12: zero by symmetry",
        kind: ToleranceKind::Rounding,
    },
    Scoring {
        prefix: "3d I_b omega",
        scale: "|∫ r × F dt|",
        tolerance: "1e-12: the same impulse, integrated as state",
        kind: ToleranceKind::Rounding,
    },
    Scoring {
        prefix: "3d passive contact",
        scale: "the initial kinetic energy",
        tolerance: "1e-9: the energy cannot rise, so the solver's accuracy",
        kind: ToleranceKind::SolverAccuracy,
    },
    Scoring {
        prefix: "3d energy in",
        scale: "the initial kinetic energy",
        tolerance: "1e-9: the losses are integrated from their own power, so the solver's accuracy",
        kind: ToleranceKind::SolverAccuracy,
    },
    Scoring {
        prefix: "3d mirrored offset",
        scale: "|ω| of the kick mirrored",
        tolerance: "1e-12: the mirror image, by symmetry",
        kind: ToleranceKind::Rounding,
    },
    Scoring { prefix: "3d mu = 0:", scale: "V/R", tolerance: "1e-12: no tangential force", kind: ToleranceKind::Rounding },
    Scoring {
        prefix: "3d shell ball, mu = 0.01 full slip",
        scale: "R μ J_n / I_b, the expected spin",
        tolerance: "1e-9: exact while the contact slides throughout, so the solver's accuracy",
        kind: ToleranceKind::SolverAccuracy,
    },
    Scoring {
        prefix: "3d shell ball, mu = 0.01: slip time",
        scale: "the contact time",
        tolerance: "1e-12: the same event",
        kind: ToleranceKind::Rounding,
    },
    Scoring {
        prefix: "3d mu = inf, rigid grip",
        scale: "|the gripping limit|",
        tolerance: "1e-9: the constraint is the limit, so the solver's accuracy",
        kind: ToleranceKind::SolverAccuracy,
    },
    Scoring {
        prefix: "3d mu = inf: |spin|",
        scale: "the closed form",
        tolerance: "1e-9: the elastic oscillator's closed form, so the solver's accuracy",
        kind: ToleranceKind::SolverAccuracy,
    },
    Scoring {
        prefix: "3d mu = inf: slip time",
        scale: "the contact time",
        tolerance: "1e-12: it never slips",
        kind: ToleranceKind::Rounding,
    },
];

/// The solvers agree to 1e-9 relative: both integrate at rtol 1e-12 and
/// locate events to rounding; 1e-9 is the accuracy `accurate` promises.
pub const MATCH_1D: f64 = 1e-9;
/// Quantities that are equal by construction up to floating-point rounding
/// accumulated over ~1e4 steps.
pub const ROUNDING: f64 = 1e-12;

/// The pair's momentum and angular momentum about the origin (world frame)
/// at `end`, and at first touch: with no drive and no gravity nothing
/// outside the pair pushes or twists it, so the two agree.
pub fn pair_momenta(kick: &Kick3d, end: &crate::outcome::EndState) -> [(Vec3, Vec3); 2] {
    let (m_f, m_b) = (kick.base.effective_foot_mass(), kick.base.ball_mass());
    let [ix, iy, iz] = kick.foot_inertia;
    let q = end.foot_orientation;
    let foot_spin = q * ((q.inverse() * end.foot_angular_velocity) * Vec3::new(ix, iy, iz));
    let after = (
        end.foot_velocity * m_f + end.ball_velocity * m_b,
        end.foot_position.cross(end.foot_velocity * m_f)
            + foot_spin
            + end.ball_position.cross(end.ball_velocity * m_b)
            + end.ball_angular_velocity * kick.ball_inertia,
    );
    let s = kick.initial_state();
    let before = (
        s.foot_velocity * m_f + s.ball_velocity * m_b,
        s.foot_position.cross(s.foot_velocity * m_f) + s.ball_position.cross(s.ball_velocity * m_b),
    );
    [before, after]
}

/// An off-center kick: offset 5 cm, μ = 0.5, other values at their defaults.
pub fn curve_kick() -> Result<Kick3d, Kick3dError> {
    try_kick(Kick3dSpec { offset: Some(0.05), ..Kick3dSpec::default() })
}

/// A kick on Table 1's baseline with the given extras.
pub fn try_kick(spec: Kick3dSpec) -> Result<Kick3d, Kick3dError> {
    Kick3d::new(Scenario::baseline(), &spec)
}

/// [`try_kick`] for tests and examples with specs known to be valid.
///
/// # Panics
/// On an invalid spec.
pub fn kick(spec: Kick3dSpec) -> Kick3d {
    match try_kick(spec) {
        Ok(k) => k,
        Err(e) => panic!("invalid test kick: {e}"),
    }
}

/// Effective mass of the tangential motion of the contact point, with the
/// foot's rotation about the axis n × t: 1/m_t = 1/m_b + R²/I_b + 1/m_f + h²/I_f.
pub fn tangential_mass(kick: &Kick3d, foot_axis_inertia: f64) -> f64 {
    let h = kick.face_distance(); // foot centre of mass to the contact point
    let r = kick.ball_radius;
    1.0 / (1.0 / kick.base.ball_mass() + r * r / kick.ball_inertia + 1.0 / kick.base.effective_foot_mass() + h * h / foot_axis_inertia)
}

/// Spin of the rigid gripping (rolling) limit: the contact point's sliding
/// velocity v_t0 is brought to zero, J_t = m_t v_t0, so
/// ω = R m_t |v_t0| / I_b about −n × t (Eq. 61 with r = −R n).
pub fn gripping_limit_spin(kick: &Kick3d, foot_axis_inertia: f64) -> Vec3 {
    let n = kick.initial_normal();
    let slide = kick.initial_sliding_velocity(); // foot over ball
    let j_t = slide * tangential_mass(kick, foot_axis_inertia); // on the ball, along the foot's sliding
    (-n * kick.ball_radius).cross(j_t) / kick.ball_inertia
}

/// Sliding velocity of the ball over the foot at time t for an always-gripping
/// spring–damper (m_t ẍ + c ẋ + k_t x = 0, x(0) = 0, ẋ(0) = v0): ẋ(t)/v0
/// (the contact's gripping spring is elastic, c = 0; the damped forms are
/// the closed form's general case).
pub fn oscillator_velocity_ratio(mass: f64, stiffness: f64, damping: f64, t: f64) -> f64 {
    let w0 = (stiffness / mass).sqrt();
    let zeta = damping / (2.0 * (stiffness * mass).sqrt());
    if zeta < 1.0 {
        let wd = w0 * (1.0 - zeta * zeta).sqrt();
        (-zeta * w0 * t).exp() * ((wd * t).cos() - zeta * w0 / wd * (wd * t).sin())
    } else if zeta == 1.0 {
        (-w0 * t).exp() * (1.0 - w0 * t)
    } else {
        let s = w0 * (zeta * zeta - 1.0).sqrt();
        let (r1, r2) = (-zeta * w0 + s, -zeta * w0 - s);
        (r1 * (r1 * t).exp() - r2 * (r2 * t).exp()) / (r1 - r2)
    }
}

fn norm(v: [f64; 3]) -> f64 {
    (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt()
}

fn solve(kick: &Kick3d) -> Result<Outcome3d, Kick3dError> {
    Accurate3d::default().solve(kick)
}

/// Every 3D check.
pub fn checks() -> Vec<CheckRow> {
    let mut rows = Vec::new();
    let mut push = |name: &str, eq: &str, r: Result<Vec<CheckRow>, Kick3dError>| match r {
        Ok(mut v) => rows.append(&mut v),
        Err(e) => rows.push(CheckRow::failed(name, eq, &e)),
    };
    push("3d central frictionless = 1d", "Eqs. 13-20", central_matches_1d());
    push("3d zero offset with friction: no spin", "Eq. 61", zero_offset_no_spin());
    push("3d angular momentum = integral r x F", "Eq. 61", angular_momentum());
    push("3d energy partition closes", "Eqs. 30-33", energy_closes());
    push("3d mirrored offsets mirror the spin", "Eq. 61", mirror());
    push("3d friction to zero", "Eq. 61", friction_to_zero());
    push("3d friction to infinity", "Eq. 61", friction_to_infinity());
    rows
}

fn central_matches_1d() -> Result<Vec<CheckRow>, Kick3dError> {
    let k = try_kick(Kick3dSpec { friction: Some(0.0), ..Kick3dSpec::default() })?;
    let one = Accurate::default().solve(&k.base)?;
    let three = solve(&k)?;
    let rel = |name: &str, e: f64, a: f64| {
        CheckRow::compare(format!("3d central frictionless = 1d: {name}"), "Eqs. 13-20", e, a, e.abs(), MATCH_1D)
    };
    Ok(vec![
        rel("ball exit speed", one.v_ball_out, three.launch_velocity[0]),
        rel("foot exit speed", one.v_foot_out, three.foot_velocity[0]),
        rel("contact time", one.contact_time, three.contact_time),
        rel("peak force", one.peak_force, three.peak_normal_force),
        rel("max compression", one.max_compression, three.max_compression),
    ])
}

fn zero_offset_no_spin() -> Result<Vec<CheckRow>, Kick3dError> {
    let k = try_kick(Kick3dSpec { friction: Some(0.5), ..Kick3dSpec::default() })?;
    let o = solve(&k)?;
    // scale: the spin of the rolling limit at this foot speed, V/R
    let scale = k.base.foot_speed() / k.ball_radius;
    Ok(vec![CheckRow::compare("3d zero offset, mu = 0.5: |spin| (rad/s)", "Eq. 61", 0.0, norm(o.spin), scale, ROUNDING)])
}

fn angular_momentum() -> Result<Vec<CheckRow>, Kick3dError> {
    // A rising foot too, so all three components are non-zero.
    let k = try_kick(Kick3dSpec { offset: Some(0.05), approach_angle_deg: Some(10.0), ..Kick3dSpec::default() })?;
    let o = solve(&k)?;
    let l = o.ball_angular_momentum(k.ball_inertia);
    let scale = norm(o.angular_impulse);
    Ok((0..3)
        .map(|i| {
            CheckRow::compare(
                format!("3d I_b omega_{} = (integral r x F dt)_{}", ["x", "y", "z"][i], ["x", "y", "z"][i]),
                "Eq. 61",
                o.angular_impulse[i],
                l[i],
                scale,
                ROUNDING,
            )
        })
        .collect())
}

fn energy_closes() -> Result<Vec<CheckRow>, Kick3dError> {
    let k = curve_kick()?;
    let o = solve(&k)?;
    let e = o.energy;
    // Kinetic + elastic energy along the run (every accepted step and event) may only fall.
    let (_, samples) = Accurate3d::default().solve_recorded(&k)?;
    let rise = samples.windows(2).map(|w| w[1].1 - w[0].1).fold(0.0f64, f64::max);
    let monotone = CheckRow::compare(
        "3d passive contact: largest rise of kinetic + elastic energy (J)",
        "Eqs. 30-33",
        0.0,
        rise,
        e.kinetic_initial,
        MATCH_1D,
    );
    // The losses are integrated from their own power densities: closure tests the solver (1e-9, its promise).
    Ok(vec![
        monotone,
        CheckRow::compare(
            "3d energy in = kinetic + spin + foot + elastic + damping + friction (J)",
            "Eqs. 30-33",
            e.kinetic_initial + e.drive_work + e.gravity_work,
            e.ball_translation + e.ball_spin + e.foot + e.elastic_final + e.normal_damping_loss + e.friction_loss,
            e.kinetic_initial,
            MATCH_1D,
        ),
    ])
}

fn mirror() -> Result<Vec<CheckRow>, Kick3dError> {
    let a = solve(&try_kick(Kick3dSpec { offset: Some(0.05), approach_angle_deg: Some(10.0), ..Kick3dSpec::default() })?)?;
    let b = solve(&try_kick(Kick3dSpec { offset: Some(-0.05), approach_angle_deg: Some(10.0), ..Kick3dSpec::default() })?)?;
    // Reflection y → −y: ω is a pseudovector, so ω_x and ω_z flip and ω_y stays.
    let scale = norm(a.spin);
    let expected = [-a.spin[0], a.spin[1], -a.spin[2]];
    Ok((0..3)
        .map(|i| {
            CheckRow::compare(format!("3d mirrored offset: spin_{}", ["x", "y", "z"][i]), "Eq. 61", expected[i], b.spin[i], scale, ROUNDING)
        })
        .collect())
}

fn friction_to_zero() -> Result<Vec<CheckRow>, Kick3dError> {
    let k0 = try_kick(Kick3dSpec { offset: Some(0.05), friction: Some(0.0), ..Kick3dSpec::default() })?;
    let o0 = solve(&k0)?;
    let scale = k0.base.foot_speed() / k0.ball_radius;
    // Small μ: the contact slides throughout, |F_t| = μ F_n, so |ΔL| = R μ ∫F_n dt.
    // The shell ball: its normal force starts from zero, so the slider slips
    // from first touch (`crate::tangential`); under the paper's law the force
    // jumps to c V_n at touch and the relaxed spring first takes a few
    // microseconds to reach μ c V_n, gripping.
    let mu = 0.01;
    let shell = Scenario::baseline().with_law(kick_core::LawKind::Shell, None)?;
    let k = Kick3d::new(shell, &Kick3dSpec { offset: Some(0.05), friction: Some(mu), ..Kick3dSpec::default() })?;
    let o = solve(&k)?;
    let expected = k.ball_radius * mu * o.normal_impulse / k.ball_inertia;
    Ok(vec![
        CheckRow::compare("3d mu = 0: |spin| (rad/s)", "Eq. 61", 0.0, norm(o0.spin), scale, ROUNDING),
        CheckRow::compare(
            "3d shell ball, mu = 0.01 full slip: |spin| = R mu J_n / I_b",
            "Eq. 61",
            expected,
            norm(o.spin),
            expected,
            MATCH_1D,
        ),
        CheckRow::compare("3d shell ball, mu = 0.01: slip time = contact time", "-", o.contact_time, o.slip_time, o.contact_time, ROUNDING),
    ])
}

fn friction_to_infinity() -> Result<Vec<CheckRow>, Kick3dError> {
    // A foot that does not turn keeps the normal fixed; μ = ∞ grips from
    // first touch, so the tangential motion is the undamped oscillator
    // m_t ẍ + k_t x = 0 (the gripping spring is elastic, `crate::tangential`).
    let stiff_foot = 1e12;
    let spec =
        Kick3dSpec { offset: Some(0.05), friction: Some(f64::INFINITY), foot_inertia: Some([stiff_foot; 3]), ..Kick3dSpec::default() };
    let k = try_kick(spec)?;
    let o = solve(&k)?;
    let m_t = tangential_mass(&k, stiff_foot);
    let ratio = oscillator_velocity_ratio(m_t, k.tangential_stiffness, 0.0, o.contact_time);
    let expected = norm(gripping_limit_spin(&k, stiff_foot).to_array()) * (1.0 - ratio);
    // Rigid grip (k_t = inf): a constraint, the limit itself.
    let constrained = try_kick(Kick3dSpec { tangential_stiffness: Some(f64::INFINITY), ..spec })?;
    let o_constrained = solve(&constrained)?;
    let exact = gripping_limit_spin(&constrained, stiff_foot);
    Ok(vec![
        CheckRow::compare(
            "3d mu = inf, rigid grip (k_t = inf): spin_z = gripping limit",
            "Eq. 61",
            exact.z,
            o_constrained.spin[2],
            exact.z.abs(),
            MATCH_1D,
        ),
        CheckRow::compare(
            "3d mu = inf: |spin| = elastic tangential oscillator closed form",
            "Eq. 61",
            expected,
            norm(o.spin),
            expected,
            MATCH_1D,
        ),
        CheckRow::compare("3d mu = inf: slip time", "-", 0.0, o.slip_time, o.contact_time, ROUNDING),
    ])
}
