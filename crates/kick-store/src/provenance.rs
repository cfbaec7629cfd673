//! Who wrote a result file and from what: deterministic, so that a run
//! repeated on the same sources gives the same bytes.
//!
//! No wall-clock time is recorded. The commit is the last one that changed
//! the *sources* (everything but `results/` and `paper/`, which `kick
//! reproduce` writes), and `git_dirty` says whether the sources differ from
//! it: committing regenerated results changes neither, so a second run
//! after that commit writes the same bytes. `kick reproduce --check` ignores
//! these two attributes ([`PROVENANCE_ATTRIBUTES`]): they describe the
//! checkout, not the numbers.
//!
//! Clean reruns: a result file whose content (every dataset and attribute
//! but these two) the run would write again unchanged is not rewritten
//! ([`crate::compare::same_content`], [`crate::output::Staged::commit_unless`]).
//! So the two attributes name the sources of the run that last *changed* the
//! file: a later commit that changes no number (a comment, another model, a
//! formatting pass) leaves every file as committed, and a fresh clone's
//! `kick reproduce` leaves `git status` clean but for the timing outputs.
//! That keeps the record honest: the sources named did produce exactly
//! these numbers, and `kick reproduce --check` confirms the current sources
//! produce them too. Recording a hash of the sources instead would change
//! with every unrelated commit, which is what made every file differ.

use std::time::{SystemTime, UNIX_EPOCH};

/// Root attributes that describe the checkout rather than the results.
pub const PROVENANCE_ATTRIBUTES: [&str; 2] = ["git_commit", "git_dirty"];

/// Directories (relative to the repository's top) written by `kick reproduce`,
/// left out of the source state.
pub const GENERATED_DIRECTORIES: [&str; 2] = ["results", "paper"];

/// Root attributes of every result file.
#[derive(Debug, Clone, PartialEq)]
pub struct Provenance {
    /// Program that wrote the file (e.g. `kick`).
    pub tool: String,
    pub tool_version: String,
    /// The last commit that changed the sources ([`source_commit`]), in a git checkout.
    pub git_commit: Option<String>,
    /// Whether the tracked sources differ from that commit ([`sources_dirty`]), when known.
    pub git_dirty: Option<bool>,
    /// Experiment name (the file's stem unless the file names it).
    pub experiment: String,
    /// Path of the experiment file as given.
    pub experiment_file: String,
    /// Full text of the experiment file.
    pub experiment_text: String,
}

impl Provenance {
    /// Provenance of a run now, with the source state looked up in the current directory.
    pub fn now(experiment: &str, experiment_file: &str, experiment_text: &str) -> Provenance {
        Provenance {
            tool: "kick".into(),
            tool_version: env!("CARGO_PKG_VERSION").into(),
            git_commit: source_commit(),
            git_dirty: sources_dirty(),
            experiment: experiment.into(),
            experiment_file: experiment_file.into(),
            experiment_text: experiment_text.into(),
        }
    }
}

/// Pathspecs of the sources: the whole checkout but the generated directories.
fn source_pathspecs() -> Vec<String> {
    let mut specs = vec![":(top)".to_string()];
    specs.extend(GENERATED_DIRECTORIES.iter().map(|d| format!(":(top,exclude){d}")));
    specs
}

fn git(args: &[&str]) -> Option<std::process::Output> {
    std::process::Command::new("git").args(args).stderr(std::process::Stdio::null()).output().ok().filter(|o| o.status.success())
}

/// The last commit that changed the sources, or `None` outside a checkout or without git.
pub fn source_commit() -> Option<String> {
    let specs = source_pathspecs();
    let mut args = vec!["log", "-1", "--format=%H", "--"];
    args.extend(specs.iter().map(String::as_str));
    let commit = String::from_utf8(git(&args)?.stdout).ok()?.trim().to_string();
    (commit.len() >= 7 && commit.bytes().all(|b| b.is_ascii_hexdigit())).then_some(commit)
}

/// True when tracked sources differ from the last commit (results and pages
/// left out); `None` without git.
pub fn sources_dirty() -> Option<bool> {
    let specs = source_pathspecs();
    let mut args = vec!["status", "--porcelain", "--untracked-files=no", "--"];
    args.extend(specs.iter().map(String::as_str));
    git(&args).map(|o| !o.stdout.is_empty())
}

/// `YYYY-MM-DDTHH:MM:SSZ` for a system time (UTC), without a date library.
pub fn utc_timestamp(time: SystemTime) -> String {
    let seconds = time.duration_since(UNIX_EPOCH).map(|d| d.as_secs()).unwrap_or(0) as i64;
    let (days, rest) = (seconds.div_euclid(86_400), seconds.rem_euclid(86_400));
    let (year, month, day) = civil_from_days(days);
    format!("{year:04}-{month:02}-{day:02}T{:02}:{:02}:{:02}Z", rest / 3600, (rest / 60) % 60, rest % 60)
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
