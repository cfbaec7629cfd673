"""Compare kick with your own measurements: the model run at each
measurement's own conditions, and the normalised residuals (model - measured)/u.

    python crates/kick-py/examples/compare_measurements.py [--kicks FILE] [--plate FILE]
        [--fit REPORT.json ...] [--set NAME=VALUE ...]

The guide paper/guides/measurements.md walks through it; its files
(paper/guides/measurements/lab_kicks.csv, lab_plate.csv, the defaults here)
hold illustrative numbers invented for the guide, not measurements.

- Kicks (``--kicks``): a ball at rest kicked at the measured foot speed, its
  centre ``offset`` sideways of the foot's line of motion; ball speed, spin
  and contact time, each with its standard uncertainty. Solved as
  ``kick.simulate3d_many(law="shell", ...)``: every row in one call, at its
  own conditions.
- Plate tests (``--plate``): the ball fired square at a rigid plate at a
  speed and inflation pressure; restitution and contact time. Solved as
  ``kick.bounce_many(...)`` (``kick bounce``).

A sheet's columns are ``name``, ``role``, its observables with their ``u_``,
and conditions: every other column must be a keyword of the call that solves
it (``kick.keywords``), e.g. ``contact_depth`` or ``inflation_pressure`` of a
kick, and each row runs at its own value; a column that is neither is
refused, never ignored.
- ``--fit REPORT.json`` (repeatable) holds every parameter a fit estimated
  (the report ``kick fit data SPEC --format json`` prints) at its estimate,
  and ``--set NAME=VALUE`` (repeatable, after the fits) a declared parameter
  at a value; each in every row whose model takes it (a plate test has no
  foot).

Each row's ``role`` column says whether it was used to calibrate a parameter
(``calibration``) or not (``prediction``): only the second kind tests the
model. A residual beyond 2 in size is flagged; chi^2 is summed per role.
"""

from __future__ import annotations

import argparse
import csv
import pathlib

import numpy as np

import kick

GUIDE = pathlib.Path(__file__).resolve().parents[3] / "paper" / "guides" / "measurements"


def read(path: pathlib.Path) -> dict:
    """A measurement sheet: '#' lines are comments; columns by their header; numbers as float arrays."""
    with open(path, newline="") as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    if not rows:
        raise SystemExit(f"{path}: no rows")
    table = {}
    for key in rows[0]:
        values = [r[key] for r in rows]
        try:
            table[key] = np.array([float(v) for v in values])
        except ValueError:
            table[key] = np.array(values)
    return table


def settings(pairs: list[str]) -> dict:
    """``NAME=VALUE`` pairs as keywords (a declared parameter each)."""
    out = {}
    for pair in pairs:
        name, _, value = pair.partition("=")
        try:
            out[name] = float(value)
        except ValueError:
            raise SystemExit(f"--set {pair}: give NAME=VALUE with a number") from None
    return out


def fitted(paths: list[pathlib.Path]) -> dict:
    """The estimates of ``kick fit data --format json`` reports, by parameter name."""
    import json

    out = {}
    for path in paths:
        for estimate in json.loads(path.read_text())["estimates"]:
            out[estimate["parameter"]] = estimate["value"]
    return out


def held(function: str, fixed: dict) -> dict:
    """The settings ``function`` takes (a plate test has no foot)."""
    names = {p["name"] for p in kick.keywords(function)}
    return {k: v for k, v in fixed.items() if k in names}


KICK_OBSERVABLES = ("ball_speed", "spin", "contact_time")
PLATE_OBSERVABLES = ("restitution", "contact_time")


def conditions(sheet: dict, function: str, observables: tuple, path: str) -> dict:
    """The sheet's condition columns, each a keyword of ``function``; any other column is refused."""
    names = {p["name"] for p in kick.keywords(function)}
    bookkeeping = {"name", "role", *observables, *("u_" + o for o in observables)}
    out = {}
    for column, values in sheet.items():
        if column in bookkeeping:
            continue
        if column not in names:
            raise SystemExit(f"{path}: column `{column}` is neither an observable ({', '.join(observables)}, u_*) nor a condition {function} takes")
        out[column] = values
    return out


def kicks(sheet: dict, fixed: dict, path: str = "kicks") -> list:
    """(name, role, observable, model, measured, u) of every kick observable."""
    # A row's own condition wins over a setting held for every row.
    given = conditions(sheet, "simulate3d_many", KICK_OBSERVABLES, path)
    out = kick.simulate3d_many(law="shell", **{**held("simulate3d_many", fixed), **given})
    if np.any(out["status"] != 0):
        raise SystemExit(f"kicks not solved: {out['failure_message']}")
    model = {
        "ball_speed": out["speed"],
        "spin": np.linalg.norm(out["spin"], axis=-1) / (2 * np.pi),  # rev/s
        "contact_time": out["contact_time"],
    }
    return rows(sheet, model)


def plate(sheet: dict, fixed: dict, path: str = "plate") -> list:
    given = conditions(sheet, "bounce_many", PLATE_OBSERVABLES, path)
    out = kick.bounce_many(**{**held("bounce_many", fixed), **given})
    if np.any(out["status"] != 0):
        raise SystemExit(f"plate tests not solved: {out['failure_message']}")
    return rows(sheet, {"restitution": out["restitution"], "contact_time": out["contact_time"]})


def rows(sheet: dict, model: dict) -> list:
    found = []
    for i, name in enumerate(sheet["name"]):
        for observable, values in model.items():
            found.append((name, sheet["role"][i], observable, values[i], sheet[observable][i], sheet["u_" + observable][i]))
    return found


def report(found: list) -> dict:
    """Print the residual table; chi^2 and count per role."""
    print(f"{'measurement':<20} {'role':<12} {'observable':<13} {'model':>10} {'measured':>10} {'u':>8} {'z':>7}")
    totals = {}
    for name, role, observable, model, measured, u in found:
        z = (model - measured) / u
        flag = "  <-- |z| > 2" if abs(z) > 2 else ""
        print(f"{name:<20} {role:<12} {observable:<13} {model:10.4g} {measured:10.4g} {u:8.2g} {z:7.2f}{flag}")
        chi2, n = totals.get(role, (0.0, 0))
        totals[role] = (chi2 + z * z, n + 1)
    for role, (chi2, n) in sorted(totals.items()):
        print(f"{role}: chi^2 = {chi2:.2f} over {n} residuals")
    return totals


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--kicks", type=pathlib.Path, default=GUIDE / "lab_kicks.csv")
    parser.add_argument("--plate", type=pathlib.Path, default=GUIDE / "lab_plate.csv")
    parser.add_argument("--fit", action="append", default=[], type=pathlib.Path, metavar="REPORT.json")
    parser.add_argument("--set", action="append", default=[], metavar="NAME=VALUE")
    args = parser.parse_args(argv)
    fixed = {**fitted(args.fit), **settings(args.set)}
    if fixed:
        print("held: " + ", ".join(f"{k} = {v:.6g}" for k, v in fixed.items()))
    found = plate(read(args.plate), fixed, str(args.plate)) + kicks(read(args.kicks), fixed, str(args.kicks))
    return found, report(found)


if __name__ == "__main__":
    main()
