//! The result files of `kick laws` and `kick fit` (HDF5, through
//! kick-store's writers; every dataset has `units`, the root the
//! provenance), and their readers. Figures and `paper/laws.md`,
//! `paper/identification.md` are drawn from these files only.
//!
//! `laws.h5` — the sweep layout (this crate's README.md): one row per
//! Table 2 scenario (`scenario_names`), parameters the eight scenario
//! parameters and `target_restitution`; one outcome set per law (the paper's
//! at the root, the others under `solvers/<law>`), columns the observables
//! of `kick simulate`, `onset_force` (F(0⁺), N) and the law's own
//! dissipation parameter (`hysteresis` χ in s/m; Kelvin–Voigt's
//! `linear_stiffness` N/m and `linear_damping` N s/m); histories
//! `histories/<row>/{time, force}` are the force pulses. Beside it,
//! `restitution_formulas/`: `target_restitution` and, per law, the
//! restitution it gives when asked for that target (baseline, simulated).
//!
//! Fit reports (layout `kick-fit`, version 2, under a group G):
//!
//! ```text
//! G                         attributes law, termination, converged ("true"/"false")
//! G/chi_square, degrees_of_freedom, residual_variance (absent when m ≤ n), evaluations   (1)
//! G/parameters              strings, the estimates' order
//! G/estimates/<p>/value, start, standard_uncertainty (absent when not identified), truth (when known)   unit of p
//! G/correlation/<p>         row of the correlation matrix (absent when not identified), 1
//! G/singular_values         1
//! G/residuals/<observable>/observed, predicted, sigma (its unit), weighted (1)
//! G/residuals/<channel>/time (s), observed, predicted, sigma (its unit), weighted (1)
//! G/measurements/<i>        attribute name; conditions/<parameter> (its unit); residuals/... as above
//! ```
//!
//! `kick fit data --out` writes one report at `/fit`. `kick fit table2 --out`
//! (layout `kick-fit-table2`, version 1) writes `/rows/<i>` per Table 2 row
//! (attributes name, parameter): the fit at `/rows/<i>/fit`, `file_value`
//! (the value in experiments/table2.toml) and `seed_fit_value` (the same fit
//! to seed-rk4's unrounded outputs at that value), each in the parameter's
//! unit; the baseline row has `baseline_residuals/<observable>` (weighted, 1).
//!
//! `identifiability.h5` (layout `kick-identifiability`, version 1): `settings/` (seed,
//! history_times, exit_speed_sigma), `truth/<p>`, `history_sigma/<channel>`,
//! `profiles/<source>/<p>/{factor, value, chi_square, others/<q>}` with
//! `profiles/<source>/parameters` giving the order, and
//! `maps/<source>/{x_factor, y_factor, chi_square}` (rows = grid points, x
//! fastest; attributes x, y), for source `exit_speed` and `histories`.

use crate::h5::{read_history, Compression};
use crate::run::{create_table, fill_table, finish_table};
use crate::StoreError;
use crate::{Column, Provenance, ResultFile, ResultWriter, SweepData};
use indicatif::ProgressBar;
use kick_core::laws::LawKind;
use kick_core::Parameter;
use kick_identify::data::Observations;
use kick_identify::fit::FitReport;
use kick_identify::laws::{LawComparison, RESTITUTION_LAWS};
use kick_identify::profile::{IdentifiabilityStudy, MisfitMap, Profile};
use kick_identify::table2::Table2Fit;
use kick_identify::FitParameter;
use kick_study::level::laws::LawTable;
use kick_study::level::Level;
use kick_study::StudyError;
use std::path::{Path, PathBuf};

/// Write `laws.h5` (module docs): the comparison rows through the run loop
/// ([`LawTable`]), their pulses beside them as histories, and the
/// restitution table.
pub fn write_laws(
    path: &Path,
    provenance: &Provenance,
    all: &[LawComparison],
    samples: u32,
    formula_targets: &[f64],
    formulas: &[Vec<f64>],
) -> Result<PathBuf, StoreError> {
    let level = LawTable::new(all, samples).map_err(StudyError::from)?;
    let mut writer = create_table(&level, path, provenance, level.rows(), Compression::None)?;
    let names: Vec<String> = all.iter().map(|c| c.name.clone()).collect();
    crate::h5::write_strings(writer.file(), path, "scenario_names", &names)?;
    let bar = ProgressBar::hidden();
    fill_table(&level, 0..level.rows(), &mut writer, &bar)?;
    for row in 0..all.len() {
        for set in 0..LawKind::ALL.len() {
            let (time, force) = level.pulse(row, set);
            writer.write_history(set, row, &[(Column::new("time", "s"), &time), (Column::new("force", "N"), &force)])?;
        }
    }
    let w = writer.file();
    let group = crate::h5::new_group(w, "restitution_formulas").map_err(crate::h5::h5err(path))?;
    crate::h5::write_str_attr(
        &group,
        path,
        "description",
        "restitution each law gives when asked for target_restitution (baseline masses, k, n, V0; accurate solver)",
    )?;
    crate::h5::write_column(&group, path, &Column::new("target_restitution", "1"), formula_targets)?;
    for (k, law) in RESTITUTION_LAWS.iter().enumerate() {
        let column: Vec<f64> = formulas.iter().map(|row| row[k]).collect();
        crate::h5::write_column(&group, path, &Column::new(law.name(), "1"), &column)?;
    }
    Ok(finish_table(&level, writer, &bar)?.path)
}

/// `laws.h5` read back.
pub struct LawsData {
    pub path: PathBuf,
    pub sweep: SweepData,
    pub names: Vec<String>,
    pub formula_targets: Vec<f64>,
    /// Per law of [`RESTITUTION_LAWS`], its restitution at each target.
    pub formulas: Vec<(LawKind, Vec<f64>)>,
}

impl LawsData {
    pub fn read(path: &Path) -> Result<LawsData, StoreError> {
        let sweep = SweepData::read(path)?;
        let names = sweep.names.clone().ok_or_else(|| StoreError::Lacks { path: path.to_path_buf(), what: "no scenario_names".into() })?;
        let file = ResultFile::open(path)?;
        let formula_targets = file.values("restitution_formulas/target_restitution")?;
        let formulas = RESTITUTION_LAWS
            .iter()
            .map(|&law| Ok((law, file.values(&format!("restitution_formulas/{}", law.name()))?)))
            .collect::<Result<Vec<_>, StoreError>>()?;
        Ok(LawsData { path: path.to_path_buf(), sweep, names, formula_targets, formulas })
    }

    pub fn rows(&self) -> usize {
        self.names.len()
    }

    /// An outcome column of one law.
    pub fn column(&self, law: LawKind, name: &str) -> Result<&[f64], StoreError> {
        let set = self.sweep.set(law.name())?;
        set.column(name).ok_or_else(|| StoreError::Lacks { path: self.path.clone(), what: format!("law {} has no `{name}`", law.name()) })
    }

    /// A parameter column.
    pub fn parameter(&self, name: &str) -> Result<&[f64], StoreError> {
        Ok(self.sweep.parameter(name)?)
    }

    /// The force pulse (t in s, F in N) of `law` on row `row`.
    pub fn pulse(&self, law: LawKind, row: usize) -> Result<(Vec<f64>, Vec<f64>), StoreError> {
        let group = &self.sweep.set(law.name())?.group;
        let columns = read_history(&self.path, group, row)?;
        let get = |name: &str| {
            columns.iter().find(|(c, _)| c.name == name).map(|(_, v)| v.clone()).ok_or_else(|| StoreError::Lacks {
                path: self.path.clone(),
                what: format!("pulse {row} of {} has no `{name}`", law.name()),
            })
        };
        Ok((get("time")?, get("force")?))
    }
}

fn write_scalar(w: &ResultWriter, group: &str, name: &str, unit: &str, value: f64) -> Result<(), StoreError> {
    Ok(w.scalar(group, name, unit, value)?)
}

/// Write a fit report under `group` (module docs), with the data it was fitted to
/// and the true values when known.
pub fn write_fit(
    w: &ResultWriter,
    group: &str,
    report: &FitReport,
    observations: &Observations,
    truth: &[(FitParameter, f64)],
) -> Result<(), StoreError> {
    w.text(group, "law", report.law.name())?;
    w.text(group, "termination", &report.termination)?;
    w.text(group, "converged", if report.converged { "true" } else { "false" })?;
    write_scalar(w, group, "chi_square", "1", report.chi_square)?;
    write_scalar(w, group, "degrees_of_freedom", "1", report.degrees_of_freedom as f64)?;
    if let Some(s2) = report.residual_variance {
        write_scalar(w, group, "residual_variance", "1", s2)?;
    }
    write_scalar(w, group, "evaluations", "1", report.evaluations as f64)?;
    if !report.outside_validity.is_empty() {
        let outside: Vec<String> = report.outside_validity.iter().map(|o| o.to_string()).collect();
        w.strings(group, "outside_validity", &outside)?;
    }
    let names: Vec<String> = report.estimates.iter().map(|e| e.parameter.name().to_string()).collect();
    w.strings(group, "parameters", &names)?;
    for (i, e) in report.estimates.iter().enumerate() {
        let g = format!("{group}/estimates/{}", e.parameter.name());
        let unit = e.parameter.unit();
        write_scalar(w, &g, "value", unit, e.value)?;
        write_scalar(w, &g, "start", unit, e.start)?;
        if let Some(s) = e.standard_uncertainty {
            write_scalar(w, &g, "standard_uncertainty", unit, s)?;
        }
        if let Some((_, t)) = truth.iter().find(|(p, _)| *p == e.parameter) {
            write_scalar(w, &g, "truth", unit, *t)?;
        }
        if let Some(c) = &report.correlation {
            w.column(&format!("{group}/correlation"), &Column::new(e.parameter.name(), "1"), &c[i])?;
        }
    }
    w.column(group, &Column::new("singular_values", "1"), &report.singular_values)?;
    // Residuals in `predict`'s order: scalars, then each channel over all
    // times; then each measurement's, under measurements/<i>.
    let mut residuals = report.residuals.iter();
    write_residuals(w, group, observations, &mut residuals)?;
    for (i, m) in observations.measurements.iter().enumerate() {
        let g = format!("{group}/measurements/{i}");
        w.text(&g, "name", &m.name)?;
        for (p, value) in &m.conditions {
            write_scalar(w, &format!("{g}/conditions"), p.name(), p.unit(), *value)?;
        }
        write_residuals(w, &g, &m.observations, &mut residuals)?;
    }
    Ok(())
}

/// The residuals of `observations`' own scalars and history, taken in order from `residuals`.
fn write_residuals<'a>(
    w: &ResultWriter,
    group: &str,
    observations: &Observations,
    residuals: &mut impl Iterator<Item = &'a kick_identify::fit::Residual>,
) -> Result<(), StoreError> {
    let mut next = |label: &str| residuals.next().ok_or_else(|| StoreError::NoResidual { label: label.to_string() });
    for s in &observations.scalars {
        let r = next(s.observable.name())?;
        let g = format!("{group}/residuals/{}", s.observable.name());
        let unit = s.observable.unit();
        write_scalar(w, &g, "observed", unit, r.observed)?;
        write_scalar(w, &g, "predicted", unit, r.predicted)?;
        write_scalar(w, &g, "sigma", unit, r.sigma)?;
        write_scalar(w, &g, "weighted", "1", r.weighted)?;
    }
    if let Some(h) = &observations.history {
        for (channel, _) in &h.data.channels {
            let rows = h.data.times.iter().map(|_| next(channel.name()).cloned()).collect::<Result<Vec<_>, _>>()?;
            let g = format!("{group}/residuals/{}", channel.name());
            let unit = channel.unit();
            w.column(&g, &Column::new("time", "s"), &h.data.times)?;
            for (name, unit, values) in [
                ("observed", unit, rows.iter().map(|r| r.observed).collect::<Vec<_>>()),
                ("predicted", unit, rows.iter().map(|r| r.predicted).collect()),
                ("sigma", unit, rows.iter().map(|r| r.sigma).collect()),
                ("weighted", "1", rows.iter().map(|r| r.weighted).collect()),
            ] {
                w.column(&g, &Column::new(name, unit), &values)?;
            }
        }
    }
    Ok(())
}

/// One estimate of a fit report read back.
#[derive(Debug, Clone, PartialEq)]
pub struct EstimateData {
    pub name: String,
    pub unit: String,
    pub value: f64,
    pub start: f64,
    pub standard_uncertainty: Option<f64>,
    pub truth: Option<f64>,
}

impl EstimateData {
    /// (estimate − truth)/σ, when both are known.
    pub fn pull(&self) -> Option<f64> {
        Some((self.value - self.truth?) / self.standard_uncertainty?)
    }
}

/// A fit report read back.
#[derive(Debug, Clone, PartialEq)]
pub struct FitData {
    pub law: String,
    pub converged: bool,
    pub termination: String,
    pub chi_square: f64,
    pub degrees_of_freedom: f64,
    pub residual_variance: Option<f64>,
    pub estimates: Vec<EstimateData>,
    pub correlation: Option<Vec<Vec<f64>>>,
    pub singular_values: Vec<f64>,
}

impl FitData {
    pub fn estimate(&self, name: &str) -> Option<&EstimateData> {
        self.estimates.iter().find(|e| e.name == name)
    }

    /// Correlation of two estimates, by name.
    pub fn correlation(&self, a: &str, b: &str) -> Option<f64> {
        let i = self.estimates.iter().position(|e| e.name == a)?;
        let j = self.estimates.iter().position(|e| e.name == b)?;
        Some(self.correlation.as_ref()?[i][j])
    }
}

fn optional(file: &ResultFile, path: &str) -> Result<Option<f64>, StoreError> {
    if file.exists(path) {
        Ok(Some(file.scalar(path)?))
    } else {
        Ok(None)
    }
}

/// Read the fit report under `group`.
pub fn read_fit(file: &ResultFile, group: &str) -> Result<FitData, StoreError> {
    let names = file.strings(&format!("{group}/parameters"))?;
    let mut estimates = Vec::new();
    for name in &names {
        let g = format!("{group}/estimates/{name}");
        let (column, value) = file.column(&format!("{g}/value"))?;
        let [value] = value[..] else { return Err(StoreError::NotScalar { dataset: format!("{g}/value") }) };
        estimates.push(EstimateData {
            name: name.clone(),
            unit: column.unit,
            value,
            start: file.scalar(&format!("{g}/start"))?,
            standard_uncertainty: optional(file, &format!("{g}/standard_uncertainty"))?,
            truth: optional(file, &format!("{g}/truth"))?,
        });
    }
    let correlation = if file.exists(&format!("{group}/correlation")) {
        Some(names.iter().map(|n| file.values(&format!("{group}/correlation/{n}"))).collect::<Result<Vec<_>, _>>()?)
    } else {
        None
    };
    Ok(FitData {
        law: file.text(group, "law")?,
        converged: file.text(group, "converged")? == "true",
        termination: file.text(group, "termination")?,
        chi_square: file.scalar(&format!("{group}/chi_square"))?,
        degrees_of_freedom: file.scalar(&format!("{group}/degrees_of_freedom"))?,
        residual_variance: optional(file, &format!("{group}/residual_variance"))?,
        estimates,
        correlation,
        singular_values: file.values(&format!("{group}/singular_values"))?,
    })
}

/// Write `kick fit table2 --out` (module docs). `file_values` and
/// `seed_fits` are per row (None for the baseline).
pub fn write_table2_fits(
    path: &Path,
    provenance: &Provenance,
    fits: &[Table2Fit],
    observations: &[Observations],
    file_values: &[Option<f64>],
    seed_fits: &[Option<f64>],
) -> Result<PathBuf, StoreError> {
    let w = ResultWriter::create(path, provenance, &crate::layouts::FIT_TABLE2)?;
    for (i, f) in fits.iter().enumerate() {
        let g = format!("rows/{i:02}");
        w.text(&g, "name", &f.name)?;
        w.text(&g, "parameter", f.parameter.map_or("", |p| p.name()))?;
        if let (Some(report), Some(p)) = (&f.report, f.parameter) {
            write_fit(&w, &format!("{g}/fit"), report, &observations[i], &[])?;
            if let Some(v) = file_values[i] {
                write_scalar(&w, &g, "file_value", p.unit(), v)?;
            }
            if let Some(v) = seed_fits[i] {
                write_scalar(&w, &g, "seed_fit_value", p.unit(), v)?;
            }
        }
        for (observable, weighted) in f.baseline_residuals.iter().flatten() {
            write_scalar(&w, &format!("{g}/baseline_residuals"), observable.name(), "1", *weighted)?;
        }
    }
    Ok(w.finish()?)
}

/// One row of `kick fit table2 --out` read back.
pub struct Table2Row {
    pub name: String,
    /// The fitted parameter's name; None for the baseline.
    pub parameter: Option<String>,
    pub fit: Option<FitData>,
    pub file_value: Option<f64>,
    pub seed_fit_value: Option<f64>,
    /// Baseline only: weighted residuals at Table 1.
    pub baseline_residuals: Vec<(String, f64)>,
}

pub fn read_table2_fits(path: &Path) -> Result<Vec<Table2Row>, StoreError> {
    let file = ResultFile::open(path)?;
    let mut rows = Vec::new();
    for member in file.members("rows")? {
        let g = format!("rows/{member}");
        let parameter = file.text(&g, "parameter")?;
        let baseline_residuals = if file.exists(&format!("{g}/baseline_residuals")) {
            file.members(&format!("{g}/baseline_residuals"))?
                .into_iter()
                .map(|o| Ok((o.clone(), file.scalar(&format!("{g}/baseline_residuals/{o}"))?)))
                .collect::<Result<Vec<_>, StoreError>>()?
        } else {
            Vec::new()
        };
        rows.push(Table2Row {
            name: file.text(&g, "name")?,
            fit: if parameter.is_empty() { None } else { Some(read_fit(&file, &format!("{g}/fit"))?) },
            parameter: (!parameter.is_empty()).then_some(parameter),
            file_value: optional(&file, &format!("{g}/file_value"))?,
            seed_fit_value: optional(&file, &format!("{g}/seed_fit_value"))?,
            baseline_residuals,
        });
    }
    Ok(rows)
}

/// The two data sources of the identifiability study, as group names.
pub const SOURCES: [&str; 2] = ["exit_speed", "histories"];

fn write_profiles(w: &ResultWriter, source: &str, profiles: &[Profile]) -> Result<(), StoreError> {
    let g = format!("profiles/{source}");
    let names: Vec<String> = profiles.iter().map(|p| p.parameter.name().to_string()).collect();
    w.strings(&g, "parameters", &names)?;
    for p in profiles {
        let pg = format!("{g}/{}", p.parameter.name());
        write_scalar(w, &pg, "truth", p.parameter.unit(), p.truth)?;
        w.column(&pg, &Column::new("factor", "1"), &p.points.iter().map(|q| q.factor).collect::<Vec<_>>())?;
        w.column(&pg, &Column::new("value", p.parameter.unit()), &p.points.iter().map(|q| q.value).collect::<Vec<_>>())?;
        w.column(&pg, &Column::new("chi_square", "1"), &p.points.iter().map(|q| q.chi_square).collect::<Vec<_>>())?;
        let others: Vec<FitParameter> = p.points.first().map(|q| q.others.iter().map(|o| o.0).collect()).unwrap_or_default();
        for (k, other) in others.iter().enumerate() {
            let factors: Vec<f64> = p.points.iter().map(|q| q.others.get(k).map_or(f64::NAN, |o| o.1)).collect();
            w.column(&format!("{pg}/others"), &Column::new(other.name(), "1"), &factors)?;
        }
    }
    Ok(())
}

fn write_map(w: &ResultWriter, source: &str, map: &MisfitMap) -> Result<(), StoreError> {
    let g = format!("maps/{source}");
    w.text(&g, "x", map.x.name())?;
    w.text(&g, "y", map.y.name())?;
    let (mut x, mut y, mut chi) = (Vec::new(), Vec::new(), Vec::new());
    for (iy, &fy) in map.y_factors.iter().enumerate() {
        for (ix, &fx) in map.x_factors.iter().enumerate() {
            x.push(fx);
            y.push(fy);
            chi.push(map.chi_square[iy][ix]);
        }
    }
    w.column(&g, &Column::new("x_factor", "1"), &x)?;
    w.column(&g, &Column::new("y_factor", "1"), &y)?;
    Ok(w.column(&g, &Column::new("chi_square", "1"), &chi)?)
}

/// Write `identifiability.h5` (module docs).
pub fn write_identifiability(path: &Path, provenance: &Provenance, study: &IdentifiabilityStudy) -> Result<PathBuf, StoreError> {
    let w = ResultWriter::create(path, provenance, &crate::layouts::IDENTIFIABILITY)?;
    write_scalar(&w, "settings", "seed", "1", study.seed as f64)?;
    write_scalar(&w, "settings", "history_times", "1", study.history_times as f64)?;
    write_scalar(&w, "settings", "exit_speed_sigma", "m/s", study.exit_speed_sigma)?;
    w.text("settings", "law", study.truth.law_kind().name())?;
    for p in Parameter::ALL {
        write_scalar(&w, "truth", p.name(), p.unit(), study.truth.get(p))?;
    }
    for (channel, sigma) in &study.history_sigma {
        write_scalar(&w, "history_sigma", channel.name(), channel.unit(), *sigma)?;
    }
    write_profiles(&w, SOURCES[0], &study.exit_speed_profiles)?;
    write_profiles(&w, SOURCES[1], &study.history_profiles)?;
    write_map(&w, SOURCES[0], &study.exit_speed_map)?;
    write_map(&w, SOURCES[1], &study.history_map)?;
    Ok(w.finish()?)
}

/// One misfit profile read back.
#[derive(Debug, Clone, PartialEq)]
pub struct ProfileData {
    pub parameter: String,
    pub unit: String,
    pub truth: f64,
    pub factor: Vec<f64>,
    pub value: Vec<f64>,
    pub chi_square: Vec<f64>,
}

impl ProfileData {
    /// Δχ² = χ² − `least` along the profile; `least` is [`least_chi_square`]
    /// of the profiles of the same data, so that every profile's Δχ² = 1
    /// has one baseline (each profile's own minimum differs by up to ~1).
    pub fn delta_chi_square(&self, least: f64) -> Vec<f64> {
        self.chi_square.iter().map(|c| c - least).collect()
    }
}

/// The smallest χ² on any of `profiles` (those of one data set).
pub fn least_chi_square(profiles: &[ProfileData]) -> f64 {
    profiles.iter().flat_map(|p| p.chi_square.iter().copied()).fold(f64::INFINITY, f64::min)
}

/// `identifiability.h5` read back (profiles only; the maps stay in the file).
pub struct IdentifiabilityData {
    pub seed: f64,
    pub history_times: f64,
    pub exit_speed_sigma: f64,
    /// Channel, σ, unit.
    pub history_sigma: Vec<(String, f64, String)>,
    /// Per source of [`SOURCES`], the profiles in the study's order.
    pub profiles: Vec<Vec<ProfileData>>,
}

pub fn read_identifiability(path: &Path) -> Result<IdentifiabilityData, StoreError> {
    let file = ResultFile::open(path)?;
    let mut profiles = Vec::new();
    for source in SOURCES {
        let g = format!("profiles/{source}");
        let mut list = Vec::new();
        for name in file.strings(&format!("{g}/parameters"))? {
            let pg = format!("{g}/{name}");
            let (value_column, value) = file.column(&format!("{pg}/value"))?;
            list.push(ProfileData {
                parameter: name,
                unit: value_column.unit,
                truth: file.scalar(&format!("{pg}/truth"))?,
                factor: file.values(&format!("{pg}/factor"))?,
                value,
                chi_square: file.values(&format!("{pg}/chi_square"))?,
            });
        }
        profiles.push(list);
    }
    let mut history_sigma = Vec::new();
    for channel in file.members("history_sigma")? {
        let path = format!("history_sigma/{channel}");
        let (column, _) = file.column(&path)?;
        history_sigma.push((channel, file.scalar(&path)?, column.unit));
    }
    Ok(IdentifiabilityData {
        seed: file.scalar("settings/seed")?,
        history_times: file.scalar("settings/history_times")?,
        exit_speed_sigma: file.scalar("settings/exit_speed_sigma")?,
        history_sigma,
        profiles,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn profile(chi_square: Vec<f64>) -> ProfileData {
        let n = chi_square.len();
        ProfileData { parameter: "p".into(), unit: "1".into(), truth: 1.0, factor: vec![1.0; n], value: vec![1.0; n], chi_square }
    }

    /// Two profiles of one data set whose own minima differ: both are read
    /// against the lower one, so only it touches Δχ² = 0.
    #[test]
    fn profiles_of_one_data_set_share_their_baseline() {
        let profiles = [profile(vec![325.0, 320.5, 330.0]), profile(vec![340.0, 319.4, 321.0])];
        let least = least_chi_square(&profiles);
        assert_eq!(least, 319.4);
        let (a, b) = (profiles[0].delta_chi_square(least), profiles[1].delta_chi_square(least));
        assert!((a[1] - 1.1).abs() < 1e-12 && b[1] == 0.0, "{a:?} {b:?}");
    }
}
