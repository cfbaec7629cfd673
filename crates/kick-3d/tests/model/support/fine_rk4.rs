//! An independent check of peaks: classical RK4 at a fixed step h of
//! 1/steps of the contact (graded near first touch, h_i = t_i/100, where δⁿ
//! is not smooth and would otherwise cost RK4 its order), every step
//! sampled; grip/slip switches (the sign of the phase's switch function,
//! `kick_3d::tangential`) located by bisection on RK4 sub-steps from the
//! step's start, the phase switched there (the spring put on the cap where
//! grip starts) and the step finished from there, so none straddles the kink; a smooth maximum taken as the maximum of the quartic through
//! the five samples around the largest (time error O(h⁴)).
//!
//! Shares only the right-hand side (`Dynamics`) with the solvers: no
//! adaptive steps, no event machinery, no rate estimates.

use kick_3d::dynamics::{self, Dynamics, State};
use kick_3d::Kick3d;

/// (value, time) of the largest normal and tangential force.
pub type FinePeaks = [(f64, f64); 2];

fn watched(d: &Dynamics, y: &State) -> [f64; 2] {
    let c = d.contact(y);
    [c.normal_force, c.tangential_force.length()]
}

/// A sample: time, values, and whether it is a located switch (a kink).
struct Point {
    t: f64,
    q: [f64; 2],
    switch: bool,
}

/// One RK4 step of `step` from (d, y), stopped at a grip/slip switch inside
/// it: (the state at the step's end or at the switch, the time taken, the
/// right-hand side to go on with, whether it switched).
fn march(d: Dynamics, y: &State, step: f64) -> (State, f64, Dynamics, bool) {
    let next = d.rk4_step(y, step);
    let (g0, g1) = (d.contact(y).grip_margin, d.contact(&next).grip_margin);
    if !((g0 > 0.0 && g1 < 0.0) || (g0 < 0.0 && g1 > 0.0)) {
        return (next, step, d, false);
    }
    // Bisect the switch on sub-steps from y (each exact to O(h^5)).
    let (mut lo, mut hi) = (0.0, step);
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        let g = d.contact(&d.rk4_step(y, mid)).grip_margin;
        if (g > 0.0) == (g0 > 0.0) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let at_switch = d.rk4_step(y, hi);
    let at_switch = if d.slipping { d.spring_on_cap(&at_switch) } else { at_switch };
    (at_switch, hi, d.switched(), true)
}

/// Peaks of `kick` over a contact of about `contact_time`, with `steps` RK4 steps over it.
pub fn peaks(kick: &Kick3d, contact_time: f64, steps: f64) -> FinePeaks {
    let mut y = dynamics::initial_state(kick);
    let mut d = Dynamics::new(kick).at_touch(&y);
    let h = contact_time / steps;
    let mut t = 0.0;
    let mut points = vec![Point { t, q: watched(&d, &y), switch: false }];
    while t < 2.0 * contact_time {
        let step = if t < 100.0 * h { (0.01 * t).max(1e-9 * h) } else { h };
        let (mut next, taken, after, switched) = march(d, &y, step);
        if switched {
            // The switch is a sample of both phases; the step is finished from there.
            points.push(Point { t: t + taken, q: watched(&d, &next), switch: true });
            next = after.rk4_step(&next, step - taken);
        }
        d = after;
        y = next;
        t += step;
        if d.contact(&y).compression < 0.0 {
            break;
        }
        points.push(Point { t, q: watched(&d, &y), switch: false });
    }
    [0, 1].map(|k| {
        let (i, best) = points.iter().enumerate().fold((0, f64::MIN), |acc, (i, p)| if p.q[k] > acc.1 { (i, p.q[k]) } else { acc });
        let p = &points[i];
        if p.switch || i < 2 || i + 2 >= points.len() {
            return (best, p.t);
        }
        let f: Vec<f64> = points[i - 2..=i + 2].iter().map(|p| p.q[k]).collect();
        assert!(points[i - 2].t >= 100.0 * h, "a maximum in the graded start: change the step");
        assert!(
            points[i - 2..=i + 2].iter().all(|p| !p.switch),
            "a smooth maximum within two steps of a switch at t = {}: change the step",
            p.t
        );
        let (value, s) = kick_core::roots::quartic_maximum([f[0], f[1], f[2], f[3], f[4]]);
        (value, p.t + s * h)
    })
}

/// The world-frame state and its phase's right-hand side at each of `times`
/// (ascending, all before separation), RK4 as [`peaks`] marches (graded
/// start, switches located, no step across one); a time inside a step is
/// reached by one RK4 sub-step from the step's start, and the march goes on
/// from the step's end.
pub fn states_at(kick: &Kick3d, times: &[f64], contact_time: f64, steps: f64) -> Vec<(State, Dynamics)> {
    let mut y = dynamics::initial_state(kick);
    let mut d = Dynamics::new(kick).at_touch(&y);
    let h = contact_time / steps;
    let mut t = 0.0;
    let mut out = Vec::with_capacity(times.len());
    let mut next_time = times.iter().peekable();
    while let Some(&&target) = next_time.peek() {
        let step = if t < 100.0 * h { (0.01 * t).max(1e-9 * h) } else { h };
        // Stop this step at a switch: the next starts there.
        let (next, taken, after, _) = march(d, &y, step);
        let end = t + taken;
        if target <= end {
            out.push((d.rk4_step(&y, target - t), d));
            next_time.next();
            continue;
        }
        d = after;
        y = next;
        t = end;
    }
    out
}
