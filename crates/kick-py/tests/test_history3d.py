"""kick.history3d against the HDF5 and CSV history files of
`kick simulate3d --history FILE`, and its own promises."""

import numpy as np
import pytest

import kick
from conftest import cli, flags
from test_history import read_csv

# An off-center kick with grip and slip phases, and one rising over a rounded border.
CASES = [
    {"offset": 0.05, "friction": 0.5},
    {"offset": 0.04, "approach_angle": 20.0, "foot_half_extents": (0.03, 0.12, 0.05), "border_radius": 0.01},
]


@pytest.mark.parametrize("case", CASES)
def test_history3d_equals_the_cli_hdf5_file(kick_bin, tmp_path, case):
    h5py = pytest.importorskip("h5py")
    path = tmp_path / "h.h5"
    summary = cli(kick_bin, "simulate3d", "--format", "json", "--history", path, "--samples", 151, *flags(**case))
    h = kick.history3d(samples=151, **case)
    assert list(h) == [name for name, _ in kick.HISTORY_COLUMNS_3D]
    with h5py.File(path, "r") as f:
        assert f.attrs["layout"] == "history" and f.attrs["level"] == "3d"
        assert sorted(f["history"]) == sorted(h)
        for name, unit in kick.HISTORY_COLUMNS_3D:
            assert f["history"][name].attrs["units"] == unit, name
            np.testing.assert_array_equal(h[name], f["history"][name][()], err_msg=name)
        assert f["fixed"]["offset"][()].tolist() == [case["offset"]]
    assert len(h["time"]) == 151
    assert h["time"][-1] == pytest.approx(summary["contact_time"], rel=1e-15)
    launch = [h[f"ball_velocity_{c}"][-1] for c in "xyz"]
    np.testing.assert_allclose(launch, summary["launch_velocity"], rtol=1e-15, atol=0)


def test_history3d_equals_the_cli_csv_file(kick_bin, tmp_path):
    path = tmp_path / "h.csv"
    case = CASES[0]
    cli(kick_bin, "simulate3d", "--format", "json", "--history", path, "--interval", 1e-4, *flags(**case))
    names, units, expected = read_csv(path)
    h = kick.history3d(interval=1e-4, **case)
    assert names == list(h) and units == [u for _, u in kick.HISTORY_COLUMNS_3D]
    for name in names:
        np.testing.assert_array_equal(h[name], expected[name], err_msg=name)


def test_history3d_grid_grip_slip_and_separation():
    n = 101
    h = kick.history3d(samples=n, offset=0.05, friction=0.5)
    t_end = h["time"][-1]
    np.testing.assert_array_equal(h["time"][:-1], np.arange(n - 1) * (t_end / (n - 1)))
    state = h["contact_state"]
    assert state[-1] == 0.0 and set(state[:-1]) == {1.0, 2.0}
    # Slipping rows carry |F_t| = mu F_n.
    normal = np.hypot.reduce([h[f"normal_force_{c}"] for c in "xyz"])
    tangential = np.hypot.reduce([h[f"tangential_force_{c}"] for c in "xyz"])
    slip = state == 2.0
    np.testing.assert_allclose(tangential[slip], 0.5 * normal[slip], rtol=1e-12)
    assert np.all(tangential[state == 1.0] <= 0.5 * normal[state == 1.0] * (1 + 1e-12))


def test_history3d_refusals_carry_the_message():
    with pytest.raises(ValueError, match="exactly one of `samples`"):
        kick.history3d()
    with pytest.raises(ValueError, match="`samples` = 1: must be between 2"):
        kick.history3d(samples=1)
    # Named in the call's own words; rapier's step was blamed (`dt` = 0), a
    # keyword history3d does not take.
    for solver in ("full-state", "rapier"):
        with pytest.raises(ValueError, match=f"`solver` = {solver} gives none") as refused:
            kick.history3d(samples=10, solver=solver)
        assert "dt" not in str(refused.value) and "--" not in str(refused.value)
    with pytest.raises(ValueError, match="history too long"):
        kick.history3d(interval=1e-12)
