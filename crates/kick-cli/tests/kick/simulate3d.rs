//! `kick simulate3d` and `kick run3d`: JSON contract, agreement with kick-3d, errors.

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
