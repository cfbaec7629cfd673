//! A setting that does not apply is refused, naming it, never ignored: the
//! library functions every front end calls (`kick simulate`, `kick
//! simulate3d`, `kick sweep`, experiment files, Python) share the rule.

use kick_3d::KickSpec;
use kick_core::{LawKind, ScenarioSpec};
use kick_study::experiment::parse;
use kick_study::sample::SampledSweep;
use kick_study::simulate::{simulate, simulate3d};
use std::path::Path;

fn spec(law: LawKind, damping: Option<f64>, restitution: Option<f64>) -> ScenarioSpec {
    ScenarioSpec { law: Some(law), damping, restitution, ..Default::default() }
}

/// `kick simulate --restitution 0.5` (the paper's law), `--law flores
/// --restitution 0.5 --damping 100`, `--solver accurate --dt 1e-6`.
#[test]
fn simulate_refuses_settings_that_do_not_apply() {
    let e = simulate(&spec(LawKind::PowerLaw, None, Some(0.5)), "auto", None, None, None).unwrap_err().to_string();
    assert!(e.starts_with("`restitution` does not apply to law `power-law`"), "{e}");
    let e = simulate(&spec(LawKind::Flores, Some(100.0), Some(0.5)), "auto", None, None, None).unwrap_err().to_string();
    assert!(e.starts_with("`damping` does not apply to law `flores`"), "{e}");
    for solver in ["accurate", "auto", "dop853", "series", "closed-form"] {
        let e = simulate(&ScenarioSpec::default(), solver, Some(1e-6), None, None).unwrap_err().to_string();
        assert!(e.starts_with(&format!("`dt` does not apply to solver `{solver}`")), "{e}");
    }
    // What applies still runs: the fixed-step solvers take dt, each law its own damping.
    for solver in ["seed-rk4", "rk4-events"] {
        assert!(simulate(&ScenarioSpec::default(), solver, Some(1e-6), None, None).is_ok(), "{solver}");
    }
    assert!(simulate(&spec(LawKind::PowerLaw, Some(100.0), None), "auto", None, None, None).is_ok());
    assert!(simulate(&spec(LawKind::Flores, None, Some(0.5)), "auto", None, None, None).is_ok());
}

#[test]
fn simulate3d_refuses_settings_that_do_not_apply() {
    let kick = |scenario| KickSpec { scenario, ..Default::default() };
    let e = simulate3d(&KickSpec::default(), "accurate", Some(1e-6), None, None).unwrap_err().to_string();
    assert!(e.starts_with("`dt` does not apply to 3D solver `accurate`"), "{e}");
    let e = simulate3d(&kick(spec(LawKind::PowerLaw, None, Some(0.5))), "auto", None, None, None).unwrap_err().to_string();
    assert!(e.starts_with("`restitution` does not apply"), "{e}");
    let e = simulate3d(&kick(spec(LawKind::HuntCrossley, Some(50.0), Some(0.5))), "auto", None, None, None).unwrap_err().to_string();
    assert!(e.starts_with("`damping` does not apply to law `hunt-crossley`"), "{e}");
    assert!(simulate3d(&kick(spec(LawKind::HuntCrossley, None, Some(0.5))), "auto", None, None, None).is_ok());
    let e = kick_study::simulate::scene_convergence(&kick(spec(LawKind::PowerLaw, None, Some(0.5)))).unwrap_err().to_string();
    assert!(e.starts_with("`restitution` does not apply"), "{e}");
}

/// `kick sweep --law flores --restitution 0.6 --damping 5`: the held damping is refused.
#[test]
fn a_sweep_refuses_a_held_damping_its_law_ignores() {
    let sweep = SampledSweep { ranges: Default::default(), samples: 2, seed: 1, fixed: spec(LawKind::Flores, Some(5.0), Some(0.6)) };
    let e = sweep.scenario(0).unwrap_err().to_string();
    assert!(e.starts_with("`damping` does not apply to law `flores`"), "{e}");
    let sweep = SampledSweep { ranges: Default::default(), samples: 2, seed: 1, fixed: spec(LawKind::Flores, None, Some(0.6)) };
    assert_eq!(sweep.scenario(0).unwrap().law_kind(), LawKind::Flores);
}

/// Experiment files: the key and its line are named.
#[test]
fn experiment_keys_that_do_not_apply_name_their_line() {
    let cases = [
        // (file, line, key, start of the message)
        ("name = \"e\"\nrestitution = 0.5\n", 2, "restitution", "`restitution` does not apply to law `power-law`"),
        ("name = \"e\"\n[base]\nrestitution = 0.5\n", 3, "base.restitution", "`restitution` does not apply"),
        (
            "name = \"e\"\nlaw = \"flores\"\nrestitution = 0.5\n[base]\ndamping = 10.0\n",
            5,
            "base.damping",
            "`damping` does not apply to law `flores`",
        ),
        (
            "name = \"e\"\nlaw = \"flores\"\nrestitution = 0.5\n[[scenario]]\nname = \"a\"\ndamping = 10.0\n",
            6,
            "scenario.a.damping",
            "`damping` does not apply",
        ),
        (
            "name = \"e\"\nlaw = \"flores\"\nrestitution = 0.5\n[[sweep]]\nparameter = \"damping\"\nvalues = [1.0, 2.0]\n",
            5,
            "sweep.damping",
            "`damping` does not apply",
        ),
        ("name = \"e\"\nsolver = \"accurate\"\ndt = 1e-6\n", 3, "dt", "`dt` does not apply to solver `accurate`"),
        ("name = \"e\"\nsolvers = [\"auto\", \"dop853\"]\ndt = 1e-6\n", 3, "dt", "`dt` does not apply to solver `auto`"),
    ];
    for (text, line, key, message) in cases {
        let e = parse(Path::new("e.toml"), text).unwrap_err();
        assert_eq!((e.line, e.key.as_str()), (line, key), "{text}: {e}");
        assert!(e.message.starts_with(message), "{text}: {e}");
        assert!(e.to_string().contains(&format!("e.toml:{line}")), "{e}");
    }
    // dt beside a fixed-step solver applies to it.
    assert!(parse(Path::new("e.toml"), "name = \"e\"\nsolvers = [\"seed-rk4\", \"accurate\"]\ndt = 1e-6\n").is_ok());
}

/// The same for 3D experiment files.
#[test]
fn experiment_3d_keys_that_do_not_apply_name_their_line() {
    let cases = [
        ("level = \"3d\"\nname = \"e\"\nrestitution = 0.5\n", 3, "restitution"),
        ("level = \"3d\"\nname = \"e\"\nlaw = \"flores\"\nrestitution = 0.5\n[base]\ndamping = 10.0\n", 6, "base.damping"),
        ("level = \"3d\"\nname = \"e\"\n[[sweep]]\nparameter = \"restitution\"\nvalues = [0.5, 0.6]\n", 4, "sweep.restitution"),
    ];
    for (text, line, key) in cases {
        let e = kick_study::experiment::parse(Path::new("e.toml"), text).unwrap_err();
        assert_eq!((e.line, e.key.as_str()), (line, key), "{text}: {e}");
        assert!(e.message.contains("does not apply"), "{text}: {e}");
    }
}

/// `kick sweep` and `kick sweep3d` with `--law shell --inflation-pressure
/// 6e4`: the file records the ball it was solved with (its attributes and
/// the command line), and a 1D row equals a solve with that ball built here.
#[test]
fn a_sweep_records_the_shell_ball_it_solved_with() {
    use kick_store::h5::{read_f64_attr, Compression, SweepData};
    let dir = crate::scratch("shell-ball-sweeps");
    let fixed = ScenarioSpec { law: Some(LawKind::Shell), inflation_pressure: Some(6.0e4), ..Default::default() };
    let settings = kick_store::sweep::SweepSettings {
        ranges: Default::default(),
        samples: 4,
        seed: 3,
        solver: "accurate".into(),
        dt: None,
        out: dir.join("sweep.h5"),
        fixed,
        shard: None,
        threads: None,
        compress: Compression::None,
    };
    let one = kick_store::sweep::sweep(&settings).unwrap().path;
    let mut kick = KickSpec::default();
    kick.scenario = fixed;
    let three = kick_store::sweep3d::sweep3d(&kick_store::sweep3d::Sweep3dSettings {
        ranges: Default::default(),
        flight: None,
        samples: 2,
        seed: 3,
        out: dir.join("sweep3d.h5"),
        fixed: kick,
        shard: None,
        threads: None,
        compress: Compression::None,
    })
    .unwrap()
    .path;
    for path in [&one, &three] {
        let f = hdf5::File::open(path).unwrap();
        // Held: a root attribute, or (a 3D sweep stores every parameter its law uses) a column of that value.
        let held = read_f64_attr(&f, "inflation_pressure").or_else(|| {
            let column = f.dataset("parameters/inflation_pressure").ok()?.read_raw::<f64>().ok()?;
            column.iter().all(|&p| p == column[0]).then(|| column[0])
        });
        assert_eq!(held, Some(6.0e4), "{}", path.display());
        let text = f.attr("experiment_text").unwrap().read_scalar::<hdf5::types::VarLenUnicode>().unwrap().to_string();
        assert!(text.lines().next().unwrap().ends_with("--law shell --inflation-pressure 60000"), "{text}");
    }
    let ball = kick_core::ShellBall::new(6.0e4, kick_core::DEFAULT_BALL_RADIUS, 1.4, 0.0, kick_core::shell::SHELL_DAMPING.default_number())
        .unwrap();
    let data = SweepData::read(&one).unwrap();
    // The shell's file has no k, c, n columns (the law does not use them): any value does.
    let column = |p: kick_core::Parameter| {
        data.parameters.iter().find(|(c, _)| c.name == p.def().name).map_or(kick_core::Scenario::BASELINE.get(p), |(_, v)| v[0])
    };
    let values = kick_core::Parameter::ALL.map(column);
    let scenario = kick_core::Scenario::from_values(values).unwrap().with_shell(ball);
    let solved = kick_core::Solver::solve(&kick_compliant::Accurate::default(), &scenario).unwrap();
    let contact_time = data.sets[0].columns.iter().find(|(c, _)| c.name == "contact_time").map(|(_, v)| v[0]).unwrap();
    assert_eq!(contact_time, solved.contact_time);
}
