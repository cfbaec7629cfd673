"""kick.dask on a LocalCluster of 2 workers: the same arrays as the local call, bit for bit."""

import time

import numpy as np
import pytest

distributed = pytest.importorskip("distributed")

import kick  # noqa: E402
import kick.dask  # noqa: E402
from conftest import assert_same  # noqa: E402


@pytest.fixture(scope="module")
def client():
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        with distributed.Client(cluster) as c:
            yield c



def test_1d_chunks_equal_the_local_call(client):
    rng = np.random.default_rng(7)
    mass = rng.uniform(0.5, 15.0, size=(50, 1))
    stiffness = np.geomspace(1e4, 1e7, 40)
    drive = np.where(rng.uniform(size=40) < 0.3, 5e4, 0.0)  # some rows trapped
    args = dict(foot_mass=mass, stiffness=stiffness, drive_force=drive, threads=1)
    local = kick.simulate_many(**args)
    spread = kick.dask.simulate_many(client, chunks=333, **args)
    assert_same(spread, local)
    assert len(local["failure_message"]) > 0  # failures land at their rows across chunks
    assert spread["v_ball_out"].shape == (50, 40)


def test_3d_chunks_equal_the_local_call(client):
    offset = np.linspace(0.0, 0.08, 6)
    extents = np.array([[0.03, 0.12, 0.05], [0.03, 0.10, 0.04]])[:, None, :]
    local = kick.simulate3d_many(offset=offset, foot_half_extents=extents, friction=0.5)
    spread = kick.dask.simulate3d_many(client, chunks=5, offset=offset, foot_half_extents=extents, friction=0.5)
    assert_same(spread, local)
    assert spread["spin"].shape == (2, 6, 3)


def test_scalars_and_bad_input(client):
    assert_same(kick.dask.simulate_many(client, foot_mass=2.0), kick.simulate_many(foot_mass=2.0))
    with pytest.raises(ValueError, match="`chunks` = 0: must be between 1"):
        kick.dask.simulate_many(client, chunks=0, foot_mass=[1.0])
    # A bool is an int in Python: refused as every count of the package refuses it.
    for chunks, got in [(True, "bool True"), (np.True_, "bool"), (2.0, "float 2.0")]:
        with pytest.raises(TypeError, match=f"`chunks` takes a whole number \\(int\\), got {got}"):
            kick.dask.simulate_many(client, chunks=chunks, foot_mass=[1.0, 2.0])
    assert_same(kick.dask.simulate_many(client, chunks=np.int64(1), foot_mass=[1.0, 2.0]), kick.simulate_many(foot_mass=[1.0, 2.0]))
    with pytest.raises(ValueError, match="unknown parameter `foot_mas`"):
        kick.dask.simulate_many(client, foot_mas=[1.0])


def test_values_are_checked_as_the_local_call_checks_them(client):
    """The client side reads keywords as `simulate_many` does, not by a silent float64 cast."""
    with pytest.raises(TypeError, match=r"`foot_mass` takes real numbers, got .*complex128"):
        kick.dask.simulate_many(client, foot_mass=np.array([3.0 + 1.0j, 4.0]))
    with pytest.raises(ValueError, match=r"`foot_mass` has 1 masked"):
        kick.dask.simulate_many(client, foot_mass=np.ma.masked_array([3.0, 4.0], mask=[False, True]))
    with pytest.raises(TypeError, match=r"`foot_mass` takes real numbers, got str"):
        kick.dask.simulate_many(client, foot_mass="3")
    # Switches travel as bools.
    local = kick.simulate3d_many(offset=0.03, gravity=np.array([False, True]))
    assert_same(kick.dask.simulate3d_many(client, chunks=1, offset=0.03, gravity=np.array([False, True])), local)


def test_progress_is_checked_on_the_client_and_drawn_by_no_worker(client, capsys):
    local = kick.simulate_many(foot_mass=[1.0, 2.0, 3.0])
    assert_same(kick.dask.simulate_many(client, chunks=2, foot_mass=[1.0, 2.0, 3.0], progress=True), local)
    assert "rows" not in capsys.readouterr().err  # the client's check of the options draws none either
    _, options, _ = kick.dask._split("simulate_many", {"foot_mass": [1.0], "progress": True, "law": "hertz"})
    assert options == {"law": "hertz", "threads": 1}  # what every task is given
    with pytest.raises(TypeError, match="`progress` takes true or false, got int 1"):
        kick.dask.simulate_many(client, foot_mass=[1.0], progress=1)


def test_flights_equal_the_local_call(client):
    speed = np.linspace(15.0, 32.0, 7)
    spin = np.array([[0.0, 0.0, 60.0], [0.0, -40.0, 0.0]])[:, None, :]
    local = kick.flight_many(speed=speed, spin=spin, distance=20.0, threads=1)
    spread = kick.dask.flight_many(client, chunks=4, speed=speed, spin=spin, distance=20.0)
    assert_same(spread, local)
    assert spread["landing_point"].shape == (2, 7, 2)


def test_each_task_solves_on_one_thread_by_default(monkeypatch):
    """A task that left `threads` unset would start rayon's pool, one thread per
    core, in every task of every worker: the default is one thread per task."""
    seen = []
    real = kick._kick.simulate_many

    def spy(**arrays):
        seen.append(arrays.get("threads"))
        return real(**arrays)

    monkeypatch.setattr(kick._kick, "simulate_many", spy)
    with distributed.LocalCluster(n_workers=1, threads_per_worker=2, processes=False, dashboard_address=None) as cluster:
        with distributed.Client(cluster) as c:
            kick.dask.simulate_many(c, chunks=2, foot_mass=[1.0, 2.0, 3.0, 4.0, 5.0])
            tasks = list(seen)
            seen.clear()
            kick.dask.simulate_many(c, chunks=2, foot_mass=[1.0, 2.0, 3.0], threads=2)
            assert seen and set(seen) == {2}
    assert len(tasks) >= 3 and set(tasks) == {1}, tasks


def test_to_zarr_writes_on_the_workers_the_local_result(client, tmp_path):
    xr = pytest.importorskip("xarray")
    pytest.importorskip("zarr")
    rng = np.random.default_rng(3)
    mass = rng.uniform(0.5, 15.0, size=(9, 1))
    stiffness = np.geomspace(1e4, 1e7, 7)
    drive = np.where(rng.uniform(size=7) < 0.4, 5e4, 0.0)  # some rows trapped
    args = dict(foot_mass=mass, stiffness=stiffness, drive_force=drive)
    local = kick.simulate_many(**args, threads=1)
    store = str(tmp_path / "sweep.zarr")
    summaries = kick.dask.to_zarr(client, store, "simulate_many", chunks=20, **args)
    # Blocks of whole rows of the last axis: 20 rows -> 2 x 7, five tasks for 9 x 7.
    assert [s["region"] for s in summaries][:2] == [((0, 2), (0, 7)), ((2, 4), (0, 7))]
    assert len(summaries) == 5 and sum(s["rows"] for s in summaries) == 63
    assert {s["threads"] for s in summaries} == {1}
    failures = sorted(f for s in summaries for f in s["failures"])
    assert failures == sorted(zip(local["failure_index"].tolist(), local["failure_message"]))
    assert len(failures) > 0
    read = xr.open_zarr(store).load()
    expected = kick.to_xarray(local).drop_vars("failure_message")
    for key in expected.data_vars:
        assert read[key].dtype == expected[key].dtype and read[key].dims == expected[key].dims, key
        np.testing.assert_array_equal(read[key].values, expected[key].values, err_msg=key)  # bit for bit, NaN where NaN
        assert read[key].attrs["units"] == expected[key].attrs["units"], key
    for name in ("foot_mass", "stiffness", "drive_force"):
        np.testing.assert_array_equal(read[name].values, expected[name].values)
        assert read[name].attrs["units"] == expected[name].attrs["units"]
    with pytest.raises(FileExistsError, match="sweep.zarr: exists"):
        kick.dask.to_zarr(client, store, "simulate_many", **args)  # never over an existing store


def test_to_zarr_3d_vectors(client, tmp_path):
    xr = pytest.importorskip("xarray")
    pytest.importorskip("zarr")
    offset = np.linspace(0.0, 0.06, 5)
    extents = np.array([[0.03, 0.12, 0.05], [0.03, 0.10, 0.04]])[:, None, :]
    local = kick.simulate3d_many(offset=offset, foot_half_extents=extents, friction=0.5, threads=1)
    store = str(tmp_path / "kicks.zarr")
    summaries = kick.dask.to_zarr(client, store, "simulate3d_many", chunks=3, offset=offset, foot_half_extents=extents, friction=0.5)
    assert len(summaries) == 4  # blocks of 1 x 3 over 2 x 5
    read = xr.open_zarr(store).load()
    assert read["spin"].dims == ("dim_0", "offset", "xyz")
    np.testing.assert_array_equal(read["spin"].values, local["spin"])
    np.testing.assert_array_equal(read["foot_half_extents"].values, extents[:, 0, :])


def test_to_zarr_leaves_nothing_when_a_task_fails(tmp_path, monkeypatch):
    pytest.importorskip("zarr")
    # A worker that fails after others wrote: the store must not be left
    # half written (its unwritten rows would read back as status 0, solved).
    real = kick.dask._write_block

    def failing(store, function, options, part, region, *rest):
        if region[0].start == 2:
            raise RuntimeError("a worker lost")
        if region[0].start == 3:
            time.sleep(1.0)  # still writing when block 2 fails
        return real(store, function, options, part, region, *rest)

    monkeypatch.setattr(kick.dask, "_write_block", failing)
    store = tmp_path / "bad.zarr"
    with distributed.LocalCluster(n_workers=1, threads_per_worker=2, processes=False, dashboard_address=None) as cluster:
        with distributed.Client(cluster) as c:
            with pytest.raises(RuntimeError, match="a worker lost"):
                kick.dask.to_zarr(c, str(store), "simulate_many", chunks=1, foot_mass=[1.0, 2.0, 3.0, 4.0])
    assert list(tmp_path.iterdir()) == []  # no store, no partial one


def test_all_scalar_inputs_are_one_row_as_locally(client):
    # No array at all (it failed in numpy: zero-dimensional arrays cannot be concatenated).
    assert_same(kick.dask.simulate_many(client), kick.simulate_many())
    assert_same(kick.dask.simulate3d_many(client), kick.simulate3d_many())  # vectors (3,) too
