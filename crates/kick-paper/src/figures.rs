//! Figures 1–7 of the paper, drawn from the result files (never re-simulated).
//!
//! Each figure reads `RESULTS/figureN*.h5` and writes `FIGURES/figureN.png`
//! and `FIGURES/figureN.svg`. Text uses DejaVu Sans, bundled in
//! `assets/` and registered with plotters' `ab_glyph` backend, so no system
//! font library is needed.

use crate::h5::{read_history, Column, H5Error, SweepData};
use crate::output::{OutputError, Staged};
use plotters::coord::ranged1d::ValueFormatter;
use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::{Path, PathBuf};
use std::sync::Once;

mod legend;
pub mod text;

static FONT: &[u8] = include_bytes!("../assets/DejaVuSans.ttf");
const FAMILY: &str = "sans-serif";
/// Pixel size of a PNG (and SVG) figure.
pub const SIZE: (u32, u32) = (1400, 950);

#[derive(Debug, thiserror::Error)]
pub enum FigureError {
    #[error(transparent)]
    H5(#[from] H5Error),
    #[error("figure {figure}: {message}")]
    Draw { figure: String, message: String },
    #[error(transparent)]
    Output(#[from] OutputError),
}

fn register_font() -> Result<(), FigureError> {
    static ONCE: Once = Once::new();
    let mut result = Ok(());
    ONCE.call_once(|| {
        result = plotters::style::register_font(FAMILY, FontStyle::Normal, FONT)
            .map_err(|_| FigureError::Draw { figure: "-".into(), message: "bundled font DejaVuSans.ttf is invalid".into() });
    });
    result
}

/// One curve of a panel.
#[derive(Debug, Clone)]
pub struct Series {
    pub label: String,
    pub points: Vec<(f64, f64)>,
    pub color: RGBColor,
    pub dashed: bool,
    pub markers: bool,
    /// x intervals shaded over the panel's height, drawn under every curve
    /// (a shade series has no points: [`Series::shade`]).
    pub shade: Vec<(f64, f64)>,
}

impl Series {
    pub fn line(label: &str, color: RGBColor, x: &[f64], y: &[f64]) -> Series {
        Series { label: label.into(), points: finite_points(x, y), color, dashed: false, markers: false, shade: Vec::new() }
    }
    /// Vertical bands over the x intervals `from..to` in a light `color`
    /// (e.g. the phases of a contact), labelled once in the legend.
    pub fn shade(label: &str, color: RGBColor, intervals: &[(f64, f64)]) -> Series {
        Series { shade: intervals.to_vec(), ..Series::line(label, color, &[], &[]) }
    }
    pub fn dashed(mut self) -> Series {
        self.dashed = true;
        self
    }
    pub fn with_markers(mut self) -> Series {
        self.markers = true;
        self
    }
}

/// Points with both coordinates finite (failed scenarios are NaN in the files).
fn finite_points(x: &[f64], y: &[f64]) -> Vec<(f64, f64)> {
    x.iter().zip(y).filter(|(a, b)| a.is_finite() && b.is_finite()).map(|(&a, &b)| (a, b)).collect()
}

/// One set of axes.
#[derive(Debug, Clone)]
pub struct Panel {
    pub title: String,
    pub x_label: String,
    pub y_label: String,
    pub log_x: bool,
    pub series: Vec<Series>,
    /// Force the y range to include zero.
    pub y_from_zero: bool,
    /// Where the legend goes (drawn when two or more curves are labelled).
    pub legend: SeriesLabelPosition,
}

impl Panel {
    /// Linear axes from zero, legend at the upper right.
    pub fn new(title: &str, x_label: &str, y_label: &str, series: Vec<Series>) -> Panel {
        Panel {
            title: title.into(),
            x_label: x_label.into(),
            y_label: y_label.into(),
            log_x: false,
            series,
            y_from_zero: true,
            legend: SeriesLabelPosition::UpperRight,
        }
    }
}

/// The palette of every figure: black first (a reference curve), then tab10.
pub const COLORS: [RGBColor; 9] = [
    RGBColor(0, 0, 0),
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
    RGBColor(255, 127, 14),
    RGBColor(23, 190, 207),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
];

/// Colour of the i-th curve of a figure (skipping the reference black).
pub fn color(i: usize) -> RGBColor {
    COLORS[1 + i % (COLORS.len() - 1)]
}

fn draw_err(figure: &str) -> impl Fn(String) -> FigureError + '_ {
    move |message| FigureError::Draw { figure: figure.to_string(), message }
}

/// Tick label of a log10 axis position: the value itself, 3 significant
/// digits, at powers of ten only (the ticks between stay unlabelled).
fn log_tick(v: f64) -> String {
    let x = 10f64.powf(v);
    if (0.01..10_000.0).contains(&x) {
        // Three significant digits, enough for 1, 2 and 5 times a power of ten.
        let digits = (2 - x.log10().floor() as i32).max(0) as usize;
        let text = format!("{x:.digits$}");
        if text.contains('.') {
            text.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            text
        }
    } else {
        format!("{x:.0e}")
    }
}

/// Key points of a log axis spanning (x0, x1) in decades: 1, 2 and 5 times
/// each power of ten over up to three and a half decades, powers of ten alone beyond;
/// light points at every digit times a power of ten.
fn log_key_points(x0: f64, x1: f64) -> (Vec<f64>, Vec<f64>) {
    if !(x0.is_finite() && x1.is_finite() && x0 < x1) {
        return (Vec::new(), Vec::new());
    }
    let multiples: &[f64] = if x1 - x0 <= 3.5 { &[1.0, 2.0, 5.0] } else { &[1.0] };
    let (mut keys, mut lights) = (Vec::new(), Vec::new());
    for decade in (x0.floor() as i32)..=(x1.ceil() as i32) {
        for digit in 1..10 {
            let v = (f64::from(digit) * 10f64.powi(decade)).log10();
            if !(x0..=x1).contains(&v) {
                continue;
            }
            if multiples.contains(&f64::from(digit)) {
                keys.push(v);
            } else {
                lights.push(v);
            }
        }
    }
    (keys, lights)
}

fn padded(min: f64, max: f64) -> (f64, f64) {
    if !(min.is_finite() && max.is_finite()) {
        return (0.0, 1.0);
    }
    let span = (max - min).abs().max(1e-12 * max.abs().max(1.0));
    (min - 0.05 * span, max + 0.05 * span)
}

/// A log axis' range (in decades) with room for the end markers.
fn padded_log(min: f64, max: f64) -> (f64, f64) {
    if !(min.is_finite() && max.is_finite()) {
        return (0.0, 1.0);
    }
    let pad = 0.03 * (max - min).abs().max(0.1);
    (min - pad, max + pad)
}

/// The layout every panel's axes share.
fn chart_builder<'a, 'b, DB: DrawingBackend>(area: &'a DrawingArea<DB, Shift>, panel: &Panel) -> ChartBuilder<'a, 'b, DB> {
    let mut builder = ChartBuilder::on(area);
    builder.caption(&panel.title, (FAMILY, 22)).margin(12).x_label_area_size(48).y_label_area_size(78);
    builder
}

/// The legend's top-left corner (pixels in the plot) and the top of the y
/// range that leaves it free of data ([`legend`]), tried on a scratch bitmap
/// of the panel's size with the panel's own layout.
fn place_legend(
    dims: (u32, u32),
    panel: &Panel,
    labels: &[&str],
    x: (f64, f64),
    y: (f64, f64),
    tx: impl Fn(f64) -> f64,
) -> Result<Option<((i32, i32), f64)>, String> {
    let font: TextStyle = (FAMILY, 15).into_font().into();
    let size = legend::box_size(labels, &font)?;
    let mut scratch = vec![0u8; dims.0 as usize * dims.1 as usize * 3];
    for headroom in legend::HEADROOM {
        let top = y.1 + headroom * (y.1 - y.0);
        let area = BitMapBackend::with_buffer(&mut scratch, dims).into_drawing_area();
        let chart = chart_builder(&area, panel).build_cartesian_2d(x.0..x.1, y.0..top).map_err(|e| e.to_string())?;
        let (xs, ys) = chart.plotting_area().get_pixel_range();
        let curves: Vec<Vec<(i32, i32)>> = panel
            .series
            .iter()
            .map(|s| {
                s.points
                    .iter()
                    .map(|&(px, py)| {
                        let (u, v) = chart.backend_coord(&(tx(px), py));
                        (u - xs.start, v - ys.start)
                    })
                    .collect()
            })
            .collect();
        let plot = (xs.end - xs.start, ys.end - ys.start);
        if let Some(corner) = legend::free_position(&curves, size, plot, &panel.legend) {
            return Ok(Some((corner, top)));
        }
    }
    Ok(None)
}

/// The pixel size of a panel's plotting area (inside its labels and caption) in `area`.
fn plot_pixels<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, panel: &Panel) -> Result<(f64, f64), String> {
    let dims = area.dim_in_pixel();
    let mut scratch = vec![0u8; dims.0 as usize * dims.1 as usize * 3];
    let scratch_area = BitMapBackend::with_buffer(&mut scratch, dims).into_drawing_area();
    let chart = chart_builder(&scratch_area, panel).build_cartesian_2d(0.0..1.0, 0.0..1.0).map_err(|e| e.to_string())?;
    let (xs, ys) = chart.plotting_area().get_pixel_range();
    Ok((f64::from(xs.end - xs.start), f64::from(ys.end - ys.start)))
}

/// Widen the shorter of two linear ranges so that a metre along x and along
/// y take the same pixels on a plot `pixels` wide and high: x grows to the
/// right (its start, e.g. the kick, stays at the left edge), y about its middle.
pub fn equal_scale(x: (f64, f64), y: (f64, f64), pixels: (f64, f64)) -> ((f64, f64), (f64, f64)) {
    let (per_x, per_y) = ((x.1 - x.0) / pixels.0, (y.1 - y.0) / pixels.1);
    if per_x > per_y {
        let (middle, half) = ((y.0 + y.1) / 2.0, per_x * pixels.1 / 2.0);
        (x, (middle - half, middle + half))
    } else {
        ((x.0, x.0 + per_y * pixels.0), y)
    }
}

fn draw_panel<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, panel: &Panel, equal: bool) -> Result<(), String> {
    let tx = |x: f64| if panel.log_x { x.log10() } else { x };
    let xs = panel.series.iter().flat_map(|s| s.points.iter().map(|p| tx(p.0)));
    let ys = panel.series.iter().flat_map(|s| s.points.iter().map(|p| p.1));
    let (x0, x1) = xs.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| (a.min(x), b.max(x)));
    let (mut y0, mut y1) = ys.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), y| (a.min(y), b.max(y)));
    if panel.y_from_zero {
        y0 = y0.min(0.0);
        y1 = y1.max(0.0);
    }
    let (x0, x1) = if panel.log_x { padded_log(x0, x1) } else { padded(x0, x1) };
    let (y0, mut y1) = padded(y0, y1);
    let labels: Vec<&str> = panel.series.iter().map(|s| s.label.as_str()).filter(|l| !l.is_empty()).collect();
    let mut legend_at = panel.legend.clone();
    // Equal scale: the ranges follow from the data and the plot's shape, and
    // the legend goes where it is free at them (no headroom added above).
    let equal = equal && !panel.log_x;
    let ((x0, x1), (y0, y_top)) = if equal { equal_scale((x0, x1), (y0, y1), plot_pixels(area, panel)?) } else { ((x0, x1), (y0, y1)) };
    y1 = y_top;
    if equal && labels.len() > 1 {
        if let Some((corner, top)) = place_legend(area.dim_in_pixel(), panel, &labels, (x0, x1), (y0, y1), tx)? {
            if top == y1 {
                legend_at = SeriesLabelPosition::Coordinate(corner.0, corner.1);
            }
        }
    } else if labels.len() > 1 {
        if let Some(((x, y), top)) = place_legend(area.dim_in_pixel(), panel, &labels, (x0, x1), (y0, y1), tx)? {
            legend_at = SeriesLabelPosition::Coordinate(x, y);
            y1 = top;
        }
    }
    let mut builder = chart_builder(area, panel);
    if panel.log_x {
        // Labels at 1, 2 and 5 times each power of ten (powers alone over a wide range), a light line at every digit.
        let (keys, lights) = log_key_points(x0, x1);
        let chart = builder.build_cartesian_2d(LogAxis { inner: (x0..x1).into(), keys, lights }, y0..y1).map_err(|e| e.to_string())?;
        finish_panel(chart, panel, (y0, y1), legend_at, 64, &|v: &f64| log_tick(*v))
    } else {
        let chart = builder.build_cartesian_2d(x0..x1, y0..y1).map_err(|e| e.to_string())?;
        finish_panel(chart, panel, (y0, y1), legend_at, 10, &|v: &f64| format!("{}", (v * 1e6).round() / 1e6))
    }
}

/// A log axis in decades with its own labels (plotters' key points on a
/// linear range in decades would be 10^0.5 and the like).
struct LogAxis {
    inner: RangedCoordf64,
    keys: Vec<f64>,
    lights: Vec<f64>,
}

impl Ranged for LogAxis {
    type ValueType = f64;
    type FormatOption = plotters::coord::ranged1d::NoDefaultFormatting;
    fn map(&self, value: &f64, limit: (i32, i32)) -> i32 {
        self.inner.map(value, limit)
    }
    fn key_points<Hint: plotters::coord::ranged1d::KeyPointHint>(&self, hint: Hint) -> Vec<f64> {
        if hint.weight().allow_light_points() {
            self.lights.clone()
        } else {
            self.keys.clone()
        }
    }
    fn range(&self) -> std::ops::Range<f64> {
        self.inner.range()
    }
}

impl ValueFormatter<f64> for LogAxis {
    fn format(value: &f64) -> String {
        log_tick(*value)
    }
}

/// Mesh, shades, curves and legend of a panel whose chart is built (`x_labels`: plotters' hint; a log axis gives
/// its own key points and ignores it, but plotters multiplies it, so it stays small).
fn finish_panel<'a, DB: DrawingBackend + 'a, X>(
    mut chart: ChartContext<'a, DB, Cartesian2d<X, RangedCoordf64>>,
    panel: &Panel,
    (y0, y1): (f64, f64),
    legend_at: SeriesLabelPosition,
    x_labels: usize,
    x_fmt: &dyn Fn(&f64) -> String,
) -> Result<(), String>
where
    X: Ranged<ValueType = f64> + ValueFormatter<f64>,
{
    let tx = |x: f64| if panel.log_x { x.log10() } else { x };
    chart
        .configure_mesh()
        .x_labels(x_labels)
        .x_desc(panel.x_label.as_str())
        .y_desc(panel.y_label.as_str())
        .x_label_formatter(x_fmt)
        .label_style((FAMILY, 15))
        .axis_desc_style((FAMILY, 17))
        .light_line_style(RGBColor(235, 235, 235))
        .draw()
        .map_err(|e| e.to_string())?;
    // Shades first, under the curves.
    const SHADE: f64 = 0.2;
    for s in panel.series.iter().filter(|s| !s.shade.is_empty()) {
        let fill = s.color.mix(SHADE).filled();
        let anno =
            chart.draw_series(s.shade.iter().map(|&(a, b)| Rectangle::new([(tx(a), y0), (tx(b), y1)], fill))).map_err(|e| e.to_string())?;
        if !s.label.is_empty() {
            let color = s.color;
            anno.label(s.label.as_str()).legend(move |(x, y)| Rectangle::new([(x, y - 6), (x + 20, y + 6)], color.mix(SHADE).filled()));
        }
    }
    for s in panel.series.iter().filter(|s| s.shade.is_empty()) {
        let points: Vec<(f64, f64)> = s.points.iter().map(|&(x, y)| (tx(x), y)).collect();
        let style = s.color.stroke_width(2);
        let color = s.color;
        let anno = if s.dashed {
            chart.draw_series(DashedLineSeries::new(points.clone(), 9, 6, style)).map_err(|e| e.to_string())?
        } else {
            chart.draw_series(LineSeries::new(points.clone(), style)).map_err(|e| e.to_string())?
        };
        if !s.label.is_empty() {
            let dashed = s.dashed;
            anno.label(s.label.as_str()).legend(move |(x, y)| {
                if dashed {
                    PathElement::new(vec![(x, y), (x + 8, y)], color.stroke_width(2))
                } else {
                    PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2))
                }
            });
        }
        if s.markers {
            chart.draw_series(points.iter().map(|&p| Circle::new(p, 3, color.filled()))).map_err(|e| e.to_string())?;
        }
    }
    if panel.series.iter().filter(|s| !s.label.is_empty()).count() > 1 {
        chart
            .configure_series_labels()
            .label_font((FAMILY, 15))
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .position(legend_at)
            .draw()
            .map_err(|e| e.to_string())?;
    }
    Ok(())
}

fn draw_grid<DB: DrawingBackend>(
    root: DrawingArea<DB, Shift>,
    title: &str,
    layout: (usize, usize),
    panels: &[Panel],
    equal_scale_panels: &[usize],
    tall: bool,
) -> Result<(), String> {
    root.fill(&WHITE).map_err(|e| e.to_string())?;
    let root = root.titled(title, (FAMILY, 26)).map_err(|e| e.to_string())?;
    let areas = if tall && layout.1 == 1 {
        // A tall figure in one column: an equal-scale row (a plan view) takes
        // twice the height of the others, so its data fill it rather than a widened range.
        let weight = |i: usize| if equal_scale_panels.contains(&i) { 2 } else { 1 };
        let total: i32 = (0..layout.0).map(weight).sum();
        let height = root.dim_in_pixel().1 as i32;
        let mut breaks = Vec::new();
        let mut at = 0;
        for i in 0..layout.0.saturating_sub(1) {
            at += weight(i);
            breaks.push(height * at / total);
        }
        root.split_by_breakpoints(Vec::<i32>::new(), breaks)
    } else {
        root.split_evenly(layout)
    };
    for (i, (area, panel)) in areas.iter().zip(panels).enumerate() {
        draw_panel(area, panel, equal_scale_panels.contains(&i))?;
    }
    root.present().map_err(|e| e.to_string())
}

/// The PNG backend of every figure (`size`: [`SIZE`] but for a tall plan view), text by [`text::TextBackend`].
fn png_backend(path: &Path, size: (u32, u32)) -> Result<text::TextBackend<'_>, FigureError> {
    text::TextBackend::new(BitMapBackend::new(path, size), FONT)
        .map_err(|_| FigureError::Draw { figure: path.display().to_string(), message: "bundled font DejaVuSans.ttf is invalid".into() })
}

/// Write `name.png` and `name.svg` of a grid of panels.
pub fn save_grid(dir: &Path, name: &str, title: &str, layout: (usize, usize), panels: &[Panel]) -> Result<Vec<PathBuf>, FigureError> {
    save_grid_equal_scale(dir, name, title, layout, panels, &[], None)
}

/// [`save_grid`], the panels numbered in `equal_scale` (linear axes, both in
/// the same unit, e.g. a plan view in metres) drawn at equal scale: a unit
/// along x takes as many pixels as a unit along y ([`equal_scale`]).
/// `height` [px]: a taller figure than [`SIZE`] for a plan view about as
/// wide as long (same width; in one column such a row then takes twice the
/// others' height).
pub fn save_grid_equal_scale(
    dir: &Path,
    name: &str,
    title: &str,
    layout: (usize, usize),
    panels: &[Panel],
    equal_scale: &[usize],
    height: Option<u32>,
) -> Result<Vec<PathBuf>, FigureError> {
    register_font()?;
    let size = (SIZE.0, height.unwrap_or(SIZE.1));
    let png = Staged::begin(&dir.join(format!("{name}.png")))?;
    let svg = Staged::begin(&dir.join(format!("{name}.svg")))?;
    let tall = height.is_some();
    draw_grid(png_backend(png.temporary(), size)?.into_drawing_area(), title, layout, panels, equal_scale, tall).map_err(draw_err(name))?;
    draw_grid(SVGBackend::new(svg.temporary(), size).into_drawing_area(), title, layout, panels, equal_scale, tall)
        .map_err(draw_err(name))?;
    // The two forms of one figure: both or neither.
    Ok(crate::output::commit_all(vec![png, svg])?)
}

fn column<'a>(columns: &'a [(Column, Vec<f64>)], name: &str, path: &Path) -> Result<&'a [f64], FigureError> {
    columns
        .iter()
        .find(|(c, _)| c.name == name)
        .map(|(_, v)| v.as_slice())
        .ok_or_else(|| FigureError::Draw { figure: path.display().to_string(), message: format!("no column `{name}`") })
}

fn scaled(values: &[f64], factor: f64) -> Vec<f64> {
    values.iter().map(|v| v * factor).collect()
}

fn outcome<'a>(data: &'a SweepData, solver: &str, name: &str) -> Result<&'a [f64], FigureError> {
    let set = data.set(solver)?;
    set.column(name).ok_or_else(|| FigureError::Draw { figure: data.path.display().to_string(), message: format!("no outcome `{name}`") })
}

/// Figure 1: the baseline time history.
pub fn figure1(results: &Path, out: &Path) -> Result<Vec<PathBuf>, FigureError> {
    let path = results.join("figure1.h5");
    let h = read_history(&path, "", 0)?;
    let t = scaled(column(&h, "time", &path)?, 1e3);
    let panels = vec![
        Panel {
            title: "(a) Contact force".into(),
            x_label: "time t (ms)".into(),
            y_label: "force F (kN)".into(),
            log_x: false,
            y_from_zero: true,
            legend: SeriesLabelPosition::UpperRight,
            series: vec![Series::line("", color(0), &t, &scaled(column(&h, "force", &path)?, 1e-3))],
        },
        Panel {
            title: "(b) Velocities".into(),
            x_label: "time t (ms)".into(),
            y_label: "velocity (m/s)".into(),
            log_x: false,
            y_from_zero: true,
            legend: SeriesLabelPosition::LowerRight,
            series: vec![
                Series::line("foot v_f", color(0), &t, column(&h, "foot_velocity", &path)?),
                Series::line("ball v_b", color(1), &t, column(&h, "ball_velocity", &path)?),
            ],
        },
        Panel {
            title: "(c) Compression".into(),
            x_label: "time t (ms)".into(),
            y_label: "compression δ (mm)".into(),
            log_x: false,
            y_from_zero: true,
            legend: SeriesLabelPosition::UpperRight,
            series: vec![Series::line("", color(2), &t, &scaled(column(&h, "compression", &path)?, 1e3))],
        },
        {
            let kinetic = column(&h, "kinetic", &path)?;
            let elastic = column(&h, "elastic", &path)?;
            let dissipated = column(&h, "dissipated", &path)?;
            let total: Vec<f64> = (0..t.len()).map(|i| kinetic[i] + elastic[i] + dissipated[i]).collect();
            Panel {
                title: "(d) Energies".into(),
                x_label: "time t (ms)".into(),
                y_label: "energy (J)".into(),
                log_x: false,
                y_from_zero: true,
                legend: SeriesLabelPosition::MiddleRight,
                series: vec![
                    Series::line("kinetic K", color(0), &t, kinetic),
                    Series::line("elastic U(δ)", color(1), &t, elastic),
                    Series::line("dissipated D", color(2), &t, dissipated),
                    Series::line("K + U + D", color(3), &t, &total).dashed(),
                ],
            }
        },
    ];
    save_grid(out, "figure1", "Figure 1: baseline time history (accurate solver)", (2, 2), &panels)
}

/// Figure 2: speed ratio versus effective foot mass, with Eq. 38 at e = 1.
pub fn figure2(results: &Path, out: &Path) -> Result<Vec<PathBuf>, FigureError> {
    let data = SweepData::read(&results.join("figure2.h5"))?;
    let solver = data.sets[0].solver.clone();
    let mf = data.parameter("foot_mass")?;
    let mb = data.parameter("ball_mass")?;
    // Eq. 38 with e = 1: the perfectly elastic bound for a ball at rest.
    let bound: Vec<f64> = mf.iter().zip(mb).map(|(f, b)| 2.0 * f / (f + b)).collect();
    let panels = vec![Panel {
        title: "Ball-to-foot speed ratio versus effective foot mass".into(),
        x_label: "effective foot mass m_f (kg), log scale".into(),
        y_label: "speed ratio v_b⁺ / v_f⁻ (1)".into(),
        log_x: true,
        y_from_zero: true,
        legend: SeriesLabelPosition::LowerRight,
        series: vec![
            Series::line(&format!("compliant model ({solver})"), color(0), mf, outcome(&data, &solver, "speed_ratio")?),
            Series::line("perfectly elastic bound, Eq. 38 with e = 1", color(1), mf, &bound).dashed(),
        ],
    }];
    save_grid(out, "figure2", "Figure 2: effective impact mass", (1, 1), &panels)
}

/// Force histories of every row of a history file, labelled by one parameter.
fn force_histories(path: &Path, parameter: &str, label: impl Fn(f64) -> String) -> Result<Vec<Series>, FigureError> {
    let data = SweepData::read(path)?;
    let values = data.parameter(parameter)?.to_vec();
    let mut series = Vec::new();
    for (row, v) in values.iter().enumerate() {
        // Rows with an outcome: separated, or outside the law's validity (numbers kept).
        let has_outcome = |code: &u8| kick_study::printable::Status::ALL.iter().any(|s| s.code() == *code && s.has_outcome());
        if !data.sets[0].status.get(row).is_some_and(has_outcome) {
            continue;
        }
        let h = read_history(path, "", row)?;
        let t = scaled(column(&h, "time", path)?, 1e3);
        series.push(Series::line(&label(*v), color(row), &t, &scaled(column(&h, "force", path)?, 1e-3)));
    }
    Ok(series)
}

/// Figure 3: stiffness sweep.
pub fn figure3(results: &Path, out: &Path) -> Result<Vec<PathBuf>, FigureError> {
    let data = SweepData::read(&results.join("figure3.h5"))?;
    let solver = data.sets[0].solver.clone();
    let k = data.parameter("stiffness")?;
    let panels = vec![
        Panel {
            title: "(a) Force pulses".into(),
            x_label: "time t (ms)".into(),
            y_label: "force F (kN)".into(),
            log_x: false,
            y_from_zero: true,
            legend: SeriesLabelPosition::UpperRight,
            series: force_histories(&results.join("figure3_histories.h5"), "stiffness", |v| format!("k = {v:.2e} N/m^n"))?,
        },
        Panel {
            title: "(b) Peak force".into(),
            x_label: "stiffness k (N/m^n), log scale".into(),
            y_label: "peak force (kN)".into(),
            log_x: true,
            y_from_zero: true,
            legend: SeriesLabelPosition::UpperRight,
            series: vec![Series::line("", color(1), k, &scaled(outcome(&data, &solver, "peak_force")?, 1e-3))],
        },
        Panel {
            title: "(c) Contact time".into(),
            x_label: "stiffness k (N/m^n), log scale".into(),
            y_label: "contact time t_c (ms)".into(),
            log_x: true,
            y_from_zero: true,
            legend: SeriesLabelPosition::UpperRight,
            series: vec![Series::line("", color(2), k, &scaled(outcome(&data, &solver, "contact_time")?, 1e3))],
        },
        Panel {
            title: "(d) Ball exit speed".into(),
            x_label: "stiffness k (N/m^n), log scale".into(),
            y_label: "exit speed v_b⁺ (m/s)".into(),
            log_x: true,
            y_from_zero: true,
            legend: SeriesLabelPosition::UpperRight,
            series: vec![Series::line("", color(0), k, outcome(&data, &solver, "v_ball_out")?)],
        },
    ];
    save_grid(out, "figure3", "Figure 3: stiffness sweep (n = 1.35)", (2, 2), &panels)
}

/// Figure 4: damping sweep.
pub fn figure4(results: &Path, out: &Path) -> Result<Vec<PathBuf>, FigureError> {
    let data = SweepData::read(&results.join("figure4.h5"))?;
    let solver = data.sets[0].solver.clone();
    let c = data.parameter("damping")?;
    let (vf, vb) = (data.parameter("foot_speed")?, data.parameter("ball_speed")?);
    // F(0⁺) = c V0: the force jump at first touch.
    let onset: Vec<f64> = (0..c.len()).map(|i| c[i] * (vf[i] - vb[i]) * 1e-3).collect();
    let panels = vec![
        Panel {
            title: "(a) Force pulses".into(),
            x_label: "time t (ms)".into(),
            y_label: "force F (kN)".into(),
            log_x: false,
            y_from_zero: true,
            legend: SeriesLabelPosition::UpperRight,
            series: force_histories(&results.join("figure4_histories.h5"), "damping", |v| format!("c = {v} N s/m"))?,
        },
        Panel {
            title: "(b) Ball exit speed".into(),
            x_label: "damping c (N s/m)".into(),
            y_label: "exit speed v_b⁺ (m/s)".into(),
            log_x: false,
            y_from_zero: true,
            legend: SeriesLabelPosition::UpperRight,
            series: vec![Series::line("", color(0), c, outcome(&data, &solver, "v_ball_out")?)],
        },
        Panel {
            title: "(c) Peak force".into(),
            x_label: "damping c (N s/m)".into(),
            y_label: "force (kN)".into(),
            log_x: false,
            y_from_zero: true,
            legend: SeriesLabelPosition::UpperRight,
            series: vec![
                Series::line("peak force", color(1), c, &scaled(outcome(&data, &solver, "peak_force")?, 1e-3)),
                Series::line("onset jump F(0⁺) = c V0", color(3), c, &onset).dashed(),
            ],
        },
        Panel {
            title: "(d) Effective restitution".into(),
            x_label: "damping c (N s/m)".into(),
            y_label: "restitution e (1)".into(),
            log_x: false,
            y_from_zero: true,
            legend: SeriesLabelPosition::UpperRight,
            series: vec![Series::line("", color(2), c, outcome(&data, &solver, "restitution")?)],
        },
    ];
    save_grid(out, "figure4", "Figure 4: damping sweep", (2, 2), &panels)
}

/// Figure 5: drive force during contact.
pub fn figure5(results: &Path, out: &Path) -> Result<Vec<PathBuf>, FigureError> {
    let data = SweepData::read(&results.join("figure5.h5"))?;
    let solver = data.sets[0].solver.clone();
    let f = data.parameter("drive_force")?;
    let (mf, mb) = (data.parameter("foot_mass")?, data.parameter("ball_mass")?);
    let vb = outcome(&data, &solver, "v_ball_out")?;
    let tc = outcome(&data, &solver, "contact_time")?;
    // Gains relative to the undriven row (the sweep starts at F = 0).
    let vb0 = f.iter().position(|&x| x == 0.0).map(|i| vb[i]).unwrap_or(f64::NAN);
    let gain: Vec<f64> = vb.iter().map(|v| v - vb0).collect();
    // Eq. 55: J_drive ~ F t_c, shared by foot and ball: the centre-of-mass gain.
    let shared: Vec<f64> = (0..f.len()).map(|i| f[i] * tc[i] / (mf[i] + mb[i])).collect();
    let panels = vec![
        Panel {
            title: "(a) Exit speeds".into(),
            x_label: "drive force F_drive (N)".into(),
            y_label: "exit speed (m/s)".into(),
            log_x: false,
            y_from_zero: true,
            legend: SeriesLabelPosition::LowerRight,
            series: vec![
                Series::line("ball v_b⁺", color(0), f, vb),
                Series::line("foot v_f⁺", color(1), f, outcome(&data, &solver, "v_foot_out")?),
            ],
        },
        Panel {
            title: "(b) Ball speed gained from the drive".into(),
            x_label: "drive force F_drive (N)".into(),
            y_label: "speed gain (m/s)".into(),
            log_x: false,
            y_from_zero: true,
            legend: SeriesLabelPosition::UpperLeft,
            series: vec![
                Series::line("v_b⁺(F) − v_b⁺(0)", color(0), f, &gain),
                Series::line("F t_c / (m_f + m_b), Eq. 55 spread over both", color(3), f, &shared).dashed(),
            ],
        },
    ];
    save_grid(out, "figure5", "Figure 5: drive force during contact", (1, 2), &panels)
}

/// Figure 6: final versus initial ball velocity.
pub fn figure6(results: &Path, out: &Path) -> Result<Vec<PathBuf>, FigureError> {
    let data = SweepData::read(&results.join("figure6.h5"))?;
    let solver = data.sets[0].solver.clone();
    let v0 = data.parameter("ball_speed")?;
    let panels = vec![
        Panel {
            title: "(a) Final ball velocity".into(),
            x_label: "initial ball velocity v_b⁻ (m/s)".into(),
            y_label: "final ball velocity v_b⁺ (m/s)".into(),
            log_x: false,
            y_from_zero: true,
            legend: SeriesLabelPosition::LowerRight,
            series: vec![
                Series::line("compliant model", color(0), v0, outcome(&data, &solver, "v_ball_out")?),
                Series::line("v_b⁺ = v_b⁻ (no contact)", RGBColor(128, 128, 128), v0, v0).dashed(),
            ],
        },
        Panel {
            title: "(b) Peak force".into(),
            x_label: "initial ball velocity v_b⁻ (m/s)".into(),
            y_label: "peak force (kN)".into(),
            log_x: false,
            y_from_zero: true,
            legend: SeriesLabelPosition::UpperRight,
            series: vec![Series::line("", color(1), v0, &scaled(outcome(&data, &solver, "peak_force")?, 1e-3))],
        },
    ];
    save_grid(out, "figure6", "Figure 6: initial ball velocity (foot speed 22 m/s)", (1, 2), &panels)
}

/// Bar fills of Figure 7: dark, middle and light, so the groups stay apart
/// in greyscale print (luminance 0.15, 0.47, 0.85), each with a black outline.
pub const BAR_COLORS: [RGBColor; 3] = [RGBColor(0, 45, 110), RGBColor(213, 94, 0), RGBColor(200, 220, 240)];

/// Relative luminance of a colour as greyscale printing sees it (Rec. 601 weights).
pub fn luminance(c: RGBColor) -> f64 {
    (0.299 * c.0 as f64 + 0.587 * c.1 as f64 + 0.114 * c.2 as f64) / 255.0
}

fn draw_bars<DB: DrawingBackend>(root: DrawingArea<DB, Shift>, names: &[String], groups: &[(String, Vec<f64>)]) -> Result<(), String> {
    root.fill(&WHITE).map_err(|e| e.to_string())?;
    let root = root.titled("Figure 7: ball exit speed of the Table 2 scenarios", (FAMILY, 26)).map_err(|e| e.to_string())?;
    let n = names.len();
    let max = groups.iter().flat_map(|g| g.1.iter().copied()).filter(|v| v.is_finite()).fold(0.0, f64::max);
    let mut chart = ChartBuilder::on(&root)
        .margin(16)
        .x_label_area_size(50)
        .y_label_area_size(220)
        .build_cartesian_2d(0.0..max * 1.12, 0.0..n as f64)
        .map_err(|e| e.to_string())?;
    let names_owned = names.to_vec();
    let y_fmt = move |v: &f64| {
        let i = (n as f64 - v - 0.5).round();
        if (v.fract() - 0.5).abs() < 1e-6 && i >= 0.0 && (i as usize) < n {
            names_owned[i as usize].clone()
        } else {
            String::new()
        }
    };
    chart
        .configure_mesh()
        .disable_y_mesh()
        .y_labels(2 * n + 1)
        .y_label_formatter(&y_fmt)
        .x_desc("ball exit speed v_b⁺ (m/s)")
        .label_style((FAMILY, 16))
        .axis_desc_style((FAMILY, 17))
        .draw()
        .map_err(|e| e.to_string())?;
    let g = groups.len() as f64;
    let height = 0.8 / g;
    for (k, (label, values)) in groups.iter().enumerate() {
        let c = BAR_COLORS[k % BAR_COLORS.len()];
        let corners = move |(i, &v): (usize, &f64)| {
            // Row 0 at the top.
            let top = n as f64 - i as f64 - 0.1 - k as f64 * height;
            [(0.0, top - height), (v, top)]
        };
        let finite = || values.iter().enumerate().filter(|(_, v)| v.is_finite());
        chart
            .draw_series(finite().map(corners).map(|r| Rectangle::new(r, c.filled())))
            .map_err(|e| e.to_string())?
            .label(label.as_str())
            .legend(move |(x, y)| {
                EmptyElement::at((x, y))
                    + Rectangle::new([(0, -6), (16, 6)], c.filled())
                    + Rectangle::new([(0, -6), (16, 6)], BLACK.stroke_width(1))
            });
        chart.draw_series(finite().map(corners).map(|r| Rectangle::new(r, BLACK.stroke_width(1)))).map_err(|e| e.to_string())?;
    }
    chart
        .configure_series_labels()
        .label_font((FAMILY, 16))
        .background_style(WHITE.mix(0.9))
        .border_style(BLACK)
        .position(SeriesLabelPosition::LowerRight)
        .draw()
        .map_err(|e| e.to_string())?;
    root.present().map_err(|e| e.to_string())
}

/// Figure 7: exit speed of the Table 2 scenarios, printed and computed.
pub fn figure7(results: &Path, out: &Path) -> Result<Vec<PathBuf>, FigureError> {
    register_font()?;
    let path = results.join("figure7.h5");
    let data = SweepData::read(&path)?;
    let names = data.names.clone().ok_or_else(|| draw_err("figure7")("no scenario_names".into()))?;
    // The paper's printed values, stored beside the computed ones.
    let printed = crate::h5::ResultFile::open(&path)?.values("paper/v_ball_out")?;
    let mut groups = vec![("paper (printed)".to_string(), printed)];
    for set in &data.sets {
        let v = set.column("v_ball_out").ok_or_else(|| draw_err("figure7")("no v_ball_out".into()))?;
        groups.push((set.solver.clone(), v.to_vec()));
    }
    let png = Staged::begin(&out.join("figure7.png"))?;
    let svg = Staged::begin(&out.join("figure7.svg"))?;
    draw_bars(png_backend(png.temporary(), SIZE)?.into_drawing_area(), &names, &groups).map_err(draw_err("figure7"))?;
    draw_bars(SVGBackend::new(svg.temporary(), SIZE).into_drawing_area(), &names, &groups).map_err(draw_err("figure7"))?;
    // The two forms of one figure: both or neither.
    Ok(crate::output::commit_all(vec![png, svg])?)
}

/// A figure: its name and the function drawing it.
pub type FigureFn = fn(&Path, &Path) -> Result<Vec<PathBuf>, FigureError>;

/// Every figure, in the paper's order.
pub const FIGURES: [(&str, FigureFn); 7] = [
    ("figure1", figure1),
    ("figure2", figure2),
    ("figure3", figure3),
    ("figure4", figure4),
    ("figure5", figure5),
    ("figure6", figure6),
    ("figure7", figure7),
];

/// Draw every figure from `results` into `out`.
pub fn draw_all(results: &Path, out: &Path) -> Result<Vec<PathBuf>, FigureError> {
    let mut written = Vec::new();
    for (_, draw) in FIGURES {
        written.extend(draw(results, out)?);
    }
    Ok(written)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn figure7_bars_differ_in_greyscale() {
        for (i, a) in BAR_COLORS.iter().enumerate() {
            for b in &BAR_COLORS[i + 1..] {
                let gap = (luminance(*a) - luminance(*b)).abs();
                assert!(gap >= 0.2, "{a:?} and {b:?} print {gap:.2} apart in grey");
            }
        }
    }

    /// Figure 4(c)'s shape: two curves rising into the upper right corner,
    /// where the legend used to sit. The placement moves it to the next
    /// position in order, the upper left, which the curves (at most 9 kN
    /// below c = 400 N s/m) leave free, on the panel's own pixel layout.
    #[test]
    fn the_legend_leaves_the_curves_free() {
        register_font().unwrap();
        let c: Vec<f64> = (0..=50).map(|k| 20.0 * k as f64).collect();
        let rise: Vec<f64> = c.iter().map(|c| 22.0 * c / 1000.0).collect();
        let peak: Vec<f64> = c.iter().map(|&c| (22.0 * c / 1000.0).max(5.3 - c / 100.0)).collect();
        let mut panel = Panel::new(
            "(c) Peak force",
            "damping c (N s/m)",
            "force (kN)",
            vec![Series::line("peak force", color(1), &c, &peak), Series::line("onset jump F(0+) = c V0", color(3), &c, &rise).dashed()],
        );
        panel.legend = SeriesLabelPosition::UpperRight;
        let labels = ["peak force", "onset jump F(0+) = c V0"];
        let dims = (SIZE.0 / 2, SIZE.1 / 2);
        let ((x, y), top) = place_legend(dims, &panel, &labels, padded(0.0, 1000.0), padded(0.0, 22.0), |x| x).unwrap().unwrap();
        assert_eq!(top, padded(0.0, 22.0).1, "no headroom needed: the upper left is free");
        assert_eq!((x, y), (5, 5), "legend not at the upper left");
    }

    #[test]
    fn log_ticks_read_as_the_numbers_they_mark() {
        assert_eq!(log_tick(1.0), "10");
        assert_eq!(log_tick(2.0), "100");
        assert_eq!(log_tick(2f64.log10()), "2");
        assert_eq!(log_tick(50f64.log10()), "50");
        assert_eq!(log_tick(0.05f64.log10()), "0.05");
        assert_eq!(log_tick(-3.0), "1e-3");
    }

    /// 1, 2 and 5 per decade over up to three decades, powers of ten alone
    /// beyond, each inside the range; the other digits are light lines.
    #[test]
    fn log_axes_are_labelled_at_one_two_and_five() {
        let (keys, lights) = log_key_points(0.1, 2.9);
        let shown: Vec<String> = keys.iter().map(|&v| log_tick(v)).collect();
        assert_eq!(shown, ["2", "5", "10", "20", "50", "100", "200", "500"]);
        // 3, 4, 6, 7, 8 and 9 from 1.26 to 794: six in each full decade, 300 to 700 in the last.
        assert_eq!(lights.len(), 6 + 6 + 4, "{lights:?}");
        let (keys, _) = log_key_points(-0.5, 3.9);
        let shown: Vec<String> = keys.iter().map(|&v| log_tick(v)).collect();
        assert_eq!(shown, ["1", "10", "100", "1000"]);
    }

    #[test]
    fn log_axes_keep_their_end_markers_inside() {
        let (lo, hi) = padded_log(0.5, 3.1);
        assert!(lo < 0.5 - 0.05 && hi > 3.1 + 0.05, "{lo} {hi}");
    }

    /// Equal scale: the shorter range grows until a unit takes as many pixels
    /// along x as along y; the data's ranges stay inside; x keeps its start.
    #[test]
    fn equal_scale_gives_both_axes_the_same_pixels_per_unit() {
        let pixels = (1290.0, 350.0);
        for (x, y) in [((0.0, 28.0), (-4.0, 4.0)), ((0.0, 28.0), (-15.0, 4.0)), ((-1.0, 30.0), (-0.5, 0.5))] {
            let ((x0, x1), (y0, y1)) = equal_scale(x, y, pixels);
            let (per_x, per_y) = ((x1 - x0) / pixels.0, (y1 - y0) / pixels.1);
            assert!((per_x / per_y - 1.0).abs() < 1e-12, "{x:?} {y:?}: {per_x} vs {per_y}");
            assert!(x0 == x.0 && x1 >= x.1 && y0 <= y.0 && y1 >= y.1);
            assert!(x1 == x.1 || (y0, y1) == y, "only one range grows");
        }
    }

    /// The plan views' panel shape, measured on the panel's own layout.
    #[test]
    fn the_plot_area_is_measured_inside_the_labels() {
        let panel = Panel::new("from above", "x (m)", "y (m)", vec![]);
        let mut buffer = vec![0u8; SIZE.0 as usize * SIZE.1 as usize * 3];
        let area = BitMapBackend::with_buffer(&mut buffer, SIZE).into_drawing_area();
        let halves = area.split_evenly((2, 1));
        let (w, h) = plot_pixels(&halves[0], &panel).unwrap();
        assert!(
            w > 0.85 * f64::from(SIZE.0) && w < f64::from(SIZE.0) && h > 0.3 * f64::from(SIZE.1) && h < 0.5 * f64::from(SIZE.1),
            "{w} x {h}"
        );
    }
}
