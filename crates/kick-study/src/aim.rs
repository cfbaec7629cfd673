//! `kick aim` and Python's `kick.aim`: which launch, or which kick, sends
//! the ball over the wall to a target in the goal plane (kick-flight's
//! [`kick_flight::aim`] solves it; this adds the kick half and the forms a
//! front end prints).
//!
//! `--from kick` frees the 3D kick instead of the launch: foot speed, the
//! contact's lateral offset e and depth h below the ball's centre (the free
//! kick of [`crate::free_kick`]: the lateral kick at offset √(e² + h²),
//! turned about the foot's path by [`free_kick::roll_at`]) and the heading ψ,
//! the whole kick turned about the vertical (the run-up's direction; the
//! flight does not change under it). Every other kick parameter is the
//! spec's; the foot's path stays horizontal with no gravity during the
//! contact, which the turn about the path needs.

use crate::error::StudyError;
use crate::flight::After;
use crate::free_kick::{self, VERTICAL_OFFSET};
use crate::printable::Printable;
use kick_3d::KickSpec;
use kick_core::number::{sig, vector};
use kick_flight::aim::{aim_launch_cancellable, aim_with, check_unique, AimError, AimSolution, Free, LaunchFree, Scene, Wall};
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

/// A kick parameter `--from kick` may free.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum KickFree {
    FootSpeed,
    LateralOffset,
    ContactDepth,
    Heading,
}

impl KickFree {
    pub const ALL: [KickFree; 4] = [KickFree::FootSpeed, KickFree::LateralOffset, KickFree::ContactDepth, KickFree::Heading];

    pub fn name(self) -> &'static str {
        match self {
            KickFree::FootSpeed => "foot_speed",
            KickFree::LateralOffset => "lateral_offset",
            KickFree::ContactDepth => "contact_depth",
            KickFree::Heading => "heading",
        }
    }

    pub fn unit(self) -> &'static str {
        match self {
            KickFree::FootSpeed => "m/s",
            KickFree::LateralOffset | KickFree::ContactDepth => "m",
            KickFree::Heading => "deg",
        }
    }

    /// Bounds: foot speed 12–35 m/s (kick-core's sampled range of
    /// `foot_speed`, the kicks of its sweeps); e ±7 cm and h 0–7 cm, so
    /// √(e² + h²) ≤ 9.9 cm stays inside the 11 cm ball (kick-3d refuses an
    /// offset outside it) and within the 0–9 cm of the free-kick grid;
    /// heading ±45° (the goal is ahead).
    pub fn range(self) -> (f64, f64) {
        match self {
            KickFree::FootSpeed => (12.0, 35.0),
            KickFree::LateralOffset => (-0.07, 0.07),
            KickFree::ContactDepth => (0.0, 0.07),
            KickFree::Heading => (-45.0, 45.0),
        }
    }

    pub fn from_name(name: &str) -> Result<KickFree, AimError> {
        KickFree::ALL
            .into_iter()
            .find(|p| p.name() == name)
            .ok_or_else(|| AimError::UnknownFree { name: name.to_string(), expected: KickFree::ALL.map(|p| p.name()).join(", ") })
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
    /// Names of the free parameters [launch: speed, launch_angle, azimuth;
    /// kick: foot_speed, lateral_offset, contact_depth, heading].
    pub free: Option<Vec<String>>,
    /// Fixed flight parameters (and the starts of free launch parameters).
    pub flight: FlightSpec,
    /// Fixed kick parameters (`--from kick`; foot_speed, when free, is its start).
    pub kick: KickSpec,
}

/// The kick an aim found (`--from kick`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct AimedKick {
    /// Offset of the lateral kick solved, √(e² + h²), m.
    pub offset: f64,
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
        _ => None,
    };
    match error {
        AimError::Flight(e) => e.into(),
        source => StudyError::Aim { source, flag },
    }
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
            let free = match &request.free {
                None => LaunchFree::DEFAULT.to_vec(),
                Some(names) => names.iter().map(|n| LaunchFree::from_name(n)).collect::<Result<Vec<_>, _>>().map_err(aim_error)?,
            };
            if request.kick != KickSpec::default() {
                return Err(StudyError::Flag { flag: "from", message: "kick parameters (and --law) apply only with --from kick".into() });
            }
            let solution = aim_launch_cancellable(target, wall, &free, &request.flight, cancel).map_err(aim_error)?;
            Ok(AimReport { from, solution, kick: None })
        }
        AimFrom::Kick => aim_kick(target, wall, request, cancel),
    }
}

fn aim_kick(target: [f64; 3], wall: Wall, request: &AimRequest, cancel: &dyn Fn() -> bool) -> Result<AimReport, StudyError> {
    let free = match &request.free {
        None => KickFree::ALL.to_vec(),
        Some(names) => names.iter().map(|n| KickFree::from_name(n)).collect::<Result<Vec<_>, _>>().map_err(aim_error)?,
    };
    check_unique(&free, KickFree::name).map_err(aim_error)?;
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
    let k = &request.kick.kick3d;
    for (name, given) in [
        ("offset", k.offset.is_some()),
        ("approach_angle", k.approach_angle_deg.is_some()),
        ("gravity", k.gravity == Some(true)),
        ("ground", k.ground == Some(true)),
    ] {
        if given {
            return Err(StudyError::Flag {
                flag: "from",
                message: format!(
                    "kick parameter `{name}` cannot be given with --from kick: the contact is placed by lateral_offset and \
                     contact_depth on a horizontal path without gravity (flag --{})",
                    name.replace('_', "-")
                ),
            });
        }
    }
    // The kick as given, validated once (its ball radius places the target).
    let base = request.kick.build()?;
    let scene = Scene::new(target, wall, base.ball_radius).map_err(aim_error)?;
    let start = |p: KickFree| match p {
        KickFree::FootSpeed => request.kick.scenario.foot_speed.unwrap_or(18.0),
        KickFree::LateralOffset => 0.02,
        KickFree::ContactDepth => VERTICAL_OFFSET,
        KickFree::Heading => target[1].atan2(target[0]).to_degrees(),
    };
    let mut parameters = Vec::with_capacity(free.len());
    for &p in &free {
        let (low, high) = p.range();
        let start = start(p);
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
    // The kick at a trial (foot speed, e, h, ψ) and its launch.
    let kick_of = |values: &[f64]| -> Result<(f64, kick_3d::Outcome3d, [f64; 3], [f64; 3]), AimError> {
        if cancel() {
            return Err(AimError::Cancelled);
        }
        let value = |p: KickFree| free.iter().position(|&q| q == p).map_or_else(|| start(p), |i| values[i]);
        let (e, h, heading) = (value(KickFree::LateralOffset), value(KickFree::ContactDepth), value(KickFree::Heading));
        let mut spec = request.kick;
        spec.scenario.foot_speed = Some(value(KickFree::FootSpeed));
        let (_, outcome) = free_kick::kick_at(&spec, e, h).map_err(|f| AimError::Kick(f.message))?;
        let (c, s) = (heading.to_radians().cos(), heading.to_radians().sin());
        let turn = |v: [f64; 3]| {
            let [x, y, z] = free_kick::roll_at(v, e, h);
            [x * c - y * s, x * s + y * c, z]
        };
        Ok((e.hypot(h), outcome, turn(outcome.launch_velocity), turn(outcome.spin)))
    };
    let launch = |values: &[f64]| -> Result<Flight, AimError> {
        let (_, _, v, w) = kick_of(values)?;
        if !(v[2] > 0.0) {
            return Err(AimError::Kick(format!("the kick launches the ball at {} m/s, not upward", vector(&v))));
        }
        Flight::from_launch(v, w, &rest).map_err(|e: FlightError| e.into())
    };
    // Restarts: deeper and shallower contacts, other foot speeds.
    let restarts: Vec<Vec<f64>> = [(0.045, 20.0, 0.0), (0.02, 16.0, 0.035), (0.05, 24.0, -0.02)]
        .iter()
        .map(|&(h, speed, e)| {
            free.iter()
                .zip(&parameters)
                .map(|(&p, f)| match p {
                    KickFree::ContactDepth => h,
                    KickFree::FootSpeed => speed,
                    KickFree::LateralOffset => e,
                    KickFree::Heading => f.start,
                })
                .collect()
        })
        .collect();
    let solution = aim_with(&scene, &parameters, &restarts, &launch).map_err(aim_error)?;
    let values: Vec<f64> = solution.parameters.iter().map(|p| p.value).collect();
    let (offset, outcome, _, w) = kick_of(&values).map_err(aim_error)?;
    let kick = AimedKick {
        offset,
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
        if let Some(k) = &self.kick {
            let _ = writeln!(
                w,
                "{:<18} {} m (lateral kick), contact {} s, spin {} rev/s",
                "kick",
                sig(k.offset),
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
            "{:<18} {} m (centre at y = {} m, z = {} m)",
            "wall clearance",
            sig(s.wall_clearance),
            sig(s.wall_crossing[0]),
            sig(s.wall_crossing[1])
        );
        let _ = writeln!(w, "{:<18} {} residual evaluations, {} start(s)", "solve", s.evaluations, s.starts);
        w
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use kick_3d::Accurate3d;
    use kick_core::parameters::{SetParameter, Value};
    use kick_flight::aim::MISS_TOLERANCE;

    /// The aimed kick rebuilt here: kick-3d's lateral kick at √(e² + h²),
    /// its launch turned about x by −atan2(h, e) and about z by ψ, flown
    /// from scratch to the goal plane and the wall.
    #[test]
    fn an_aimed_kick_rebuilt_and_flown_reaches_the_target_over_the_wall() {
        let target = [25.0, -2.5, 1.7];
        let report = aim(&AimRequest { target: Some(target), from: Some(AimFrom::Kick), ..AimRequest::default() }).unwrap();
        let v: Vec<f64> = report.solution.parameters.iter().map(|p| p.value).collect();
        let names: Vec<&str> = report.solution.parameters.iter().map(|p| p.name).collect();
        assert_eq!(names, ["foot_speed", "lateral_offset", "contact_depth", "heading"]);
        let (speed, e, h, psi) = (v[0], v[1], v[2], v[3].to_radians());
        let mut spec = KickSpec::default();
        spec.set_named("foot_speed", Value::Number(speed)).unwrap();
        spec.set_named("offset", Value::Number((e * e + h * h).sqrt())).unwrap();
        let outcome = Accurate3d::default().solve(&spec.build().unwrap()).unwrap();
        let beta = h.atan2(e);
        let turn = |a: [f64; 3]| {
            let (y, z) = (a[1] * beta.cos() + a[2] * beta.sin(), -a[1] * beta.sin() + a[2] * beta.cos());
            [a[0] * psi.cos() - y * psi.sin(), a[0] * psi.sin() + y * psi.cos(), z]
        };
        let (launch, spin) = (turn(outcome.launch_velocity), turn(outcome.spin));
        let cross = |d: f64| {
            let rest = FlightSpec { distance: Some(d), ball_mass: Some(0.43), ..FlightSpec::default() };
            let c = kick_flight::solve(&Flight::from_launch(launch, spin, &rest).unwrap()).unwrap().crossing.unwrap();
            [c.lateral_offset, c.height]
        };
        let [y, z] = cross(25.0);
        let miss = (y - target[1]).hypot(z - target[2]);
        assert!(miss <= MISS_TOLERANCE, "miss {miss} m");
        let [yw, zw] = cross(9.15);
        let clearance = (zw - 0.11 - 1.8).max(yw.abs() - 0.11 - 1.0);
        assert!(clearance >= 0.0, "clearance {clearance} m");
        assert!(v.iter().zip(&report.solution.parameters).all(|(x, p)| *x >= p.low && *x <= p.high));
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
        let text = error(AimRequest { flight: FlightSpec { speed: Some(80.0), ..FlightSpec::default() }, ..base.clone() });
        assert!(text.contains("(flag --speed)"), "{text}");
        let text = error(AimRequest { flight: FlightSpec { air_density: Some(f64::NAN), ..FlightSpec::default() }, ..base.clone() });
        assert!(text.contains("(flag --air-density)"), "{text}");
        let kick = AimRequest { from: Some(AimFrom::Kick), ..base.clone() };
        let mut offset = KickSpec::default();
        offset.set_named("offset", Value::Number(0.02)).unwrap();
        let text = error(AimRequest { kick: offset, ..kick.clone() });
        assert!(text.contains("(flag --offset)"), "{text}");
        let text = error(AimRequest { kick: offset, ..base.clone() });
        assert!(text.contains("--from kick"), "{text}");
        let text = error(AimRequest { flight: FlightSpec { speed: Some(20.0), ..FlightSpec::default() }, ..kick.clone() });
        assert!(text.contains("`speed`") && text.contains("3D kick"), "{text}");
        assert!(AimFrom::from_name("foot").unwrap_err().to_string().contains("--from"));
    }
}
