"""simulate_many / simulate3d_many: broadcasting, rows equal to the single
call (and so to the CLI), status codes instead of exceptions, threads, memory."""

import tracemalloc

import numpy as np
import pytest

import kick
from conftest import cli, flags

STATUS = {name: code for code, name in kick.STATUS.items()}
OUTCOMES = [name for name, _ in kick.OBSERVABLES] + ["energy_residual"]


def test_status_codes_are_the_library_ones():
    assert kick.STATUS == {0: "separated", 1: "numerical failure", 2: "trapped", 3: "refused", 4: "outside validity"}


def test_rows_outside_their_law_keep_their_numbers_with_status_4(kick_bin):
    """Issue 33, fault 5: a row past its contact law's validity (the shell ball
    past R/2, another law past R) keeps its numbers, status 4 and the reason,
    in every _many function; a single call returns it with a warning."""
    bounces = kick.bounce_many(speed=[20.0, 45.0, 100.0])
    assert bounces["status"].tolist() == [0, 4, 4]
    assert np.all(np.isfinite(bounces["max_compression"]))
    assert bounces["max_compression"][1] > 0.055 and bounces["max_compression"][0] < 0.055
    assert bounces["failure_index"].tolist() == [1, 2]
    assert all("outside the validity of law `shell`" in m for m in bounces["failure_message"])
    shell = kick.simulate_many(law="shell", foot_speed=[20.0, 1000.0])
    assert shell["status"].tolist() == [0, 4] and np.isfinite(shell["v_ball_out"][1])
    paper = kick.simulate_many(stiffness=1e4, foot_speed=[20.0, 100.0])
    assert paper["status"].tolist() == [0, 4]
    kick3d = kick.simulate3d_many(law="shell", foot_speed=[20.0, 60.0])
    assert kick3d["status"].tolist() == [0, 4] and np.isfinite(kick3d["speed"][1])
    with pytest.warns(kick.OutsideValidityWarning, match=r"exceeds R/2"):
        one = kick.bounce(speed=100.0)
    assert one["status"] == "outside_validity" and one["outside_validity"]["limit"] == "R/2"
    with pytest.warns(kick.OutsideValidityWarning):
        one = kick.simulate(law="shell", foot_speed=1000.0)
    assert one["status"] == "outside_validity"
    assert one["max_compression"] == shell["max_compression"][1]
    with pytest.warns(kick.OutsideValidityWarning):
        kick.simulate3d(law="shell", foot_speed=60.0)
    with pytest.warns(kick.OutsideValidityWarning):
        kick.history(law="shell", foot_speed=1000.0, samples=20)
    assert kick.bounce(speed=20.0)["status"] == "separated"


def test_broadcasting_shapes():
    out = kick.simulate_many(foot_mass=np.array([[1.0], [3.0], [8.0]]), stiffness=[1e5, 4.2e5, 1e6, 3e6])
    for name in OUTCOMES + ["status", "evaluations"]:
        assert out[name].shape == (3, 4), name
    assert out["status"].dtype == np.uint8 and out["evaluations"].dtype == np.uint64
    assert out["failure_index"].dtype == np.int64 and out["failure_message"] == []
    # Scalars only: one row of shape ().
    assert kick.simulate_many()["v_ball_out"].shape == ()
    assert kick.simulate_many(foot_mass=3.0)["v_ball_out"] == kick.simulate()["v_ball_out"]
    # Empty axes stay empty.
    assert kick.simulate_many(foot_mass=np.zeros((0, 2)))["v_ball_out"].shape == (0, 2)
    # Any dtype numpy can turn into float64, any strides.
    ints = kick.simulate_many(foot_mass=np.arange(1, 7).reshape(2, 3)[:, ::2])
    floats = kick.simulate_many(foot_mass=np.array([[1.0, 3.0], [4.0, 6.0]]))
    np.testing.assert_array_equal(ints["v_ball_out"], floats["v_ball_out"])


def test_mismatched_shapes_are_refused():
    with pytest.raises(ValueError, match=r"shape mismatch: .*`foot_mass` \[3\].*`stiffness` \[4\]"):
        kick.simulate_many(foot_mass=[1.0, 2.0, 3.0], stiffness=[1e5, 2e5, 3e5, 4e5])
    with pytest.raises(ValueError, match=r"`foot_inertia` takes three numbers \(x, y, z\) on its last axis, got shape \[2\]"):
        kick.simulate3d_many(foot_inertia=[0.01, 0.02])
    with pytest.raises(ValueError, match="unknown parameter `foot_mas` of the 1D scenario"):
        kick.simulate_many(foot_mas=[1.0])


def test_rows_equal_the_single_call_bit_for_bit():
    m = np.array([0.6, 3.0, 8.0])
    c = np.array([[0.0], [120.0], [450.0]])
    out = kick.simulate_many(foot_mass=m, damping=c, drive_force=200.0)
    for i in range(3):
        for j in range(3):
            one = kick.simulate(foot_mass=m[j], damping=c[i, 0], drive_force=200.0)
            for name in OUTCOMES:
                assert out[name][i, j] == one[name], (name, i, j)
            assert out["evaluations"][i, j] == one["evaluations"]


def test_the_shell_balls_pressure_is_a_broadcast_keyword():
    """Every declared parameter broadcasts: the shell ball's pressure in 1D and
    3D rows equals the single call; a harder ball is in contact for less time
    (the 1D exit speed is the law's restitution's, the same at every pressure)
    and, struck off-centre, leaves faster."""
    pressure = np.array([6.0e4, 8.5e4, 1.1e5])
    one_d = kick.simulate_many(law="shell", inflation_pressure=pressure)
    three_d = kick.simulate3d_many(law="shell", inflation_pressure=pressure, offset=0.03)
    for i, p in enumerate(pressure):
        assert one_d["v_ball_out"][i] == kick.simulate(law="shell", inflation_pressure=p)["v_ball_out"]
        assert three_d["speed"][i] == kick.simulate3d(law="shell", inflation_pressure=p, offset=0.03)["speed"]
    assert np.all(np.diff(one_d["contact_time"]) < -1e-4) and np.all(np.diff(three_d["speed"]) > 0.01)


def test_failed_rows_get_a_status_and_the_cli_message(kick_bin):
    drive = np.array([0.0, 1e5, 0.0, 0.0])
    mass = np.array([3.0, 3.0, -1.0, 3.0])
    out = kick.simulate_many(drive_force=drive, foot_mass=mass)
    assert out["status"].tolist() == [STATUS["separated"], STATUS["trapped"], STATUS["refused"], STATUS["separated"]]
    assert out["failure_index"].tolist() == [1, 2]
    assert out["failure_message"] == [
        cli(kick_bin, "simulate", *flags(drive_force=1e5), ok=False),
        cli(kick_bin, "simulate", *flags(foot_mass=-1.0), ok=False),
    ]
    # seed-rk4 runs into its step budget under the same drive: not a proof of trapping.
    seed = kick.simulate_many(drive_force=drive, solver="seed-rk4", dt=np.float64(5e-6))
    assert seed["status"].tolist()[1] == STATUS["numerical failure"]
    assert seed["failure_message"] == [cli(kick_bin, "simulate", "--solver", "seed-rk4", *flags(drive_force=1e5), ok=False)]
    assert np.isnan(out["v_ball_out"][[1, 2]]).all() and np.isfinite(out["v_ball_out"][[0, 3]]).all()
    assert out["evaluations"][1] == 0
    # A fixed step too large for a stiff contact: a numerical failure, not physics.
    stiff = kick.simulate_many(stiffness=[4.2e5, 1e12], solver="seed-rk4", dt=1e-4)
    assert stiff["status"].tolist()[1] == STATUS["numerical failure"]


def test_thread_counts_give_the_same_numbers_and_are_bounded():
    k = np.geomspace(1e4, 1e7, 3000)
    one = kick.simulate_many(stiffness=k, threads=1)
    two = kick.simulate_many(stiffness=k, threads=2)
    default = kick.simulate_many(stiffness=k)
    for name in OUTCOMES:
        np.testing.assert_array_equal(one[name], two[name])
        np.testing.assert_array_equal(one[name], default[name])
    for bad in (0, 10**6):
        with pytest.raises(ValueError, match=rf"`threads` = {bad}: must be between 1 and \d+"):
            kick.simulate_many(stiffness=k, threads=bad)


def test_3d_rows_equal_the_single_call_and_vectors_trail():
    offset = np.array([0.0, 0.03, 0.06])
    friction = np.array([[0.3], [np.inf]])
    inertia = np.array([0.01, 0.02, 0.02])
    out = kick.simulate3d_many(offset=offset, friction=friction, foot_inertia=inertia)
    assert out["launch_velocity"].shape == (2, 3, 3) and out["spin"].shape == (2, 3, 3)
    assert out["speed"].shape == (2, 3)
    for i in range(2):
        for j in range(3):
            one = kick.simulate3d(offset=offset[j], friction=friction[i, 0], foot_inertia=tuple(inertia))
            np.testing.assert_array_equal(out["launch_velocity"][i, j], one["launch_velocity"])
            np.testing.assert_array_equal(out["spin"][i, j], one["spin"])
            assert out["contact_time"][i, j] == one["contact_time"]
            assert out["energy_friction_loss"][i, j] == one["energy"]["friction_loss"]
            assert out["energy_residual"][i, j] == one["energy_residual"]
    # A row whose offset misses the ball is refused, with the CLI's message.
    bad = kick.simulate3d_many(offset=[0.0, 0.2])
    assert bad["status"].tolist() == [STATUS["separated"], STATUS["refused"]]
    assert "offset 0.2 m misses the ball" in bad["failure_message"][0]
    # Per-row vectors: the trailing axis carries x, y, z.
    extents = np.array([[0.03, 0.12, 0.05], [0.03, 0.10, 0.04]])
    rows = kick.simulate3d_many(offset=0.03, foot_half_extents=extents)
    assert rows["speed"][1] == kick.simulate3d(offset=0.03, foot_half_extents=tuple(extents[1]))["speed"]


def test_3d_rows_fly_with_broadcast_air_and_a_plane_axis():
    offset = np.array([0.0, 0.04])
    air = np.array([[1.0], [1.225]])
    out = kick.simulate3d_many(offset=offset, contact_depth=0.03, flight=True, distance=[9.15, 25.0], air_density=air)
    assert out["flight_time"].shape == (2, 2) and out["landing_point"].shape == (2, 2, 2)
    assert out["crossing_height"].shape == (2, 2, 2) and out["crossing_velocity"].shape == (2, 2, 2, 3)
    assert (out["flight_status"] == 0).all()
    for i in range(2):
        for j in range(2):
            one = kick.simulate3d(offset=offset[j], contact_depth=0.03, flight=True, distance=[9.15, 25.0], air_density=air[i, 0])
            assert out["flight_time"][i, j] == one["flight"]["flight_time"]
            for k, c in enumerate(one["flight"]["crossings"]):
                assert out["crossing_height"][i, j, k] == c["height"]
                assert out["crossing_lateral_offset"][i, j, k] == c["lateral_offset"]
                np.testing.assert_array_equal(out["crossing_velocity"][i, j, k], c["velocity"])
    # A ball that does not leave the ground: its flight refused, its kick kept.
    flat = kick.simulate3d_many(friction=[0.3, 0.6], flight=True, distance=25.0)
    assert flat["status"].tolist() == [0, 0] and flat["flight_status"].tolist() == [STATUS["refused"]] * 2
    assert np.isnan(flat["crossing_height"]).all() and not np.isnan(flat["speed"]).any()
    # Why is said, row by row (it was not: a refused air density read as a
    # ball that does not leave the ground).
    assert flat["failure_index"].tolist() == [0, 1]
    assert all(m.startswith("the flight after the kick: ") for m in flat["failure_message"])
    air = kick.simulate3d_many(flight=True, contact_depth=0.03, air_density=[1.2, np.nan, -1.0])
    assert air["status"].tolist() == [0, 0, 0] and air["flight_status"].tolist() == [0, STATUS["refused"], STATUS["refused"]]
    assert air["failure_index"].tolist() == [1, 2]
    assert all("air_density" in m for m in air["failure_message"]), air["failure_message"]


def test_a_million_rows_allocate_only_the_output_arrays():
    """No per-row Python objects: the traced peak is the output arrays (plus
    the input), whatever the number of rows."""
    n = 1_000_000
    mass = np.linspace(0.5, 15.0, n)
    tracemalloc.start()
    tracemalloc.reset_peak()
    out = kick.simulate_many(foot_mass=mass, damping=0.0)
    current, peak = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    outputs = sum(v.nbytes for v in out.values() if isinstance(v, np.ndarray))
    assert outputs == n * (8 * len(OUTCOMES) + 1 + 8) + 0  # 16 float64 columns, status, evaluations
    assert (out["status"] == 0).all()
    print(f"\n{n} rows: outputs {outputs / 1e6:.1f} MB, traced peak {peak / 1e6:.1f} MB")
    assert peak < outputs + 1_000_000, (peak, outputs)


def test_more_axes_than_numpy_1_allows_are_a_value_error_naming_the_keyword():
    with pytest.raises(ValueError, match=r"`foot_mass` has 33 axes: at most 32"):
        kick.simulate_many(foot_mass=np.ones((1,) * 33))
    with pytest.raises(ValueError, match=r"`foot_inertia` has 33 axes: at most 32"):
        kick.simulate3d_many(foot_inertia=np.full((1,) * 32 + (3,), 0.02))
    # 32 row axes fit a 1D call; a 3D call's vector outcomes need one more.
    assert kick.simulate_many(foot_mass=np.ones((1,) * 32))["v_ball_out"].ndim == 32
    with pytest.raises(ValueError, match=r"`offset`.* 32 axes.* would have 33: at most 32"):
        kick.simulate3d_many(offset=np.zeros((1,) * 32))


def test_outputs_too_large_to_allocate_are_a_memory_error():
    # 1e12 rows: 145 TB of outputs, refused before any row is solved.
    with pytest.raises(MemoryError):
        kick.simulate_many(foot_mass=np.broadcast_to(3.0, (10**6, 10**6)))
    # 2^80 rows: the size does not fit a machine word.
    with pytest.raises(MemoryError, match=r"outputs of .* rows"):
        kick.simulate_many(foot_mass=np.broadcast_to(3.0, (2**40,)), stiffness=np.broadcast_to(4e5, (2**40, 1)))
    with pytest.raises(MemoryError):
        kick.simulate3d_many(offset=np.broadcast_to(0.01, (10**5, 10**5)))
