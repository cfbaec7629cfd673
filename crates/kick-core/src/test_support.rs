//! What the unit tests of several modules share.

use crate::laws::{AnyLaw, LawKind, LawParameters};

/// Every selectable law at one set of parameters (Table 1's masses, a soft
/// k and a 22 m/s impact for the restitution laws).
pub(crate) fn laws() -> Vec<AnyLaw> {
    let p = LawParameters {
        stiffness: 4.2e5,
        exponent: 1.35,
        damping: 120.0,
        restitution: 0.7,
        impact_speed: 22.0,
        reduced_mass: 0.43 * 3.0 / 3.43,
        linear_stiffness: 1.0e5,
        shell: None,
    };
    LawKind::ALL.iter().map(|&k| AnyLaw::new(k, &p).unwrap()).collect()
}

/// ∫₀^b f by composite Simpson on `panels` (even) panels: error O(h⁴) for a
/// smooth f, O(h^(n+1)) for one like sⁿ at 0.
pub(crate) fn simpson(f: impl Fn(f64) -> f64, b: f64, panels: usize) -> f64 {
    let h = b / panels as f64;
    let sum: f64 = (0..=panels)
        .map(|i| {
            let w = if i == 0 || i == panels {
                1.0
            } else if i % 2 == 1 {
                4.0
            } else {
                2.0
            };
            w * f(i as f64 * h)
        })
        .sum();
    sum * h / 3.0
}
