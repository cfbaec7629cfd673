//! `series`: the paper's law (Eq. 20) by power series through compression,
//! and the return from δ_max by its energy integral.
//!
//! Compression obeys Eq. 18 with the damping branch on. In units of the
//! scenario (length L, time L/V0) it reads
//!
//! x'' = −a xⁿ − γ x' + φ,   x(0) = 0, x'(0) = 1,
//!
//! with a = k Lⁿ⁺¹/(μ V0²), γ = c L/(μ V0) and φ = (μ/m_f) F_drive L/(μ V0²).
//! L is the shortest of the undamped δ* (Eq. 34), the damping length μV0/c
//! and the drive length μV0²/|f_s|, so a, |γ|, |φ| ≤ O(1) for every scenario.
//!
//! - Onset: xⁿ has a branch point at τ = 0, so no power series in τ
//!   converges there. The solution is instead a double series in τ and
//!   s = τⁿ⁺¹ (a Frobenius expansion), x = Σ g_ij τ^(1+i) s^j, whose
//!   coefficients follow from a recurrence ([`Onset`]).
//! - Afterwards: Taylor steps of order [`ORDER`] with the power xⁿ expanded
//!   by the J. C. P. Miller recurrence, one `powf` per step ([`TaylorStep`]).
//!   The branch point at τ = 0 limits each step to a fraction of τ, so steps
//!   grow geometrically and a compression takes a handful of them.
//! - Every segment is a polynomial in time, so maximum compression (δ̇ = 0)
//!   and the force peak (dF/dt = 0) are roots of polynomials, found without
//!   re-integrating.
//! - Trapping under a drive: E = ½ μ δ̇² + U(δ) − f_s δ only falls while
//!   compressing (dE/dt = −c δ̇²). The ball reaches δ = 0 again only if
//!   E(δ_max) ≥ 0, so the run stops as soon as E < 0 (`Trapped`),
//!   which also bounds an over-damped creep towards the drive's equilibrium.
//! - Return: undamped, so δ̇(δ) follows from E and only the time needs a
//!   quadrature: the Beta function without a drive, tanh–sinh with one
//!   ([`kick_core::special::driven_return_integral`]).
//!
//! Without a drive, the dissipated energy comes from the energy balance,
//! D = ½ μ V0² − U(δ_max), and the exit speed from U(δ_max). Under a drive
//! that balance reads D = ½ μ V0² + f_s δ_max − U(δ_max), and f_s δ_max and
//! U(δ_max) can be far larger than their difference; so D is integrated
//! along the series, and the exit speed taken from ½ μ w² = ½ μ V0² − D when
//! U(δ_max) > ½ μ V0² (see [`crate::closed::undamped_return`]).
//!
//! Accuracy: the local error per segment is held below [`DEFAULT_TOLERANCE`].
//! At that default every observable is within 1e-10 relative of the closed
//! forms, of a hand-solved linear law under a drive and of `accurate` at
//! 1e-14 on the shared test models, and within 1e-9 over the sweep's box
//! (`tests/solvers/series.rs`; `kick bench` measures ~2e-11 on its set),
//! and within 1e-9 for exponents far past it, n from 11 to 80 (measured
//! 1.2e-10 at most; `branch_radius_share` keeps the steps inside xⁿ's
//! radius there), but for an undamped driven kick at n = 80, whose return
//! quadrature misses the contact time by 3.4e-9; over the
//! stress box it agrees with `reduced` at 1e-14 (`tests/solvers/stress.rs`).
//! Order and tolerance were chosen by instruction counts (callgrind) at
//! that accuracy: order 16 beat 12, 14, 18, 20 and 24.
//! No allocation: coefficient arrays live on the stack.

use crate::closed::{released_energy, undamped_return, CompressionEnd};
use kick_core::{roots, KickError, LawKind, Outcome, Scenario, Solver, SolverPath, StopReason};

/// Order of the Taylor steps.
pub const ORDER: usize = 16;
/// Default local error per segment: of x' relative to the size of x' and
/// x'' (Taylor steps), and in the scaled units at the onset (where x' ≈ 1).
/// Observables then come out within 1e-10 (module docs).
pub const DEFAULT_TOLERANCE: f64 = 3e-11;
/// Amplification of errors in the exit speed accepted at the set tolerance;
/// beyond it the compression is redone with the tolerance scaled down.
const AMPLIFICATION_ALLOWED: f64 = 10.0;
/// The tightest tolerance a refinement goes to (rounding sets the floor).
const TIGHTEST_TOLERANCE: f64 = 1e-15;
/// Highest total weight i + j(n+1) kept in the onset series.
const ONSET_WEIGHT: f64 = 12.0;
const ONSET_COLUMNS: usize = 13;
/// Rows of the onset series; for n < 1 the kept weight shrinks to below
/// ONSET_ROWS (n+1) so that no row is cut short.
const ONSET_ROWS: usize = 7;
/// Longest onset segment in scaled time (the compression takes ~1.5).
const ONSET_REACH_CAP: f64 = 1.0;
/// Bound on Taylor steps in one compression (typical: 3 to 10).
pub const MAX_STEPS: u32 = 2_000;
/// Points per Taylor step at which δ̇ and dF/dt are sampled for sign changes.
const SAMPLES: usize = 4;
/// Sample points of the onset segment, as fractions of its length.
const ONSET_SAMPLES: [f64; 6] = [1e-6, 1e-4, 1e-2, 0.1, 0.4, 1.0];

/// The scaled compression problem.
#[derive(Debug, Clone, Copy)]
struct Scaled {
    exponent: f64,
    a: f64,
    gamma: f64,
    phi: f64,
}

impl Scaled {
    /// (x, xⁿ, x') at τ with xⁿ from x itself. The series' own xⁿ is only as
    /// good as the motion needs it, which is little when a is small; a
    /// located force (and its rate: peaks are flat, so their time is only as
    /// good as df/dτ) needs it in full.
    fn located(&self, segment: &impl Segment, tau: f64) -> (f64, f64, f64) {
        let (x, _, v) = segment.state(tau);
        (x, x.max(0.0).powf(self.exponent), v)
    }
    fn located_force_rate(&self, segment: &impl Segment, tau: f64) -> f64 {
        let (x, p, v) = self.located(segment, tau);
        self.force_rate(x, p, v)
    }
    /// Force in units of μ V0²/L: f = a xⁿ + γ x'.
    #[inline]
    fn force(&self, power: f64, rate: f64) -> f64 {
        self.a * power + self.gamma * rate
    }
    /// df/dτ = n a xⁿ⁻¹ x' + γ x'' along the solution.
    #[inline]
    fn force_rate(&self, x: f64, power: f64, rate: f64) -> f64 {
        let stiffness = if x > 0.0 { self.exponent * self.a * power / x } else { 0.0 };
        stiffness * rate + self.gamma * (self.phi - self.a * power - self.gamma * rate)
    }
    /// E / (μ V0²) = ½ x'² + a xⁿ⁺¹/(n+1) − φ x.
    #[inline]
    fn energy(&self, x: f64, power: f64, rate: f64) -> f64 {
        0.5 * rate * rate + self.a * x * power / (self.exponent + 1.0) - self.phi * x
    }
}

/// The Frobenius expansion at first touch: x = τ Σ g_ij τ^i s^j and
/// xⁿ = τⁿ Σ p_ij τ^i s^j with s = τⁿ⁺¹, over i + j(n+1) ≤ ONSET_WEIGHT
/// (or less, see ONSET_ROWS).
struct Onset {
    g: [[f64; ONSET_COLUMNS]; ONSET_ROWS],
    /// e_ij g_ij: the coefficients of x'.
    rate: [[f64; ONSET_COLUMNS]; ONSET_ROWS],
    p: [[f64; ONSET_COLUMNS]; ONSET_ROWS],
    /// Last column index kept in row j.
    last: [usize; ONSET_ROWS],
    rows: usize,
    /// Highest weight kept.
    weight_limit: f64,
    exponent: f64,
}

impl Onset {
    /// Substituting the double series into x'' = −a xⁿ − γ x' + φ and
    /// matching τ^(i−1) s^j gives, with e = 1 + i + j(n+1),
    /// e (e − 1) g_ij = −a p_i,j−1 − γ (e − 1) g_i−1,j + φ [i = 1, j = 0],
    /// and G·D(P) = n P·D(G) with D = τ d/dτ (P = Gⁿ) gives
    /// w_ij p_ij = Σ_(a,b)≠0 (n w_ab − w_i−a,j−b) g_ab p_i−a,j−b, w = i + j(n+1).
    fn new(s: &Scaled) -> Onset {
        let n = s.exponent;
        let n1 = n + 1.0;
        let weight_limit = ONSET_WEIGHT.min(ONSET_ROWS as f64 * n1 * (1.0 - 1e-9));
        let mut onset = Onset {
            g: [[0.0; ONSET_COLUMNS]; ONSET_ROWS],
            rate: [[0.0; ONSET_COLUMNS]; ONSET_ROWS],
            p: [[0.0; ONSET_COLUMNS]; ONSET_ROWS],
            last: [0; ONSET_ROWS],
            rows: 0,
            weight_limit,
            exponent: n,
        };
        for j in 0..ONSET_ROWS {
            let room = weight_limit - j as f64 * n1;
            if room < 0.0 {
                break;
            }
            onset.rows = j + 1;
            onset.last[j] = (room.floor() as usize).min(ONSET_COLUMNS - 1);
        }
        // w_ab = a + b(n+1); since w_(i−a,j−b) = w_ij − w_ab, the sum's
        // factor is (n+1) w_ab − w_ij.
        let column: [f64; ONSET_COLUMNS] = std::array::from_fn(|i| i as f64);
        let Onset { g, rate, p, last, rows, .. } = &mut onset;
        g[0][0] = 1.0;
        rate[0][0] = 1.0;
        p[0][0] = 1.0;
        for j in 0..*rows {
            let row_weight = j as f64 * n1;
            for i in usize::from(j == 0)..last[j] + 1 {
                let w = column[i] + row_weight;
                let e = 1.0 + w;
                let mut rhs = if i == 1 && j == 0 { s.phi } else { 0.0 };
                if j >= 1 {
                    rhs -= s.a * p[j - 1][i];
                }
                if i >= 1 {
                    rhs -= s.gamma * w * g[j][i - 1];
                }
                g[j][i] = rhs / (e * w);
                rate[j][i] = rhs / w;
                let mut sum = 0.0;
                for b in 0..j + 1 {
                    let (gb, pb) = (&g[b], &p[j - b]);
                    let offset = b as f64 * n1 * n1 - w;
                    for a in usize::from(b == 0)..i + 1 {
                        sum += (n1 * column[a] + offset) * gb[a] * pb[i - a];
                    }
                }
                p[j][i] = sum / w;
            }
        }
        onset
    }

    /// (x, xⁿ, x') at τ > 0: one `powf` for s = τⁿ⁺¹.
    fn state(&self, tau: f64) -> (f64, f64, f64) {
        let s = tau.powf(self.exponent + 1.0);
        let (mut x, mut p, mut v) = (0.0, 0.0, 0.0);
        for j in (0..self.rows).rev() {
            let end = self.last[j] + 1;
            let (mut xr, mut pr, mut vr) = (0.0, 0.0, 0.0);
            for ((&g, &p), &r) in self.g[j][..end].iter().zip(&self.p[j][..end]).zip(&self.rate[j][..end]).rev() {
                xr = xr * tau + g;
                pr = pr * tau + p;
                vr = vr * tau + r;
            }
            x = x * s + xr;
            p = p * s + pr;
            v = v * s + vr;
        }
        // τⁿ = s/τ.
        (tau * x, s / tau * p, v)
    }

    /// How far the series holds `tolerance`: the terms of the top layer of
    /// weights, (weight_limit − n − 2, weight_limit], stand for the truncated
    /// rest (a layer that wide holds a non-zero term of every row even when
    /// γ = φ = 0 leaves only the powers of s).
    fn reach(&self, tolerance: f64) -> f64 {
        let n = self.exponent;
        let log_tolerance = tolerance.ln();
        let mut log_reach = ONSET_REACH_CAP.ln();
        for j in 0..self.rows {
            for i in 0..self.last[j] + 1 {
                let w = i as f64 + j as f64 * (n + 1.0);
                if w <= self.weight_limit - n - 2.0 || w == 0.0 {
                    continue;
                }
                // x' = Σ e g τ^w is the more sensitive of x and x'.
                let size = self.rate[j][i].abs().max(self.p[j][i].abs()) * self.rows as f64;
                if size > 0.0 {
                    log_reach = log_reach.min((log_tolerance - size.ln()) / w);
                }
            }
        }
        log_reach.exp()
    }
}

/// Work arrays of Miller's recurrence, kept across steps: x_j and
/// (n+1) j x_j for j = 1..=ORDER, and p stored backwards with zeros for
/// negative orders, backwards[ORDER − i] = p_i. The sums over j = 1..=m are
/// then dot products over forward slices, padded to a multiple of four with
/// terms that meet those zeros (so whatever an earlier step left past m
/// does not count).
struct Recurrence {
    rates: [f64; ORDER + 4],
    weighted: [f64; ORDER + 4],
    backwards: [f64; 2 * ORDER + 4],
}

impl Recurrence {
    fn new() -> Recurrence {
        Recurrence { rates: [0.0; ORDER + 4], weighted: [0.0; ORDER + 4], backwards: [0.0; 2 * ORDER + 4] }
    }
}

/// Taylor coefficients of x (and of xⁿ) about a point with x > 0.
struct TaylorStep {
    x: [f64; ORDER + 1],
    /// xⁿ, to the order x needs (ORDER − 2; the rest zero).
    p: [f64; ORDER + 1],
}

/// (Σ a_k c_k, Σ b_k c_k) over the first `4 * chunks` terms, with four
/// independent partial sums each (so the loop vectorises).
#[inline(always)]
fn dot2(a: &[f64], b: &[f64], c: &[f64], chunks: usize) -> (f64, f64) {
    let (a, b, c) = (&a[..4 * chunks], &b[..4 * chunks], &c[..4 * chunks]);
    let (mut sa, mut sb) = ([0.0; 4], [0.0; 4]);
    for ((ca, cb), cc) in a.chunks_exact(4).zip(b.chunks_exact(4)).zip(c.chunks_exact(4)) {
        for lane in 0..4 {
            sa[lane] += ca[lane] * cc[lane];
            sb[lane] += cb[lane] * cc[lane];
        }
    }
    ((sa[0] + sa[1]) + (sa[2] + sa[3]), (sb[0] + sb[1]) + (sb[2] + sb[3]))
}

impl TaylorStep {
    /// Miller's recurrence for p = xⁿ: x p' = n x' p, so
    /// m x_0 p_m = Σ_(j=1..m) ((n + 1) j − m) x_j p_(m−j);
    /// then x_(m+2) = (−a p_m − γ (m+1) x_(m+1) + φ [m = 0]) / ((m+1)(m+2)).
    fn new(s: &Scaled, x0: f64, v0: f64, work: &mut Recurrence) -> TaylorStep {
        let n1 = s.exponent + 1.0;
        let mut x = [0.0; ORDER + 1];
        let mut p = [0.0; ORDER + 1];
        let Recurrence { rates, weighted, backwards } = work;
        x[0] = x0;
        x[1] = v0;
        rates[0] = v0;
        weighted[0] = n1 * v0;
        p[0] = x0.powf(s.exponent);
        backwards[ORDER] = p[0];
        let inverse_x0 = 1.0 / x0;
        // p as far as x needs it: the step's own error is in x_(ORDER).
        for m in 0..ORDER - 1 {
            if m >= 1 {
                let mf = m as f64;
                let window = &backwards[ORDER + 1 - m..];
                let (weighted_sum, rate_sum) = dot2(&weighted[..], &rates[..], window, m.div_ceil(4));
                p[m] = (weighted_sum - mf * rate_sum) * inverse_x0 / mf;
                backwards[ORDER - m] = p[m];
            }
            let m1 = (m + 1) as f64;
            let drive = if m == 0 { s.phi } else { 0.0 };
            x[m + 2] = (drive - s.a * p[m] - s.gamma * m1 * x[m + 1]) / (m1 * (m1 + 1.0));
            rates[m + 1] = x[m + 2];
            weighted[m + 1] = n1 * (m + 2) as f64 * x[m + 2];
        }
        TaylorStep { x, p }
    }

    /// Step that keeps the last terms of x' below `tolerance` times the size
    /// of x' and x'' here (Jorba–Zou style). Relative to x' and x'', not to 1:
    /// in an over-damped creep both are tiny, and the time of δ̇ = 0 is only
    /// as good as x' relative to them.
    fn step(&self, tolerance: f64) -> f64 {
        let log_allowed = (tolerance * self.x[1].abs().max(2.0 * self.x[2].abs())).ln();
        let mut log_h = f64::INFINITY;
        for m in [ORDER - 1, ORDER] {
            let term = m as f64 * self.x[m].abs();
            if term > 0.0 {
                log_h = log_h.min((log_allowed - term.ln()) / (m - 1) as f64);
            }
        }
        0.9 * log_h.exp()
    }

    /// (x, xⁿ, x') at h.
    #[inline]
    fn state(&self, h: f64) -> (f64, f64, f64) {
        let (mut x, mut p, mut v) = (self.x[ORDER], 0.0, ORDER as f64 * self.x[ORDER]);
        for m in (1..ORDER).rev() {
            x = x * h + self.x[m];
            v = v * h + m as f64 * self.x[m];
        }
        x = x * h + self.x[0];
        for m in (0..ORDER - 1).rev() {
            p = p * h + self.p[m];
        }
        (x, p, v)
    }
}

/// A running maximum of the force with its time.
#[derive(Debug, Clone, Copy)]
struct Peak {
    force: f64,
    time: f64,
}

impl Peak {
    fn offer(&mut self, force: f64, time: f64) {
        if force > self.force {
            *self = Peak { force, time };
        }
    }
}

/// End of compression in scaled units.
#[derive(Debug, Clone, Copy)]
struct ScaledCompression {
    tau_max: f64,
    x_max: f64,
    /// D/(μ V0²) = γ ∫ x'² dτ, integrated only under a drive (NaN without).
    dissipated: f64,
    peak: Peak,
    powers: u64,
}

/// One analytic piece of the compression, in absolute scaled time.
trait Segment {
    /// (x, xⁿ, x') at τ.
    fn state(&self, tau: f64) -> (f64, f64, f64);
    /// x' at τ.
    fn rate(&self, tau: f64) -> f64;
    /// (x', df/dτ) at the sample points.
    fn samples<const N: usize>(&self, taus: &[f64; N]) -> [(f64, f64); N];
}

struct OnsetSegment<'a> {
    onset: &'a Onset,
    scaled: &'a Scaled,
    powers: std::cell::Cell<u64>,
}

impl Segment for OnsetSegment<'_> {
    fn state(&self, tau: f64) -> (f64, f64, f64) {
        self.powers.set(self.powers.get() + 1);
        self.onset.state(tau)
    }
    fn rate(&self, tau: f64) -> f64 {
        self.state(tau).2
    }
    fn samples<const N: usize>(&self, taus: &[f64; N]) -> [(f64, f64); N] {
        taus.map(|tau| {
            let (x, p, v) = self.state(tau);
            (v, self.scaled.force_rate(x, p, v))
        })
    }
}

/// A Taylor step as polynomials in h = τ − τ0: x, xⁿ, x' and df/dτ.
struct TaylorSegment {
    start: f64,
    step: TaylorStep,
    /// x' = Σ rate_m h^m.
    rate: [f64; ORDER],
    /// df/dτ = a (xⁿ)' + γ x'' = Σ force_rate_m h^m, to spot its sign changes.
    force_rate: [f64; ORDER],
}

impl TaylorSegment {
    fn new(s: &Scaled, start: f64, step: TaylorStep) -> TaylorSegment {
        let mut rate = [0.0; ORDER];
        let mut force_rate = [0.0; ORDER];
        for m in 0..ORDER {
            let m1 = (m + 1) as f64;
            rate[m] = m1 * step.x[m + 1];
            let second = if m + 2 <= ORDER { m1 * (m1 + 1.0) * step.x[m + 2] } else { 0.0 };
            force_rate[m] = s.a * m1 * step.p[m + 1] + s.gamma * second;
        }
        TaylorSegment { start, step, rate, force_rate }
    }
}

#[inline(always)]
fn horner(c: &[f64; ORDER], h: f64) -> f64 {
    c.iter().rev().fold(0.0, |acc, &c| acc * h + c)
}

impl TaylorSegment {
    /// ∫ x'² dτ over [start, start + h], from the product series of x'
    /// truncated at the order the step keeps.
    fn rate_square_integral(&self, h: f64) -> f64 {
        let r = &self.rate;
        let mut integral = 0.0;
        for m in (0..ORDER).rev() {
            // (x'²)_m = Σ_(i+j=m) r_i r_j, each pair once and doubled.
            let half = m.div_ceil(2);
            let pairs: f64 = r[..half].iter().zip(r[m + 1 - half..m + 1].iter().rev()).map(|(a, b)| a * b).sum();
            let middle = if m % 2 == 0 { r[m / 2] * r[m / 2] } else { 0.0 };
            integral = (integral + (2.0 * pairs + middle) / (m + 1) as f64) * h;
        }
        integral
    }
}

impl Segment for TaylorSegment {
    fn state(&self, tau: f64) -> (f64, f64, f64) {
        self.step.state(tau - self.start)
    }
    fn rate(&self, tau: f64) -> f64 {
        horner(&self.rate, tau - self.start)
    }
    fn samples<const N: usize>(&self, taus: &[f64; N]) -> [(f64, f64); N] {
        // The points in lockstep: independent Horner chains.
        let h = taus.map(|t| t - self.start);
        let (mut v, mut f) = ([0.0; N], [0.0; N]);
        for m in (0..ORDER).rev() {
            for k in 0..N {
                v[k] = v[k] * h[k] + self.rate[m];
                f[k] = f[k] * h[k] + self.force_rate[m];
            }
        }
        std::array::from_fn(|k| (v[k], f[k]))
    }
}

/// Watch the segment from τa through the increasing sample points `taus`:
/// return the first δ̇ = 0 and offer every interior force maximum
/// (dF/dt: + → −) to `peak`, from sign changes between the points.
/// `start` is (x', df/dτ) at τa.
fn watch<const N: usize>(
    segment: &impl Segment,
    s: &Scaled,
    tau_a: f64,
    taus: &[f64; N],
    start: (f64, f64),
    peak: &mut Peak,
) -> Option<f64> {
    let tolerance = 4.0 * f64::EPSILON * taus[N - 1].abs();
    let values = segment.samples(taus);
    let (mut tau_prev, mut prev) = (tau_a, start);
    for (&tau, &here) in taus.iter().zip(&values) {
        // The first turnaround in this sample interval ends the phase.
        let turn = if prev.0 > 0.0 && here.0 <= 0.0 {
            roots::brent(|t| segment.rate(t), tau_prev, tau, tolerance, 200).map(|r| r.x)
        } else {
            None
        };
        let (end, end_force_rate) = match turn {
            Some(t) => (t, s.located_force_rate(segment, t)),
            None => (tau, here.1),
        };
        if prev.1 > 0.0 && end_force_rate <= 0.0 {
            if let Some(r) = roots::brent(|t| s.located_force_rate(segment, t), tau_prev, end, tolerance, 200) {
                let (_, p, v) = s.located(segment, r.x);
                peak.offer(s.force(p, v), r.x);
            }
        }
        if turn.is_some() {
            return turn;
        }
        (tau_prev, prev) = (tau, here);
    }
    None
}

/// The end of compression at a located turnaround τ.
fn turnaround(segment: &impl Segment, s: &Scaled, tau_max: f64, mut peak: Peak, dissipated: f64, powers: u64) -> ScaledCompression {
    let (x, p, _) = s.located(segment, tau_max);
    peak.offer(s.a * p, tau_max);
    ScaledCompression { tau_max, x_max: x, dissipated, peak, powers }
}

/// Integrate the compression to δ̇ = 0. `Err` carries the scaled time at
/// which the ball was found trapped (E < 0 under a drive).
fn compress(s: &Scaled, tolerance: f64) -> Result<Result<ScaledCompression, f64>, KickError> {
    // Onset value of the force: F(0⁺) = c V0, i.e. f = γ.
    let mut peak = Peak { force: s.gamma, time: 0.0 };
    let onset = Onset::new(s);
    let reach = onset.reach(tolerance);
    let segment = OnsetSegment { onset: &onset, scaled: s, powers: std::cell::Cell::new(0) };
    // Watching starts a hair after touch, where x' and dF/dt are finite
    // for every n; F(0⁺) itself is the onset value above. Near τ = 0,
    // dF/dτ carries n a xⁿ⁻¹ x', which for n near 1 changes over decades of
    // τ: the samples are spaced geometrically, then evenly.
    let first = reach * 1e-9;
    let (x, p, v) = segment.state(first);
    let taus = ONSET_SAMPLES.map(|fraction| fraction * reach);
    // Under a drive the exit speed comes from ½ μ V0² − D (see `compression`),
    // so D is integrated: over the onset from the energy balance (every term
    // is O(1) there), then step by step from x'².
    let driven = s.phi != 0.0;
    let onset_dissipation = |tau: f64| {
        let (x, p, v) = segment.state(tau);
        0.5 - s.energy(x, p, v)
    };
    if let Some(tau_max) = watch(&segment, s, first, &taus, (v, s.force_rate(x, p, v)), &mut peak) {
        let dissipated = if driven { onset_dissipation(tau_max) } else { f64::NAN };
        return Ok(Ok(turnaround(&segment, s, tau_max, peak, dissipated, segment.powers.get())));
    }
    let mut dissipated = if driven { onset_dissipation(reach) } else { f64::NAN };
    let (mut x, _, mut v) = segment.state(reach);
    let mut powers = segment.powers.get();
    let mut tau = reach;
    let mut work = Recurrence::new();
    for _ in 0..MAX_STEPS {
        let step = TaylorStep::new(s, x, v, &mut work);
        powers += 1;
        // xⁿ at the step's start comes with the step.
        // Short of release by more than the rounding of its terms (the
        // proof's margin, `events::TRAP_MARGIN`).
        let potential = s.a * x * step.p[0] / (s.exponent + 1.0);
        if s.phi > 0.0 && crate::events::proves_trapped(-s.energy(x, step.p[0], v), potential.max(s.phi * x)) {
            return Ok(Err(tau));
        }
        let h = step.step(tolerance);
        let radius = branch_radius_share(s.exponent) * tau;
        let h = h.min(radius);
        if !(h.is_finite() && h > 0.0) {
            return Err(KickError::Integration {
                time: tau,
                reason: format!("series step {} at scaled time {}", kick_core::short(h), kick_core::short(tau)),
            });
        }
        let segment = TaylorSegment::new(s, tau, step);
        let start = (v, segment.force_rate[0]);
        let taus: [f64; SAMPLES] = std::array::from_fn(|k| tau + h * (k + 1) as f64 / SAMPLES as f64);
        if let Some(tau_max) = watch(&segment, s, tau, &taus, start, &mut peak) {
            if driven {
                dissipated += s.gamma * segment.rate_square_integral(tau_max - tau);
            }
            return Ok(Ok(turnaround(&segment, s, tau_max, peak, dissipated, powers)));
        }
        if driven {
            dissipated += s.gamma * segment.rate_square_integral(h);
        }
        (x, _, v) = segment.step.state(h);
        tau += h;
    }
    Err(KickError::Integration { time: tau, reason: format!("compression not over after {MAX_STEPS} series steps") })
}

/// A Taylor step's longest reach as a share of its distance τ from first
/// touch, the branch point of xⁿ (x = 0 there). The step's error estimate
/// reads the last kept terms, which tell the branch point only once the
/// terms fall by then: xⁿ's terms about x > 0 grow with ratio
/// (n − m)/(m + 1) · h/τ, so past n ≈ ORDER they were still growing at the
/// order kept, the estimate saw nearly free flight, and the step leapt past
/// the compression (n = 18 gave 1.8e10 m/s). Within this share they fall by
/// at least 2 at the last order.
fn branch_radius_share(exponent: f64) -> f64 {
    let order = ORDER as f64;
    if exponent > order {
        (0.5 * (order + 1.0) / (exponent - order)).min(1.0)
    } else {
        1.0
    }
}

/// The `series` solver: the paper's law with any drive.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Series {
    /// Local error per segment in scaled units.
    pub tolerance: f64,
}

impl Default for Series {
    fn default() -> Self {
        Series { tolerance: DEFAULT_TOLERANCE }
    }
}

impl Series {
    pub fn with_tolerance(tolerance: f64) -> Result<Series, KickError> {
        if !(tolerance.is_finite() && tolerance > 0.0 && tolerance < 1.0) {
            return Err(KickError::InvalidParameter { name: "tolerance", value: tolerance, requirement: "in (0, 1)" });
        }
        Ok(Series { tolerance })
    }

    /// The paper's law, or the shell ball with a drive ≥ 0
    /// ([`crate::shell_series`]).
    pub fn applies(scenario: &Scenario) -> bool {
        match scenario.boot() {
            Some(_) => crate::boot::series::applies(scenario),
            None => scenario.law_kind() == LawKind::PowerLaw || crate::shell_series::applies(scenario),
        }
    }

    /// Maximum compression, its time, the force peak and the dissipated
    /// energy of the compression phase, in SI units.
    pub fn compression(&self, scenario: &Scenario) -> Result<(CompressionEnd, u64), KickError> {
        let law = scenario.paper_law();
        let mu = scenario.reduced_mass();
        let v0 = scenario.approach_speed();
        let drive_share = mu / scenario.effective_foot_mass() * scenario.drive_force();
        let elastic_length = scenario.elastic_max_compression();
        let mut length = elastic_length;
        if law.damping > 0.0 {
            length = length.min(mu * v0 / law.damping);
        }
        if drive_share != 0.0 {
            length = length.min(mu * v0 * v0 / drive_share.abs());
        }
        let time = length / v0;
        let force_unit = mu * v0 * v0 / length;
        let n = law.exponent;
        let scaled = Scaled {
            exponent: n,
            // k L^(n+1)/(μ V0²) = (n+1)/2 (L/δ*)^(n+1), from U(δ*) = ½ μ V0².
            a: 0.5 * (n + 1.0) * (length / elastic_length).powf(n + 1.0),
            gamma: law.damping * length / (mu * v0),
            phi: drive_share * length / (mu * v0 * v0),
        };
        // compress works in scaled time; errors leave in seconds.
        let in_seconds = |e: KickError| match e {
            KickError::Integration { time: tau, reason } => KickError::Integration { time: tau * time, reason },
            e => e,
        };
        let compression =
            match compress(&scaled, self.tolerance).map_err(in_seconds)? {
                Ok(c) => c,
                Err(tau) => return Err(KickError::Trapped {
                    time: tau * time,
                    reason:
                        "the ball never leaves the foot, no separation: while compressing, ½μδ̇² + U(δ) − (μ/m_f)F_drive δ fell below zero, \
                             so the ball cannot get back to δ = 0 (the drive keeps it pressed)"
                            .into(),
                }),
            };
        let max_compression = compression.x_max * length;
        let stored = kick_core::ContactLaw::potential(&law, max_compression);
        let end = CompressionEnd {
            max_compression,
            max_compression_time: compression.tau_max * time,
            // Integrated under a drive; without one the energy balance of the
            // relative motion over compression is as good (no f_s δ to cancel).
            dissipated: if drive_share != 0.0 {
                compression.dissipated * mu * v0 * v0
            } else {
                scenario.relative_kinetic_energy() - stored
            },
            peak_force: compression.peak.force * force_unit,
            peak_force_time: compression.peak.time * time,
        };
        Ok((end, compression.powers))
    }
}

impl Solver for Series {
    fn name(&self) -> &'static str {
        "series"
    }
    fn solve(&self, scenario: &Scenario) -> Result<Outcome, KickError> {
        if let Some(boot) = scenario.boot() {
            return match scenario.contact_law() {
                kick_core::AnyLaw::Shell(ball) if crate::boot::series::applies(scenario) => {
                    crate::boot::series::solve(scenario, ball, boot, self.tolerance)
                }
                _ => Err(KickError::NotApplicable {
                    solver: "series",
                    reason: "with a boot in series its Taylor steps are written for the shell ball under a drive >= 0",
                }),
            };
        }
        if let kick_core::AnyLaw::Shell(ball) = scenario.contact_law() {
            if crate::shell_series::applies(scenario) {
                return crate::shell_series::solve(scenario, ball, self.tolerance);
            }
        }
        if !Self::applies(scenario) {
            return Err(KickError::NotApplicable {
                solver: "series",
                reason: "its power series are written for the paper's law (Eq. 20) and the shell ball under a drive >= 0",
            });
        }
        let (mut end, mut powers) = self.compression(scenario)?;
        // Near a trapping drive the exit speed is a small difference of
        // larger energies (`released_energy`): tighten the tolerance by the
        // amplification so that w keeps the accuracy of the other observables.
        let (_, amplification) = released_energy(scenario, &end);
        let tightened = (self.tolerance * AMPLIFICATION_ALLOWED / amplification).max(TIGHTEST_TOLERANCE);
        if amplification > AMPLIFICATION_ALLOWED && tightened < self.tolerance {
            let (refined, more) = Series { tolerance: tightened }.compression(scenario)?;
            (end, powers) = (refined, powers + more);
        }
        let mut outcome = undamped_return(scenario, end)?;
        outcome.evaluations = powers;
        outcome.method = SolverPath::Series;
        outcome.stop = StopReason::Separated { t: outcome.contact_time };
        Ok(outcome)
    }
}
