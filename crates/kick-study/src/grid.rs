//! The one grid of the experiment files (1D and 3D): axes of declared
//! parameters (`kick_core::parameters`) and their values, and the one
//! grid-index decoder. Cell `index` of a grid is, for each axis, a position
//! in its values, in C order (the last axis varies fastest). How a cell's
//! values become a kick is the level's (a 1D [`kick_core::Scenario`], a 3D
//! [`kick_3d::Kick3d`]).

use crate::columns::Column;
use kick_core::parameters::ParameterDef;

/// One swept parameter and its values.
#[derive(Debug, Clone, PartialEq)]
pub struct Axis {
    pub parameter: &'static ParameterDef,
    pub values: Vec<f64>,
}

/// Every combination of the axes' values (one cell without axes).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Grid {
    pub axes: Vec<Axis>,
}

impl Grid {
    /// Number of cells (1 without axes).
    pub fn len(&self) -> u64 {
        self.axes.iter().map(|a| a.values.len() as u64).product()
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The grid's shape, one length per axis.
    pub fn shape(&self) -> Vec<usize> {
        self.axes.iter().map(|a| a.values.len()).collect()
    }

    /// The axes as columns (name and unit), in axis order.
    pub fn columns(&self) -> Vec<Column> {
        self.axes.iter().map(|a| Column::new(a.parameter.name, a.parameter.unit)).collect()
    }

    /// The axes' values at cell `index`, in axis order.
    pub fn coordinates(&self, index: u64) -> Vec<f64> {
        let mut out = vec![0.0; self.axes.len()];
        self.coordinates_into(index, &mut out);
        out
    }

    /// [`Self::coordinates`] into `out` (one slot per axis), allocating nothing.
    pub fn coordinates_into(&self, index: u64, out: &mut [f64]) {
        self.decode(index, |k, _, value| out[k] = value);
    }

    /// `rest` with the values of the flight's axes (declared at
    /// [`kick_core::Level::Flight`]) at cell `index`: the flight of that cell.
    pub fn flight_spec(&self, index: u64, rest: &kick_flight::FlightSpec) -> kick_flight::FlightSpec {
        let mut spec = *rest;
        self.decode(index, |_, axis, value| {
            let flight = axis.parameter.level == kick_core::Level::Flight;
            if let Some(q) = kick_flight::FlightParameter::from_name(axis.parameter.name).ok().filter(|_| flight) {
                // A scalar flight parameter (checked when the file was read): setting it cannot fail.
                let _ = spec.set(q, &[value]);
            }
        });
        spec
    }

    /// Call `visit(axis, value)` for every axis at cell `index`, first axis
    /// first (as the columns are ordered), allocating nothing.
    pub fn decode_forward(&self, index: u64, mut visit: impl FnMut(&Axis, f64)) {
        let mut rest = index;
        let mut positions = [0usize; 64];
        for (k, axis) in self.axes.iter().enumerate().rev() {
            let n = axis.values.len() as u64;
            if k < positions.len() {
                positions[k] = (rest % n) as usize;
            }
            rest /= n;
        }
        for (k, axis) in self.axes.iter().enumerate().take(positions.len()) {
            visit(axis, axis.values[positions[k]]);
        }
    }

    /// Whether an axis is the flight's.
    pub fn has_flight_axes(&self) -> bool {
        self.axes.iter().any(|a| a.parameter.level == kick_core::Level::Flight)
    }

    /// Call `visit(k, axis, value)` for every axis `k` at cell `index`, last
    /// axis first, allocating nothing (it runs once per row of a sweep).
    pub fn decode(&self, index: u64, mut visit: impl FnMut(usize, &Axis, f64)) {
        decode(self.axes.iter().map(|a| a.values.len()), index, |k, position| {
            let axis = &self.axes[k];
            visit(k, axis, axis.values[position])
        });
    }
}

/// Call `visit(axis, position)` for every axis of a grid of axes of these
/// `lengths` at cell `index`, last axis first. No allocation: it runs once
/// per row of a sweep.
pub fn decode(lengths: impl DoubleEndedIterator<Item = usize> + ExactSizeIterator, index: u64, mut visit: impl FnMut(usize, usize)) {
    let mut rest = index;
    for (axis, n) in lengths.enumerate().rev() {
        let n = n as u64;
        visit(axis, (rest % n) as usize);
        rest /= n;
    }
}

#[cfg(test)]
mod tests {
    use super::{decode, Axis, Grid};
    use kick_core::parameters;

    /// Every cell of a 2 x 3 x 4 grid once, in C order.
    #[test]
    fn cells_come_in_c_order() {
        let lengths = [2usize, 3, 4];
        let mut k = 0;
        for i in 0..2 {
            for j in 0..3 {
                for l in 0..4 {
                    let mut at = [usize::MAX; 3];
                    decode(lengths.iter().copied(), k, |axis, position| at[axis] = position);
                    assert_eq!(at, [i, j, l], "cell {k}");
                    k += 1;
                }
            }
        }
    }

    /// One grid of a 1D axis (stiffness), a 3D axis (offset) and a 1D axis
    /// (foot_speed): its length, shape and the coordinates of every cell
    /// against the mixed-radix decode done by hand, index = (i·3 + j)·4 + l.
    #[test]
    fn a_grid_of_1d_and_3d_axes_decodes_by_hand() {
        let stiffness = parameters::find("stiffness").unwrap();
        let offset = parameters::find("offset").unwrap();
        let foot_speed = parameters::find("foot_speed").unwrap();
        assert_eq!((stiffness.level, offset.level), (parameters::Level::Scenario, parameters::Level::Kick3d));
        let (a, b, c) = ([1e5, 1e6], [0.0, 0.01, 0.02], [10.0, 20.0, 30.0, 40.0]);
        let grid = Grid {
            axes: vec![
                Axis { parameter: stiffness, values: a.to_vec() },
                Axis { parameter: offset, values: b.to_vec() },
                Axis { parameter: foot_speed, values: c.to_vec() },
            ],
        };
        assert_eq!((grid.len(), grid.shape()), (24, vec![2, 3, 4]));
        let names: Vec<String> = grid.columns().into_iter().map(|c| c.name).collect();
        assert_eq!(names, ["stiffness", "offset", "foot_speed"]);
        for index in 0..24u64 {
            let (i, j, l) = ((index / 12) as usize, ((index / 4) % 3) as usize, (index % 4) as usize);
            assert_eq!(grid.coordinates(index), vec![a[i], b[j], c[l]], "cell {index}");
            let mut visited = Vec::new();
            grid.decode(index, |k, axis, value| visited.push((k, axis.parameter.name, value)));
            assert_eq!(visited, vec![(2, "foot_speed", c[l]), (1, "offset", b[j]), (0, "stiffness", a[i])], "cell {index}");
        }
        assert_eq!((Grid::default().len(), Grid::default().coordinates(0)), (1, vec![]));
    }
}
