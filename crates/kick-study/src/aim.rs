//! `kick aim` and Python's `kick.aim`: which launch, or which kick, sends
//! the ball past the wall to a target in the goal plane (kick-flight's
//! [`kick_flight::aim`] solves it; this adds the kick half and the forms a
//! front end prints).
//!
//! Every launch and kick parameter is held or free. Held: the value its
//! flag (keyword) gives, or its default. Free: those `--free` names, else
//! the default free ones less any given (launch: speed, launch_angle,
//! azimuth; kick: foot_speed, offset, contact_depth, heading), each within
//! bounds (`--range NAME=LOW,HIGH`, else the aim's own: [`LaunchFree::range`],
//! [`kick_bounds`]); a free parameter's given value is its start.
//!
//! `--from kick` solves the 3D kick (kick-3d, `auto` path) before the
//! launch: any scalar parameter of the kick may be free (the offset e and
//! contact depth h of the foot's line of motion, its foot speed and
//! approach angle, the ball's pressure, ...), and the heading ψ, the whole
//! kick turned about the vertical (the run-up's direction; the flight does
//! not change under it, nor a kick without a ground).
//!
//! More free parameters than the target's two equations leave a family of
//! solutions: the report gives its extent (each parameter's range over the
//! members found, the time to the goal line, the clearance) and
//! `--objective` picks one member ([`Objective`]; `kick_flight::aim::family`).

use crate::error::StudyError;
use crate::flight::After;
use crate::printable::Printable;
use kick_3d::{KickSpec, Solver3d};
use kick_core::number::{sig, vector};
use kick_core::parameters::{self, ParameterDef, SetParameter, Shape, Value};
use kick_flight::aim::{aim_best, aim_launch_with, check_unique, AimError, AimSolution, Free, LaunchFree, Objective, Scene, Wall};
/// How close an aim must come, and the wall's margin (kick-flight's aim scene).
pub use kick_flight::aim::{FamilyEnd, WallPass, MISS_TOLERANCE, WALL_MARGIN};
use kick_flight::{Flight, FlightError, FlightParameter, FlightSpec};
use serde::Serialize;
use std::fmt::Write as _;

/// What is solved for: the launch state, or the 3D kick before it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum AimFrom {
    Launch,
    Kick,
}

impl AimFrom {
    pub const NAMES: [&'static str; 2] = ["launch", "kick"];

    pub fn from_name(name: &str) -> Result<AimFrom, StudyError> {
        match name {
            "launch" => Ok(AimFrom::Launch),
            "kick" => Ok(AimFrom::Kick),
            _ => {
                Err(StudyError::Flag { flag: "from", message: format!("unknown `from` = `{name}`: expected launch or kick (flag --from)") })
            }
        }
    }
}

/// The name of the kick's turn about the vertical, a free parameter of `--from kick` of its own.
pub const HEADING: &str = "heading";

/// A kick parameter `--from kick` may hold or free: a declared scalar of
/// the kick's levels, or the heading.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum KickFree {
    Declared(&'static ParameterDef),
    Heading,
}

impl KickFree {
    /// Free unless held (given) or `--free` names others.
    pub const DEFAULT: [&'static str; 4] = ["foot_speed", "offset", "contact_depth", HEADING];

    pub fn name(self) -> &'static str {
        match self {
            KickFree::Declared(p) => p.name,
            KickFree::Heading => HEADING,
        }
    }

    pub fn unit(self) -> &'static str {
        match self {
            KickFree::Declared(p) => p.unit,
            KickFree::Heading => "deg",
        }
    }

    pub fn from_name(name: &str) -> Result<KickFree, AimError> {
        if name == HEADING {
            return Ok(KickFree::Heading);
        }
        match parameters::find_at(KickSpec::LEVELS, name) {
            Ok(p) if p.shape == Shape::Scalar => Ok(KickFree::Declared(p)),
            _ => {
                let mut names: Vec<&str> =
                    parameters::at_levels(KickSpec::LEVELS).filter(|p| p.shape == Shape::Scalar).map(|p| p.name).collect();
                names.push(HEADING);
                Err(AimError::UnknownFree { name: name.to_string(), expected: names.join(", ") })
            }
        }
    }
}

/// The aim's bounds of a free kick parameter without `--range`: foot speed
/// 12–35 m/s (kick-core's sampled range of `foot_speed`, the kicks of its
/// sweeps); e ±7 cm and h 0–7 cm, so √(e² + h²) ≤ 9.9 cm stays inside the
/// 11 cm ball (kick-3d refuses a line outside it); approach angle −20…30°
/// (the off-center box of kick-3d); heading ±45° (the goal is ahead); any
/// other parameter its declared sampling range (None: give `--range`).
pub fn kick_bounds(p: KickFree) -> Option<(f64, f64)> {
    match p {
        KickFree::Heading => Some((-45.0, 45.0)),
        KickFree::Declared(d) => match d.name {
            "foot_speed" => Some((12.0, 35.0)),
            "offset" => Some((-0.07, 0.07)),
            "contact_depth" => Some((0.0, 0.07)),
            "approach_angle" => Some((-20.0, 30.0)),
            _ => d.sample.map(|s| (s.from, s.to)),
        },
    }
}

/// One aim as a front end gives it.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct AimRequest {
    /// X,Y,Z: the goal plane x = X and the ball centre's (Y, Z) there, m.
    pub target: Option<[f64; 3]>,
    /// DIST,HEIGHT,HALF_WIDTH, m [9.15, 1.8, 1].
    pub wall: Option<[f64; 3]>,
    /// launch (default) or kick.
    pub from: Option<AimFrom>,
    /// Names of the free parameters [the default free ones less those given].
    pub free: Option<Vec<String>>,
    /// Held flight parameters (and the starts of free launch parameters).
    pub flight: FlightSpec,
    /// Held kick parameters (`--from kick`; a free one's value is its start).
    pub kick: KickSpec,
    /// Bounds of free parameters, `NAME=LOW,HIGH` (`--range`).
    pub ranges: Vec<String>,
    /// Which member of the family (default: the one the solve reaches from the starts).
    pub objective: Option<Objective>,
}

/// The kick an aim found (`--from kick`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct AimedKick {
    /// Every declared parameter of the kick solved, as built (defaults filled in).
    pub parameters: Vec<(&'static str, Value)>,
    /// The kick's turn about the vertical, degrees.
    pub heading: f64,
    pub contact_time: f64,
    /// |ω| at launch, rev/s.
    pub spin_rev_per_s: f64,
}

/// What `kick aim` prints.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct AimReport {
    pub from: AimFrom,
    #[serde(flatten)]
    pub solution: AimSolution,
    pub kick: Option<AimedKick>,
}

/// An aim error as front ends show it, naming the flag.
pub fn aim_error(error: AimError) -> StudyError {
    let flag = match &error {
        AimError::Flight(_) => None,
        AimError::Invalid { name, .. } => Some(match FlightParameter::from_name(name) {
            Ok(p) => p.def().flag(),
            Err(_) => format!("--{}", name.replace('_', "-")),
        }),
        AimError::UnknownFree { .. } | AimError::DuplicateFree { .. } | AimError::NoFree => Some("--free".into()),
        AimError::Objective { .. } | AimError::UnknownObjective { .. } => Some("--objective".into()),
        _ => None,
    };
    match error {
        AimError::Flight(e) => e.into(),
        source => StudyError::Aim { source, flag },
    }
}

/// `NAME=LOW,HIGH` texts (`--range`) as (name, low, high), each name one
/// this aim can free (`known`: Err if not, else its declaration where it
/// has one), both ends inside the parameter's valid values.
fn parse_bounds(
    given: &[String],
    known: &dyn Fn(&str) -> Result<Option<&'static ParameterDef>, ()>,
) -> Result<Vec<(String, f64, f64)>, StudyError> {
    let refuse = |text: &str, why: &str| StudyError::Flag { flag: "range", message: format!("--range {text}: {why}") };
    let mut out: Vec<(String, f64, f64)> = Vec::new();
    for text in given {
        let (name, bounds) = text.split_once('=').ok_or_else(|| refuse(text, "expected NAME=LOW,HIGH"))?;
        let name = name.trim();
        let Ok(declared) = known(name) else {
            return Err(refuse(text, "not a parameter this aim can free"));
        };
        let numbers: Vec<f64> = bounds
            .split(',')
            .map(|x| x.trim().parse::<f64>())
            .collect::<Result<_, _>>()
            .map_err(|_| refuse(text, "LOW and HIGH must be numbers"))?;
        let [low, high] = numbers[..] else { return Err(refuse(text, "expected two numbers LOW,HIGH")) };
        if !(low.is_finite() && high.is_finite() && low < high) {
            return Err(refuse(text, "LOW and HIGH must be finite with LOW < HIGH"));
        }
        // A range reaching outside the valid values would be searched there
        // and its failures reported as "no solution".
        if let Some(p) = declared.filter(|p| !(p.valid.contains(low) && p.valid.contains(high))) {
            return Err(refuse(text, &format!("`{}` must be {}", p.name, p.valid.requirement)));
        }
        if out.iter().any(|(n, _, _)| n == name) {
            return Err(refuse(text, "given twice"));
        }
        out.push((name.to_string(), low, high));
    }
    Ok(out)
}

/// `kick aim`: solve `request` (see the module docs and [`kick_flight::aim`]).
pub fn aim(request: &AimRequest) -> Result<AimReport, StudyError> {
    aim_cancellable(request, &|| false)
}

/// [`aim`], asking `cancel` before every trial kick and flight: once it
/// says yes the solve ends at once (Python's Ctrl-C, `kick.aim`).
pub fn aim_cancellable(request: &AimRequest, cancel: &dyn Fn() -> bool) -> Result<AimReport, StudyError> {
    let target = request.target.ok_or(StudyError::Flag { flag: "target", message: "`target` is required (flag --target X,Y,Z)".into() })?;
    let wall = match request.wall {
        None => Wall::default(),
        Some([distance, height, half_width]) => Wall { distance, height, half_width },
    };
    let from = request.from.unwrap_or(AimFrom::Launch);
    match from {
        AimFrom::Launch => {
            if request.kick != KickSpec::default() {
                return Err(StudyError::Flag { flag: "from", message: "kick parameters (and --law) apply only with --from kick".into() });
            }
            let given = |p: LaunchFree| match p {
                LaunchFree::Speed => request.flight.speed.is_some(),
                LaunchFree::LaunchAngle => request.flight.launch_angle.is_some(),
                LaunchFree::Azimuth => request.flight.azimuth.is_some(),
                _ => request.flight.spin.is_some(),
            };
            let free = match &request.free {
                None => LaunchFree::DEFAULT.into_iter().filter(|&p| !given(p)).collect(),
                Some(names) => names.iter().map(|n| LaunchFree::from_name(n)).collect::<Result<Vec<_>, _>>().map_err(aim_error)?,
            };
            let bounds = parse_bounds(&request.ranges, &|n| {
                LaunchFree::from_name(n).map(|_| FlightParameter::ALL.iter().find(|f| f.name() == n).map(|f| f.def())).map_err(|_| ())
            })?;
            if let Some((name, _, _)) = bounds.iter().find(|(n, _, _)| !free.iter().any(|p| p.name() == n)) {
                return Err(StudyError::Flag { flag: "range", message: format!("--range {name}: `{name}` is not free (flag --free)") });
            }
            let solution = aim_launch_with(target, wall, &free, &request.flight, &bounds, request.objective, cancel).map_err(aim_error)?;
            Ok(AimReport { from, solution, kick: None })
        }
        AimFrom::Kick => aim_kick(target, wall, request, cancel),
    }
}

fn aim_kick(target: [f64; 3], wall: Wall, request: &AimRequest, cancel: &dyn Fn() -> bool) -> Result<AimReport, StudyError> {
    let free = match &request.free {
        None => KickFree::DEFAULT
            .iter()
            .map(|n| KickFree::from_name(n))
            .collect::<Result<Vec<_>, _>>()
            .map_err(aim_error)?
            .into_iter()
            .filter(|p| match p {
                KickFree::Declared(d) => request.kick.value(d).is_none(),
                KickFree::Heading => true,
            })
            .collect(),
        Some(names) => names.iter().map(|n| KickFree::from_name(n)).collect::<Result<Vec<_>, _>>().map_err(aim_error)?,
    };
    check_unique(&free.iter().map(|p| p.name()).collect::<Vec<_>>(), |n| n).map_err(aim_error)?;
    if let Some(p) = FlightParameter::ALL.into_iter().find(|&p| After::Kick3d.sets(p) && request.flight.is_set(p)) {
        return Err(StudyError::Flag {
            flag: "from",
            message: format!(
                "flight parameter `{}` is set by the 3D kick and cannot be given with --from kick (flag {})",
                p.name(),
                p.def().flag()
            ),
        });
    }
    if let Some(d) = request.flight.distance {
        return Err(aim_error(AimError::Invalid {
            name: "distance",
            values: vec![d],
            requirement: "left out: the target's X is the goal plane",
        }));
    }
    if request.kick.kick3d.ground == Some(true) {
        return Err(StudyError::Flag {
            flag: "ground",
            message:
                "kick parameter `ground` cannot be given with --from kick: the heading turns the kick about the vertical, which a ground \
                      would not allow, and the ball flies from the ground anyway (flag --ground)"
                    .into(),
        });
    }
    let bounds = parse_bounds(&request.ranges, &|n| match KickFree::from_name(n) {
        Ok(KickFree::Declared(p)) => Ok(Some(p)),
        Ok(KickFree::Heading) => Ok(None),
        Err(_) => Err(()),
    })?;
    if let Some((name, _, _)) = bounds.iter().find(|(n, _, _)| !free.iter().any(|p| p.name() == n)) {
        return Err(StudyError::Flag { flag: "range", message: format!("--range {name}: `{name}` is not free (flag --free)") });
    }
    // The kick as given, validated once (its ball radius places the target).
    let base = request.kick.build()?;
    let scene = Scene::new(target, wall, base.ball_radius).map_err(aim_error)?;
    let start = |p: KickFree| -> Option<f64> {
        match p {
            KickFree::Heading => Some(target[1].atan2(target[0]).to_degrees()),
            KickFree::Declared(d) => match request.kick.value(d) {
                Some(Value::Number(x)) => Some(x),
                _ => match d.name {
                    "foot_speed" => Some(18.0),
                    "offset" => Some(0.02),
                    "contact_depth" => Some(crate::free_kick::CONTACT_DEPTH),
                    _ => base.parameter_value(d).and_then(|v| if let Value::Number(x) = v { Some(x) } else { None }),
                },
            },
        }
    };
    let mut parameters = Vec::with_capacity(free.len());
    for &p in &free {
        let given = bounds.iter().find(|(n, _, _)| n == p.name()).map(|&(_, lo, hi)| (lo, hi));
        let (low, high) = given.or_else(|| kick_bounds(p)).ok_or_else(|| StudyError::Flag {
            flag: "range",
            message: format!("`{}` has no bounds of its own to be free within: give them (flag --range {}=LOW,HIGH)", p.name(), p.name()),
        })?;
        let held = matches!(p, KickFree::Declared(d) if request.kick.value(d).is_some());
        let start = start(p).unwrap_or(0.5 * (low + high));
        let start = if held { start } else { start.clamp(low, high) };
        if !(start >= low && start <= high) {
            return Err(aim_error(AimError::Invalid {
                name: p.name(),
                values: vec![start],
                requirement: "within the free parameter's range (the solve's start)",
            }));
        }
        parameters.push(Free { name: p.name(), unit: p.unit(), low, high, start });
    }
    let rest = FlightSpec {
        ball_mass: Some(base.base.ball_mass()),
        ball_radius: Some(base.ball_radius),
        gravity: Some(kick_core::GRAVITY),
        ..request.flight
    };
    // The kick at trial values and its launch, turned by the heading.
    let kick_of = |values: &[f64]| -> Result<(kick_3d::Kick3d, kick_3d::Outcome3d, f64, [f64; 3], [f64; 3]), AimError> {
        if cancel() {
            return Err(AimError::Cancelled);
        }
        let mut spec = request.kick;
        let mut heading = start(KickFree::Heading).unwrap_or(0.0);
        for (&p, &v) in free.iter().zip(values) {
            match p {
                KickFree::Heading => heading = v,
                KickFree::Declared(d) => spec.set_parameter(d, Value::Number(v)).map_err(|e| AimError::Kick(e.to_string()))?,
            }
        }
        let kick = spec.build().map_err(|e| AimError::Kick(e.to_string()))?;
        let outcome = Solver3d::Auto.solve(&kick).map_err(|e| AimError::Kick(e.to_string()))?;
        let (c, s) = (heading.to_radians().cos(), heading.to_radians().sin());
        let turn = |[x, y, z]: [f64; 3]| [x * c - y * s, x * s + y * c, z];
        Ok((kick, outcome, heading, turn(outcome.launch_velocity), turn(outcome.spin)))
    };
    let launch = |values: &[f64]| -> Result<Flight, AimError> {
        let (_, _, _, v, w) = kick_of(values)?;
        if !(v[2] > 0.0) {
            return Err(AimError::Kick(format!("the kick launches the ball at {} m/s, not upward", vector(&v))));
        }
        Flight::from_launch(v, w, &rest).map_err(|e: FlightError| e.into())
    };
    // Restarts: deeper and shallower contacts, other foot speeds (where free).
    let restarts: Vec<Vec<f64>> = [(0.045, 20.0, 0.0), (0.02, 16.0, 0.035), (0.05, 24.0, -0.02)]
        .iter()
        .map(|&(h, speed, e)| {
            free.iter()
                .zip(&parameters)
                .map(|(&p, f)| {
                    let v = match p.name() {
                        "contact_depth" => h,
                        "foot_speed" => speed,
                        "offset" => e,
                        _ => f.start,
                    };
                    v.clamp(f.low, f.high)
                })
                .collect()
        })
        .collect();
    let solution = aim_best(&scene, &parameters, &restarts, &launch, request.objective).map_err(aim_error)?;
    let values: Vec<f64> = solution.parameters.iter().map(|p| p.value).collect();
    let (kick, outcome, heading, _, w) = kick_of(&values).map_err(aim_error)?;
    let kick = AimedKick {
        parameters: kick
            .parameter_values()
            .into_iter()
            .filter(|(p, _)| p.level != kick_core::Level::Instep || kick.instep.is_some())
            .map(|(p, v)| (p.name, v))
            .collect(),
        heading,
        contact_time: outcome.contact_time,
        spin_rev_per_s: (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]).sqrt() / std::f64::consts::TAU,
    };
    Ok(AimReport { from: AimFrom::Kick, solution, kick: Some(kick) })
}

impl Printable for AimReport {
    fn text(&self) -> String {
        let s = &self.solution;
        let mut w = String::new();
        let [x, y, z] = s.scene.target;
        let wall = s.scene.wall;
        let _ = writeln!(w, "{:<18} x = {} m: y = {} m, z = {} m (the ball's centre)", "target", sig(x), sig(y), sig(z));
        let _ = writeln!(w, "{:<18} x = {} m, top {} m, |y| <= {} m", "wall", sig(wall.distance), sig(wall.height), sig(wall.half_width));
        let _ = writeln!(
            w,
            "solved for the {} (range; d(y, z at the goal)/d parameter):",
            match self.from {
                AimFrom::Launch => "launch",
                AimFrom::Kick => "kick",
            }
        );
        for p in &s.parameters {
            let _ = writeln!(
                w,
                "  {:<16} {} {:<6} in [{}, {}]; dy {}, dz {} m per {}",
                p.name,
                sig(p.value),
                p.unit,
                sig(p.low),
                sig(p.high),
                sig(p.sensitivity[0]),
                sig(p.sensitivity[1]),
                p.unit
            );
        }
        if let Some(f) = &s.family {
            let _ = writeln!(
                w,
                "{:<18} {} dimension(s), {} member(s) found of {} tried (pivots {} and {}); over them:",
                "family", f.dimension, f.members, f.tried, f.pivots[0], f.pivots[1]
            );
            for e in &f.extent {
                let _ = writeln!(w, "  {:<16} {} to {} {}", e.name, sig(e.low), sig(e.high), e.unit);
            }
            let _ = writeln!(w, "  {:<16} {} to {} s", "time to goal", sig(f.goal_time[0]), sig(f.goal_time[1]));
            let _ = writeln!(w, "  {:<16} {} to {} m", "wall clearance", sig(f.clearance[0]), sig(f.clearance[1]));
            let _ = writeln!(w, "  {:<16} {} to {} m/s", "launch speed", sig(f.launch_speed[0]), sig(f.launch_speed[1]));
            let chosen = f.objective.map_or("none: the member the solve reached from the starts".to_string(), |o| o.name().to_string());
            let _ = writeln!(w, "{:<18} {chosen}", "objective");
            for end in &f.best_at_end {
                let _ = writeln!(
                    w,
                    "  {:<16} its best member is the {} end, {} {}: {}",
                    end.name,
                    if end.low { "low" } else { "high" },
                    sig(end.value),
                    end.unit,
                    if end.bound {
                        "the parameter's range bound; a wider range would improve the objective"
                    } else {
                        "beyond it the solve found no member that reaches the target past the wall"
                    }
                );
            }
        }
        if let Some(k) = &self.kick {
            let shown: Vec<String> = k
                .parameters
                .iter()
                .filter(|(name, _)| ["foot_speed", "offset", "contact_depth", "approach_angle", "friction"].contains(name))
                .map(|(name, v)| format!("{name} {}", v.numbers().iter().map(|x| sig(*x).to_string()).collect::<Vec<_>>().join(",")))
                .collect();
            let _ = writeln!(
                w,
                "{:<18} {}, heading {} deg; contact {} s, spin {} rev/s",
                "kick",
                shown.join(", "),
                sig(k.heading),
                sig(k.contact_time),
                sig(k.spin_rev_per_s)
            );
        }
        let _ = writeln!(w, "{:<18} {} m/s", "launch_velocity", vector(&s.launch_velocity));
        let _ = writeln!(w, "{:<18} {} rad/s", "spin", vector(&s.spin));
        let _ = writeln!(w, "{:<18} y = {} m, z = {} m", "goal crossing", sig(s.crossing[1]), sig(s.crossing[2]));
        let _ = writeln!(w, "{:<18} {} m", "miss", sig(s.miss));
        let _ = writeln!(
            w,
            "{:<18} {} m, {} the wall (centre at y = {} m, z = {} m)",
            "wall clearance",
            sig(s.wall_clearance),
            s.wall_pass.name(),
            sig(s.wall_crossing[0]),
            sig(s.wall_crossing[1])
        );
        let _ = writeln!(
            w,
            "{:<18} {} residual evaluations, {} start(s); {} more flights for the sensitivities",
            "solve", s.evaluations, s.starts, s.sensitivity_flights
        );
        w
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use kick_flight::aim::{WallPass, MISS_TOLERANCE};

    fn flown(launch: [f64; 3], spin: [f64; 3], d: f64) -> [f64; 2] {
        let rest = FlightSpec { distance: Some(d), ball_mass: Some(0.43), ..FlightSpec::default() };
        let c = kick_flight::solve(&Flight::from_launch(launch, spin, &rest).unwrap()).unwrap().crossing.unwrap();
        [c.lateral_offset, c.height]
    }

    /// The aimed kick rebuilt here: kick-3d's kick at the reported offset
    /// and contact depth (the one definition), solved by the accurate path,
    /// its launch turned about z by ψ, flown from scratch to the goal plane
    /// and the wall.
    #[test]
    fn an_aimed_kick_rebuilt_and_flown_reaches_the_target_past_the_wall() {
        let target = [25.0, -2.5, 1.7];
        let report = aim(&AimRequest { target: Some(target), from: Some(AimFrom::Kick), ..AimRequest::default() }).unwrap();
        let v: Vec<f64> = report.solution.parameters.iter().map(|p| p.value).collect();
        let names: Vec<&str> = report.solution.parameters.iter().map(|p| p.name).collect();
        assert_eq!(names, ["foot_speed", "offset", "contact_depth", "heading"]);
        let (speed, e, h, psi) = (v[0], v[1], v[2], v[3].to_radians());
        let mut spec = KickSpec::default();
        spec.set_named("foot_speed", Value::Number(speed)).unwrap();
        spec.set_named("offset", Value::Number(e)).unwrap();
        spec.set_named("contact_depth", Value::Number(h)).unwrap();
        let outcome = kick_3d::Accurate3d::default().solve(&spec.build().unwrap()).unwrap();
        let turn = |a: [f64; 3]| [a[0] * psi.cos() - a[1] * psi.sin(), a[0] * psi.sin() + a[1] * psi.cos(), a[2]];
        let (launch, spin) = (turn(outcome.launch_velocity), turn(outcome.spin));
        let [y, z] = flown(launch, spin, 25.0);
        let miss = (y - target[1]).hypot(z - target[2]);
        assert!(miss <= MISS_TOLERANCE, "miss {miss} m");
        let [yw, zw] = flown(launch, spin, 9.15);
        let clearance = (zw - 0.11 - 1.8).max(yw.abs() - 0.11 - 1.0);
        assert!(clearance >= 0.0, "clearance {clearance} m");
        assert_eq!(report.solution.wall_pass, WallPass::of(&Wall::default(), 0.11, yw, zw));
        assert!(v.iter().zip(&report.solution.parameters).all(|(x, p)| *x >= p.low && *x <= p.high));
        let kick = report.kick.unwrap();
        let value = |name: &str| kick.parameters.iter().find(|(n, _)| *n == name).map(|(_, v)| *v);
        assert_eq!((value("offset"), value("contact_depth")), (Some(Value::Number(e)), Some(Value::Number(h))));
        // Four free parameters: a family of two dimensions, the solution one of its members.
        let family = report.solution.family.unwrap();
        assert_eq!(family.dimension, 2);
        assert!(family.members >= 1);
        for (x, e) in v.iter().zip(&family.extent) {
            assert!(e.low <= *x && *x <= e.high, "{}: {x} outside {} .. {}", e.name, e.low, e.high);
        }
    }

    /// A parameter given is held: with the offset at 5 cm, the foot speed,
    /// contact depth and heading are free; with `--free`, a given value is
    /// the start; a parameter with no bounds of its own needs `--range`.
    #[test]
    fn given_parameters_are_held_and_free_ones_solved() {
        let target = [25.0, -2.0, 1.8];
        let mut kick = KickSpec::default();
        kick.set_named("offset", Value::Number(0.05)).unwrap();
        let report = aim(&AimRequest { target: Some(target), from: Some(AimFrom::Kick), kick, ..AimRequest::default() }).unwrap();
        let names: Vec<&str> = report.solution.parameters.iter().map(|p| p.name).collect();
        assert_eq!(names, ["foot_speed", "contact_depth", "heading"]);
        let k = report.kick.unwrap();
        assert_eq!(k.parameters.iter().find(|(n, _)| *n == "offset").map(|(_, v)| *v), Some(Value::Number(0.05)));
        let error = aim(&AimRequest {
            target: Some(target),
            from: Some(AimFrom::Kick),
            free: Some(vec!["foot_speed".into(), "ball_inertia".into(), "heading".into()]),
            ..AimRequest::default()
        })
        .unwrap_err();
        assert!(error.to_string().contains("flag --range ball_inertia=LOW,HIGH"), "{error}");
    }

    /// The objective picks one member of the family of the launch (speed,
    /// elevation and azimuth free: one dimension): min-speed is at most the
    /// speed of every member found, min-time at most every time,
    /// max-clearance at least every clearance, each to the compass search's
    /// resolution; each flown again reaches the target.
    #[test]
    fn objectives_pick_the_best_member_of_the_launch_family() {
        let target = [25.0, 2.6, 2.0];
        let base = AimRequest {
            target: Some(target),
            flight: FlightSpec { spin: Some([0.0, 0.0, 50.0]), ..FlightSpec::default() },
            ..AimRequest::default()
        };
        let solve = |o: Option<Objective>| aim(&AimRequest { objective: o, ..base.clone() }).unwrap().solution;
        let free = solve(None);
        let family = free.family.clone().unwrap();
        assert_eq!(family.dimension, 1);
        assert!(family.members >= 5, "{family:?}");
        let speed = |s: &AimSolution| vector_length(s.launch_velocity);
        let slow = solve(Some(Objective::MinSpeed));
        let quick = solve(Some(Objective::MinTime));
        let safe = solve(Some(Objective::MaxClearance));
        let time = |s: &AimSolution| s.outcome.crossing.unwrap().time;
        assert!(speed(&slow) <= family.launch_speed[0] + 1e-3, "{} vs {:?}", speed(&slow), family.launch_speed);
        assert!(time(&quick) <= family.goal_time[0] + 1e-4, "{} vs {:?}", time(&quick), family.goal_time);
        assert!(safe.wall_clearance >= family.clearance[1] - 1e-3, "{} vs {:?}", safe.wall_clearance, family.clearance);
        assert!(speed(&slow) < speed(&quick) && time(&quick) < time(&slow));
        for s in [&slow, &quick, &safe] {
            let [y, z] = flown(s.launch_velocity, s.spin, target[0]);
            assert!((y - target[1]).hypot(z - target[2]) <= MISS_TOLERANCE);
            assert!(s.wall_clearance >= 0.0);
        }
        // min-speed's best member is the family's low end in speed, and the
        // report says so: the same launch held 1 cm/s slower, the two
        // other parameters free, reaches the target past the wall from no start.
        let ends = slow.family.as_ref().unwrap().best_at_end.clone();
        assert_eq!(ends.len(), 1, "{ends:?}");
        assert!(ends[0].name == "speed" && ends[0].low && !ends[0].bound, "{ends:?}");
        let held = FlightSpec { speed: Some(ends[0].value - 0.01), ..base.flight.clone() };
        let slower = aim(&AimRequest { flight: held, ..base.clone() });
        assert!(matches!(slower, Err(StudyError::Aim { source: AimError::NoSolution { .. }, .. })), "{slower:?}");
        let text = aim(&AimRequest { objective: Some(Objective::MinSpeed), ..base.clone() }).unwrap().text();
        assert!(text.contains("its best member is the low end"), "{text}");
        let error = aim(&AimRequest { objective: Some(Objective::MinFootSpeed), ..base.clone() }).unwrap_err();
        // The value given is named (it printed "invalid `objective` = :"), and its flag.
        assert!(error.to_string().starts_with("invalid `objective` = min-foot-speed: must be "), "{error}");
        assert!(error.to_string().ends_with("(flag --objective)"), "{error}");
    }

    fn vector_length(v: [f64; 3]) -> f64 {
        (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt()
    }

    /// A `--range` reaching outside the parameter's valid values is refused
    /// naming `--range` (it was searched and its failures reported as "no
    /// solution", or named `--speed` and a value the user never gave).
    #[test]
    fn ranges_outside_the_valid_values_name_the_range() {
        let base = AimRequest { target: Some([20.0, 0.0, 1.0]), ..AimRequest::default() };
        for (range, from) in
            // 1e200 m/s was searched, and its flights' refusal aborted the
            // aim naming `launch_velocity`, printing inf.
            [
                ("speed=-40,-5", AimFrom::Launch),
                ("speed=1,1e200", AimFrom::Launch),
                ("launch_angle=170,190", AimFrom::Launch),
                ("ball_mass=0,1", AimFrom::Kick),
            ]
        {
            let request = AimRequest {
                from: Some(from),
                ranges: vec![range.into()],
                free: (from == AimFrom::Kick).then(|| vec!["foot_speed".into(), "ball_mass".into()]),
                ..base.clone()
            };
            let error = aim(&request).unwrap_err();
            assert!(matches!(error, StudyError::Flag { flag: "range", .. }), "{error:?}");
            assert!(error.to_string().starts_with(&format!("--range {range}: ")), "{error}");
        }
    }

    /// A family never has more members than solves tried: the first
    /// solution and the ends' bisection count as tries (it said "18
    /// member(s) found of 17 tried").
    #[test]
    fn a_family_has_no_more_members_than_tries() {
        let request = AimRequest { target: Some([0.25, 0.0, 0.2]), wall: Some([0.12, 0.0, 0.0]), ..AimRequest::default() };
        let family = aim(&request).unwrap().solution.family.unwrap();
        assert!(family.members >= 2 && family.members <= family.tried, "{} of {}", family.members, family.tried);
    }

    #[test]
    fn bad_requests_name_their_flags() {
        let error = |r: AimRequest| aim(&r).unwrap_err().to_string();
        let base = AimRequest { target: Some([25.0, 0.0, 1.5]), ..AimRequest::default() };
        let typed = aim(&AimRequest { target: None, ..base.clone() }).unwrap_err();
        assert!(matches!(typed, StudyError::Flag { flag: "target", .. }), "{typed:?}");
        assert!(error(AimRequest { target: None, ..base.clone() }).contains("--target"));
        let text = error(AimRequest { target: Some([25.0, 0.0, 10.0]), ..base.clone() });
        assert!(text.contains("`target`") && text.contains("(flag --target)"), "{text}");
        let text = error(AimRequest { wall: Some([30.0, 1.8, 1.0]), ..base.clone() });
        assert!(text.contains("(flag --wall)"), "{text}");
        let text = error(AimRequest { free: Some(vec!["spinz".into()]), ..base.clone() });
        assert!(text.contains("spin_z") && text.contains("(flag --free)"), "{text}");
        // A free parameter's start outside its range names its flag.
        let free_speed = Some(vec!["speed".into(), "launch_angle".into(), "azimuth".into()]);
        let text =
            error(AimRequest { free: free_speed, flight: FlightSpec { speed: Some(80.0), ..FlightSpec::default() }, ..base.clone() });
        assert!(text.contains("(flag --speed)"), "{text}");
        let text = error(AimRequest { flight: FlightSpec { air_density: Some(f64::NAN), ..FlightSpec::default() }, ..base.clone() });
        assert!(text.contains("(flag --air-density)"), "{text}");
        let text = error(AimRequest { ranges: vec!["speed=30,20".into()], ..base.clone() });
        assert!(text.contains("--range speed=30,20"), "{text}");
        let text = error(AimRequest { ranges: vec!["spin_x=-5,5".into()], ..base.clone() });
        assert!(text.contains("not free"), "{text}");
        let kick = AimRequest { from: Some(AimFrom::Kick), ..base.clone() };
        let mut ground = KickSpec::default();
        ground.set_named("ground", Value::Switch(true)).unwrap();
        let text = error(AimRequest { kick: ground, ..kick.clone() });
        assert!(text.contains("(flag --ground)"), "{text}");
        let mut offset = KickSpec::default();
        offset.set_named("offset", Value::Number(0.02)).unwrap();
        let text = error(AimRequest { kick: offset, ..base.clone() });
        assert!(text.contains("--from kick"), "{text}");
        let text = error(AimRequest { flight: FlightSpec { speed: Some(20.0), ..FlightSpec::default() }, ..kick.clone() });
        assert!(text.contains("`speed`") && text.contains("3D kick"), "{text}");
        assert!(AimFrom::from_name("foot").unwrap_err().to_string().contains("--from"));
    }
}
