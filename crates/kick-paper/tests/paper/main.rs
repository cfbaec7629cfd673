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

mod compress;
mod flight_grid;
mod histories;
mod identify;
mod law;
mod reproduce_check;
mod result_file;
mod runner;
mod settings;
mod shard;
mod sweep3d;
mod text;
