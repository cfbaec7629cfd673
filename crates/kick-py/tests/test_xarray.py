"""kick.to_xarray: dimensions from the broadcast axes, coordinates equal to the inputs, declared units."""

import numpy as np
import pytest

xr = pytest.importorskip("xarray")

import kick  # noqa: E402


def declared(name, level_flight=False):
    return next(p for p in kick.PARAMETERS if p["name"] == name and (p["level"] == "flight") == level_flight)


def test_1d_axes_coordinates_and_units():
    mass = np.geomspace(0.5, 15.0, 5)[:, None]
    stiffness = np.geomspace(1e4, 1e7, 4)
    out = kick.simulate_many(foot_mass=mass, stiffness=stiffness, damping=30.0, solver="accurate")
    ds = kick.to_xarray(out)
    assert ds["v_ball_out"].dims == ("foot_mass", "stiffness")
    np.testing.assert_array_equal(ds["foot_mass"].values, mass[:, 0])
    np.testing.assert_array_equal(ds["stiffness"].values, stiffness)
    assert ds["damping"].ndim == 0 and ds["damping"].item() == 30.0
    for name in ("foot_mass", "stiffness", "damping"):
        assert ds[name].attrs["units"] == declared(name)["unit"], name
    units = dict(kick.OBSERVABLES)
    assert ds["v_ball_out"].attrs["units"] == units["v_ball_out"] == "m/s"
    assert ds["energy_residual"].attrs["units"] == "J"
    np.testing.assert_array_equal(ds["v_ball_out"].values, out["v_ball_out"])
    assert ds["status"].dtype == np.uint8 and ds.attrs["function"] == "simulate_many" and ds.attrs["solver"] == "accurate"
    # Selection by the physical value, as xarray users expect.
    assert ds["v_ball_out"].sel(foot_mass=mass[2, 0], stiffness=stiffness[1]).item() == out["v_ball_out"][2, 1]
    # No vector here: no `xyz` axis (a stray one was always added).
    assert "xyz" not in ds.dims and "xyz" not in ds.coords


def test_zero_rows_label_as_any_other():
    # An axis of length 0 (it raised IndexError).
    ds = kick.to_xarray(kick.simulate_many(foot_mass=np.empty(0)))
    assert ds["v_ball_out"].shape == (0,) and ds["v_ball_out"].dims == ("foot_mass",)
    ds = kick.to_xarray(kick.simulate_many(foot_mass=np.empty((0, 1)), stiffness=[3e5, 4e5]))
    assert ds["v_ball_out"].shape == (0, 2) and ds["v_ball_out"].dims == ("foot_mass", "stiffness")


def test_failures_land_on_their_rows():
    drive = np.array([0.0, 5e4, 0.0])  # the 5e4 N drive on a soft foot traps the ball
    out = kick.simulate_many(drive_force=drive, foot_mass=8.0, stiffness=1e4)
    ds = kick.to_xarray(out)
    assert ds["status"].dims == ("drive_force",)
    assert list(ds["status"].values) == list(out["status"])
    assert out["status"][1] != 0 and ds["failure_message"].values[1] == out["failure_message"][0]
    assert ds["failure_message"].values[0] == "" and np.isnan(ds["v_ball_out"].values[1])


def test_3d_vectors_and_unnamed_axes():
    offset = np.linspace(0.0, 0.06, 3)
    extents = np.array([[0.03, 0.12, 0.05], [0.03, 0.10, 0.04]])[:, None, :]
    out = kick.simulate3d_many(offset=offset, foot_half_extents=extents, friction=0.5)
    ds = kick.to_xarray(out)
    # Axis 0 is spanned by a vector input only: unnamed, the vector a coordinate over it.
    assert ds["spin"].dims == ("dim_0", "offset", "xyz")
    assert list(ds["xyz"].values) == ["x", "y", "z"]
    np.testing.assert_array_equal(ds["offset"].values, offset)
    np.testing.assert_array_equal(ds["foot_half_extents"].values, extents[:, 0, :])
    assert ds["foot_half_extents"].dims == ("dim_0", "xyz")
    assert ds["foot_half_extents"].attrs["units"] == declared("foot_half_extents")["unit"]
    units = dict(kick._kick.OBSERVABLES_3D)
    assert ds["spin"].attrs["units"] == units["spin_x"] == "rad/s"
    assert ds["launch_velocity"].attrs["units"] == "m/s" and ds["contact_time"].attrs["units"] == "s"
    np.testing.assert_array_equal(ds["spin"].values, out["spin"])
    # Every number has its unit (the fixed-point angular impulse had none).
    assert ds["angular_impulse_fixed_point"].attrs["units"] == "N m s"
    assert all(v.attrs["units"] for k, v in ds.data_vars.items() if k != "failure_message"), [
        k for k, v in ds.data_vars.items() if not v.attrs["units"]
    ]


def test_flight_axes_and_units():
    speed = np.array([20.0, 25.0, 30.0])
    angle = np.array([10.0, 20.0])[:, None]
    out = kick.flight_many(speed=speed, launch_angle=angle, distance=20.0)
    ds = kick.to_xarray(out)
    assert ds["flight_time"].dims == ("launch_angle", "speed")
    assert ds["landing_point"].dims == ("launch_angle", "speed", "xy")
    assert ds["landing_point"].attrs["units"] == "m" and ds["crossing_height"].attrs["units"] == "m"
    assert ds["speed"].attrs["units"] == declared("speed", True)["unit"] == "m/s"
    assert ds["launch_angle"].attrs["units"] == declared("launch_angle", True)["unit"]
    np.testing.assert_array_equal(ds["speed"].values, speed)
    np.testing.assert_array_equal(ds["flight_time"].values, out["flight_time"])


def test_flown_kicks_label_their_planes():
    """Two crossing planes are a `distance` axis, not `xy` (an axis of 2 is not a point)."""
    offset = np.array([0.0, 0.03, 0.06])
    out = kick.simulate3d_many(offset=offset, contact_depth=0.03, flight=True, distance=[9.15, 25.0])
    ds = kick.to_xarray(out)
    assert ds["crossing_height"].dims == ("offset", "distance")
    assert ds["crossing_velocity"].dims == ("offset", "distance", "xyz")
    assert ds["landing_point"].dims == ("offset", "xy")
    np.testing.assert_array_equal(ds["distance"].values, [9.15, 25.0])
    assert ds["distance"].attrs["units"] == "m" and "distance" not in ds.attrs
    assert ds["crossing_height"].attrs["units"] == "m" and ds["flight_time"].attrs["units"] == "s"
    np.testing.assert_array_equal(ds["crossing_lateral_offset"].sel(distance=25.0).values, out["crossing_lateral_offset"][:, 1])
    # One plane: no plane axis.
    one = kick.to_xarray(kick.simulate3d_many(offset=offset, contact_depth=0.03, flight=True, distance=25.0))
    assert one["crossing_height"].dims == ("offset",) and one.attrs["distance"] == 25.0


def test_two_inputs_along_one_axis_and_a_plain_dict():
    mass = np.array([2.0, 4.0, 8.0])
    stiffness = np.array([2e5, 4e5, 8e5])
    args = dict(foot_mass=mass, stiffness=stiffness)
    out = kick.simulate_many(**args)
    ds = kick.to_xarray(out)
    assert ds["v_ball_out"].dims == ("dim_0",)
    np.testing.assert_array_equal(ds["foot_mass"].values, mass)
    np.testing.assert_array_equal(ds["stiffness"].values, stiffness)
    plain = dict(out)
    with pytest.raises(ValueError, match="`function` is needed"):
        kick.to_xarray(plain)
    again = kick.to_xarray(plain, function="simulate_many", **args)
    xr.testing.assert_identical(again, ds)
    with pytest.raises(ValueError, match="unknown parameter `foot_mas`"):
        kick.to_xarray(plain, function="simulate_many", foot_mas=mass)
