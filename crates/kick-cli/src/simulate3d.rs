//! `kick simulate3d`: one off-center 3D kick (spin, friction; kick-3d).

use crate::output::{json, CliResult, Format};
use crate::flags::Flags;
use kick_3d::{Kick3d, KickSpec, Outcome3d, Solver3d};
use serde_json::{Map, Value};
use std::time::Instant;

#[derive(clap::Args, Debug)]
pub struct Args {
    /// The declared 1D and 3D parameters and --law (the normal force's law).
    #[command(flatten)]
    kick: Flags<KickSpec>,
    /// auto | accurate | 1d | rapier
    #[arg(long, default_value = "auto", value_parser = Solver3d::NAMES)]
    solver: String,
    /// Step of the rapier scene path, s
    #[arg(long, default_value_t = 1e-6, allow_negative_numbers = true)]
    dt: f64,
    #[arg(long, value_enum, default_value_t = Format::Text)]
    format: Format,
    /// Print the wall time of the solve (one run) on stderr
    #[arg(long)]
    time: bool,
    /// Instead of one solve: the rapier scene path at steps 4e-5 s halving to
    /// 6.25e-7 s against the accurate path (error, observed order, wall time)
    #[arg(long)]
    scene_convergence: bool,
}

impl Args {
    fn kick(&self) -> Result<Kick3d, String> {
        self.kick.spec().build().map_err(|e| e.to_string())
    }
}

/// The JSON object of one 3D run: the outcome (with `law`, the normal law's
/// name), the energy residual and `law_parameters` (the law as solved).
pub fn outcome_json(kick: &Kick3d, o: &Outcome3d) -> Result<Map<String, Value>, String> {
    match serde_json::to_value(o).map_err(|e| e.to_string())? {
        Value::Object(mut m) => {
            m.insert("energy_residual".into(), o.energy.residual().into());
            m.insert("law_parameters".into(), serde_json::to_value(kick.law()).map_err(|e| e.to_string())?);
            Ok(m)
        }
        _ => Err("outcome is not an object".into()),
    }
}

// kick-3d is used with its default features, so the rapier path is present.
fn scene_convergence(kick: &Kick3d) -> CliResult {
    let steps: Vec<f64> = (0..7).map(|i| 4e-5 / f64::from(1u32 << i)).collect();
    let (rows, accurate) = kick_3d::scene::convergence(kick, &steps).map_err(|e| e.to_string())?;
    println!("accurate-3d: {:.3} ms", accurate * 1e3);
    println!("{:>10} {:>12} {:>12} {:>12} {:>7} {:>10}", "dt_s", "velocity", "spin", "contact_t", "order", "ms");
    for r in rows {
        let order = r.velocity_order.map_or("-".to_string(), |p| format!("{p:.3}"));
        println!("{:>10.3e} {:>12.3e} {:>12.3e} {:>12.3e} {:>7} {:>10.3}", r.step, r.velocity_error, r.spin_error, r.contact_time_error, order, r.seconds * 1e3);
    }
    Ok(())
}

pub fn run(args: Args) -> CliResult {
    let kick = args.kick()?;
    if args.scene_convergence {
        return scene_convergence(&kick);
    }
    let solver = Solver3d::from_name(&args.solver, args.dt).map_err(|e| e.to_string())?;
    let start = Instant::now();
    let o = solver.solve(&kick).map_err(|e| e.to_string())?;
    let elapsed = start.elapsed();
    if args.time {
        eprintln!("solver {} took {:.3} ms", o.solver, elapsed.as_secs_f64() * 1e3);
    }
    match args.format {
        Format::Json => println!("{}", json(&outcome_json(&kick, &o)?)?),
        Format::Text => {
            let v = |a: [f64; 3], unit: &str| format!("[{:+.6e}, {:+.6e}, {:+.6e}] {unit}", a[0], a[1], a[2]);
            println!("solver: {}, normal law: {}", o.solver, o.law.name());
            println!("{:<24} {}", "launch_velocity", v(o.launch_velocity, "m/s"));
            println!("{:<24} {}", "spin", v(o.spin, "rad/s"));
            for (name, value, unit) in [
                ("speed", o.speed, "m/s"),
                ("spin_rpm", o.spin_rpm, "rpm"),
                ("launch_angle", o.launch_angle, "deg"),
                ("launch_azimuth", o.launch_azimuth, "deg"),
                ("contact_time", o.contact_time, "s"),
                ("peak_normal_force", o.peak_normal_force, "N"),
                ("peak_tangential_force", o.peak_tangential_force, "N"),
                ("max_compression", o.max_compression, "m"),
                ("slip_time", o.slip_time, "s"),
                ("energy_ball_spin", o.energy.ball_spin, "J"),
                ("energy_friction_loss", o.energy.friction_loss, "J"),
                ("energy_residual", o.energy.residual(), "J"),
            ] {
                println!("{name:<24} {value:>16.10e} {unit}");
            }
            println!("{:<24} {}", "evaluations", o.evaluations);
        }
    }
    Ok(())
}
