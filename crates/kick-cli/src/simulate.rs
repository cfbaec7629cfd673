use crate::output::{json, CliResult, Format};
use kick_compliant::SolverChoice;
use kick_core::{LawKind, Outcome, Parameter, RecordingSolver, Scenario, ScenarioSpec, Solver, OBSERVABLES};
use serde_json::{Map, Value};
use std::io::Write;

/// The contact law as flags (`--law`, `--restitution`), shared by every
/// command that builds scenarios.
#[derive(clap::Args, Debug, Clone, Copy)]
pub struct LawArgs {
    /// Contact law: power-law (the paper's, Eq. 20), hunt-crossley, lankarani-nikravesh, flores, hunt-crossley-exact, kelvin-voigt
    #[arg(long, default_value = "power-law", value_parser = parse_law)]
    pub law: LawKind,
    /// Target restitution e of the laws other than the paper's (their damping follows from it)
    #[arg(long, allow_negative_numbers = true)]
    pub restitution: Option<f64>,
}

fn parse_law(name: &str) -> Result<LawKind, String> {
    LawKind::from_name(name).map_err(|e| e.to_string())
}

/// The eight parameters of Table 1 and the contact law as flags; left out,
/// each parameter takes the baseline and the law is the paper's.
#[derive(clap::Args, Debug)]
pub struct ScenarioArgs {
    /// Effective foot mass m_f, kg [3.0]
    #[arg(long, allow_negative_numbers = true)]
    pub foot_mass: Option<f64>,
    /// Ball mass m_b, kg [0.43]
    #[arg(long, allow_negative_numbers = true)]
    pub ball_mass: Option<f64>,
    /// Foot speed before contact v_f⁻, m/s [22]
    #[arg(long, allow_negative_numbers = true)]
    pub foot_speed: Option<f64>,
    /// Ball speed before contact v_b⁻ (along the foot's path in 3D), m/s [0]
    #[arg(long, allow_negative_numbers = true)]
    pub ball_speed: Option<f64>,
    /// Stiffness k, N/m^n [4.2e5]
    #[arg(long, allow_negative_numbers = true)]
    pub stiffness: Option<f64>,
    /// Damping c, N s/m [120]
    #[arg(long, allow_negative_numbers = true)]
    pub damping: Option<f64>,
    /// Exponent n [1.35]
    #[arg(long, allow_negative_numbers = true)]
    pub exponent: Option<f64>,
    /// Drive force on the foot along its velocity during contact, N [0]
    #[arg(long, allow_negative_numbers = true)]
    pub drive_force: Option<f64>,
    #[command(flatten)]
    pub law: LawArgs,
}

impl ScenarioArgs {
    /// The parameters and the law given.
    pub fn spec(&self) -> ScenarioSpec {
        ScenarioSpec {
            foot_mass: self.foot_mass,
            ball_mass: self.ball_mass,
            foot_speed: self.foot_speed,
            ball_speed: self.ball_speed,
            stiffness: self.stiffness,
            damping: self.damping,
            exponent: self.exponent,
            drive_force: self.drive_force,
            law: Some(self.law.law),
            restitution: self.law.restitution,
        }
    }
}

#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    scenario: ScenarioArgs,
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
            let object = outcome_json(&scenario, solver.name(), &outcome);
            match &history {
                None => println!("{}", json(&object)?),
                // Samples serialised as written: no JSON tree of the history (~2.5 kB a sample).
                Some(h) => {
                    #[derive(serde::Serialize)]
                    struct WithHistory<'a> {
                        #[serde(flatten)]
                        outcome: &'a Map<String, Value>,
                        history: &'a [kick_core::Sample],
                    }
                    let mut out = std::io::BufWriter::new(std::io::stdout().lock());
                    serde_json::to_writer_pretty(&mut out, &WithHistory { outcome: &object, history: &h.samples })
                        .map_err(std::io::Error::from)
                        .and_then(|()| writeln!(out))
                        .and_then(|()| out.flush())
                        .map_err(|e| format!("cannot write JSON: {e}"))?;
                }
            }
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
