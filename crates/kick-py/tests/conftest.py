"""Shared helpers: the `kick` binary for comparisons with the command line."""

import json
import os
import pathlib
import subprocess

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[3]


@pytest.fixture(scope="session")
def kick_bin() -> str:
    """The built `kick` binary: $KICK_BIN, else target/release/kick of this checkout."""
    path = pathlib.Path(os.environ.get("KICK_BIN", ROOT / "target" / "release" / "kick"))
    if not path.is_file():
        pytest.fail(f"no kick binary at {path}: run `cargo build --release --bin kick` or set KICK_BIN")
    return str(path)


def flags(**params) -> list:
    """Keywords as the CLI's flags: `--` plus the kebab case, vectors comma-separated, switches bare."""
    out = []
    for name, value in params.items():
        flag = "--" + name.replace("_", "-")
        if value is True:
            out.append(flag)
        elif isinstance(value, (list, tuple)):
            out += [flag, ",".join(repr(float(v)) for v in value)]
        else:
            out += [flag, repr(value) if isinstance(value, float) else str(value)]
    return out


def cli(kick_bin, *args, ok=True):
    """Run `kick ARGS`; the parsed JSON on success, else the error message (stderr after `error: `)."""
    done = subprocess.run([kick_bin, *map(str, args)], capture_output=True, text=True, cwd=ROOT)
    if ok:
        assert done.returncode == 0, done.stderr
        return json.loads(done.stdout)
    assert done.returncode == 1, (done.returncode, done.stdout)
    message = done.stderr.strip()
    assert message.startswith("error: "), message
    return message[len("error: "):]


def same(python, cli_value, path="") -> None:
    """Equal, value for value (floats bit for bit): numpy arrays compared as lists."""
    if hasattr(python, "tolist"):
        python = python.tolist()
    if isinstance(cli_value, dict):
        assert isinstance(python, dict), path
        assert sorted(python) == sorted(cli_value), (path, sorted(python), sorted(cli_value))
        for key in cli_value:
            same(python[key], cli_value[key], f"{path}.{key}")
    elif isinstance(cli_value, list):
        assert len(python) == len(cli_value), path
        for i, (a, b) in enumerate(zip(python, cli_value)):
            same(a, b, f"{path}[{i}]")
    else:
        assert python == cli_value and type(python) is type(cli_value), (path, python, cli_value)


def assert_same(a: dict, b: dict) -> None:
    """Two `*_many` results equal key for key: arrays bit for bit (NaN where NaN), same dtype and shape."""
    import numpy as np

    assert sorted(a) == sorted(b)
    for key in a:
        if key == "failure_message":
            assert a[key] == b[key]
        else:
            assert a[key].dtype == b[key].dtype and a[key].shape == b[key].shape, key
            np.testing.assert_array_equal(a[key], b[key], err_msg=key)  # NaN where NaN
