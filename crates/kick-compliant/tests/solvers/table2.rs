//! Table 2: seed-rk4 prints as the paper, the scenario file is what the fit gives.

use kick_compliant::table2::{self, matches_printed, Table2File};
use kick_compliant::{Accurate, SeedRk4};
use kick_core::paper::TABLE2;
use kick_core::{models, ContactLaw, Solver};

fn scenario_file() -> Table2File {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../experiments/table2.toml");
    Table2File::parse(&std::fs::read_to_string(path).unwrap()).unwrap()
}

#[test]
fn seed_rk4_reproduces_every_printed_digit() {
    let file = scenario_file();
    let seed = SeedRk4::new(file.dt).unwrap();
    for ((name, scenario), printed) in file.scenarios().unwrap().iter().zip(TABLE2.iter()) {
        assert_eq!(name, printed.name);
        let outcome = seed.solve(scenario).unwrap();
        assert!(matches_printed(&outcome, printed), "{name}: {:?}", table2::columns(&outcome));
    }
}

#[test]
fn the_scenario_file_is_what_the_fit_finds() {
    let file = scenario_file();
    let fitted = table2::fit().unwrap();
    assert_eq!(file.row.len(), fitted.row.len());
    for (stored, found) in file.row.iter().zip(&fitted.row) {
        assert_eq!(stored.parameter, found.parameter, "{}", stored.name);
        assert_eq!(stored.value, found.value, "{}", stored.name);
        // The Brent root is converged to 1e-12 of the bracket; allow that.
        match (stored.root, found.root) {
            (Some(a), Some(b)) => assert!((a - b).abs() <= 1e-9 * a.abs(), "{}", stored.name),
            (a, b) => assert_eq!(a, b),
        }
    }
    // The shared test models carry the same values.
    for ((name, scenario), (file_name, file_scenario)) in models::table2().iter().zip(file.scenarios().unwrap()) {
        assert_eq!(*name, file_name);
        assert_eq!(*scenario, file_scenario);
    }
}

/// Where the seed method and the exact answer part: the soft and damped rows'
/// true peak is the damping jump F(0⁺) = c V0 at first touch.
#[test]
fn accurate_peak_is_the_onset_jump_where_damping_dominates() {
    for (name, scenario) in models::table2() {
        let accurate = Accurate::default().solve(&scenario).unwrap();
        let onset = scenario.paper_law().onset_force(scenario.approach_speed());
        let seed = SeedRk4::default().solve(&scenario).unwrap();
        if name == "Very soft ball" || name == "Highly damped" {
            assert_eq!(accurate.peak_force, onset, "{name}");
            assert_eq!(accurate.peak_force_time, 0.0, "{name}");
            assert!(seed.peak_force < onset, "{name}");
        } else {
            assert!(accurate.peak_force > onset, "{name}");
        }
    }
}
