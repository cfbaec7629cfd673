//! The foot behind the contact in 3D: the leg's 6×6 apparent inertia
//! (`leg`) and the boot in series (`boot_stiffness`).
//!
//! - The accurate path against the full-state reference tightened
//!   (`kick_3d::precision::reference`: another state, frame, geometry code,
//!   integrator and event machinery, carrying the leg's mobility and the boot
//!   too) within 1e-9 on every observable it promises, peaks and their times
//!   included, over offsets, approach angles, friction, laws and drive.
//! - With the patch (which the full state does not carry): against the
//!   accurate path tightened to rtol 1e-15, flat face and cap.
//! - The leg's dynamics written as the box's own mobility reproduce the box
//!   kick (in one plane Euler's term vanishes), and a central square kick
//!   with a boot is the 1D booted kick: two independent checks of the new
//!   code paths; the energy budget closes.

use kick_3d::precision::{self, Errors3d};
use kick_3d::{Accurate3d, Kick3d, Kick3dSpec, KickSpec, Solver3d};
use kick_core::parameters::{SetParameter, Value};
use kick_core::{Scenario, ScenarioSpec, Solver};

const TOLERANCE: f64 = 1e-9;

fn kick(scenario: &str, kick3d: Kick3dSpec) -> Kick3d {
    let spec: ScenarioSpec = toml::from_str(scenario).unwrap();
    KickSpec { scenario: spec, kick3d }.build().unwrap_or_else(|e| panic!("{scenario}: {e}"))
}

fn check(name: &str, solved: &kick_3d::Outcome3d, reference: &kick_3d::Outcome3d, kick: &Kick3d) -> Errors3d {
    let errors = Errors3d::of(kick, solved, reference);
    for (quantity, error) in Errors3d::NAMES.iter().zip(errors.values()) {
        assert!(error <= TOLERANCE, "{name}: {quantity} off by {error:.3e} relative\n{solved:?}\n{reference:?}");
    }
    let residual = solved.energy.relative_residual().abs();
    assert!(residual <= 1e-10, "{name}: energy residual {residual:.3e}");
    errors
}

fn worst(label: &str, errors: &[Errors3d]) -> f64 {
    let max = errors.iter().map(Errors3d::max).fold(0.0, f64::max);
    println!("{label}: worst {max:.2e} over {} kicks", errors.len());
    max
}

/// The point contact on the knife-edge box: the leg, the boot and both,
/// against the tightened full state.
#[test]
fn the_leg_and_the_boot_match_the_full_state_reference() {
    let mut errors = Vec::new();
    let feet =
        ["leg = true\nboot_stiffness = inf\n", "boot_stiffness = 4.0e4\n", "leg = true\n", "leg = true\nknee = 50.0\nankle = 80.0\n"];
    let laws = ["", "law = \"shell\"\n", "law = \"hunt-crossley\"\nrestitution = 0.6\n"];
    for foot in feet {
        for law in laws {
            for (offset, approach, friction) in [(0.0, 0.0, 0.5), (0.03, 0.0, 0.5), (0.06, 10.0, f64::INFINITY), (0.05, -5.0, 0.2)] {
                let k = kick(
                    &format!("{foot}{law}"),
                    Kick3dSpec { offset: Some(offset), approach_angle_deg: Some(approach), friction: Some(friction), ..Default::default() },
                );
                let name = format!("{foot:?} {law:?} e {offset} α {approach} μ {friction}");
                let solved = Accurate3d::default().solve(&k).unwrap_or_else(|e| panic!("{name}: {e}"));
                let reference = precision::reference().solve(&k).unwrap_or_else(|e| panic!("{name}: reference: {e}"));
                errors.push(check(&name, &solved, &reference, &k));
            }
        }
    }
    // A drive on the leg's foot.
    let k = kick("leg = true\nlaw = \"shell\"\ndrive_force = 300.0\n", Kick3dSpec { offset: Some(0.04), ..Default::default() });
    let (solved, reference) = (Accurate3d::default().solve(&k).unwrap(), precision::reference().solve(&k).unwrap());
    errors.push(check("drive", &solved, &reference, &k));
    worst("leg and boot, accurate vs full state", &errors);
}

/// The patch (flat face and cap) with the leg and the boot: within 1e-9 of
/// the accurate path tightened to rtol 1e-15.
#[test]
fn the_patch_with_the_leg_and_the_boot_matches_the_tightened_path() {
    let tight = Accurate3d::new(1e-15).unwrap();
    let mut errors = Vec::new();
    for foot in ["leg = true\n", "boot_stiffness = 6.0e4\nboot_damping = 20.0\n"] {
        for cap in [None, Some(0.15)] {
            for (offset, friction) in [(0.0, 0.5), (0.05, 0.5), (0.08, 1.0)] {
                let k = kick(
                    &format!("law = \"shell\"\n{foot}"),
                    Kick3dSpec {
                        offset: Some(offset),
                        friction: Some(friction),
                        patch_contact: Some(true),
                        instep_radius: cap,
                        face_yaw_deg: cap.map(|_| 0.0),
                        ..Default::default()
                    },
                );
                let name = format!("{foot:?} cap {cap:?} e {offset} μ {friction}");
                let solved = Accurate3d::default().solve(&k).unwrap_or_else(|e| panic!("{name}: {e}"));
                let reference = tight.solve(&k).unwrap_or_else(|e| panic!("{name}: tight: {e}"));
                errors.push(check(&name, &solved, &reference, &k));
            }
        }
    }
    worst("patch with leg and boot, accurate vs rtol 1e-15", &errors);
}

/// The leg's code path given the box's own mobility, diag(I⁻¹, 1/m) at
/// its centre, is the box kick wherever Euler's term Ω × IΩ vanishes: a kick
/// in one plane turns the foot about one principal axis.
#[test]
fn the_leg_path_with_the_box_mobility_is_the_box() {
    for (offset, friction) in [(0.04, 0.5), (0.07, f64::INFINITY)] {
        let spec = Kick3dSpec { offset: Some(offset), friction: Some(friction), ..Default::default() };
        let mut boxed = Kick3d::new(Scenario::baseline(), &spec).unwrap();
        let solved_box = Accurate3d::default().solve(&boxed).unwrap();
        let [ix, iy, iz] = boxed.foot_inertia;
        let m = boxed.base.effective_foot_mass();
        // The box's principal axes are its body axes, turned by the knife edge's yaw.
        let q = boxed.initial_state().foot_orientation;
        let world = |i: f64, axis: parry3d_f64::math::Vec3| (q * axis, 1.0 / i);
        let mut mobility = [[0.0; 6]; 6];
        for (axis, inverse) in
            [world(ix, parry3d_f64::math::Vec3::X), world(iy, parry3d_f64::math::Vec3::Y), world(iz, parry3d_f64::math::Vec3::Z)]
        {
            let a = [axis.x, axis.y, axis.z];
            for r in 0..3 {
                for c in 0..3 {
                    mobility[r][c] += inverse * a[r] * a[c];
                }
            }
        }
        for i in 3..6 {
            mobility[i][i] = 1.0 / m;
        }
        let mut inertia = [[0.0; 6]; 6];
        let inverse = nalgebra::Matrix6::from_fn(|r, c| mobility[r][c]).try_inverse().unwrap();
        for r in 0..6 {
            for c in 0..6 {
                inertia[r][c] = inverse[(r, c)];
            }
        }
        boxed.leg = Some(kick_3d::model::LegDynamics { mobility, inertia, initial_velocity: boxed.initial_state().foot_velocity });
        let solved_leg = Accurate3d::default().solve(&boxed).unwrap();
        let errors = Errors3d::of(&boxed, &solved_leg, &solved_box);
        assert!(errors.max() < 1e-10, "e {offset}: {errors:?}");
        let foot = (solved_leg.energy.foot - solved_box.energy.foot).abs() / solved_box.energy.kinetic_initial;
        assert!(foot < 1e-10, "{foot:e}");
    }
}

/// A central square kick with a boot is the 1D booted kick (auto takes the
/// 1D path; the accurate path agrees with it); with the leg it is not (its
/// contact point swings), and auto takes the accurate path.
#[test]
fn a_central_booted_kick_is_the_1d_booted_kick() {
    let k = kick("law = \"shell\"\nboot_stiffness = 4.0e4\n", Kick3dSpec::default());
    assert!(k.is_one_dimensional());
    let one_d = Solver3d::Auto.solve(&k).unwrap();
    let accurate = Accurate3d::default().solve(&k).unwrap();
    let errors = Errors3d::of(&k, &accurate, &one_d);
    assert!(errors.max() < 1e-9, "{errors:?}");
    let direct = kick_compliant::Auto::default().solve(&k.normal_scenario().unwrap()).unwrap();
    assert!((one_d.speed - direct.v_ball_out).abs() < 1e-12 * direct.v_ball_out);
    let leg = kick("law = \"shell\"\nleg = true\n", Kick3dSpec::default());
    assert!(!leg.is_one_dimensional());
    assert_eq!(Solver3d::Auto.solve(&leg).unwrap().solver, "accurate-3d");
}

/// The leg's foot in 3D moves along the forward direction as its 1D mass
/// says at first touch, and a stiffer and stiffer boot tends to no boot.
#[test]
fn the_1d_projection_and_the_stiff_boot_limit() {
    let leg = kick("leg = true\nboot_stiffness = inf\n", Kick3dSpec::default());
    let foot = kick_core::leg::LegFoot::new(kick_core::leg::LegPose::DEFAULT).unwrap();
    assert_eq!(leg.base.effective_foot_mass(), foot.effective_mass);
    let ld = leg.leg.unwrap();
    // The foot's centre lies behind the contact point: its own mobility
    // along x differs, the contact point's is 1/m_eff.
    let (_, a) = ld.response(parry3d_f64::math::Vec3::ZERO, parry3d_f64::math::Vec3::X);
    assert!(a.x > 0.0);
    let rigid = Accurate3d::default().solve(&kick("law = \"shell\"\n", Kick3dSpec { offset: Some(0.03), ..Default::default() })).unwrap();
    let gap = |k_b: f64| {
        let o = Accurate3d::default()
            .solve(&kick(
                &format!("law = \"shell\"\nboot_stiffness = {k_b:e}\nboot_damping = {:e}\n", 1e-3 * k_b),
                Kick3dSpec { offset: Some(0.03), ..Default::default() },
            ))
            .unwrap();
        (o.speed - rigid.speed).abs() / rigid.speed
    };
    let (g6, g7) = (gap(1e7), gap(1e8));
    assert!(g7 < 0.2 * g6 && g7 < 1e-2, "{g6:e} {g7:e}");
}

/// What the leg and a boot do not take is refused by name.
#[test]
fn settings_the_foot_does_not_take_are_refused() {
    let refused = |scenario: &str, kick3d: Kick3dSpec| {
        let spec: ScenarioSpec = toml::from_str(scenario).unwrap();
        KickSpec { scenario: spec, kick3d }.build().unwrap_err().to_string()
    };
    let e = refused("leg = true\n", Kick3dSpec { tangential_stiffness: Some(f64::INFINITY), ..Default::default() });
    assert!(e.starts_with("`tangential_stiffness` does not apply"), "{e}");
    let e = refused("boot_stiffness = 4e4\n", Kick3dSpec { ground: Some(true), ..Default::default() });
    assert!(e.starts_with("`ground` does not apply"), "{e}");
    let e = refused("leg = true\n", Kick3dSpec { gravity: Some(true), ..Default::default() });
    assert!(e.starts_with("`gravity` does not apply"), "{e}");
    let e = refused("leg = true\n", Kick3dSpec { foot_inertia: Some([0.01, 0.01, 0.01]), ..Default::default() });
    assert!(e.starts_with("`foot_inertia` does not apply"), "{e}");
    // A foot setting by name on a 3D spec lands in the scenario.
    let mut spec = KickSpec::default();
    spec.set_named("leg", Value::Switch(true)).unwrap();
    spec.set_named("knee", Value::Number(45.0)).unwrap();
    let k = spec.build().unwrap();
    assert_eq!(k.base.foot().leg.unwrap().knee, 45.0);
    assert!(k.base.foot().boot == Some(kick_core::boot::IDENTIFIED));
}

/// A kick that stalls (`kick sweep3d --law shell --leg`, seed 1, row 7162:
/// the point contact slipping on the knife edge's rounded border behind the
/// boot, its step size stuck near 3e-14 s with every other step rejected)
/// stops as a numerical failure after `STALL_STEPS` tiny steps, where it ran
/// into the million-step budget after 7.7 s; its variants that settle (no
/// boot; μ = ∞) do not stall. (`build_drawn`: the sweep's own build, which
/// takes the drawn foot mass beside the leg.)
#[test]
fn a_stalled_kick_fails_at_once() {
    let spec = shell_row(
        [3.940127199239893, 0.44367942932528065, 34.7412326286056, -9.253187736840848, 0.0, 66995.13568577074],
        true,
        Kick3dSpec {
            offset: Some(0.06716504890929391),
            approach_angle_deg: Some(27.174114265518483),
            friction: Some(0.24330882169897938),
            tangential_stiffness: Some(73728.52915510784),
            ..Default::default()
        },
    );
    let kick = spec.build_drawn().unwrap();
    let error = match Accurate3d::default().solve(&kick) {
        Ok(_) => panic!("the stalled kick separated"),
        Err(e) => e,
    };
    let text = error.to_string();
    assert!(text.contains("stalled") && error.status() == kick_core::Status::NumericalFailure, "{text}");
    // Stopped where it stalls (5.875 ms), not after the step budget.
    assert!(text.contains("t = 0.005875"), "{text}");
    for settled in [
        KickSpec { scenario: ScenarioSpec { boot_stiffness: Some(f64::INFINITY), ..spec.scenario }, ..spec },
        KickSpec { kick3d: Kick3dSpec { friction: Some(f64::INFINITY), ..spec.kick3d }, ..spec },
    ] {
        let o = Accurate3d::default().solve(&settled.build_drawn().unwrap()).expect("separates");
        assert!(o.evaluations < 5000, "{}", o.evaluations);
    }
}

/// A fast kick into an incoming ball (row 342 of `sweep3d`'s box with the
/// identified boot, made central): 5.8 cm of ball and 8.6 cm of layer, the
/// ball's centre inside the foot's box. The accurate path is still the 1D
/// booted kick (its geometry is the face's plane); the full state's parry
/// distance reads the nearest face there (on row 342 itself, 7.9° off
/// square, it gave 3.9 m/s where the accurate path gives 57), so it
/// refuses, naming the limit.
#[test]
fn a_centre_inside_the_foot_s_box_is_refused_by_the_full_state() {
    let scenario = "law = \"shell\"\nfoot_mass = 7.0546\nball_mass = 0.41332\nfoot_speed = 33.510\nball_speed = -8.5438\n\
                    inflation_pressure = 61475.0\nboot_stiffness = 35066.065\nboot_damping = 38.3008\n";
    let k = kick(scenario, Kick3dSpec { friction: Some(1.129), ..Default::default() });
    let one_d = kick_compliant::Auto::default().solve(&k.normal_scenario().unwrap()).unwrap();
    let accurate = Accurate3d::default().solve(&k).unwrap();
    let speed = |v: [f64; 3]| (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    assert!((speed(accurate.launch_velocity) - one_d.v_ball_out).abs() < 1e-9 * one_d.v_ball_out, "{accurate:?} {one_d:?}");
    match precision::reference().solve(&k) {
        Err(kick_3d::Kick3dError::Core(kick_core::KickError::BeyondGeometry { compression, limit, .. })) => {
            assert!(compression > limit && limit == k.ball_radius, "{compression} {limit}")
        }
        other => panic!("the full state answered: {other:?}"),
    }
}

/// A row `kick sweep3d --law shell` draws (seed 1): foot mass, ball mass,
/// foot speed, ball speed, drive force and inflation pressure, with or
/// without the leg, and the 3D draws.
fn shell_row(draws: [f64; 6], leg: bool, kick3d: Kick3dSpec) -> KickSpec {
    let [foot_mass, ball_mass, foot_speed, ball_speed, drive_force, inflation_pressure] = draws.map(Some);
    let scenario = ScenarioSpec {
        foot_mass,
        ball_mass,
        foot_speed,
        ball_speed,
        drive_force,
        law: Some(kick_core::LawKind::Shell),
        inflation_pressure,
        leg: leg.then_some(true),
        ..Default::default()
    };
    KickSpec { scenario, kick3d }
}

/// The accurate path at its default within 1e-9 of the full-state reference.
fn assert_within_the_reference(spec: &KickSpec) {
    let kick = spec.build_drawn().unwrap();
    let accurate = Accurate3d::default().solve(&kick).unwrap();
    let reference = precision::reference().solve(&kick).unwrap();
    let e = Errors3d::of(&kick, &accurate, &reference);
    assert!(e.max() <= 1e-9, "{e:?}");
}

/// A grip shorter than the reference's step (`kick sweep3d --law shell
/// --leg`, seed 1, row 93: 79 µs of grip between two slips near
/// separation). The full state at rtol 1e-13 used to step over it, its
/// margin crossing zero and back inside one step, and was off by 7.2e-3 of
/// the contact in slip time; it now locates the margin's turn in such a step
/// and agrees with the accurate path and with itself at rtol 1e-12 to 1e-9.
#[test]
fn the_full_state_finds_a_grip_shorter_than_its_step() {
    let spec = shell_row(
        [4.426664136974946, 0.44956149134867074, 28.742696946636944, -3.955968970153232, 0.0, 76093.14022054964],
        true,
        Kick3dSpec {
            offset: Some(0.07375028109685516),
            approach_angle_deg: Some(23.861170701460864),
            friction: Some(0.3161170607704938),
            tangential_stiffness: Some(84545.17240461207),
            ..Default::default()
        },
    );
    let kick = spec.build_drawn().unwrap();
    let accurate = Accurate3d::default().solve(&kick).unwrap();
    let reference = precision::reference().solve(&kick).unwrap();
    let looser = kick_3d::FullState3d::new(1e-12, 1e-15).unwrap().solve(&kick).unwrap();
    for other in [&reference, &looser] {
        let e = Errors3d::of(&kick, &accurate, other);
        assert!(e.max() <= 1e-9, "{e:?}");
    }
    // The grip is there: slip is not the whole of the contact's end.
    assert!(accurate.slip_time < accurate.contact_time, "{accurate:?}");
}

/// The reference at first touch where the shell ball's force starts from
/// zero (`kick sweep3d --law shell --range contact_depth=0,0.05 --range
/// approach_angle=0,20`, seed 1, row 2894): parry's overlap came out a hair
/// below zero, the clamped law gave the cap no rate, and the element slipped
/// from touch, where μ Ḟ exceeds k_t |v_t| by 0.6 % and the accurate path
/// grips for 45 µs: slip time off by 5.6e-3 of the contact, spin by 1.1e-6.
/// The cap's rate at touch is now the law's slope at δ = 0.
#[test]
fn the_full_state_takes_the_caps_rate_at_touch_from_the_law() {
    let spec = shell_row(
        [7.629952896889974, 0.4330969276469102, 29.09505491969855, -6.606901990390533, 0.0, 81590.27210018948],
        false,
        Kick3dSpec {
            offset: Some(0.05085765501595918),
            contact_depth: Some(0.04005163139732537),
            approach_angle_deg: Some(7.9648089663972454),
            friction: Some(0.738027521409045),
            tangential_stiffness: Some(127092.64122463706),
            ..Default::default()
        },
    );
    assert_within_the_reference(&spec);
}

/// A grip from first touch whose margin starts at zero, behind the leg and
/// its boot (`kick sweep3d --law shell --leg`, seed 1, row 1127): the
/// reference read the margin's sign from parry's overlap at 6.5e-17 s, below
/// what its rounding resolves, and ended the grip there; the accurate path
/// grips for 0.58 µs. Slip time off by 5.2e-5 of the contact. The first
/// phase's switch is now looked for from where the overlap is resolved.
#[test]
fn the_full_state_keeps_a_grip_that_starts_below_its_rounding() {
    let spec = shell_row(
        [1.7040947752204474, 0.41967599126879485, 32.0435170421502, -6.841329246189298, 0.0, 81833.83767578992],
        true,
        Kick3dSpec {
            offset: Some(0.05368973361318666),
            approach_angle_deg: Some(-5.821784656806727),
            friction: Some(2.0233849192563547),
            tangential_stiffness: Some(521765.4944771233),
            ..Default::default()
        },
    );
    assert_within_the_reference(&spec);
}

/// A grip from first touch on the convex instep's patch, with the leg and its
/// boot (`kick sweep3d --law shell --leg --patch-contact --instep-radius 0.15
/// --face-yaw 0`, seed 1, row 153): the margin starts at zero and stays
/// positive for 17 µs. The accurate path's first step took all of that in,
/// and the switch's root was sought from a made-up value at touch
/// (`locate_switch`), where Brent's first secant fell within 1e-300 of touch:
/// the grip ended at touch at every rtol from 1e-11 to 1e-14 (slip time off
/// by 1.4e-3 of the contact, spin by 4.4e-7), but not at 1e-15, whose first
/// step was shorter than the grip.
#[test]
fn a_grip_from_touch_on_the_patch_ends_where_its_margin_does() {
    let spec = shell_row(
        [7.278410412328385, 0.42132572341628527, 30.68724635614008, -1.056282389287194, 992.6833115121005, 78522.69525443029],
        true,
        Kick3dSpec {
            offset: Some(0.07858644179025004),
            approach_angle_deg: Some(-8.599579527996314),
            friction: Some(0.2856904698925872),
            tangential_stiffness: Some(111734.44080803785),
            face_yaw_deg: Some(0.0),
            instep_radius: Some(0.15),
            patch_contact: Some(true),
            ..Default::default()
        },
    );
    let kick = spec.build_drawn().unwrap();
    let tight = Accurate3d::new(1e-15).unwrap().solve(&kick).unwrap();
    for rtol in [1e-12, kick_3d::accurate::DEFAULT_TOLERANCE] {
        let solved = Accurate3d::new(rtol).unwrap().solve(&kick).unwrap();
        let e = Errors3d::of(&kick, &solved, &tight);
        assert!(e.max() <= 1e-9, "rtol {rtol:e}: {e:?}");
    }
    // The grip from touch is there: 17 µs of the contact do not slip.
    assert!(tight.contact_time - tight.slip_time > 1.5e-5, "{tight:?}");
}
