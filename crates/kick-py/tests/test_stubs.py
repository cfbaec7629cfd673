"""The type stub is generated from the declared lists and kept current."""

import pathlib
import subprocess
import sys

import kick

HERE = pathlib.Path(__file__).resolve().parent


def test_the_stub_is_current():
    sys.path.insert(0, str(HERE.parent))
    import stubgen

    assert stubgen.STUB.read_text() == stubgen.render(), "stale: run `python crates/kick-py/stubgen.py`"


def test_the_package_ships_stub_and_marker():
    package = pathlib.Path(kick.__file__).parent
    assert (package / "__init__.pyi").is_file() and (package / "py.typed").is_file()
    text = (package / "__init__.pyi").read_text()
    assert "def simulate3d_many(" in text and "foot_inertia: ArrayLike | None = ..." in text


def test_help_reads_well():
    out = subprocess.run([sys.executable, "-c", "import kick; help(kick.simulate_many)"], capture_output=True, text=True)
    assert "simulate_many(*, foot_mass=3.0, ball_mass=0.43" in out.stdout
    assert "status`` (uint8: 0 separated, 1 numerical failure, 2 trapped, 3 refused" in out.stdout
