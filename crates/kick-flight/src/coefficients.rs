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
    /// function of Reynolds number (see [`DragCrisis`]).
    DragCrisis,
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
    /// Re_c ≈ 1.84e5.
    pub fn critical_reynolds() -> f64 {
        Self::CRISIS_SPEED * Self::REFERENCE_DIAMETER / Self::reference_kinematic_viscosity()
    }
    /// Re_s ≈ 1.97e4.
    pub fn reynolds_width() -> f64 {
        Self::CRISIS_WIDTH * Self::REFERENCE_DIAMETER / Self::reference_kinematic_viscosity()
    }
    /// C_D at Reynolds number `re`.
    pub fn at(re: f64) -> f64 {
        logistic(Self::SUPERCRITICAL, Self::DROP, (re - Self::critical_reynolds()) / Self::reynolds_width())
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
            DragModel::DragCrisis => "goff_carre_2010",
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

/// The drag law in the speed form the right-hand side evaluates:
/// C_D(v) = base + drop / (1 + exp((v − centre)/width)), for one ball in one air.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct DragLaw {
    pub base: f64,
    pub drop: f64,
    pub centre: f64,
    /// 1/width, s/m.
    pub inverse_width: f64,
}

impl DragLaw {
    /// `reynolds_per_speed` = ρ D/μ, s/m.
    pub fn new(model: DragModel, reynolds_per_speed: f64) -> DragLaw {
        match model {
            DragModel::Constant { value } => DragLaw { base: value, drop: 0.0, centre: 0.0, inverse_width: 0.0 },
            DragModel::DragCrisis => DragLaw {
                base: DragCrisis::SUPERCRITICAL,
                drop: DragCrisis::DROP,
                centre: DragCrisis::critical_reynolds() / reynolds_per_speed,
                inverse_width: reynolds_per_speed / DragCrisis::reynolds_width(),
            },
        }
    }

    #[inline]
    pub fn at_speed(&self, speed: f64) -> f64 {
        if self.drop == 0.0 {
            self.base
        } else {
            logistic(self.base, self.drop, (speed - self.centre) * self.inverse_width)
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
        let law = DragLaw::new(DragModel::DragCrisis, air.density * 0.22 / air.viscosity);
        for v in [5.0, 10.0, 12.19, 14.0, 20.0, 30.0] {
            let eq3 = 0.155 + 0.346 / (1.0 + ((v - 12.19) / 1.309_f64).exp());
            assert!((law.at_speed(v) - eq3).abs() < 1e-14, "{v}");
        }
        // Limits: subcritical 0.501, supercritical 0.155; no NaN at extreme speeds.
        assert!((law.at_speed(0.0) - 0.501).abs() < 1e-3);
        assert_eq!(law.at_speed(1e6), 0.155);
        assert!((DragCrisis::critical_reynolds() - 1.836e5).abs() < 1e2);
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
}
