//! `kick sweep --samples N --seed S [--solver NAME] --out FILE.h5`: random
//! scenarios around the baseline, solved in parallel, streamed to HDF5.

use crate::output::CliResult;
use kick_compliant::{Auto, SolverChoice};
use crate::flags::Flags;
use kick_core::ScenarioSpec;
use kick_runner::sample::{ranges, SampledSweep};
use kick_runner::{Experiment, Output, Scenarios};
use std::path::PathBuf;

#[derive(clap::Args, Debug)]
pub struct Args {
    /// Number of scenarios
    #[arg(long)]
    samples: u64,
    /// Seed of the sampler (the same seed gives the same file)
    #[arg(long, default_value_t = 1)]
    seed: u64,
    #[arg(long, default_value = "auto", value_parser = SolverChoice::NAMES)]
    solver: String,
    /// Step of the fixed-step solvers, s
    #[arg(long, default_value_t = 5e-6)]
    dt: f64,
    /// Result file (its directory is created)
    #[arg(long)]
    out: PathBuf,
    /// Worker threads (default: one per core)
    #[arg(long)]
    threads: Option<usize>,
    /// A 1D parameter given is held at that value instead of drawn; --law
    /// and --restitution set the contact law of every scenario
    #[command(flatten)]
    fixed: Flags<ScenarioSpec>,
}

pub fn run(args: Args) -> CliResult {
    crate::run::set_threads(args.threads)?;
    if args.samples == 0 {
        return Err("--samples must be at least 1".into());
    }
    let name = args
        .out
        .file_stem()
        .and_then(|s| s.to_str())
        .filter(|_| args.out.extension().is_some_and(|e| e == "h5"))
        .ok_or_else(|| format!("--out {} must name a file NAME.h5", args.out.display()))?
        .to_string();
    let directory = args.out.parent().map(PathBuf::from).unwrap_or_default();
    let solver = SolverChoice::from_name(&args.solver, args.dt).map_err(|e| e.to_string())?;
    let sweep = SampledSweep { samples: args.samples, seed: args.seed, fixed: args.fixed.spec() };
    sweep.scenario(0).map_err(|e| e.to_string())?;
    // The provenance keeps what made the file: the command and the ranges.
    let fixed: String = args.fixed.given.iter().map(|(p, v)| format!(" {} {}", p.flag(), match v {
        kick_core::Value::Number(x) => x.to_string(),
        other => format!("{other:?}"),
    })).collect();
    let text = format!(
        "# kick sweep --samples {} --seed {} --solver {} --dt {} --law {}{fixed}\n# ranges (a parameter given is fixed):\n{}\n# auto paths: no drive and c = 0 or n = 1 -> closed-form; \
         otherwise the paper's law -> series; another law -> reduced\n",
        args.samples,
        args.seed,
        args.solver,
        args.dt,
        args.fixed.law.unwrap_or(kick_core::LawKind::PowerLaw).name(),
        ranges().lines().map(|l| format!("#   {l}")).collect::<Vec<_>>().join("\n")
    );
    let experiment = Experiment {
        name: name.clone(),
        description: format!("random sweep of {} scenarios around the baseline (seed {})", args.samples, args.seed),
        path: PathBuf::from(format!("kick sweep (seed {})", args.seed)),
        text,
        solvers: vec![solver],
        scenarios: Scenarios::Sampled(sweep),
        output: Output::Summary,
    };
    let started = std::time::Instant::now();
    let summary = kick_runner::run(&experiment, &directory, true).map_err(|e| e.to_string())?;
    let seconds = started.elapsed().as_secs_f64();
    let failed: u64 = summary.failures.iter().map(|(_, n)| n).sum();
    println!(
        "{} scenarios with {} in {:.3} s on {} threads: {:.0} scenarios/s -> {} ({} failed)",
        summary.scenarios,
        args.solver,
        seconds,
        rayon::current_num_threads(),
        summary.scenarios as f64 / seconds,
        summary.path.display(),
        failed
    );
    if args.solver == "auto" {
        // Which path auto took, counted from the scenarios (a pure function of them).
        let mut counts = std::collections::BTreeMap::new();
        for i in 0..args.samples.min(100_000) {
            if let Ok(s) = sweep.scenario(i) {
                *counts.entry(Auto::path(&s)).or_insert(0u64) += 1;
            }
        }
        let shown: Vec<String> = counts.iter().map(|(k, v)| format!("{k}: {v}")).collect();
        println!("auto paths over the first {} scenarios: {}", args.samples.min(100_000), shown.join(", "));
    }
    Ok(())
}
