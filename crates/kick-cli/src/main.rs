//! `kick`: the command line of the kick workspace.

mod bench;
mod check;
mod fit;
mod identify_figures;
mod identify_files;
mod identify_report;
mod laws;
mod leg;
mod output;
mod reproduce;
mod run;
mod simulate;
mod simulate3d;
mod sweep;
mod run3d;
mod table2;

use clap::{Parser, Subcommand};
use std::process::ExitCode;

#[derive(Parser)]
#[command(name = "kick", version, about = "Millisecond physics of a soccer kick")]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Simulate one 1D contact (defaults: Table 1's baseline).
    Simulate(simulate::Args),
    /// Simulate one off-center 3D kick: spin, friction, launch direction.
    Simulate3d(simulate3d::Args),
    /// Run 3D sweeps (experiments/3d/*.toml) into HDF5 and figures.
    Run3d(run3d::Args),
    /// Table 2 side by side: printed, seed-rk4 and accurate values.
    Table2(table2::Args),
    /// Cross-model checks: each model level against the others' limits (exits 1 on a failure).
    Check(check::Args),
    /// Effective mass of the articulated leg (Eq. 11) and the exit speed it gives.
    Leg(leg::Args),
    /// Contact laws (paper, Hunt–Crossley, Lankarani–Nikravesh, Flores, Kelvin–Voigt) on Table 2's scenarios.
    Laws(laws::Args),
    /// Identify parameters from printed or measured data.
    #[command(subcommand)]
    Fit(fit::FitCommand),
    /// Run one experiment file (experiments/*.toml) into DIR/NAME.h5.
    Run(run::Args),
    /// Work–precision of every 1D solver, cost ratios and sweep throughput (HDF5 + figure).
    Bench(bench::Args),
    /// Random scenarios around the baseline, solved in parallel into one HDF5 file.
    Sweep(sweep::Args),
    /// Run every experiment, draw the figures, run the checks, write paper/README.md.
    Reproduce(reproduce::Args),
}

/// Run one `kick` command line from inside the program (`kick reproduce` uses it).
pub(crate) fn dispatch(argv: &[String]) -> Result<(), String> {
    let cli = Cli::try_parse_from(argv).map_err(|e| e.to_string())?;
    execute(cli.command)
}

fn main() -> ExitCode {
    kick_runner::h5::disable_file_locking();
    if let Err(e) = kick_runner::output::install_signal_cleanup() {
        eprintln!("warning: {e}; an interrupted run may leave a temporary file");
    }
    let cli = Cli::parse();
    match execute(cli.command) {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("error: {message}");
            ExitCode::FAILURE
        }
    }
}

fn execute(command: Command) -> Result<(), String> {
    match command {
        Command::Simulate(args) => simulate::run(args),
        Command::Simulate3d(args) => simulate3d::run(args),
        Command::Run3d(args) => run3d::run(args),
        Command::Table2(args) => table2::run(args),
        Command::Check(args) => check::run(args),
        Command::Leg(args) => leg::run(args),
        Command::Laws(args) => laws::run(args),
        Command::Fit(command) => fit::run(command),
        Command::Run(args) => run::run(args),
        Command::Reproduce(args) => reproduce::run(args),
        Command::Sweep(args) => sweep::run(args),
        Command::Bench(args) => bench::run(args),
    }
}
