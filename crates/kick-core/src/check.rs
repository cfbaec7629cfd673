//! One row of a cross-model check: a prediction of one model level
//! (`expected`) against another level's result (`actual`). Shared by
//! `kick-checks`, `kick-3d` and the report.

use serde::Serialize;

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CheckRow {
    pub name: String,
    /// The equation(s) of the paper the check tests, e.g. "Eq. 37".
    pub equation: String,
    pub expected: f64,
    pub actual: f64,
    /// |actual − expected| / scale (the scale is given per check).
    pub error: f64,
    pub tolerance: f64,
    pub passed: bool,
}

impl CheckRow {
    /// Compare with a relative error |actual − expected| / scale.
    pub fn compare(name: impl Into<String>, equation: &str, expected: f64, actual: f64, scale: f64, tolerance: f64) -> CheckRow {
        let error = (actual - expected).abs() / scale;
        CheckRow {
            name: name.into(),
            equation: equation.into(),
            expected,
            actual,
            error,
            tolerance,
            passed: expected.is_finite() && actual.is_finite() && error.is_finite() && error <= tolerance,
        }
    }

    /// A check that could not be computed: it fails and says why.
    pub fn failed(name: impl Into<String>, equation: &str, why: &dyn std::fmt::Display) -> CheckRow {
        CheckRow {
            name: format!("{} (failed: {why})", name.into()),
            equation: equation.into(),
            expected: f64::NAN,
            actual: f64::NAN,
            error: f64::INFINITY,
            tolerance: 0.0,
            passed: false,
        }
    }
}
