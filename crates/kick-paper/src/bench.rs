//! `kick bench`: work–precision of every 1D solver, the headline ratios, and
//! sweep throughput, measured in one run of one binary.
//!
//! What depends on the clock (times, ratios, throughput, the work–precision
//! figure, whose x axis is time) goes to the timing file and page, with the
//! machine's description; `kick reproduce` puts them in `results/timing/` and
//! `paper/timing.md`, the only outputs a second run may change. Errors and
//! evaluation counts do not depend on the clock: they make the solvers page.

use crate::error::PaperError;
use crate::figures::{save_grid, Panel, Series};
use crate::h5::SweepData;
use crate::printable::Printable;
pub use kick_store::bench::{file_runs, flown_command, leg_command, sweep3d_rates, FileRun, Sweep3dRates};
pub use kick_study::bench::*;
use plotters::prelude::SeriesLabelPosition;
use serde::Serialize;
use std::io::Write;
use std::path::PathBuf;

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
    /// 3D kicks with the leg and its boot into a file on 2 threads (`sweep3d --leg`, shell ball; issue 31: at least 10,000).
    pub sweep3d_leg_rows_per_second_2_threads: f64,
    #[serde(skip)]
    pub written: Vec<PathBuf>,
}

impl Printable for BenchReport {
    fn text(&self) -> String {
        self.written.iter().map(|p| format!("-> {}\n", p.display())).collect()
    }
}

/// Measure every solver's work and precision, the headline ratios and the
/// sweep throughput (one run, one binary: kick-study times, kick-store
/// writes the timed sweeps and work_precision.h5); draw its figure and, if
/// asked, the pages. Progress lines go to `log`.
pub fn bench(args: &BenchSettings, log: &mut dyn Write) -> Result<BenchReport, PaperError> {
    let min_time = if args.quick { 0.02 } else { args.min_time };
    // Settings and folders are checked before an hour of timing, not at its end.
    kick_study::bench::check_settings(args.min_time, args.sweep_samples)?;
    let report_folders = [&args.report, &args.solvers_report].into_iter().flatten().filter_map(|r| r.parent());
    for folder in std::iter::once(args.out.join("figures").as_path()).chain(report_folders).filter(|f| !f.as_os_str().is_empty()) {
        std::fs::create_dir_all(folder).map_err(|source| PaperError::Io { what: "create", path: folder.to_path_buf(), source })?;
    }
    let t = kick_study::bench::measure(args.quick, args.min_time, args.sweep_samples, log)?;
    let files = file_runs(args.quick)?;
    let sweeps = sweep3d_rates(args.quick)?;
    let _ = writeln!(
        log,
        "flown 3D kicks into a file, 2 threads: {} rows/s, the same kicks unflown {} rows/s, {} the cost ({})",
        sweeps.flown.show(0, ""),
        sweeps.unflown.show(0, ""),
        sweeps.cost.show(2, "x"),
        flown_command(sweeps.samples, true)
    );
    let _ = writeln!(
        log,
        "3D kicks with the leg into a file, 2 threads: {} rows/s, without it {} rows/s, {} the cost ({})",
        sweeps.leg.show(0, ""),
        sweeps.shell.show(0, ""),
        sweeps.leg_cost.show(2, "x"),
        leg_command(sweeps.samples, true)
    );
    for run in &files {
        let _ = writeln!(
            log,
            "{}: {} s, {} rows/s, {} MB",
            run.command,
            kick_study::printable::sig(run.seconds),
            kick_study::printable::sig(run.rows as f64 / run.seconds),
            kick_study::printable::sig(run.bytes as f64 / 1e6)
        );
    }

    let text = format!("kick bench{} --min-time {min_time}", if args.quick { " --quick" } else { "" });
    let machine = Machine::this();
    let path = kick_store::bench::write_work_precision(&args.out.join("work_precision.h5"), &t, &sweeps, &machine, BUILD, &text)?;
    let mut written = vec![path.clone()];
    written.extend(draw(&path, &args.out.join("figures"))?);
    let measured = Measured {
        points: &t.points,
        seed: &t.seed,
        auto: &t.auto,
        headline: t.headline,
        equal: t.equal.as_ref(),
        reference_error: t.reference_error,
        box_errors: &t.box_errors,
        one: t.one,
        two: t.two,
        speed_up: t.speed_up,
        samples: t.samples,
        cost: &t.cost,
        cost_3d: t.cost_3d,
        files: &files,
        sweeps: &sweeps,
        other: &t.other,
    };
    if let Some(report) = &args.report {
        let report_dir = report.parent().unwrap_or(std::path::Path::new(""));
        let figure = crate::links::relative(report_dir, &args.out.join("figures/work_precision.png"));
        let data = crate::links::relative(report_dir, &path);
        crate::output::write(report, measured.timing_markdown(&figure, &data, &text, &machine))?;
        written.push(report.clone());
    }
    if let Some(report) = &args.solvers_report {
        let timing = args.report.as_ref().map(|t| crate::links::relative(report.parent().unwrap_or(std::path::Path::new("")), t));
        crate::output::write(report, measured.solvers_markdown(&text, timing.as_deref()))?;
        written.push(report.clone());
    }
    Ok(BenchReport {
        cost_ratio: t.headline.median,
        auto_max_error: t.auto.max_error,
        seed_max_error: t.seed.max_error,
        sweep_per_second_1_thread: t.one.median,
        sweep_per_second_2_threads: t.two.median,
        off_center_3d_vs_1d_cost_ratio: t.cost_3d.median,
        shell_vs_paper_law_1d_cost_ratio: t.other.shell_cost.median,
        leg_boot_vs_shell_1d_cost_ratio: t.other.leg_cost.median,
        flights_per_second_2_threads: t.other.flights_2.median,
        sweep3d_flown_rows_per_second_2_threads: sweeps.flown.median,
        sweep3d_leg_rows_per_second_2_threads: sweeps.leg.median,
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

struct Measured<'a> {
    points: &'a [PrecisionPoint],
    seed: &'a PrecisionPoint,
    auto: &'a PrecisionPoint,
    /// seed-rk4 / auto (default).
    headline: Spread,
    equal: Option<&'a EqualAccuracy>,
    reference_error: ReferenceError,
    box_errors: &'a BoxErrors,
    /// Scenarios per second on 1 and 2 threads, and 2 over 1.
    one: Spread,
    two: Spread,
    speed_up: Spread,
    samples: u64,
    /// The 3D cost run whose ratio is the median of [`Measured::cost_3d`].
    cost: &'a CostRatio,
    cost_3d: Spread,
    files: &'a [FileRun],
    sweeps: &'a Sweep3dRates,
    other: &'a Other,
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
             the tight reference ({auto_floor}); `seed-rk4` at 5 µs: {seed:.2e} \
             (step quantisation of the contact time and the missed onset jump c·V0).\n\n\
             ## Where each solver is trustworthy\n\n\
             Held by `crates/kick-compliant/tests/solvers/stress.rs` (k 1e2–1e12, n 1–3, ζ 0–50, m_f/m_b 1e-3–1e6, V0 1e-3–1e3 m/s, drives to 1e4 N, \
             grazing contact) and `crates/kick-compliant/tests/solvers/accurate_vs_closed_forms.rs`:\n\n\
             - At their defaults over the whole box (`stress.rs`): `auto` and `series` agree with `reduced` to 1e-8 times \
             the drive ratio 1 + (μ/m_f) F δ_max/(½ μ V0²) (1 without a drive), and `reduced` with the closed forms \
             (`closed-form`) to 1e-8; `series` is within 1e-9 of `accurate` at 1e-14 on the sweep's box \
             (`crates/kick-compliant/tests/solvers/series.rs`, 200 random scenarios). `reduced-return` is held only by \
             the measurement that follows. Here μ = m_f m_b/(m_f + m_b), V0 the approach speed at first touch, ζ the \
             damping ratio, and a trapped scenario one whose drive keeps the ball pressed (no separation). Measured \
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
            ref_tol = REFERENCE_TOLERANCE,
            closed = r.against_closed_forms,
            series = r.against_series,
            series_tol = SERIES_CHECK_TOLERANCE,
            auto_tol = self.auto.setting,
            auto_closed = error(self.auto.max_error_closed_form),
            auto_tight = self.auto.max_error_tight,
            auto_floor = {
                let floor = r.against_closed_forms.max(r.against_series);
                if self.auto.max_error_tight > floor {
                    format!("above that reference's floor, {floor:.1e}: `auto`'s own error, within its tolerance")
                } else {
                    format!("at that reference's floor, {floor:.1e}")
                }
            },
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
                    format!(
                        "{} ({:+.0}%)",
                        kick_study::printable::sig(run.bytes as f64 / 1e6),
                        100.0 * (run.bytes as f64 / p.bytes as f64 - 1.0)
                    )
                }
                _ => kick_study::printable::sig(run.bytes as f64 / 1e6).to_string(),
            };
            files.push_str(&format!(
                "| `{}`{} | {} | {} | {size} |\n",
                run.command,
                run.note.as_ref().map_or(String::new(), |n| format!(" ({n})")),
                kick_study::printable::sig(run.seconds),
                kick_study::printable::sig(run.rows as f64 / run.seconds)
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
        let flown_command = flown_command(self.sweeps.samples, true);
        let leg_command = leg_command(self.sweeps.samples, true);
        // A target of the issues against this run's median.
        let met = |median: f64, least: f64| if median >= least { "met" } else { "not met" };
        let [tx, ty, tz] = crate::free_kick::AIM_TARGET;
        let [sx, sy, sz] = crate::free_kick::AIM_SPIN;
        let short = kick_study::printable::short;
        let target = format!("{},{},{}", short(tx), short(ty), short(tz));
        let kick_names = [
            "μ = ∞, default spring".to_string(),
            "a stiff spring at μ = 0.5 (k_t = 1e9 N/m, towards rigid grip at that μ)".into(),
            "μ = ∞, rigid grip as a constraint (`--tangential-stiffness inf`)".into(),
            "the shell ball, μ = 0.5".into(),
            "the shell ball's patch (`--patch-contact`) on the knife-edge face, μ = 0.5".into(),
            "the patch on the knife-edge face, rigid grip at μ = ∞".into(),
            format!("the patch on a convex instep (`--instep-radius {} --face-yaw 0`), μ = 0.5", ASSUMED_INSTEP_RADIUS),
            "the patch on the convex instep, rigid grip at μ = ∞".into(),
            "the same, on the baseline x86-64 copy".into(),
            format!(
                "the realistic foot (`--leg`: the leg's 6×6 apparent inertia and its boot) on the convex instep's patch, μ = 0.5 \
                 (issue 31: ≤ 120 µs, {} in this run)",
                if o.kicks[KICK_FORMS - 1].0.median <= 120.0 { "met" } else { "not met" }
            ),
        ];
        let mut kick_rows = String::new();
        for (name, (t, evaluations)) in kick_names.iter().zip(&o.kicks) {
            kick_rows.push_str(&format!("| {name} | {:.1} | {:.1}–{:.1} | {evaluations} |\n", t.median, t.low, t.high));
        }
        // The realistic foot against the rigid foot on the same patch (the rows before the baseline copy's).
        let ((rigid, rigid_evaluations), (foot, foot_evaluations)) = (&o.kicks[6], &o.kicks[KICK_FORMS - 1]);
        let per = |t: &kick_study::bench::Spread, n: u64| t.median * 1e3 / n as f64;
        kick_rows.push_str(&format!(
            "\nThe realistic foot's kick takes {:.2}x the evaluations of the rigid foot's on the same patch \
             ({foot_evaluations} against {rigid_evaluations}), at {:.0} against {:.0} ns each. The leg alone takes {}, \
             the boot alone {}, the leg and its boot without slip (μ = ∞) {}. Two fast modes hold the 8th-order \
             steps at the default tolerance (1e-13): the boot's layer relaxes on c_b/(k_b + k), {:.2} ms at touch, \
             starting away from its slow motion; and in slip the slider's direction turns towards the sliding on \
             |ξ|/v_t, a time that shrinks with the normal force towards separation. Both reach every state through \
             the contact force. `cargo run --release -p kick-3d --example step_sizes_3d` prints the steps of each form.\n",
            *foot_evaluations as f64 / *rigid_evaluations as f64,
            per(foot, *foot_evaluations),
            per(rigid, *rigid_evaluations),
            o.foot.leg_only,
            o.foot.boot_only,
            o.foot.without_slip,
            o.foot.layer_time * 1e3,
        ));
        let body = format!(
            "# Timing of the 1D solvers\n\n\
             Generated by `{command}` (part of `kick reproduce`) on {}, {}. Build: {}. Every number below was measured \
             in that run and changes from run to run: this page, `{data}` and its figure (`results/timing/figures/`) \
             are the only outputs of `kick reproduce` that do. Timings on a shared machine move by tens of percent between runs; ratios are taken within one \
             run, each from measurements taken in alternation, and given as the median with the range over the \
             repetitions.\n\n\
             ## Work–precision\n\n![work–precision]({figure})\n\n\
             | solver | tolerance or step (s) | max error | µs per scenario |\n| --- | --- | --- | --- |\n{rows}\n\
             Errors are against closed forms or `accurate` at 1e-14, whichever the scenario has; [solvers.md](solvers.md) \
             gives the two apart and the tight reference's own error.\n\n\
             ## Headline numbers\n\n\
             - Cost ratio seed-rk4 / auto, each at its default (seed-rk4's step 5 µs, auto's tolerance {:.0e}): **{}** (5 alternating measurements), at errors {:.2e} \
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
             {:.0} scenarios/s, **{}** the shell ball's cost (`kick_compliant::boot::series`; issue 31: at most 2x, {} in this run).\n\
             - Flights: {} free kicks (18°, 9 rev/s of sidespin, 22–32 m/s, `kick_flight::models::free_kick_speeds`) \
             through `flight_many` (Python's `kick.flight_many`): {} flights/s on 1 thread, **{} flights/s on 2 \
             threads**, speed-up {} (3 alternating runs), {:.2} µs per flight on one.\n\
             - Flown 3D kicks into a file (`{flown_command} --out flown.h5`, the shell ball, each kick inside the \
             model's validity flown from the ground across the planes x = 9.15 and 25 m, the others written unflown: \
             the file run below says how many; issue 32: at least 10,000 rows/s, {} in this run): **{} rows/s \
             on 2 threads**; the same kicks without `--flight ...`: {} rows/s; the run with flights costs {} the \
             run without (3 alternating runs, medians): the 3D kick, not its flight, sets the rate.\n\
             - The realistic foot in 3D sweeps (`{leg_command} --out leg.h5`, the leg's 6×6 apparent inertia and its boot \
             on the shell ball over the default box, point contact; issue 31: at least 10,000 kicks/s, {} in this run): \
             **{} rows/s on 2 threads**; without `--leg`: {} rows/s; the leg and its boot cost {} (3 runs alternating \
             with the flown ones, medians).\n\
             - The two aim solves of [flight.md](flight.md), to its target ({target}) m: {} ms for the launch \
             (`kick aim --target {target} --spin {},{},{}`), {} ms through the 3D kick \
             (`kick aim --target {target} --from kick --objective max-clearance`) (5 alternating solves each).\n\n\
             ## One off-center kick\n\n\
             Table 1, 5 cm offset, `accurate`, one core, 5 alternating measurements of each form (µs per kick, median and \
             range; right-hand-side evaluations). They run the kick's AVX2 copy where the CPU has AVX2 (the results are \
             the baseline copy's, bit for bit); the row “the same, on the baseline x86-64 copy” runs the baseline copy: {} the AVX2 copy's time.\n\n\
             | kick | µs | range | evaluations |\n| --- | --- | --- | --- |\n{kick_rows}",
            machine.describe(),
            crate::provenance::utc_timestamp(std::time::SystemTime::now()),
            BUILD,
            self.auto.setting,
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
            if o.leg_cost.median <= 2.0 { "met" } else { "not met" },
            o.flight_rows,
            o.flights_1.show(0, ""),
            o.flights_2.show(0, ""),
            o.flight_speed_up.show(2, "x"),
            1e6 / o.flights_1.median,
            met(self.sweeps.flown.median, 10_000.0),
            self.sweeps.flown.show(0, ""),
            self.sweeps.unflown.show(0, ""),
            self.sweeps.cost.show(2, "x"),
            met(self.sweeps.leg.median, 10_000.0),
            self.sweeps.leg.show(0, ""),
            self.sweeps.shell.show(0, ""),
            self.sweeps.leg_cost.show(2, "x"),
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
             and their outcomes are mostly noise in their last digits, which deflate cannot shrink.\n\n\
             | command | s | rows per s | file (MB) |\n| --- | --- | --- | --- |\n{files}",
            crate::h5::Compression::DEFAULT_LEVEL
        )
    }
}

/// Error against cost, log–log, one curve per solver, from the file.
fn draw(path: &std::path::Path, out: &std::path::Path) -> Result<Vec<PathBuf>, PaperError> {
    let data = SweepData::read(path)?;
    let names = data.names.clone().ok_or_else(|| PaperError::missing("work_precision.h5 has no solver names"))?;
    let set = data.set("bench")?;
    let error = set.column("max_error").ok_or_else(|| PaperError::missing("no max_error"))?;
    let seconds = set.column("seconds_per_scenario").ok_or_else(|| PaperError::missing("no seconds_per_scenario"))?;
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
    Ok(save_grid(out, "work_precision", "kick bench", (1, 1), &[panel])?)
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
