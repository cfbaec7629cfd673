"""``simulate_many`` and ``simulate3d_many`` spread over a dask ``distributed`` cluster.

The rows (the parameters broadcast by numpy's rules, in C order) are cut into
contiguous chunks of ``chunks`` rows; each chunk is one task that calls the
local function on a worker, and the answers are joined in row order. Every
row is solved independently and deterministically, so the arrays equal the
local call's bit for bit.

    from distributed import Client, LocalCluster
    import kick.dask
    with LocalCluster(n_workers=2) as cluster, Client(cluster) as client:
        out = kick.dask.simulate_many(client, chunks=100_000, foot_mass=m, stiffness=k)
"""

from __future__ import annotations

import numpy as np

import kick
from kick import _kick

__all__ = ["simulate_many", "simulate3d_many"]


def _solve(function: str, options: dict, arrays: dict) -> dict:
    """One task: the local function on one chunk of rows (runs on a worker)."""
    import kick as local

    return getattr(local, function)(**options, **arrays)


def _run(function, client, chunks, options, arrays):
    # As every count of the package: an int or numpy integer, not a bool or float.
    chunks = _kick.whole_number("chunks", chunks, 1)
    shapes = {p["name"]: p["shape"] for p in kick.keywords(function)}
    given = {}
    row_shapes = []
    for name, value in arrays.items():
        if value is None:
            continue
        # Read as the local call reads it (unknown names, types, masks refused);
        # switches travel as bools.
        a = _kick.many_input(function, name, value)
        if shapes[name] == "switch":
            a = a.astype(bool)
        vector = shapes[name] == "vector3"
        if vector and (a.ndim == 0 or a.shape[-1] != 3):
            raise ValueError(f"`{name}` takes three numbers (x, y, z) on its last axis, got shape {a.shape}")
        given[name] = (a, vector)
        row_shapes.append(a.shape[:-1] if vector else a.shape)
    shape = np.broadcast_shapes(*row_shapes) if row_shapes else ()
    rows = int(np.prod(shape, dtype=np.int64))
    futures = []
    for start in range(0, rows, chunks):
        stop = min(start + chunks, rows)
        index = np.unravel_index(np.arange(start, stop), shape) if shape else ()
        part = {}
        for name, (a, vector) in given.items():
            full = np.broadcast_to(a, shape + ((3,) if vector else ()))
            part[name] = full[index] if shape else full.reshape((1, 3) if vector else (1,))
        futures.append(client.submit(_solve, function, options, part, pure=False))
    answers = client.gather(futures)
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
    return out


def simulate_many(client, chunks: int = 100_000, *, solver="auto", law="power-law", dt=None, threads=None, **arrays):
    """``kick.simulate_many`` over the workers of ``client`` (a ``distributed.Client``),
    ``chunks`` rows per task; ``threads`` is each task's thread count. Same
    keywords and the same dict of arrays as the local call."""
    options = dict(solver=solver, law=law, dt=dt, threads=threads)
    return _run("simulate_many", client, chunks, options, arrays)


def simulate3d_many(client, chunks: int = 1_000, *, solver="auto", law="power-law", dt=None, threads=None, **arrays):
    """``kick.simulate3d_many`` over the workers of ``client``, ``chunks`` rows per task."""
    options = dict(solver=solver, law=law, dt=dt, threads=threads)
    return _run("simulate3d_many", client, chunks, options, arrays)
