//! Aerodynamic coefficients of a soccer ball: drag against Reynolds number
//! (with the drag crisis), lift against spin parameter. Sources and what was
//! checked against them: `SOURCES.md` beside this crate's `Cargo.toml`.

use serde::Serialize;

/// C_D model.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum DragModel {
    /// The same C_D at every speed.
    Constant { value: f64 },
    /// The default: Goff & Carré (2010), Eq. 3, a logistic fit to the
    /// non-spinning wind-tunnel C_D of Asai et al. (2007), taken as a
    /// function of Reynolds number (see [`DragCrisis`]), its crisis moved to
    /// the ball construction's critical Reynolds number
    /// ([`BallConstruction`]), joined above the crisis to the spinning
    /// ball's Eq. 4 ([`SpinDrag`]).
    DragCrisis { construction: BallConstruction },
}

/// A ball construction with a published critical Reynolds number: Asai &
/// Hong (2021), *Scientific Reports* 11, doi:10.1038/s41598-021-89162-y, Introduction (checked against
/// the text): "as the number of ball panels decreases from 32 to 14 and 8,
/// their critical Reynolds numbers tend to increase from ~2.5 × 10⁵ to
/// ~3.1 × 10⁵ and to ~3.6 × 10⁵ ... reduced to 6, ... ~2.3 × 10⁵ and
/// 2.7 × 10⁵" (two six-panel balls; the model takes their mean, 2.5 × 10⁵).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct BallConstruction {
    /// Number of panels: one of [`BALL_CONSTRUCTIONS`]'s.
    pub panels: u8,
}

/// The declared constructions: panel count, critical Re, example balls.
/// 14 panels (Teamgeist 2006) is the default: Eq. 3 was fitted to a
/// Teamgeist's C_D, so the default ball keeps Eq. 3 exactly.
pub const BALL_CONSTRUCTIONS: [(u8, f64, &str); 4] = [
    (32, 2.5e5, "conventional 12 pentagons and 20 hexagons"),
    (14, 3.1e5, "Teamgeist 2006"),
    (8, 3.6e5, "Jabulani 2010"),
    (6, 2.5e5, "Brazuca 2014, Telstar18 2018: 2.3-2.7e5, mean"),
];

impl BallConstruction {
    /// The default: 14 panels.
    pub const DEFAULT_PANELS: u8 = 14;

    /// The construction with `panels` panels, if one is declared.
    pub fn with_panels(panels: f64) -> Option<BallConstruction> {
        BALL_CONSTRUCTIONS.iter().find(|c| c.0 as f64 == panels).map(|c| BallConstruction { panels: c.0 })
    }
    /// Published critical Reynolds number (Asai & Hong 2021; their
    /// definition was not read, so only its ratio to the 14-panel ball's is used).
    pub fn published_critical_reynolds(self) -> f64 {
        BALL_CONSTRUCTIONS.iter().find(|c| c.0 == self.panels).map_or(f64::NAN, |c| c.1)
    }
    /// Factor on Eq. 3's Reynolds numbers: this ball's critical Re over the
    /// Teamgeist's (14 panels), 1 for the default.
    pub fn reynolds_scale(self) -> f64 {
        self.published_critical_reynolds() / BallConstruction::default().published_critical_reynolds()
    }
}

impl Default for BallConstruction {
    fn default() -> Self {
        BallConstruction { panels: Self::DEFAULT_PANELS }
    }
}

/// Drag of a spinning ball above the crisis: Goff & Carré (2010), Eq. 4,
/// C_D = 0.4127 S^0.3056 (S > 0.05, v above the crisis), joined to the
/// no-spin supercritical C_D₀ = 0.155 of Eq. 3 by
///
/// C_D,super(S) = C_D₀ (1 + (S/S*)⁴)^(p/4), S* = (C_D₀/a)^(1/p),
///
/// the power mean of order 4/p of C_D₀ and a S^p (a = 0.4127, p = 0.3056):
/// C_D₀ exactly at S = 0 (rising as S⁴), a S^p (1 + (S*/S)⁴)^(p/4) → Eq. 4
/// as S grows (2.8 % above it at S = 0.05, 0.2 % at 0.1). It is a smooth
/// function of S², so of ω and v (no kink where ω × v = 0, no event).
pub struct SpinDrag;

impl SpinDrag {
    /// a of Eq. 4.
    pub const FACTOR: f64 = 0.4127;
    /// p of Eq. 4.
    pub const EXPONENT: f64 = 0.3056;
    /// Eq. 4 itself.
    pub fn eq4(spin_parameter: f64) -> f64 {
        Self::FACTOR * spin_parameter.powf(Self::EXPONENT)
    }
    /// S* ≈ 0.0406, where Eq. 4 meets the no-spin C_D₀.
    pub fn crossover() -> f64 {
        (DragCrisis::SUPERCRITICAL / Self::FACTOR).powf(1.0 / Self::EXPONENT)
    }
    /// C_D,super at spin parameter S.
    pub fn supercritical(spin_parameter: f64) -> f64 {
        let q = (spin_parameter / Self::crossover()).powi(2);
        Self::of_square_ratio(DragCrisis::SUPERCRITICAL, q)
    }
    /// `base` (1 + q²)^(p/4), q = (S/S*)²; q capped so that an extreme
    /// spin parameter (a ball nearly at rest) stays finite.
    #[inline]
    fn of_square_ratio(base: f64, q: f64) -> f64 {
        if q == 0.0 {
            base
        } else {
            base * (1.0 + (q * q).min(1e300)).powf(0.25 * Self::EXPONENT)
        }
    }
}

/// C_L model.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum LiftModel {
    /// The same C_L whenever ω × v ≠ 0.
    Constant { value: f64 },
    /// The default: C_L = C_L∞ (1 − exp(−(S/S_L)²)), least squares to the
    /// published points in [`LIFT_POINTS`] (see [`SaturatingLift`]).
    Saturating,
}

/// Goff & Carré (2010), Eur. J. Phys. 31, 775–784, Eq. 3:
/// C_D = 0.155 + 0.346 / (1 + exp((v − v_c)/v_s)), v_c = 12.19 m/s, v_s = 1.309 m/s,
/// fitted to Asai et al. (2007), Sports Eng. 10, 101–110 (Teamgeist, no spin).
///
/// The fit is written in speed for a size-5 ball in the tunnel's air. Here it
/// is a function of Re = ρ v D/μ: v_c and v_s become Re_c = v_c D_ref/ν_ref and
/// Re_s = v_s D_ref/ν_ref with D_ref = 0.22 m and ν_ref of the standard
/// atmosphere at sea level, so that the default ball (R = 0.11 m) in default
/// air (1.225 kg/m³, 15 °C) has exactly Eq. 3, and another ball or other air
/// moves the crisis as Reynolds similarity says. The logistic is smooth
/// (C^∞), so the integrator needs no event at the crisis.
pub struct DragCrisis;

impl DragCrisis {
    /// C_D far above the crisis.
    pub const SUPERCRITICAL: f64 = 0.155;
    /// Drop of C_D across the crisis (subcritical C_D = 0.155 + 0.346 = 0.501).
    pub const DROP: f64 = 0.346;
    /// v_c, m/s.
    pub const CRISIS_SPEED: f64 = 12.19;
    /// v_s, m/s.
    pub const CRISIS_WIDTH: f64 = 1.309;
    /// D_ref, m: the ball diameter for which the speeds above become Reynolds numbers.
    pub const REFERENCE_DIAMETER: f64 = 0.22;

    /// ν_ref, m²/s: standard sea-level air.
    pub fn reference_kinematic_viscosity() -> f64 {
        crate::air::Air::standard().kinematic_viscosity()
    }
    /// Re_c ≈ 1.84e5, the logistic's centre: C_D halfway down. Not the
    /// critical Re ([`DragCrisis::critical_reynolds`]).
    pub fn centre_reynolds() -> f64 {
        Self::CRISIS_SPEED * Self::REFERENCE_DIAMETER / Self::reference_kinematic_viscosity()
    }
    /// The drop's share done at the critical Re: 95 %.
    pub const CRITICAL_SHARE: f64 = 0.95;
    /// The critical Reynolds number, the project's one definition of it:
    /// where [`DragCrisis::CRITICAL_SHARE`] of the drop is done,
    /// Re_c + Re_s ln(0.95/0.05) ≈ 2.42e5 (C_D ≈ 0.172). The logistic has no
    /// minimum; a critical Re read where a measured C_D bottoms out, as for
    /// a smooth sphere, lies near the end of the drop, not at its centre.
    /// SOURCES.md, "Drag coefficient", says why.
    pub fn critical_reynolds() -> f64 {
        Self::centre_reynolds() + Self::reynolds_width() * (Self::CRITICAL_SHARE / (1.0 - Self::CRITICAL_SHARE)).ln()
    }
    /// Re_s ≈ 1.97e4.
    pub fn reynolds_width() -> f64 {
        Self::CRISIS_WIDTH * Self::REFERENCE_DIAMETER / Self::reference_kinematic_viscosity()
    }
    /// C_D at Reynolds number `re`.
    pub fn at(re: f64) -> f64 {
        logistic(Self::SUPERCRITICAL, Self::DROP, (re - Self::centre_reynolds()) / Self::reynolds_width())
    }
}

#[inline]
fn logistic(base: f64, drop: f64, x: f64) -> f64 {
    // exp overflows to inf for large x, and 1/(1 + inf) = 0: no NaN.
    base + drop / (1.0 + x.exp())
}

/// (S, C_L) points of the default lift model: the medians of Asai et al.'s
/// (2007) wind-tunnel series for S ≤ 0.27 as replotted in Goff & Carré (2010)
/// Fig. 6, and Goff & Carré's (2009) two trajectory values at S = 0.49 and
/// 0.71. Read from a third-party transcription of those figures, not from
/// the figures themselves: see SOURCES.md.
pub const LIFT_POINTS: [(f64, f64); 7] =
    [(0.05, 0.05), (0.11, 0.22), (0.16, 0.24), (0.20, 0.29), (0.27, 0.29), (0.49, 0.285), (0.71, 0.31)];

/// C_L = C_L∞ (1 − exp(−(S/S_L)²)): zero slope at S = 0 (the points rise
/// slowly below S ≈ 0.05), a plateau above S ≈ 0.25 as the points show, and
/// smooth in ω and v. Of the two-parameter forms tried (tanh, S²/(b²+S²),
/// S/(b+S), this one), this one has the smallest residual on [`LIFT_POINTS`]
/// (RMS 0.015); the constants are their least-squares optimum, recomputed by
/// this module's tests.
pub struct SaturatingLift;

impl SaturatingLift {
    /// C_L∞.
    pub const PLATEAU: f64 = 0.2923;
    /// S_L.
    pub const SPIN_SCALE: f64 = 0.1027;

    pub fn at(spin_parameter: f64) -> f64 {
        Self::of_square(spin_parameter * spin_parameter)
    }
    /// C_L from S² (what the right-hand side has without a square root).
    #[inline]
    pub fn of_square(s2: f64) -> f64 {
        -Self::PLATEAU * (-s2 / (Self::SPIN_SCALE * Self::SPIN_SCALE)).exp_m1()
    }
}

impl DragModel {
    pub fn name(&self) -> &'static str {
        match self {
            DragModel::Constant { .. } => "constant",
            DragModel::DragCrisis { .. } => "goff_carre_2010_spin",
        }
    }
}

impl LiftModel {
    pub fn name(&self) -> &'static str {
        match self {
            LiftModel::Constant { .. } => "constant",
            LiftModel::Saturating => "saturating_fit",
        }
    }
}

/// The drag law in the form the right-hand side evaluates, for one ball in
/// one air: with σ(v) = 1/(1 + exp((v − centre)/width)) the logistic weight
/// of Eq. 3 (1 below the crisis, 0 above),
/// C_D(v, S) = C_D,super(S) + σ(v) (C_D,sub − C_D,super(S)),
/// C_D,sub = base + drop. Without spin this is Eq. 3, base + drop σ(v).
/// Below the crisis spin changes nothing (no published data there).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct DragLaw {
    pub base: f64,
    pub drop: f64,
    pub centre: f64,
    /// 1/width, s/m.
    pub inverse_width: f64,
    /// 1/S*², for C_D,super (0: no spin dependence).
    pub inverse_crossover_squared: f64,
}

impl DragLaw {
    /// `reynolds_per_speed` = ρ D/μ, s/m.
    pub fn new(model: DragModel, reynolds_per_speed: f64) -> DragLaw {
        match model {
            DragModel::Constant { value } => {
                DragLaw { base: value, drop: 0.0, centre: 0.0, inverse_width: 0.0, inverse_crossover_squared: 0.0 }
            }
            DragModel::DragCrisis { construction } => {
                let scale = construction.reynolds_scale();
                DragLaw {
                    base: DragCrisis::SUPERCRITICAL,
                    drop: DragCrisis::DROP,
                    centre: scale * DragCrisis::centre_reynolds() / reynolds_per_speed,
                    inverse_width: reynolds_per_speed / (scale * DragCrisis::reynolds_width()),
                    inverse_crossover_squared: SpinDrag::crossover().powi(-2),
                }
            }
        }
    }

    /// C_D without spin.
    #[inline]
    pub fn at_speed(&self, speed: f64) -> f64 {
        self.at(speed, 0.0)
    }

    /// C_D at `speed` and squared spin parameter `s2`.
    #[inline]
    pub fn at(&self, speed: f64, s2: f64) -> f64 {
        if self.drop == 0.0 {
            return self.base;
        }
        let x = (speed - self.centre) * self.inverse_width;
        let q = s2 * self.inverse_crossover_squared;
        if q == 0.0 {
            // Eq. 3 as written (the form before spin was added, to the bit).
            logistic(self.base, self.drop, x)
        } else {
            let sigma = 1.0 / (1.0 + x.exp());
            let sup = SpinDrag::of_square_ratio(self.base, q);
            sup + sigma * (self.base + self.drop - sup)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn default_ball_in_default_air_is_eq3_in_speed() {
        // Re/v for R = 0.11 m in standard sea-level air.
        let air = crate::air::Air::standard();
        let law = DragLaw::new(DragModel::DragCrisis { construction: BallConstruction::default() }, air.density * 0.22 / air.viscosity);
        for v in [5.0, 10.0, 12.19, 14.0, 20.0, 30.0] {
            let eq3 = 0.155 + 0.346 / (1.0 + ((v - 12.19) / 1.309_f64).exp());
            assert!((law.at_speed(v) - eq3).abs() < 1e-14, "{v}");
        }
        // Limits: subcritical 0.501, supercritical 0.155; no NaN at extreme speeds.
        assert!((law.at_speed(0.0) - 0.501).abs() < 1e-3);
        assert_eq!(law.at_speed(1e6), 0.155);
        assert!((DragCrisis::centre_reynolds() - 1.836e5).abs() < 1e2);
        // The critical Re: 95 % of the drop done, C_D = 0.155 + 0.05 × 0.346.
        assert!((DragCrisis::at(DragCrisis::critical_reynolds()) - (0.155 + 0.05 * 0.346)).abs() < 1e-12);
        assert!((DragCrisis::critical_reynolds() - 2.416e5).abs() < 1e2, "{}", DragCrisis::critical_reynolds());
    }

    #[test]
    fn lift_constants_are_the_least_squares_optimum() {
        // Gauss–Newton from a distant start on the published points.
        let (mut a, mut b) = (0.5_f64, 0.3_f64);
        for _ in 0..200 {
            let (mut jtj, mut jtr) = ([[0.0; 2]; 2], [0.0; 2]);
            for (s, c) in LIFT_POINTS {
                let e = (-(s / b).powi(2)).exp();
                let r = a * (1.0 - e) - c;
                let j = [1.0 - e, -a * e * 2.0 * s * s / b.powi(3)];
                for p in 0..2 {
                    jtr[p] += j[p] * r;
                    for q in 0..2 {
                        jtj[p][q] += j[p] * j[q];
                    }
                }
            }
            let det = jtj[0][0] * jtj[1][1] - jtj[0][1] * jtj[1][0];
            a -= (jtj[1][1] * jtr[0] - jtj[0][1] * jtr[1]) / det;
            b -= (jtj[0][0] * jtr[1] - jtj[1][0] * jtr[0]) / det;
        }
        assert!((SaturatingLift::PLATEAU / a - 1.0).abs() < 5e-4, "C_L∞ optimum {a}");
        assert!((SaturatingLift::SPIN_SCALE / b - 1.0).abs() < 5e-4, "S_L optimum {b}");
        let rms = (LIFT_POINTS.iter().map(|&(s, c)| (SaturatingLift::at(s) - c).powi(2)).sum::<f64>() / 7.0).sqrt();
        assert!(rms < 0.016, "rms {rms}");
    }

    #[test]
    fn lift_shape() {
        assert_eq!(SaturatingLift::at(0.0), 0.0);
        // Small S: C_L ≈ C_L∞ (S/S_L)², to rounding (exp_m1 keeps it exact there).
        let s = 1e-6;
        let expected = SaturatingLift::PLATEAU * (s / SaturatingLift::SPIN_SCALE).powi(2);
        assert!((SaturatingLift::at(s) / expected - 1.0).abs() < 1e-9);
        assert!((SaturatingLift::at(10.0) - SaturatingLift::PLATEAU).abs() < 1e-15);
    }

    /// C_D of a default ball in default air, at speed v and spin parameter S.
    fn drag(construction: BallConstruction, v: f64, s: f64) -> f64 {
        let air = crate::air::Air::standard();
        DragLaw::new(DragModel::DragCrisis { construction }, air.density * 0.22 / air.viscosity).at(v, s * s)
    }

    /// The join's limits: no spin gives Eq. 3 exactly at every speed; far
    /// above the crisis a spinning ball has Eq. 4 as S grows (the power mean
    /// exceeds it by the factor (1 + (S*/S)⁴)^(p/4), under 3 % at S = 0.05,
    /// 0.2 % at 0.1); below the crisis spin changes nothing.
    #[test]
    fn spin_drag_limits() {
        let c = BallConstruction::default();
        for v in [3.0, 10.0, 12.19, 15.0, 25.0, 35.0] {
            let eq3 = 0.155 + 0.346 / (1.0 + ((v - 12.19) / 1.309_f64).exp());
            assert!((drag(c, v, 0.0) - eq3).abs() < 1e-14, "{v}");
        }
        // Eq. 4 meets 0.155 at S* = (0.155/0.4127)^(1/0.3056) ≈ 0.0406.
        assert!((SpinDrag::crossover() - 0.04058).abs() < 1e-4, "{}", SpinDrag::crossover());
        // 60 m/s: σ = e^-36, Eq. 3 is 0.155 to 1e-16.
        for (s, bound) in [(0.05, 0.03), (0.1, 2.1e-3), (0.2, 1.4e-4), (0.3, 3e-5), (0.6, 2e-6)] {
            let eq4 = 0.4127 * f64::powf(s, 0.3056);
            let ratio = drag(c, 60.0, s) / eq4;
            assert!(ratio > 1.0 && ratio - 1.0 < bound, "S {s}: C_D/Eq. 4 = {ratio}");
        }
        // A ball at S = 0.2 (the free kick): C_D ≈ 0.25, not 0.155.
        assert!((drag(c, 60.0, 0.2) - 0.2525).abs() < 1e-3, "{}", drag(c, 60.0, 0.2));
        // Far below the crisis (σ → 1): the subcritical 0.501 whatever the spin.
        assert!((drag(c, 2.0, 0.5) - 0.501).abs() < 1e-3, "{}", drag(c, 2.0, 0.5));
        // The join never falls below either curve (a power mean is above both).
        for i in 1..=500 {
            let s = i as f64 * 1e-3;
            assert!(SpinDrag::supercritical(s) >= 0.155_f64.max(SpinDrag::eq4(s)), "{s}");
        }
    }

    /// Smooth enough for located events: C_D,super is C¹ (indeed C^∞) in S,
    /// with zero slope at S = 0 (so smooth in ω through ω × v = 0): second
    /// differences shrink as h² everywhere (a kink would leave them O(h)).
    #[test]
    fn spin_drag_is_smooth() {
        let f = SpinDrag::supercritical;
        for h in [1e-3, 1e-4] {
            let mut worst = 0.0_f64;
            for i in 0..=600 {
                let s = i as f64 * 5e-4 + 1e-5;
                let second = (f(s + h) - 2.0 * f(s) + f((s - h).abs())) / (h * h);
                worst = worst.max(second.abs());
            }
            // |C''| is bounded (≈ 12 near S*): a kink would give ~|ΔC'|/h ≥ 1e3 here.
            assert!(worst < 30.0, "h {h}: |second difference|/h² up to {worst}");
        }
        // Zero slope at S = 0: C(h) − C(0) = O(h⁴).
        // (1 + x)^a − 1 ≤ a x: C(h) − C(0) ≤ 0.155 (p/4) (h/S*)⁴.
        assert_eq!(f(0.0), 0.155);
        for h in [1e-2, 1e-3] {
            let rise = f(h) - f(0.0);
            assert!(rise >= 0.0 && rise <= 0.155 * 0.3056 / 4.0 * (h / SpinDrag::crossover()).powi(4) + 1e-16, "{h}: {rise}");
        }
        // And in speed at fixed spin (the logistic weight): continuous through the crisis.
        let c = BallConstruction::default();
        let g = |v: f64| drag(c, v, 0.11 * 50.0 / v);
        for i in 0..400 {
            let v = 3.0 + i as f64 * 0.1;
            let h = 1e-4;
            let second = (g(v + h) - 2.0 * g(v) + g(v - h)) / (h * h);
            assert!(second.abs() < 1.0, "v {v}: {second}");
        }
    }

    /// Each construction's crisis sits at its published critical Re relative
    /// to the 14-panel ball's: the Re at which C_D is halfway down (found by
    /// bisection on the law) scales by Re_crit/3.1e5.
    #[test]
    fn constructions_move_the_crisis() {
        let air = crate::air::Air::standard();
        let per_speed = air.density * 0.22 / air.viscosity;
        let halfway = |c: BallConstruction| {
            let (mut lo, mut hi) = (1.0, 40.0);
            for _ in 0..100 {
                let mid = 0.5 * (lo + hi);
                if drag(c, mid, 0.0) > 0.155 + 0.5 * 0.346 {
                    lo = mid
                } else {
                    hi = mid
                }
            }
            0.5 * (lo + hi) * per_speed
        };
        let teamgeist = halfway(BallConstruction::default());
        assert!((teamgeist / 1.836e5 - 1.0).abs() < 1e-3, "{teamgeist}");
        for (panels, re, published) in [(32, 2.5e5, 2.5), (14, 3.1e5, 3.1), (8, 3.6e5, 3.6), (6, 2.5e5, 2.5)] {
            let c = BallConstruction::with_panels(panels as f64).unwrap();
            assert_eq!(c.published_critical_reynolds(), re);
            let ratio = halfway(c) / teamgeist;
            assert!((ratio / (published / 3.1) - 1.0).abs() < 1e-9, "{panels}: {ratio}");
        }
        assert_eq!(BallConstruction::with_panels(12.0), None);
        assert_eq!(BallConstruction::with_panels(f64::NAN), None);
    }
}
