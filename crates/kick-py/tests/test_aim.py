"""kick.aim: the aimed launch flown again by kick.flight reaches the target;
no solution and bad input are ValueErrors saying so."""

import math

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
    assert [p["name"] for p in out["parameters"]] == ["foot_speed", "lateral_offset", "contact_depth", "heading"]
    assert out["miss"] <= 1e-6 and out["kick"]["contact_time"] > 0.0
    # Kick keywords reach the kick: a heavier foot swings slower to the same target.
    heavy = kick.aim([25.0, -2.0, 1.8], from_="kick", wall=(9.15, 1.9, 1.0), foot_mass=6.0)
    assert heavy["parameters"][0]["value"] < out["parameters"][0]["value"] - 1.0
    with pytest.raises(ValueError, match="--from kick"):
        kick.aim([25.0, -2.0, 1.8], foot_mass=6.0)


def test_no_solution_and_bad_input_are_value_errors():
    with pytest.raises(ValueError, match="no solution within the parameters' ranges"):
        kick.aim((25.0, 0.0, 1.5), speed=12.0, free=["launch_angle", "azimuth"])
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
