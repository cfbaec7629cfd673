//! The validation chapter's data file parses, and every number in it carries
//! a citation and an honest check status.

use kick_core::measurements::{Checked, Measurements, MEASUREMENTS_FILE};
use std::path::Path;

fn load() -> Measurements {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..").join(MEASUREMENTS_FILE);
    Measurements::load(&path).unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn the_file_parses_and_every_entry_has_a_citation() {
    let m = load();
    assert!(m.measurements.len() >= 40, "{} measurements", m.measurements.len());
    for x in &m.measurements {
        let s = m.source(&x.source).expect("parse checks source keys");
        let citation = s.citation();
        assert!(!s.authors.is_empty() && !s.title.is_empty() && !s.container.is_empty(), "{citation}");
        assert!(s.year.is_some() || s.year_note.is_some(), "{}", s.key);
        // What is not read in the text says what was found instead.
        if matches!(x.checked, Checked::Unchecked) {
            assert!(x.note.is_some() || x.claim.is_some(), "`{}` is unchecked without a note", x.key);
        }
        // A number read only as quoted names where it was read.
        if let Checked::Secondary(which) = &x.checked {
            assert!(which.len() > 5, "`{}`: secondary source not named", x.key);
        }
        if let Some([lo, hi]) = x.interval_si() {
            assert!(lo.is_finite() && hi.is_finite() && lo <= hi, "`{}`", x.key);
        }
    }
}

#[test]
fn published_units_reach_si() {
    let m = load();
    let si = |key: &str| m.get(key, "test").unwrap().interval_si().unwrap();
    assert_eq!(si("contact_time_instep"), [9.0e-3, 14.0e-3]);
    let [lo, hi] = si("law2_mass");
    assert!((lo - 0.410).abs() < 1e-15 && (hi - 0.450).abs() < 1e-15);
    let [lo, hi] = si("free_kick_spin");
    assert!((lo - 8.0 * std::f64::consts::TAU).abs() < 1e-12 && (hi - 10.0 * std::f64::consts::TAU).abs() < 1e-12);
    // value ± spread
    let [lo, hi] = si("ball_speed_instep_nunome2002");
    assert!((lo - 25.9).abs() < 1e-12 && (hi - 30.1).abs() < 1e-12);
    // Tol et al.'s quoted peak is their mean force as the peak of a half sine.
    let peak = m.get("peak_force_tol2002", "test").unwrap().value.unwrap();
    let mean = m.get("mean_force_tol2002", "test").unwrap().value.unwrap();
    assert!((peak / mean - std::f64::consts::FRAC_PI_2).abs() < 1e-3, "{}", peak / mean);
}
