//! The held spec of a `kick sweep3d` in its provenance text: every value
//! the sweep held, exactly, so that a merge ([`crate::shard`]) can redraw the
//! sweep's rows from the file alone.

use kick_3d::KickSpec;
use kick_core::parameters::{self, SetParameter};
use kick_study::flight::FlightPlan;
use kick_study::level::sampled_3d::{find_range, SampledKicks, SampledSweep3d};
use kick_study::sample::Ranges;
use std::fmt::Write as _;

/// The first line of the held parameters in a sweep's provenance text.
const HELD: &str = "# held:";

/// The held spec, every given value exactly (TOML, `#   name = value`
/// lines under [`HELD`]; the ranges as `[range]` `name = [low, high]`, the
/// flight as `[flight]` with its `distances`), so a merge can redraw the
/// sweep's rows; nothing (and no check at the merge) should it not serialize.
pub(crate) fn held_text(fixed: &KickSpec, ranges: &Ranges, flight: Option<&FlightPlan>) -> String {
    let table = || -> Option<String> {
        let mut table = toml::Table::try_from(fixed.scenario).ok()?;
        table.extend(toml::Table::try_from(fixed.kick3d).ok()?);
        if !ranges.0.is_empty() {
            let mut range = toml::Table::new();
            for r in &ranges.0 {
                range.insert(r.parameter.name.into(), toml::Value::Array(vec![r.range.from.into(), r.range.to.into()]));
            }
            table.insert("range".into(), toml::Value::Table(range));
        }
        if let Some(plan) = flight {
            let mut rest = toml::Table::try_from(plan.rest).ok()?;
            if let Some(planes) = &plan.planes {
                rest.insert("distances".into(), toml::Value::Array(planes.iter().map(|&d| d.into()).collect()));
            }
            table.insert("flight".into(), toml::Value::Table(rest));
        }
        toml::to_string(&table).ok()
    };
    let Some(lines) = table() else { return String::new() };
    let mut text = format!("{HELD}\n");
    for line in lines.lines().filter(|l| !l.is_empty()) {
        let _ = writeln!(text, "#   {line}");
    }
    text
}

/// The sampled sweep a part of `kick sweep3d` was cut from: its seed and
/// samples (root attributes) and the held spec of its provenance `text`;
/// None when the text has no held spec this version can read.
pub(crate) fn sampled_sweep(text: &str, seed: u64, samples: u64) -> Option<SampledSweep3d> {
    let held = text.split_once(&format!("\n{HELD}\n"))?.1;
    let lines: Vec<&str> = held.lines().map(|l| l.strip_prefix("#   ")).collect::<Option<_>>()?;
    let table: toml::Table = lines.join("\n").parse().ok()?;
    let mut fixed = KickSpec::default();
    let mut ranges = Vec::new();
    let mut flight = None;
    for (name, value) in table {
        let value = match value {
            toml::Value::String(law) if name == "law" => {
                fixed.scenario.law = Some(kick_core::LawKind::from_name(&law).ok()?);
                continue;
            }
            toml::Value::Table(given) if name == "range" => {
                for (p, bounds) in given {
                    let bounds: Vec<f64> = bounds.as_array()?.iter().map(|x| x.as_float()).collect::<Option<_>>()?;
                    ranges.push(format!("{p}={:?},{:?}", bounds.first()?, bounds.get(1)?));
                }
                continue;
            }
            toml::Value::Table(mut rest) if name == "flight" => {
                let planes: Option<Vec<f64>> =
                    rest.remove("distances").map(|d| d.as_array().map(|a| a.iter().filter_map(toml::Value::as_float).collect())).flatten();
                let rest: kick_flight::FlightSpec = toml::Value::Table(rest).try_into().ok()?;
                flight = Some(match planes {
                    Some(planes) => FlightPlan::planes(rest, planes).ok()?,
                    None => FlightPlan::new(rest),
                });
                continue;
            }
            toml::Value::Float(x) => parameters::Value::Number(x),
            toml::Value::Integer(x) => parameters::Value::Number(x as f64),
            toml::Value::Boolean(on) => parameters::Value::Switch(on),
            toml::Value::Array(xs) => {
                let xs: Vec<f64> = xs.iter().map(|x| x.as_float().or_else(|| x.as_integer().map(|i| i as f64))).collect::<Option<_>>()?;
                parameters::Value::Vector(xs.try_into().ok()?)
            }
            _ => return None,
        };
        fixed.set_named(&name, value).ok()?;
    }
    let ranges = Ranges::parse(&ranges, |name| find_range(name, flight.is_some())).ok()?;
    Some(SampledSweep3d::new(SampledKicks { seed, fixed, ranges }, samples, flight))
}
