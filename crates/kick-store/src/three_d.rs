//! 3D experiments (`kick run`, see `kick_study::experiment::three_d`) into
//! `DIR/NAME.h5` (kick-paper draws the 3D figures back from those files),
//! and bounce experiments (`level = "bounce"`, the ball alone) in the same
//! grid layout with `level = "bounce"` ([`run_bounce_part`]).
//!
//! The file is a sweep table ([`crate::h5`]): one row per grid cell (C
//! order), `/parameters/<axis>` the swept values per row, `/outcomes/<name>`
//! every column of [`kick_3d::OBSERVABLES_3D`] (vectors as `_x`, `_y`, `_z`),
//! plus `/grid` (axis coordinates, `grid_shape` attribute, see
//! [`crate::h5::write_grid`]), `/fixed/<name>` every parameter not swept
//! (defaults filled in; vectors as three numbers, switches as 0 or 1) with
//! its unit, and the root attribute `level = "3d"`.

use crate::experiment::{Experiment, Kicks3d, KicksBounce};
use crate::h5::{new_group, write_column, write_grid, write_str_attr, Column, H5Error};
use crate::provenance::Provenance;
use crate::table::{create_table, fill_table, finish_table, progress, Part, RunError, RunSummary};
use kick_study::grid::Grid;
use kick_study::level::Level;
use std::path::Path;

/// The 3D part of [`crate::run::run_part`]: the cells `part.rows` of
/// `experiment` (whose kicks are `kicks`) into `part.path`, solved in
/// parallel in chunks and written in grid order (the file does not depend
/// on the threads); `attributes` adds root attributes of the caller's.
/// `/grid` and `/fixed` describe the whole experiment in every part.
pub(crate) fn run_part(
    experiment: &Experiment,
    kicks: &Kicks3d,
    part: &Part,
    attributes: &dyn Fn(&hdf5::File) -> Result<(), H5Error>,
) -> Result<RunSummary, RunError> {
    // Every parameter not swept, as the first cell was built with it.
    let fixed = |group: &hdf5::Group, path: &Path| -> Result<(), RunError> {
        let first = kicks.kick(0).map_err(|e| H5Error::Layout { path: path.to_path_buf(), message: e.to_string() })?;
        for (def, value) in first.parameter_values() {
            if kicks.grid.axes.iter().any(|a| a.parameter.name == def.name) {
                continue;
            }
            write_column(group, path, &Column::new(def.name, def.unit), &value.numbers())?;
        }
        Ok(())
    };
    grid_part(experiment, &kicks.grid, part, "3d", &fixed, attributes)
}

/// The bounce part of [`crate::run::run_part`]: the grid layout of
/// [`run_part`], `/fixed/<name>` every bounce parameter not swept (given or
/// defaulted; a vector as three numbers; the speed, when a drop height gives
/// it, left out), root attribute `level = "bounce"` (the law is among the
/// outcome set's settings).
pub(crate) fn run_bounce_part(
    experiment: &Experiment,
    kicks: &KicksBounce,
    part: &Part,
    attributes: &dyn Fn(&hdf5::File) -> Result<(), H5Error>,
) -> Result<RunSummary, RunError> {
    let fixed = |group: &hdf5::Group, path: &Path| -> Result<(), RunError> {
        for (def, value) in kicks.fixed() {
            write_column(group, path, &Column::new(def.name, def.unit), &value)?;
        }
        Ok(())
    };
    grid_part(experiment, &kicks.grid, part, "bounce", &fixed, attributes)
}

/// The layout both grid parts share: the table, its description and
/// `level`, the grid's coordinates, `/fixed` (written by `fixed`), the
/// caller's attributes, then the rows.
fn grid_part(
    experiment: &Experiment,
    grid: &Grid,
    part: &Part,
    level: &str,
    fixed: &dyn Fn(&hdf5::Group, &Path) -> Result<(), RunError>,
    attributes: &dyn Fn(&hdf5::File) -> Result<(), H5Error>,
) -> Result<RunSummary, RunError> {
    let path = part.path.clone();
    let out_dir = path.parent().unwrap_or(Path::new("."));
    let rows = part.rows.end - part.rows.start;
    kick_study::limits::OutputSize::check(experiment, &part.rows, out_dir)?;
    let provenance = Provenance::now(&experiment.name, &experiment.path.display().to_string(), &experiment.text);
    let mut writer = create_table(experiment, &path, &provenance, rows, experiment.compress)?;
    let file = writer.file().clone();
    write_str_attr(&file, &path, "description", &experiment.description)?;
    write_str_attr(&file, &path, "level", level)?;
    let axes = experiment.parameter_columns();
    let coordinates: Vec<(Column, &[f64])> = axes.into_iter().zip(grid.axes.iter().map(|a| a.values.as_slice())).collect();
    write_grid(&file, &path, &coordinates)?;
    let group = new_group(&file, "fixed").map_err(|e| H5Error::hdf5(&path, &e))?;
    fixed(&group, &path)?;
    attributes(&file)?;
    drop(file);
    let bar = progress(rows, false);
    fill_table(experiment, part.rows.clone(), &mut writer, &bar)?;
    finish_table(experiment, writer, &bar)
}

#[cfg(test)]
mod tests {
    use crate::experiment::parse;
    use crate::h5::{read_grid_shape, SweepData};
    use kick_3d::{Accurate3d, KickSpec};
    use kick_core::parameters::{SetParameter, Value};
    use std::path::Path;

    /// A 2-axis grid over a 1D and a 3D parameter: shape kept, fixed
    /// parameters stored, each cell equal to a kick built by name and solved alone.
    #[test]
    fn a_two_axis_3d_grid_keeps_its_shape_and_equals_single_kicks() {
        let text = "description = \"t\"\n[base]\nfoot_mass = 2.0\n[kick3d]\nfriction = 0.7\n\
                    [[sweep]]\nparameter = \"foot_speed\"\nvalues = [18.0, 24.0]\n\
                    [[sweep]]\nparameter = \"offset\"\nlinear = { from = 0.0, to = 0.06, count = 3 }\n";
        let e = parse(Path::new("grid.toml"), text).unwrap();
        assert!(e.three_d().is_some(), "read as 1D");
        let dir = std::env::temp_dir().join(format!("kick-grid3d-{}", std::process::id()));
        let summary = crate::run::run(&e, &dir, false).unwrap();
        let data = SweepData::read(&summary.path).unwrap();
        let file = hdf5::File::open(&summary.path).unwrap();
        assert_eq!(read_grid_shape(&file), Some(vec![2, 3]));
        assert_eq!(file.dataset("fixed/friction").unwrap().read_raw::<f64>().unwrap(), vec![0.7]);
        assert_eq!(file.dataset("fixed/foot_mass").unwrap().read_raw::<f64>().unwrap(), vec![2.0]);
        assert_eq!(file.dataset("fixed/foot_half_extents").unwrap().read_raw::<f64>().unwrap().len(), 3);
        assert!(!file.link_exists("fixed/offset"));
        let set = &data.sets[0];
        let mut row = 0;
        for speed in [18.0, 24.0] {
            for offset in [0.0, 0.03, 0.06] {
                let mut spec = KickSpec::default();
                for (name, v) in [("foot_mass", 2.0), ("friction", 0.7), ("foot_speed", speed), ("offset", offset)] {
                    spec.set_named(name, Value::Number(v)).unwrap();
                }
                let o = Accurate3d::default().solve(&spec.build().unwrap()).unwrap();
                assert_eq!(data.parameters[0].1[row], speed);
                assert_eq!(data.parameters[1].1[row], offset);
                for (k, (name, _)) in kick_3d::OBSERVABLES_3D.iter().enumerate() {
                    assert_eq!(set.column(name).unwrap()[row], o.observable_values()[k], "{name} at row {row}");
                }
                row += 1;
            }
        }
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn bad_3d_keys_are_refused_with_their_line() {
        let e = parse(Path::new("x.toml"), "level = \"3d\"\n[kick3d]\nfriction = 0.5\nofset = 0.02\n").unwrap_err();
        assert_eq!((e.line, e.key.as_str()), (4, "ofset"), "{e}");
        let e = parse(Path::new("x.toml"), "[[sweep]]\nparameter = \"offset\"\nvalues = [0.0, 0.2]\n").unwrap_err();
        assert_eq!((e.line, e.key.as_str()), (3, "sweep.offset"), "{e}");
        let e = parse(Path::new("x.toml"), "[kick3d]\noffset = 0.5\n").unwrap_err();
        assert_eq!((e.line, e.key.as_str()), (2, "kick3d.offset"), "{e}");
    }
}
