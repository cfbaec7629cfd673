//! Who wrote a result file, when, and from what.

use std::time::{SystemTime, UNIX_EPOCH};

/// Root attributes of every result file.
#[derive(Debug, Clone, PartialEq)]
pub struct Provenance {
    /// Program that wrote the file (e.g. `kick`).
    pub tool: String,
    pub tool_version: String,
    /// `git rev-parse HEAD` at run time, when the work tree is a git checkout.
    pub git_commit: Option<String>,
    /// Whether tracked files differed from that commit (`git status`), when known.
    pub git_dirty: Option<bool>,
    /// ISO 8601, UTC, second resolution.
    pub created_utc: String,
    /// Experiment name (the file's stem unless the file names it).
    pub experiment: String,
    /// Path of the experiment file as given.
    pub experiment_file: String,
    /// Full text of the experiment file.
    pub experiment_text: String,
}

impl Provenance {
    /// Provenance stamped now, with the git commit looked up in the current directory.
    pub fn now(experiment: &str, experiment_file: &str, experiment_text: &str) -> Provenance {
        Provenance {
            tool: "kick".into(),
            tool_version: env!("CARGO_PKG_VERSION").into(),
            git_commit: git_commit(),
            git_dirty: git_dirty(),
            created_utc: utc_timestamp(SystemTime::now()),
            experiment: experiment.into(),
            experiment_file: experiment_file.into(),
            experiment_text: experiment_text.into(),
        }
    }
}

/// `git rev-parse HEAD`, or `None` outside a checkout or without git.
pub fn git_commit() -> Option<String> {
    let output = std::process::Command::new("git")
        .args(["rev-parse", "HEAD"])
        .stderr(std::process::Stdio::null())
        .output()
        .ok()?;
    if !output.status.success() {
        return None;
    }
    let commit = String::from_utf8(output.stdout).ok()?.trim().to_string();
    (commit.len() >= 7 && commit.bytes().all(|b| b.is_ascii_hexdigit())).then_some(commit)
}

/// True when tracked files differ from HEAD; `None` without git.
pub fn git_dirty() -> Option<bool> {
    let output = std::process::Command::new("git")
        .args(["status", "--porcelain", "--untracked-files=no"])
        .stderr(std::process::Stdio::null())
        .output()
        .ok()?;
    output.status.success().then(|| !output.stdout.is_empty())
}

/// `YYYY-MM-DDTHH:MM:SSZ` for a system time (UTC), without a date library.
pub fn utc_timestamp(time: SystemTime) -> String {
    let seconds = time.duration_since(UNIX_EPOCH).map(|d| d.as_secs()).unwrap_or(0) as i64;
    let (days, rest) = (seconds.div_euclid(86_400), seconds.rem_euclid(86_400));
    let (year, month, day) = civil_from_days(days);
    format!(
        "{year:04}-{month:02}-{day:02}T{:02}:{:02}:{:02}Z",
        rest / 3600,
        (rest / 60) % 60,
        rest % 60
    )
}

/// Proleptic Gregorian date of a day count since 1970-01-01 (H. Hinnant's algorithm).
fn civil_from_days(days: i64) -> (i64, u32, u32) {
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z.rem_euclid(146_097);
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let day = (doy - (153 * mp + 2) / 5 + 1) as u32;
    let month = if mp < 10 { mp + 3 } else { mp - 9 } as u32;
    let year = yoe + era * 400 + i64::from(month <= 2);
    (year, month, day)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::time::Duration;

    #[test]
    fn timestamps_of_known_instants() {
        // 2000-03-01 (after a leap day) and 2024-02-29T23:59:59 (a leap day).
        assert_eq!(utc_timestamp(UNIX_EPOCH), "1970-01-01T00:00:00Z");
        assert_eq!(utc_timestamp(UNIX_EPOCH + Duration::from_secs(951_868_800)), "2000-03-01T00:00:00Z");
        assert_eq!(utc_timestamp(UNIX_EPOCH + Duration::from_secs(1_709_251_199)), "2024-02-29T23:59:59Z");
    }
}
