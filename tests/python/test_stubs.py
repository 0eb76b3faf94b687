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
