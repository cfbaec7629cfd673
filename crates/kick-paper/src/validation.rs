//! The validation chapter's page, `paper/validation.md`, from the
//! comparisons kick-study makes (`kick_study::validation`: every comparison
//! of the model with a published measurement, and the rules each row
//! follows) and writes to `results/validation/validation.json`. The reasons
//! each comparison agrees or misses are in `experiments/validation/NOTES.md`.

use crate::error::PaperError;
use crate::units::{three, ZERO_SPIN};
use kick_study::parameters::DEFAULT_BALL_RADIUS;
use kick_study::printable::short;
pub use kick_study::validation::rows::{self, headline, Headline, Role, Row};
pub use kick_study::validation::*;
use std::fmt::Write as _;
use std::path::Path;

/// [`validate`], then write `out/validation.json` and `page` (links relative to the page).
pub fn write(measurements: &Path, out: &Path, page: &Path, notes: &Path) -> Result<Validation, PaperError> {
    let mut v = validate(&kick_store::measurements::read(measurements)?)?;
    let json_path = out.join("validation.json");
    crate::output::write(&json_path, crate::printable::json(&v)?)?;
    let page_dir = page.parent().unwrap_or(Path::new("."));
    // Inputs are read where they are, the page may be written into a scratch
    // folder (`reproduce --check`): link them from the page's folder name, so
    // both give the same bytes.
    let input_from = if page_dir.is_absolute() { page_dir.file_name().map_or(Path::new("."), Path::new) } else { page_dir };
    let text = markdown(
        &v,
        &crate::links::relative(page_dir, &json_path),
        &crate::links::relative(input_from, measurements),
        &crate::links::relative(input_from, notes),
    );
    crate::output::write(page, text)?;
    v.written = vec![json_path, page.to_path_buf()];
    Ok(v)
}

/// An estimate as the page prints it: "not identified" when its σ exceeds it.
pub fn estimate_cell(value: Option<f64>, sigma: Option<f64>) -> String {
    match (value, sigma) {
        (None, _) => "not identified".into(),
        (Some(v), Some(s)) if s > v.abs() => {
            format!("not identified (σ = {} > {})", kick_study::printable::short(s), kick_study::printable::short(v))
        }
        (Some(v), Some(s)) => format!("{} ± {}", kick_study::printable::short(v), kick_study::printable::short(s)),
        (Some(v), None) => format!("{} (no σ: the source gives means only)", kick_study::printable::short(v)),
    }
}

/// A number in a table cell: a spin zero to rounding below [`ZERO_SPIN`].
fn value_cell(x: f64, unit: &str) -> String {
    if unit == "rad/s" {
        spin_text(x)
    } else {
        format!("{}", short(x))
    }
}

/// The measured side in a table cell: "v ± u" only for an uncertainty the
/// source states (a rounding-only u is in the row's note).
fn measured_cell(m: &Measured) -> String {
    match (m.low, m.high, &m.uncertainty) {
        (Some(lo), Some(hi), Some(u)) if lo == hi && u.is_stated() => format!("{} ± {}", short(lo), short(u.u())),
        (Some(lo), Some(hi), _) if lo == hi => format!("{}", short(lo)),
        (Some(lo), Some(hi), _) => format!("{} – {}", short(lo), short(hi)),
        _ => "(in words)".to_string(),
    }
}

/// A spin as printed in a table cell: zero to rounding below [`ZERO_SPIN`] (no `|` inside a cell).
pub fn spin_text(x: f64) -> String {
    if x.abs() < ZERO_SPIN {
        "0 (< 1e-12)".into()
    } else {
        format!("{}", short(x))
    }
}

/// The residual cell: z for a value with an uncertainty its source states,
/// model/measured for a value without one, the miss beyond a range.
fn residual_cell(r: &Row) -> String {
    let c = &r.comparison;
    if r.model_text.is_some() {
        return "–".into();
    }
    match (c.z, &c.measured.uncertainty) {
        (Some(z), Some(u)) if u.is_stated() => return format!("z = {}", three(z)),
        _ => {}
    }
    match (c.measured.low, c.measured.high, c.outside) {
        (Some(lo), Some(hi), Some(o)) if hi > lo => {
            if o == 0.0 {
                "inside".into()
            } else {
                format!("{} beyond", short(o))
            }
        }
        (Some(_), Some(_), Some(_)) => c.ratio.map_or("–".into(), |x| format!("ratio {}", three(x))),
        _ => "–".into(),
    }
}

/// The numbered note of one row: both sides' conditions, why, what the verdict hinges on, u.
fn note(r: &Row) -> String {
    let c = &r.comparison;
    let mut parts = vec![format!("model run at: {}", r.model_conditions), format!("measured at: {}", r.measured_conditions)];
    if !c.note.is_empty() && c.note != r.model_conditions {
        parts.push(c.note.clone());
    }
    if let Some(what) = &r.sets {
        parts.push(format!("sets {what}"));
    }
    if let Some(h) = &r.hinges_on {
        parts.push(format!("hinges on {h}{}", r.would_meet.as_ref().map_or(String::new(), |w| format!(": {w}"))));
    }
    if let (Some(why), true) = (&r.not_counted, r.role != Role::Prediction) {
        parts.push(format!("not like for like: {why}"));
    }
    if let Some(u) = &c.measured.uncertainty {
        parts.push(format!("u = {} {}, {}", short(u.u()), c.measured.unit, u.describe()));
    }
    parts.join("; ").replace('|', "/")
}

/// Rows as Markdown tables, one per model, each row on one line with a
/// numbered note below its table; `first` numbers the first note.
fn tables(w: &mut String, rows: &[Row], first: &mut usize) {
    let mut models: Vec<&str> = Vec::new();
    for r in rows {
        if !models.contains(&r.model.as_str()) {
            models.push(&r.model);
        }
    }
    for model in models {
        let group: Vec<&Row> = rows.iter().filter(|r| r.model == model).collect();
        let _ = writeln!(w, "**{model}**{}\n", group[0].foot.as_ref().map_or(String::new(), |f| format!(" — foot: {f}")));
        let _ = writeln!(w, "| # | role | quantity | measured | model | unit | z, ratio or miss | counted? | source (checked) |");
        let _ = writeln!(w, "|---|---|---|---|---|---|---|---|---|");
        let mut notes = Vec::with_capacity(group.len());
        for r in &group {
            let c = &r.comparison;
            let n = *first + notes.len();
            let model_cell = r.model_text.clone().unwrap_or_else(|| value_cell(c.model, c.measured.unit));
            let checked = match &c.measured.checked {
                Checked::Secondary(_) => "secondary".to_string(),
                Checked::Transcription(_) => "transcription".to_string(),
                other => other.to_string(),
            };
            let _ = writeln!(
                w,
                "| {n} | {} | {} | {} | {model_cell} | {} | {} | {} | `{}` ({checked}) |",
                r.role.name(),
                c.quantity,
                measured_cell(&c.measured),
                c.measured.unit,
                residual_cell(r),
                r.count_note(),
                c.measured.key
            );
            notes.push(note(r));
        }
        let _ = writeln!(w);
        for (i, text) in notes.iter().enumerate() {
            let _ = writeln!(w, "{}. {text}", *first + i);
        }
        let _ = writeln!(w);
        *first += notes.len();
    }
}

/// The page of `v`; `data`, `file` and `notes` are the JSON, the measurement
/// file and the notes as links from the page.
pub fn markdown(v: &Validation, data: &str, file: &str, notes: &str) -> String {
    let mut w = String::new();
    let h = &v.headline;
    let _ = writeln!(w, "# Validation: the model beside published measurements\n");
    let _ = writeln!(
        w,
        "Generated by `kick reproduce` from [{file}]({file}) ({} measurements from the {} sources listed at the end, each \
         with its citation, where it stands in the source and how far it was checked: *text*, *abstract*, *secondary*, \
         *transcription* or *unchecked*). Data: [{data}]({data}). Why each row agrees or misses, and what stays \
         unchecked: [the notes]({notes}).\n",
        v.measurements, v.sources
    );
    let _ = writeln!(
        w,
        "**Counted: {} prediction{} ({} within 2u).** A row is counted when it is a prediction (the measurement set \
         nothing), like for like with the model run, read in the source itself (text or abstract), and its value comes \
         with a measurement uncertainty u the source states; each distinct measurement and model counts once, by its \
         normalised residual z = (model − measured)/u. A population's spread (players, kicks) is not a measurement \
         uncertainty; where a source states none, the row's note gives the rounding of its published digits, a lower \
         bound on u, the table gives model/measured instead of z, and the row is not counted. Every kick runs with one declared foot, **{}** \
         (`kick_paper::validation::VALIDATION_FOOT`), but for the 1D shell ball's rows run again on the realistic foot (`--leg`): \
         **{}**, whose boot the limb's fastest kick set, so its contact-time row there is a calibration. A row whose verdict hinges on \
         either foot is a *sensitivity* statement (neither was measured with the kicks compared) and says which foot mass or \
         speed would meet the measurement. A finite-element result is a *model \
         comparison*, not a measurement. Values in SI units; spins in rad/s.\n",
        h.counted,
        if h.counted == 1 { "" } else { "s" },
        h.within_two_u,
        v.foot.name(),
        Foot::Leg.name()
    );
    let _ = writeln!(w, "| rows | number |\n|---|---|");
    // Every row once: the predictions split into counted and not counted, by reason.
    for (role, n) in &h.by_role {
        if *role == Role::Prediction {
            let not_counted: usize = h.not_counted.iter().map(|(_, k)| k).sum();
            let _ = writeln!(w, "| prediction, counted | {} |", n - not_counted);
            for (why, k) in &h.not_counted {
                let _ = writeln!(w, "| prediction, not counted: {why} | {k} |");
            }
        } else {
            let _ = writeln!(w, "| {} | {n} |", role.name());
        }
    }
    let _ = writeln!(w);
    let mut first = 1;
    let _ = writeln!(w, "## The ball alone\n");
    let _ = writeln!(
        w,
        "The shell ball (`--law shell`, `kick_core::ShellBall`) is calibrated on the FIFA rebound test only: its loss \
         β is set there, its pressure is the test's 0.8 bar, and nothing about a kick went into it.\n"
    );
    tables(&mut w, &v.ball, &mut first);
    let _ = writeln!(w, "## The 1D instep kick\n");
    let _ = writeln!(
        w,
        "Both laws, `accurate` solver, one table each. A force is compared at the ball speed measured with it: the foot \
         speed is lowered until the ball leaves at that speed (`kick_identify::validation::with_ball_speed`). The \
         nearly rigid mechanical kicking limb (Peacock & Ball 2016) is run at its paired published ends: foot 9.1 m/s \
         with ball 13.0 m/s (ratio 1.43), foot 21.2 m/s with ball 29.7 m/s (ratio 1.40), paired by the published \
         correlation of ball with foot speed. What each law was calibrated on: the paper's law takes Table 1's k, n and \
         c (the paper's values, fitted to none of these measurements); the shell ball takes the FIFA rebound's β and \
         the test's 0.8 bar, and nothing else.\n"
    );
    tables(&mut w, &v.contact, &mut first);
    let _ = writeln!(w, "## Stiffness and foot mass implied by the measurements\n");
    let _ = writeln!(
        w,
        "Identified only from like-for-like soccer instep targets measured together in one experiment: Tol et al.'s \
         ball speed and mean force. Not used: contact times pooled with rugby and Australian-football punts, a \
         between-player range of ball speeds without a measured foot speed, Tol et al.'s 1610 N (their mean × π/2, \
         not a measured peak), and Asai et al.'s 2439 N (from video and a simulation). An estimate whose σ exceeds \
         it is printed as not identified.\n"
    );
    let _ = writeln!(w, "| law | parameter | estimate | unit | targets | note |");
    let _ = writeln!(w, "|---|---|---|---|---|---|");
    for i in &v.implied {
        let _ =
            writeln!(w, "| {} | {} | {} | {} | {} | {} |", i.law, i.parameter, estimate_cell(i.value, i.sigma), i.unit, i.targets, i.note);
    }
    let ck = &v.curve_kicks;
    let _ = writeln!(w, "\n## Curve kicks: spin against offset and friction\n");
    let _ = writeln!(
        w,
        "Two models, each named with its normal law: the paper's law on the rigid sphere (`kick_3d`, a knife-edge face \
         tilted by asin(e/R)), and the shell ball's force spread over its patch on a convex instep. A spin is compared \
         where the model's ball leaves at the measured ball speed: the offset is chosen for that speed at μ = 0.5 \
         (kick-3d's default friction and tangential spring, assumed, calibrated on nothing here). Asai et al.'s (2002) \
         numbers are finite-element results: model comparisons.\n"
    );
    tables(&mut w, &ck.rows, &mut first);
    let frictions: Vec<String> = ck.curves.iter().map(|c| c.first().map_or("?".into(), |p| format!("{}", short(p.friction)))).collect();
    let _ = writeln!(
        w,
        "Spin (rad/s) and ball speed (m/s) against offset, the paper's law on the rigid sphere, {} at {} m/s, by friction μ:\n",
        VALIDATION_FOOT.name(),
        short(kick_study::parameters::FOOT_SPEED.default_number())
    );
    let _ = write!(w, "| offset (mm) |");
    for mu in &frictions {
        let _ = write!(w, " spin μ={mu} |");
    }
    for mu in &frictions {
        let _ = write!(w, " speed μ={mu} |");
    }
    let _ = writeln!(w, "\n|---|{}", "---|".repeat(2 * frictions.len()));
    let n = ck.curves.first().map_or(0, Vec::len);
    for i in 0..n {
        let _ = write!(w, "| {} |", short(1e3 * ck.curves[0][i].offset));
        for c in &ck.curves {
            let _ = write!(w, " {} |", spin_text(c[i].spin));
        }
        for c in &ck.curves {
            let _ = write!(w, " {} |", short(c[i].speed));
        }
        let _ = writeln!(w);
    }
    for p in &ck.largest {
        let _ = writeln!(
            w,
            "\nLargest spin at μ = {}, paper's law: {} at e = {} mm, inside the ball (R = {} mm), where the ball leaves \
             at {} m/s (golden-section search to {} mm).",
            short(p.friction),
            crate::units::spin(p.spin),
            three(1e3 * p.offset),
            short(1e3 * DEFAULT_BALL_RADIUS),
            three(p.speed),
            short(1e3 * OFFSET_TOLERANCE)
        );
    }
    let _ = writeln!(w, "\n## Flight: the drag crisis\n");
    let d = &v.drag_crisis_model;
    let _ = writeln!(
        w,
        "One definition of the critical Reynolds number throughout: where 95 % of the drag crisis's drop is done \
         (`kick_flight::coefficients::DragCrisis::critical_reynolds`); for the default 14-panel ball in sea-level air it \
         is {} ({} m/s for R = 0.11 m). Eq. 3's centre, where C_D is halfway down, lies at {} and is not called \
         critical. The sources' own definition was not read (crates/kick-flight/SOURCES.md). Each other \
         construction's factor on the crisis is its published critical Re over the 14-panel ball's: those rows set a \
         ratio and are calibrations of it, while their values carry the 14-panel row's miss, a second measurement \
         of the default ball's crisis against the Teamgeist's that set it. The constants \
         of Goff & Carré's Eq. 3 and Eq. 4 themselves were read only in code bases' transcriptions.\n",
        short(d.critical),
        three(d.critical_speed),
        short(d.centre)
    );
    tables(&mut w, &v.flight, &mut first);
    let _ = writeln!(w, "## Flight: measured trajectories\n");
    let _ = writeln!(
        w,
        "Mencke et al. (2020) filmed kicked soccer balls with phones and report, in their abstract, that a simulation \
         with the Magnus force predicts their 3D curveball trajectories accurately. Their launch conditions and \
         trajectories were read only in a public code base's digitisation of their figures, whose units and axes could \
         not be checked against the paper: the rows are shown, not counted.\n"
    );
    tables(&mut w, &v.measured_flights, &mut first);
    let f = &v.free_kicks.kicks;
    let _ = writeln!(w, "## Free kicks\n");
    let _ = writeln!(
        w,
        "Launched at {}° (assumed) with sidespin about the vertical, kick-flight's defaults (drag crisis joined to \
         the spinning ball's drag of Goff & Carré 2010 Eq. 4, saturating lift); lateral offset where the ball crosses \
         x = {} m. Re, S, C_D and C_L are the flight's own launch report. The circle estimate is a *check* of the \
         integrator, not a comparison with a measurement: the horizontal path as a circle of the launch curvature \
         with the same C_L. No measured deflection was found to set these beside, and the lift plateau they fly with \
         was read only in transcriptions ([flight.md](flight.md) shows what the bend owes to it). Speeds from `{}` \
         ({}), spins from `{}` ({}): an illustration in Physics World, not a measurement.\n",
        short(f.launch_angle),
        short(f.distance),
        f.launch_speed.key,
        short_status(&f.launch_speed.checked),
        f.launch_spin.key,
        short_status(&f.launch_spin.checked)
    );
    let e = &f.estimate;
    let mid = |m: &kick_study::validation::Measured| short(m.midpoint().unwrap_or(f64::NAN));
    let _ = writeln!(
        w,
        "The article's own numbers for that kick (`{}`, `{}`, `{}`, `{}`; {}, as a course page paraphrases them) are an \
         estimate, not a measurement, and are not counted: about {} N of side force, about {} s in the air over about \
         {} m, about {} m of bend, as a constant sideways acceleration from rest. The grid's middle kick ({} m/s, {} \
         rad/s) flown over the same {} m takes {} s and ends {} m to the side; its lift at launch is {} N. The article's \
         {} N at {} m/s is C_L = {}, below the default's plateau (the table's C_L column); [flight.md](flight.md) flies \
         the free kick at such constant values.\n",
        e.side_force.key,
        e.distance.key,
        e.flight_time.key,
        e.bend.key,
        short_status(&e.bend.checked),
        mid(&e.side_force),
        mid(&e.flight_time),
        mid(&e.distance),
        mid(&e.bend),
        short(e.kick.speed),
        three(e.kick.spin),
        mid(&e.distance),
        three(e.kick.time),
        three(e.kick.lateral_offset),
        three(e.lift_force),
        mid(&e.side_force),
        short(e.kick.speed),
        three(e.implied_lift_coefficient)
    );
    let _ = writeln!(
        w,
        "| speed (m/s) | spin (rad/s) | Re at launch | S at launch | C_D at launch | C_L at launch | lateral offset (m) | circle estimate (check, m) | height (m) | time (s) |"
    );
    let _ = writeln!(w, "|---|---|---|---|---|---|---|---|---|---|");
    for (k, a) in f.kicks.iter().zip(&v.free_kicks.launch) {
        let _ = writeln!(
            w,
            "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |",
            short(k.speed),
            three(k.spin),
            short(a.reynolds),
            short(a.spin_parameter),
            short(a.drag_coefficient),
            short(a.lift_coefficient),
            short(k.lateral_offset),
            short(k.circle_estimate),
            short(k.height),
            short(k.time)
        );
    }
    let _ = writeln!(w, "\n## How far each number was checked\n");
    let _ = writeln!(w, "From the measurement file's `checked` field (each entry's note says where it was read):\n");
    for (status, keys) in &v.checked {
        if !keys.is_empty() {
            let list: Vec<String> = keys.iter().map(|k| format!("`{k}`")).collect();
            let _ = writeln!(w, "- **{status}** ({}): {}", keys.len(), list.join(", "));
        }
    }
    let _ = writeln!(w, "\n## Sources\n");
    let _ = writeln!(w, "All {} sources of the measurement file:\n", v.citations.len());
    for (key, citation) in &v.citations {
        let _ = writeln!(w, "- `{key}`: {citation}");
    }
    w
}

/// A check status without the "which" of a secondary source (for prose).
fn short_status(c: &Checked) -> &'static str {
    match c {
        Checked::Text => "text",
        Checked::Abstract => "abstract",
        Checked::Secondary(_) => "secondary",
        Checked::Transcription(_) => "transcription",
        Checked::Unchecked => "unchecked",
    }
}

#[cfg(test)]
mod tests;
