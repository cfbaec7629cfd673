use crate::output::{json, CliResult, Format};
use crate::simulate::LawArgs;
use kick_core::{Parameter, Scenario};
use kick_identify::data::{Channel, FitSpec};
use kick_identify::fit::{fit, FitOptions, FitProblem, FitReport};
use kick_identify::profile::{identifiability_study, IdentifiabilityStudy};
use kick_identify::{synthetic, FitParameter, IdentifyError, ModelPoint};
use kick_runner::{Provenance, ResultWriter};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

#[derive(clap::Subcommand, Debug)]
pub enum FitCommand {
    /// Table 2: each row's changed parameter by least squares on the four printed
    /// observables (accurate solver); --write keeps writing the seed-rk4 scenario file.
    Table2 {
        #[arg(long, value_enum, default_value_t = Format::Text)]
        format: Format,
        /// Write the scenario file (TOML, seed-rk4 Brent roots) here
        #[arg(long)]
        write: Option<PathBuf>,
        /// Write the fits (HDF5) here, with the scenario file's values and the
        /// same fits to seed-rk4's unrounded outputs at those values
        #[arg(long)]
        out: Option<PathBuf>,
        /// The scenario file whose values --out compares with
        #[arg(long, default_value = "experiments/table2.toml")]
        scenarios: PathBuf,
    },
    /// Fit the parameters a specification file names to its data (TOML/JSON; see README).
    Data {
        /// Fit specification (TOML, or JSON)
        spec: PathBuf,
        #[arg(long, value_enum, default_value_t = Format::Text)]
        format: Format,
        /// Write the fit report (HDF5: estimates, uncertainties, correlations, residuals) here
        #[arg(long)]
        out: Option<PathBuf>,
    },
    /// Write a synthetic history (CSV) and a fit specification for it: Table 1's
    /// baseline (with the law given) plus seeded noise, to be fitted back with `kick fit data`.
    Synthesize {
        /// Directory for NAME.csv and NAME.toml
        #[arg(long, default_value = "results/identification")]
        out: PathBuf,
        /// File stem of the data and the specification
        #[arg(long, default_value = "synthetic")]
        name: String,
        #[arg(long, default_value_t = 1)]
        seed: u64,
        /// Samples over 1.2 contact times (from t = 0, whatever the time offset)
        #[arg(long, default_value_t = 80)]
        times: usize,
        #[command(flatten)]
        law: crate::simulate::LawArgs,
        /// Time of first touch in the data, s; when non-zero the specification also fits `time_offset`
        #[arg(long, default_value_t = 0.0, allow_negative_numbers = true)]
        time_offset: f64,
    },
    /// Identifiability (Section 17.8): misfit profiles of m_f, k, c, n from the exit
    /// speed alone and from noisy histories, and (k, c) misfit maps.
    Profile {
        #[arg(long, value_enum, default_value_t = Format::Text)]
        format: Format,
        /// Write identifiability.h5 and identifiability.png/svg (drawn from it) here
        #[arg(long)]
        out: Option<PathBuf>,
        /// Profile over [1/spread, spread] x the truth
        #[arg(long, default_value_t = 1.5)]
        spread: f64,
        #[arg(long, default_value_t = 9)]
        points: usize,
        /// Grid points per axis of the misfit maps
        #[arg(long, default_value_t = 21)]
        map_points: usize,
        #[arg(long, default_value_t = 5)]
        seed: u64,
    },
}

fn text(e: IdentifyError) -> String {
    e.to_string()
}

pub fn run(command: FitCommand) -> CliResult {
    match command {
        FitCommand::Table2 { format, write, out, scenarios } => table2(format, write, out, &scenarios),
        FitCommand::Data { spec, format, out } => data(spec, format, out),
        FitCommand::Synthesize { out, name, seed, times, law, time_offset } => {
            synthesize(&out, &name, seed, times, law, time_offset)
        }
        FitCommand::Profile { format, out, spread, points, map_points, seed } => {
            if !(3..=101).contains(&points) || !(3..=201).contains(&map_points) {
                return Err(format!("--points must be in 3..=101 and --map-points in 3..=201 (got {points}, {map_points})"));
            }
            let study = identifiability_study(
                &Scenario::baseline(),
                spread,
                points,
                map_points,
                80,
                seed,
                &FitOptions::default(),
            )
            .map_err(text)?;
            if let Some(dir) = out {
                std::fs::create_dir_all(&dir).map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
                let command = format!(
                    "kick fit profile --spread {spread} --points {points} --map-points {map_points} --seed {seed}"
                );
                let provenance = Provenance::now("identifiability", "kick fit profile (command line)", &command);
                let h5 = crate::identify_files::write_identifiability(&dir.join("identifiability.h5"), &provenance, &study)?;
                eprintln!("wrote {}", h5.display());
                for path in crate::identify_figures::identifiability(&h5, &dir)? {
                    eprintln!("wrote {}", path.display());
                }
            }
            match format {
                Format::Json => println!("{}", json(&study)?),
                Format::Text => print_study(&study),
            }
            Ok(())
        }
    }
}

/// Write `kick fit table2 --out`: the fits, the scenario file's values and
/// the same fits to seed-rk4's unrounded outputs at those values.
fn write_table2(path: &Path, scenarios: &Path, fits: &[kick_identify::table2::Table2Fit]) -> CliResult {
    let file = crate::table2::load(&scenarios.to_path_buf())?;
    let seed = kick_compliant::SeedRk4::new(file.dt).map_err(|e| e.to_string())?;
    let options = FitOptions::default();
    let mut file_values = Vec::new();
    let mut seed_fits = Vec::new();
    let mut observations = Vec::new();
    for (index, (row, (_, scenario))) in file.row.iter().zip(file.scenarios().map_err(|e| e.to_string())?).enumerate() {
        observations.push(kick_identify::table2::printed_observations(&kick_core::paper::TABLE2[index]));
        file_values.push(row.value);
        seed_fits.push(match row.parameter {
            None => None,
            Some(_) => {
                let outcome = kick_core::Solver::solve(&seed, &scenario).map_err(|e| e.to_string())?;
                let unrounded = kick_identify::table2::unrounded_observations(&outcome);
                kick_identify::table2::fit_row_to(index, unrounded, &options).map_err(text)?.value()
            }
        });
    }
    let text = std::fs::read_to_string(scenarios).map_err(|e| format!("{}: {e}", scenarios.display()))?;
    let provenance = Provenance::now("table2_fit", &scenarios.display().to_string(), &format!("# kick fit table2 --out
{text}"));
    let written = crate::identify_files::write_table2_fits(path, &provenance, fits, &observations, &file_values, &seed_fits)?;
    eprintln!("wrote {}", written.display());
    Ok(())
}

fn table2(format: Format, write: Option<PathBuf>, out: Option<PathBuf>, scenarios: &Path) -> CliResult {
    if let Some(path) = write {
        let file = kick_compliant::table2::fit().map_err(|e| e.to_string())?;
        let body = toml::to_string_pretty(&file).map_err(|e| e.to_string())?;
        let text = format!(
            "# Generated by `kick fit table2 --write {}`; do not edit.\n\
             # root: Brent root of seed-rk4's v_b+ on the printed value; value: the root\n\
             # rounded to the fewest significant digits that reproduce all five printed\n\
             # columns; residuals: seed-rk4 at value minus printed (m/s, 1, N, ms, mm).\n{body}",
            path.display()
        );
        kick_runner::output::write(&path, text).map_err(|e| e.to_string())?;
    }
    let fits = kick_identify::table2::fit_all(&FitOptions::default()).map_err(text)?;
    if let Some(path) = out {
        write_table2(&path, scenarios, &fits)?;
    }
    match format {
        Format::Json => println!("{}", json(&fits)?),
        Format::Text => {
            println!("Table 2 by least squares (accurate; v_b+, peak force, contact time, compression; σ = half the last printed digit)");
            for f in &fits {
                match (&f.report, &f.baseline_residuals) {
                    (Some(r), _) => {
                        let e = &r.estimates[0];
                        let weighted: Vec<String> = r.residuals.iter().map(|x| format!("{} {:+.2}", x.label, x.weighted)).collect();
                        println!(
                            "{:<24} {:<10} {:>14.6} ± {:<10} chi2 {:>7.2}  residuals/σ: {}",
                            f.name,
                            e.parameter.name(),
                            e.value,
                            e.standard_uncertainty.map(|s| format!("{s:.3e}")).unwrap_or_else(|| "-".into()),
                            r.chi_square,
                            weighted.join(", ")
                        );
                    }
                    (None, Some(res)) => {
                        let weighted: Vec<String> = res.iter().map(|(o, w)| format!("{} {w:+.2}", o.name())).collect();
                        println!("{:<24} {:<10} {:>14} {:<13} {:>12}  residuals/σ: {}", f.name, "-", "(Table 1)", "", "", weighted.join(", "));
                    }
                    _ => {}
                }
            }
        }
    }
    Ok(())
}

fn data(spec_path: PathBuf, format: Format, out: Option<PathBuf>) -> CliResult {
    let (spec, observations) = FitSpec::load(&spec_path).map_err(text)?;
    let name = spec_path.display().to_string();
    let start = spec.start(&name).map_err(text)?;
    let free = spec.free_parameters().map_err(text)?;
    let truth = spec.truth().map_err(text)?;
    let problem = FitProblem { start, free, observations };
    let report = fit(&problem, &FitOptions::default()).map_err(text)?;
    if let Some(path) = &out {
        let spec_text = std::fs::read_to_string(&spec_path).map_err(|e| format!("{name}: {e}"))?;
        let stem = path.file_stem().and_then(|s| s.to_str()).unwrap_or("fit");
        let provenance = Provenance::now(stem, &name, &spec_text);
        let w = ResultWriter::create(path, &provenance, "kick-fit-1").map_err(|e| e.to_string())?;
        crate::identify_files::write_fit(&w, "fit", &report, &problem.observations, &truth)?;
        eprintln!("wrote {}", w.finish().map_err(|e| e.to_string())?.display());
    }
    match format {
        Format::Json => println!("{}", json(&report)?),
        Format::Text => print_report(&report, &truth),
    }
    if report.converged {
        Ok(())
    } else {
        Err(format!("the fit stopped without converging: {}", report.termination))
    }
}

fn print_report(report: &FitReport, truth: &[(FitParameter, f64)]) {
    println!("contact law: {}", report.law.name());
    println!("{:<12} {:>16} {:>14} {:>16} {:>16}", "parameter", "estimate", "std. unc.", "start", "(est-truth)/σ");
    for e in &report.estimates {
        let pull = truth
            .iter()
            .find(|(p, _)| *p == e.parameter)
            .zip(e.standard_uncertainty)
            .map_or(String::new(), |((_, t), s)| format!("{:+.2}", (e.value - t) / s));
        println!(
            "{:<12} {:>16.8e} {:>14} {:>16.8e} {:>16}",
            e.parameter.name(),
            e.value,
            e.standard_uncertainty.map(|s| format!("{s:.3e}")).unwrap_or_else(|| "not identified".into()),
            e.start,
            pull
        );
    }
    println!(
        "chi2 {:.4} over {} residuals, {} degrees of freedom, s2 {}; {} ({} evaluations)",
        report.chi_square,
        report.residuals.len(),
        report.degrees_of_freedom,
        report.residual_variance.map(|s| format!("{s:.4}")).unwrap_or_else(|| "-".into()),
        report.termination,
        report.evaluations
    );
    if let Some(c) = &report.correlation {
        println!("correlation:");
        for row in c {
            println!("  {}", row.iter().map(|v| format!("{v:+.4}")).collect::<Vec<_>>().join(" "));
        }
    }
    let worst = report.residuals.iter().max_by(|a, b| a.weighted.abs().total_cmp(&b.weighted.abs()));
    if let Some(w) = worst {
        println!("largest residual: {} = {:+.3} σ", w.label, w.weighted);
    }
}

fn synthesize(out: &Path, name: &str, seed: u64, times: usize, law: LawArgs, time_offset: f64) -> CliResult {
    if !(2..=100_000).contains(&times) {
        return Err(format!("--times must be in 2..=100000 (got {times})"));
    }
    if name.is_empty() || name.contains(['/', '\\']) {
        return Err(format!("--name must be a plain file stem (got `{name}`)"));
    }
    let scenario = Scenario::baseline().with_law(law.law, law.restitution).map_err(|e| e.to_string())?;
    let truth = ModelPoint::new(scenario, time_offset).map_err(text)?;
    let options = FitOptions::default();
    let sigma = synthetic::lab_sigma(&Channel::ALL);
    let grid = synthetic::time_grid(&scenario, times, 1.2);
    let data = synthetic::history(&options.solver, &truth, grid, &sigma, seed).map_err(text)?;
    let history = data.history.ok_or("no history produced")?;
    std::fs::create_dir_all(out).map_err(|e| format!("cannot create {}: {e}", out.display()))?;
    let csv = out.join(format!("{name}.csv"));
    kick_runner::output::write(&csv, history.data.to_csv()).map_err(|e| e.to_string())?;
    let toml_path = out.join(format!("{name}.toml"));
    let spec = synthetic_spec(&truth, &format!("{name}.csv"), &sigma, seed, &toml_path);
    kick_runner::output::write(&toml_path, spec).map_err(|e| e.to_string())?;
    println!("wrote {} and {}", csv.display(), toml_path.display());
    Ok(())
}

/// Starting guesses of a synthetic fit, as factors of the truth: far enough
/// that the fit has to travel, near enough to stay in the basin.
const SYNTHETIC_START: [(Parameter, f64); 4] =
    [(Parameter::FootMass, 1.2), (Parameter::Stiffness, 0.714), (Parameter::Damping, 1.333), (Parameter::Exponent, 0.926)];

/// The fit specification of synthetic data: the law's fittable parameters
/// among m_f, k, c, n (and e, t0), started away from the truth.
fn synthetic_spec(truth: &ModelPoint, csv: &str, sigma: &BTreeMap<Channel, f64>, seed: u64, path: &Path) -> String {
    let mut free = Vec::new();
    let mut guesses = Vec::new();
    let mut truths = Vec::new();
    for (p, factor) in SYNTHETIC_START {
        if truth.check_fittable(p.into(), true).is_ok() {
            free.push(format!("\"{}\"", p.name()));
            guesses.push(format!("{} = {:.4e}", p.name(), truth.scenario.get(p) * factor));
            truths.push(format!("{} = {:e}", p.name(), truth.scenario.get(p)));
        }
    }
    let mut top = String::new();
    if let Some(e) = truth.scenario.restitution_target() {
        free.push("\"restitution\"".into());
        top.push_str(&format!("law = \"{}\"\nrestitution = {:e} # start\n", truth.scenario.law_kind().name(), 0.8 * e));
        truths.push(format!("restitution = {e:e}"));
    }
    if truth.time_offset != 0.0 {
        free.push("\"time_offset\"".into());
        top.push_str("time_offset = 0.0 # start\n");
        truths.push(format!("time_offset = {:e}", truth.time_offset));
    }
    let sigma_text: Vec<String> = sigma.iter().map(|(c, s)| format!("{} = {s:e}", c.name())).collect();
    format!(
        "# Synthetic data: Table 1's baseline with contact law {} plus Gaussian noise (seed {seed}),\n\
         # written by `kick fit synthesize`. Fit back with `kick fit data {}`.\n\
         free = [{}]\n{top}\n\
         [scenario] # starting guesses\n{}\n\n\
         [history]\nfile = \"{csv}\"\nsigma = {{ {} }}\n\n\
         [truth] # the values the data were made with\n{}\n",
        truth.scenario.law_kind().name(),
        path.display(),
        free.join(", "),
        guesses.join("\n"),
        sigma_text.join(", "),
        truths.join("\n")
    )
}

fn print_study(study: &IdentifiabilityStudy) {
    for (title, profiles) in [("exit speed alone", &study.exit_speed_profiles), ("histories", &study.history_profiles)] {
        println!("Profiles of chi2 ({title}); each point re-fits the other three parameters:");
        for p in profiles {
            let values: Vec<String> = p.points.iter().map(|q| format!("{:.3}:{:.3e}", q.factor, q.chi_square)).collect();
            println!("  {:<10} {}", p.parameter.name(), values.join("  "));
        }
    }
}
