"""kick.dask on a LocalCluster of 2 workers: the same arrays as the local call, bit for bit."""

import numpy as np
import pytest

distributed = pytest.importorskip("distributed")

import kick  # noqa: E402
import kick.dask  # noqa: E402


@pytest.fixture(scope="module")
def client():
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        with distributed.Client(cluster) as c:
            yield c


def assert_same(a: dict, b: dict):
    assert sorted(a) == sorted(b)
    for key in a:
        if key == "failure_message":
            assert a[key] == b[key]
        else:
            assert a[key].dtype == b[key].dtype and a[key].shape == b[key].shape, key
            np.testing.assert_array_equal(a[key], b[key], err_msg=key)  # NaN where NaN


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
