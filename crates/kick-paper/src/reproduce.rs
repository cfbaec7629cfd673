//! `kick reproduce`: every experiment, the figures, the cross-model checks and
//! the reproduction report.

use crate::error::PaperError;
use crate::identify::report::{
    LAWS, SYNTHETIC_FIT, SYNTHETIC_LAW_FIT, SYNTHETIC_LAW_SEED, SYNTHETIC_SEED, SYNTHETIC_WRONG_LAW_FIT, TABLE2_FIT,
};
use crate::links::relative;
use crate::printable::Printable;
use crate::report::CheckLine;
use std::io::Write;
use std::path::{Path, PathBuf};

/// Where `kick reproduce` reads and writes.
#[derive(Debug, Clone, PartialEq)]
pub struct ReproduceSettings {
    /// Directory of experiment files (every *.toml directly inside is run; 3D ones in its `3d/`).
    pub experiments: PathBuf,
    /// Directory for the result files; figures go to OUT/figures.
    pub out: PathBuf,
    /// Report to (re)generate; the other pages go beside it.
    pub report: PathBuf,
    /// The benchmark's short variant (`kick bench --quick`), for tests.
    pub quick_bench: bool,
    /// Which steps to run.
    pub steps: Steps,
}

/// The steps of a reproduction to run ([`step_names`]).
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub enum Steps {
    /// Everything: experiments, figures, checks, pages, 3D, leg, laws, fits, bench, the model page.
    #[default]
    All,
    /// These steps only, in the order of [`step_names`] (`kick reproduce --only`).
    Only(Vec<String>),
}

impl Steps {
    /// [`Steps::Only`] these names.
    pub fn only(names: &[&str]) -> Steps {
        Steps::Only(names.iter().map(|n| n.to_string()).collect())
    }
}

/// Subdirectory of the results (and page beside the report) holding the
/// timing-dependent outputs, the only ones a second run may change.
pub const TIMING_DIRECTORY: &str = "timing";
/// The timing page, beside the report.
pub const TIMING_PAGE: &str = "timing.md";

impl Default for ReproduceSettings {
    fn default() -> Self {
        ReproduceSettings {
            experiments: PathBuf::from("experiments"),
            out: PathBuf::from("results"),
            report: PathBuf::from("paper/README.md"),
            quick_bench: false,
            steps: Steps::All,
        }
    }
}

/// The pages written beside the report, with their titles in its list of sections.
pub const SECTIONS: [(&str, &str); 10] = [
    (crate::model::PAGE, "The model: the paper's equations by number, and what kick adds"),
    ("solvers.md", "Solvers of the 1D model: precision, trust regions"),
    (TIMING_PAGE, "Timing of the 1D solvers on the machine that ran the reproduction"),
    ("3d.md", "Off-center 3D kicks: spin, friction, launch direction, the speed–spin trade-off"),
    ("flight.md", "Ball flight: free kicks from the 3D kick, deflection at 25 m"),
    ("ball.md", "The ball alone: restitution, contact time and compression against impact speed and pressure"),
    ("leg.md", "Effective mass of the articulated leg"),
    ("laws.md", "Contact laws compared"),
    ("identification.md", "Parameter identification and identifiability"),
    ("validation.md", "Validation: the model beside published measurements"),
];

/// Before any step: nothing the reproduction writes (the report and the
/// pages beside it, anything in the results folder) is a file it reads
/// (every file below the experiments folder), by `kick_store::output::check_paths`.
pub fn check_paths(args: &ReproduceSettings) -> Result<(), PaperError> {
    let inputs: Vec<PathBuf> = crate::compare::files_below(&args.experiments, &[]).into_iter().map(|f| args.experiments.join(f)).collect();
    let reads: Vec<&Path> = inputs.iter().map(PathBuf::as_path).collect();
    crate::output::check_output(&args.report, "--report", "md", &reads)?;
    let report_dir = args.report.parent().unwrap_or(Path::new(""));
    let pages: Vec<PathBuf> = SECTIONS.iter().map(|(page, _)| report_dir.join(page)).collect();
    let mut writes: Vec<crate::output::Target> = pages.iter().map(|path| crate::output::Target::File { flag: "--report", path }).collect();
    writes.push(crate::output::Target::Folder { flag: "--out", path: &args.out });
    Ok(crate::output::check_paths(&writes, &reads)?)
}

/// What a reproduction did.
#[derive(Debug, Clone, serde::Serialize)]
pub struct Reproduction {
    pub checks: usize,
    pub failed_checks: usize,
    pub report: PathBuf,
}

impl Printable for Reproduction {
    fn text(&self) -> String {
        String::new()
    }
}

/// Write `text` to `log`, for the progress of a long run (a closed log is
/// not an error: the files are what counts).
fn say(log: &mut dyn Write, text: &str) {
    let _ = log.write_all(text.as_bytes());
}

/// One library call of a reproduction, holding the arguments it is made
/// with; [`Call::command`] prints them as the `kick` command line that makes
/// the same files alone, so the line and the call cannot disagree.
#[derive(Debug, Clone)]
pub enum Call {
    /// `paper/model.md`, the model with the paper's equation numbers, from
    /// its parts and the declarations (part of `kick reproduce` only).
    Model,
    /// `kick run FILE --out OUT` for a 1D experiment file.
    Run { file: PathBuf, out: PathBuf },
    /// Figures 1-7 from the 1D result files (part of `kick reproduce` only).
    Figures { out: PathBuf, figures: PathBuf },
    /// `kick check`: the cross-model checks, kept for the report.
    Checks,
    /// `kick run FILE --out OUT` for a 3D experiment file, then its figures.
    Run3d { file: PathBuf, out: PathBuf, figures: PathBuf },
    /// One off-center kick's force history and its figure.
    ForceHistory { out: PathBuf, figures: PathBuf },
    /// The contact patch: spin against offset beside Asai et al. and one
    /// kick's patch over time, their files and figures (part of `kick reproduce` only).
    Patch { out: PathBuf, figures: PathBuf },
    /// `kick leg --knee K --ankle A --sweep-out OUT`.
    Leg(crate::leg::LegRun),
    /// `kick laws`.
    Laws(crate::identify::LawsSettings),
    /// `kick fit profile`.
    Profile(crate::identify::ProfileSettings),
    /// `kick fit synthesize`.
    Synthesize {
        out: PathBuf,
        name: String,
        seed: u64,
        times: usize,
        truth: kick_study::parameters::ScenarioSpec,
        time_offset: f64,
        other_law: Option<kick_study::parameters::LawKind>,
    },
    /// `kick fit data SPEC --out OUT`; a fit that does not converge stops the reproduction.
    FitData { spec: PathBuf, out: PathBuf },
    /// `kick fit table2 --scenarios FILE --out OUT`.
    FitTable2 { scenarios: PathBuf, out: PathBuf },
    /// `kick bench`.
    Bench(crate::bench::BenchSettings),
    /// The ball alone: the figures of the bounce experiments (`experiments/ball/`,
    /// run before it), the synthetic plate tests and their fit, and
    /// `paper/ball.md` (part of `kick reproduce` only).
    Ball,
    /// `paper/leg.md`, `laws.md` and `identification.md` from their result files (part of `kick reproduce` only).
    Pages,
    /// The validation chapter: the model beside published measurements (part of `kick reproduce` only).
    Validation,
    /// Free kicks through the flight, `paper/3d.md` and `paper/flight.md` (part of `kick reproduce` only).
    Pages3d,
    /// The report, `paper/README.md`, written last (part of `kick reproduce` only).
    Report,
}

/// A named step of a reproduction: the calls it makes, in order.
#[derive(Debug, Clone)]
pub struct Step {
    /// What `--only` takes.
    pub name: &'static str,
    pub calls: Vec<Call>,
}

/// The names of the steps, in the order they run: the studies
/// `kick_study::studies` declares as reproduced.
pub fn step_names() -> Vec<&'static str> {
    kick_study::studies::reproduce_steps().map(|s| s.name).collect()
}

/// A number in a command line: the shorter of plain and scientific form,
/// both of which read back to the same `f64`.
fn number(x: f64) -> String {
    let (plain, scientific) = (format!("{x}"), format!("{x:e}"));
    if scientific.len() < plain.len() {
        scientific
    } else {
        plain
    }
}

/// The 1D scenario's flags as `kick fit synthesize` (and `simulate`) take them.
fn scenario_flags(spec: &kick_study::parameters::ScenarioSpec) -> String {
    let mut flags = String::new();
    for p in kick_study::parameters::Parameter::ALL {
        if let Some(x) = spec.get(p) {
            flags.push_str(&format!(" --{} {}", p.name().replace('_', "-"), number(x)));
        }
    }
    if let Some(law) = spec.law {
        flags.push_str(&format!(" --law {}", law.name()));
    }
    if let Some(e) = spec.restitution {
        flags.push_str(&format!(" --restitution {}", number(e)));
    }
    flags
}

impl Call {
    /// The command line that makes the same files alone; for the parts that
    /// only `kick reproduce` makes, `kick reproduce ... --only STEP`.
    pub fn command(&self, args: &ReproduceSettings, step: &str) -> String {
        let d = |p: &Path| p.display().to_string();
        match self {
            Call::Run { file, out } | Call::Run3d { file, out, .. } => format!("kick run {} --out {}", d(file), d(out)),
            Call::Checks => "kick check".into(),
            Call::ForceHistory { out, .. } => crate::force_history::force_history_command(out),
            Call::Leg(leg) => {
                format!(
                    "kick leg --knee {} --ankle {} --sweep-out {}",
                    number(leg.settings.knee),
                    number(leg.settings.ankle),
                    leg.sweep_out.as_deref().map(d).unwrap_or_default()
                )
            }
            Call::Laws(laws) => format!(
                "kick laws --scenarios {} --samples {}{}",
                d(&laws.scenarios),
                laws.samples,
                laws.out.as_deref().map(|o| format!(" --out {}", d(o))).unwrap_or_default()
            ),
            Call::Profile(p) => format!(
                "kick fit profile{} --spread {} --points {} --map-points {} --seed {}",
                p.out.as_deref().map(|o| format!(" --out {}", d(o))).unwrap_or_default(),
                number(p.spread),
                p.points,
                p.map_points,
                p.seed
            ),
            Call::Synthesize { out, name, seed, times, truth, time_offset, other_law } => format!(
                "kick fit synthesize --out {} --name {name} --seed {seed} --times {times}{}{}{}",
                d(out),
                scenario_flags(truth),
                if *time_offset != 0.0 { format!(" --time-offset {}", number(*time_offset)) } else { String::new() },
                other_law.map(|law| format!(" --also-fit-law {}", law.name())).unwrap_or_default()
            ),
            Call::FitData { spec, out } => format!("kick fit data {} --out {}", d(spec), d(out)),
            Call::FitTable2 { scenarios, out } => format!("kick fit table2 --scenarios {} --out {}", d(scenarios), d(out)),
            Call::Bench(b) => format!(
                "kick bench{} --out {} --min-time {} --sweep-samples {}{}{}",
                if b.quick { " --quick" } else { "" },
                d(&b.out),
                number(b.min_time),
                b.sweep_samples,
                b.report.as_deref().map(|r| format!(" --report {}", d(r))).unwrap_or_default(),
                b.solvers_report.as_deref().map(|r| format!(" --solvers-report {}", d(r))).unwrap_or_default()
            ),
            Call::Model
            | Call::Figures { .. }
            | Call::Patch { .. }
            | Call::Ball
            | Call::Pages
            | Call::Validation
            | Call::Pages3d
            | Call::Report => {
                format!(
                    "kick reproduce --experiments {} --out {} --report {}{} --only {step}",
                    d(&args.experiments),
                    d(&args.out),
                    d(&args.report),
                    if args.quick_bench { " --quick-bench" } else { "" }
                )
            }
        }
    }
}

/// The leg's call: the default pose, its figure data into OUT.
fn leg_call(args: &ReproduceSettings) -> Call {
    Call::Leg(crate::leg::LegRun { sweep_out: Some(args.out.clone()), ..Default::default() })
}

/// The steps of a reproduction with `args`, every call's arguments filled
/// in: what `kick reproduce --list` prints and [`reproduce`] runs.
pub fn steps(args: &ReproduceSettings) -> Result<Vec<Step>, PaperError> {
    let toml_files = |dir: &Path| -> Result<Vec<PathBuf>, std::io::Error> {
        let mut files: Vec<PathBuf> = std::fs::read_dir(dir)?
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| p.is_file() && p.extension().is_some_and(|x| x == "toml"))
            .collect();
        files.sort();
        Ok(files)
    };
    let files = toml_files(&args.experiments).map_err(|source| PaperError::Flag {
        flag: "--experiments",
        message: format!("--experiments {}: cannot read the folder: {source}", args.experiments.display()),
    })?;
    if files.is_empty() {
        return Err(PaperError::NoExperiments(args.experiments.clone()));
    }
    let out = args.out.clone();
    let figures = args.out.join("figures");
    let fits = args.out.join("identification");
    let report_dir = args.report.parent().unwrap_or(Path::new("")).to_path_buf();
    let three_d = toml_files(&args.experiments.join("3d")).unwrap_or_default();
    let ball = toml_files(&args.experiments.join("ball")).unwrap_or_default();
    let law_name = "synthetic_hunt_crossley";
    let hunt_crossley = kick_study::parameters::ScenarioSpec {
        law: Some(kick_study::parameters::LawKind::HuntCrossleyExact),
        restitution: Some(0.66),
        ..kick_study::parameters::ScenarioSpec::default()
    };
    let synthesize = |name: &str, seed, truth, time_offset, other_law| Call::Synthesize {
        out: fits.clone(),
        name: name.into(),
        seed,
        times: 80,
        truth,
        time_offset,
        other_law,
    };
    // Each step's calls, by the name the study registry gives it.
    let mut calls: Vec<(&str, Vec<Call>)> = vec![
        ("experiments", files.into_iter().map(|file| Call::Run { file, out: out.clone() }).collect()),
        ("figures", vec![Call::Figures { out: out.clone(), figures: figures.clone() }]),
        ("checks", vec![Call::Checks]),
        ("3d", three_d.into_iter().map(|file| Call::Run3d { file, out: out.clone(), figures: figures.clone() }).collect()),
        ("force-history", vec![Call::ForceHistory { out: out.clone(), figures: figures.clone() }]),
        ("patch", vec![Call::Patch { out: out.clone(), figures: figures.clone() }]),
        ("leg", vec![leg_call(args)]),
        ("ball", ball.into_iter().map(|file| Call::Run { file, out: out.clone() }).chain([Call::Ball]).collect()),
        (
            "laws",
            vec![Call::Laws(crate::identify::LawsSettings {
                scenarios: args.experiments.join("table2.toml"),
                out: Some(fits.clone()),
                samples: 200,
            })],
        ),
        (
            "profile",
            vec![Call::Profile(crate::identify::ProfileSettings {
                out: Some(fits.clone()),
                spread: 1.5,
                points: 9,
                map_points: 21,
                seed: 5,
            })],
        ),
        // Synthetic data (the paper's law; Hunt-Crossley with a late first touch), fitted back;
        // the Hunt-Crossley data fitted with the paper's law too (a wrong law: model error).
        (
            "synthesize",
            vec![
                synthesize("synthetic", SYNTHETIC_SEED, kick_study::parameters::ScenarioSpec::default(), 0.0, None),
                synthesize(law_name, SYNTHETIC_LAW_SEED, hunt_crossley, 2.5e-4, Some(kick_study::parameters::LawKind::PowerLaw)),
            ],
        ),
        (
            "fit",
            [
                ("synthetic".to_string(), SYNTHETIC_FIT),
                (law_name.to_string(), SYNTHETIC_LAW_FIT),
                (crate::identify::other_law_name(law_name, kick_study::parameters::LawKind::PowerLaw), SYNTHETIC_WRONG_LAW_FIT),
            ]
            .into_iter()
            .map(|(spec, fit)| Call::FitData { spec: fits.join(format!("{spec}.toml")), out: fits.join(fit) })
            .collect(),
        ),
        ("table2-fit", vec![Call::FitTable2 { scenarios: args.experiments.join("table2.toml"), out: fits.join(TABLE2_FIT) }]),
        (
            "bench",
            vec![Call::Bench(crate::bench::BenchSettings {
                out: args.out.join(TIMING_DIRECTORY),
                report: Some(report_dir.join(TIMING_PAGE)),
                solvers_report: Some(report_dir.join("solvers.md")),
                quick: args.quick_bench,
                ..Default::default()
            })],
        ),
        ("pages", vec![Call::Pages]),
        ("validation", vec![Call::Validation]),
        ("3d-pages", vec![Call::Pages3d]),
        ("model", vec![Call::Model]),
        ("report", vec![Call::Report]),
    ];
    // In the registry's order; a step the registry names without calls here (or the reverse) is a bug.
    let mut steps = Vec::with_capacity(calls.len());
    for study in kick_study::studies::reproduce_steps() {
        let at = calls.iter().position(|(name, _)| *name == study.name);
        let at = at.ok_or_else(|| {
            PaperError::Registry(format!("kick_study::studies names the step `{}`, which kick-paper cannot run", study.name))
        })?;
        steps.push(Step { name: study.name, calls: calls.swap_remove(at).1 });
    }
    if let Some((name, _)) = calls.first() {
        return Err(PaperError::Registry(format!("kick-paper runs a step `{name}` that kick_study::studies does not declare")));
    }
    Ok(steps)
}

/// The steps `args.steps` selects, in the order they run; an unknown name
/// is an error naming `--only` and listing the steps.
pub fn selected(args: &ReproduceSettings) -> Result<Vec<Step>, PaperError> {
    let all = steps(args)?;
    let Steps::Only(names) = &args.steps else { return Ok(all) };
    for name in names {
        kick_study::studies::reproduce_step(name, "--only")?;
    }
    Ok(all.into_iter().filter(|s| names.iter().any(|n| n == s.name)).collect())
}

/// `kick reproduce --list`: each selected step's name and command lines.
#[derive(Debug, Clone, serde::Serialize)]
pub struct StepList {
    pub steps: Vec<(String, Vec<String>)>,
}

impl Printable for StepList {
    fn text(&self) -> String {
        let mut text = String::new();
        for (name, commands) in &self.steps {
            text.push_str(name);
            text.push('\n');
            for command in commands {
                text.push_str(&format!("    {command}\n"));
            }
        }
        text
    }
}

/// The steps [`reproduce`] would run with `args`, with their command lines.
pub fn list(args: &ReproduceSettings) -> Result<StepList, PaperError> {
    let steps = selected(args)?;
    Ok(StepList { steps: steps.iter().map(|s| (s.name.to_string(), s.calls.iter().map(|c| c.command(args, s.name)).collect())).collect() })
}

/// What the steps leave for the later ones.
#[derive(Default)]
struct State {
    /// Result files of the 1D experiments and the file that wrote each.
    written: Vec<(PathBuf, PathBuf)>,
    checks: Option<Vec<CheckLine>>,
}

impl Call {
    fn run(&self, args: &ReproduceSettings, state: &mut State, log: &mut dyn Write) -> Result<(), PaperError> {
        let report_dir = args.report.parent().unwrap_or(Path::new("")).to_path_buf();
        let fits = args.out.join("identification");
        match self {
            Call::Model => {
                let written = crate::model::write(&report_dir.join(crate::model::PAGE))?;
                say(log, &format!("the model: {}\n", written.display()));
            }
            Call::Run { file, out } => {
                let run = crate::shard::run_file(file, out, None)?;
                say(log, &run.text());
                let path = run.summary.path;
                // Two files naming the same experiment would overwrite each other.
                if let Some((_, first)) = state.written.iter().find(|(p, _)| *p == path) {
                    return Err(PaperError::SameFile { first: first.to_path_buf(), second: file.to_path_buf(), file: path.to_path_buf() });
                }
                state.written.push((path, file.clone()));
            }
            Call::Figures { out, figures } => {
                let drawn = crate::figures::draw_all(out, figures)?;
                say(log, &format!("figures: {} files in {}\n", drawn.len(), figures.display()));
            }
            Call::Checks => {
                let checks: Vec<CheckLine> = crate::checks::run_all().rows;
                let failed = checks.iter().filter(|c| !c.passed).count();
                say(log, &format!("checks: {} of {} pass\n", checks.len() - failed, checks.len()));
                state.checks = Some(checks);
            }
            Call::Run3d { file, out, figures } => {
                let run = crate::shard::run_file(file, out, None)?;
                say(log, &run.text());
                let drawn = crate::three_d::figures(&run.summary.path, figures)?;
                say(log, &format!("figures: {} files in {}\n", drawn.len(), figures.display()));
            }
            Call::ForceHistory { out, figures } => {
                // One off-center kick's force history, grip and slip shaded (from its HDF5 history).
                let (_, summary, drawn) = crate::force_history::reproduce_force_history(out, figures)?;
                say(log, &summary);
                say(log, &format!("figures: {} files in {}\n", drawn.len() - 1, figures.display()));
            }
            Call::Patch { out, figures } => {
                let measurements = args.experiments.join("validation/measurements.toml");
                let written = crate::patch::write(out, figures, &measurements, &self.command(args, "patch"))?;
                say(log, &format!("the contact patch: {} files\n", written.len()));
            }
            Call::Leg(settings) => {
                // The command goes into the files' provenance.
                let run = crate::leg::LegRun { command: self.command(args, "leg"), ..settings.clone() };
                say(log, &crate::leg::leg(&run)?.text());
            }
            Call::Laws(settings) => say(log, &crate::identify::laws(settings)?.text()),
            Call::Profile(settings) => say(log, &crate::identify::profile(settings)?.text()),
            Call::Synthesize { out, name, seed, times, truth, time_offset, other_law } => {
                say(log, &crate::identify::synthesize(out, name, *seed, *times, truth, *time_offset, *other_law)?.text())
            }
            Call::FitData { spec, out } => {
                let fitted = crate::identify::data(spec, Some(out))?;
                say(log, &fitted.text());
                fitted.converged()?;
            }
            Call::FitTable2 { scenarios, out } => say(log, &crate::identify::table2(None, Some(out), scenarios)?.text()),
            Call::Bench(settings) => {
                let bench = crate::bench::bench(settings, log)?;
                say(log, &bench.text());
            }
            Call::Ball => {
                let written =
                    crate::ball::write(&args.out, &args.out.join("figures"), &report_dir.join("ball.md"), &self.command(args, "ball"))?;
                say(log, &format!("the ball alone: {} files\n", written.len()));
            }
            Call::Pages => {
                let out = args.out.display().to_string();
                // The leg's section: its figures, drawn from results/leg_*.h5.
                let figures_from_report = relative(&report_dir, &args.out.join("figures"));
                let leg = leg_call(args).command(args, "leg");
                let leg_page = crate::leg::page(&args.out, &out, &figures_from_report, &leg)?;
                crate::output::write(report_dir.join("leg.md"), leg_page)?;
                // Contact laws and identification: from results/identification/*.h5.
                let identification_from_report = relative(&report_dir, &fits);
                let laws_page = crate::identify::report::laws(&fits.join(LAWS), &identification_from_report)?;
                crate::output::write(report_dir.join("laws.md"), laws_page)?;
                let identification_page = crate::identify::report::identification(&fits, &identification_from_report)?;
                crate::output::write(report_dir.join("identification.md"), identification_page)?;
            }
            Call::Validation => {
                // The validation chapter: the model beside published measurements.
                let validation = crate::validation::write(
                    &args.experiments.join("validation/measurements.toml"),
                    &args.out.join("validation"),
                    &report_dir.join("validation.md"),
                    &args.experiments.join("validation/NOTES.md"),
                )?;
                say(log, &validation.text());
            }
            // Free kicks through the flight, and the generated 3D and flight pages
            // (after every figure they link is drawn).
            Call::Pages3d => {
                crate::pages_3d::write_all(&args.out, &report_dir, log)?;
            }
            Call::Report => {
                // Written last, so that its list of result files is the same on every run
                // (not whatever an earlier run left when this step came).
                if state.checks.is_none() {
                    state.checks = Some(crate::checks::run_all().rows);
                }
                let checks = state.checks.as_deref();
                let mut text = crate::report::render(&args.out, &relative(&report_dir, &args.out.join("figures")), checks)?;
                // Point the report at the sections written beside it.
                let present: Vec<String> = SECTIONS
                    .iter()
                    .filter(|(file, _)| report_dir.join(file).exists())
                    .map(|(file, title)| format!("- [{title}]({file})"))
                    .collect();
                if !present.is_empty() {
                    text.push_str("\n## Further sections\n\n");
                    text.push_str(&present.join("\n"));
                    text.push('\n');
                }
                crate::output::write(&args.report, text)?;
                say(log, &format!("report: {}\n", args.report.display()));
            }
        }
        Ok(())
    }
}

/// Every experiment into result files, the figures, the cross-model checks
/// and the report pages: the 1D experiments and Figures 1-7, `paper/README.md`,
/// the 3D sweeps, the leg, the contact laws, the identification files and the
/// solver benchmark with their pages; the [`steps`] `args.steps` selects.
/// `log` gets what each call reports, under the command line that makes
/// the same files alone ([`Call::command`]).
pub fn reproduce(args: &ReproduceSettings, log: &mut dyn Write) -> Result<Reproduction, PaperError> {
    check_paths(args)?;
    let mut state = State::default();
    for step in selected(args)? {
        for call in &step.calls {
            say(log, &format!("\n# {}\n", call.command(args, step.name)));
            call.run(args, &mut state, log)?;
        }
    }
    let checks = state.checks.unwrap_or_default();
    let failed = checks.iter().filter(|c| !c.passed).count();
    Ok(Reproduction { checks: checks.len(), failed_checks: failed, report: args.report.clone() })
}

/// What `kick reproduce --check` found.
#[derive(Debug, Clone, serde::Serialize)]
pub struct CheckReport {
    /// Files compared.
    pub compared: usize,
    pub differences: Vec<crate::compare::Difference>,
}

impl Printable for CheckReport {
    fn text(&self) -> String {
        let mut text = String::new();
        for d in &self.differences {
            text.push_str(&format!("{}: {}\n", d.file.display(), d.what));
        }
        let files = {
            let mut files: Vec<&PathBuf> = self.differences.iter().map(|d| &d.file).collect();
            files.dedup();
            files.len()
        };
        text.push_str(&format!("{} files compared (timing outputs left out), {files} differ\n", self.compared));
        text
    }
}

/// Removes a folder when dropped.
struct Scratch(PathBuf);

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// `kick reproduce --check`: regenerate into a temporary folder and compare
/// with the files at `args.out` and beside `args.report`, by value for HDF5
/// (every dataset and attribute but `git_commit`/`git_dirty`), by bytes
/// otherwise. Left out: the timing outputs (`OUT/timing/`, `timing.md`).
/// Every regenerated file is compared; a committed file under OUT that is
/// no longer generated is a difference too. The report's folder may hold
/// hand-written pages: they are copied into the temporary
/// folder first, so the report links them as in the checkout.
pub fn check(args: &ReproduceSettings, log: &mut dyn Write) -> Result<CheckReport, PaperError> {
    static SEQUENCE: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(0);
    let n = SEQUENCE.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let scratch = Scratch(std::env::temp_dir().join(format!("kick-check-{}-{n}", std::process::id())));
    let _ = std::fs::remove_dir_all(&scratch.0);
    let name = |p: &Path, fallback: &str| p.file_name().map(PathBuf::from).unwrap_or_else(|| PathBuf::from(fallback));
    let report_dir = args.report.parent().unwrap_or(Path::new("")).to_path_buf();
    let out = scratch.0.join(name(&args.out, "results"));
    let pages = scratch.0.join(name(&report_dir, "paper"));
    if out == pages {
        return Err(PaperError::SameFolder { out: args.out.clone(), report: report_dir.to_path_buf() });
    }
    // Hand-written pages beside the report (linked from it when present) as committed.
    for file in crate::compare::files_below(&report_dir, &[]) {
        let target = pages.join(&file);
        std::fs::create_dir_all(target.parent().unwrap_or(&pages)).map_err(|source| PaperError::Io {
            what: "create",
            path: pages.clone(),
            source,
        })?;
        std::fs::copy(report_dir.join(&file), &target).map_err(|source| PaperError::Io { what: "copy", path: file.clone(), source })?;
    }
    let regenerated = ReproduceSettings { out: out.clone(), report: pages.join(name(&args.report, "README.md")), ..args.clone() };
    reproduce(&regenerated, log)?;
    // Paths of the temporary folders, as written into the files, back to the committed ones.
    let (out_text, pages_text) = (out.display().to_string(), pages.display().to_string());
    let (committed_out, committed_pages) = (args.out.display().to_string(), report_dir.display().to_string());
    let rename = move |s: &str| s.replace(&out_text, &committed_out).replace(&pages_text, &committed_pages);
    let timing = Path::new(TIMING_DIRECTORY);
    let mut compared = 0;
    let mut differences = Vec::new();
    let regenerated_out = crate::compare::files_below(&out, &[timing]);
    for file in &regenerated_out {
        compared += 1;
        differences.extend(crate::compare::compare_file(&args.out.join(file), &out.join(file), &rename));
    }
    for file in crate::compare::files_below(&args.out, &[timing]) {
        if !regenerated_out.contains(&file) {
            differences.push(crate::compare::Difference {
                file: args.out.join(file),
                what: "committed but no longer written by kick reproduce".into(),
            });
        }
    }
    for file in crate::compare::files_below(&pages, &[Path::new(TIMING_PAGE)]) {
        compared += 1;
        differences.extend(crate::compare::compare_file(&report_dir.join(&file), &pages.join(&file), &rename));
    }
    Ok(CheckReport { compared, differences })
}
