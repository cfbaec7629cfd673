"""kick.flight: the declared keywords, and the vacuum parabola as the truth."""

import math

import numpy as np
import pytest

import kick


def test_without_air_forces_the_flight_is_a_parabola():
    v, angle, g = 25.0, 30.0, 9.81
    out = kick.flight(speed=v, launch_angle=angle, drag_coefficient=0.0, lift_coefficient=0.0, gravity=g)
    theta = math.radians(angle)
    assert out["flight_time"] == pytest.approx(2 * v * math.sin(theta) / g, rel=1e-10)
    assert out["landing_point"].shape == (2,)
    assert out["landing_point"][0] == pytest.approx(v * v * math.sin(2 * theta) / g, rel=1e-10)
    assert out["landing_point"][1] == 0.0
    # Apex height of the centre above the ground: R + (v sin θ)²/2g.
    assert out["apex_height"] == pytest.approx(0.11 + (v * math.sin(theta)) ** 2 / (2 * g), rel=1e-10)
    np.testing.assert_allclose(out["landing_velocity"], [v * math.cos(theta), 0.0, -v * math.sin(theta)], rtol=1e-10, atol=1e-9)
    assert out["crossing"] is None


def test_crossing_when_a_distance_is_given():
    v, angle, d, g = 25.0, 30.0, 9.15, 9.81
    out = kick.flight(speed=v, launch_angle=angle, distance=d, drag_coefficient=0.0, lift_coefficient=0.0)
    c = out["crossing"]
    vx, vz = v * math.cos(math.radians(angle)), v * math.sin(math.radians(angle))
    t = d / vx
    assert c["time"] == pytest.approx(t, rel=1e-10)
    assert c["height"] == pytest.approx(0.11 + vz * t - 0.5 * g * t * t, rel=1e-9)
    assert c["velocity"].shape == (3,)


def test_spin_curves_and_keywords_are_the_declared_ones():
    curl = kick.flight(speed=25.0, launch_angle=20.0, spin=(0.0, 0.0, 50.0))
    assert curl["landing_point"][1] > 0.5  # ω_z > 0 curves toward +y (declared doc)
    names = [p["name"] for p in kick.keywords("flight")]
    assert names[:5] == ["speed", "launch_angle", "azimuth", "launch_velocity", "spin"]
    with pytest.raises(ValueError, match=r"unknown flight parameter `sped`: did you mean `speed`\?"):
        kick.flight(sped=20.0, launch_angle=20.0)
    with pytest.raises(ValueError, match="parameter `speed` is required"):
        kick.flight(launch_angle=20.0)
    with pytest.raises(ValueError, match=r"invalid parameter `launch_angle` = 95: must be in \(0, 90\]"):
        kick.flight(speed=20.0, launch_angle=95.0)
    with pytest.raises(ValueError, match="`spin` takes three numbers, got a number"):
        kick.flight(speed=20.0, launch_angle=20.0, spin=3.0)
