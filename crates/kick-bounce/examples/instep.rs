//! A preview of issue 22 item 6, not a validated prediction: Table 1's
//! baseline kick (3 kg foot at 22 m/s, rigid-foot 1D contact) with the shell
//! ball in place of Eq. 20, through the library (`Accurate::solve_law`).
//! `cargo run -p kick-bounce --example instep`.

use kick_compliant::Accurate;
use kick_core::{Scenario, ShellBall, DEFAULT_BALL_RADIUS};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let s = Scenario::BASELINE;
    let paper = Accurate::default().solve_law(&s, s.contact_law())?;
    let shell = Accurate::default().solve_law(&s, ShellBall::default_with_radius(DEFAULT_BALL_RADIUS)?)?;
    for (name, o) in [("paper's law", paper), ("shell ball", shell)] {
        println!(
            "{name:12} t_c {:.2} ms  F_peak {:.0} N  δ_max {:.1} mm  v_b+ {:.2} m/s  ratio {:.3}  e {:.3}",
            o.contact_time * 1e3,
            o.peak_force,
            o.max_compression * 1e3,
            o.v_ball_out,
            o.speed_ratio.unwrap_or(f64::NAN),
            o.restitution
        );
    }
    Ok(())
}
