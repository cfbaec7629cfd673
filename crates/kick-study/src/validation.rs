//! The validation chapter: every comparison of the model with a published
//! measurement (`experiments/validation/measurements.toml`), written to
//! `results/validation/validation.json` and drawn as `paper/validation.md`.
//!
//! The rules ([`rows`], issues 23 and 31): every row has a role
//! (calibration, check, prediction, sensitivity statement, model
//! comparison); the model runs at the measurement's own conditions (a force
//! or contact time at the measured ball speed, through
//! [`kick_identify::validation::with_ball_speed`]; the mechanical limb at its
//! own paired foot and ball speeds; a spin where the ball leaves at the
//! measured speed) and the row says them; every kick runs with the declared
//! foot [`VALIDATION_FOOT`], and a row whose verdict hinges on that assumed
//! foot is a sensitivity statement; the count takes each distinct
//! measurement and model once, predictions read in the source with an
//! uncertainty it states, by z = (model − measured)/u. The reasons each
//! comparison agrees or misses are in `experiments/validation/NOTES.md`.

pub mod rows;

/// How close a patch kick's offset is found to the one asked for, m.
pub use kick_3d::validation::OFFSET_TOLERANCE;

use crate::printable::Printable;
use crate::units::three;
/// |ω| below this is printed as zero to rounding, rad/s.
use kick_3d::validation::{largest_spin, patch_spin_point, spin_curve, spin_point, SpinPoint, ASSUMED_INSTEP_RADIUS, REFERENCE_FRICTION};
pub use kick_core::measurements::{Checked, Measured};
use kick_core::measurements::{Comparison, Measurements};
use kick_core::{short, LawKind, Parameter, Scenario, ShellBall, Value, DEFAULT_BALL_RADIUS};
use kick_flight::validation::{DragCrisisModel, FreeKicks, FREE_KICK_DISTANCE, FREE_KICK_ELEVATION};
use kick_identify::validation::{contact_model, with_ball_speed, ContactModel};
use rows::{headline, Headline, Role, Row};
use serde::Serialize;

use std::path::PathBuf;

const NEEDED_BY: &str = "the validation chapter (kick_study::validation)";
/// Drop height of the FIFA rebound test, m.
pub const FIFA_DROP_HEIGHT: f64 = 2.0;

/// The foot every kick of the chapter runs with but the realistic foot's
/// own 1D rows ([`laws`]): Table 1's, the paper's level.
pub const VALIDATION_FOOT: Foot = Foot::Table1;

/// A foot the kick rows can run with.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Foot {
    /// Table 1's rigid foot: 3 kg of effective mass at 22 m/s, the paper's
    /// values, set for none of these kicks.
    Table1,
    /// The realistic foot (`leg = true`): the leg's apparent mass along the
    /// line of motion at its default pose (Eq. 11) and the boot identified
    /// from the mechanical limb's fastest kick in series.
    Leg,
}

impl Foot {
    pub fn name(self) -> &'static str {
        match self {
            Foot::Table1 => "Table 1's rigid foot, 3 kg effective mass (assumed)",
            Foot::Leg => {
                "the leg at its default pose (knee 30°, ankle 60°, thigh 10°: assumed; its apparent mass along the line of motion, Eq. 11) \
                 with the boot identified from the limb's fastest kick in series"
            }
        }
    }
    /// Not measured or derived for the kicks compared: rows whose verdict
    /// hinges on it are sensitivity statements.
    pub fn assumed(self) -> bool {
        match self {
            // The leg's pose is assumed, and no kick compared measured its foot.
            Foot::Table1 | Foot::Leg => true,
        }
    }
    /// `s` with this foot.
    pub fn apply(self, s: &Scenario) -> Result<Scenario, kick_core::KickError> {
        match self {
            Foot::Table1 => Ok(*s),
            Foot::Leg => {
                s.on_foot(kick_core::Foot { leg: Some(kick_core::leg::LegPose::DEFAULT), boot: Some(kick_core::boot::IDENTIFIED) })
            }
        }
    }
}

/// The patch kicks' offsets: [`kick_study::patch`]'s grid inside the ball, so
/// the validation page and paper/3d.md quote the same kicks.
pub fn patch_offsets() -> Vec<f64> {
    crate::patch::offsets().into_iter().filter(|&e| e < DEFAULT_BALL_RADIUS).collect()
}

/// One law the 1D kick is run with, on its foot.
#[derive(Debug, Clone, Copy)]
struct Law {
    name: &'static str,
    scenario: Scenario,
    pressure: Option<f64>,
    foot: Foot,
}

/// The two normal laws of the 1D kick, each with [`VALIDATION_FOOT`], and
/// the shell ball on the realistic foot ([`Foot::Leg`]), whose boot the
/// limb's fastest kick set (those rows are its calibration).
fn laws() -> Result<[Law; 3], ValidationError> {
    let base = VALIDATION_FOOT.apply(&Scenario::baseline())?;
    let ball = ShellBall::default_with_radius(DEFAULT_BALL_RADIUS)?;
    let leg = Foot::Leg.apply(&Scenario::baseline())?;
    Ok([
        Law { name: "paper's law (Table 1)", scenario: base, pressure: None, foot: VALIDATION_FOOT },
        Law { name: "shell ball (FIFA-calibrated)", scenario: base.with_shell(ball), pressure: Some(ball.pressure), foot: VALIDATION_FOOT },
        Law {
            name: "shell ball (FIFA-calibrated) on the leg and its boot",
            scenario: leg.with_shell(ball),
            pressure: Some(ball.pressure),
            foot: Foot::Leg,
        },
    ])
}

/// The conditions of a 1D model run, in words.
fn conditions(law: &Law, s: &Scenario, why_speed: &str) -> String {
    let pressure = law.pressure.map_or(String::new(), |p| format!(", {} bar", short(p / 1e5)));
    let boot =
        s.boot().map_or(String::new(), |b| format!(" through the boot (k_b {} N/m, c_b {} N s/m)", short(b.stiffness), short(b.damping)));
    format!(
        "instep, foot {} kg{boot} at {:.2} m/s{why_speed}; ball {} kg, R {} m{pressure}, at rest",
        short(s.effective_foot_mass()),
        s.foot_speed(),
        short(s.ball_mass()),
        DEFAULT_BALL_RADIUS
    )
}

/// An identified parameter (or why it is not).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Identified {
    pub law: String,
    pub parameter: String,
    pub unit: String,
    /// None: not identified.
    pub value: Option<f64>,
    /// One standard uncertainty, when the targets carry one.
    pub sigma: Option<f64>,
    /// The targets used (like-for-like soccer instep measurements only).
    pub targets: String,
    pub note: String,
}

/// The free kicks with the aerodynamics at launch of each.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FreeKicksAtLaunch {
    #[serde(flatten)]
    pub kicks: FreeKicks,
    /// Re, S, C_D, C_L at launch of each kick (the flight's own launch report), in `kicks.kicks` order.
    pub launch: Vec<kick_flight::Aerodynamics>,
    /// The circle estimate's role: a check of the integrator (same C_L), not a measurement.
    pub circle_estimate_role: Role,
}

/// The curve kicks: the sweep and the rows.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CurveKicks {
    /// Spin against offset at μ = 0, 0.5 and 1 (the paper's law, [`VALIDATION_FOOT`] at 22 m/s).
    pub curves: Vec<Vec<SpinPoint>>,
    /// The largest spin at μ = 0.5 and at μ = 1 (paper's law).
    pub largest: Vec<SpinPoint>,
    /// The kicks at the offsets where the μ = 0.5 ball leaves at the measured speeds.
    pub at_measured_speed: Vec<SpinPoint>,
    pub rows: Vec<Row>,
}

/// Every comparison and the model runs behind them.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Validation {
    /// The measurement file read.
    pub measurements_file: String,
    /// Sources listed (every source of the file; each row's sources among them).
    pub sources: usize,
    pub measurements: usize,
    /// The foot every kick ran with.
    pub foot: Foot,
    /// The count: distinct (measurement, model) predictions counted, and the rows by role.
    pub headline: Headline,
    /// The ball alone: the FIFA rebound (calibration) and Law 2 (checks).
    pub ball: Vec<Row>,
    /// The 1D instep kick under both laws.
    pub contact: Vec<Row>,
    /// Stiffness and foot mass from like-for-like soccer instep targets.
    pub implied: Vec<Identified>,
    pub curve_kicks: CurveKicks,
    /// The default C_D(Re)'s crisis.
    pub drag_crisis_model: DragCrisisModel,
    pub flight: Vec<Row>,
    /// Measured trajectories flown from their launch.
    pub measured_flights: Vec<Row>,
    pub free_kicks: FreeKicksAtLaunch,
    /// Every source of the file: (key, citation).
    pub citations: Vec<(String, String)>,
    /// Measurement keys by how far they were checked: (status, keys).
    pub checked: Vec<(String, Vec<String>)>,
    #[serde(skip)]
    pub written: Vec<PathBuf>,
}

/// Why the validation could not be made: a measurement it reads missing or
/// without a number (the key named), or a model run that failed (the
/// model's own error).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ValidationError {
    #[error(transparent)]
    Measurements(#[from] kick_core::measurements::MeasurementError),
    #[error(transparent)]
    Kick(#[from] kick_core::KickError),
    #[error(transparent)]
    Kick3d(#[from] kick_3d::Kick3dError),
    #[error(transparent)]
    Parameter(#[from] kick_core::parameters::ParameterError),
    #[error(transparent)]
    FlightValidation(#[from] kick_flight::validation::FlightValidationError),
    #[error(transparent)]
    Identify(#[from] kick_identify::validation::ValidationError),
    #[error(transparent)]
    Flight(#[from] kick_flight::FlightError),
    #[error(transparent)]
    CurveKick(#[from] kick_3d::validation::CurveKickError),
    #[error(transparent)]
    IdentifyFit(#[from] kick_identify::IdentifyError),
    /// A measurement read as a number that has none (a claim in words).
    #[error("`{key}` has no number")]
    NoNumber { key: String },
    /// Two measurements whose ratio is undefined: `what` says which must be > 0.
    #[error("{what} must be > 0")]
    ZeroRatio { what: &'static str },
    /// The FIFA drop that gave no rebound height.
    #[error("the FIFA drop gave no rebound height")]
    NoRebound,
    /// No offset of the spin curve sends the ball off at `speed` (m/s).
    #[error("no offset sends the ball off at {speed} m/s")]
    NoOffset { speed: f64 },
    /// A root search on the model that did not converge (`what`).
    #[error("{what} failed")]
    Search { what: &'static str },
    /// A measurement the validation reads as a speed, with none (`what`).
    #[error("no {what}")]
    NoSpeed { what: &'static str },
}

/// The front ends and the page writers still returning text print the message.
impl From<ValidationError> for String {
    fn from(e: ValidationError) -> String {
        e.to_string()
    }
}

/// The value of `input` in [`low`, `high`] (searched in its logarithm) at
/// which `model(input)` meets `target`, when one does.
fn meeting(target: f64, low: f64, high: f64, model: impl Fn(f64) -> Result<f64, ValidationError>) -> Option<f64> {
    let f = |ln_x: f64| model(ln_x.exp()).map_or(f64::NAN, |y| y - target);
    kick_core::roots::brent(f, low.ln(), high.ln(), 1e-10, 200).map(|r| r.x.exp())
}

/// "m_f = 1.234 kg meets it" or why none does.
fn mass_meeting(target: f64, model: impl Fn(f64) -> Result<f64, ValidationError>) -> Option<String> {
    Some(match meeting(target, 0.1, 100.0, model) {
        Some(m) => format!("m_f = {} kg meets it", three(m)),
        None => "no foot mass in 0.1–100 kg meets it".into(),
    })
}

/// The ball alone: the FIFA rebound of the shell ball (what its loss β was
/// set on) and the default ball against Law 2.
fn ball_rows(m: &Measurements) -> Result<Vec<Row>, ValidationError> {
    let mut spec = kick_bounce::BounceSpec::default();
    spec.set("drop_height", Value::Number(FIFA_DROP_HEIGHT))?;
    let bounce = kick_bounce::run(&spec)?;
    let ball = ShellBall::default_with_radius(DEFAULT_BALL_RADIUS)?;
    let rebound = bounce.rebound_height.ok_or(ValidationError::NoRebound)?;
    let mut rows = vec![Row::new(
        m,
        Role::Calibration,
        "shell ball (kick_bounce::run)",
        format!(
            "dropped {FIFA_DROP_HEIGHT} m onto a rigid plate ({:.3} m/s), {} bar, gravity on; contact {:.2} ms, peak {} N",
            bounce.impact_velocity[2].abs(),
            short(ball.pressure / 1e5),
            1e3 * bounce.contact_time,
            short(bounce.peak_force)
        ),
        Comparison::new(
            "rebound height",
            m.measured("fifa_rebound_height", NEEDED_BY)?,
            rebound,
            "β was identified from the band's middle: the 2 m drop, gravity on during contact as in the test, \
             rebounds 140 cm",
        ),
    )
    .sets(format!("shell loss β = {} Pa s/m (crates/kick-bounce/SOURCES.md)", short(ball.shell_damping)))];
    for r in kick_flight::validation::ball_comparisons(m)? {
        rows.push(Row::new(m, Role::Check, "default ball", "Table 1's ball, R = 0.11 m", r));
    }
    Ok(rows)
}

/// The 1D instep kick beside every contact measurement, under both laws.
fn contact_rows(m: &Measurements) -> Result<Vec<Row>, ValidationError> {
    let get = |key: &str| m.measured(key, NEEDED_BY);
    let mid = |key: &str| -> Result<f64, ValidationError> {
        get(key)?.midpoint().ok_or_else(|| ValidationError::NoNumber { key: key.to_string() })
    };
    let tol_speed = mid("ball_speed_tol2002")?;
    let nunome_speed = mid("ball_speed_instep_nunome2002")?;
    let mut rows = Vec::new();
    for law in laws()? {
        let (s, foot) = (law.scenario, law.foot);
        let run = |s: &Scenario| contact_model(s);
        let at_speed = |s: &Scenario, v: f64| -> Result<(Scenario, ContactModel), ValidationError> {
            let matched = with_ball_speed(s, v)?;
            Ok((matched, run(&matched)?))
        };
        let with_mass = |s: &Scenario, mass: f64| s.with(Parameter::FootMass, mass);
        let row = |role, c: &Scenario, why: &str, comparison| Row::new(m, role, law.name, conditions(&law, c, why), comparison);
        let base = run(&s)?;
        let assumed = "the assumed foot (mass and speed): no foot speed goes with the pooled range";
        let pooled = "pooled over soccer instep kicks and rugby and Australian-football punts";
        let short_contact = match (law.pressure, foot) {
            (None, _) => "a rigid sphere on a rigid instep through Table 1's stiff power law; a real ball wraps around the instep and its shell bends, which is softer and lasts longer",
            (Some(_), Foot::Table1) => "the pressurised ball flattens on a flat, rigid instep (pressure times patch area); the foot's soft tissue and a curved instep, not modelled, lengthen a real contact",
            (Some(_), Foot::Leg) => "the pressurised ball flattens on a flat instep behind the boot's layer, which the limb's fastest kick set (a linear layer, so the contact time hardly moves with speed); a curved instep is not modelled",
        };
        rows.push(
            row(
                Role::Prediction,
                &s,
                " (Table 1's)",
                Comparison::new("contact time", get("contact_time_instep")?, base.contact_time, short_contact),
            )
            .hinges_on(foot, assumed, None)
            .not_counted(pooled),
        );
        rows.push(
            row(
                Role::Prediction,
                &s,
                " (Table 1's)",
                Comparison::new(
                    "ball travel on the foot",
                    get("ball_travel_instep")?,
                    base.ball_travel,
                    "the centre-of-mass drift m_f v_f t_c/(m_f + m_b) (no drive): it scales with the assumed foot speed and the contact time",
                ),
            )
            .hinges_on(foot, assumed, None)
            .not_counted(pooled),
        );
        // The mechanical kicking limb at its paired foot and ball speeds.
        for (end, foot_key, ball_key, time_key, travel_key) in [
            ("slowest", "foot_speed_limb_slow", "ball_speed_limb_slow", "contact_time_limb_slow", "contact_distance_limb_slow"),
            ("fastest", "foot_speed_limb_fast", "ball_speed_limb_fast", "contact_time_limb_fast", "contact_distance_limb_fast"),
        ] {
            let v = mid(foot_key)?;
            let c = s.with(Parameter::FootSpeed, v)?;
            let k = run(&c)?;
            let why = format!(" (the limb's {end} foot)");
            let af = "an Australian-football ball in the limb, the model's soccer ball here";
            let limb_mass = "the foot's mass (the limb's own effective mass was not read)";
            let ratio = Measured::ratio(&get(ball_key)?, &get(foot_key)?).ok_or(ValidationError::ZeroRatio { what: "limb speeds" })?;
            let target = ratio.midpoint().unwrap_or(f64::NAN);
            let e = k.speed_ratio * (c.effective_foot_mass() + c.ball_mass()) / c.effective_foot_mass() - 1.0;
            // On the leg, the fastest kick's contact time and restitution set
            // the boot. The ratio row is not among them: the restitution set
            // there is the COR band's centre, and the ratio then hinges on the
            // assumed foot mass (a sensitivity, not a calibration).
            let sets_boot = foot == Foot::Leg && end == "fastest";
            let role = if sets_boot { Role::Calibration } else { Role::Prediction };
            let calibrated = |r: Row| {
                if sets_boot {
                    r.sets("the boot's k_b and c_b (kick_compliant::boot::identify: this contact time and the COR band's centre 0.725)")
                } else {
                    r
                }
            };
            rows.push(
                row(
                    Role::Prediction,
                    &c,
                    &why,
                    Comparison::new(
                        format!("ball/foot speed, limb, {end}"),
                        ratio,
                        k.speed_ratio,
                        format!(
                            "a rigid foot gives (1 + e) m_f/(m_f + m_b): model e = {e:.3} (the limb's measured COR 0.66-0.79, no pairing with speed published{}); {af}",
                            if sets_boot { "; the boot's identification set it to the band's centre, the foot's mass stays assumed" } else { "" }
                        ),
                    ),
                )
                .hinges_on(foot, limb_mass, mass_meeting(target, |mass| Ok(run(&with_mass(&c, mass)?)?.speed_ratio))),
            );
            let t = mid(time_key)?;
            rows.push(calibrated(
                row(role, &c, &why, Comparison::new(format!("contact time, limb, {end}"), get(time_key)?, k.contact_time, af)).hinges_on(
                    foot,
                    limb_mass,
                    mass_meeting(t, |mass| Ok(run(&with_mass(&c, mass)?)?.contact_time)),
                ),
            ));
            let d = mid(travel_key)?;
            rows.push(
                row(Role::Prediction, &c, &why, Comparison::new(format!("ball travel, limb, {end}"), get(travel_key)?, k.ball_travel, af))
                    .hinges_on(foot, limb_mass, mass_meeting(d, |mass| Ok(run(&with_mass(&c, mass)?)?.ball_travel))),
            );
        }
        // Forces at the ball speed measured with them.
        let (tol, tol_model) = at_speed(&s, tol_speed)?;
        let tol_why = format!(" (lowered so the ball leaves at Tol et al.'s {tol_speed} m/s)");
        let tol_force = mid("mean_force_tol2002")?;
        rows.push(
            row(
                Role::Prediction,
                &tol,
                &tol_why,
                Comparison::new(
                    "mean force over contact",
                    get("mean_force_tol2002")?,
                    tol_model.mean_force,
                    format!(
                        "the impulse matches theirs (m_b x {tol_speed} m/s), so the force ratio is the inverse contact-time ratio (model {:.2} ms, theirs m_b v/F = {:.2} ms)",
                        1e3 * tol_model.contact_time,
                        1e3 * tol.ball_mass() * tol_speed / tol_force
                    ),
                ),
            )
            .hinges_on(
                foot,
                "the foot's mass (none was measured with these kicks; the foot speed is matched to the ball speed)",
                mass_meeting(tol_force, |mass| Ok(at_speed(&with_mass(&s, mass)?, tol_speed)?.1.mean_force)),
            ),
        );
        let (nunome, nunome_model) = at_speed(&s, nunome_speed)?;
        let nunome_why =
            format!(" (the source read gives no ball speed with this force: lowered so the ball leaves at Nunome et al.'s (2002) instep {nunome_speed} m/s)");
        rows.push(
            row(
                Role::ModelComparison,
                &nunome,
                &nunome_why,
                Comparison::new(
                    "peak force",
                    get("peak_force_instep_asai2002")?,
                    nunome_model.peak_force,
                    "from 4500 Hz video and a finite-element simulation, not a force measurement",
                ),
            )
            .with_foot(foot),
        );
        rows.push(
            row(
                Role::Prediction,
                &nunome,
                &nunome_why,
                Comparison::new(
                    "peak force",
                    get("peak_force_shinkai2009")?,
                    nunome_model.peak_force,
                    "from the motion of the ball's centre of gravity in ultra-high-speed video",
                ),
            )
            .hinges_on(foot, "the ball speed (none was read with this force) and the foot's mass", None),
        );
        for key in ["ball_speed_max_instep", "ball_speed_instep_nunome2002"] {
            let middle = mid(key)?;
            let foot_speed = with_ball_speed(&s, middle)?.foot_speed();
            rows.push(
                row(
                    Role::Prediction,
                    &s,
                    " (Table 1's)",
                    Comparison::new("ball speed after contact", get(key)?, base.ball_speed, "set by m_f, v_f and the restitution"),
                )
                .hinges_on(
                    foot,
                    "the foot's speed (none was measured with these ball speeds)",
                    Some(format!("v_f = {} m/s meets the middle, {} m/s", three(foot_speed), short(middle))),
                ),
            );
        }
        let pulse = Measured::ratio(&get("peak_force_punt")?, &get("mean_force_punt")?)
            .ok_or(ValidationError::ZeroRatio { what: "mean_force_punt" })?;
        rows.push(
            row(
                Role::Check,
                &s,
                " (Table 1's)",
                Comparison::new(
                    "peak / mean force (pulse shape)",
                    pulse,
                    base.peak_to_mean,
                    "measured in rugby-league punt kicks, not a soccer instep kick: a check of the pulse's shape only (a half sine gives pi/2)",
                ),
            )
            .with_foot(foot),
        );
    }
    Ok(rows)
}

/// k from Tol et al.'s soccer instep kicks: the contact time m_b v/F̄ at
/// their ball speed, the foot speed lowered until the ball leaves at it, the
/// foot's mass [`VALIDATION_FOOT`]'s.
fn identify(m: &Measurements) -> Result<Vec<Identified>, ValidationError> {
    let get = |key: &str| m.measured(key, NEEDED_BY)?.midpoint().ok_or_else(|| ValidationError::NoNumber { key: key.to_string() });
    let (speed, force) = (get("ball_speed_tol2002")?, get("mean_force_tol2002")?);
    let base = VALIDATION_FOOT.apply(&Scenario::baseline())?;
    let target = base.ball_mass() * speed / force;
    use kick_core::Solver as _;
    let restitution = kick_compliant::Accurate::default().solve(&base)?.restitution;
    let hunt_crossley = base.with_law(LawKind::HuntCrossleyExact, Some(restitution))?;
    let targets = format!(
        "Tol et al. (2002), 150 instep kicks by 15 elite players: ball {speed} m/s, mean force {force} N, so a contact of m_b v/F = {:.3} ms",
        1e3 * target
    );
    let mut out = Vec::new();
    for (name, s) in [("paper's law, c = 120 N s/m", base), (&*format!("Hunt-Crossley (exact), e = {}", short(restitution)), hunt_crossley)]
    {
        let contact = |ln_k: f64| -> f64 {
            let run = || -> Result<f64, ValidationError> {
                let c = s.with(Parameter::Stiffness, ln_k.exp())?;
                Ok(contact_model(&with_ball_speed(&c, speed)?)?.contact_time - target)
            };
            run().unwrap_or(f64::NAN)
        };
        let k = kick_core::roots::brent(contact, 1e3f64.ln(), 1e7f64.ln(), 1e-12, 200).map(|r| r.x.exp());
        out.push(Identified {
            law: name.to_string(),
            parameter: "stiffness k".into(),
            unit: "N/m^1.35".into(),
            value: k,
            sigma: None,
            targets: targets.clone(),
            note: format!(
                "{} Table 1's k, with m_f held at {} kg ({}); one target, no spread published with it",
                k.map_or("no k in [1e3, 1e7] meets it;".into(), |k| format!("{} x", short(k / base.get(Parameter::Stiffness)))),
                short(base.effective_foot_mass()),
                VALIDATION_FOOT.name()
            ),
        });
        out.push(Identified {
            law: name.to_string(),
            parameter: "foot mass m_f".into(),
            unit: "kg".into(),
            value: None,
            sigma: None,
            targets: targets.clone(),
            note: "no foot speed was measured with these kicks: the ball speed fixes only (1 + e) v_f m_f/(m_f + m_b)".into(),
        });
    }
    Ok(out)
}

/// The offset at which the μ = `friction` ball of `curve` leaves at `speed`
/// (speed falls with the offset up to the largest spin).
fn offset_at_speed(base: &Scenario, curve: &[SpinPoint], speed: f64) -> Result<SpinPoint, ValidationError> {
    let i = curve.windows(2).position(|w| w[0].speed >= speed && w[1].speed < speed).ok_or(ValidationError::NoOffset { speed })?;
    let mu = curve[i].friction;
    let f = |e: f64| spin_point(base, e, mu).map_or(f64::NAN, |p| p.speed - speed);
    let root = kick_core::roots::brent(f, curve[i].offset, curve[i + 1].offset, 1e-12, 200)
        .ok_or(ValidationError::Search { what: "offset search" })?;
    Ok(spin_point(base, root.x, mu)?)
}

/// The offset–friction sweep of the paper's 3D kick beside Asai et al. (2002) and the measured swerve and free kicks.
fn curve_kicks(m: &Measurements) -> Result<CurveKicks, ValidationError> {
    let foot = VALIDATION_FOOT;
    let base = foot.apply(&Scenario::baseline())?;
    let curves: Vec<Vec<SpinPoint>> = [0.0, REFERENCE_FRICTION, 1.0].iter().map(|&mu| spin_curve(&base, mu)).collect::<Result<_, _>>()?;
    let largest = vec![largest_spin(&base, &curves[1])?, largest_spin(&base, &curves[2])?];
    let get = |key: &str| m.measured(key, NEEDED_BY);
    let swerve = get("ball_speed_swerve_instep")?.midpoint().ok_or(ValidationError::NoSpeed { what: "swerve speed" })?;
    let curling = get("barber_carre2010_launch_speed")?.midpoint().ok_or(ValidationError::NoSpeed { what: "curling free-kick speed" })?;
    let at_swerve = offset_at_speed(&base, &curves[1], swerve)?;
    let at_curling = offset_at_speed(&base, &curves[1], curling)?;
    let model = "3D rigid sphere, paper's law";
    let cond = |p: &SpinPoint, why: &str| {
        format!(
            "foot {} kg at {} m/s, knife-edge face tilted by asin(e/R), e = {:.1} mm{why}, mu = {}; ball leaves at {:.2} m/s",
            short(base.effective_foot_mass()),
            short(base.foot_speed()),
            1e3 * p.offset,
            short(p.friction),
            p.speed
        )
    };
    let offset_caveat =
        "Asai et al.'s offset (foot axis to ball axis, on a deforming ball) is not the model's (a knife-edge normal tilted by asin(e/R))";
    let chosen = "the assumed foot, and the offset, chosen so the mu = 0.5 ball leaves at the measured speed";
    let mut rows = vec![
        Row::new(
            m,
            Role::Prediction,
            model,
            cond(&at_curling, &format!(" (where the mu = 0.5 ball leaves at Barber & Carré's {curling} m/s)")),
            Comparison::new(
                "spin of a curling free kick",
                get("barber_carre2010_launch_spin")?,
                at_curling.spin,
                "spin from friction alone (the normal passes through the centre); their kicks' offsets and feet are not known",
            ),
        )
        .hinges_on(foot, chosen, None),
        Row::new(
            m,
            Role::Prediction,
            model,
            cond(&at_swerve, &format!(" (where the mu = 0.5 ball leaves at the swerve kicks' {swerve} m/s)")),
            Comparison::new(
                "spin of a swerve kick",
                get("spin_max_professional")?,
                at_swerve.spin,
                "the measured number is the largest recorded, not a mean",
            ),
        )
        .hinges_on(foot, chosen, None),
    ];
    let (zero, one) = (spin_point(&base, at_swerve.offset, 0.0)?, spin_point(&base, at_swerve.offset, 1.0)?);
    rows.push(
        Row::new(
            m,
            Role::ModelComparison,
            model,
            cond(&at_swerve, &format!(" (where the mu = 0.5 ball leaves at {swerve} m/s)")),
            Comparison::new(
                "spin added by friction 0 -> 1",
                get("spin_friction_gain_asai2002")?,
                one.spin - zero.spin,
                format!("a rigid sphere spins from friction alone, so all of its spin is friction's; {offset_caveat}"),
            ),
        )
        .with_foot(foot),
    );
    let zero_spin = curves[0].iter().map(|p| p.spin).fold(0.0, f64::max);
    rows.push(
        Row::new(
            m,
            Role::ModelComparison,
            model,
            "mu = 0, every offset of the sweep",
            Comparison::new(
                "spin without friction (largest over offsets)",
                m.claimed("spin_zero_friction_asai2002", NEEDED_BY)?,
                zero_spin,
                "the rigid sphere's normal passes through its centre: no spin without friction; Asai et al.'s wrapping spin has no number in their abstract",
            ),
        )
        .with_foot(foot),
    );
    for p in &largest {
        rows.push(
            Row::new(
                m,
                Role::ModelComparison,
                model,
                cond(p, " (the largest spin over offsets, golden-section search)"),
                Comparison::new(
                    format!("offset of largest spin, mu = {}", short(p.friction)),
                    get("spin_peak_offset_asai2002")?,
                    p.offset,
                    format!(
                        "{} there; beyond it the tilted normal lets the foot glance off; the ball leaves at {:.1} m/s there; {offset_caveat}",
                        crate::units::spin(p.spin),
                        p.speed
                    ),
                ),
            )
            .with_foot(foot),
        );
    }
    rows.push(
        Row::new(
            m,
            Role::ModelComparison,
            model,
            "mu = 0.5 and 1, the sweep",
            Comparison::new(
                "spin growth with offset",
                m.claimed("spin_trend_asai2002", NEEDED_BY)?,
                largest[0].spin,
                format!(
                    "spin rises at every step of the sweep up to its largest value (mu = 0.5: {}, mu = 1: {}); speed falls with the offset",
                    rises(&curves[1]),
                    rises(&curves[2])
                ),
            ),
        )
        .with_foot(foot),
    );
    rows.extend(patch_rows(m)?);
    Ok(CurveKicks { curves, largest, at_measured_speed: vec![at_swerve, at_curling], rows })
}

/// The same claims set beside the level above the rigid sphere: the shell
/// ball's force spread over its patch on a convex instep, with Asai et al.'s
/// own offset (ball centre to the swing line through the instep's apex).
fn patch_rows(m: &Measurements) -> Result<Vec<Row>, ValidationError> {
    let foot = VALIDATION_FOOT;
    let shell = laws()?[1].scenario;
    let radius = ASSUMED_INSTEP_RADIUS;
    let model = format!("3D shell ball (FIFA-calibrated), patch contact on a convex instep, r_i = {radius} m (assumed)");
    let cond = |what: &str| {
        format!(
            "foot {} kg at {} m/s, face square to the swing, offset = ball centre to the swing line through the instep's apex, {what}",
            short(shell.effective_foot_mass()),
            shell.foot_speed()
        )
    };
    let kick = |e: f64, mu: f64, r_i: f64| patch_spin_point(&shell, e, mu, r_i);
    let offsets = patch_offsets();
    let gain_at = |e: f64, r_i: f64| -> Result<f64, ValidationError> { Ok(kick(e, 1.0, r_i)?.0.spin - kick(e, 0.0, r_i)?.0.spin) };
    let mut gains = Vec::with_capacity(offsets.len());
    for &e in &offsets {
        gains.push((e, gain_at(e, radius)?));
    }
    let (gain_offset, gain) = gains.iter().copied().fold((0.0, f64::NEG_INFINITY), |a, b| if b.1 > a.1 { b } else { a });
    let flatter = 2.0 * radius;
    let gain_flatter = gain_at(gain_offset, flatter)?;
    let get = |key: &str| m.measured(key, NEEDED_BY);
    let last = offsets[offsets.len() - 1];
    let (zero, zero_spin) = kick(last, 0.0, radius)?;
    let (_, rubbed) = kick(last, REFERENCE_FRICTION, radius)?;
    let same_sense = zero_spin.iter().zip(&rubbed).map(|(a, b)| a * b).sum::<f64>() > 0.0;
    let mut reference = Vec::with_capacity(offsets.len());
    for &e in &offsets {
        reference.push(kick(e, REFERENCE_FRICTION, radius)?.0);
    }
    let peak = reference.iter().copied().fold(reference[0], |a, b| if b.spin > a.spin { b } else { a });
    let rising = rises(&reference);
    let sweep = format!("0–{} mm", short(1e3 * last));
    let mut peak_row = Row::new(
        m,
        Role::ModelComparison,
        &model,
        cond(&format!("mu = {}, e = {sweep} in 5 mm steps", short(REFERENCE_FRICTION))),
        Comparison::new(
            format!("offset of largest spin, mu = {}", short(REFERENCE_FRICTION)),
            get("spin_peak_offset_asai2002")?,
            peak.offset,
            format!("spin rises at every step up to {} mm: {rising}; {} there", short(1e3 * peak.offset), crate::units::spin(peak.spin)),
        ),
    )
    .with_foot(foot);
    if peak.offset >= last {
        // The sweep's edge is no maximum: say so instead of scoring it.
        peak_row = peak_row.model_text(format!("no maximum within {sweep}"));
        peak_row.comparison.outside = None;
        peak_row.comparison.ratio = None;
    }
    Ok(vec![
        Row::new(
            m,
            Role::ModelComparison,
            &model,
            cond(&format!("e = {sweep}")),
            Comparison::new(
                "spin added by friction 0 -> 1 (largest over offsets)",
                get("spin_friction_gain_asai2002")?,
                gain,
                format!(
                    "largest at e = {} mm; the gain grows with the instep's curvature, which no measurement fixes: \
                     {:.3} rad/s there on a cap of r_i = {} m",
                    short(1e3 * gain_offset),
                    gain_flatter,
                    short(flatter)
                ),
            ),
        )
        .with_foot(foot),
        Row::new(
            m,
            Role::ModelComparison,
            &model,
            cond(&format!("mu = 0, e = {} mm", short(1e3 * last))),
            Comparison::new(
                "spin without friction",
                m.claimed("spin_zero_friction_asai2002", NEEDED_BY)?,
                zero.spin,
                format!(
                    "in friction's sense (as friction's spin at mu = {}): {same_sense}; sliding over the convex instep \
                     presses the trailing side of the patch faster, so the force passes behind the centre",
                    short(REFERENCE_FRICTION)
                ),
            ),
        )
        .with_foot(foot),
        peak_row,
    ])
}

fn rises(curve: &[SpinPoint]) -> bool {
    let peak = (0..curve.len()).max_by(|&a, &b| curve[a].spin.total_cmp(&curve[b].spin)).unwrap_or(0);
    curve[..=peak].windows(2).all(|w| w[1].spin > w[0].spin)
}

/// The flight's crisis: calibrations (the crisis and each construction's
/// factor were set from these numbers) and the transition beside them.
fn flight_rows(m: &Measurements) -> Result<Vec<Row>, ValidationError> {
    let model = "kick-flight's default C_D(Re)";
    let cond = "no spin, standard sea-level air, R = 0.11 m; critical Re: 95 % of the drop done";
    let mut rows = Vec::new();
    for c in kick_flight::validation::drag_crisis_comparisons(m)? {
        let key = c.measured.key.clone();
        let panels = kick_flight::validation::keys::PANELS.iter().find(|p| p.0 == key).map(|p| p.1);
        let row = Row::new(m, Role::Prediction, model, cond, c);
        rows.push(match (key.as_str(), panels) {
            ("critical_re_asai2007", _) => Row { role: Role::Calibration, ..row }
                .sets("the drag crisis: Goff & Carré's (2010) logistic fit to Asai et al.'s (2007) Teamgeist C_D"),
            // The 14-panel ball's factor is 1: nothing was set from its row,
            // a second measurement of the default ball's crisis.
            (_, Some(14)) => row,
            // Only the ratio to the 14-panel ball was set: the absolute
            // value carries the 14-panel row's miss.
            (_, Some(n)) => {
                let factor = kick_flight::coefficients::BallConstruction { panels: n }.reynolds_scale();
                Row { role: Role::Calibration, ..row }.sets(format!(
                    "only the {n}-panel ball's ratio to the 14-panel ball, {} (their published critical Re's); its own value \
                     carries the 14-panel row's miss",
                    short(factor)
                ))
            }
            // One published statement (Re ≈ 2e5 ≈ 14 m/s) in two units: one measurement.
            (kick_flight::validation::keys::TRANSITION_SPEED, _) => {
                row.not_counted("the transition's Reynolds number again, as a speed: one statement, counted once")
            }
            _ => row,
        });
    }
    Ok(rows)
}

/// Mencke et al.'s measured flights beside the default flight model.
fn measured_flight_rows(m: &Measurements) -> Result<Vec<Row>, ValidationError> {
    let model = "kick-flight's defaults (C_D(Re, S), C_L(S))";
    Ok(kick_flight::validation::measured_flights(m)?
        .into_iter()
        .map(|c| {
            let note = c.note.clone();
            Row::new(m, Role::Prediction, model, note, c)
        })
        .collect())
}

fn free_kicks(m: &Measurements) -> Result<FreeKicksAtLaunch, ValidationError> {
    let kicks = kick_flight::validation::free_kicks(m, FREE_KICK_ELEVATION, FREE_KICK_DISTANCE)?;
    // The same flights as kick_flight::validation::free_kick, for their launch report.
    let launch = kicks
        .kicks
        .iter()
        .map(|k| {
            let flight = kick_flight::FlightSpec {
                spin: Some([0.0, 0.0, k.spin]),
                distance: Some(FREE_KICK_DISTANCE),
                ..kick_flight::FlightSpec::from_exit_speed(k.speed, FREE_KICK_ELEVATION)
            }
            .build()?;
            Ok(kick_flight::solve(&flight)?.launch)
        })
        .collect::<Result<_, ValidationError>>()?;
    Ok(FreeKicksAtLaunch { kicks, launch, circle_estimate_role: Role::Check })
}

/// Measurement keys by check status, strongest first.
fn by_status(m: &Measurements) -> Vec<(String, Vec<String>)> {
    let kinds: [(&str, fn(&Checked) -> bool); 5] = [
        ("text", |c| matches!(c, Checked::Text)),
        ("abstract", |c| matches!(c, Checked::Abstract)),
        ("secondary", |c| matches!(c, Checked::Secondary(_))),
        ("transcription", |c| matches!(c, Checked::Transcription(_))),
        ("unchecked", |c| matches!(c, Checked::Unchecked)),
    ];
    kinds
        .iter()
        .map(|(name, is)| (name.to_string(), m.measurements.iter().filter(|x| is(&x.checked)).map(|x| x.key.clone()).collect()))
        .collect()
}

/// Compare the model with the measurements `m` (kick-store reads the file).
pub fn validate(m: &Measurements) -> Result<Validation, ValidationError> {
    let ball = ball_rows(m)?;
    let contact = contact_rows(m)?;
    let implied = identify(m)?;
    let curve_kicks = curve_kicks(m)?;
    let flight = flight_rows(m)?;
    let measured_flights = measured_flight_rows(m)?;
    let free_kicks = free_kicks(m)?;
    let citations: Vec<(String, String)> = m.sources.iter().map(|s| (s.key.clone(), s.citation())).collect();
    let headline = headline(ball.iter().chain(&contact).chain(&curve_kicks.rows).chain(&flight).chain(&measured_flights));
    Ok(Validation {
        measurements_file: m.file.clone(),
        sources: citations.len(),
        measurements: m.measurements.len(),
        foot: VALIDATION_FOOT,
        headline,
        ball,
        contact,
        implied,
        curve_kicks,
        drag_crisis_model: kick_flight::validation::drag_crisis_model(),
        flight,
        measured_flights,
        free_kicks,
        checked: by_status(&m),
        citations,
        written: Vec::new(),
    })
}

impl Validation {
    /// All comparison rows.
    pub fn rows(&self) -> impl Iterator<Item = &Row> {
        self.ball.iter().chain(&self.contact).chain(&self.curve_kicks.rows).chain(&self.flight).chain(&self.measured_flights)
    }
}

impl Printable for Validation {
    fn text(&self) -> String {
        format!(
            "validation: {} measurements from {} sources; {} counted predictions ({} within 2u)\n",
            self.measurements, self.sources, self.headline.counted, self.headline.within_two_u
        )
    }
    fn written(&self) -> &[PathBuf] {
        &self.written
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use kick_core::measurements::MeasurementError;

    /// Measurements without what the chapter reads: the error is the
    /// measurement file's, naming the file and the first key missing.
    #[test]
    fn a_missing_measurement_names_the_file_and_the_key() {
        let empty = Measurements::check("x.toml", Vec::new(), Vec::new()).unwrap();
        let e = validate(&empty).unwrap_err();
        let ValidationError::Measurements(MeasurementError::Missing { file, key, .. }) = &e else { panic!("{e:?}") };
        assert_eq!((file.as_str(), key.as_str()), ("x.toml", "fifa_rebound_height"));
        assert!(e.to_string().starts_with("x.toml: no measurement `fifa_rebound_height`"), "{e}");
    }
}
