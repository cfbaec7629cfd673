//! Free kicks, from the foot to the goal (issue 14): the grid of lateral
//! offset × friction and the kick at a contact (e, h) below and beside the
//! ball's centre. kick-3d's offset is lateral only; with a horizontal path
//! and no gravity during the contact (kick-3d's default) its kick is
//! symmetric about the foot's path, so the kick at offset √(e² + h²),
//! turned about the path by β = atan2(h, e), is the kick at (e, h): its
//! launch velocity and spin are the lateral kick's, rotated by β about x
//! ([`roll`]). kick-paper writes the file and figures.

use crate::columns::{Column, OutcomeSet, Setting};
use crate::level::{Failure, Level, Row};
use kick_3d::{Accurate3d, Kick3d, KickSpec, Outcome3d};
use kick_core::parameters::{SetParameter, Value};
use kick_flight::{Flight, FlightSpec};

/// Depth of the contact below the ball's centre, h, m.
pub const VERTICAL_OFFSET: f64 = 0.03;
/// Lateral offsets of the grid, m.
pub const LATERAL_OFFSETS: [f64; 10] = [0.0, 0.01, 0.02, 0.03, 0.04, 0.05, 0.06, 0.07, 0.08, 0.09];
/// Coulomb coefficients of the grid (∞: never slips).
pub const FRICTIONS: [f64; 4] = [0.2, 0.5, 1.0, f64::INFINITY];
/// The goal line from the ball, m (the 25 m free kick).
pub const GOAL_DISTANCE: f64 = 25.0;
/// The wall, m (Law 13: 9.15 m), defined once in kick-flight.
pub use kick_flight::models::WALL_DISTANCE;
/// Columns of the `launch` set: the free kick's launch (rotated) and the contact.
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

/// The lateral kick (offset √(e² + h²)) at friction `friction`, solved.
pub fn lateral_kick(lateral_offset: f64, friction: f64) -> Result<(Kick3d, Outcome3d), Failure> {
    let mut spec = KickSpec::default();
    spec.set_named("friction", Value::Number(friction)).map_err(|e| Failure::refused(e.to_string()))?;
    kick_at(&spec, lateral_offset, VERTICAL_OFFSET)
}

/// `spec`'s kick at the contact (e, h), solved as the lateral kick at
/// offset √(e² + h²) (its launch still to be turned by [`roll_at`]).
pub fn kick_at(spec: &KickSpec, lateral_offset: f64, depth: f64) -> Result<(Kick3d, Outcome3d), Failure> {
    let mut spec = *spec;
    spec.set_named("offset", Value::Number(lateral_offset.hypot(depth))).map_err(|e| Failure::refused(e.to_string()))?;
    let kick = spec.build()?;
    let outcome = Accurate3d::default().solve(&kick)?;
    Ok((kick, outcome))
}

/// `v` turned about x by −β, β = atan2(h, e): the lateral kick's +y side
/// goes to (0, cos β, −sin β), below the centre, so a ball sent toward −y
/// rises (see the module docs).
pub fn roll(v: [f64; 3], lateral_offset: f64) -> [f64; 3] {
    roll_at(v, lateral_offset, VERTICAL_OFFSET)
}

/// [`roll`] for a contact `depth` h below the centre (a central contact, e = h = 0, is not turned).
pub fn roll_at(v: [f64; 3], lateral_offset: f64, depth: f64) -> [f64; 3] {
    let r = lateral_offset.hypot(depth);
    if r == 0.0 {
        return v;
    }
    let (c, s) = (lateral_offset / r, depth / r);
    // Rotation about x by −β: y' = y cos β + z sin β, z' = −y sin β + z cos β.
    [v[0], v[1] * c + v[2] * s, -v[1] * s + v[2] * c]
}

/// One free kick: the kick, its rotated launch and the flight spec after it.
pub struct FreeKick {
    pub kick: Kick3d,
    pub outcome: Outcome3d,
    pub launch_velocity: [f64; 3],
    pub spin: [f64; 3],
}

impl FreeKick {
    pub fn new(lateral_offset: f64, friction: f64) -> Result<FreeKick, Failure> {
        let (kick, outcome) = lateral_kick(lateral_offset, friction)?;
        Ok(FreeKick {
            launch_velocity: roll(outcome.launch_velocity, lateral_offset),
            spin: roll(outcome.spin, lateral_offset),
            kick,
            outcome,
        })
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

/// The rows of the grid: (lateral offset, friction), friction fastest.
pub fn grid() -> Vec<(f64, f64)> {
    LATERAL_OFFSETS.iter().flat_map(|&e| FRICTIONS.iter().map(move |&mu| (e, mu))).collect()
}

/// The free-kick grid as a [`Level`]: parameters `lateral_offset` (m) and
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
        (LATERAL_OFFSETS.len() * FRICTIONS.len()) as u64
    }

    fn parameter_columns(&self) -> Vec<Column> {
        vec![Column::new("lateral_offset", "m"), Column::new("friction", "1")]
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
                settings: vec![("vertical_offset".into(), Setting::Number(VERTICAL_OFFSET))],
                columns: columns(&LAUNCH_COLUMNS),
            },
            flight_set("goal", GOAL_DISTANCE),
            flight_set("wall", WALL_DISTANCE),
        ]
    }

    fn solve_row(&self, index: u64, row: &mut Row) {
        // Grid order, friction fastest (as `grid`), without building the grid.
        let i = index as usize;
        let (e, mu) = (LATERAL_OFFSETS[i / FRICTIONS.len()], FRICTIONS[i % FRICTIONS.len()]);
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
