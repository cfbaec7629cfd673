//! `kick reproduce`: every experiment, the figures, the cross-model checks and
//! the reproduction report.

use crate::identify_report::{LAWS, SYNTHETIC_FIT, SYNTHETIC_LAW_FIT, TABLE2_FIT};
use crate::output::CliResult;
use kick_runner::report::CheckLine;
use std::path::{Component, Path, PathBuf};

#[derive(clap::Args, Debug)]
pub struct Args {
    /// Directory of experiment files (every *.toml directly inside is run)
    #[arg(long, default_value = "experiments")]
    experiments: PathBuf,
    /// Directory for the result files; figures go to OUT/figures
    #[arg(long, default_value = "results")]
    out: PathBuf,
    /// Report to (re)generate
    #[arg(long, default_value = "paper/README.md")]
    report: PathBuf,
    /// Worker threads (default: one per core)
    #[arg(long)]
    threads: Option<usize>,
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

pub fn run(args: Args) -> CliResult {
    crate::run::set_threads(args.threads)?;
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
        let path = crate::run::run_file(file, &args.out)?;
        // Two files naming the same experiment would overwrite each other.
        if let Some((_, first)) = written.iter().find(|(p, _)| *p == path) {
            return Err(format!("{} and {} both write {}", first.display(), file.display(), path.display()));
        }
        written.push((path, file));
    }

    let figures = args.out.join("figures");
    let written = kick_runner::figures::draw_all(&args.out, &figures).map_err(|e| e.to_string())?;
    println!("figures: {} files in {}", written.len(), figures.display());

    let checks: Vec<CheckLine> = crate::check::rows();
    let failed = checks.iter().filter(|c| !c.passed).count();
    println!("checks: {} of {} pass", checks.len() - failed, checks.len());

    let report_dir = args.report.parent().unwrap_or(Path::new(""));
    kick_runner::report::write(&args.out, &relative(report_dir, &figures), Some(&checks), &args.report)
        .map_err(|e| e.to_string())?;
    println!("report: {}", args.report.display());

    // The rest of the workspace's results: 3D sweeps, contact laws,
    // identifiability, and the solvers' work–precision.
    let out = args.out.display().to_string();
    let report_dir = report_dir.to_path_buf();
    let mut three_d: Vec<String> = std::fs::read_dir(args.experiments.join("3d"))
        .map(|entries| {
            entries
                .filter_map(|e| e.ok().map(|e| e.path()))
                .filter(|p| p.extension().is_some_and(|x| x == "toml"))
                .map(|p| p.display().to_string())
                .collect()
        })
        .unwrap_or_default();
    three_d.sort();
    let identification = args.out.join("identification").display().to_string();
    let solvers_report = report_dir.join("solvers.md").display().to_string();
    let mut commands: Vec<Vec<String>> = Vec::new();
    if !three_d.is_empty() {
        let mut argv = vec!["kick".to_string(), "run3d".to_string()];
        argv.extend(three_d);
        argv.extend(["--out".to_string(), out.clone()]);
        commands.push(argv);
    }
    commands.push(["kick", "leg", "--knee", "30", "--ankle", "60", "--sweep-out", &out].map(String::from).to_vec());
    commands.push(["kick", "laws", "--out", &identification].map(String::from).to_vec());
    commands.push(["kick", "fit", "profile", "--out", &identification].map(String::from).to_vec());
    // Synthetic data (the paper's law; Hunt–Crossley with a late first touch), fitted back.
    let fits = args.out.join("identification");
    let spec = |name: &str| fits.join(format!("{name}.toml")).display().to_string();
    let fit_file = |name: &str| fits.join(name).display().to_string();
    commands.push(["kick", "fit", "synthesize", "--out", &identification, "--seed", "1"].map(String::from).to_vec());
    commands.push(
        [
            "kick", "fit", "synthesize", "--out", &identification, "--name", "synthetic_hunt_crossley", "--seed", "2", "--law",
            "hunt-crossley-exact", "--restitution", "0.66", "--time-offset", "2.5e-4",
        ]
        .map(String::from)
        .to_vec(),
    );
    commands.push(["kick", "fit", "data", &spec("synthetic"), "--out", &fit_file(SYNTHETIC_FIT)].map(String::from).to_vec());
    commands.push(
        ["kick", "fit", "data", &spec("synthetic_hunt_crossley"), "--out", &fit_file(SYNTHETIC_LAW_FIT)].map(String::from).to_vec(),
    );
    commands.push(["kick", "fit", "table2", "--out", &fit_file(TABLE2_FIT)].map(String::from).to_vec());
    commands.push(["kick", "bench", "--out", &out, "--report", &solvers_report].map(String::from).to_vec());
    for argv in &commands {
        println!("\n$ {}", argv.join(" "));
        crate::dispatch(argv)?;
    }
    // The leg's section: its figures, drawn from results/leg_*.h5.
    let figures_from_report = relative(&report_dir, &args.out.join("figures"));
    let leg = format!(
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
    kick_runner::output::write(report_dir.join("leg.md"), leg).map_err(|e| e.to_string())?;
    // Contact laws and identification: from results/identification/*.h5.
    let identification_from_report = relative(&report_dir, &fits);
    let laws = crate::identify_report::laws(&fits.join(LAWS), &identification_from_report)?;
    kick_runner::output::write(report_dir.join("laws.md"), laws).map_err(|e| e.to_string())?;
    let identification = crate::identify_report::identification(&fits, &identification_from_report)?;
    kick_runner::output::write(report_dir.join("identification.md"), identification)
        .map_err(|e| e.to_string())?;
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
        kick_runner::output::write(&args.report, text).map_err(|e| e.to_string())?;
    }
    if failed > 0 {
        return Err(format!("{failed} cross-model check(s) failed; see {}", args.report.display()));
    }
    Ok(())
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
