//! The generated pages of the 3D kick (`paper/3d.md`) and of the flight
//! (`paper/flight.md`), written by `kick reproduce` from the result files
//! (`OUT/3d_*.h5`, `OUT/flight/free_kick.h5`); every number on them is read
//! from those files or computed here at generation time.

use crate::free_kick;
use crate::h5::SweepData;
use crate::links::relative;
use crate::three_d::{curves, value_label};
use kick_3d::{Accurate3d, Kick3d, KickSpec, Solver3d};
use kick_core::parameters::{SetParameter, Value};
use kick_core::Solver;
use std::fmt::Write as _;
use std::io::Write;
use std::path::{Path, PathBuf};

/// The 2-axis grid behind the 3D page's main figures.
pub const OFFSET_FRICTION: &str = "3d_offset_friction";
/// The force-history figure (drawn by another step), linked when present.
pub const FORCE_HISTORY_FIGURE: &str = "3d_force_history.png";
/// Kicks of the box whose accuracy the page states.
pub const ACCURACY_KICKS: u64 = 6;

fn err(e: impl std::fmt::Display) -> String {
    e.to_string()
}

/// `x` to `digits` significant digits, as text.
fn sig(x: f64, digits: usize) -> String {
    if !x.is_finite() {
        return "—".into();
    }
    if x == 0.0 {
        return "0".into();
    }
    let magnitude = x.abs().log10().floor() as i32;
    let decimals = (digits as i32 - 1 - magnitude).max(0) as usize;
    format!("{x:.decimals$}")
}

/// The kick the force-history figure shows: offset 5 cm, μ 0.5, baseline otherwise.
fn history_kick() -> Result<Kick3d, String> {
    let mut spec = KickSpec::default();
    spec.set_named("offset", Value::Number(0.05)).map_err(err)?;
    spec.set_named("friction", Value::Number(0.5)).map_err(err)?;
    spec.build().map_err(err)
}

/// Largest relative error of the accurate path against the tightened
/// full-state reference over the first `kicks` kicks of the box, per
/// observable (kick_3d::precision::Errors3d order).
fn box_errors(kicks: u64) -> Result<[f64; 8], String> {
    let sample = kick_3d::models::OffCenterBox::new(kick_3d::models::BENCH_SEED);
    let mut worst = [0.0f64; 8];
    for i in 0..kicks {
        let kick = sample.kick(i).map_err(err)?;
        let solved = Accurate3d::default().solve(&kick).map_err(err)?;
        let reference = kick_3d::precision::reference().solve(&kick).map_err(err)?;
        let e = kick_3d::precision::Errors3d::of(&kick, &solved, &reference);
        for (w, v) in worst.iter_mut().zip(e.values()) {
            *w = w.max(v);
        }
    }
    Ok(worst)
}

/// Relative gap between the accurate 3D path on a central frictionless
/// kick and the 1D accurate solver on its scenario (exit speed).
fn central_gap() -> Result<f64, String> {
    let mut spec = KickSpec::default();
    spec.set_named("friction", Value::Number(0.0)).map_err(err)?;
    let kick = spec.build().map_err(err)?;
    let three = Accurate3d::default().solve(&kick).map_err(err)?;
    let one = kick_compliant::SolverChoice::from_name("accurate", 5e-6).map_err(err)?.solve(&kick.base).map_err(err)?;
    Ok(((three.speed - one.v_ball_out) / one.v_ball_out).abs())
}

/// The scene path's launch-velocity error against `accurate` on the kick of
/// [`history_kick`] at two steps, and the observed order, in words.
fn scene_errors() -> Result<String, String> {
    let kick = history_kick()?;
    let exact = Accurate3d::default().solve(&kick).map_err(err)?;
    let mut errors = Vec::new();
    for dt in [1e-5, 5e-6] {
        let Ok(solver) = Solver3d::from_name("rapier", dt) else {
            return Ok("first order in the step (not built here: cargo feature `rapier` off)".into());
        };
        let o = solver.solve(&kick).map_err(err)?;
        let d: f64 = (0..3).map(|i| (o.launch_velocity[i] - exact.launch_velocity[i]).powi(2)).sum::<f64>().sqrt();
        errors.push(d / exact.speed);
    }
    Ok(format!(
        "on the kick at e = 5 cm, μ = 0.5: launch velocity off by {:.1e} relative at a step of 1e-5 s and {:.1e} at 5e-6 s, \
         observed order {:.2}",
        errors[0],
        errors[1],
        (errors[0] / errors[1]).log2()
    ))
}

/// Rows of `data` for each curve of its second axis, with (x, column) values.
struct Grid2 {
    data: SweepData,
    curves: Vec<(String, Vec<usize>)>,
}

impl Grid2 {
    fn read(path: &Path) -> Result<Grid2, String> {
        let data = crate::three_d::read_grid_file(path).map_err(err)?;
        let curves = curves(&data);
        Ok(Grid2 { data, curves })
    }
    fn x(&self) -> &[f64] {
        &self.data.parameters[0].1
    }
    fn column(&self, name: &str) -> Result<&[f64], String> {
        self.data.sets[0].column(name).ok_or_else(|| format!("{}: no column {name}", self.data.path.display()))
    }
    /// The value of `name` on curve `c` at the first-axis value nearest `x`.
    fn at(&self, c: usize, x: f64, name: &str) -> Result<(f64, f64), String> {
        let column = self.column(name)?;
        let rows = &self.curves[c].1;
        let row = *rows
            .iter()
            .min_by(|&&a, &&b| (self.x()[a] - x).abs().total_cmp(&(self.x()[b] - x).abs()))
            .ok_or("empty curve")?;
        Ok((self.x()[row], column[row]))
    }
    fn last(&self, c: usize, name: &str) -> Result<(f64, f64), String> {
        let row = *self.curves[c].1.last().ok_or("empty curve")?;
        Ok((self.x()[row], self.column(name)?[row]))
    }
}

/// `paper/3d.md`: the model, the paths and their accuracy, the figures and
/// what they show, from `out/3d_*.h5` (links relative to `report_dir`).
pub fn page_3d(out: &Path, report_dir: &Path) -> Result<String, String> {
    let figures = out.join("figures");
    let fig = relative(report_dir, &figures);
    let res = relative(report_dir, out).trim_end_matches('/').to_string();
    let res = if res.is_empty() { ".".to_string() } else { res };
    let k = Kick3d::baseline();
    let b = k.base;
    let default_of = |name: &str| kick_core::parameters::find(name).map(|p| p.default_number()).unwrap_or(f64::NAN);
    let (kt, ct) = (k.tangential_stiffness, k.tangential_damping);
    // Tangent stiffness of the normal law at the 1D baseline's δ_max, and
    // the tangential damping ratio on the gripping contact's mass m_t.
    let one = kick_compliant::SolverChoice::from_name("accurate", 5e-6).map_err(err)?.solve(&b).map_err(err)?;
    let (stiffness, exponent) = (b.get(kick_core::Parameter::Stiffness), b.get(kick_core::Parameter::Exponent));
    let tangent = stiffness * exponent * one.max_compression.powf(exponent - 1.0);
    let foot_mass = b.effective_foot_mass();
    let m_t = 1.0 / (1.0 / b.ball_mass() + k.ball_radius * k.ball_radius / k.ball_inertia + 1.0 / foot_mass);
    let zeta = ct / (2.0 * (kt * m_t).sqrt());
    // The instep's size as given (border included).
    let [hx, hy, hz] = k.foot_shape.outer_half_extents();
    let mut w = String::new();
    let _ = writeln!(w, "# Off-center kicks: spin, friction, launch direction and the speed–spin trade-off\n");
    let _ = writeln!(
        w,
        "Generated by `kick reproduce` from `{res}/3d_*.h5` (experiment files `experiments/3d/*.toml`, run by `kick run`); \
         every number below is read from those files or computed when the page is written. Costs are not here: they \
         depend on the machine and are in [timing.md](timing.md).\n\n\
         The paper's model is one-dimensional and central; its Section 17.4–17.5 points out that real impacts are \
         off-center, that tangential forces make spin, and that an off-center impulse J at r gives the ball the \
         angular impulse ΔL = r × J (Eq. 61), so one contact splits its energy between launch speed and spin. The \
         crate `kick-3d` adds exactly this.\n"
    );
    let _ = writeln!(w, "## Model\n");
    let _ = writeln!(
        w,
        "- Ball: rigid sphere, R = {} m, m_b = {} kg, thin-shell inertia I_b = 2/3 m_b R² = {} kg m² by default \
         (configurable, at most the thin-shell value).\n\
         - Foot: rigid instep box (or rounded box) of half-extents {} × {} × {} m with the effective mass m_f = {} kg \
         of Table 1 and a principal inertia tensor (default: a uniform solid box of that size and mass, an assumption). \
         It approaches with speed V = {} m/s along (cos α, 0, sin α).\n\
         - Geometry: the foot's line of motion passes the ball centre at a lateral offset e; the face is tangent to \
         the ball where that line meets it, so the contact normal is tilted by φ = asin(e/R). A flat face hit square \
         on would push through the centre whatever the offset, so this tilt is what the offset means for a rigid \
         sphere. α tilts the foot's path upward with the face held (the foot slides up the ball).\n\
         - Normal force: the scenario's contact law — in every result here the paper's F_n = k δⁿ + c max(δ̇, 0) \
         (Eq. 20); any law of `kick_core::laws` with `--law`/`--restitution` or the experiment file's \
         `law`/`restitution` keys (see [laws.md](laws.md)).\n\
         - Tangential force: Coulomb friction μ with tangential compliance: a spring k_t and damper c_t in series \
         with a slider capped at μ F_n (Cundall–Strack). The spring extension is part of the state; grip ↔ slip \
         switches are located events. Defaults k_t = {} N/m ({} of the normal law's tangent stiffness \
         k n δ_max^(n−1) = {} N/m at the 1D baseline's δ_max = {} mm) and c_t = {} N s/m (damping ratio \
         c_t / (2√(k_t m_t)) = {} on the gripping contact's mass m_t, 1/m_t = 1/m_b + R²/I_b + 1/m_f): \
         **assumptions, not measurements**.\n",
        sig(k.ball_radius, 3),
        sig(b.ball_mass(), 3),
        sig(k.ball_inertia, 4),
        sig(hx, 3),
        sig(hy, 3),
        sig(hz, 3),
        sig(foot_mass, 3),
        sig(b.foot_speed(), 3),
        sig(default_of("tangential_stiffness"), 3),
        sig(kt / tangent, 2),
        sig(tangent, 3),
        sig(one.max_compression * 1e3, 3),
        sig(default_of("tangential_damping"), 3),
        sig(zeta, 2),
    );

    // Paths and their accuracy, computed now.
    let worst = box_errors(ACCURACY_KICKS)?;
    let gap = central_gap()?;
    let scene = scene_errors()?;
    let names = ["launch velocity", "spin", "contact time", "peak normal force", "its time", "peak tangential force", "its time", "max compression"];
    let listed: Vec<String> = names.iter().zip(worst).map(|(n, e)| format!("{n} {:.1e}", e)).collect();
    let _ = writeln!(w, "## Paths and their accuracy\n");
    let _ = writeln!(
        w,
        "| path | what | error |\n| --- | --- | --- |\n\
         | `accurate` | the relative motion in the foot's frame on DOP853, grip/slip, damping and face/edge switches \
         located on the dense output; analytic geometry on the face, parry3d on edges and rounded borders | over the \
         first {ACCURACY_KICKS} kicks of the test box (`kick_3d::models::OffCenterBox`, seed {}: offset 0–9 cm, \
         approach −20…30°, μ 0.2–∞, foot 1–10 kg), largest relative error against the full-state path at rtol 1e-13: \
         {}; the promise, held over 200 kicks by `crates/kick-3d/tests/model/box_accuracy.rs`, is 1e-9 |\n\
         | `full-state` | both rigid bodies in the world frame, parry3d at every evaluation: the independent reference \
         of `accurate` | the reference itself (rtol 1e-13 above) |\n\
         | `1d` | the 1D accurate solver along the normal, for central square kicks (nothing slides) | central, \
         frictionless: `accurate` and the 1D solver differ by {:.1e} in exit speed (held to ≤ 1e-9) |\n\
         | `rapier` | a rapier3d world (ground, gravity) with the same law applied as forces each step | {}; for scenes, \
         not precision (`kick simulate3d --scene-convergence` prints the same study for any kick) |\n\n\
         `auto` takes `1d` for central square kicks, `rapier` when the scene has a ground, `accurate` otherwise. The \
         cost of each path, and the 3D/1D cost ratio, are measured on the machine that runs the reproduction: \
         [timing.md](timing.md).\n",
        kick_3d::models::BENCH_SEED,
        listed.join(", "),
        gap,
        scene,
    );

    // Offset × friction.
    let grid_path = out.join(format!("{OFFSET_FRICTION}.h5"));
    if !grid_path.exists() {
        let _ = writeln!(w, "`{res}/{OFFSET_FRICTION}.h5` was not made (no `experiments/3d/offset_friction.toml`).\n");
        return Ok(w);
    }
    let g = Grid2::read(&grid_path)?;
    let _ = writeln!(w, "## Spin and launch direction against offset, per friction\n");
    let _ = writeln!(
        w,
        "`experiments/3d/offset_friction.toml` → `{res}/{OFFSET_FRICTION}.h5`: offset 0–9 cm × μ ∈ {{0.2, 0.5, 1, ∞}} \
         (∞: the contact never slips), Table 1 baseline, square approach (α = 0).\n\n\
         ![spin and launch direction]({fig}/{OFFSET_FRICTION}.png)\n"
    );
    let mut spin_at_5 = Vec::new();
    let mut lines = Vec::new();
    let mut rising_curves = Vec::new();
    let mut falling_notes = Vec::new();
    let (slip, contact) = (g.column("slip_time")?, g.column("contact_time")?);
    for (c, (label, rows)) in g.curves.iter().enumerate() {
        let (x5, rpm5) = g.at(c, 0.05, "spin_rpm")?;
        let (xe, rpm_end) = g.last(c, "spin_rpm")?;
        let (_, az5) = g.at(c, 0.05, "launch_azimuth")?;
        let (_, az_end) = g.last(c, "launch_azimuth")?;
        let (_, s0) = g.at(c, 0.0, "spin_rpm")?;
        let rpm = g.column("spin_rpm")?;
        let rising = rows.windows(2).all(|p| rpm[p[1]] >= rpm[p[0]]);
        let peak = *rows.iter().max_by(|&&a, &&b| rpm[a].total_cmp(&rpm[b])).ok_or("empty curve")?;
        if rising {
            rising_curves.push(label.clone());
        } else {
            // Where the contact slides from first touch to release.
            let sliding: Vec<usize> = rows.iter().copied().filter(|&r| slip[r] >= 0.999 * contact[r]).collect();
            let from = sliding.iter().map(|&r| g.x()[r]).fold(f64::INFINITY, f64::min);
            falling_notes.push(format!(
                "for {label} the spin peaks at {} rpm at {} cm and falls beyond{}",
                sig(rpm[peak], 3),
                sig(g.x()[peak] * 100.0, 2),
                if from.is_finite() {
                    format!(
                        "; from {} cm on the contact slides from first touch to release (slip time = contact time in the file), so the spin is R μ J_n / I_b and falls with the normal impulse",
                        sig(from * 100.0, 2)
                    )
                } else {
                    String::new()
                }
            ));
        }
        spin_at_5.push((label.clone(), rpm5, x5));
        lines.push(format!(
            "- {label}: spin {} rpm at e = 0, {} rpm at {} cm, {} rpm at {} cm; launch azimuth {}° at {} cm and {}° at {} cm",
            sig(s0, 3),
            sig(rpm5, 3),
            sig(x5 * 100.0, 2),
            sig(rpm_end, 3),
            sig(xe * 100.0, 2),
            sig(az5, 3),
            sig(x5 * 100.0, 2),
            sig(az_end, 3),
            sig(xe * 100.0, 2),
        ));
    }
    let elevation = g.column("launch_angle")?.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let tilt5 = (0.05 / k.ball_radius).asin().to_degrees();
    let _ = writeln!(w, "{}\n", lines.join("\n"));
    let rad = |rpm: f64| rpm * std::f64::consts::TAU / 60.0;
    let (lo, hi) = spin_at_5.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), s| (a.min(s.1), b.max(s.1)));
    let _ = writeln!(
        w,
        "Spin grows with the offset at every step of the grid for {}: the lever arm of the tangential force grows \
         with e, and so does the tangential component of the approach speed that the tilted normal leaves to grip{}. \
         At 5 cm the four frictions give {}–{} rpm, {} rad/s apart (Asai et al. 2002 report at most about 13 rad/s \
         from μ = 0 to 1): once μ is moderate, the offset sets the spin. The launch direction follows the tilted \
         normal: the azimuth grows in size with the offset; at 5 cm it is smaller in size than the normal's tilt \
         φ = asin(e/R) = {}°, the tangential impulse pulling the ball back toward the foot's path. The largest \
         elevation over the grid is {}°: with a square, horizontal approach the kick stays in the ground plane (an \
         approach angle, or a contact below the centre as on [flight.md](flight.md), lifts it).\n",
        if rising_curves.is_empty() { "none of the frictions".to_string() } else { rising_curves.join(", ") },
        if falling_notes.is_empty() { String::new() } else { format!("; {}", falling_notes.join("; ")) },
        sig(lo, 3),
        sig(hi, 3),
        sig(rad(hi) - rad(lo), 2),
        sig(tilt5, 3),
        sig(elevation, 2),
    );

    let _ = writeln!(w, "## The speed–spin trade-off\n");
    let _ = writeln!(w, "![speed against spin]({fig}/{OFFSET_FRICTION}_tradeoff.png)\n");
    let mut trade = Vec::new();
    for (c, (label, _)) in g.curves.iter().enumerate() {
        let (_, v0) = g.at(c, 0.0, "speed")?;
        let (x5, v5) = g.at(c, 0.05, "speed")?;
        let (_, s5) = g.at(c, 0.05, "spin_rpm")?;
        let (xe, ve) = g.last(c, "speed")?;
        let (_, se) = g.last(c, "spin_rpm")?;
        trade.push(format!(
            "- {label}: {} m/s without spin (e = 0), {} m/s with {} rpm at {} cm, {} m/s with {} rpm at {} cm",
            sig(v0, 4),
            sig(v5, 4),
            sig(s5, 3),
            sig(x5 * 100.0, 2),
            sig(ve, 4),
            sig(se, 3),
            sig(xe * 100.0, 2)
        ));
    }
    let _ = writeln!(
        w,
        "Each marker is one offset of the grid; moving along a curve, the ball gains spin and loses speed, since one \
         contact's energy goes to launch, to spin, to the foot and to losses:\n\n{}\n",
        trade.join("\n")
    );

    // The one-axis files.
    for (name, what) in [("3d_friction", "friction at a 5 cm offset"), ("3d_approach_angle", "approach angle, central, μ = 0.5"), ("3d_offset", "offset at μ = 0.5")] {
        let path = out.join(format!("{name}.h5"));
        if !path.exists() {
            continue;
        }
        let one = Grid2::read(&path)?;
        let (x_end, rpm_end) = one.last(0, "spin_rpm")?;
        let rpm = one.column("spin_rpm")?;
        let (peak_row, peak) = rpm.iter().enumerate().fold((0, f64::NEG_INFINITY), |m, (i, &v)| if v > m.1 { (i, v) } else { m });
        let axis = &one.data.parameters[0].0;
        let unit = if axis.unit == "1" { String::new() } else { format!(" {}", axis.unit) };
        let _ = writeln!(
            w,
            "### {what}\n\n![{name}]({fig}/{name}.png)\n\n`{res}/{name}.h5`: spin {} rpm at {} = {}{}, largest {} rpm at {}{}; \
             speed {}–{} m/s over the axis.\n",
            sig(rpm[0], 3),
            axis.name,
            sig(one.x()[0], 3),
            unit,
            sig(rpm_end.max(peak), 3),
            sig(one.x()[peak_row], 3),
            unit,
            sig(one.column("speed")?.iter().cloned().fold(f64::INFINITY, f64::min), 4),
            sig(one.column("speed")?.iter().cloned().fold(f64::NEG_INFINITY, f64::max), 4),
        );
        let _ = x_end;
    }

    // Force history of one kick, when the figure is there.
    let kick = history_kick()?;
    let o = Solver3d::Auto.solve(&kick).map_err(err)?;
    let _ = writeln!(w, "## Forces of one off-center kick: grip and slip\n");
    if figures.join(FORCE_HISTORY_FIGURE).exists() {
        let _ = writeln!(w, "![force history]({fig}/{FORCE_HISTORY_FIGURE})\n");
    }
    let _ = writeln!(
        w,
        "The kick at e = 5 cm, μ = 0.5 (baseline otherwise), solved when this page is written: contact {} ms; peak \
         normal force {} kN at {} ms, peak tangential force {} kN at {} ms (the two peaks at different times; their \
         ratio {} against μ = 0.5). The tangential force sits on its Coulomb cap μ F_n (slip) for {} ms, {}% of the \
         contact; for the rest the contact grips and the force is the tangential spring and damper's, \
         |k_t ξ + c_t v_t| < μ F_n. Launch: {} m/s, {} rpm.\n",
        sig(o.contact_time * 1e3, 3),
        sig(o.peak_normal_force * 1e-3, 3),
        sig(o.peak_normal_force_time * 1e3, 3),
        sig(o.peak_tangential_force * 1e-3, 3),
        sig(o.peak_tangential_force_time * 1e3, 3),
        sig(o.peak_tangential_force / o.peak_normal_force, 2),
        sig(o.slip_time * 1e3, 3),
        sig(100.0 * o.slip_time / o.contact_time, 3),
        sig(o.speed, 4),
        sig(o.spin_rpm, 3),
    );

    let _ = writeln!(
        w,
        "## Against published curve-kick studies\n\n\
         Asai, Carré, Akatsuka and Haake (2002, *The curve kick of a football I: impact with the foot*, Sports \
         Engineering) filmed curve kicks and built a finite-element model of the foot–ball impact. They report that \
         spin grows with the offset between foot and ball axis and with friction, that offset matters more than \
         friction (μ from 0 to 1 changed spin by at most 13 rad/s), that the ball spins even with friction near zero \
         because it deforms around the foot, that spin was largest near an offset of about 100 mm, and that speed and \
         spin trade off across offsets.\n\n\
         Where this model follows them: spin grows with offset, speed falls with it (the trade-off), and once μ is \
         moderate the offset dominates. Where a rigid sphere cannot: at μ = 0 the normal force passes through the \
         centre (r ∥ n in Eq. 61), so the spin is exactly zero, where the deforming ball of the FE model spins; and \
         the tilted-face geometry gives no optimum offset inside the ball (e < R) — the optimum near 100 mm comes from \
         a contact patch the rigid geometry lacks. The tangential constants are assumed (above), so details of the \
         spin's dependence on μ near grip are properties of the assumed compliance, not predictions.\n\n\
         ## Checks (`kick check`, `cargo test -p kick-3d`)\n\n\
         Central frictionless = 1D to ≤ 1e-9; zero offset with friction: zero spin; I_b Δω = ∫ r × F dt (Eq. 61); the \
         energy partition (ball translation, ball spin, foot, elastic, normal damping, friction) closes; mechanical \
         energy never rises along the run; mirrored offsets give mirrored spin exactly; μ = ∞ matches the closed-form \
         damped tangential oscillator and, with a stiff critically damped spring, the rigid gripping limit \
         ω = R m_t |v_t0| / I_b; the scene path converges at order 1.\n"
    );
    Ok(w)
}

/// `paper/flight.md`: the free kicks of [`crate::free_kick`] from `out/flight/free_kick.h5`,
/// and the flight outcomes of experiment grids.
pub fn page_flight(out: &Path, report_dir: &Path) -> Result<String, String> {
    let fig = relative(report_dir, &out.join("figures"));
    let path = out.join("flight").join(free_kick::FILE);
    let file = relative(report_dir, &path);
    let data = SweepData::read(&path).map_err(err)?;
    let set = |name: &str| data.set(name).map_err(err);
    let (launch, goal, wall) = (set("launch")?, set("goal")?, set("wall")?);
    let col = |s: &crate::h5::SetData, name: &str| s.column(name).map(<[f64]>::to_vec).ok_or_else(|| format!("{file}: no {name}"));
    let offsets = data.parameter("lateral_offset").map_err(err)?.to_vec();
    let frictions = data.parameter("friction").map_err(err)?.to_vec();
    let (speed, rev, elev, az) = (col(launch, "speed")?, col(launch, "spin_rev_per_s")?, col(launch, "launch_angle")?, col(launch, "launch_azimuth")?);
    let (vx, vy) = (col(launch, "launch_velocity_x")?, col(launch, "launch_velocity_y")?);
    let (gy, gh, gc) = (col(goal, "crossing_lateral_offset")?, col(goal, "crossing_height")?, col(goal, "crossed")?);
    let (wh, wc) = (col(wall, "crossing_height")?, col(wall, "crossed")?);
    let d = free_kick::GOAL_DISTANCE;
    let mut w = String::new();
    let _ = writeln!(w, "# Ball flight: free kicks from the 3D kick\n");
    let _ = writeln!(
        w,
        "Generated by `kick reproduce` (`kick_runner::free_kick`) from `{file}`; every number below is read from that \
         file. The flight model (crate `kick-flight`: drag with the drag crisis, Magnus lift, optional spin decay; \
         sources in `crates/kick-flight/SOURCES.md`) is validated on [validation.md](validation.md).\n"
    );
    let _ = writeln!(w, "## The free kick\n\n{}\n", free_kick::setup_note());
    // A realistic free kick: the rows with speed and spin in the published ranges.
    let realistic: Vec<usize> = (0..data.rows()).filter(|&r| (25.0..=30.0).contains(&speed[r]) && (8.0..=10.0).contains(&rev[r])).collect();
    let describe = |r: usize| format!("e = {} cm, μ = {}", sig(offsets[r] * 100.0, 2), value_label(frictions[r]));
    let _ = writeln!(
        w,
        "Of the {} kicks of the grid, {} leave at 25–30 m/s with 8–10 rev/s, the free kicks Asai et al. (2002) \
         measured: {}.\n",
        data.rows(),
        realistic.len(),
        realistic.iter().map(|&r| format!("{} ({} m/s, {} rev/s)", describe(r), sig(speed[r], 3), sig(rev[r], 2))).collect::<Vec<_>>().join("; ")
    );
    let _ = writeln!(w, "![free kicks from above and from the side]({fig}/flight_free_kick.png)\n");
    let _ = writeln!(w, "![deflection and heights against the lateral offset]({fig}/flight_deflection.png)\n");
    let _ = writeln!(w, "The kicks at μ = 0.5 and μ = ∞ (all four frictions are in the file and the figures):\n");
    let _ = writeln!(
        w,
        "| e (cm) | μ | speed (m/s) | spin (rev/s) | elevation (°) | azimuth (°) | height at the wall (m) | height at {d} m (m) | y at {d} m (m) | curve at {d} m (m) |\n\
         | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"
    );
    for r in 0..data.rows() {
        if frictions[r].to_bits() != 0.5f64.to_bits() && !frictions[r].is_infinite() {
            continue;
        }
        let crossed = gc[r] == 1.0;
        let curve = gy[r] - d * vy[r] / vx[r];
        let _ = writeln!(
            w,
            "| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |",
            sig(offsets[r] * 100.0, 2),
            value_label(frictions[r]),
            sig(speed[r], 3),
            sig(rev[r], 2),
            sig(elev[r], 3),
            sig(az[r], 3),
            if wc[r] == 1.0 { sig(wh[r], 3) } else { "lands first".into() },
            if crossed { sig(gh[r], 3) } else { "lands first".into() },
            if crossed { sig(gy[r], 3) } else { "—".into() },
            if crossed { sig(curve, 3) } else { "—".into() },
        );
    }
    // Deflection per cm of offset, and the friction spread, where the ball reaches the goal line.
    let reach: Vec<usize> = (0..data.rows()).filter(|&r| gc[r] == 1.0).collect();
    let curve = |r: usize| gy[r] - d * vy[r] / vx[r];
    let widest = reach.iter().copied().max_by(|&a, &b| curve(a).abs().total_cmp(&curve(b).abs())).ok_or("no kick reaches the goal line")?;
    let same_offset: Vec<usize> = reach.iter().copied().filter(|&r| offsets[r] == offsets[widest]).collect();
    let (cmin, cmax) = same_offset.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &r| (a.min(curve(r)), b.max(curve(r))));
    let last_offset = reach.iter().map(|&r| offsets[r]).fold(0.0, f64::max);
    let half_row = |e: f64| (0..data.rows()).find(|&r| offsets[r] == e && frictions[r] == 0.5).unwrap_or(0);
    let wall_last = (0..data.rows()).filter(|&r| frictions[r] == 0.5 && wc[r] == 1.0).max_by(|&a, &b| offsets[a].total_cmp(&offsets[b])).unwrap_or(0);
    let _ = writeln!(
        w,
        "\nWhat the figures show. Spin bends the path toward the side the offset sends the ball (Magnus lift \
         along ω × v): the curve at {d} m — lateral position minus the straight launch line's — grows with the \
         lateral offset, to {} m at {}, and the friction coefficients spread it by only {} m at that offset (from {} \
         to {} m over μ), so the offset, not μ, sets the curve. The backspin of the contact below the centre lifts \
         the ball; as the offset grows more of the launch goes sideways and the speed drops, so the ball passes \
         lower: at μ = 0.5 its centre is {} m high at the wall ({} m) for e = 0 and {} m at e = {} cm, and balls \
         launched from offsets above {} cm land before the goal line. The launch direction itself swings out with \
         the offset (the tilted normal of the rigid geometry, [3d.md](3d.md)): a \
         rigid sphere cannot wrap around the foot, so the model's free kick has to be aimed by turning the whole \
         kick about the vertical, which the flight does not change.\n",
        sig(curve(widest), 3),
        describe(widest),
        sig(cmax - cmin, 2),
        sig(cmin, 3),
        sig(cmax, 3),
        sig(wh[half_row(0.0)], 3),
        free_kick::WALL_DISTANCE,
        sig(wh[wall_last], 3),
        sig(offsets[wall_last] * 100.0, 2),
        sig(last_offset * 100.0, 2),
    );
    let _ = writeln!(
        w,
        "## Flight outcomes in experiment grids\n\n\
         Any experiment file (1D or 3D) may carry a `[flight]` table with flight parameters by their declared names \
         (`kick flight --help`: `distance`, `air_density` or `temperature`/`pressure`/`altitude`, `drag_coefficient`, \
         `lift_coefficient`, `spin_decay`; for a 1D kick also `launch_angle` (required), `azimuth`, `ball_radius` and \
         `gravity`, which a 3D kick sets itself). Every row is then flown after its kick (`kick_runner::flight::after_1d`, `after_3d`, bit for \
         bit the same numbers) and the file gets an outcome set `solvers/<solver>+flight` per kick set: \
         `flight_time`, `landing_point_x`/`_y`, `apex_height`, `apex_time`, `landing_velocity_x`/`_y`/`_z`, \
         `landing_spin_x`/`_y`/`_z`, and with `distance` `crossed` (1, or 0 when the ball lands first and the crossing \
         columns hold no number), `crossing_time`, `crossing_height`, `crossing_lateral_offset`, `crossing_velocity_x`/`_y`/`_z`, each \
         with its unit; a row whose kick failed, or whose 3D launch is not upward, has status 1 and its message.\n"
    );
    Ok(w)
}

/// The free-kick file, its figures and both pages: `out/flight/free_kick.h5`,
/// `out/figures/flight_*`, `report_dir/3d.md` and `report_dir/flight.md`.
pub fn write_all(out: &Path, report_dir: &Path, log: &mut dyn Write) -> Result<Vec<PathBuf>, String> {
    let _ = writeln!(log, "\n# free kicks -> {}", out.join("flight").join(free_kick::FILE).display());
    let path = free_kick::write(out)?;
    let drawn = free_kick::figures(&path, &out.join("figures")).map_err(err)?;
    let _ = writeln!(log, "figures: {} files in {}", drawn.len(), out.join("figures").display());
    let mut written = vec![path];
    written.push(crate::output::write(report_dir.join("3d.md"), page_3d(out, report_dir)?).map_err(err)?);
    written.push(crate::output::write(report_dir.join("flight.md"), page_flight(out, report_dir)?).map_err(err)?);
    Ok(written)
}
