//! The contact patch on the 3D page (issue 22, item 8): spin against offset
//! for the shell ball's point contact and its patch on a cap, beside Asai et
//! al. (2002), and one off-center kick's patch over time. Both are written
//! to HDF5 first (`OUT/3d_patch_spin.h5`, layout `patch-spin`;
//! `OUT/3d_patch_history.h5`, the history layout with the patch's columns),
//! then drawn and discussed from those files: every number on the page is
//! read from them when it is written.

use crate::figures::{color, save_grid, FigureError, Panel, Series};
use crate::links::relative;
use crate::{Provenance, ResultFile, ResultWriter};
use kick_3d::{ContactState, Kick3d, Kick3dError, Kick3dSpec, KickSpec};
use kick_core::measurements::Measurements;
use kick_core::{short, LawKind, Scenario, Spacing};
use kick_store::h5::Column;
use kick_store::history::HistoryRequest;
use plotters::prelude::{RGBColor, SeriesLabelPosition};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// The spin file and figure, below the results and figures directories.
pub const SPIN_FILE: &str = "3d_patch_spin.h5";
pub const SPIN_FIGURE: &str = "3d_patch_spin";
/// The history file and figure.
pub const HISTORY_FILE: &str = "3d_patch_history.h5";
pub const HISTORY_FIGURE: &str = "3d_patch_history";

/// The cap's radius of curvature, m: an assumption (no published instep
/// curvature was found, `kick_3d::patch`), of the order of the ball's
/// radius and at least the face's half-extents, as the instep requires.
pub const CAP_RADIUS: f64 = kick_3d::validation::ASSUMED_INSTEP_RADIUS;
/// Friction coefficients of the curves (Asai et al. compare 0 and 1).
pub const FRICTIONS: [f64; 3] = [0.0, 0.5, 1.0];
/// Offsets: 0 to 110 mm (the ball's radius) in 5 mm steps.
pub const OFFSET_STEP: f64 = 0.005;
pub const OFFSETS: usize = 23;
/// The history's kick: 5 cm off the swing line, μ = 0.5, patch on the cap.
pub const HISTORY_OFFSET: f64 = 0.05;
pub const HISTORY_FRICTION: f64 = 0.5;
/// Rows of the history: grip/slip shaded to 1/2000 of the contact.
pub const HISTORY_SAMPLES: usize = 2001;

/// One contact model of the spin figure.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Contact {
    /// Its group below `/curves`.
    pub key: &'static str,
    pub label: &'static str,
    pub patch: bool,
    /// r_i, m (None: the flat face).
    pub instep_radius: Option<f64>,
    /// ψ, degrees (None: asin(e/R), the knife edge).
    pub face_yaw_deg: Option<f64>,
}

/// The level below (the rigid sphere's point contact on the knife-edge
/// face, with the shell ball's law) and the patch on a cap square to the swing.
pub const CONTACTS: [Contact; 2] = [
    Contact { key: "point", label: "point contact (knife edge)", patch: false, instep_radius: None, face_yaw_deg: None },
    Contact { key: "patch_cap", label: "patch on a cap", patch: true, instep_radius: Some(CAP_RADIUS), face_yaw_deg: Some(0.0) },
];

/// The shell ball (FIFA-calibrated defaults) on Table 1's foot.
pub fn shell() -> Result<Scenario, String> {
    Scenario::baseline().with_law(LawKind::Shell, None).map_err(|e| e.to_string())
}

impl Contact {
    /// The kick's spec at offset `e`, friction `mu`.
    pub fn spec(&self, offset: f64, friction: f64) -> Kick3dSpec {
        Kick3dSpec {
            offset: Some(offset),
            friction: Some(friction),
            patch_contact: self.patch.then_some(true),
            instep_radius: self.instep_radius,
            face_yaw_deg: self.face_yaw_deg,
            ..Kick3dSpec::default()
        }
    }
    /// What the contact is, in words (the file's `contact` attribute).
    pub fn description(&self) -> String {
        match (self.patch, self.instep_radius) {
            (true, Some(r)) => format!(
                "normal force spread over the patch, instep a sphere cap of radius {} m (an assumption) square to the swing (face_yaw 0)",
                short(r)
            ),
            (true, None) => "normal force spread over the patch on the flat knife-edge face".into(),
            (false, _) => {
                "point contact (rigid sphere: the normal force through the centre), flat face tilted by asin(e/R) (knife edge)".into()
            }
        }
    }
}

/// The offsets asked for, m.
pub fn offsets() -> Vec<f64> {
    (0..OFFSETS).map(|i| OFFSET_STEP * i as f64).collect()
}

/// One curve: the kicks of one contact model and friction that were solved.
#[derive(Debug, Clone, PartialEq)]
pub struct Curve {
    /// Index into [`CONTACTS`].
    pub contact: usize,
    pub friction: f64,
    pub offset: Vec<f64>,
    /// ω_z, rad/s (z up).
    pub spin_z: Vec<f64>,
    /// |ω|, rad/s.
    pub spin: Vec<f64>,
    pub speed: Vec<f64>,
    /// deg.
    pub launch_azimuth: Vec<f64>,
    pub contact_time: Vec<f64>,
    /// Offsets left out and why.
    pub refused: Vec<(f64, String)>,
}

/// The spin file's content.
#[derive(Debug, Clone, PartialEq)]
pub struct SpinData {
    pub offsets: Vec<f64>,
    pub curves: Vec<Curve>,
}

fn solve(base: Scenario, contact: &Contact, offset: f64, friction: f64) -> Result<kick_3d::Outcome3d, Kick3dError> {
    kick_3d::Accurate3d::default().solve(&Kick3d::new(base, &contact.spec(offset, friction))?)
}

/// Every kick of the figure, solved (accurate path); a refused kick is
/// left out of its curve with its reason. A numerical failure is an error.
pub fn compute() -> Result<SpinData, String> {
    let offsets = offsets();
    let base = shell()?;
    let mut curves = Vec::new();
    for (c, contact) in CONTACTS.iter().enumerate() {
        for &friction in &FRICTIONS {
            let mut curve = Curve {
                contact: c,
                friction,
                offset: Vec::new(),
                spin_z: Vec::new(),
                spin: Vec::new(),
                speed: Vec::new(),
                launch_azimuth: Vec::new(),
                contact_time: Vec::new(),
                refused: Vec::new(),
            };
            for &e in &offsets {
                match solve(base, contact, e, friction) {
                    Ok(o) => {
                        let [x, y, z] = o.spin;
                        curve.offset.push(e);
                        curve.spin_z.push(z);
                        curve.spin.push((x * x + y * y + z * z).sqrt());
                        curve.speed.push(o.speed);
                        curve.launch_azimuth.push(o.launch_azimuth);
                        curve.contact_time.push(o.contact_time);
                    }
                    Err(err) if err.status() == kick_core::Status::Refused => curve.refused.push((e, err.to_string())),
                    Err(err) => return Err(format!("{}, e = {e} m, μ = {friction}: {err}", contact.label)),
                }
            }
            curves.push(curve);
        }
    }
    Ok(SpinData { offsets, curves })
}

fn h5(e: impl std::fmt::Display) -> String {
    e.to_string()
}

fn curve_group(curve: &Curve) -> String {
    format!("curves/{}/mu_{}", CONTACTS[curve.contact].key, short(curve.friction))
}

/// Write `data` to `path` (whole or not at all), with the parameters the
/// kicks share under `/fixed` and `command` in the provenance.
pub fn write_spin(path: &Path, data: &SpinData, asai: &AsaiClaims, command: &str) -> Result<PathBuf, String> {
    let provenance = Provenance::now("3d_patch_spin", "kick reproduce (patch)", command);
    let w = ResultWriter::create(path, &provenance, &kick_store::layouts::PATCH_SPIN).map_err(h5)?;
    w.text("", "description", "spin against offset, shell ball on Table 1's foot: point contact against the patch on a cap").map_err(h5)?;
    w.text("", "law", LawKind::Shell.name()).map_err(h5)?;
    w.text("", "solver", "accurate-3d").map_err(h5)?;
    // The parameters every kick shares: those equal in both contacts' kicks, offset and friction aside.
    let base = shell()?;
    let metas: Vec<_> = CONTACTS
        .iter()
        .map(|c| Kick3d::new(base, &c.spec(HISTORY_OFFSET, HISTORY_FRICTION)).map(|k| kick_study::simulate::meta_3d(&k).fixed))
        .collect::<Result<_, _>>()
        .map_err(h5)?;
    for (name, unit, values) in &metas[0] {
        let shared = metas[1..].iter().all(|m| m.iter().any(|(n, _, v)| n == name && v == values));
        if shared && name != "offset" && name != "friction" {
            w.column("fixed", &Column::new(name, unit), values).map_err(h5)?;
        }
    }
    w.column("grid", &Column::new("offset", "m"), &data.offsets).map_err(h5)?;
    // What the figure is drawn beside: Asai et al.'s (2002) published numbers.
    w.scalar("asai2002", "friction_gain", "rad/s", asai.friction_gain).map_err(h5)?;
    w.scalar("asai2002", "peak_offset", "m", asai.peak_offset).map_err(h5)?;
    w.text("asai2002", "source", &asai.source).map_err(h5)?;
    for curve in &data.curves {
        let g = curve_group(curve);
        let contact = &CONTACTS[curve.contact];
        w.text(&g, "contact", &contact.description()).map_err(h5)?;
        w.scalar(&g, "friction", "1", curve.friction).map_err(h5)?;
        w.scalar(&g, "patch_contact", "1", if contact.patch { 1.0 } else { 0.0 }).map_err(h5)?;
        w.scalar(&g, "instep_radius", "m", contact.instep_radius.unwrap_or(0.0)).map_err(h5)?;
        for (name, unit, values) in [
            ("offset", "m", &curve.offset),
            ("spin_z", "rad/s", &curve.spin_z),
            ("spin", "rad/s", &curve.spin),
            ("speed", "m/s", &curve.speed),
            ("launch_azimuth", "deg", &curve.launch_azimuth),
            ("contact_time", "s", &curve.contact_time),
        ] {
            w.column(&g, &Column::new(name, unit), values).map_err(h5)?;
        }
        let (at, why): (Vec<f64>, Vec<String>) = curve.refused.iter().cloned().unzip();
        w.column(&g, &Column::new("refused_offset", "m"), &at).map_err(h5)?;
        w.strings(&g, "refused_reason", &why).map_err(h5)?;
    }
    w.finish().map_err(h5)
}

/// The spin file read back.
pub fn read_spin(path: &Path) -> Result<SpinData, String> {
    let f = ResultFile::open(path).map_err(h5)?;
    let offsets = f.values("grid/offset").map_err(h5)?;
    let mut curves = Vec::new();
    for (c, contact) in CONTACTS.iter().enumerate() {
        let group = format!("curves/{}", contact.key);
        let mut found = Vec::new();
        for member in f.members(&group).map_err(h5)? {
            let g = format!("{group}/{member}");
            let v = |name: &str| f.values(&format!("{g}/{name}")).map_err(h5);
            let refused_at = v("refused_offset")?;
            let reasons = f.strings(&format!("{g}/refused_reason")).map_err(h5)?;
            found.push(Curve {
                contact: c,
                friction: f.scalar(&format!("{g}/friction")).map_err(h5)?,
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

impl SpinData {
    /// The curve of contact `c` at friction `mu`.
    pub fn curve(&self, contact: usize, friction: f64) -> Option<&Curve> {
        self.curves.iter().find(|k| k.contact == contact && k.friction == friction)
    }

    /// The sign of ω_z that friction gives (+1 or −1): that of the point
    /// contact's spin at the largest friction, where all of it is friction's.
    pub fn friction_sense(&self) -> f64 {
        let mu = FRICTIONS[FRICTIONS.len() - 1];
        let sum: f64 = self.curve(0, mu).map_or(0.0, |k| k.spin_z.iter().sum());
        if sum < 0.0 {
            -1.0
        } else {
            1.0
        }
    }
}

impl Curve {
    /// Sidespin in friction's sense, s ω_z (s = [`SpinData::friction_sense`]).
    pub fn sidespin(&self, sense: f64) -> Vec<f64> {
        self.spin_z.iter().map(|w| sense * w).collect()
    }

    /// The solved offset of the largest sidespin and that spin (on the grid).
    pub fn largest(&self, sense: f64) -> Option<(f64, f64)> {
        let s = self.sidespin(sense);
        (0..s.len()).max_by(|&a, &b| s[a].total_cmp(&s[b])).map(|i| (self.offset[i], s[i]))
    }

    /// The sidespin at offset `e`, if it was solved.
    pub fn at(&self, e: f64, sense: f64) -> Option<f64> {
        self.offset.iter().position(|&x| x == e).map(|i| sense * self.spin_z[i])
    }
}

/// Sidespin added by friction 0 → 1 for contact `c` at each offset solved
/// on both curves: (offsets, gains), friction's sense.
pub fn friction_gain(data: &SpinData, contact: usize) -> (Vec<f64>, Vec<f64>) {
    let sense = data.friction_sense();
    let (Some(zero), Some(one)) = (data.curve(contact, 0.0), data.curve(contact, 1.0)) else { return (Vec::new(), Vec::new()) };
    one.offset.iter().filter_map(|&e| Some((e, one.at(e, sense)? - zero.at(e, sense)?))).unzip()
}

/// Asai et al.'s (2002) abstract, as published in the measurement file:
/// the largest gain from friction 0 → 1 (rad/s) and the offset of largest spin (m).
#[derive(Debug, Clone, PartialEq)]
pub struct AsaiClaims {
    pub friction_gain: f64,
    pub peak_offset: f64,
    /// The measurement file and keys they were read from.
    pub source: String,
}

/// The claims as the spin file holds them.
pub fn read_asai(path: &Path) -> Result<AsaiClaims, String> {
    let f = ResultFile::open(path).map_err(h5)?;
    Ok(AsaiClaims {
        friction_gain: f.scalar("asai2002/friction_gain").map_err(h5)?,
        peak_offset: f.scalar("asai2002/peak_offset").map_err(h5)?,
        source: f.text("asai2002", "source").map_err(h5)?,
    })
}

pub fn asai_claims(measurements: &Path) -> Result<AsaiClaims, String> {
    use kick_3d::validation::keys;
    let m = Measurements::load(measurements).map_err(h5)?;
    let needed = "the patch spin figure (kick_paper::patch)";
    let gain = m.measured(keys::FRICTION_GAIN, needed).map_err(h5)?;
    let peak = m.measured(keys::PEAK_OFFSET, needed).map_err(h5)?;
    let friction_gain = gain.high.ok_or("no friction gain")?;
    let peak_offset = peak.midpoint().ok_or("no peak offset")?;
    let source = format!("{}: {}, {}", measurements.display(), keys::FRICTION_GAIN, keys::PEAK_OFFSET);
    Ok(AsaiClaims { friction_gain, peak_offset, source })
}

fn line_style(contact: usize, s: Series) -> Series {
    if CONTACTS[contact].patch {
        s
    } else {
        s.dashed()
    }
}

/// The spin figure from the file: sidespin, friction's gain 0 → 1, speed
/// and launch azimuth against offset; one colour per μ, dashed the point
/// contact, solid the patch; Asai et al.'s claims as what they are (a line
/// at their offset, a bound on the gain), no curve of theirs.
pub fn draw_spin(data: &SpinData, asai: &AsaiClaims, figures: &Path) -> Result<Vec<PathBuf>, FigureError> {
    let sense = data.friction_sense();
    let mm = |v: &[f64]| v.iter().map(|x| x * 1e3).collect::<Vec<f64>>();
    let mu_index = |mu: f64| FRICTIONS.iter().position(|&m| m == mu).unwrap_or(0);
    let per_curve = |y: &dyn Fn(&Curve) -> Vec<f64>, labelled: bool| -> Vec<Series> {
        data.curves
            .iter()
            .map(|k| {
                let label = if labelled { format!("{}, μ = {}", CONTACTS[k.contact].label, short(k.friction)) } else { String::new() };
                line_style(k.contact, Series::line(&label, color(mu_index(k.friction)), &mm(&k.offset), &y(k)).with_markers())
            })
            .collect()
    };
    let black = RGBColor(0, 0, 0);
    let x_label = "offset e (mm)";
    let axis = if sense < 0.0 { "−ω_z" } else { "ω_z" };
    let mut spin = per_curve(&|k| k.sidespin(sense), true);
    let all: Vec<f64> = data.curves.iter().flat_map(|k| k.sidespin(sense)).collect();
    let (lo, hi) = all.iter().fold((0.0f64, 0.0f64), |(a, b), &v| (a.min(v), b.max(v)));
    let peak = asai.peak_offset * 1e3;
    spin.push(Series::line(&format!("Asai et al. (2002): largest spin near {} mm", short(peak)), black, &[peak, peak], &[lo, hi]));
    let mut gain: Vec<Series> = (0..CONTACTS.len())
        .map(|c| {
            let (e, g) = friction_gain(data, c);
            line_style(c, Series::line(CONTACTS[c].label, color(3), &mm(&e), &g).with_markers())
        })
        .collect();
    let span = [0.0, data.offsets.last().copied().unwrap_or(0.0) * 1e3];
    gain.push(
        Series::line(&format!("Asai et al. (2002): at most {} rad/s", short(asai.friction_gain)), black, &span, &[asai.friction_gain; 2])
            .with_markers(),
    );
    let panel = |title: &str, y_label: &str, series: Vec<Series>, legend| Panel { legend, ..Panel::new(title, x_label, y_label, series) };
    let panels = [
        panel(
            "Sidespin (colour: μ; dashed: point contact, solid: patch)",
            &format!("sidespin {axis} (rad/s; > 0 as friction turns the ball)"),
            spin,
            SeriesLabelPosition::UpperLeft,
        ),
        panel(
            "Sidespin added by friction, μ = 0 → 1, at each offset",
            "sidespin at μ = 1 less at μ = 0 (rad/s)",
            gain,
            SeriesLabelPosition::UpperLeft,
        ),
        panel(
            "Ball speed (curves as in the first panel)",
            "speed |v| (m/s)",
            per_curve(&|k| k.speed.clone(), false),
            SeriesLabelPosition::LowerLeft,
        ),
        panel(
            "Launch azimuth (curves as in the first panel)",
            "azimuth from the foot's path (deg)",
            per_curve(&|k| k.launch_azimuth.clone(), false),
            SeriesLabelPosition::LowerLeft,
        ),
    ];
    save_grid(
        figures,
        SPIN_FIGURE,
        &format!("Shell ball on Table 1's foot at 22 m/s: spin against offset (cap radius {} m assumed)", short(CAP_RADIUS)),
        (2, 2),
        &panels,
    )
}

/// The command that writes the history file alone.
pub fn history_command(out: &Path) -> String {
    format!(
        "kick simulate3d --law shell --patch-contact --instep-radius {CAP_RADIUS} --face-yaw 0 --offset {HISTORY_OFFSET} \
         --friction {HISTORY_FRICTION} --history {} --samples {HISTORY_SAMPLES}",
        out.join(HISTORY_FILE).display()
    )
}

/// The history's kick as a spec.
pub fn history_spec() -> KickSpec {
    let mut spec = KickSpec::default();
    spec.scenario.law = Some(LawKind::Shell);
    spec.kick3d = CONTACTS[1].spec(HISTORY_OFFSET, HISTORY_FRICTION);
    spec
}

/// The history of the patch kick, as the page and figure read it (ms, mm, kN).
pub struct PatchHistory {
    pub time_ms: Vec<f64>,
    /// |F| of the normal force's resultant, kN.
    pub force_kn: Vec<f64>,
    /// Its lever, s M_z / |F| (mm; NaN where F = 0), friction's sense.
    pub lever_mm: Vec<f64>,
    /// |a|, friction's arm (mm).
    pub arm_mm: Vec<f64>,
    pub compression_mm: Vec<f64>,
    pub state: Vec<f64>,
    pub radius_mm: f64,
    pub friction: f64,
    pub offset: f64,
}

/// The history file read back; `sense` is friction's sign of ω_z.
pub fn read_history(path: &Path, sense: f64) -> Result<PatchHistory, String> {
    let f = ResultFile::open(path).map_err(h5)?;
    let v = |name: &str| f.values(&format!("history/{name}")).map_err(h5);
    let vector = |name: &str| -> Result<[Vec<f64>; 3], String> {
        Ok([v(&format!("{name}_x"))?, v(&format!("{name}_y"))?, v(&format!("{name}_z"))?])
    };
    let time = v("time")?;
    let [fx, fy, fz] = vector("normal_force")?;
    let [_, _, mz] = vector("normal_moment")?;
    let [ax, ay, az] = vector("contact_arm")?;
    let n = time.len();
    let force: Vec<f64> = (0..n).map(|i| (fx[i] * fx[i] + fy[i] * fy[i] + fz[i] * fz[i]).sqrt()).collect();
    let lever = (0..n).map(|i| if force[i] > 0.0 { 1e3 * sense * mz[i] / force[i] } else { f64::NAN }).collect();
    let arm = (0..n).map(|i| 1e3 * (ax[i] * ax[i] + ay[i] * ay[i] + az[i] * az[i]).sqrt()).collect();
    Ok(PatchHistory {
        time_ms: time.iter().map(|t| 1e3 * t).collect(),
        force_kn: force.iter().map(|x| 1e-3 * x).collect(),
        lever_mm: lever,
        arm_mm: arm,
        compression_mm: v("compression")?.iter().map(|d| 1e3 * d).collect(),
        state: v("contact_state")?,
        radius_mm: 1e3 * f.scalar("fixed/ball_radius").map_err(h5)?,
        friction: f.scalar("fixed/friction").map_err(h5)?,
        offset: f.scalar("fixed/offset").map_err(h5)?,
    })
}

/// The history figure: the normal force's resultant, its lever and
/// friction's arm against time, grip and slip shaded.
pub fn draw_history(h: &PatchHistory, figures: &Path) -> Result<Vec<PathBuf>, FigureError> {
    let t = &h.time_ms;
    let (grip, slip) = (ContactState::Grip.code(), ContactState::Slip.code());
    let shades = || {
        vec![
            Series::shade("grip", RGBColor(44, 160, 44), &crate::force_history::phases(t, &h.state, grip)),
            Series::shade("slip", RGBColor(255, 127, 14), &crate::force_history::phases(t, &h.state, slip)),
        ]
    };
    let with = |mut s: Vec<Series>, more: Vec<Series>| {
        s.extend(more);
        s
    };
    let black = RGBColor(0, 0, 0);
    let radius = [h.radius_mm; 2];
    let ends = [t[0], t[t.len() - 1]];
    let flat: Vec<f64> = h.compression_mm.iter().map(|d| h.radius_mm - d).collect();
    let x_label = "time t (ms)";
    let panels = [
        Panel::new(
            "Normal force over the patch: its resultant",
            x_label,
            "|F| (kN)",
            with(shades(), vec![Series::line("|F|", color(0), t, &h.force_kn)]),
        ),
        Panel {
            legend: SeriesLabelPosition::LowerRight,
            ..Panel::new(
                "Lever of the normal force about the ball's centre (> 0: turns the ball as friction does)",
                x_label,
                "M_z / |F| (mm)",
                with(shades(), vec![Series::line("lever M_z / |F|", color(1), t, &h.lever_mm)]),
            )
        },
        Panel {
            legend: SeriesLabelPosition::LowerLeft,
            y_from_zero: false,
            ..Panel::new(
                "Friction's arm: the patch centroid's distance from the ball's centre",
                x_label,
                "distance (mm)",
                with(
                    shades(),
                    vec![
                        Series::line("|a|, patch centroid", color(2), t, &h.arm_mm),
                        Series::line("R (a point contact's arm)", black, &ends, &radius).dashed(),
                        Series::line("R − δ", RGBColor(127, 127, 127), t, &flat).dashed(),
                    ],
                ),
            )
        },
    ];
    save_grid(
        figures,
        HISTORY_FIGURE,
        &format!(
            "Patch of one off-center kick: shell ball, cap {} m, e = {} cm, μ = {}",
            short(CAP_RADIUS),
            short(h.offset * 1e2),
            short(h.friction)
        ),
        (3, 1),
        &panels,
    )
}

/// `kick reproduce`'s step: both files and both figures; returns the files written.
pub fn write(out: &Path, figures: &Path, measurements: &Path, command: &str) -> Result<Vec<PathBuf>, String> {
    std::fs::create_dir_all(out).map_err(|e| format!("cannot create {}: {e}", out.display()))?;
    let data = compute()?;
    let mut written = vec![write_spin(&out.join(SPIN_FILE), &data, &asai_claims(measurements)?, command)?];
    let data = read_spin(&out.join(SPIN_FILE))?;
    let asai = read_asai(&out.join(SPIN_FILE))?;
    written.extend(draw_spin(&data, &asai, figures).map_err(h5)?);
    let path = out.join(HISTORY_FILE);
    let request = HistoryRequest { path: path.clone(), spacing: Spacing::Count(HISTORY_SAMPLES), open: kick_store::history::open };
    let run = kick_study::simulate::simulate3d(&history_spec(), "accurate", None, Some(&request), None)?;
    written.extend(run.written);
    let history = read_history(&path, data.friction_sense())?;
    written.extend(draw_history(&history, figures).map_err(h5)?);
    Ok(written)
}

/// The runs of a state, total time (ms).
/// Three significant digits, as the 3D page prints.
fn sig3(x: f64) -> String {
    crate::pages_3d::sig(x, 3)
}

/// A spin: zero to rounding below [`crate::validation::ZERO_SPIN`].
fn spin3(x: f64) -> String {
    if x.abs() < crate::validation::ZERO_SPIN {
        "zero (to rounding)".into()
    } else {
        format!("{} rad/s", sig3(x))
    }
}

fn time_in(h: &PatchHistory, code: f64) -> f64 {
    crate::force_history::phases(&h.time_ms, &h.state, code).iter().map(|(a, b)| b - a).sum()
}

/// The page's section on the patch (`paper/3d.md`), from the two files;
/// empty when they were not made.
pub fn page_section(out: &Path, report_dir: &Path) -> Result<String, String> {
    let (spin_path, history_path) = (out.join(SPIN_FILE), out.join(HISTORY_FILE));
    if !spin_path.exists() || !history_path.exists() {
        return Ok(String::new());
    }
    let fig = relative(report_dir, &out.join("figures"));
    let data = read_spin(&spin_path)?;
    let sense = data.friction_sense();
    let mut w = String::new();
    let _ = writeln!(w, "## The contact patch: spin against offset beside Asai et al. (2002)\n");
    let _ = writeln!(
        w,
        "`{}` (`kick reproduce --only patch`): the shell ball (`--law shell`, its FIFA-calibrated defaults, \
         [ball.md](ball.md)) on Table 1's foot at 22 m/s, square approach, offsets 0–{} mm in {} mm steps, μ ∈ {{{}}}, \
         solved on the accurate path. Every spin of this section is the shell ball's normal law (the sections above run \
         the paper's law). Two contacts: the rigid sphere's **point contact** on the knife-edge face (the \
         normal force through the centre, the level below) and the **patch** on a cap (`--patch-contact \
         --instep-radius {} --face-yaw 0`): the normal force spread over the contact patch, whose moment about the \
         ball's centre need not vanish, friction at the patch's centroid (`kick_3d::patch`). The cap's radius {} m is \
         an assumption: no published measurement of the instep's curvature was found. Sidespin is ω_z in the sense \
         friction turns the ball ({}ω_z here).\n\n![spin against offset]({fig}/{SPIN_FIGURE}.png)\n",
        relative(report_dir, &spin_path),
        short(data.offsets.last().copied().unwrap_or(0.0) * 1e3),
        short(OFFSET_STEP * 1e3),
        FRICTIONS.map(short).map(|m| m.to_string()).join(", "),
        short(CAP_RADIUS),
        short(CAP_RADIUS),
        if sense < 0.0 { "−" } else { "" },
    );
    let asai = read_asai(&spin_path)?;
    let mut gains = Vec::new();
    let mut peaks = Vec::new();
    let mut zeros = Vec::new();
    for (c, contact) in CONTACTS.iter().enumerate() {
        let mut parts = Vec::new();
        for &mu in &FRICTIONS[1..] {
            let Some(k) = data.curve(c, mu) else { continue };
            let Some((e, s)) = k.largest(sense) else { continue };
            let last = k.offset.last().copied().unwrap_or(f64::NAN);
            let zero = data.curve(c, 0.0).and_then(|z| z.at(e, sense));
            let first = k.offset.first().copied().unwrap_or(0.0);
            let range = format!("{}–{} mm", short(first * 1e3), short(last * 1e3));
            let gain = match zero {
                Some(z) => format!(", where μ = 0 gives {}, so friction 0 → {} adds {} rad/s there", spin3(z), short(mu), sig3(s - z)),
                None => String::new(),
            };
            if e == last {
                // The sweep's edge is no maximum: say so instead of scoring it.
                parts.push(format!(
                    "at μ = {} the sidespin has no maximum within {range}: it still rises at {} mm, {}{gain}",
                    short(mu),
                    short(e * 1e3),
                    crate::units::spin(s)
                ));
                peaks.push(format!("no maximum within {range} for the {} at μ = {}", contact.label, short(mu)));
            } else {
                parts.push(format!(
                    "at μ = {} the sidespin is largest, {}, at e = {} mm{gain}",
                    short(mu),
                    crate::units::spin(s),
                    short(e * 1e3)
                ));
                peaks.push(format!("largest at {} mm for the {} at μ = {}", short(e * 1e3), contact.label, short(mu)));
            }
        }
        let (e, g) = friction_gain(&data, c);
        let most = (0..g.len()).max_by(|&a, &b| g[a].total_cmp(&g[b]));
        if let Some(i) = most {
            parts.push(format!("over the offsets friction 0 → 1 adds at most {} rad/s (at e = {} mm)", sig3(g[i]), short(e[i] * 1e3)));
            gains.push(format!("{} rad/s for the {}", sig3(g[i]), contact.label));
        }
        let zero = data.curve(c, 0.0).and_then(|z| {
            let s = z.sidespin(sense);
            (0..s.len()).max_by(|&a, &b| s[a].abs().total_cmp(&s[b].abs())).map(|i| (z.offset[i], s[i]))
        });
        let zero_text = match zero {
            Some((_, s0)) if s0.abs() < crate::validation::ZERO_SPIN => {
                zeros.push(format!("the {} does not", contact.label));
                format!("at μ = 0 it does not spin (|ω_z| < {} rad/s at every offset)", short(crate::validation::ZERO_SPIN))
            }
            Some((e0, s0)) => {
                let sense_text = if s0 > 0.0 { "in" } else { "against" };
                zeros.push(format!("the {} does, {sense_text} friction's sense", contact.label));
                // Why, said only where the data show it: the loss acts on the ball
                // material's approach to the foot, which on a convex cap is faster
                // on the trailing side of the sliding patch.
                let why = if s0 > 0.0 && contact.instep_radius.is_some() {
                    " (each element's loss acts on the ball material's approach to the foot; sliding over the convex cap \
                     presses the trailing side of the patch faster, so the resultant passes behind the centre)"
                } else {
                    ""
                };
                format!(
                    "at μ = 0 it spins, {sense_text} friction's sense{why}, up to {} rad/s (at e = {} mm)",
                    sig3(s0.abs()),
                    short(e0 * 1e3)
                )
            }
            None => "μ = 0 was not solved".into(),
        };
        parts.insert(0, zero_text);
        // Offsets left out, said once when every friction left out the same ones.
        let curves: Vec<&Curve> = data.curves.iter().filter(|k| k.contact == c).collect();
        let left = |k: &Curve| k.refused.iter().map(|(e, _)| short(e * 1e3).to_string()).collect::<Vec<_>>().join(", ");
        if curves.iter().any(|k| !k.refused.is_empty()) {
            if curves
                .iter()
                .all(|k| left(k) == left(curves[0]) && k.refused.first().map(|r| &r.1) == curves[0].refused.first().map(|r| &r.1))
            {
                parts.push(format!("e = {} mm left out at every μ ({})", left(curves[0]), curves[0].refused[0].1));
            } else {
                for k in curves.iter().filter(|k| !k.refused.is_empty()) {
                    parts.push(format!("μ = {}: e = {} mm left out ({})", short(k.friction), left(k), k.refused[0].1));
                }
            }
        }
        let _ = writeln!(w, "- **{}**: {}.", contact.label, parts.join("; "));
    }
    let _ = writeln!(
        w,
        "\nBeside Asai et al.'s abstract, which gives three things and no curve (so the figure draws them as what they \
         are: a line at their offset, a bound on the gain; no curve of theirs): friction 0 → 1 adds at most {} rad/s \
         there, against at most {} here; their spin is largest \"around {} mm\", here {}; and their ball \
         spins at nearly zero friction (no number, and no sense, in the abstract), where here {}. Their offset runs \
         from the foot's axis to the ball's on a deforming finite-element ball, the model's from the swing line \
         through the instep's pole to the ball's centre, so the offsets compare only roughly.\n",
        short(asai.friction_gain),
        gains.join(" and "),
        short(asai.peak_offset * 1e3),
        peaks.join(", "),
        zeros.join(" and "),
    );
    // μ = 1 against μ = 0.5, offset by offset: the trend against friction.
    let mut orders = Vec::new();
    let mut any_less = false;
    for (c, contact) in CONTACTS.iter().enumerate() {
        let (Some(half), Some(one)) = (data.curve(c, 0.5), data.curve(c, 1.0)) else { continue };
        let pairs: Vec<(f64, f64)> =
            half.offset.iter().filter(|&&e| e > 0.0).filter_map(|&e| Some((half.at(e, sense)?, one.at(e, sense)?))).collect();
        let less = pairs.iter().filter(|(h, o)| o < h).count();
        any_less |= less > 0;
        orders.push(format!("the {} at {} of its {} offsets", contact.label, less, pairs.len()));
    }
    if !any_less && !orders.is_empty() {
        let _ = writeln!(w, "μ = 1 spins at least as much as μ = 0.5 at every offset solved, as Asai et al.'s trend has it.\n");
    } else if !orders.is_empty() {
        let _ = writeln!(
            w,
            "μ = 1 spins less than μ = 0.5 for {}: once the contact points come to rest, the contact grips and the \
             ball vibrates tangentially on the shell's spring, whose period at the default stiffness is close to the \
             contact time, so the longer grip of the larger μ hands more of the tangential momentum back (the \
             section on spin against friction below shows the trend turn with the assumed stiffness).\n",
            orders.join(" and ")
        );
    }

    let h = read_history(&history_path, sense)?;
    let n = h.time_ms.len();
    let peak = (0..n).max_by(|&a, &b| h.force_kn[a].total_cmp(&h.force_kn[b])).ok_or("empty history")?;
    let lever: Vec<usize> = (0..n).filter(|&i| h.lever_mm[i].is_finite()).collect();
    let lowest = *lever.iter().min_by(|&&a, &&b| h.lever_mm[a].total_cmp(&h.lever_mm[b])).ok_or("no lever")?;
    let highest = *lever.iter().max_by(|&&a, &&b| h.lever_mm[a].total_cmp(&h.lever_mm[b])).ok_or("no lever")?;
    // Where the lever changes sign (rows with a force on both sides).
    let turns: Vec<f64> = lever
        .windows(2)
        .filter(|p| {
            p[1] == p[0] + 1 && h.lever_mm[p[0]] != 0.0 && h.lever_mm[p[0]].signum() != h.lever_mm[p[1]].signum() && h.lever_mm[p[1]] != 0.0
        })
        .map(|p| 0.5 * (h.time_ms[p[0]] + h.time_ms[p[1]]))
        .collect();
    let arm_min = (0..n).min_by(|&a, &b| h.arm_mm[a].total_cmp(&h.arm_mm[b])).ok_or("empty history")?;
    let contact = h.time_ms[n - 1];
    let slip = time_in(&h, ContactState::Slip.code());
    let slips = crate::force_history::phases(&h.time_ms, &h.state, ContactState::Slip.code());
    let lever_text = match turns.as_slice() {
        [] => format!("keeps one sign, from {} to {} mm", sig3(h.lever_mm[lowest]), sig3(h.lever_mm[highest])),
        [t] => format!(
            "changes sign once, at {} ms: it is {} friction's sense before (down to {} mm at {} ms) and {} it after (up to {} mm at {} ms)",
            sig3(*t),
            if h.lever_mm[lowest] < 0.0 && h.time_ms[lowest] < *t { "against" } else { "with" },
            sig3(h.lever_mm[lowest]),
            sig3(h.time_ms[lowest]),
            if h.lever_mm[highest] > 0.0 && h.time_ms[highest] > *t { "with" } else { "against" },
            sig3(h.lever_mm[highest]),
            sig3(h.time_ms[highest]),
        ),
        many => format!("changes sign {} times, between {} and {} mm", many.len(), sig3(h.lever_mm[lowest]), sig3(h.lever_mm[highest])),
    };
    let _ = writeln!(w, "## One off-center kick's patch over time\n");
    let _ = writeln!(
        w,
        "`{}` (`{}`): the patch kick above at e = {} cm, μ = {}, {n} rows uniform in time. The normal force's \
         resultant is the sum of the element forces, its lever the signed distance of its line of action from the \
         ball's centre (M_z / |F|, > 0 in friction's sense), and friction's arm the patch centroid's distance from \
         the centre (a point contact's is R).\n\n![patch over time]({fig}/{HISTORY_FIGURE}.png)\n\n\
         Contact {} ms; the resultant peaks at {} kN at {} ms, where its lever is {} mm. The lever {lever_text}; \
         its largest size is {}% of friction's smallest arm. Friction's arm falls to {} mm at {} ms, {} mm inside R = {} mm, where the ball is \
         compressed by {} mm: a point contact's lever R overstates it by up to {}%. The contact slips for {} ms \
         ({}% of it: {}) and grips for the rest.\n",
        relative(report_dir, &history_path),
        history_command(out),
        short(h.offset * 1e2),
        short(h.friction),
        sig3(contact),
        sig3(h.force_kn[peak]),
        sig3(h.time_ms[peak]),
        sig3(h.lever_mm[peak]),
        sig3(100.0 * h.lever_mm[lowest].abs().max(h.lever_mm[highest].abs()) / h.arm_mm[arm_min]),
        sig3(h.arm_mm[arm_min]),
        sig3(h.time_ms[arm_min]),
        sig3(h.radius_mm - h.arm_mm[arm_min]),
        sig3(h.radius_mm),
        sig3(h.compression_mm[arm_min]),
        sig3(100.0 * (h.radius_mm / h.arm_mm[arm_min] - 1.0)),
        sig3(slip),
        sig3(100.0 * slip / contact),
        slips.iter().map(|(a, b)| format!("{}–{} ms", sig3(*a), sig3(*b))).collect::<Vec<_>>().join(", "),
    );
    Ok(w)
}

#[cfg(test)]
mod tests {
    use super::*;
    use kick_3d::Accurate3d;

    fn scratch(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("kick-patch-{name}-{}", std::process::id()));
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
    /// reason; the figures and the history file are written.
    #[test]
    fn the_spin_file_holds_the_solvers_kicks() {
        let dir = scratch("file");
        let written = write(&dir, &dir.join("figures"), &measurements(), "kick reproduce --only patch").unwrap();
        let names: Vec<String> = written.iter().map(|p| p.file_name().unwrap().to_string_lossy().into_owned()).collect();
        assert_eq!(
            names,
            [
                "3d_patch_spin.h5",
                "3d_patch_spin.png",
                "3d_patch_spin.svg",
                "3d_patch_history.h5",
                "3d_patch_history.png",
                "3d_patch_history.svg"
            ]
        );
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
        // The page's section states the file's numbers: the largest sidespin of
        // the point contact at μ = 0.5 and its offset, found here by hand.
        let page = page_section(&dir, &dir).unwrap();
        let k = data.curve(0, 0.5).unwrap();
        let (mut best, mut at) = (f64::NEG_INFINITY, 0.0);
        for (i, &w) in k.spin_z.iter().enumerate() {
            if -w > best {
                (best, at) = (-w, k.offset[i]);
            }
        }
        let said = format!("at μ = 0.5 the sidespin is largest, {}, at e = {} mm", crate::units::spin(best), short(at * 1e3));
        assert!(page.contains(&said), "{said}\n{page}");
        // The history's lever is M_z / |F| of its columns, friction's sense.
        let h = read_history(&dir.join(HISTORY_FILE), data.friction_sense()).unwrap();
        let f = ResultFile::open(&dir.join(HISTORY_FILE)).unwrap();
        let col = |n: &str| f.values(&format!("history/{n}")).unwrap();
        let (fx, fy, fz, mz) = (col("normal_force_x"), col("normal_force_y"), col("normal_force_z"), col("normal_moment_z"));
        let i = HISTORY_SAMPLES / 3;
        let lever = data.friction_sense() * 1e3 * mz[i] / (fx[i] * fx[i] + fy[i] * fy[i] + fz[i] * fz[i]).sqrt();
        assert!((h.lever_mm[i] - lever).abs() <= 1e-12 * lever.abs(), "{} vs {lever}", h.lever_mm[i]);
        let _ = std::fs::remove_dir_all(&dir);
    }

    fn curve(contact: usize, friction: f64, offset: &[f64], spin_z: &[f64]) -> Curve {
        let n = offset.len();
        Curve {
            contact,
            friction,
            offset: offset.to_vec(),
            spin_z: spin_z.to_vec(),
            spin: spin_z.iter().map(|w| w.abs()).collect(),
            speed: vec![20.0; n],
            launch_azimuth: vec![0.0; n],
            contact_time: vec![0.008; n],
            refused: Vec::new(),
        }
    }

    /// What the figure and page compute, on curves made up by hand:
    /// friction's sense is the point contact's sign at μ = 1, the largest
    /// sidespin and its offset, and the gain μ 0 → 1 only where both solved.
    #[test]
    fn sidespin_largest_and_gain_by_hand() {
        let e = [0.0, 0.01, 0.02, 0.03];
        let data = SpinData {
            offsets: e.to_vec(),
            curves: vec![
                curve(0, 0.0, &e, &[0.0, 0.0, 0.0, 0.0]),
                curve(0, 1.0, &e, &[0.0, -3.0, -7.0, -5.0]),
                // The patch: μ = 0 spins against friction; μ = 1 misses 0.02.
                curve(1, 0.0, &e, &[0.0, 1.0, 2.0, 4.0]),
                curve(1, 1.0, &[0.0, 0.01, 0.03], &[0.0, -2.0, -6.0]),
            ],
        };
        let s = data.friction_sense();
        assert_eq!(s, -1.0);
        assert_eq!(data.curves[1].largest(s), Some((0.02, 7.0)));
        assert_eq!(data.curves[2].largest(s), Some((0.0, 0.0)));
        assert_eq!(data.curves[3].largest(s), Some((0.03, 6.0)));
        // Gains: (2 − (−1)) at 0.01 and (6 − (−4)) at 0.03; 0.02 left out.
        assert_eq!(friction_gain(&data, 1), (vec![0.0, 0.01, 0.03], vec![0.0, 3.0, 10.0]));
        assert_eq!(friction_gain(&data, 0), (e.to_vec(), vec![0.0, 3.0, 7.0, 5.0]));
    }

    /// Asai et al.'s numbers as published (their abstract: at most 13 rad/s,
    /// around 100 mm), read from the measurement file.
    #[test]
    fn asai_claims_are_the_published_ones() {
        let a = asai_claims(&measurements()).unwrap();
        assert_eq!((a.friction_gain, a.peak_offset), (13.0, 0.1));
        assert!(a.source.contains("spin_friction_gain_asai2002") && a.source.contains("spin_peak_offset_asai2002"));
    }
}
