//! `kick fit`: Table 2 by least squares, fits of specification files,
//! synthetic data and the identifiability study, with their result files
//! (the identifiability figure is kick-paper's, drawn from its file).

use crate::identify::files;
use crate::printable::Printable;
use crate::StoreError;
use crate::{Provenance, ResultWriter};
use kick_core::{short, sig, LawKind, Parameter, Scenario, ScenarioSpec};
use kick_identify::data::{Channel, FitSpec};
use kick_identify::fit::{fit, FitOptions, FitProblem, FitReport};
use kick_identify::profile::{identifiability_study, IdentifiabilityStudy};
use kick_identify::table2::Table2Fit;
use kick_identify::{synthetic, FitParameter, ModelPoint};
use serde::Serialize;
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// The fit's settings a report states (kick-identify's).
pub use kick_identify::fit::{JACOBIAN_STEP, MAX_ONSET_RESTARTS, RANK_TOLERANCE};
pub use kick_identify::model::RECORD_FRACTION;

/// The identifiability study's file, below `--out`.
pub const IDENTIFIABILITY_FILE: &str = "identifiability.h5";

/// The identifiability study's settings (`kick fit profile`).
#[derive(Debug, Clone, PartialEq)]
pub struct ProfileSettings {
    /// Write identifiability.h5 here (and kick-paper its figure).
    pub out: Option<PathBuf>,
    /// Profile over [1/spread, spread] x the truth.
    pub spread: f64,
    pub points: usize,
    /// Grid points per axis of the misfit maps.
    pub map_points: usize,
    pub seed: u64,
}

/// The study and the files written.
#[derive(Debug, Clone, Serialize)]
#[serde(transparent)]
pub struct ProfileReport {
    pub study: IdentifiabilityStudy,
    #[serde(skip)]
    pub written: Vec<PathBuf>,
}

/// The widest `--spread`: profiles over a decade either side of the truth.
pub const MAX_SPREAD: f64 = 10.0;

/// Identifiability (Section 17.8): misfit profiles of m_f, k, c, n from the
/// exit speed alone and from noisy histories, and (k, c) misfit maps.
pub fn profile(settings: &ProfileSettings) -> Result<ProfileReport, StoreError> {
    let ProfileSettings { out, spread, points, map_points, seed } = settings.clone();
    if !(3..=101).contains(&points) || !(3..=201).contains(&map_points) {
        let message = format!("--points must be in 3..=101 and --map-points in 3..=201 (got {points}, {map_points})");
        return Err(StoreError::Flag { flag: if (3..=101).contains(&points) { "--map-points" } else { "--points" }, message });
    }
    // At most a decade either side: the profile scales the exponent n too
    // (1e300 made a foot of 1e-300 kg, refused naming flags never given).
    if !(spread > 1.0 && spread <= MAX_SPREAD) {
        return Err(StoreError::Flag {
            flag: "--spread",
            message: format!("--spread {}: must be in (1, {MAX_SPREAD}]", kick_core::short(spread)),
        });
    }
    let study = identifiability_study(&Scenario::baseline(), spread, points, map_points, 80, seed, &FitOptions::default())?;
    let mut written = Vec::new();
    if let Some(dir) = out {
        // Reads nothing: the files themselves are checked.
        let files = [dir.join(IDENTIFIABILITY_FILE)];
        crate::output::check_paths(&files.each_ref().map(|path| crate::output::Target::File { flag: "--out", path }), &[])?;
        let command = format!("kick fit profile --spread {spread} --points {points} --map-points {map_points} --seed {seed}");
        let provenance = Provenance::now("identifiability", "kick fit profile (command line)", &command);
        written.push(files::write_identifiability(&dir.join(IDENTIFIABILITY_FILE), &provenance, &study)?);
    }
    Ok(ProfileReport { study, written })
}

impl Printable for ProfileReport {
    fn text(&self) -> String {
        let mut w = String::new();
        let study = &self.study;
        for (title, profiles) in [("exit speed alone", &study.exit_speed_profiles), ("histories", &study.history_profiles)] {
            let _ = writeln!(w, "Profiles of chi2 ({title}); each point re-fits the other three parameters:");
            for p in profiles {
                let values: Vec<String> = p.points.iter().map(|q| format!("{}:{}", sig(q.factor), sig(q.chi_square))).collect();
                let _ = writeln!(w, "  {:<10} {}", p.parameter.name(), values.join("  "));
            }
        }
        w
    }
    fn written(&self) -> &[PathBuf] {
        &self.written
    }
}

/// Write `kick fit table2 --out`: the fits, the scenario file's values and
/// the same fits to seed-rk4's unrounded outputs at those values.
fn write_table2(path: &Path, scenarios: &Path, fits: &[Table2Fit]) -> Result<PathBuf, StoreError> {
    let file = crate::table2::load(scenarios)?;
    let seed = kick_compliant::SeedRk4::new(file.dt)?;
    let options = FitOptions::default();
    let mut file_values = Vec::new();
    let mut seed_fits = Vec::new();
    let mut observations = Vec::new();
    for (index, (row, (_, scenario))) in file.row.iter().zip(file.scenarios()?).enumerate() {
        observations.push(kick_identify::table2::printed_observations(&kick_core::paper::TABLE2[index]));
        file_values.push(row.value);
        seed_fits.push(match row.parameter {
            None => None,
            Some(_) => {
                let outcome = kick_core::Solver::solve(&seed, &scenario)?;
                let unrounded = kick_identify::table2::unrounded_observations(&outcome);
                kick_identify::table2::fit_row_to(index, unrounded, &options)?.value()
            }
        });
    }
    let text = crate::table2::read_text(scenarios)?;
    let provenance = Provenance::now(
        "table2_fit",
        &scenarios.display().to_string(),
        &format!(
            "# kick fit table2 --out
{text}"
        ),
    );
    files::write_table2_fits(path, &provenance, fits, &observations, &file_values, &seed_fits)
}

/// Table 2 by least squares (JSON: the fits).
#[derive(Debug, Clone, Serialize)]
#[serde(transparent)]
pub struct Table2Fits {
    pub fits: Vec<Table2Fit>,
    #[serde(skip)]
    pub written: Vec<PathBuf>,
}

/// Table 2: each row's changed parameter by least squares on the four
/// printed observables (accurate solver). `write`: the seed-rk4 scenario
/// file (Brent roots); `out`: the fits (HDF5) beside the values of the
/// scenario file `scenarios`.
pub fn table2(write: Option<&Path>, out: Option<&Path>, scenarios: &Path) -> Result<Table2Fits, StoreError> {
    // The scenario file is read only for --out.
    let reads: Vec<&Path> = out.map(|_| scenarios).into_iter().collect();
    if let Some(path) = write {
        crate::output::check_output(path, "--write", "toml", &reads)?;
    }
    if let Some(path) = out {
        let inputs: Vec<&Path> = reads.iter().copied().chain(write).collect();
        crate::output::check_output(path, "--out", "h5", &inputs)?;
    }
    let mut written = Vec::new();
    if let Some(path) = write {
        let file = kick_compliant::table2::fit()?;
        let body = toml::to_string_pretty(&file)?;
        let text = format!(
            "# Generated by `kick fit table2 --write {}`; do not edit.\n\
             # root: Brent root of seed-rk4's v_b+ on the printed value; value: the root\n\
             # rounded to the fewest significant digits that reproduce all five printed\n\
             # columns; residuals: seed-rk4 at value minus printed (m/s, 1, N, ms, mm).\n\
             # The paper prints no parameters: each row's value is fitted to its printed\n\
             # v_b+, so that column (and the ratio v_b+/v_f-, v_f- = 22 m/s in every row)\n\
             # reproduces by construction; peak force, contact time and compression are\n\
             # what \"seed-rk4 prints as the paper\" (paper/README.md) checks.\n{body}",
            path.display()
        );
        crate::output::write(path, text)?;
    }
    let fits = kick_identify::table2::fit_all(&FitOptions::default())?;
    if let Some(path) = out {
        written.push(write_table2(path, scenarios, &fits)?);
    }
    Ok(Table2Fits { fits, written })
}

impl Printable for Table2Fits {
    fn text(&self) -> String {
        let mut w = String::new();
        let _ = writeln!(
            w,
            "Table 2 by least squares (accurate; v_b+, peak force, contact time, compression; σ = half the last printed digit)"
        );
        let _ = writeln!(
            w,
            "{:<24} {:<12} {:>12} {:>14} {:<6} {:>8}  residuals/σ",
            "row", "parameter", "estimate", "standard error", "unit", "chi2"
        );
        for f in &self.fits {
            let (estimate, residuals): (Option<(&kick_identify::fit::Estimate, f64)>, Vec<String>) =
                match (&f.report, &f.baseline_residuals) {
                    (Some(r), _) => (
                        r.estimates.first().map(|e| (e, r.chi_square)),
                        r.residuals.iter().map(|x| format!("{} {}", x.label, sig(x.weighted))).collect(),
                    ),
                    (None, Some(res)) => (None, res.iter().map(|(o, w)| format!("{} {}", o.name(), sig(*w))).collect()),
                    _ => continue,
                };
            let columns = match estimate {
                Some((e, chi_square)) => format!(
                    "{:<12} {:>12} {:>14} {:<6} {:>8}",
                    e.parameter.name(),
                    sig(e.value),
                    e.standard_uncertainty.map_or_else(|| "-".into(), |s| sig(s).to_string()),
                    e.parameter.unit(),
                    sig(chi_square)
                ),
                None => format!("{:<12} {:>12} {:>14} {:<6} {:>8}", "-", "(Table 1)", "", "", ""),
            };
            let _ = writeln!(w, "{:<24} {columns}  {}", f.name, residuals.join(", "));
        }
        w
    }
    fn written(&self) -> &[PathBuf] {
        &self.written
    }
}

/// A fit of a specification file: the report and the truth the file names.
#[derive(Debug, Clone, Serialize)]
#[serde(transparent)]
pub struct DataFit {
    pub report: FitReport,
    #[serde(skip)]
    pub truth: Vec<(FitParameter, f64)>,
    #[serde(skip)]
    pub written: Vec<PathBuf>,
}

/// Fit the parameters the specification file `spec_path` names to its data
/// (TOML/JSON); `out`: the fit report (HDF5).
pub fn data(spec_path: &Path, out: Option<&Path>) -> Result<DataFit, StoreError> {
    let (spec, observations) = FitSpec::load(spec_path)?;
    let name = spec_path.display().to_string();
    if let Some(path) = out {
        let history = spec.history.as_ref().map(|h| spec_path.parent().unwrap_or(Path::new(".")).join(&h.file));
        let inputs: Vec<&Path> = std::iter::once(spec_path).chain(history.as_deref()).collect();
        crate::output::check_output(path, "--out", "h5", &inputs)?;
    }
    let start = spec.start(&name)?;
    let free = spec.free_parameters()?;
    let truth = spec.truth()?;
    let problem = FitProblem { start, free, observations };
    let report = fit(&problem, &FitOptions::default())?;
    let mut written = Vec::new();
    if let Some(path) = out {
        let spec_text = kick_core::input::read_text(spec_path, kick_core::input::MAX_TEXT_BYTES)
            .map_err(|source| StoreError::Input { name: name.clone(), source })?;
        let stem = path.file_stem().and_then(|s| s.to_str()).unwrap_or("fit");
        let provenance = Provenance::now(stem, &name, &spec_text);
        let w = ResultWriter::create(path, &provenance, &crate::layouts::FIT)?;
        files::write_fit(&w, "fit", &report, &problem.observations, &truth)?;
        written.push(w.finish()?);
    }
    Ok(DataFit { report, truth, written })
}

impl DataFit {
    /// An error unless the fit converged.
    pub fn converged(&self) -> Result<(), StoreError> {
        if self.report.converged {
            Ok(())
        } else {
            Err(StoreError::NotConverged { termination: self.report.termination.clone() })
        }
    }
}

impl Printable for DataFit {
    fn text(&self) -> String {
        report_text(&self.report, &self.truth)
    }
    fn written(&self) -> &[PathBuf] {
        &self.written
    }
    /// As `kick bounce`: printed whole, then an error (exit 1).
    fn outside_validity(&self) -> Option<String> {
        let outside = &self.report.outside_validity;
        let first = outside.first()?;
        let more = match outside.len() {
            1 => String::new(),
            n => format!(" (and {} more contacts of the fit)", n - 1),
        };
        Some(format!("a fit with a contact outside its law's validity at the estimate: {first}{more}"))
    }
}

/// A fit report as a table: estimates, uncertainties, pulls, χ², correlations.
pub fn report_text(report: &FitReport, truth: &[(FitParameter, f64)]) -> String {
    let mut w = String::new();
    let _ = writeln!(w, "contact law: {}", report.law.name());
    let _ = writeln!(
        w,
        "{:<14} {:>12} {:>14} {:<8} {:>12} {:>14}",
        "parameter", "estimate", "standard error", "unit", "start", "(est-truth)/σ"
    );
    for e in &report.estimates {
        let pull = truth
            .iter()
            .find(|(p, _)| *p == e.parameter)
            .zip(e.standard_uncertainty)
            .map_or(String::new(), |((_, t), s)| sig((e.value - t) / s).to_string());
        let _ = writeln!(
            w,
            "{:<14} {:>12} {:>14} {:<8} {:>12} {:>14}",
            e.parameter.name(),
            sig(e.value),
            e.standard_uncertainty.map_or_else(|| "not identified".into(), |s| sig(s).to_string()),
            e.parameter.unit(),
            sig(e.start),
            pull
        );
    }
    let _ = writeln!(
        w,
        "chi2 {} over {} residuals, {} degrees of freedom, s2 {}; {} ({} evaluations)",
        sig(report.chi_square),
        report.residuals.len(),
        report.degrees_of_freedom,
        report.residual_variance.map_or_else(|| "-".into(), |s| sig(s).to_string()),
        report.termination,
        report.evaluations
    );
    if let Some(c) = &report.correlation {
        let names: Vec<&str> = report.estimates.iter().map(|e| e.parameter.name()).collect();
        // Columns as wide as the longest name, so declared names never run together.
        let width = names.iter().map(|n| n.chars().count()).max().unwrap_or(0).max(12);
        let _ = writeln!(w, "correlation:\n  {:<width$}{}", "", names.iter().map(|n| format!(" {n:>width$}")).collect::<String>());
        for (name, row) in names.iter().zip(c) {
            let _ = writeln!(w, "  {name:<width$}{}", row.iter().map(|&v| format!(" {:>width$}", sig(v))).collect::<String>());
        }
    }
    // Identifiability: a singular value near zero is a combination the data do not resolve.
    if let (Some(&largest), Some(&smallest)) = (report.singular_values.first(), report.singular_values.last()) {
        let values: Vec<String> = report.singular_values.iter().map(|&v| sig(v).to_string()).collect();
        let ratio = if smallest > 0.0 { sig(largest / smallest).to_string() } else { "inf (not identified)".into() };
        let _ = writeln!(w, "singular values of the weighted Jacobian: {} (largest/smallest {ratio})", values.join(", "));
    }
    let worst = report.residuals.iter().max_by(|a, b| a.weighted.abs().total_cmp(&b.weighted.abs()));
    if let Some(r) = worst {
        let _ = writeln!(w, "largest residual: {} = {} σ", r.label, sig(r.weighted));
    }
    for outside in &report.outside_validity {
        let _ = writeln!(w, "status {}: {outside}", kick_core::Status::OutsideValidity.name());
    }
    w
}

/// The synthetic data and specifications written.
#[derive(Debug, Clone, Serialize)]
pub struct Synthesized {
    pub csv: PathBuf,
    pub spec: PathBuf,
    /// The specification fitting the same data with another law, when asked.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub other_law_spec: Option<PathBuf>,
}

impl Printable for Synthesized {
    fn text(&self) -> String {
        match &self.other_law_spec {
            Some(other) => format!("wrote {}, {} and {}\n", self.csv.display(), self.spec.display(), other.display()),
            None => format!("wrote {} and {}\n", self.csv.display(), self.spec.display()),
        }
    }
}

/// The file stem of the specification that fits `name`'s data with `law`.
pub fn other_law_name(name: &str, law: LawKind) -> String {
    format!("{name}_as_{}", law.name().replace('-', "_"))
}

/// Write a synthetic history (CSV, `out/NAME.csv`) and a fit specification
/// for it (`out/NAME.toml`): the scenario `truth` (Table 1's baseline where
/// not given) plus seeded noise, `times` samples over 1.2 contact times, the
/// data's first touch at `time_offset`. With `other_law`, also
/// `out/NAME_as_LAW.toml`: the same data fitted with that law (its
/// parameters free, t0 too when non-zero), to see what a wrong law leaves
/// in the residuals.
pub fn synthesize(
    out: &Path,
    name: &str,
    seed: u64,
    times: usize,
    truth: &ScenarioSpec,
    time_offset: f64,
    other_law: Option<LawKind>,
) -> Result<Synthesized, StoreError> {
    if !(2..=100_000).contains(&times) {
        return Err(StoreError::Flag { flag: "--times", message: format!("--times must be in 2..=100000 (got {times})") });
    }
    if name.is_empty() || name.contains(['/', '\\']) {
        return Err(StoreError::Flag { flag: "--name", message: format!("--name must be a plain file stem (got `{name}`)") });
    }
    let csv = out.join(format!("{name}.csv"));
    let toml_path = out.join(format!("{name}.toml"));
    // Reads nothing; the two files are checked before the work.
    let targets = [&csv, &toml_path].map(|path| crate::output::Target::File { flag: "--out", path });
    crate::output::check_paths(&targets, &[])?;
    let scenario = truth.build()?;
    if let Some(law) = other_law.filter(|&law| law == scenario.law_kind()) {
        let message = format!("--also-fit-law {}: the data's own law; give another", law.name());
        return Err(StoreError::Flag { flag: "--also-fit-law", message });
    }
    let truth = ModelPoint::new(scenario, time_offset)?;
    let options = FitOptions::default();
    let sigma = synthetic::lab_sigma(&Channel::ALL);
    let grid = synthetic::time_grid(&scenario, times, SYNTHETIC_SPAN);
    check_sampled_contact(&options, &scenario, time_offset, grid[grid.len() - 1])?;
    let data = synthetic::history(&options.solver, &truth, grid, &sigma, seed)?;
    let history = data.history.ok_or(StoreError::NoHistory)?;
    let spec = synthetic_spec(&truth, &truth, &format!("{name}.csv"), &sigma, seed, &toml_path);
    // The data and the specification that reads it: both or neither.
    let data = history.data.to_csv();
    crate::output::write_all(&[(&csv, data.as_bytes()), (&toml_path, spec.as_bytes())])?;
    let other_law_spec = match other_law {
        Some(law) => {
            // The other law's start: the truth's values; its restitution, when it takes one, the data's.
            let e = match truth.scenario.restitution_target() {
                Some(e) => e,
                None => kick_core::Solver::solve(&kick_compliant::Accurate::default(), &truth.scenario)?.restitution,
            };
            let e = Some(e);
            let start = ModelPoint::new(truth.scenario.with_law(law, e)?, truth.time_offset)?;
            let path = out.join(format!("{}.toml", other_law_name(name, law)));
            let target = [crate::output::Target::File { flag: "--out", path: &path }];
            crate::output::check_paths(&target, &[])?;
            crate::output::write(&path, synthetic_spec(&truth, &start, &format!("{name}.csv"), &sigma, seed, &path))?;
            Some(path)
        }
        None => None,
    };
    Ok(Synthesized { csv, spec: toml_path, other_law_spec })
}

/// A synthetic history's span, in undamped contact times from 0.
const SYNTHETIC_SPAN: f64 = 1.2;

/// Refuse a `--time-offset` whose contact [t0, t0 + t_c] lies less than
/// half (of itself, or of the window when it is the longer) in the sampled
/// window [0, end]: its data would be mostly or wholly free flight, which
/// no fit can read a contact from. t0 = 0 always passes.
fn check_sampled_contact(options: &FitOptions, scenario: &Scenario, time_offset: f64, end: f64) -> Result<(), StoreError> {
    let contact = kick_core::Solver::solve(&options.solver, scenario)?.contact_time;
    let needed = 0.5 * contact.min(end);
    let sampled = (end.min(time_offset + contact) - time_offset.max(0.0)).max(0.0);
    if sampled >= needed {
        return Ok(());
    }
    let message = format!(
        "--time-offset {}: the data are sampled over [0, {}] s ({SYNTHETIC_SPAN} undamped contact times), which holds {}% of \
         the contact at [{}, {}] s; give a first touch in [{}, {}] s, so that at least half of it is sampled",
        short(time_offset),
        short(end),
        sig(100.0 * sampled / contact),
        short(time_offset),
        short(time_offset + contact),
        short(needed - contact),
        short(end - needed)
    );
    Err(StoreError::Flag { flag: "--time-offset", message })
}

/// Starting guesses of a synthetic fit, as factors of the truth: far enough
/// that the fit has to travel, near enough to stay in the basin.
const SYNTHETIC_START: [(Parameter, f64); 4] =
    [(Parameter::FootMass, 1.2), (Parameter::Stiffness, 0.714), (Parameter::Damping, 1.333), (Parameter::Exponent, 0.926)];

/// The fit specification of synthetic data made with `truth`, fitted with
/// the law of `fit`: that law's fittable parameters among m_f, k, c, n (and
/// e, t0), started away from `fit`'s values. The truth is listed for what
/// the data were made with and the fit shares (all of it when the laws are
/// the same; t0 only otherwise).
fn synthetic_spec(truth: &ModelPoint, fit: &ModelPoint, csv: &str, sigma: &BTreeMap<Channel, f64>, seed: u64, path: &Path) -> String {
    let same_law = truth.scenario.law_kind() == fit.scenario.law_kind();
    let mut free = Vec::new();
    let mut guesses = Vec::new();
    let mut truths = Vec::new();
    for (p, factor) in SYNTHETIC_START {
        if fit.check_fittable(p.into(), true).is_ok() {
            free.push(format!("\"{}\"", p.name()));
            guesses.push(format!("{} = {:.4e}", p.name(), fit.scenario.get(p) * factor));
            if same_law {
                truths.push(format!("{} = {:e}", p.name(), truth.scenario.get(p)));
            }
        }
    }
    let mut top = String::new();
    if fit.scenario.law_kind() != LawKind::PowerLaw {
        top.push_str(&format!("law = \"{}\"\n", fit.scenario.law_kind().name()));
    }
    if let Some(e) = fit.scenario.restitution_target() {
        free.push("\"restitution\"".into());
        top.push_str(&format!("restitution = {:e} # start\n", 0.8 * e));
        if same_law {
            truths.push(format!("restitution = {e:e}"));
        }
    }
    if truth.time_offset != 0.0 {
        free.push("\"time_offset\"".into());
        top.push_str("time_offset = 0.0 # start\n");
        truths.push(format!("time_offset = {:e}", truth.time_offset));
    }
    let sigma_text: Vec<String> = sigma.iter().map(|(c, s)| format!("{} = {s:e}", c.name())).collect();
    let (fitted, truth_note) = if same_law {
        ("Fit back".to_string(), "the values the data were made with")
    } else {
        (
            format!("Fit with another law, {},", fit.scenario.law_kind().name()),
            "what the data were made with that this fit shares; the other law's parameters have no true value",
        )
    };
    format!(
        "# Synthetic data: Table 1's baseline with contact law {} plus Gaussian noise (seed {seed}),\n\
         # written by `kick fit synthesize`. {fitted} with `kick fit data {}`.\n\
         free = [{}]\n{top}\n\
         [scenario] # starting guesses\n{}\n\n\
         [history]\nfile = \"{csv}\"\nsigma = {{ {} }}\n\n\
         [truth] # {truth_note}\n{}\n",
        truth.scenario.law_kind().name(),
        path.display(),
        free.join(", "),
        guesses.join("\n"),
        sigma_text.join(", "),
        truths.join("\n")
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A refused setting is the flag the user gave, before any work.
    #[test]
    fn a_refused_setting_names_its_flag() {
        let out = std::env::temp_dir().join(format!("kick-store-fit-flags-{}", std::process::id()));
        let e = synthesize(&out, "x", 1, 1, &ScenarioSpec::default(), 0.0, None).unwrap_err();
        assert!(matches!(e, StoreError::Flag { flag: "--times", .. }), "{e:?}");
        assert_eq!(e.to_string(), "--times must be in 2..=100000 (got 1)");
        let e = synthesize(&out, "a/b", 1, 10, &ScenarioSpec::default(), 0.0, None).unwrap_err();
        assert!(matches!(e, StoreError::Flag { flag: "--name", .. }), "{e:?}");
        assert!(e.to_string().contains("`a/b`"), "{e}");
        // A first touch that leaves the sampled window without the contact.
        for t0 in [0.02, 1e9, -0.01] {
            let e = synthesize(&out, "x", 1, 10, &ScenarioSpec::default(), t0, None).unwrap_err();
            assert!(matches!(e, StoreError::Flag { flag: "--time-offset", .. }), "{t0}: {e:?}");
            assert!(e.to_string().contains("holds 0% of the contact"), "{e}");
        }
        let settings = ProfileSettings { out: None, spread: 2.0, points: 5, map_points: 2, seed: 1 };
        let e = profile(&settings).unwrap_err();
        assert!(matches!(e, StoreError::Flag { flag: "--map-points", .. }), "{e:?}");
        assert!(!out.exists());
    }
}
