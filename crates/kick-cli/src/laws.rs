//! `kick laws`: the contact-law family on Table 2's scenarios.

use crate::output::{json, CliResult, Format};
use kick_compliant::Accurate;
use kick_identify::laws::{compare, LawComparison};
use std::path::PathBuf;

#[derive(clap::Args, Debug)]
pub struct Args {
    #[arg(long, value_enum, default_value_t = Format::Text)]
    format: Format,
    /// Scenario file with the rows' parameters
    #[arg(long, default_value = "experiments/table2.toml")]
    scenarios: PathBuf,
    /// Write laws.json (outcomes and force pulses) and laws.png/svg here
    #[arg(long)]
    out: Option<PathBuf>,
    /// Pulse samples per undamped contact time (at most)
    #[arg(long, default_value_t = 200)]
    samples: u32,
}

pub fn comparisons(args: &Args) -> Result<Vec<LawComparison>, String> {
    if !(10..=100_000).contains(&args.samples) {
        return Err(format!("--samples must be in 10..=100000 (got {})", args.samples));
    }
    let file = crate::table2::load(&args.scenarios)?;
    let solver = Accurate::default();
    file.scenarios()
        .map_err(|e| e.to_string())?
        .iter()
        .map(|(name, s)| {
            compare(name, s, &solver, s.elastic_contact_time() / args.samples as f64).map_err(|e| format!("{name}: {e}"))
        })
        .collect()
}

pub fn run(args: Args) -> CliResult {
    let all = comparisons(&args)?;
    if let Some(dir) = &args.out {
        std::fs::create_dir_all(dir).map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
        let path = dir.join("laws.json");
        std::fs::write(&path, json(&all)?).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
        crate::identify_figures::laws(&all, dir)?;
    }
    match args.format {
        Format::Json => println!("{}", json(&all)?),
        Format::Text => {
            for c in &all {
                println!("{} (target e = paper's law's e = {:.4})", c.name, c.restitution);
                println!(
                    "  {:<20} {:>8} {:>10} {:>10} {:>10} {:>10} {:>10}",
                    "law", "e", "v_b+ m/s", "F(0+) N", "peak N", "t_c ms", "δmax mm"
                );
                for r in &c.runs {
                    let o = &r.outcome;
                    println!(
                        "  {:<20} {:>8.4} {:>10.3} {:>10.1} {:>10.1} {:>10.3} {:>10.3}",
                        r.law.name(),
                        o.restitution,
                        o.v_ball_out,
                        r.pulse.first().map_or(0.0, |p| p.1),
                        o.peak_force,
                        o.contact_time * 1e3,
                        o.max_compression * 1e3
                    );
                }
            }
        }
    }
    Ok(())
}
