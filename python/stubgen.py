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


# pybind11-stubgen types every array function as a bare numpy.ufunc. As
# numpy's own _umath_linalg.pyi, the stub gives each public one a generic
# type that carries its operands (positional, as numpy passes them), its
# name and its core signature, with the signature and the operands' names in
# a comment beside it.
UFUNC_TYPEVARS = """
_Name = typing.TypeVar("_Name", bound=str)
_Signature = typing.TypeVar("_Signature", bound=str)
"""
UFUNC_CLASS = """
class _GUFunc_Nin{nin}_Nout{nout}(numpy.ufunc, typing.Generic[_Name, _Signature]):
    \"\"\"A numpy generalized ufunc of {nin} operand(s) and {results}.\"\"\"
    @property
    def __name__(self) -> _Name: ...
    @property
    def signature(self) -> _Signature: ...
    @property
    def nin(self) -> typing.Literal[{nin}]: ...
    @property
    def nout(self) -> typing.Literal[{nout}]: ...
    def __call__(
        self,
        {operands}
        /,
        out: {out} = ...,
        *,
        where: numpy.typing.ArrayLike = ...,
        axes: list[tuple[int, ...]] = ...,
        axis: int = ...,
        keepdims: bool = ...,
        casting: typing.Literal["no", "equiv", "safe", "same_kind", "unsafe"] = ...,
        order: typing.Literal["K", "A", "C", "F"] = ...,
        dtype: numpy.typing.DTypeLike = ...,
        subok: bool = ...,
        signature: typing.Any = ...,
    ) -> {returns}: ...
"""


def type_array_functions(stub: str) -> str:
    """The stub with each public array function of chasles._core typed
    (UFUNC_CLASS) instead of a bare numpy.ufunc."""
    import inspect

    import numpy as np

    # The installed chasles: python/chasles beside this script (sys.path[0]
    # when it runs as a script) has no compiled _core.
    here = Path(__file__).resolve().parent
    sys.path[:] = [p for p in sys.path if Path(p or ".").resolve() != here]
    from chasles import _core

    lines = stub.splitlines(keepends=True)
    arities: set[tuple[int, int]] = set()
    for i, line in enumerate(lines):
        name = line.split(":")[0]
        u = getattr(_core, name, None) if line.endswith(": numpy.ufunc\n") else None
        if not isinstance(u, np.ufunc) or name.startswith("_"):
            continue
        arities.add((u.nin, u.nout))
        params = ", ".join(inspect.signature(u).parameters)  # named by ufunc.hpp's describe_ufunc
        params = ", ".join(p for p in params.split(", ")[: u.nin])
        lines[i] = (
            f"# {name}({params}): {u.signature}\n"
            f'{name}: _GUFunc_Nin{u.nin}_Nout{u.nout}[typing.Literal["{name}"], typing.Literal["{u.signature}"]]\n'
        )
    array = "numpy.typing.NDArray[numpy.floating[typing.Any]]"
    classes = "".join(
        UFUNC_CLASS.format(
            nin=n,
            nout=k,
            results="one result" if k == 1 else f"{k} results",
            operands=" ".join(f"x{j}: numpy.typing.ArrayLike," for j in range(1, n + 1)),
            out="numpy.ndarray | tuple[numpy.ndarray] | None"
            if k == 1
            else f"tuple[{', '.join(['numpy.ndarray'] * k)}] | None",
            returns=array if k == 1 else f"tuple[{', '.join([array] * k)}]",
        )
        for n, k in sorted(arities)
    )
    at = next(i for i, line in enumerate(lines) if line.startswith("__all__"))
    return "".join(lines[: at + 1]) + UFUNC_TYPEVARS + classes + "".join(lines[at + 1 :])


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
        return type_array_functions((Path(out) / "chasles" / "_core.pyi").read_text())


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
