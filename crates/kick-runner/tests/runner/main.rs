//! kick-runner's tests, one binary: experiment files in, result files out, read back.

mod law;
mod result_file;
mod runner;
mod histories;
mod reproduce_check;
mod shard;
mod sweep3d;
mod settings;
mod text;
