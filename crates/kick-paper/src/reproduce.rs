//! `kick reproduce`: every experiment, the figures, the cross-model checks and
//! the reproduction report.

use crate::identify::report::{LAWS, SYNTHETIC_FIT, SYNTHETIC_LAW_FIT, TABLE2_FIT};
use crate::printable::Printable;
use crate::report::CheckLine;
use std::io::Write;
use crate::links::relative;
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

/// The steps of a reproduction.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Steps {
    /// Everything: experiments, figures, checks, pages, 3D, leg, laws, fits, bench.
    #[default]
    All,
    /// The 1D experiment files only (for a quick check of a few files).
    Experiments,
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

/// Every experiment into result files, the figures, the cross-model checks
/// and the report pages: the 1D experiments and Figures 1-7, `paper/README.md`,
/// the 3D sweeps, the leg, the contact laws, the identification files and the
/// solver benchmark with their pages. Each step is a library call; `log`
/// gets what each step reports, under the command that does the same step alone.
pub fn reproduce(args: &ReproduceSettings, log: &mut dyn Write) -> Result<Reproduction, String> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(&args.experiments)
        .map_err(|e| format!("cannot read {}: {e}", args.experiments.display()))?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.is_file() && p.extension().is_some_and(|x| x == "toml"))
        .collect();
    files.sort();
    if files.is_empty() {
        return Err(format!("no experiment files in {}", args.experiments.display()));
    }
    let mut written: Vec<(PathBuf, &PathBuf)> = Vec::new();
    for file in &files {
        let run = crate::shard::run_file(file, &args.out, None)?;
        say(log, &run.text());
        let path = run.summary.path;
        // Two files naming the same experiment would overwrite each other.
        if let Some((_, first)) = written.iter().find(|(p, _)| *p == path) {
            return Err(format!("{} and {} both write {}", first.display(), file.display(), path.display()));
        }
        written.push((path, file));
    }
    if args.steps == Steps::Experiments {
        return Ok(Reproduction { checks: 0, failed_checks: 0, report: args.report.clone() });
    }

    let figures = args.out.join("figures");
    let drawn = crate::figures::draw_all(&args.out, &figures).map_err(|e| e.to_string())?;
    say(log, &format!("figures: {} files in {}\n", drawn.len(), figures.display()));

    let checks: Vec<CheckLine> = crate::checks::run_all().rows;
    let failed = checks.iter().filter(|c| !c.passed).count();
    say(log, &format!("checks: {} of {} pass\n", checks.len() - failed, checks.len()));

    let report_dir = args.report.parent().unwrap_or(Path::new("")).to_path_buf();

    // The rest of the workspace's results: 3D sweeps, the leg, contact laws,
    // identifiability, and the solvers' work-precision; each under the
    // command that makes the same files alone.
    let out = args.out.display().to_string();
    let mut three_d: Vec<PathBuf> = std::fs::read_dir(args.experiments.join("3d"))
        .map(|entries| {
            entries.filter_map(|e| e.ok().map(|e| e.path())).filter(|p| p.extension().is_some_and(|x| x == "toml")).collect()
        })
        .unwrap_or_default();
    three_d.sort();
    for file in &three_d {
        say(log, &format!("\n# kick run {} --out {out}\n", file.display()));
        let run = crate::shard::run_file(file, &args.out, None)?;
        say(log, &run.text());
        let drawn = crate::three_d::figures(&run.summary.path, &figures).map_err(|e| e.to_string())?;
        say(log, &format!("figures: {} files in {}\n", drawn.len(), figures.display()));
    }
    // One off-center kick's force history, grip and slip shaded (from its HDF5 history).
    let (command, summary, drawn) = crate::force_history::reproduce_force_history(&args.out, &figures)?;
    say(log, &format!("\n# {command}\n{summary}"));
    say(log, &format!("figures: {} files in {}\n", drawn.len() - 1, figures.display()));
    let leg_command = format!("kick leg --knee 30 --ankle 60 --sweep-out {out}");
    say(log, &format!("\n# {leg_command}\n"));
    let leg = crate::leg::leg(&crate::leg::LegSettings {
        sweep_out: Some(args.out.clone()),
        command: leg_command,
        ..crate::leg::LegSettings::default()
    })?;
    say(log, &leg.text());

    let fits = args.out.join("identification");
    let identification = fits.display().to_string();
    say(log, &format!("\n# kick laws --out {identification}\n"));
    let laws = crate::identify::LawsSettings { scenarios: args.experiments.join("table2.toml"), out: Some(fits.clone()), samples: 200 };
    say(log, &crate::identify::laws(&laws)?.text());
    say(log, &format!("\n# kick fit profile --out {identification}\n"));
    let profile = crate::identify::ProfileSettings { out: Some(fits.clone()), spread: 1.5, points: 9, map_points: 21, seed: 5 };
    say(log, &crate::identify::profile(&profile)?.text());
    // Synthetic data (the paper's law; Hunt-Crossley with a late first touch), fitted back.
    say(log, &format!("\n# kick fit synthesize --out {identification} --seed 1\n"));
    say(log, &crate::identify::synthesize(&fits, "synthetic", 1, 80, &kick_core::ScenarioSpec::default(), 0.0)?.text());
    let law_name = "synthetic_hunt_crossley";
    say(
        log,
        &format!(
            "\n# kick fit synthesize --out {identification} --name {law_name} --seed 2 --law hunt-crossley-exact \
             --restitution 0.66 --time-offset 2.5e-4\n"
        ),
    );
    let hunt_crossley = kick_core::ScenarioSpec {
        law: Some(kick_core::LawKind::HuntCrossleyExact),
        restitution: Some(0.66),
        ..kick_core::ScenarioSpec::default()
    };
    say(log, &crate::identify::synthesize(&fits, law_name, 2, 80, &hunt_crossley, 2.5e-4)?.text());
    for (spec, fit) in [("synthetic", SYNTHETIC_FIT), (law_name, SYNTHETIC_LAW_FIT)] {
        let spec = fits.join(format!("{spec}.toml"));
        say(log, &format!("\n# kick fit data {} --out {}\n", spec.display(), fits.join(fit).display()));
        let fitted = crate::identify::data(&spec, Some(&fits.join(fit)))?;
        say(log, &fitted.text());
        fitted.converged()?;
    }
    say(log, &format!("\n# kick fit table2 --out {}\n", fits.join(TABLE2_FIT).display()));
    say(log, &crate::identify::table2(None, Some(&fits.join(TABLE2_FIT)), &laws.scenarios)?.text());
    let solvers_report = report_dir.join("solvers.md");
    let timing_report = report_dir.join(TIMING_PAGE);
    let timing = args.out.join(TIMING_DIRECTORY);
    let quick = if args.quick_bench { " --quick" } else { "" };
    say(
        log,
        &format!(
            "\n# kick bench{quick} --out {} --report {} --solvers-report {}\n",
            timing.display(),
            timing_report.display(),
            solvers_report.display()
        ),
    );
    let bench = crate::bench::BenchSettings {
        out: timing,
        report: Some(timing_report),
        solvers_report: Some(solvers_report),
        quick: args.quick_bench,
        ..Default::default()
    };
    let bench = crate::bench::bench(&bench, log)?;
    say(log, &bench.text());

    // The leg's section: its figures, drawn from results/leg_*.h5.
    let figures_from_report = relative(&report_dir, &args.out.join("figures"));
    let leg_page = format!(
        "# Effective mass of the articulated leg (Eq. 11)\n\n\
         Generated by `kick reproduce` (`kick leg --knee 30 --ankle 60 --sweep-out {out}`). A three-segment leg \
         (thigh, shank, foot; de Leva 1996 segment parameters for a 73 kg, 1.741 m male), pinned at the hip, \
         struck at the instep along the foot's line of motion: m_eff = (nᵀ J M⁻¹ Jᵀ n)⁻¹ (Eq. 11) with the ankle \
         locked or free. Data: `{out}/leg_effective_mass.h5`, `{out}/leg_exit_speed.h5`; see the README section \
         \"Articulated leg\" for the model choices and the tests.\n\n\
         ![effective mass]({figures_from_report}/leg_effective_mass.png)\n\n\
         The exit speed that follows through the 1D model (baseline contact, `accurate`), with the perfectly \
         elastic bound of Eq. 38: gains flatten once m_f is several ball masses (Section 14.1).\n\n\
         ![exit speed]({figures_from_report}/leg_exit_speed.png)\n"
    );
    crate::output::write(report_dir.join("leg.md"), leg_page).map_err(|e| e.to_string())?;
    // Contact laws and identification: from results/identification/*.h5.
    let identification_from_report = relative(&report_dir, &fits);
    let laws_page = crate::identify::report::laws(&fits.join(LAWS), &identification_from_report)?;
    crate::output::write(report_dir.join("laws.md"), laws_page).map_err(|e| e.to_string())?;
    let identification_page = crate::identify::report::identification(&fits, &identification_from_report)?;
    crate::output::write(report_dir.join("identification.md"), identification_page).map_err(|e| e.to_string())?;
    // The validation chapter: the model beside published measurements.
    let validation_dir = args.out.join("validation");
    say(log, &format!("\n# validation -> {}, {}\n", validation_dir.display(), report_dir.join("validation.md").display()));
    let validation = crate::validation::write(
        &args.experiments.join("validation/measurements.toml"),
        &validation_dir,
        &report_dir.join("validation.md"),
        &args.experiments.join("validation/NOTES.md"),
    )?;
    say(log, &validation.text());
    // Free kicks through the flight, and the generated 3D and flight pages
    // (after every figure they link is drawn).
    say(log, &format!("\n# 3D and flight pages -> {}, {}\n", report_dir.join("3d.md").display(), report_dir.join("flight.md").display()));
    crate::pages_3d::write_all(&args.out, &report_dir, log)?;
    // Point the report at the sections written beside it.
    // Written last, so that its list of result files is the same on every run
    // (not whatever an earlier run left when this step came).
    let mut text = crate::report::render(&args.out, &relative(&report_dir, &figures), Some(&checks)).map_err(|e| e.to_string())?;
    let sections = [
        ("solvers.md", "Solvers of the 1D model: precision, trust regions"),
        (TIMING_PAGE, "Timing of the 1D solvers on the machine that ran the reproduction"),
        ("3d.md", "Off-center 3D kicks: spin, friction, launch direction, the speed–spin trade-off"),
        ("flight.md", "Ball flight: free kicks from the 3D kick, deflection at 25 m"),
        ("leg.md", "Effective mass of the articulated leg"),
        ("laws.md", "Contact laws compared"),
        ("identification.md", "Parameter identification and identifiability"),
        ("validation.md", "Validation: the model beside published measurements"),
    ];
    let present: Vec<String> = sections
        .iter()
        .filter(|(file, _)| report_dir.join(file).exists())
        .map(|(file, title)| format!("- [{title}]({file})"))
        .collect();
    if !present.is_empty() {
        text.push_str("\n## Further sections\n\n");
        text.push_str(&present.join("\n"));
        text.push('\n');
    }
    crate::output::write(&args.report, text).map_err(|e| e.to_string())?;
    say(log, &format!("report: {}\n", args.report.display()));
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
        text.push_str(&format!(
            "{} files compared (timing outputs left out), {files} differ\n",
            self.compared
        ));
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
pub fn check(args: &ReproduceSettings, log: &mut dyn Write) -> Result<CheckReport, String> {
    static SEQUENCE: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(0);
    let n = SEQUENCE.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let scratch = Scratch(std::env::temp_dir().join(format!("kick-check-{}-{n}", std::process::id())));
    let _ = std::fs::remove_dir_all(&scratch.0);
    let name = |p: &Path, fallback: &str| p.file_name().map(PathBuf::from).unwrap_or_else(|| PathBuf::from(fallback));
    let report_dir = args.report.parent().unwrap_or(Path::new("")).to_path_buf();
    let out = scratch.0.join(name(&args.out, "results"));
    let pages = scratch.0.join(name(&report_dir, "paper"));
    if out == pages {
        return Err(format!("{} and {} must be different folders", args.out.display(), report_dir.display()));
    }
    // Hand-written pages beside the report (linked from it when present) as committed.
    for file in crate::compare::files_below(&report_dir, &[]) {
        let target = pages.join(&file);
        std::fs::create_dir_all(target.parent().unwrap_or(&pages)).map_err(|e| format!("cannot create {}: {e}", pages.display()))?;
        std::fs::copy(report_dir.join(&file), &target).map_err(|e| format!("cannot copy {}: {e}", file.display()))?;
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
