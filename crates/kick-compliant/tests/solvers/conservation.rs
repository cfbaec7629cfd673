//! Conservation laws and identities of the 1D model, for both solvers.

use crate::support::assert_close;
use kick_compliant::events::{Engine, StopAt};
use kick_compliant::ode::{self, Branch, ContactOde};
use kick_compliant::{Accurate, SeedRk4};
use kick_core::{models, Parameter, RecordingSolver, Scenario, Solver};

fn passive_models() -> Vec<(&'static str, Scenario)> {
    let mut all = models::table2();
    all.extend(models::elastic());
    all.extend(models::linear());
    all
}

/// Eq. 27: without drive, m_f v_f + m_b v_b is conserved. Both RK4 and Dop853
/// preserve linear invariants exactly, so only rounding remains.
#[test]
fn momentum_is_conserved_to_rounding_without_drive() {
    for (case, s) in passive_models() {
        let p0 = s.effective_foot_mass() * s.foot_speed() + s.ball_mass() * s.ball_speed();
        for outcome in [Accurate::default().solve(&s).unwrap(), SeedRk4::default().solve(&s).unwrap()] {
            let p1 = s.effective_foot_mass() * outcome.v_foot_out + s.ball_mass() * outcome.v_ball_out;
            let scale = s.effective_foot_mass() * s.foot_speed().abs() + s.ball_mass() * s.ball_speed().abs();
            assert!((p1 - p0).abs() <= 1e-13 * scale, "{case}: P0 = {p0}, P1 = {p1}");
            // Eq. 2: the ball's momentum change is the integrated impulse.
            assert_close(case, "impulse vs m_b Δv_b", outcome.impulse, s.ball_mass() * (outcome.v_ball_out - s.ball_speed()), 1e-12);
        }
    }
}

/// Eq. 26: with a drive, the total momentum grows by F_drive t_c.
#[test]
fn momentum_grows_by_the_drive_impulse() {
    for (case, s) in models::driven() {
        let o = Accurate::default().solve(&s).unwrap();
        let p0 = s.effective_foot_mass() * s.foot_speed() + s.ball_mass() * s.ball_speed();
        let p1 = s.effective_foot_mass() * o.v_foot_out + s.ball_mass() * o.v_ball_out;
        assert_close(case, "momentum", p1, p0 + s.drive_force() * o.contact_time, 1e-12);
    }
}

/// Eq. 29: at maximum compression both bodies move at V_cm.
#[test]
fn both_move_at_the_centre_of_mass_speed_at_maximum_compression() {
    for (case, s) in passive_models() {
        // The full state where the engine located δ̇ = 0.
        let law = s.contact_law();
        let system = ContactOde::new(&s, law, Branch::InContact);
        let mut engine = Engine::new(Accurate::default().method(), system, &s).unwrap();
        let end = engine.run(&s, &law, ode::initial_state(&s), StopAt::MaxCompression, None).unwrap();
        let (foot_velocity, ball_velocity) = (end.state[ode::FOOT_VELOCITY], end.state[ode::BALL_VELOCITY]);
        let v_cm = s.centre_of_mass_speed();
        let scale = s.foot_speed().abs().max(s.ball_speed().abs());
        assert!((foot_velocity - v_cm).abs() <= 1e-10 * scale, "{case}: v_f {foot_velocity} vs V_cm {v_cm}");
        assert!((ball_velocity - v_cm).abs() <= 1e-10 * scale, "{case}: v_b {ball_velocity} vs V_cm {v_cm}");
    }
}

/// K⁻ + W = K⁺ + U⁺ + D, with D and W integrated on their own.
#[test]
fn energy_identity_closes() {
    let mut all = passive_models();
    all.extend(models::driven());
    for (case, s) in all {
        let accurate = Accurate::default().solve(&s).unwrap();
        assert!(accurate.energy.relative_residual().abs() < 1e-11, "{case}: accurate residual {:e}", accurate.energy.relative_residual());
        // RK4 integrates D alongside the state with the same fourth-order error;
        // the budget closes to that error (measured ≤ 2e-6 on these models at 5 µs).
        let seed = SeedRk4::default().solve(&s).unwrap();
        assert!(seed.energy.relative_residual().abs() < 1e-5, "{case}: seed residual {:e}", seed.energy.relative_residual());
        // Along the whole history too.
        let (_, history) = Accurate::default().solve_recorded(&s, 2e-4).unwrap();
        let k0 = s.initial_kinetic_energy();
        for x in &history.samples {
            let residual = k0 + x.drive_work - (x.kinetic + x.elastic + x.dissipated);
            assert!(residual.abs() < 1e-11 * (k0 + x.drive_work.abs()), "{case} at t = {}: {residual:e}", x.time);
        }
    }
}

/// A passive contact cannot return more relative speed than it received.
#[test]
fn restitution_is_at_most_one_for_passive_contact() {
    for (case, s) in passive_models() {
        let o = Accurate::default().solve(&s).unwrap();
        // Up to the accurate solver's stated 1e-9 relative error.
        assert!(o.restitution <= 1.0 + 1e-9, "{case}: e = {}", o.restitution);
        assert!(o.energy.dissipated >= 0.0, "{case}");
        let damping = s.get(Parameter::Damping);
        if damping == 0.0 {
            assert!((o.restitution - 1.0).abs() < 1e-9, "{case}: e = {}", o.restitution);
        }
    }
}

/// The seed method converges to the accurate answer at fourth order in the
/// smooth observables once the stop quantisation is removed: halving Δt
/// shrinks the exit-speed error by ≥ 2 (the last partial step is first order).
#[test]
fn seed_method_converges_to_the_accurate_solution() {
    let s = Scenario::baseline();
    let exact = Accurate::default().solve(&s).unwrap();
    let mut previous = f64::INFINITY;
    for dt in [2e-5, 1e-5, 5e-6, 2.5e-6] {
        let seed = SeedRk4::new(dt).unwrap().solve(&s).unwrap();
        let error = (seed.v_ball_out - exact.v_ball_out).abs();
        assert!(error < previous / 1.9, "dt = {dt}: error {error:e} vs previous {previous:e}");
        assert!((seed.contact_time - exact.contact_time).abs() <= dt, "dt = {dt}: contact time off by more than a step");
        previous = error;
    }
}
