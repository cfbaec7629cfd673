//! Input files read with bounds: a regular file only (not a FIFO, a device
//! such as `/dev/zero`, or a directory), its size checked before reading and
//! the read itself capped, so no input can block, exhaust memory or run for
//! minutes. Errors name the file and the limit, never its contents.

use std::io::Read;
use std::path::Path;

/// Experiment, scenario and fit-specification files (TOML, JSON). The
/// largest of the workspace is 2.5 kB; a list of 10,000 named scenarios at
/// 200 bytes each is 2 MB. 16 MiB is far beyond what a researcher writes and
/// bounds the parser's memory (~40× the text) to well under a gigabyte.
pub const MAX_TEXT_BYTES: u64 = 16 << 20;

/// Measured histories (CSV). A 1 MHz record of a 100 ms contact is 100,000
/// rows of a few channels, ~6 MB; 64 MiB leaves room for many more channels.
/// The rows themselves are capped by the reader (`kick_identify::data`).
pub const MAX_DATA_BYTES: u64 = 64 << 20;

/// Why an input file was not read. The messages name the limit, never the
/// contents; the caller puts the file's name (or the flag or key that gave
/// it) in front.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum InputError {
    /// The operating system's refusal (no such file, no permission).
    #[error("cannot read: {0}")]
    Read(String),
    /// A directory, device, FIFO or socket: `what` says which.
    #[error("cannot read: {what}; give a file")]
    NotAFile { what: &'static str },
    #[error("{bytes} bytes, more than the {cap} bytes an input may have")]
    TooLarge { bytes: u64, cap: u64 },
    /// A file that grew past the cap while it was read.
    #[error("more than the {cap} bytes an input may have")]
    Grew { cap: u64 },
    /// `valid_up_to`: the first byte that is not UTF-8.
    #[error("not UTF-8 text (byte {valid_up_to} is not); give a text file")]
    NotText { valid_up_to: usize },
}

/// The whole of `path` as UTF-8 text, at most `cap` bytes; the error says
/// why, naming neither more nor less than the file and the limit.
pub fn read_text(path: &Path, cap: u64) -> Result<String, InputError> {
    let metadata = std::fs::metadata(path).map_err(|e| InputError::Read(e.to_string()))?;
    if !metadata.is_file() {
        let what = if metadata.is_dir() { "a directory" } else { "not a regular file (a device, FIFO or socket)" };
        return Err(InputError::NotAFile { what });
    }
    if metadata.len() > cap {
        return Err(InputError::TooLarge { bytes: metadata.len(), cap });
    }
    let file = std::fs::File::open(path).map_err(|e| InputError::Read(e.to_string()))?;
    let mut bytes = Vec::with_capacity(metadata.len() as usize);
    // Capped again: the file may grow while read.
    file.take(cap + 1).read_to_end(&mut bytes).map_err(|e| InputError::Read(e.to_string()))?;
    if bytes.len() as u64 > cap {
        return Err(InputError::Grew { cap });
    }
    String::from_utf8(bytes).map_err(|e| InputError::NotText { valid_up_to: e.utf8_error().valid_up_to() })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(name: &str) -> std::path::PathBuf {
        let dir = std::env::temp_dir().join(format!("kick-input-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    #[test]
    fn regular_files_within_the_cap_are_read_whole() {
        let dir = scratch("read");
        let file = dir.join("a.toml");
        std::fs::write(&file, "x = 1\n").unwrap();
        assert_eq!(read_text(&file, 6).unwrap(), "x = 1\n");
        let e = read_text(&file, 5).unwrap_err();
        assert_eq!(e, InputError::TooLarge { bytes: 6, cap: 5 });
        let message = e.to_string();
        assert!(message.contains("6 bytes") && message.contains("5 bytes"), "{message}");
        std::fs::write(&file, b"a\xffb").unwrap();
        let message = read_text(&file, 100).unwrap_err().to_string();
        assert!(message.contains("not UTF-8") && message.contains("byte 1"), "{message}");
        assert!(read_text(&dir, 100).unwrap_err().to_string().contains("a directory"));
        let _ = std::fs::remove_dir_all(&dir);
    }

    /// `/dev/zero` would be read until memory runs out, a FIFO would block:
    /// both are refused at once.
    #[cfg(unix)]
    #[test]
    fn devices_and_fifos_are_refused_without_reading() {
        let message = read_text(Path::new("/dev/zero"), MAX_TEXT_BYTES).unwrap_err().to_string();
        assert!(message.contains("not a regular file"), "{message}");
        let dir = scratch("fifo");
        let fifo = dir.join("fifo.toml");
        let status = std::process::Command::new("mkfifo").arg(&fifo).status().unwrap();
        assert!(status.success());
        let message = read_text(&fifo, MAX_TEXT_BYTES).unwrap_err().to_string();
        assert!(message.contains("not a regular file"), "{message}");
        let _ = std::fs::remove_dir_all(&dir);
    }
}
