"""The guide paper/guides/measurements.md: every command and Python block in
it runs, and its files agree with each other (the fit files list exactly the
sheets' calibration rows, the kick fit holds the plate fit's estimate)."""

import csv
import json
import os
import pathlib
import re
import subprocess
import sys
import textwrap

import numpy as np
import pytest

import kick

from conftest import ROOT

GUIDE = ROOT / "paper" / "guides" / "measurements.md"
FILES = ROOT / "paper" / "guides" / "measurements"
tomllib = pytest.importorskip("tomllib")  # Python >= 3.11


def blocks(language: str) -> list:
    return re.findall(rf"^ *```{language}\n(.*?)^ *```", GUIDE.read_text(), flags=re.S | re.M)


@pytest.fixture(scope="module")
def workdir(tmp_path_factory, kick_bin):
    """A directory like the repository's root (its paper/ and crates/), with
    `kick` and this Python first on PATH: where the guide's commands run."""
    here = tmp_path_factory.mktemp("guide")
    for name in ("paper", "crates"):
        (here / name).symlink_to(ROOT / name)
    env = dict(os.environ, PATH=os.pathsep.join([str(pathlib.Path(kick_bin).parent), str(pathlib.Path(sys.executable).parent), os.environ["PATH"]]))
    return here, env


def test_every_command_of_the_guide_runs(workdir):
    here, env = workdir
    commands = [line.strip() for block in blocks("sh") for line in block.splitlines() if line.strip()]
    assert len(commands) >= 7 and any(c.startswith("kick fit data") for c in commands)
    for command in commands:
        done = subprocess.run(["bash", "-c", command], cwd=here, env=env, capture_output=True, text=True, timeout=300)
        assert done.returncode == 0, f"{command}\n{done.stderr}"
        if "--format json" in command and ">" not in command:
            json.loads(done.stdout)
    # The comparison after calibration: both roles summed, the estimates held.
    last = subprocess.run(["bash", "-c", commands[-1]], cwd=here, env=env, capture_output=True, text=True, timeout=300).stdout
    assert last.startswith("held: shell_damping = ") and "foot_mass = " in last
    assert re.search(r"^calibration: chi\^2 = ", last, re.M) and re.search(r"^prediction: chi\^2 = ", last, re.M)


def test_every_python_block_of_the_guide_runs(workdir, monkeypatch):
    here, _ = workdir
    monkeypatch.chdir(here)
    namespace = {}
    code = blocks("python")
    assert len(code) >= 3
    for block in code:
        exec(compile(textwrap.dedent(block), str(GUIDE), "exec"), namespace)
    assert (namespace["rows"]["status"] == 0).all()


def sheet(name):
    with open(FILES / name, newline="") as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def spec(name):
    return tomllib.loads((FILES / name).read_text())


@pytest.mark.parametrize("sheet_name,fit_name,conditions,observables", [
    ("lab_plate.csv", "plate_fit.toml", ["speed", "inflation_pressure"], {"restitution": "restitution", "contact_time": "contact_time"}),
    ("lab_kicks.csv", "kick_fit.toml", ["foot_speed"], {"ball_speed": "v_ball_out", "contact_time": "contact_time"}),
])
def test_the_fit_files_hold_exactly_the_calibration_rows(sheet_name, fit_name, conditions, observables):
    rows = {r["name"]: r for r in sheet(sheet_name)}
    assert {r["role"] for r in rows.values()} == {"calibration", "prediction"}
    measurements = spec(fit_name)["measurement"]
    assert sorted(m["name"] for m in measurements) == sorted(n for n, r in rows.items() if r["role"] == "calibration")
    for m in measurements:
        row = rows[m["name"]]
        for c in conditions:
            assert m[c] == float(row[c]), (m["name"], c)
        if "offset" in row:
            assert float(row["offset"]) == 0.0  # a 1D kick fit: straight kicks only
        given = {s["observable"]: (s["value"], s["sigma"]) for s in m["scalar"]}
        assert given == {o: (float(row[c]), float(row["u_" + c])) for c, o in observables.items()}


def test_the_kick_fit_holds_the_plate_fits_estimate(kick_bin):
    done = subprocess.run([kick_bin, "fit", "data", str(FILES / "plate_fit.toml"), "--format", "json"], capture_output=True, text=True, cwd=ROOT)
    assert done.returncode == 0, done.stderr
    (estimate,) = json.loads(done.stdout)["estimates"]
    assert estimate["parameter"] == "shell_damping"
    held = spec("kick_fit.toml")["scenario"]["shell_damping"]
    # Within a tenth of the estimate's standard error: the printed digits.
    assert abs(held - estimate["value"]) < 0.1 * estimate["standard_uncertainty"]


def test_the_residuals_are_the_models_at_each_rows_conditions():
    """compare_measurements.py's z against single calls made here."""
    sys.path.insert(0, str(ROOT / "crates" / "kick-py" / "examples"))
    try:
        import compare_measurements as compare
    finally:
        sys.path.pop(0)
    found, totals = compare.main(["--set", "shell_damping=3500"])
    by = {(name, observable): (model, measured, u) for name, _, observable, model, measured, u in found}
    plate = kick.bounce(speed=15.0, inflation_pressure=8e4, shell_damping=3500.0)
    assert by[("plate 0.8 bar fast", "restitution")] == (plate["restitution"], 0.71, 0.01)
    one = kick.simulate3d(law="shell", foot_speed=20.0, offset=0.05, shell_damping=3500.0)
    model, measured, u = by[("curve 5 cm", "spin")]
    assert model == pytest.approx(np.linalg.norm(one["spin"]) / (2 * np.pi), rel=1e-12) and (measured, u) == (6.0, 0.3)
    chi2 = sum(((m - x) / s) ** 2 for m, x, s in by.values())
    assert sum(c for c, _ in totals.values()) == pytest.approx(chi2)
    assert sum(n for _, n in totals.values()) == len(found) == 6 * 2 + 5 * 3


def test_a_sheets_every_condition_column_reaches_the_model(tmp_path):
    """A condition column beyond foot_speed and offset (here contact_depth and
    inflation_pressure) runs each row at its own value; a column that is
    neither a condition nor an observable is refused, not ignored."""
    sys.path.insert(0, str(ROOT / "crates" / "kick-py" / "examples"))
    try:
        import compare_measurements as compare
    finally:
        sys.path.pop(0)
    sheet = ROOT / "paper" / "guides" / "measurements" / "lab_kicks.csv"
    lines = [l for l in sheet.read_text().splitlines() if not l.startswith("#")]
    header, rows = lines[0], lines[1:]
    extended = tmp_path / "kicks.csv"
    extended.write_text("\n".join([header + ",contact_depth,inflation_pressure"] + [r + ",0.05,110000" for r in rows]) + "\n")
    found, _ = compare.main(["--kicks", str(extended)])
    by = {(name, observable): model for name, _, observable, model, _, _ in found}
    one = kick.simulate3d(law="shell", foot_speed=20.0, offset=0.05, contact_depth=0.05, inflation_pressure=1.1e5)
    assert by[("curve 5 cm", "spin")] == pytest.approx(np.linalg.norm(one["spin"]) / (2 * np.pi), rel=1e-12)
    assert by[("curve 5 cm", "ball_speed")] == pytest.approx(one["speed"], rel=1e-12)
    stray = tmp_path / "stray.csv"
    stray.write_text("\n".join([header + ",kneee"] + [r + ",30" for r in rows]) + "\n")
    with pytest.raises(SystemExit, match="column `kneee` is neither an observable"):
        compare.main(["--kicks", str(stray)])
