//! Free kicks, from the foot to the goal (issue 14): the 3D kick chained
//! into kick-flight, over lateral offset × friction, written to
//! `OUT/flight/free_kick.h5`, and the figures drawn back from that file.
//!
//! Setup (a choice, stated on the generated page): Table 1's foot (3 kg at
//! 22 m/s), its ball and contact law, the foot's path horizontal (α = 0),
//! the defaults of kick-3d otherwise. The contact lies below the ball's
//! centre by [`VERTICAL_OFFSET`] and beside it by the lateral offset e, so
//! the ball rises with backspin and curves with sidespin, as a free kick
//! over a wall does. kick-3d's offset is lateral only; with a horizontal
//! path and no gravity during the contact (kick-3d's default) its kick is
//! symmetric about the foot's path, so the kick at offset √(e² + h²),
//! turned about the path by β = atan2(h, e), is the kick at (e, h): its
//! launch velocity and spin are the lateral kick's, rotated by β about x.
//!
//! File layout (a sweep table, [`crate::h5`]): parameters `lateral_offset`
//! (m) and `friction` (1) per row (grid order: offset, then friction
//! fastest; `/grid`, `grid_shape`); outcome sets `launch` (the rotated
//! launch: [`LAUNCH_COLUMNS`]), `goal` (the flight with its crossing of
//! x = [`GOAL_DISTANCE`]) and `wall` (crossing x = [`WALL_DISTANCE`]), both
//! [`kick_flight::OUTCOME_COLUMNS`]; root attribute `vertical_offset` (m);
//! the trajectories of [`TRAJECTORY_OFFSETS`] × [`TRAJECTORY_FRICTIONS`] as
//! `solvers/goal/histories/<row>` ([`TRAJECTORY_COLUMNS`], uniform in time).

use crate::figures::{color, save_grid, FigureError, Panel, Series};
use crate::h5::{write_grid, write_str_attr, Column, H5Error, SweepData};
use crate::provenance::Provenance;
use crate::run::{create_table, fill_table};
use kick_3d::Kick3d;
use kick_flight::{history, Sampling};
use kick_study::level::Level;
use plotters::prelude::{RGBColor, SeriesLabelPosition};
use std::path::{Path, PathBuf};

/// The physics (the grid, the lateral kick turned into an (e, h) kick) is kick-study's.
pub use kick_study::free_kick::*;

/// Rows whose trajectories are kept: these offsets...
pub const TRAJECTORY_OFFSETS: [f64; 4] = [0.0, 0.02, 0.04, 0.06];
/// ...at these frictions.
pub const TRAJECTORY_FRICTIONS: [f64; 2] = [0.5, f64::INFINITY];
/// Samples per trajectory.
pub const TRAJECTORY_SAMPLES: usize = 301;
/// The wall drawn and the goal (Law 1): one definition, kick-flight's aim scene.
pub use kick_flight::aim::{GOAL_HEIGHT, GOAL_WIDTH, WALL_HALF_WIDTH, WALL_HEIGHT};

/// Columns of a stored trajectory.
pub const TRAJECTORY_COLUMNS: [(&str, &str); 7] =
    [("time", "s"), ("x", "m"), ("y", "m"), ("z", "m"), ("velocity_x", "m/s"), ("velocity_y", "m/s"), ("velocity_z", "m/s")];

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

/// The file's name under `OUT/flight/`.
pub const FILE: &str = "free_kick.h5";

fn columns(list: &[(&str, &str)]) -> Vec<Column> {
    list.iter().map(|(n, u)| Column::new(n, u)).collect()
}

/// Solve the grid and write `out/flight/free_kick.h5`.
pub fn write(out: &Path) -> Result<PathBuf, String> {
    let dir = out.join("flight");
    std::fs::create_dir_all(&dir).map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
    let path = dir.join(FILE);
    let text = format!(
        "kick_paper::free_kick: lateral offsets {LATERAL_OFFSETS:?} m x friction {FRICTIONS:?}, contact {VERTICAL_OFFSET} m below \
         the centre, Table 1 foot, horizontal path; flights to x = {GOAL_DISTANCE} m and {WALL_DISTANCE} m"
    );
    let provenance = Provenance::now("free_kick", "kick_paper::free_kick", &text);
    let rows = grid();
    let mut writer = create_table(&FreeKicks, &path, &provenance, rows.len() as u64, Default::default()).map_err(|e| e.to_string())?;
    let file = writer.file().clone();
    let h5 = |e: H5Error| e.to_string();
    let parameters = FreeKicks.parameter_columns();
    write_str_attr(&file, &path, "description", "Free kicks: the 3D kick (contact below and beside the centre) chained into the flight")
        .map_err(h5)?;
    write_grid(&file, &path, &[(parameters[0].clone(), &LATERAL_OFFSETS[..]), (parameters[1].clone(), &FRICTIONS[..])]).map_err(h5)?;
    fill_table(&FreeKicks, 0..rows.len() as u64, &mut writer, &indicatif::ProgressBar::hidden()).map_err(h5)?;
    for (row, &(e, mu)) in rows.iter().enumerate() {
        let keep = TRAJECTORY_OFFSETS.contains(&e) && TRAJECTORY_FRICTIONS.iter().any(|m| m.to_bits() == mu.to_bits());
        if keep {
            let f = FreeKick::new(e, mu)?.flight(GOAL_DISTANCE)?;
            let h = history(&f, Sampling::Samples(TRAJECTORY_SAMPLES)).map_err(crate::flight::flight_error)?;
            let values: Vec<Vec<f64>> = vec![
                h.samples.iter().map(|s| s.time).collect(),
                h.samples.iter().map(|s| s.position[0]).collect(),
                h.samples.iter().map(|s| s.position[1]).collect(),
                h.samples.iter().map(|s| s.position[2]).collect(),
                h.samples.iter().map(|s| s.velocity[0]).collect(),
                h.samples.iter().map(|s| s.velocity[1]).collect(),
                h.samples.iter().map(|s| s.velocity[2]).collect(),
            ];
            let named: Vec<(Column, &[f64])> = columns(&TRAJECTORY_COLUMNS).into_iter().zip(values.iter().map(Vec::as_slice)).collect();
            writer.write_history(1, row, &named).map_err(h5)?;
        }
    }
    writer.finish().map_err(h5)
}

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
    let offsets = data.parameter("lateral_offset")?.to_vec();
    let frictions = data.parameter("friction")?.to_vec();
    let label =
        |row: usize| format!("e = {} cm, μ = {}", kick_core::short(offsets[row] * 100.0), crate::three_d::value_label(frictions[row]));
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
        &format!("from above (wall at {WALL_DISTANCE} m, goal {GOAL_WIDTH} m wide at {GOAL_DISTANCE} m; dashed: μ = ∞)"),
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
    let mut written = save_grid(
        dir,
        "flight_free_kick",
        &format!("Free kicks from the 3D kick through the flight (shown to x = {SHOWN_TO} m)"),
        (2, 1),
        &[top_panel, side_panel],
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
    let x_label = "lateral offset e (cm)";
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
    written.extend(save_grid(dir, "flight_deflection", "Free kicks against the lateral offset", (2, 2), &panels)?);
    Ok(written)
}

/// The free-kick setup in words, with the numbers it uses (for the page).
pub fn setup_note() -> String {
    let k = Kick3d::baseline();
    let b = k.base;
    format!(
        "The kick: Table 1's foot (m_f = {} kg at V = {} m/s, ball {} kg at rest, the paper's contact law) with \
         kick-3d's defaults (μ per row, the tangential spring and slider, the instep box), the foot's path horizontal \
         (α = 0). The contact lies h = {} cm below the ball's centre and e = 0–{} cm beside it, so the ball rises with \
         backspin and curves with sidespin, as a free kick over a wall does. kick-3d's offset is lateral only; with a \
         horizontal path and no gravity during the few milliseconds of contact (kick-3d's default) the kick is \
         symmetric about the foot's path, so the kick at (e, h) is the lateral kick at offset √(e² + h²) turned about \
         the path by β = atan2(h, e): its launch velocity and spin are that kick's, rotated (`kick_study::free_kick::roll`). \
         h is a choice: deep enough that the ball clears a wall, shallow enough that the spin stays mostly sidespin \
         at the larger offsets. The flight: kick-flight's defaults (the drag crisis of a \
         14-panel ball joined to a spinning ball's drag, Goff & Carré 2010 Eq. 4; saturating lift in the spin \
         parameter; no spin decay; sea-level air), the kick's ball and g; the goal line at {} m (the \
         issue's free kick), the wall at {} m (Law 13), the goal {} m wide and {} m high (Law 1), drawn centred on the \
         foot's path. Heights are those of the ball's centre, which starts at R = {} m.",
        kick_core::short(b.effective_foot_mass()),
        kick_core::short(b.foot_speed()),
        kick_core::short(b.ball_mass()),
        kick_core::short(VERTICAL_OFFSET * 100.0),
        kick_core::short(LATERAL_OFFSETS[LATERAL_OFFSETS.len() - 1] * 100.0),
        GOAL_DISTANCE,
        WALL_DISTANCE,
        GOAL_WIDTH,
        GOAL_HEIGHT,
        kick_core::short(k.ball_radius),
    )
}

/// The aimed free kick of paper/flight.md: the ball's centre 2.6 m to the
/// +y side of the goal's centre and 2 m up at the goal line (under the bar
/// by the post), past the default wall.
pub const AIM_TARGET: [f64; 3] = [GOAL_DISTANCE, 2.6, 2.0];
/// Its launch aim holds this sidespin (about 8 rev/s, curving toward +y).
pub const AIM_SPIN: [f64; 3] = [0.0, 0.0, 50.0];

/// The two aims of the page: the launch (speed, elevation, azimuth free,
/// [`AIM_SPIN`] held) and the 3D kick (foot speed, e, h, heading free), to [`AIM_TARGET`].
pub fn aims() -> Result<[kick_study::aim::AimReport; 2], String> {
    use kick_study::aim::{aim, AimFrom, AimRequest};
    let launch = AimRequest {
        target: Some(AIM_TARGET),
        from: Some(AimFrom::Launch),
        flight: kick_flight::FlightSpec { spin: Some(AIM_SPIN), ..kick_flight::FlightSpec::default() },
        ..AimRequest::default()
    };
    let kick = AimRequest { target: Some(AIM_TARGET), from: Some(AimFrom::Kick), ..AimRequest::default() };
    Ok([aim(&launch)?, aim(&kick)?])
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
        let h = history(&s.flight, Sampling::Samples(TRAJECTORY_SAMPLES)).map_err(|e| draw_error(e.to_string()))?;
        let shown: Vec<_> = h.samples.iter().take_while(|p| p.position[0] <= SHOWN_TO).collect();
        let x: Vec<f64> = shown.iter().map(|p| p.position[0]).collect();
        let y: Vec<f64> = shown.iter().map(|p| p.position[1]).collect();
        let z: Vec<f64> = shown.iter().map(|p| p.position[2]).collect();
        let label = match report.from {
            kick_study::aim::AimFrom::Launch => format!("launch aimed ({} rad/s sidespin held)", kick_core::short(AIM_SPIN[2])),
            kick_study::aim::AimFrom::Kick => "3D kick aimed (foot speed, e, h, heading)".to_string(),
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
    top.extend(cross(&target, (tx, ty), (0.6, 0.25)));
    side.push(Series::line("", GREY, &[WALL_DISTANCE, WALL_DISTANCE], &[0.0, WALL_HEIGHT]));
    side.push(Series::line("", RGBColor(0, 0, 0), &[GOAL_DISTANCE, GOAL_DISTANCE, GOAL_DISTANCE + 1.0], &[0.0, GOAL_HEIGHT, GOAL_HEIGHT]));
    side.extend(cross(&target, (tx, tz), (0.6, 0.12)));
    let mut top_panel = Panel::new(
        &format!("from above (wall {} m wide at {WALL_DISTANCE} m, goal {GOAL_WIDTH} m wide at {GOAL_DISTANCE} m)", 2.0 * WALL_HALF_WIDTH),
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
    save_grid(dir, "flight_aim", "Aimed free kicks (kick aim): over the wall to the target under the bar", (2, 1), &[top_panel, side_panel])
}
