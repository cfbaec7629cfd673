//! A convex instep with its own orientation, and the contact as a patch
//! (issue 22, items 3 and 4). Both are options; without them the 3D kick is
//! the knife-edge face and the point contact of [`crate::contact`], bit for bit.
//!
//! **The instep** (`face_yaw` ψ, `face_pitch` θ, `instep_radius` r_i): the
//! foot's contact surface is a flat face (r_i = 0) or a sphere cap of radius
//! r_i whose pole sits where the box's face centre was (h_x from the foot's
//! centre of mass along the face normal), the face normal at the pole being
//! n_f = (cos θ cos ψ, −cos θ sin ψ, sin θ). The pole moves on the foot's
//! line of motion, P + s û (P = e ŷ − h v̂, [`crate::model`]: the offset e
//! and contact depth h are the ball centre's distances from it, as for the
//! knife edge), and first touch is where the surface meets the ball (closed
//! form: a plane, or two spheres). Left out, ψ and θ are the knife edge's
//! (its normal's yaw and pitch), so a flat face with the default angles
//! touches the ball at the pole, where the line meets it: the knife edge's
//! face, with the foot's box kept level instead of rolled about the line
//! (the same kick on a horizontal path with h = 0: the test
//! `the_knife_edge_is_one_configuration`). A cap's
//! contact with the ball is a sphere–sphere contact: normal along the line of
//! centres, δ = R + r_i − |r − c_i|, smooth everywhere (no face/border switch).
//!
//! Instep curvature: no published measurement of the instep's (or a
//! boot's vamp's) radius of curvature at the kicking zone was found (searched:
//! shoe-last and dorsum curvature, kick pressure maps). So r_i stays a
//! parameter with default 0 (the flat face, today's kick); a value of the order
//! of the ball's radius is an assumption a study must state.
//!
//! **The patch** (`patch_contact`, law `shell`). Candidates: hydroelastic
//! contact (Elandt et al. 2019, Drake) — a pressure field ∝ local
//! penetration, integrated over the contact surface; volumetric contact
//! (Gonthier, McPhee et al.) — force ∝ interpenetration volume, with its
//! moment from the volume's centroid and inertia; Cross's offset normal force
//! (I ω̇ = F R + N D, a shift D of the normal force's line). Chosen:
//! hydroelastic-shaped, but with no new fitted constant. The shell law is
//! affine in the rate, F = E(δ) + D(δ) δ̇ before its clamp: E = F_el(δ), the
//! elastic force, and D = ∂F/∂δ̇ = β A(δ), the slope: the ball's own law,
//! calibrated on ball-only tests. Both are spread over the patch (the part
//! of the foot's surface inside the undeformed ball) with weights ∝ the
//! local depth h (hydroelastic's linear pressure field; only its shape is
//! used, its total is the law's), and each element applies the slope to its
//! own rate: f_i = w_i (E(δ) + D(δ) ḣ_i), Σ w_i (ν_i · n) = 1, acting along
//! the foot's normal ν_i at the element (`elastic` and `slope` of
//! [`Patch::resultant`]). ḣ_i is the ball material's approach to the foot
//! at the element, −ν_i · (ṙ + Ω × q_i) (Ω the ball's angular velocity less
//! the foot's): the relative normal velocity Hunt–Crossley and hydroelastic
//! contact damp (Elandt et al. 2019). With it the loss is passive: the
//! power it takes is D(δ) Σ w_i ḣ_i² ≥ 0. (Until this change ḣ_i was the
//! rate of the overlap's depth at a point fixed on the foot; that made
//! sliding over a plane load its leading edge, turned the ball against
//! friction's sense at μ = 0, and its power was no sum of squares.)
//! What follows: sliding over a flat face compresses nothing unevenly
//! (the moment is the rolling resistance −slope M₂ Ω_⊥ of a ball turning on
//! it); sliding over a convex instep does — the cap's surface rises under
//! the trailing side of the patch, whose material is pressed faster — so
//! the resultant's line passes behind the ball's centre and the ball spins
//! without friction, in the sense friction turns it: the wrap Asai et al.
//! (2002) found in their finite-element kicks, here from the shell law's
//! calibrated loss and the instep's curvature, with no constant of its own.
//! Volumetric contact would need a volume stiffness, and Cross's offset D a
//! fitted length. Friction acts at the patch's centroid (lever R − δ on a
//! flat face, not R). Rigid grip holds the material points at the centroid
//! together; since the centroid moves with δ (and on a cap with the normal),
//! its motion is in the constraint ([`Patch::resultant_and_centroid_rate`],
//! `Relative::patch_grip_force` in [`crate::contact`]).
//!
//! Integration over the patch: on a flat face in closed form (depth and
//! rate are functions of ρ alone, the moment's integral is a polynomial in
//! δ); on a cap exact in the angle and 6-node Gauss–Legendre across the
//! rings in the ball's half chord, where the integrands are nearly
//! polynomial ([`Quadrature`]).
//! Both are smooth in the state, so the right-hand side is smooth within a
//! phase and the accurate path's events and 1e-9 hold (a test tightens it to
//! 1e-15). A central square kick on a flat face gives ḣ = δ̇ everywhere and
//! F = E(δ) + D(δ) δ̇: the 1D law exactly. A unit test sums the elements
//! of a 64 × 64 polar grid with the depth's rate by finite differences and
//! finds the closed form and the rings.
//!
//! Energy: the elastic resultant is E(δ) n (the quadrature is symmetric),
//! so the law's potential U(δ) holds; the loss integral is the exact balance
//! −(power of the element forces on the relative motion) − E δ̇.

pub use crate::model::instep::{first_touch, instep, Quadrature, Touch};
use parry3d_f64::math::Vec3;

/// Most Gauss–Legendre rings of a [`Quadrature`].
pub const MAX_RINGS: usize = 64;

/// The instep's surface in the foot's body frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Surface {
    /// The plane x = h_x: n = e_x.
    Flat,
    /// A sphere of `radius` about `centre`.
    Sphere { centre: Vec3, radius: f64 },
}

/// The nodes of a [`Quadrature`], fixed arrays (no allocation per evaluation).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Patch {
    rings: usize,
    /// u_i in (0, 1): the ring's height on the cap's axis, z = x_f + (r_f − x_f) u.
    node: [f64; MAX_RINGS],
    /// 1 − u_i (r_f − z without cancellation).
    rest: [f64; MAX_RINGS],
    /// g_i: ρ dρ = −z dz, so ∫ f ρ dρ ∝ Σ g_i z_i f(z_i).
    weight: [f64; MAX_RINGS],
}

/// Gauss–Legendre nodes and weights on (0, 1) (kick-core's rule).
fn gauss_legendre(n: usize) -> ([f64; MAX_RINGS], [f64; MAX_RINGS]) {
    let (mut x, mut w) = ([0.0; MAX_RINGS], [0.0; MAX_RINGS]);
    for i in 0..n {
        (x[i], w[i]) = kick_core::special::gauss_legendre_node(n, i);
    }
    (x, w)
}

impl Patch {
    /// `q.rings` clamped to 1..=MAX_RINGS; the default rule is computed once
    /// per process (its Newton iterations cost a few kicks' right-hand sides).
    pub fn new(q: Quadrature) -> Patch {
        static DEFAULT: std::sync::OnceLock<Patch> = std::sync::OnceLock::new();
        if q == Quadrature::default() {
            return *DEFAULT.get_or_init(|| Patch::compute(q));
        }
        Patch::compute(q)
    }

    fn compute(q: Quadrature) -> Patch {
        let rings = q.rings.clamp(1, MAX_RINGS);
        let (u, g) = gauss_legendre(rings);
        // The rule is symmetric: 1 − u_i is the node u_(n−1−i), accurate where u_i → 1.
        let mut rest = [0.0; MAX_RINGS];
        for i in 0..rings {
            rest[i] = u[rings - 1 - i];
        }
        Patch { rings, node: u, rest, weight: g }
    }

    /// The normal force over the patch (body frame): its resultant on the
    /// ball, its moment about the ball's centre and the patch's centroid.
    /// `r` and `r_dot` are the ball centre and its rate in the foot's frame,
    /// `turn` the ball's angular velocity less the foot's (Ω, foot frame),
    /// `delta` and `n` the compression and normal of the rigid geometry, and
    /// the law's unclamped force is `elastic + slope · rate` (affine in the rate).
    ///
    /// Element at radius ρ = a s, angle θ of the disc normal to n: the foot's
    /// surface point x, its normal ν, q = x − r; depth along ν to the
    /// undeformed ball h = (R² − |q|²)/(S − ν·q), S = √((ν·q)² + R² − |q|²)
    /// (no cancellation at small δ); its rate is the ball material's approach
    /// to the foot there, ḣ = −ν·(ṙ + Ω × q). On a cap (ν = (z n + ρ⃗)/r_f,
    /// q × ν = (d/r_f) ρ⃗ × n) that is ḣ = −(z/r_f) ṙ_n − ρ⃗·V/r_f with
    /// V = ṙ_t + d (n × Ω): the ball's velocity field at the cap's centre.
    #[allow(clippy::too_many_arguments)]
    #[inline]
    pub fn resultant(
        &self,
        surface: Surface,
        ball_radius: f64,
        r: Vec3,
        r_dot: Vec3,
        turn: Vec3,
        delta: f64,
        n: Vec3,
        elastic: f64,
        slope: f64,
    ) -> PatchForce {
        self.resultant_on::<false, false>(surface, ball_radius, r, r_dot, turn, delta, n, elastic, slope).0
    }

    /// [`Patch::resultant`] and, on a cap, the centroid height's rate dζ/dδ
    /// (rigid grip's held point moves with δ; 0 on the flat face, where the
    /// centroid's motion is δ̇ n), from the same rings: the derivative of
    /// the integrals at a fixed angle on the cap, where only the depth
    /// moves with δ (the rim adds nothing: the depth is zero there), summed
    /// against y − ȳ with y = z − x_f = (S − S₀)(S + S₀)/(κ²(z + x_f)) taken
    /// from the rim, so it stays accurate as δ → 0 (y and its mean are of
    /// the patch's size, not r_f's). The rule's error in it: 6 rings
    /// against 40, ≤ 9e-14 up to δ = 3 cm, 2.3e-11 at 5 cm. A unit test holds
    /// it to a five-point difference of the centroid.
    #[allow(clippy::too_many_arguments)]
    #[inline]
    pub fn resultant_and_centroid_rate(
        &self,
        surface: Surface,
        ball_radius: f64,
        r: Vec3,
        r_dot: Vec3,
        turn: Vec3,
        delta: f64,
        n: Vec3,
        elastic: f64,
        slope: f64,
    ) -> (PatchForce, f64) {
        let (p, zeta_rate, _) = self.resultant_on::<true, false>(surface, ball_radius, r, r_dot, turn, delta, n, elastic, slope);
        (p, zeta_rate)
    }

    /// [`Patch::resultant`] and the ratio ρ of the normal force's loss to
    /// the 1D law's, with its rate dρ/dδ, from the same rings: the normal
    /// component is F_el + slope δ̇ ρ(δ), ρ = Σ g z² / (r_f Σ g z) on a cap (a
    /// function of δ alone), 1 on the flat face (what a slipping contact's
    /// cap μ F_n needs for its rate). dρ/dδ as [`Patch::resultant_and_centroid_rate`]
    /// differentiates: the rule's sums of t = ∂g/∂δ at a fixed angle, in
    /// y = z − x_f from the rim (no cancellation at a small patch):
    /// r_f (Σ g z)² dρ/dδ = x_f² (T₁G₀ − T₀G₁) + x_f (T₂G₀ − T₀G₂) + T₂G₁ − T₁G₂,
    /// G_k = Σ g y^k, T_k = Σ t y^k. A unit test holds it to a difference of ρ.
    #[allow(clippy::too_many_arguments)]
    #[inline]
    pub fn resultant_and_normal_ratio(
        &self,
        surface: Surface,
        ball_radius: f64,
        r: Vec3,
        r_dot: Vec3,
        turn: Vec3,
        delta: f64,
        n: Vec3,
        elastic: f64,
        slope: f64,
    ) -> (PatchForce, (f64, f64)) {
        let (p, _, ratio) = self.resultant_on::<false, true>(surface, ball_radius, r, r_dot, turn, delta, n, elastic, slope);
        (p, ratio)
    }

    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn resultant_on<const RATE: bool, const NORMAL: bool>(
        &self,
        surface: Surface,
        ball_radius: f64,
        r: Vec3,
        r_dot: Vec3,
        turn: Vec3,
        delta: f64,
        n: Vec3,
        elastic: f64,
        slope: f64,
    ) -> (PatchForce, f64, (f64, f64)) {
        let big_r = ball_radius;
        let r_n = n.dot(r_dot);
        let point = PatchForce { force: n * (elastic - slope * r_n), moment: Vec3::ZERO, centroid: r - n * big_r, rate_weight: 1.0 };
        if !(delta > 0.0) {
            return (point, 0.0, (1.0, 0.0));
        }
        let r_t = r_dot - n * r_n;
        let Surface::Sphere { centre, radius: rf } = surface else {
            return (flat(big_r, r, r_n, turn, delta, n, elastic, slope), 0.0, (1.0, 0.0));
        };
        let mut zeta_rate = 0.0;
        let mut normal_ratio = (1.0, 0.0);
        let flat_a2 = delta * (2.0 * big_r - delta);
        // Sums over the rings, each already summed over θ (per N spokes).
        let (mut sum_g, mut sum_gz) = (0.0, 0.0);
        let d = big_r + rf - delta;
        let inv_rf = 1.0 / rf;
        let (total, along, across, rated) = {
            let kappa = d * inv_rf;
            // The rings are spaced in S = √((ν·q)² + R² − |q|²), the half
            // chord of the ball along ν: S² = κ² z² − B² (ν runs through
            // the cap's centre), S from S₀ at the rim to R at the pole.
            // In S the integrands' nearest singularities are S = ±iB, far
            // from the patch, where in z or ρ² they sit at κz = B, about
            // the patch's own height away.
            let b2 = (rf - delta) * (d + big_r); // d² − R²
                                                 // R − S₀ = δ + κ (r_f − x_f) = δ + a²/(2 r_f), a² = δ(2R − δ):
                                                 // d cancels, so the rings start without waiting for a division.
            let span = delta + flat_a2 * (0.5 * inv_rf);
            let s0 = big_r - span;
            // κ x_f = r_f + S₀ (S₀² + B² = κ² x_f²): each ring's κ (z + x_f) from its own root.
            let rim = rf + s0;
            let inv_kappa = 1.0 / kappa;
            let n = self.rings;
            let (mut sum_gzz, mut spread) = (0.0, 0.0);
            // Rigid grip's dζ/dδ from the same rings, without
            // differentiating the rule: at a fixed angle θ on the cap
            // (z = r_f cos θ, ρ = r_f sin θ) the depth is
            // h = r_f − d cos θ + S, S = √(R² − d² sin² θ), so
            // ∂h/∂d = −z/r_f − d ρ²/(r_f² S), while the element's area
            // does not move with d; h vanishes at the rim, so the moving
            // rim adds nothing. With ζ = Σ g z / Σ g and dδ = −dd:
            // dζ/dδ = Σ t (y − ȳ) / Σ g, t = w S (z/r_f + d ρ²/(r_f² S)),
            // y = z − x_f taken from the rim (no cancellation against
            // ζ ≈ r_f at a small patch). No division per ring.
            let (mut sum_t, mut sum_ty, mut sum_gy) = (0.0, 0.0, 0.0);
            // For dρ/dδ also Σ g y² and Σ t y².
            let (mut sum_gyy, mut sum_tyy) = (0.0, 0.0);
            // ρ² = r_f² − z² = (R − S)(R + S)/κ², R − S = span (1 − u) from the rule's other end.
            let rho_scale = span * inv_kappa * inv_kappa;
            // Eight rings at a time into small arrays (not 64 slots cleared
            // per evaluation), then summed in order: no dependence between
            // rings, so their square roots and divisions go two at a time (packed).
            const CHUNK: usize = 8;
            for start in (0..n).step_by(CHUNK) {
                let m = (n - start).min(CHUNK);
                let (node, weight, rest) = (&self.node[start..start + m], &self.weight[start..start + m], &self.rest[start..start + m]);
                let (mut zs, mut gs, mut rhos, mut ys, mut ts) = ([0.0; CHUNK], [0.0; CHUNK], [0.0; CHUNK], [0.0; CHUNK], [0.0; CHUNK]);
                for j in 0..m {
                    let (v, w) = (node[j], weight[j]);
                    let s = s0 + span * v;
                    let root = (s * s + b2).sqrt(); // κ z
                                                    // h = r_f − κ z + S, written as (S − S₀)(1 − (S + S₀)/(κ (z + x_f))) (zero at the rim, no cancellation).
                    let ratio = (s + s0) / (root + rim);
                    let h = span * v * (1.0 - ratio);
                    zs[j] = root * inv_kappa;
                    // z dz = S dS / κ².
                    gs[j] = w * h * s;
                    rhos[j] = rest[j] * (2.0 * big_r - span * rest[j]) * rho_scale;
                    if RATE || NORMAL {
                        ys[j] = span * v * ratio * inv_kappa;
                        ts[j] = w * (s * zs[j] + d * rhos[j] * inv_rf) * inv_rf;
                    }
                }
                // Σ g, Σ g z, Σ g z² and Σ g ρ²; for the rate Σ t, Σ t y and Σ g y.
                for j in 0..m {
                    let (g, z) = (gs[j], zs[j]);
                    sum_g += g;
                    sum_gz += g * z;
                    sum_gzz += g * z * z;
                    spread += g * rhos[j];
                    if RATE || NORMAL {
                        sum_t += ts[j];
                        sum_ty += ts[j] * ys[j];
                        sum_gy += g * ys[j];
                    }
                    if NORMAL {
                        sum_tyy += ts[j] * ys[j] * ys[j];
                        sum_gyy += g * ys[j] * ys[j];
                    }
                }
            }
            if RATE {
                let mean_y = sum_gy / sum_g;
                zeta_rate = (sum_ty - mean_y * sum_t) / sum_g;
            }
            if NORMAL {
                // x_f, the rim's height: κ x_f = r_f + S₀.
                let x_f = rim * inv_kappa;
                let (g0, g1, g2, t0, t1, t2) = (sum_g, sum_gy, sum_gyy, sum_t, sum_ty, sum_tyy);
                let top = x_f * x_f * (t1 * g0 - t0 * g1) + x_f * (t2 * g0 - t0 * g2) + (t2 * g1 - t1 * g2);
                normal_ratio = (sum_gzz / (rf * sum_gz), top / (rf * sum_gz * sum_gz));
            }
            // ν · n = z/r_f; ḣ's part along n is −(z/r_f) ṙ_n.
            let total = sum_gz * inv_rf;
            let rated = sum_gzz * inv_rf * inv_rf;
            // Σ_θ ν (−ρ⃗·V/r_f) = −ρ² V / (2 r_f²) per spoke.
            (total, elastic * total - slope * r_n * rated, -slope * spread * 0.5 * inv_rf * inv_rf, rated)
        };
        if !(total > 0.0) {
            return (point, 0.0, (1.0, 0.0));
        }
        let v = r_t + n.cross(turn) * d;
        // lever q × ν = (d/r_f) ρ⃗ × n; Σ_θ (ρ⃗ × n)(ρ⃗·V) = ρ² (V × n)/2.
        let inv_total = 1.0 / total;
        let force = n * (along * inv_total) + v * (across * inv_total);
        let moment = v.cross(n) * (across * d * inv_total);
        (PatchForce { force, moment, centroid: centre + n * (sum_gz / sum_g), rate_weight: rated * inv_total }, zeta_rate, normal_ratio)
    }
}

/// The flat face in closed form: every element's normal is n, its depth
/// h = √(R² − ρ²) − (R − δ) a function of ρ alone and its rate
/// ḣ = −ṙ_n − ρ⃗·(n × Ω) (sliding over a plane compresses nothing), so
/// ∫ h ρ dρ = δ²(3R − δ)/6 and ∫ h ρ³ dρ = δ³(20c² + 25cδ + 8δ²)/60,
/// c = R − δ. The resultant is (F_el + slope δ̇) n (the 1D law: ḣ averages
/// to δ̇), and its moment about the ball's centre −slope M₂ Ω_⊥ with
/// M₂ = ∫ h ρ³/2 / ∫ h ρ = δ(20R² − 15Rδ + 3δ²)/(20(3R − δ)) (→ a²/6):
/// the rolling resistance of a ball turning on the face.
#[allow(clippy::too_many_arguments)]
#[inline]
pub(crate) fn flat(big_r: f64, r: Vec3, r_n: f64, turn: Vec3, delta: f64, n: Vec3, elastic: f64, slope: f64) -> PatchForce {
    let m2 = delta * (20.0 * big_r * big_r - 15.0 * big_r * delta + 3.0 * delta * delta) / (20.0 * (3.0 * big_r - delta));
    let turn_t = turn - n * n.dot(turn);
    PatchForce { force: n * (elastic - slope * r_n), moment: turn_t * (-slope * m2), centroid: r - n * (big_r - delta), rate_weight: 1.0 }
}

/// The normal force over the patch, body frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PatchForce {
    /// On the ball.
    pub force: Vec3,
    /// About the ball's centre, on the ball.
    pub moment: Vec3,
    /// The patch's centroid (depth-weighted), where friction acts.
    pub centroid: Vec3,
    /// w in ∂(n · force)/∂(n · ṙ) = −slope w: how the normal force moves with
    /// the ball's normal rate (1 on a flat face, Σ over the rings on a cap);
    /// a boot in series solves its balance with it.
    pub rate_weight: f64,
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Kick3dError;

    /// A cap as wide as the face, its half-extent printed and rounded down,
    /// is that cap; 0.1% narrower is refused naming `instep_radius`.
    #[test]
    fn the_face_half_extent_rounded_down_is_the_smallest_cap() {
        let at = |r: f64| {
            let spec = crate::Kick3dSpec { instep_radius: Some(r), face_yaw_deg: Some(0.0), ..crate::Kick3dSpec::default() };
            crate::Kick3d::new(kick_core::Scenario::baseline(), &spec)
        };
        let [_, hy, hz] = crate::Kick3d::baseline().foot_shape.core_half_extents();
        let smallest = hy.max(hz);
        assert_eq!(at(smallest * (1.0 - 3e-4)).unwrap().instep.unwrap().radius, smallest);
        assert_eq!(at(0.15).unwrap().instep.unwrap().radius, 0.15);
        match at(smallest * (1.0 - 1e-3)) {
            Err(Kick3dError::InvalidParameter { name: "instep_radius", .. }) => {}
            other => panic!("{other:?}"),
        }
    }

    /// The element sum written out independently: every element of a polar
    /// grid (64 Gauss nodes in s = ρ/a with weight s, 64 angles) on the foot's
    /// surface, its depth along ν by the plain formula ν·q + √((ν·q)² + R² − |q|²)
    /// and its rate by a central difference of the penetration into the foot
    /// of the undeformed ball's point y = x − h ν as the ball moves rigidly
    /// (ṙ, Ω). The closed form (flat) and the ring rule (cap) agree to the
    /// difference's error.
    #[allow(clippy::too_many_arguments)]
    fn brute(
        surface: Surface,
        big_r: f64,
        r: Vec3,
        r_dot: Vec3,
        turn: Vec3,
        delta: f64,
        n: Vec3,
        elastic: f64,
        slope: f64,
    ) -> (PatchForce, f64) {
        let depth = |x: Vec3, nu: Vec3, r: Vec3| {
            let q = x - r;
            let nq = nu.dot(q);
            nq + (nq * nq + big_r * big_r - q.length_squared()).max(0.0).sqrt()
        };
        let a2 = match surface {
            Surface::Flat => delta * (2.0 * big_r - delta),
            Surface::Sphere { radius: rf, .. } => {
                let d = big_r + rf - delta;
                let xf = (d * d + rf * rf - big_r * big_r) / (2.0 * d);
                rf * rf - xf * xf
            }
        };
        let (s_nodes, g) = gauss_legendre(64);
        let e1 = Vec3::Z.cross(n).normalize();
        let e2 = n.cross(e1);
        let eps = 1e-7;
        let (mut total, mut force, mut moment, mut loss) = (0.0, Vec3::ZERO, Vec3::ZERO, 0.0);
        for i in 0..64 {
            for j in 0..64 {
                let angle = std::f64::consts::TAU * (j as f64 + 0.5) / 64.0;
                let rho = (e1 * angle.cos() + e2 * angle.sin()) * (a2.sqrt() * s_nodes[i]);
                let (x, nu) = match surface {
                    Surface::Flat => (r - n * (big_r - delta) + rho, n),
                    Surface::Sphere { centre, radius: rf } => {
                        let z = (rf * rf - rho.length_squared()).sqrt();
                        (centre + n * z + rho, (n * z + rho) / rf)
                    }
                };
                let h = depth(x, nu, r);
                let y = x - nu * h;
                let moved = |t: f64| y + (r_dot + turn.cross(y - r)) * t;
                let inside = |p: Vec3| match surface {
                    Surface::Flat => n.dot(r - n * (big_r - delta) - p),
                    Surface::Sphere { centre, radius: rf } => rf - (p - centre).length(),
                };
                let rate = (inside(moved(eps)) - inside(moved(-eps))) / (2.0 * eps);
                let w = g[i] * s_nodes[i] * h;
                total += w * nu.dot(n);
                let f = nu * (w * (elastic + slope * rate));
                force += f;
                moment += (x - r).cross(f);
                loss += w * slope * rate * rate;
            }
        }
        (PatchForce { force: force / total, moment: moment / total, centroid: Vec3::ZERO, rate_weight: 1.0 }, loss / total)
    }

    /// Ball radius, cap radius, the cap's centre and a tilted normal: the
    /// cap the unit tests press the ball onto.
    fn tilted_cap() -> (f64, f64, Vec3, Vec3) {
        let (big_r, rf) = (0.11, 0.15);
        (big_r, rf, Vec3::new(0.03 - rf, 0.0, 0.0), Vec3::new(0.98, -0.15, 0.1).normalize())
    }

    #[test]
    fn closed_form_and_rings_are_the_element_sum() {
        let (big_r, rf) = (0.11, 0.15);
        for delta in [0.002, 0.02, 0.04] {
            for (r_dot, turn) in [
                (Vec3::new(-12.0, 0.0, 0.0), Vec3::ZERO),
                (Vec3::new(-10.0, 5.0, 2.0), Vec3::ZERO),
                (Vec3::new(4.0, -6.0, 1.0), Vec3::new(30.0, -50.0, 80.0)),
                (Vec3::new(-8.0, 0.0, 0.0), Vec3::new(0.0, 0.0, 60.0)),
            ] {
                let flat_r = Vec3::new(0.03 + big_r - delta, 0.01, -0.02);
                let centre = Vec3::new(0.03 - rf, 0.0, 0.0);
                let n = Vec3::new(0.99, 0.1, -0.05).normalize();
                let cap_r = centre + n * (big_r + rf - delta);
                let patch = Patch::new(Quadrature::default());
                for (surface, r, n) in [(Surface::Flat, flat_r, Vec3::X), (Surface::Sphere { centre, radius: rf }, cap_r, n)] {
                    let (elastic, slope) = (1500.0, 70.0);
                    let got = patch.resultant(surface, big_r, r, r_dot, turn, delta, n, elastic, slope);
                    let (want, _) = brute(surface, big_r, r, r_dot, turn, delta, n, elastic, slope);
                    let scale = want.force.length();
                    assert!(
                        (got.force - want.force).length() <= 1e-7 * scale,
                        "{surface:?} δ={delta}: {:?} vs {:?}",
                        got.force,
                        want.force
                    );
                    // The moment against its own size (it is ∝ slope · δ · v_t).
                    let m = 1e-6 * want.moment.length() + 1e-11 * scale * big_r;
                    assert!(
                        (got.moment - want.moment).length() <= m,
                        "{surface:?} δ={delta} {r_dot:?}: {:?} vs {:?}",
                        got.moment,
                        want.moment
                    );
                }
            }
        }
    }

    /// The loss is passive: the power the element forces take out of the
    /// relative motion, less the elastic part, is slope Σ w ḣ² ≥ 0 (each
    /// element's loss force times its own rate), summed independently on the
    /// polar grid. A rate other than the material's (e.g. the depth's rate at
    /// a point fixed on the foot) breaks the square.
    #[test]
    fn the_loss_takes_power_as_a_sum_of_squares() {
        let (big_r, rf, centre, n) = tilted_cap();
        let patch = Patch::new(Quadrature::default());
        for delta in [0.003, 0.03] {
            for (r_dot, turn) in [
                (Vec3::new(-9.0, 7.0, 0.0), Vec3::ZERO),
                (Vec3::new(3.0, -8.0, 2.0), Vec3::new(-40.0, 10.0, 90.0)),
                (Vec3::new(0.0, 0.0, 12.0), Vec3::new(0.0, 70.0, 0.0)),
            ] {
                let (flat_r, cap_r) = (Vec3::new(0.03 + big_r - delta, 0.01, -0.02), centre + n * (big_r + rf - delta));
                for (surface, r, n) in [(Surface::Flat, flat_r, Vec3::X), (Surface::Sphere { centre, radius: rf }, cap_r, n)] {
                    let (elastic, slope) = (1500.0, 70.0);
                    let got = patch.resultant(surface, big_r, r, r_dot, turn, delta, n, elastic, slope);
                    let taken = -(got.force.dot(r_dot) + got.moment.dot(turn) - elastic * n.dot(r_dot));
                    let (_, want) = brute(surface, big_r, r, r_dot, turn, delta, n, elastic, slope);
                    assert!(
                        want > 0.0 && (taken - want).abs() <= 1e-6 * want,
                        "{surface:?} δ={delta} {r_dot:?} {turn:?}: {taken} vs {want}"
                    );
                }
            }
        }
    }

    /// Sliding over a plane compresses no part of the ball more than another:
    /// no moment without a turn, on the flat face.
    #[test]
    fn sliding_over_a_plane_turns_nothing() {
        let patch = Patch::new(Quadrature::default());
        let (big_r, delta) = (0.11, 0.02);
        let r = Vec3::new(0.03 + big_r - delta, 0.04, 0.0);
        let p = patch.resultant(Surface::Flat, big_r, r, Vec3::new(-10.0, 8.0, -3.0), Vec3::ZERO, delta, Vec3::X, 1500.0, 70.0);
        assert_eq!(p.moment, Vec3::ZERO);
        assert_eq!(p.force, Vec3::X * (1500.0 + 70.0 * 10.0));
    }

    /// The cap's centroid height and its rate: ζ is the resultant's
    /// centroid, and dζ/dδ is its five-point central difference (step
    /// 1e-3 δ: truncation ~1e-12, rounding ~1e-9 of the rate) and, to 1e-12,
    /// the rate of a 40-ring rule, from a fraction of a millimetre to 3 cm.
    #[test]
    fn the_cap_centroid_rate_is_its_derivative() {
        let (big_r, rf, centre, n) = tilted_cap();
        let patch = Patch::new(Quadrature::default());
        let zeta = |delta: f64| {
            let r = centre + n * (big_r + rf - delta);
            let p = patch.resultant(Surface::Sphere { centre, radius: rf }, big_r, r, Vec3::ZERO, Vec3::ZERO, delta, n, 1000.0, 50.0);
            (p.centroid - centre).dot(n)
        };
        for delta in [3e-4, 0.003, 0.01, 0.03] {
            let r = centre + n * (big_r + rf - delta);
            let (p, rate) = patch.resultant_and_centroid_rate(
                Surface::Sphere { centre, radius: rf },
                big_r,
                r,
                Vec3::ZERO,
                Vec3::ZERO,
                delta,
                n,
                1000.0,
                50.0,
            );
            let z = (p.centroid - centre).dot(n);
            let h = 1e-3 * delta;
            let fd = (8.0 * (zeta(delta + h) - zeta(delta - h)) - (zeta(delta + 2.0 * h) - zeta(delta - 2.0 * h))) / (12.0 * h);
            println!("δ {delta}: ζ {z} rate {rate} (difference {fd})");
            assert!((z - zeta(delta)).abs() <= 1e-15, "δ {delta}: {z} vs {}", zeta(delta));
            assert!((rate - fd).abs() <= 1e-8 * rate.abs(), "δ {delta}: {rate} vs {fd}");
            // The rule's own error in the rate: against 40 rings (measured ≤ 9e-14 to 3 cm).
            let fine = Patch::new(Quadrature { rings: 40 })
                .resultant_and_centroid_rate(
                    Surface::Sphere { centre, radius: rf },
                    big_r,
                    r,
                    Vec3::ZERO,
                    Vec3::ZERO,
                    delta,
                    n,
                    1000.0,
                    50.0,
                )
                .1;
            assert!((rate - fine).abs() <= 1e-12 * fine.abs(), "δ {delta}: {rate} vs {fine} (40 rings)");
        }
    }

    /// Fault 11 of issue 33 and its kind: a contact off the instep's face
    /// is refused naming a parameter the user gave (before, `face_yaw = 0`,
    /// derived, for `--approach-angle 30`). Over a grid of patch kicks,
    /// given or not given face angles, every such refusal names one of the
    /// given parameters, on the axis the contact misses by most.
    #[test]
    fn a_contact_off_the_face_names_what_the_user_gave() {
        use kick_core::parameters::{SetLaw, SetParameter, Value};
        let mut spec = crate::KickSpec::default();
        spec.set_law(kick_core::LawKind::Shell);
        spec.set_named("patch_contact", Value::Switch(true)).unwrap();
        spec.set_named("approach_angle", Value::Number(30.0)).unwrap();
        // The derived face turns with the foot's path (one offset definition,
        // issue 32), so the kick of the fault now meets its face square on.
        let kick = spec.build().expect("a rising kick on the derived face");
        let pitch = kick.instep.as_ref().map(|i| i.pitch.to_degrees());
        assert!(pitch.is_some_and(|p| (p - 30.0).abs() < 1e-12), "{pitch:?}");
        // A face held square while the path rises is refused naming what was given.
        spec.set_named("face_pitch", Value::Number(0.0)).unwrap();
        match spec.build() {
            Err(Kick3dError::InvalidParameter { name, .. }) => assert!(["approach_angle", "face_pitch"].contains(&name), "{name}"),
            other => panic!("{other:?}"),
        }
        let mut refused = 0;
        for offset in [None, Some(0.03), Some(0.08)] {
            for angle in [None, Some(-35.0), Some(25.0)] {
                for yaw in [None, Some(0.0), Some(30.0)] {
                    for pitch in [None, Some(0.0), Some(-20.0)] {
                        let mut spec = crate::KickSpec::default();
                        spec.set_law(kick_core::LawKind::Shell);
                        spec.set_named("patch_contact", Value::Switch(true)).unwrap();
                        let mut given = vec![];
                        for (name, value) in [("offset", offset), ("approach_angle", angle), ("face_yaw", yaw), ("face_pitch", pitch)] {
                            if let Some(x) = value {
                                spec.set_named(name, Value::Number(x)).unwrap();
                                given.push(name);
                            }
                        }
                        if let Err(Kick3dError::InvalidParameter { name, .. }) = spec.build() {
                            refused += 1;
                            assert!(given.contains(&name), "{given:?}: `{name}` named");
                        }
                    }
                }
            }
        }
        assert!(refused > 0);
    }

    /// The cap's normal-force ratio: the normal component of the resultant is
    /// F_el + slope δ̇ ρ(δ) for any sliding and turn, and dρ/dδ is ρ's
    /// five-point central difference (step 1e-3 δ) and, to 1e-11, a 40-ring
    /// rule's, from a fraction of a millimetre to 3 cm (what a slipping
    /// contact's cap rate d(μ F_n)/dt rests on).
    #[test]
    fn the_cap_normal_ratio_rate_is_its_derivative() {
        let (big_r, rf, centre, n) = tilted_cap();
        let patch = Patch::new(Quadrature::default());
        let (elastic, slope) = (1000.0, 50.0);
        let at = |delta: f64, rings: Patch| {
            let r = centre + n * (big_r + rf - delta);
            rings.resultant_and_normal_ratio(
                Surface::Sphere { centre, radius: rf },
                big_r,
                r,
                Vec3::ZERO,
                Vec3::ZERO,
                delta,
                n,
                elastic,
                slope,
            )
        };
        for delta in [3e-4, 0.003, 0.01, 0.03] {
            let r = centre + n * (big_r + rf - delta);
            // Sliding and turning: the normal component still follows ρ.
            let r_dot = n * -7.0 + Vec3::new(0.0, 3.0, -2.0).reject_from(n);
            let (p, (rho, rate)) = patch.resultant_and_normal_ratio(
                Surface::Sphere { centre, radius: rf },
                big_r,
                r,
                r_dot,
                Vec3::new(20.0, -30.0, 50.0),
                delta,
                n,
                elastic,
                slope,
            );
            let normal = n.dot(p.force);
            assert!((normal - (elastic + slope * 7.0 * rho)).abs() <= 1e-13 * normal, "δ {delta}: {normal} vs ρ {rho}");
            let value = |d: f64| at(d, patch).1 .0;
            let h = 1e-3 * delta;
            let fd = (8.0 * (value(delta + h) - value(delta - h)) - (value(delta + 2.0 * h) - value(delta - 2.0 * h))) / (12.0 * h);
            println!("δ {delta}: ρ {rho} dρ/dδ {rate} (difference {fd})");
            assert!((rate - fd).abs() <= 1e-7 * rate.abs(), "δ {delta}: {rate} vs {fd}");
            let fine = at(delta, Patch::new(Quadrature { rings: 40 })).1 .1;
            assert!((rate - fine).abs() <= 1e-11 * fine.abs(), "δ {delta}: {rate} vs {fine} (40 rings)");
        }
    }

    /// Gauss–Legendre on (0, 1) integrates polynomials of degree 2n − 1 exactly.
    #[test]
    fn gauss_legendre_is_exact_to_degree_2n_minus_1() {
        for n in [1, 2, 4, 8, MAX_RINGS] {
            let (x, w) = gauss_legendre(n);
            for k in 0..(2 * n) {
                let sum: f64 = (0..n).map(|i| w[i] * x[i].powi(k as i32)).sum();
                assert!((sum - 1.0 / (k as f64 + 1.0)).abs() < 1e-14, "n={n} k={k}: {sum}");
            }
        }
    }
}
