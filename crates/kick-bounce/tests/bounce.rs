//! `kick_bounce` against closed forms, an independent tolerance-tightened
//! solve, the calibration measurement, and bad input.

use kick_bounce::{normal_scenario, run, solve, BallLaw, Bounce, BounceSpec, LawChoice, NormalSolver, Tangential};
use kick_compliant::Accurate;
use kick_core::laws::exact_restitution;
use kick_core::parameters::Value;
use kick_core::{ContactLaw, KickError};

fn spec(values: &[(&str, Value)]) -> BounceSpec {
    let mut s = BounceSpec::default();
    for &(name, value) in values {
        s.set(name, value).unwrap();
    }
    s
}

fn n(x: f64) -> Value {
    Value::Number(x)
}

fn built(values: &[(&str, Value)]) -> Bounce {
    spec(values).build().unwrap()
}

fn close(a: f64, b: f64, tol: f64, what: &str) {
    assert!((a - b).abs() <= tol * b.abs(), "{what}: {a} vs {b} ({:e} relative)", (a - b).abs() / b.abs());
}

/// The stated speed dependence: at small compression the shell law is
/// Hunt–Crossley, k δ (1 + χ δ̇) with k = 2πR p0 + k_s and
/// χ = β/(p0 + k_s/(2πR)), so restitution is the exact hysteresis relation
/// at x0 = χ V: it falls with speed and rises with pressure through βV/p0.
/// At V ≤ 0.1 m/s (δ ≤ 0.3 mm) the law's own corrections are O(δ/R) in the
/// force (the patch's −δ/2R, the gas's compression): 1 − e is held to within
/// δ_max/R of itself (measured: at most 1.2e-4 of it, against δ_max/R ≈ 2.5e-3).
#[test]
fn slow_impacts_follow_the_hunt_crossley_relation() {
    for (v, beta, k_s, gamma, p) in
        [(0.05, 3600.0, 0.0, 1.4, 8.0e4), (0.05, 1.0e5, 5.0e3, 1.0, 6.0e4), (0.1, 5.0e4, 2.0e4, 1.4, 1.1e5), (0.02, 2.0e5, 0.0, 1.4, 8.0e4)]
    {
        let b = built(&[
            ("speed", n(v)),
            ("gravity", n(0.0)),
            ("shell_damping", n(beta)),
            ("shell_stiffness", n(k_s)),
            ("gas_exponent", n(gamma)),
            ("inflation_pressure", n(p)),
        ]);
        let BallLaw::Shell(law) = b.law else { panic!("the shell by default") };
        let chi = beta / (p + k_s / (2.0 * std::f64::consts::PI * b.radius));
        close(law.small_compression_hysteresis(), chi, 1e-15, "χ");
        let o = solve(&b, NormalSolver::default()).unwrap();
        let e = exact_restitution(chi * v);
        let relative = (o.restitution - e).abs() / (1.0 - e);
        println!("V={v} β={beta}: e {} vs {e} ({relative:.1e} of 1 − e)", o.restitution);
        assert!(relative < o.max_compression / b.radius, "V={v} β={beta}: {} vs {e} ({relative:e} of 1 − e)", o.restitution);
    }
}

/// Restitution rises with pressure over Law 2's range, at the FIFA drop and
/// at a shot's speed; contact time and compression fall (the ball stiffens).
#[test]
fn restitution_rises_with_pressure() {
    let atm = kick_core::shell::SEA_LEVEL_PRESSURE;
    for v in [(2.0 * kick_core::GRAVITY * 2.0_f64).sqrt(), 19.2] {
        let outcomes: Vec<_> = [0.6, 0.7, 0.8, 0.9, 1.0, 1.1]
            .iter()
            .map(|&x| run(&spec(&[("speed", n(v)), ("inflation_pressure", n(x * atm))])).unwrap())
            .collect();
        for w in outcomes.windows(2) {
            assert!(w[1].restitution > w[0].restitution, "V={v}: {:?}", outcomes.iter().map(|o| o.restitution).collect::<Vec<_>>());
            assert!(w[1].contact_time < w[0].contact_time, "V={v}");
            assert!(w[1].max_compression < w[0].max_compression, "V={v}");
        }
    }
}

/// Losses off, no gravity: e = 1, the energy budget closes, and δ_max is
/// the root of U(δ) = ½ μ V² with U the closed-form potential; the peak
/// force is the elastic force there (F_elastic increases with δ).
#[test]
fn lossless_bounce_conserves_energy() {
    for v in [1.0, 6.26, 25.0] {
        let b = built(&[("speed", n(v)), ("gravity", n(0.0)), ("shell_damping", n(0.0)), ("shell_stiffness", n(3.0e3))]);
        let BallLaw::Shell(law) = b.law else { panic!("the shell by default") };
        let scenario = normal_scenario(&b, v).unwrap();
        let o = NormalSolver::default().solve(&scenario, law).unwrap();
        close(o.restitution, 1.0, 1e-9, "e");
        assert!(o.energy.relative_residual().abs() <= 1e-9, "{:?}", o.energy);
        let energy = 0.5 * scenario.reduced_mass() * v * v;
        let d = kick_core::roots::brent(|d| law.potential(d) - energy, 0.0, b.radius, 1e-16, 200).unwrap().x;
        close(o.max_compression, d, 1e-9, "δ_max");
        close(o.peak_force, law.elastic_force(d), 1e-9, "peak force");
        close(o.max_compression_time, o.peak_force_time, 1e-9, "peak at δ_max");
        close(o.max_compression_time, 0.5 * o.contact_time, 1e-9, "symmetric pulse");
    }
}

/// Small impact speed: a linear spring k = 2πR p0 + k_s, so
/// t_c = π √(m/k) and δ_max = V √(m/k); corrections O(δ/R) ≈ 1e-5.
#[test]
fn slow_impact_is_the_pressure_spring() {
    let v = 1e-3;
    let b = built(&[
        ("speed", n(v)),
        ("gravity", n(0.0)),
        ("shell_damping", n(0.0)),
        ("inflation_pressure", n(6.0e4)),
        ("shell_stiffness", n(1.0e4)),
    ]);
    let k = 2.0 * std::f64::consts::PI * b.radius * 6.0e4 + 1.0e4;
    let o = solve(&b, NormalSolver::default()).unwrap();
    close(o.contact_time, std::f64::consts::PI * (b.mass / k).sqrt(), 1e-4, "t_c");
    close(o.max_compression, v * (b.mass / k).sqrt(), 1e-4, "δ_max");
    close(o.peak_force, k * o.max_compression, 1e-4, "F");
}

/// The default solve against Dop853 on the full state at a 100× tighter
/// tolerance: ≤ 1e-9 relative on restitution, peak force, δ_max and the
/// event times (against the contact time).
#[test]
fn tightened_independent_solve_agrees() {
    let tight = NormalSolver::Accurate(Accurate::new(1e-14, 1e-14).unwrap());
    let cases: [&[(&str, Value)]; 8] = [
        &[("drop_height", n(2.0))],
        &[("drop_height", n(2.0)), ("inflation_pressure", n(0.6 * kick_core::shell::SEA_LEVEL_PRESSURE))],
        &[("speed", n(19.2)), ("inflation_pressure", n(1.1 * kick_core::shell::SEA_LEVEL_PRESSURE))],
        // A rebound faster than p0/β: the clamp F = 0 engages before separation.
        &[("speed", n(30.0)), ("inflation_pressure", n(2.0e4)), ("shell_damping", n(2.0e4))],
        &[("speed", n(20.0))],
        &[("speed", n(35.0)), ("inflation_pressure", n(1.1e5))],
        &[
            ("speed", n(12.0)),
            ("gas_exponent", n(1.0)),
            ("shell_stiffness", n(1.0e4)),
            ("angle", n(40.0)),
            ("spin", Value::Vector([0.0, 30.0, 5.0])),
        ],
        &[("speed", n(3.0)), ("shell_damping", n(15000.0))],
    ];
    for values in cases {
        let b = built(values);
        let a = solve(&b, NormalSolver::default()).unwrap();
        let t = solve(&b, tight).unwrap();
        let tc = t.contact_time;
        close(a.restitution, t.restitution, 1e-9, "e");
        close(a.peak_force, t.peak_force, 1e-9, "peak force");
        close(a.max_compression, t.max_compression, 1e-9, "δ_max");
        close(a.contact_time, tc, 1e-9, "t_c");
        assert!((a.peak_force_time - t.peak_force_time).abs() <= 1e-9 * tc, "{values:?}: peak time");
        assert!((a.max_compression_time - t.max_compression_time).abs() <= 1e-9 * tc, "{values:?}: δ_max time");
        for i in 0..3 {
            assert!((a.exit_velocity[i] - t.exit_velocity[i]).abs() <= 1e-9 * b.speed, "{values:?}: v[{i}]");
            assert!((a.exit_spin[i] - t.exit_spin[i]).abs() <= 1e-9 * (b.speed / b.radius), "{values:?}: ω[{i}]");
        }
    }
}

/// The calibration holds: dropped 2 m at 0.8 bar (gravity on during the
/// contact, as in the test), the default ball rebounds to 1.40 m, the middle
/// of FIFA's 115–165 cm; β solved here again by Brent's method on the rebound.
#[test]
fn shell_damping_is_the_fifa_rebound() {
    let o = run(&spec(&[("drop_height", n(2.0))])).unwrap();
    close(o.rebound_height.unwrap(), 1.40, 1e-8, "rebound");
    let rebound = |beta: f64| run(&spec(&[("drop_height", n(2.0)), ("shell_damping", n(beta))])).unwrap().rebound_height.unwrap() - 1.40;
    let beta = kick_core::roots::brent(rebound, 1.0e3, 1.0e4, 1e-12, 200).unwrap().x;
    close(kick_core::shell::SHELL_DAMPING.default_number(), beta, 1e-8, "β");
}

/// The dynamic stiffness against plate tests, as SOURCES.md states it
/// (abstract numbers, not counted as validation). Dowell & Krebs (1991):
/// d = 2.80 v mm; the default ball's δ_max/V at 2, 4 and 6 m/s lies 1–7 %
/// below it, the line is met at the FIFA drop's speed near 0.66 atm
/// (read by the sagitta, d = δ_max), and at a shot's speed the model is
/// stiffer: below 0.9 × 2.80 v at 15 and 30 m/s. Mills et al. (2026): a
/// contact near 0.3 ms / 2.8 % = 10.7 ms at 5.93 m/s is longer than the
/// model's at every pressure in Law 2's range (0.6 atm the softest).
#[test]
fn stiffness_against_plate_tests() {
    let atm = kick_core::shell::SEA_LEVEL_PRESSURE;
    let dk = |v: f64| 2.80e-3 * v;
    for v in [2.0, 4.0, 6.0] {
        let miss = 1.0 - run(&spec(&[("speed", n(v))])).unwrap().max_compression / dk(v);
        assert!((0.01..0.07).contains(&miss), "V={v}: δ_max {miss:.3} below 2.80 V");
    }
    let v0 = (2.0 * kick_core::GRAVITY * 2.0_f64).sqrt();
    let at = |p_atm: f64| run(&spec(&[("speed", n(v0)), ("inflation_pressure", n(p_atm * atm))])).unwrap().max_compression - dk(v0);
    let meets = kick_core::roots::brent(at, 0.6, 1.1, 1e-10, 100).unwrap().x;
    assert!((meets - 0.66).abs() < 0.005, "2.80 V met at {meets} atm");
    for v in [15.0, 30.0] {
        let d = run(&spec(&[("speed", n(v))])).unwrap().max_compression;
        assert!(d < 0.9 * dk(v), "V={v}: {d} vs {}", dk(v));
    }
    let mills = 0.3e-3 / 0.028;
    let softest = run(&spec(&[("speed", n(5.93)), ("inflation_pressure", n(0.6 * atm))])).unwrap().contact_time;
    let fifa = run(&spec(&[("speed", n(5.93))])).unwrap().contact_time;
    assert!(fifa < softest && softest < mills && (softest / mills - 1.0).abs() < 0.06, "{fifa} {softest} vs {mills}");
}

/// Prediction, not fitted: restitution falls with impact speed.
#[test]
fn restitution_falls_with_speed() {
    let e: Vec<f64> = [3.0, 6.0, 12.0, 20.0, 30.0].iter().map(|&v| run(&spec(&[("speed", n(v))])).unwrap().restitution).collect();
    assert!(e.windows(2).all(|w| w[1] < w[0]), "{e:?}");
}

/// Tangential closed forms (impulse model, m_t = m I/(I + m R²) = 2m/5 for a thin shell).
#[test]
fn tangential_impulse_closed_forms() {
    let theta: f64 = 30.0;
    let (s, c) = theta.to_radians().sin_cos();
    let v = 10.0;
    // μ = 0: tangential velocity and spin untouched.
    let o = run(&spec(&[("speed", n(v)), ("angle", n(theta)), ("friction", n(0.0)), ("spin", Value::Vector([1.0, 2.0, 3.0]))])).unwrap();
    assert_eq!(o.tangential, Tangential::Slides);
    assert_eq!((o.exit_velocity[0], o.exit_velocity[1], o.exit_spin), (v * s, 0.0, [1.0, 2.0, 3.0]));
    // μ = ∞, e_t = 0: leaves rolling, v_x = (3/5) V sin θ, ω_y = v_x/R.
    let o = run(&spec(&[("speed", n(v)), ("angle", n(theta)), ("friction", n(f64::INFINITY))])).unwrap();
    let b = built(&[("speed", n(v))]);
    assert_eq!(o.tangential, Tangential::Grips);
    close(o.exit_velocity[0], 0.6 * v * s, 1e-14, "rolling v_x");
    close(o.exit_spin[1], o.exit_velocity[0] / b.radius, 1e-14, "rolling ω_y");
    // e_t = 1 with full grip: the slip reverses, u⁺ = −u⁻.
    let o =
        run(&spec(&[("speed", n(v)), ("angle", n(theta)), ("friction", n(f64::INFINITY)), ("tangential_restitution", n(1.0))])).unwrap();
    close(o.exit_velocity[0] - b.radius * o.exit_spin[1], -v * s, 1e-14, "reversed slip");
    // Sliding throughout: |Δv_t| = μ J_n/m, and J_n = m (1 + e) V cos θ without gravity.
    let o = run(&spec(&[("speed", n(v)), ("angle", n(theta)), ("friction", n(0.1)), ("gravity", n(0.0))])).unwrap();
    assert_eq!(o.tangential, Tangential::Slides);
    close(o.normal_impulse, b.mass * (1.0 + o.restitution) * v * c, 1e-12, "J_n");
    close(v * s - o.exit_velocity[0], 0.1 * o.normal_impulse / b.mass, 1e-12, "Δv_t");
    close(o.exit_velocity[2], o.restitution * v * c, 1e-15, "v_z");
    // Spin about the normal only: no slip, no tangential impulse.
    let o = run(&spec(&[("speed", n(v)), ("spin", Value::Vector([0.0, 0.0, 50.0]))])).unwrap();
    assert_eq!((o.tangential, o.exit_spin, o.exit_velocity[0]), (Tangential::NoSlip, [0.0, 0.0, 50.0], 0.0));
}

/// Every refusal names the parameter (the flag is `--` plus its kebab case).
#[test]
fn bad_input_names_the_parameter() {
    let refused = |values: &[(&str, Value)]| -> String {
        match spec(values).build() {
            Err(KickError::InvalidParameter { name, .. }) => name.to_string(),
            Err(KickError::DoesNotApply { given, .. }) => given.to_string(),
            other => panic!("{values:?}: {other:?}"),
        }
    };
    assert_eq!(refused(&[("speed", n(0.0))]), "speed");
    assert_eq!(refused(&[("speed", n(-3.0))]), "speed");
    assert_eq!(refused(&[("speed", n(f64::NAN))]), "speed");
    assert_eq!(refused(&[]), "speed");
    assert_eq!(refused(&[("speed", n(5.0)), ("angle", n(90.0))]), "angle");
    assert_eq!(refused(&[("speed", n(5.0)), ("angle", n(-1.0))]), "angle");
    assert_eq!(refused(&[("speed", n(5.0)), ("inflation_pressure", n(0.0))]), "inflation_pressure");
    assert_eq!(refused(&[("speed", n(5.0)), ("inflation_pressure", n(-2e4))]), "inflation_pressure");
    assert_eq!(refused(&[("speed", n(5.0)), ("inflation_pressure", n(f64::NAN))]), "inflation_pressure");
    assert_eq!(refused(&[("speed", n(5.0)), ("spin", Value::Vector([0.0, f64::INFINITY, 0.0]))]), "spin");
    assert_eq!(refused(&[("speed", n(5.0)), ("drop_height", n(2.0))]), "speed");
    assert_eq!(refused(&[("drop_height", n(2.0)), ("angle", n(10.0))]), "angle");
    assert_eq!(refused(&[("drop_height", n(2.0)), ("gravity", n(0.0))]), "gravity");
    assert_eq!(refused(&[("drop_height", n(0.0))]), "drop_height");
    assert_eq!(refused(&[("speed", n(5.0)), ("ball_inertia", n(1.0))]), "ball_inertia");
    // The thin shell printed and rounded up (issue 34) is the thin shell; 0.1% above is not.
    let shell = built(&[("speed", n(5.0))]).inertia;
    assert_eq!(built(&[("speed", n(5.0)), ("ball_inertia", n(0.0034687))]).inertia, shell);
    assert_eq!(refused(&[("speed", n(5.0)), ("ball_inertia", n(shell * 1.001))]), "ball_inertia");
    assert_eq!(refused(&[("speed", n(5.0)), ("ball_radius", n(0.0))]), "ball_radius");
    assert_eq!(refused(&[("speed", n(5.0)), ("friction", n(-0.1))]), "friction");
    assert_eq!(refused(&[("speed", n(5.0)), ("gas_exponent", n(2.0))]), "gas_exponent");
    assert_eq!(refused(&[("speed", n(5.0)), ("shell_damping", n(-1.0))]), "shell_damping");
    assert_eq!(refused(&[("speed", n(5.0)), ("tangential_restitution", n(1.5))]), "tangential_restitution");
    let unknown = BounceSpec::default().set("pressure", n(1.0)).unwrap_err().to_string();
    assert!(unknown.contains("inflation_pressure"), "{unknown}");
    let shape = BounceSpec::default().set("spin", n(1.0)).unwrap_err().to_string();
    assert!(shape.contains("spin"), "{shape}");
    kick_core::parameters::check_declarations(&kick_bounce::BOUNCE_PARAMETERS).unwrap();
}

/// Valid values whose 1D contact leaves double precision are refused in the
/// bounce's own names: the refusal names the parameter given (or the ones
/// the quantity comes from), every name in it is a bounce parameter, and no
/// 1D name of the kick (foot_mass, foot_speed, ball_speed, drive_force) is in it.
#[test]
fn refusals_of_the_normal_contact_name_the_bounces_own_parameters() {
    type Case<'a> = (&'a str, &'a [(&'a str, Value)], &'a str);
    // (A drop height past the largest impact speed is refused as invalid
    // before any contact: a_drop_height_beyond_the_largest_impact_speed_is_refused.)
    let cases: [Case; 7] = [
        ("shell", &[("speed", n(5.0)), ("ball_mass", n(1e-300))], "ball_mass"),
        ("shell", &[("speed", n(5.0)), ("ball_mass", n(1e300))], "ball_mass"),
        ("shell", &[("speed", n(1e-300))], "speed"),
        ("shell", &[("speed", n(5.0)), ("gravity", n(1e300))], "gravity"),
        ("shell", &[("speed", n(5.0)), ("ball_radius", n(1e-300))], "ball_radius"),
        ("power-law", &[("speed", n(5.0)), ("stiffness", n(1e-300))], "stiffness"),
        ("power-law", &[("speed", n(5.0)), ("damping", n(1e300))], "damping"),
    ];
    for (law, values, given) in cases {
        let spec = with_law(law, values);
        let error = match run(&spec) {
            Err(e @ KickError::OutOfRange { .. }) => e,
            other => panic!("{values:?}: {other:?}"),
        };
        let KickError::OutOfRange { parameters, quantity, .. } = &error else { unreachable!() };
        let text = error.to_string();
        for one_d in ["foot", "ball_speed", "drive_force"] {
            assert!(!text.contains(one_d), "{values:?}: {text}");
        }
        assert!(!quantity.contains("foot"), "{quantity}");
        let names: Vec<&str> = parameters.split(", ").collect();
        assert!(names.contains(&given), "{values:?}: {text}");
        for name in names {
            assert!(kick_bounce::parameter(name).is_ok(), "{name} in {text}");
        }
    }
}

/// The JSON carries the fields `kick bounce` promises, rebound_height only with a drop.
#[test]
fn json_fields() {
    let o = run(&spec(&[("drop_height", n(2.0))])).unwrap();
    let j = serde_json::to_value(o).unwrap();
    for key in ["restitution", "contact_time", "peak_force", "max_compression", "exit_velocity", "exit_spin", "rebound_height"] {
        assert!(j.get(key).is_some(), "{key}");
    }
    assert_eq!(j["exit_velocity"].as_array().unwrap().len(), 3);
    let o = run(&spec(&[("speed", n(5.0))])).unwrap();
    assert!(serde_json::to_value(o).unwrap().get("rebound_height").is_none());
}

fn with_law(law: &str, values: &[(&str, Value)]) -> BounceSpec {
    let mut s = spec(values);
    s.law = Some(LawChoice::from_name(law).unwrap());
    s
}

/// The kick's default ball (the paper's law, Table 1's k, c, n) on the FIFA
/// test: issue 22 reports e ≈ 0.64, about 0.8 m, where a licensed ball must
/// rebound 1.15–1.65 m; the shell ball meets it.
#[test]
fn the_papers_ball_misses_the_fifa_test() {
    let o = run(&with_law("power-law", &[("drop_height", n(2.0))])).unwrap();
    let h = o.rebound_height.unwrap();
    assert!((0.75..0.85).contains(&h) && (o.restitution - 0.64).abs() < 0.01, "{h} {}", o.restitution);
}

/// A hysteresis law with the exact χ meets its target restitution at the
/// bounce's speed (gravity off), through the same normal phase.
#[test]
fn kick_family_laws_bounce_too() {
    let o = run(&with_law("hunt-crossley-exact", &[("speed", n(15.0)), ("restitution", n(0.7)), ("gravity", n(0.0))])).unwrap();
    close(o.restitution, 0.7, 1e-9, "e");
    let refused = |s: BounceSpec| match s.build() {
        Err(KickError::DoesNotApply { given, .. }) => given,
        other => panic!("{other:?}"),
    };
    assert_eq!(refused(with_law("power-law", &[("speed", n(5.0)), ("inflation_pressure", n(7e4))])), "inflation_pressure");
    assert_eq!(refused(with_law("shell", &[("speed", n(5.0)), ("stiffness", n(1e5))])), "stiffness");
    assert_eq!(refused(with_law("flores", &[("speed", n(5.0)), ("restitution", n(0.7)), ("damping", n(10.0))])), "damping");
    assert!(LawChoice::from_name("hertz").unwrap_err().to_string().contains("shell"));
}

/// A ball set down slowly comes to rest on the plate: its weight holds it
/// once the loss has taken ½ m V² (the energy ½ μ δ̇² + U − m g δ falls
/// below zero at a maximum compression, so it can never get back to
/// δ = 0). That is physics, reported as trapped, not as a solver that ran
/// out of time: at 2 mm/s it was "no separation found" at the 8.8 s horizon.
/// A faster ball, 5 mm/s, still leaves; the proof comes within the first
/// tenth of a second.
#[test]
fn a_slow_ball_comes_to_rest_and_is_said_to() {
    for v in [1e-3, 2e-3] {
        match solve(&built(&[("speed", n(v))]), NormalSolver::default()) {
            Err(KickError::Trapped { time, .. }) => assert!(time < 0.1, "{v}: proven at {time} s"),
            other => panic!("{v}: {other:?}"),
        }
    }
    assert!(solve(&built(&[("speed", n(5e-3))]), NormalSolver::default()).is_ok());
}

/// A grazing ball is trapped only in its normal motion: the refusal says it
/// goes on along the plate at V sin θ (it said the ball "comes to rest",
/// sliding at 20 m/s).
#[test]
fn a_grazing_ball_is_said_to_go_on_along_the_plate() {
    let error = solve(&built(&[("speed", n(20.0)), ("angle", n(89.999))]), NormalSolver::default()).unwrap_err().to_string();
    assert!(error.contains("its motion along the plate (20 m/s) goes on") && !error.contains("comes to rest"), "{error}");
}

/// A drop height is held to the impact speed's own bound, V = √(2 g H) ≤
/// 1000 m/s, and named (1e9 m ran into the solver's step limit instead).
#[test]
fn a_drop_height_beyond_the_largest_impact_speed_is_refused() {
    let limit = 1000.0f64.powi(2) / (2.0 * 9.81);
    let refused = spec(&[("drop_height", n(1.001 * limit)), ("gravity", n(9.81))]).build().unwrap_err();
    assert!(matches!(refused, KickError::InvalidParameter { name: "drop_height", .. }), "{refused:?}");
    assert!(spec(&[("drop_height", n(0.999 * limit)), ("gravity", n(9.81))]).build().is_ok());
    // The bound is read at the gravity given: 1e6 m/s² holds a drop to 0.5 m.
    let refused = spec(&[("drop_height", n(0.6)), ("gravity", n(1e6))]).build().unwrap_err().to_string();
    assert!(refused.contains("= 0.5 m") && refused.contains("g = 1e6") && !refused.contains("9.81"), "{refused}");
    assert!(spec(&[("drop_height", n(0.4)), ("gravity", n(1e6))]).build().is_ok());
}

/// A solver that gives up says where, in seconds, and in words of its own
/// (it said t = 0 s and "Stopped at x = 0.000000216…. Step size underflow.").
#[test]
fn a_solver_that_gives_up_says_when() {
    match run(&spec(&[("speed", n(10.0)), ("ball_radius", n(1e-6))])) {
        Err(KickError::Integration { time, reason }) => {
            assert!(time > 0.0 && time < 1e-3, "{time}");
            assert!(!reason.contains("Stopped at") && reason.contains("step size"), "{reason}");
        }
        other => panic!("{other:?}"),
    }
}
