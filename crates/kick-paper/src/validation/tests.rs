//! The chapter's rules, checked on the committed measurements: each test
//! reads the JSON (or solves the model) independently of the code that wrote it.

use super::rows::estimate_cell;
use super::*;
use std::sync::OnceLock;

fn file() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..").join(kick_core::measurements::MEASUREMENTS_FILE)
}

/// One validation for all tests (the 3D sweep takes a while in a debug build).
fn validation() -> &'static (Validation, String, serde_json::Value) {
    static V: OnceLock<(Validation, String, serde_json::Value)> = OnceLock::new();
    V.get_or_init(|| {
        let v = validate(&file()).expect("the committed measurements validate");
        let page = v.markdown("v.json", "m.toml", "NOTES.md");
        let json = serde_json::to_value(&v).unwrap();
        (v, page, json)
    })
}

fn json_rows(json: &serde_json::Value) -> Vec<&serde_json::Value> {
    [&json["ball"], &json["contact"], &json["curve_kicks"]["rows"], &json["flight"]]
        .into_iter()
        .flat_map(|g| g.as_array().expect("a row group").iter())
        .collect()
}

#[test]
fn every_row_has_a_valid_role() {
    let (_, page, json) = validation();
    let rows = json_rows(json);
    assert!(rows.len() >= 30, "{} rows", rows.len());
    let mut seen = std::collections::BTreeSet::new();
    for row in &rows {
        let role = row["role"].as_str().unwrap_or_else(|| panic!("no role: {row}"));
        assert!(["calibration", "prediction", "check"].contains(&role), "{role}");
        seen.insert(role);
        if role == "calibration" {
            assert!(row["sets"].as_str().is_some_and(|s| !s.is_empty()), "a calibration names what it sets: {row}");
        }
        assert!(!row["model_conditions"].as_str().unwrap_or("").is_empty(), "{row}");
    }
    assert_eq!(seen.len(), 3, "{seen:?}");
    assert_eq!(json["free_kicks"]["circle_estimate_role"], "check");
    // Prose states only what was computed: no literal foot of another scenario.
    assert!(!page.contains("m_f = 1.2 kg"));
    assert!(!page.contains("NaN"));
}

/// The headline, recounted from the JSON: predictions, like for like, with an
/// interval of nonzero width; a point (low = high) is never counted.
#[test]
fn headline_counts_predictions_with_intervals_only() {
    let (v, page, json) = validation();
    let (mut counted, mut inside, mut points) = (0, 0, 0);
    for row in json_rows(json) {
        let c = &row["comparison"];
        let (lo, hi, model) = (c["measured"]["low"].as_f64(), c["measured"]["high"].as_f64(), c["model"].as_f64());
        if let (Some(lo), Some(hi)) = (lo, hi) {
            if lo == hi {
                points += 1;
            }
        }
        let prediction = row["role"] == "prediction" && row["not_counted"].is_null();
        if let (true, Some(lo), Some(hi), Some(model)) = (prediction, lo, hi, model) {
            if hi > lo {
                counted += 1;
                inside += usize::from(lo <= model && model <= hi);
            }
        }
    }
    assert!(points >= 5 && counted >= 5, "{points} points, {counted} counted");
    assert_eq!((v.predictions_inside, v.predictions_counted), (inside, counted));
    assert!(page.contains(&format!("**{inside} of {counted} predictions fall inside")), "{inside} of {counted}");
    for r in v.rows().filter(|r| r.is_point()) {
        assert!(!r.counted() && r.count_note().starts_with("no"), "{}", r.comparison.measured.key);
    }
}

/// Every source a measurement cites (its `source` and `cites`) is listed, and
/// the count in the header is the list's length.
#[test]
fn every_cited_source_is_listed() {
    let (v, page, _) = validation();
    let m = Measurements::load(&file()).unwrap();
    for x in &m.measurements {
        for key in std::iter::once(&x.source).chain(&x.cites) {
            assert!(page.contains(&format!("- `{key}`: ")), "source `{key}` of `{}` is not listed", x.key);
        }
    }
    let listed = page.split("## Sources").nth(1).unwrap().lines().filter(|l| l.starts_with("- `")).count();
    assert_eq!(listed, v.sources);
    assert!(page.contains(&format!("from the {listed} sources listed")));
}

/// A peak force is compared at the ball speed measured with it: the row's
/// model value equals a direct solve at the foot speed that sends the ball
/// off at Tol et al.'s 24.6 m/s, found here by bisection.
#[test]
fn peak_force_is_solved_at_the_measured_ball_speed() {
    use kick_core::Solver;
    let (v, _, _) = validation();
    let row = v
        .contact
        .iter()
        .find(|r| r.comparison.measured.key == "peak_force_tol2002" && r.model.starts_with("paper"))
        .expect("Tol et al.'s peak-force row");
    let solver = kick_compliant::Accurate::default();
    let base = Scenario::baseline();
    let exit = |v_f: f64| solver.solve(&base.with(Parameter::FootSpeed, v_f).unwrap()).unwrap();
    let (mut lo, mut hi) = (5.0, 40.0);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if exit(mid).v_ball_out < 24.6 {
            lo = mid;
        } else {
            hi = mid;
        }
        if hi - lo < 1e-13 {
            break;
        }
    }
    let direct = exit(0.5 * (lo + hi));
    assert!((direct.v_ball_out - 24.6).abs() < 1e-10, "{}", direct.v_ball_out);
    let rel = (row.comparison.model - direct.peak_force).abs() / direct.peak_force;
    assert!(rel < 1e-8, "row {} N, direct {} N ({rel:e})", row.comparison.model, direct.peak_force);
    // Not the baseline kick's peak (31.98 m/s ball).
    assert!((row.comparison.model - exit(22.0).peak_force).abs() > 100.0);
}

/// An estimate whose σ exceeds it is printed as not identified, never as a number.
#[test]
fn not_identified_when_sigma_exceeds_the_value() {
    assert!(estimate_cell(Some(13.96), Some(40.035)).starts_with("not identified"));
    assert!(estimate_cell(Some(2.63), Some(1.69)).starts_with("2.63 ± 1.69"));
    let (v, _, _) = validation();
    let mut v = v.clone();
    v.implied.push(Identified {
        law: "test".into(),
        parameter: "foot mass m_f".into(),
        unit: "kg".into(),
        value: Some(13.96),
        sigma: Some(40.035),
        targets: "t".into(),
        note: "n".into(),
    });
    let page = v.markdown("v.json", "m.toml", "NOTES.md");
    assert!(page.contains("| test | foot mass m_f | not identified (σ = 40.035 > 13.96) |"));
    assert!(!page.contains("13.96 ±"));
}

/// The zero-friction spin is printed as zero to rounding, one way everywhere.
#[test]
fn zero_friction_spin_is_zero_to_rounding() {
    let (v, page, _) = validation();
    let zero = v.curve_kicks.curves[0].iter().map(|p| p.spin).fold(0.0, f64::max);
    assert!(zero < ZERO_SPIN, "{zero}");
    assert!(page.contains("0 (< 1e-12)"));
    assert!(!page.contains("e-19") && !page.contains("e-14"));
}

/// The patch rows: the frictionless spin is a kick built here by hand (shell
/// ball, cap, face square, patch) and turns as friction turns the ball; the
/// friction gain is the largest of its differences over the sweep.
#[test]
fn patch_rows_are_the_kicks_they_name() {
    let (v, _, _) = validation();
    let row = |quantity: &str| {
        v.curve_kicks
            .rows
            .iter()
            .find(|r| r.model.contains("patch") && r.comparison.quantity == quantity)
            .unwrap_or_else(|| panic!("no patch row {quantity}"))
    };
    let shell = Scenario::baseline().with_shell(ShellBall::default_with_radius(DEFAULT_BALL_RADIUS).unwrap());
    let solve = |e: f64, mu: f64| {
        let spec = kick_3d::Kick3dSpec {
            offset: Some(e),
            friction: Some(mu),
            face_yaw_deg: Some(0.0),
            instep_radius: Some(0.15),
            patch_contact: Some(true),
            ..kick_3d::Kick3dSpec::default()
        };
        kick_3d::Accurate3d::default().solve(&kick_3d::Kick3d::new(shell, &spec).unwrap()).unwrap().spin
    };
    let norm = |w: [f64; 3]| (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]).sqrt();
    let last = 0.105; // the 5 mm grid's last offset inside the ball
    let (zero, rubbed) = (solve(last, 0.0), solve(last, 0.5));
    let frictionless = row("spin without friction");
    assert!((frictionless.comparison.model - norm(zero)).abs() <= 1e-12 * norm(zero), "{} vs {zero:?}", frictionless.comparison.model);
    assert!(norm(zero) > 1.0 && zero.iter().zip(&rubbed).map(|(a, b)| a * b).sum::<f64>() > 0.0, "{zero:?} {rubbed:?}");
    assert!(frictionless.comparison.note.contains("friction's sense (as friction's spin at mu = 0.5): true"));
    let gain = row("spin added by friction 0 -> 1 (largest over offsets)").comparison.model;
    let mut best = f64::NEG_INFINITY;
    for i in 0..=21 {
        let e = 0.005 * i as f64;
        best = best.max(norm(solve(e, 1.0)) - norm(solve(e, 0.0)));
    }
    assert!((gain - best).abs() <= 1e-9 * best, "{gain} vs {best}");
}
