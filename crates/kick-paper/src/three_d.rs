//! The 3D figures, drawn back from the 3D result files kick-store writes
//! (`kick_store::three_d`).

use crate::figures::{color, save_grid, FigureError, Panel, Series};
use kick_store::h5::SweepData;
use std::path::{Path, PathBuf};

/// A value as a curve label shows it (`∞` for infinity).
pub fn value_label(v: f64) -> String {
    if v == f64::INFINITY {
        "∞".into()
    } else {
        kick_study::printable::short(v).to_string()
    }
}

/// A 3D result file read whole, its parameter columns in the grid's axis
/// order (`/grid/axes`; HDF5 lists a group's members alphabetically).
pub fn read_grid_file(h5: &Path) -> Result<SweepData, FigureError> {
    let mut data = SweepData::read(h5)?;
    let file = kick_store::h5::ResultFile::open(h5)?;
    if file.exists("grid/axes") {
        let axes = file.strings("grid/axes")?;
        data.parameters.sort_by_key(|(c, _)| axes.iter().position(|a| *a == c.name).unwrap_or(usize::MAX));
    }
    Ok(data)
}

/// Rows of a result file's grid, split by the value of its second axis (one
/// curve each, in the grid's order), or one curve of every row for one axis.
/// Each curve: its label (`μ = 0.5`, the declared symbol) and its rows.
pub fn curves(data: &SweepData) -> Vec<(String, Vec<usize>)> {
    let rows = data.rows();
    match data.parameters.get(1) {
        None => vec![(String::new(), (0..rows).collect())],
        Some((column, values)) => {
            let symbol = kick_study::parameters::find(&column.name).map_or(column.name.as_str(), |p| p.symbol);
            let mut out: Vec<(f64, Vec<usize>)> = Vec::new();
            for (row, &v) in values.iter().enumerate() {
                match out.iter_mut().find(|(w, _)| w.to_bits() == v.to_bits()) {
                    Some((_, list)) => list.push(row),
                    None => out.push((v, vec![row])),
                }
            }
            out.into_iter().map(|(v, list)| (format!("{symbol} = {}", value_label(v)), list)).collect()
        }
    }
}

/// Figures of a 3D result file of one or two axes into `dir/NAME.{png,svg}`:
/// ball speed, spin and the launch direction (elevation and azimuth of the
/// launch velocity; a panel that is zero throughout is left out) against the
/// first axis, one curve per value of the second. When the first axis is the
/// offset and a second axis gives a family of curves, also `NAME_tradeoff`:
/// ball speed against spin, one curve per value of the second axis (the
/// speed–spin trade-off; paper/3d.md shows the offset × friction one, whose
/// μ = 0.5 curve is the one-axis offset file's). Files of other shapes draw nothing.
pub fn figures(h5: &Path, dir: &Path) -> Result<Vec<PathBuf>, FigureError> {
    let data = read_grid_file(h5)?;
    if data.parameters.is_empty() || data.parameters.len() > 2 {
        return Ok(Vec::new());
    }
    let (axis, x) = &data.parameters[0];
    let set = &data.sets[0];
    let column = |name: &str| {
        set.column(name)
            .map(<[f64]>::to_vec)
            .ok_or_else(|| FigureError::Draw { figure: h5.display().to_string(), message: format!("no column {name}") })
    };
    let curves = curves(&data);
    let pick = |v: &[f64], rows: &[usize]| -> Vec<f64> { rows.iter().map(|&r| v[r]).collect() };
    let series = |y: &[f64], x: &[f64]| -> Vec<Series> {
        curves
            .iter()
            .enumerate()
            .map(|(i, (label, rows))| Series::line(label, color(i), &pick(x, rows), &pick(y, rows)).with_markers())
            .collect()
    };
    let symbol = kick_study::parameters::find(&axis.name).map_or(String::new(), |p| format!(" {}", p.symbol));
    let x_label = format!("{}{symbol} ({})", axis.name.replace('_', " "), axis.unit);
    // Spin in rad/s, as every page quotes it (the file's column is in rpm).
    let (speed, rad) = (column("speed")?, column("spin_rpm")?.iter().map(|r| r / crate::units::RPM_PER_RAD_PER_S).collect::<Vec<_>>());
    let mut panels = vec![
        Panel::new("ball speed", &x_label, "speed |v| (m/s)", series(&speed, x)),
        Panel::new("ball spin", &x_label, "spin |ω| (rad/s)", series(&rad, x)),
    ];
    for (name, title, label) in [
        ("launch_angle", "launch elevation", "elevation above the ground (deg)"),
        ("launch_azimuth", "launch azimuth", "azimuth from the foot's path (deg)"),
    ] {
        let y = column(name)?;
        if y.iter().any(|v| *v != 0.0 && v.is_finite()) {
            panels.push(Panel::new(title, &x_label, label, series(&y, x)));
        }
    }
    let layout = if panels.len() > 2 { (2, 2) } else { (1, 2) };
    let name = h5.file_stem().and_then(|s| s.to_str()).unwrap_or("3d");
    let title = kick_store::h5::file_str_attr(h5, "", "description").unwrap_or_default();
    let mut written = save_grid(dir, name, &title, layout, &panels)?;
    if axis.name == "offset" && curves.len() > 1 {
        let trade = vec![Panel::new(
            "ball speed against spin across offsets (markers: the offsets of the grid)",
            "spin |ω| (rad/s)",
            "speed |v| (m/s)",
            series(&speed, &rad),
        )];
        written.extend(save_grid(
            dir,
            &format!("{name}_tradeoff"),
            "the speed–spin trade-off across offsets, per friction",
            (1, 1),
            &trade,
        )?);
    }
    Ok(written)
}
