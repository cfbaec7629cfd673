"""``progress=True`` on every ``*_many`` function: a bar on stderr counting
the rows done, the same rows as without it, nothing printed without it, and
Ctrl-C still heard at once (tests/test_interrupt.py, "simulate3d_many with a bar")."""

import re
import subprocess
import sys

import numpy as np
import pytest

import kick
from conftest import assert_same

# Each function on a grid of rows more than one chunk (1024 rows) long, with
# a row that fails among them (its NaN and message must survive the bar).
CALLS = {
    "simulate_many": lambda **o: kick.simulate_many(foot_mass=np.r_[np.linspace(1.0, 8.0, 2999), -1.0], threads=2, **o),
    "simulate3d_many": lambda **o: kick.simulate3d_many(
        offset=np.linspace(0.0, 0.06, 40)[:, None], foot_speed=np.linspace(15.0, 25.0, 30), threads=2, **o
    ),
    "flight_many": lambda **o: kick.flight_many(speed=np.linspace(15.0, 30.0, 1500), launch_angle=20.0, threads=2, **o),
    "bounce_many": lambda **o: kick.bounce_many(speed=np.linspace(5.0, 25.0, 1100), threads=2, **o),
}
ROWS = {"simulate_many": 3000, "simulate3d_many": 1200, "flight_many": 1500, "bounce_many": 1100}



@pytest.mark.parametrize("function", sorted(CALLS))
def test_the_bar_counts_the_rows_on_stderr_and_changes_no_row(function, capfd):
    quiet = CALLS[function]()
    out, err = capfd.readouterr()
    assert out == "" and err == "", "progress=False (the default) prints nothing"
    assert_same(CALLS[function](progress=False), quiet)
    assert capfd.readouterr() == ("", "")

    shown = CALLS[function](progress=True)
    out, err = capfd.readouterr()
    assert out == ""
    rows = ROWS[function]
    # The last drawing: the function's name and every row done, the line ended.
    last = err.split("\r")[-1]
    assert re.search(rf"^{function} \[=+\] {rows}/{rows} rows", last), err[-300:]
    assert err.endswith("\n")
    assert_same(shown, quiet)
    assert int(np.prod(shown["status"].shape)) == rows


def test_the_bar_counts_up():
    """Drawn while the rows are solved, not only at the end: a call of about
    a second, with a log's one redraw a second, shows a count below the total."""
    script = (
        "import numpy as np, kick\n"
        "kick.simulate3d_many(offset=np.linspace(0.0, 0.06, 5_000), threads=1, progress=True)\n"
    )
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    counts = [int(n) for n in re.findall(r"(\d+)/5000 rows", done.stderr)]
    assert counts[-1] == 5000
    assert counts == sorted(counts)
    assert any(0 < n < 5000 for n in counts), done.stderr


@pytest.mark.parametrize("function", sorted(CALLS))
@pytest.mark.parametrize("value,got", [(1, "int 1"), ("yes", "str 'yes'"), ([True], "list"), (np.array([True, False]), "ndarray")])
def test_progress_takes_a_bool(function, value, got):
    with pytest.raises(TypeError, match=rf"`progress` takes true or false, got {re.escape(got)}"):
        CALLS[function](progress=value)


def test_numpy_bools_and_none_are_taken(capfd):
    a = kick.simulate_many(foot_mass=[1.0, 2.0], progress=np.False_)
    b = kick.simulate_many(foot_mass=[1.0, 2.0], progress=None)
    assert capfd.readouterr().err == ""
    kick.simulate_many(foot_mass=[1.0, 2.0], progress=np.True_)
    assert "2/2 rows" in capfd.readouterr().err
    assert_same(a, b)


def test_no_rows_no_bar(capfd):
    out = kick.simulate_many(foot_mass=np.empty(0), progress=True)
    assert out["status"].shape == (0,)
    assert capfd.readouterr().err == ""


def test_progress_is_not_an_attribute_of_the_result():
    pytest.importorskip("xarray")
    ds = kick.to_xarray(kick.simulate_many(foot_mass=[1.0, 2.0], progress=True))
    assert "progress" not in ds.attrs
