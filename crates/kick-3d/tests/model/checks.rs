//! Every row of `kick_3d::checks::checks()` passes (the rows compare against
//! the 1D solver, closed forms and conservation laws; see `checks.rs`).

#[test]
fn every_check_passes() {
    let rows = kick_3d::checks::checks();
    for r in &rows {
        println!(
            "{:<70} expected {:>+.12e} actual {:>+.12e} error {:.2e} tol {:.0e} {}",
            r.name,
            r.expected,
            r.actual,
            r.error,
            r.tolerance,
            if r.passed { "ok" } else { "FAIL" }
        );
    }
    assert!(rows.len() >= 17);
    let failed: Vec<_> = rows.iter().filter(|r| !r.passed).map(|r| r.name.clone()).collect();
    assert!(failed.is_empty(), "failed: {failed:?}");
}

/// Every row is scored by exactly one entry of `SCORING` (scale, tolerance
/// and its origin, printed by the report), and every entry scores a row.
#[test]
fn every_row_says_how_it_is_scored() {
    let rows = kick_3d::checks::checks();
    for r in &rows {
        let matching: Vec<_> = kick_3d::checks::SCORING.iter().filter(|s| r.name.starts_with(s.prefix)).collect();
        assert_eq!(matching.len(), 1, "{}: {matching:?}", r.name);
    }
    for s in &kick_3d::checks::SCORING {
        assert!(rows.iter().any(|r| r.name.starts_with(s.prefix)), "no row for {}", s.prefix);
    }
}
