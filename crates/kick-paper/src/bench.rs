//! `kick bench`: work–precision of every 1D solver, the headline ratios, and
//! sweep throughput, measured in one run of one binary.
//!
//! What depends on the clock (times, ratios, throughput, the work–precision
//! figure, whose x axis is time) goes to the timing file and page, with the
//! machine's description; `kick reproduce` puts them in `results/timing/` and
//! `paper/timing.md`, the only outputs a second run may change. Errors and
//! evaluation counts do not depend on the clock: they make the solvers page.

use crate::figures::{save_grid, Panel, Series};
use crate::h5::{write_f64_attr, write_strings, Column, OutcomeSet, Setting, SweepData, SweepWriter};
use crate::printable::Printable;
use crate::sample::SampledSweep;
use crate::Provenance;
use kick_compliant::precision::{self, PrecisionPoint};
use kick_compliant::SolverChoice;
use kick_core::Solver;
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
    /// Free kicks through `flight_many` on 2 threads.
    pub flights_per_second_2_threads: f64,
    #[serde(skip)]
    pub written: Vec<PathBuf>,
}

impl Printable for BenchReport {
    fn text(&self) -> String {
        self.written.iter().map(|p| format!("-> {}\n", p.display())).collect()
    }
}

const COLUMNS: [(&str, &str); 3] = [("max_error", "1"), ("seconds_per_scenario", "s"), ("evaluations_per_scenario", "1")];

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

/// Seconds of one aim solve, median of `repeats`: the launch to a target by
/// the far post over the wall with sidespin held (as `kick aim --target
/// 25,2.8,2 --spin 0,0,50`), and through the 3D kick (as `kick aim --target
/// 25,-3,1.5 --from kick`).
fn aim_seconds(repeats: usize) -> Result<(f64, f64), String> {
    use kick_flight::aim::{aim_launch, LaunchFree, Wall};
    let curl = kick_flight::FlightSpec { spin: Some([0.0, 0.0, 50.0]), ..kick_flight::FlightSpec::default() };
    let request = kick_study::aim::AimRequest {
        target: Some([25.0, -3.0, 1.5]),
        from: Some(kick_study::aim::AimFrom::Kick),
        ..kick_study::aim::AimRequest::default()
    };
    let (mut launch, mut kick) = (Vec::new(), Vec::new());
    for _ in 0..repeats {
        let started = Instant::now();
        std::hint::black_box(aim_launch([25.0, 2.8, 2.0], Wall::default(), &LaunchFree::DEFAULT, &curl).map_err(|e| e.to_string())?);
        launch.push(started.elapsed().as_secs_f64());
        let started = Instant::now();
        std::hint::black_box(kick_study::aim::aim(&request).map_err(|e| e.to_string())?);
        kick.push(started.elapsed().as_secs_f64());
    }
    Ok((median(&mut launch), median(&mut kick)))
}

/// How many forms [`kick_costs`] times.
pub const KICK_FORMS: usize = 9;

/// One off-center 3D kick (Table 1, 5 cm offset, `accurate`, one core) in
/// [`KICK_FORMS`] forms, µs per kick and evaluations, timed in alternation,
/// medians: the default spring at μ = ∞, a stiff spring at μ = 0.5
/// (k_t = 1e9 N/m, which tends to rigid grip at that μ), rigid grip as a
/// constraint (k_t = ∞), the shell ball at μ = 0.5; then the shell ball's
/// patch (issue 22's ≤ 100 µs at any μ): on the knife-edge face at μ = 0.5
/// and in rigid grip at μ = ∞, and on a convex instep (the assumed cap,
/// face square) likewise; the last again on the baseline x86-64 copy
/// (`Accurate3d::solve_baseline`: what a CPU without AVX2 runs).
fn kick_costs(min_seconds: f64) -> Result<[(f64, u64); KICK_FORMS], String> {
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
    ];
    let solver = Accurate3d::default();
    let mut times: [Vec<f64>; KICK_FORMS] = Default::default();
    let mut evaluations = [0u64; KICK_FORMS];
    let forms: Vec<(&kick_3d::Kick3d, bool)> = kicks.iter().map(|k| (k, false)).chain([(&kicks[7], true)]).collect();
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
    let mut out = [(0.0, 0); KICK_FORMS];
    for i in 0..KICK_FORMS {
        out[i] = (median(&mut times[i]) * 1e6, evaluations[i]);
    }
    Ok(out)
}

fn median(values: &mut [f64]) -> f64 {
    values.sort_by(f64::total_cmp);
    values[values.len() / 2]
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
            shard: None,
            threads: None,
            compress: Compression::None,
        };
        let report = pool.install(|| crate::sweep3d::sweep3d(&settings))?;
        let bytes = std::fs::metadata(&report.path).map_err(|e| e.to_string())?.len();
        let command = format!("kick sweep3d --samples {samples_3d} --seed 1 --threads 2 --law shell --out sweep3d.h5");
        runs.push(FileRun { command, rows: samples_3d, seconds: report.seconds, bytes });
        let _ = std::fs::remove_file(&report.path);
        Ok(())
    };
    let result = measure();
    let _ = std::fs::remove_dir_all(&dir);
    result.map(|()| runs)
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
    let mut ratios = Vec::new();
    let (mut seed, mut auto) = (None, None);
    for _ in 0..5 {
        let s = precision::measure("seed-rk4", 5e-6, &seed_rk4, &cases, min_time).map_err(|e| e.to_string())?;
        let a = precision::measure("auto", kick_compliant::series::DEFAULT_TOLERANCE, &default_auto, &cases, min_time)
            .map_err(|e| e.to_string())?;
        ratios.push(s.seconds_per_scenario / a.seconds_per_scenario);
        (seed, auto) = (Some(s), Some(a));
    }
    ratios.sort_by(f64::total_cmp);
    let ratio = ratios[ratios.len() / 2];
    let (seed, auto) = (seed.ok_or("no seed point")?, auto.ok_or("no auto point")?);
    let _ = writeln!(
        log,
        "\nauto (default) vs seed-rk4 at 5 µs: error {:.2e} vs {:.2e}; cost ratio {:.1}x (median of 5 alternating runs; {:.1}-{:.1}x)",
        auto.max_error,
        seed.max_error,
        ratio,
        ratios[0],
        ratios[ratios.len() - 1]
    );
    let sweep = SampledSweep::new(if args.quick { 2_000 } else { args.sweep_samples }, 1);
    // 1 and 2 threads in alternation, three times; the medians (shared machine).
    let (mut ones, mut twos) = (Vec::new(), Vec::new());
    for _ in 0..3 {
        ones.push(throughput(&default_auto, sweep, 1)?);
        twos.push(throughput(&default_auto, sweep, 2)?);
    }
    ones.sort_by(f64::total_cmp);
    twos.sort_by(f64::total_cmp);
    let (one, two) = (ones[1], twos[1]);
    let _ = writeln!(
        log,
        "sweep of {} sampled scenarios (auto, summary only): {:.0}/s on 1 thread, {:.0}/s on 2 threads, speed-up {:.2}x \
         (medians of 3 alternating runs; 2 threads {:.0}-{:.0}/s)",
        sweep.samples,
        one,
        two,
        two / one,
        twos[0],
        twos[2]
    );
    let kicks = if args.quick { 20 } else { 200 };
    let cost = kick_3d::precision::cost_ratio(kicks, kick_3d::models::BENCH_SEED, min_time / 30.0).map_err(|e| e.to_string())?;
    let _ = writeln!(
        log,
        "off-center 3D kick (auto) vs the same kick's 1D contact (auto): {:.1} µs vs {:.2} µs, ratio {:.1}x \
         (medians over {kicks} kicks of kick_3d::models::OffCenterBox, timed alternately)",
        cost.seconds_3d * 1e6,
        cost.seconds_1d * 1e6,
        cost.ratio
    );

    // The shell ball's 1D cost beside the paper's law: the same sampled
    // scenarios with `law = shell`, auto, one thread, alternated, medians.
    let mut shell_sweep = sweep;
    shell_sweep.fixed.law = Some(kick_core::LawKind::Shell);
    let (mut paper_law, mut shell) = (Vec::new(), Vec::new());
    for _ in 0..3 {
        paper_law.push(throughput(&default_auto, sweep, 1)?);
        shell.push(throughput(&default_auto, shell_sweep, 1)?);
    }
    let (paper_law, shell) = (median(&mut paper_law), median(&mut shell));
    let _ = writeln!(
        log,
        "shell ball, 1D (auto, 1 thread): {shell:.0} scenarios/s against {paper_law:.0} with the paper's law, {:.1}x the cost",
        paper_law / shell
    );
    // Flights through `flight_many`, 1 and 2 threads alternated, medians.
    let flight_rows = if args.quick { 1_000 } else { 50_000 };
    let (mut flights_1, mut flights_2) = (Vec::new(), Vec::new());
    for _ in 0..3 {
        flights_1.push(flights_per_second(flight_rows, 1)?);
        flights_2.push(flights_per_second(flight_rows, 2)?);
    }
    let (flights_1, flights_2) = (median(&mut flights_1), median(&mut flights_2));
    let _ = writeln!(log, "flight_many of {flight_rows} free kicks: {flights_1:.0} flights/s on 1 thread, {flights_2:.0} on 2 threads");
    let (aim_launch_s, aim_kick_s) = aim_seconds(if args.quick { 1 } else { 5 })?;
    let _ = writeln!(log, "aim solve: {:.2} ms for the launch, {:.2} ms through the 3D kick", aim_launch_s * 1e3, aim_kick_s * 1e3);
    let kicks = kick_costs(min_time / 30.0)?;
    let _ = writeln!(
        log,
        "5 cm kick, one core: default spring {:.1} µs, stiff spring {:.1} µs, rigid grip {:.1} µs, shell ball {:.1} µs; \
         patch: knife edge {:.1} µs, rigid {:.1} µs; cap {:.1} µs, rigid {:.1} µs (baseline copy {:.1} µs)",
        kicks[0].0, kicks[1].0, kicks[2].0, kicks[3].0, kicks[4].0, kicks[5].0, kicks[6].0, kicks[7].0, kicks[8].0
    );
    let other = Other { shell, paper_law, flight_rows, flights_1, flights_2, aim_launch: aim_launch_s, aim_kick: aim_kick_s, kicks };

    let files = file_runs(args.quick)?;
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
        writer.push_outcome(0, Ok(&[p.max_error, p.seconds_per_scenario, p.evaluations_per_scenario])).map_err(|e| e.to_string())?;
    }
    let names: Vec<String> = points.iter().map(|p| p.solver.to_string()).collect();
    write_strings(writer.file(), &path, "scenario_names", &names).map_err(|e| e.to_string())?;
    for (name, value) in [
        ("auto_vs_seed_cost_ratio", ratio),
        ("auto_max_error", auto.max_error),
        ("sweep_per_second_1_thread", one),
        ("sweep_per_second_2_threads", two),
        ("sweep_samples", sweep.samples as f64),
        ("off_center_3d_vs_1d_cost_ratio", cost.ratio),
        ("shell_vs_paper_law_1d_cost_ratio", paper_law / shell),
        ("flights_per_second_1_thread", flights_1),
        ("flights_per_second_2_threads", flights_2),
        ("aim_launch_seconds", aim_launch_s),
        ("aim_kick_seconds", aim_kick_s),
    ] {
        write_f64_attr(writer.file(), &path, name, value).map_err(|e| e.to_string())?;
    }
    crate::h5::write_str_attr(writer.file(), &path, "machine_cpu", &machine.cpu).map_err(|e| e.to_string())?;
    write_f64_attr(writer.file(), &path, "machine_cores", machine.cores as f64).map_err(|e| e.to_string())?;
    let path = writer.finish().map_err(|e| e.to_string())?;
    let mut written = vec![path.clone()];
    written.extend(draw(&path, &args.out.join("figures"))?);
    let measured = Measured {
        points: &points,
        seed: &seed,
        auto: &auto,
        ratio,
        ratios: &ratios,
        one,
        two,
        samples: sweep.samples,
        cost: &cost,
        files: &files,
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
        cost_ratio: ratio,
        auto_max_error: auto.max_error,
        seed_max_error: seed.max_error,
        sweep_per_second_1_thread: one,
        sweep_per_second_2_threads: two,
        off_center_3d_vs_1d_cost_ratio: cost.ratio,
        shell_vs_paper_law_1d_cost_ratio: paper_law / shell,
        flights_per_second_2_threads: flights_2,
        written,
    })
}

struct Measured<'a> {
    points: &'a [PrecisionPoint],
    seed: &'a PrecisionPoint,
    auto: &'a PrecisionPoint,
    ratio: f64,
    ratios: &'a [f64],
    one: f64,
    two: f64,
    samples: u64,
    cost: &'a kick_3d::precision::CostRatio,
    files: &'a [FileRun],
    other: &'a Other,
}

/// The shell ball's cost, flights and aims.
struct Other {
    /// Scenarios/s, auto, one thread: the shell ball and the paper's law.
    shell: f64,
    paper_law: f64,
    flight_rows: usize,
    flights_1: f64,
    flights_2: f64,
    /// Seconds per aim solve.
    aim_launch: f64,
    aim_kick: f64,
    /// µs and evaluations per kick ([`kick_costs`]).
    kicks: [(f64, u64); KICK_FORMS],
}

/// The machine a timing was taken on.
#[derive(Debug, Clone, PartialEq)]
pub struct Machine {
    /// CPU model (`model name` of /proc/cpuinfo), or "unknown".
    pub cpu: String,
    /// Cores this process may use.
    pub cores: usize,
}

impl Machine {
    pub fn this() -> Machine {
        let cpu = std::fs::read_to_string("/proc/cpuinfo")
            .ok()
            .and_then(|text| {
                text.lines().find(|l| l.starts_with("model name")).and_then(|l| l.split_once(':')).map(|(_, v)| v.trim().to_string())
            })
            .unwrap_or_else(|| "unknown".into());
        let cores = std::thread::available_parallelism().map(|n| n.get()).unwrap_or(1);
        Machine { cpu, cores }
    }

    fn describe(&self) -> String {
        format!("{}, {} cores available, {} {}", self.cpu, self.cores, std::env::consts::OS, std::env::consts::ARCH)
    }
}

impl Measured<'_> {
    /// Errors and evaluation counts: the same on every run.
    fn solvers_markdown(&self, command: &str, timing: Option<&str>) -> String {
        let mut rows = String::new();
        for p in self.points {
            rows.push_str(&format!("| {} | {:.2e} | {:.2e} | {:.0} |\n", p.solver, p.setting, p.max_error, p.evaluations_per_scenario));
        }
        let timing = timing
            .map(|t| {
                format!("Times, cost ratios, sweep throughput and the work–precision figure depend on the machine: see [timing]({t}).\n\n")
            })
            .unwrap_or_default();
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
             (times of the peak and of δ_max relative to the contact time), over Table 2, five elastic, six linear and \
             three driven scenarios, against the closed forms where they exist and `accurate` at 1e-14 elsewhere.\n\n\
             | solver | tolerance or step (s) | max error | evaluations per scenario |\n| --- | --- | --- | --- |\n{rows}\n\
             - `auto` at its default tolerance: largest error {:.2e}; `seed-rk4` at 5 µs: {:.2e} \
             (step quantisation of the contact time and the missed onset jump c·V0).\n\n\
             ## Where each solver is trustworthy\n\n\
             Held by `crates/kick-compliant/tests/solvers/stress.rs` (k 1e2–1e12, n 1–3, ζ 0–50, m_f/m_b 1e-3–1e6, V0 1e-3–1e3 m/s, drives to 1e4 N, \
             grazing contact) and `crates/kick-compliant/tests/solvers/accurate_vs_closed_forms.rs`:\n\n\
             - `closed-form`, `series`, `reduced-return`, `reduced`, `auto`: agree with each other and the closed forms to \
             1e-8 over the whole box; against the closed forms and `accurate` at 1e-14 on the paper's range and the sweep's \
             box, 1e-9 (measured ~1e-11; `crates/kick-compliant/tests/solvers/series.rs`).\n\
             - `accurate`, `dop853`, `dopri5`, `rk4-events` carry x_f, x_b, v_f, v_b, whose differences make δ and δ̇: \
             their error grows with |v|/V0 and |v| t_c/δ_max (grazing contact at high speed, long shallow contacts), \
             and under a drive with (μ/m_f) F δ_max / (½ μ V0²); within 1e-8 times that conditioning.\n\
             - `seed-rk4`: fourth order between steps, but the contact time is quantised to the step and a damped \
             contact's peak misses the onset jump; ~2e-2 relative at 5 µs on this set.\n\
             - A drive that keeps the ball pressed ends in a typed `NoSeparation` error: proved at the first maximum \
             compression for the paper's law, or after the documented horizon (1000 undriven contact times, or 100 000 \
             steps in one phase).\n",
            self.auto.max_error, self.seed.max_error,
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
        // One kick form of [`kick_costs`]: µs (evaluations).
        let kick = |i: usize| format!("{:.1} µs ({})", self.other.kicks[i].0, self.other.kicks[i].1);
        let body = format!(
            "# Timing of the 1D solvers\n\n\
             Generated by `{command}` (part of `kick reproduce`) on {}, {}. Every number below was measured in that run \
             and changes from run to run: this page and `{data}` are the only outputs of `kick reproduce` that do. \
             Timings on a shared machine move by tens of percent between runs; ratios are taken within one run.\n\n\
             ## Work–precision\n\n![work–precision]({figure})\n\n\
             | solver | tolerance or step (s) | max error | µs per scenario |\n| --- | --- | --- | --- |\n{rows}\n\
             ## Headline numbers\n\n\
             - Cost ratio seed-rk4 / auto: **{:.1}x** (median of 5 alternating measurements, range {:.1}–{:.1}x).\n\
             - Sampled sweep of {} scenarios (auto, summary only, no file): {:.0} scenarios/s on 1 thread, \
             {:.0} scenarios/s on 2 threads, parallel speed-up {:.2}x (medians of 3 alternating runs).\n\
             - Off-center 3D kick against the same kick's 1D contact along its normal (both `auto`, one core, \
             medians over {} kicks of `kick_3d::models::OffCenterBox`, seed {}, timed alternately): {:.1} µs against \
             {:.2} µs, **{:.1}x**; {:.0} against {:.0} right-hand-side evaluations per kick. The 3D path's error \
             against its tightened reference is held to 1e-9 by `crates/kick-3d/tests/model/box_accuracy.rs`.\n\
             - The shell ball (`law = shell`) in 1D, the same sampled scenarios, `auto`, one thread: {:.0} scenarios/s \
             against {:.0} with the paper's law: **{:.1}x** the cost (medians of 3 alternating runs); both take the \
             `series` path (`kick_compliant::shell_series` for the shell ball).\n\
             - Flights: {} free kicks (18°, 9 rev/s of sidespin, 22–32 m/s, `kick_flight::models::free_kick_speeds`) \
             through `flight_many` (Python's `kick.flight_many`): {:.0} flights/s on 1 thread, **{:.0} flights/s on 2 \
             threads** (medians of 3 alternating runs), {:.2} µs per flight on one.\n\
             - Aim solves (median of 5): {:.2} ms for the launch (`kick aim --target 25,2.8,2 --spin 0,0,50`), \
             {:.2} ms through the 3D kick (`kick aim --target 25,-3,1.5 --from kick`).\n\
             - One off-center kick (Table 1, 5 cm offset, `accurate`, one core, medians of 5 alternating \
             measurements), µs and right-hand-side evaluations: μ = ∞ with the default spring {}; a stiff \
             spring at μ = 0.5 (k_t = 1e9 N/m: slip, then grip within a micrometre of rigid grip's) {}; rigid grip as a \
             constraint (`--tangential-stiffness inf`) {}; the shell ball at μ = 0.5 {}. \
             The shell ball's patch (`--patch-contact`): on the knife-edge face at μ = 0.5 {}, in rigid \
             grip at μ = ∞ {}; on a convex instep (`--instep-radius {} --face-yaw 0`) at μ = 0.5 {}, \
             in rigid grip at μ = ∞ {}. These run the kick's AVX2 copy where the CPU has AVX2 (the results are \
             the baseline copy's, bit for bit); the last on the baseline x86-64 copy: {}.\n",
            machine.describe(),
            crate::provenance::utc_timestamp(std::time::SystemTime::now()),
            self.ratio,
            self.ratios[0],
            self.ratios[self.ratios.len() - 1],
            self.samples,
            self.one,
            self.two,
            self.two / self.one,
            self.cost.kicks,
            self.cost.seed,
            self.cost.seconds_3d * 1e6,
            self.cost.seconds_1d * 1e6,
            self.cost.ratio,
            self.cost.evaluations_3d,
            self.cost.evaluations_1d,
            self.other.shell,
            self.other.paper_law,
            self.other.paper_law / self.other.shell,
            self.other.flight_rows,
            self.other.flights_1,
            self.other.flights_2,
            1e6 / self.other.flights_1,
            self.other.aim_launch * 1e3,
            self.other.aim_kick * 1e3,
            kick(0),
            kick(1),
            kick(2),
            kick(3),
            kick(4),
            kick(5),
            kick_3d::validation::ASSUMED_INSTEP_RADIUS,
            kick(6),
            kick(7),
            kick(8),
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
