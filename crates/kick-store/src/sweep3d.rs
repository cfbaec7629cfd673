//! `kick sweep3d --samples N --seed S --out FILE.h5 [--range NAME=LOW,HIGH]...
//! [--flight [--distance D]...] [--compress [LEVEL]]`: random off-center
//! kicks around the baseline, solved (and flown) in parallel, written to one
//! HDF5 file (compressed: [`crate::h5::Compression`]).
//!
//! Kick `i` of seed `s` ([`SampledKicks`], kick-study's `level::sampled_3d`):
//! offset, approach angle, friction and foot mass from the off-center box
//! (`kick_3d::models::OffCenterBox`, the box where the accurate path states
//! its speed and accuracy), every other parameter with a sampling range
//! from it (`--range`, else the declared one: the 1D parameters, the
//! tangential spring, the shell ball's pressure under `--law shell`), every
//! other parameter at its default. A parameter given on the command line is
//! held there instead. Rows are pure functions of (seed, index) and are
//! written in index order, so the data do not depend on the thread count.
//! With `--shard I/N` only samples `floor(I*N_s/N) .. floor((I+1)*N_s/N)` are
//! solved, into `NAME.shard-I-of-N.h5` (file rows from 0; see [`crate::shard`]
//! for the merge).
//!
//! The file is a sweep table ([`crate::h5`], the one result layout): one
//! row per kick, `/parameters/<name>` every declared parameter the kicks'
//! law uses (vectors as `_x`, `_y`, `_z` columns, switches 0/1; the
//! instep's only when one is given; each with `symbol` and `description`
//! attributes) and every flight parameter drawn, `/outcomes/<name>`
//! kick-3d's [`kick_3d::OBSERVABLES_3D`] of the set `auto-3d` and, with
//! `--flight`, the set `auto-3d+flight` (the flight from the ground after
//! the kick, `kick_study::flight::FlightPlan::columns`), status codes of
//! `kick_core::Status`; root attributes `level = "3d"`, `law` (the set's
//! setting), `seed` and `samples` (the sweep's; `rows` is the file's), and a
//! shard's attributes ([`crate::shard`]). The provenance's experiment text
//! ends with the held spec exactly (`# held:`, then `#   name = value` TOML
//! lines, with `[range]` and `[flight]` tables), from which `kick merge`
//! redraws every row's parameters.

use crate::error::StoreError;
use crate::h5::{write_str_attr, write_u64_attr, Compression, H5Error};
use crate::limits;
use crate::printable::Printable;
use crate::provenance::Provenance;
use crate::sweep::SweepTarget;
use crate::table::{create_table, fill_table, finish_table, RunError};
use kick_3d::KickSpec;
use kick_core::parameters::{self, SetParameter};
use kick_core::Status;
use kick_study::flight::FlightPlan;
pub use kick_study::level::sampled_3d::{find_range, SampledKicks, SampledSweep3d};
use kick_study::level::Level;
use kick_study::sample::Ranges;
use serde::Serialize;
use std::fmt::Write as _;
use std::path::PathBuf;

/// What to sweep.
#[derive(Debug, Clone, PartialEq)]
pub struct Sweep3dSettings {
    pub samples: u64,
    pub seed: u64,
    /// Result file NAME.h5 (its directory is created).
    pub out: PathBuf,
    /// Parameters held fixed instead of drawn, and the normal contact law.
    pub fixed: KickSpec,
    /// Ranges drawn from instead of the box's and the declared ones (`--range`, parsed).
    pub ranges: Ranges,
    /// `--flight`: each kick flown from the ground after it.
    pub flight: Option<FlightPlan>,
    /// `--shard I/N` as given: only that slice of the samples (see [`crate::sweep`]).
    pub shard: Option<String>,
    /// `--threads`: worker threads (default: one per core).
    pub threads: Option<usize>,
    /// `--compress [LEVEL]`: how the per-row datasets are stored.
    pub compress: crate::h5::Compression,
}

/// What a sweep did.
#[derive(Debug, Clone, Serialize)]
pub struct Sweep3dReport {
    pub kicks: u64,
    pub seconds: f64,
    /// CPU time of the process over the sweep (all threads), s: the machine's
    /// load does not enter it, unlike `seconds`.
    pub cpu_seconds: Option<f64>,
    pub threads: usize,
    pub path: PathBuf,
    /// Rows per status other than separated: (status name, count).
    pub not_separated: Vec<(&'static str, u64)>,
    /// With `--flight`: the rows flown, and those not flown per status (a
    /// kick that failed, or a ball that does not leave the ground: refused).
    pub flown: Option<(u64, Vec<(&'static str, u64)>)>,
    /// With `--shard`: which shard and samples.
    pub shard: Option<String>,
}

/// Sample `settings.samples` kicks, solve them in parallel and write the file.
pub fn sweep3d(settings: &Sweep3dSettings) -> Result<Sweep3dReport, StoreError> {
    let target = SweepTarget::check(settings.samples, &settings.out, settings.shard.as_deref(), settings.threads)?;
    let rows = target.rows.end - target.rows.start;
    let kicks = SampledKicks { seed: settings.seed, fixed: settings.fixed, ranges: settings.ranges.clone() };
    kicks.check(settings.flight.as_ref())?;
    let level = SampledSweep3d::new(kicks.clone(), settings.samples, settings.flight.clone());
    limits::check_rows("--samples", settings.samples, rows, level.bytes_per_row(), &target.directory)?;
    // A held value the model refuses is refused before the run, and so is a
    // held damping or restitution the law would ignore (the drawn damping is
    // the sampler's, not the user's): the held values on Table 1's and the
    // declared defaults for the rest. A drawn row the model refuses is that
    // row's failure, not the sweep's (it used to abort on row 0's draw).
    settings.fixed.build()?;
    let law = settings.fixed.scenario.law.unwrap_or(kick_core::LawKind::PowerLaw);
    let mut given = String::new();
    for p in parameters::at_levels(KickSpec::LEVELS) {
        if let Some(value) = settings.fixed.value(p) {
            let shown: Vec<String> = value.numbers().iter().map(|x| x.to_string()).collect();
            let _ = write!(given, " {} {}", p.flag(), shown.join(","));
        }
    }
    for r in &settings.ranges.0 {
        let _ = write!(given, " --range {}={:?},{:?}", r.parameter.name, r.range.from, r.range.to);
    }
    if let Some(plan) = &settings.flight {
        let _ = write!(given, " --flight");
        for d in plan.distances() {
            let _ = write!(given, " --distance {d:?}");
        }
    }
    let text = format!(
        "# kick sweep3d --samples {} --seed {} --law {}{given}\n# ranges (a parameter given is held):\n{}\n{}",
        settings.samples,
        settings.seed,
        law.name(),
        kicks.describe_ranges().lines().map(|l| format!("#   {l}")).collect::<Vec<_>>().join("\n"),
        crate::held::held_text(&settings.fixed, &settings.ranges, settings.flight.as_ref())
    );
    let provenance = Provenance::now(&target.name, &format!("kick sweep3d (seed {})", settings.seed), &text);
    let started = std::time::Instant::now();
    let cpu_started = cpu_seconds();
    let (path, not_separated, flown) = write(&target, &provenance, &level, settings.compress)?;
    Ok(Sweep3dReport {
        kicks: rows,
        shard: target.describe_shard(),
        seconds: started.elapsed().as_secs_f64(),
        cpu_seconds: cpu_started.zip(cpu_seconds()).map(|(a, b)| b - a),
        threads: rayon::current_num_threads(),
        path,
        not_separated,
        flown,
    })
}

/// User plus system CPU time of this process so far, s (None where it cannot be asked).
#[cfg(unix)]
pub fn cpu_seconds() -> Option<f64> {
    // SAFETY: getrusage fills the zeroed struct.
    let mut usage: libc::rusage = unsafe { std::mem::zeroed() };
    if unsafe { libc::getrusage(libc::RUSAGE_SELF, &mut usage) } != 0 {
        return None;
    }
    let seconds = |t: libc::timeval| t.tv_sec as f64 + t.tv_usec as f64 * 1e-6;
    Some(seconds(usage.ru_utime) + seconds(usage.ru_stime))
}

#[cfg(not(unix))]
pub fn cpu_seconds() -> Option<f64> {
    None
}

fn write(
    target: &SweepTarget,
    provenance: &Provenance,
    level: &SampledSweep3d,
    compress: Compression,
) -> Result<(PathBuf, Vec<(&'static str, u64)>, Option<(u64, Vec<(&'static str, u64)>)>), RunError> {
    let out = target.path.as_path();
    let rows = target.rows.end - target.rows.start;
    let mut writer = create_table(level, out, provenance, rows, compress)?;
    let file = writer.file().clone();
    write_str_attr(&file, out, "level", "3d")?;
    write_u64_attr(&file, out, "seed", level.kicks.seed)?;
    write_u64_attr(&file, out, "samples", target.samples)?;
    // Symbol and meaning of every parameter column, from its declaration.
    let flight: Vec<&'static parameters::ParameterDef> = level.kicks.flight_parameters();
    for p in level.kicks.row_parameters().into_iter().chain(flight) {
        for name in p.columns() {
            let d = file.dataset(&format!("parameters/{name}")).map_err(|e| H5Error::hdf5(out, &e))?;
            write_str_attr(&d, out, "symbol", p.symbol)?;
            write_str_attr(&d, out, "description", p.doc)?;
        }
    }
    if let Some(shard) = target.shard {
        crate::shard::write_shard_attributes(&file, out, shard, target.samples, &provenance.experiment_text)?;
    }
    drop(file);
    let bar = crate::table::progress(rows, true);
    bar.set_message("sweep3d");
    fill_table(level, target.rows.clone(), &mut writer, &bar)?;
    let counts = writer.status_counts(0);
    let flight_counts = level.flight.as_ref().map(|_| writer.status_counts(1));
    finish_table(level, writer, &bar)?;
    let others = |counts: &[u64]| -> Vec<(&'static str, u64)> {
        Status::ALL[1..].iter().copied().map(|s| (s.name(), counts[usize::from(s.code())])).filter(|&(_, n)| n > 0).collect()
    };
    let flown = flight_counts.map(|c| (c[usize::from(Status::Separated.code())], others(&c)));
    Ok((out.to_path_buf(), others(&counts), flown))
}

impl Printable for Sweep3dReport {
    fn text(&self) -> String {
        let mut w = String::new();
        // Rows outside their law's validity keep their numbers: not failures.
        let failed: u64 = self.not_separated.iter().filter(|(s, _)| *s != Status::OutsideValidity.name()).map(|(_, n)| n).sum();
        let _ = writeln!(
            w,
            "{} kicks with auto in {} s on {} threads: {} kicks/s -> {} ({failed} not separated)",
            self.kicks,
            kick_core::sig(self.seconds),
            self.threads,
            kick_core::sig(self.kicks as f64 / self.seconds),
            self.path.display(),
        );
        // An empty shard has no per-kick cost to give.
        if let Some(cpu) = self.cpu_seconds.filter(|_| self.kicks > 0) {
            let _ = writeln!(
                w,
                "CPU time {} s: {} us per kick, {} kicks/s per busy core",
                kick_core::sig(cpu),
                kick_core::sig(cpu / self.kicks as f64 * 1e6),
                kick_core::sig(self.kicks as f64 / cpu)
            );
        }
        for (status, n) in &self.not_separated {
            let _ = writeln!(w, "  {status}: {n}");
        }
        if let Some((flown, not)) = &self.flown {
            let shown: Vec<String> = not.iter().map(|(s, n)| format!("{s} {n}")).collect();
            let _ = writeln!(
                w,
                "flights: {flown} flown to the ground{}",
                if shown.is_empty() { String::new() } else { format!(", not flown: {}", shown.join(", ")) }
            );
        }
        if let Some(shard) = &self.shard {
            let _ = writeln!(w, "{shard} (join the parts with `kick merge`)");
        }
        w
    }
    fn no_answer(&self) -> Option<String> {
        // Trapped is an answer (physics); refused and failed rows are not.
        let none: u64 = self
            .not_separated
            .iter()
            .filter(|(s, _)| [Status::Refused.name(), Status::NumericalFailure.name()].contains(s))
            .map(|(_, n)| n)
            .sum();
        (self.kicks > 0 && none == self.kicks).then(|| {
            format!(
                "every one of the {} kicks was refused or failed; {} holds why, row by row (failures/message): check --range and the values held",
                self.kicks,
                self.path.display()
            )
        })
    }
}
