//! `kick sweep --samples N --seed S [--solver NAME] --out FILE.h5`: random
//! scenarios around the baseline, solved in parallel, streamed to HDF5.

use crate::printable::Printable;
use crate::sample::{ranges, SampledSweep};
use crate::{Experiment, Output, Scenarios};
use kick_compliant::{Auto, SolverChoice};
use kick_core::{LawKind, Parameter, ScenarioSpec, SolverPath};
use serde::Serialize;
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::PathBuf;

/// What to sweep.
#[derive(Debug, Clone, PartialEq)]
pub struct SweepSettings {
    pub samples: u64,
    pub seed: u64,
    /// `--solver` name.
    pub solver: String,
    /// Step of the fixed-step solvers, s.
    pub dt: f64,
    /// Result file NAME.h5 (its directory is created).
    pub out: PathBuf,
    /// Parameters held fixed, and the law of every scenario.
    pub fixed: ScenarioSpec,
}

/// What a sweep did.
#[derive(Debug, Clone, Serialize)]
pub struct SweepReport {
    pub scenarios: u64,
    pub solver: String,
    pub seconds: f64,
    pub threads: usize,
    pub path: PathBuf,
    pub failed: u64,
    /// Which path `auto` took over the first (at most 100 000) scenarios.
    pub auto_paths: Option<(u64, BTreeMap<SolverPath, u64>)>,
}

/// Sample `settings.samples` scenarios, solve them in parallel and stream
/// them into the result file.
pub fn sweep(settings: &SweepSettings) -> Result<SweepReport, String> {
    if settings.samples == 0 {
        return Err("--samples must be at least 1".into());
    }
    let out = &settings.out;
    let name = out
        .file_stem()
        .and_then(|s| s.to_str())
        .filter(|_| out.extension().is_some_and(|e| e == "h5"))
        .ok_or_else(|| format!("--out {} must name a file NAME.h5", out.display()))?
        .to_string();
    let directory = out.parent().map(PathBuf::from).unwrap_or_default();
    let solver = SolverChoice::from_name(&settings.solver, settings.dt).map_err(|e| e.to_string())?;
    let sweep = SampledSweep { samples: settings.samples, seed: settings.seed, fixed: settings.fixed };
    sweep.scenario(0).map_err(|e| e.to_string())?;
    // The provenance keeps what made the file: the command and the ranges.
    let mut fixed: String = Parameter::ALL
        .iter()
        .filter_map(|&p| settings.fixed.get(p).map(|v| format!(" {} {v}", p.def().flag())))
        .collect();
    if let Some(e) = settings.fixed.restitution {
        fixed.push_str(&format!(" --restitution {e}"));
    }
    let text = format!(
        "# kick sweep --samples {} --seed {} --solver {} --dt {} --law {}{fixed}\n# ranges (a parameter given is fixed):\n{}\n\
         # auto paths: no drive and c = 0 or n = 1 -> closed-form; otherwise the paper's law -> series; another law -> reduced\n",
        settings.samples,
        settings.seed,
        settings.solver,
        settings.dt,
        settings.fixed.law.unwrap_or(LawKind::PowerLaw).name(),
        ranges().lines().map(|l| format!("#   {l}")).collect::<Vec<_>>().join("\n")
    );
    let experiment = Experiment {
        name: name.clone(),
        description: format!("random sweep of {} scenarios around the baseline (seed {})", settings.samples, settings.seed),
        path: PathBuf::from(format!("kick sweep (seed {})", settings.seed)),
        text,
        solvers: vec![solver],
        scenarios: Scenarios::Sampled(sweep),
        output: Output::Summary,
        flight: None,
    };
    let started = std::time::Instant::now();
    let summary = crate::run(&experiment, &directory, true).map_err(|e| e.to_string())?;
    let seconds = started.elapsed().as_secs_f64();
    let auto_paths = matches!(solver, SolverChoice::Auto(_)).then(|| {
        // Which path auto took, counted from the scenarios (a pure function of them).
        let counted = settings.samples.min(100_000);
        let mut counts = BTreeMap::new();
        for i in 0..counted {
            if let Ok(s) = sweep.scenario(i) {
                *counts.entry(Auto::path(&s)).or_insert(0u64) += 1;
            }
        }
        (counted, counts)
    });
    Ok(SweepReport {
        scenarios: summary.scenarios,
        solver: settings.solver.clone(),
        seconds,
        threads: rayon::current_num_threads(),
        path: summary.path,
        failed: summary.failures.iter().map(|(_, n)| n).sum(),
        auto_paths,
    })
}

impl Printable for SweepReport {
    fn text(&self) -> String {
        let mut w = String::new();
        let _ = writeln!(
            w,
            "{} scenarios with {} in {:.3} s on {} threads: {:.0} scenarios/s -> {} ({} failed)",
            self.scenarios,
            self.solver,
            self.seconds,
            self.threads,
            self.scenarios as f64 / self.seconds,
            self.path.display(),
            self.failed
        );
        if let Some((counted, counts)) = &self.auto_paths {
            let shown: Vec<String> = counts.iter().map(|(k, v)| format!("{k}: {v}")).collect();
            let _ = writeln!(w, "auto paths over the first {counted} scenarios: {}", shown.join(", "));
        }
        w
    }
}
