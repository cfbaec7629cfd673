//! The free kicks' file, `OUT/flight/free_kick.h5` (issue 14): the grid of
//! [`kick_study::free_kick`] solved into a sweep table ([`crate::h5`]):
//! parameters `offset` (m) and `friction` (1) per row (grid order: offset,
//! then friction fastest; `/grid`, `grid_shape`); outcome sets `launch`
//! (its setting `contact_depth`), `goal` (the flight with its crossing of
//! the goal line) and `wall` (crossing the wall's plane); the trajectories
//! of [`TRAJECTORY_OFFSETS`] × [`TRAJECTORY_FRICTIONS`] as
//! `solvers/goal/histories/<row>` ([`TRAJECTORY_COLUMNS`], uniform in time).

use crate::h5::{write_grid, write_str_attr, Column};
use crate::provenance::Provenance;
use crate::table::{create_table, fill_table};
use crate::StoreError;
use kick_study::free_kick::*;
use kick_study::level::Level;
use kick_study::StudyError;
use std::path::{Path, PathBuf};

/// Rows whose trajectories are kept: these offsets...
pub const TRAJECTORY_OFFSETS: [f64; 4] = [0.0, 0.02, 0.04, 0.06];
/// ...at these frictions.
pub const TRAJECTORY_FRICTIONS: [f64; 2] = [0.5, f64::INFINITY];
/// Samples per trajectory.
pub const TRAJECTORY_SAMPLES: usize = 301;
/// Columns of a stored trajectory.
pub const TRAJECTORY_COLUMNS: [(&str, &str); 7] =
    [("time", "s"), ("x", "m"), ("y", "m"), ("z", "m"), ("velocity_x", "m/s"), ("velocity_y", "m/s"), ("velocity_z", "m/s")];

/// The file's name under `OUT/flight/`.
pub const FILE: &str = "free_kick.h5";

fn columns(list: &[(&str, &str)]) -> Vec<Column> {
    list.iter().map(|(n, u)| Column::new(n, u)).collect()
}

/// Solve the grid and write `out/flight/free_kick.h5`.
pub fn write(out: &Path) -> Result<PathBuf, StoreError> {
    let dir = out.join("flight");
    std::fs::create_dir_all(&dir).map_err(|source| StoreError::CreateDir { path: dir.clone(), source })?;
    let path = dir.join(FILE);
    let text = format!(
        "kick_study::free_kick: offsets {OFFSETS:?} m x friction {FRICTIONS:?}, contact_depth {CONTACT_DEPTH} m (the foot's line \
         below the centre), Table 1 foot, horizontal path; flights to x = {GOAL_DISTANCE} m and {WALL_DISTANCE} m"
    );
    let provenance = Provenance::now("free_kick", "kick_study::free_kick", &text);
    let rows = grid();
    let mut writer = create_table(&FreeKicks, &path, &provenance, rows.len() as u64, Default::default())?;
    let file = writer.file().clone();
    let parameters = FreeKicks.parameter_columns();
    write_str_attr(&file, &path, "description", "Free kicks: the 3D kick (contact below and beside the centre) chained into the flight")?;
    write_grid(&file, &path, &[(parameters[0].clone(), &OFFSETS[..]), (parameters[1].clone(), &FRICTIONS[..])])?;
    fill_table(&FreeKicks, 0..rows.len() as u64, &mut writer, &indicatif::ProgressBar::hidden())?;
    for (row, &(e, mu)) in rows.iter().enumerate() {
        let keep = TRAJECTORY_OFFSETS.contains(&e) && TRAJECTORY_FRICTIONS.iter().any(|m| m.to_bits() == mu.to_bits());
        if keep {
            let values = trajectory(e, mu, TRAJECTORY_SAMPLES).map_err(StudyError::from)?;
            let named: Vec<(Column, &[f64])> = columns(&TRAJECTORY_COLUMNS).into_iter().zip(values.iter().map(Vec::as_slice)).collect();
            writer.write_history(1, row, &named)?;
        }
    }
    Ok(writer.finish()?)
}
