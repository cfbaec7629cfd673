//! `kick reproduce`: every experiment, the figures, the cross-model checks and
//! the reproduction report.

use crate::identify::report::{LAWS, SYNTHETIC_FIT, SYNTHETIC_LAW_FIT, TABLE2_FIT};
use crate::printable::Printable;
use crate::report::CheckLine;
use std::io::Write;
use std::path::{Component, Path, PathBuf};

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
}

impl Default for ReproduceSettings {
    fn default() -> Self {
        ReproduceSettings {
            experiments: PathBuf::from("experiments"),
            out: PathBuf::from("results"),
            report: PathBuf::from("paper/README.md"),
            quick_bench: false,
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

/// `to` relative to the directory `from` (both relative to the working
/// directory), e.g. paper → results/figures gives ../results/figures.
fn relative(from: &Path, to: &Path) -> String {
    if from.is_absolute() || to.is_absolute() {
        return to.display().to_string();
    }
    let depth = from.components().filter(|c| matches!(c, Component::Normal(_))).count();
    let mut path = String::new();
    for _ in 0..depth {
        path.push_str("../");
    }
    path.push_str(&to.display().to_string().replace('\\', "/"));
    path
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
        let run = crate::run::run_file(file, &args.out)?;
        say(log, &run.text());
        let path = run.summary.path;
        // Two files naming the same experiment would overwrite each other.
        if let Some((_, first)) = written.iter().find(|(p, _)| *p == path) {
            return Err(format!("{} and {} both write {}", first.display(), file.display(), path.display()));
        }
        written.push((path, file));
    }

    let figures = args.out.join("figures");
    let drawn = crate::figures::draw_all(&args.out, &figures).map_err(|e| e.to_string())?;
    say(log, &format!("figures: {} files in {}\n", drawn.len(), figures.display()));

    let checks: Vec<CheckLine> = crate::checks::run_all().rows;
    let failed = checks.iter().filter(|c| !c.passed).count();
    say(log, &format!("checks: {} of {} pass\n", checks.len() - failed, checks.len()));

    let report_dir = args.report.parent().unwrap_or(Path::new("")).to_path_buf();
    crate::report::write(&args.out, &relative(&report_dir, &figures), Some(&checks), &args.report).map_err(|e| e.to_string())?;
    say(log, &format!("report: {}\n", args.report.display()));

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
        let run = crate::run::run_file(file, &args.out)?;
        say(log, &run.text());
        let drawn = crate::three_d::figures(&run.summary.path, &figures).map_err(|e| e.to_string())?;
        say(log, &format!("figures: {} files in {}\n", drawn.len(), figures.display()));
    }
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
    let quick = if args.quick_bench { " --quick" } else { "" };
    say(log, &format!("\n# kick bench{quick} --out {out} --report {}\n", solvers_report.display()));
    let bench = crate::bench::BenchSettings {
        out: args.out.clone(),
        report: Some(solvers_report),
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
    // Point the report at the sections written beside it.
    let mut text = std::fs::read_to_string(&args.report).map_err(|e| format!("cannot read {}: {e}", args.report.display()))?;
    let sections = [
        ("solvers.md", "Solvers of the 1D model: work–precision, cost, trust regions"),
        ("3d.md", "Off-center 3D kicks: spin and friction"),
        ("leg.md", "Effective mass of the articulated leg"),
        ("laws.md", "Contact laws compared"),
        ("identification.md", "Parameter identification and identifiability"),
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
        crate::output::write(&args.report, text).map_err(|e| e.to_string())?;
    }
    Ok(Reproduction { checks: checks.len(), failed_checks: failed, report: args.report.clone() })
}

#[cfg(test)]
mod tests {
    use super::relative;
    use std::path::Path;

    #[test]
    fn figures_relative_to_the_report() {
        assert_eq!(relative(Path::new("paper"), Path::new("results/figures")), "../results/figures");
        assert_eq!(relative(Path::new(""), Path::new("results/figures")), "results/figures");
        assert_eq!(relative(Path::new("a/b"), Path::new("r/f")), "../../r/f");
    }
}
