//! The rapier scene path: same law as the accurate path, first order in its step.
#![cfg(feature = "rapier")]

use kick_3d::checks::kick;
use kick_3d::scene::Scene;
use kick_3d::{Accurate3d, Kick3d, Kick3dSpec};
use kick_core::{LawKind, Scenario};

fn spec() -> Kick3dSpec {
    Kick3dSpec { offset: Some(0.05), approach_angle_deg: Some(10.0), ..Kick3dSpec::default() }
}

fn norm(v: [f64; 3]) -> f64 {
    v.iter().map(|x| x * x).sum::<f64>().sqrt()
}

/// Errors of the scene path against the accurate path (relative: launch velocity, spin, contact time).
fn errors(step: f64) -> [f64; 3] {
    let k = kick(spec());
    let exact = Accurate3d::default().solve(&k).unwrap();
    let o = Scene::new(step).unwrap().solve(&k).unwrap();
    let dv: Vec<f64> = (0..3).map(|i| o.launch_velocity[i] - exact.launch_velocity[i]).collect();
    let dw: Vec<f64> = (0..3).map(|i| o.spin[i] - exact.spin[i]).collect();
    [
        norm([dv[0], dv[1], dv[2]]) / exact.speed,
        norm([dw[0], dw[1], dw[2]]) / norm(exact.spin),
        (o.contact_time - exact.contact_time).abs() / exact.contact_time,
    ]
}

#[test]
fn scene_path_converges_at_first_order() {
    let steps = [4e-5, 2e-5, 1e-5, 5e-6];
    let e: Vec<[f64; 3]> = steps.iter().map(|&h| errors(h)).collect();
    for (h, err) in steps.iter().zip(&e) {
        println!("dt {h:.1e}: velocity {:.3e} spin {:.3e} contact time {:.3e}", err[0], err[1], err[2]);
    }
    for k in 0..2 {
        let orders: Vec<f64> = e.windows(2).map(|w| (w[0][k] / w[1][k]).log2()).collect();
        println!("observed orders ({}) {orders:?}", ["velocity", "spin"][k]);
        // Semi-implicit Euler with a force held over each step: order 1.
        for p in orders {
            assert!((0.9..=1.1).contains(&p), "order {p}");
        }
    }
}

#[test]
fn ground_and_gravity_live_in_the_scene() {
    // Horizontal kick of a ball resting on the ground, with gravity: rapier's
    // own ground contact holds the ball up, so the launch has no downward
    // velocity, unlike the same kick in free fall.
    let step = 1e-5;
    let with = |ground: bool| {
        let k = kick(Kick3dSpec { offset: Some(0.05), ground: Some(ground), gravity: Some(true), ..Kick3dSpec::default() });
        Scene::new(step).unwrap().solve(&k).unwrap()
    };
    let (floor, free) = (with(true), with(false));
    let accurate =
        Accurate3d::default().solve(&kick(Kick3dSpec { offset: Some(0.05), gravity: Some(true), ..Kick3dSpec::default() })).unwrap();
    println!(
        "vz: ground {:.6e}, free {:.6e}, accurate free {:.6e}; contact {:.6e}",
        floor.launch_velocity[2], free.launch_velocity[2], accurate.launch_velocity[2], accurate.contact_time
    );
    // In free fall both bodies fall together: v_z = −g t_c for the ball.
    let fall = -kick_3d::model::GRAVITY * accurate.contact_time;
    assert!((accurate.launch_velocity[2] - fall).abs() <= 1e-9 * accurate.speed);
    assert!((free.launch_velocity[2] - fall).abs() <= 1e-2 * fall.abs());
    // On the ground the ball cannot fall (rapier's soft contact may let it sink a little).
    assert!(floor.launch_velocity[2].abs() <= 1e-3 * fall.abs(), "{}", floor.launch_velocity[2]);
}

/// The scene path applies the kick's own law: with Hunt–Crossley and
/// Kelvin–Voigt (e = 0.6) it converges at first order to the accurate path
/// (which matches the 1D solver with that law, tests/model/accurate.rs), within
/// the bound scene.rs documents, 3e-4 relative per microsecond of step
/// (measured up to 0.9e-4, Kelvin–Voigt's spin).
#[test]
fn scene_path_runs_the_kicks_law() {
    for kind in [LawKind::HuntCrossleyExact, LawKind::KelvinVoigt] {
        let base = Scenario::baseline().with_law(kind, Some(0.6)).unwrap();
        let k = Kick3d::new(base, &spec()).unwrap();
        let steps = [2e-5, 1e-5];
        let (rows, _) = kick_3d::scene::convergence(&k, &steps).unwrap();
        for r in &rows {
            println!("{} dt {:.1e}: velocity {:.3e} spin {:.3e}", kind.name(), r.step, r.velocity_error, r.spin_error);
            let bound = 3e-4 * r.step / 1e-6;
            assert!(r.velocity_error <= bound && r.spin_error <= bound, "{}: {r:?}", kind.name());
        }
        for (e0, e1) in [(rows[0].velocity_error, rows[1].velocity_error), (rows[0].spin_error, rows[1].spin_error)] {
            let order = (e0 / e1).log2();
            assert!((0.9..=1.1).contains(&order), "{}: order {order}", kind.name());
        }
        let o = Scene::new(1e-5).unwrap().solve(&k).unwrap();
        assert_eq!(o.law, kind);
        // The paper's law on the same kick is much farther off: the law matters.
        let paper = Accurate3d::default().solve(&kick(spec())).unwrap();
        assert!((paper.speed - o.speed).abs() / o.speed > 10.0 * rows[1].velocity_error, "{}: {} vs {}", kind.name(), paper.speed, o.speed);
    }
}

#[test]
fn scene_error_stays_within_its_documented_bound() {
    // scene.rs: at most 3e-4 relative per microsecond of step in launch
    // velocity and spin across the swept range; checked at 1e-5 s.
    let step = 1e-5;
    let bound = 3e-4 * step / 1e-6;
    for (e, a, mu) in [(0.09, 0.0, 0.5), (0.0, 40.0, 0.5), (-0.09, 40.0, 0.5), (0.05, 0.0, 0.1), (0.05, 0.0, 2.0)] {
        let k = kick(Kick3dSpec { offset: Some(e), approach_angle_deg: Some(a), friction: Some(mu), ..Kick3dSpec::default() });
        let (rows, _) = kick_3d::scene::convergence(&k, &[step]).unwrap();
        let r = rows[0];
        println!("e {e} a {a} mu {mu}: velocity {:.3e} spin {:.3e}", r.velocity_error, r.spin_error);
        assert!(r.velocity_error <= bound && r.spin_error <= bound);
    }
}
