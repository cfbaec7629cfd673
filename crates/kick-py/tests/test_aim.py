"""kick.aim: the aimed launch flown again by kick.flight reaches the target;
no solution and bad input are ValueErrors saying so."""

import math

import numpy as np
import pytest

import kick


def test_the_aimed_launch_flown_again_reaches_the_target():
    target = (25.0, 2.8, 2.0)
    out = kick.aim(target, spin=(0.0, 0.0, 50.0))
    assert [p["name"] for p in out["parameters"]] == ["speed", "launch_angle", "azimuth"]
    again = kick.flight(launch_velocity=out["launch_velocity"], spin=out["spin"], distance=25.0)
    c = again["crossing"]
    assert math.hypot(c["lateral_offset"] - 2.8, c["height"] - 2.0) <= 1e-6
    assert out["miss"] <= 1e-6 and out["wall_clearance"] >= 0.0
    # The wall plane: the centre passes over the 1.8 m wall (or beside it).
    wall = kick.flight(launch_velocity=out["launch_velocity"], spin=out["spin"], distance=9.15)["crossing"]
    assert max(wall["height"] - 0.11 - 1.8, abs(wall["lateral_offset"]) - 0.11 - 1.0) >= 0.0
    assert out["from"] == "launch" and out["kick"] is None


def test_from_the_kick():
    out = kick.aim([25.0, -2.0, 1.8], from_="kick", wall=(9.15, 1.9, 1.0))
    assert [p["name"] for p in out["parameters"]] == ["foot_speed", "offset", "contact_depth", "heading"]
    assert out["miss"] <= 1e-6 and out["kick"]["contact_time"] > 0.0
    # Kick keywords reach the kick: a heavier foot swings slower to the same target.
    heavy = kick.aim([25.0, -2.0, 1.8], from_="kick", wall=(9.15, 1.9, 1.0), foot_mass=6.0)
    assert heavy["parameters"][0]["value"] < out["parameters"][0]["value"] - 1.0
    with pytest.raises(ValueError, match="--from kick"):
        kick.aim([25.0, -2.0, 1.8], foot_mass=6.0)


def test_a_keyword_holds_its_parameter_under_any_law():
    # "With a 5 cm offset, which foot speed, depth and heading?" on the shell ball at 0.9 bar.
    out = kick.aim([25.0, -2.0, 1.8], from_="kick", offset=0.05, law="shell", inflation_pressure=9.0e4)
    assert [p["name"] for p in out["parameters"]] == ["foot_speed", "contact_depth", "heading"]
    solved = dict(out["kick"]["parameters"])
    assert solved["offset"] == 0.05 and solved["inflation_pressure"] == 9.0e4
    assert "stiffness" not in solved  # the shell ball's law uses no k, c, n
    assert out["family"]["dimension"] == 1 and out["miss"] <= 1e-6
    assert out["wall_pass"] in ("over", "beside")


def test_an_objective_picks_one_member_and_bounds_bound_it():
    target = (25.0, 2.6, 2.0)
    slow = kick.aim(target, spin=(0.0, 0.0, 50.0), objective="min-speed")
    quick = kick.aim(target, spin=(0.0, 0.0, 50.0), objective="min-time")
    speed = lambda out: math.hypot(*out["launch_velocity"])
    assert slow["family"]["objective"] == "min-speed" and quick["family"]["objective"] == "min-time"
    assert speed(slow) < speed(quick)
    assert quick["outcome"]["crossing"]["time"] < slow["outcome"]["crossing"]["time"]
    assert speed(slow) <= slow["family"]["launch_speed"][0] + 1e-3
    bounded = kick.aim(target, spin=(0.0, 0.0, 50.0), bounds={"speed": (26.0, 27.0)})
    p = {q["name"]: q for q in bounded["parameters"]}["speed"]
    assert (p["low"], p["high"]) == (26.0, 27.0) and 26.0 <= p["value"] <= 27.0
    with pytest.raises(ValueError, match="min-foot-speed"):
        kick.aim(target, spin=(0.0, 0.0, 50.0), objective="min-foot-speed")


def test_no_solution_and_bad_input_are_value_errors():
    with pytest.raises(ValueError, match="no solution found within the parameters' ranges"):
        kick.aim((25.0, 0.0, 1.5), speed=12.0)
    with pytest.raises(ValueError, match="`target`"):
        kick.aim((25.0, 0.0, 10.0))
    with pytest.raises(ValueError, match="`target` takes three numbers"):
        kick.aim((25.0, 0.0))
    with pytest.raises(ValueError, match="`wall`"):
        kick.aim((25.0, 0.0, 1.0), wall=(30.0, 1.8, 1.0))
    with pytest.raises(ValueError, match="unknown flight parameter `sped`"):
        kick.aim((25.0, 0.0, 1.0), sped=20.0)
    with pytest.raises(ValueError, match="--from"):
        kick.aim((25.0, 0.0, 1.0), from_="foot")


def test_the_law_keyword_and_the_target_as_kick_aim_takes_them():
    """Issue 33, faults 9 and 10: ``law`` is the kick's normal law as ``kick aim
    --law`` takes it (it was refused as an unknown flight parameter), and
    ``target`` goes through the one argument guard: ``True`` is not 1 m."""
    shell = kick.aim([25.0, -2.0, 1.8], from_="kick", wall=(9.15, 1.9, 1.0), law="shell")
    paper = kick.aim([25.0, -2.0, 1.8], from_="kick", wall=(9.15, 1.9, 1.0))
    assert shell["miss"] <= 1e-6
    assert shell["parameters"][0]["value"] != paper["parameters"][0]["value"]
    with pytest.raises(ValueError, match="--from kick"):
        kick.aim((25.0, 0.0, 1.5), law="shell")
    with pytest.raises(ValueError, match="unknown contact law `hertz`"):
        kick.aim((25.0, 0.0, 1.5), from_="kick", law="hertz")
    for target in [(True, 0.0, 1.0), (25.0, False, 1.0), [25.0, 0.0, True]]:
        with pytest.raises(TypeError, match=r"`target` takes three numbers \(x, y, z\), got .*bool"):
            kick.aim(target)
    with pytest.raises(TypeError, match=r"`wall` takes three numbers .*got .*str"):
        kick.aim((25.0, 0.0, 1.5), wall="9.15,1.8,1")


def test_bounds_go_through_the_argument_guard_in_the_call_s_words():
    target = (20.0, 2.0, 1.5)
    # Said of bounds[...], not of `--range`, an option Python has not.
    for given, match in [
        ({"sped": (10.0, 30.0)}, r'bounds\["sped"\]: not a parameter this aim can free'),
        ({"speed": (30.0, 10.0)}, r'bounds\["speed"\]: LOW and HIGH must be finite with LOW < HIGH'),
        ({"speed": (1.0, 1e200)}, r'bounds\["speed"\]: `speed` must be in \(0, 1000\] m/s'),
    ]:
        with pytest.raises(ValueError, match=match) as refused:
            kick.aim(target, bounds=given)
        assert "--range" not in str(refused.value)
    # A bool is no number (it was taken as 1.0); three numbers are not a pair.
    with pytest.raises(TypeError, match=r'bounds\["speed"\]'):
        kick.aim(target, bounds={"speed": (True, 30.0)})
    with pytest.raises(ValueError, match=r'`bounds\["speed"\]` takes two numbers'):
        kick.aim(target, bounds={"speed": (10.0, 20.0, 30.0)})
    with pytest.raises(TypeError, match="`bounds` takes a dict"):
        kick.aim(target, bounds=[("speed", 10.0, 30.0)])
    # A list, an array: two numbers as well as a tuple.
    listed = kick.aim((25.0, 2.6, 2.0), spin=(0.0, 0.0, 50.0), bounds={"speed": [26.0, 27.0]})
    arrayed = kick.aim((25.0, 2.6, 2.0), spin=(0.0, 0.0, 50.0), bounds={"speed": np.array([26.0, 27.0])})
    np.testing.assert_array_equal(listed["launch_velocity"], arrayed["launch_velocity"])


def test_the_signature_lists_only_what_aim_takes():
    # distance and launch_velocity are refused by aim; they were listed all the same.
    import inspect

    names = inspect.signature(kick.aim).parameters
    assert "distance" not in names and "launch_velocity" not in names
    assert "speed" in names and "foot_speed" in names and "bounds" in names
    for refused in ({"distance": 20.0}, {"launch_velocity": (20.0, 0.0, 5.0)}):
        with pytest.raises(ValueError):
            kick.aim((25.0, 0.0, 1.0), **refused)
