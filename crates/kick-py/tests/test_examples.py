"""The worked examples under crates/kick-py/examples run, and what they print
obeys the physics they illustrate (facts that follow from the mechanics, not
numbers copied from a run)."""

import contextlib
import io
import pathlib
import runpy

import numpy as np
import pytest

EXAMPLES = pathlib.Path(__file__).resolve().parents[1] / "examples"


@pytest.fixture(scope="module")
def free_kick():
    """The script run as `python pressure_offset_free_kick.py` runs it: its globals, and what it printed."""
    pytest.importorskip("xarray")
    printed = io.StringIO()
    with contextlib.redirect_stdout(printed):
        script = runpy.run_path(str(EXAMPLES / "pressure_offset_free_kick.py"), run_name="__main__")
    return {**script, "printed": printed.getvalue()}


def test_the_free_kick_study_runs_and_prints_its_tables(free_kick):
    ds, best = free_kick["ds"], free_kick["best"]
    lines = free_kick["printed"].splitlines()
    assert len([line for line in lines if line.split()[:1] in (["0.6"], ["0.8"], ["1.1"])]) == 12 + 3
    assert lines[-1].startswith("Best from 25 m: ")
    assert ds.sizes == {"inflation_pressure": 3, "offset": 4, "distance": 2, "xyz": 3, "xy": 2}
    assert set(best) == set(free_kick["PRESSURES"])
    assert (ds["status"] == 0).all() and (ds["flight_status"] == 0).all()


def test_spin_and_bend_grow_with_offset(free_kick):
    """A tangential impulse with a lever arm: no sidespin and no bend on the
    foot's line (symmetry), both growing with the offset, toward -y for offset > 0."""
    ds = free_kick["ds"]
    spin_z = ds["spin"].sel(xyz="z").values
    assert np.all(np.abs(spin_z[:, 0]) < 1e-9)
    assert np.all(np.diff(spin_z, axis=1) < 0)  # more negative with each step of offset
    assert np.all(np.diff(ds["spin_rev_per_s"].values, axis=1) > 0)
    bend = ds["bend"].values
    assert np.all(np.abs(bend[:, 0]) < 1e-9)
    finite = bend[:, 1:3]  # 2 and 4 cm reach the goal line
    assert np.all(np.isfinite(finite)) and np.all(finite < 0) and np.all(np.diff(bend[:, :3], axis=1) < 0)


def test_speed_rises_with_pressure_and_falls_with_offset(free_kick):
    """A firmer ball stores less of the impact in loss and returns more of the
    foot's speed, in a shorter contact; an offset kick turns speed into spin
    and meets the ball obliquely."""
    ds = free_kick["ds"]
    speed = ds["speed"].values  # (pressure, offset)
    assert np.all(np.diff(speed, axis=0) > 0)
    assert np.all(np.diff(speed, axis=1) < 0)
    assert np.all(np.diff(ds["contact_time"].values, axis=0) < 0)
    # Every ball leaves below the foot's 2x speed bound of a free ball hit by a heavier one.
    assert np.all(speed < 2 * 22.0)


def test_every_aimed_kick_goes_over_the_wall_and_a_firmer_ball_needs_less_foot(free_kick):
    best, wall, target = free_kick["best"], free_kick["WALL"], free_kick["TARGET"]
    for aimed in best.values():
        assert aimed["wall_pass"] == "over" and aimed["wall_clearance"] > 0
        assert aimed["miss"] < 1e-6
        np.testing.assert_allclose(aimed["crossing"], target, atol=1e-6)  # where it crosses the goal line
        assert aimed["wall_crossing"][1] > wall[1]
    feet = [free_kick["foot_speed"](best[p]) for p in sorted(best)]
    assert np.all(np.diff(feet) < 0), feet
