//! The library crates' tests through kick-paper, one binary: experiment files in, result files out, read back.

use std::path::PathBuf;

/// A fresh, empty directory for one test (`name` unique in this binary),
/// with HDF5 file locking off as the `kick` binary has it.
pub fn scratch(name: &str) -> PathBuf {
    kick_store::h5::disable_file_locking();
    let dir = std::env::temp_dir().join(format!("kick-paper-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir
}

mod law;
mod result_file;
mod runner;
mod histories;
mod reproduce_check;
mod shard;
mod sweep3d;
mod flight_grid;
mod settings;
mod text;
mod compress;
mod identify;
