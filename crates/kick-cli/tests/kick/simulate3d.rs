//! `kick simulate3d` and `kick run` on 3D files: JSON contract, agreement with kick-3d, errors.

use crate::kick;

fn vec3(v: &serde_json::Value) -> [f64; 3] {
    let a = v.as_array().expect("array");
    assert_eq!(a.len(), 3);
    [a[0].as_f64().unwrap(), a[1].as_f64().unwrap(), a[2].as_f64().unwrap()]
}

#[test]
fn simulate3d_json_has_the_contract_keys_and_matches_the_library() {
    let out = kick(&["simulate3d", "--offset", "0.05", "--approach-angle", "10", "--friction", "0.6", "--format", "json"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    for key in
        ["speed", "spin_rpm", "launch_angle", "contact_time", "peak_normal_force", "peak_tangential_force", "max_compression", "slip_time"]
    {
        assert!(v[key].is_f64(), "{key}");
    }
    let (launch, spin) = (vec3(&v["launch_velocity"]), vec3(&v["spin"]));
    let norm = |a: [f64; 3]| a.iter().map(|x| x * x).sum::<f64>().sqrt();
    // serde_json's default float parsing may be off by an ulp: compare to 4 ulp.
    let same = |a: f64, b: f64| (a - b).abs() <= 4.0 * f64::EPSILON * b.abs();
    assert!(same(v["speed"].as_f64().unwrap(), norm(launch)));
    assert!(same(v["spin_rpm"].as_f64().unwrap(), norm(spin) * 60.0 / std::f64::consts::TAU));
    assert_eq!(v["solver"], "accurate-3d");
    let k = kick_3d::checks::kick(kick_3d::Kick3dSpec {
        offset: Some(0.05),
        approach_angle_deg: Some(10.0),
        friction: Some(0.6),
        ..Default::default()
    });
    let o = kick_3d::Accurate3d::default().solve(&k).unwrap();
    for i in 0..3 {
        assert!(same(launch[i], o.launch_velocity[i]) && same(spin[i], o.spin[i]));
    }
    assert!(same(v["slip_time"].as_f64().unwrap(), o.slip_time));
}

#[test]
fn simulate3d_central_frictionless_runs_the_1d_solver() {
    let out = kick(&["simulate3d", "--friction", "0", "--format", "json"]);
    assert!(out.status.success());
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["solver"], "1d");
    assert_eq!(vec3(&v["spin"]), [0.0; 3]);
}

/// `--law` and `--restitution` reach the 3D model: a central frictionless
/// kick with Hunt–Crossley's law (1d and accurate paths) gives `kick
/// simulate`'s numbers with the same flags, and the JSON names the law.
#[test]
fn simulate3d_takes_the_contact_law_flags() {
    let law = ["--law", "hunt-crossley-exact", "--restitution", "0.6"];
    let one = kick(&[&["simulate", "--format", "json", "--solver", "accurate"][..], &law].concat());
    assert!(one.status.success(), "{}", String::from_utf8_lossy(&one.stderr));
    let one: serde_json::Value = serde_json::from_slice(&one.stdout).unwrap();
    for solver in ["1d", "accurate"] {
        let out = kick(&[&["simulate3d", "--friction", "0", "--format", "json", "--solver", solver][..], &law].concat());
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
        let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
        assert_eq!(v["law"], "hunt-crossley-exact");
        assert_eq!(v["law_parameters"]["model"], "exact");
        assert_eq!(v["law_parameters"]["target_restitution"], 0.6);
        let (a, b) = (vec3(&v["launch_velocity"])[0], one["v_ball_out"].as_f64().unwrap());
        // The 3D accurate path matches the 1D solver to 1e-9 (kick-3d's MATCH_1D).
        assert!((a - b).abs() <= 1e-9 * b, "{solver}: {a} vs {b}");
    }
    let out = kick(&["simulate3d", "--law", "hertz"]);
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("unknown contact law `hertz`"));
    let out = kick(&["simulate3d", "--law", "flores"]);
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("restitution"));
}

#[test]
fn simulate3d_refuses_bad_input_by_name() {
    for (args, word) in [
        (vec!["simulate3d", "--offset", "0.2"], "offset"),
        (vec!["simulate3d", "--ball-inertia", "1"], "ball_inertia"),
        (vec!["simulate3d", "--friction", "-1"], "friction"),
        (vec!["simulate3d", "--solver", "rapier", "--dt", "0"], "dt"),
        // A step the budget cannot cover is refused up front, naming the flag.
        (vec!["simulate3d", "--solver", "rapier", "--dt", "1e-10"], "`--dt`"),
        (vec!["simulate3d", "--foot-inertia", "1,2"], "foot-inertia"),
        // The flag given is blamed, not the inner half-extent it would make negative.
        (vec!["simulate3d", "--border-radius", "0.04"], "border_radius"),
        (vec!["simulate3d", "--foot-half-extents", "0.03,0,0.05"], "foot_half_extents"),
    ] {
        let out = kick(&args);
        assert!(!out.status.success(), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(word), "{args:?}: {err}");
    }
}

#[test]
fn run3d_is_run_on_the_unified_format() {
    let dir = std::env::temp_dir().join(format!("kick3d-run3d-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("tiny.toml");
    std::fs::write(
        &file,
        "name = \"3d_tiny\"\ndescription = \"tiny\"\n[[sweep]]\nparameter = \"offset\"\nlinear = { from = 0.0, to = 0.04, count = 3 }\n",
    )
    .unwrap();
    let out = kick(&["run3d", file.to_str().unwrap(), "--out", dir.to_str().unwrap()]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(dir.join("3d_tiny.h5").exists());
    let data = kick_store::h5::SweepData::read(&dir.join("3d_tiny.h5")).unwrap();
    assert_eq!(data.parameter("offset").unwrap(), &[0.0, 0.02, 0.04]);
    std::fs::remove_dir_all(&dir).ok();
}

/// `kick simulate3d --format json` with `args`: the parsed object.
fn simulate3d_json(args: &[&str]) -> serde_json::Value {
    let mut all = vec!["simulate3d", "--format", "json"];
    all.extend_from_slice(args);
    let out = kick(&all);
    assert!(out.status.success(), "{args:?}: {}", String::from_utf8_lossy(&out.stderr));
    serde_json::from_slice(&out.stdout).unwrap()
}

/// Run the experiment `text` (3D) into a fresh directory; its file read back.
fn run3d_text(tag: &str, text: &str) -> kick_store::h5::SweepData {
    let dir = std::env::temp_dir().join(format!("kick3d-{tag}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join(format!("{tag}.toml"));
    std::fs::write(&file, text).unwrap();
    let out = kick(&["run3d", file.to_str().unwrap(), "--out", dir.to_str().unwrap()]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let data = kick_store::h5::SweepData::read(&dir.join(format!("3d_{tag}.h5"))).unwrap();
    std::fs::remove_dir_all(&dir).ok();
    data
}

/// A 3D file with no `[[sweep]]` is its one base kick (it failed with
/// "outcome set 0 pushed out of step with the parameters at row 0"), and
/// every declared parameter is a `[base]` key: the shell ball's pressure too.
#[test]
fn a_3d_file_without_a_sweep_is_its_base_kick() {
    let data = run3d_text(
        "nosweep",
        "name = \"3d_nosweep\"\nlevel = \"3d\"\nlaw = \"shell\"\n[base]\noffset = 0.03\ncontact_depth = 0.02\ninflation_pressure = 9.0e4\n",
    );
    let set = data.set("accurate-3d").unwrap();
    assert_eq!(set.status, [0]);
    let one = simulate3d_json(&["--offset", "0.03", "--contact-depth", "0.02", "--law", "shell", "--inflation-pressure", "9e4"]);
    assert_eq!(set.column("speed").unwrap(), [one["speed"].as_f64().unwrap()]);
    let spin = vec3(&one["spin"]);
    assert_eq!([set.column("spin_x").unwrap()[0], set.column("spin_y").unwrap()[0], set.column("spin_z").unwrap()[0]], spin);
    // h > 0 lifts the ball with backspin, e > 0 sends it to -y spinning clockwise from above.
    assert!(spin[1] < 0.0 && spin[2] < 0.0 && vec3(&one["launch_velocity"])[1] < 0.0, "{spin:?}");
}

/// The shell ball's pressure and the air's density are axes of one 3D file
/// whose kicks are flown to two planes: each row is `kick simulate3d
/// --flight --distance 9.15 --distance 25` at its values, and the pressure
/// changes what the ball does (a harder ball leaves faster).
#[test]
fn pressure_and_air_are_axes_of_a_flown_3d_file() {
    let data = run3d_text(
        "axes",
        "name = \"3d_axes\"\nlevel = \"3d\"\nlaw = \"shell\"\n[base]\noffset = 0.04\ncontact_depth = 0.03\n\
         [[sweep]]\nparameter = \"inflation_pressure\"\nvalues = [6.0e4, 1.1e5]\n\
         [[sweep]]\nparameter = \"air_density\"\nvalues = [1.0, 1.225]\n\
         [flight]\ndistances = [9.15, 25.0]\n",
    );
    assert_eq!(data.parameter("inflation_pressure").unwrap(), [6.0e4, 6.0e4, 1.1e5, 1.1e5]);
    assert_eq!(data.parameter("air_density").unwrap(), [1.0, 1.225, 1.0, 1.225]);
    let unit = |name: &str| data.parameters.iter().find(|(c, _)| c.name == name).map(|(c, _)| c.unit.clone());
    assert_eq!(unit("inflation_pressure").as_deref(), Some("Pa"));
    let (kick, flown) = (data.set("accurate-3d").unwrap(), data.set("accurate-3d+flight").unwrap());
    for row in 0..4 {
        let p = data.parameter("inflation_pressure").unwrap()[row].to_string();
        let rho = data.parameter("air_density").unwrap()[row].to_string();
        let one = simulate3d_json(&[
            "--offset",
            "0.04",
            "--contact-depth",
            "0.03",
            "--law",
            "shell",
            "--inflation-pressure",
            &p,
            "--flight",
            "--air-density",
            &rho,
            "--distance",
            "9.15",
            "--distance",
            "25",
        ]);
        assert_eq!(kick.column("speed").unwrap()[row], one["speed"].as_f64().unwrap(), "row {row}");
        for (k, c) in one["flight"]["crossings"].as_array().unwrap().iter().enumerate() {
            for (column, key) in [("crossing_height", "height"), ("crossing_lateral_offset", "lateral_offset"), ("crossing_time", "time")] {
                let stored = flown.column(&format!("{column}_{k}")).unwrap()[row];
                assert_eq!(stored, c[key].as_f64().unwrap(), "row {row} {column}_{k}");
            }
        }
    }
    let speed = kick.column("speed").unwrap();
    assert!(speed[2] > speed[0] + 0.1, "a harder ball leaves faster: {speed:?}");
    // Thinner air: less drag, so the ball reaches 25 m sooner.
    let t = flown.column("crossing_time_1").unwrap();
    assert!(t[0] < t[1] && t[2] < t[3], "{t:?}");
}

/// `kick sweep3d --law shell` samples the pressure (its declared range, or
/// `--range`) and stores no k, c, n; `--flight` flies every kick, and
/// `--range` of a flight parameter wants `--flight`.
#[test]
fn sweep3d_samples_the_pressure_and_flies_its_kicks() {
    let dir = std::env::temp_dir().join(format!("kick3d-sweep3d-range-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("s.h5");
    let out = kick(&[
        "sweep3d",
        "--samples",
        "40",
        "--seed",
        "2",
        "--law",
        "shell",
        "--range",
        "inflation_pressure=5e4,1e5",
        "--contact-depth",
        "0.03",
        "--flight",
        "--distance",
        "9.15",
        "--distance",
        "25",
        "--out",
        file.to_str().unwrap(),
    ]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let data = kick_store::h5::SweepData::read(&file).unwrap();
    let names: Vec<&str> = data.parameters.iter().map(|(c, _)| c.name.as_str()).collect();
    assert!(!names.contains(&"stiffness") && !names.contains(&"damping") && !names.contains(&"exponent"), "{names:?}");
    let pressure = data.parameter("inflation_pressure").unwrap();
    assert!(pressure.iter().all(|p| (5e4..=1e5).contains(p)), "{pressure:?}");
    let mut distinct = pressure.to_vec();
    distinct.sort_by(f64::total_cmp);
    distinct.dedup();
    assert_eq!(distinct.len(), 40);
    let flown = data.sets.iter().find(|s| s.solver.ends_with("+flight")).expect("a flight set");
    let flown_rows = flown.status.iter().filter(|&&s| s == 0).count();
    assert!(flown_rows > 0, "{:?}", flown.status);
    // A row again by hand, every stored parameter as its flag: bit for bit
    // (an unstored k, c or n drawn under the shell law moved it by 2e-14).
    let crossed = flown.column("crossed_1").unwrap();
    let row = (0..crossed.len()).find(|&r| flown.status[r] == 0 && crossed[r] == 1.0).expect("a ball crossing 25 m");
    let mut args: Vec<String> =
        vec!["--law".into(), "shell".into(), "--flight".into(), "--distance".into(), "9.15".into(), "--distance".into(), "25".into()];
    for (c, v) in &data.parameters {
        let Some(p) = kick_core::parameters::find(&c.name) else { continue };
        if p.shape == kick_core::parameters::Shape::Scalar {
            args.push(p.flag());
            args.push(format!("{:?}", v[row]));
        }
    }
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    let one = simulate3d_json(&args);
    let crossing = &one["flight"]["crossings"][1];
    assert_eq!(Some(flown.column("crossing_height_1").unwrap()[row]), crossing["height"].as_f64(), "row {row}: {args:?}");
    let out = kick(&["sweep3d", "--samples", "2", "--range", "air_density=1,1.2", "--out", file.to_str().unwrap()]);
    assert!(!out.status.success() && String::from_utf8_lossy(&out.stderr).contains("add --flight"));
    std::fs::remove_dir_all(&dir).ok();
}

/// `--scene-convergence` prints its own study: a history file, a flight, a
/// format or a solver given with it is refused (they were ignored, and no
/// file was written), and nothing is written.
#[test]
fn scene_convergence_refuses_what_it_would_ignore() {
    let history = std::env::temp_dir().join(format!("kick-scene-{}.csv", std::process::id()));
    for extra in [vec!["--history", history.to_str().unwrap()], vec!["--flight"], vec!["--format", "json"], vec!["--solver", "rapier"]] {
        let mut args = vec!["simulate3d", "--scene-convergence"];
        args.extend(&extra);
        let out = kick(&args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{extra:?}: {stderr}");
        assert!(stderr.contains("cannot be used with") && stderr.contains(extra[0]), "{stderr}");
    }
    assert!(!history.exists());
}
