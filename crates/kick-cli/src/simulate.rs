use crate::flags::Flags;
use crate::output::{json, CliResult, Format};
use kick_compliant::SolverChoice;
use kick_core::{Outcome, Parameter, RecordingSolver, Scenario, ScenarioSpec, Solver, OBSERVABLES};
use serde_json::{Map, Value};

#[derive(clap::Args, Debug)]
pub struct Args {
    /// The declared 1D parameters and --law; left out, Table 1's baseline and the paper's law.
    #[command(flatten)]
    scenario: Flags<ScenarioSpec>,
    /// Step of seed-rk4, s
    #[arg(long, default_value_t = 5e-6, allow_negative_numbers = true)]
    dt: f64,
    #[arg(long, default_value = "auto", value_parser = SolverChoice::NAMES)]
    solver: String,
    #[arg(long, value_enum, default_value_t = Format::Text)]
    format: Format,
    /// Also output the time history, sampled at most this far apart (s)
    #[arg(long)]
    history: Option<f64>,
}

/// The JSON object of one run: every observable, the energy residual, the
/// solver and the scenario.
pub fn outcome_json(scenario: &Scenario, solver: &str, outcome: &Outcome) -> Map<String, Value> {
    let mut object = Map::new();
    for ((name, _), value) in OBSERVABLES.iter().zip(outcome.observable_values()) {
        object.insert((*name).into(), value.into());
    }
    object.insert("energy_residual".into(), outcome.energy.residual().into());
    object.insert("solver".into(), solver.into());
    object.insert("method".into(), outcome.method.into());
    object.insert("stop".into(), serde_json::to_value(outcome.stop).unwrap_or(Value::Null));
    object.insert("evaluations".into(), outcome.evaluations.into());
    let mut parameters = Map::new();
    for p in Parameter::ALL {
        parameters.insert(p.name().into(), scenario.get(p).into());
    }
    object.insert("scenario".into(), Value::Object(parameters));
    object.insert("law".into(), serde_json::to_value(scenario.contact_law()).unwrap_or(Value::Null));
    object
}

pub fn run(args: Args) -> CliResult {
    let scenario = args.scenario.spec().build().map_err(|e| e.to_string())?;
    let solver = SolverChoice::from_name(&args.solver, args.dt).map_err(|e| e.to_string())?;
    let (outcome, history) = match args.history {
        Some(interval) => {
            let (o, h) = solver.solve_recorded(&scenario, interval).map_err(|e| e.to_string())?;
            (o, Some(h))
        }
        None => (solver.solve(&scenario).map_err(|e| e.to_string())?, None),
    };
    match args.format {
        Format::Json => {
            let mut object = outcome_json(&scenario, solver.name(), &outcome);
            if let Some(h) = &history {
                object.insert("history".into(), serde_json::to_value(&h.samples).map_err(|e| e.to_string())?);
            }
            println!("{}", json(&object)?);
        }
        Format::Text => {
            println!("solver: {} (path: {})", solver.name(), outcome.method);
            for ((name, unit), value) in OBSERVABLES.iter().zip(outcome.observable_values()) {
                println!("{name:<24} {value:>16.10e} {unit}");
            }
            println!("{:<24} {:>16.3e} J", "energy_residual", outcome.energy.residual());
            if let Some(h) = &history {
                println!("\ntime_s,foot_position_m,foot_velocity_m_s,ball_position_m,ball_velocity_m_s,compression_m,force_N,kinetic_J,elastic_J,dissipated_J,drive_work_J");
                for s in &h.samples {
                    println!(
                        "{},{},{},{},{},{},{},{},{},{},{}",
                        s.time, s.foot_position, s.foot_velocity, s.ball_position, s.ball_velocity,
                        s.compression, s.force, s.kinetic, s.elastic, s.dissipated, s.drive_work
                    );
                }
            }
        }
    }
    Ok(())
}
