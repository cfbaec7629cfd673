//! Free kicks, from the foot to the goal (issue 14): the grid of offset ×
//! friction at a contact depth h: the foot's line of motion passes h below
//! the ball's centre and e beside it (kick-3d's `offset` and
//! `contact_depth`, one definition for every front end), on a horizontal
//! path. kick-store writes the file, kick-paper the figures.

use crate::columns::{Column, OutcomeSet, Setting};
use crate::level::{Failure, Level, Row};
use kick_3d::{Accurate3d, Kick3d, KickSpec, Outcome3d};
use kick_core::parameters::{SetParameter, Value};
use kick_flight::{Flight, FlightSpec};

/// The ball's centre above the foot's line of motion, h, m (kick-3d's `contact_depth`).
pub const CONTACT_DEPTH: f64 = 0.03;
/// Offsets of the grid, m.
pub const OFFSETS: [f64; 10] = [0.0, 0.01, 0.02, 0.03, 0.04, 0.05, 0.06, 0.07, 0.08, 0.09];
/// Coulomb coefficients of the grid (∞: never slips).
pub const FRICTIONS: [f64; 4] = [0.2, 0.5, 1.0, f64::INFINITY];
/// The goal line from the ball, m (the 25 m free kick).
pub const GOAL_DISTANCE: f64 = 25.0;
/// The wall drawn and the goal (Law 1): one definition, kick-flight's aim scene.
pub use kick_flight::aim::{GOAL_HEIGHT, GOAL_WIDTH, WALL_HALF_WIDTH, WALL_HEIGHT};
/// The wall, m (Law 13: 9.15 m), defined once in kick-flight.
pub use kick_flight::models::WALL_DISTANCE;

/// How a ball of radius `r` whose centre crosses the wall's plane at (y, z)
/// passes the drawn wall: `kick aim`'s rule (`kick_flight::aim::WallPass`).
pub fn wall_pass(r: f64, y: f64, z: f64) -> kick_flight::aim::WallPass {
    kick_flight::aim::WallPass::of(&kick_flight::aim::Wall::default(), r, y, z)
}
/// C_D far above the drag crisis without spin (Goff & Carré's Eq. 3, kick-flight's default).
pub const NO_SPIN_DRAG: f64 = kick_flight::coefficients::DragCrisis::SUPERCRITICAL;
/// Columns of the `launch` set: the free kick's launch and the contact.
pub const LAUNCH_COLUMNS: [(&str, &str); 12] = [
    ("launch_velocity_x", "m/s"),
    ("launch_velocity_y", "m/s"),
    ("launch_velocity_z", "m/s"),
    ("spin_x", "rad/s"),
    ("spin_y", "rad/s"),
    ("spin_z", "rad/s"),
    ("speed", "m/s"),
    ("spin_rev_per_s", "rev/s"),
    ("launch_angle", "deg"),
    ("launch_azimuth", "deg"),
    ("contact_time", "s"),
    ("slip_time", "s"),
];

/// The kick at offset e and the grid's contact depth, at friction `friction`, solved.
pub fn kick(offset: f64, friction: f64) -> Result<(Kick3d, Outcome3d), Failure> {
    let mut spec = KickSpec::default();
    spec.set_named("friction", Value::Number(friction)).map_err(|e| Failure::refused(e.to_string()))?;
    kick_at(&spec, offset, CONTACT_DEPTH)
}

/// `spec`'s kick at offset e and contact depth h, solved on the accurate path.
pub fn kick_at(spec: &KickSpec, offset: f64, depth: f64) -> Result<(Kick3d, Outcome3d), Failure> {
    let mut spec = *spec;
    spec.kick3d.offset = Some(offset);
    spec.kick3d.contact_depth = Some(depth);
    let kick = spec.build()?;
    let outcome = Accurate3d::default().solve(&kick)?;
    Ok((kick, outcome))
}

/// One free kick: the kick, its launch and the flight spec after it.
pub struct FreeKick {
    pub kick: Kick3d,
    pub outcome: Outcome3d,
    pub launch_velocity: [f64; 3],
    pub spin: [f64; 3],
}

impl FreeKick {
    pub fn new(offset: f64, friction: f64) -> Result<FreeKick, Failure> {
        let (kick, outcome) = kick(offset, friction)?;
        Ok(FreeKick { launch_velocity: outcome.launch_velocity, spin: outcome.spin, kick, outcome })
    }

    /// The flight after it, crossing x = `distance` (kick-flight's defaults:
    /// drag crisis joined to the spinning ball's drag, saturating lift, no spin decay, sea-level air; the kick's
    /// ball and g).
    pub fn flight(&self, distance: f64) -> Result<Flight, Failure> {
        let rest = FlightSpec {
            ball_mass: Some(self.kick.base.ball_mass()),
            ball_radius: Some(self.kick.ball_radius),
            gravity: Some(kick_core::GRAVITY),
            distance: Some(distance),
            ..FlightSpec::default()
        };
        Flight::from_launch(self.launch_velocity, self.spin, &rest).map_err(crate::flight::flight_failure)
    }

    /// [`LAUNCH_COLUMNS`] values.
    pub fn launch_values(&self) -> Vec<f64> {
        let [vx, vy, vz] = self.launch_velocity;
        let [wx, wy, wz] = self.spin;
        vec![
            vx,
            vy,
            vz,
            wx,
            wy,
            wz,
            (vx * vx + vy * vy + vz * vz).sqrt(),
            (wx * wx + wy * wy + wz * wz).sqrt() / std::f64::consts::TAU,
            vz.atan2(vx.hypot(vy)).to_degrees(),
            vy.atan2(vx).to_degrees(),
            self.outcome.contact_time,
            self.outcome.slip_time,
        ]
    }
}

/// The rows of the grid: (offset, friction), friction fastest.
pub fn grid() -> Vec<(f64, f64)> {
    OFFSETS.iter().flat_map(|&e| FRICTIONS.iter().map(move |&mu| (e, mu))).collect()
}

/// The free-kick grid as a [`Level`]: parameters `offset` (m) and
/// `friction` (1), grid order (friction fastest); outcome sets `launch`
/// ([`LAUNCH_COLUMNS`]), `goal` and `wall` (the flight crossing x =
/// [`GOAL_DISTANCE`] and x = [`WALL_DISTANCE`], kick-flight's columns).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct FreeKicks;

fn columns(list: &[(&str, &str)]) -> Vec<Column> {
    list.iter().map(|(n, u)| Column::new(n, u)).collect()
}

impl Level for FreeKicks {
    fn rows(&self) -> u64 {
        (OFFSETS.len() * FRICTIONS.len()) as u64
    }

    fn parameter_columns(&self) -> Vec<Column> {
        let declared = |p: &kick_core::ParameterDef| Column::new(p.name, p.unit);
        vec![declared(&kick_core::parameters::OFFSET), declared(&kick_core::parameters::FRICTION)]
    }

    fn outcome_sets(&self) -> Vec<OutcomeSet> {
        let flight_set = |name: &str, distance: f64| OutcomeSet {
            solver: name.into(),
            settings: vec![("distance".into(), Setting::Number(distance))],
            columns: columns(kick_flight::outcome_columns(true)),
        };
        vec![
            OutcomeSet {
                solver: "launch".into(),
                settings: vec![(kick_core::parameters::CONTACT_DEPTH.name.into(), Setting::Number(CONTACT_DEPTH))],
                columns: columns(&LAUNCH_COLUMNS),
            },
            flight_set("goal", GOAL_DISTANCE),
            flight_set("wall", WALL_DISTANCE),
        ]
    }

    fn solve_row(&self, index: u64, row: &mut Row) {
        // Grid order, friction fastest (as `grid`), without building the grid.
        let i = index as usize;
        let (e, mu) = (OFFSETS[i / FRICTIONS.len()], FRICTIONS[i % FRICTIONS.len()]);
        row.parameters.copy_from_slice(&[e, mu]);
        let kick = FreeKick::new(e, mu);
        row.put(0, kick.as_ref().map(FreeKick::launch_values).map_err(Clone::clone));
        for (set, distance) in [(1, GOAL_DISTANCE), (2, WALL_DISTANCE)] {
            let flown = kick
                .as_ref()
                .map_err(|f| Failure::refused(format!("no flight: the kick failed: {f}")))
                .and_then(|k| k.flight(distance))
                .and_then(|f| kick_flight::solve(&f).map_err(crate::flight::flight_failure))
                .map(|o| o.values());
            row.put(set, flown);
        }
    }
}

/// Physics World's free kick (Asai, Akatsuka & Haake 1998, as quoted:
/// `free_kick_speed` and `free_kick_spin` of the measurement file, which a
/// test holds these to): launch speeds, m/s...
pub const ILLUSTRATED_SPEEDS: [f64; 2] = [25.0, 30.0];
/// ...and spins, rad/s (8–10 rev/s).
pub const ILLUSTRATED_SPINS: [f64; 2] = [8.0 * std::f64::consts::TAU, 10.0 * std::f64::consts::TAU];
/// The kick whose bend paper/flight.md takes apart: the middle of those
/// (speed m/s, sidespin rad/s), launched as the validation chapter's free kicks.
pub const PLATEAU_KICK: (f64, f64) = (27.5, 9.0 * std::f64::consts::TAU);
/// Constant lift coefficients it is flown with: the fit's plateau, and below it.
pub const PLATEAU_LIFTS: [f64; 3] = [0.29, 0.24, 0.20];
/// Shares of the spin left at landing it is flown with (what-ifs: no measured decay rate).
pub const SPIN_KEPT: [f64; 3] = [0.9, 0.75, 0.5];

/// The ball's trajectory after the kick at (e, μ) to the goal line:
/// `samples` rows uniform in time, as columns time, x, y, z (m) and
/// velocity x, y, z (m/s).
pub fn trajectory(offset: f64, friction: f64, samples: usize) -> Result<[Vec<f64>; 7], Failure> {
    flight_columns(&FreeKick::new(offset, friction)?.flight(GOAL_DISTANCE)?, samples)
}

/// A flight's trajectory as [`trajectory`]'s columns.
pub fn flight_columns(flight: &Flight, samples: usize) -> Result<[Vec<f64>; 7], Failure> {
    let h = kick_flight::history(flight, kick_flight::Sampling::Samples(samples)).map_err(crate::flight::flight_failure)?;
    let column = |f: &dyn Fn(&kick_flight::FlightSample) -> f64| h.samples.iter().map(f).collect::<Vec<f64>>();
    Ok([
        column(&|s| s.time),
        column(&|s| s.position[0]),
        column(&|s| s.position[1]),
        column(&|s| s.position[2]),
        column(&|s| s.velocity[0]),
        column(&|s| s.velocity[1]),
        column(&|s| s.velocity[2]),
    ])
}
