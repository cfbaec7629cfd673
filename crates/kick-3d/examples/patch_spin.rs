//! Spin against offset at μ = 0, 0.5, 1: the shell ball (law `shell`, FIFA
//! calibration) on Table 1's foot at 22 m/s, point contact against the patch
//! (`kick_3d::patch`), on the knife-edge face and on a cap square to the
//! swing (`instep_radius` given, face_yaw = 0). Beside Asai et al. (2002):
//! friction 0 → 1 adds at most ~13 rad/s; the largest spin near 100 mm.
//!
//! `cargo run -p kick-3d --example patch_spin [CAP_RADIUS_M]` (default 0.15, an assumption).
use kick_3d::{Accurate3d, Kick3d, Kick3dSpec};
use kick_core::{LawKind, Scenario};
use parry3d_f64::math::Vec3;

/// A row's name and its spec at (offset, μ).
type Config = (&'static str, fn(f64, f64) -> Kick3dSpec);

fn main() {
    let cap: f64 = std::env::args().nth(1).map(|a| a.parse().expect("cap radius, m")).unwrap_or(0.15);
    let base = Scenario::baseline().with_law(LawKind::Shell, None).expect("shell");
    let solver = Accurate3d::default();
    let configs: [Config; 4] = [
        ("point, knife edge", |e, mu| Kick3dSpec { offset: Some(e), friction: Some(mu), ..Kick3dSpec::default() }),
        ("patch, knife edge", |e, mu| Kick3dSpec {
            offset: Some(e),
            friction: Some(mu),
            patch_contact: Some(true),
            ..Kick3dSpec::default()
        }),
        ("point, cap, yaw 0", |e, mu| Kick3dSpec { offset: Some(e), friction: Some(mu), face_yaw_deg: Some(0.0), ..Kick3dSpec::default() }),
        ("patch, cap, yaw 0", |e, mu| Kick3dSpec {
            offset: Some(e),
            friction: Some(mu),
            patch_contact: Some(true),
            face_yaw_deg: Some(0.0),
            ..Kick3dSpec::default()
        }),
    ];
    println!("config               e (m)   μ    spin_z (rad/s)  |spin| (rad/s)  speed (m/s)  azimuth (deg)  contact (ms)");
    for (name, make) in configs {
        for mu in [0.0, 0.5, 1.0] {
            for e in [0.0, 0.02, 0.04, 0.05, 0.06, 0.08, 0.10] {
                let mut spec = make(e, mu);
                if name.contains("cap") {
                    spec.instep_radius = Some(cap);
                }
                let row = Kick3d::new(base, &spec).and_then(|k| solver.solve(&k));
                match row {
                    Ok(o) => {
                        let spin = Vec3::from(o.spin);
                        println!(
                            "{name:<20} {e:5.2}  {mu:3.1}  {:14.3}  {:14.3}  {:11.3}  {:13.2}  {:12.3}",
                            spin.z,
                            spin.length(),
                            o.speed,
                            o.launch_azimuth,
                            o.contact_time * 1e3
                        );
                    }
                    Err(err) => println!("{name:<20} {e:5.2}  {mu:3.1}  refused: {err}"),
                }
            }
        }
    }
}
