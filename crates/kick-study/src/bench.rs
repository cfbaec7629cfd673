//! The benchmark's measurements (`kick bench`): the work–precision ladder
//! of every 1D solver, the headline cost ratios, sweep and flight
//! throughput, the aims and the 3D kicks' costs, each timed in one run of
//! one binary and repeated in alternation (the machine is shared). The
//! files of the timed sweeps and `work_precision.h5` are kick-store's
//! (`kick_store::bench`), the page and figure kick-paper's.

use crate::sample::SampledSweep;
pub use kick_3d::precision::CostRatio;
use kick_compliant::precision;
pub use kick_compliant::precision::{PrecisionPoint, ReferenceError, REFERENCE_TOLERANCE, SERIES_CHECK_TOLERANCE};
use kick_compliant::SolverChoice;
use kick_core::Solver;
use rayon::prelude::*;
use serde::Serialize;
use std::io::Write;
use std::time::Instant;

/// Why a benchmark could not be taken: a model's error where a timed solve
/// failed (its scenario named where the bench knows it), or a thread pool
/// that cannot be built.
#[derive(Debug, thiserror::Error)]
pub enum BenchError {
    #[error(transparent)]
    ThreadPool(#[from] rayon::ThreadPoolBuildError),
    #[error(transparent)]
    Kick(#[from] kick_core::KickError),
    #[error(transparent)]
    Kick3d(#[from] kick_3d::Kick3dError),
    #[error(transparent)]
    Flight(#[from] kick_flight::FlightError),
    #[error(transparent)]
    Study(#[from] crate::error::StudyError),
    /// One of the timed flights failed.
    #[error("a bench flight failed: {0}")]
    FlightRow(kick_flight::FlightError),
    /// The reference solve of a box scenario failed (not a trapped foot).
    #[error("box scenario {index}: the reference: {source}")]
    BoxReference { index: u64, source: kick_core::KickError },
    /// A box solver failed where the reference separates.
    #[error("box scenario {index}: {solver}: {source}")]
    BoxSolver { index: u64, solver: &'static str, source: kick_core::KickError },
    /// A ladder point that could not be measured.
    #[error("{solver}: {source}")]
    Ladder { solver: &'static str, source: kick_core::KickError },
    /// A setting out of range, the message naming its flag.
    #[error("{0}")]
    Setting(String),
    /// A run the bench takes and then reads back was not there (`what`).
    #[error("no {0}")]
    NoRun(&'static str),
}

/// The front ends and the page writers still returning text print the message.
impl From<BenchError> for String {
    fn from(e: BenchError) -> String {
        e.to_string()
    }
}

/// The seed of kick-3d's test box of off-center kicks.
pub use kick_3d::models::BENCH_SEED;
/// The instep radius the patch kicks assume, m.
pub use kick_3d::validation::ASSUMED_INSTEP_RADIUS;
/// `auto`'s default tolerance (the `series` path's).
pub use kick_compliant::series::DEFAULT_TOLERANCE as AUTO_TOLERANCE;

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
    pub fn show(&self, decimals: usize, unit: &str) -> String {
        format!("{:.decimals$}{unit} (range {:.decimals$}–{:.decimals$}{unit})", self.median, self.low, self.high)
    }
}

/// Scenarios per second of `solver` on the sweep, on a pool of `threads`.
pub fn throughput(solver: &SolverChoice, sweep: SampledSweep, threads: usize) -> Result<f64, BenchError> {
    let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build()?;
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
pub fn flights_per_second(rows: usize, threads: usize) -> Result<f64, BenchError> {
    let (base, speeds) = kick_flight::models::free_kick_speeds(rows);
    let columns = [kick_flight::Column { parameter: kick_flight::FlightParameter::Speed, values: &speeds }];
    let started = Instant::now();
    let out = kick_flight::flight_many(&base, &columns, rows, Some(threads))?;
    let seconds = started.elapsed().as_secs_f64();
    if let Some(Err(e)) = out.iter().find(|r| r.is_err()) {
        return Err(BenchError::FlightRow(e.clone()));
    }
    Ok(rows as f64 / seconds)
}

/// Seconds of each aim solve of paper/flight.md ([`crate::aimed::aim_requests`]:
/// the launch, then through the 3D kick), `repeats` times in alternation.
pub fn aim_seconds(repeats: usize) -> Result<[Vec<f64>; 2], BenchError> {
    let requests = crate::aimed::aim_requests();
    let mut seconds: [Vec<f64>; 2] = Default::default();
    for _ in 0..repeats {
        for (request, out) in requests.iter().zip(seconds.iter_mut()) {
            let started = Instant::now();
            std::hint::black_box(crate::aim::aim(request)?);
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
pub fn kick_costs(min_seconds: f64) -> Result<[(Vec<f64>, u64); KICK_FORMS], BenchError> {
    use kick_3d::{Accurate3d, Kick3dSpec, KickSpec};
    let at = |scenario: kick_core::ScenarioSpec, kick3d: Kick3dSpec| KickSpec { scenario, kick3d }.build();
    let spec = Kick3dSpec { offset: Some(0.05), friction: Some(f64::INFINITY), ..Kick3dSpec::default() };
    let shell = kick_core::ScenarioSpec { law: Some(kick_core::LawKind::Shell), ..Default::default() };
    let cap = Kick3dSpec { friction: Some(f64::INFINITY), ..kick_3d::models::cap_patch_kick() };
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
                evaluations[i] = std::hint::black_box(solved?).evaluations;
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

/// Where the realistic foot's 3D kick spends its evaluations (the last form
/// of [`kick_costs`], issue 31's ≤ 120 µs): the same kick with the leg
/// alone, the boot alone, and the leg with its boot at μ = ∞ (no slip), one
/// solve each (evaluation counts do not vary from run to run), and the
/// boot's relaxation time at touch, c_b/(k_b + k(0)).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FootCost {
    pub leg_only: u64,
    pub boot_only: u64,
    pub without_slip: u64,
    /// s.
    pub layer_time: f64,
}

/// See [`FootCost`].
pub fn foot_cost() -> Result<FootCost, BenchError> {
    use kick_3d::{Accurate3d, Kick3dSpec, KickSpec};
    let shell = kick_core::ScenarioSpec { law: Some(kick_core::LawKind::Shell), ..Default::default() };
    let cap = kick_3d::models::cap_patch_kick();
    let boot = kick_core::boot::IDENTIFIED;
    let evaluations = |scenario: kick_core::ScenarioSpec, friction: f64| -> Result<u64, BenchError> {
        let kick = KickSpec { scenario, kick3d: Kick3dSpec { friction: Some(friction), ..cap } }.build()?;
        Ok(Accurate3d::default().solve(&kick)?.evaluations)
    };
    let leg_only = evaluations(kick_core::ScenarioSpec { leg: Some(true), boot_stiffness: Some(f64::INFINITY), ..shell }, 0.5)?;
    let boot_only =
        evaluations(kick_core::ScenarioSpec { boot_stiffness: Some(boot.stiffness), boot_damping: Some(boot.damping), ..shell }, 0.5)?;
    let without_slip = evaluations(kick_core::ScenarioSpec { leg: Some(true), ..shell }, f64::INFINITY)?;
    let kick = KickSpec { scenario: shell, kick3d: cap }.build()?;
    let layer_time = boot.time_constant(kick_core::ContactLaw::force_gradient(&kick.law, 0.0, 0.0).0);
    Ok(FootCost { leg_only, boot_only, without_slip, layer_time })
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
pub fn box_errors(samples: u64) -> Result<BoxErrors, BenchError> {
    let sweep = SampledSweep::new(samples, 1);
    let tight = kick_compliant::Accurate::new(precision::REFERENCE_TOLERANCE, precision::REFERENCE_TOLERANCE)?;
    let solvers: Vec<SolverChoice> = BOX_SOLVERS.iter().map(|n| SolverChoice::from_name(n, 5e-6)).collect::<Result<_, _>>()?;
    let mut errors: Vec<(&'static str, f64, u64)> = BOX_SOLVERS.iter().map(|&n| (n, 0.0, 0)).collect();
    let mut trapped = 0;
    for i in 0..samples {
        let scenario = sweep.scenario(i)?;
        let reference = match tight.solve(&scenario) {
            Ok(o) => o,
            Err(kick_core::KickError::Trapped { .. }) => {
                trapped += 1;
                continue;
            }
            Err(source) => return Err(BenchError::BoxReference { index: i, source }),
        };
        for (solver, entry) in solvers.iter().zip(errors.iter_mut()) {
            match solver.solve(&scenario) {
                Ok(o) => {
                    entry.1 = entry.1.max(precision::max_relative_error(&o, &reference));
                    entry.2 += 1;
                }
                Err(kick_core::KickError::NotApplicable { .. }) => {}
                Err(source) => return Err(BenchError::BoxSolver { index: i, solver: entry.0, source }),
            }
        }
    }
    Ok(BoxErrors { samples, trapped, errors })
}

/// The cost ratio at equal accuracy ([`equal_accuracy_pair`]), re-timed in alternation.
#[derive(Debug, Clone)]
pub struct EqualAccuracy {
    pub fixed: PrecisionPoint,
    pub auto: PrecisionPoint,
    /// fixed / auto, seconds per scenario.
    pub ratio: Spread,
}

/// What [`measure`] timed, in one run.
#[derive(Debug, Clone)]
pub struct Timings {
    /// The work–precision ladder.
    pub points: Vec<PrecisionPoint>,
    /// seed-rk4 at 5 µs and `auto` at its default, from the headline's last run.
    pub seed: PrecisionPoint,
    pub auto: PrecisionPoint,
    /// seed-rk4 / auto (default), 5 alternating runs.
    pub headline: Spread,
    pub equal: Option<EqualAccuracy>,
    pub reference_error: ReferenceError,
    pub box_errors: BoxErrors,
    /// Scenarios per second on 1 and 2 threads, and 2 over 1.
    pub one: Spread,
    pub two: Spread,
    pub speed_up: Spread,
    pub samples: u64,
    /// The 3D cost run whose ratio is the median of [`Timings::cost_3d`].
    pub cost: CostRatio,
    pub cost_3d: Spread,
    pub other: Other,
}

/// The longest `--min-time` per point: the bench times some 80 points,
/// so an hour's run at most.
pub const MAX_MIN_TIME: f64 = 60.0;

/// `--min-time` in (0, [`MAX_MIN_TIME`]] s and `--sweep-samples` in
/// 1..=[`crate::limits::MAX_SCENARIOS`], checked before anything runs (1e300
/// s timed one point for ever; NaN ran the default).
pub fn check_settings(min_time: f64, sweep_samples: u64) -> Result<(), BenchError> {
    if !(min_time > 0.0 && min_time <= MAX_MIN_TIME) {
        return Err(BenchError::Setting(format!(
            "--min-time {}: must be a time in (0, {}] s",
            kick_core::short(min_time),
            kick_core::short(MAX_MIN_TIME)
        )));
    }
    if !(1..=crate::limits::MAX_SCENARIOS).contains(&sweep_samples) {
        return Err(BenchError::Setting(format!(
            "--sweep-samples {sweep_samples}: must be between 1 and {}",
            crate::limits::MAX_SCENARIOS
        )));
    }
    Ok(())
}

/// Time everything but the files: the ladder (a few points when `quick`),
/// each point at least `min_time` s, the throughput over `sweep_samples`
/// sampled scenarios. Progress lines go to `log`.
pub fn measure(quick: bool, min_time: f64, sweep_samples: u64, log: &mut dyn Write) -> Result<Timings, BenchError> {
    check_settings(min_time, sweep_samples)?;
    let min_time = if quick { 0.02 } else { min_time };
    let cases = precision::cases()?;
    let mut ladder = precision::ladder();
    if quick {
        ladder.retain(|(name, setting)| matches!((*name, *setting), ("seed-rk4", s) if s == 5e-6) || *setting == 1e-12 || *setting == 1e-8);
    }
    let mut points: Vec<PrecisionPoint> = Vec::new();
    for (name, setting) in ladder {
        let solver = precision::solver(name, setting)?;
        let point =
            precision::measure(name, setting, &solver, &cases, min_time).map_err(|source| BenchError::Ladder { solver: name, source })?;
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
    let seed_rk4 = SolverChoice::from_name("seed-rk4", 5e-6)?;
    let default_auto = SolverChoice::from_name("auto", 5e-6)?;
    let (mut seed_times, mut auto_times) = (Vec::new(), Vec::new());
    let (mut seed, mut auto) = (None, None);
    for _ in 0..5 {
        let s = precision::measure("seed-rk4", 5e-6, &seed_rk4, &cases, min_time)?;
        let a = precision::measure("auto", kick_compliant::series::DEFAULT_TOLERANCE, &default_auto, &cases, min_time)?;
        seed_times.push(s.seconds_per_scenario);
        auto_times.push(a.seconds_per_scenario);
        (seed, auto) = (Some(s), Some(a));
    }
    let headline = Spread::of_ratios(&seed_times, &auto_times);
    let (seed, auto) = (seed.ok_or(BenchError::NoRun("seed point"))?, auto.ok_or(BenchError::NoRun("auto point"))?);
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
            let (fixed_solver, auto_solver) =
                (precision::solver(fixed.solver, fixed.setting)?, precision::solver(cheap.solver, cheap.setting)?);
            let (mut f, mut a) = (Vec::new(), Vec::new());
            for _ in 0..5 {
                f.push(precision::measure(fixed.solver, fixed.setting, &fixed_solver, &cases, min_time)?.seconds_per_scenario);
                a.push(precision::measure(cheap.solver, cheap.setting, &auto_solver, &cases, min_time)?.seconds_per_scenario);
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
    let reference_error = precision::reference_error(&cases)?;
    let box_errors = box_errors(if quick { 200 } else { 2000 })?;
    let sweep = SampledSweep::new(if quick { 2_000 } else { sweep_samples }, 1);
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
    let kicks = if quick { 20 } else { 200 };
    let mut costs = Vec::new();
    for _ in 0..3 {
        costs.push(kick_3d::precision::cost_ratio(kicks, kick_3d::models::BENCH_SEED, min_time / 30.0)?);
    }
    let cost_3d = Spread::of(&costs.iter().map(|c| c.ratio).collect::<Vec<_>>());
    // The run whose ratio is the median, for its times and counts.
    let cost = costs.iter().find(|c| c.ratio == cost_3d.median).copied().ok_or(BenchError::NoRun("3D cost run"))?;
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
    let flight_rows = if quick { 1_000 } else { 50_000 };
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
    let aims = aim_seconds(if quick { 1 } else { 5 })?.map(|t| Spread::of(&t.iter().map(|s| s * 1e3).collect::<Vec<_>>()));
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
        foot: foot_cost()?,
    };

    Ok(Timings {
        points,
        seed,
        auto,
        headline,
        equal,
        reference_error,
        box_errors,
        one,
        two,
        speed_up,
        samples: sweep.samples,
        cost,
        cost_3d,
        other,
    })
}

/// The shell ball's cost, flights and aims.
#[derive(Debug, Clone, PartialEq)]
pub struct Other {
    /// Scenarios/s, auto, one thread: the shell ball and the paper's law, and the cost ratio.
    pub shell: Spread,
    pub paper_law: Spread,
    pub shell_cost: Spread,
    /// The shell ball with the leg and its boot, and its cost over the shell ball's.
    pub leg: Spread,
    pub leg_cost: Spread,
    pub flight_rows: usize,
    pub flights_1: Spread,
    pub flights_2: Spread,
    pub flight_speed_up: Spread,
    /// Milliseconds per aim solve: the launch, through the 3D kick.
    pub aims: [Spread; 2],
    /// µs and evaluations per kick ([`kick_costs`]).
    pub kicks: [(Spread, u64); KICK_FORMS],
    /// The baseline x86-64 copy over the AVX2 copy, the last form.
    pub baseline_copy: Spread,
    /// Where the realistic foot's kick spends its evaluations.
    pub foot: FootCost,
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

    pub fn describe(&self) -> String {
        let clock = match (self.clock_mhz, self.max_mhz) {
            (Some(now), Some(max)) => format!("clock {now:.0} MHz at the start (cpufreq maximum {max:.0} MHz)"),
            (Some(now), None) => format!("clock {now:.0} MHz at the start (/proc/cpuinfo; no frequency scaling exposed)"),
            (None, _) => "clock unknown".into(),
        };
        format!("{}, {}, {} cores available, {} {}", self.cpu, clock, self.cores, std::env::consts::OS, std::env::consts::ARCH)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// What the timing page says of the realistic foot's kick: each of the
    /// leg, the boot and the slip costs evaluations of its own, and the
    /// layer's relaxation time is c_b/(k_b + k) at touch, k from a
    /// difference of the shell law's force (not its gradient).
    #[test]
    fn each_part_of_the_realistic_foot_costs_evaluations() {
        let foot = foot_cost().unwrap();
        let full = kick_costs(0.0).unwrap()[KICK_FORMS - 1].1;
        assert!(foot.leg_only < full && foot.boot_only < full && foot.without_slip < full, "{foot:?} against {full}");
        let kick = kick_3d::KickSpec {
            scenario: kick_core::ScenarioSpec { law: Some(kick_core::LawKind::Shell), ..Default::default() },
            kick3d: kick_3d::models::cap_patch_kick(),
        }
        .build()
        .unwrap();
        let h = 1e-7;
        let k = kick_core::ContactLaw::force(&kick.law, h, 0.0) / h;
        let boot = kick_core::boot::IDENTIFIED;
        let expected = boot.damping / (boot.stiffness + k);
        assert!((foot.layer_time / expected - 1.0).abs() < 1e-5, "{} against {expected}", foot.layer_time);
    }
}
