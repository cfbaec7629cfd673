//! The `*_many` studies (Python's `simulate_many`, `simulate3d_many`,
//! `flight_many` and `bounce_many`): a model's rows over arrays of its
//! declared parameters, broadcast by numpy's rules ([`Broadcast`], a
//! [`Level`]), run by the one run loop ([`crate::level::run_rows_until`])
//! into column slices the caller owns ([`Slots`]). The front end parses
//! keywords into arrays, allocates the outputs and hears Ctrl-C; the rows,
//! their solves and the loop are here.

use crate::columns::{Column, OutcomeSet};
use crate::error::{Failure, StudyError};
use crate::level::{run_rows_until, Level, Row, RowSink, Stop};
use crate::limits::LimitError;
use kick_3d::{KickSpec, Outcome3d, Solver3d};
use kick_bounce::{BounceOutcome, BounceSpec, Tangential};
use kick_compliant::SolverChoice;
use kick_core::parameters::{ParameterDef, SetParameter, Shape, Value};
use kick_core::{ScenarioSpec, Solver, Status, OBSERVABLES};
use kick_flight::{FlightOutcome, FlightParameter, FlightSpec};
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};

/// Most axes an array may have: numpy 1's limit.
pub const MAX_AXES: usize = 32;

/// A model the rows are solved with: its output columns and one solve.
pub trait RowModel: Sync {
    type Spec: Clone + Send + Sync;
    /// Set a declared parameter; the front end checked its name and shape.
    fn set(&self, spec: &mut Self::Spec, parameter: &'static ParameterDef, value: Value);
    /// Output columns: name and trailing axes ([]: one number a row; [3]: a
    /// vector; [P] or [P, 3]: one per crossing plane).
    fn columns(&self) -> &[(String, Vec<usize>)];
    /// Solve one row into `row` (the columns' values, vectors expanded): the
    /// evaluations spent (and why the numbers lie outside their law's
    /// validity, if they do), or the failure.
    fn solve(&self, spec: &Self::Spec, row: &mut [f64]) -> Result<Solved, Failure>;
}

/// A row solved: its evaluations, and why its numbers lie outside their
/// contact law's validity, if they do (status 4, the numbers kept).
pub struct Solved {
    pub evaluations: u64,
    pub outside_validity: Option<String>,
    /// Why the flight after the kick was not flown (its `flight_status`
    /// says how): the row keeps the kick's status and numbers, and this
    /// message goes to `failure_message`.
    pub flight_failure: Option<String>,
}

impl Solved {
    pub fn new(evaluations: u64, outside_validity: Option<kick_core::OutsideValidity>) -> Solved {
        Solved { evaluations, outside_validity: outside_validity.map(|o| o.to_string()), flight_failure: None }
    }
}

/// The numbers a row of columns with these trailing axes takes.
pub fn width(axes: &[usize]) -> usize {
    axes.iter().product()
}

/// One parameter given as an array: C-ordered values and their shape (a
/// vector's with its trailing axis of 3).
pub struct Input<'a> {
    pub parameter: &'static ParameterDef,
    pub data: &'a [f64],
    pub shape: Vec<usize>,
}

/// An input read at a row index: per row axis, the step through its data
/// (0 along an axis it is broadcast over).
struct Strided<'a> {
    parameter: &'static ParameterDef,
    data: &'a [f64],
    strides: Vec<usize>,
}

impl Strided<'_> {
    fn value(&self, index: &[usize]) -> Value {
        let at: usize = index.iter().zip(&self.strides).map(|(i, s)| i * s).sum();
        match self.parameter.shape {
            Shape::Scalar => Value::Number(self.data[at]),
            Shape::Switch => Value::Switch(self.data[at] != 0.0),
            Shape::Vector3 => Value::Vector([self.data[3 * at], self.data[3 * at + 1], self.data[3 * at + 2]]),
        }
    }
}

/// The rows of a `*_many` call: `base` with the inputs' values at each row
/// of `shape` (C order), solved by `model`. Its one outcome set holds the
/// columns, vectors expanded, then the evaluations.
pub struct Broadcast<'a, M: RowModel> {
    model: &'a M,
    base: M::Spec,
    inputs: Vec<Strided<'a>>,
    shape: Vec<usize>,
    rows: u64,
    width: usize,
    /// Rows solved so far, when a progress bar shows them ([`Broadcast::counting`]).
    solved: Option<&'a AtomicU64>,
}

impl<'a, M: RowModel> Broadcast<'a, M> {
    /// The rows of `shape` (at most [`MAX_AXES`]); every input broadcasts to
    /// it by numpy's rules (shapes aligned at the right, each axis equal or
    /// 1) and holds as many values as its shape says, or the error names it.
    pub fn new(model: &'a M, base: M::Spec, inputs: Vec<Input<'a>>, shape: &[usize]) -> Result<Self, StudyError> {
        let refuse = |flag: &'static str, message: String| StudyError::Flag { flag, message };
        if shape.len() > MAX_AXES {
            return Err(refuse("shape", format!("the rows' shape has {} axes: at most {MAX_AXES}", shape.len())));
        }
        let rows = shape.iter().try_fold(1u64, |n, &k| n.checked_mul(k as u64));
        let rows = rows.ok_or_else(|| refuse("shape", format!("the rows' shape {shape:?} has more rows than a count holds")))?;
        let mut strided = Vec::with_capacity(inputs.len());
        for Input { parameter, data, shape: given } in inputs {
            let name = parameter.name;
            let mut own = given.clone();
            if parameter.shape == Shape::Vector3 && own.pop() != Some(3) {
                return Err(refuse(name, format!("`{name}` takes three numbers (x, y, z) on its last axis, got shape {given:?}")));
            }
            let fits = own.len() <= shape.len() && own.iter().rev().zip(shape.iter().rev()).all(|(&a, &b)| a == b || a == 1);
            if !fits {
                return Err(refuse(name, format!("`{name}` of shape {given:?} does not broadcast to the rows' shape {shape:?}")));
            }
            let values = width(&given);
            if data.len() != values {
                return Err(refuse(name, format!("`{name}` of shape {given:?} holds {} values, not {values}", data.len())));
            }
            // C-order steps of its own axes, in units of a row's value (a vector's three count as one).
            let offset = shape.len() - own.len();
            let mut strides = vec![0usize; shape.len()];
            let mut step = 1;
            for (axis, &n) in own.iter().enumerate().rev() {
                strides[offset + axis] = if n == 1 { 0 } else { step };
                step *= n;
            }
            strided.push(Strided { parameter, data, strides });
        }
        let width = model.columns().iter().map(|(_, axes)| width(axes)).sum();
        Ok(Broadcast { model, base, inputs: strided, shape: shape.to_vec(), rows, width, solved: None })
    }
}

impl<'a, M: RowModel> Broadcast<'a, M> {
    /// Count each row as it is solved into `solved` (a progress bar's count:
    /// the run loop's own count moves a chunk at a time, after it is pushed).
    pub fn counting(self, solved: &'a AtomicU64) -> Self {
        Broadcast { solved: Some(solved), ..self }
    }
}

/// Row `i` (C order) of `shape` as an index.
fn unravel(mut i: u64, shape: &[usize], index: &mut [usize]) {
    for (slot, &n) in index.iter_mut().zip(shape).rev() {
        *slot = (i % n as u64) as usize;
        i /= n as u64;
    }
}

impl<M: RowModel> Level for Broadcast<'_, M> {
    fn rows(&self) -> u64 {
        self.rows
    }
    /// None: the inputs are the caller's own arrays.
    fn parameter_columns(&self) -> Vec<Column> {
        Vec::new()
    }
    fn outcome_sets(&self) -> Vec<OutcomeSet> {
        let mut columns = Vec::with_capacity(self.width + 1);
        for (name, axes) in self.model.columns() {
            for k in 0..width(axes) {
                let name = if axes.is_empty() { name.clone() } else { format!("{name}_{k}") };
                columns.push(Column { name, unit: String::new() });
            }
        }
        columns.push(Column::new("evaluations", "1"));
        vec![OutcomeSet { solver: "many".into(), settings: Vec::new(), columns }]
    }
    fn solve_row(&self, index: u64, row: &mut Row) {
        let mut at = [0usize; MAX_AXES];
        let at = &mut at[..self.shape.len()];
        unravel(index, &self.shape, at);
        let mut spec = self.base.clone();
        for input in &self.inputs {
            self.model.set(&mut spec, input.parameter, input.value(at));
        }
        let out = &mut row.outcomes[0];
        match self.model.solve(&spec, &mut out[..self.width]) {
            Ok(Solved { evaluations, outside_validity, flight_failure }) => {
                out[self.width] = evaluations as f64;
                row.failures[0] = None;
                let flight = flight_failure.map(|m| format!("the flight after the kick: {m}"));
                match (outside_validity, flight) {
                    (Some(why), flight) => {
                        let message = flight.map_or(why.clone(), |f| format!("{why}; {f}"));
                        row.flag(0, Failure::new(Status::OutsideValidity, message));
                    }
                    // The kick stands (status 0); the flight's refusal is said.
                    (None, Some(f)) => row.flag(0, Failure::new(Status::Separated, f)),
                    (None, None) => {}
                }
            }
            Err(failure) => row.fail(0, failure),
        }
        if let Some(solved) = self.solved {
            solved.fetch_add(1, Ordering::Relaxed);
        }
    }
}

/// Where the rows go: per column its slice (vectors expanded, rows in C
/// order), the status codes and evaluations, and (row, message) of every
/// row that failed or lies outside its law's validity.
pub struct Slots<'a> {
    columns: Vec<&'a mut [f64]>,
    widths: Vec<usize>,
    status: &'a mut [u8],
    evaluations: &'a mut [u64],
    pub failures: Vec<(u64, String)>,
    next: usize,
}

impl<'a> Slots<'a> {
    /// Slices for every row of `model`'s columns; each as long as its rows times its width.
    pub fn new<M: RowModel>(model: &M, columns: Vec<&'a mut [f64]>, status: &'a mut [u8], evaluations: &'a mut [u64]) -> Slots<'a> {
        let widths = model.columns().iter().map(|(_, axes)| width(axes)).collect();
        Slots { columns, widths, status, evaluations, failures: Vec::new(), next: 0 }
    }
}

impl RowSink for Slots<'_> {
    type Error = std::convert::Infallible;
    fn push_row(&mut self, row: &Row) -> Result<(), Self::Error> {
        let j = self.next;
        let values = &row.outcomes[0];
        let mut at = 0;
        for (column, &w) in self.columns.iter_mut().zip(&self.widths) {
            column[j * w..(j + 1) * w].copy_from_slice(&values[at..at + w]);
            at += w;
        }
        let evaluations = values[at];
        self.evaluations[j] = if evaluations.is_finite() { evaluations as u64 } else { 0 };
        self.status[j] = row.status(0).code();
        if let Some(f) = &row.failures[0] {
            self.failures.push((j as u64, f.message.clone()));
        }
        self.next += 1;
        Ok(())
    }
}

/// Every row of `rows` into `slots`, on `threads` workers of a pool of its
/// own (rayon's global pool when None), until `cancel` is set.
pub fn run<M: RowModel>(rows: &Broadcast<M>, slots: &mut Slots, threads: Option<usize>, cancel: &AtomicBool) -> Result<Stop, StudyError> {
    let all = 0..rows.rows();
    let progress = |_| {};
    let stop = match threads {
        None => run_rows_until(rows, all, slots, &progress, cancel),
        Some(n) => {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(n)
                .build()
                .map_err(|e| LimitError::Threads { threads: n, message: e.to_string() })?;
            pool.install(|| run_rows_until(rows, all, slots, &progress, cancel))
        }
    };
    match stop {
        Ok(stop) => Ok(stop),
        Err(never) => match never {},
    }
}

/// `simulate_many`'s rows: a 1D scenario per row, its observables and energy residual.
pub struct Many1d {
    solver: SolverChoice,
    columns: Vec<(String, Vec<usize>)>,
}

impl Many1d {
    pub fn new(solver: SolverChoice) -> Many1d {
        let mut columns: Vec<(String, Vec<usize>)> = OBSERVABLES.iter().map(|(n, _)| (n.to_string(), vec![])).collect();
        columns.push(("energy_residual".into(), vec![]));
        Many1d { solver, columns }
    }
}

impl RowModel for Many1d {
    type Spec = ScenarioSpec;
    fn set(&self, spec: &mut ScenarioSpec, parameter: &'static ParameterDef, value: Value) {
        let _ = spec.set_parameter(parameter, value);
    }
    fn columns(&self) -> &[(String, Vec<usize>)] {
        &self.columns
    }
    fn solve(&self, spec: &ScenarioSpec, row: &mut [f64]) -> Result<Solved, Failure> {
        let scenario = spec.build()?;
        let outcome = self.solver.solve(&scenario)?;
        row[..OBSERVABLES.len()].copy_from_slice(&outcome.observable_values());
        row[OBSERVABLES.len()] = outcome.energy.residual();
        Ok(Solved::new(outcome.evaluations, scenario.check_validity(&outcome).err()))
    }
}

/// The 3D outcome's numbers as `simulate3d` names them: its serde fields,
/// vectors as width-3 columns, `energy.x` as `energy_x`, plus `energy_residual`.
fn flatten3d(outcome: &Outcome3d, out: &mut Vec<(String, Vec<f64>)>) {
    fn walk(prefix: &str, value: &serde_json::Value, out: &mut Vec<(String, Vec<f64>)>) {
        use serde_json::Value as J;
        match value {
            J::Number(n) => out.push((prefix.to_string(), vec![n.as_f64().unwrap_or(f64::NAN)])),
            J::Array(items) if items.iter().all(J::is_number) => {
                out.push((prefix.to_string(), items.iter().map(|x| x.as_f64().unwrap_or(f64::NAN)).collect()))
            }
            J::Object(map) => {
                for (k, v) in map {
                    let name = if prefix.is_empty() { k.clone() } else { format!("{prefix}_{k}") };
                    walk(&name, v, out);
                }
            }
            _ => {} // names (solver, law) are per call, not per row
        }
    }
    out.clear();
    walk("", &serde_json::to_value(outcome).unwrap_or_default(), out);
    out.push(("energy_residual".into(), vec![outcome.energy.residual()]));
}

/// The flight after each 3D kick of `simulate3d_many(flight=True)`: its
/// plan and whether `distance` was a list (a trailing plane axis).
pub struct Flown {
    pub plan: crate::flight::FlightPlan,
    pub planes: Option<usize>,
}

/// The flight's outputs after a kick, in [`kick_flight::plane_values`]'
/// order: the landing and apex, then the crossing columns (per plane with a
/// plane axis), and `flight_status` (the flight's status code: 0 flown,
/// 3 refused: a flight input refused, or a ball that does not leave the
/// ground; 1 a numerical failure), why in the row's `failure_message`.
fn flight_columns(planes: Option<usize>, single: bool) -> Vec<(String, Vec<usize>)> {
    let mut columns: Vec<(String, Vec<usize>)> = vec![
        ("flight_time".into(), vec![]),
        ("landing_point".into(), vec![2]),
        ("apex_height".into(), vec![]),
        ("apex_time".into(), vec![]),
        ("landing_velocity".into(), vec![3]),
        ("landing_spin".into(), vec![3]),
    ];
    let crossing = |axes: Vec<usize>, vector: Vec<usize>| -> Vec<(String, Vec<usize>)> {
        vec![
            ("crossed".into(), axes.clone()),
            ("crossing_time".into(), axes.clone()),
            ("crossing_height".into(), axes.clone()),
            ("crossing_lateral_offset".into(), axes),
            ("crossing_velocity".into(), vector),
        ]
    };
    match planes {
        Some(p) => columns.extend(crossing(vec![p], vec![p, 3])),
        None if single => columns.extend(crossing(vec![], vec![3])),
        None => {}
    }
    columns.push(("flight_status".into(), vec![]));
    columns
}

/// `simulate3d_many`'s rows: a 3D kick per row (and its flight, with `Flown`).
pub struct Many3d {
    solver: Solver3d,
    columns: Vec<(String, Vec<usize>)>,
    /// Numbers of the kick's own columns (before the flight's).
    kick_width: usize,
    /// For each of those numbers, its index in `Outcome3d::field_values`:
    /// a row is filled without building the serde tree `flatten3d` walks.
    picks: Vec<usize>,
    flight: Option<Flown>,
    /// Where each plane-by-plane crossing number goes (see [`regroup_planes`]).
    regroup: Option<Regroup>,
}

impl Many3d {
    pub fn new(solver: Solver3d, flight: Option<Flown>) -> Result<Many3d, StudyError> {
        // The columns of a solved kick (the baseline on the cheap 1D path).
        let baseline = kick_3d::one_d::solve(&kick_3d::Kick3d::baseline())?;
        let mut flat = Vec::new();
        flatten3d(&baseline, &mut flat);
        let mut columns: Vec<(String, Vec<usize>)> = flat
            .into_iter()
            .filter(|(n, _)| n != "evaluations")
            .map(|(n, v)| {
                let axes = if v.len() == 1 { vec![] } else { vec![v.len()] };
                (n, axes)
            })
            .collect();
        let kick_width = columns.iter().map(|(_, a)| width(a)).sum();
        let picks = field_picks(&columns)?;
        let regroup = flight.as_ref().and_then(|f| f.planes).map(Regroup::new);
        if let Some(f) = &flight {
            columns.extend(flight_columns(f.planes, f.plan.rest.distance.is_some()));
        }
        Ok(Many3d { solver, columns, kick_width, picks, flight, regroup })
    }

    /// Whether each kick is flown.
    pub fn flies(&self) -> bool {
        self.flight.is_some()
    }
}

impl RowModel for Many3d {
    type Spec = (KickSpec, FlightSpec);
    fn set(&self, spec: &mut Self::Spec, parameter: &'static ParameterDef, value: Value) {
        match FlightParameter::from_name(parameter.name) {
            Ok(q) if parameter.level == kick_core::Level::Flight => {
                let _ = match value {
                    Value::Number(x) => spec.1.set(q, &[x]),
                    Value::Vector(v) => spec.1.set(q, &v),
                    Value::Switch(_) => Ok(()),
                };
            }
            _ => {
                let _ = spec.0.set_parameter(parameter, value);
            }
        }
    }
    fn columns(&self) -> &[(String, Vec<usize>)] {
        &self.columns
    }
    fn solve(&self, spec: &Self::Spec, row: &mut [f64]) -> Result<Solved, Failure> {
        let failed = |e: kick_3d::Kick3dError| Failure::new(e.status(), e.to_string());
        let kick = spec.0.build().map_err(failed)?;
        let outcome = self.solver.solve(&kick).map_err(failed)?;
        let values = outcome.field_values();
        for (x, &i) in row.iter_mut().zip(&self.picks) {
            *x = values[i];
        }
        if let Some(f) = &self.flight {
            let out = &mut row[self.kick_width..];
            let plan = crate::flight::FlightPlan { rest: spec.1, planes: f.plan.planes.clone() };
            let flown = crate::flight::flight_after_3d(&kick, &outcome, &spec.1).and_then(|flight| plan.fly_into(&flight, out));
            let last = out.len() - 1;
            let mut flight_failure = None;
            match flown {
                Ok(_) => out[last] = 0.0,
                Err(failure) => {
                    out.fill(f64::NAN);
                    out[last] = f64::from(failure.status.code());
                    flight_failure = Some(failure.message);
                }
            }
            // `crossed` and the crossing's columns come plane by plane in
            // `plane_values`; the outputs want each quantity over the planes.
            if let Some(r) = &self.regroup {
                r.apply(&mut out[kick_flight::LANDING_COLUMNS..last]);
            }
            return Ok(Solved { flight_failure, ..Solved::new(outcome.evaluations, kick.check_validity(&outcome).err()) });
        }
        Ok(Solved::new(outcome.evaluations, kick.check_validity(&outcome).err()))
    }
}

/// Where each number of the kick's output columns is in
/// `Outcome3d::field_values` (by the field's name and width).
fn field_picks(columns: &[(String, Vec<usize>)]) -> Result<Vec<usize>, StudyError> {
    let mut picks = Vec::new();
    for (name, axes) in columns {
        let mut start = 0;
        let found = kick_3d::FIELDS_3D.iter().find_map(|&(field, w)| {
            start += w;
            (field == name && w == width(axes)).then_some(start - w..start)
        });
        picks.extend(found.ok_or_else(|| StudyError::Column { column: name.clone() })?);
    }
    Ok(picks)
}

/// `plane_values`' crossings (plane by plane, 7 numbers each) as the
/// outputs hold them: `crossed`, `crossing_time`, `crossing_height`,
/// `crossing_lateral_offset` each over the planes, then `crossing_velocity`
/// plane by plane (3 each). The permutation is worked out once per call
/// and applied in place, cycle by cycle, so a row allocates nothing.
struct Regroup {
    /// Output position i takes the input's `from[i]`.
    from: Vec<usize>,
    /// One position on each cycle of `from` longer than one.
    leaders: Vec<usize>,
}

impl Regroup {
    fn new(planes: usize) -> Regroup {
        let per = kick_flight::OUTCOME_COLUMNS.len() - kick_flight::LANDING_COLUMNS;
        let mut from = Vec::with_capacity(per * planes);
        for q in 0..4 {
            from.extend((0..planes).map(|k| k * per + q));
        }
        for k in 0..planes {
            from.extend((4..7).map(|q| k * per + q));
        }
        let mut seen = vec![false; from.len()];
        let mut leaders = Vec::new();
        for i in 0..from.len() {
            if seen[i] || from[i] == i {
                continue;
            }
            leaders.push(i);
            let mut j = i;
            while !seen[j] {
                seen[j] = true;
                j = from[j];
            }
        }
        Regroup { from, leaders }
    }

    fn apply(&self, values: &mut [f64]) {
        for &i in &self.leaders {
            let first = values[i];
            let mut j = i;
            while self.from[j] != i {
                values[j] = values[self.from[j]];
                j = self.from[j];
            }
            values[j] = first;
        }
    }
}

/// Writes an outcome's numbers of one column into its slots.
type Get = fn(&FlightOutcome, &mut [f64]);

/// Output columns of `flight_many`: name, width (vectors with a trailing
/// axis of 2 or 3) and the outcome's numbers.
const FLIGHT_COLUMNS: [(&str, usize, Get); 16] = [
    ("flight_time", 1, |o, x| x[0] = o.flight_time),
    ("landing_point", 2, |o, x| x.copy_from_slice(&o.landing_point)),
    ("apex_height", 1, |o, x| x[0] = o.apex_height),
    ("apex_time", 1, |o, x| x[0] = o.apex_time),
    ("landing_velocity", 3, |o, x| x.copy_from_slice(&o.landing_velocity)),
    ("landing_spin", 3, |o, x| x.copy_from_slice(&o.landing_spin)),
    ("crossed", 1, |o, x| x[0] = if o.crossing.is_some() { 1.0 } else { 0.0 }),
    ("crossing_time", 1, |o, x| x[0] = o.crossing.map_or(f64::NAN, |c| c.time)),
    ("crossing_height", 1, |o, x| x[0] = o.crossing.map_or(f64::NAN, |c| c.height)),
    ("crossing_lateral_offset", 1, |o, x| x[0] = o.crossing.map_or(f64::NAN, |c| c.lateral_offset)),
    ("crossing_velocity", 3, |o, x| x.copy_from_slice(&o.crossing.map_or([f64::NAN; 3], |c| c.velocity))),
    ("launch_reynolds", 1, |o, x| x[0] = o.launch.reynolds),
    ("launch_spin_parameter", 1, |o, x| x[0] = o.launch.spin_parameter),
    ("launch_drag_coefficient", 1, |o, x| x[0] = o.launch.drag_coefficient),
    ("launch_lift_coefficient", 1, |o, x| x[0] = o.launch.lift_coefficient),
    ("steps", 1, |o, x| x[0] = o.steps as f64),
];

/// Columns of a table of (name, width, …): vectors get a trailing axis.
fn named_columns<T>(table: &[(&str, usize, T)]) -> Vec<(String, Vec<usize>)> {
    table.iter().map(|(n, w, _)| (n.to_string(), if *w == 1 { vec![] } else { vec![*w] })).collect()
}

/// `flight_many`'s rows: a flight spec per row through `kick_flight::solve`.
pub struct ManyFlights {
    columns: Vec<(String, Vec<usize>)>,
}

impl Default for ManyFlights {
    fn default() -> Self {
        ManyFlights { columns: named_columns(&FLIGHT_COLUMNS) }
    }
}

impl RowModel for ManyFlights {
    type Spec = FlightSpec;
    fn set(&self, spec: &mut FlightSpec, parameter: &'static ParameterDef, value: Value) {
        // A declared flight parameter of the shape its input was checked for: cannot fail.
        if let Ok(p) = FlightParameter::from_name(parameter.name) {
            let _ = spec.set(p, &value.numbers());
        }
    }
    fn columns(&self) -> &[(String, Vec<usize>)] {
        &self.columns
    }
    fn solve(&self, spec: &FlightSpec, row: &mut [f64]) -> Result<Solved, Failure> {
        let failed = |e: kick_flight::FlightError| Failure::new(e.status(), e.to_string());
        let o = kick_flight::solve(&spec.build().map_err(failed)?).map_err(failed)?;
        let mut at = 0;
        for (_, width, get) in &FLIGHT_COLUMNS {
            get(&o, &mut row[at..at + width]);
            at += width;
        }
        Ok(Solved::new(o.evaluations, None))
    }
}

/// Output columns of `bounce_many`: (name, width, unit).
pub const BOUNCE_COLUMNS: [(&str, usize, &str); 12] = [
    ("restitution", 1, "1"),
    ("contact_time", 1, "s"),
    ("peak_force", 1, "N"),
    ("peak_force_time", 1, "s"),
    ("max_compression", 1, "m"),
    ("max_compression_time", 1, "s"),
    ("normal_impulse", 1, "N s"),
    ("impact_velocity", 3, "m/s"),
    ("exit_velocity", 3, "m/s"),
    ("exit_spin", 3, "rad/s"),
    ("tangential", 1, "0 no slip, 1 grips, 2 slides"),
    ("rebound_height", 1, "m (NaN without drop_height)"),
];

/// The numbers of one outcome in [`BOUNCE_COLUMNS`] order.
fn bounce_values(o: &BounceOutcome, row: &mut [f64]) {
    let mut at = 0;
    let mut put = |values: &[f64]| {
        row[at..at + values.len()].copy_from_slice(values);
        at += values.len();
    };
    put(&[o.restitution, o.contact_time, o.peak_force, o.peak_force_time, o.max_compression, o.max_compression_time, o.normal_impulse]);
    put(&o.impact_velocity);
    put(&o.exit_velocity);
    put(&o.exit_spin);
    put(&[match o.tangential {
        Tangential::NoSlip => 0.0,
        Tangential::Grips => 1.0,
        Tangential::Slides => 2.0,
    }]);
    put(&[o.rebound_height.unwrap_or(f64::NAN)]);
}

/// `bounce_many`'s rows: a spec per row through `kick_bounce::run`.
pub struct ManyBounces {
    columns: Vec<(String, Vec<usize>)>,
}

impl Default for ManyBounces {
    fn default() -> Self {
        ManyBounces { columns: named_columns(&BOUNCE_COLUMNS) }
    }
}

impl RowModel for ManyBounces {
    type Spec = BounceSpec;
    fn set(&self, spec: &mut BounceSpec, parameter: &'static ParameterDef, value: Value) {
        let _ = spec.set(parameter.name, value);
    }
    fn columns(&self) -> &[(String, Vec<usize>)] {
        &self.columns
    }
    fn solve(&self, spec: &BounceSpec, row: &mut [f64]) -> Result<Solved, Failure> {
        let o = kick_bounce::run(spec)?;
        bounce_values(&o, row);
        Ok(Solved::new(o.evaluations, o.outside_validity))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use kick_core::parameters::find_at;

    fn def(name: &str) -> &'static ParameterDef {
        find_at(ScenarioSpec::LEVELS, name).unwrap()
    }

    /// numpy's broadcast of a (3, 1) and a (2,) input: six rows, each the
    /// solve of its own scenario, bit for bit as one `solve` of that spec.
    #[test]
    fn broadcast_rows_are_the_solves_of_their_own_specs() {
        let model = Many1d::new(SolverChoice::from_name("auto", 1e-6).unwrap());
        let speeds = [10.0, 20.0, 30.0];
        let masses = [2.0, 3.0];
        let inputs = vec![
            Input { parameter: def("foot_speed"), data: &speeds, shape: vec![3, 1] },
            Input { parameter: def("foot_mass"), data: &masses, shape: vec![2] },
        ];
        let rows = Broadcast::new(&model, ScenarioSpec::default(), inputs, &[3, 2]).unwrap();
        assert_eq!(rows.rows(), 6);
        let n = model.columns().len();
        let mut columns: Vec<Vec<f64>> = vec![vec![0.0; 6]; n];
        let (mut status, mut evaluations) = (vec![9u8; 6], vec![0u64; 6]);
        let mut slots = Slots::new(&model, columns.iter_mut().map(|c| c.as_mut_slice()).collect(), &mut status, &mut evaluations);
        let solved = AtomicU64::new(0);
        let rows = rows.counting(&solved);
        let stop = run(&rows, &mut slots, Some(2), &AtomicBool::new(false)).unwrap();
        assert_eq!(solved.load(Ordering::Relaxed), 6);
        assert_eq!(stop, Stop::Finished);
        assert!(slots.failures.is_empty());
        for (i, &v) in speeds.iter().enumerate() {
            for (j, &m) in masses.iter().enumerate() {
                let mut spec = ScenarioSpec::default();
                spec.set_parameter(def("foot_speed"), Value::Number(v)).unwrap();
                spec.set_parameter(def("foot_mass"), Value::Number(m)).unwrap();
                let mut expected = vec![0.0; n];
                let solved = model.solve(&spec, &mut expected).unwrap();
                let r = 2 * i + j;
                for (k, column) in columns.iter().enumerate() {
                    assert_eq!(column[r].to_bits(), expected[k].to_bits(), "row {r} column {}", model.columns()[k].0);
                }
                assert_eq!(evaluations[r], solved.evaluations);
                assert_eq!(status[r], 0);
            }
        }
    }

    /// A row that fails gets its status, NaN numbers and its message; the others solve.
    #[test]
    fn a_failed_row_gets_its_status_and_message() {
        let model = Many1d::new(SolverChoice::from_name("auto", 1e-6).unwrap());
        let speeds = [10.0, -5.0];
        let inputs = vec![Input { parameter: def("foot_speed"), data: &speeds, shape: vec![2] }];
        let rows = Broadcast::new(&model, ScenarioSpec::default(), inputs, &[2]).unwrap();
        let mut columns: Vec<Vec<f64>> = vec![vec![0.0; 2]; model.columns().len()];
        let (mut status, mut evaluations) = (vec![9u8; 2], vec![7u64; 2]);
        let mut slots = Slots::new(&model, columns.iter_mut().map(|c| c.as_mut_slice()).collect(), &mut status, &mut evaluations);
        run(&rows, &mut slots, None, &AtomicBool::new(false)).unwrap();
        assert_eq!(slots.failures.len(), 1);
        assert_eq!(slots.failures[0].0, 1);
        assert!(slots.failures[0].1.contains("-5 m/s"), "{}", slots.failures[0].1);
        assert_eq!((status[0], status[1]), (0, Status::Refused.code()));
        assert!(columns.iter().all(|c| c[0].is_finite() && c[1].is_nan()));
        assert_eq!(evaluations[1], 0);
    }

    /// A 3D row, filled from the observables by index, holds the numbers of
    /// the outcome's serde fields (what `simulate3d_many` has always
    /// returned), bit for bit, for a square and an off-centre shell kick.
    #[test]
    fn a_3d_row_is_the_outcome_s_fields() {
        let model = Many3d::new(Solver3d::Auto, None).unwrap();
        for offset in [0.0, 0.05] {
            let mut spec = (KickSpec::default(), FlightSpec::default());
            spec.0.set_parameter(find_at(KickSpec::LEVELS, "offset").unwrap(), Value::Number(offset)).unwrap();
            let mut row = vec![f64::NAN; model.kick_width];
            model.solve(&spec, &mut row).unwrap();
            let mut flat = Vec::new();
            flatten3d(&Solver3d::Auto.solve(&spec.0.build().unwrap()).unwrap(), &mut flat);
            let expected: Vec<f64> = flat.into_iter().filter(|(n, _)| n != "evaluations").flat_map(|(_, v)| v).collect();
            assert_eq!(expected.len(), row.len());
            for (k, (a, b)) in row.iter().zip(&expected).enumerate() {
                assert_eq!(a.to_bits(), b.to_bits(), "offset {offset}, number {k}");
            }
        }
    }

    /// The in-place regrouping of crossings equals a copy read plane by plane.
    #[test]
    fn crossings_regroup_in_place_as_by_a_copy() {
        let per = kick_flight::OUTCOME_COLUMNS.len() - kick_flight::LANDING_COLUMNS;
        assert_eq!(per, 7);
        for planes in [1, 2, 3, 5, 8] {
            let input: Vec<f64> = (0..per * planes).map(|i| i as f64).collect();
            let mut expected = Vec::new();
            for q in 0..4 {
                expected.extend((0..planes).map(|k| input[k * per + q]));
            }
            for k in 0..planes {
                expected.extend_from_slice(&input[k * per + 4..k * per + 7]);
            }
            let mut values = input.clone();
            Regroup::new(planes).apply(&mut values);
            assert_eq!(values, expected, "{planes} planes");
        }
    }

    /// A flight row holds the outcome's numbers in `FLIGHT_COLUMNS` order,
    /// NaN for a crossing the ball does not make.
    #[test]
    fn a_flight_row_holds_the_outcome() {
        let model = ManyFlights::default();
        let width: usize = FLIGHT_COLUMNS.iter().map(|c| c.1).sum();
        for distance in [10.0, 1.0e3] {
            let mut spec = FlightSpec::default();
            for (name, value) in [("speed", 25.0), ("launch_angle", 15.0), ("distance", distance)] {
                spec.set(FlightParameter::from_name(name).unwrap(), &[value]).unwrap();
            }
            let mut row = vec![0.0; width];
            model.solve(&spec, &mut row).unwrap();
            let o = kick_flight::solve(&spec.build().unwrap()).unwrap();
            let c = o.crossing;
            assert_eq!(c.is_some(), distance == 10.0);
            let mut expected = vec![o.flight_time, o.landing_point[0], o.landing_point[1], o.apex_height, o.apex_time];
            expected.extend(o.landing_velocity.iter().chain(&o.landing_spin));
            expected.push(if c.is_some() { 1.0 } else { 0.0 });
            expected.extend(c.map_or([f64::NAN; 3], |c| [c.time, c.height, c.lateral_offset]));
            expected.extend(c.map_or([f64::NAN; 3], |c| c.velocity));
            let l = o.launch;
            expected.extend([l.reynolds, l.spin_parameter, l.drag_coefficient, l.lift_coefficient, o.steps as f64]);
            let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
            assert_eq!(bits(&row), bits(&expected), "distance {distance}");
        }
    }

    /// Inputs that do not broadcast, and a vector without its axis of 3, are refused by name.
    #[test]
    fn inputs_that_do_not_broadcast_are_refused_by_name() {
        let model = Many1d::new(SolverChoice::from_name("auto", 1e-6).unwrap());
        let three = [1.0, 2.0, 3.0];
        let bad = vec![Input { parameter: def("foot_speed"), data: &three, shape: vec![3] }];
        let e = Broadcast::new(&model, ScenarioSpec::default(), bad, &[2]).err().unwrap();
        assert!(e.to_string().contains("`foot_speed` of shape [3] does not broadcast"), "{e}");
        let inertia = find_at(KickSpec::LEVELS, "foot_inertia").unwrap();
        assert_eq!(inertia.shape, Shape::Vector3);
        let short = vec![Input { parameter: inertia, data: &three[..2], shape: vec![2] }];
        let e = Broadcast::new(&model, ScenarioSpec::default(), short, &[]).err().unwrap();
        assert!(e.to_string().contains("`foot_inertia` takes three numbers"), "{e}");
    }
}
