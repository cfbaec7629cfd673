//! `kick sweep3d --samples N --seed S --out FILE.h5 [--compress [LEVEL]]`:
//! random off-center kicks around the baseline, solved in parallel, written
//! to one HDF5 file (compressed: [`crate::h5::Compression`]).
//!
//! Kick `i` of seed `s` ([`SampledKicks`]): offset, approach angle, friction
//! and foot mass from the off-center box (`kick_3d::models::OffCenterBox`, the
//! box where the accurate path states its speed and accuracy), the other 1D
//! parameters from their declared sampling ranges (`kick_core::parameters`),
//! every other 3D parameter at its default. A parameter given on the command
//! line is held there instead. Rows are pure functions of (seed, index) and
//! are written in index order, so the data do not depend on the thread count.
//! With `--shard I/N` only samples `floor(I*N_s/N) .. floor((I+1)*N_s/N)` are
//! solved, into `NAME.shard-I-of-N.h5` (file rows from 0; see [`crate::shard`]
//! for the merge).
//!
//! The file is a sweep table ([`crate::h5`], the one result layout): one
//! row per kick, `/parameters/<name>` every declared 1D and 3D parameter
//! (vectors as `_x`, `_y`, `_z` columns, switches 0/1, restitution NaN
//! under the paper's law; each with `symbol` and `description` attributes),
//! `/outcomes/<name>` kick-3d's [`kick_3d::OBSERVABLES_3D`] of the set
//! `auto-3d`, status codes of `kick_core::Status`; root attributes `level =
//! "3d"`, `law` (the set's setting), `seed` and `samples` (the sweep's; `rows` is the file's),
//! and a shard's attributes ([`crate::shard`]). The provenance's experiment
//! text ends with the held spec exactly (`# held:`, then `#   name = value`
//! TOML lines), from which `kick merge` redraws every row's parameters.

use crate::error::StoreError;
use crate::h5::{write_str_attr, write_u64_attr, Compression, H5Error};
use crate::limits;
use crate::printable::Printable;
use crate::provenance::Provenance;
use crate::run::{create_table, fill_table, finish_table, RunError};
use crate::sweep::SweepTarget;
use kick_3d::KickSpec;
use kick_core::parameters::{self, SetParameter, Shape};
use kick_core::{Parameter, Status};
pub use kick_study::level::sampled_3d::{solved_value, SampledKicks, SampledSweep3d};
use kick_study::level::Level;
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
    /// With `--shard`: which shard and samples.
    pub shard: Option<String>,
}

/// Sample `settings.samples` kicks, solve them in parallel and write the file.
pub fn sweep3d(settings: &Sweep3dSettings) -> Result<Sweep3dReport, StoreError> {
    let target = SweepTarget::check(settings.samples, &settings.out, settings.shard.as_deref(), settings.threads)?;
    let rows = target.rows.end - target.rows.start;
    limits::check_rows(
        "--samples",
        settings.samples,
        rows,
        SampledSweep3d { kicks: SampledKicks { seed: settings.seed, fixed: settings.fixed }, samples: settings.samples }.bytes_per_row(),
        &target.directory,
    )?;
    let kicks = SampledKicks { seed: settings.seed, fixed: settings.fixed };
    // A held value the model refuses is refused before the run, and so is a
    // held damping or restitution the law would ignore (the drawn damping is
    // the sampler's, not the user's).
    settings.fixed.scenario.check_given()?;
    kicks.spec(0).build_drawn()?;
    let law = settings.fixed.scenario.law.unwrap_or(kick_core::LawKind::PowerLaw);
    let mut given = String::new();
    for p in parameters::at_levels(KickSpec::ROW_LEVELS) {
        let value = solved_value(p, &settings.fixed, None);
        let held = match p.name {
            "offset" => settings.fixed.kick3d.offset.is_some(),
            "approach_angle" => settings.fixed.kick3d.approach_angle_deg.is_some(),
            "friction" => settings.fixed.kick3d.friction.is_some(),
            _ => Parameter::ALL.iter().any(|q| q.def().name == p.name && settings.fixed.scenario.get(*q).is_some()),
        };
        if held {
            let _ = write!(given, " {} {}", p.flag(), value[0]);
        }
    }
    for (p, v) in settings.fixed.scenario.given_ball() {
        let _ = write!(given, " {} {v}", p.flag());
    }
    let text = format!(
        "# kick sweep3d --samples {} --seed {} --law {}{given}\n# ranges (a parameter given is held):\n{}\n{}",
        settings.samples,
        settings.seed,
        law.name(),
        SampledKicks::ranges().lines().map(|l| format!("#   {l}")).collect::<Vec<_>>().join("\n"),
        held_text(&settings.fixed)
    );
    let provenance = Provenance::now(&target.name, &format!("kick sweep3d (seed {})", settings.seed), &text);
    let started = std::time::Instant::now();
    let cpu_started = cpu_seconds();
    let (path, not_separated) = write(&target, &provenance, &kicks, settings.compress)?;
    Ok(Sweep3dReport {
        kicks: rows,
        shard: target.describe_shard(),
        seconds: started.elapsed().as_secs_f64(),
        cpu_seconds: cpu_started.zip(cpu_seconds()).map(|(a, b)| b - a),
        threads: rayon::current_num_threads(),
        path,
        not_separated,
    })
}

/// The first line of the held parameters in a sweep's provenance text.
const HELD: &str = "# held:";

/// The held spec, every given value exactly (TOML, `#   name = value`
/// lines under [`HELD`]), so a merge can redraw the sweep's rows; nothing
/// (and no check at the merge) should it not serialize.
fn held_text(fixed: &KickSpec) -> String {
    let table = || -> Option<String> {
        let mut table = toml::Table::try_from(fixed.scenario).ok()?;
        table.extend(toml::Table::try_from(fixed.kick3d).ok()?);
        toml::to_string(&table).ok()
    };
    let Some(lines) = table() else { return String::new() };
    let mut text = format!("{HELD}\n");
    for line in lines.lines().filter(|l| !l.is_empty()) {
        let _ = writeln!(text, "#   {line}");
    }
    text
}

/// The sampled sweep a part of `kick sweep3d` was cut from: its seed and
/// samples (root attributes) and the held spec of its provenance `text`;
/// None when the text has no held spec this version can read.
pub(crate) fn sampled_sweep(text: &str, seed: u64, samples: u64) -> Option<SampledSweep3d> {
    let held = text.split_once(&format!("\n{HELD}\n"))?.1;
    let lines: Vec<&str> = held.lines().map(|l| l.strip_prefix("#   ")).collect::<Option<_>>()?;
    let table: toml::Table = lines.join("\n").parse().ok()?;
    let mut fixed = KickSpec::default();
    for (name, value) in table {
        let value = match value {
            toml::Value::String(law) if name == "law" => {
                fixed.scenario.law = Some(kick_core::LawKind::from_name(&law).ok()?);
                continue;
            }
            toml::Value::Float(x) => parameters::Value::Number(x),
            toml::Value::Integer(x) => parameters::Value::Number(x as f64),
            toml::Value::Boolean(on) => parameters::Value::Switch(on),
            toml::Value::Array(xs) => {
                let xs: Vec<f64> = xs.iter().map(|x| x.as_float().or_else(|| x.as_integer().map(|i| i as f64))).collect::<Option<_>>()?;
                parameters::Value::Vector(xs.try_into().ok()?)
            }
            _ => return None,
        };
        fixed.set_named(&name, value).ok()?;
    }
    Some(SampledSweep3d { kicks: SampledKicks { seed, fixed }, samples })
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
    kicks: &SampledKicks,
    compress: Compression,
) -> Result<(PathBuf, Vec<(&'static str, u64)>), RunError> {
    let out = target.path.as_path();
    let rows = target.rows.end - target.rows.start;
    let level = SampledSweep3d { kicks: *kicks, samples: target.samples };
    let mut writer = create_table(&level, out, provenance, rows, compress)?;
    let file = writer.file().clone();
    write_str_attr(&file, out, "level", "3d")?;
    write_u64_attr(&file, out, "seed", kicks.seed)?;
    write_u64_attr(&file, out, "samples", target.samples)?;
    // Symbol and meaning of every parameter column, from its declaration.
    for p in parameters::at_levels(KickSpec::ROW_LEVELS) {
        let names: Vec<String> = match p.shape {
            Shape::Vector3 => ["x", "y", "z"].map(|a| format!("{}_{a}", p.name)).to_vec(),
            _ => vec![p.name.to_string()],
        };
        for name in names {
            let d = file.dataset(&format!("parameters/{name}")).map_err(|e| H5Error::hdf5(out, &e))?;
            write_str_attr(&d, out, "symbol", p.symbol)?;
            write_str_attr(&d, out, "description", p.doc)?;
        }
    }
    if let Some(shard) = target.shard {
        crate::shard::write_shard_attributes(&file, out, shard, target.samples, &provenance.experiment_text)?;
    }
    drop(file);
    let bar = crate::run::progress(rows, true);
    bar.set_message("sweep3d");
    fill_table(&level, target.rows.clone(), &mut writer, &bar)?;
    let counts = writer.status_counts(0);
    finish_table(&level, writer, &bar)?;
    let not_separated =
        Status::ALL[1..].iter().copied().map(|s| (s.name(), counts[usize::from(s.code())])).filter(|&(_, n)| n > 0).collect();
    Ok((out.to_path_buf(), not_separated))
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
        if let Some(cpu) = self.cpu_seconds {
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
        if let Some(shard) = &self.shard {
            let _ = writeln!(w, "{shard} (join the parts with `kick merge`)");
        }
        w
    }
}
