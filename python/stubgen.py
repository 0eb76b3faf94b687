"""Regenerates the type stub python/chasles/_core.pyi from the installed
extension chasles._core, with pybind11-stubgen.

    pip install .[test]                    # builds chasles._core, installs pybind11-stubgen
    python python/stubgen.py               # rewrites python/chasles/_core.pyi
    python python/stubgen.py --check       # exit 1 with a diff if the committed stub is stale

Run it with the interpreter that has chasles installed; the working directory
does not matter. tests/python/test_stubs.py runs the --check form, so a
binding changed without regenerating the stub fails the test suite.
"""

from __future__ import annotations

import argparse
import difflib
import subprocess
import sys
import tempfile
from pathlib import Path

STUB = Path(__file__).resolve().parent / "chasles" / "_core.pyi"
MODULE = "chasles._core"

# pybind11-stubgen asks inspect for a function's signature first and reads
# pybind11's typed signature lines (the top of __doc__) only when inspect
# finds none. chasles' functions carry a __text_signature__ for help() and
# inspect.signature (names and defaults, no types: bindings/signatures.hpp),
# so the driver below makes inspect decline for them, and the stub keeps
# pybind11's annotations.
DRIVER = """
import inspect
import sys

import pybind11_stubgen

_getfullargspec = inspect.getfullargspec


def getfullargspec(func):
    module = getattr(func, "__module__", None) or ""
    if module.split(".")[0] == "chasles" and getattr(func, "__text_signature__", None):
        raise TypeError("typed signature lines in __doc__")
    return _getfullargspec(func)


inspect.getfullargspec = getfullargspec
sys.argv[0] = "pybind11-stubgen"
pybind11_stubgen.main()
"""


def generate() -> str:
    """The stub pybind11-stubgen writes for the installed chasles._core."""
    with tempfile.TemporaryDirectory() as out:
        # Run from the temporary directory so that `import chasles` finds the
        # installed package, not a source tree that happens to be the cwd.
        subprocess.run(
            [sys.executable, "-c", DRIVER, MODULE, "--exit-code", "-o", out],
            cwd=out,
            check=True,
            capture_output=True,
            text=True,
        )
        return (Path(out) / "chasles" / "_core.pyi").read_text()


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--check", action="store_true", help="compare instead of writing")
    args = parser.parse_args(argv)
    try:
        fresh = generate()
    except subprocess.CalledProcessError as e:
        sys.stderr.write(f"pybind11-stubgen failed:\n{e.stdout}{e.stderr}")
        return 2
    if not args.check:
        STUB.write_text(fresh)
        print(f"wrote {STUB}")
        return 0
    committed = STUB.read_text() if STUB.exists() else ""
    if committed == fresh:
        print(f"{STUB} is up to date")
        return 0
    diff = difflib.unified_diff(
        committed.splitlines(keepends=True),
        fresh.splitlines(keepends=True),
        fromfile=f"{STUB} (committed)",
        tofile="pybind11-stubgen chasles._core (fresh)",
    )
    sys.stdout.writelines(diff)
    print(f"\n{STUB} is stale: regenerate it with `python python/stubgen.py`.")
    return 1


if __name__ == "__main__":
    sys.exit(main())
