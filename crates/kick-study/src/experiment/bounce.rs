//! Bounce experiments: the ball alone on the rigid plate (kick-bounce), in
//! the one experiment format (see the parent module).
//!
//! ```toml
//! level = "bounce"                 # required: the keys below are a bounce's
//! name = "ball_pressure"
//! description = "Restitution, contact time and compression against pressure"
//! law = "shell"                    # optional, `kick bounce --law` names (default shell)
//!
//! [base]                           # any declared bounce parameter (`kick bounce --help`)
//! shell_stiffness = 0.0
//!
//! [[sweep]]                        # grid axes: any scalar bounce parameter
//! parameter = "inflation_pressure"
//! linear = { from = 60795.0, to = 111457.5, count = 51 }
//! ```
//!
//! Every row is `kick bounce` with the base values and the row's axis values,
//! square or oblique as the values say. A value is refused at its line with
//! its key, alone against the base (a sweep value) and in every combination.

use super::{axis_values, experiment_name, Axis, ExperimentError, Grid, Locator, RawAxis};
use kick_bounce::{BounceSpec, LawChoice};
use kick_core::parameters::{Shape, Value};
use kick_core::short;
use serde::Deserialize;
use std::collections::BTreeMap;
use toml::Spanned;

/// Most rows one bounce grid may hold (a bounce is ~10 µs).
pub const MAX_CELLS_BOUNCE: u64 = 100_000_000;

/// The bounce part of an experiment: the base bounce and a grid of its
/// parameters (cell order: the last axis varies fastest).
#[derive(Debug, Clone, PartialEq)]
pub struct KicksBounce {
    /// The values every row starts from, and the law.
    pub spec: BounceSpec,
    /// Axes of scalar bounce parameters.
    pub grid: Grid,
}

impl KicksBounce {
    /// Every bounce parameter the grid does not sweep, as given or by its
    /// declared default (a vector as three numbers); one without either (a
    /// speed that a drop height gives) is left out.
    pub fn fixed(&self) -> Vec<(&'static kick_core::parameters::ParameterDef, Vec<f64>)> {
        use kick_core::parameters::DefaultValue;
        use kick_core::parameters::{DAMPING, EXPONENT, RESTITUTION, STIFFNESS};
        // The other kind of law's parameters do not act.
        let shell = self.spec.law.unwrap_or(LawChoice::Shell) == LawChoice::Shell;
        let acts = |name: &str| {
            let of_kick_laws = [&STIFFNESS, &DAMPING, &EXPONENT, &RESTITUTION].iter().any(|p| p.name == name);
            let of_shell = kick_core::shell::BALL_PARAMETERS.iter().any(|p| p.name == name);
            if shell {
                !of_kick_laws
            } else {
                !of_shell
            }
        };
        kick_bounce::BOUNCE_PARAMETERS
            .iter()
            .filter(|def| acts(def.name) && !self.grid.axes.iter().any(|a| a.parameter.name == def.name))
            .filter_map(|def| {
                let value = match (self.spec.given(def.name), def.default) {
                    (Some(v), _) => v.numbers(),
                    (None, DefaultValue::Number(x)) => vec![x],
                    (None, DefaultValue::Vector(v)) => v.to_vec(),
                    _ => return None,
                };
                Some((def, value))
            })
            .collect()
    }

    /// The bounce of cell `index`: the base with the cell's axis values.
    pub fn spec_at(&self, index: u64) -> BounceSpec {
        let mut spec = self.spec;
        self.grid.decode(index, |_, axis, value| {
            // A declared scalar of the bounce (checked when read).
            let _ = spec.set(axis.parameter.name, Value::Number(value));
        });
        spec
    }
}

/// The keys of a bounce file.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawBounce {
    #[allow(dead_code)]
    level: Spanned<String>,
    name: Option<Spanned<String>>,
    description: Option<String>,
    law: Option<Spanned<String>>,
    base: Option<BTreeMap<String, Spanned<toml::Value>>>,
    sweep: Option<Vec<RawAxis>>,
    compress: Option<Spanned<toml::Value>>,
}

/// A declared bounce value from TOML, by the parameter's shape.
fn value(shape: Shape, given: &toml::Value) -> Option<Value> {
    let number = |v: &toml::Value| v.as_float().or_else(|| v.as_integer().map(|i| i as f64));
    match shape {
        Shape::Scalar => number(given).map(Value::Number),
        Shape::Vector3 => {
            let a = given.as_array()?;
            let v: Vec<f64> = a.iter().map(number).collect::<Option<_>>()?;
            <[f64; 3]>::try_from(v).ok().map(Value::Vector)
        }
        Shape::Switch => given.as_bool().map(Value::Switch),
    }
}

/// A bounce experiment (the parent's `parse` found `level = "bounce"`):
/// its name, description, `compress` and kicks.
pub(super) fn parse(
    at: &Locator,
    text: &str,
    stem: String,
) -> Result<(String, String, Option<Spanned<toml::Value>>, KicksBounce), ExperimentError> {
    let raw: RawBounce = toml::from_str(text).map_err(|e| at.toml_error(&e))?;
    let name = experiment_name(at, raw.name.as_ref(), stem)?;
    let mut spec = BounceSpec::default();
    if let Some(law) = &raw.law {
        spec.law = Some(LawChoice::from_name(law.get_ref()).map_err(|e| at.error(law.span(), "law", e.to_string()))?);
    }
    let mut first = None;
    for (key, given) in raw.base.iter().flatten() {
        let dotted = format!("base.{key}");
        let parameter = kick_bounce::parameter(key).map_err(|e| at.error(given.span(), &dotted, e.to_string()))?;
        let v = value(parameter.shape, given.get_ref())
            .ok_or_else(|| at.error(given.span(), &dotted, format!("`{key}` takes {}", parameter.shape.describe())))?;
        spec.set(key, v).map_err(|e| at.error(given.span(), &dotted, e.to_string()))?;
        first.get_or_insert((given.span(), dotted));
    }
    // The base alone; a speed an axis gives stands in as 1 when the base
    // gives none (its values, and their clash with the base, are checked below).
    let swept = |name: &str| raw.sweep.iter().flatten().any(|a| a.parameter.get_ref() == name);
    let check = |spec: &BounceSpec| -> Result<(), kick_core::KickError> {
        let mut probe = *spec;
        let impact_given = spec.given("speed").is_some() || spec.given("drop_height").is_some();
        for axis in ["speed", "drop_height"] {
            if swept(axis) && !impact_given {
                let _ = probe.set(axis, Value::Number(1.0));
            }
        }
        probe.build().map(drop)
    };
    check(&spec).map_err(|e| {
        let blamed = match &e {
            kick_core::KickError::InvalidParameter { name, .. } | kick_core::KickError::DoesNotApply { given: name, .. } => Some(*name),
            _ => None,
        };
        let located = blamed.and_then(|n| raw.base.as_ref().and_then(|b| b.get(n)).map(|v| (v.span(), format!("base.{n}"))));
        let (span, key) = located.or(first.clone()).unwrap_or((0..0, "base".into()));
        at.error(span, &key, e.to_string())
    })?;

    let mut axes: Vec<Axis> = Vec::new();
    let mut total: u64 = 1;
    let mut last_span = 0..0;
    for axis in raw.sweep.iter().flatten() {
        let name = axis.parameter.get_ref();
        let key = format!("sweep.{name}");
        let parameter = kick_bounce::parameter(name).map_err(|e| at.error(axis.parameter.span(), &key, e.to_string()))?;
        if parameter.shape != Shape::Scalar {
            return Err(at.error(
                axis.parameter.span(),
                &key,
                format!("a sweep axis takes a number; `{name}` is {}", parameter.shape.describe()),
            ));
        }
        if axes.iter().any(|a| a.parameter.name == parameter.name) {
            return Err(at.error(axis.parameter.span(), &key, "parameter swept twice"));
        }
        if let Some(fixed) = raw.base.as_ref().and_then(|b| b.get(name)) {
            return Err(at.error(fixed.span(), &format!("base.{name}"), "this parameter is also swept; set it in one place"));
        }
        let (values, span, value_spans) = axis_values(at, axis, &key)?;
        total = total.saturating_mul(values.len() as u64);
        if total > MAX_CELLS_BOUNCE {
            return Err(at.error(span, &key, format!("the grid exceeds {MAX_CELLS_BOUNCE} bounces")));
        }
        for (i, &v) in values.iter().enumerate() {
            let value_span = value_spans.at(i);
            let mut one = spec;
            one.set(name, Value::Number(v)).map_err(|e| at.error(value_span.clone(), &key, e.to_string()))?;
            parameter.check(v).map_err(|e| at.error(value_span.clone(), &key, format!("value {}: {e}", short(v))))?;
        }
        axes.push(Axis { parameter, values });
        last_span = span;
    }
    let kicks = KicksBounce { spec, grid: Grid { axes } };
    // Every combination builds (a speed with a drop height, say, does not).
    for i in 0..kicks.grid.len() {
        if let Err(e) = kicks.spec_at(i).build() {
            let at_cell: Vec<String> = kicks
                .grid
                .axes
                .iter()
                .zip(kicks.grid.coordinates(i))
                .map(|(a, v)| format!("{} = {}", a.parameter.name, short(v)))
                .collect();
            return Err(at.error(last_span, "sweep", format!("grid point {i} ({}): {e}", at_cell.join(", "))));
        }
    }
    Ok((name, raw.description.unwrap_or_default(), raw.compress, kicks))
}

#[cfg(test)]
mod tests {
    use crate::experiment::{parse, Kicks};
    use kick_core::parameters::Value;
    use std::path::Path;

    /// A pressure sweep at two speeds: every cell is `kick bounce` with those
    /// values, the last axis varying fastest.
    #[test]
    fn cells_are_bounces_with_their_values() {
        let text = "level = \"bounce\"\n[base]\nshell_stiffness = 1000.0\n\
                    [[sweep]]\nparameter = \"speed\"\nvalues = [6.0, 19.2]\n\
                    [[sweep]]\nparameter = \"inflation_pressure\"\nlinear = { from = 6.0e4, to = 1.1e5, count = 3 }\n";
        let e = parse(Path::new("p.toml"), text).unwrap();
        let Kicks::Bounce(kicks) = &e.kicks else { panic!("{:?}", e.kicks) };
        assert_eq!((e.name.as_str(), kicks.grid.len()), ("p", 6));
        for (i, (v, p)) in [(6.0, 6.0e4), (6.0, 8.5e4), (6.0, 1.1e5), (19.2, 6.0e4), (19.2, 8.5e4), (19.2, 1.1e5)].into_iter().enumerate() {
            let mut spec = kick_bounce::BounceSpec::default();
            spec.set("shell_stiffness", Value::Number(1000.0)).unwrap();
            spec.set("speed", Value::Number(v)).unwrap();
            spec.set("inflation_pressure", Value::Number(p)).unwrap();
            assert_eq!(kicks.spec_at(i as u64).build().unwrap(), spec.build().unwrap(), "cell {i}");
        }
    }

    /// Malformed files are refused at the line and key of the problem.
    #[test]
    fn refusals_name_line_and_key() {
        let cases = [
            ("level = \"bounce\"\n[base]\nspeed = 5.0\npresure = 1.0\n", 4, "base.presure", "unknown parameter `presure`"),
            ("level = \"bounce\"\n[base]\nspeed = -5.0\n", 3, "base.speed", "(0, 1000]"),
            ("level = \"bounce\"\n[base]\nspeed = 5.0\nspin = 3.0\n", 4, "base.spin", "three numbers"),
            ("level = \"bounce\"\n[[sweep]]\nparameter = \"speed\"\nvalues = [5.0, -1.0]\n", 4, "sweep.speed", "value -1"),
            ("level = \"bounce\"\n[base]\nspeed = 5.0\n[[sweep]]\nparameter = \"spin\"\nvalues = [1.0]\n", 5, "sweep.spin", "a number"),
            ("level = \"bounce\"\n[base]\nspeed = 5.0\n[[sweep]]\nparameter = \"speed\"\nvalues = [1.0]\n", 3, "base.speed", "also swept"),
            ("level = \"bounce\"\nlaw = \"hertz\"\n", 2, "law", "unknown"),
            ("level = \"bounce\"\n[base]\nstiffness = 1e5\nspeed = 5.0\n", 3, "base.stiffness", "law"),
            (
                "level = \"bounce\"\n[base]\ndrop_height = 2.0\n[[sweep]]\nparameter = \"speed\"\nvalues = [3.0]\n",
                6,
                "sweep",
                "grid point 0 (speed = 3)",
            ),
            ("level = \"bounce\"\nsolver = \"accurate\"\n", 2, "solver", "unknown field"),
        ];
        for (text, line, key, needle) in cases {
            let e = parse(Path::new("b.toml"), text).unwrap_err();
            assert_eq!((e.line, e.key.as_str()), (line, key), "{text}\n{e}");
            assert!(e.to_string().contains(needle), "{text}\n{e}");
        }
    }
}
