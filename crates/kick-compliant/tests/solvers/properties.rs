//! Properties over random passive scenarios around the baseline.

use kick_compliant::Accurate;
use kick_core::{Scenario, Solver};
use proptest::prelude::*;
use proptest::test_runner::RngSeed;

fn passive_scenario() -> impl Strategy<Value = Scenario> {
    (0.3f64..30.0, 0.3f64..0.6, 5.0f64..40.0, -15.0f64..4.0, 4.0f64..7.0, 0.0f64..2000.0, 1.0f64..2.0)
        .prop_map(|(m_f, m_b, v_f, v_b, log_k, c, n)| Scenario::from_values([m_f, m_b, v_f, v_b, 10f64.powf(log_k), c, n, 0.0]).unwrap())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, rng_seed: RngSeed::Fixed(2024), ..ProptestConfig::default() })]

    /// e ≤ 1, momentum conserved, energy closes, V_cm bounds (Eq. 37 with 0 ≤ e ≤ 1).
    #[test]
    fn passive_contacts_obey_the_conservation_laws(s in passive_scenario()) {
        let o = Accurate::default().solve(&s).unwrap();
        prop_assert!(o.restitution <= 1.0 + 1e-9 && o.restitution >= 0.0, "e = {}", o.restitution);
        let p0 = s.effective_foot_mass() * s.foot_speed() + s.ball_mass() * s.ball_speed();
        let p1 = s.effective_foot_mass() * o.v_foot_out + s.ball_mass() * o.v_ball_out;
        let scale = s.effective_foot_mass() * s.foot_speed().abs() + s.ball_mass() * s.ball_speed().abs();
        prop_assert!((p1 - p0).abs() <= 1e-12 * scale);
        // Each energy is accurate to the solver's stated 1e-9 relative.
        prop_assert!(o.energy.relative_residual().abs() < 1e-9, "residual {:e}", o.energy.relative_residual());
        prop_assert!(o.v_ball_out >= s.centre_of_mass_speed() - 1e-9 * scale);
        prop_assert!(o.v_foot_out <= s.centre_of_mass_speed() + 1e-9 * scale);
        prop_assert!(o.contact_time > o.max_compression_time && o.max_compression_time > 0.0);
    }
}
