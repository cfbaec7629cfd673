//! Bracketing root finder used for event location and parameter fits.

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
pub fn brent<F: FnMut(f64) -> f64>(
    mut f: F,
    mut a: f64,
    mut b: f64,
    x_tol: f64,
    max_iter: usize,
) -> Option<Root> {
    let mut fa = f(a);
    let mut fb = f(b);
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_cube_root_of_two() {
        let root = brent(|x| x * x * x - 2.0, 0.0, 2.0, 1e-15, 100).unwrap();
        assert!((root.x - 2f64.cbrt()).abs() < 1e-14);
    }

    #[test]
    fn refuses_non_bracket() {
        assert!(brent(|x| x * x + 1.0, -1.0, 1.0, 1e-12, 100).is_none());
    }
}
