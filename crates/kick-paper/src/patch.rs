//! The contact patch on the 3D page (issue 22, item 8), drawn and discussed
//! from its two files: spin against offset for the shell ball's point
//! contact and its patch on a cap, beside Asai et al. (2002), and one
//! off-center kick's patch over time. kick-study solves them
//! (`kick_study::patch`), kick-store writes and reads them
//! (`kick_store::patch`); every number on the page is read from the files.

use crate::error::PaperError;
use crate::figures::{color, save_grid, FigureError, Panel, Series};
use crate::links::relative;
use crate::ResultFile;
pub use kick_store::patch::{read_asai, read_spin, HISTORY_FILE, SPIN_FILE};
use kick_study::history::ContactState;
pub use kick_study::patch::{
    friction_gain, offsets, AsaiClaims, Curve, SpinData, CAP_RADIUS, CONTACTS, FRICTIONS, HISTORY_FRICTION, HISTORY_OFFSET,
    HISTORY_SAMPLES, OFFSET_STEP,
};
use kick_study::printable::short;
use plotters::prelude::{RGBColor, SeriesLabelPosition};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// The spin figure, below the figures directory.
pub const SPIN_FIGURE: &str = "3d_patch_spin";
/// The history figure.
pub const HISTORY_FIGURE: &str = "3d_patch_history";

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
            "sidespin at μ = 1 minus at μ = 0 (rad/s)",
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
pub fn read_history(path: &Path, sense: f64) -> Result<PatchHistory, PaperError> {
    let f = ResultFile::open(path)?;
    let v = |name: &str| f.values(&format!("history/{name}"));
    let vector = |name: &str| -> Result<[Vec<f64>; 3], PaperError> {
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
        radius_mm: 1e3 * f.scalar("fixed/ball_radius")?,
        friction: f.scalar("fixed/friction")?,
        offset: f.scalar("fixed/offset")?,
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

/// `kick reproduce`'s step: both files (kick-store) and both figures; returns the files written.
pub fn write(out: &Path, figures: &Path, measurements: &Path, command: &str) -> Result<Vec<PathBuf>, PaperError> {
    let mut written = kick_store::patch::run(out, measurements, command)?;
    let data = read_spin(&out.join(SPIN_FILE))?;
    let asai = read_asai(&out.join(SPIN_FILE))?;
    written.extend(draw_spin(&data, &asai, figures)?);
    let history = read_history(&out.join(HISTORY_FILE), data.friction_sense())?;
    written.extend(draw_history(&history, figures)?);
    Ok(written)
}
/// The runs of a state, total time (ms).
/// Three significant digits, as the 3D page prints.
fn sig3(x: f64) -> String {
    crate::units::sig(x, 3)
}

/// A spin: zero to rounding below [`crate::units::ZERO_SPIN`].
fn spin3(x: f64) -> String {
    if x.abs() < crate::units::ZERO_SPIN {
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
pub fn page_section(out: &Path, report_dir: &Path) -> Result<String, PaperError> {
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
            // Offsets where the ball leaves spinning against friction's sense (beyond rounding).
            let side = k.sidespin(sense);
            let against: Vec<usize> = (0..side.len()).filter(|&i| side[i] < -crate::units::ZERO_SPIN).collect();
            let gain = match (against.first(), against.last()) {
                (Some(&a), Some(&b)) => {
                    let least = against.iter().map(|&i| side[i]).fold(f64::INFINITY, f64::min);
                    let at = if a == b {
                        format!("{} mm", short(k.offset[a] * 1e3))
                    } else {
                        format!("{}–{} mm", short(k.offset[a] * 1e3), short(k.offset[b] * 1e3))
                    };
                    format!("{gain}; at {at} it spins against friction's sense (down to {})", crate::units::spin(least))
                }
                _ => gain,
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
            Some((_, s0)) if s0.abs() < crate::units::ZERO_SPIN => {
                zeros.push(format!("the {} does not", contact.label));
                format!("at μ = 0 it does not spin (|ω_z| < {} rad/s at every offset)", short(crate::units::ZERO_SPIN))
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
         there, against at most {} here; their spin is largest near {} mm, here {}; and their ball \
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
    let peak = (0..n).max_by(|&a, &b| h.force_kn[a].total_cmp(&h.force_kn[b])).ok_or_else(|| PaperError::missing("empty history"))?;
    let lever: Vec<usize> = (0..n).filter(|&i| h.lever_mm[i].is_finite()).collect();
    let lowest = *lever.iter().min_by(|&&a, &&b| h.lever_mm[a].total_cmp(&h.lever_mm[b])).ok_or_else(|| PaperError::missing("no lever"))?;
    let highest =
        *lever.iter().max_by(|&&a, &&b| h.lever_mm[a].total_cmp(&h.lever_mm[b])).ok_or_else(|| PaperError::missing("no lever"))?;
    // Where the lever changes sign (rows with a force on both sides).
    let turns: Vec<f64> = lever
        .windows(2)
        .filter(|p| {
            p[1] == p[0] + 1 && h.lever_mm[p[0]] != 0.0 && h.lever_mm[p[0]].signum() != h.lever_mm[p[1]].signum() && h.lever_mm[p[1]] != 0.0
        })
        .map(|p| 0.5 * (h.time_ms[p[0]] + h.time_ms[p[1]]))
        .collect();
    let arm_min = (0..n).min_by(|&a, &b| h.arm_mm[a].total_cmp(&h.arm_mm[b])).ok_or_else(|| PaperError::missing("empty history"))?;
    let contact = h.time_ms[n - 1];
    let slip = time_in(&h, ContactState::Slip.code());
    let slips = crate::force_history::phases(&h.time_ms, &h.state, ContactState::Slip.code());
    let lever_text = match turns.as_slice() {
        [] => format!("keeps one sign, from {} to {} mm", sig3(h.lever_mm[lowest]), sig3(h.lever_mm[highest])),
        [t] => {
            // Each side of the turn by its own largest lever (> 0: friction's sense).
            let side = |before: bool| {
                let i = *lever
                    .iter()
                    .filter(|&&i| (h.time_ms[i] < *t) == before)
                    .max_by(|&&a, &&b| h.lever_mm[a].abs().total_cmp(&h.lever_mm[b].abs()))
                    .unwrap_or(&lowest);
                let (sense, extreme) = if h.lever_mm[i] > 0.0 { ("with", "up to") } else { ("against", "down to") };
                format!(
                    "{sense} friction's sense {} ({extreme} {} mm at {} ms)",
                    if before { "before" } else { "after" },
                    sig3(h.lever_mm[i]),
                    sig3(h.time_ms[i])
                )
            };
            format!("changes sign once, at {} ms: it is {} and {}", sig3(*t), side(true), side(false))
        }
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

    fn scratch(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("kick-patch-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        dir
    }

    fn measurements() -> PathBuf {
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../experiments/validation/measurements.toml")
    }

    /// The step writes both files and both figures, and the page states the
    /// files' numbers: the largest sidespin of the point contact at μ = 0.5
    /// and its offset, found here by hand, and the history's lever is
    /// M_z / |F| of its columns in friction's sense.
    #[test]
    fn the_page_states_the_files_numbers() {
        let dir = scratch("file");
        let written = write(&dir, &dir.join("figures"), &measurements(), "kick reproduce --only patch").unwrap();
        let names: Vec<String> = written.iter().map(|p| p.file_name().unwrap().to_string_lossy().into_owned()).collect();
        assert_eq!(
            names,
            [
                "3d_patch_spin.h5",
                "3d_patch_history.h5",
                "3d_patch_spin.png",
                "3d_patch_spin.svg",
                "3d_patch_history.png",
                "3d_patch_history.svg"
            ]
        );
        let data = read_spin(&dir.join(SPIN_FILE)).unwrap();
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
}
