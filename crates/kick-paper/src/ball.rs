//! The ball alone (`paper/ball.md`): the shell ball fired square at a rigid
//! plate against impact speed and against inflation pressure over Law 2's
//! range (the bounce experiments in `experiments/ball/`, run by `kick run`
//! into `results/ball_bounce.h5` and `results/ball_pressure.h5`), their
//! figures drawn from those files, the measurements set beside them with
//! where each number was read, and a fit of the ball to synthetic plate
//! tests (`kick fit data` on `results/identification/ball_plate.toml`).

use crate::error::PaperError;
use crate::figures::{color, save_grid, Panel, Series};
use crate::links::relative;
use crate::units::three;
use crate::SweepData;
pub use kick_study::ball::*;
use kick_study::printable::{short, sig};
use plotters::prelude::{RGBColor, SeriesLabelPosition};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// The one plate speed the ISBS 2022 abstract (commons.nmu.edu/isbs/vol40/iss1/12)
/// names, m/s: there a lower pressure did not lower the peak force.
const ISBS_EXCEPTION_SPEED: f64 = 4.6;

/// The speed table, below the results directory (experiments/ball/speeds.toml).
pub const FILE: &str = "ball_bounce.h5";
/// The pressure table (experiments/ball/pressure.toml).
pub const PRESSURE_FILE: &str = "ball_pressure.h5";
/// The figures' names, below the figures directory.
pub const FIGURE: &str = "ball_bounce";
pub const PRESSURE_FIGURE: &str = "ball_pressure";
/// Draw both figures from the result files, write the synthetic plate
/// tests and fit them, and write the page; returns every file written.
pub fn write(out: &Path, figures: &Path, page: &Path, command: &str) -> Result<Vec<PathBuf>, PaperError> {
    let speeds = SweepData::read(&out.join(FILE))?;
    let pressures = SweepData::read(&out.join(PRESSURE_FILE))?;
    let mut written = draw_speeds(&speeds, figures)?;
    written.extend(draw_pressures(&pressures, figures)?);
    let (fit, fit_files) = fit_plate_tests(out)?;
    written.extend(fit_files);
    let report_dir = page.parent().unwrap_or(Path::new(""));
    let link = |p: &Path| relative(report_dir, p);
    let text = page_text(
        &speeds,
        &pressures,
        &fit,
        &Links {
            speeds: link(&out.join(FILE)),
            pressures: link(&out.join(PRESSURE_FILE)),
            speed_figure: link(&figures.join(format!("{FIGURE}.png"))),
            pressure_figure: link(&figures.join(format!("{PRESSURE_FIGURE}.png"))),
            fit_spec: link(&out.join(FIT_SPEC)),
            command_spec: out.join(FIT_SPEC).display().to_string(),
            command_report: out.join(FIT_REPORT).display().to_string(),
        },
        command,
    )?;
    crate::output::write(page, text)?;
    written.push(page.to_path_buf());
    Ok(written)
}

/// Paths as the page links them.
struct Links {
    speeds: String,
    pressures: String,
    speed_figure: String,
    pressure_figure: String,
    fit_spec: String,
    /// The spec and report as a command line from the working directory names them.
    command_spec: String,
    command_report: String,
}

/// A bounce table's columns: the axes and the outcomes the page uses.
struct Bounces<'a> {
    speed: &'a [f64],
    /// None in the speed table (its pressure is the default's).
    pressure: Option<&'a [f64]>,
    restitution: &'a [f64],
    contact_time: &'a [f64],
    peak_force: &'a [f64],
    max_compression: &'a [f64],
}

fn bounces(data: &SweepData) -> Result<Bounces<'_>, PaperError> {
    let set = data.set("bounce")?;
    let column = |name: &str| set.column(name).ok_or_else(|| PaperError::lacks(&data.path, format!("no column {name}")));
    Ok(Bounces {
        speed: data.parameter("speed")?,
        pressure: data.parameter("inflation_pressure").ok(),
        restitution: column("restitution")?,
        contact_time: column("contact_time")?,
        peak_force: column("peak_force")?,
        max_compression: column("max_compression")?,
    })
}

/// Rows of the table at `speed` (its pressure curve), in file order.
fn at_speed(b: &Bounces, speed: f64) -> Vec<usize> {
    (0..b.speed.len()).filter(|&i| b.speed[i] == speed).collect()
}

/// The distinct speeds of a table, in file order.
fn distinct(values: &[f64]) -> Vec<f64> {
    let mut out: Vec<f64> = Vec::new();
    for &v in values {
        if !out.contains(&v) {
            out.push(v);
        }
    }
    out
}

/// The compression Dowell & Krebs's d would be for the model's ball, from
/// the imprint the model leaves: its patch is the flat cap, diameter
/// D = 2√(2Rδ − δ²); converted back by the sagitta of a chord D on a sphere
/// of radius R it is δ itself, by the small-cap formula D²/(8R) it is
/// δ − δ²/(2R).
fn small_cap_compression(delta: f64, radius: f64) -> f64 {
    delta - delta * delta / (2.0 * radius)
}

fn mm(x: &[f64]) -> Vec<f64> {
    x.iter().map(|v| 1e3 * v).collect()
}

/// The shell law's stated validity, δ ≤ R/2 (`LawKind::validity`): a grey
/// line across `ends` at R/2 in mm; curves above it are outside the law's region.
fn validity_line(ends: &[f64; 2], radius: f64) -> Series {
    let limit = 1e3 * 0.5 * radius;
    Series::line(&format!("R/2 = {} mm: above, outside the law's validity", short(limit)), RGBColor(150, 150, 150), ends, &[limit, limit])
        .dashed()
}

/// A table cell of δ_max in mm, marked † past the law's validity (δ > R/2).
fn compression_cell(delta: f64, radius: f64) -> String {
    if delta > 0.5 * radius {
        format!("{} †", sig(1e3 * delta))
    } else {
        sig(1e3 * delta).to_string()
    }
}

/// The impact speed (m/s) at which δ_max reaches R/2 in a speed table, by
/// linear interpolation between its rows; `None` when no row passes it.
fn validity_speed(b: &Bounces, radius: f64) -> Option<f64> {
    let rows: Vec<usize> = (0..b.speed.len()).collect();
    crossing(b.speed, &rows, b.max_compression, 0.5 * radius)
}

/// A grey dashed vertical line at the speed where δ_max reaches R/2, from 0
/// to `top`, for the panels whose y is not a compression (the same marker as
/// [`validity_line`]): beyond it, outside the law's validity.
fn validity_speed_line(speed: f64, top: f64) -> Series {
    Series::line(
        &format!("δ_max > R/2 beyond {} m/s: outside the law's validity", three(speed)),
        RGBColor(150, 150, 150),
        &[speed, speed],
        &[0.0, top],
    )
    .dashed()
}

/// Where a curve of the pressure table (the rows of one speed) lies past R/2:
/// `None` when nowhere, else whether at every row and the range of those rows' pressures, kPa.
fn outside_pressures(b: &Bounces, pressure: &[f64], rows: &[usize], radius: f64) -> Option<(bool, f64, f64)> {
    let outside: Vec<f64> = rows.iter().filter(|&&i| b.max_compression[i] > 0.5 * radius).map(|&i| 1e-3 * pressure[i]).collect();
    let (lo, hi) = (outside.iter().copied().fold(f64::INFINITY, f64::min), outside.iter().copied().fold(f64::NEG_INFINITY, f64::max));
    (!outside.is_empty()).then_some((outside.len() == rows.len(), lo, hi))
}

/// Restitution, contact time and compression against impact speed at 0.8
/// bar; the FIFA band (the calibration) and Dowell & Krebs's line beside them.
fn draw_speeds(data: &SweepData, figures: &Path) -> Result<Vec<PathBuf>, PaperError> {
    let b = bounces(data)?;
    let radius = kick_study::parameters::DEFAULT_BALL_RADIUS;
    let band = |h: f64| (h / FIFA_DROP).sqrt();
    let black = RGBColor(0, 0, 0);
    let fifa = Series::line(
        "FIFA rebound band, 2 m drop at 0.8 bar (calibration)",
        black,
        &[fifa_speed(); 2],
        &[band(FIFA_REBOUND.0), band(FIFA_REBOUND.1)],
    )
    .with_markers();
    let line_speeds = [0.0, DROP_LINE_END];
    let dowell =
        Series::line("Dowell & Krebs (abstract): d = 2.80 v", black, &line_speeds, &line_speeds.map(|s| DOWELL_KREBS_MM_PER_MPS * s))
            .dashed();
    let small_cap: Vec<f64> = b.max_compression.iter().map(|&d| 1e3 * small_cap_compression(d, radius)).collect();
    let panel = |title: &str, y_label: &str, series: Vec<Series>, legend| Panel {
        title: title.into(),
        x_label: "impact speed (m/s)".into(),
        y_label: y_label.into(),
        log_x: false,
        series,
        y_from_zero: true,
        legend,
    };
    let label = "shell ball, 0.8 bar";
    let top = |values: &[f64]| values.iter().copied().filter(|v| v.is_finite()).fold(0.0, f64::max);
    let mut restitution = vec![Series::line(label, color(0), b.speed, b.restitution), fifa];
    let mut contact = vec![Series::line(label, color(0), b.speed, &mm(b.contact_time))];
    // The law's validity ends where δ_max reaches R/2: marked in the panels
    // whose y is not δ (the compression panel has the R/2 line itself).
    if let Some(limit) = validity_speed(&b, radius) {
        restitution.push(validity_speed_line(limit, top(b.restitution).max(band(FIFA_REBOUND.1))));
        contact.push(validity_speed_line(limit, top(&mm(b.contact_time))));
    }
    let panels = [
        panel("Restitution", "e", restitution, SeriesLabelPosition::LowerLeft),
        panel("Contact time", "t_c (ms)", contact, SeriesLabelPosition::LowerLeft),
        panel(
            "Maximum compression",
            "δ_max (mm)",
            vec![
                Series::line("shell ball: δ_max (= d by the sagitta)", color(0), b.speed, &mm(b.max_compression)),
                Series::line("shell ball: d by D²/8R", color(1), b.speed, &small_cap).dashed(),
                dowell,
                validity_line(&[0.0, b.speed.iter().copied().fold(0.0, f64::max)], radius),
            ],
            SeriesLabelPosition::UpperLeft,
        ),
    ];
    Ok(save_grid(figures, FIGURE, "The ball alone against impact speed: square impacts on a rigid plate", (1, 3), &panels)?)
}

/// Restitution, contact time and compression against inflation pressure
/// over Law 2's range at three impact speeds; the FIFA band at the test's
/// pressure and Dowell & Krebs's d at the FIFA drop's speed beside them.
fn draw_pressures(data: &SweepData, figures: &Path) -> Result<Vec<PathBuf>, PaperError> {
    let b = bounces(data)?;
    let pressure = b.pressure.ok_or_else(|| PaperError::lacks(&data.path, "no inflation_pressure axis"))?;
    let black = RGBColor(0, 0, 0);
    let kpa = |rows: &[usize]| rows.iter().map(|&i| 1e-3 * pressure[i]).collect::<Vec<f64>>();
    let pick = |rows: &[usize], column: &[f64], scale: f64| rows.iter().map(|&i| scale * column[i]).collect::<Vec<f64>>();
    let (mut e, mut t, mut d) = (Vec::new(), Vec::new(), Vec::new());
    let radius = kick_study::parameters::DEFAULT_BALL_RADIUS;
    for (k, v) in distinct(b.speed).into_iter().enumerate() {
        let rows = at_speed(&b, v);
        // A curve past the law's validity says so in every panel's legend.
        let label = match outside_pressures(&b, pressure, &rows, radius) {
            None => format!("{} m/s", short(v)),
            Some((true, _, _)) => format!("{} m/s: δ_max > R/2, outside validity", short(v)),
            Some((false, lo, hi)) => format!("{} m/s: δ_max > R/2 at {}–{} kPa", short(v), three(lo), three(hi)),
        };
        e.push(Series::line(&label, color(k), &kpa(&rows), &pick(&rows, b.restitution, 1.0)));
        t.push(Series::line(&label, color(k), &kpa(&rows), &pick(&rows, b.contact_time, 1e3)));
        d.push(Series::line(&label, color(k), &kpa(&rows), &pick(&rows, b.max_compression, 1e3)));
    }
    let band = |h: f64| (h / FIFA_DROP).sqrt();
    e.push(
        Series::line(
            "FIFA band at 0.8 bar, 2 m drop (calibration)",
            black,
            &[1e-3 * FIFA_PRESSURE; 2],
            &[band(FIFA_REBOUND.0), band(FIFA_REBOUND.1)],
        )
        .with_markers(),
    );
    let ends = [1e-3 * pressure.iter().copied().fold(f64::INFINITY, f64::min), 1e-3 * pressure.iter().copied().fold(0.0, f64::max)];
    let dk = DOWELL_KREBS_MM_PER_MPS * fifa_speed();
    d.push(Series::line("Dowell & Krebs at 6.26 m/s (abstract)", black, &ends, &[dk, dk]).dashed());
    d.push(validity_line(&ends, radius));
    let panel = |title: &str, y_label: &str, series: Vec<Series>, legend| Panel {
        title: title.into(),
        x_label: "inflation pressure (kPa, gauge)".into(),
        y_label: y_label.into(),
        log_x: false,
        series,
        y_from_zero: true,
        legend,
    };
    let panels = [
        panel("Restitution", "e", e, SeriesLabelPosition::LowerRight),
        panel("Contact time", "t_c (ms)", t, SeriesLabelPosition::LowerLeft),
        panel("Maximum compression", "δ_max (mm)", d, SeriesLabelPosition::LowerLeft),
    ];
    Ok(save_grid(figures, PRESSURE_FIGURE, "The ball alone against inflation pressure over Law 2's range (0.6–1.1 atm)", (1, 3), &panels)?)
}

/// The pressure (Pa) at which `column` at the rows of one speed crosses
/// `target`, by linear interpolation; `None` when it stays on one side.
fn crossing(pressure: &[f64], rows: &[usize], column: &[f64], target: f64) -> Option<f64> {
    rows.windows(2).find_map(|w| {
        let (a, b) = (column[w[0]] - target, column[w[1]] - target);
        (a * b <= 0.0 && a != b).then(|| pressure[w[0]] + (pressure[w[1]] - pressure[w[0]]) * a / (a - b))
    })
}

/// The synthetic plate tests (`kick_study::ball::plate_test_spec`) written
/// as a fit specification, then fitted back (kick-store).
fn fit_plate_tests(out: &Path) -> Result<(crate::identify::DataFit, Vec<PathBuf>), PaperError> {
    let spec_path = out.join(FIT_SPEC);
    crate::output::write(&spec_path, plate_test_spec(&spec_path)?)?;
    let fit = crate::identify::data(&spec_path, Some(&out.join(FIT_REPORT)))?;
    fit.converged()?;
    let mut written = vec![spec_path];
    written.extend(fit.written.iter().cloned());
    Ok((fit, written))
}

/// The row nearest `speed` in a speed table.
fn nearest(v: &[f64], speed: f64) -> usize {
    (0..v.len()).min_by(|&a, &b| (v[a] - speed).abs().total_cmp(&(v[b] - speed).abs())).unwrap_or(0)
}

fn page_text(
    speeds: &SweepData,
    pressures: &SweepData,
    fit: &crate::identify::DataFit,
    links: &Links,
    command: &str,
) -> Result<String, PaperError> {
    let s = bounces(speeds)?;
    let p = bounces(pressures)?;
    let pressure = p.pressure.ok_or_else(|| PaperError::missing("no pressure axis"))?;
    let ball = kick_study::ball::default_ball()?;
    let radius = ball.radius;
    let atm = |x: f64| x / SEA_LEVEL_PRESSURE;
    let mut w = String::new();

    // The calibration and its band.
    let band: Vec<(f64, f64)> = [FIFA_REBOUND.0, FIFA_PRO_FLOOR, 1.40, FIFA_REBOUND.1]
        .iter()
        .map(|&h| damping_for_rebound(h).map(|b| (h, b)))
        .collect::<Result<_, _>>()?;
    let drops: Vec<(f64, _)> = [0.6 * SEA_LEVEL_PRESSURE, FIFA_PRESSURE, 1.1 * SEA_LEVEL_PRESSURE]
        .iter()
        .map(|&p0| bounce(&[("drop_height", FIFA_DROP), ("inflation_pressure", p0)]).map(|o| (p0, o)))
        .collect::<Result<_, _>>()?;

    let _ = write!(
        w,
        "# The ball alone\n\n\
         Generated by `{command}` from the bounce experiments `experiments/ball/speeds.toml` and \
         `experiments/ball/pressure.toml` (`kick run`, data: [{sp}]({sp}), [{pr}]({pr})). The shell ball (`--law shell`, \
         `kick_core::ShellBall`) fired square at a rigid, massive plate (`kick bounce`, crates/kick-bounce), gravity on: \
         the gauge pressure acts over the flat contact patch A(δ) = π(2Rδ − δ²), the gas is compressed adiabatically by \
         the cap it loses, and the losses sit in the shell: \
         F = A(δ) (P(δ) − p_atm + β δ̇) + k_s δ.\n\n",
        sp = links.speeds,
        pr = links.pressures
    );
    // The gas's heat loss, estimated from the FIFA drop's contact: a layer
    // √(α t_c) thick exchanges heat, 3ℓ/R of the gas; it loses of the order of
    // (γ − 1) times that share of what it stores, at most that share of the
    // impact's energy, so Δe ≤ loss/(2e).
    let fifa_drop = &drops[1].1;
    let gamma = kick_study::parameters::GAS_EXPONENT.default_number();
    let kick_study::ball::GasHeatLoss { layer, share, loss: heat_loss } =
        kick_study::ball::gas_heat_loss(fifa_drop.contact_time, radius, gamma);
    let band_half = 0.5 * ((FIFA_REBOUND.1 / FIFA_DROP).sqrt() - (FIFA_REBOUND.0 / FIFA_DROP).sqrt());
    let _ = write!(
        w,
        "## Where the losses are\n\n\
         The shell material (carcass, bladder, outer panels) is flattened over the patch at the rate δ̇ and resists \
         with a viscous stress β δ̇; the air is elastic. Why: the finite-element models of Price, Jones, Harland & \
         Silberschmidt (2008, J Mater Sci 43, 2833; abstract read) put a ball's kinetic-energy loss in the viscoelastic \
         layers of its shell, the outer panels' damping dominating. The air is compressed for {} ms in the FIFA drop, \
         so it exchanges heat only within ℓ = √(α t_c) ≈ {} mm of the wall (α = {} m²/s), a layer holding 3ℓ/R ≈ {} % \
         of the gas. The estimated loss is of the order of (γ − 1) × {} % ≈ {} % of what the gas stores (γ = {}), so \
         Δe ≤ {} %/(2e) ≈ {} with the drop's e = {}, against the FIFA band's ±{}: left out. The shell's loss \
         depends on how far and how fast it is flattened, not on the pressure behind it, so a harder ball, which \
         stores more of the impact in its gas, returns more of it: **restitution rises with pressure**. The loss \
         is zero at first touch (A(0) = 0). Cross (1999, Am. J. Phys. 67, 222; passages read in a copy) measured the \
         force on balls bouncing on a piezo plate and found F = 0 at t = 0 for every ball but the tennis ball.\n\n\
         **Its speed dependence, stated.** At small compression the law is 2πR (p0 + k_s/(2πR) + β δ̇) δ: Hunt–Crossley \
         with χ = β/(p0 + k_s/(2πR)) ({} s/m for the default ball), so restitution is the exact hysteresis relation of \
         x0 = β V/(p0 + k_s/(2πR)): it falls with impact speed and rises with pressure through that one ratio \
         (tests `slow_impacts_follow_the_hunt_crossley_relation`, `restitution_rises_with_pressure` in kick-bounce). \
         This is a choice: a loss that vanishes at touch and grows with the patch. The mechanical kicking limb of \
         Peacock & Ball (2016, abstract only) finds no significant trend of the foot–ball restitution with foot speed \
         (0.66–0.79, r = −0.347, n.s., 9.1–21.2 m/s, an Australian-football ball): a kick's restitution with a foot, \
         not a ball's on a plate, so it does not test this; a plate test at two speeds does (the fit below).\n\n",
        three(1e3 * fifa_drop.contact_time),
        three(1e3 * layer),
        short(kick_study::ball::AIR_DIFFUSIVITY),
        three(100.0 * share),
        three(100.0 * share),
        three(100.0 * heat_loss),
        short(gamma),
        three(100.0 * heat_loss),
        three(heat_loss / (2.0 * fifa_drop.restitution)),
        three(fifa_drop.restitution),
        three(band_half),
        sig(ball.small_compression_hysteresis)
    );
    let _ = write!(
        w,
        "## What was calibrated on what\n\n\
         The pressure is the FIFA test's 0.8 bar ({} Pa gauge). The mass is Table 1's m_b = {} kg. The radius is \
         kick-core's default R = {} m (circumference {} m, inside Law 2's 0.68–0.70 m); Table 1 gives no radius. \
         k_s = 0 (not identified: no checked ball-only stiffness was found). The loss β = {} Pa s/m is set by one \
         measurement, the FIFA Quality Programme's rebound test: dropped 2 m onto steel at 0.8 bar, a licensed ball \
         rebounds 115–165 cm (secondary: two ball makers' pages describing the test, adsport.sk and derbystar.de; \
         crates/kick-bounce/SOURCES.md). β makes `kick bounce \
         --drop-height 2` (gravity on during contact, as in the test) rebound to the band's middle, 140 cm. The band \
         is the spread of licensed balls, not a measurement error; across it β runs ",
        sig(ball.pressure),
        short(kick_study::parameters::BALL_MASS.default_number()),
        short(radius),
        three(2.0 * std::f64::consts::PI * radius),
        sig(ball.shell_damping)
    );
    let band_text: Vec<String> = band.iter().map(|(h, b)| format!("{} Pa s/m at {} cm", sig(*b), short(100.0 * h))).collect();
    let _ = write!(
        w,
        "{} (FIFA Quality Pro's floor is 120 cm). Nothing else was fitted: every other point on this page is a \
         prediction of that ball.\n\n",
        band_text.join(", ")
    );

    // Pressure.
    let _ = write!(
        w,
        "## Against pressure, over Law 2's range\n\n\
         ![The ball alone against pressure]({})\n\n\
         Law 2 allows 0.6–1.1 atm gauge at sea level. The same 2 m drop rebounds {} at 0.6 atm, {} at the FIFA test's \
         0.8 bar ({} atm, the calibration) and {} at 1.1 atm: restitution rises with pressure, the contact shortens \
         and the ball flattens less (the patch's stiffness is 2πR p0). Rows of the file, on Law 2's grid in atm (its \
         0.8 atm row is {} kPa, not the test's {} kPa):\n\n\
         | impact speed (m/s) | pressure (atm) | pressure (kPa) | e | contact time (ms) | peak force (N) | δ_max (mm) |\n\
         | --- | --- | --- | --- | --- | --- | --- |\n",
        links.pressure_figure,
        format!("{} m", sig(drops[0].1.rebound_height.unwrap_or(f64::NAN))),
        format!("{} m", sig(drops[1].1.rebound_height.unwrap_or(f64::NAN))),
        three(atm(FIFA_PRESSURE)),
        format!("{} m", sig(drops[2].1.rebound_height.unwrap_or(f64::NAN))),
        sig(0.8e-3 * SEA_LEVEL_PRESSURE),
        sig(1e-3 * FIFA_PRESSURE),
    );
    for v in distinct(p.speed).into_iter().take(2) {
        for &i in at_speed(&p, v).iter().step_by(10) {
            let _ = writeln!(
                w,
                "| {} | {} | {} | {} | {} | {} | {} |",
                sig(v),
                short((100.0 * atm(pressure[i])).round() / 100.0),
                sig(1e-3 * pressure[i]),
                sig(p.restitution[i]),
                sig(1e3 * p.contact_time[i]),
                sig(p.peak_force[i]),
                compression_cell(p.max_compression[i], radius)
            );
        }
    }

    let past: Vec<(f64, String)> = distinct(p.speed)
        .into_iter()
        .filter_map(|v| {
            outside_pressures(&p, pressure, &at_speed(&p, v), radius).map(|(all, lo, hi)| {
                (v, if all { "at every pressure".to_string() } else { format!("from {} to {} kPa", sig(lo), sig(hi)) })
            })
        })
        .collect();
    if !past.is_empty() {
        let _ = writeln!(
            w,
            "\nPast R/2 = {} mm the shell law is outside its stated validity (status \"outside validity\" in the file). \
             The file's {}: drawn for continuity in all three panels of the figure, marked in its legends, not as \
             predictions.",
            short(1e3 * 0.5 * radius),
            past.iter()
                .map(|(v, at)| format!("{} m/s curve compresses the ball past it {at}", short(*v)))
                .collect::<Vec<_>>()
                .join("; the ")
        );
    }

    // Speed.
    let e_rows: Vec<usize> = [2.0, 6.0, 10.0, 19.0, 30.0].iter().map(|&v| nearest(s.speed, v)).collect();
    let (first, last) = (e_rows[0], e_rows[e_rows.len() - 1]);
    // The contact time over the table's rows: its longest and its range.
    let longest = e_rows.iter().copied().max_by(|&a, &b| s.contact_time[a].total_cmp(&s.contact_time[b])).unwrap_or(first);
    // δ_max/V over the table's rows, and the last row inside the law's validity (δ_max ≤ R/2).
    let per_speed = |i: usize| 1e3 * s.max_compression[i] / s.speed[i];
    let last_valid = e_rows.iter().copied().filter(|&i| s.max_compression[i] <= 0.5 * radius).last().unwrap_or(first);
    let (t_low, t_high) = e_rows.iter().fold((f64::INFINITY, 0.0f64), |(a, b), &i| (a.min(s.contact_time[i]), b.max(s.contact_time[i])));
    let _ = write!(
        w,
        "\n## Against impact speed, at 0.8 bar\n\n\
         ![The ball alone against speed]({})\n\n\
         - Restitution falls with impact speed, from {} at {} m/s to {} at {} m/s over the table below (the stated \
         dependence above). Measurements of restitution against speed to set beside it (Andersen et al. 2008, Mills \
         et al. 2022) were not read in a checkable copy, so only the FIFA band is drawn.\n\
         - The contact time barely moves with speed because the ball is nearly a linear spring: p·A(δ) ≈ 2πR p0 δ, \
         so t_c ≈ π√(m/(2πR p0)) whatever the speed. Over the table it moves by {} %: from {} ms at {} m/s up to {} ms at {} m/s, \
         then down to {} ms at {} m/s, a fall that is the gas's stiffening as the cap it loses grows.\n\
         - Compression is not proportional to speed: δ_max/V falls from {} mm per m/s at {} m/s to {} at {} m/s \
         ({} %); up to {} m/s, the table's last row inside the law's validity, it falls {} %.\n\n\
         | impact speed (m/s) | e | contact time (ms) | peak force (N) | δ_max (mm) | δ_max / V (mm per m/s) |\n\
         | --- | --- | --- | --- | --- | --- |\n",
        links.speed_figure,
        sig(s.restitution[first]),
        sig(s.speed[first]),
        sig(s.restitution[last]),
        sig(s.speed[last]),
        three(100.0 * (t_high / t_low - 1.0)),
        sig(1e3 * s.contact_time[first]),
        sig(s.speed[first]),
        sig(1e3 * s.contact_time[longest]),
        sig(s.speed[longest]),
        sig(1e3 * s.contact_time[last]),
        sig(s.speed[last]),
        three(per_speed(first)),
        sig(s.speed[first]),
        three(per_speed(last)),
        sig(s.speed[last]),
        three(100.0 * (1.0 - per_speed(last) / per_speed(first))),
        sig(s.speed[last_valid]),
        three(100.0 * (1.0 - per_speed(last_valid) / per_speed(first))),
    );
    for &i in &e_rows {
        let _ = writeln!(
            w,
            "| {} | {} | {} | {} | {} | {} |",
            sig(s.speed[i]),
            sig(s.restitution[i]),
            sig(1e3 * s.contact_time[i]),
            sig(s.peak_force[i]),
            compression_cell(s.max_compression[i], radius),
            sig(1e3 * s.max_compression[i] / s.speed[i])
        );
    }
    let past: Vec<f64> = (0..s.speed.len()).filter(|&i| s.max_compression[i] > 0.5 * radius).map(|i| s.speed[i]).collect();
    if let Some(&from) = past.iter().min_by(|a, b| a.total_cmp(b)) {
        let _ = writeln!(
            w,
            "\n† δ_max > R/2 = {} mm: outside the shell law's stated validity (`kick_core::LawKind::validity`; status \
             \"outside validity\" in the file), from {} m/s on in this file. Drawn for continuity, not as predictions.",
            short(1e3 * 0.5 * radius),
            sig(from)
        );
    }

    // The stiffness check.
    let fifa_rows = at_speed(&p, distinct(p.speed)[0]);
    let v0 = p.speed[fifa_rows[0]];
    let target = DOWELL_KREBS_MM_PER_MPS * 1e-3 * v0;
    let small_cap: Vec<f64> = p.max_compression.iter().map(|&d| small_cap_compression(d, radius)).collect();
    let dk_pressure = crossing(pressure, &fifa_rows, p.max_compression, target);
    let dk_small_pressure = crossing(pressure, &fifa_rows, &small_cap, target);
    // Three digits: the abstract's line d = 2.80 v carries three.
    let describe = |x: Option<f64>| match x {
        Some(x) => format!("{} atm", three(atm(x))),
        None => "no pressure within Law 2's range (lower: the model's d stays below theirs)".to_string(),
    };
    let (lo, hi) = (fifa_rows[0], fifa_rows[fifa_rows.len() - 1]);
    let mills_contact = MILLS_ERROR.1 / MILLS_ERROR.0;
    let mills_low = bounce(&[("speed", MILLS_LOW_SPEED), ("inflation_pressure", FIFA_PRESSURE)])?;
    // The abstract's digits, 2.8 % and 0.3 ms, hold ±0.05 % and ±0.05 ms: the quotient's range.
    let (mills_short, mills_long) =
        ((MILLS_ERROR.1 - 0.05e-3) / (MILLS_ERROR.0 + 0.0005), (MILLS_ERROR.1 + 0.05e-3) / (MILLS_ERROR.0 - 0.0005));
    let model_range = (p.contact_time[hi].min(mills_low.contact_time), p.contact_time[lo].max(mills_low.contact_time));
    let overlap = model_range.0 <= mills_long && mills_short <= model_range.1;
    let _ = write!(
        w,
        "\n## The ball's dynamic stiffness against plate tests\n\n\
         **Dowell & Krebs (1991)** dropped a soccer ball from four heights onto paper over carbon paper, measured the \
         diameter D of its imprint, and from it calculated a compression d, linear in impact speed: d = 2.80 v (mm, v \
         in m/s). Their abstract gives neither the heights, the ball's size nor its pressure, nor how d was calculated \
         from D. The model's patch is the flat cap, so the imprint it leaves has D = 2√(2Rδ_max − δ_max²); a compression \
         calculated from D by the sagitta of a chord on a sphere of radius R, R − √(R² − D²/4), is δ_max itself, and by \
         the small-cap formula D²/(8R) it is δ_max − δ_max²/(2R) (the dashed curve \"d by D²/8R\" in the compression \
         panel of the speed figure; the pressure figure draws δ_max only). At the FIFA drop's {} m/s their \
         line gives {} mm; the model gives {} mm at 0.6 atm and {} mm at 1.1 atm. Read by the sagitta, the model meets \
         their value at {}; read by the small-cap formula, at {}. A consistency check, not a validation: the pressure \
         of their ball is not known. Their line is drawn to 8 m/s, a 3.3 m drop: our choice, since the abstract states \
         no heights.\n\n\
         **Mills, Billingham & Goodwill (2026)** fired twelve FIFA-certified balls at a rigid plate at 5.93 and 19.2 m/s \
         and state a model error for contact time of \"2.8 % (corresponding to 0.3 ms)\": contact times near \
         0.3/0.028 ≈ {} ms, an inference from the abstract, with no speed or pressure attached; its two rounded \
         figures (0.25–0.35 ms, 2.75–2.85 %) allow {}–{} ms. The model gives {} ms at 5.93 m/s and 0.8 bar, and {} ms \
         to {} ms over Law 2's range at {} m/s: {}. The full text (open access, SHURA eprint 37603) was not read \
         here; its per-ball contact times and deformations are the first check to make.\n\n",
        sig(v0),
        sig(1e3 * target),
        sig(1e3 * p.max_compression[lo]),
        sig(1e3 * p.max_compression[hi]),
        describe(dk_pressure),
        describe(dk_small_pressure),
        sig(1e3 * mills_contact),
        three(1e3 * mills_short),
        three(1e3 * mills_long),
        sig(1e3 * mills_low.contact_time),
        sig(1e3 * p.contact_time[lo]),
        sig(1e3 * p.contact_time[hi]),
        sig(v0),
        if overlap {
            "the ranges overlap, so the abstract's numbers neither confirm nor contradict the ball; only the inference's \
             centre would need a pressure below Law 2's range, or a ball softer than the pressure over the flat patch"
        } else {
            "outside the abstract's range: a ball softer than the pressure over the flat patch (a smaller patch, a shell \
             that buckles inward) would be needed"
        },
    );
    let _ = write!(
        w,
        "## The measurements, where each number was read\n\n\
         | source | what | number | read in | counted as validation |\n\
         | --- | --- | --- | --- | --- |\n\
         | FIFA Quality Programme (adsport.sk, derbystar.de) | rebound from 2 m at 0.8 bar | 115–165 cm | secondary: two ball makers' pages describing the test | no: the calibration |\n\
         | Dowell & Krebs 1991, Br J Sports Med 25, 34 | compression from an imprint | d = 2.80 v mm | abstract (bisp-surf, moam) | no: abstract only |\n\
         | Mills, Billingham & Goodwill 2026, Proc IMechE P | contact-time error | 2.8 % ≙ 0.3 ms | abstract (SHURA 37603) | no: abstract only, an inference |\n\
         | ISBS 2022 (commons.nmu.edu, isbs vol 40 no 12) | peak force on a plate, 0.4–0.95 atm | lower at lower pressure at every speed but {} m/s (no values) | abstract | no: abstract only, direction |\n\
         | Price et al. 2008, J Mater Sci 43, 2833 | where a ball loses energy | the shell's viscoelastic layers | abstract | no: a modelling choice |\n\
         | Peacock & Ball 2016 (ISBS) | a limb kick's restitution against foot speed | 0.66–0.79, no significant trend | abstract | no: a kick, abstract only |\n\n\
         No measurement of a football's restitution or contact time against inflation pressure was found in a \
         checkable copy (searched: public pages, documentation, code and issue corpora, for restitution, rebound, contact \
         time and compression against pressure). The ISBS 2022 abstract reports that a lower pressure lowered the peak \
         force at every speed but {} m/s. That is the only plate speed it names, {} m/s below the {} m/s compared here. \
         The model's peak force at {} m/s rises from {} N at 0.6 atm to {} N at 1.1 atm: the direction the abstract \
         reports at its other speeds. Not counted.\n\n",
        short(ISBS_EXCEPTION_SPEED),
        short(ISBS_EXCEPTION_SPEED),
        three(p.speed[fifa_rows[0]] - ISBS_EXCEPTION_SPEED),
        sig(p.speed[fifa_rows[0]]),
        sig(p.speed[fifa_rows[0]]),
        sig(p.peak_force[lo]),
        sig(p.peak_force[hi])
    );

    // The fit.
    let report = &fit.report;
    let _ = write!(
        w,
        "## Calibrating the ball from your own plate tests\n\n\
         `kick fit` fits the ball to plate tests, each at its own impact speed and pressure: a fit specification with \
         `level = \"bounce\"`, the free parameters, starting guesses in `[bounce]` and one `[[measurement]]` per test \
         with its conditions and its observables (restitution, contact time, peak force, compression) with their \
         standard uncertainties (the format: crates/kick-identify/README.md). Here on synthetic data: the default ball \
         with shell_damping = {} Pa s/m and shell_stiffness = {} N/m, fired at {} m/s and {} atm ({} tests), restitution \
         to ±{}, contact time to ±{} ms and compression to ±{} mm, Gaussian noise (seed {FIT_SEED}): [{spec}]({spec}), \
         fitted by `kick fit data {command_spec} --out {command_report}`.\n\n\
         | parameter | truth | start | estimate | standard uncertainty | (estimate − truth)/σ |\n\
         | --- | --- | --- | --- | --- | --- |\n",
        sig(FIT_TRUTH[0].1),
        sig(FIT_TRUTH[1].1),
        FIT_SPEEDS.map(|v| short(v).to_string()).join(", "),
        FIT_PRESSURES_ATM.map(|v| short(v).to_string()).join(", "),
        FIT_SPEEDS.len() * FIT_PRESSURES_ATM.len(),
        short(FIT_SIGMA[0].1),
        short(1e3 * FIT_SIGMA[1].1),
        short(1e3 * FIT_SIGMA[2].1),
        spec = links.fit_spec,
        command_spec = links.command_spec,
        command_report = links.command_report,
    );
    for e in &report.estimates {
        let truth = fit.truth.iter().find(|(q, _)| *q == e.parameter).map(|(_, t)| *t);
        let u = e.standard_uncertainty;
        let _ = writeln!(
            w,
            "| `{}` ({}) | {} | {} | {} | {} | {} |",
            e.parameter.name(),
            e.parameter.unit(),
            truth.map_or("—".into(), |t| sig(t).to_string()),
            sig(e.start),
            sig(e.value),
            u.map_or("not identified".into(), |u| sig(u).to_string()),
            match (truth, u) {
                (Some(t), Some(u)) => format!("{:+.2}", (e.value - t) / u),
                _ => "—".into(),
            }
        );
    }
    let correlation = report.correlation.as_ref().map(|c| c[0][1]);
    let ratio = match (report.singular_values.first(), report.singular_values.last()) {
        (Some(a), Some(b)) if *b > 0.0 => a / b,
        _ => f64::INFINITY,
    };
    let _ = write!(
        w,
        "\nχ² = {} over {} degrees of freedom (s² = {}); the correlation of the two estimates is {}; the weighted \
         Jacobian's singular values span a factor {}: both parameters are identified by these tests, β mostly by the \
         restitutions, k_s by the contact times and compressions (it adds a stiffness that does not scale with the \
         pressure, which the gauge gives). These are synthetic data from the model itself: on real data, s² well \
         above 1 says the law misses (its speed dependence first), and the uncertainties then understate the error.\n",
        sig(report.chi_square),
        report.degrees_of_freedom,
        report.residual_variance.map_or("—".into(), |v| sig(v).to_string()),
        correlation.map_or("—".into(), |c| format!("{c:+.3}")),
        sig(ratio),
    );
    Ok(w)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The imprint's diameter converted back by the sagitta is δ; by the
    /// small-cap formula D²/(8R) it is δ − δ²/(2R).
    #[test]
    fn imprint_diameter_maps_back_to_the_compression() {
        let r: f64 = 0.11;
        for delta in [0.005_f64, 0.017, 0.04] {
            let d = 2.0 * (2.0 * r * delta - delta * delta).sqrt();
            let sagitta = r - (r * r - d * d / 4.0).sqrt();
            assert!((sagitta - delta).abs() < 1e-15, "{sagitta} vs {delta}");
            assert!((d * d / (8.0 * r) - small_cap_compression(delta, r)).abs() < 1e-16);
        }
    }

    /// The bounce experiments run, the page is drawn from their files: its
    /// pressure rows are the file's, each `kick bounce` at its values, bit
    /// for bit; the synthetic plate tests are fitted back within 3σ of the truth.
    #[test]
    fn page_figures_and_fit_come_from_the_files() {
        let dir = std::env::temp_dir().join(format!("kick-ball-page-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        let experiments = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../experiments/ball");
        for file in ["speeds.toml", "pressure.toml"] {
            kick_store::shard::run_file(&experiments.join(file), &dir, None).unwrap();
        }
        let written = write(&dir, &dir.join("figures"), &dir.join("ball.md"), "kick reproduce --only ball").unwrap();
        for name in ["ball_bounce.png", "ball_pressure.png", "ball_plate.toml", "ball_plate_fit.h5", "ball.md"] {
            assert!(written.iter().any(|p| p.ends_with(name)), "{name}: {written:?}");
        }
        let data = SweepData::read(&dir.join(PRESSURE_FILE)).unwrap();
        let b = bounces(&data).unwrap();
        let page = std::fs::read_to_string(dir.join("ball.md")).unwrap();
        let pressure = b.pressure.unwrap();
        for i in [0, 20, 50] {
            let o = bounce(&[("speed", b.speed[i]), ("inflation_pressure", pressure[i])]).unwrap();
            assert_eq!((b.restitution[i], b.contact_time[i]), (o.restitution, o.contact_time), "row {i}");
            let row = format!("| {} | {} | {} |", sig(1e-3 * pressure[i]), sig(b.restitution[i]), sig(1e3 * b.contact_time[i]));
            assert!(page.contains(&row), "{row}\n{page}");
        }
        // Restitution rises with pressure in the file, at every speed.
        for v in distinct(b.speed) {
            let rows = at_speed(&b, v);
            assert!(rows.windows(2).all(|w| b.restitution[w[1]] > b.restitution[w[0]]), "{v}");
        }
        let file = kick_store::ResultFile::open(&dir.join(FIT_REPORT)).unwrap();
        let data = crate::identify::files::read_fit(&file, "fit").unwrap();
        for e in &data.estimates {
            let pull = e.pull().unwrap();
            assert!(pull.abs() < 3.0, "{}: {pull}", e.name);
        }
        let _ = std::fs::remove_dir_all(&dir);
    }

    /// A crossing by linear interpolation, and none when the curve stays on one side.
    #[test]
    fn crossing_interpolates() {
        let p = [1.0, 2.0, 3.0];
        let y = [10.0, 8.0, 6.0];
        assert_eq!(crossing(&p, &[0, 1, 2], &y, 7.0), Some(2.5));
        assert_eq!(crossing(&p, &[0, 1, 2], &y, 11.0), None);
    }
}
