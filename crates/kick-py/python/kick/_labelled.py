"""``kick.to_xarray``: a ``*_many`` result as an ``xarray.Dataset``.

The dimensions are the broadcast axes of the inputs: an axis along which
exactly one input varies (its other axes of length 1, as ``x[:, None]``)
takes that input's name and values as its coordinate; an axis no single
input spans is ``dim_K``. Inputs that vary along several axes are
coordinates over those axes; scalar inputs are 0-d coordinates. Vectors
have a trailing ``xyz`` (``xy`` for ``landing_point``) dimension; the
crossings of a flown kick at a list of planes (``simulate3d_many(flight=True,
distance=[...])``) a ``distance`` dimension, the planes' distances its
coordinate. Every
input and output carries ``units`` (the declared unit, ``kick.PARAMETERS``;
the outputs' units from the library's column lists).
"""

from __future__ import annotations

import numpy as np


class ManyResult(dict):
    """The dict a ``*_many`` call returns, remembering the call: ``function``,
    ``inputs`` (the given parameter arrays) and ``options`` (solver, law, ...),
    so that ``kick.to_xarray(result)`` can label it."""

    def __init__(self, values, function: str, inputs: dict, options: dict):
        super().__init__(values)
        self.function = function
        self.inputs = inputs
        self.options = options


def output_units(function: str) -> dict:
    """Unit of every output key of ``function`` (vectors by their base name)."""
    from . import _kick

    if function == "simulate_many":
        table = list(_kick.OBSERVABLES) + [("energy_residual", "J")]
    elif function == "simulate3d_many":
        # With flight=True, the flight's columns follow the kick's.
        # The fixed-point angular impulse is a field, not one of the observables.
        table = list(_kick.OBSERVABLES_3D) + [(f"angular_impulse_fixed_point_{a}", "N m s") for a in "xyz"]
        table += list(_kick.FLIGHT_COLUMNS) + [("flight_status", "1")]
    elif function == "flight_many":
        table = list(_kick.FLIGHT_COLUMNS) + [
            ("launch_reynolds", "1"),
            ("launch_spin_parameter", "1"),
            ("launch_drag_coefficient", "1"),
            ("launch_lift_coefficient", "1"),
            ("steps", "1"),
        ]
    elif function == "bounce_many":
        table = list(_kick.BOUNCE_COLUMNS)
    else:
        raise ValueError(f"`{function}` is not a *_many function (simulate_many, simulate3d_many, flight_many, bounce_many)")
    units = {"evaluations": "1", "status": "1", "failure_message": ""}
    for name, unit in table:
        units[name] = unit
        for suffix in ("_x", "_y", "_z"):
            if name.endswith(suffix):
                units.setdefault(name[: -len(suffix)], unit)
    return units


def _parameters(function: str) -> dict:
    from . import keywords

    return {p["name"]: p for p in keywords(function)}


def to_xarray(result, function: str | None = None, **inputs):
    """An ``xarray.Dataset`` of a ``*_many`` result (``simulate_many``,
    ``simulate3d_many``, ``flight_many``, ``bounce_many``, or ``kick.dask``'s).

    The result remembers its call; ``function`` and the input keywords given
    here are needed only for a plain dict (e.g. one read back from a file).
    """
    import xarray as xr

    function = function or getattr(result, "function", None)
    if function is None:
        raise ValueError("`function` is needed for a plain dict: the *_many function that made `result`")
    given = dict(getattr(result, "inputs", {}) or {})
    given.update(inputs)
    options = dict(getattr(result, "options", {}) or {})
    declared = _parameters(function)
    unknown = [n for n in given if n not in declared]
    if unknown:
        raise ValueError(f"unknown parameter `{unknown[0]}` of {function}")
    units = output_units(function)

    shape = tuple(np.shape(result["status"]))
    ndim = len(shape)
    rows = {}  # input name -> (array, row shape padded to ndim, vector)
    for name, value in given.items():
        if value is None:
            continue
        a = np.asarray(value)
        vector = declared[name]["shape"] == "vector3"
        row = a.shape[:-1] if vector else a.shape
        if len(row) > ndim:
            raise ValueError(f"`{name}` has shape {a.shape}, more axes than the result's {shape}")
        rows[name] = (a.reshape((1,) * (ndim - len(row)) + a.shape), (1,) * (ndim - len(row)) + row, vector)

    def spans(row):
        # An axis of length 0 is spanned too (index 0 does not exist there).
        return [k for k in range(ndim) if row[k] != 1]

    dims = []
    index = {}
    for k in range(ndim):
        along = [n for n, (_, row, vector) in rows.items() if not vector and spans(row) == [k] and row[k] == shape[k]]
        if len(along) == 1 and along[0] not in dims:
            dims.append(along[0])
            index[along[0]] = k
        else:
            dims.append(f"dim_{k}")

    def attrs(name):
        p = declared[name]
        return {"units": p["unit"], "long_name": p["doc"], "symbol": p["symbol"]}

    coords = {}
    for name, (a, row, vector) in rows.items():
        axes = spans(row)
        take = tuple(slice(None) if k in axes else 0 for k in range(ndim))
        values = a[take]
        cdims = [dims[k] for k in axes] + (["xyz"] if vector else [])
        coords[name] = (cdims, values, attrs(name))

    # simulate3d_many(flight=True, distance=[...]): the crossing columns have
    # a trailing axis of the planes, labelled by their distances.
    planes = options.get("distance")
    planes = None if function != "simulate3d_many" or planes is None or np.ndim(planes) == 0 else np.asarray(planes, dtype=float)
    if planes is not None:
        coords["distance"] = ("distance", planes, {"units": "m", "long_name": "the plane x = distance whose crossing is reported"})
        options.pop("distance")

    data = {}
    for key, value in result.items():
        if key in ("failure_index", "failure_message"):
            continue
        v = np.asarray(value)
        extra = v.shape[ndim:]
        if planes is not None and (key == "crossed" or key.startswith("crossing_")):
            vdims = list(dims) + ["distance"] + (["xyz"] if extra[1:] == (3,) else [])
        else:
            vdims = list(dims) + (["xyz"] if extra == (3,) else ["xy"] if extra == (2,) else [f"{key}_{i}" for i in range(len(extra))])
        data[key] = (vdims, v, {"units": units.get(key, "")})
    # The component labels only where a variable has that axis.
    if any("xy" in d[0] for d in data.values()):
        coords["xy"] = ("xy", ["x", "y"])
    if any("xyz" in d[0] for d in list(data.values()) + list(coords.values())):
        coords["xyz"] = ("xyz", ["x", "y", "z"])
    data["status"][2]["flag_values"] = np.array(sorted(_status()), dtype=np.uint8)
    data["status"][2]["flag_meanings"] = " ".join(_status()[c].replace(" ", "_") for c in sorted(_status()))
    message = np.full(shape, "", dtype=object)
    if len(result.get("failure_index", [])):
        message.reshape(-1)[np.asarray(result["failure_index"])] = list(result["failure_message"])
    data["failure_message"] = (dims, message, {"long_name": "the library's message for a row that failed, lies outside its law's validity, or whose flight was not flown"})

    ds = xr.Dataset(data, coords=coords)
    ds.attrs["function"] = function
    for key, value in options.items():
        if value is not None:
            ds.attrs[key] = value
    return ds


def _status():
    from . import STATUS

    return STATUS
