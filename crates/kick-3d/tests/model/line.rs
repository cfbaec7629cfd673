//! One definition of where the foot meets the ball (`kick_3d::model`): the
//! offset e and the contact depth h are the distances of the ball's centre
//! from the foot's line of motion, lateral and vertical; the knife edge and
//! the instep are geometries placed on that line.

use kick_3d::{Accurate3d, Kick3d, Kick3dSpec, Outcome3d, Solver3d};
use kick_core::{Parameter, Scenario, Solver};
use parry3d_f64::math::{Rot3, Vec3};

fn kick(offset: f64, depth: f64, alpha: f64, mu: f64) -> Kick3d {
    let spec = Kick3dSpec {
        offset: Some(offset),
        contact_depth: Some(depth),
        approach_angle_deg: Some(alpha),
        friction: Some(mu),
        ..Kick3dSpec::default()
    };
    Kick3d::new(Scenario::baseline(), &spec).unwrap()
}

fn solve(k: &Kick3d) -> Outcome3d {
    Accurate3d::default().solve(k).unwrap()
}

fn v(a: [f64; 3]) -> Vec3 {
    Vec3::new(a[0], a[1], a[2])
}

/// The line through P = e ŷ − h v̂ along û, written out here: the knife
/// edge's first touch p = −R n0 lies on it and P is the point of the line
/// closest to the centre, at e sideways and h below; an instep's pole (the
/// face centre, h_x from the foot's centre of mass along its normal) moves
/// on the same line, flat or curved, at the default angles or others.
#[test]
fn the_line_of_motion_passes_the_centre_at_e_and_h() {
    for (e, h, alpha) in [(0.05f64, 0.0f64, 0.0f64), (0.04, 0.03, 0.0), (-0.05, 0.02, 10.0), (0.0, -0.04, 25.0), (0.03, 0.05, -15.0)] {
        let k = kick(e, h, alpha, 0.5);
        let a = f64::to_radians(alpha);
        let u = Vec3::new(a.cos(), 0.0, a.sin());
        let up = Vec3::new(-a.sin(), 0.0, a.cos());
        let p = k.line_point();
        assert!(p.dot(u).abs() < 1e-17 && (p.y - e).abs() < 1e-17 && (p.dot(up) + h).abs() < 1e-17, "{e} {h} {alpha}: {p:?}");
        let off_line = |x: Vec3| (x - p).cross(u).length();
        let touch = -k.initial_normal() * k.ball_radius;
        assert!(off_line(touch) < 1e-15, "knife edge {e} {h} {alpha}: touch {touch:?} off the line by {}", off_line(touch));
        // The knife edge's normal is the lateral kick's, rolled: tilt φ from û.
        let r = e.hypot(h);
        assert!((k.initial_normal().dot(u) - (1.0 - (r / k.ball_radius).powi(2)).sqrt()).abs() < 1e-15);
        for extra in [
            Kick3dSpec { instep_radius: Some(0.0), ..Kick3dSpec::default() },
            Kick3dSpec { instep_radius: Some(0.15), ..Kick3dSpec::default() },
            Kick3dSpec { face_yaw_deg: Some(10.0), face_pitch_deg: Some(5.0), instep_radius: Some(0.2), ..Kick3dSpec::default() },
        ] {
            let spec = Kick3dSpec { offset: Some(e), contact_depth: Some(h), approach_angle_deg: Some(alpha), ..extra };
            let Ok(k) = Kick3d::new(Scenario::baseline(), &spec) else { continue };
            let s = k.initial_state();
            let pole = s.foot_position + s.foot_orientation * Vec3::new(k.face_distance(), 0.0, 0.0);
            assert!(off_line(pole) < 1e-15, "instep {extra:?} at {e} {h} {alpha}: pole {pole:?} off the line by {}", off_line(pole));
        }
    }
}

/// The kick at (e, h) on a path at α, ball at rest, is the lateral kick at
/// r = √(e² + h²) on a horizontal path, turned about x by −β = −atan2(h, e)
/// and about y by −α (the knife edge is symmetric about the line of motion
/// without gravity): launch velocity and spin to 1e-9 of their size, the
/// contact's scalars to 1e-9. Both solved from scratch; the turn is done here.
#[test]
fn a_kick_at_e_and_h_is_the_lateral_kick_turned_about_the_line() {
    for (e, h, alpha) in [(0.04f64, 0.03f64, 0.0f64), (-0.05, 0.02, 0.0), (0.0, 0.04, 0.0), (0.03, -0.02, 15.0), (0.05, 0.03, 25.0)] {
        for mu in [0.5, f64::INFINITY] {
            let r = e.hypot(h);
            let signed = if e < 0.0 { -r } else { r };
            let lateral = solve(&kick(signed, 0.0, 0.0, mu));
            let turned = solve(&kick(e, h, alpha, mu));
            let beta = (h / signed).atan2(e / signed);
            let q = Rot3::from_rotation_y(-alpha.to_radians()) * Rot3::from_rotation_x(-beta);
            let (lv, lw) = (q * v(lateral.launch_velocity), q * v(lateral.spin));
            let (tv, tw) = (v(turned.launch_velocity), v(turned.spin));
            let scale = lv.length();
            assert!((lv - tv).length() <= 1e-9 * scale, "{e} {h} {alpha} {mu}: {lv:?} vs {tv:?}");
            assert!((lw - tw).length() <= 1e-9 * scale / 0.11, "{e} {h} {alpha} {mu}: spin {lw:?} vs {tw:?}");
            for (x, y) in [
                (lateral.contact_time, turned.contact_time),
                (lateral.peak_normal_force, turned.peak_normal_force),
                (lateral.max_compression, turned.max_compression),
            ] {
                assert!((x - y).abs() <= 1e-9 * x.abs(), "{e} {h} {alpha} {mu}: {x} vs {y}");
            }
        }
    }
}

/// The signs of the figure on paper/3d.md: e > 0 sends the ball toward −y
/// spinning ω_z < 0; h > 0 lifts it with backspin ω_y < 0; h < 0 (the line
/// above the centre) sends it down with topspin.
#[test]
fn offset_and_depth_set_the_sense_of_launch_and_spin() {
    let side = solve(&kick(0.05, 0.0, 0.0, 0.5));
    assert!(side.launch_velocity[1] < 0.0 && side.spin[2] < 0.0, "{side:?}");
    let below = solve(&kick(0.0, 0.03, 0.0, 0.5));
    assert!(below.launch_velocity[2] > 0.0 && below.spin[1] < 0.0, "{below:?}");
    let above = solve(&kick(0.0, -0.03, 0.0, 0.5));
    assert!(above.launch_velocity[2] < 0.0 && above.spin[1] > 0.0, "{above:?}");
}

/// Through the centre on a rising path the kick is the 1D kick along û
/// (nothing slides): `auto` takes the 1D path, the ball leaves along û at
/// the 1D exit speed without spin.
#[test]
fn a_central_kick_on_a_rising_path_leaves_along_it() {
    let k = kick(0.0, 0.0, 20.0, 0.5);
    assert!(k.is_one_dimensional());
    let o = Solver3d::Auto.solve(&k).unwrap();
    let exit = kick_compliant::Accurate::default().solve(&Scenario::baseline()).unwrap().v_ball_out;
    let u = Vec3::new(20f64.to_radians().cos(), 0.0, 20f64.to_radians().sin());
    assert!((v(o.launch_velocity) - u * exit).length() <= 1e-12 * exit, "{:?} vs {exit}", o.launch_velocity);
    assert_eq!(o.spin, [0.0; 3]);
    // The accurate path agrees.
    let a = solve(&k);
    assert!((v(a.launch_velocity) - u * exit).length() <= 1e-9 * exit, "{:?}", a.launch_velocity);
}

/// The knife edge at an approach angle used to keep its face vertical,
/// tangent at (−√(R² − e²), e, 0): that face is the one at
/// h = −√(R² − e²) sin α (the line passing above the centre), and the
/// central kick of experiments/3d/approach_angle.toml gave topspin there.
#[test]
fn the_old_rising_face_is_a_contact_above_the_centre() {
    let radius = Kick3d::baseline().ball_radius;
    for (e, alpha) in [(0.0, 20.0), (0.05, 10.0), (-0.03, 30.0)] {
        let c = (radius * radius - e * e).sqrt();
        let h = -c * f64::to_radians(alpha).sin();
        let n = kick(e, h, alpha, 0.5).initial_normal();
        assert!((n - Vec3::new(c, -e, 0.0) / radius).length() < 1e-15, "{e} {alpha}: {n:?}");
    }
    let h = -radius * 20f64.to_radians().sin();
    let topspin = solve(&kick(0.0, h, 20.0, 0.5));
    assert!(topspin.spin[1] > 0.0 && topspin.spin[0].abs() < 1e-9 && topspin.spin[2].abs() < 1e-9, "{:?}", topspin.spin);
    // The ball passes out of reach of the foot's face, and the contact's
    // checks refuse a line outside the ball.
    let spec = Kick3dSpec { offset: Some(0.08), contact_depth: Some(0.08), ..Kick3dSpec::default() };
    let error = Kick3d::new(Scenario::baseline().with(Parameter::FootSpeed, 20.0).unwrap(), &spec).unwrap_err();
    assert!(error.to_string().contains("contact_depth 0.08 m miss the ball"), "{error}");
}
