//! Simulated restitution of each law against its target e (n = 1.35, baseline masses).
use kick_compliant::Accurate;
use kick_core::laws::{HysteresisContact, HysteresisModel, KelvinVoigt};
use kick_core::{Parameter, Scenario};

fn main() {
    let solver = Accurate::default();
    println!("{:<22} {:>6} {:>10} {:>10} {:>10}", "law", "e", "e_sim", "first", "x");
    for n in [1.0, 1.35, 1.5] {
        let s = Scenario::baseline().with(Parameter::Exponent, n).unwrap();
        for e in [0.99, 0.95, 0.9, 0.8, 0.7, 0.5, 0.3] {
            for model in [HysteresisModel::HuntCrossley, HysteresisModel::LankaraniNikravesh, HysteresisModel::Flores] {
                let law = HysteresisContact::new(model, s.law().stiffness, n, e, s.approach_speed()).unwrap();
                let o = solver.solve_law(&s, law).unwrap();
                let x = 4.0 / 3.0 * law.hysteresis * s.approach_speed();
                println!("n={n} {:<18?} {e:>6} {:>10.6} {:>10.6} {:>10.6}", model, o.restitution, (1.0 - x).max(0.0).sqrt(), x);
            }
            let kv = KelvinVoigt::from_restitution(1.0e5, s.reduced_mass(), e).unwrap();
            let o = solver.solve_law(&s, kv).unwrap();
            println!("n={n} {:<18} {e:>6} {:>10.6}", "KelvinVoigt", o.restitution);
        }
    }
}
