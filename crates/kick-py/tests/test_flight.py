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


def test_flight_many_rows_are_single_flights():
    speed = np.array([[20.0, 25.0, -1.0], [27.0, 30.0, 22.0]])
    spin = np.array([0.0, 0.0, 50.0])
    out = kick.flight_many(speed=speed, launch_angle=18.0, spin=spin, distance=9.15, threads=2)
    assert out["flight_time"].shape == (2, 3)
    assert out["landing_point"].shape == (2, 3, 2)
    assert out["crossing_velocity"].shape == (2, 3, 3)
    assert out["status"].dtype == np.uint8
    # The refused row (speed -1) alone: status 3, NaN outcomes, its message.
    assert out["status"].tolist() == [[0, 0, 3], [0, 0, 0]]
    assert np.isnan(out["flight_time"][0, 2])
    assert out["failure_index"].tolist() == [2]
    assert "speed" in out["failure_message"][0]
    for i, j in [(0, 0), (1, 1), (1, 2)]:
        one = kick.flight(speed=float(speed[i, j]), launch_angle=18.0, spin=tuple(spin), distance=9.15)
        assert out["flight_time"][i, j] == one["flight_time"]
        np.testing.assert_array_equal(out["landing_point"][i, j], one["landing_point"])
        assert out["crossing_height"][i, j] == one["crossing"]["height"]
        assert out["launch_drag_coefficient"][i, j] == one["launch"]["drag_coefficient"]
    with pytest.raises(ValueError, match="shape mismatch"):
        kick.flight_many(speed=np.ones(3), launch_angle=np.ones(4))
    with pytest.raises(ValueError, match="`spin` takes three numbers"):
        kick.flight_many(speed=20.0, launch_angle=20.0, spin=np.ones((4, 2)))
    with pytest.raises(ValueError, match="threads"):
        kick.flight_many(speed=20.0, launch_angle=20.0, threads=0)


def test_launch_coefficients_follow_the_spin():
    # No spin: Goff & Carré (2010) Eq. 3 at 25 m/s; spin parameter 0.2 far
    # above the crisis: close to Eq. 4, 0.4127 * 0.2**0.3056.
    v = 25.0
    plain = kick.flight(speed=v, launch_angle=20.0)["launch"]
    assert plain["drag_coefficient"] == pytest.approx(0.155 + 0.346 / (1 + math.exp((v - 12.19) / 1.309)), rel=1e-12)
    assert plain["spin_parameter"] == 0.0 and plain["lift_coefficient"] == 0.0
    # Vertical spin axis, 20° up: |ω × v| = ω v cos 20°.
    w = 0.2 * v / (0.11 * math.cos(math.radians(20.0)))
    spun = kick.flight(speed=v, launch_angle=20.0, spin=(0.0, 0.0, w))["launch"]
    assert spun["spin_parameter"] == pytest.approx(0.2, rel=1e-12)
    assert spun["drag_coefficient"] == pytest.approx(0.4127 * 0.2**0.3056, rel=2e-3)
    assert spun["reynolds"] == pytest.approx(1.225 * v * 0.22 / 1.7894e-5, rel=1e-4)


def test_the_trajectory_comes_as_arrays_and_several_planes_at_once():
    out = kick.flight(speed=27.0, launch_angle=16.0, spin=(0.0, 0.0, 56.5), samples=101, distance=[9.15, 25.0])
    t = out["trajectory"]
    assert t["time"].shape == (101,) and t["position"].shape == (101, 3)
    assert t["velocity"].shape == (101, 3) and t["spin"].shape == (101, 3)
    assert t["time"][0] == 0.0 and t["time"][-1] == out["flight_time"]
    assert t["position"][-1][:2].tolist() == list(out["landing_point"])
    # Each plane's crossing is the one distance's, and lies on the trajectory's path.
    for c in out["crossings"]:
        one = kick.flight(speed=27.0, launch_angle=16.0, spin=(0.0, 0.0, 56.5), distance=c["distance"])["crossing"]
        assert c["time"] == one["time"] and c["height"] == one["height"] and c["lateral_offset"] == one["lateral_offset"]
        assert t["position"][:, 0].min() < c["distance"] < t["position"][:, 0].max()
    with pytest.raises(ValueError, match="samples"):
        kick.flight(speed=27.0, launch_angle=16.0, samples=1)
