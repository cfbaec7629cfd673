//! `aim`: the aimed launch flown again on its own reaches the target; an
//! unreachable target is said to be; the sensitivities are the forward
//! flight's slopes; bad scenes are refused by name.

use kick_flight::aim::{aim_launch, AimError, AimSolution, LaunchFree, Wall, MISS_TOLERANCE};
use kick_flight::{solve, Flight, FlightSpec};

/// The crossing (y, z) of plane x = d by the flight of this launch, flown from scratch.
fn fly_to(launch_velocity: [f64; 3], spin: [f64; 3], d: f64) -> [f64; 2] {
    let rest = FlightSpec { distance: Some(d), ..FlightSpec::default() };
    let outcome = solve(&Flight::from_launch(launch_velocity, spin, &rest).unwrap()).unwrap();
    let c = outcome.crossing.expect("reaches the plane");
    [c.lateral_offset, c.height]
}

fn check_reflown(solution: &AimSolution, target: [f64; 3], wall: Wall) {
    let [y, z] = fly_to(solution.launch_velocity, solution.spin, target[0]);
    let miss = (y - target[1]).hypot(z - target[2]);
    assert!(miss <= MISS_TOLERANCE, "re-flown miss {miss} m");
    assert!((miss - solution.miss).abs() <= 1e-9, "reported miss {} vs {miss}", solution.miss);
    let [yw, zw] = fly_to(solution.launch_velocity, solution.spin, wall.distance);
    let r = kick_core::DEFAULT_BALL_RADIUS;
    let clearance = (zw - r - wall.height).max(yw.abs() - r - wall.half_width);
    assert!(clearance >= 0.0, "hits the wall: clearance {clearance} m");
    assert!((clearance - solution.wall_clearance).abs() <= 1e-9);
}

#[test]
fn an_aimed_launch_flown_again_reaches_the_target_over_the_wall() {
    let wall = Wall::default();
    // Under the bar by the far post, with the sidespin of a curled free kick.
    let target = [25.0, 2.8, 2.0];
    let fixed = FlightSpec { spin: Some([0.0, 0.0, 50.0]), ..FlightSpec::default() };
    let solution = aim_launch(target, wall, &LaunchFree::DEFAULT, &fixed).unwrap();
    check_reflown(&solution, target, wall);
    // The launch is the reported speed, elevation and azimuth.
    let [vx, vy, vz] = solution.launch_velocity;
    let value = |name: &str| solution.parameters.iter().find(|p| p.name == name).unwrap().value;
    assert!(((vx * vx + vy * vy + vz * vz).sqrt() - value("speed")).abs() < 1e-12 * value("speed"));
    assert!((vz.atan2(vx.hypot(vy)).to_degrees() - value("launch_angle")).abs() < 1e-9);
    assert!((vy.atan2(vx).to_degrees() - value("azimuth")).abs() < 1e-9);
    // The wall is in the way of a straight line: the path had to rise over it.
    assert!(solution.wall_crossing[0].abs() < wall.half_width + 0.11);
}

/// Speed and elevation held, azimuth and sidespin free: two equations in two
/// unknowns (the spin moves the height through the spinning ball's drag).
#[test]
fn azimuth_and_sidespin_alone_reach_the_corner() {
    let wall = Wall::default();
    let target = [25.0, 3.0, 1.9];
    let fixed = FlightSpec { speed: Some(27.0), launch_angle: Some(18.0), ..FlightSpec::default() };
    let solution = aim_launch(target, wall, &[LaunchFree::Azimuth, LaunchFree::SpinZ], &fixed).unwrap();
    check_reflown(&solution, target, wall);
    assert_eq!(solution.launch_velocity[2], 27.0 * 18f64.to_radians().sin());
    assert_eq!((solution.spin[0], solution.spin[1]), (0.0, 0.0));
}

#[test]
fn a_target_out_of_reach_has_no_solution() {
    // 12 m/s carries a ball at most (12²/g ≈ 14.7 m in vacuum) short of a goal 25 m away.
    let fixed = FlightSpec { speed: Some(12.0), ..FlightSpec::default() };
    match aim_launch([25.0, 0.0, 1.5], Wall::default(), &[LaunchFree::LaunchAngle, LaunchFree::Azimuth], &fixed) {
        Err(AimError::NoSolution { miss, starts, .. }) => {
            assert!(miss > 5.0 && miss.is_finite(), "miss {miss}");
            assert!(starts >= 2);
        }
        other => panic!("expected no solution, got {other:?}"),
    }
    // A wall 10 m high and 5 m to either side: at 25 m/s the only path that
    // comes down under the bar at 25 m and rises over it is a lob steeper
    // than the 60° bound (vacuum: 25 m/s at 60° carries 55 m).
    let fixed = FlightSpec { speed: Some(25.0), ..FlightSpec::default() };
    let wall = Wall { distance: 9.15, height: 10.0, half_width: 5.0 };
    assert!(matches!(
        aim_launch([25.0, 0.0, 1.5], wall, &[LaunchFree::LaunchAngle, LaunchFree::Azimuth], &fixed),
        Err(AimError::NoSolution { .. })
    ));
}

/// The reported ∂(y, z)/∂p against plain central differences of the forward
/// flight built here, at another step (1e-4 of the range).
#[test]
fn sensitivities_are_the_forward_flights_slopes() {
    let target = [25.0, -1.5, 1.6];
    let free = [LaunchFree::Speed, LaunchFree::LaunchAngle, LaunchFree::Azimuth, LaunchFree::SpinZ];
    let fixed = FlightSpec { spin: Some([0.0, -20.0, 30.0]), ..FlightSpec::default() };
    let solution = aim_launch(target, Wall::default(), &free, &fixed).unwrap();
    let values: Vec<f64> = solution.parameters.iter().map(|p| p.value).collect();
    let crossing = |v: &[f64]| -> [f64; 2] {
        let spec = FlightSpec {
            speed: Some(v[0]),
            launch_angle: Some(v[1]),
            azimuth: Some(v[2]),
            spin: Some([0.0, -20.0, v[3]]),
            distance: Some(25.0),
            ..FlightSpec::default()
        };
        let c = solve(&spec.build().unwrap()).unwrap().crossing.unwrap();
        [c.lateral_offset, c.height]
    };
    for (i, p) in solution.parameters.iter().enumerate() {
        let h = 1e-4 * (p.high - p.low);
        let (mut plus, mut minus) = (values.clone(), values.clone());
        plus[i] += h;
        minus[i] -= h;
        let (a, b) = (crossing(&plus), crossing(&minus));
        for k in 0..2 {
            let expected = (a[k] - b[k]) / (2.0 * h);
            let got = p.sensitivity[k];
            // Truncation of the plain difference (~h² f''') and the flight's 1e-12 noise / h.
            assert!((got - expected).abs() <= 1e-5 * expected.abs().max(0.01), "{} [{k}]: {got} vs {expected}", p.name);
        }
    }
}

#[test]
fn bad_scenes_are_refused_by_name() {
    let fixed = FlightSpec::default();
    let name = |target: [f64; 3], wall: Wall| match aim_launch(target, wall, &LaunchFree::DEFAULT, &fixed) {
        Err(AimError::Invalid { name, .. }) => name,
        other => panic!("{target:?} {wall:?}: expected a refusal, got {other:?}"),
    };
    let wall = Wall::default();
    assert_eq!(name([25.0, 0.0, 10.0], wall), "target"); // over the bar
    assert_eq!(name([25.0, 5.0, 1.0], wall), "target"); // wide of the post
    assert_eq!(name([25.0, 0.0, 0.05], wall), "target"); // the ball would be in the ground
    assert_eq!(name([25.0, f64::NAN, 1.0], wall), "target");
    assert_eq!(name([-25.0, 0.0, 1.0], wall), "target");
    assert_eq!(name([25.0, 0.0, 1.0], Wall { distance: 30.0, ..wall }), "wall"); // behind the goal
    assert_eq!(name([25.0, 0.0, 1.0], Wall { height: f64::NAN, ..wall }), "wall");
    assert_eq!(name([25.0, 0.0, 1.0], Wall { half_width: -1.0, ..wall }), "wall");
    assert!(matches!(
        aim_launch([25.0, 0.0, 1.0], wall, &[LaunchFree::Speed, LaunchFree::Speed], &fixed),
        Err(AimError::DuplicateFree { .. })
    ));
    assert!(matches!(aim_launch([25.0, 0.0, 1.0], wall, &[], &fixed), Err(AimError::NoFree)));
    assert!(matches!(LaunchFree::from_name("spinz"), Err(AimError::UnknownFree { .. })));
    // A start outside the range, and a fixed parameter the flight refuses.
    let fast = FlightSpec { speed: Some(80.0), ..fixed };
    assert!(matches!(aim_launch([25.0, 0.0, 1.0], wall, &LaunchFree::DEFAULT, &fast), Err(AimError::Invalid { name: "speed", .. })));
    let thin = FlightSpec { air_density: Some(-1.0), ..fixed };
    assert!(matches!(
        aim_launch([25.0, 0.0, 1.0], wall, &LaunchFree::DEFAULT, &thin),
        Err(AimError::Flight(kick_flight::FlightError::InvalidParameter { name: "air_density", .. }))
    ));
}

/// A low shot at the goal's centre behind a high wall: the path the target
/// alone gives goes through the wall, so the wall's residual has to lift it.
#[test]
fn the_wall_lifts_a_path_that_would_go_through_it() {
    let target = [25.0, 0.3, 0.8];
    let high = Wall { distance: 9.15, height: 2.2, half_width: 1.0 };
    let no_wall = Wall { height: 0.0, half_width: 0.0, ..high };
    let fixed = FlightSpec::default();
    let free = solve_or_panic(aim_launch(target, no_wall, &LaunchFree::DEFAULT, &fixed));
    let r = kick_core::DEFAULT_BALL_RADIUS;
    assert!(free.wall_crossing[1] - r < high.height && free.wall_crossing[0].abs() - r < high.half_width, "{:?}", free.wall_crossing);
    let over = solve_or_panic(aim_launch(target, high, &LaunchFree::DEFAULT, &fixed));
    check_reflown(&over, target, high);
    assert!(over.wall_crossing[1] - r >= high.height, "{:?}", over.wall_crossing);
    // From the first start, where the target alone leads into the wall (no restart needed).
    assert_eq!(over.starts, 1);
    // The sensitivities' flights are counted apart from the solve's (they were left out):
    // flown again here, a free parameter's two differences take four flights.
    assert_eq!(over.sensitivity_flights, 4 * LaunchFree::DEFAULT.len());
}

fn solve_or_panic(r: Result<AimSolution, AimError>) -> AimSolution {
    r.unwrap_or_else(|e| panic!("{e}"))
}

/// A ball both over the wall and beside it is named by the larger margin,
/// the one the clearance reports: 3.566 m over the top and 0.214 m beside
/// (the max-clearance aim's member) is "over", not "beside".
#[test]
fn the_wall_pass_is_named_by_the_larger_margin() {
    use kick_flight::aim::WallPass;
    let wall = Wall { distance: 9.15, height: 1.8, half_width: 1.0 };
    let r = 0.11;
    assert_eq!(WallPass::of(&wall, r, -1.32448, 5.47574), WallPass::Over);
    assert_eq!(WallPass::of(&wall, r, -2.5, 2.0), WallPass::Beside);
    assert_eq!(WallPass::of(&wall, r, 1.5, 1.0), WallPass::Beside);
    assert_eq!(WallPass::of(&wall, r, 0.0, 2.5), WallPass::Over);
    assert_eq!(WallPass::of(&wall, r, 0.5, 1.0), WallPass::Hits);
}
