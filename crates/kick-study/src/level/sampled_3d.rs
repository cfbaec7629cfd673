//! Random off-center kicks (`kick sweep3d`) as a [`Level`]: kick `i` of seed
//! `s` drawn from (s, i) alone, every declared 1D and 3D parameter stored in
//! its row (vectors as `_x`, `_y`, `_z` columns, switches 0/1), solved by
//! `auto`, outcome columns kick-3d's [`OBSERVABLES_3D`].

use super::{Level, Row};
use crate::columns::{Column, OutcomeSet, Setting};
use kick_3d::models::{OffCenterBox, BOX_RANGES};
use kick_3d::{Kick3d, KickSpec, Solver3d, OBSERVABLES_3D};
use kick_core::parameters::{self, ParameterDef, SetParameter, Shape, Value};
use kick_core::Parameter;
use rand::RngExt;

/// Seed stream of the 1D draws, apart from the box's (which uses the seed itself).
const SCENARIO_STREAM: u64 = 0x5EED_3D00_0000_0001;

/// The random kicks of one seed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SampledKicks {
    pub seed: u64,
    /// Given parameters (held), and the law of every kick.
    pub fixed: KickSpec,
}

impl SampledKicks {
    /// The spec of kick `index`: the given parameters, the rest drawn. Every
    /// parameter takes its draws whether held or not, so holding one leaves
    /// the others as they were.
    pub fn spec(&self, index: u64) -> KickSpec {
        let [offset, approach, friction, foot_mass] = OffCenterBox::new(self.seed).values(index);
        let mut spec = self.fixed;
        let mut rng = crate::sample::row_rng(self.seed ^ SCENARIO_STREAM, index);
        let mut uniform = || rng.random::<f64>();
        for p in Parameter::ALL {
            let drawn = match p {
                Parameter::FootMass => foot_mass,
                _ => p.def().sample.map_or(f64::NAN, |range| range.draw(&mut uniform)),
            };
            if spec.scenario.get(p).is_none() {
                // A declared scalar of the 1D level: setting it cannot fail.
                let _ = spec.scenario.set_parameter(p.def(), Value::Number(drawn));
            }
        }
        let k = &mut spec.kick3d;
        k.offset = k.offset.or(Some(offset));
        k.approach_angle_deg = k.approach_angle_deg.or(Some(approach));
        k.friction = k.friction.or(Some(friction));
        spec
    }

    /// The ranges drawn from, one line each (for the file's provenance).
    pub fn ranges() -> String {
        let box_names = ["offset", "approach_angle", "friction", "foot_mass"];
        let mut lines: Vec<String> = BOX_RANGES.lines().map(String::from).collect();
        for p in Parameter::ALL.iter().map(|p| p.def()).filter(|d| !box_names.contains(&d.name)) {
            let range = p.sample.map_or_else(|| "not sampled".to_string(), |s| s.describe());
            lines.push(format!("{:<15} {range} {}", p.name, p.unit));
        }
        lines.push("every other parameter at its default".into());
        lines.join("\n")
    }
}

/// A declared parameter's value in a kick as solved: `[x, NaN, NaN]` for a
/// scalar, 0/1 for a switch. Read from the built kick, except where the kick
/// keeps a converted form (the approach angle in radians, the instep's inner
/// size), which come from the spec so a rerun from the file is the same kick.
pub fn solved_value(p: &ParameterDef, spec: &KickSpec, kick: Option<&Kick3d>) -> [f64; 3] {
    let one = |x: f64| [x, f64::NAN, f64::NAN];
    let nan = [f64::NAN; 3];
    if let Some(q) = Parameter::ALL.into_iter().find(|q| q.def().name == p.name) {
        return one(kick.map_or(spec.scenario.get(q).unwrap_or(f64::NAN), |k| k.base.get(q)));
    }
    let d = &spec.kick3d;
    let switch = |on: bool| one(f64::from(u8::from(on)));
    match (p.name, kick) {
        ("offset", _) => one(d.offset.unwrap_or(parameters::OFFSET.default_number())),
        ("approach_angle", _) => one(d.approach_angle_deg.unwrap_or(parameters::APPROACH_ANGLE.default_number())),
        ("friction", _) => one(d.friction.unwrap_or(Kick3d::DEFAULT_FRICTION)),
        ("foot_half_extents", _) => d.foot_half_extents.unwrap_or(kick_3d::FootShape::DEFAULT_HALF_EXTENTS),
        ("restitution", Some(k)) => one(k.base.restitution_target().unwrap_or(f64::NAN)),
        ("ball_radius", Some(k)) => one(k.ball_radius),
        ("ball_inertia", Some(k)) => one(k.ball_inertia),
        ("tangential_stiffness", Some(k)) => one(k.tangential_stiffness),
        ("foot_inertia", Some(k)) => k.foot_inertia,
        ("border_radius", Some(k)) => one(k.foot_shape.border_radius()),
        ("gravity", Some(k)) => switch(k.gravity),
        ("ground", Some(k)) => switch(k.ground),
        _ => nan,
    }
}

/// The solver of every sampled kick: `auto` (the accurate path off the centre line).
pub const SOLVER: &str = "auto-3d";

/// The parameter columns of a sampled kick: every declared 1D and 3D
/// parameter under its name, a vector as three columns `NAME_x`, `NAME_y`, `NAME_z`.
pub fn parameter_columns() -> Vec<Column> {
    let mut columns = Vec::new();
    for p in parameters::at_levels(KickSpec::ROW_LEVELS) {
        if p.shape == Shape::Vector3 {
            columns.extend(["x", "y", "z"].map(|axis| Column::new(&format!("{}_{axis}", p.name), p.unit)));
        } else {
            columns.push(Column::new(p.name, p.unit));
        }
    }
    columns
}

/// The random kicks of one seed, `samples` of them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SampledSweep3d {
    pub kicks: SampledKicks,
    pub samples: u64,
}

impl Level for SampledSweep3d {
    fn rows(&self) -> u64 {
        self.samples
    }

    fn parameter_columns(&self) -> Vec<Column> {
        parameter_columns()
    }

    fn outcome_sets(&self) -> Vec<OutcomeSet> {
        let law = self.kicks.fixed.scenario.law.unwrap_or(kick_core::LawKind::PowerLaw);
        let mut settings = vec![("law".into(), Setting::Text(law.name().into()))];
        if let (kick_core::LawKind::Shell, Ok(ball)) = (law, self.kicks.fixed.scenario.shell_ball()) {
            settings.extend(crate::columns::ball_settings(kick_core::AnyLaw::Shell(ball)));
        }
        vec![OutcomeSet { solver: SOLVER.into(), settings, columns: OBSERVABLES_3D.iter().map(|(n, u)| Column::new(n, u)).collect() }]
    }

    fn solve_row(&self, index: u64, row: &mut Row) {
        let spec = self.kicks.spec(index);
        let kick = spec.build_drawn();
        put_parameters(&spec, kick.as_ref().ok(), &mut row.parameters);
        match kick.and_then(|k| Solver3d::Auto.solve(&k)) {
            Ok(o) => row.set(0, &o.observable_values()),
            Err(e) => row.fail(0, e.into()),
        }
    }

    fn parameters_into(&self, index: u64, parameters: &mut [f64]) -> bool {
        let spec = self.kicks.spec(index);
        put_parameters(&spec, spec.build_drawn().as_ref().ok(), parameters);
        true
    }
}

/// The values of [`parameter_columns`] of a kick as solved ([`solved_value`]).
fn put_parameters(spec: &KickSpec, kick: Option<&Kick3d>, parameters: &mut [f64]) {
    let mut slot = 0;
    for p in parameters::at_levels(KickSpec::ROW_LEVELS) {
        let value = solved_value(p, spec, kick);
        let width = if p.shape == Shape::Vector3 { 3 } else { 1 };
        parameters[slot..slot + width].copy_from_slice(&value[..width]);
        slot += width;
    }
}
