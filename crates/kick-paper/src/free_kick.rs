//! Free kicks, from the foot to the goal (issue 14): the 3D kick chained
//! into kick-flight, over offset × friction, written to
//! `OUT/flight/free_kick.h5`, and the figures drawn back from that file.
//!
//! Setup (a choice, stated on the generated page): Table 1's foot (3 kg at
//! 22 m/s), its ball and contact law, the foot's path horizontal (α = 0),
//! the defaults of kick-3d otherwise. The foot's line of motion passes
//! [`CONTACT_DEPTH`] below the ball's centre and e beside it (kick-3d's
//! `contact_depth` and `offset`), so the ball rises with backspin and curves
//! with sidespin, as a free kick over a wall does.
//!
//! File layout (a sweep table, [`crate::h5`]): parameters `offset` (m) and
//! `friction` (1) per row (grid order: offset, then friction fastest;
//! `/grid`, `grid_shape`); outcome sets `launch` ([`LAUNCH_COLUMNS`], its
//! setting `contact_depth`), `goal` (the flight with its crossing of
//! x = [`GOAL_DISTANCE`]) and `wall` (crossing x = [`WALL_DISTANCE`]), both
//! [`kick_flight::OUTCOME_COLUMNS`]; the trajectories of
//! [`TRAJECTORY_OFFSETS`] × [`TRAJECTORY_FRICTIONS`] as
//! `solvers/goal/histories/<row>` ([`TRAJECTORY_COLUMNS`], uniform in time).

use crate::figures::{color, save_grid, save_grid_equal_scale, FigureError, Panel, Series};
use crate::h5::SweepData;
use plotters::prelude::{RGBColor, SeriesLabelPosition};
use std::path::{Path, PathBuf};

/// The physics (the grid, the kick at (e, h)) is kick-study's, the file kick-store's.
pub use kick_store::free_kick::{write, FILE, TRAJECTORY_COLUMNS, TRAJECTORY_FRICTIONS, TRAJECTORY_OFFSETS, TRAJECTORY_SAMPLES};
pub use kick_study::aimed::*;
pub use kick_study::free_kick::*;

/// Trajectories are drawn up to this x, m (a little past the goal line).
pub const SHOWN_TO: f64 = GOAL_DISTANCE + 3.0;

const GREY: RGBColor = RGBColor(90, 90, 90);

/// Figures from `h5` (written by [`write`]) into `dir`: `flight_free_kick`
/// (trajectories from above and from the side, wall and goal drawn) and
/// `flight_deflection` (at the goal line and the wall against the lateral
/// offset, one curve per friction).
pub fn figures(h5: &Path, dir: &Path) -> Result<Vec<PathBuf>, FigureError> {
    let data = SweepData::read(h5)?;
    let missing = |what: &str| FigureError::Draw { figure: h5.display().to_string(), message: format!("no {what}") };
    let goal = data.set("goal")?;
    let wall = data.set("wall")?;
    let launch = data.set("launch")?;
    let offsets = data.parameter(kick_study::parameters::OFFSET.name)?.to_vec();
    let frictions = data.parameter("friction")?.to_vec();
    let label = |row: usize| {
        format!("e = {} cm, μ = {}", kick_study::printable::short(offsets[row] * 100.0), crate::three_d::value_label(frictions[row]))
    };
    // Trajectories: every row with a stored history.
    let mut top = Vec::new();
    let mut side = Vec::new();
    let mut drawn = 0;
    for (row, &friction) in frictions.iter().enumerate() {
        let Ok(h) = crate::h5::read_history(h5, &goal.group, row) else { continue };
        let get = |name: &str| h.iter().find(|(c, _)| c.name == name).map(|(_, v)| v.clone()).ok_or_else(|| missing(name));
        let (x, y, z) = (get("x")?, get("y")?, get("z")?);
        // Up to a little past the goal line: the free kick, not the rest of the flight.
        let shown = x.iter().position(|&v| v > SHOWN_TO).map_or(x.len(), |i| i + 1);
        let (x, y, z) = (&x[..shown], &y[..shown], &z[..shown]);
        let mut line = Series::line(&label(row), color(drawn), x, y);
        let mut height = Series::line(&label(row), color(drawn), x, z);
        if friction.is_infinite() {
            line = line.dashed();
            height = height.dashed();
        }
        top.push(line);
        side.push(height);
        drawn += 1;
    }
    if drawn == 0 {
        return Err(missing("trajectories"));
    }
    let half = GOAL_WIDTH / 2.0;
    // The wall: a marker across the path from above, a 1.8 m segment from the side;
    // the goal: the line between the posts from above, posts and bar from the side.
    top.push(Series::line("", GREY, &[WALL_DISTANCE, WALL_DISTANCE], &[-WALL_HALF_WIDTH, WALL_HALF_WIDTH]).with_markers());
    top.push(Series::line("", RGBColor(0, 0, 0), &[GOAL_DISTANCE, GOAL_DISTANCE], &[-half, half]).with_markers());
    side.push(Series::line("", GREY, &[WALL_DISTANCE, WALL_DISTANCE], &[0.0, WALL_HEIGHT]));
    side.push(Series::line("", RGBColor(0, 0, 0), &[GOAL_DISTANCE, GOAL_DISTANCE, GOAL_DISTANCE + 1.0], &[0.0, GOAL_HEIGHT, GOAL_HEIGHT]));
    let mut top_panel = Panel::new(
        &format!("from above, equal scale (wall at {WALL_DISTANCE} m, goal {GOAL_WIDTH} m wide at {GOAL_DISTANCE} m; dashed: μ = ∞)"),
        "x along the foot's path (m)",
        "lateral y (m)",
        top,
    );
    top_panel.y_from_zero = false;
    top_panel.legend = SeriesLabelPosition::LowerLeft;
    let mut side_panel = Panel::new(
        &format!("from the side (wall {WALL_HEIGHT} m, crossbar {GOAL_HEIGHT} m; height of the ball's centre)"),
        "x along the foot's path (m)",
        "height z (m)",
        side,
    );
    side_panel.legend = SeriesLabelPosition::UpperLeft;
    // The plan view at equal scale: a stretched lateral axis would exaggerate the bend.
    let mut written = save_grid_equal_scale(
        dir,
        "flight_free_kick",
        &format!("Free kicks from the 3D kick through the flight (shown to x = {SHOWN_TO} m)"),
        (2, 1),
        &[top_panel, side_panel],
        &[0],
        // The plan is about as wide as it is long (the 6 cm kicks bend 14 m in 21 m).
        Some(1500),
    )?;

    // Against the lateral offset, one curve per friction.
    let column = |set: &crate::h5::SetData, name: &str| set.column(name).map(<[f64]>::to_vec).ok_or_else(|| missing(name));
    let y_goal = column(goal, "crossing_lateral_offset")?;
    let (vx, vy) = (column(launch, "launch_velocity_x")?, column(launch, "launch_velocity_y")?);
    // The curve: lateral position at the goal line minus the straight launch line's.
    let curve: Vec<f64> = (0..data.rows()).map(|r| y_goal[r] - GOAL_DISTANCE * vy[r] / vx[r]).collect();
    let (h_goal, h_wall) = (column(goal, "crossing_height")?, column(wall, "crossing_height")?);
    let per_friction = |y: &[f64]| -> Vec<Series> {
        let mut list: Vec<f64> = Vec::new();
        for &m in &frictions {
            if !list.iter().any(|w| w.to_bits() == m.to_bits()) {
                list.push(m);
            }
        }
        list.iter()
            .enumerate()
            .map(|(i, &m)| {
                let rows: Vec<usize> = (0..data.rows()).filter(|&r| frictions[r].to_bits() == m.to_bits()).collect();
                let xs: Vec<f64> = rows.iter().map(|&r| offsets[r] * 100.0).collect();
                let ys: Vec<f64> = rows.iter().map(|&r| y[r]).collect();
                Series::line(&format!("μ = {}", crate::three_d::value_label(m)), color(i), &xs, &ys).with_markers()
            })
            .collect()
    };
    let x_label = "offset e (cm)";
    let panels = vec![
        Panel::new(
            &format!("curve at {GOAL_DISTANCE} m: lateral position minus the launch line's"),
            x_label,
            "deflection (m)",
            per_friction(&curve),
        ),
        Panel::new(&format!("lateral position at {GOAL_DISTANCE} m"), x_label, "y (m)", per_friction(&y_goal)),
        Panel::new(&format!("height at the wall ({WALL_DISTANCE} m)"), x_label, "height of the centre (m)", per_friction(&h_wall)),
        Panel::new(&format!("height at the goal line ({GOAL_DISTANCE} m)"), x_label, "height of the centre (m)", per_friction(&h_goal)),
    ];
    written.extend(save_grid(dir, "flight_deflection", "Free kicks against the offset", (2, 2), &panels)?);
    written.extend(axes_figure(h5, dir)?);
    Ok(written)
}

/// The row of `flight_axes`: e = 4 cm, μ = 0.5 (a stored trajectory).
pub const AXES_ROW: (f64, f64) = (0.04, 0.5);

/// `flight_axes`: what offset and contact depth mean, and what they do,
/// drawn from the file's row [`AXES_ROW`] (its e, its launch and spin, its
/// stored trajectory) and the grid's contact depth: the contact from above
/// and from the side (the ball, the foot's line of motion at e beside and h
/// below the centre, where it meets the ball, the launch direction and the
/// sense of the spin), then the flight from above and from the side (the
/// curve away from the straight launch line).
pub fn axes_figure(h5: &Path, dir: &Path) -> Result<Vec<PathBuf>, FigureError> {
    let data = SweepData::read(h5)?;
    let missing = |what: &str| FigureError::Draw { figure: h5.display().to_string(), message: format!("no {what}") };
    let offsets = data.parameter(kick_study::parameters::OFFSET.name)?.to_vec();
    let frictions = data.parameter("friction")?.to_vec();
    let row = (0..data.rows())
        .find(|&r| offsets[r] == AXES_ROW.0 && frictions[r] == AXES_ROW.1)
        .ok_or_else(|| missing("row e = 4 cm, μ = 0.5"))?;
    let launch = data.set("launch")?;
    let get = |name: &str| launch.column(name).map(|c| c[row]).ok_or_else(|| missing(name));
    let (v, w) = (
        [get("launch_velocity_x")?, get("launch_velocity_y")?, get("launch_velocity_z")?],
        [get("spin_x")?, get("spin_y")?, get("spin_z")?],
    );
    let goal = data.set("goal")?;
    let h = crate::h5::read_history(h5, &goal.group, row)?;
    let column = |name: &str| h.iter().find(|(c, _)| c.name == name).map(|(_, v)| v.clone()).ok_or_else(|| missing(name));
    let (x, y, z) = (column("x")?, column("y")?, column("z")?);
    let (e, depth, big_r) = (offsets[row] * 100.0, CONTACT_DEPTH * 100.0, kick_study::numbers_3d::baseline_kick().ball_radius * 100.0);
    let ink = RGBColor(0, 0, 0);
    // The ball's outline, and a frame that keeps it round in a panel about 1.7 times as wide as high.
    let circle = |label: &str| {
        let t: Vec<f64> = (0..=96).map(|k| std::f64::consts::TAU * k as f64 / 96.0).collect();
        Series::line(
            label,
            GREY,
            &t.iter().map(|a| big_r * a.cos()).collect::<Vec<_>>(),
            &t.iter().map(|a| big_r * a.sin()).collect::<Vec<_>>(),
        )
    };
    let frame = || [Series::line("", ink, &[-26.0], &[-15.5]), Series::line("", ink, &[26.0], &[15.5])];
    // An arrow from (a, b) along (da, db), its head two short strokes.
    let arrow = |label: &str, c: RGBColor, (a, b): (f64, f64), (da, db): (f64, f64)| -> Vec<Series> {
        let (ex, ey) = (a + da, b + db);
        let l = da.hypot(db).max(1e-12);
        let (ux, uy) = (da / l, db / l);
        let head = |s: f64| Series::line("", c, &[ex, ex - 2.0 * ux + s * 1.2 * uy], &[ey, ey - 2.0 * uy - s * 1.2 * ux]);
        vec![Series::line(label, c, &[a, ex], &[b, ey]), head(1.0), head(-1.0)]
    };
    // The sense of a spin component: an arc round the ball, its head where it turns to.
    let spin_arc = |label: &str, c: RGBColor, turning: f64| -> Vec<Series> {
        let r = big_r + 3.0;
        let sign = turning.signum();
        let t: Vec<f64> = (0..=40).map(|k| 0.25 * std::f64::consts::PI + sign * 1.4 * k as f64 / 40.0).collect();
        let (xs, ys): (Vec<f64>, Vec<f64>) = t.iter().map(|a| (r * a.cos(), r * a.sin())).unzip();
        let last = *t.last().unwrap_or(&0.0);
        let (ex, ey) = (r * last.cos(), r * last.sin());
        let (tx, ty) = (-sign * last.sin(), sign * last.cos());
        let head = |s: f64| Series::line("", c, &[ex, ex - 2.0 * tx + s * 1.2 * ty], &[ey, ey - 2.0 * ty - s * 1.2 * tx]);
        vec![Series::line(label, c, &xs, &ys), head(1.0), head(-1.0)]
    };
    let touch = (big_r * big_r - e * e - depth * depth).sqrt();
    let speed = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    let launch_arrow = |a: f64, b: f64| (18.0 * a / speed, 18.0 * b / speed);
    let sig = |x: f64| kick_study::printable::short((x * 10.0).round() / 10.0);
    let mut top = vec![circle("the ball (R = 11 cm), kicked along +x")];
    top.extend(frame());
    top.push(Series::line(
        &format!("the foot's line of motion, e = {} cm to the +y side of the centre", sig(e)),
        color(0),
        &[-24.0, -touch],
        &[e, e],
    ));
    top.extend(arrow("", color(0), (-24.0, e), (8.0, 0.0)));
    top.extend(arrow(
        &format!("launch: ({}, {}, {}) m/s", sig(v[0]), sig(v[1]), sig(v[2])),
        color(1),
        (0.0, 0.0),
        launch_arrow(v[0], v[1]),
    ));
    top.extend(spin_arc(&format!("spin ω_z = {} rad/s < 0: clockwise from above", sig(w[2])), color(2), w[2]));
    let mut top_panel = Panel::new("contact from above (x, y)", "x (cm): the foot's direction", "y (cm): the kicker's left", top);
    top_panel.y_from_zero = false;
    top_panel.legend = SeriesLabelPosition::LowerLeft;
    let mut side = vec![circle("the ball")];
    side.extend(frame());
    side.push(Series::line(
        &format!("the foot's line of motion, h = {} cm below the centre", sig(depth)),
        color(0),
        &[-24.0, -touch],
        &[-depth, -depth],
    ));
    side.extend(arrow("", color(0), (-24.0, -depth), (8.0, 0.0)));
    side.extend(arrow("launch (x, z)", color(1), (0.0, 0.0), launch_arrow(v[0], v[2])));
    // Seen from −y (x right, z up), ω_y < 0 turns counterclockwise: backspin.
    side.extend(spin_arc(&format!("spin ω_y = {} rad/s < 0: backspin", sig(w[1])), color(2), -w[1]));
    let mut side_panel = Panel::new("contact from the side (x, z), seen from −y", "x (cm)", "z (cm)", side);
    side_panel.y_from_zero = false;
    side_panel.legend = SeriesLabelPosition::LowerLeft;
    let shown = x.iter().position(|&v| v > SHOWN_TO).map_or(x.len(), |i| i + 1);
    let (x, y, z) = (&x[..shown], &y[..shown], &z[..shown]);
    let straight: Vec<f64> = x.iter().map(|&xi| xi * v[1] / v[0]).collect();
    let mut path_top = vec![
        Series::line("the flight (curves toward −y: Magnus lift along ω × v)", color(3), x, y),
        Series::line("the straight launch line", color(1), x, &straight).dashed(),
    ];
    path_top.push(Series::line("", GREY, &[WALL_DISTANCE, WALL_DISTANCE], &[-WALL_HALF_WIDTH, WALL_HALF_WIDTH]).with_markers());
    path_top.push(Series::line("", ink, &[GOAL_DISTANCE, GOAL_DISTANCE], &[-GOAL_WIDTH / 2.0, GOAL_WIDTH / 2.0]).with_markers());
    let mut flight_top = Panel::new("flight from above: wall at 9.15 m, goal line at 25 m", "x (m)", "y (m)", path_top);
    flight_top.y_from_zero = false;
    flight_top.legend = SeriesLabelPosition::LowerLeft;
    let path_side = vec![
        Series::line("height of the ball's centre (rises with backspin)", color(3), x, z),
        Series::line("", GREY, &[WALL_DISTANCE, WALL_DISTANCE], &[0.0, WALL_HEIGHT]),
        Series::line("", ink, &[GOAL_DISTANCE, GOAL_DISTANCE, GOAL_DISTANCE + 1.0], &[0.0, GOAL_HEIGHT, GOAL_HEIGHT]),
    ];
    let mut flight_side = Panel::new("flight from the side", "x (m)", "z (m)", path_side);
    flight_side.legend = SeriesLabelPosition::UpperLeft;
    save_grid(
        dir,
        "flight_axes",
        &format!(
            "Offset e and contact depth h: the ball's centre from the foot's line of motion (e = {} cm, h = {} cm, μ = 0.5)",
            sig(e),
            sig(depth)
        ),
        (2, 2),
        &[top_panel, side_panel, flight_top, flight_side],
    )
}

/// The free-kick setup in words, with the numbers it uses (for the page).
pub fn setup_note() -> String {
    let k = kick_study::numbers_3d::baseline_kick();
    let b = k.base;
    format!(
        "The kick: Table 1's foot (m_f = {} kg at V = {} m/s, ball {} kg at rest, the paper's contact law) with \
         kick-3d's defaults (μ per row, the tangential spring and slider, the instep box), the foot's path horizontal \
         (α = 0). The foot's line of motion passes h = {} cm below the ball's centre and e = 0–{} cm beside it \
         (kick-3d's `contact_depth` and `offset`: the distances of the centre from the line, the one definition \
         of every front end, drawn on the first figure), so the ball rises with backspin and curves with sidespin, \
         as a free kick over a wall does. h is a choice: it lifts the ball with backspin while the spin stays mostly \
         sidespin at the larger offsets (whether a kick clears the wall: below). The flight: kick-flight's defaults (the drag crisis of a \
         14-panel ball joined to a spinning ball's drag, Goff & Carré 2010 Eq. 4, constants as code bases transcribe them; saturating lift in the spin \
         parameter; no spin decay; sea-level air), the kick's ball and g; the goal line at {} m (the \
         issue's free kick), the wall at {} m (Law 13), the goal {} m wide and {} m high (Law 1), drawn centred on the \
         foot's path. Heights are those of the ball's centre, which starts at R = {} m.",
        kick_study::printable::short(b.effective_foot_mass()),
        kick_study::printable::short(b.foot_speed()),
        kick_study::printable::short(b.ball_mass()),
        kick_study::printable::short(CONTACT_DEPTH * 100.0),
        kick_study::printable::short(OFFSETS[OFFSETS.len() - 1] * 100.0),
        GOAL_DISTANCE,
        WALL_DISTANCE,
        GOAL_WIDTH,
        GOAL_HEIGHT,
        kick_study::printable::short(k.ball_radius),
    )
}

/// The target's marker: apart from the trajectories' colours.
const TARGET_GREEN: RGBColor = RGBColor(0, 140, 60);

/// `flight_aim.png`/`.svg`: the aimed free kicks from above and from the
/// side, with the wall, the goal and the target.
pub fn aim_figure(aims: &[kick_study::aim::AimReport], dir: &Path) -> Result<Vec<PathBuf>, FigureError> {
    let draw_error = |message: String| FigureError::Draw { figure: "flight_aim".into(), message };
    let mut top = Vec::new();
    let mut side = Vec::new();
    for (i, report) in aims.iter().enumerate() {
        let s = &report.solution;
        let [_, x, y, z, ..] = flight_columns(&s.flight, TRAJECTORY_SAMPLES).map_err(|e| draw_error(e.to_string()))?;
        let shown = x.iter().take_while(|&&x| x <= SHOWN_TO).count();
        let (x, y, z) = (&x[..shown], &y[..shown], &z[..shown]);
        let label = match report.from {
            kick_study::aim::AimFrom::Launch => format!("launch aimed ({} rad/s sidespin held)", kick_study::printable::short(AIM_SPIN[2])),
            kick_study::aim::AimFrom::Kick => "3D kick aimed (foot speed, e, h, heading; max clearance)".to_string(),
        };
        top.push(Series::line(&label, color(i), &x, &y));
        side.push(Series::line(&label, color(i), &x, &z));
    }
    let [tx, ty, tz] = AIM_TARGET;
    let half = GOAL_WIDTH / 2.0;
    top.push(Series::line("", GREY, &[WALL_DISTANCE, WALL_DISTANCE], &[-WALL_HALF_WIDTH, WALL_HALF_WIDTH]).with_markers());
    top.push(Series::line("", RGBColor(0, 0, 0), &[GOAL_DISTANCE, GOAL_DISTANCE], &[-half, half]).with_markers());
    let target = format!("target ({tx}, {ty}, {tz}) m");
    // A cross over the target, scaled to each panel's axes.
    let cross = |label: &str, (a, b): (f64, f64), (da, db): (f64, f64)| {
        [Series::line(label, TARGET_GREEN, &[a - da, a + da], &[b, b]), Series::line("", TARGET_GREEN, &[a, a], &[b - db, b + db])]
    };
    top.extend(cross(&target, (tx, ty), (0.4, 0.4)));
    side.push(Series::line("", GREY, &[WALL_DISTANCE, WALL_DISTANCE], &[0.0, WALL_HEIGHT]));
    side.push(Series::line("", RGBColor(0, 0, 0), &[GOAL_DISTANCE, GOAL_DISTANCE, GOAL_DISTANCE + 1.0], &[0.0, GOAL_HEIGHT, GOAL_HEIGHT]));
    side.extend(cross(&target, (tx, tz), (0.6, 0.12)));
    let mut top_panel = Panel::new(
        &format!(
            "from above, equal scale (wall {} m wide at {WALL_DISTANCE} m, goal {GOAL_WIDTH} m wide at {GOAL_DISTANCE} m)",
            2.0 * WALL_HALF_WIDTH
        ),
        "x toward the goal (m)",
        "lateral y (m)",
        top,
    );
    top_panel.y_from_zero = false;
    top_panel.legend = SeriesLabelPosition::UpperLeft;
    let mut side_panel = Panel::new(
        &format!("from the side (wall {WALL_HEIGHT} m, crossbar {GOAL_HEIGHT} m; height of the ball's centre)"),
        "x toward the goal (m)",
        "height z (m)",
        side,
    );
    side_panel.legend = SeriesLabelPosition::UpperLeft;
    save_grid_equal_scale(
        dir,
        "flight_aim",
        "Aimed free kicks (kick aim): past the wall to the target under the bar",
        (2, 1),
        &[top_panel, side_panel],
        &[0],
        None,
    )
}
