//! Aiming a free kick: the inverse problem of a flight. Which launch sends
//! the ball over the wall and through the goal plane at a target point?
//!
//! The scene ([`Scene`]): the ball starts at (0, 0, R); the wall stands in
//! the plane x = `wall.distance`, centred on y = 0, `wall.half_width` to
//! either side, its top `wall.height` above the ground; the goal plane is
//! x = X of the target, the goal centred on y = 0 (Law 1: 7.32 m × 2.44 m). The
//! target is where the ball's centre should cross the goal plane: the whole
//! ball inside the posts and under the bar.
//!
//! The solve ([`aim_with`]): least squares over the free parameters of the
//! residuals (y − Y, z − Z) at the goal plane and the wall's shortfall
//! max(0, [`WALL_MARGIN`] − clearance), by Levenberg–Marquardt (crate
//! `levenberg-marquardt`, as `kick fit`) with a central-difference Jacobian.
//! Why: the residuals come from located events (plane crossings found by
//! Brent's method on the integrator's dense output) and are smooth in the
//! launch while the crossing exists, but their derivatives would need the
//! variational equations through the drag crisis and the event location;
//! differences of the forward flight (solved to 1e-12 relative, so its
//! noise over a step of 1e-5 in u is far below what LM's steps need) cost a
//! few flights of about 10 µs each. The Jacobian only steers the steps: the
//! solution is judged by its miss, measured on the flight itself. LM rather than Newton because the free parameters
//! usually outnumber the two target equations (speed, elevation and azimuth
//! by default): LM's damped steps go to a nearby solution of the
//! under-determined system, and the wall's hinge residual pushes the path up
//! only while it is too low.
//!
//! Bounds are kept by the change of variables p = lo + (hi − lo)(1 + sin u)/2
//! (as MINUIT does): LM moves u freely and p never leaves [lo, hi].
//!
//! Where the ball lands before a plane, its "crossing" is continued below
//! the ground, height R − (d − x_landing): continuous where the crossing
//! disappears, so LM can climb back from a kick that falls short.
//!
//! The family ([`family`]): with more free parameters than the target's
//! two equations the solutions form a family of n − 2 dimensions. Two free
//! parameters are its pivots (the pair whose range-scaled sensitivities
//! are the least singular at the first solution); the others are its
//! coordinates. A grid over the coordinates' ranges, each point solved for
//! the pivots from its nearest solved neighbour (continuation), gives the
//! members that reach the target past the wall: their extent (each free
//! parameter's, the time to the goal line's and the wall clearance's) is
//! reported, and an [`Objective`] picks one: the best member, refined by a
//! compass search on the coordinates (step halved to 1e-4 of a range).
//!
//! Success: the crossing within [`MISS_TOLERANCE`] of the target and the
//! wall cleared. Otherwise [`AimError::NoSolution`] with the best miss
//! found, after at most [`MAX_STARTS`] starts of at most
//! [`MAX_EVALUATIONS`] residual evaluations each.

use crate::{solve, Flight, FlightError, FlightOutcome};
use kick_core::short;
use levenberg_marquardt::{LeastSquaresProblem, LevenbergMarquardt};
use nalgebra::{storage::Owned, DMatrix, DVector, Dyn};
use serde::Serialize;
use std::cell::RefCell;
use thiserror::Error;

/// Goal width between the posts' inner edges, m (Law 1: 7.32 m).
pub const GOAL_WIDTH: f64 = 7.32;
/// Height of the crossbar's lower edge, m (Law 1: 2.44 m).
pub const GOAL_HEIGHT: f64 = 2.44;
/// The wall's top, m: a standing wall of 1.8 m players (the figure;
/// a jump adds to it: `--wall 9.15,2.2,1`).
pub const WALL_HEIGHT: f64 = 1.8;
/// Half the wall's width, m: four players shoulder to shoulder at about
/// 0.5 m each (an assumption of the scene, not a measurement).
pub const WALL_HALF_WIDTH: f64 = 1.0;
/// The ball passes the wall by at least this much at the solution, m.
pub const WALL_MARGIN: f64 = 0.01;
/// An aimed ball's centre crosses the goal plane within this of the target, m.
pub const MISS_TOLERANCE: f64 = 1e-6;
/// Starts of the solve before it says there is no solution.
pub const MAX_STARTS: usize = 4;
/// Residual evaluations per start (each is two flights).
pub const MAX_EVALUATIONS: usize = 400;
/// Step in the unbounded coordinate u of the Jacobian's central differences.
const JACOBIAN_STEP: f64 = 1e-5;

/// The defensive wall: the plane x = distance, |y| ≤ half_width, up to height.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Wall {
    /// m (Law 13: 9.15 m).
    pub distance: f64,
    /// m above the ground.
    pub height: f64,
    /// m to either side of y = 0.
    pub half_width: f64,
}

impl Default for Wall {
    fn default() -> Wall {
        Wall { distance: crate::models::WALL_DISTANCE, height: WALL_HEIGHT, half_width: WALL_HALF_WIDTH }
    }
}

/// What is aimed at: the target point in the goal plane, past the wall.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Scene {
    /// (X, Y, Z): the goal plane x = X, the ball's centre at (Y, Z) there, m.
    pub target: [f64; 3],
    pub wall: Wall,
}

impl Scene {
    /// Validate against a ball of `radius`: the target inside the goal (the
    /// whole ball between the posts and under the bar), the wall between
    /// the ball and the goal. Errors name `target` or `wall`.
    pub fn new(target: [f64; 3], wall: Wall, radius: f64) -> Result<Scene, AimError> {
        let [x, y, z] = target;
        if !target.iter().all(|v| v.is_finite()) {
            return Err(AimError::Invalid { name: "target", values: target.to_vec(), requirement: "three finite numbers X,Y,Z, m" });
        }
        if !(x > 0.0) {
            return Err(AimError::Invalid {
                name: "target",
                values: target.to_vec(),
                requirement: "a goal plane X > 0 m in front of the ball",
            });
        }
        let (half, top) = (0.5 * GOAL_WIDTH - radius, GOAL_HEIGHT - radius);
        if !(y.abs() <= half && z >= radius && z <= top) {
            return Err(AimError::Invalid {
                name: "target",
                values: target.to_vec(),
                requirement: "inside the goal: |Y| <= 3.66 m - R (posts) and R <= Z <= 2.44 m - R (ground, bar), the ball's centre",
            });
        }
        let w = [wall.distance, wall.height, wall.half_width];
        if !w.iter().all(|v| v.is_finite()) || wall.height < 0.0 || wall.half_width < 0.0 {
            return Err(AimError::Invalid {
                name: "wall",
                values: w.to_vec(),
                requirement: "finite DIST,HEIGHT,HALF_WIDTH with HEIGHT and HALF_WIDTH >= 0, m",
            });
        }
        if !(wall.distance > radius && wall.distance < x - radius) {
            return Err(AimError::Invalid {
                name: "wall",
                values: w.to_vec(),
                requirement: "DIST between the ball and the target's plane (R < DIST < X - R; the default wall stands at \
                              9.15 m: a nearer target needs a nearer --wall, or --target farther)",
            });
        }
        Ok(Scene { target, wall })
    }
}

/// One free parameter: name, unit, bounds and where the solve starts.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Free {
    pub name: &'static str,
    pub unit: &'static str,
    pub low: f64,
    pub high: f64,
    pub start: f64,
}

/// One free parameter's value at the solution and how the crossing moves with it.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Solved {
    pub name: &'static str,
    pub unit: &'static str,
    pub value: f64,
    pub low: f64,
    pub high: f64,
    /// ∂(y, z of the goal-plane crossing)/∂(this parameter), m per unit:
    /// Richardson-extrapolated central differences (truncation O(h⁴)); held
    /// to 1e-5 relative of plain differences at a 10× smaller step by
    /// `tests/flight/aim.rs`.
    pub sensitivity: [f64; 2],
}

/// An aimed kick.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct AimSolution {
    pub scene: Scene,
    pub parameters: Vec<Solved>,
    pub launch_velocity: [f64; 3],
    pub spin: [f64; 3],
    /// Where the centre crosses the goal plane, m.
    pub crossing: [f64; 3],
    /// Distance from the crossing to the target, m.
    pub miss: f64,
    /// How far the ball passes the wall: over its top (centre height − R −
    /// height) or beside it (|y| − R − half_width), the larger; m.
    pub wall_clearance: f64,
    /// Centre at the wall plane (y, z), m.
    pub wall_crossing: [f64; 2],
    /// How the ball passes the wall: over its top, or beside it.
    pub wall_pass: WallPass,
    /// The solution family this member was chosen from (more free
    /// parameters than two), and by which objective.
    pub family: Option<Family>,
    /// The flight to its landing, crossing the goal plane.
    pub outcome: FlightOutcome,
    /// The flight flown (its launch, ball, air, coefficients; crossing the goal plane).
    #[serde(skip)]
    pub flight: Flight,
    /// Residual evaluations over all starts (each two flights), Jacobians included.
    pub evaluations: usize,
    /// Flights flown for [`Solved::sensitivity`] at the solution, after the
    /// solve: four per free parameter (central differences at h and h/2).
    pub sensitivity_flights: usize,
    /// Starts tried (the last one succeeded).
    pub starts: usize,
}

/// How a ball passes the wall plane.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum WallPass {
    /// Above its top, by more than it passes beside it (the clearance's sense).
    Over,
    /// Outside its width, by more than it passes over it.
    Beside,
    /// Into it.
    Hits,
}

impl WallPass {
    /// How a ball of radius `r` whose centre crosses the wall plane at (y, z) passes `wall`.
    /// A ball both over and beside is named by the larger margin, the one the
    /// clearance reports (it said "beside" of 3.57 m over the top and 0.21 m beside).
    pub fn of(wall: &Wall, r: f64, y: f64, z: f64) -> WallPass {
        let (beside, over) = (y.abs() - r - wall.half_width, z - r - wall.height);
        if beside < 0.0 && over < 0.0 {
            WallPass::Hits
        } else if over >= beside {
            WallPass::Over
        } else {
            WallPass::Beside
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            WallPass::Over => "over",
            WallPass::Beside => "beside",
            WallPass::Hits => "into",
        }
    }
}

/// Which member of the solution family an aim returns.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Objective {
    /// The least foot speed (`foot_speed` free).
    MinFootSpeed,
    /// The least launch speed.
    MinSpeed,
    /// The least time to the goal line (the keeper's least time).
    MinTime,
    /// The most room over or beside the wall.
    MaxClearance,
}

impl Objective {
    pub const ALL: [Objective; 4] = [Objective::MinFootSpeed, Objective::MinSpeed, Objective::MinTime, Objective::MaxClearance];

    pub fn name(self) -> &'static str {
        match self {
            Objective::MinFootSpeed => "min-foot-speed",
            Objective::MinSpeed => "min-speed",
            Objective::MinTime => "min-time",
            Objective::MaxClearance => "max-clearance",
        }
    }

    pub fn from_name(name: &str) -> Result<Objective, AimError> {
        Objective::ALL
            .into_iter()
            .find(|o| o.name() == name)
            .ok_or_else(|| AimError::UnknownObjective { name: name.to_string(), expected: Objective::ALL.map(Objective::name).join(", ") })
    }

    /// The member's score, lower better; None when the objective does not
    /// apply to these free parameters (`min-foot-speed` without a free `foot_speed`).
    fn score(self, member: &Member, free: &[Free]) -> Option<f64> {
        Some(match self {
            Objective::MinFootSpeed => member.values[free.iter().position(|f| f.name == "foot_speed")?],
            Objective::MinSpeed => member.launch_speed,
            Objective::MinTime => member.goal_time,
            Objective::MaxClearance => -member.clearance,
        })
    }
}

/// One member of a solution family: its free parameters' values and what it gives.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Member {
    pub values: Vec<f64>,
    /// Time from launch to the goal plane, s.
    pub goal_time: f64,
    /// Wall clearance, m.
    pub clearance: f64,
    /// |v0|, m/s.
    pub launch_speed: f64,
    /// |ω0|, rad/s.
    pub spin: f64,
}

/// One free parameter's extent over the family's members found.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Extent {
    pub name: &'static str,
    pub unit: &'static str,
    pub low: f64,
    pub high: f64,
}

/// The solution family an aim's member was chosen from.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Family {
    /// n − 2 for n free parameters.
    pub dimension: usize,
    /// The two parameters solved for at each point of the others.
    pub pivots: [&'static str; 2],
    /// Grid points tried and members found (reaching the target past the wall).
    pub tried: usize,
    pub members: usize,
    /// Each free parameter's extent over the members found.
    pub extent: Vec<Extent>,
    /// Time to the goal line and wall clearance over the members, (least, most).
    pub goal_time: [f64; 2],
    pub clearance: [f64; 2],
    pub launch_speed: [f64; 2],
    /// The objective the returned member minimises (None: the member LM reached from the start).
    pub objective: Option<Objective>,
    /// Residual evaluations of the family's solves (each two flights).
    pub evaluations: usize,
    /// The coordinates along which the objective's best member is an end of
    /// the members found: what stops it there is the parameter's range or
    /// the end of the solutions found, not an optimum of the objective.
    pub best_at_end: Vec<FamilyEnd>,
}

/// The objective's best member at an end of the family along one coordinate.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FamilyEnd {
    pub name: &'static str,
    pub unit: &'static str,
    pub value: f64,
    /// The low end (else the high one).
    pub low: bool,
    /// On the parameter's range bound (else the last member found: beyond
    /// it no member reaches the target past the wall).
    pub bound: bool,
}

/// Grid points per coordinate of a family of `dimension` coordinates.
fn grid_points(dimension: usize) -> usize {
    match dimension {
        0 => 1,
        1 => 17,
        2 => 7,
        3 => 4,
        4 => 3,
        _ => 2,
    }
}

/// The member an aim's solution is.
fn member_of(solution: &AimSolution) -> Member {
    let v = solution.launch_velocity;
    let w = solution.spin;
    Member {
        values: solution.parameters.iter().map(|p| p.value).collect(),
        goal_time: solution.outcome.crossing.map_or(f64::NAN, |c| c.time),
        clearance: solution.wall_clearance,
        launch_speed: (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt(),
        spin: (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]).sqrt(),
    }
}

/// The family of `solution` (an aim over `free` by `launch`), and the
/// member `objective` picks (None: `solution` itself). See the module docs.
pub fn family(
    scene: &Scene,
    free: &[Free],
    launch: &Launch,
    solution: &AimSolution,
    objective: Option<Objective>,
) -> Result<(Family, Member), AimError> {
    let n = free.len();
    let first = member_of(solution);
    if let Some(o) = objective {
        if o.score(&first, free).is_none() {
            return Err(AimError::Objective {
                name: o.name(),
                requirement: "min-foot-speed with foot_speed free (--from kick); min-speed, min-time or max-clearance otherwise",
            });
        }
    }
    let extent_of = |members: &[Member]| -> Vec<Extent> {
        free.iter()
            .enumerate()
            .map(|(i, f)| {
                let (low, high) =
                    members.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), m| (a.min(m.values[i]), b.max(m.values[i])));
                Extent { name: f.name, unit: f.unit, low, high }
            })
            .collect()
    };
    let span = |members: &[Member], get: fn(&Member) -> f64| {
        members.iter().fold([f64::INFINITY, f64::NEG_INFINITY], |[a, b], m| [a.min(get(m)), b.max(get(m))])
    };
    let summary = |members: &[Member], pivots, tried, evaluations| Family {
        dimension: n.saturating_sub(2),
        pivots,
        tried,
        members: members.len(),
        extent: extent_of(members),
        goal_time: span(members, |m| m.goal_time),
        clearance: span(members, |m| m.clearance),
        launch_speed: span(members, |m| m.launch_speed),
        objective,
        evaluations,
        best_at_end: Vec::new(),
    };
    if n <= 2 {
        let pivots = [free.first().map_or("", |f| f.name), free.get(1).map_or("", |f| f.name)];
        return Ok((summary(std::slice::from_ref(&first), pivots, 1, 0), first));
    }
    // Pivots: the pair whose range-scaled sensitivities are the least singular.
    let scaled: Vec<[f64; 2]> =
        solution.parameters.iter().map(|p| [p.sensitivity[0] * (p.high - p.low), p.sensitivity[1] * (p.high - p.low)]).collect();
    let (mut pi, mut pj, mut best) = (0, 1, -1.0);
    for i in 0..n {
        for j in i + 1..n {
            let det = (scaled[i][0] * scaled[j][1] - scaled[i][1] * scaled[j][0]).abs();
            if det > best {
                (pi, pj, best) = (i, j, det);
            }
        }
    }
    let coordinates: Vec<usize> = (0..n).filter(|&k| k != pi && k != pj).collect();
    let mut evaluations = 0usize;
    // The member at coordinate values `c`, its pivots started at `guess`.
    let mut solve_at = |c: &[f64], guess: [f64; 2]| -> Option<Member> {
        let pivot = |k: usize, start: f64| Free { start: start.clamp(free[k].low, free[k].high), ..free[k] };
        let pivots = [pivot(pi, guess[0]), pivot(pj, guess[1])];
        let assemble = |v2: &[f64]| -> Vec<f64> {
            let mut full = vec![0.0; n];
            full[pi] = v2[0];
            full[pj] = v2[1];
            for (&k, &x) in coordinates.iter().zip(c) {
                full[k] = x;
            }
            full
        };
        let reduced = |v2: &[f64]| launch(&assemble(v2));
        let found = aim_with(scene, &pivots, &[], &reduced);
        match found {
            Ok(s) => {
                evaluations += s.evaluations;
                let mut m = member_of(&s);
                m.values = assemble(&m.values);
                Some(m)
            }
            Err(_) => {
                evaluations += MAX_EVALUATIONS;
                None
            }
        }
    };
    // The grid over the coordinates, nearest to the first solution first.
    let points = grid_points(coordinates.len());
    let axes: Vec<Vec<f64>> = coordinates
        .iter()
        .map(|&k| {
            (0..points)
                .map(|i| {
                    if points == 1 {
                        first.values[k]
                    } else {
                        free[k].low + (free[k].high - free[k].low) * i as f64 / (points - 1) as f64
                    }
                })
                .collect()
        })
        .collect();
    let mut grid: Vec<Vec<f64>> = vec![Vec::new()];
    for axis in &axes {
        grid = grid.iter().flat_map(|p| axis.iter().map(move |&x| [p.clone(), vec![x]].concat())).collect();
    }
    let scaled_distance = |a: &[f64], b: &[f64]| -> f64 {
        coordinates.iter().zip(a.iter().zip(b)).map(|(&k, (x, y))| ((x - y) / (free[k].high - free[k].low)).powi(2)).sum::<f64>()
    };
    let start_c: Vec<f64> = coordinates.iter().map(|&k| first.values[k]).collect();
    grid.sort_by(|a, b| scaled_distance(a, &start_c).total_cmp(&scaled_distance(b, &start_c)));
    let mut members = vec![first.clone()];
    // The first solution is a member tried too, as is every solve below.
    let mut tried = grid.len() + 1;
    for c in &grid {
        let coords = |m: &Member| -> Vec<f64> { coordinates.iter().map(|&k| m.values[k]).collect() };
        let nearest =
            members.iter().min_by(|a, b| scaled_distance(&coords(a), c).total_cmp(&scaled_distance(&coords(b), c))).unwrap_or(&first);
        if let Some(m) = solve_at(c, [nearest.values[pi], nearest.values[pj]]) {
            members.push(m);
        }
    }
    // One coordinate: its members' ends found by bisection toward the
    // grid's neighbours outside (to 1/64 of a grid step).
    if coordinates.len() == 1 {
        let k = coordinates[0];
        let step = (free[k].high - free[k].low) / (points - 1) as f64;
        for toward in [-1.0, 1.0] {
            let end = members.iter().map(|m| m.values[k]).fold(if toward < 0.0 { f64::INFINITY } else { f64::NEG_INFINITY }, |a, x| {
                if toward < 0.0 {
                    a.min(x)
                } else {
                    a.max(x)
                }
            });
            let Some(mut inside) = members.iter().find(|m| m.values[k] == end).cloned() else { continue };
            let mut gap = step;
            for _ in 0..6 {
                gap *= 0.5;
                let c = (inside.values[k] + toward * gap).clamp(free[k].low, free[k].high);
                if c == inside.values[k] {
                    break;
                }
                tried += 1;
                if let Some(m) = solve_at(&[c], [inside.values[pi], inside.values[pj]]) {
                    members.push(m.clone());
                    inside = m;
                }
            }
        }
    }
    let pivots = [free[pi].name, free[pj].name];
    let Some(objective) = objective else {
        return Ok((summary(&members, pivots, tried, evaluations), first));
    };
    let score = |m: &Member| objective.score(m, free).unwrap_or(f64::INFINITY);
    let mut best = members.iter().min_by(|a, b| score(a).total_cmp(&score(b))).cloned().unwrap_or(first);
    // Compass search on the coordinates from the best member.
    let mut steps: Vec<f64> = coordinates.iter().map(|&k| (free[k].high - free[k].low) / (2.0 * (points.max(2) - 1) as f64)).collect();
    let mut probes = 0;
    while probes < 400 && coordinates.iter().zip(&steps).any(|(&k, s)| *s > 1e-4 * (free[k].high - free[k].low)) {
        let mut improved = false;
        for d in 0..coordinates.len() {
            for sign in [1.0, -1.0] {
                let mut c: Vec<f64> = coordinates.iter().map(|&k| best.values[k]).collect();
                let k = coordinates[d];
                c[d] = (c[d] + sign * steps[d]).clamp(free[k].low, free[k].high);
                if c[d] == best.values[k] {
                    continue;
                }
                probes += 1;
                if let Some(m) = solve_at(&c, [best.values[pi], best.values[pj]]) {
                    if score(&m) < score(&best) {
                        members.push(m.clone());
                        best = m;
                        improved = true;
                    } else {
                        members.push(m);
                    }
                }
            }
        }
        if !improved {
            steps.iter_mut().for_each(|s| *s *= 0.5);
        }
    }
    let mut family = summary(&members, pivots, tried + probes, evaluations);
    family.best_at_end = coordinates
        .iter()
        .filter_map(|&k| {
            let v = best.values[k];
            let (low, high) = members.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), m| (a.min(m.values[k]), b.max(m.values[k])));
            // A range with one member has no end to speak of.
            if low == high || (v != low && v != high) {
                return None;
            }
            let at_low = v == low;
            let bound = if at_low { v <= free[k].low } else { v >= free[k].high };
            Some(FamilyEnd { name: free[k].name, unit: free[k].unit, value: v, low: at_low, bound })
        })
        .collect();
    Ok((family, best))
}

/// [`aim_with`], then the family of its solution and the member
/// `objective` picks, reported with every parameter's sensitivity at it:
/// the aim of `kick aim`.
pub fn aim_best(
    scene: &Scene,
    free: &[Free],
    restarts: &[Vec<f64>],
    launch: &Launch,
    objective: Option<Objective>,
) -> Result<AimSolution, AimError> {
    let solution = aim_with(scene, free, restarts, launch)?;
    if free.len() <= 2 && objective.is_none() {
        return Ok(solution);
    }
    let (family, best) = family(scene, free, launch, &solution, objective)?;
    let mut chosen = match objective {
        None => solution,
        Some(_) => {
            // The member itself, a solution found with its coordinates held
            // (on target past the wall by construction): its report with
            // every parameter's sensitivity. Solving again from it with every
            // parameter free drifted along the family (away from the
            // objective's best: 1.913 against 1.917 m of clearance in
            // flight.md's kick aim).
            let flight = launch(&best.values)?;
            let t = trial(scene, &flight)?;
            let miss = (t.goal[0] - scene.target[1]).hypot(t.goal[1] - scene.target[2]);
            let (evaluations, starts) = (solution.evaluations + family.evaluations, solution.starts);
            solution_of(scene, free, launch, &best.values, (t, flight), miss, evaluations, starts)?
        }
    };
    chosen.family = Some(family);
    Ok(chosen)
}

/// Why aiming was refused or found nothing.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum AimError {
    #[error("invalid `{name}` = {}: must be {requirement}", values.iter().map(|v| kick_core::number::given(*v).to_string()).collect::<Vec<_>>().join(","))]
    Invalid { name: &'static str, values: Vec<f64>, requirement: &'static str },
    /// An objective the family's members have no value of (min-foot-speed without the kick).
    #[error("invalid `objective` = {name}: must be {requirement}")]
    Objective { name: &'static str, requirement: &'static str },
    #[error("unknown objective `{name}`: expected one of {expected}")]
    UnknownObjective { name: String, expected: String },
    #[error("unknown free parameter `{name}`: expected one of {expected}")]
    UnknownFree { name: String, expected: String },
    #[error("free parameter `{name}` given twice")]
    DuplicateFree { name: String },
    #[error("nothing to solve for: no free parameters")]
    NoFree,
    #[error("the launch: {0}")]
    Flight(#[from] FlightError),
    #[error("the kick: {0}")]
    Kick(String),
    #[error(
        "no solution found within the parameters' ranges from {starts} starts (one may still exist elsewhere in them: `--free` with a parameter's flag starts it there): the best misses the target by {} m with the wall {} by {} m",
        short(*miss), if *wall_clearance >= 0.0 { "cleared" } else { "hit" }, short(wall_clearance.abs())
    )]
    NoSolution { miss: f64, wall_clearance: f64, starts: usize },
    /// The caller's cancel check said stop (Python's Ctrl-C).
    #[error("cancelled by the caller")]
    Cancelled,
}

/// What one trial launch gives: the flight, or an error that ends the start.
pub type Launch<'a> = dyn Fn(&[f64]) -> Result<Flight, AimError> + 'a;

/// The crossing of plane x = d, continued below the ground past a landing short of it: (y, z).
fn crossing_of(flight: &Flight, d: f64) -> Result<([f64; 2], FlightOutcome), AimError> {
    let outcome = solve(&flight.with_distance(Some(d))?)?;
    let point = match outcome.crossing {
        Some(c) => [c.lateral_offset, c.height],
        None => [outcome.landing_point[1], flight.ball_radius() - (d - outcome.landing_point[0])],
    };
    Ok((point, outcome))
}

/// Goal-plane crossing, wall crossing and wall clearance of one flight.
struct Trial {
    goal: [f64; 2],
    wall: [f64; 2],
    clearance: f64,
    outcome: FlightOutcome,
}

fn trial(scene: &Scene, flight: &Flight) -> Result<Trial, AimError> {
    let (goal, outcome) = crossing_of(flight, scene.target[0])?;
    let (wall, _) = crossing_of(flight, scene.wall.distance)?;
    let r = flight.ball_radius();
    let clearance = (wall[1] - r - scene.wall.height).max(wall[0].abs() - r - scene.wall.half_width);
    Ok(Trial { goal, wall, clearance, outcome })
}

fn residuals_of(scene: &Scene, t: &Trial) -> DVector<f64> {
    DVector::from_vec(vec![t.goal[0] - scene.target[1], t.goal[1] - scene.target[2], (WALL_MARGIN - t.clearance).max(0.0)])
}

/// p = lo + (hi − lo)(1 + sin u)/2 and back.
fn to_value(f: &Free, u: f64) -> f64 {
    f.low + (f.high - f.low) * 0.5 * (1.0 + u.sin())
}
fn to_u(f: &Free, value: f64) -> f64 {
    // A start on a bound would have zero slope: start just inside.
    let s = (2.0 * (value - f.low) / (f.high - f.low) - 1.0).clamp(-0.999, 0.999);
    s.asin()
}

struct Problem<'a> {
    scene: &'a Scene,
    free: &'a [Free],
    launch: &'a Launch<'a>,
    u: DVector<f64>,
    evaluations: RefCell<usize>,
    failure: RefCell<Option<AimError>>,
}

impl Problem<'_> {
    fn values(&self, u: &DVector<f64>) -> Vec<f64> {
        self.free.iter().zip(u.iter()).map(|(f, &u)| to_value(f, u)).collect()
    }
    fn residuals_at(&self, u: &DVector<f64>) -> Result<DVector<f64>, AimError> {
        *self.evaluations.borrow_mut() += 1;
        let flight = (self.launch)(&self.values(u))?;
        Ok(residuals_of(self.scene, &trial(self.scene, &flight)?))
    }
    fn keep<T>(&self, r: Result<T, AimError>) -> Option<T> {
        r.map_err(|e| *self.failure.borrow_mut() = Some(e)).ok()
    }
}

impl LeastSquaresProblem<f64, Dyn, Dyn> for Problem<'_> {
    type ResidualStorage = Owned<f64, Dyn>;
    type JacobianStorage = Owned<f64, Dyn, Dyn>;
    type ParameterStorage = Owned<f64, Dyn>;

    fn set_params(&mut self, u: &DVector<f64>) {
        self.u.copy_from(u);
    }
    fn params(&self) -> DVector<f64> {
        self.u.clone()
    }
    fn residuals(&self) -> Option<DVector<f64>> {
        self.keep(self.residuals_at(&self.u))
    }
    fn jacobian(&self) -> Option<DMatrix<f64>> {
        let mut j = DMatrix::zeros(3, self.u.len());
        for col in 0..self.u.len() {
            let (mut plus, mut minus) = (self.u.clone(), self.u.clone());
            plus[col] += JACOBIAN_STEP;
            minus[col] -= JACOBIAN_STEP;
            let column = self.keep(self.residuals_at(&plus))? - self.keep(self.residuals_at(&minus))?;
            j.set_column(col, &(column / (2.0 * JACOBIAN_STEP)));
        }
        Some(j)
    }
}

/// ∂(goal-plane y, z)/∂p at `values`, central differences at steps h and
/// h/2 combined by Richardson extrapolation (error O(h⁴)), h = 1e-3 of the
/// parameter's range, moved inside the range at a bound.
fn sensitivities(scene: &Scene, free: &[Free], launch: &Launch, values: &[f64]) -> Result<Vec<[f64; 2]>, AimError> {
    let goal = |v: &[f64]| -> Result<[f64; 2], AimError> { Ok(crossing_of(&launch(v)?, scene.target[0])?.0) };
    let mut out = Vec::with_capacity(free.len());
    for (i, f) in free.iter().enumerate() {
        let h = 1e-3 * (f.high - f.low);
        // The centre of the stencil: inside [lo + h, hi − h].
        let centre = values[i].clamp(f.low + h, f.high - h);
        let mut at = values.to_vec();
        let mut difference = |step: f64| -> Result<[f64; 2], AimError> {
            at[i] = centre + step;
            let plus = goal(&at)?;
            at[i] = centre - step;
            let minus = goal(&at)?;
            Ok([(plus[0] - minus[0]) / (2.0 * step), (plus[1] - minus[1]) / (2.0 * step)])
        };
        let (coarse, fine) = (difference(h)?, difference(0.5 * h)?);
        out.push([(4.0 * fine[0] - coarse[0]) / 3.0, (4.0 * fine[1] - coarse[1]) / 3.0]);
    }
    Ok(out)
}

/// The solution at `values`, a launch already flown and found on target
/// past the wall: its sensitivities, crossings and report.
#[allow(clippy::too_many_arguments)]
fn solution_of(
    scene: &Scene,
    free: &[Free],
    launch: &Launch,
    values: &[f64],
    (t, flight): (Trial, Flight),
    miss: f64,
    evaluations: usize,
    starts: usize,
) -> Result<AimSolution, AimError> {
    let slopes = sensitivities(scene, free, launch, values)?;
    let parameters = free
        .iter()
        .zip(values)
        .zip(slopes)
        .map(|((f, &value), sensitivity)| Solved { name: f.name, unit: f.unit, value, low: f.low, high: f.high, sensitivity })
        .collect();
    Ok(AimSolution {
        scene: *scene,
        parameters,
        launch_velocity: flight.launch_velocity(),
        spin: flight.spin(),
        crossing: [scene.target[0], t.goal[0], t.goal[1]],
        miss,
        wall_clearance: t.clearance,
        wall_crossing: t.wall,
        wall_pass: WallPass::of(&scene.wall, flight.ball_radius(), t.wall[0], t.wall[1]),
        family: None,
        outcome: t.outcome,
        flight: flight.with_distance(Some(scene.target[0]))?,
        evaluations,
        sensitivity_flights: 4 * free.len(),
        starts,
    })
}

/// Aim: the free parameters (`free`, starts and bounds) that make
/// `launch`'s flight cross the goal plane at the target past the wall (see
/// the module docs). `restarts` are further starts tried in turn when one
/// fails, each a full set of start values (at most [`MAX_STARTS`] in all).
pub fn aim_with(scene: &Scene, free: &[Free], restarts: &[Vec<f64>], launch: &Launch) -> Result<AimSolution, AimError> {
    if free.is_empty() {
        return Err(AimError::NoFree);
    }
    for f in free {
        if !(f.low.is_finite() && f.high.is_finite() && f.low < f.high && f.start.is_finite()) {
            return Err(AimError::Invalid { name: f.name, values: vec![f.start], requirement: "a finite start within finite bounds" });
        }
        if !(f.start >= f.low && f.start <= f.high) {
            return Err(AimError::Invalid { name: f.name, values: vec![f.start], requirement: "a start within the parameter's range" });
        }
    }
    let first: Vec<f64> = free.iter().map(|f| f.start).collect();
    let starts = std::iter::once(&first).chain(restarts.iter().filter(|s| s.len() == free.len())).take(MAX_STARTS);
    let mut best: Option<(f64, f64, f64)> = None;
    let (mut evaluations, mut tried) = (0, 0);
    let mut failure = None;
    for start in starts {
        tried += 1;
        let u0 = DVector::from_iterator(free.len(), free.iter().zip(start).map(|(f, &v)| to_u(f, v.clamp(f.low, f.high))));
        let problem = Problem { scene, free, launch, u: u0, evaluations: RefCell::new(0), failure: RefCell::new(None) };
        let lm =
            LevenbergMarquardt::new().with_ftol(1e-15).with_xtol(1e-15).with_gtol(0.0).with_patience(MAX_EVALUATIONS / (free.len() + 1));
        let (solved, _report) = lm.minimize(problem);
        evaluations += *solved.evaluations.borrow();
        let values = solved.values(&solved.u);
        let checked = launch(&values).and_then(|flight| Ok((trial(scene, &flight)?, flight)));
        let (t, flight) = match checked {
            Ok(found) => found,
            // No further start once the caller asked to stop.
            Err(AimError::Cancelled) => return Err(AimError::Cancelled),
            Err(e) => {
                failure = Some(e);
                continue;
            }
        };
        let miss = (t.goal[0] - scene.target[1]).hypot(t.goal[1] - scene.target[2]);
        if miss <= MISS_TOLERANCE && t.clearance >= 0.0 {
            return solution_of(scene, free, launch, &values, (t, flight), miss, evaluations, tried);
        }
        // Rank failed starts by miss, then by how badly the wall is hit.
        let score = miss + t.clearance.min(0.0).abs();
        if best.is_none_or(|(_, _, b)| score < b) {
            best = Some((miss, t.clearance, score));
        }
        failure = solved.failure.into_inner().or(failure);
    }
    match best {
        Some((miss, wall_clearance, _)) => Err(AimError::NoSolution { miss, wall_clearance, starts: tried }),
        // No start gave a flight: the launch itself is the problem.
        None => Err(failure.unwrap_or(AimError::NoSolution { miss: f64::INFINITY, wall_clearance: f64::NEG_INFINITY, starts: tried })),
    }
}

/// A launch parameter the solve may free (`kick aim --from launch --free ...`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum LaunchFree {
    Speed,
    LaunchAngle,
    Azimuth,
    SpinX,
    SpinY,
    SpinZ,
}

/// Spin bound per component, rad/s: the range over which the flight's
/// accuracy is tested (80 rad/s per axis, crate docs), above the 8–10 rev/s
/// (50–63 rad/s) of measured free kicks (Asai, Akatsuka & Haake 1998).
pub const SPIN_BOUND: f64 = 80.0;

impl LaunchFree {
    pub const ALL: [LaunchFree; 6] =
        [LaunchFree::Speed, LaunchFree::LaunchAngle, LaunchFree::Azimuth, LaunchFree::SpinX, LaunchFree::SpinY, LaunchFree::SpinZ];
    /// Free unless chosen: the launch velocity, spin held at what is given (0 unless given).
    pub const DEFAULT: [LaunchFree; 3] = [LaunchFree::Speed, LaunchFree::LaunchAngle, LaunchFree::Azimuth];

    pub fn name(self) -> &'static str {
        match self {
            LaunchFree::Speed => "speed",
            LaunchFree::LaunchAngle => "launch_angle",
            LaunchFree::Azimuth => "azimuth",
            LaunchFree::SpinX => "spin_x",
            LaunchFree::SpinY => "spin_y",
            LaunchFree::SpinZ => "spin_z",
        }
    }

    pub fn unit(self) -> &'static str {
        match self {
            LaunchFree::Speed => "m/s",
            LaunchFree::LaunchAngle | LaunchFree::Azimuth => "deg",
            _ => "rad/s",
        }
    }

    /// Bounds: speed 5–40 m/s (the flight's tested 3–40 m/s, around the
    /// 25–30 m/s of measured free kicks, Asai, Akatsuka & Haake 1998);
    /// elevation 1–60° (a kick along the ground cannot clear a wall, a lob
    /// steeper than 60° does not reach a goal 25 m away at these speeds);
    /// azimuth ±45° (the goal is ahead); spin ±[`SPIN_BOUND`] per component.
    pub fn range(self) -> (f64, f64) {
        match self {
            LaunchFree::Speed => (5.0, 40.0),
            LaunchFree::LaunchAngle => (1.0, 60.0),
            LaunchFree::Azimuth => (-45.0, 45.0),
            _ => (-SPIN_BOUND, SPIN_BOUND),
        }
    }

    pub fn from_name(name: &str) -> Result<LaunchFree, AimError> {
        LaunchFree::ALL
            .into_iter()
            .find(|p| p.name() == name)
            .ok_or_else(|| AimError::UnknownFree { name: name.to_string(), expected: LaunchFree::ALL.map(|p| p.name()).join(", ") })
    }
}

/// Refuse a free list naming one parameter twice.
pub fn check_unique<T: PartialEq + Copy>(free: &[T], name: impl Fn(T) -> &'static str) -> Result<(), AimError> {
    match free.iter().enumerate().find(|(i, p)| free[..*i].contains(p)) {
        Some((_, &p)) => Err(AimError::DuplicateFree { name: name(p).to_string() }),
        None => Ok(()),
    }
}

/// Aim the launch: `free` solved for (bounds: [`LaunchFree::range`]),
/// everything else from `fixed` (a free parameter given there is its start;
/// otherwise speed 25 m/s, elevation 15°, azimuth toward the target, spin 0).
/// `fixed` may not set `launch_velocity` or `distance` (the target sets the plane).
pub fn aim_launch(target: [f64; 3], wall: Wall, free: &[LaunchFree], fixed: &crate::FlightSpec) -> Result<AimSolution, AimError> {
    aim_launch_with(target, wall, free, fixed, &[], None, &|| false)
}

/// [`aim_launch`], asking `cancel` before every trial flight: once it says
/// yes, the solve ends with [`AimError::Cancelled`] (Python's Ctrl-C).
pub fn aim_launch_cancellable(
    target: [f64; 3],
    wall: Wall,
    free: &[LaunchFree],
    fixed: &crate::FlightSpec,
    cancel: &dyn Fn() -> bool,
) -> Result<AimSolution, AimError> {
    aim_launch_with(target, wall, free, fixed, &[], None, cancel)
}

/// [`aim_launch_cancellable`] with bounds of free parameters other than
/// [`LaunchFree::range`] (`bounds`: name, low, high) and the family's
/// member `objective` picks ([`aim_best`]).
pub fn aim_launch_with(
    target: [f64; 3],
    wall: Wall,
    free: &[LaunchFree],
    fixed: &crate::FlightSpec,
    bounds: &[(String, f64, f64)],
    objective: Option<Objective>,
    cancel: &dyn Fn() -> bool,
) -> Result<AimSolution, AimError> {
    check_unique(free, LaunchFree::name)?;
    if let Some(v) = fixed.launch_velocity {
        return Err(AimError::Invalid {
            name: "launch_velocity",
            values: v.to_vec(),
            requirement: "left out: the launch is aimed as speed, launch_angle and azimuth",
        });
    }
    if let Some(d) = fixed.distance {
        return Err(AimError::Invalid { name: "distance", values: vec![d], requirement: "left out: the target's X is the goal plane" });
    }
    let radius = fixed.ball_radius.unwrap_or(kick_core::DEFAULT_BALL_RADIUS);
    if !(radius.is_finite() && radius > 0.0) {
        return Err(FlightError::InvalidParameter { name: "ball_radius", value: radius, requirement: "finite and > 0, m" }.into());
    }
    let scene = Scene::new(target, wall, radius)?;
    let spin = fixed.spin.unwrap_or([0.0; 3]);
    let given = |p: LaunchFree| match p {
        LaunchFree::Speed => fixed.speed,
        LaunchFree::LaunchAngle => fixed.launch_angle,
        LaunchFree::Azimuth => fixed.azimuth,
        LaunchFree::SpinX => fixed.spin.map(|s| s[0]),
        LaunchFree::SpinY => fixed.spin.map(|s| s[1]),
        LaunchFree::SpinZ => fixed.spin.map(|s| s[2]),
    };
    let default_start = |p: LaunchFree| match p {
        LaunchFree::Speed => 25.0,
        LaunchFree::LaunchAngle => 15.0,
        LaunchFree::Azimuth => target[1].atan2(target[0]).to_degrees(),
        _ => 0.0,
    };
    let mut parameters = Vec::with_capacity(free.len());
    for &p in free {
        let (low, high) = bounds.iter().find(|(n, _, _)| n == p.name()).map_or(p.range(), |&(_, lo, hi)| (lo, hi));
        // A default start moves inside bounds given; a start given does not.
        let start = given(p).unwrap_or_else(|| if low < high { default_start(p).clamp(low, high) } else { default_start(p) });
        if !(start >= low && start <= high) {
            return Err(AimError::Invalid {
                name: p.name(),
                values: vec![start],
                requirement: "within the free parameter's range (the solve's start)",
            });
        }
        parameters.push(Free { name: p.name(), unit: p.unit(), low, high, start });
    }
    // Restarts: other elevations and speeds where those are free.
    let restarts: Vec<Vec<f64>> = [(10.0, 20.0), (22.0, 28.0), (30.0, 35.0)]
        .iter()
        .map(|&(angle, speed)| {
            free.iter()
                .zip(&parameters)
                .map(|(&p, f)| match p {
                    LaunchFree::LaunchAngle => angle,
                    LaunchFree::Speed => speed,
                    _ => f.start,
                })
                .collect()
        })
        .collect();
    let base = crate::FlightSpec { spin: Some(spin), ..*fixed };
    let launch = move |values: &[f64]| -> Result<Flight, AimError> {
        if cancel() {
            return Err(AimError::Cancelled);
        }
        let mut spec = base;
        let mut w = spin;
        for (&p, &v) in free.iter().zip(values) {
            match p {
                LaunchFree::Speed => spec.speed = Some(v),
                LaunchFree::LaunchAngle => spec.launch_angle = Some(v),
                LaunchFree::Azimuth => spec.azimuth = Some(v),
                LaunchFree::SpinX => w[0] = v,
                LaunchFree::SpinY => w[1] = v,
                LaunchFree::SpinZ => w[2] = v,
            }
        }
        spec.spin = Some(w);
        Ok(spec.build()?)
    };
    aim_best(&scene, &parameters, &restarts, &launch, objective)
}
