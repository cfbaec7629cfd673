//! The validation chapter's data file parses, and every number in it carries
//! a citation and an honest check status.

use kick_core::measurements::{Checked, Measurements};
use kick_store::measurements::{read, MEASUREMENTS_FILE};
use std::path::Path;

fn load() -> Measurements {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..").join(MEASUREMENTS_FILE);
    read(&path).unwrap_or_else(|e| panic!("{e}"))
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

/// Every source is a publication (or a test standard as published): the
/// project's own issue tracker and task statements are not sources.
#[test]
fn no_source_is_the_project_itself() {
    let m = load();
    for s in &m.sources {
        let text = format!("{} {} {}", s.authors, s.title, s.container).to_lowercase();
        assert!(!text.contains("issue tracker") && !text.contains("task statement") && !text.contains("kick project"), "{}", s.key);
        assert!(!s.citation_note.as_deref().unwrap_or("").contains("not a publication"), "{}", s.key);
    }
    for x in &m.measurements {
        assert!(!x.location.contains("task statement"), "`{}`", x.key);
    }
}

/// The mechanical limb's ratios are its paired published ends, 13.0/9.1 and
/// 29.7/21.2, each with the rounding of its four published numbers.
#[test]
fn the_limb_ratios_pair_the_published_ends() {
    use kick_core::measurements::Measured;
    let m = load();
    let get = |k: &str| m.measured(k, "test").unwrap();
    for (ball, foot, ratio) in
        [("ball_speed_limb_slow", "foot_speed_limb_slow", 13.0 / 9.1), ("ball_speed_limb_fast", "foot_speed_limb_fast", 29.7 / 21.2)]
    {
        let r = Measured::ratio(&get(ball), &get(foot)).unwrap();
        assert!(r.is_point() && (r.low.unwrap() - ratio).abs() < 1e-14, "{r:?}");
        let u = r.uncertainty.unwrap();
        assert!(!u.is_stated() && u.u() > 0.0 && u.u() < 0.01, "{u:?}");
    }
    assert!((13.0_f64 / 9.1 - 1.43).abs() < 5e-3 && (29.7_f64 / 21.2 - 1.40).abs() < 5e-3);
    // The pairing agrees with the published ratio band.
    let [lo, hi] = m.get("speed_ratio_mechanical_limb", "test").unwrap().interval_si().unwrap();
    assert!(lo <= 29.7 / 21.2 && 13.0 / 9.1 <= hi);
}

/// Asai et al.'s numbers as published (their abstract: at most 13 rad/s,
/// around 100 mm), read from the measurement file.
#[test]
fn asai_claims_are_the_published_ones() {
    let a = kick_study::patch::asai_claims(&load()).unwrap();
    assert_eq!((a.friction_gain, a.peak_offset), (13.0, 0.1));
    assert!(a.source.contains("spin_friction_gain_asai2002") && a.source.contains("spin_peak_offset_asai2002"));
}
