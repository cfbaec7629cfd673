"""The ``*_many`` functions spread over a dask ``distributed`` cluster.

The rows (the parameters broadcast by numpy's rules, in C order) are cut into
chunks of about ``chunks`` rows; each chunk is one task that calls the local
function on a worker. Every row is solved independently and
deterministically, so the answers equal the local call's bit for bit.

- ``simulate_many``, ``simulate3d_many``, ``flight_many``, ``bounce_many``
  (keywords as the local call's, options such as ``solver`` or a flown kick's
  flight options passed on to every task) gather the arrays to the client,
  joined in row order: for results that fit in the client's memory.
- ``to_zarr(client, store, function, ...)`` writes each chunk's result on its
  worker into a Zarr store (``kick.to_xarray``'s dataset: dimensions, units,
  coordinates) and returns only a summary per chunk; the client never holds
  the outcomes. Read it with ``xarray.open_zarr(store)``. The chunks are
  rectangular blocks of the broadcast shape (the trailing axes whole, the
  leading ones cut), one Zarr chunk per task, so no two tasks write one chunk.

Each task solves with ``threads=1`` unless told otherwise: a dask worker runs
one task per thread it has, so the cluster's ``threads_per_worker`` (or
``--nthreads``) sets the parallelism, and rayon's default of one thread per
core in every task would oversubscribe the node.

    from distributed import Client, LocalCluster
    import kick.dask
    with LocalCluster(n_workers=2, threads_per_worker=1) as cluster, Client(cluster) as client:
        out = kick.dask.simulate_many(client, chunks=100_000, foot_mass=m, stiffness=k)
        kick.dask.to_zarr(client, "spin.zarr", "simulate3d_many", chunks=1_000, offset=d, friction=mu)
"""

from __future__ import annotations

import numpy as np

import kick
from kick import _kick
from kick._labelled import ManyResult

__all__ = ["simulate_many", "simulate3d_many", "flight_many", "bounce_many", "to_zarr"]

# What runs on a cluster is declared with the studies (kick_study::studies).
_FUNCTIONS = tuple(f for study in kick.STUDIES for f in study["dask"])
_DEFAULT_CHUNKS = {"simulate_many": 100_000, "simulate3d_many": 1_000, "flight_many": 10_000, "bounce_many": 1_000}


def _solve(function: str, options: dict, arrays: dict) -> dict:
    """One task: the local function on one chunk of rows (runs on a worker)."""
    import kick as local

    return dict(getattr(local, function)(**options, **arrays))


def _split(function, arrays):
    """The declared parameters (read and checked as the local call reads them)
    and the other keywords (options handed to every task unchanged)."""
    if function not in _FUNCTIONS:
        raise ValueError(f"`function` = {function!r}: one of {', '.join(_FUNCTIONS)}")
    shapes = {p["name"]: p["shape"] for p in kick.keywords(function)}
    # No bar on the workers (`progress` is checked on the client, then dropped).
    options = {k: v for k, v in arrays.items() if k not in shapes and k not in ("threads", "progress")}
    options["threads"] = arrays.get("threads", 1)
    given = {}
    row_shapes = []
    for name, value in arrays.items():
        if name not in shapes or value is None:
            continue
        # Read as the local call reads it (types, masks refused); switches travel as bools.
        a = _kick.many_input(function, name, value)
        if shapes[name] == "switch":
            a = a.astype(bool)
        vector = shapes[name] == "vector3"
        if vector and (a.ndim == 0 or a.shape[-1] != 3):
            raise ValueError(f"`{name}` takes three numbers (x, y, z) on its last axis, got shape {a.shape}")
        given[name] = (a, vector)
        row_shapes.append(a.shape[:-1] if vector else a.shape)
    shape = tuple(np.broadcast_shapes(*row_shapes)) if row_shapes else ()
    return given, options, shape


def _check_options(function, arrays):
    """Unknown keywords and bad options refused on the client, by the local
    call on no rows (its message names the keyword and the nearby ones)."""
    if function not in _FUNCTIONS:
        raise ValueError(f"`function` = {function!r}: one of {', '.join(_FUNCTIONS)}")
    scalar = next(p["name"] for p in kick.keywords(function) if p["shape"] != "vector3")
    declared = {p["name"] for p in kick.keywords(function)}
    options = {k: v for k, v in arrays.items() if k not in declared}
    getattr(kick, function)(**{"threads": 1, **options}, **{scalar: np.empty(0)})


def _rows(given, shape, start, stop):
    index = np.unravel_index(np.arange(start, stop), shape) if shape else ()
    part = {}
    for name, (a, vector) in given.items():
        full = np.broadcast_to(a, shape + ((3,) if vector else ()))
        part[name] = full[index] if shape else full.reshape((1, 3) if vector else (1,))
    return part


def _run(function, client, chunks, arrays):
    chunks = _kick.whole_number("chunks", chunks, 1)
    _check_options(function, arrays)
    given, options, shape = _split(function, arrays)
    if not given:
        # No input at all: one row, whose answer is 0-d as the local call's
        # (joining it as blocks of rows failed inside numpy).
        answer = client.submit(_solve, function, options, {}, pure=False).result()
        return ManyResult(answer, function, {}, {k: v for k, v in options.items()})
    rows = int(np.prod(shape, dtype=np.int64))
    futures = []
    for start in range(0, rows, chunks):
        part = _rows(given, shape, start, min(start + chunks, rows))
        futures.append(client.submit(_solve, function, options, part, pure=False))
    answers = client.gather(futures)
    inputs = {k: a for k, (a, _) in given.items()}
    if not answers:  # no rows: the local call on the empty shape
        return getattr(kick, function)(**options, **arrays)
    out = {}
    for key, first in answers[0].items():
        if key == "failure_index":
            starts = range(0, rows, chunks)
            out[key] = np.concatenate([a[key] + s for a, s in zip(answers, starts)]).astype(np.int64)
        elif key == "failure_message":
            out[key] = [m for a in answers for m in a[key]]
        else:
            joined = np.concatenate([a[key] for a in answers], axis=0)
            out[key] = joined.reshape(shape + joined.shape[1:])
    return ManyResult(out, function, inputs, {k: v for k, v in options.items()})


def simulate_many(client, chunks: int = 100_000, **arrays):
    """``kick.simulate_many`` over the workers of ``client`` (a ``distributed.Client``),
    ``chunks`` rows per task, ``threads`` (default 1) per task. Same keywords
    and the same dict of arrays as the local call."""
    return _run("simulate_many", client, chunks, arrays)


def simulate3d_many(client, chunks: int = 1_000, **arrays):
    """``kick.simulate3d_many`` over the workers of ``client``, ``chunks`` rows per task."""
    return _run("simulate3d_many", client, chunks, arrays)


def flight_many(client, chunks: int = 10_000, **arrays):
    """``kick.flight_many`` over the workers of ``client``, ``chunks`` rows per task."""
    return _run("flight_many", client, chunks, arrays)


def bounce_many(client, chunks: int = 1_000, **arrays):
    """``kick.bounce_many`` over the workers of ``client``, ``chunks`` rows per task."""
    return _run("bounce_many", client, chunks, arrays)


def _blocks(shape, chunks):
    """Rectangular blocks of about ``chunks`` rows covering ``shape``: the
    trailing axes whole while they fit, one axis cut, the leading ones by 1."""
    n = len(shape)
    block = [1] * n
    size = 1
    for k in range(n - 1, -1, -1):
        if size * shape[k] <= chunks:
            block[k] = shape[k]
            size *= shape[k]
        else:
            block[k] = max(1, chunks // size)
            break
    return tuple(block)


def _write_block(store, function, options, part, region, shape, layout):
    """One task: solve a block and write it into its region of the store
    (runs on a worker); returns its summary."""
    import time

    import xarray as xr

    import kick as local

    started = time.perf_counter()
    out = getattr(local, function)(**options, **part)
    status = np.asarray(out["status"])
    ds = xr.Dataset({key: (layout[key], np.asarray(out[key])) for key in layout})
    cut = dict(zip(layout["status"], region))
    ds.to_zarr(store, region={d: cut.get(d, slice(None)) for d in ds.dims})
    # Failed rows by their flat index in the whole result.
    local_index = np.unravel_index(np.asarray(out["failure_index"], dtype=np.int64), status.shape)
    index = np.ravel_multi_index(tuple(i + r.start for i, r in zip(local_index, region)), shape)
    return {
        "region": tuple((r.start, r.stop) for r in region),
        "rows": int(status.size),
        "failures": [(int(i), m) for i, m in zip(index, out["failure_message"])],
        "threads": options.get("threads"),
        "seconds": time.perf_counter() - started,
    }


def to_zarr(client, store, function: str, chunks: int | None = None, **arrays) -> list:
    """Run ``function`` (a ``*_many`` name) on the workers of ``client``,
    each task writing its block into a new Zarr store at the path ``store``,
    labelled as ``kick.to_xarray`` labels the result (coordinates, units);
    ``failure_message`` stays out of the store (the summaries carry it).
    Returns one summary dict per task, in block order: region (start, stop
    per axis), rows, failures (flat row index, message), threads, seconds.
    ``threads`` (default 1) per task."""
    import dask.array as da
    import xarray as xr

    import os

    if chunks is None:
        chunks = _DEFAULT_CHUNKS.get(function, 1_000)
    if os.path.exists(store):
        raise FileExistsError(f"{store}: exists; to_zarr writes a new store, never into an old one")
    chunks = _kick.whole_number("chunks", chunks, 1)
    _check_options(function, arrays)
    given, options, shape = _split(function, arrays)
    if not shape or 0 in shape:
        raise ValueError(f"to_zarr needs at least one axis and one row: the inputs broadcast to shape {shape}")
    block = _blocks(shape, chunks)
    # The layout (keys, dtypes, trailing axes) from the first row, the
    # coordinates and units from the whole inputs; the data variables lazy
    # zeros that are never computed (compute=False writes only metadata).
    inputs = {k: a for k, (a, _) in given.items()}
    sample = kick.to_xarray(getattr(kick, function)(**options, **_rows(given, shape, 0, 1)))
    labels = kick.to_xarray(ManyResult({"status": np.zeros(shape, np.uint8)}, function, inputs, options))
    dims = labels["status"].dims
    template = xr.Dataset(coords=labels.coords, attrs=labels.attrs)
    layout = {}
    for key, var in sample.data_vars.items():
        if key == "failure_message":
            continue
        trailing_dims = var.dims[1:]
        trailing = var.shape[1:]
        layout[key] = tuple(dims) + trailing_dims
        data = da.zeros(shape + trailing, dtype=var.dtype, chunks=block + trailing)
        template[key] = (layout[key], data, var.attrs)
    for name in _trailing_coords(sample):
        template.coords[name] = (name, sample[name].values)
    # The tasks write into a sibling that becomes `store` only once every
    # block is in: a store that exists is whole (a stopped run's unwritten
    # rows would read back as status 0, solved, with zeros).
    import shutil
    import uuid

    partial = f"{os.fspath(store).rstrip(os.sep)}.partial-{uuid.uuid4().hex}"
    futures = []
    try:
        template.to_zarr(partial, compute=False, mode="w-")
        full = {name: np.broadcast_to(a, shape + ((3,) if vector else ())) for name, (a, vector) in given.items()}
        for corner in np.ndindex(*[-(-s // b) for s, b in zip(shape, block)]):
            region = tuple(slice(i * b, min((i + 1) * b, s)) for i, b, s in zip(corner, block, shape))
            part = {name: np.ascontiguousarray(a[region]) for name, a in full.items()}
            futures.append(client.submit(_write_block, partial, function, options, part, region, shape, layout, pure=False))
        summaries = client.gather(futures)
        if os.path.exists(store):
            raise FileExistsError(f"{store}: appeared while the run wrote; the run is left out, never merged into it")
        os.rename(partial, store)
    except BaseException:
        # A failed task, an interrupt or a store that appeared: nothing is
        # left. A task cancelled while it runs goes on to its end on its
        # worker, and its write would make the store's folders again: the
        # partial store goes once no worker runs a task.
        client.cancel(futures)
        _settle(client)
        shutil.rmtree(partial, ignore_errors=True)
        raise
    return summaries


def _settle(client):
    """Wait until no worker of ``client`` is running a task."""
    import time

    while any(client.run(lambda dask_worker: dask_worker.state.executing_count).values()):
        time.sleep(0.05)


def _trailing_coords(ds):
    return [c for c in ("xyz", "xy") if c in ds.coords]
