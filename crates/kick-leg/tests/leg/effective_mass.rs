//! Eq. 11 against cases with known answers, and the properties any effective
//! mass must have. Tolerances: the computations are a 3×3 to 8×8 Cholesky
//! solve on O(1) numbers, so agreement with closed forms is to rounding
//! (1e-12 relative leaves three orders of margin over ~1e-15 per operation).

use kick_core::Scenario;
use kick_leg::{
    effective_mass_grid, exit_speed_curve, AnkleJoint, Body, Chain, HipSupport, Impact, Joint, Leg, LegError, Motion, Pose, Variant,
};
use nalgebra::{Matrix3, Vector3};

const ROUNDING: f64 = 1e-12;

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

fn rod(mass: f64, length: f64) -> Body {
    // Uniform thin rod along +x from the origin: I_cm = m L²/12 about y and z.
    let i = mass * length * length / 12.0;
    Body { mass, centre: Vector3::new(length / 2.0, 0.0, 0.0), inertia: Matrix3::from_diagonal(&Vector3::new(1e-3 * i, i, i)) }
}

#[test]
fn single_segment_pinned_at_one_end() {
    let (m, l) = (4.0, 0.8);
    let chain = Chain {
        bodies: vec![rod(m, l)],
        joints: vec![Joint { motion: Motion::Revolute { axis: Vector3::z(), point: Vector3::zeros() }, first_body: 0 }],
    };
    let pivot_inertia = m * l * l / 3.0; // I_cm + m (L/2)²
    for r in [0.2, 0.5, 0.8] {
        let x = Vector3::new(r, 0.0, 0.0);
        // Perpendicular impulse: m_eff = I_pivot / r².
        let m_eff = chain.effective_mass(&x, &Vector3::y()).unwrap();
        assert!(rel(m_eff, pivot_inertia / (r * r)) < ROUNDING, "{m_eff}");
        // At angle φ to the perpendicular only the normal component moves the point.
        let phi = 0.3f64;
        let n = Vector3::new(phi.sin(), phi.cos(), 0.0);
        let m_eff = chain.effective_mass(&x, &n).unwrap();
        assert!(rel(m_eff, pivot_inertia / (r * r * phi.cos().powi(2))) < ROUNDING);
    }
    // Along the segment the point cannot move: unbounded, reported as an error.
    let err = chain.effective_mass(&Vector3::new(0.5, 0.0, 0.0), &Vector3::x()).unwrap_err();
    assert!(matches!(err, LegError::Degenerate(_)), "{err}");
}

#[test]
fn free_rigid_body_planar_and_spatial() {
    let body = Body {
        mass: 2.5,
        centre: Vector3::new(0.1, -0.2, 0.05),
        inertia: Matrix3::new(0.05, 0.004, -0.002, 0.004, 0.03, 0.001, -0.002, 0.001, 0.04),
    };
    let x = Vector3::new(0.3, 0.1, 0.0);
    let r = x - body.centre;
    let prismatic = |d: Vector3<f64>| Joint { motion: Motion::Prismatic { direction: d }, first_body: 0 };
    let revolute = |a: Vector3<f64>| Joint { motion: Motion::Revolute { axis: a, point: Vector3::zeros() }, first_body: 0 };
    // Spatial: 1/m_eff = 1/m + (r × n)ᵀ I⁻¹ (r × n).
    let spatial = Chain {
        bodies: vec![body],
        joints: vec![
            prismatic(Vector3::x()),
            prismatic(Vector3::y()),
            prismatic(Vector3::z()),
            revolute(Vector3::x()),
            revolute(Vector3::y()),
            revolute(Vector3::z()),
        ],
    };
    for n in [Vector3::x(), Vector3::new(0.3, -0.8, 0.52).normalize()] {
        let rxn = r.cross(&n);
        let expected = 1.0 / (1.0 / body.mass + rxn.dot(&(body.inertia.try_inverse().unwrap() * rxn)));
        let m_eff = spatial.effective_mass(&x, &n).unwrap();
        assert!(rel(m_eff, expected) < ROUNDING, "{m_eff} vs {expected}");
        assert!(m_eff <= body.mass);
    }
    // Planar (x, y, rotation about z through a point away from the body: the
    // pivot's position must not matter for a free body): 1/m + r⊥²/I_zz.
    let mut planar = Chain { bodies: vec![body], joints: vec![prismatic(Vector3::x()), prismatic(Vector3::y())] };
    planar.joints.push(Joint { motion: Motion::Revolute { axis: Vector3::z(), point: Vector3::new(-1.0, 2.0, 0.0) }, first_body: 0 });
    let n = Vector3::new(0.6, 0.8, 0.0);
    let r_perp = r.x * n.y - r.y * n.x;
    let expected = 1.0 / (1.0 / body.mass + r_perp * r_perp / body.inertia[(2, 2)]);
    assert!(rel(planar.effective_mass(&x, &n).unwrap(), expected) < ROUNDING);
}

#[test]
fn rigid_body_on_a_ball_joint() {
    // Spherical joint at the origin: 1/m_eff = (r × n)ᵀ I_O⁻¹ (r × n), with
    // I_O = I_cm + m (|c|² 1 − c cᵀ) (parallel axis theorem).
    let body = Body {
        mass: 3.0,
        centre: Vector3::new(0.2, -0.3, 0.05),
        inertia: Matrix3::new(0.06, 0.002, 0.0, 0.002, 0.02, -0.003, 0.0, -0.003, 0.05),
    };
    let revolute = |a: Vector3<f64>| Joint { motion: Motion::Revolute { axis: a, point: Vector3::zeros() }, first_body: 0 };
    let chain = Chain { bodies: vec![body], joints: vec![revolute(Vector3::x()), revolute(Vector3::y()), revolute(Vector3::z())] };
    let c = body.centre;
    let i_o = body.inertia + body.mass * (Matrix3::identity() * c.dot(&c) - c * c.transpose());
    let x = Vector3::new(0.35, -0.5, 0.02);
    let n = Vector3::new(1.0, 0.2, -0.1).normalize();
    let rxn = x.cross(&n);
    let expected = 1.0 / rxn.dot(&(i_o.try_inverse().unwrap() * rxn));
    assert!(rel(chain.effective_mass(&x, &n).unwrap(), expected) < ROUNDING);
}

/// The combined body of a chain's bodies: mass, centre, inertia about it.
fn combined(bodies: &[Body]) -> (f64, Vector3<f64>, Matrix3<f64>) {
    let mass: f64 = bodies.iter().map(|b| b.mass).sum();
    let centre = bodies.iter().map(|b| b.centre * b.mass).sum::<Vector3<f64>>() / mass;
    let mut inertia = Matrix3::zeros();
    for b in bodies {
        let d = b.centre - centre;
        // Parallel axis theorem for a tensor.
        inertia += b.inertia + b.mass * (Matrix3::identity() * d.dot(&d) - d * d.transpose());
    }
    (mass, centre, inertia)
}

#[test]
fn locked_leg_is_one_rigid_body() {
    let impact = Impact::default();
    for (knee, ankle) in [(0.0, 0.0), (30.0, 60.0), (90.0, 20.0)] {
        let pose = Pose { knee_flexion: knee, plantarflexion: ankle, ..Pose::default() };
        // Pinned hip: m_eff = I_hip / ((x − hip) × n)_z².
        let leg = Leg::de_leva(75.0, 1.80).unwrap();
        let (chain, x) = leg.chain(&pose, &impact, true, false).unwrap();
        let (mass, centre, inertia) = combined(&chain.bodies);
        let i_hip = inertia[(2, 2)] + mass * (centre.x * centre.x + centre.y * centre.y);
        let arm = x.x * impact.direction.y - x.y * impact.direction.x;
        let m_eff = chain.effective_mass(&x, &impact.direction).unwrap();
        assert!(rel(m_eff, i_hip / (arm * arm)) < ROUNDING, "knee {knee}: {m_eff}");
        // The same through the public entry with a braced knee and locked ankle.
        let braced = Leg { knee_locked: true, ..leg };
        let through = braced.effective_mass(&pose, &impact, AnkleJoint::Locked).unwrap().effective_mass;
        assert!(rel(through, i_hip / (arm * arm)) < ROUNDING);
        // Free hip: 1/m_eff = 1/M + r⊥²/I_cm.
        let free = Leg { hip: HipSupport::Free, ..leg };
        let (chain, x) = free.chain(&pose, &impact, true, false).unwrap();
        let r = x - centre;
        let r_perp = r.x * impact.direction.y - r.y * impact.direction.x;
        let expected = 1.0 / (1.0 / mass + r_perp * r_perp / inertia[(2, 2)]);
        assert!(rel(chain.effective_mass(&x, &impact.direction).unwrap(), expected) < ROUNDING);
    }
}

fn poses() -> Vec<Pose> {
    let mut poses = Vec::new();
    for hip in [-20.0, 10.0, 45.0] {
        for knee in [0.0, 25.0, 60.0, 110.0] {
            for ankle in [-10.0, 30.0, 70.0] {
                poses.push(Pose { hip_flexion: hip, knee_flexion: knee, plantarflexion: ankle, ..Pose::default() });
            }
        }
    }
    poses
}

#[test]
fn mass_matrix_is_symmetric_positive_definite_and_m_eff_positive() {
    for variant in [Variant::Planar, Variant::Spatial] {
        for hip in [HipSupport::Pinned, HipSupport::Free] {
            let leg = Leg { variant, hip, ..Leg::de_leva(70.0, 1.75).unwrap() };
            for pose in poses() {
                let (chain, x) = leg.chain(&pose, &Impact::default(), false, true).unwrap();
                let m = chain.mass_matrix();
                let asym = (&m - m.transpose()).amax();
                assert!(asym <= ROUNDING * m.amax(), "asymmetry {asym}");
                assert!(m.clone().cholesky().is_some(), "{variant:?} {hip:?} {pose:?}");
                let m_eff = chain.effective_mass(&x, &Vector3::x()).unwrap();
                assert!(m_eff > 0.0 && m_eff.is_finite());
            }
        }
    }
}

#[test]
fn free_floating_leg_never_exceeds_its_mass_and_every_freedom_lowers_m_eff() {
    let base = Leg::de_leva(80.0, 1.85).unwrap();
    let total = base.segments.total_mass();
    let directions = [Vector3::x(), Vector3::new(0.8, 0.6, 0.0), Vector3::new(0.6, -0.8, 0.0)];
    for variant in [Variant::Planar, Variant::Spatial] {
        let pinned = Leg { variant, ..base };
        let free = Leg { variant, hip: HipSupport::Free, ..base };
        for pose in poses() {
            for n in directions {
                let impact = Impact { direction: n, ..Impact::default() };
                let m = |leg: &Leg, ankle| leg.effective_mass(&pose, &impact, ankle).unwrap().effective_mass;
                let floating_locked = m(&free, AnkleJoint::Locked);
                let floating_free = m(&free, AnkleJoint::Free);
                // Momentum: the whole leg's centre of mass takes the impulse at least.
                assert!(floating_locked <= total * (1.0 + ROUNDING), "{floating_locked} > {total}");
                // Rayleigh: releasing a joint or the hip cannot raise m_eff.
                assert!(floating_free <= floating_locked * (1.0 + ROUNDING));
                assert!(m(&pinned, AnkleJoint::Free) <= m(&pinned, AnkleJoint::Locked) * (1.0 + ROUNDING));
                assert!(floating_locked <= m(&pinned, AnkleJoint::Locked) * (1.0 + ROUNDING));
            }
        }
    }
}

#[test]
fn spatial_leg_in_the_sagittal_plane_equals_the_planar_leg() {
    // The segments' principal axes include the mediolateral axis, so an
    // in-plane impulse at an in-plane point excites no out-of-plane motion.
    let planar = Leg::de_leva(72.0, 1.78).unwrap();
    let spatial = Leg { variant: Variant::Spatial, ..planar };
    for hip in [HipSupport::Pinned, HipSupport::Free] {
        for pose in poses() {
            for ankle in [AnkleJoint::Locked, AnkleJoint::Free] {
                let a = Leg { hip, ..planar }.effective_mass(&pose, &Impact::default(), ankle).unwrap();
                let b = Leg { hip, ..spatial }.effective_mass(&pose, &Impact::default(), ankle).unwrap();
                assert!(rel(b.effective_mass, a.effective_mass) < 1e-10, "{a:?} {b:?}");
            }
        }
    }
    // Out of the plane the spatial leg has more freedom: an off-axis contact
    // can only lower m_eff further (it also spins the foot, Eq. 61).
    let off = Impact { lateral_offset: 0.04, ..Impact::default() };
    let pose = Pose::default();
    let centred = spatial.effective_mass(&pose, &Impact::default(), AnkleJoint::Locked).unwrap().effective_mass;
    let offset = spatial.effective_mass(&pose, &off, AnkleJoint::Locked).unwrap().effective_mass;
    assert!(offset < centred);
}

#[test]
fn elastic_ankle_spans_free_to_locked_monotonically() {
    let leg = Leg::de_leva(75.0, 1.80).unwrap();
    let pose = Pose::default();
    let impact = Impact::default();
    let at = |k: f64| leg.effective_mass(&pose, &impact, AnkleJoint::Elastic { stiffness: k, contact_time: 5e-3 }).unwrap();
    let limits = at(0.0);
    assert_eq!(limits.effective_mass, limits.free_ankle);
    // κ = 1e12 N m/rad against an inertial stiffness I_a (π/t_c)² of order 1e3:
    // 1 − w ≈ 1e-9, so m_eff is within ~1e-9 relative of locked.
    let stiff = at(1e12);
    assert!(rel(stiff.effective_mass, stiff.locked_ankle) < 1e-8);
    // w = ½ exactly at κ = I_a (π/t_c)².
    let crossover = limits.ankle_inertia * (std::f64::consts::PI / 5e-3).powi(2);
    assert!((at(crossover).locked_share - 0.5).abs() < ROUNDING);
    let mut last = 0.0;
    for k in [0.0, 10.0, 100.0, 1e3, 1e4, 1e5] {
        let m = at(k).effective_mass;
        assert!(m >= last && m <= limits.locked_ankle * (1.0 + ROUNDING));
        last = m;
    }
}

#[test]
fn segment_table_scales_with_body_mass_and_height() {
    let a = Leg::de_leva(73.0, 1.741).unwrap().segments;
    let b = Leg::de_leva(146.0, 1.741 * 1.1).unwrap().segments;
    // Leg mass fraction 0.1416 + 0.0433 + 0.0137 (de Leva 1996, Table 4).
    assert!(rel(a.total_mass(), 0.1986 * 73.0) < ROUNDING);
    assert!(rel(b.thigh.mass, 2.0 * a.thigh.mass) < ROUNDING);
    assert!(rel(b.shank.length, 1.1 * a.shank.length) < ROUNDING);
    // I = m (ρ L)²: doubling mass and scaling length by 1.1 multiplies by 2.42.
    assert!(rel(b.foot.inertia_flexion, 2.42 * a.foot.inertia_flexion) < ROUNDING);
}

#[test]
fn bad_input_is_a_typed_error_naming_the_input() {
    let name = |e: LegError| match e {
        LegError::InvalidInput { name, .. } => name,
        other => panic!("expected InvalidInput, got {other}"),
    };
    assert_eq!(name(Leg::de_leva(75.0, 175.0).unwrap_err()), "height");
    assert_eq!(name(Leg::de_leva(f64::NAN, 1.8).unwrap_err()), "body_mass");
    let leg = Leg::de_leva(75.0, 1.8).unwrap();
    let knee_nan = Pose { knee_flexion: f64::NAN, ..Pose::default() };
    assert_eq!(name(leg.effective_mass(&knee_nan, &Impact::default(), AnkleJoint::Free).unwrap_err()), "knee");
    let zero = Impact { direction: Vector3::zeros(), ..Impact::default() };
    assert_eq!(name(leg.effective_mass(&Pose::default(), &zero, AnkleJoint::Free).unwrap_err()), "direction");
    let sideways = Impact { direction: Vector3::z(), ..Impact::default() };
    assert_eq!(name(leg.effective_mass(&Pose::default(), &sideways, AnkleJoint::Free).unwrap_err()), "direction_z");
    let negative = AnkleJoint::Elastic { stiffness: -1.0, contact_time: 5e-3 };
    assert_eq!(name(leg.effective_mass(&Pose::default(), &Impact::default(), negative).unwrap_err()), "ankle_stiffness");
}

#[test]
fn exit_speed_has_diminishing_returns_in_effective_mass() {
    // Section 14.1: v_b⁺ rises with m_f but ever more slowly, and stays below
    // the elastic bound 2 m_f/(m_f + m_b) v_f⁻ (Eq. 38 with e = 1).
    let base = Scenario::baseline();
    let masses = [0.5, 1.0, 2.0, 4.0, 8.0, 16.0];
    let curve = exit_speed_curve(&masses, &base).unwrap();
    for w in curve.windows(3) {
        let (s1, s2) = ((w[1].1 - w[0].1) / (w[1].0 - w[0].0), (w[2].1 - w[1].1) / (w[2].0 - w[1].0));
        assert!(s1 > 0.0 && s2 > 0.0 && s2 < s1, "{w:?}");
    }
    for (m, v) in curve {
        assert!(v < 2.0 * m / (m + base.ball_mass()) * base.foot_speed());
    }
}

#[test]
fn grid_is_knee_major_and_matches_single_calls() {
    let leg = Leg::de_leva(75.0, 1.80).unwrap();
    let (knees, ankles) = ([0.0, 40.0, 80.0], [20.0, 60.0]);
    let grid = effective_mass_grid(&leg, &Pose::default(), &Impact::default(), AnkleJoint::Locked, &knees, &ankles).unwrap();
    assert_eq!(grid.len(), 6);
    for (i, &(knee, ankle, m)) in grid.iter().enumerate() {
        assert_eq!((knee, ankle), (knees[i / 2], ankles[i % 2]));
        let pose = Pose { knee_flexion: knee, plantarflexion: ankle, ..Pose::default() };
        assert_eq!(m, leg.effective_mass(&pose, &Impact::default(), AnkleJoint::Locked).unwrap().effective_mass);
    }
}
