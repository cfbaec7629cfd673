//! The patch study's files (`kick_study::patch`): the spin against offset
//! (`3d_patch_spin.h5`, layout `patch-spin`) and the history of one
//! off-center kick (`3d_patch_history.h5`, the history layout with the
//! patch's columns), each written whole or not at all.

use crate::h5::Column;
use crate::history::HistoryRequest;
use crate::{Provenance, ResultFile, ResultWriter, StoreError};
use kick_core::{short, LawKind, Spacing};
use kick_study::patch::{asai_claims, compute, shared_fixed, AsaiClaims, Curve, SpinData, CONTACTS, HISTORY_SAMPLES};
use std::path::{Path, PathBuf};

/// The spin file, below the results directory.
pub const SPIN_FILE: &str = "3d_patch_spin.h5";
/// The history file.
pub const HISTORY_FILE: &str = "3d_patch_history.h5";

fn curve_group(curve: &Curve) -> String {
    format!("curves/{}/mu_{}", CONTACTS[curve.contact].key, short(curve.friction))
}

/// Write `data` to `path` (whole or not at all), with the parameters the
/// kicks share under `/fixed` and `command` in the provenance.
pub fn write_spin(path: &Path, data: &SpinData, asai: &AsaiClaims, command: &str) -> Result<PathBuf, StoreError> {
    let provenance = Provenance::now("3d_patch_spin", "kick reproduce (patch)", command);
    let w = ResultWriter::create(path, &provenance, &crate::layouts::PATCH_SPIN)?;
    w.text("", "description", "spin against offset, shell ball on Table 1's foot: point contact against the patch on a cap")?;
    w.text("", "law", LawKind::Shell.name())?;
    w.text("", "solver", "accurate-3d")?;
    // The parameters every kick shares, offset and friction aside.
    for (name, unit, values) in shared_fixed()? {
        w.column("fixed", &Column::new(&name, &unit), &values)?;
    }
    w.column("grid", &Column::new("offset", "m"), &data.offsets)?;
    // What the figure is drawn beside: Asai et al.'s (2002) published numbers.
    w.scalar("asai2002", "friction_gain", "rad/s", asai.friction_gain)?;
    w.scalar("asai2002", "peak_offset", "m", asai.peak_offset)?;
    w.text("asai2002", "source", &asai.source)?;
    for curve in &data.curves {
        let g = curve_group(curve);
        let contact = &CONTACTS[curve.contact];
        w.text(&g, "contact", &contact.description())?;
        w.scalar(&g, "friction", "1", curve.friction)?;
        w.scalar(&g, "patch_contact", "1", if contact.patch { 1.0 } else { 0.0 })?;
        w.scalar(&g, "instep_radius", "m", contact.instep_radius.unwrap_or(0.0))?;
        for (name, unit, values) in [
            ("offset", "m", &curve.offset),
            ("spin_z", "rad/s", &curve.spin_z),
            ("spin", "rad/s", &curve.spin),
            ("speed", "m/s", &curve.speed),
            ("launch_azimuth", "deg", &curve.launch_azimuth),
            ("contact_time", "s", &curve.contact_time),
        ] {
            w.column(&g, &Column::new(name, unit), values)?;
        }
        let (at, why): (Vec<f64>, Vec<String>) = curve.refused.iter().cloned().unzip();
        w.column(&g, &Column::new("refused_offset", "m"), &at)?;
        w.strings(&g, "refused_reason", &why)?;
    }
    Ok(w.finish()?)
}

/// The spin file read back.
pub fn read_spin(path: &Path) -> Result<SpinData, StoreError> {
    let f = ResultFile::open(path)?;
    let offsets = f.values("grid/offset")?;
    let mut curves = Vec::new();
    for (c, contact) in CONTACTS.iter().enumerate() {
        let group = format!("curves/{}", contact.key);
        let mut found = Vec::new();
        for member in f.members(&group)? {
            let g = format!("{group}/{member}");
            let v = |name: &str| f.values(&format!("{g}/{name}"));
            let refused_at = v("refused_offset")?;
            let reasons = f.strings(&format!("{g}/refused_reason"))?;
            found.push(Curve {
                contact: c,
                friction: f.scalar(&format!("{g}/friction"))?,
                offset: v("offset")?,
                spin_z: v("spin_z")?,
                spin: v("spin")?,
                speed: v("speed")?,
                launch_azimuth: v("launch_azimuth")?,
                contact_time: v("contact_time")?,
                refused: refused_at.into_iter().zip(reasons).collect(),
            });
        }
        found.sort_by(|a, b| a.friction.total_cmp(&b.friction));
        curves.extend(found);
    }
    Ok(SpinData { offsets, curves })
}

/// The claims as the spin file holds them.
pub fn read_asai(path: &Path) -> Result<AsaiClaims, StoreError> {
    let f = ResultFile::open(path)?;
    Ok(AsaiClaims {
        friction_gain: f.scalar("asai2002/friction_gain")?,
        peak_offset: f.scalar("asai2002/peak_offset")?,
        source: f.text("asai2002", "source")?,
    })
}

/// `kick reproduce`'s patch step: solves the spin figure's kicks and the
/// history's kick and writes both files under `out`; returns them.
pub fn run(out: &Path, measurements: &Path, command: &str) -> Result<Vec<PathBuf>, StoreError> {
    let data = compute()?;
    let mut written = vec![write_spin(&out.join(SPIN_FILE), &data, &asai_claims(&crate::measurements::read(measurements)?)?, command)?];
    let path = out.join(HISTORY_FILE);
    let request = HistoryRequest { path, spacing: Spacing::Count(HISTORY_SAMPLES), open: crate::history::open };
    let run = kick_study::simulate::simulate3d(&kick_study::patch::history_spec(), "accurate", None, Some(&request), None)?;
    written.extend(run.written);
    Ok(written)
}

#[cfg(test)]
mod tests {
    use super::*;
    use kick_3d::{Accurate3d, Kick3d, Kick3dSpec};
    use kick_core::Scenario;
    use kick_study::patch::FRICTIONS;

    fn scratch(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("kick-store-patch-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        dir
    }

    fn measurements() -> PathBuf {
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../experiments/validation/measurements.toml")
    }

    fn rel(a: f64, b: f64) -> f64 {
        (a - b).abs() / b.abs().max(1e-300)
    }

    /// The spin file's kicks are the solver's: at a few offsets each curve's
    /// spin, speed and azimuth equal a kick built here from its parameters
    /// (the shell ball, Table 1's foot, the instep spelled out) to 1e-12;
    /// every offset of the grid is either solved or refused with its
    /// reason; the history file is written beside it, and Asai et al.'s
    /// claims read back as the measurement file gives them.
    #[test]
    fn the_spin_file_holds_the_solvers_kicks() {
        let dir = scratch("file");
        let written = run(&dir, &measurements(), "kick reproduce --only patch").unwrap();
        let names: Vec<String> = written.iter().map(|p| p.file_name().unwrap().to_string_lossy().into_owned()).collect();
        assert_eq!(names, ["3d_patch_spin.h5", "3d_patch_history.h5"]);
        let data = read_spin(&dir.join(SPIN_FILE)).unwrap();
        assert_eq!(data.curves.len(), CONTACTS.len() * FRICTIONS.len());
        let base = Scenario::baseline().with_law(LawKind::Shell, None).unwrap();
        for k in &data.curves {
            let mut all: Vec<f64> = k.offset.iter().copied().chain(k.refused.iter().map(|r| r.0)).collect();
            all.sort_by(f64::total_cmp);
            assert_eq!(all, data.offsets, "{:?} μ = {}", CONTACTS[k.contact].key, k.friction);
            assert!(k.refused.iter().all(|(_, why)| !why.is_empty()));
            for e in [0.02, 0.05, 0.08] {
                let i = k.offset.iter().position(|&x| x == e).expect("solved");
                let spec = if k.contact == 0 {
                    Kick3dSpec { offset: Some(e), friction: Some(k.friction), ..Kick3dSpec::default() }
                } else {
                    Kick3dSpec {
                        offset: Some(e),
                        friction: Some(k.friction),
                        patch_contact: Some(true),
                        instep_radius: Some(0.15),
                        face_yaw_deg: Some(0.0),
                        ..Kick3dSpec::default()
                    }
                };
                let o = Accurate3d::default().solve(&Kick3d::new(base, &spec).unwrap()).unwrap();
                let size = (o.spin[0].powi(2) + o.spin[1].powi(2) + o.spin[2].powi(2)).sqrt();
                // ω_z against |ω| (zero at μ = 0 on the point contact).
                assert!((k.spin_z[i] - o.spin[2]).abs() <= 1e-12 * size.max(1.0), "{e} {}: {} vs {}", k.friction, k.spin_z[i], o.spin[2]);
                assert!((k.spin[i] - size).abs() <= 1e-12 * size.max(1.0));
                assert!(rel(k.speed[i], o.speed) <= 1e-12 && rel(k.contact_time[i], o.contact_time) <= 1e-12);
                assert!((k.launch_azimuth[i] - o.launch_azimuth).abs() <= 1e-12 * o.launch_azimuth.abs().max(1.0));
            }
        }
        assert_eq!(read_asai(&dir.join(SPIN_FILE)).unwrap(), asai_claims(&crate::measurements::read(&measurements()).unwrap()).unwrap());
        let _ = std::fs::remove_dir_all(&dir);
    }
}
