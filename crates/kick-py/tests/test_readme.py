"""crates/kick-py/README.md lists every public function of the module."""

import inspect
import re
from pathlib import Path

import kick
import kick.dask

README = Path(__file__).resolve().parents[1] / "README.md"


def listed() -> set:
    """The functions in the first column of the README's function table."""
    names = set()
    in_table = False
    for line in README.read_text().splitlines():
        if line.startswith("| function |"):
            in_table = True
            continue
        if in_table and not line.startswith("|"):
            break
        if in_table:
            first = line.split("|")[1]
            names.update(re.findall(r"`((?:kick\.dask\.)?\w+)\(", first))
    return names


def public() -> set:
    def functions(module, names, prefix=""):
        return {prefix + n for n in names if callable(getattr(module, n)) and not inspect.isclass(getattr(module, n))}

    return functions(kick, kick.__all__) | functions(kick.dask, kick.dask.__all__, "kick.dask.")


def test_readme_lists_every_public_function():
    names = listed()
    assert "simulate" in names and "kick.dask.to_zarr" in names
    assert names == public(), f"missing from the README: {sorted(public() - names)}; not in the module: {sorted(names - public())}"


def test_every_public_callable_is_in_all():
    """A function defined in the module but left out of __all__ would escape the README check."""
    own = {
        n
        for n, v in vars(kick).items()
        if not n.startswith("_") and inspect.isfunction(v) and v.__module__.startswith("kick")
    }
    assert own <= set(kick.__all__), sorted(own - set(kick.__all__))
