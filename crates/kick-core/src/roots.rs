//! Bracketing root finder used for event location and parameter fits, and
//! the maximum of equally spaced samples (for references built on samples).

/// Outcome of a bracketed root search.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Root {
    pub x: f64,
    pub value: f64,
    pub iterations: usize,
    /// The other end of the final bracket: f there has the sign opposite to
    /// `value` (or `x` itself when f(x) = 0). Event location uses it to step
    /// past a root without detecting it again.
    pub other: f64,
}

/// Brent's method on [a, b] where f(a) and f(b) differ in sign (or one is zero).
/// Stops when the bracket is below `x_tol` (absolute) or after `max_iter` steps.
/// Returns `None` when the interval does not bracket a root or f is not finite.
pub fn brent<F: FnMut(f64) -> f64>(mut f: F, a: f64, b: f64, x_tol: f64, max_iter: usize) -> Option<Root> {
    let (fa, fb) = (f(a), f(b));
    brent_from(f, (a, fa), (b, fb), x_tol, max_iter)
}

/// [`brent`] with f at the ends already known (`(a, f(a))`, `(b, f(b))`):
/// two evaluations fewer. The ends' values only need the right signs
/// (they seed the first interpolation); every later point is evaluated.
pub fn brent_from<F: FnMut(f64) -> f64>(
    mut f: F,
    (mut a, mut fa): (f64, f64),
    (mut b, mut fb): (f64, f64),
    x_tol: f64,
    max_iter: usize,
) -> Option<Root> {
    if !fa.is_finite() || !fb.is_finite() {
        return None;
    }
    if fa == 0.0 {
        return Some(Root { x: a, value: 0.0, iterations: 0, other: a });
    }
    if fb == 0.0 {
        return Some(Root { x: b, value: 0.0, iterations: 0, other: b });
    }
    if fa.signum() == fb.signum() {
        return None;
    }
    let (mut c, mut fc) = (a, fa);
    let mut d = b - a;
    let mut e = d;
    for iteration in 1..=max_iter {
        if fb.signum() == fc.signum() {
            c = a;
            fc = fa;
            d = b - a;
            e = d;
        }
        if fc.abs() < fb.abs() {
            a = b;
            b = c;
            c = a;
            fa = fb;
            fb = fc;
            fc = fa;
        }
        let tol = 2.0 * f64::EPSILON * b.abs() + 0.5 * x_tol;
        let m = 0.5 * (c - b);
        if m.abs() <= tol || fb == 0.0 {
            let other = if fb == 0.0 { b } else { c };
            return Some(Root { x: b, value: fb, iterations: iteration, other });
        }
        if e.abs() >= tol && fa.abs() > fb.abs() {
            let s = fb / fa;
            let (mut p, mut q);
            if a == c {
                p = 2.0 * m * s;
                q = 1.0 - s;
            } else {
                let qa = fa / fc;
                let r = fb / fc;
                p = s * (2.0 * m * qa * (qa - r) - (b - a) * (r - 1.0));
                q = (qa - 1.0) * (r - 1.0) * (s - 1.0);
            }
            if p > 0.0 {
                q = -q;
            } else {
                p = -p;
            }
            if 2.0 * p < (3.0 * m * q - (tol * q).abs()).min((e * q).abs()) {
                e = d;
                d = p / q;
            } else {
                d = m;
                e = m;
            }
        } else {
            d = m;
            e = m;
        }
        a = b;
        fa = fb;
        b += if d.abs() > tol { d } else { tol.copysign(m) };
        fb = f(b);
        if !fb.is_finite() {
            return None;
        }
    }
    let other = if fb.signum() == fc.signum() { b } else { c };
    Some(Root { x: b, value: fb, iterations: max_iter, other })
}

/// The maximum of the quartic through five equally spaced samples
/// f(−2h) .. f(2h) whose middle one is the largest: (value, offset from the
/// middle in units of h). Error O(h⁵) in the value and O(h⁴) in the offset
/// for a smooth f.
pub fn quartic_maximum(f: [f64; 5]) -> (f64, f64) {
    let d1 = (f[0] - 8.0 * f[1] + 8.0 * f[3] - f[4]) / 12.0;
    let d2 = (-f[0] + 16.0 * f[1] - 30.0 * f[2] + 16.0 * f[3] - f[4]) / 12.0;
    let d3 = (-f[0] + 2.0 * f[1] - 2.0 * f[3] + f[4]) / 2.0;
    let d4 = f[0] - 4.0 * f[1] + 6.0 * f[2] - 4.0 * f[3] + f[4];
    // Newton on the quartic's slope from the parabola's vertex; the largest
    // sample in the middle keeps the maximum within one h of it.
    let mut s = if d2 < 0.0 { (-d1 / d2).clamp(-1.0, 1.0) } else { 0.0 };
    for _ in 0..50 {
        let slope = d1 + s * (d2 + s * (d3 / 2.0 + s * d4 / 6.0));
        let curvature = d2 + s * (d3 + s * d4 / 2.0);
        if curvature >= 0.0 {
            break;
        }
        let next = (s - slope / curvature).clamp(-1.0, 1.0);
        if next == s {
            break;
        }
        s = next;
    }
    (f[2] + s * (d1 + s * (d2 / 2.0 + s * (d3 / 6.0 + s * d4 / 24.0))), s)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_cube_root_of_two() {
        let root = brent(|x| x * x * x - 2.0, 0.0, 2.0, 1e-15, 100).unwrap();
        assert!((root.x - 2f64.cbrt()).abs() < 1e-14);
    }

    #[test]
    fn quartic_maximum_is_exact_for_a_quartic() {
        // f(x) = 3 − (x − 0.3)² − 0.1 (x − 0.3)⁴, maximum 3 at x = 0.3.
        let f = |x: f64| 3.0 - (x - 0.3).powi(2) - 0.1 * (x - 0.3).powi(4);
        let (value, offset) = quartic_maximum([-2.0, -1.0, 0.0, 1.0, 2.0].map(f));
        assert!((value - 3.0).abs() < 1e-14 && (offset - 0.3).abs() < 1e-12, "{value} {offset}");
    }

    /// Known ends spare their two evaluations and find the same root; ends
    /// whose values are only approximate (right signs) still converge to the
    /// function's own root, as the run's one-sided rates do.
    #[test]
    fn known_ends_spare_two_evaluations() {
        let calls = std::cell::Cell::new(0);
        let f = |x: f64| {
            calls.set(calls.get() + 1);
            x.cos() - x
        };
        let plain = brent(f, 0.0, 1.5, 1e-15, 100).unwrap();
        let plain_calls = calls.replace(0);
        let from = brent_from(f, (0.0, f(0.0)), (1.5, f(1.5)), 1e-15, 100).unwrap();
        calls.set(calls.get() - 2);
        assert_eq!((from.x, calls.replace(0)), (plain.x, plain_calls - 2));
        // The Dottie number, cos x = x.
        let dottie = 0.739_085_133_215_160_6;
        let rough = brent_from(f, (0.0, 0.7), (1.5, -2.0), 1e-15, 100).unwrap();
        assert!((rough.x - dottie).abs() < 4e-16 && (plain.x - dottie).abs() < 4e-16, "{} {}", rough.x, plain.x);
    }

    #[test]
    fn refuses_non_bracket() {
        assert!(brent(|x| x * x + 1.0, -1.0, 1.0, 1e-12, 100).is_none());
    }
}
