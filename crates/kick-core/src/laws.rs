//! A family of contact laws beside the paper's (Eq. 20), all behind [`ContactLaw`].
//!
//! - Hysteresis-damped power laws F = k δⁿ (1 + χ δ̇), clamped at F ≥ 0, with χ
//!   chosen from a target restitution e at a reference impact speed V0:
//!   - Hunt–Crossley in the Marhefka–Orin form, χ = 3(1 − e)/(2 V0);
//!   - Lankarani–Nikravesh, χ = 3(1 − e²)/(4 V0) (their D = χ k δⁿ, i.e.
//!     D = 3 k (1 − e²) δⁿ/(4 V0));
//!   - Flores et al. (2011), χ = 8(1 − e)/(5 e V0).
//! - Linear Kelvin–Voigt F = k δ + c δ̇, clamped at F ≥ 0 so it never pulls.
//!
//! Unlike Eq. 20's `c max(δ̇, 0)`, these laws damp during restitution too.
//! The hysteresis laws start at F(0⁺) = 0; the paper's law and Kelvin–Voigt
//! jump to c V0 at first touch.
//!
//! Small-damping energy balance (used to derive the χ formulas and checked
//! by the tests): along the undamped motion ½ μ δ̇² + k δⁿ⁺¹/(n+1) = ½ μ V0²,
//! the loss over one compression/restitution cycle is
//! ΔE = ∮ χ k δⁿ δ̇² dt = (4/3) χ V0 · ½ μ V0², for every n. With
//! e² = 1 − ΔE/(½ μ V0²) this gives 1 − e² = (4/3) χ V0 to first order in χ V0.
//!
//! Exact restitution of the hysteresis laws: with U = k δⁿ⁺¹/(n+1) and
//! v = δ̇, the relative motion (Eq. 18) gives μ v dv/(1 + χ v) = −dU, which
//! no longer contains k or n. Integrating over compression (V0 → 0) and
//! restitution (0 → −V_e) and equating the two U(δ_max):
//! x0 − ln(1 + x0) = −x_e − ln(1 − x_e), x0 = χ V0, x_e = χ V_e, e = x_e/x0,
//! for every k, n and μ. Since x_e < 1, 1 + χ δ̇ stays positive and the clamp
//! never acts in a passive impact.

use crate::error::KickError;
use crate::law::{ContactLaw, PowerLawContact};
use crate::shell::ShellBall;
use serde::{Deserialize, Serialize};

/// Which formula turned a target restitution into the hysteresis factor χ.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum HysteresisModel {
    /// χ = 3(1 − e)/(2 V0) (Hunt–Crossley 1975, Marhefka–Orin 1999 form).
    HuntCrossley,
    /// χ = 3(1 − e²)/(4 V0) (Lankarani–Nikravesh 1990).
    LankaraniNikravesh,
    /// χ = 8(1 − e)/(5 e V0) (Flores, Machado, Silva, Martins 2011).
    Flores,
    /// χ V0 from the exact relation of the module docs, so the simulated
    /// restitution is the target (this workspace; no published formula).
    Exact,
}

impl HysteresisModel {
    /// χ in s/m for restitution `e` at impact speed `v0`.
    pub fn hysteresis_factor(self, e: f64, v0: f64) -> f64 {
        match self {
            HysteresisModel::HuntCrossley => 3.0 * (1.0 - e) / (2.0 * v0),
            HysteresisModel::LankaraniNikravesh => 3.0 * (1.0 - e * e) / (4.0 * v0),
            HysteresisModel::Flores => 8.0 * (1.0 - e) / (5.0 * e * v0),
            HysteresisModel::Exact => exact_hysteresis(e) / v0,
        }
    }
}

/// Restitution of a passive impact of a hysteresis law with x0 = χ V0 ≥ 0:
/// e = x_e/x0 with x_e ∈ (0, 1) the root of
/// x0 − ln(1 + x0) = −x_e − ln(1 − x_e) (module docs); 1 at x0 = 0.
pub fn exact_restitution(x0: f64) -> f64 {
    if !(x0 > 0.0) {
        return 1.0;
    }
    if x0.is_infinite() {
        return 0.0;
    }
    let lhs = x0 - x0.ln_1p();
    // g(0) = lhs > 0, g → −∞ as x_e → 1: one root, bracketed.
    let g = |xe: f64| lhs - (-xe - (-xe).ln_1p());
    let top = 1.0 - 1e-15;
    if g(top) >= 0.0 {
        // x_e = 1 − exp(−(lhs + 1)) to leading order: 1 in f64.
        return 1.0 / x0;
    }
    let xe = crate::roots::brent(g, 0.0, top, 1e-16, 200).map_or(top, |r| r.x);
    (xe / x0).min(1.0)
}

/// The x0 = χ V0 whose exact restitution is `e` ∈ (0, 1]. `exact_restitution`
/// decreases from 1 to 0 and stays below 1/x0 (x_e < 1), so the root lies in [0, 1/e].
pub fn exact_hysteresis(e: f64) -> f64 {
    if e >= 1.0 {
        return 0.0;
    }
    crate::roots::brent(|x0| exact_restitution(x0) - e, 0.0, 1.0 / e, 1e-15 / e, 200).map_or(f64::NAN, |r| r.x)
}

/// F = k δⁿ (1 + χ δ̇) for δ > 0, clamped at ≥ 0; zero for δ ≤ 0.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct HysteresisContact {
    /// k in N/mⁿ.
    pub stiffness: f64,
    /// n.
    pub exponent: f64,
    /// χ in s/m.
    pub hysteresis: f64,
    /// The formula χ came from, with its target e and reference V0.
    pub model: HysteresisModel,
    pub target_restitution: f64,
    pub impact_speed: f64,
}

impl HysteresisContact {
    /// χ from `model` for restitution `e` ∈ (0, 1] at impact speed `v0` > 0.
    pub fn new(model: HysteresisModel, stiffness: f64, exponent: f64, e: f64, v0: f64) -> Result<Self, KickError> {
        check_positive("stiffness", stiffness)?;
        check_positive("exponent", exponent)?;
        check_positive("impact_speed", v0)?;
        check_restitution(e)?;
        Ok(HysteresisContact {
            stiffness,
            exponent,
            hysteresis: model.hysteresis_factor(e, v0),
            model,
            target_restitution: e,
            impact_speed: v0,
        })
    }

    /// Restitution of a passive impact at approach speed `v0` (module docs):
    /// the root x_e ∈ (0, 1) of x_e + ln(1 − x_e) + x0 − ln(1 + x0) = 0, over x0.
    pub fn exact_restitution(&self, v0: f64) -> Result<f64, KickError> {
        check_positive("impact_speed", v0)?;
        Ok(exact_restitution(self.hysteresis * v0))
    }

    /// The unclamped value k δⁿ (1 + χ δ̇) at δ ≥ 0.
    #[inline]
    fn raw(&self, compression: f64, compression_rate: f64) -> f64 {
        self.stiffness * compression.max(0.0).powf(self.exponent) * (1.0 + self.hysteresis * compression_rate)
    }
}

impl ContactLaw for HysteresisContact {
    #[inline]
    fn force(&self, compression: f64, compression_rate: f64) -> f64 {
        if compression > 0.0 {
            // Clamped: a fast-opening contact would otherwise pull (1 + χ δ̇ < 0).
            self.raw(compression, compression_rate).max(0.0)
        } else {
            0.0
        }
    }
    #[inline]
    fn potential(&self, compression: f64) -> f64 {
        let d = compression.max(0.0);
        self.stiffness * d.powf(self.exponent + 1.0) / (self.exponent + 1.0)
    }
    #[inline]
    fn contact_force(&self, compression: f64, compression_rate: f64) -> f64 {
        self.raw(compression, compression_rate).max(0.0)
    }
    /// One power for both (the same values as the two calls).
    #[inline]
    fn elastic_and_contact_force(&self, compression: f64, compression_rate: f64) -> (f64, f64) {
        let (elastic, raw) = self.unclamped_force(compression, compression_rate);
        (elastic, raw.max(0.0))
    }
    #[inline]
    fn unclamped_force(&self, compression: f64, compression_rate: f64) -> (f64, f64) {
        let elastic = if compression > 0.0 { self.stiffness * compression.powf(self.exponent) } else { 0.0 };
        (elastic, elastic * (1.0 + self.hysteresis * compression_rate))
    }
    fn force_gradient(&self, compression: f64, compression_rate: f64) -> (f64, f64) {
        let factor = 1.0 + self.hysteresis * compression_rate;
        if factor <= 0.0 {
            return (0.0, 0.0); // clamped branch: F ≡ 0 nearby
        }
        let d = compression.max(0.0);
        let n = self.exponent;
        let d_delta = if d > 0.0 {
            n * self.stiffness * d.powf(n - 1.0) * factor
        } else if n > 1.0 {
            0.0
        } else if n == 1.0 {
            self.stiffness * factor
        } else {
            f64::INFINITY
        };
        (d_delta, self.stiffness * d.powf(n) * self.hysteresis)
    }
    fn damps_compression_only(&self) -> bool {
        false
    }
}

/// Linear Kelvin–Voigt: F = k δ + c δ̇ for δ > 0, clamped at ≥ 0 (the dashpot
/// would pull near the end of restitution); zero for δ ≤ 0.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct KelvinVoigt {
    /// k in N/m.
    pub stiffness: f64,
    /// c in N s/m.
    pub damping: f64,
}

impl KelvinVoigt {
    pub fn new(stiffness: f64, damping: f64) -> Result<Self, KickError> {
        check_positive("stiffness", stiffness)?;
        if !(damping.is_finite() && damping >= 0.0) {
            return Err(KickError::invalid("damping", damping, "finite and >= 0"));
        }
        Ok(KelvinVoigt { stiffness, damping })
    }

    /// c from the restitution e of the unclamped linear oscillator over half a
    /// damped period, e = exp(−π ζ/√(1 − ζ²)), so ζ = −ln e/√(π² + ln² e) and
    /// c = 2 ζ √(k μ) (Eq. 46). The clamp makes the simulated e differ.
    pub fn from_restitution(stiffness: f64, reduced_mass: f64, e: f64) -> Result<Self, KickError> {
        check_positive("stiffness", stiffness)?;
        check_positive("reduced_mass", reduced_mass)?;
        check_restitution(e)?;
        let l = e.ln();
        let zeta = -l / (std::f64::consts::PI.powi(2) + l * l).sqrt();
        KelvinVoigt::new(stiffness, 2.0 * zeta * (stiffness * reduced_mass).sqrt())
    }

    #[inline]
    fn raw(&self, compression: f64, compression_rate: f64) -> f64 {
        self.stiffness * compression.max(0.0) + self.damping * compression_rate
    }
}

impl ContactLaw for KelvinVoigt {
    #[inline]
    fn force(&self, compression: f64, compression_rate: f64) -> f64 {
        if compression > 0.0 {
            self.raw(compression, compression_rate).max(0.0)
        } else {
            0.0
        }
    }
    #[inline]
    fn potential(&self, compression: f64) -> f64 {
        let d = compression.max(0.0);
        0.5 * self.stiffness * d * d
    }
    #[inline]
    fn contact_force(&self, compression: f64, compression_rate: f64) -> f64 {
        self.raw(compression, compression_rate).max(0.0)
    }
    #[inline]
    fn unclamped_force(&self, compression: f64, compression_rate: f64) -> (f64, f64) {
        (self.stiffness * compression.max(0.0), self.raw(compression, compression_rate))
    }
    fn force_gradient(&self, compression: f64, compression_rate: f64) -> (f64, f64) {
        if self.raw(compression, compression_rate) <= 0.0 {
            (0.0, 0.0)
        } else {
            (self.stiffness, self.damping)
        }
    }
    fn damps_compression_only(&self) -> bool {
        false
    }
}

/// The laws selectable by name.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum LawKind {
    /// The paper's law, Eq. 20.
    PowerLaw,
    HuntCrossley,
    LankaraniNikravesh,
    Flores,
    /// k δⁿ (1 + χ δ̇) with χ from the exact restitution relation.
    HuntCrossleyExact,
    KelvinVoigt,
    /// The pressurised ball ([`ShellBall`]), from the ball's measurable
    /// quantities (inflation pressure, γ, shell stiffness and loss).
    Shell,
}

impl LawKind {
    pub const ALL: [LawKind; 6] = [
        LawKind::PowerLaw,
        LawKind::HuntCrossley,
        LawKind::LankaraniNikravesh,
        LawKind::Flores,
        LawKind::HuntCrossleyExact,
        LawKind::KelvinVoigt,
    ];
    /// Every law selectable by name: [`LawKind::ALL`] and the shell ball.
    /// `ALL` is the family `kick laws` fits to one target restitution and
    /// compares; the shell is not in it, being set by quantities measured on
    /// a ball (its restitution is a prediction, not a target). Derived from
    /// `ALL`, so a law added there is selectable too.
    pub const SELECTABLE: [LawKind; LawKind::ALL.len() + 1] = {
        let mut out = [LawKind::Shell; LawKind::ALL.len() + 1];
        let mut i = 0;
        while i < LawKind::ALL.len() {
            out[i] = LawKind::ALL[i];
            i += 1;
        }
        out
    };
    /// The names of [`LawKind::SELECTABLE`], ", "-separated, derived from it.
    pub const NAMES: &'static str = {
        match std::str::from_utf8(&NAMES_BYTES) {
            Ok(names) => names,
            Err(_) => panic!("law names are ASCII"),
        }
    };

    pub const fn name(self) -> &'static str {
        match self {
            LawKind::PowerLaw => "power-law",
            LawKind::HuntCrossley => "hunt-crossley",
            LawKind::LankaraniNikravesh => "lankarani-nikravesh",
            LawKind::Flores => "flores",
            LawKind::HuntCrossleyExact => "hunt-crossley-exact",
            LawKind::KelvinVoigt => "kelvin-voigt",
            LawKind::Shell => "shell",
        }
    }

    /// Whether this law uses the declared parameter `p` (one of kick-core's
    /// list or another level's): the paper's law k, c and n; the laws of a
    /// target restitution k, n and `restitution`; the shell ball its own
    /// (`shell::BALL_PARAMETERS`), not k, c, n; every parameter that is no
    /// law's (masses, speeds, the 3D kick's, the flight's) always. A sampled
    /// file stores only the parameters its law uses.
    pub fn uses(self, p: &crate::ParameterDef) -> bool {
        let shell = crate::shell::BALL_PARAMETERS.iter().any(|b| b.name == p.name) && p.level == crate::Level::Bounce;
        match p.name {
            _ if shell => self == LawKind::Shell,
            "stiffness" | "exponent" if p.level == crate::Level::Scenario => self != LawKind::Shell,
            "damping" if p.level == crate::Level::Scenario => self == LawKind::PowerLaw,
            "restitution" if p.level == crate::Level::Scenario => !matches!(self, LawKind::PowerLaw | LawKind::Shell),
            _ => true,
        }
    }

    /// Refuse a damping setting this law would ignore: the paper's law
    /// takes `damping` (Eq. 20), every other law takes its damping from the
    /// target `restitution`. `damping` and `restitution` say which of the two
    /// the user gave; one rule for flags, file keys and keywords.
    pub fn check_given(self, damping: bool, restitution: bool) -> Result<(), KickError> {
        let to = format!("law `{}`", self.name());
        match self {
            LawKind::PowerLaw if restitution => Err(KickError::DoesNotApply {
                given: "restitution",
                to,
                reason: "the paper's law takes its damping from `damping` (Eq. 20); a target restitution sets the other laws' damping",
            }),
            LawKind::PowerLaw => Ok(()),
            LawKind::Shell if damping || restitution => Err(KickError::DoesNotApply {
                given: if damping { "damping" } else { "restitution" },
                to,
                reason: "the shell ball's loss is `shell_damping` (calibrated on the FIFA rebound test); its restitution is predicted, not a target",
            }),
            LawKind::Shell => Ok(()),
            _ if damping => Err(KickError::DoesNotApply {
                given: "damping",
                to,
                reason: "this law takes its damping from the target `restitution`; `damping` is the paper's law's (power-law)",
            }),
            _ => Ok(()),
        }
    }

    pub fn from_name(name: &str) -> Result<LawKind, LawError> {
        LawKind::SELECTABLE
            .into_iter()
            .find(|k| k.name() == name)
            .ok_or_else(|| LawError::UnknownLaw { name: name.to_string(), expected: LawKind::NAMES })
    }
}

/// Length of [`LawKind::NAMES`].
const NAMES_LEN: usize = {
    let mut len = 0;
    let mut i = 0;
    while i < LawKind::SELECTABLE.len() {
        len += LawKind::SELECTABLE[i].name().len() + if i > 0 { 2 } else { 0 };
        i += 1;
    }
    len
};

/// The bytes of [`LawKind::NAMES`].
const NAMES_BYTES: [u8; NAMES_LEN] = {
    let mut out = [0u8; NAMES_LEN];
    let mut at = 0;
    let mut i = 0;
    while i < LawKind::SELECTABLE.len() {
        if i > 0 {
            out[at] = b',';
            out[at + 1] = b' ';
            at += 2;
        }
        let name = LawKind::SELECTABLE[i].name().as_bytes();
        let mut j = 0;
        while j < name.len() {
            out[at] = name[j];
            at += 1;
            j += 1;
        }
        i += 1;
    }
    out
};

/// What a law needs besides its name. `damping` is used by the paper's law
/// only; the others take their dissipation from `restitution`, at the
/// reference `impact_speed` (hysteresis laws) or `reduced_mass` (Kelvin–Voigt,
/// whose `linear_stiffness` is in N/m).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct LawParameters {
    pub stiffness: f64,
    pub exponent: f64,
    pub damping: f64,
    pub restitution: f64,
    pub impact_speed: f64,
    pub reduced_mass: f64,
    pub linear_stiffness: f64,
    /// The ball of law `shell` (None: refused under that law).
    #[serde(skip)]
    pub shell: Option<ShellBall>,
}

/// Unknown law name or invalid law parameter.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum LawError {
    #[error("unknown contact law `{name}`: expected one of {expected}")]
    UnknownLaw { name: String, expected: &'static str },
    #[error(transparent)]
    Invalid(#[from] KickError),
}

/// Any of the laws, dispatching [`ContactLaw`] to it.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "law", rename_all = "kebab-case")]
pub enum AnyLaw {
    #[serde(serialize_with = "serialize_power_law")]
    PowerLaw(PowerLawContact),
    Hysteresis(HysteresisContact),
    KelvinVoigt(KelvinVoigt),
    Shell(ShellBall),
}

impl AnyLaw {
    pub fn new(kind: LawKind, p: &LawParameters) -> Result<AnyLaw, LawError> {
        let hysteresis = |model| -> Result<AnyLaw, LawError> {
            Ok(AnyLaw::Hysteresis(HysteresisContact::new(model, p.stiffness, p.exponent, p.restitution, p.impact_speed)?))
        };
        match kind {
            LawKind::PowerLaw => {
                check_positive("stiffness", p.stiffness)?;
                check_positive("exponent", p.exponent)?;
                if !(p.damping.is_finite() && p.damping >= 0.0) {
                    return Err(KickError::invalid("damping", p.damping, "finite and >= 0").into());
                }
                Ok(AnyLaw::PowerLaw(PowerLawContact { stiffness: p.stiffness, damping: p.damping, exponent: p.exponent }))
            }
            LawKind::HuntCrossley => hysteresis(HysteresisModel::HuntCrossley),
            LawKind::LankaraniNikravesh => hysteresis(HysteresisModel::LankaraniNikravesh),
            LawKind::Flores => hysteresis(HysteresisModel::Flores),
            LawKind::HuntCrossleyExact => hysteresis(HysteresisModel::Exact),
            LawKind::KelvinVoigt => {
                Ok(AnyLaw::KelvinVoigt(KelvinVoigt::from_restitution(p.linear_stiffness, p.reduced_mass, p.restitution)?))
            }
            LawKind::Shell => p.shell.map(AnyLaw::Shell).ok_or_else(|| {
                KickError::InvalidParameter { name: "law", value: f64::NAN, requirement: "law `shell` needs the ball (ShellBall)" }.into()
            }),
        }
    }

    pub fn from_name(name: &str, parameters: &LawParameters) -> Result<AnyLaw, LawError> {
        AnyLaw::new(LawKind::from_name(name)?, parameters)
    }

    /// The law's numbers as solved, by name (result files store each as a
    /// typed attribute): k, c, n of the paper's law; k, n, χ, the target e
    /// and reference V0 of a hysteresis law; k (N/m) and c of Kelvin–Voigt.
    pub fn parameters(&self) -> Vec<(&'static str, f64)> {
        match *self {
            AnyLaw::PowerLaw(p) => vec![("stiffness", p.stiffness), ("damping", p.damping), ("exponent", p.exponent)],
            AnyLaw::Hysteresis(h) => vec![
                ("stiffness", h.stiffness),
                ("exponent", h.exponent),
                ("hysteresis", h.hysteresis),
                ("target_restitution", h.target_restitution),
                ("impact_speed", h.impact_speed),
            ],
            AnyLaw::KelvinVoigt(k) => vec![("stiffness", k.stiffness), ("damping", k.damping)],
            AnyLaw::Shell(b) => vec![
                ("inflation_pressure", b.pressure),
                ("ball_radius", b.radius),
                ("atmospheric_pressure", b.atmospheric_pressure),
                ("gas_exponent", b.gas_exponent),
                ("shell_stiffness", b.shell_stiffness),
                ("shell_damping", b.shell_damping),
            ],
        }
    }

    pub fn kind(&self) -> LawKind {
        match self {
            AnyLaw::PowerLaw(_) => LawKind::PowerLaw,
            AnyLaw::Hysteresis(h) => match h.model {
                HysteresisModel::HuntCrossley => LawKind::HuntCrossley,
                HysteresisModel::LankaraniNikravesh => LawKind::LankaraniNikravesh,
                HysteresisModel::Flores => LawKind::Flores,
                HysteresisModel::Exact => LawKind::HuntCrossleyExact,
            },
            AnyLaw::KelvinVoigt(_) => LawKind::KelvinVoigt,
            AnyLaw::Shell(_) => LawKind::Shell,
        }
    }
}

/// `PowerLawContact` has no `Serialize`; write its three fields.
fn serialize_power_law<S: serde::Serializer>(law: &PowerLawContact, serializer: S) -> Result<S::Ok, S::Error> {
    use serde::ser::SerializeStruct;
    let mut s = serializer.serialize_struct("PowerLawContact", 3)?;
    s.serialize_field("stiffness", &law.stiffness)?;
    s.serialize_field("damping", &law.damping)?;
    s.serialize_field("exponent", &law.exponent)?;
    s.end()
}

macro_rules! dispatch {
    ($self:ident, $law:ident => $body:expr) => {
        match $self {
            AnyLaw::PowerLaw($law) => $body,
            AnyLaw::Hysteresis($law) => $body,
            AnyLaw::KelvinVoigt($law) => $body,
            AnyLaw::Shell($law) => $body,
        }
    };
}

/// Every [`ContactLaw`] method forwarded to the law inside, so a law's own
/// overrides (the paper's law's smooth `branch_force` past δ̇ = 0, its shared
/// power in `force_and_gradient`) act through [`AnyLaw`] too. A method added
/// to the trait goes into this list; `any_law_forwards_every_method` checks
/// each one against the law inside.
macro_rules! forward_contact_law {
    ($($(#[$attr:meta])* fn $name:ident(&self $(, $arg:ident: $ty:ty)*) -> $ret:ty;)*) => {
        impl ContactLaw for AnyLaw {
            $(
                $(#[$attr])*
                fn $name(&self $(, $arg: $ty)*) -> $ret {
                    dispatch!(self, law => law.$name($($arg),*))
                }
            )*
        }
    };
}

forward_contact_law! {
    #[inline]
    fn force(&self, compression: f64, compression_rate: f64) -> f64;
    #[inline]
    fn potential(&self, compression: f64) -> f64;
    #[inline]
    fn contact_force(&self, compression: f64, compression_rate: f64) -> f64;
    fn onset_force(&self, approach_speed: f64) -> f64;
    #[inline]
    fn elastic_and_contact_force(&self, compression: f64, compression_rate: f64) -> (f64, f64);
    fn force_gradient(&self, compression: f64, compression_rate: f64) -> (f64, f64);
    #[inline]
    fn force_and_gradient(&self, compression: f64, compression_rate: f64) -> (f64, f64, f64);
    #[inline]
    fn unclamped_force(&self, compression: f64, compression_rate: f64) -> (f64, f64);
    #[inline]
    fn branch_force(&self, compression: f64, compression_rate: f64, compressing: bool) -> (f64, f64);
    #[inline]
    fn branch_force_and_gradient(&self, compression: f64, compression_rate: f64, compressing: bool) -> (f64, f64, f64);
    fn damps_compression_only(&self) -> bool;
    #[inline]
    fn rate_affine(&self, compression: f64, compressing: bool) -> (f64, f64);
}

fn check_positive(name: &'static str, value: f64) -> Result<f64, KickError> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(KickError::invalid(name, value, "finite and > 0"))
    }
}

fn check_restitution(e: f64) -> Result<f64, KickError> {
    if e.is_finite() && e > 0.0 && e <= 1.0 {
        Ok(e)
    } else {
        Err(KickError::invalid("restitution", e, "in (0, 1]"))
    }
}

#[cfg(test)]
mod uses_tests {
    use super::LawKind;
    use crate::parameters::{find, PARAMETERS};

    /// The parameters each law uses: the shell ball no k, c, n or target
    /// restitution; the paper's law no restitution and no ball; the others
    /// no damping; all of them every parameter that is no law's.
    #[test]
    fn each_law_uses_its_own_parameters() {
        let names = |law: LawKind| -> Vec<&str> { PARAMETERS.iter().filter(|p| !law.uses(p)).map(|p| p.name).collect() };
        let ball = ["inflation_pressure", "gas_exponent", "shell_stiffness", "shell_damping"];
        assert_eq!(names(LawKind::Shell), ["stiffness", "damping", "exponent", "restitution"]);
        let mut paper = vec!["restitution"];
        paper.extend(ball);
        assert_eq!(names(LawKind::PowerLaw), paper);
        let mut others = vec!["damping"];
        others.extend(ball);
        assert_eq!(names(LawKind::Flores), others);
        assert!(LawKind::Shell.uses(find("foot_speed").unwrap()) && LawKind::Shell.uses(find("offset").unwrap()));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::test_support::{laws, simpson};

    /// Analytic gradients against central differences of the force itself,
    /// away from the kinks (δ = 0, the clamp, δ̇ = 0 for Eq. 20).
    #[test]
    fn force_gradient_matches_finite_differences() {
        for law in laws() {
            for &(d, r) in &[(0.01, 5.0), (0.02, -3.0), (0.028, 0.7), (0.005, -1.0)] {
                let (gd, gr) = law.force_gradient(d, r);
                let (hd, hr) = (1e-6 * d, 1e-5);
                let fd = (law.contact_force(d + hd, r) - law.contact_force(d - hd, r)) / (2.0 * hd);
                let fr = (law.contact_force(d, r + hr) - law.contact_force(d, r - hr)) / (2.0 * hr);
                // Central differences: truncation O(h²) ≈ 1e-12 relative,
                // rounding ≈ ε F/h ≈ 1e-10 relative to the gradient scale.
                let scale_d = gd.abs().max(law.contact_force(d, r) / d);
                let scale_r = gr.abs().max(1e-3 * law.contact_force(d, 0.0));
                assert!((gd - fd).abs() <= 1e-7 * scale_d, "{:?} d={d} r={r}: {gd} vs {fd}", law.kind());
                assert!((gr - fr).abs() <= 1e-7 * scale_r, "{:?} d={d} r={r}: {gr} vs {fr}", law.kind());
            }
        }
    }

    #[test]
    fn no_tensile_force_anywhere() {
        for law in laws() {
            for i in 0..=200 {
                let d = -0.01 + 0.05 * i as f64 / 200.0;
                for j in 0..=200 {
                    let r = -200.0 + 400.0 * j as f64 / 200.0;
                    assert!(law.force(d, r) >= 0.0, "{:?} pulls at δ={d}, δ̇={r}", law.kind());
                    assert!(law.contact_force(d.max(0.0), r) >= 0.0);
                }
            }
        }
    }

    #[test]
    fn onset_force_jumps_only_for_viscous_dashpots() {
        let shell = AnyLaw::Shell(ShellBall::default_with_radius(crate::DEFAULT_BALL_RADIUS).unwrap());
        for law in laws().into_iter().chain([shell]) {
            let onset = law.onset_force(22.0);
            match law {
                // The loss multiplies an elastic force that is 0 at first touch.
                AnyLaw::Hysteresis(_) | AnyLaw::Shell(_) => assert_eq!(onset, 0.0),
                AnyLaw::PowerLaw(p) => assert_eq!(onset, p.damping * 22.0),
                AnyLaw::KelvinVoigt(k) => assert_eq!(onset, k.damping * 22.0),
            }
        }
    }

    #[test]
    fn potential_is_the_integral_of_the_elastic_force() {
        // U(δ) = ∫₀^δ F(s, 0) ds (Eq. 22) by composite Simpson; sⁿ is not smooth
        // at 0, so the error is O(h^(n+1)) ≈ 1e-8 relative with 20 000 panels.
        for law in laws() {
            let d = 0.02;
            let integral = simpson(|s| law.force(s, 0.0), d, 20_000);
            let u = law.potential(d);
            assert!((integral - u).abs() <= 1e-6 * u, "{:?}: {integral} vs {u}", law.kind());
        }
    }

    /// Series of the exact relation: 1 − e² = (2/3) x0 (1 + e³) + O(x0²)
    /// → (4/3) x0 as x0 → 0; and x_e → 1 (e → 1/x0) as x0 → ∞.
    #[test]
    fn exact_restitution_limits() {
        for x0 in [1e-4, 1e-3] {
            let law = HysteresisContact::new(HysteresisModel::LankaraniNikravesh, 1.0, 1.5, 1.0, 1.0)
                .map(|mut l| {
                    l.hysteresis = x0;
                    l
                })
                .unwrap();
            let e = law.exact_restitution(1.0).unwrap();
            let ratio = (1.0 - e * e) / (4.0 / 3.0 * x0);
            assert!((ratio - 1.0).abs() < 2.0 * x0, "x0={x0}: {ratio}");
        }
        let mut law = HysteresisContact::new(HysteresisModel::Flores, 1.0, 1.0, 0.5, 1.0).unwrap();
        law.hysteresis = 1e6;
        let e = law.exact_restitution(1.0).unwrap();
        assert!((e * 1e6 - 1.0).abs() < 1e-3, "{e}");
    }

    #[test]
    fn exact_hysteresis_inverts_exact_restitution() {
        for e in [1.0, 0.99, 0.9, 0.662, 0.5, 0.3, 0.1, 0.01] {
            let x0 = exact_hysteresis(e);
            assert!((exact_restitution(x0) - e).abs() < 1e-12, "e={e}: x0={x0}");
        }
    }

    /// `rate_affine` is each law's force on its branch: F(δ, v) = E + D v for
    /// several rates, before the clamp (where the law does not pull).
    #[test]
    fn every_law_is_affine_in_the_rate_on_its_branch() {
        let shell = AnyLaw::Shell(ShellBall::default_with_radius(crate::DEFAULT_BALL_RADIUS).unwrap());
        for law in laws().into_iter().chain([shell]) {
            for &d in &[0.002, 0.01, 0.03] {
                for compressing in [true, false] {
                    let (e, slope) = law.rate_affine(d, compressing);
                    for &v in &[-3.0, 0.5, 7.0, 20.0] {
                        let (_, raw) = law.unclamped_force(d, v);
                        let branch = if matches!(law, AnyLaw::PowerLaw(_)) { law.branch_force(d, v, compressing).1 } else { raw };
                        assert!((branch - (e + slope * v)).abs() <= 1e-12 * branch.abs().max(e), "{:?} {d} {v} {compressing}", law.kind());
                    }
                }
            }
        }
    }

    /// Each method of `AnyLaw` gives exactly what the law inside gives,
    /// including the paper's law's overrides (before forwarding, `AnyLaw`
    /// fell back to the trait's defaults for the branch forces, which clip
    /// δ̇ at 0 inside the compression phase).
    #[test]
    fn any_law_forwards_every_method() {
        fn same<L: ContactLaw>(any: &AnyLaw, law: &L) {
            for &d in &[0.0, 1e-9, 0.01, 0.028] {
                for &r in &[-5.0, -1e-3, 0.0, 0.7, 22.0] {
                    let kind = any.kind();
                    assert_eq!(any.force(d, r).to_bits(), law.force(d, r).to_bits(), "{kind:?} force");
                    assert_eq!(any.contact_force(d, r).to_bits(), law.contact_force(d, r).to_bits(), "{kind:?}");
                    assert_eq!(any.elastic_and_contact_force(d, r), law.elastic_and_contact_force(d, r), "{kind:?}");
                    assert_eq!(any.force_gradient(d, r), law.force_gradient(d, r), "{kind:?}");
                    assert_eq!(any.force_and_gradient(d, r), law.force_and_gradient(d, r), "{kind:?}");
                    assert_eq!(any.unclamped_force(d, r), law.unclamped_force(d, r), "{kind:?}");
                    for compressing in [true, false] {
                        assert_eq!(any.branch_force(d, r, compressing), law.branch_force(d, r, compressing), "{kind:?} {d} {r}");
                        assert_eq!(
                            any.branch_force_and_gradient(d, r, compressing),
                            law.branch_force_and_gradient(d, r, compressing),
                            "{kind:?} {d} {r}"
                        );
                    }
                }
                assert_eq!(any.potential(d).to_bits(), law.potential(d).to_bits());
            }
            assert_eq!(any.onset_force(22.0), law.onset_force(22.0));
            for compressing in [true, false] {
                assert_eq!(any.rate_affine(0.01, compressing), law.rate_affine(0.01, compressing));
            }
            assert_eq!(any.damps_compression_only(), law.damps_compression_only());
        }
        let shell = AnyLaw::Shell(ShellBall::default_with_radius(crate::DEFAULT_BALL_RADIUS).unwrap());
        for any in laws().into_iter().chain([shell]) {
            match any {
                AnyLaw::PowerLaw(law) => same(&any, &law),
                AnyLaw::Hysteresis(law) => same(&any, &law),
                AnyLaw::KelvinVoigt(law) => same(&any, &law),
                AnyLaw::Shell(law) => same(&any, &law),
            }
        }
        // The case that differed: compressing with δ̇ < 0 keeps the dashpot on.
        let AnyLaw::PowerLaw(paper) = laws()[0] else { panic!("the paper's law first") };
        assert_eq!(AnyLaw::PowerLaw(paper).branch_force(0.01, -1.0, true).1, paper.elastic_force(0.01) - paper.damping);
    }

    /// Every law is selectable by its name, once, and the list of names in
    /// errors is the list of selectable laws; the match has no wildcard, so a
    /// new law must be placed here (and in `ALL` or as the shell) to compile.
    #[test]
    fn every_law_is_selectable_once_and_named_in_names() {
        for kind in LawKind::SELECTABLE {
            let in_family = match kind {
                LawKind::PowerLaw
                | LawKind::HuntCrossley
                | LawKind::LankaraniNikravesh
                | LawKind::Flores
                | LawKind::HuntCrossleyExact
                | LawKind::KelvinVoigt => true,
                LawKind::Shell => false,
            };
            assert_eq!(LawKind::ALL.contains(&kind), in_family, "{kind:?}");
            assert_eq!(LawKind::SELECTABLE.iter().filter(|&&k| k == kind).count(), 1, "{kind:?}");
            assert_eq!(LawKind::from_name(kind.name()).unwrap(), kind);
        }
        assert_eq!(LawKind::SELECTABLE.len(), 7);
        let names: Vec<&str> = LawKind::SELECTABLE.iter().map(|k| k.name()).collect();
        assert_eq!(LawKind::NAMES, names.join(", "));
    }

    #[test]
    fn names_round_trip_and_bad_input_is_refused() {
        for kind in LawKind::ALL {
            assert_eq!(LawKind::from_name(kind.name()).unwrap(), kind);
        }
        assert!(matches!(LawKind::from_name("hertz"), Err(LawError::UnknownLaw { .. })));
        let mut p = LawParameters {
            stiffness: 1.0,
            exponent: 1.0,
            damping: 0.0,
            restitution: 1.2,
            impact_speed: 1.0,
            reduced_mass: 1.0,
            linear_stiffness: 1.0,
            shell: None,
        };
        assert!(AnyLaw::new(LawKind::HuntCrossley, &p).is_err());
        p.restitution = 0.5;
        p.impact_speed = f64::NAN;
        assert!(AnyLaw::new(LawKind::Flores, &p).is_err());
        p.impact_speed = 1.0;
        assert!(AnyLaw::new(LawKind::Flores, &p).is_ok());
    }
}
