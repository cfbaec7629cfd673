//! `kick laws`: the contact-law family on Table 2's scenarios, written to
//! `DIR/laws.h5` (layout in [`crate::identify::files`]); kick-paper draws
//! its figure from that file.

use crate::printable::Printable;
use crate::{Provenance, StoreError};
use kick_compliant::Accurate;
use kick_core::{sig, Scenario};
use kick_identify::laws::{compare, restitution_table, LawComparison};
use serde::Serialize;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// Where the scenarios come from, how finely pulses are sampled, where files go.
#[derive(Debug, Clone, PartialEq)]
pub struct LawsSettings {
    /// Table 2 scenario file with the rows' parameters.
    pub scenarios: PathBuf,
    /// Write laws.h5 here (and kick-paper laws.png/svg, drawn from it).
    pub out: Option<PathBuf>,
    /// Pulse samples per undamped contact time (at most).
    pub samples: u32,
}

/// Every law on every scenario (JSON: the comparisons).
#[derive(Debug, Clone, Serialize)]
#[serde(transparent)]
pub struct LawsReport {
    pub comparisons: Vec<LawComparison>,
    #[serde(skip)]
    pub written: Vec<PathBuf>,
}

/// The contact laws' file, below `--out`.
pub const LAWS_FILE: &str = "laws.h5";

/// The contact laws on Table 2's scenarios; with `out`, laws.h5.
pub fn laws(settings: &LawsSettings) -> Result<LawsReport, StoreError> {
    if let Some(dir) = &settings.out {
        let files = [dir.join(LAWS_FILE)];
        let targets = files.each_ref().map(|path| crate::output::Target::File { flag: "--out", path });
        crate::output::check_paths(&targets, &[&settings.scenarios])?;
    }
    let comparisons = comparisons(settings)?;
    let written = match &settings.out {
        Some(dir) => write(settings, &comparisons, dir)?,
        None => Vec::new(),
    };
    Ok(LawsReport { comparisons, written })
}

fn comparisons(args: &LawsSettings) -> Result<Vec<LawComparison>, StoreError> {
    if !(10..=100_000).contains(&args.samples) {
        return Err(StoreError::Flag { flag: "--samples", message: format!("--samples must be in 10..=100000 (got {})", args.samples) });
    }
    let file = crate::table2::load(&args.scenarios)?;
    let solver = Accurate::default();
    file.scenarios()?
        .iter()
        .map(|(name, s)| {
            compare(name, s, &solver, s.elastic_contact_time() / args.samples as f64)
                .map_err(|source| StoreError::Row { name: name.clone(), source })
        })
        .collect()
}

/// Targets of the restitution table (how far each χ formula misses its target).
pub const FORMULA_TARGETS: [f64; 7] = [0.99, 0.95, 0.9, 0.8, 0.7, 0.5, 0.3];

/// Write `dir/laws.h5`.
fn write(args: &LawsSettings, all: &[LawComparison], dir: &Path) -> Result<Vec<PathBuf>, StoreError> {
    std::fs::create_dir_all(dir).map_err(|source| StoreError::CreateDir { path: dir.to_path_buf(), source })?;
    let scenarios = crate::table2::read_text(&args.scenarios)?;
    let text = format!(
        "# kick laws --scenarios {} --samples {}
{scenarios}",
        args.scenarios.display(),
        args.samples
    );
    let provenance = Provenance::now("laws", &args.scenarios.display().to_string(), &text);
    let formulas = restitution_table(&Scenario::baseline(), &FORMULA_TARGETS, &Accurate::default())?;
    Ok(vec![crate::identify::files::write_laws(&dir.join(LAWS_FILE), &provenance, all, args.samples, &FORMULA_TARGETS, &formulas)?])
}

impl Printable for LawsReport {
    fn text(&self) -> String {
        let mut w = String::new();
        for c in &self.comparisons {
            let _ = writeln!(w, "{} (target e = paper's law's e = {})", c.name, sig(c.restitution));
            let _ = writeln!(
                w,
                "  {:<20} {:>10} {:>10} {:>10} {:>10} {:>10} {:>10}",
                "law", "e", "v_b+ m/s", "F(0+) N", "peak N", "t_c ms", "δmax mm"
            );
            for r in &c.runs {
                let o = &r.outcome;
                let _ = writeln!(
                    w,
                    "  {:<20} {:>10} {:>10} {:>10} {:>10} {:>10} {:>10}",
                    r.law.name(),
                    sig(o.restitution),
                    sig(o.v_ball_out),
                    sig(r.pulse.first().map_or(0.0, |p| p.1)),
                    sig(o.peak_force),
                    sig(o.contact_time * 1e3),
                    sig(o.max_compression * 1e3)
                );
            }
        }
        w
    }
    fn written(&self) -> &[PathBuf] {
        &self.written
    }
}
