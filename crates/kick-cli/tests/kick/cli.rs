//! The `kick` binary's contract: names other tools read, exit codes, messages.

use crate::kick;

#[test]
fn simulate_json_has_the_contract_keys_in_si_units() {
    let out = kick(&["simulate", "--format", "json"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let value: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    for key in [
        "v_ball_out",
        "v_foot_out",
        "speed_ratio",
        "peak_force",
        "contact_time",
        "max_compression",
        "impulse",
        "restitution",
        "energy_dissipated",
    ] {
        assert!(value[key].is_f64(), "missing {key}");
    }
    // SI: seconds and metres, not ms and mm (baseline: ~5.3 ms, ~28 mm).
    let contact_time = value["contact_time"].as_f64().unwrap();
    assert!((5.0e-3..6.0e-3).contains(&contact_time), "{contact_time}");
    let compression = value["max_compression"].as_f64().unwrap();
    assert!((0.02..0.04).contains(&compression), "{compression}");
}

#[test]
fn simulate_seed_rk4_matches_the_papers_baseline_text() {
    let out = kick(&["simulate", "--solver", "seed-rk4", "--format", "json"]);
    assert!(out.status.success());
    let value: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    // Eqs. 49–53 as printed (2 decimals of m/s, 3 significant digits elsewhere).
    assert_eq!(format!("{:.2}", value["v_ball_out"].as_f64().unwrap()), "31.98");
    assert_eq!(format!("{:.2}", value["v_foot_out"].as_f64().unwrap()), "17.42");
    assert_eq!(format!("{:.2}", value["contact_time"].as_f64().unwrap() * 1e3), "5.29");
    assert_eq!(format!("{:.2}", value["peak_force"].as_f64().unwrap() / 1e3), "3.80");
    assert_eq!(format!("{:.1}", value["max_compression"].as_f64().unwrap() * 1e3), "27.9");
}

#[test]
fn bad_input_exits_non_zero_and_names_the_problem() {
    let cases: [(&[&str], &str); 6] = [
        (&["simulate", "--foot-mass", "-1"], "foot_mass"),
        (&["simulate", "--stiffness", "0"], "stiffness"),
        (&["simulate", "--damping", "-5"], "damping"),
        (&["simulate", "--exponent", "nan"], "exponent"),
        (&["simulate", "--foot-speed", "3", "--ball-speed", "5"], "no contact"),
        (&["simulate", "--drive-force", "50000"], "no separation"),
    ];
    for (args, needle) in cases {
        let out = kick(args);
        assert!(!out.status.success(), "{args:?} should fail");
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(stderr.contains(needle), "{args:?}: {stderr}");
    }
    let out = kick(&["simulate", "--solver", "euler"]);
    assert!(!out.status.success());
}

#[test]
fn table2_text_and_json() {
    let out = kick(&["table2", "--format", "json"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let rows: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(rows.as_array().unwrap().len(), 8);
    for row in rows.as_array().unwrap() {
        assert_eq!(row["seed_matches_printed"], true, "{}", row["name"]);
        let cell = &row["columns"]["v_ball_out_m_s"];
        assert!(cell["paper"].is_f64() && cell["seed_rk4"].is_f64() && cell["accurate"].is_f64());
    }
}

#[test]
fn simulate_takes_any_contact_law() {
    let out = kick(&["simulate", "--law", "hunt-crossley-exact", "--restitution", "0.6", "--format", "json"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let value: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert!((value["restitution"].as_f64().unwrap() - 0.6).abs() < 1e-8);
    assert_eq!(value["law"]["law"], "hysteresis");
    for (args, needle) in [
        (&["simulate", "--law", "rubber"][..], "rubber"),
        (&["simulate", "--law", "flores"][..], "restitution"),
        (&["simulate", "--law", "kelvin-voigt", "--restitution", "1.4"][..], "restitution"),
    ] {
        let out = kick(args);
        assert!(!out.status.success(), "{args:?}");
        assert!(String::from_utf8_lossy(&out.stderr).contains(needle), "{args:?}");
    }
}

/// A reader that stops early (`kick check | head -1`) closes the pipe: the
/// command ends quietly with its own status (0 here), no panic, no message.
#[test]
fn a_closed_stdout_ends_the_output_quietly() {
    use std::io::{BufRead, BufReader};
    use std::process::Stdio;
    for (args, lines) in
        [(&["check"][..], 0), (&["check"][..], 1), (&["simulate3d", "--format", "json"][..], 1), (&["check", "--format", "json"][..], 0)]
    {
        let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_kick"))
            .args(args)
            .current_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."))
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .expect("kick runs");
        let mut stdout = BufReader::new(child.stdout.take().expect("stdout"));
        for _ in 0..lines {
            let mut line = String::new();
            stdout.read_line(&mut line).expect("a line");
        }
        drop(stdout);
        let out = child.wait_with_output().expect("kick ends");
        assert_eq!(out.status.code(), Some(0), "{args:?} after {lines} lines: {}", String::from_utf8_lossy(&out.stderr));
        assert!(out.stderr.is_empty(), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
    }
}

/// `kick completions SHELL` writes a completion script naming the
/// subcommands and the flags derived from the declared parameters.
#[test]
fn completions_name_the_subcommands_and_the_declared_flags() {
    for shell in ["bash", "zsh", "fish", "elvish", "powershell"] {
        let out = kick(&["completions", shell]);
        assert!(out.status.success(), "{shell}: {}", String::from_utf8_lossy(&out.stderr));
        let text = String::from_utf8(out.stdout).unwrap();
        // fish names a long flag `-l foot-mass`; the others `--foot-mass`.
        let dashes = if shell == "fish" { "-l " } else { "--" };
        for word in ["simulate3d".to_string(), format!("{dashes}foot-mass"), format!("{dashes}offset"), format!("{dashes}restitution")] {
            assert!(text.contains(&word), "{shell} completions lack {word}");
        }
    }
    let out = kick(&["completions", "tcsh"]);
    assert!(!out.status.success());
    let out = kick(&["man"]);
    assert!(out.status.success());
    let page = String::from_utf8(out.stdout).unwrap();
    assert!(page.starts_with(".ie") || page.contains(".TH kick"), "{}", &page[..page.len().min(200)]);
    assert!(page.contains("simulate3d"), "the page lists the subcommands");
}

/// `--compress` of `kick sweep` and `kick sweep3d`: without a value the
/// default level (a file smaller than the plain one), a level outside 1..9
/// refused naming the flag, nothing written.
#[test]
fn sweeps_take_compress_with_or_without_a_level() {
    let dir = std::env::temp_dir().join(format!("kick-compress-test-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    for command in ["sweep", "sweep3d"] {
        let out = |name: &str| dir.join(format!("{command}-{name}.h5")).display().to_string();
        let run = |name: &str, extra: &[&str]| {
            let path = out(name);
            let mut args = vec![command, "--samples", "3000", "--out", path.as_str()];
            args.extend_from_slice(extra);
            kick(&args)
        };
        for (name, extra) in [("plain", &[][..]), ("packed", &["--compress"][..])] {
            let result = run(name, extra);
            assert!(result.status.success(), "{command} {extra:?}: {}", String::from_utf8_lossy(&result.stderr));
        }
        let size = |name: &str| std::fs::metadata(out(name)).unwrap().len();
        assert!(size("packed") < size("plain"), "{command}: {} vs {}", size("packed"), size("plain"));
        for level in ["0", "10"] {
            let result = run("bad", &["--compress", level]);
            let stderr = String::from_utf8_lossy(&result.stderr);
            assert!(!result.status.success() && stderr.contains(&format!("--compress {level}: the deflate level must be 1")), "{stderr}");
            assert!(!std::path::Path::new(&out("bad")).exists());
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// A drawn row the model refuses is that row's failure, not the sweep's:
/// `kick sweep --foot-speed 3` (row 0 draws a ball faster than that) and
/// `kick sweep3d --range offset=0.2,0.3` (every offset beyond the ball's
/// 0.11 m) write their files with the rows refused (the second, with no
/// row answered, exits 1); held values that
/// contradict each other, and a negative plane, are refused before a run.
#[test]
fn drawn_rows_fail_alone_and_held_values_are_checked_first() {
    let dir = std::env::temp_dir().join(format!("kick-drawn-test-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let out = |name: &str| dir.join(format!("{name}.h5")).display().to_string();
    let run = |args: &[&str]| {
        let output = kick(args);
        (output.status.code(), String::from_utf8_lossy(&output.stdout).to_string() + &String::from_utf8_lossy(&output.stderr))
    };
    let (code, text) = run(&["sweep", "--samples", "50", "--foot-speed", "3", "--out", &out("slow")]);
    assert_eq!(code, Some(0), "{text}");
    assert!(text.contains("failed)") && !text.contains("(0 failed)"), "{text}");
    // Every row refused: the file is written whole all the same, and the
    // run, with no answer in it, exits 1 (a_sweep_with_no_answer_exits_1).
    let (code, text) = run(&["sweep3d", "--samples", "20", "--range", "offset=0.2,0.3", "--out", &out("wide")]);
    assert_eq!(code, Some(1), "{text}");
    assert!(text.contains("refused: 20") && std::path::Path::new(&out("wide")).is_file(), "{text}");
    for (args, named) in [
        (vec!["sweep", "--samples", "5", "--foot-speed", "3", "--ball-speed", "5"], "no contact"),
        (vec!["sweep3d", "--samples", "5", "--flight", "--distance=-9"], "`distance` = -9"),
        (vec!["sweep3d", "--samples", "5", "--flight", "--distance", "9", "--distance", "9"], "given twice"),
    ] {
        let mut args = args.clone();
        let path = out("refused");
        args.extend(["--out", path.as_str()]);
        let (code, text) = run(&args);
        assert_eq!(code, Some(1), "{args:?}: {text}");
        assert!(text.contains(named), "{args:?}: {text}");
        assert!(!std::path::Path::new(&path).exists());
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// The generated reference pages: `kick reference cli|parameters` prints
/// them, the same bytes on every run, and the committed pages are what it
/// prints now; each names every subcommand, flag and declared parameter.
#[test]
fn reference_pages_are_current() {
    let root = std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."));
    for page in ["cli", "parameters", "files"] {
        let out = kick(&["reference", page]);
        assert!(out.status.success(), "{page}: {}", String::from_utf8_lossy(&out.stderr));
        assert_eq!(kick(&["reference", page]).stdout, out.stdout, "{page}: not the same bytes on a second run");
        let text = String::from_utf8(out.stdout).unwrap();
        let path = format!("paper/reference/{page}.md");
        let committed = std::fs::read_to_string(root.join(&path)).unwrap_or_default();
        assert!(
            committed == text,
            "{path} is stale (or missing): rewrite it with `cargo run --bin kick -- reference {page} > {path}` and commit it"
        );
    }
    let cli = std::fs::read_to_string(root.join("paper/reference/cli.md")).unwrap();
    let help = String::from_utf8(kick(&["--help"]).stdout).unwrap();
    // Every subcommand `kick --help` lists has its section.
    let commands: Vec<&str> = help
        .lines()
        .skip_while(|l| !l.starts_with("Commands:"))
        .skip(1)
        .take_while(|l| l.starts_with("  "))
        .filter_map(|l| l.split_whitespace().next())
        .filter(|c| *c != "help")
        .collect();
    assert!(commands.len() >= 15, "{help}");
    for command in commands {
        assert!(cli.contains(&format!("## `kick {command}`")), "cli.md lacks `kick {command}`");
    }
    // Flags with their help and defaults, parameter flags from the declared list.
    for parameter in kick_core::parameters::PARAMETERS.iter() {
        assert!(
            cli.contains(&format!("`{} <", parameter.flag())) || cli.contains(&format!("`{}`", parameter.flag())),
            "{}",
            parameter.flag()
        );
    }
    assert!(cli.contains("| `--samples <SAMPLES>` | Number of scenarios (required) |  |"), "kick sweep's --samples");
    assert!(
        cli.contains("| `--out <OUT>` | Directory for the result files; figures go to OUT/figures | results |"),
        "kick reproduce's --out"
    );
    assert!(cli.contains("`--only <STEP>`"), "kick reproduce's --only");
    let parameters = std::fs::read_to_string(root.join("paper/reference/parameters.md")).unwrap();
    for p in kick_core::parameters::PARAMETERS.iter().chain(kick_flight::FLIGHT_PARAMETERS.iter()) {
        assert!(parameters.contains(&format!("| `{}`", p.name)) && parameters.contains(&format!("`{}`", p.flag())), "{}", p.name);
    }
}

#[test]
fn a_ball_hitting_a_resting_foot_has_an_undefined_speed_ratio_and_every_other_observable() {
    // v_f⁻ = 0: v_b⁺ / v_f⁻ is undefined (null, "undefined"), not a failure.
    let args = ["simulate", "--foot-speed", "0", "--ball-speed", "-6", "--drive-force", "0"];
    let out = kick(&[&args[..], &["--format", "json"]].concat());
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let value: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert!(value["speed_ratio"].is_null(), "{}", value["speed_ratio"]);
    // Momentum is conserved without a drive: m_f v_f⁺ + m_b v_b⁺ = m_b v_b⁻.
    let (m_f, m_b) = (value["scenario"]["foot_mass"].as_f64().unwrap(), value["scenario"]["ball_mass"].as_f64().unwrap());
    let (v_f, v_b) = (value["v_foot_out"].as_f64().unwrap(), value["v_ball_out"].as_f64().unwrap());
    assert!((m_f * v_f + m_b * v_b - m_b * -6.0).abs() < 1e-9 * m_b * 6.0, "{v_f} {v_b}");
    let e = value["restitution"].as_f64().unwrap();
    assert!(e > 0.0 && e <= 1.0, "{e}");
    let text = kick(&args);
    assert!(text.status.success(), "{}", String::from_utf8_lossy(&text.stderr));
    let line = String::from_utf8_lossy(&text.stdout).lines().find(|l| l.starts_with("speed_ratio")).unwrap().to_string();
    assert!(line.contains("undefined"), "{line}");
}

/// `--law shell` is the pressurised ball (kick-core's ShellBall) from its
/// declared defaults: the CLI's kick is `Accurate::solve_law` with that ball
/// on Table 1's scenario, bit for bit (the law's closed forms are held in
/// kick-core and kick-bounce); its flags are refused under the paper's law,
/// and the paper's damping/restitution under it.
#[test]
fn simulate_takes_the_shell_ball_by_name() {
    use kick_core::{Scenario, ShellBall, DEFAULT_BALL_RADIUS};
    let out = kick(&["simulate", "--law", "shell", "--solver", "accurate", "--format", "json"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let value: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(value["law"]["law"], "shell");
    let ball = ShellBall::default_with_radius(DEFAULT_BALL_RADIUS).unwrap();
    let expected = kick_compliant::Accurate::default().solve_law(&Scenario::BASELINE, ball).unwrap();
    let got = |key: &str| value[key].as_f64().unwrap().to_bits();
    assert_eq!(got("contact_time"), expected.contact_time.to_bits());
    assert_eq!(got("v_ball_out"), expected.v_ball_out.to_bits());
    assert_eq!(got("v_foot_out"), expected.v_foot_out.to_bits());
    assert_eq!(got("peak_force"), expected.peak_force.to_bits());
    assert_eq!(got("max_compression"), expected.max_compression.to_bits());
    assert_eq!(got("restitution"), expected.restitution.to_bits());
    // The default (auto) path gives the same kick.
    let auto = kick(&["simulate", "--law", "shell", "--format", "json"]);
    let auto: serde_json::Value = serde_json::from_slice(&auto.stdout).unwrap();
    let t = auto["contact_time"].as_f64().unwrap();
    assert!((t / expected.contact_time - 1.0).abs() < 1e-9, "{t} vs {}", expected.contact_time);
    // A set pressure reaches the ball: a softer ball stays on longer.
    let soft = kick(&["simulate", "--law", "shell", "--inflation-pressure", "6e4", "--format", "json"]);
    let soft: serde_json::Value = serde_json::from_slice(&soft.stdout).unwrap();
    assert!(soft["contact_time"].as_f64().unwrap() > t);
    for (args, needle) in [
        (&["simulate", "--inflation-pressure", "7e4"][..], "inflation_pressure"),
        (&["simulate", "--law", "flores", "--restitution", "0.6", "--shell-damping", "3000"][..], "shell_damping"),
        (&["simulate", "--law", "shell", "--damping", "100"][..], "damping"),
        (&["simulate", "--law", "shell", "--restitution", "0.6"][..], "restitution"),
    ] {
        let out = kick(args);
        assert!(!out.status.success(), "{args:?}");
        assert!(String::from_utf8_lossy(&out.stderr).contains(needle), "{args:?}");
    }
}

/// `kick bench`'s settings and folders are refused before any timing: a
/// min-time of 1e300 s timed its first point for ever, NaN ran the default,
/// and an output folder that cannot be made failed after the whole run.
#[test]
fn bench_settings_and_folders_are_refused_before_timing() {
    for (args, named) in [
        (&["bench", "--min-time", "1e300"][..], "--min-time 1e300"),
        (&["bench", "--min-time", "NaN"][..], "--min-time NaN"),
        (&["bench", "--min-time", "0"][..], "--min-time 0"),
        (&["bench", "--quick", "--sweep-samples", "0"][..], "--sweep-samples 0"),
        (&["bench", "--quick", "--sweep-samples", "100000000000"][..], "--sweep-samples 100000000000"),
        (&["bench", "--quick", "--out", "/proc/kick-bench"][..], "/proc/kick-bench/figures"),
        (&["bench", "--quick", "--out", "/tmp", "--report", "/proc/kick-bench/timing.md"][..], "/proc/kick-bench"),
    ] {
        let started = std::time::Instant::now();
        let out = kick(args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{args:?}: {stderr}");
        assert!(stderr.contains(named), "{args:?}: {stderr}");
        assert!(started.elapsed().as_secs_f64() < 5.0, "{args:?} took {:?}", started.elapsed());
    }
}

/// A sweep whose every row is refused is written whole, and said to have
/// no answer with exit 1 (it exited 0 under "10 failed", and `kick sweep`
/// printed an empty list of auto paths).
#[test]
fn a_sweep_with_no_answer_exits_1() {
    let dir = std::env::temp_dir().join(format!("kick-no-answer-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    for (args, file) in [
        (vec!["sweep", "--samples", "10", "--range", "ball_speed=100,200"], "d.h5"),
        (vec!["sweep3d", "--samples", "10", "--range", "offset=1,2"], "e.h5"),
    ] {
        let path = dir.join(file);
        let mut args = args.clone();
        let out_path = path.to_string_lossy().into_owned();
        args.extend(["--out", &out_path]);
        let out = kick(&args);
        let (stdout, stderr) = (String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr));
        assert_eq!(out.status.code(), Some(1), "{args:?}: {stderr}");
        assert!(stderr.contains("every one of the 10") && stderr.contains("failures/message"), "{stderr}");
        assert!(!stdout.contains("auto paths over the first 10 scenarios: \n"), "{stdout}");
        assert!(path.is_file(), "{args:?}: the file of failures is written");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// A vector flag with the wrong count is refused where clap knows the
/// subcommand: its usage line is the subcommand's (it printed
/// `Usage: kick <COMMAND>` after two blank lines).
#[test]
fn a_vector_flag_with_the_wrong_count_names_its_subcommand() {
    for (args, got) in [
        (&["simulate3d", "--foot-inertia", "1,2"][..], "got 2"),
        (&["flight", "--speed", "25", "--launch-angle", "20", "--spin", "1,2,3,4"][..], "got 4"),
    ] {
        let out = kick(args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{stderr}");
        assert!(stderr.contains(&format!("takes three numbers (x,y,z), {got}")), "{stderr}");
        assert!(!stderr.contains("kick <COMMAND>") && !stderr.contains("\n\n\n"), "{stderr}");
    }
    // Negative components stay values, not flags.
    let out = kick(&["flight", "--speed", "25", "--launch-angle", "20", "--spin", "-4,3,2", "--format", "json"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
}

/// `kick run --out` is a folder, and a refusal quotes the folder given (a
/// file there was quoted as `--out` = `FILE/NAME.h5`).
#[test]
fn kick_run_out_is_said_as_given() {
    let file = std::env::temp_dir().join(format!("kick-run-out-{}.toml", std::process::id()));
    std::fs::write(&file, "not a folder").unwrap();
    let given = file.to_string_lossy().into_owned();
    let out = kick(&["run", "experiments/3d/offset.toml", "--out", &given]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains(&format!("`--out` = `{given}`: it is a file, not a folder")), "{stderr}");
    let _ = std::fs::remove_file(&file);
}
