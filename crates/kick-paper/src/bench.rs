//! `kick bench`: work–precision of every 1D solver, the headline ratios, and
//! sweep throughput, measured in one run of one binary.
//!
//! What depends on the clock (times, ratios, throughput, the work–precision
//! figure, whose x axis is time) goes to the timing file and page, with the
//! machine's description; `kick reproduce` puts them in `results/timing/` and
//! `paper/timing.md`, the only outputs a second run may change. Errors and
//! evaluation counts do not depend on the clock: they make the solvers page.

use crate::figures::{save_grid, Panel, Series};
use crate::h5::{write_f64_attr, write_strings, Column, OutcomeSet, Setting, SweepData};
use crate::printable::Printable;
use crate::sample::SampledSweep;
use crate::Provenance;
use kick_compliant::precision::{self, PrecisionPoint};
use kick_compliant::SolverChoice;
use kick_core::Solver;
use kick_store::SweepWriter;
use plotters::prelude::SeriesLabelPosition;
use rayon::prelude::*;
use serde::Serialize;
use std::io::Write;
use std::path::PathBuf;
use std::time::Instant;

/// What to measure and where to write it.
#[derive(Debug, Clone, PartialEq)]
pub struct BenchSettings {
    /// Directory for work_precision.h5, timing-dependent (figures go to DIR/figures).
    pub out: PathBuf,
    /// Least wall time per measured point, s.
    pub min_time: f64,
    /// Scenarios in the throughput sweep.
    pub sweep_samples: u64,
    /// Short variant for CI: a few ladder points, little time each.
    pub quick: bool,
    /// Also write a Markdown page with the measured times here (with the machine's description).
    pub report: Option<PathBuf>,
    /// Also write the solvers' page here: what `auto` runs, errors and evaluation counts, trust regions
    /// (no time: the same on every run).
    pub solvers_report: Option<PathBuf>,
}

impl Default for BenchSettings {
    fn default() -> Self {
        BenchSettings {
            out: PathBuf::from("results"),
            min_time: 0.3,
            sweep_samples: 200_000,
            quick: false,
            report: None,
            solvers_report: None,
        }
    }
}

/// The headline numbers of a bench run and the files it wrote.
#[derive(Debug, Clone, Serialize)]
pub struct BenchReport {
    /// seed-rk4 / auto cost ratio (median of 5 alternating measurements).
    pub cost_ratio: f64,
    pub auto_max_error: f64,
    pub seed_max_error: f64,
    pub sweep_per_second_1_thread: f64,
    pub sweep_per_second_2_threads: f64,
    /// Off-center 3D kick / its 1D contact, both `auto`, one core.
    pub off_center_3d_vs_1d_cost_ratio: f64,
    /// The shell ball's 1D cost over the paper law's (auto, one thread).
    pub shell_vs_paper_law_1d_cost_ratio: f64,
    /// The 1D kick with the leg and its boot over the shell ball's (auto, one thread; issue 31: at most 2).
    pub leg_boot_vs_shell_1d_cost_ratio: f64,
    /// Free kicks through `flight_many` on 2 threads.
    pub flights_per_second_2_threads: f64,
    /// Flown 3D kicks into a file on 2 threads (`sweep3d --flight`, shell ball; issue 32: at least 10,000).
    pub sweep3d_flown_rows_per_second_2_threads: f64,
    #[serde(skip)]
    pub written: Vec<PathBuf>,
}

impl Printable for BenchReport {
    fn text(&self) -> String {
        self.written.iter().map(|p| format!("-> {}\n", p.display())).collect()
    }
}

const COLUMNS: [(&str, &str); 5] = [
    ("max_error", "1"),
    ("max_error_closed_form", "1"),
    ("max_error_tight_reference", "1"),
    ("seconds_per_scenario", "s"),
    ("evaluations_per_scenario", "1"),
];

/// A timing repeated in one run: its median and range.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Spread {
    pub median: f64,
    pub low: f64,
    pub high: f64,
}

impl Spread {
    /// Of `values` (at least one).
    pub fn of(values: &[f64]) -> Spread {
        let mut sorted = values.to_vec();
        sorted.sort_by(f64::total_cmp);
        Spread { median: sorted[sorted.len() / 2], low: sorted[0], high: sorted[sorted.len() - 1] }
    }

    /// Of the ratios a_i / b_i of measurements taken in alternation.
    pub fn of_ratios(a: &[f64], b: &[f64]) -> Spread {
        Spread::of(&a.iter().zip(b).map(|(x, y)| x / y).collect::<Vec<_>>())
    }

    /// `median (range low–high)` with `decimals` decimals, `unit` after each number.
    fn show(&self, decimals: usize, unit: &str) -> String {
        format!("{:.decimals$}{unit} (range {:.decimals$}–{:.decimals$}{unit})", self.median, self.low, self.high)
    }
}

/// Scenarios per second of `solver` on the sweep, on a pool of `threads`.
fn throughput(solver: &SolverChoice, sweep: SampledSweep, threads: usize) -> Result<f64, String> {
    let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().map_err(|e| e.to_string())?;
    let started = Instant::now();
    let solved = pool.install(|| {
        (0..sweep.samples).into_par_iter().map(|i| sweep.scenario(i).and_then(|s| solver.solve(&s)).is_ok() as u64).sum::<u64>()
    });
    std::hint::black_box(solved);
    Ok(sweep.samples as f64 / started.elapsed().as_secs_f64())
}

/// Flights per second through `kick_flight::flight_many` on a pool of
/// `threads`: `rows` free kicks of `kick_flight::models::free_kick_speeds`
/// (the criterion bench's flights), outcomes only.
fn flights_per_second(rows: usize, threads: usize) -> Result<f64, String> {
    let (base, speeds) = kick_flight::models::free_kick_speeds(rows);
    let columns = [kick_flight::Column { parameter: kick_flight::FlightParameter::Speed, values: &speeds }];
    let started = Instant::now();
    let out = kick_flight::flight_many(&base, &columns, rows, Some(threads)).map_err(|e| e.to_string())?;
    let seconds = started.elapsed().as_secs_f64();
    if let Some(Err(e)) = out.iter().find(|r| r.is_err()) {
        return Err(format!("a bench flight failed: {e}"));
    }
    Ok(rows as f64 / seconds)
}

/// Seconds of each aim solve of paper/flight.md ([`crate::free_kick::aim_requests`]:
/// the launch, then through the 3D kick), `repeats` times in alternation.
fn aim_seconds(repeats: usize) -> Result<[Vec<f64>; 2], String> {
    let requests = crate::free_kick::aim_requests();
    let mut seconds: [Vec<f64>; 2] = Default::default();
    for _ in 0..repeats {
        for (request, out) in requests.iter().zip(seconds.iter_mut()) {
            let started = Instant::now();
            std::hint::black_box(kick_study::aim::aim(request).map_err(|e| e.to_string())?);
            out.push(started.elapsed().as_secs_f64());
        }
    }
    Ok(seconds)
}

/// How many forms [`kick_costs`] times.
pub const KICK_FORMS: usize = 10;

/// One off-center 3D kick (Table 1, 5 cm offset, `accurate`, one core) in
/// [`KICK_FORMS`] forms, µs per kick and evaluations, timed in alternation,
/// medians: the default spring at μ = ∞, a stiff spring at μ = 0.5
/// (k_t = 1e9 N/m, which tends to rigid grip at that μ), rigid grip as a
/// constraint (k_t = ∞), the shell ball at μ = 0.5; then the shell ball's
/// patch (issue 22's ≤ 100 µs at any μ): on the knife-edge face at μ = 0.5
/// and in rigid grip at μ = ∞, and on a convex instep (the assumed cap,
/// face square) likewise; that rigid kick again on the baseline x86-64 copy
/// (`Accurate3d::solve_baseline`: what a CPU without AVX2 runs); and the
/// realistic foot (`--leg`: the leg's 6×6 apparent inertia and its boot) on
/// the cap's patch at μ = 0.5 (issue 31: ≤ 120 µs).
fn kick_costs(min_seconds: f64) -> Result<[(Vec<f64>, u64); KICK_FORMS], String> {
    use kick_3d::{Accurate3d, Kick3dSpec, KickSpec};
    let at = |scenario: kick_core::ScenarioSpec, kick3d: Kick3dSpec| KickSpec { scenario, kick3d }.build().map_err(|e| e.to_string());
    let spec = Kick3dSpec { offset: Some(0.05), friction: Some(f64::INFINITY), ..Kick3dSpec::default() };
    let shell = kick_core::ScenarioSpec { law: Some(kick_core::LawKind::Shell), ..Default::default() };
    let cap = Kick3dSpec {
        patch_contact: Some(true),
        instep_radius: Some(kick_3d::validation::ASSUMED_INSTEP_RADIUS),
        face_yaw_deg: Some(0.0),
        ..spec
    };
    let kicks = [
        at(Default::default(), spec)?,
        at(Default::default(), Kick3dSpec { tangential_stiffness: Some(1e9), friction: Some(0.5), ..spec })?,
        at(Default::default(), Kick3dSpec { tangential_stiffness: Some(f64::INFINITY), ..spec })?,
        at(shell, Kick3dSpec { friction: Some(0.5), ..spec })?,
        at(shell, Kick3dSpec { friction: Some(0.5), patch_contact: Some(true), ..spec })?,
        at(shell, Kick3dSpec { tangential_stiffness: Some(f64::INFINITY), patch_contact: Some(true), ..spec })?,
        at(shell, Kick3dSpec { friction: Some(0.5), ..cap })?,
        at(shell, Kick3dSpec { tangential_stiffness: Some(f64::INFINITY), ..cap })?,
        at(kick_core::ScenarioSpec { leg: Some(true), ..shell }, Kick3dSpec { friction: Some(0.5), ..cap })?,
    ];
    let solver = Accurate3d::default();
    let mut times: [Vec<f64>; KICK_FORMS] = Default::default();
    let mut evaluations = [0u64; KICK_FORMS];
    let forms: Vec<(&kick_3d::Kick3d, bool)> =
        kicks[..8].iter().map(|k| (k, false)).chain([(&kicks[7], true), (&kicks[8], false)]).collect();
    for _ in 0..5 {
        for (i, &(kick, baseline)) in forms.iter().enumerate() {
            let (mut runs, started) = (0u32, Instant::now());
            while runs == 0 || started.elapsed().as_secs_f64() < min_seconds {
                let solved = if baseline { solver.solve_baseline(kick) } else { solver.solve(kick) };
                evaluations[i] = std::hint::black_box(solved.map_err(|e| e.to_string())?).evaluations;
                runs += 1;
            }
            times[i].push(started.elapsed().as_secs_f64() / f64::from(runs));
        }
    }
    let mut out: [(Vec<f64>, u64); KICK_FORMS] = Default::default();
    for i in 0..KICK_FORMS {
        out[i] = (times[i].iter().map(|t| t * 1e6).collect(), evaluations[i]);
    }
    Ok(out)
}

/// The most accurate point of the fixed-step family (`rk4-events`) and the
/// cheapest `auto` point at least as accurate, from the ladder: the pair
/// whose cost ratio is the cost at equal accuracy.
pub fn equal_accuracy_pair(points: &[PrecisionPoint]) -> Option<(&PrecisionPoint, &PrecisionPoint)> {
    let fixed = points.iter().filter(|p| p.solver == "rk4-events").min_by(|a, b| a.max_error.total_cmp(&b.max_error))?;
    let auto = points
        .iter()
        .filter(|p| p.solver == "auto" && p.max_error <= fixed.max_error)
        .max_by(|a, b| a.setting.total_cmp(&b.setting).then(b.seconds_per_scenario.total_cmp(&a.seconds_per_scenario)))?;
    Some((fixed, auto))
}

/// Largest errors over the first `samples` scenarios of the sweep's box
/// (`kick sweep --seed 1`) of the solvers `auto` chooses among, at their
/// defaults, against `accurate` at the reference tolerance.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BoxErrors {
    pub samples: u64,
    /// Scenarios the reference finds trapped (no separation): left out.
    pub trapped: u64,
    /// (solver, largest error as `precision::max_relative_error`, scenarios it applies to).
    pub errors: Vec<(&'static str, f64, u64)>,
}

/// The solvers [`box_errors`] measures.
pub const BOX_SOLVERS: [&str; 4] = ["series", "reduced-return", "reduced", "auto"];

/// [`BoxErrors`] over `samples` scenarios; a solver that fails where the
/// reference separates is an error naming it.
pub fn box_errors(samples: u64) -> Result<BoxErrors, String> {
    let sweep = SampledSweep::new(samples, 1);
    let tight = kick_compliant::Accurate::new(precision::REFERENCE_TOLERANCE, precision::REFERENCE_TOLERANCE).map_err(|e| e.to_string())?;
    let solvers: Vec<SolverChoice> =
        BOX_SOLVERS.iter().map(|n| SolverChoice::from_name(n, 5e-6)).collect::<Result<_, _>>().map_err(|e| e.to_string())?;
    let mut errors: Vec<(&'static str, f64, u64)> = BOX_SOLVERS.iter().map(|&n| (n, 0.0, 0)).collect();
    let mut trapped = 0;
    for i in 0..samples {
        let scenario = sweep.scenario(i).map_err(|e| e.to_string())?;
        let reference = match tight.solve(&scenario) {
            Ok(o) => o,
            Err(kick_core::KickError::Trapped { .. }) => {
                trapped += 1;
                continue;
            }
            Err(e) => return Err(format!("box scenario {i}: the reference: {e}")),
        };
        for (solver, entry) in solvers.iter().zip(errors.iter_mut()) {
            match solver.solve(&scenario) {
                Ok(o) => {
                    entry.1 = entry.1.max(precision::max_relative_error(&o, &reference));
                    entry.2 += 1;
                }
                Err(kick_core::KickError::NotApplicable { .. }) => {}
                Err(e) => return Err(format!("box scenario {i}: {}: {e}", entry.0)),
            }
        }
    }
    Ok(BoxErrors { samples, trapped, errors })
}

/// One sweep written to its HDF5 file as `kick sweep`/`kick sweep3d --out`
/// write it, plain or compressed: wall time and the file's size.
#[derive(Debug, Clone, PartialEq)]
pub struct FileRun {
    /// The command that does the same run alone.
    pub command: String,
    pub rows: u64,
    pub seconds: f64,
    pub bytes: u64,
}

/// `kick sweep` and `kick sweep3d` into files on 2 threads, plain and with
/// shuffle + deflate at the default level: the throughput with the file
/// written, and what compression costs and saves. Files go to a scratch
/// directory removed afterwards.
fn file_runs(quick: bool) -> Result<Vec<FileRun>, String> {
    use crate::h5::Compression;
    let (samples_1d, samples_3d) = if quick { (2_000, 200) } else { (200_000, 20_000) };
    let dir = std::env::temp_dir().join(format!("kick-bench-files-{}", std::process::id()));
    let pool = rayon::ThreadPoolBuilder::new().num_threads(2).build().map_err(|e| e.to_string())?;
    let mut runs = Vec::new();
    let mut measure = || -> Result<(), String> {
        for compress in [Compression::None, Compression::Deflate(Compression::DEFAULT_LEVEL)] {
            let flag = match compress {
                Compression::None => String::new(),
                Compression::Deflate(level) => format!(" --compress {level}"),
            };
            let settings = crate::sweep::SweepSettings {
                samples: samples_1d,
                seed: 1,
                solver: "auto".into(),
                dt: None,
                out: dir.join("sweep.h5"),
                fixed: Default::default(),
                ranges: Default::default(),
                shard: None,
                threads: None,
                compress,
            };
            let report = pool.install(|| crate::sweep::sweep(&settings))?;
            let bytes = std::fs::metadata(&report.path).map_err(|e| e.to_string())?.len();
            let command = format!("kick sweep --samples {samples_1d} --seed 1 --threads 2 --out sweep.h5{flag}");
            runs.push(FileRun { command, rows: samples_1d, seconds: report.seconds, bytes });
            let _ = std::fs::remove_file(&report.path);
            let settings = crate::sweep3d::Sweep3dSettings {
                samples: samples_3d,
                seed: 1,
                out: dir.join("sweep3d.h5"),
                fixed: Default::default(),
                ranges: Default::default(),
                flight: None,
                shard: None,
                threads: None,
                compress,
            };
            let report = pool.install(|| crate::sweep3d::sweep3d(&settings))?;
            let bytes = std::fs::metadata(&report.path).map_err(|e| e.to_string())?.len();
            let command = format!("kick sweep3d --samples {samples_3d} --seed 1 --threads 2 --out sweep3d.h5{flag}");
            runs.push(FileRun { command, rows: samples_3d, seconds: report.seconds, bytes });
            let _ = std::fs::remove_file(&report.path);
        }
        // The shell ball in 3D (issue 22: at least 10,000 kicks/s on 2 threads).
        let mut fixed = kick_3d::KickSpec::default();
        fixed.scenario.law = Some(kick_core::LawKind::Shell);
        let settings = crate::sweep3d::Sweep3dSettings {
            samples: samples_3d,
            seed: 1,
            out: dir.join("sweep3d.h5"),
            fixed,
            ranges: Default::default(),
            flight: None,
            shard: None,
            threads: None,
            compress: Compression::None,
        };
        let report = pool.install(|| crate::sweep3d::sweep3d(&settings))?;
        let bytes = std::fs::metadata(&report.path).map_err(|e| e.to_string())?.len();
        let command = format!("kick sweep3d --samples {samples_3d} --seed 1 --threads 2 --law shell --out sweep3d.h5");
        runs.push(FileRun { command, rows: samples_3d, seconds: report.seconds, bytes });
        let _ = std::fs::remove_file(&report.path);
        // The realistic foot, the leg and its boot (issue 31: at least 10,000 kicks/s on 2 threads).
        let shell = settings.clone();
        let mut fixed = kick_3d::KickSpec::default();
        (fixed.scenario.law, fixed.scenario.leg) = (Some(kick_core::LawKind::Shell), Some(true));
        let settings = crate::sweep3d::Sweep3dSettings { out: dir.join("sweep3d.h5"), fixed, ..settings.clone() };
        let report = pool.install(|| crate::sweep3d::sweep3d(&settings))?;
        let bytes = std::fs::metadata(&report.path).map_err(|e| e.to_string())?.len();
        let command = format!("kick sweep3d --samples {samples_3d} --seed 1 --threads 2 --law shell --leg --out sweep3d.h5");
        runs.push(FileRun { command, rows: samples_3d, seconds: report.seconds, bytes });
        let _ = std::fs::remove_file(&report.path);
        // ... and the shell ball's kicks flown from the ground across the
        // wall's and the goal line's planes (issue 32: at least 10,000 rows/s
        // on 2 threads; [`flown_rates`] gives its median).
        let settings = flown_settings(shell, true)?;
        let report = pool.install(|| crate::sweep3d::sweep3d(&settings))?;
        let bytes = std::fs::metadata(&report.path).map_err(|e| e.to_string())?.len();
        let flown = report.flown.as_ref().map_or(0, |(n, _)| *n);
        let command = format!("{} --out sweep3d.h5 ({flown} of the rows flown)", flown_command(samples_3d, true));
        runs.push(FileRun { command, rows: samples_3d, seconds: report.seconds, bytes });
        let _ = std::fs::remove_file(&report.path);
        Ok(())
    };
    let result = measure();
    let _ = std::fs::remove_dir_all(&dir);
    result.map(|()| runs)
}

/// The ranges of the flown sweep: the foot's line below the centre on a
/// rising path, so the balls fly.
const FLOWN_RANGES: [&str; 2] = ["contact_depth=0,0.05", "approach_angle=0,20"];

/// `kick sweep3d` on the shell ball over [`FLOWN_RANGES`], each kick flown
/// across the wall's and the goal line's planes (`flight`) or not.
fn flown_settings(shell: crate::sweep3d::Sweep3dSettings, flight: bool) -> Result<crate::sweep3d::Sweep3dSettings, String> {
    let ranges = FLOWN_RANGES.map(String::from);
    let plan = kick_study::flight::FlightPlan::planes(Default::default(), vec![9.15, 25.0]).map_err(|e| e.to_string())?;
    Ok(crate::sweep3d::Sweep3dSettings {
        ranges: kick_study::sample::Ranges::parse(&ranges, |n| crate::sweep3d::find_range(n, true)).map_err(|e| e.to_string())?,
        flight: flight.then_some(plan),
        ..shell
    })
}

/// The command [`flown_settings`] runs, without its `--out`.
fn flown_command(samples: u64, flight: bool) -> String {
    format!(
        "kick sweep3d --samples {samples} --seed 1 --threads 2 --law shell --range {} --range {}{}",
        FLOWN_RANGES[0],
        FLOWN_RANGES[1],
        if flight { " --flight --distance 9.15 --distance 25" } else { "" }
    )
}

/// Flown 3D kicks into a file on 2 threads (issue 32: at least 10,000
/// rows/s), and the same kicks unflown, alternated: rows/s of each and the
/// flown rows' cost over the unflown (what the flight adds).
#[derive(Debug, Clone, Copy)]
struct FlownRates {
    samples: u64,
    flown: Spread,
    unflown: Spread,
    cost: Spread,
}

fn flown_rates(quick: bool) -> Result<FlownRates, String> {
    let samples = if quick { 200 } else { 5_000 };
    let dir = std::env::temp_dir().join(format!("kick-bench-flown-{}", std::process::id()));
    let pool = rayon::ThreadPoolBuilder::new().num_threads(2).build().map_err(|e| e.to_string())?;
    let mut fixed = kick_3d::KickSpec::default();
    fixed.scenario.law = Some(kick_core::LawKind::Shell);
    let shell = crate::sweep3d::Sweep3dSettings {
        samples,
        seed: 1,
        out: dir.join("flown.h5"),
        fixed,
        ranges: Default::default(),
        flight: None,
        shard: None,
        threads: None,
        compress: crate::h5::Compression::None,
    };
    let (mut flown, mut unflown) = (Vec::new(), Vec::new());
    let mut measure = || -> Result<(), String> {
        for _ in 0..3 {
            for (flight, rates) in [(true, &mut flown), (false, &mut unflown)] {
                let settings = flown_settings(shell.clone(), flight)?;
                let report = pool.install(|| crate::sweep3d::sweep3d(&settings))?;
                rates.push(samples as f64 / report.seconds);
                let _ = std::fs::remove_file(&report.path);
            }
        }
        Ok(())
    };
    let result = measure();
    let _ = std::fs::remove_dir_all(&dir);
    result?;
    Ok(FlownRates { samples, flown: Spread::of(&flown), unflown: Spread::of(&unflown), cost: Spread::of_ratios(&unflown, &flown) })
}

/// Measure every solver's work and precision, the headline ratios and the
/// sweep throughput (one run, one binary); write work_precision.h5, its
/// figure and, if asked, the Markdown section. Progress lines go to `log`.
pub fn bench(args: &BenchSettings, log: &mut dyn Write) -> Result<BenchReport, String> {
    let cases = precision::cases().map_err(|e| e.to_string())?;
    let mut ladder = precision::ladder();
    let min_time = if args.quick { 0.02 } else { args.min_time };
    if args.quick {
        ladder.retain(|(name, setting)| matches!((*name, *setting), ("seed-rk4", s) if s == 5e-6) || *setting == 1e-12 || *setting == 1e-8);
    }
    let mut points: Vec<PrecisionPoint> = Vec::new();
    for (name, setting) in ladder {
        let solver = precision::solver(name, setting).map_err(|e| e.to_string())?;
        let point = precision::measure(name, setting, &solver, &cases, min_time).map_err(|e| format!("{name}: {e}"))?;
        let _ = writeln!(
            log,
            "{:<16} {:>9.2e}  error {:>9.2e}  {:>9.2} µs/scenario  {:>7.0} evaluations",
            point.solver,
            point.setting,
            point.max_error,
            point.seconds_per_scenario * 1e6,
            point.evaluations_per_scenario
        );
        points.push(point);
    }
    // Headline ratio: the default path against the paper's method, same
    // binary, measured in alternation and the median taken (the machine is shared).
    let seed_rk4 = SolverChoice::from_name("seed-rk4", 5e-6).map_err(|e| e.to_string())?;
    let default_auto = SolverChoice::from_name("auto", 5e-6).map_err(|e| e.to_string())?;
    let (mut seed_times, mut auto_times) = (Vec::new(), Vec::new());
    let (mut seed, mut auto) = (None, None);
    for _ in 0..5 {
        let s = precision::measure("seed-rk4", 5e-6, &seed_rk4, &cases, min_time).map_err(|e| e.to_string())?;
        let a = precision::measure("auto", kick_compliant::series::DEFAULT_TOLERANCE, &default_auto, &cases, min_time)
            .map_err(|e| e.to_string())?;
        seed_times.push(s.seconds_per_scenario);
        auto_times.push(a.seconds_per_scenario);
        (seed, auto) = (Some(s), Some(a));
    }
    let headline = Spread::of_ratios(&seed_times, &auto_times);
    let (seed, auto) = (seed.ok_or("no seed point")?, auto.ok_or("no auto point")?);
    let _ = writeln!(
        log,
        "\nauto (default) vs seed-rk4 at 5 µs: error {:.2e} vs {:.2e}; cost ratio {} (5 alternating runs)",
        auto.max_error,
        seed.max_error,
        headline.show(1, "x")
    );
    // The same ratio at equal accuracy: the fixed-step family's most accurate
    // point against the cheapest `auto` point at least as accurate, alternated.
    let equal = match equal_accuracy_pair(&points) {
        None => None,
        Some((fixed, cheap)) => {
            let (fixed_solver, auto_solver) = (
                precision::solver(fixed.solver, fixed.setting).map_err(|e| e.to_string())?,
                precision::solver(cheap.solver, cheap.setting).map_err(|e| e.to_string())?,
            );
            let (mut f, mut a) = (Vec::new(), Vec::new());
            for _ in 0..5 {
                f.push(
                    precision::measure(fixed.solver, fixed.setting, &fixed_solver, &cases, min_time)
                        .map_err(|e| e.to_string())?
                        .seconds_per_scenario,
                );
                a.push(
                    precision::measure(cheap.solver, cheap.setting, &auto_solver, &cases, min_time)
                        .map_err(|e| e.to_string())?
                        .seconds_per_scenario,
                );
            }
            let ratio = Spread::of_ratios(&f, &a);
            let _ = writeln!(
                log,
                "at equal accuracy: rk4-events at {:.2e} s (error {:.2e}) vs auto at {:.0e} (error {:.2e}): {}",
                fixed.setting,
                fixed.max_error,
                cheap.setting,
                cheap.max_error,
                ratio.show(0, "x")
            );
            Some(EqualAccuracy { fixed: fixed.clone(), auto: cheap.clone(), ratio })
        }
    };
    let reference_error = precision::reference_error(&cases).map_err(|e| e.to_string())?;
    let box_errors = box_errors(if args.quick { 200 } else { 2000 })?;
    let sweep = SampledSweep::new(if args.quick { 2_000 } else { args.sweep_samples }, 1);
    // 1 and 2 threads in alternation, three times; the medians (shared machine).
    let (mut ones, mut twos) = (Vec::new(), Vec::new());
    for _ in 0..3 {
        ones.push(throughput(&default_auto, sweep.clone(), 1)?);
        twos.push(throughput(&default_auto, sweep.clone(), 2)?);
    }
    let (one, two, speed_up) = (Spread::of(&ones), Spread::of(&twos), Spread::of_ratios(&twos, &ones));
    let _ = writeln!(
        log,
        "sweep of {} sampled scenarios (auto, summary only): {}/s on 1 thread, {}/s on 2 threads, speed-up {} (3 alternating runs)",
        sweep.samples,
        one.show(0, ""),
        two.show(0, ""),
        speed_up.show(2, "x")
    );
    let kicks = if args.quick { 20 } else { 200 };
    let mut costs = Vec::new();
    for _ in 0..3 {
        costs.push(kick_3d::precision::cost_ratio(kicks, kick_3d::models::BENCH_SEED, min_time / 30.0).map_err(|e| e.to_string())?);
    }
    let cost_3d = Spread::of(&costs.iter().map(|c| c.ratio).collect::<Vec<_>>());
    // The run whose ratio is the median, for its times and counts.
    let cost = costs.iter().find(|c| c.ratio == cost_3d.median).copied().ok_or("no 3D cost run")?;
    let _ = writeln!(
        log,
        "off-center 3D kick (auto) vs the same kick's 1D contact (auto): {:.1} µs vs {:.2} µs, ratio {} \
         (3 runs, each medians over {kicks} kicks of kick_3d::models::OffCenterBox, timed alternately)",
        cost.seconds_3d * 1e6,
        cost.seconds_1d * 1e6,
        cost_3d.show(1, "x")
    );

    // The shell ball's 1D cost beside the paper's law: the same sampled
    // scenarios with `law = shell`, auto, one thread, alternated, medians.
    let mut shell_sweep = sweep.clone();
    shell_sweep.fixed.law = Some(kick_core::LawKind::Shell);
    // The realistic foot on the shell ball: the leg's mass and its boot (issue 31: at most 2x the shell ball's cost).
    let mut leg_sweep = shell_sweep.clone();
    leg_sweep.fixed.leg = Some(true);
    let (mut paper_law, mut shell, mut leg) = (Vec::new(), Vec::new(), Vec::new());
    for _ in 0..3 {
        paper_law.push(throughput(&default_auto, sweep.clone(), 1)?);
        shell.push(throughput(&default_auto, shell_sweep.clone(), 1)?);
        leg.push(throughput(&default_auto, leg_sweep.clone(), 1)?);
    }
    let shell_cost = Spread::of_ratios(&paper_law, &shell);
    let leg_cost = Spread::of_ratios(&shell, &leg);
    let (paper_law, shell, leg) = (Spread::of(&paper_law), Spread::of(&shell), Spread::of(&leg));
    let _ = writeln!(
        log,
        "shell ball, 1D (auto, 1 thread): {:.0} scenarios/s against {:.0} with the paper's law, {} the cost; \
         with the leg and its boot {:.0} scenarios/s, {} the shell ball's cost",
        shell.median,
        paper_law.median,
        shell_cost.show(2, "x"),
        leg.median,
        leg_cost.show(2, "x")
    );
    // Flights through `flight_many`, 1 and 2 threads alternated, medians.
    let flight_rows = if args.quick { 1_000 } else { 50_000 };
    let (mut flights_1, mut flights_2) = (Vec::new(), Vec::new());
    for _ in 0..3 {
        flights_1.push(flights_per_second(flight_rows, 1)?);
        flights_2.push(flights_per_second(flight_rows, 2)?);
    }
    let flight_speed_up = Spread::of_ratios(&flights_2, &flights_1);
    let (flights_1, flights_2) = (Spread::of(&flights_1), Spread::of(&flights_2));
    let _ = writeln!(
        log,
        "flight_many of {flight_rows} free kicks: {:.0} flights/s on 1 thread, {:.0} on 2 threads",
        flights_1.median, flights_2.median
    );
    let aims = aim_seconds(if args.quick { 1 } else { 5 })?.map(|t| Spread::of(&t.iter().map(|s| s * 1e3).collect::<Vec<_>>()));
    let _ = writeln!(log, "aim solve: {} ms for the launch, {} ms through the 3D kick", aims[0].show(2, ""), aims[1].show(2, ""));
    let kick_runs = kick_costs(min_time / 30.0)?;
    let kicks: [(Spread, u64); KICK_FORMS] = std::array::from_fn(|i| (Spread::of(&kick_runs[i].0), kick_runs[i].1));
    let baseline_copy = Spread::of_ratios(&kick_runs[8].0, &kick_runs[7].0);
    let _ = writeln!(
        log,
        "5 cm kick, one core: default spring {:.1} µs, stiff spring {:.1} µs, rigid grip {:.1} µs, shell ball {:.1} µs; \
         patch: knife edge {:.1} µs, rigid {:.1} µs; cap {:.1} µs, rigid {:.1} µs (baseline copy {:.1} µs); \
         the leg and its boot on the cap {:.1} µs",
        kicks[0].0.median,
        kicks[1].0.median,
        kicks[2].0.median,
        kicks[3].0.median,
        kicks[4].0.median,
        kicks[5].0.median,
        kicks[6].0.median,
        kicks[7].0.median,
        kicks[8].0.median,
        kicks[9].0.median
    );
    let other = Other {
        shell,
        paper_law,
        shell_cost,
        leg,
        leg_cost,
        flight_rows,
        flights_1,
        flights_2,
        flight_speed_up,
        aims,
        kicks,
        baseline_copy,
    };

    let files = file_runs(args.quick)?;
    let flown = flown_rates(args.quick)?;
    let _ = writeln!(
        log,
        "flown 3D kicks into a file, 2 threads: {} rows/s, the same kicks unflown {} rows/s, {} the cost ({})",
        flown.flown.show(0, ""),
        flown.unflown.show(0, ""),
        flown.cost.show(2, "x"),
        flown_command(flown.samples, true)
    );
    for run in &files {
        let _ = writeln!(
            log,
            "{}: {} s, {} rows/s, {} MB",
            run.command,
            kick_core::sig(run.seconds),
            kick_core::sig(run.rows as f64 / run.seconds),
            kick_core::sig(run.bytes as f64 / 1e6)
        );
    }

    // Results file, then the figure drawn from it.
    std::fs::create_dir_all(&args.out).map_err(|e| format!("cannot create {}: {e}", args.out.display()))?;
    let path = args.out.join("work_precision.h5");
    let text = format!("kick bench{} --min-time {min_time}", if args.quick { " --quick" } else { "" });
    let provenance = Provenance::now("work_precision", "kick bench", &text);
    let machine = Machine::this();
    let set = OutcomeSet {
        solver: "bench".into(),
        // References: closed forms, else accurate at this tolerance.
        settings: Setting::numbers([("reference_tolerance", precision::REFERENCE_TOLERANCE)]),
        columns: COLUMNS.iter().map(|(n, u)| Column::new(n, u)).collect(),
    };
    let parameters = [Column::new("setting", "tolerance (1) or step (s)")];
    let mut writer = SweepWriter::create(&path, &provenance, &parameters, &[set], points.len() as u64).map_err(|e| e.to_string())?;
    for p in &points {
        writer.push_parameters(&[p.setting]).map_err(|e| e.to_string())?;
        writer
            .push_outcome(
                0,
                Ok(&[p.max_error, p.max_error_closed_form, p.max_error_tight, p.seconds_per_scenario, p.evaluations_per_scenario]),
            )
            .map_err(|e| e.to_string())?;
    }
    let names: Vec<String> = points.iter().map(|p| p.solver.to_string()).collect();
    write_strings(writer.file(), &path, "scenario_names", &names).map_err(|e| e.to_string())?;
    for (name, value) in [
        ("auto_vs_seed_cost_ratio", headline.median),
        ("auto_vs_rk4_events_cost_ratio_at_equal_accuracy", equal.as_ref().map_or(f64::NAN, |e| e.ratio.median)),
        ("auto_max_error", auto.max_error),
        ("reference_error_against_closed_forms", reference_error.against_closed_forms),
        ("reference_error_against_series", reference_error.against_series),
        ("sweep_per_second_1_thread", one.median),
        ("sweep_per_second_2_threads", two.median),
        ("sweep_samples", sweep.samples as f64),
        ("off_center_3d_vs_1d_cost_ratio", cost_3d.median),
        ("shell_vs_paper_law_1d_cost_ratio", shell_cost.median),
        ("leg_boot_vs_shell_1d_cost_ratio", leg_cost.median),
        ("sweep3d_flown_rows_per_second_2_threads", flown.flown.median),
        ("sweep3d_flown_vs_unflown_cost_ratio", flown.cost.median),
        ("flights_per_second_1_thread", flights_1.median),
        ("flights_per_second_2_threads", flights_2.median),
        ("aim_launch_seconds", aims[0].median * 1e-3),
        ("aim_kick_seconds", aims[1].median * 1e-3),
    ] {
        write_f64_attr(writer.file(), &path, name, value).map_err(|e| e.to_string())?;
    }
    crate::h5::write_str_attr(writer.file(), &path, "machine_cpu", &machine.cpu).map_err(|e| e.to_string())?;
    write_f64_attr(writer.file(), &path, "machine_cores", machine.cores as f64).map_err(|e| e.to_string())?;
    write_f64_attr(writer.file(), &path, "machine_clock_mhz", machine.clock_mhz.unwrap_or(f64::NAN)).map_err(|e| e.to_string())?;
    crate::h5::write_str_attr(writer.file(), &path, "build", BUILD).map_err(|e| e.to_string())?;
    let path = writer.finish().map_err(|e| e.to_string())?;
    let mut written = vec![path.clone()];
    written.extend(draw(&path, &args.out.join("figures"))?);
    let measured = Measured {
        points: &points,
        seed: &seed,
        auto: &auto,
        headline,
        equal: equal.as_ref(),
        reference_error,
        box_errors: &box_errors,
        one,
        two,
        speed_up,
        samples: sweep.samples,
        cost: &cost,
        cost_3d,
        files: &files,
        flown: &flown,
        other: &other,
    };
    if let Some(report) = &args.report {
        let report_dir = report.parent().unwrap_or(std::path::Path::new(""));
        let figure = crate::links::relative(report_dir, &args.out.join("figures/work_precision.png"));
        let data = crate::links::relative(report_dir, &path);
        crate::output::write(report, measured.timing_markdown(&figure, &data, &text, &machine)).map_err(|e| e.to_string())?;
        written.push(report.clone());
    }
    if let Some(report) = &args.solvers_report {
        let timing = args.report.as_ref().map(|t| crate::links::relative(report.parent().unwrap_or(std::path::Path::new("")), t));
        crate::output::write(report, measured.solvers_markdown(&text, timing.as_deref())).map_err(|e| e.to_string())?;
        written.push(report.clone());
    }
    Ok(BenchReport {
        cost_ratio: headline.median,
        auto_max_error: auto.max_error,
        seed_max_error: seed.max_error,
        sweep_per_second_1_thread: one.median,
        sweep_per_second_2_threads: two.median,
        off_center_3d_vs_1d_cost_ratio: cost_3d.median,
        shell_vs_paper_law_1d_cost_ratio: shell_cost.median,
        leg_boot_vs_shell_1d_cost_ratio: leg_cost.median,
        flights_per_second_2_threads: flights_2.median,
        sweep3d_flown_rows_per_second_2_threads: flown.flown.median,
        written,
    })
}

/// A relative error as the pages print it: 3 digits, and an exact 0 (a
/// closed form taken where it is exact) as 0.
fn error(x: f64) -> String {
    if x == 0.0 {
        "0".into()
    } else {
        format!("{x:.2e}")
    }
}

/// The build of this binary (compiler, profile and its settings, target
/// features, RUSTFLAGS), from kick-paper's build script.
pub const BUILD: &str = env!("KICK_BUILD");

/// The cost ratio at equal accuracy ([`equal_accuracy_pair`]), re-timed in alternation.
#[derive(Debug, Clone)]
struct EqualAccuracy {
    fixed: PrecisionPoint,
    auto: PrecisionPoint,
    /// fixed / auto, seconds per scenario.
    ratio: Spread,
}

struct Measured<'a> {
    points: &'a [PrecisionPoint],
    seed: &'a PrecisionPoint,
    auto: &'a PrecisionPoint,
    /// seed-rk4 / auto (default).
    headline: Spread,
    equal: Option<&'a EqualAccuracy>,
    reference_error: precision::ReferenceError,
    box_errors: &'a BoxErrors,
    /// Scenarios per second on 1 and 2 threads, and 2 over 1.
    one: Spread,
    two: Spread,
    speed_up: Spread,
    samples: u64,
    /// The 3D cost run whose ratio is the median of [`Measured::cost_3d`].
    cost: &'a kick_3d::precision::CostRatio,
    cost_3d: Spread,
    files: &'a [FileRun],
    flown: &'a FlownRates,
    other: &'a Other,
}

/// The shell ball's cost, flights and aims.
struct Other {
    /// Scenarios/s, auto, one thread: the shell ball and the paper's law, and the cost ratio.
    shell: Spread,
    paper_law: Spread,
    shell_cost: Spread,
    /// The shell ball with the leg and its boot, and its cost over the shell ball's.
    leg: Spread,
    leg_cost: Spread,
    flight_rows: usize,
    flights_1: Spread,
    flights_2: Spread,
    flight_speed_up: Spread,
    /// Milliseconds per aim solve: the launch, through the 3D kick.
    aims: [Spread; 2],
    /// µs and evaluations per kick ([`kick_costs`]).
    kicks: [(Spread, u64); KICK_FORMS],
    /// The baseline x86-64 copy over the AVX2 copy, the last form.
    baseline_copy: Spread,
}

/// The machine a timing was taken on.
#[derive(Debug, Clone, PartialEq)]
pub struct Machine {
    /// CPU model (`model name` of /proc/cpuinfo), or "unknown".
    pub cpu: String,
    /// Cores this process may use.
    pub cores: usize,
    /// `cpu MHz` of /proc/cpuinfo when the run started (the kernel's figure for the first core).
    pub clock_mhz: Option<f64>,
    /// The largest frequency the kernel may set (cpufreq), MHz, when it exposes one.
    pub max_mhz: Option<f64>,
}

impl Machine {
    pub fn this() -> Machine {
        let cpuinfo = std::fs::read_to_string("/proc/cpuinfo").unwrap_or_default();
        let field =
            |name: &str| cpuinfo.lines().find(|l| l.starts_with(name)).and_then(|l| l.split_once(':')).map(|(_, v)| v.trim().to_string());
        let cpu = field("model name").unwrap_or_else(|| "unknown".into());
        let clock_mhz = field("cpu MHz").and_then(|v| v.parse().ok());
        let max_mhz = std::fs::read_to_string("/sys/devices/system/cpu/cpu0/cpufreq/cpuinfo_max_freq")
            .ok()
            .and_then(|v| v.trim().parse::<f64>().ok())
            .map(|khz| khz / 1e3);
        let cores = std::thread::available_parallelism().map(|n| n.get()).unwrap_or(1);
        Machine { cpu, cores, clock_mhz, max_mhz }
    }

    fn describe(&self) -> String {
        let clock = match (self.clock_mhz, self.max_mhz) {
            (Some(now), Some(max)) => format!("clock {now:.0} MHz at the start (cpufreq maximum {max:.0} MHz)"),
            (Some(now), None) => format!("clock {now:.0} MHz at the start (/proc/cpuinfo; no frequency scaling exposed)"),
            (None, _) => "clock unknown".into(),
        };
        format!("{}, {}, {} cores available, {} {}", self.cpu, clock, self.cores, std::env::consts::OS, std::env::consts::ARCH)
    }
}

impl Measured<'_> {
    /// Errors and evaluation counts: the same on every run.
    fn solvers_markdown(&self, command: &str, timing: Option<&str>) -> String {
        let mut rows = String::new();
        for p in self.points {
            rows.push_str(&format!(
                "| {} | {:.2e} | {} | {} | {:.0} |\n",
                p.solver,
                p.setting,
                error(p.max_error_closed_form),
                error(p.max_error_tight),
                p.evaluations_per_scenario
            ));
        }
        let timing = timing
            .map(|t| {
                format!("Times, cost ratios, sweep throughput and the work–precision figure depend on the machine: see [timing]({t}).\n\n")
            })
            .unwrap_or_default();
        let r = self.reference_error;
        let b = self.box_errors;
        let box_list: Vec<String> =
            b.errors.iter().map(|(name, error, applied)| format!("`{name}` {error:.1e} ({applied} scenarios)")).collect();
        format!(
            "# Solvers of the 1D model\n\n\
             Generated by `{command}` (part of `kick reproduce`). Errors and evaluation counts do not depend on the clock \
             and are the same on every run. {timing}\
             ## What `auto` runs\n\n\
             | scene | path | why it is exact |\n| --- | --- | --- |\n\
             | no drive, c = 0 | `closed-form` | energy integral (Eq. 33), contact time from the Beta function |\n\
             | no drive, n = 1 | `closed-form` | damped oscillator to δ_max, undamped quarter swing back |\n\
             | the paper's law, otherwise | `series` | power series through compression (a Frobenius double series in t and t^(n+1) at \
             first touch, Taylor steps after), the undamped return from its energy integral (Beta function, or tanh–sinh \
             quadrature under a drive) |\n\
             | the shell ball (`law = shell`), drive ≥ 0 | `series` | Taylor steps of order 20 from first touch to separation \
             (its force is analytic at δ = 0), the power (1 − c)^(−γ) by Miller's recurrence, events as roots of the step \
             polynomials; within 1e-10 of `reduced` at 1e-14 over the sweep's box |\n\
             | another contact law | `reduced` | Dop853 on δ (Eq. 18) through the whole contact |\n\
             | a time history is wanted | `accurate` | full state of Eq. 47, every sample an integrator point |\n\n\
             ## Precision\n\n\
             Error: the largest relative error over v_b⁺, v_f⁺, ratio, peak force, contact time, δ_max, impulse and e \
             (times of the peak and of δ_max relative to the contact time; `kick_compliant::precision::max_relative_error`). \
             Two references, in two columns: the closed forms, exact to rounding, on five elastic and six linear scenarios; \
             and `accurate` at {ref_tol:e} on Table 2 and three driven scenarios, which has an error of its own. That \
             reference is within {closed:.1e} of the closed forms where they exist, and within {series:.1e} of `series` at \
             {series_tol:e} (a second, independent method) on the Table 2 and driven scenarios; an error in the last \
             column below about {series:.1e} is at the reference's floor and says only that the solver agrees with it that \
             far.\n\n\
             | solver | tolerance or step (s) | max error, closed forms | max error, `accurate` at {ref_tol:e} | evaluations per scenario |\n\
             | --- | --- | --- | --- | --- |\n{rows}\n\
             - `auto` at its default tolerance ({auto_tol:e}, the `series` path's `kick_compliant::series::DEFAULT_TOLERANCE`; \
             closed forms where exact): largest error {auto_closed} against the closed forms, {auto_tight:.2e} against \
             the tight reference (whose own floor is above); `seed-rk4` at 5 µs: {seed:.2e} \
             (step quantisation of the contact time and the missed onset jump c·V0).\n\n\
             ## Where each solver is trustworthy\n\n\
             Held by `crates/kick-compliant/tests/solvers/stress.rs` (k 1e2–1e12, n 1–3, ζ 0–50, m_f/m_b 1e-3–1e6, V0 1e-3–1e3 m/s, drives to 1e4 N, \
             grazing contact) and `crates/kick-compliant/tests/solvers/accurate_vs_closed_forms.rs`:\n\n\
             - `closed-form`, `series`, `reduced-return`, `reduced`, `auto`: agree with each other and the closed forms to \
             1e-8 over the whole box; against the closed forms and `accurate` at 1e-14 on the paper's range and the sweep's \
             box, 1e-9 (`crates/kick-compliant/tests/solvers/series.rs`: 200 random scenarios of that box). Measured \
             here, the largest relative error (as above) at each solver's default over the first {box_n} scenarios of the \
             sweep's box (`kick sweep --samples {box_n} --seed 1`; {trapped} trapped ones left out) against `accurate` at \
             {ref_tol:e}: {box_list}.\n\
             - `accurate`, `dop853`, `dopri5`, `rk4-events` carry x_f, x_b, v_f, v_b, whose differences make δ and δ̇: \
             their error grows with |v|/V0 and |v| t_c/δ_max (grazing contact at high speed, long shallow contacts), \
             and under a drive with (μ/m_f) F δ_max / (½ μ V0²); within 1e-8 times that conditioning.\n\
             - `seed-rk4`: fourth order between steps, but the contact time is quantised to the step and a damped \
             contact's peak misses the onset jump; ~2e-2 relative at 5 µs on this set.\n\
             - A drive that keeps the ball pressed ends in a typed `NoSeparation` error: proved at the first maximum \
             compression for the paper's law, or after the documented horizon (1000 undriven contact times, or 100 000 \
             steps in one phase).\n",
            ref_tol = precision::REFERENCE_TOLERANCE,
            closed = r.against_closed_forms,
            series = r.against_series,
            series_tol = precision::SERIES_CHECK_TOLERANCE,
            auto_tol = self.auto.setting,
            auto_closed = error(self.auto.max_error_closed_form),
            auto_tight = self.auto.max_error_tight,
            seed = self.seed.max_error,
            box_n = b.samples,
            trapped = b.trapped,
            box_list = box_list.join(", "),
        )
    }

    /// Times and ratios: change from run to run and machine to machine.
    fn timing_markdown(&self, figure: &str, data: &str, command: &str, machine: &Machine) -> String {
        let mut rows = String::new();
        for p in self.points {
            rows.push_str(&format!("| {} | {:.2e} | {:.2e} | {:.2} |\n", p.solver, p.setting, p.max_error, p.seconds_per_scenario * 1e6));
        }
        let mut files = String::new();
        for run in self.files {
            // Its plain twin: the same command without --compress.
            let plain = self.files.iter().find(|p| !p.command.contains("--compress") && run.command.starts_with(&p.command));
            let size = match plain {
                Some(p) if p.command != run.command => {
                    format!("{} ({:+.0}%)", kick_core::sig(run.bytes as f64 / 1e6), 100.0 * (run.bytes as f64 / p.bytes as f64 - 1.0))
                }
                _ => kick_core::sig(run.bytes as f64 / 1e6).to_string(),
            };
            files.push_str(&format!(
                "| `{}` | {} | {} | {size} |\n",
                run.command,
                kick_core::sig(run.seconds),
                kick_core::sig(run.rows as f64 / run.seconds)
            ));
        }
        let o = self.other;
        let equal = match self.equal {
            Some(e) => format!(
                " At equal accuracy the ratio is another: the fixed-step method's most accurate point of the ladder, \
                 `rk4-events` at Δt = {:.2e} s (error {:.2e}), against the cheapest `auto` point at least as accurate, \
                 tolerance {:.0e} (error {:.2e}): **{}** (5 alternating measurements).",
                e.fixed.setting,
                e.fixed.max_error,
                e.auto.setting,
                e.auto.max_error,
                e.ratio.show(0, "x")
            ),
            None => " The ratio at equal accuracy needs the `rk4-events` ladder, which this (quick) run leaves out.".into(),
        };
        let flown_command = flown_command(self.flown.samples, true);
        let [tx, ty, tz] = crate::free_kick::AIM_TARGET;
        let [sx, sy, sz] = crate::free_kick::AIM_SPIN;
        let short = kick_core::short;
        let target = format!("{},{},{}", short(tx), short(ty), short(tz));
        let kick_names = [
            "μ = ∞, default spring".to_string(),
            "a stiff spring at μ = 0.5 (k_t = 1e9 N/m: slip, then grip within a micrometre of rigid grip's)".into(),
            "μ = ∞, rigid grip as a constraint (`--tangential-stiffness inf`)".into(),
            "the shell ball, μ = 0.5".into(),
            "the shell ball's patch (`--patch-contact`) on the knife-edge face, μ = 0.5".into(),
            "the patch on the knife-edge face, rigid grip at μ = ∞".into(),
            format!(
                "the patch on a convex instep (`--instep-radius {} --face-yaw 0`), μ = 0.5",
                kick_3d::validation::ASSUMED_INSTEP_RADIUS
            ),
            "the patch on the convex instep, rigid grip at μ = ∞".into(),
            "the same, on the baseline x86-64 copy".into(),
            "the realistic foot (`--leg`: the leg's 6×6 apparent inertia and its boot) on the convex instep's patch, μ = 0.5 (issue 31: ≤ 120 µs)".into(),
        ];
        let mut kick_rows = String::new();
        for (name, (t, evaluations)) in kick_names.iter().zip(&o.kicks) {
            kick_rows.push_str(&format!("| {name} | {:.1} | {:.1}–{:.1} | {evaluations} |\n", t.median, t.low, t.high));
        }
        let body = format!(
            "# Timing of the 1D solvers\n\n\
             Generated by `{command}` (part of `kick reproduce`) on {}, {}. Build: {}. Every number below was measured \
             in that run and changes from run to run: this page and `{data}` are the only outputs of `kick reproduce` \
             that do. Timings on a shared machine move by tens of percent between runs; ratios are taken within one \
             run, each from measurements taken in alternation, and given as the median with the range over the \
             repetitions.\n\n\
             ## Work–precision\n\n![work–precision]({figure})\n\n\
             | solver | tolerance or step (s) | max error | µs per scenario |\n| --- | --- | --- | --- |\n{rows}\n\
             Errors are against closed forms or `accurate` at 1e-14, whichever the scenario has; [solvers.md](solvers.md) \
             gives the two apart and the tight reference's own error.\n\n\
             ## Headline numbers\n\n\
             - Cost ratio seed-rk4 / auto, each at its default: **{}** (5 alternating measurements), at errors {:.2e} \
             against {:.2e}, {:.0} orders of magnitude apart: not a ratio at equal accuracy.{equal}\n\
             - Sampled sweep of {} scenarios (auto, summary only, no file): {} scenarios/s on 1 thread, \
             {} scenarios/s on 2 threads, parallel speed-up {} (3 alternating runs).\n\
             - Off-center 3D kick against the same kick's 1D contact along its normal (both `auto`, one core, \
             medians over {} kicks of `kick_3d::models::OffCenterBox`, seed {}, timed alternately, 3 runs): \
             **{}**; in the median run {:.1} µs against {:.2} µs and {:.0} against {:.0} right-hand-side \
             evaluations per kick. The 3D path's error against its tightened reference is held to 1e-9 by \
             `crates/kick-3d/tests/model/box_accuracy.rs`.\n\
             - The shell ball (`law = shell`) in 1D, the same sampled scenarios, `auto`, one thread: {:.0} scenarios/s \
             against {:.0} with the paper's law (medians): **{}** the cost (3 alternating runs); both take the \
             `series` path (`kick_compliant::shell_series` for the shell ball). With the realistic foot (`--leg`: \
             the leg's mass along the line of motion and its boot in series) on the shell ball, the same scenarios: \
             {:.0} scenarios/s, **{}** the shell ball's cost (`kick_compliant::boot::series`; issue 31: at most 2x).\n\
             - Flights: {} free kicks (18°, 9 rev/s of sidespin, 22–32 m/s, `kick_flight::models::free_kick_speeds`) \
             through `flight_many` (Python's `kick.flight_many`): {} flights/s on 1 thread, **{} flights/s on 2 \
             threads**, speed-up {} (3 alternating runs), {:.2} µs per flight on one.\n\
             - Flown 3D kicks into a file (`{flown_command} --out flown.h5`, the shell ball, each kick flown from the \
             ground across the planes x = 9.15 and 25 m; issue 32: at least 10,000 rows/s): **{} rows/s on 2 threads**; \
             the same kicks unflown (without `--flight ...`): {} rows/s; the flown rows cost {} the unflown \
             (3 alternating runs, medians): the 3D kick, not its flight, sets the rate.\n\
             - The two aim solves of [flight.md](flight.md), to its target ({target}) m: {} ms for the launch \
             (`kick aim --target {target} --spin {},{},{}`), {} ms through the 3D kick \
             (`kick aim --target {target} --from kick`) (5 alternating solves each).\n\n\
             ## One off-center kick\n\n\
             Table 1, 5 cm offset, `accurate`, one core, 5 alternating measurements of each form (µs per kick, median and \
             range; right-hand-side evaluations). They run the kick's AVX2 copy where the CPU has AVX2 (the results are \
             the baseline copy's, bit for bit); the row “the same, on the baseline x86-64 copy” runs the baseline copy: {} the AVX2 copy's time.\n\n\
             | kick | µs | range | evaluations |\n| --- | --- | --- | --- |\n{kick_rows}",
            machine.describe(),
            crate::provenance::utc_timestamp(std::time::SystemTime::now()),
            BUILD,
            self.headline.show(1, "x"),
            self.seed.max_error,
            self.auto.max_error,
            (self.seed.max_error / self.auto.max_error).log10(),
            self.samples,
            self.one.show(0, ""),
            self.two.show(0, ""),
            self.speed_up.show(2, "x"),
            self.cost.kicks,
            self.cost.seed,
            self.cost_3d.show(1, "x"),
            self.cost.seconds_3d * 1e6,
            self.cost.seconds_1d * 1e6,
            self.cost.evaluations_3d,
            self.cost.evaluations_1d,
            o.shell.median,
            o.paper_law.median,
            o.shell_cost.show(2, "x"),
            o.leg.median,
            o.leg_cost.show(2, "x"),
            o.flight_rows,
            o.flights_1.show(0, ""),
            o.flights_2.show(0, ""),
            o.flight_speed_up.show(2, "x"),
            1e6 / o.flights_1.median,
            self.flown.flown.show(0, ""),
            self.flown.unflown.show(0, ""),
            self.flown.cost.show(2, "x"),
            o.aims[0].show(2, ""),
            short(sx),
            short(sy),
            short(sz),
            o.aims[1].show(2, ""),
            o.baseline_copy.show(2, "x"),
        );
        format!(
            "{body}\n## Sweeps into result files\n\n\
             `kick sweep` and `kick sweep3d` with `--out`, on 2 threads, each run once: wall time with the HDF5 file \
             written, and the file's size, plain and with shuffle + deflate (`--compress`, level {}). Random parameters \
             and their outcomes are mostly noise in their last digits, which deflate cannot shrink; a small file can \
             even grow, each compressed dataset carrying a chunk index.\n\n\
             | command | s | rows per s | file (MB) |\n| --- | --- | --- | --- |\n{files}",
            crate::h5::Compression::DEFAULT_LEVEL
        )
    }
}

/// Error against cost, log–log, one curve per solver, from the file.
fn draw(path: &std::path::Path, out: &std::path::Path) -> Result<Vec<PathBuf>, String> {
    let data = SweepData::read(path).map_err(|e| e.to_string())?;
    let names = data.names.clone().ok_or("work_precision.h5 has no solver names")?;
    let set = data.set("bench").map_err(|e| e.to_string())?;
    let error = set.column("max_error").ok_or("no max_error")?;
    let seconds = set.column("seconds_per_scenario").ok_or("no seconds_per_scenario")?;
    let colors = crate::figures::COLORS;
    let mut solvers: Vec<&str> = Vec::new();
    for n in &names {
        if !solvers.contains(&n.as_str()) {
            solvers.push(n);
        }
    }
    let mut series = Vec::new();
    for (i, solver) in solvers.iter().enumerate() {
        let mut rows: Vec<(f64, f64)> = names
            .iter()
            .zip(seconds.iter().zip(error))
            .filter(|(n, _)| n == solver)
            .map(|(_, (&t, &e))| (t * 1e6, e.max(1e-16).log10()))
            .collect();
        rows.sort_by(|a, b| a.0.total_cmp(&b.0));
        rows.dedup_by(|a, b| a.0 == b.0);
        let (x, y): (Vec<f64>, Vec<f64>) = rows.into_iter().unzip();
        series.push(Series::line(solver, colors[i % colors.len()], &x, &y).with_markers());
    }
    let panel = Panel {
        title: "Work-precision of the 1D solvers (Table 2, elastic, linear and driven models)".into(),
        x_label: "time per scenario (µs, log scale)".into(),
        y_label: "log10 of the largest relative error".into(),
        log_x: true,
        series,
        y_from_zero: false,
        legend: SeriesLabelPosition::UpperRight,
    };
    save_grid(out, "work_precision", "kick bench", (1, 1), &[panel]).map_err(|e| e.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn point(solver: &'static str, setting: f64, max_error: f64, seconds: f64) -> PrecisionPoint {
        PrecisionPoint {
            solver,
            setting,
            max_error,
            max_error_closed_form: max_error,
            max_error_tight: max_error,
            seconds_per_scenario: seconds,
            evaluations_per_scenario: 1.0,
        }
    }

    /// The pair of the equal-accuracy ratio: rk4-events' most accurate point
    /// and the loosest (cheapest) `auto` tolerance at least as accurate.
    #[test]
    fn equal_accuracy_pairs_the_best_fixed_step_with_the_cheapest_auto_as_good() {
        let points = [
            point("seed-rk4", 5e-6, 2e-2, 1e-4),
            point("rk4-events", 2.5e-6, 1.8e-8, 4e-4),
            point("rk4-events", 1.25e-6, 1.1e-9, 8e-4),
            point("auto", 1e-6, 5.5e-8, 1.8e-6),
            point("auto", 1e-8, 7.9e-10, 2.0e-6),
            point("auto", 1e-10, 9e-12, 2.7e-6),
        ];
        let (fixed, auto) = equal_accuracy_pair(&points).unwrap();
        assert_eq!((fixed.setting, auto.setting), (1.25e-6, 1e-8));
        assert!(equal_accuracy_pair(&points[..3]).is_none(), "no auto point");
        // No auto point as accurate: none.
        assert!(equal_accuracy_pair(&[point("rk4-events", 1e-6, 1e-13, 1e-3), point("auto", 1e-8, 1e-12, 1e-6)]).is_none());
    }

    #[test]
    fn a_spread_of_ratios_pairs_the_alternated_runs() {
        let s = Spread::of_ratios(&[10.0, 12.0, 9.0], &[1.0, 2.0, 1.0]);
        assert_eq!((s.median, s.low, s.high), (9.0, 6.0, 10.0));
        assert_eq!(s.show(1, "x"), "9.0x (range 6.0–10.0x)");
    }
}
