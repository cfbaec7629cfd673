"""kick.history and kick.history3d against the history files of
`kick simulate --history FILE` and `kick simulate3d --history FILE`."""

import numpy as np
import pytest

import kick
from conftest import cli, flags


def read_csv(path):
    """(names, units, columns) of a history CSV: header `name [unit]`, then numbers only."""
    with open(path) as f:
        header = f.readline().rstrip("\n").split(",")
    names = [h.split(" [")[0] for h in header]
    units = [h.split(" [")[1].rstrip("]") for h in header]
    data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    return names, units, {n: data[:, i] for i, n in enumerate(names)}


@pytest.mark.parametrize(
    "case",
    [{}, {"solver": "seed-rk4"}, {"drive_force": 300.0, "solver": "accurate"}, {"law": "hunt-crossley", "restitution": 0.7}],
)
def test_history_equals_the_cli_file(kick_bin, tmp_path, case):
    interval = 2e-5
    path = tmp_path / "h.csv"
    cli(kick_bin, "simulate", "--format", "json", "--history", path, "--interval", interval, *flags(**case))
    names, units, expected = read_csv(path)
    h = kick.history(interval=interval, **case)
    assert list(h) == names == [name for name, _ in kick.HISTORY_COLUMNS]
    assert units == [unit for _, unit in kick.HISTORY_COLUMNS]
    for name, column in h.items():
        assert column.dtype == np.float64
        # The CSV's numbers are the shortest round-trip form: equal to the bit.
        np.testing.assert_array_equal(column, expected[name], err_msg=name)


def test_samples_span_first_touch_to_separation():
    n = 101
    h = kick.history(samples=n)
    t_c = kick.simulate()["contact_time"]
    assert len(h["time"]) == n
    # Uniform grid t_k = k t_end/(n - 1) for the first n - 1 rows, then the separation row at
    # t_end: the contact time of the recording path (auto records on the full state, which
    # agrees with the summary's path to its accuracy, 1e-10).
    t_end = h["time"][-1]
    np.testing.assert_array_equal(h["time"][:-1], np.arange(n - 1) * (t_end / (n - 1)))
    assert t_end == pytest.approx(t_c, rel=1e-10)
    assert h["phase"][-1] == 0.0 and h["compression"][-1] == 0.0
    assert h["compression"][0] == 0.0 and h["force"].max() <= kick.simulate()["peak_force"]


def test_spacing_is_checked():
    with pytest.raises(ValueError, match="exactly one of `samples`"):
        kick.history()
    with pytest.raises(ValueError, match="exactly one of `samples`"):
        kick.history(samples=10, interval=1e-5)
    with pytest.raises(ValueError, match="`samples` = 1: must be between 2 and 1000000"):
        kick.history(samples=1)
    with pytest.raises(ValueError, match="invalid parameter `interval` = -1: must be finite and > 0"):
        kick.history(interval=-1.0)
    with pytest.raises(ValueError, match="history too long"):
        kick.history(interval=1e-12)
