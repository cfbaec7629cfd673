//! The validation chapter: every comparison of the model with a published
//! measurement (`experiments/validation/measurements.toml`), computed by the
//! model crates' `validation` modules, written to
//! `results/validation/validation.json` and drawn as `paper/validation.md`.
//!
//! The page holds numbers only as they come out of these functions; the
//! reasons each comparison agrees or misses are in
//! `experiments/validation/NOTES.md`, which the page links.

use crate::printable::Printable;
use kick_3d::validation::CurveKicks;
use kick_core::measurements::{Comparison, Measured, Measurements};
use kick_core::{short, Scenario};
use kick_flight::validation::{DragCrisisModel, FreeKicks, FREE_KICK_DISTANCE, FREE_KICK_ELEVATION};
use kick_identify::validation::Implied;
use serde::Serialize;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// Every comparison and the model runs behind them.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Validation {
    /// The measurement file read.
    pub measurements_file: String,
    pub sources: usize,
    pub measurements: usize,
    /// The 1D contact at Table 1's baseline (`accurate`).
    pub contact: Vec<Comparison>,
    /// Stiffness and foot mass implied by the measured contact time, ball
    /// speed and peak force, under three law setups.
    pub implied: Vec<Implied>,
    /// Spin against offset and friction (3D, baseline contact).
    pub curve_kicks: CurveKicks,
    /// The default C_D(Re)'s crisis and the default ball.
    pub drag_crisis_model: DragCrisisModel,
    pub flight: Vec<Comparison>,
    /// Free kicks over the measured launch speeds and spins.
    pub free_kicks: FreeKicks,
    /// Every source cited by a row: (key, citation).
    pub citations: Vec<(String, String)>,
    #[serde(skip)]
    pub written: Vec<PathBuf>,
}

/// Compare the model with the measurements in `measurements`.
pub fn validate(measurements: &Path) -> Result<Validation, String> {
    let m = Measurements::load(measurements).map_err(|e| e.to_string())?;
    let baseline = Scenario::baseline();
    let contact = kick_identify::validation::contact_comparisons(&m, &baseline).map_err(|e| e.to_string())?;
    let implied = kick_identify::validation::implied_parameter_study(&m).map_err(|e| e.to_string())?;
    let curve_kicks = kick_3d::validation::curve_kick_comparisons(&m, &baseline).map_err(|e| e.to_string())?;
    let mut flight = kick_flight::validation::drag_crisis_comparisons(&m).map_err(|e| e.to_string())?;
    flight.extend(kick_flight::validation::ball_comparisons(&m).map_err(|e| e.to_string())?);
    let free_kicks =
        kick_flight::validation::free_kicks(&m, FREE_KICK_ELEVATION, FREE_KICK_DISTANCE).map_err(|e| e.to_string())?;
    let mut keys: Vec<&str> = contact
        .iter()
        .chain(&curve_kicks.comparisons)
        .chain(&flight)
        .flat_map(|c| c.measured.source.split('/'))
        .chain(free_kicks.launch_speed.source.split('/'))
        .chain(free_kicks.launch_spin.source.split('/'))
        .collect();
    keys.sort_unstable();
    keys.dedup();
    let citations = keys.iter().filter_map(|k| m.source(k).map(|s| (k.to_string(), s.citation()))).collect();
    Ok(Validation {
        measurements_file: measurements.display().to_string(),
        sources: m.sources.len(),
        measurements: m.measurements.len(),
        contact,
        implied,
        curve_kicks,
        drag_crisis_model: kick_flight::validation::drag_crisis_model(),
        flight,
        free_kicks,
        citations,
        written: Vec::new(),
    })
}

/// [`validate`], then write `out/validation.json` and `page` (links relative to the page).
pub fn write(measurements: &Path, out: &Path, page: &Path, notes: &Path) -> Result<Validation, String> {
    let mut v = validate(measurements)?;
    let json_path = out.join("validation.json");
    crate::output::write(&json_path, crate::printable::json(&v)?).map_err(|e| e.to_string())?;
    let page_dir = page.parent().unwrap_or(Path::new("."));
    // Inputs are read where they are, the page may be written into a scratch
    // folder (`reproduce --check`): link them from the page's folder name, so
    // both give the same bytes.
    let input_from = if page_dir.is_absolute() { page_dir.file_name().map_or(Path::new("."), Path::new) } else { page_dir };
    let text = v.markdown(
        &crate::links::relative(page_dir, &json_path),
        &crate::links::relative(input_from, measurements),
        &crate::links::relative(input_from, notes),
    );
    crate::output::write(page, text).map_err(|e| e.to_string())?;
    v.written = vec![json_path, page.to_path_buf()];
    Ok(v)
}

fn interval(m: &Measured) -> String {
    match (m.low, m.high) {
        (Some(lo), Some(hi)) if lo == hi => format!("{}", short(lo)),
        (Some(lo), Some(hi)) => format!("{} – {}", short(lo), short(hi)),
        _ => "(in words)".to_string(),
    }
}

/// Comparison rows as a Markdown table.
fn table(w: &mut String, rows: &[Comparison]) {
    let _ = writeln!(w, "| quantity | measured | model | unit | model / midpoint | inside? | source (checked) | conditions |");
    let _ = writeln!(w, "|---|---|---|---|---|---|---|---|");
    for c in rows {
        let ratio = c.ratio.map_or("–".to_string(), |r| format!("{}", short(r)));
        let inside = match c.agrees() {
            Some(true) => "yes".to_string(),
            Some(false) => format!("no ({:+})", short(c.outside.unwrap_or(f64::NAN))),
            None => "–".to_string(),
        };
        let _ = writeln!(
            w,
            "| {} | {} | {} | {} | {} | {} | `{}` ({}) | {} |",
            c.quantity,
            interval(&c.measured),
            short(c.model),
            c.measured.unit,
            ratio,
            inside,
            c.measured.key,
            c.measured.checked,
            c.note.replace('|', "/")
        );
    }
}

impl Validation {
    /// All comparison rows (contact, curve kicks, flight).
    pub fn rows(&self) -> impl Iterator<Item = &Comparison> {
        self.contact.iter().chain(&self.curve_kicks.comparisons).chain(&self.flight)
    }

    /// The page; `data`, `file` and `notes` are the JSON, the measurement
    /// file and the notes as links from the page.
    pub fn markdown(&self, data: &str, file: &str, notes: &str) -> String {
        let mut w = String::new();
        let rows: Vec<&Comparison> = self.rows().collect();
        let ranged = rows.iter().filter(|c| c.agrees().is_some()).count();
        let inside = rows.iter().filter(|c| c.agrees() == Some(true)).count();
        let _ = writeln!(w, "# Validation: the model beside published measurements\n");
        let _ = writeln!(
            w,
            "Generated by `kick reproduce` from [{file}]({file}) ({} measurements from {} sources, each with its \
             citation, where it stands in the source and how far it was checked: *text*, *abstract*, *secondary* \
             or *unchecked*). Data: [{data}]({data}). Why each row agrees or misses, and what stays unchecked: \
             [the notes]({notes}).\n",
            self.measurements, self.sources
        );
        let _ = writeln!(
            w,
            "{inside} of {ranged} comparisons with a measured interval fall inside it. \"model / midpoint\" divides \
             the model by the interval's midpoint; \"inside?\" gives the signed miss beyond the nearest bound. \
             Measured values are in SI units.\n"
        );
        let _ = writeln!(w, "## The 1D contact at Table 1's baseline\n");
        let _ = writeln!(w, "`accurate` solver, paper's law, m_f = 1.2 kg, v_f = 20 m/s.\n");
        table(&mut w, &self.contact);
        let _ = writeln!(w, "\n## Stiffness and foot mass implied by the measurements\n");
        let _ = writeln!(
            w,
            "Least squares (`kick_identify`) on the measured contact time, ball speed and peak force, with \
             stated σ; σ scaled by √(χ²/dof) where dof > 0.\n"
        );
        let _ = writeln!(w, "| law | e | v_f (m/s) | parameter | value | unit | σ | σ scaled | χ² | dof |");
        let _ = writeln!(w, "|---|---|---|---|---|---|---|---|---|---|");
        for i in &self.implied {
            for e in &i.estimates {
                let _ = writeln!(
                    w,
                    "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |",
                    i.law.name(),
                    i.restitution.map_or("–".to_string(), |e| format!("{}", short(e))),
                    short(i.foot_speed),
                    e.parameter.name(),
                    short(e.value),
                    e.unit,
                    short(e.sigma),
                    e.sigma_scaled.map_or("–".to_string(), |s| format!("{}", short(s))),
                    short(i.chi_square),
                    i.degrees_of_freedom
                );
            }
        }
        let _ = writeln!(w, "\n## Curve kicks: spin against offset and friction\n");
        table(&mut w, &self.curve_kicks.comparisons);
        let frictions: Vec<String> =
            self.curve_kicks.curves.iter().map(|c| c.first().map_or("?".into(), |p| format!("{}", short(p.friction)))).collect();
        let _ = writeln!(w, "\nSpin (rad/s) and ball speed (m/s) against offset, baseline contact, by friction μ:\n");
        let _ = write!(w, "| offset (mm) |");
        for mu in &frictions {
            let _ = write!(w, " spin μ={mu} |");
        }
        for mu in &frictions {
            let _ = write!(w, " speed μ={mu} |");
        }
        let _ = writeln!(w, "\n|---|{}", "---|".repeat(2 * frictions.len()));
        let n = self.curve_kicks.curves.first().map_or(0, Vec::len);
        for i in 0..n {
            let _ = write!(w, "| {} |", short(1e3 * self.curve_kicks.curves[0][i].offset));
            for c in &self.curve_kicks.curves {
                let _ = write!(w, " {} |", short(c[i].spin));
            }
            for c in &self.curve_kicks.curves {
                let _ = write!(w, " {} |", short(c[i].speed));
            }
            let _ = writeln!(w);
        }
        for p in &self.curve_kicks.largest {
            let _ = writeln!(
                w,
                "\nLargest spin at μ = {}: {} rad/s ({} rev/s) at {} mm, ball speed {} m/s.",
                short(p.friction),
                short(p.spin),
                short(p.spin / std::f64::consts::TAU),
                short(1e3 * p.offset),
                short(p.speed)
            );
        }
        let _ = writeln!(w, "\n## Flight: the drag crisis and the ball\n");
        table(&mut w, &self.flight);
        let f = &self.free_kicks;
        let _ = writeln!(w, "\n## Free kicks\n");
        let _ = writeln!(
            w,
            "Launched at {}° with sidespin about the vertical; lateral offset where the ball crosses x = {} m, \
             beside an independent estimate (the horizontal path as a circle of the launch curvature). Speeds \
             from `{}` ({}), spins from `{}` ({}).\n",
            short(f.launch_angle),
            short(f.distance),
            f.launch_speed.key,
            f.launch_speed.checked,
            f.launch_spin.key,
            f.launch_spin.checked
        );
        let _ = writeln!(w, "| speed (m/s) | spin (rev/s) | lateral offset (m) | circle estimate (m) | height (m) | time (s) |");
        let _ = writeln!(w, "|---|---|---|---|---|---|");
        for k in &f.kicks {
            let _ = writeln!(
                w,
                "| {} | {} | {} | {} | {} | {} |",
                short(k.speed),
                short(k.spin / std::f64::consts::TAU),
                short(k.lateral_offset),
                short(k.circle_estimate),
                short(k.height),
                short(k.time)
            );
        }
        let _ = writeln!(w, "\n## Sources\n");
        for (key, citation) in &self.citations {
            let _ = writeln!(w, "- `{key}`: {citation}");
        }
        w
    }
}

impl Printable for Validation {
    fn text(&self) -> String {
        let rows: Vec<&Comparison> = self.rows().collect();
        let ranged = rows.iter().filter(|c| c.agrees().is_some()).count();
        let inside = rows.iter().filter(|c| c.agrees() == Some(true)).count();
        format!(
            "validation: {} measurements from {} sources; {inside} of {ranged} ranged comparisons inside the measured interval\n",
            self.measurements, self.sources
        )
    }
    fn written(&self) -> &[PathBuf] {
        &self.written
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The page carries every comparison row and every cited source, and its
    /// counts agree with the rows (an independent count over the JSON).
    #[test]
    fn page_lists_every_row_and_counts_them() {
        let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..").join(kick_core::measurements::MEASUREMENTS_FILE);
        let v = validate(&file).expect("the committed measurements validate");
        let page = v.markdown("v.json", "m.toml", "NOTES.md");
        let json: serde_json::Value = serde_json::to_value(&v).unwrap();
        let mut rows = 0;
        let mut inside = 0;
        let mut ranged = 0;
        for group in [&json["contact"], &json["curve_kicks"]["comparisons"], &json["flight"]] {
            for row in group.as_array().unwrap() {
                rows += 1;
                assert!(page.contains(&format!("`{}`", row["measured"]["key"].as_str().unwrap())));
                if let (Some(lo), Some(hi), Some(model)) =
                    (row["measured"]["low"].as_f64(), row["measured"]["high"].as_f64(), row["model"].as_f64())
                {
                    ranged += 1;
                    inside += usize::from(lo <= model && model <= hi);
                }
            }
        }
        assert!(rows >= 15, "{rows} rows");
        assert!(page.contains(&format!("{inside} of {ranged} comparisons")), "{inside} of {ranged}");
        for (key, _) in &v.citations {
            assert!(v.rows().any(|c| c.measured.source.split('/').any(|s| s == key))
                || f_sources(&v).any(|s| s == key));
            assert!(page.contains(&format!("- `{key}`")));
        }
        // The table prints each model value in the short form.
        assert!(page.contains(&format!("| {} |", short(v.contact[0].model))));
        assert!(!page.contains("NaN"));
    }

    fn f_sources(v: &Validation) -> impl Iterator<Item = &str> {
        v.free_kicks.launch_speed.source.split('/').chain(v.free_kicks.launch_spin.source.split('/'))
    }
}
