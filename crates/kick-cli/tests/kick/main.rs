//! The `kick` binary's contract, one test binary: names other tools read, exit codes, messages, files.

mod check_and_leg;
mod cli;
mod fit_and_laws;
mod run_reproduce;
mod simulate3d;
