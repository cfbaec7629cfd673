//! The `kick` binary's contract, one test binary: names other tools read, exit codes, messages, files.

mod aim;
mod bounce;
mod check_and_leg;
mod cli;
mod fit_and_laws;
mod flight;
mod history;
mod run_reproduce;
mod shard;
mod simulate3d;

/// Run `kick` with `args` in the workspace root.
fn kick(args: &[&str]) -> std::process::Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_kick"))
        .args(args)
        .current_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."))
        .output()
        .expect("kick runs")
}
mod reliability;
