//! The validation chapter: every comparison of the model with a published
//! measurement (`experiments/validation/measurements.toml`), written to
//! `results/validation/validation.json` and drawn as `paper/validation.md`.
//!
//! The rules (issue 23, [`rows`]): every row has a role (calibration,
//! prediction, check); the model runs at the measurement's own conditions
//! (a force or contact time at the measured ball speed, through
//! [`kick_identify::validation::with_ball_speed`]; a spin where the ball
//! leaves at the measured speed) and the row says them; a point without a
//! published spread is shown, never counted; the headline counts predictions
//! inside their measured interval over predictions made. The reasons each
//! comparison agrees or misses are in `experiments/validation/NOTES.md`.

pub mod rows;

use crate::printable::Printable;
use kick_3d::validation::{largest_spin, patch_spin_point, spin_curve, spin_point, SpinPoint, ASSUMED_INSTEP_RADIUS, REFERENCE_FRICTION};
use kick_core::measurements::{Comparison, Measured, Measurements};
use kick_core::{short, LawKind, Parameter, Scenario, ShellBall, Value, DEFAULT_BALL_RADIUS};
use kick_flight::validation::{DragCrisisModel, FreeKicks, FREE_KICK_DISTANCE, FREE_KICK_ELEVATION};
use kick_identify::validation::{contact_model, with_ball_speed, ContactModel};
use rows::{estimate_cell, headline, Role, Row};
use serde::Serialize;
use std::f64::consts::TAU;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

const NEEDED_BY: &str = "the validation chapter (kick_paper::validation)";
/// Drop height of the FIFA rebound test, m.
pub const FIFA_DROP_HEIGHT: f64 = 2.0;
/// |ω| below this is printed as zero to rounding, rad/s.
pub const ZERO_SPIN: f64 = 1e-12;

/// The patch kicks' offsets: [`crate::patch`]'s grid inside the ball, so
/// the validation page and paper/3d.md quote the same kicks.
pub fn patch_offsets() -> Vec<f64> {
    crate::patch::offsets().into_iter().filter(|&e| e < DEFAULT_BALL_RADIUS).collect()
}

/// One law the 1D kick is run with.
#[derive(Debug, Clone, Copy)]
struct Law {
    name: &'static str,
    scenario: Scenario,
    pressure: Option<f64>,
}

fn laws() -> Result<[Law; 2], String> {
    let base = Scenario::baseline();
    let ball = ShellBall::default_with_radius(DEFAULT_BALL_RADIUS).map_err(|e| e.to_string())?;
    Ok([
        Law { name: "paper's law (Table 1)", scenario: base, pressure: None },
        Law { name: "shell ball (FIFA-calibrated)", scenario: base.with_shell(ball), pressure: Some(ball.pressure) },
    ])
}

/// The conditions of a 1D model run, in words.
fn conditions(law: &Law, s: &Scenario, why_speed: &str) -> String {
    let pressure = law.pressure.map_or(String::new(), |p| format!(", {} bar", short(p / 1e5)));
    format!(
        "instep, foot {} kg at {:.2} m/s{why_speed}; ball {} kg, R {} m{pressure}, at rest",
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
    /// Spin against offset at μ = 0, 0.5 and 1 (Table 1's kick at 22 m/s).
    pub curves: Vec<Vec<SpinPoint>>,
    /// The largest spin at μ = 0.5 and at μ = 1.
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
    /// Predictions inside their measured interval, and predictions counted.
    pub predictions_inside: usize,
    pub predictions_counted: usize,
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
    pub free_kicks: FreeKicksAtLaunch,
    /// Every source of the file: (key, citation).
    pub citations: Vec<(String, String)>,
    #[serde(skip)]
    pub written: Vec<PathBuf>,
}

fn error(e: impl std::fmt::Display) -> String {
    e.to_string()
}

/// The ball alone: the FIFA rebound of the shell ball (what its loss β was
/// set on) and the default ball against Law 2.
fn ball_rows(m: &Measurements) -> Result<Vec<Row>, String> {
    let mut spec = kick_bounce::BounceSpec::default();
    spec.set("drop_height", Value::Number(FIFA_DROP_HEIGHT)).map_err(error)?;
    let bounce = kick_bounce::run(&spec).map_err(error)?;
    let ball = ShellBall::default_with_radius(DEFAULT_BALL_RADIUS).map_err(error)?;
    let rebound = bounce.rebound_height.ok_or("the FIFA drop gave no rebound height")?;
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
            m.measured("fifa_rebound_height", NEEDED_BY).map_err(error)?,
            rebound,
            "β was identified from the band's middle: the 2 m drop, gravity on during contact as in the test, \
             rebounds 140 cm",
        ),
    )
    .sets(format!("shell loss β = {} Pa s/m (crates/kick-bounce/SOURCES.md)", short(ball.shell_damping)))];
    for r in kick_flight::validation::ball_comparisons(m).map_err(error)? {
        rows.push(Row::new(m, Role::Check, "default ball", "Table 1's ball, R = 0.11 m", r));
    }
    Ok(rows)
}

/// The 1D instep kick beside every contact measurement, under both laws.
fn contact_rows(m: &Measurements) -> Result<Vec<Row>, String> {
    let get = |key: &str| m.measured(key, NEEDED_BY).map_err(error);
    let mid = |key: &str| -> Result<f64, String> { get(key)?.midpoint().ok_or_else(|| format!("`{key}` has no number")) };
    let tol_speed = mid("ball_speed_tol2002")?;
    let nunome_speed = mid("ball_speed_instep_nunome2002")?;
    let limb = get("foot_speed_mechanical_limb")?;
    let (limb_slow, limb_fast) = (limb.low.unwrap_or(f64::NAN), limb.high.unwrap_or(f64::NAN));
    let mut rows = Vec::new();
    for law in laws()? {
        let s = law.scenario;
        let run = |s: &Scenario| contact_model(s).map_err(error);
        let at_speed = |v: f64| -> Result<(Scenario, ContactModel), String> {
            let matched = with_ball_speed(&s, v).map_err(error)?;
            Ok((matched, run(&matched)?))
        };
        let row = |role, c: &Scenario, why: &str, comparison| Row::new(m, role, law.name, conditions(&law, c, why), comparison);
        let base = run(&s)?;
        let table1 = " (Table 1's; no ball speed goes with the pooled range)";
        let short_contact = match law.pressure {
            None => "a rigid sphere on a rigid instep through Table 1's stiff power law; a real ball wraps around the instep and its shell bends, which is softer and lasts longer",
            Some(_) => "the pressurised ball flattens on a flat, rigid instep (pressure times patch area); the foot's soft tissue and a curved instep, not modelled, lengthen a real contact",
        };
        rows.push(row(
            Role::Prediction,
            &s,
            table1,
            Comparison::new("contact time", get("contact_time_instep")?, base.contact_time, short_contact),
        ));
        let effective = get("contact_time_instep")?
            .scaled_by(&get("effective_contact_fraction")?)
            .ok_or("effective_contact_fraction must be a fraction >= 0")?;
        rows.push(
            row(
                Role::Prediction,
                &s,
                table1,
                Comparison::new(
                    "contact time vs the part of the measured contact that accelerates the ball",
                    effective,
                    base.contact_time,
                    "measured contact scaled by Nunome et al.'s 3/4: every instant of the model's contact carries force",
                ),
            )
            .not_counted("the pooled range above scaled by 3/4: one measurement, counted once"),
        );
        rows.push(row(
            Role::Prediction,
            &s,
            table1,
            Comparison::new(
                "ball travel while on the foot",
                get("ball_travel_instep")?,
                base.ball_travel,
                "the centre-of-mass drift m_f v_f t_c/(m_f + m_b) (no drive): it scales with the contact time",
            ),
        ));
        // The mechanical kicking limb: a nearly rigid foot, like the model's, at its two measured foot speeds.
        for (v, time_key, travel_key) in [
            (limb_slow, "contact_time_limb_slow", "contact_distance_limb_slow"),
            (limb_fast, "contact_time_limb_fast", "contact_distance_limb_fast"),
        ] {
            let c = s.with(Parameter::FootSpeed, v).map_err(error)?;
            let k = run(&c)?;
            let why = " (the limb's measured foot speed)";
            let af = "an Australian-football ball in the limb, the model's soccer ball here";
            rows.push(row(
                Role::Prediction,
                &c,
                why,
                Comparison::new(
                    "ball speed / foot speed, mechanical limb",
                    get("speed_ratio_mechanical_limb")?,
                    k.speed_ratio,
                    format!(
                        "a rigid foot gives (1 + e) m_f/(m_f + m_b): model e = {:.3} (the limb's measured COR 0.66-0.79); {af}; Table 1's 3 kg foot, the limb's own mass not read",
                        k.speed_ratio * (c.effective_foot_mass() + c.ball_mass()) / c.effective_foot_mass() - 1.0
                    ),
                ),
            ));
            rows.push(row(Role::Prediction, &c, why, Comparison::new("contact time, mechanical limb", get(time_key)?, k.contact_time, af)));
            rows.push(row(
                Role::Prediction,
                &c,
                why,
                Comparison::new("ball travel while on the foot, mechanical limb", get(travel_key)?, k.ball_travel, af),
            ));
        }
        rows.push(
            row(
                Role::Prediction,
                &s,
                " (Table 1's)",
                Comparison::new(
                    "ball speed / foot speed, players",
                    get("speed_ratio_instep")?,
                    base.speed_ratio,
                    "a rigid foot with restitution e gives (1 + e) m_f/(m_f + m_b); a player's foot and ankle give way",
                ),
            )
            .not_counted("players' feet yield, the model's does not: the like-for-like ratio is the mechanical limb's (above)"),
        );
        // Forces at the ball speed measured with them.
        let (tol, tol_model) = at_speed(tol_speed)?;
        let tol_why = format!(" (lowered so the ball leaves at Tol et al.'s {tol_speed} m/s)");
        rows.push(row(
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
                    1e3 * tol.ball_mass() * tol_speed / mid("mean_force_tol2002")?
                ),
            ),
        ));
        rows.push(
            row(
                Role::Prediction,
                &tol,
                &tol_why,
                Comparison::new("peak force", get("peak_force_tol2002")?, tol_model.peak_force, "at Tol et al.'s own ball speed"),
            )
            .not_counted("1025 N x pi/2: Tol et al.'s mean force drawn as a half sine, not a measured peak"),
        );
        let (nunome, nunome_model) = at_speed(nunome_speed)?;
        let nunome_why =
            format!(" (the source read gives no ball speed with this force: lowered so the ball leaves at Nunome et al.'s (2002) instep {nunome_speed} m/s)");
        for (key, what) in [
            ("peak_force_instep_asai2002", "from 4500 Hz video and a finite-element simulation, not a force measurement"),
            ("peak_force_shinkai2009", "from the motion of the ball's centre of gravity in ultra-high-speed video"),
        ] {
            rows.push(row(Role::Prediction, &nunome, &nunome_why, Comparison::new("peak force", get(key)?, nunome_model.peak_force, what)));
        }
        for key in ["ball_speed_max_instep", "ball_speed_instep_nunome2002"] {
            rows.push(
                row(
                    Role::Prediction,
                    &s,
                    " (Table 1's)",
                    Comparison::new("ball speed after contact", get(key)?, base.ball_speed, "set by m_f, v_f and the restitution"),
                )
                .not_counted("no foot speed was measured with these ball speeds: the model's follows the assumed 22 m/s"),
            );
        }
        let pulse = Measured::ratio(&get("peak_force_punt")?, &get("mean_force_punt")?).ok_or("mean_force_punt must be > 0")?;
        rows.push(row(
            Role::Check,
            &s,
            " (Table 1's)",
            Comparison::new(
                "peak / mean force (pulse shape)",
                pulse,
                base.peak_to_mean,
                "measured in rugby-league punt kicks, not a soccer instep kick: a check of the pulse's shape only (a half sine gives pi/2)",
            ),
        ));
    }
    Ok(rows)
}

/// k from Tol et al.'s soccer instep kicks: the contact time m_b v/F̄ at
/// their ball speed, the foot speed lowered until the ball leaves at it, m_f
/// held at Table 1's 3 kg.
fn identify(m: &Measurements) -> Result<Vec<Identified>, String> {
    let get = |key: &str| m.measured(key, NEEDED_BY).map_err(error)?.midpoint().ok_or_else(|| format!("`{key}` has no number"));
    let (speed, force) = (get("ball_speed_tol2002")?, get("mean_force_tol2002")?);
    let base = Scenario::baseline();
    let target = base.ball_mass() * speed / force;
    use kick_core::Solver as _;
    let restitution = kick_compliant::Accurate::default().solve(&base).map_err(error)?.restitution;
    let hunt_crossley = base.with_law(LawKind::HuntCrossleyExact, Some(restitution)).map_err(error)?;
    let targets = format!(
        "Tol et al. (2002), 150 instep kicks by 15 elite players: ball {speed} m/s, mean force {force} N, so a contact of m_b v/F = {:.3} ms",
        1e3 * target
    );
    let mut out = Vec::new();
    for (name, s) in [("paper's law, c = 120 N s/m", base), (&*format!("Hunt-Crossley (exact), e = {}", short(restitution)), hunt_crossley)]
    {
        let contact = |ln_k: f64| -> f64 {
            let run = || -> Result<f64, String> {
                let c = s.with(Parameter::Stiffness, ln_k.exp()).map_err(error)?;
                Ok(contact_model(&with_ball_speed(&c, speed).map_err(error)?).map_err(error)?.contact_time - target)
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
                "{} Table 1's k, with m_f held at 3 kg; one target, no spread published with it",
                k.map_or("no k in [1e3, 1e7] meets it;".into(), |k| format!("{} x", short(k / base.get(Parameter::Stiffness))))
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
fn offset_at_speed(base: &Scenario, curve: &[SpinPoint], speed: f64) -> Result<SpinPoint, String> {
    let i = curve
        .windows(2)
        .position(|w| w[0].speed >= speed && w[1].speed < speed)
        .ok_or(format!("no offset sends the ball off at {speed} m/s"))?;
    let mu = curve[i].friction;
    let f = |e: f64| spin_point(base, e, mu).map_or(f64::NAN, |p| p.speed - speed);
    let root = kick_core::roots::brent(f, curve[i].offset, curve[i + 1].offset, 1e-12, 200).ok_or("offset search failed")?;
    spin_point(base, root.x, mu).map_err(error)
}

/// The offset–friction sweep of Table 1's kick beside Asai et al. (2002) and the measured swerve and free kicks.
fn curve_kicks(m: &Measurements) -> Result<CurveKicks, String> {
    let base = Scenario::baseline();
    let curves: Vec<Vec<SpinPoint>> =
        [0.0, REFERENCE_FRICTION, 1.0].iter().map(|&mu| spin_curve(&base, mu)).collect::<Result<_, _>>().map_err(error)?;
    let largest = vec![largest_spin(&base, &curves[1]).map_err(error)?, largest_spin(&base, &curves[2]).map_err(error)?];
    let get = |key: &str| m.measured(key, NEEDED_BY).map_err(error);
    let swerve = get("ball_speed_swerve_instep")?.midpoint().ok_or("no swerve speed")?;
    let free = get("free_kick_speed")?.midpoint().ok_or("no free-kick speed")?;
    let at_swerve = offset_at_speed(&base, &curves[1], swerve)?;
    let at_free = offset_at_speed(&base, &curves[1], free)?;
    let model = "3D rigid sphere, paper's law";
    let cond = |p: &SpinPoint, why: &str| {
        format!(
            "foot 3 kg at 22 m/s, knife-edge face tilted by asin(e/R), e = {:.1} mm{why}, mu = {}; ball leaves at {:.2} m/s",
            1e3 * p.offset,
            short(p.friction),
            p.speed
        )
    };
    let offset_caveat =
        "Asai et al.'s offset (foot axis to ball axis, on a deforming ball) is not the model's (a knife-edge normal tilted by asin(e/R))";
    let mut rows = vec![
        Row::new(
            m,
            Role::Prediction,
            model,
            cond(&at_free, &format!(" (chosen so the ball leaves at {free} m/s, the middle of the measured launch speeds)")),
            Comparison::new(
                "spin of a free kick",
                get("free_kick_spin")?,
                at_free.spin,
                "spin from friction alone (the normal passes through the centre)",
            ),
        ),
        Row::new(
            m,
            Role::Prediction,
            model,
            cond(&at_swerve, &format!(" (chosen so the ball leaves at the swerve kicks' {swerve} m/s)")),
            Comparison::new(
                "spin of a swerve kick",
                get("spin_max_professional")?,
                at_swerve.spin,
                "the measured number is the largest recorded, not a mean",
            ),
        ),
    ];
    let mut gain_at = |p: &SpinPoint, why: &str| -> Result<(), String> {
        let (zero, one) = (spin_point(&base, p.offset, 0.0).map_err(error)?, spin_point(&base, p.offset, 1.0).map_err(error)?);
        rows.push(Row::new(
            m,
            Role::Prediction,
            model,
            cond(p, why),
            Comparison::new(
                "spin added by friction 0 -> 1",
                get("spin_friction_gain_asai2002")?,
                one.spin - zero.spin,
                format!("a rigid sphere spins from friction alone, so all of its spin is friction's; {offset_caveat}"),
            ),
        ));
        Ok(())
    };
    gain_at(&at_swerve, &format!(" (where the mu = 0.5 ball leaves at {swerve} m/s)"))?;
    let zero = curves[0].iter().map(|p| p.spin).fold(0.0, f64::max);
    rows.push(Row::new(
        m,
        Role::Prediction,
        model,
        "mu = 0, every offset of the sweep",
        Comparison::new(
            "spin without friction (largest over offsets)",
            m.claimed("spin_zero_friction_asai2002", NEEDED_BY).map_err(error)?,
            zero,
            "the rigid sphere's normal passes through its centre: no spin without friction; Asai et al.'s wrapping spin has no number in their abstract",
        ),
    ));
    for p in &largest {
        rows.push(Row::new(
            m,
            Role::Prediction,
            model,
            cond(p, " (the largest spin over offsets)"),
            Comparison::new(
                format!("offset of largest spin, mu = {}", short(p.friction)),
                get("spin_peak_offset_asai2002")?,
                p.offset,
                format!(
                    "beyond it the tilted normal lets the foot glance off; the ball leaves at {:.1} m/s there; {offset_caveat}",
                    p.speed
                ),
            ),
        ));
    }
    rows.push(Row::new(
        m,
        Role::Prediction,
        model,
        "mu = 0.5 and 1, the sweep",
        Comparison::new(
            "spin growth with offset",
            m.claimed("spin_trend_asai2002", NEEDED_BY).map_err(error)?,
            largest[0].spin,
            format!(
                "spin rises at every step of the sweep up to its largest value (mu = 0.5: {}, mu = 1: {}); speed falls with the offset",
                rises(&curves[1]),
                rises(&curves[2])
            ),
        ),
    ));
    rows.extend(patch_rows(m)?);
    Ok(CurveKicks { curves, largest, at_measured_speed: vec![at_swerve, at_free], rows })
}

/// The same claims set beside the level above the rigid sphere: the shell
/// ball's force spread over its patch on a convex instep, with Asai et al.'s
/// own offset (ball centre to the swing line through the instep's apex).
fn patch_rows(m: &Measurements) -> Result<Vec<Row>, String> {
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
    let kick = |e: f64, mu: f64, r_i: f64| patch_spin_point(&shell, e, mu, r_i).map_err(error);
    let offsets = patch_offsets();
    let gain_at = |e: f64, r_i: f64| -> Result<f64, String> { Ok(kick(e, 1.0, r_i)?.0.spin - kick(e, 0.0, r_i)?.0.spin) };
    let mut gains = Vec::with_capacity(offsets.len());
    for &e in &offsets {
        gains.push((e, gain_at(e, radius)?));
    }
    let (gain_offset, gain) = gains.iter().copied().fold((0.0, f64::NEG_INFINITY), |a, b| if b.1 > a.1 { b } else { a });
    let flatter = 2.0 * radius;
    let gain_flatter = gain_at(gain_offset, flatter)?;
    let get = |key: &str| m.measured(key, NEEDED_BY).map_err(error);
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
    Ok(vec![
        Row::new(
            m,
            Role::Prediction,
            &model,
            cond(&format!("e = 0 to {} mm", short(1e3 * last))),
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
        ),
        Row::new(
            m,
            Role::Prediction,
            &model,
            cond(&format!("mu = 0, e = {} mm", short(1e3 * last))),
            Comparison::new(
                "spin without friction",
                m.claimed("spin_zero_friction_asai2002", NEEDED_BY).map_err(error)?,
                zero.spin,
                format!(
                    "in friction's sense (as friction's spin at mu = {}): {same_sense}; sliding over the convex instep \
                     presses the trailing side of the patch faster, so the force passes behind the centre",
                    short(REFERENCE_FRICTION)
                ),
            ),
        ),
        Row::new(
            m,
            Role::Prediction,
            &model,
            cond(&format!("mu = {}, e = 0 to {} mm", short(REFERENCE_FRICTION), short(1e3 * last))),
            Comparison::new(
                format!("offset of largest spin, mu = {}", short(REFERENCE_FRICTION)),
                get("spin_peak_offset_asai2002")?,
                peak.offset,
                format!(
                    "spin rises at every step up to it: {rising}; {}",
                    if peak.offset >= last { "still rising at the largest offset swept (the ball's edge)" } else { "inside the sweep" }
                ),
            ),
        ),
    ])
}

fn rises(curve: &[SpinPoint]) -> bool {
    let peak = (0..curve.len()).max_by(|&a, &b| curve[a].spin.total_cmp(&curve[b].spin)).unwrap_or(0);
    curve[..=peak].windows(2).all(|w| w[1].spin > w[0].spin)
}

/// The flight's crisis and the free kicks with their launch aerodynamics.
fn flight_rows(m: &Measurements) -> Result<Vec<Row>, String> {
    let model = "kick-flight's default C_D(Re)";
    let cond = "no spin, standard sea-level air, R = 0.11 m";
    let fourteen = "the model's curve is a 14-panel ball's (Teamgeist): not like for like";
    let mut rows = Vec::new();
    for c in kick_flight::validation::drag_crisis_comparisons(m).map_err(error)? {
        let key = c.measured.key.clone();
        let row = Row::new(m, Role::Prediction, model, cond, c);
        rows.push(match key.as_str() {
            "critical_re_asai2007" if rows.is_empty() => Row { role: Role::Calibration, ..row }
                .sets("the drag crisis: Goff & Carré's (2010) logistic fit to Asai et al.'s (2007) Teamgeist C_D"),
            "critical_re_asai2007" => Row { role: Role::Check, ..row },
            "critical_re_32_panels" | "critical_re_8_panels" | "critical_re_6_panels" => row.not_counted(fourteen),
            _ => row,
        });
    }
    Ok(rows)
}

fn free_kicks(m: &Measurements) -> Result<FreeKicksAtLaunch, String> {
    let kicks = kick_flight::validation::free_kicks(m, FREE_KICK_ELEVATION, FREE_KICK_DISTANCE).map_err(error)?;
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
            .build()
            .map_err(error)?;
            Ok(kick_flight::solve(&flight).map_err(error)?.launch)
        })
        .collect::<Result<_, String>>()?;
    Ok(FreeKicksAtLaunch { kicks, launch, circle_estimate_role: Role::Check })
}

/// Compare the model with the measurements in `measurements`.
pub fn validate(measurements: &Path) -> Result<Validation, String> {
    let m = Measurements::load(measurements).map_err(error)?;
    let ball = ball_rows(&m)?;
    let contact = contact_rows(&m)?;
    let implied = identify(&m)?;
    let curve_kicks = curve_kicks(&m)?;
    let flight = flight_rows(&m)?;
    let free_kicks = free_kicks(&m)?;
    let citations: Vec<(String, String)> = m.sources.iter().map(|s| (s.key.clone(), s.citation())).collect();
    let (inside, counted) = headline(ball.iter().chain(&contact).chain(&curve_kicks.rows).chain(&flight));
    Ok(Validation {
        measurements_file: measurements.display().to_string(),
        sources: citations.len(),
        measurements: m.measurements.len(),
        predictions_inside: inside,
        predictions_counted: counted,
        ball,
        contact,
        implied,
        curve_kicks,
        drag_crisis_model: kick_flight::validation::drag_crisis_model(),
        flight,
        free_kicks,
        citations,
        written: Vec::new(),
    })
}

/// [`validate`], then write `out/validation.json` and `page` (links relative to the page).
pub fn write(measurements: &Path, out: &Path, page: &Path, notes: &Path) -> Result<Validation, String> {
    let mut v = validate(measurements)?;
    let json_path = out.join("validation.json");
    crate::output::write(&json_path, crate::printable::json(&v)?).map_err(|e| e.to_string())?;
    let page_dir = page.parent().unwrap_or(Path::new("."));
    // Inputs are read where they are, the page may be written into a scratch
    // folder (`reproduce --check`): link them from the page's folder name, so
    // both give the same bytes.
    let input_from = if page_dir.is_absolute() { page_dir.file_name().map_or(Path::new("."), Path::new) } else { page_dir };
    let text = v.markdown(
        &crate::links::relative(page_dir, &json_path),
        &crate::links::relative(input_from, measurements),
        &crate::links::relative(input_from, notes),
    );
    crate::output::write(page, text).map_err(|e| e.to_string())?;
    v.written = vec![json_path, page.to_path_buf()];
    Ok(v)
}

fn interval(m: &Measured) -> String {
    match (m.low, m.high) {
        (Some(lo), Some(hi)) if lo == hi => format!("{} (point)", short(lo)),
        (Some(lo), Some(hi)) => format!("{} – {}", short(lo), short(hi)),
        _ => "(in words)".to_string(),
    }
}

/// A spin as printed in a table cell: zero to rounding below [`ZERO_SPIN`] (no `|` inside a cell).
pub fn spin_text(x: f64) -> String {
    if x.abs() < ZERO_SPIN {
        "0 (< 1e-12)".into()
    } else {
        format!("{}", short(x))
    }
}

/// Rows as a Markdown table.
fn table(w: &mut String, rows: &[Row]) {
    let _ = writeln!(w, "| role | quantity | model | measured | model value | unit | inside? | counted? | source (checked) | model run at | measured at | why |");
    let _ = writeln!(w, "|---|---|---|---|---|---|---|---|---|---|---|---|");
    for r in rows {
        let c = &r.comparison;
        let inside = match c.agrees() {
            Some(true) => "yes".to_string(),
            Some(false) => format!("no ({:+})", short(c.outside.unwrap_or(f64::NAN))),
            None => "–".to_string(),
        };
        let value = if c.measured.unit == "rad/s" { spin_text(c.model) } else { format!("{}", short(c.model)) };
        let role = match &r.sets {
            Some(what) => format!("calibration: sets {what}"),
            None => r.role.name().to_string(),
        };
        let _ = writeln!(
            w,
            "| {role} | {} | {} | {} | {value} | {} | {inside} | {} | `{}` ({}) | {} | {} | {} |",
            c.quantity,
            r.model,
            interval(&c.measured),
            c.measured.unit,
            r.count_note(),
            c.measured.key,
            c.measured.checked,
            r.model_conditions.replace('|', "/"),
            r.measured_conditions.replace('|', "/"),
            c.note.replace('|', "/")
        );
    }
}

impl Validation {
    /// All comparison rows.
    pub fn rows(&self) -> impl Iterator<Item = &Row> {
        self.ball.iter().chain(&self.contact).chain(&self.curve_kicks.rows).chain(&self.flight)
    }

    /// The page; `data`, `file` and `notes` are the JSON, the measurement
    /// file and the notes as links from the page.
    pub fn markdown(&self, data: &str, file: &str, notes: &str) -> String {
        let mut w = String::new();
        let _ = writeln!(w, "# Validation: the model beside published measurements\n");
        let _ = writeln!(
            w,
            "Generated by `kick reproduce` from [{file}]({file}) ({} measurements from the {} sources listed at the end, each \
             with its citation, where it stands in the source and how far it was checked: *text*, *abstract*, *secondary* \
             or *unchecked*). Data: [{data}]({data}). Why each row agrees or misses, and what stays unchecked: \
             [the notes]({notes}).\n",
            self.measurements, self.sources
        );
        let _ = writeln!(
            w,
            "**{} of {} predictions fall inside their measured interval.** Every row has a role: *calibration* (the \
             measurement set a parameter, named), *prediction* (it set nothing) or *check* (a consistency or definition \
             check). Counted are predictions with a measured interval of nonzero width (a range, or a mean ± the SD its \
             source gives) that are like for like with the model run; a point without a published spread, a claim in \
             words, and a comparison whose conditions differ from the model's are shown with the reason and left out. \
             Each row gives the conditions the model ran at beside the measurement's own. \"inside?\" gives the signed \
             miss beyond the nearest bound. Values in SI units.\n",
            self.predictions_inside, self.predictions_counted
        );
        let _ = writeln!(w, "## The ball alone\n");
        let _ = writeln!(
            w,
            "The shell ball (`--law shell`, `kick_core::ShellBall`) is calibrated on the FIFA rebound test only: its loss \
             β is set there, its pressure is the test's 0.8 bar, and nothing about a kick went into it. Every shell-ball \
             row below is a prediction of that ball.\n"
        );
        table(&mut w, &self.ball);
        let _ = writeln!(w, "\n## The 1D instep kick\n");
        let _ = writeln!(
            w,
            "Both laws, `accurate` solver, Table 1's foot ({} kg effective mass). A force is compared at the ball speed \
             measured with it: the foot speed is lowered until the ball leaves at that speed \
             (`kick_identify::validation::with_ball_speed`). The rigid foot is set against a nearly rigid mechanical \
             kicking limb at the limb's own foot speeds; players' ratios are shown apart. What each law was calibrated on: \
             the paper's law takes Table 1's k, n and c (the paper's values, fitted to none of these measurements); \
             the shell ball takes the FIFA rebound's β and the test's 0.8 bar, and nothing else.\n",
            short(Scenario::baseline().effective_foot_mass())
        );
        table(&mut w, &self.contact);
        let _ = writeln!(w, "\n## Stiffness and foot mass implied by the measurements\n");
        let _ = writeln!(
            w,
            "Identified only from like-for-like soccer instep targets measured together in one experiment: Tol et al.'s \
             ball speed and mean force. Not used: contact times pooled with rugby and Australian-football punts, a \
             between-player range of ball speeds without a measured foot speed, Tol et al.'s 1610 N (their mean × π/2, \
             not a measured peak), and Asai et al.'s 2439 N (from video and a simulation). An estimate whose σ exceeds \
             it is printed as not identified.\n"
        );
        let _ = writeln!(w, "| law | parameter | estimate | unit | targets | note |");
        let _ = writeln!(w, "|---|---|---|---|---|---|");
        for i in &self.implied {
            let _ = writeln!(
                w,
                "| {} | {} | {} | {} | {} | {} |",
                i.law,
                i.parameter,
                estimate_cell(i.value, i.sigma),
                i.unit,
                i.targets,
                i.note
            );
        }
        let ck = &self.curve_kicks;
        let _ = writeln!(w, "\n## Curve kicks: spin against offset and friction\n");
        let _ = writeln!(
            w,
            "Table 1's kick in 3D (`kick_3d`), the rigid sphere on a knife-edge face tilted by asin(e/R). A spin is \
             compared where the model's ball leaves at the measured ball speed: the offset is chosen for that speed \
             at μ = 0.5 (kick-3d's default friction and tangential spring, assumed, calibrated on nothing here).\n"
        );
        table(&mut w, &ck.rows);
        let frictions: Vec<String> = ck.curves.iter().map(|c| c.first().map_or("?".into(), |p| format!("{}", short(p.friction)))).collect();
        let _ = writeln!(w, "\nSpin (rad/s) and ball speed (m/s) against offset, Table 1's kick at 22 m/s, by friction μ:\n");
        let _ = write!(w, "| offset (mm) |");
        for mu in &frictions {
            let _ = write!(w, " spin μ={mu} |");
        }
        for mu in &frictions {
            let _ = write!(w, " speed μ={mu} |");
        }
        let _ = writeln!(w, "\n|---|{}", "---|".repeat(2 * frictions.len()));
        let n = ck.curves.first().map_or(0, Vec::len);
        for i in 0..n {
            let _ = write!(w, "| {} |", short(1e3 * ck.curves[0][i].offset));
            for c in &ck.curves {
                let _ = write!(w, " {} |", spin_text(c[i].spin));
            }
            for c in &ck.curves {
                let _ = write!(w, " {} |", short(c[i].speed));
            }
            let _ = writeln!(w);
        }
        for p in &ck.largest {
            let _ = writeln!(
                w,
                "\nLargest spin at μ = {}: {} rad/s ({} rev/s) at e = {} mm, inside the ball (R = {} mm), where the ball \
                 leaves at {} m/s.",
                short(p.friction),
                short(p.spin),
                short(p.spin / TAU),
                short(1e3 * p.offset),
                short(1e3 * DEFAULT_BALL_RADIUS),
                short(p.speed)
            );
        }
        let _ = writeln!(w, "\n## Flight: the drag crisis\n");
        table(&mut w, &self.flight);
        let f = &self.free_kicks.kicks;
        let _ = writeln!(w, "\n## Free kicks\n");
        let _ = writeln!(
            w,
            "Launched at {}° (assumed) with sidespin about the vertical, kick-flight's defaults (drag crisis joined to \
             the spinning ball's drag of Goff & Carré 2010 Eq. 4, saturating lift); lateral offset where the ball crosses \
             x = {} m. Re, S, C_D and C_L are the flight's own launch report. The circle estimate is a *check* of the \
             integrator, not a comparison with a measurement: the horizontal path as a circle of the launch curvature \
             with the same C_L. No measured deflection was found to set these beside. Speeds from `{}` ({}), spins \
             from `{}` ({}).\n",
            short(f.launch_angle),
            short(f.distance),
            f.launch_speed.key,
            f.launch_speed.checked,
            f.launch_spin.key,
            f.launch_spin.checked
        );
        let _ = writeln!(
            w,
            "| speed (m/s) | spin (rev/s) | Re at launch | S at launch | C_D at launch | C_L at launch | lateral offset (m) | circle estimate (check, m) | height (m) | time (s) |"
        );
        let _ = writeln!(w, "|---|---|---|---|---|---|---|---|---|---|");
        for (k, a) in f.kicks.iter().zip(&self.free_kicks.launch) {
            let _ = writeln!(
                w,
                "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |",
                short(k.speed),
                short(k.spin / TAU),
                short(a.reynolds),
                short(a.spin_parameter),
                short(a.drag_coefficient),
                short(a.lift_coefficient),
                short(k.lateral_offset),
                short(k.circle_estimate),
                short(k.height),
                short(k.time)
            );
        }
        let _ = writeln!(w, "\n## Sources\n");
        let _ = writeln!(w, "All {} sources of the measurement file:\n", self.citations.len());
        for (key, citation) in &self.citations {
            let _ = writeln!(w, "- `{key}`: {citation}");
        }
        w
    }
}

impl Printable for Validation {
    fn text(&self) -> String {
        format!(
            "validation: {} measurements from {} sources; {} of {} predictions inside their measured interval\n",
            self.measurements, self.sources, self.predictions_inside, self.predictions_counted
        )
    }
    fn written(&self) -> &[PathBuf] {
        &self.written
    }
}

#[cfg(test)]
mod tests;
