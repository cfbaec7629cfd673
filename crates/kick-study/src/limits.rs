//! Bounds on what one run may ask for: threads, rows and bytes on disk.
//!
//! A run is refused before it starts when it asks for more threads than the
//! machine can use, more rows than [`MAX_SCENARIOS`], or a file larger than
//! the free space where it goes; a large run states its size first.

use kick_core::short;
use std::path::Path;

pub use kick_core::threads::{cores, max_threads, MAX_THREADS, THREADS_PER_CORE};

/// The most rows (scenarios, samples or cells) one run may hold.
pub const MAX_SCENARIOS: u64 = 100_000_000;

/// Runs from this many estimated bytes, or [`LARGE_OUTPUT_ROWS`] rows, on
/// state their size before starting.
pub const LARGE_OUTPUT_BYTES: u64 = 1 << 30;
/// See [`LARGE_OUTPUT_BYTES`].
pub const LARGE_OUTPUT_ROWS: u64 = 1_000_000;

#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum LimitError {
    #[error("`{name}` = {requested}: must be at least 1")]
    NoThreads { name: String, requested: usize },
    #[error(
        "`{name}` = {requested}: more than {max}, the most this machine can use \
         ({THREADS_PER_CORE} x its {cores} cores, never above {MAX_THREADS})"
    )]
    TooManyThreads { name: String, requested: usize, max: usize, cores: usize },
    #[error("cannot start {threads} threads: {message}")]
    Threads { threads: usize, message: String },
    #[error("{what} = {rows}: more than the {MAX_SCENARIOS} scenarios one run may hold; split the run")]
    TooManyRows { what: &'static str, rows: u64 },
    #[error(
        "the output would need about {} ({rows} rows), more than the {} free on the file system of {}",
        bytes(*.needed), bytes(*.free), directory
    )]
    NoSpace { rows: u64, needed: u64, free: u64, directory: String },
}

/// `n` bytes in short form: `1.2 GB`.
pub fn bytes(n: u64) -> String {
    let n = n as f64;
    match n {
        n if n >= 1e12 => format!("{} TB", short(n / 1e12)),
        n if n >= 1e9 => format!("{} GB", short(n / 1e9)),
        n if n >= 1e6 => format!("{} MB", short(n / 1e6)),
        n if n >= 1e3 => format!("{} kB", short(n / 1e3)),
        n => format!("{n} B"),
    }
}

/// Use `requested` rayon workers for the rest of the process (default: one
/// per core); `name` is the setting as the user gave it (`--threads`).
pub fn use_threads(requested: Option<usize>, name: &str) -> Result<(), LimitError> {
    let Some(n) = requested else { return Ok(()) };
    if n == 0 {
        return Err(LimitError::NoThreads { name: name.into(), requested: n });
    }
    if n > max_threads() {
        return Err(LimitError::TooManyThreads { name: name.into(), requested: n, max: max_threads(), cores: cores() });
    }
    rayon::ThreadPoolBuilder::new().num_threads(n).build_global().map_err(|e| LimitError::Threads { threads: n, message: e.to_string() })
}

/// Use `threads` rayon workers for the rest of the process (if given).
pub fn set_threads(threads: Option<usize>) -> Result<(), LimitError> {
    use_threads(threads, "--threads")
}

/// The size of a run's result file, estimated before it runs.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OutputSize {
    pub rows: u64,
    /// Data bytes: parameters, outcomes and status of every row, and the
    /// histories at their elastic contact time (failure messages and HDF5's
    /// own structures come on top: ~15% in a sweep with 10% failures).
    pub bytes: u64,
}

impl OutputSize {
    pub fn is_large(&self) -> bool {
        self.bytes >= LARGE_OUTPUT_BYTES || self.rows >= LARGE_OUTPUT_ROWS
    }

    /// "N rows, about X" for messages.
    pub fn describe(&self) -> String {
        format!("{} rows, about {}", self.rows, bytes(self.bytes))
    }
}

/// [`OutputSize::check`] for a table of `rows` rows of `bytes_per_row` data bytes each
/// (`what` names the row count in a refusal).
pub fn check_rows(what: &'static str, total: u64, rows: u64, bytes_per_row: u64, directory: &Path) -> Result<OutputSize, LimitError> {
    if total > MAX_SCENARIOS {
        return Err(LimitError::TooManyRows { what, rows: total });
    }
    check_space(OutputSize { rows, bytes: rows.saturating_mul(bytes_per_row) }, directory, free_space(directory))
}

/// The size, or refused when more than `free` bytes (None: not known).
pub(crate) fn check_space(size: OutputSize, directory: &Path, free: Option<u64>) -> Result<OutputSize, LimitError> {
    match free {
        Some(free) if size.bytes > free => {
            Err(LimitError::NoSpace { rows: size.rows, needed: size.bytes, free, directory: directory.display().to_string() })
        }
        _ => Ok(size),
    }
}

/// Bytes available to this user on the file system holding `path` (or its
/// nearest existing ancestor); None where it cannot be asked.
#[cfg(unix)]
pub fn free_space(path: &Path) -> Option<u64> {
    use std::os::unix::ffi::OsStrExt;
    let mut at = if path.as_os_str().is_empty() { Path::new(".") } else { path };
    while !at.exists() {
        at = at.parent().filter(|p| !p.as_os_str().is_empty()).unwrap_or(Path::new("."));
    }
    let name = std::ffi::CString::new(at.as_os_str().as_bytes()).ok()?;
    // SAFETY: statvfs reads a NUL-terminated path and fills the zeroed struct.
    let mut stat: libc::statvfs = unsafe { std::mem::zeroed() };
    if unsafe { libc::statvfs(name.as_ptr(), &mut stat) } != 0 {
        return None;
    }
    #[allow(clippy::useless_conversion)] // the field types differ between systems
    Some(u64::from(stat.f_bavail).saturating_mul(u64::from(stat.f_frsize)))
}

#[cfg(not(unix))]
pub fn free_space(_path: &Path) -> Option<u64> {
    None
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::experiment::{Experiment, Kicks, Scenarios};

    #[test]
    fn byte_counts_read_short() {
        assert_eq!(bytes(512), "512 B");
        assert_eq!(bytes(64_418_120), "64.418 MB");
        assert_eq!(bytes(2_000_000_000_000), "2 TB");
    }

    #[test]
    fn thread_requests_are_bounded() {
        let e = use_threads(Some(0), "--threads").unwrap_err();
        assert!(e.to_string().contains("`--threads` = 0"), "{e}");
        let e = use_threads(Some(max_threads() + 1), "--threads").unwrap_err();
        assert!(matches!(e, LimitError::TooManyThreads { .. }) && e.to_string().contains("--threads"), "{e}");
        let e = use_threads(Some(20_000), "--threads").unwrap_err();
        assert!(e.to_string().contains(&MAX_THREADS.min(max_threads()).to_string()), "{e}");
    }

    fn sweep(samples: u64) -> Experiment {
        let mut e = crate::experiment::parse(Path::new("e.toml"), "").unwrap();
        if let Kicks::OneD(kicks) = &mut e.kicks {
            kicks.scenarios = Scenarios::Sampled(crate::sample::SampledSweep::new(samples, 1));
        }
        e
    }

    #[test]
    fn rows_and_bytes_are_bounded_before_a_run() {
        let e = OutputSize::check(&sweep(1_000_000_000_000), &(0..1), Path::new(".")).unwrap_err();
        assert_eq!(e.to_string(), "samples = 1000000000000: more than the 100000000 scenarios one run may hold; split the run");
        // 8 parameters, 15 outcomes and a status byte of one solver: 185 bytes a row.
        let size = OutputSize::of(&sweep(100_000), &(0..100_000));
        assert_eq!(size, OutputSize { rows: 100_000, bytes: 18_500_000 });
        assert!(!size.is_large() && OutputSize::of(&sweep(1_000_000), &(0..1_000_000)).is_large());
        let e = check_space(size, Path::new("out"), Some(10_000_000)).unwrap_err();
        assert_eq!(e.to_string(), "the output would need about 18.5 MB (100000 rows), more than the 10 MB free on the file system of out");
        assert!(check_space(size, Path::new("out"), Some(20_000_000)).is_ok());
    }

    /// A shard is sized by its own rows: 1/8 of a 4e6-sample sweep is
    /// 500 000 rows of 185 bytes, not 4e6; a history experiment's shards
    /// add up to the whole, each with its own rows' histories.
    #[test]
    fn a_shard_is_sized_by_its_own_rows() {
        let e = sweep(4_000_000);
        let rows = crate::shard::Shard { index: 3, count: 8 }.rows(4_000_000);
        assert_eq!(rows, 1_500_000..2_000_000);
        let size = OutputSize::of(&e, &rows);
        assert_eq!(size, OutputSize { rows: 500_000, bytes: 92_500_000 });
        assert!(OutputSize::of(&e, &(0..4_000_000)).is_large() && !size.is_large());
        let text = "solver = \"accurate\"\n[[sweep]]\nparameter = \"stiffness\"\nvalues = [1e5, 4e5, 1.6e6, 6.4e6]\n\
                    [output]\nmode = \"history\"\ninterval = 1e-6\n";
        let h = crate::experiment::parse(Path::new("h.toml"), text).unwrap();
        let (whole, first, second) = (OutputSize::of(&h, &(0..4)), OutputSize::of(&h, &(0..1)), OutputSize::of(&h, &(1..4)));
        assert_eq!((first.rows, second.rows), (1, 3));
        assert_eq!(first.bytes + second.bytes, whole.bytes);
        // The softest ball's contact is the longest: its history alone is
        // more than a quarter of the file (contact time ~ k^(-1/(n+1))).
        assert!(first.bytes * 4 > whole.bytes, "{first:?} of {whole:?}");
    }

    #[test]
    fn free_space_is_found_from_a_path_not_yet_made() {
        let free = free_space(&std::env::temp_dir().join("kick-no-such-dir/deeper")).unwrap();
        assert!(free > 0);
    }
}
