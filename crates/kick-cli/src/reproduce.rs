//! `kick reproduce`: every experiment, the figures, the cross-model checks and
//! the reproduction report.

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
    commands.push(["kick", "laws", "--out", &identification].map(String::from).to_vec());
    commands.push(["kick", "fit", "profile", "--out", &identification].map(String::from).to_vec());
    commands.push(["kick", "bench", "--out", &out, "--report", &solvers_report].map(String::from).to_vec());
    for argv in &commands {
        println!("\n$ {}", argv.join(" "));
        crate::dispatch(argv)?;
    }
    // Point the report at the sections written beside it.
    let mut text = std::fs::read_to_string(&args.report).map_err(|e| format!("cannot read {}: {e}", args.report.display()))?;
    let sections = [
        ("solvers.md", "Solvers of the 1D model: work–precision, cost, trust regions"),
        ("3d.md", "Off-center 3D kicks: spin and friction"),
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
        std::fs::write(&args.report, text).map_err(|e| format!("cannot write {}: {e}", args.report.display()))?;
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
