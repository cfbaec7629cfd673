//! Helpers shared by the solver tests.

/// |a − b| / |b|, or |a| when b = 0.
pub fn relative_error(actual: f64, expected: f64) -> f64 {
    if expected == 0.0 {
        actual.abs()
    } else {
        ((actual - expected) / expected).abs()
    }
}

/// Assert a relative error bound with a message naming the case and quantity.
#[track_caller]
pub fn assert_close(case: &str, quantity: &str, actual: f64, expected: f64, tolerance: f64) {
    let error = relative_error(actual, expected);
    assert!(
        error <= tolerance,
        "{case}: {quantity} = {actual:.17e}, expected {expected:.17e}, relative error {error:.3e} > {tolerance:.1e}"
    );
}
