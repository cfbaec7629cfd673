//! Uniform 3D histories (`Accurate3d::solve_streamed`) against an independent
//! method (fixed-step RK4 on the world-frame right-hand side, switches
//! located, see `support/fine_rk4.rs`), the outcome at separation, the
//! sample counts of both spacings, and conservation across samples.

use crate::support::fine_rk4;
use kick_3d::dynamics::{self, Dynamics};
use kick_3d::{Accurate3d, ContactState, Kick3d, Kick3dSpec, Sample3d, HISTORY_COLUMNS_3D};
use kick_core::{ContactLaw, LawKind, Parameter, Scenario, Spacing};

/// The accurate path's promise on its observables, held by every sample.
const SAMPLE_TOLERANCE: f64 = 1e-9;
/// RK4 steps per contact of the reference: the largest difference is 3e-10
/// of a scale at 2e4 steps and 1e-11 at 1e5 (measured), the reference's own error.
const REFERENCE_STEPS: f64 = 1e5;

fn history(kick: &Kick3d, spacing: Spacing) -> (kick_3d::Outcome3d, Vec<Sample3d>) {
    Accurate3d::default().solve_sampled(kick, spacing, 1_000_000).expect("solves")
}

fn named(name: &str) -> Kick3d {
    kick_3d::models::named_kicks().unwrap().into_iter().find(|(n, _)| *n == name).expect(name).1
}

/// Kicks with grip and slip phases, over an edge, on a rounded border, driven.
fn cases() -> Vec<(String, Kick3d)> {
    let mut cases: Vec<(String, Kick3d)> =
        ["curve 5 cm", "slide 9 cm mu 0.2", "rounded 4 cm rising 20 deg", "driven 800 N 5 cm", "gravity 5 cm"]
            .iter()
            .map(|n| (n.to_string(), named(n)))
            .collect();
    for (name, kick) in kick_3d::models::peak_after_switch().unwrap() {
        cases.push((name.to_string(), kick));
    }
    cases
}

/// The columns of a reference state (world frame, as `Sample3d`).
fn reference_values(d: &Dynamics, t: f64, y: &dynamics::State) -> [f64; 30] {
    let c = d.contact(y);
    let v = |i: usize| [y[i], y[i + 1], y[i + 2]];
    let n = c.normal * c.normal_force;
    let f = c.tangential_force;
    Sample3d {
        time: t,
        ball_position: v(dynamics::BALL_POSITION),
        ball_velocity: v(dynamics::BALL_VELOCITY),
        ball_angular_velocity: v(dynamics::BALL_ANGULAR_VELOCITY),
        foot_position: v(dynamics::FOOT_POSITION),
        foot_velocity: v(dynamics::FOOT_VELOCITY),
        foot_angular_velocity: v(dynamics::FOOT_ANGULAR_VELOCITY),
        compression: c.compression,
        normal_force: [n.x, n.y, n.z],
        tangential_force: [f.x, f.y, f.z],
        contact_state: if c.is_slipping() { ContactState::Slip } else { ContactState::Grip },
        normal_moment: [0.0; 3],
        contact_arm: [0.0; 3],
        slip_velocity: [c.slip_velocity.x, c.slip_velocity.y, c.slip_velocity.z],
    }
    .values()
}

/// Every grid sample within 1e-9 of each quantity's scale (the largest size
/// of that vector over the history) of the independent reference at the
/// same time; the grip/slip state equal away from a switch.
#[test]
fn samples_match_an_independent_fine_rk4_reference() {
    for (name, kick) in cases() {
        let (outcome, samples) = history(&kick, Spacing::Count(61));
        let grid = &samples[..samples.len() - 1];
        let times: Vec<f64> = grid.iter().map(|s| s.time).collect();
        let reference = fine_rk4::states_at(&kick, &times, outcome.contact_time, REFERENCE_STEPS);
        // Columns in groups of one quantity: (first column, width).
        let groups = [(1, 3), (4, 3), (7, 3), (10, 3), (13, 3), (16, 3), (19, 1), (20, 3), (23, 3), (27, 3)];
        let rows: Vec<([f64; 30], [f64; 30])> =
            grid.iter().zip(&reference).map(|(s, (y, d))| (s.values(), reference_values(d, s.time, y))).collect();
        let mut slipped = false;
        for (first, width) in groups {
            let size = |v: &[f64; 30]| v[first..first + width].iter().map(|x| x * x).sum::<f64>().sqrt();
            let scale = rows.iter().map(|(_, r)| size(r)).fold(0.0, f64::max);
            let worst =
                rows.iter().map(|(a, r)| (first..first + width).map(|i| (a[i] - r[i]).abs()).fold(0.0, f64::max)).fold(0.0, f64::max);
            let column = HISTORY_COLUMNS_3D[first].0;
            println!("{name}: {column}: {:.2e} of {scale:.3e}", worst / scale);
            assert!(worst <= SAMPLE_TOLERANCE * scale, "{name}: {column} off by {:.3e} of its scale {scale:.3e}", worst / scale);
        }
        for ((a, r), (s, (y, d))) in rows.iter().zip(grid.iter().zip(&reference)) {
            let c = d.contact(y);
            slipped |= a[26] == ContactState::Slip.code();
            if kick.friction.is_finite() && kick.friction > 0.0 && c.grip_margin.abs() > 1e-6 * kick.friction * c.normal_force {
                assert_eq!(a[26], r[26], "{name}: contact state at t = {}", s.time);
            }
        }
        if kick.friction < 1.0 {
            assert!(slipped, "{name}: a case meant to slip never did");
        }
    }
}

/// The last row is separation: the outcome's end state to the bit; the
/// outcome and its evaluation count are those of a solve without a history.
#[test]
fn separation_row_is_the_outcome_and_the_outcome_is_unchanged() {
    for (name, kick) in cases() {
        let plain = Accurate3d::default().solve(&kick).unwrap();
        for spacing in [Spacing::Count(201), Spacing::Interval(1e-4)] {
            let (outcome, samples) = history(&kick, spacing);
            assert_eq!(outcome, plain, "{name}: the history changed the outcome");
            let last = samples.last().unwrap();
            assert_eq!(last.contact_state, ContactState::Separation, "{name}");
            assert_eq!(last.time, plain.contact_time, "{name}");
            assert_eq!(last.ball_velocity, plain.launch_velocity, "{name}");
            assert_eq!(last.ball_angular_velocity, plain.spin, "{name}");
            assert_eq!(last.foot_velocity, plain.foot_velocity, "{name}");
            assert_eq!(last.foot_angular_velocity, plain.foot_angular_velocity, "{name}");
            assert!(samples[..samples.len() - 1].iter().all(|s| s.contact_state != ContactState::Separation));
            assert!(samples.windows(2).all(|w| w[0].time < w[1].time), "{name}: times not increasing");
        }
    }
}

/// `Count(n)`: n rows, t_k = k t_c/(n − 1) and the separation row;
/// `Interval(Δ)`: every k Δ < t_c and the separation row.
#[test]
fn sample_counts_are_exact() {
    let kick = named("curve 5 cm");
    let t_c = Accurate3d::default().solve(&kick).unwrap().contact_time;
    for n in [2usize, 3, 17, 201, 1000] {
        let (_, samples) = history(&kick, Spacing::Count(n));
        assert_eq!(samples.len(), n, "Count({n})");
        for (k, s) in samples[..n - 1].iter().enumerate() {
            assert_eq!(s.time, k as f64 * (t_c / (n - 1) as f64), "Count({n}) row {k}");
        }
    }
    for dt in [1e-3, 2.5e-4, 1e-5, 3.3e-6] {
        let (_, samples) = history(&kick, Spacing::Interval(dt));
        let grid = (0u64..).take_while(|&k| (k as f64) * dt < t_c).count();
        assert_eq!(samples.len(), grid + 1, "Interval({dt})");
        assert_eq!(samples[grid - 1].time, (grid - 1) as f64 * dt);
    }
    // A spacing that makes no grid names its key.
    let e = Accurate3d::default().solve_sampled(&kick, Spacing::Count(1), 10).unwrap_err().to_string();
    assert!(e.contains("samples"), "{e}");
    let e = Accurate3d::default().solve_sampled(&kick, Spacing::Interval(-1.0), 10).unwrap_err().to_string();
    assert!(e.contains("interval"), "{e}");
}

/// Across every sample: the pair's momentum changes only by the drive and
/// gravity, and its centre of mass moves as a free particle under them.
#[test]
fn momentum_and_centre_of_mass_hold_across_samples() {
    for name in ["driven 800 N 5 cm", "gravity 5 cm", "rounded 4 cm rising 20 deg"] {
        let kick = named(name);
        let (m_f, m_b) = (kick.base.effective_foot_mass(), kick.base.ball_mass());
        let (_, samples) = history(&kick, Spacing::Count(301));
        let first = samples[0];
        let external = kick.drive() + kick.gravity_vector() * (m_f + m_b);
        let external = [external.x, external.y, external.z];
        let p0: Vec<f64> = (0..3).map(|i| m_b * first.ball_velocity[i] + m_f * first.foot_velocity[i]).collect();
        let x0: Vec<f64> = (0..3).map(|i| m_b * first.ball_position[i] + m_f * first.foot_position[i]).collect();
        let scale_p = p0.iter().map(|p| p * p).sum::<f64>().sqrt();
        for s in &samples {
            let t = s.time;
            for i in 0..3 {
                let p = m_b * s.ball_velocity[i] + m_f * s.foot_velocity[i];
                let expected = p0[i] + external[i] * t;
                assert!((p - expected).abs() <= 1e-12 * scale_p, "{name}: momentum {i} at {t}: {p} vs {expected}");
                let x = m_b * s.ball_position[i] + m_f * s.foot_position[i];
                let expected = x0[i] + p0[i] * t + 0.5 * external[i] * t * t;
                assert!((x - expected).abs() <= 1e-12 * scale_p * t.max(1e-3), "{name}: centre of mass {i} at {t}: {x} vs {expected}");
            }
        }
    }
}

/// A central, frictionless kick without damping keeps kinetic plus elastic
/// energy in every sample (the foot does not turn: its energy is ½ m_f |v_f|²).
#[test]
fn undamped_energy_holds_in_every_sample() {
    let base = Scenario::baseline().with(Parameter::Damping, 0.0).unwrap();
    let kick = Kick3d::new(base, &Kick3dSpec { friction: Some(0.0), ..Kick3dSpec::default() }).unwrap();
    let (m_f, m_b) = (kick.base.effective_foot_mass(), kick.base.ball_mass());
    let law = kick.law();
    let (_, samples) = history(&kick, Spacing::Count(101));
    let energy = |s: &Sample3d| {
        let sq = |v: [f64; 3]| v.iter().map(|x| x * x).sum::<f64>();
        0.5 * m_b * sq(s.ball_velocity) + 0.5 * m_f * sq(s.foot_velocity) + law.potential(s.compression.max(0.0))
    };
    let e0 = energy(&samples[0]);
    let mut largest_elastic = 0.0f64;
    for s in &samples {
        largest_elastic = largest_elastic.max(law.potential(s.compression.max(0.0)));
        assert!((energy(s) - e0).abs() <= 1e-11 * e0, "t = {}: {} vs {e0}", s.time, energy(s));
    }
    // Not trivially: a good part of the energy passes through the contact.
    assert!(largest_elastic > 0.1 * e0, "{largest_elastic} of {e0}");
}

/// ∫ τ dt over a history by the trapezoid rule, τ = M + a × F_t (the
/// normal force's moment and friction's, world frame): per component.
fn moment_integral(samples: &[Sample3d]) -> [f64; 3] {
    let torque = |s: &Sample3d| {
        let (a, f, m) = (s.contact_arm, s.tangential_force, s.normal_moment);
        [m[0] + a[1] * f[2] - a[2] * f[1], m[1] + a[2] * f[0] - a[0] * f[2], m[2] + a[0] * f[1] - a[1] * f[0]]
    };
    let mut sum = [0.0; 3];
    for w in samples.windows(2) {
        let (t0, t1) = (torque(&w[0]), torque(&w[1]));
        for i in 0..3 {
            sum[i] += 0.5 * (w[1].time - w[0].time) * (t0[i] + t1[i]);
        }
    }
    sum
}

/// The moment channels integrated over the contact are the ball's change of
/// angular momentum, I_b Δω = ∫ (M + a × F_t) dt (a sphere: no gyroscopic
/// term in the world frame; gravity has no moment about the centre), for
/// the shell ball's patch on a 15 cm cap and on the flat knife-edge face
/// (μ = 0: all of its spin is the patch's moment), and for the point
/// contact (M = 0, a = −R n). The tolerance is the trapezoid rule's error
/// on 64001 samples, far above the solver's own (rtol 1e-13): without
/// friction the moment is smooth and the rule is exact to rounding
/// (measured ≤ 3e-14 of I_b |Δω|: held to 1e-12); with friction F_t has a
/// kink at each grip/slip switch and the rule converges as h² (measured
/// 5e-7, 5e-8, 4e-9 at 4001, 16001, 64001 samples: held to 1e-8).
/// Friction's arm taken as R n (the undeformed surface) instead of the
/// patch's centroid misses by a third on the cap, the patch's moment left
/// out by 0.7%: both fail.
#[test]
fn the_moment_channels_integrate_to_the_change_of_spin() {
    let shell = Scenario::baseline().with_law(LawKind::Shell, None).unwrap();
    let spec = |mu: f64, patch: bool, cap: Option<f64>, yaw: Option<f64>| Kick3dSpec {
        offset: Some(0.05),
        friction: Some(mu),
        patch_contact: patch.then_some(true),
        instep_radius: cap,
        face_yaw_deg: yaw,
        ..Kick3dSpec::default()
    };
    for (name, spec, tolerance) in [
        ("patch on a cap, mu 0.5", spec(0.5, true, Some(0.15), Some(0.0)), 1e-8),
        ("patch on a cap, mu 0", spec(0.0, true, Some(0.15), Some(0.0)), 1e-12),
        ("patch on the knife edge, mu 0.5", spec(0.5, true, None, None), 1e-8),
        ("point contact, mu 0.5", spec(0.5, false, None, None), 1e-8),
    ] {
        let kick = Kick3d::new(shell, &spec).unwrap();
        let (outcome, samples) = history(&kick, Spacing::Count(64001));
        let integral = moment_integral(&samples);
        let (first, last) = (samples[0], samples[samples.len() - 1]);
        let change: Vec<f64> =
            (0..3).map(|i| kick.ball_inertia * (last.ball_angular_velocity[i] - first.ball_angular_velocity[i])).collect();
        let scale = change.iter().map(|x| x * x).sum::<f64>().sqrt();
        assert!(scale > 0.01 * kick.ball_inertia * outcome.speed / kick.ball_radius, "{name}: the kick spins ({scale})");
        for i in 0..3 {
            assert!(
                (integral[i] - change[i]).abs() <= tolerance * scale,
                "{name}: component {i}: ∫τ dt = {} vs I_b Δω = {}",
                integral[i],
                change[i]
            );
        }
    }
}
