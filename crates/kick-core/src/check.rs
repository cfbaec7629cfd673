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

/// How a family of check rows is scored, said once beside the checks
/// (`kick_checks::SCORING`, `kick_3d::checks::SCORING`) and printed by the
/// report: what the error is divided by and where the tolerance comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct Scoring {
    /// The rows whose name starts with this.
    pub prefix: &'static str,
    /// The scale: error = |actual − expected| / scale.
    pub scale: &'static str,
    /// The tolerance, as the code computes it.
    pub tolerance: &'static str,
    pub kind: ToleranceKind,
}

/// Where a tolerance comes from. Each is computed from its formula before
/// the comparison; none is a number chosen after seeing the error.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum ToleranceKind {
    /// A rigorous bound derived from the model: the check is that the bound
    /// holds. Where the limit approaches the bound, error/tolerance tends
    /// to 1 by construction.
    Bound,
    /// The first term an asymptotic expansion drops, with the stated factor
    /// for the rest: an a-priori estimate, not a bound.
    Estimate,
    /// The solver's stated accuracy (1e-9 relative), held by its own tests:
    /// the two sides are equal in exact arithmetic.
    SolverAccuracy,
    /// Floating-point rounding: the two sides are equal by construction.
    Rounding,
}

impl ToleranceKind {
    pub fn describe(self) -> &'static str {
        match self {
            ToleranceKind::Bound => "a priori: a rigorous bound",
            ToleranceKind::Estimate => "a priori: the leading dropped term, an estimate",
            ToleranceKind::SolverAccuracy => "a priori: the solver's stated accuracy",
            ToleranceKind::Rounding => "a priori: rounding (equal by construction)",
        }
    }
}

/// The scoring of the row called `name`: the entry of `table` with the
/// longest prefix of it.
pub fn scoring_of<'a>(name: &str, table: &'a [Scoring]) -> Option<&'a Scoring> {
    table.iter().filter(|s| name.starts_with(s.prefix)).max_by_key(|s| s.prefix.len())
}
