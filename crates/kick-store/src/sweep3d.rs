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
//! Layout (`layout = "sweep3d"`; every dataset has a `units` attribute):
//!
//! ```text
//! /                                  provenance, layout, solver, law, seed, samples, rows
//!                                    (u64; `rows` the file's, `samples` the sweep's); a shard
//!                                    (`--shard I/N`) adds the attributes of [`crate::shard`]
//! /parameters/<name>                 f64[rows] or f64[rows, 3] (vectors), every declared
//!                                    1D and 3D parameter under its `simulate3d` flag's name
//!                                    (switches 0/1; restitution NaN under the paper's law)
//! /outcomes/<name>                   f64[rows] or f64[rows, 3], NaN where status != 0
//! /outcomes/energy/<name>            the energy partition, J
//! /outcomes/status                   u8[rows]: kick_core::Status codes
//! /failures/index, /failures/message rows that did not separate (u64, the file's rows) and why
//! ```

use crate::h5::{new_group, per_row, write_str_attr, write_u64_attr, Compression, H5Error, ResultWriter};
use crate::limits;
use crate::sweep::SweepTarget;
use crate::printable::Printable;
use crate::provenance::Provenance;
use kick_3d::models::{OffCenterBox, BOX_RANGES};
use kick_3d::{Kick3d, Kick3dError, KickSpec, Outcome3d, Solver3d};
use kick_core::parameters::{self, ParameterDef, SetParameter, Shape, Value};
use kick_core::{Parameter, Status};
use rand::RngExt;
use rayon::prelude::*;
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

/// Seed stream of the 1D draws, apart from the box's (which uses the seed itself).
const SCENARIO_STREAM: u64 = 0x5EED_3D00_0000_0001;

/// The random kicks of one seed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SampledKicks {
    pub seed: u64,
    /// Given parameters (held), and the law of every kick.
    pub fixed: KickSpec,
}

impl SampledKicks {
    /// The spec of kick `index`: the given parameters, the rest drawn. Every
    /// parameter takes its draws whether held or not, so holding one leaves
    /// the others as they were.
    pub fn spec(&self, index: u64) -> KickSpec {
        let [offset, approach, friction, foot_mass] = OffCenterBox::new(self.seed).values(index);
        let mut spec = self.fixed;
        let mut rng = crate::sample::row_rng(self.seed ^ SCENARIO_STREAM, index);
        let mut uniform = || rng.random::<f64>();
        for p in Parameter::ALL {
            let drawn = match p {
                Parameter::FootMass => foot_mass,
                _ => p.def().sample.map_or(f64::NAN, |range| range.draw(&mut uniform)),
            };
            if spec.scenario.get(p).is_none() {
                // A declared scalar of the 1D level: setting it cannot fail.
                let _ = spec.scenario.set_parameter(p.def(), Value::Number(drawn));
            }
        }
        let k = &mut spec.kick3d;
        k.offset = k.offset.or(Some(offset));
        k.approach_angle_deg = k.approach_angle_deg.or(Some(approach));
        k.friction = k.friction.or(Some(friction));
        spec
    }

    /// The ranges drawn from, one line each (for the file's provenance).
    pub fn ranges() -> String {
        let box_names = ["offset", "approach_angle", "friction", "foot_mass"];
        let mut lines: Vec<String> = BOX_RANGES.lines().map(String::from).collect();
        for p in Parameter::ALL.iter().map(|p| p.def()).filter(|d| !box_names.contains(&d.name)) {
            let range = p.sample.map_or_else(|| "not sampled".to_string(), |s| s.describe());
            lines.push(format!("{:<15} {range} {}", p.name, p.unit));
        }
        lines.push("every other parameter at its default".into());
        lines.join("\n")
    }
}

/// A declared parameter's value in a kick as solved: `[x, NaN, NaN]` for a
/// scalar, 0/1 for a switch. Read from the built kick, except where the kick
/// keeps a converted form (the approach angle in radians, the instep's inner
/// size), which come from the spec so a rerun from the file is the same kick.
fn solved_value(p: &ParameterDef, spec: &KickSpec, kick: Option<&Kick3d>) -> [f64; 3] {
    let one = |x: f64| [x, f64::NAN, f64::NAN];
    let nan = [f64::NAN; 3];
    if let Some(q) = Parameter::ALL.into_iter().find(|q| q.def().name == p.name) {
        return one(kick.map_or(spec.scenario.get(q).unwrap_or(f64::NAN), |k| k.base.get(q)));
    }
    let d = &spec.kick3d;
    let switch = |on: bool| one(f64::from(u8::from(on)));
    match (p.name, kick) {
        ("offset", _) => one(d.offset.unwrap_or(parameters::OFFSET.default_number())),
        ("approach_angle", _) => one(d.approach_angle_deg.unwrap_or(parameters::APPROACH_ANGLE.default_number())),
        ("friction", _) => one(d.friction.unwrap_or(Kick3d::DEFAULT_FRICTION)),
        ("foot_half_extents", _) => d.foot_half_extents.unwrap_or(kick_3d::FootShape::DEFAULT_HALF_EXTENTS),
        ("restitution", Some(k)) => one(k.base.restitution_target().unwrap_or(f64::NAN)),
        ("ball_radius", Some(k)) => one(k.ball_radius),
        ("ball_inertia", Some(k)) => one(k.ball_inertia),
        ("tangential_stiffness", Some(k)) => one(k.tangential_stiffness),
        ("tangential_damping", Some(k)) => one(k.tangential_damping),
        ("foot_inertia", Some(k)) => k.foot_inertia,
        ("border_radius", Some(k)) => one(k.foot_shape.border_radius()),
        ("gravity", Some(k)) => switch(k.gravity),
        ("ground", Some(k)) => switch(k.ground),
        _ => nan,
    }
}

/// An outcome column: name, unit, width (1 or 3), value (`[x, NaN, NaN]` for a scalar).
type OutcomeColumn = (&'static str, &'static str, usize, fn(&Outcome3d) -> [f64; 3]);

fn one(x: f64) -> [f64; 3] {
    [x, f64::NAN, f64::NAN]
}

/// The stored outcome: every vector whole, every scalar of the summary.
pub const OUTCOMES: [OutcomeColumn; 22] = [
    ("launch_velocity", "m/s", 3, |o| o.launch_velocity),
    ("spin", "rad/s", 3, |o| o.spin),
    ("foot_velocity", "m/s", 3, |o| o.foot_velocity),
    ("foot_angular_velocity", "rad/s", 3, |o| o.foot_angular_velocity),
    ("impulse", "N s", 3, |o| o.impulse),
    ("angular_impulse", "N m s", 3, |o| o.angular_impulse),
    ("angular_impulse_fixed_point", "N m s", 3, |o| o.angular_impulse_fixed_point),
    ("normal_impulse", "N s", 1, |o| one(o.normal_impulse)),
    ("contact_time", "s", 1, |o| one(o.contact_time)),
    ("peak_normal_force", "N", 1, |o| one(o.peak_normal_force)),
    ("peak_normal_force_time", "s", 1, |o| one(o.peak_normal_force_time)),
    ("peak_tangential_force", "N", 1, |o| one(o.peak_tangential_force)),
    ("peak_tangential_force_time", "s", 1, |o| one(o.peak_tangential_force_time)),
    ("max_compression", "m", 1, |o| one(o.max_compression)),
    ("max_compression_time", "s", 1, |o| one(o.max_compression_time)),
    ("slip_time", "s", 1, |o| one(o.slip_time)),
    ("speed", "m/s", 1, |o| one(o.speed)),
    ("spin_rpm", "rpm", 1, |o| one(o.spin_rpm)),
    ("launch_angle", "deg", 1, |o| one(o.launch_angle)),
    ("launch_azimuth", "deg", 1, |o| one(o.launch_azimuth)),
    ("energy_residual", "J", 1, |o| one(o.energy.residual())),
    ("evaluations", "1", 1, |o| one(o.evaluations as f64)),
];

/// The energy partition (`kick_3d::EnergyPartition`), J.
pub const ENERGY: [(&str, fn(&Outcome3d) -> f64); 9] = [
    ("kinetic_initial", |o| o.energy.kinetic_initial),
    ("ball_translation", |o| o.energy.ball_translation),
    ("ball_spin", |o| o.energy.ball_spin),
    ("foot", |o| o.energy.foot),
    ("elastic_final", |o| o.energy.elastic_final),
    ("normal_damping_loss", |o| o.energy.normal_damping_loss),
    ("friction_loss", |o| o.energy.friction_loss),
    ("drive_work", |o| o.energy.drive_work),
    ("gravity_work", |o| o.energy.gravity_work),
];


fn parameter_width(p: &ParameterDef) -> usize {
    if p.shape == Shape::Vector3 {
        3
    } else {
        1
    }
}

/// One solved row.
struct Row {
    /// Each declared parameter's value(s), in declaration order.
    parameters: Vec<[f64; 3]>,
    outcome: Result<Outcome3d, (Status, String)>,
}

fn solve_row(kicks: &SampledKicks, index: u64) -> Row {
    let spec = kicks.spec(index);
    let kick = spec.build_drawn();
    let parameters = parameters::at_levels(KickSpec::LEVELS).map(|p| solved_value(p, &spec, kick.as_ref().ok())).collect();
    let outcome = kick.and_then(|k| Solver3d::Auto.solve(&k)).map_err(|e: Kick3dError| (e.status(), e.to_string()));
    Row { parameters, outcome }
}

/// Rows solved together and written together (bounded memory: a block at a time).
const BLOCK: u64 = 8192;

/// Data bytes of a row (parameters, outcomes, status).
fn bytes_per_row() -> u64 {
    let parameters: usize = parameters::at_levels(KickSpec::LEVELS).map(parameter_width).sum();
    let outcomes: usize = OUTCOMES.iter().map(|c| c.2).sum::<usize>() + ENERGY.len();
    8 * (parameters + outcomes) as u64 + 1
}

/// Sample `settings.samples` kicks, solve them in parallel and write the file.
pub fn sweep3d(settings: &Sweep3dSettings) -> Result<Sweep3dReport, String> {
    let target = SweepTarget::check(settings.samples, &settings.out, settings.shard.as_deref(), settings.threads)?;
    let rows = target.rows.end - target.rows.start;
    limits::check_rows("--samples", settings.samples, rows, bytes_per_row(), &target.directory).map_err(|e| e.to_string())?;
    let kicks = SampledKicks { seed: settings.seed, fixed: settings.fixed };
    // A held value the model refuses is refused before the run, and so is a
    // held damping or restitution the law would ignore (the drawn damping is
    // the sampler's, not the user's).
    settings.fixed.scenario.check_given().map_err(|e| e.to_string())?;
    kicks.spec(0).build_drawn().map_err(|e| e.to_string())?;
    let law = settings.fixed.scenario.law.unwrap_or(kick_core::LawKind::PowerLaw);
    let mut given = String::new();
    for p in parameters::at_levels(KickSpec::LEVELS) {
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
    let text = format!(
        "# kick sweep3d --samples {} --seed {} --law {}{given}\n# ranges (a parameter given is held):\n{}\n",
        settings.samples,
        settings.seed,
        law.name(),
        SampledKicks::ranges().lines().map(|l| format!("#   {l}")).collect::<Vec<_>>().join("\n")
    );
    let provenance = Provenance::now(&target.name, &format!("kick sweep3d (seed {})", settings.seed), &text);
    let started = std::time::Instant::now();
    let cpu_started = cpu_seconds();
    let (path, not_separated) = write(&target, &provenance, &kicks, law, settings.compress).map_err(|e| e.to_string())?;
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
    law: kick_core::LawKind,
    compress: Compression,
) -> Result<(PathBuf, Vec<(&'static str, u64)>), H5Error> {
    let out = target.path.as_path();
    let rows = (target.rows.end - target.rows.start) as usize;
    let writer = ResultWriter::create(out, provenance, "sweep3d")?;
    let file = writer.file().clone();
    let err = |e: hdf5::Error| H5Error::Hdf5 { path: out.to_path_buf(), message: e.to_string() };
    write_str_attr(&file, out, "solver", "auto (accurate-3d off the centre line)")?;
    write_str_attr(&file, out, "law", law.name())?;
    write_u64_attr(&file, out, "seed", kicks.seed)?;
    write_u64_attr(&file, out, "samples", target.samples)?;
    write_u64_attr(&file, out, "rows", rows as u64)?;
    if let Some(shard) = target.shard {
        crate::shard::write_shard_attributes(&file, out, shard, target.samples, &provenance.experiment_text)?;
    }
    let dataset = |group: &hdf5::Group, name: &str, unit: &str, width: usize| per_row::<f64>(group, name, unit, (rows, width), compress, out);
    let parameter_group = new_group(&file, "parameters").map_err(err)?;
    let mut parameter_sets = Vec::new();
    for p in parameters::at_levels(KickSpec::LEVELS) {
        let d = dataset(&parameter_group, p.name, p.unit, parameter_width(p))?;
        write_str_attr(&d, out, "symbol", p.symbol)?;
        write_str_attr(&d, out, "description", p.doc)?;
        parameter_sets.push((d, parameter_width(p)));
    }
    let outcome_group = new_group(&file, "outcomes").map_err(err)?;
    let mut outcome_sets = Vec::new();
    for &(name, unit, width, _) in &OUTCOMES {
        outcome_sets.push((dataset(&outcome_group, name, unit, width)?, width));
    }
    let energy_group = new_group(&outcome_group, "energy").map_err(err)?;
    let energy_sets = ENERGY.iter().map(|(name, _)| dataset(&energy_group, name, "J", 1)).collect::<Result<Vec<_>, _>>()?;
    let status_set = per_row::<u8>(&outcome_group, "status", "1", (rows, 1), compress, out)?;
    let meaning = [Status::Separated, Status::NumericalFailure, Status::Trapped, Status::Refused]
        .map(|s| format!("{}: {}", s.code(), s.name()))
        .join("; ");
    write_str_attr(&status_set, out, "meaning", &meaning)?;

    let bar = crate::run::progress(rows as u64, true);
    bar.set_message("sweep3d");
    let mut failures: Vec<(u64, String)> = Vec::new();
    let mut counts = [0u64; 4];
    // Sample indices `start..end`, file rows from 0 (a shard's own rows).
    let first = target.rows.start;
    let mut start = first;
    while start < target.rows.end {
        let end = (start + BLOCK).min(target.rows.end);
        let block: Vec<Row> = (start..end).into_par_iter().map(|i| solve_row(kicks, i)).collect();
        let n = block.len();
        let range = (start - first) as usize..(end - first) as usize;
        let put = |d: &hdf5::Dataset, width: usize, value: &dyn Fn(&Row) -> [f64; 3]| -> Result<(), H5Error> {
            if width == 3 {
                let flat: Vec<f64> = block.iter().flat_map(value).collect();
                let view = ndarray::ArrayView2::from_shape((n, 3), &flat).map_err(|e| H5Error::Layout {
                    path: out.to_path_buf(),
                    message: e.to_string(),
                })?;
                d.write_slice(view, (range.clone(), ..)).map_err(err)
            } else {
                let flat: Vec<f64> = block.iter().map(|r| value(r)[0]).collect();
                d.write_slice(&flat, range.clone()).map_err(err)
            }
        };
        for (k, (d, width)) in parameter_sets.iter().enumerate() {
            put(d, *width, &|r: &Row| r.parameters[k])?;
        }
        for ((d, width), (_, _, _, get)) in outcome_sets.iter().zip(&OUTCOMES) {
            put(d, *width, &|r: &Row| r.outcome.as_ref().map_or([f64::NAN; 3], get))?;
        }
        for (d, (_, get)) in energy_sets.iter().zip(ENERGY) {
            put(d, 1, &|r: &Row| one(r.outcome.as_ref().map_or(f64::NAN, get)))?;
        }
        let status: Vec<u8> = block.iter().map(|r| r.outcome.as_ref().map_or_else(|(s, _)| s.code(), |_| Status::Separated.code())).collect();
        status_set.write_slice(&status, range.clone()).map_err(err)?;
        for (i, row) in block.iter().enumerate() {
            let code = status[i];
            counts[usize::from(code).min(3)] += 1;
            if let Err((_, message)) = &row.outcome {
                failures.push((start - first + i as u64, message.clone()));
            }
        }
        bar.inc(n as u64);
        start = end;
    }
    bar.finish_and_clear();
    let index: Vec<u64> = failures.iter().map(|(i, _)| *i).collect();
    let messages: Vec<String> = failures.into_iter().map(|(_, m)| m).collect();
    let failure_group = new_group(&file, "failures").map_err(err)?;
    match compress {
        Compression::None => crate::h5::write_indices(&failure_group, out, "index", "1", &index)?,
        _ => {
            let d = per_row::<u64>(&failure_group, "index", "1", (index.len(), 1), compress, out)?;
            if !index.is_empty() {
                d.write(&index).map_err(err)?;
            }
        }
    }
    writer.strings("failures", "message", &messages)?;
    drop(file);
    let path = writer.finish()?;
    let not_separated = [Status::NumericalFailure, Status::Trapped, Status::Refused]
        .into_iter()
        .map(|s| (s.name(), counts[usize::from(s.code())]))
        .filter(|&(_, n)| n > 0)
        .collect();
    Ok((path, not_separated))
}

impl Printable for Sweep3dReport {
    fn text(&self) -> String {
        let mut w = String::new();
        let failed: u64 = self.not_separated.iter().map(|(_, n)| n).sum();
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
