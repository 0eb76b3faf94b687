"""The committed type stub python/chasles/_core.pyi equals a fresh
pybind11-stubgen run on the installed extension (python/stubgen.py --check)."""

from __future__ import annotations

import importlib.util
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
SCRIPT = ROOT / "python" / "stubgen.py"


@pytest.mark.skipif(
    importlib.util.find_spec("pybind11_stubgen") is None,
    reason="pybind11-stubgen is not installed (pip install .[test] installs it)",
)
def test_committed_stub_matches_a_fresh_generation():
    assert SCRIPT.exists(), f"{SCRIPT} is missing"
    r = subprocess.run(
        [sys.executable, str(SCRIPT), "--check"],
        capture_output=True,
        text=True,
        timeout=300,
        check=False,
    )
    assert r.returncode == 0, r.stdout + r.stderr


def test_the_package_ships_the_stub_and_the_marker():
    import chasles

    package = Path(chasles.__file__).parent
    assert (package / "py.typed").exists()
    assert (package / "_core.pyi").exists()


def test_the_stub_keeps_the_types_of_pybind11s_signature_lines():
    """The functions carry a __text_signature__ without types (for help and
    inspect); stubgen.py makes pybind11-stubgen read the typed lines instead."""
    stub = (ROOT / "python" / "chasles" / "_core.pyi").read_text()
    for line in (
        "def exp(w: numpy.typing.ArrayLike) -> SO3:",
        "def from_screw(point: numpy.typing.ArrayLike, direction: numpy.typing.ArrayLike, "
        "pitch: float, theta: float) -> SE3:",
        "def is_approx(self, other: SO3, tol: float = 1e-09) -> bool:",
        "def rotation(self) -> SO3:",
        "def translation(self) -> numpy.typing.NDArray[numpy.float64]:",
        "def pitch(self) -> float:",
        "def __eq__(self, other: typing.Any) -> bool:",
        "def rplus(g: SE3, xi: numpy.typing.ArrayLike) -> SE3:",
    ):
        assert line in stub, line
    assert "def exp(w):" not in stub
