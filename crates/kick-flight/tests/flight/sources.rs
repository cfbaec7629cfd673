//! SOURCES.md and the validation chapter's measurement file hold the same
//! numbers with the same check status: the table "Shared with the
//! validation chapter" is compared with the file entry by entry, and the
//! file's notes never describe SOURCES.md (issue 34: notes that described
//! old states of this file).

use kick_core::measurements::Checked;
use kick_store::measurements::{read, MEASUREMENTS_FILE};
use std::path::Path;

fn root() -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// (key, value text, unit, checked) of each row of the shared table.
fn shared_rows() -> Vec<(String, String, String, String)> {
    let text = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("SOURCES.md")).unwrap();
    let table = text.split("## Shared with the validation chapter").nth(1).expect("the shared table's heading");
    table
        .lines()
        .filter(|l| l.starts_with("| `"))
        .map(|l| {
            let cells: Vec<String> = l.trim_matches('|').split('|').map(|c| c.trim().to_string()).collect();
            (cells[0].trim_matches('`').to_string(), cells[1].clone(), cells[2].clone(), cells[3].clone())
        })
        .collect()
}

fn status(c: &Checked) -> &'static str {
    match c {
        Checked::Text => "text",
        Checked::Abstract => "abstract",
        Checked::Secondary(_) => "secondary",
        Checked::Transcription(_) => "transcription",
        Checked::Unchecked => "unchecked",
    }
}

#[test]
fn the_shared_table_is_the_measurement_file() {
    let m = read(&root().join(MEASUREMENTS_FILE)).unwrap();
    let rows = shared_rows();
    assert!(rows.len() >= 20, "{} rows", rows.len());
    for (key, value, unit, checked) in &rows {
        let x = m.get(key, "SOURCES.md's shared table").unwrap_or_else(|e| panic!("{e}"));
        let numbers: Vec<f64> = value.split('–').map(|v| v.trim().parse().unwrap_or_else(|_| panic!("{key}: {value}"))).collect();
        match (x.value, x.range, numbers.as_slice()) {
            (Some(v), None, [n]) => assert_eq!(v, *n, "{key}"),
            (None, Some([lo, hi]), [a, b]) => assert_eq!([lo, hi], [*a, *b], "{key}"),
            _ => panic!("{key}: SOURCES.md gives {value}, the file {:?} / {:?}", x.value, x.range),
        }
        let file_unit = serde_json::to_value(x.unit).unwrap();
        assert_eq!(file_unit.as_str(), Some(unit.as_str()), "{key}: unit");
        assert_eq!(status(&x.checked), checked, "{key}: SOURCES.md says {checked}, the file {}", x.checked);
    }
    // The file's notes point to the table, never describe SOURCES.md themselves.
    for x in &m.measurements {
        for field in [x.note.as_deref().unwrap_or(""), &x.location, &x.conditions, &x.checked.to_string()] {
            assert!(!field.contains("kick-flight/SOURCES.md"), "`{}` describes SOURCES.md: {field}", x.key);
        }
    }
    for s in &m.sources {
        assert!(!s.citation_note.as_deref().unwrap_or("").contains("kick-flight/SOURCES.md"), "source `{}`", s.key);
    }
}
