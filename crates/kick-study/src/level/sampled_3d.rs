//! Random off-center kicks (`kick sweep3d`) as a [`Level`]: kick `i` of seed
//! `s` drawn from (s, i) alone, every declared parameter the kick's law uses
//! stored in its row (vectors as `_x`, `_y`, `_z` columns, switches 0/1),
//! solved by `auto`, outcome columns kick-3d's [`OBSERVABLES_3D`], and with
//! a flight plan each kick flown from the ground after it.
//!
//! What is drawn ([`crate::sample`]): `offset`, `approach_angle`, `friction`
//! and `foot_mass` from the off-center box (`kick_3d::models::OffCenterBox`,
//! where the accurate path states its speed and accuracy), the other 1D
//! parameters from their declared ranges on the stream they always came
//! from, every other parameter with a declared range (the tangential
//! spring's, the shell ball's pressure under law `shell`) from a stream of
//! its own; `--range NAME=LOW,HIGH` (any scalar parameter of the kick, or
//! of the flight with `--flight`) draws that one from its own stream
//! instead, and a parameter given is held.

use super::{Failure, Level, Row};
use crate::columns::{Column, OutcomeSet, Setting};
use crate::flight::FlightPlan;
use crate::sample::{draw_own, Ranges};
use crate::StudyError;
use kick_3d::models::{OffCenterBox, BOX_RANGES};
use kick_3d::{Kick3d, KickSpec, Solver3d, OBSERVABLES_3D};
use kick_core::parameters::{self, Level as ParameterLevel, ParameterDef, SetParameter, Shape, Value};
use kick_core::{LawKind, Parameter};
use kick_flight::{FlightParameter, FlightSpec};
use rand::RngExt;

/// Seed stream of the 1D draws, apart from the box's (which uses the seed itself).
const SCENARIO_STREAM: u64 = 0x5EED_3D00_0000_0001;

/// The box's parameters, in the order [`OffCenterBox::values`] gives them.
const BOX: [&str; 4] = ["offset", "approach_angle", "friction", "foot_mass"];

/// The random kicks of one seed.
#[derive(Debug, Clone, PartialEq)]
pub struct SampledKicks {
    pub seed: u64,
    /// Given parameters (held), and the law of every kick.
    pub fixed: KickSpec,
    /// Ranges given instead of the box's and the declared ones (`--range`).
    pub ranges: Ranges,
}

impl SampledKicks {
    pub fn new(seed: u64, fixed: KickSpec) -> SampledKicks {
        SampledKicks { seed, fixed, ranges: Ranges::default() }
    }

    fn law(&self) -> LawKind {
        self.fixed.scenario.law.unwrap_or(LawKind::PowerLaw)
    }

    /// The parameters of a row, in declaration order: every one of the
    /// kick's levels the law uses; the instep's only when one of them is
    /// held or ranged (without, the kick has no instep). The foot (leg,
    /// pose, boot) is held, recorded with the outcomes' settings.
    pub fn row_parameters(&self) -> Vec<&'static ParameterDef> {
        let law = self.law();
        let instep = parameters::at_level(ParameterLevel::Instep).any(|p| self.fixed.value(p).is_some() || self.ranges.given(p).is_some());
        parameters::at_levels(KickSpec::LEVELS)
            .filter(|p| law.uses(p) && p.level != ParameterLevel::Foot && (p.level != ParameterLevel::Instep || instep))
            .collect()
    }

    /// The flight parameters drawn (`--range` of a flight parameter).
    pub fn flight_parameters(&self) -> Vec<&'static ParameterDef> {
        self.ranges.0.iter().map(|r| r.parameter).filter(|p| p.level == ParameterLevel::Flight).collect()
    }

    /// Refuse a range for a parameter held too, or one the law does not use.
    pub fn check(&self, flight: Option<&FlightPlan>) -> Result<(), StudyError> {
        for r in &self.ranges.0 {
            let p = r.parameter;
            let refuse = |why: String| Err(StudyError::Flag { flag: "range", message: format!("--range {}: {why}", p.name) });
            if p.level == ParameterLevel::Flight {
                let Some(plan) = flight else { return refuse(format!("`{}` is a flight parameter: add --flight", p.name)) };
                if FlightParameter::from_name(p.name).is_ok_and(|q| plan.rest.is_set(q)) {
                    return refuse(format!("`{}` is also held (flag {}); give one", p.name, p.flag()));
                }
                continue;
            }
            if !self.law().uses(p) {
                return refuse(format!("law `{}` does not use `{}`", self.law().name(), p.name));
            }
            if p.level == ParameterLevel::Foot {
                return refuse(format!("the foot (`{}`) is held in a sampled sweep; give it by its flag", p.name));
            }
            if self.fixed.value(p).is_some() {
                return refuse(format!("`{}` is also held (flag {}); give one", p.name, p.flag()));
            }
        }
        Ok(())
    }

    /// The spec of kick `index`: the given parameters, the rest drawn
    /// (module docs). Every parameter takes its draws whether held or not,
    /// so holding one leaves the others as they were.
    pub fn spec(&self, index: u64) -> KickSpec {
        let boxed = OffCenterBox::new(self.seed).values(index);
        let mut spec = self.fixed;
        let own = |p: &ParameterDef| self.ranges.given(p).map(|range| draw_own(self.seed, index, p, &range));
        let mut rng = crate::sample::row_rng(self.seed ^ SCENARIO_STREAM, index);
        let mut uniform = || rng.random::<f64>();
        for p in Parameter::ALL {
            let drawn = match p {
                Parameter::FootMass => boxed[3],
                _ => p.def().sample.map_or(f64::NAN, |range| range.draw(&mut uniform)),
            };
            // One the law ignores (the shell's k, c, n) stays unset: it is no
            // column, so it must not reach the solve (its step sizes) either.
            if spec.scenario.get(p).is_none() && self.law().uses(p.def()) {
                // A declared scalar of the 1D level: setting it cannot fail.
                let _ = spec.scenario.set_parameter(p.def(), Value::Number(own(p.def()).unwrap_or(drawn)));
            }
        }
        for (name, drawn) in BOX.iter().zip(boxed).take(3) {
            if let Some(p) = parameters::find(name) {
                if spec.value(p).is_none() {
                    let _ = spec.set_parameter(p, Value::Number(own(p).unwrap_or(drawn)));
                }
            }
        }
        // Every other parameter the law uses with a range, from its own stream.
        let law = self.law();
        for p in parameters::at_levels(KickSpec::LEVELS) {
            if BOX.contains(&p.name) || Parameter::from_name(p.name).is_some() || !law.uses(p) || p.shape != Shape::Scalar {
                continue;
            }
            if let (None, Some(range)) = (spec.value(p), self.ranges.of(p)) {
                let _ = spec.set_parameter(p, Value::Number(draw_own(self.seed, index, p, &range)));
            }
        }
        spec
    }

    /// The flight of kick `index` after `rest`: its ranged parameters drawn.
    pub fn flight_spec(&self, rest: &FlightSpec, index: u64) -> FlightSpec {
        let mut spec = *rest;
        for r in self.ranges.0.iter().filter(|r| r.parameter.level == ParameterLevel::Flight) {
            if let Ok(q) = FlightParameter::from_name(r.parameter.name) {
                let _ = spec.set(q, &[draw_own(self.seed, index, r.parameter, &r.range)]);
            }
        }
        spec
    }

    /// The ranges drawn from, one line each (for the file's provenance).
    pub fn describe_ranges(&self) -> String {
        let mut lines: Vec<String> = BOX_RANGES
            .lines()
            .filter(|l| {
                l.split_whitespace().next().is_some_and(|name| parameters::find(name).is_some_and(|p| self.ranges.given(p).is_none()))
            })
            .map(String::from)
            .collect();
        let law = self.law();
        for p in parameters::at_levels(KickSpec::LEVELS).chain(self.flight_parameters()) {
            if (BOX.contains(&p.name) && self.ranges.given(p).is_none()) || !law.uses(p) || p.shape != Shape::Scalar {
                continue;
            }
            if let Some(range) = self.ranges.of(p) {
                lines.push(format!("{:<20} {} {}", p.name, range.describe(), p.unit));
            }
        }
        lines.push("every other parameter held (at its default unless given)".into());
        lines.join("\n")
    }
}

/// The solver of every sampled kick: `auto` (the accurate path off the centre line).
pub const SOLVER: &str = "auto-3d";

/// Columns of `parameters`, a vector as three columns `NAME_x`, `NAME_y`, `NAME_z`.
pub fn columns_of(parameters: &[&'static ParameterDef]) -> Vec<Column> {
    let mut columns = Vec::new();
    for p in parameters {
        for name in p.columns() {
            columns.push(Column::new(&name, p.unit));
        }
    }
    columns
}

/// The random kicks of one seed, `samples` of them, each flown with `flight`.
#[derive(Debug, Clone, PartialEq)]
pub struct SampledSweep3d {
    pub kicks: SampledKicks,
    pub samples: u64,
    pub flight: Option<FlightPlan>,
    /// The row's parameters ([`SampledKicks::row_parameters`]) and drawn flight parameters, once.
    parameters: Vec<&'static ParameterDef>,
    flight_parameters: Vec<FlightParameter>,
}

impl SampledSweep3d {
    pub fn new(kicks: SampledKicks, samples: u64, flight: Option<FlightPlan>) -> SampledSweep3d {
        let parameters = kicks.row_parameters();
        let flight_parameters = kicks.flight_parameters().iter().filter_map(|p| FlightParameter::from_name(p.name).ok()).collect();
        SampledSweep3d { kicks, samples, flight, parameters, flight_parameters }
    }

    /// No allocation: it runs once per row.
    fn put_parameters(&self, spec: &KickSpec, kick: Option<&Kick3d>, flight: &FlightSpec, out: &mut [f64]) {
        let mut slot = 0;
        for p in &self.parameters {
            // The value given or drawn (a rerun from the file is the same
            // kick), else the built kick's default.
            let value = spec.value(p).or_else(|| kick.and_then(|k| k.parameter_value(p)));
            match (value, p.shape) {
                (Some(Value::Vector(v)), _) => out[slot..slot + 3].copy_from_slice(&v),
                (Some(Value::Number(x)), _) => out[slot] = x,
                (Some(Value::Switch(on)), _) => out[slot] = f64::from(u8::from(on)),
                (None, Shape::Vector3) => out[slot..slot + 3].fill(f64::NAN),
                (None, _) => out[slot] = f64::NAN,
            }
            slot += if p.shape == Shape::Vector3 { 3 } else { 1 };
        }
        for &q in &self.flight_parameters {
            out[slot] = flight.number(q).unwrap_or(f64::NAN);
            slot += 1;
        }
    }
}

impl Level for SampledSweep3d {
    fn rows(&self) -> u64 {
        self.samples
    }

    fn parameter_columns(&self) -> Vec<Column> {
        let mut list = self.parameters.clone();
        list.extend(self.flight_parameters.iter().map(|q| q.def()));
        columns_of(&list)
    }

    fn outcome_sets(&self) -> Vec<OutcomeSet> {
        let law = self.kicks.law();
        let mut settings = vec![("law".into(), Setting::Text(law.name().into()))];
        if let (LawKind::Shell, Ok(ball)) = (law, self.kicks.fixed.scenario.shell_ball()) {
            // The ball's parameters held (the drawn ones are columns).
            let held = crate::columns::ball_settings(kick_core::AnyLaw::Shell(ball));
            settings.extend(held.into_iter().filter(|(name, _)| parameters::find(name).is_some_and(|p| self.kicks.ranges.of(p).is_none())));
        }
        if let Ok(foot) = self.kicks.fixed.scenario.foot() {
            settings.extend(crate::columns::foot_settings(foot));
        }
        let kick = OutcomeSet { solver: SOLVER.into(), settings, columns: OBSERVABLES_3D.iter().map(|(n, u)| Column::new(n, u)).collect() };
        let mut sets = vec![kick];
        if let Some(plan) = &self.flight {
            let spec = FlightSpec { gravity: Some(kick_core::GRAVITY), ..plan.rest };
            let flown = kick_flight::Flight::from_launch([1.0, 0.0, 1.0], [0.0; 3], &spec).ok();
            sets.push(crate::flight::flight_set(SOLVER, plan, flown.as_ref()));
        }
        sets
    }

    fn solve_row(&self, index: u64, row: &mut Row) {
        let spec = self.kicks.spec(index);
        let kick = spec.build_drawn();
        let rest = self.flight.as_ref().map(|plan| self.kicks.flight_spec(&plan.rest, index)).unwrap_or_default();
        self.put_parameters(&spec, kick.as_ref().ok(), &rest, &mut row.parameters);
        let outcome = kick.and_then(|k| Solver3d::Auto.solve(&k).map(|o| (k, o)));
        let mut outside = None;
        match &outcome {
            Ok((k, o)) => {
                row.set(0, &o.observable_values());
                // Outside the law's validity: the numbers kept, flagged, and the flight's too.
                outside = k.check_validity(o).err().map(Failure::from);
                if let Some(flag) = &outside {
                    row.flag(0, flag.clone());
                }
            }
            Err(e) => row.fail(0, e.clone().into()),
        }
        if let Some(plan) = &self.flight {
            let mut values = [0.0; crate::flight::MAX_FLIGHT_VALUES];
            let flown = match &outcome {
                Ok((k, o)) => crate::flight::flight_after_3d(k, o, &rest).and_then(|f| plan.fly_into(&f, &mut values)),
                Err(e) => Err(Failure::refused(format!("no flight: the kick failed: {e}"))),
            };
            row.put(1, flown.map(|n| &values[..n]));
            if let Some(flag) = &outside {
                row.flag_after(1, flag);
            }
        }
    }

    fn parameters_into(&self, index: u64, parameters: &mut [f64]) -> bool {
        let spec = self.kicks.spec(index);
        let rest = self.flight.as_ref().map(|plan| self.kicks.flight_spec(&plan.rest, index)).unwrap_or_default();
        self.put_parameters(&spec, spec.build_drawn().as_ref().ok(), &rest, parameters);
        true
    }
}

/// Why a `--range NAME` of `kick sweep3d` names no parameter it samples
/// (the refusal [`crate::sample::Ranges::parse`] puts after `--range TEXT`).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum RangeNameError {
    /// No kick parameter (without `--flight`).
    #[error(transparent)]
    Unknown(parameters::ParameterError),
    /// With `--flight`: neither a kick parameter nor one the flight takes after the kick.
    #[error("{0}, nor a flight parameter the kick leaves")]
    NorFlight(parameters::ParameterError),
    /// A flight parameter, given without `--flight`.
    #[error("`{name}` is a parameter of the flight: add --flight to fly the kicks")]
    NeedsFlight { name: String },
}

/// The parameter a `--range` of `kick sweep3d` names: one of the kick's
/// (their levels), or with `--flight` one the flight after it takes.
pub fn find_range(name: &str, flight: bool) -> Result<&'static parameters::ParameterDef, RangeNameError> {
    let kick = parameters::find_at(KickSpec::LEVELS, name);
    match (kick, flight) {
        (Ok(p), _) => Ok(p),
        (Err(e), true) => kick_flight::FlightParameter::from_name(name)
            .ok()
            .filter(|&q| !crate::flight::After::Kick3d.sets(q))
            .map(|q| q.def())
            .ok_or(RangeNameError::NorFlight(e)),
        (Err(_), false) if kick_flight::FlightParameter::from_name(name).is_ok() => {
            Err(RangeNameError::NeedsFlight { name: name.to_string() })
        }
        (Err(e), false) => Err(RangeNameError::Unknown(e)),
    }
}

#[cfg(test)]
mod range_name_tests {
    use super::*;

    /// A `--range` name that is no kick parameter says which flag is
    /// missing or that it is none at all, naming what the user gave.
    #[test]
    fn a_range_name_refused_names_the_parameter() {
        assert_eq!(find_range("contact_depth", false).unwrap().name, "contact_depth");
        let e = find_range("air_density", false).unwrap_err();
        assert_eq!(e, RangeNameError::NeedsFlight { name: "air_density".into() });
        assert_eq!(e.to_string(), "`air_density` is a parameter of the flight: add --flight to fly the kicks");
        assert_eq!(find_range("air_density", true).unwrap().name, "air_density");
        let e = find_range("stifness", true).unwrap_err();
        assert!(matches!(e, RangeNameError::NorFlight(_)), "{e:?}");
        assert!(e.to_string().contains("stifness") && e.to_string().ends_with(", nor a flight parameter the kick leaves"), "{e}");
        // Through the flag's parser: the flag and the text given lead.
        let e = crate::sample::Ranges::parse(&["air_density=1,2".into()], |n| find_range(n, false)).unwrap_err();
        assert!(matches!(e, crate::error::StudyError::Flag { flag: "range", .. }), "{e:?}");
        assert!(e.to_string().starts_with("--range air_density=1,2: `air_density` is a parameter of the flight"), "{e}");
    }
}
