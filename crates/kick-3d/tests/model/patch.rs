//! The instep as a surface of its own and the contact as a patch (`kick_3d::patch`).

use kick_3d::checks::MATCH_1D;
use kick_3d::patch::Quadrature;
use kick_3d::{Accurate3d, Kick3d, Kick3dSpec, Outcome3d};
use kick_core::{LawKind, Scenario};
use parry3d_f64::math::Vec3;

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs().max(f64::MIN_POSITIVE)
}

fn shell() -> Scenario {
    Scenario::baseline().with_law(LawKind::Shell, None).unwrap()
}

fn solve(k: &Kick3d) -> Outcome3d {
    Accurate3d::default().solve(k).unwrap()
}

fn norm(v: [f64; 3]) -> f64 {
    (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt()
}

/// The knife edge is one configuration: a flat face given face_yaw =
/// asin(e/R) (in degrees, as a user types it) and no patch is today's kick,
/// foot placed and turned by the new geometry, to 1e-12 (the degrees' round
/// trip). With friction slipping and gripping, under two laws, and with a
/// drive. (Off a horizontal path or with a contact depth the knife edge's
/// box is rolled about the line of motion, the instep's kept level: the
/// same face on the same line, a foot turned otherwise about its normal.)
#[test]
fn the_knife_edge_is_one_configuration() {
    for base in [Scenario::baseline(), shell(), shell().with(kick_core::Parameter::DriveForce, 500.0).unwrap()] {
        for (offset, alpha, mu) in [(0.05, 0.0, 0.5), (0.03, 0.0, 0.2), (0.08, 0.0, f64::INFINITY), (-0.06, 0.0, 0.0)] {
            let spec = Kick3dSpec { offset: Some(offset), approach_angle_deg: Some(alpha), friction: Some(mu), ..Kick3dSpec::default() };
            let today = Kick3d::new(base, &spec).unwrap();
            let yaw = (offset / today.ball_radius).asin().to_degrees();
            let instep = Kick3d::new(base, &Kick3dSpec { face_yaw_deg: Some(yaw), ..spec }).unwrap();
            assert!(today.instep.is_none() && instep.instep.is_some());
            let (a, b) = (solve(&today), solve(&instep));
            let speed = norm(a.launch_velocity);
            for i in 0..3 {
                assert!((a.launch_velocity[i] - b.launch_velocity[i]).abs() <= 1e-12 * speed, "{offset} {alpha} {mu}: {a:?} {b:?}");
                assert!(
                    (a.spin[i] - b.spin[i]).abs() <= 1e-12 * speed / today.ball_radius,
                    "{offset} {alpha} {mu}: spin {:?} {:?}",
                    a.spin,
                    b.spin
                );
            }
            for (x, y) in
                [(a.contact_time, b.contact_time), (a.peak_normal_force, b.peak_normal_force), (a.max_compression, b.max_compression)]
            {
                assert!(rel(y, x) <= 1e-12, "{offset} {alpha} {mu}: {x} vs {y}");
            }
        }
    }
}

/// A face square to the swing (face_yaw = 0) struck 5 cm off its line
/// pushes along the line: the ball touches the face off its centre and
/// leaves along x (no sliding, no friction), where the knife edge sends it
/// 19 degrees off. The foot turns (the force misses its centre of mass).
#[test]
fn a_square_face_pushes_along_the_swing_line() {
    // A foot that hardly turns: the face stays square and nothing slides.
    let spec = Kick3dSpec { offset: Some(0.05), face_yaw_deg: Some(0.0), foot_inertia: Some([1e6; 3]), ..Kick3dSpec::default() };
    let k = Kick3d::new(Scenario::baseline(), &spec).unwrap();
    assert_eq!(k.initial_normal(), Vec3::X);
    assert!((k.touch().y - -0.05).abs() < 1e-15, "{:?}", k.touch());
    let o = solve(&k);
    // Momentum along the normal only, and no torque on the ball: v_y, v_z, spin at rounding.
    assert!(o.launch_velocity[1].abs() < 1e-6 * o.speed && o.launch_velocity[2].abs() < 1e-9 * o.speed, "{:?}", o.launch_velocity);
    assert!(norm(o.spin) < 1e-6, "{:?}", o.spin);
    let free = Kick3d::new(Scenario::baseline(), &Kick3dSpec { foot_inertia: None, ..spec }).unwrap();
    assert!(norm(solve(&free).foot_angular_velocity) > 1.0);
}

/// A central square kick with the patch on a flat face is the 1D kick with
/// the same law (kick_compliant::Accurate), to MATCH_1D: every element's
/// depth rate is δ̇, so the patch carries F_el(δ)(1 + χ δ̇).
#[test]
fn central_square_patch_kick_is_the_1d_kick() {
    let base = shell();
    let spec = Kick3dSpec { friction: Some(0.5), patch_contact: Some(true), ..Kick3dSpec::default() };
    let k = Kick3d::new(base, &spec).unwrap();
    assert!(k.instep.unwrap().patch.is_some());
    let o1 = kick_core::Solver::solve(&kick_compliant::Accurate::default(), &base).unwrap();
    let o3 = solve(&k);
    for (name, three, one) in [
        ("v_ball_out", o3.launch_velocity[0], o1.v_ball_out),
        ("v_foot_out", o3.foot_velocity[0], o1.v_foot_out),
        ("contact_time", o3.contact_time, o1.contact_time),
        ("peak_force", o3.peak_normal_force, o1.peak_force),
        ("max_compression", o3.max_compression, o1.max_compression),
        ("dissipated", o3.energy.normal_damping_loss, o1.energy.dissipated),
    ] {
        println!("{name:<16} {:.2e}", rel(three, one));
        assert!(rel(three, one) <= MATCH_1D, "{name}: {three} vs {one}");
    }
}

fn oblique(mu: f64, radius: Option<f64>) -> Kick3d {
    let spec = Kick3dSpec {
        offset: Some(0.05),
        approach_angle_deg: Some(10.0),
        friction: Some(mu),
        instep_radius: radius,
        face_yaw_deg: radius.map(|_| 0.0),
        patch_contact: Some(true),
        ..Kick3dSpec::default()
    };
    Kick3d::new(shell(), &spec).unwrap()
}

/// No drive, no gravity: the pair's momentum and angular momentum are
/// conserved through a patch kick (element forces act at one point on both
/// bodies), flat face and cap, with and without friction: momentum to
/// rounding, angular momentum to the solver's 1e-9 of the ball's.
#[test]
fn patch_kicks_conserve_momentum_and_angular_momentum() {
    for k in [oblique(0.0, None), oblique(0.5, None), oblique(0.0, Some(0.15)), oblique(0.5, Some(0.15))] {
        let (o, e) = Accurate3d::default().solve_to_state(&k).unwrap();
        let [(p0, l0), (p1, l1)] = kick_3d::checks::pair_momenta(&k, &e);
        let l_scale = k.ball_inertia * norm(o.spin);
        let (dp, dl) = ((p1 - p0).length() / p0.length(), (l1 - l0).length() / l_scale);
        println!("μ {} cap {:?}: spin {:?}, drift p {dp:.1e} L {dl:.1e}", k.friction, k.instep.unwrap().radius, o.spin);
        assert!(dp <= 1e-12 && dl <= 1e-9, "{dp:.2e} {dl:.2e}");
        assert!(o.energy.relative_residual().abs() <= 1e-9, "{:?}", o.energy);
    }
}

/// Doubling the rule's rings moves spin and launch velocity by
/// less than the error `Quadrature` states (1e-9 relative).
#[test]
fn the_patch_quadrature_converges() {
    for mu in [0.0, 0.5] {
        for radius in [None, Some(0.15)] {
            let k = oblique(mu, radius);
            let mut fine = k;
            fine.instep.as_mut().unwrap().patch = Some(Quadrature { rings: 2 * Quadrature::default().rings });
            let (a, b) = (solve(&k), solve(&fine));
            let (ds, dv) = (
                norm([a.spin[0] - b.spin[0], a.spin[1] - b.spin[1], a.spin[2] - b.spin[2]]) / norm(b.spin),
                norm([0, 1, 2].map(|i| a.launch_velocity[i] - b.launch_velocity[i])) / b.speed,
            );
            println!("μ {mu} cap {radius:?}: spin {:?} vs {:?}: {ds:.1e}, velocity {dv:.1e}", a.spin, b.spin);
            assert!(ds <= 1e-9 && dv <= 1e-9, "{ds:.2e} {dv:.2e}");
        }
    }
}

/// At μ = 0 the point contact gives no spin (its force passes through the
/// ball's centre); the patch on a convex instep does, and in the sense
/// friction gives, the sense of Asai et al.'s (2002) frictionless spin. The
/// loss acts on the ball material's approach to the foot: as the ball slides
/// over the cap the foot's surface rises under the trailing side of the
/// patch, which is compressed faster, so the resultant's line passes behind
/// the centre.
#[test]
fn a_frictionless_kick_on_a_convex_instep_spins_as_friction_does() {
    let point = Kick3d::new(shell(), &Kick3dSpec { offset: Some(0.05), friction: Some(0.0), ..Kick3dSpec::default() }).unwrap();
    assert_eq!(norm(solve(&point).spin), 0.0);
    let k = oblique(0.0, Some(0.15));
    let n = k.initial_normal();
    let t = -k.initial_sliding_velocity().normalize();
    let axis = t.cross(n).normalize();
    let spin = Vec3::from(solve(&k).spin);
    println!("μ = 0 cap patch spin {spin:?} (along t̂ × n {:.3} rad/s)", spin.dot(axis));
    assert!(spin.dot(axis) < -1.0, "{spin:?} against {axis:?}");
    // Friction's spin, point contact and patch alike, turns the same way.
    let rubbed = Kick3d::new(shell(), &Kick3dSpec { offset: Some(0.05), approach_angle_deg: Some(10.0), ..Kick3dSpec::default() }).unwrap();
    assert!(Vec3::from(solve(&rubbed).spin).dot(axis) < -1.0);
    assert!(Vec3::from(solve(&oblique(0.5, Some(0.15))).spin).dot(axis) < spin.dot(axis));
}

/// Bad instep input is refused naming the parameter.
#[test]
fn bad_instep_input_names_its_parameter() {
    let named = |spec: Kick3dSpec, base: Scenario| match Kick3d::new(base, &spec) {
        Err(e) => e.to_string(),
        Ok(_) => panic!("accepted {spec:?}"),
    };
    assert!(named(Kick3dSpec { patch_contact: Some(true), ..Kick3dSpec::default() }, Scenario::baseline()).contains("patch_contact"));
    assert!(named(Kick3dSpec { face_yaw_deg: Some(95.0), ..Kick3dSpec::default() }, shell()).contains("face_yaw"));
    assert!(named(Kick3dSpec { instep_radius: Some(0.01), ..Kick3dSpec::default() }, shell()).contains("instep_radius"));
    assert!(named(Kick3dSpec { instep_radius: Some(-1.0), ..Kick3dSpec::default() }, shell()).contains("instep_radius"));
    // A cap too flat for its digits is refused by name (it was solved as a kick that never touched).
    assert!(named(Kick3dSpec { instep_radius: Some(1e300), face_yaw_deg: Some(0.0), ..Kick3dSpec::default() }, shell())
        .contains("instep_radius"));
    assert!(named(Kick3dSpec { instep_radius: Some(1e10), face_yaw_deg: Some(0.0), ..Kick3dSpec::default() }, shell())
        .contains("instep_radius"));
    assert!(named(Kick3dSpec { offset: Some(0.1), face_yaw_deg: Some(-60.0), ..Kick3dSpec::default() }, shell()).contains("face_yaw"));
    // Only the pitch given: the refusal names it, with the value given (not the yaw it derived).
    let pitched = named(Kick3dSpec { offset: Some(0.05), face_pitch_deg: Some(89.0), ..Kick3dSpec::default() }, shell());
    assert!(pitched.contains("face_pitch") && pitched.contains("= 89"), "{pitched}");
    let k = oblique(0.5, Some(0.15));
    assert!(kick_3d::FullState3d::default().solve(&k).unwrap_err().to_string().contains("accurate path only"));
    // A patch that reaches the knife-edge face's edge is refused, naming what keeps it on one surface.
    let edged = Kick3d::new(shell(), &Kick3dSpec { offset: Some(0.105), patch_contact: Some(true), ..Kick3dSpec::default() }).unwrap();
    let refused = Accurate3d::default().solve(&edged).unwrap_err().to_string();
    assert!(["offset", "instep_radius", "patch_contact"].iter().all(|key| refused.contains(key)), "{refused}");
}

/// A kick with an instep records its settings among its parameter values
/// (result files' `/fixed`, histories), and they rebuild the same kick; a
/// kick without one records none of them (its rows are unchanged).
#[test]
fn a_kick_with_an_instep_records_its_settings() {
    use kick_core::parameters::SetParameter;
    let instep_names = ["face_yaw", "face_pitch", "instep_radius", "patch_contact"];
    let plain = Kick3d::new(shell(), &Kick3dSpec::default()).unwrap();
    assert!(plain.parameter_values().iter().all(|(p, _)| !instep_names.contains(&p.name)));
    let k = oblique(0.5, Some(0.15));
    let mut spec = kick_3d::KickSpec::default();
    spec.scenario.law = Some(LawKind::Shell);
    let values = k.parameter_values();
    assert_eq!(values.iter().filter(|(p, _)| instep_names.contains(&p.name)).count(), 4);
    for (def, value) in values {
        spec.set_parameter(def, value).unwrap();
    }
    // As sweeps rebuild rows: every 1D value drawn, the law's unused damping too.
    assert_eq!(spec.build_drawn().unwrap(), k);
}

/// `auto` takes the 1D path only where it is exact: a central square kick
/// with a flat patch (above: the 1D kick to MATCH_1D) or a cap's point
/// contact (two spheres along their centres), not a cap's patch, whose
/// elements off the axis compress faster than δ̇ along the cap's normals.
#[test]
fn auto_takes_the_1d_path_only_where_it_is_exact() {
    let central = |radius: Option<f64>, patch| {
        let spec = Kick3dSpec { instep_radius: radius, patch_contact: Some(patch), face_pitch_deg: Some(0.0), ..Kick3dSpec::default() };
        Kick3d::new(shell(), &spec).unwrap()
    };
    let o1 = kick_core::Solver::solve(&kick_compliant::Accurate::default(), &shell()).unwrap();
    for (k, one_d) in [(central(None, true), true), (central(Some(0.15), false), true), (central(Some(0.15), true), false)] {
        assert_eq!(k.is_one_dimensional(), one_d);
        let o = solve(&k);
        let r = rel(o.launch_velocity[0], o1.v_ball_out);
        println!(
            "cap {:?} patch {}: v {} against 1D {}: {r:.1e}",
            k.instep.unwrap().radius,
            k.instep.unwrap().patch.is_some(),
            o.launch_velocity[0],
            o1.v_ball_out
        );
        assert_eq!(r <= MATCH_1D, one_d);
    }
}

/// The accurate path's promise holds on patch kicks: every observable it
/// promises (launch velocity, spin, contact time, peak forces and their
/// times, δ_max) within 1e-9 of the same path tightened to rtol 1e-15, on
/// kicks where grip and slip switch (μ = 0.5, ∞) and without friction, flat
/// face and cap; and on the hardest kicks of a 574-kick patch box (offset
/// 0–8 cm, μ 0–∞, rigid grip or spring, flat or r_i 0.12–0.3 m, approach
/// 0 and 15°, foot 1–8 kg), a 1 kg foot 2 cm off centre on a tight cap,
/// whose peak tangential force's time is off by 5.1e-10 and 2.9e-10 (the
/// box's worst observable at the default tolerance: a flat maximum's time
/// is its least well-conditioned). (Not independent: the full-state path
/// has no patch; the patch's own error is the quadrature's, above.)
#[test]
fn patch_kicks_meet_the_accurate_paths_tolerance() {
    let tight = Accurate3d::new(1e-15).unwrap();
    let light = |mu: f64, radius: f64| {
        let kick3d = Kick3dSpec {
            offset: Some(0.02),
            friction: Some(mu),
            instep_radius: Some(radius),
            face_yaw_deg: Some(0.0),
            patch_contact: Some(true),
            ..Kick3dSpec::default()
        };
        let scenario = kick_core::ScenarioSpec { law: Some(LawKind::Shell), foot_mass: Some(1.0), ..Default::default() };
        kick_3d::KickSpec { scenario, kick3d }.build().unwrap()
    };
    let mut kicks: Vec<Kick3d> =
        [0.0, 0.5, f64::INFINITY].into_iter().flat_map(|mu| [None, Some(0.15)].map(|radius| oblique(mu, radius))).collect();
    kicks.extend([light(f64::INFINITY, 0.12), light(1.0, 0.3)]);
    for k in &kicks {
        let (o, reference) = (solve(k), tight.solve(k).unwrap());
        let e = kick_3d::precision::Errors3d::of(k, &o, &reference);
        println!(
            "μ {} instep {:?}: max error {:.1e} ({e:?}), slip {:.2e} of {:.2e} s",
            k.friction,
            k.instep.map(|i| i.radius),
            e.max(),
            o.slip_time,
            o.contact_time
        );
        assert!(e.max() <= 1e-9, "{e:?}");
    }
}

/// A face pitched up by θ with no friction pushes along its normal: a ball
/// at rest leaves at elevation θ (a foot too heavy to turn keeps the face's
/// normal), below its centre, so lofted; yaw likewise sends it at −ψ in azimuth.
#[test]
fn a_pitched_or_yawed_face_pushes_along_its_normal() {
    for (yaw, pitch) in [(0.0, 15.0), (20.0, 0.0), (10.0, -8.0)] {
        let spec = Kick3dSpec {
            face_yaw_deg: Some(yaw),
            face_pitch_deg: Some(pitch),
            friction: Some(0.0),
            foot_inertia: Some([1e9; 3]),
            ..Kick3dSpec::default()
        };
        let k = Kick3d::new(shell(), &spec).unwrap();
        let n = k.initial_normal();
        let (p, y) = (f64::to_radians(pitch), f64::to_radians(yaw));
        assert!((n - Vec3::new(p.cos() * y.cos(), -p.cos() * y.sin(), p.sin())).length() < 1e-15, "{n:?}");
        let o = solve(&k);
        assert!(
            (o.launch_angle - pitch).abs() < 1e-6 && (o.launch_azimuth + yaw).abs() < 1e-6,
            "{yaw} {pitch}: {} {}",
            o.launch_angle,
            o.launch_azimuth
        );
    }
}

/// A cap flattened toward a plane is the flat face: the cap's ring rule and
/// the flat face's closed form (two derivations of the same patch) meet as
/// 1/r_i: the gap is first order in the curvature (measured 0.24 m / r_i
/// in spin, 0.022 m / r_i in velocity, relative), shrinking a hundredfold
/// from r_i = 10 to 1000 m. (A cap's geometry tilts the normal by about
/// the sliding distance over r_i, so no smaller order is expected.)
#[test]
fn a_flatter_cap_tends_to_the_flat_face() {
    let kick = |radius: Option<f64>| {
        let spec = Kick3dSpec {
            offset: Some(0.05),
            approach_angle_deg: Some(10.0),
            friction: Some(0.5),
            face_yaw_deg: Some(0.0),
            face_pitch_deg: Some(0.0),
            instep_radius: radius,
            patch_contact: Some(true),
            ..Kick3dSpec::default()
        };
        solve(&Kick3d::new(shell(), &spec).unwrap())
    };
    let flat = kick(None);
    let gap = |r: f64| {
        let o = kick(Some(r));
        let ds = norm([0, 1, 2].map(|i| o.spin[i] - flat.spin[i])) / norm(flat.spin);
        let dv = norm([0, 1, 2].map(|i| o.launch_velocity[i] - flat.launch_velocity[i])) / flat.speed;
        println!("r_i {r}: spin {ds:.2e}, velocity {dv:.2e}");
        ds.max(dv)
    };
    let (near, far) = (gap(10.0), gap(1000.0));
    assert!(near <= 0.3 / 10.0 && far <= 0.3 / 1000.0, "{near:.2e} {far:.2e}");
    assert!((near / far - 100.0).abs() < 10.0, "first order in 1/r_i: {near:.2e} {far:.2e}");
}

/// Only the loss breaks the patch's symmetry: with the shell's loss off
/// (χ = 0) the elastic resultant is F_el(δ) n along the line of centres, so
/// a frictionless kick on the cap leaves the ball without spin (to the
/// solver's 1e-9 of the lossy kick's spin).
#[test]
fn without_loss_the_patch_does_not_turn_the_ball() {
    let lossy = solve(&oblique(0.0, Some(0.15)));
    let ball =
        kick_core::ShellBall { shell_damping: 0.0, ..kick_core::ShellBall::default_with_radius(kick_core::DEFAULT_BALL_RADIUS).unwrap() };
    let spec = Kick3dSpec {
        offset: Some(0.05),
        approach_angle_deg: Some(10.0),
        friction: Some(0.0),
        instep_radius: Some(0.15),
        face_yaw_deg: Some(0.0),
        patch_contact: Some(true),
        ..Kick3dSpec::default()
    };
    let elastic = solve(&Kick3d::new(Scenario::baseline().with_shell(ball), &spec).unwrap());
    println!("spin lossy {:?}, elastic {:?}", lossy.spin, elastic.spin);
    assert!(norm(lossy.spin) > 1.0);
    assert!(norm(elastic.spin) <= 1e-9 * norm(lossy.spin), "{:?}", elastic.spin);
}
