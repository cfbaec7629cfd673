//! `kick sweep --samples N --seed S [--solver NAME] --out FILE.h5 [--shard I/N]
//! [--compress [LEVEL]]`: random scenarios around the baseline, solved in
//! parallel, streamed to HDF5 (compressed: [`crate::h5::Compression`]).
//!
//! With `--shard I/N` (from 0, as `kick run --shard`), only samples
//! `floor(I*N_s/N) .. floor((I+1)*N_s/N)` are solved, into
//! `NAME.shard-I-of-N.h5` beside `--out NAME.h5`; sample i is the same
//! scenario in every shard (drawn from (seed, i)), and `kick merge
//! NAME.h5 PART...` joins the parts into the unsharded sweep's file.

use crate::error::StoreError;
use crate::experiment::MAX_SCENARIOS;
use crate::limits::LimitError;
use crate::printable::Printable;
use crate::sample::SampledSweep;
use crate::shard::Shard;
use crate::{Experiment, Output, Scenarios};
use kick_compliant::{Auto, SolverChoice};
use kick_core::{LawKind, Parameter, ScenarioSpec, SolverPath};
use kick_study::{Kicks, Kicks1d};
use serde::Serialize;
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::ops::Range;
use std::path::{Path, PathBuf};

/// What to sweep.
#[derive(Debug, Clone, PartialEq)]
pub struct SweepSettings {
    pub samples: u64,
    pub seed: u64,
    /// `--solver` name.
    pub solver: String,
    /// Step of the fixed-step solvers, s (given with another solver: refused).
    pub dt: Option<f64>,
    /// Result file NAME.h5 (its directory is created).
    pub out: PathBuf,
    /// Parameters held fixed, and the law of every scenario.
    pub fixed: ScenarioSpec,
    /// Ranges drawn from instead of the declared ones (`--range`, parsed).
    pub ranges: kick_study::sample::Ranges,
    /// `--shard I/N` as given: only that slice of the samples.
    pub shard: Option<String>,
    /// `--threads`: worker threads (default: one per core).
    pub threads: Option<usize>,
    /// `--compress [LEVEL]`: how the per-row datasets are stored.
    pub compress: crate::h5::Compression,
}

/// Where a random sweep (`kick sweep`, `kick sweep3d`) goes, its settings checked.
#[derive(Debug, Clone, PartialEq)]
pub struct SweepTarget {
    /// NAME of `--out NAME.h5`.
    pub name: String,
    /// The directory of `--out` (created when written).
    pub directory: PathBuf,
    pub samples: u64,
    /// The shard to solve, if any.
    pub shard: Option<Shard>,
    /// The samples this run solves: all, or the shard's.
    pub rows: Range<u64>,
    /// The file written: `--out`, or `NAME.shard-I-of-N.h5` beside it.
    pub path: PathBuf,
}

impl SweepTarget {
    /// Check `--samples` (1 ..= [`MAX_SCENARIOS`]), `--out` (a file NAME.h5)
    /// and `--shard`, then start `--threads` workers; errors name the flag.
    pub fn check(samples: u64, out: &Path, shard: Option<&str>, threads: Option<usize>) -> Result<SweepTarget, StoreError> {
        if samples == 0 {
            return Err(StoreError::Flag { flag: "samples", message: "--samples must be at least 1".into() });
        }
        if samples > MAX_SCENARIOS {
            return Err(LimitError::TooManyRows { what: "--samples", rows: samples }.into());
        }
        let name = out
            .file_stem()
            .and_then(|s| s.to_str())
            .filter(|_| out.extension().is_some_and(|e| e == "h5"))
            .ok_or_else(|| StoreError::Flag { flag: "out", message: format!("--out {} must name a file NAME.h5", out.display()) })?
            .to_string();
        let directory = out.parent().map(PathBuf::from).unwrap_or_default();
        let shard = shard.map(|given| Shard::parse(given, "--shard")).transpose()?;
        crate::limits::use_threads(threads, "--threads")?;
        let (rows, path) = match shard {
            Some(shard) => (shard.rows(samples), directory.join(shard.file_name(&name))),
            None => (0..samples, out.to_path_buf()),
        };
        // Reads nothing: the file itself must be one to write.
        crate::output::check_paths(&[crate::output::Target::File { flag: "--out", path: &path }], &[])?;
        Ok(SweepTarget { name, directory, samples, shard, rows, path })
    }

    /// "shard I/N: samples a..b", for reports.
    pub fn describe_shard(&self) -> Option<String> {
        self.shard.map(|s| format!("shard {}/{}: samples {}..{}", s.index, s.count, self.rows.start, self.rows.end))
    }
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
    /// With `--shard`: which shard and samples.
    pub shard: Option<String>,
}

/// Sample `settings.samples` scenarios, solve them in parallel and stream
/// them into the result file.
pub fn sweep(settings: &SweepSettings) -> Result<SweepReport, StoreError> {
    let target = SweepTarget::check(settings.samples, &settings.out, settings.shard.as_deref(), settings.threads)?;
    let SweepTarget { name, directory, .. } = target.clone();
    let solver = SolverChoice::with_step(&settings.solver, settings.dt)?;
    let sweep = SampledSweep { samples: settings.samples, seed: settings.seed, fixed: settings.fixed, ranges: settings.ranges.clone() };
    sweep.check()?;
    // The held values, on Table 1's for the rest: a drawn row the model
    // refuses is that row's failure, not the sweep's (it used to abort on row 0's draw).
    settings.fixed.build()?;
    // The provenance keeps what made the file: the command and the ranges.
    let mut fixed: String =
        Parameter::ALL.iter().filter_map(|&p| settings.fixed.get(p).map(|v| format!(" {} {v}", p.def().flag()))).collect();
    if let Some(e) = settings.fixed.restitution {
        fixed.push_str(&format!(" --restitution {e}"));
    }
    for (p, v) in settings.fixed.given_ball() {
        fixed.push_str(&format!(" {} {v}", p.flag()));
    }
    for r in &settings.ranges.0 {
        fixed.push_str(&format!(" --range {}={:?},{:?}", r.parameter.name, r.range.from, r.range.to));
    }
    let text = format!(
        "# kick sweep --samples {} --seed {} --solver {}{} --law {}{fixed}\n# ranges (a parameter given is fixed):\n{}\n\
         # auto paths: no drive and c = 0 or n = 1 -> closed-form; otherwise the paper's law or the shell ball (drive >= 0) -> series; another law -> reduced\n",
        settings.samples,
        settings.seed,
        settings.solver,
        settings.dt.map(|dt| format!(" --dt {dt}")).unwrap_or_default(),
        settings.fixed.law.unwrap_or(LawKind::PowerLaw).name(),
        kick_study::sample::describe_ranges(sweep.parameters(), &sweep.ranges, settings.fixed.law.unwrap_or(LawKind::PowerLaw))
            .lines()
            .map(|l| format!("#   {l}"))
            .collect::<Vec<_>>()
            .join("\n")
    );
    let experiment = Experiment {
        name: name.clone(),
        description: format!("random sweep of {} scenarios around the baseline (seed {})", settings.samples, settings.seed),
        path: PathBuf::from(format!("kick sweep (seed {})", settings.seed)),
        read: Vec::new(),
        text,
        output: Output::Summary,
        flight: None,
        compress: settings.compress,
        kicks: Kicks::OneD(Kicks1d { solvers: vec![solver], scenarios: Scenarios::Sampled(sweep.clone()) }),
    };
    let started = std::time::Instant::now();
    let summary = match target.shard {
        None => crate::run(&experiment, &directory, true)?,
        Some(shard) => crate::shard::run_shard(&experiment, shard, &directory, true)?,
    };
    let seconds = started.elapsed().as_secs_f64();
    let auto_paths = matches!(solver, SolverChoice::Auto(_)).then(|| {
        // Which path auto took, counted from the scenarios (a pure function of them).
        let counted = (target.rows.end - target.rows.start).min(100_000);
        let mut counts = BTreeMap::new();
        for i in target.rows.start..target.rows.start + counted {
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
        shard: target.describe_shard(),
    })
}

impl Printable for SweepReport {
    fn text(&self) -> String {
        let mut w = String::new();
        let _ = writeln!(
            w,
            "{} scenarios with {} in {} s on {} threads: {} scenarios/s -> {} ({} failed)",
            self.scenarios,
            self.solver,
            kick_core::sig(self.seconds),
            self.threads,
            kick_core::sig(self.scenarios as f64 / self.seconds),
            self.path.display(),
            self.failed
        );
        if let Some(shard) = &self.shard {
            let _ = writeln!(w, "{shard} (join the parts with `kick merge`)");
        }
        if let Some((counted, counts)) = &self.auto_paths {
            let shown: Vec<String> = counts.iter().map(|(k, v)| format!("{k}: {v}")).collect();
            // Counted over the rows the model takes: none when all were refused.
            if !shown.is_empty() {
                let _ = writeln!(w, "auto paths over the first {counted} scenarios: {}", shown.join(", "));
            }
        }
        w
    }
    fn no_answer(&self) -> Option<String> {
        (self.scenarios > 0 && self.failed == self.scenarios).then(|| {
            format!(
                "every one of the {} scenarios failed; {} holds why, row by row (failures/message): check --range and the values held",
                self.scenarios,
                self.path.display()
            )
        })
    }
}
