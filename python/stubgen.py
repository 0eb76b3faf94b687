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


def generate() -> str:
    """The stub pybind11-stubgen writes for the installed chasles._core."""
    with tempfile.TemporaryDirectory() as out:
        # Run from the temporary directory so that `import chasles` finds the
        # installed package, not a source tree that happens to be the cwd.
        subprocess.run(
            [sys.executable, "-m", "pybind11_stubgen", MODULE, "--exit-code", "-o", out],
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
