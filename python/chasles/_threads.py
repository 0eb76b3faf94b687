"""How many threads an array function may split a large batch across: the
count the extension's loops read (bindings/parallel.hpp), checked here, and
the environment variable CHASLES_NUM_THREADS, read once at import."""

from __future__ import annotations

import operator
import os
import warnings
from typing import Any, SupportsIndex

from chasles import _core

_RANGE = f"an int from 1 to {_core._max_threads}"


def _count(what: str, n: Any) -> int:
    """n as a thread count: TypeError for what is not an integer (a bool
    included), ValueError outside 1 .. _core._max_threads."""
    t = type(n)
    if isinstance(n, bool) or not hasattr(t, "__index__"):
        name = t.__name__ if t.__module__ == "builtins" else f"{t.__module__}.{t.__qualname__}"
        raise TypeError(f"{what} must be {_RANGE}, got {name}")
    value = operator.index(n)
    if not 1 <= value <= _core._max_threads:
        raise ValueError(f"{what} must be {_RANGE}, got {value}")
    return value


def set_num_threads(n: SupportsIndex) -> None:
    """Sets how many threads an array function may split a large batch across.

    The default is 1, or the environment variable CHASLES_NUM_THREADS read at
    import. With n > 1, a call on a batch of N elements runs on
    min(n, N // grain) threads, each on a contiguous part of the batch, inside
    the ufunc's loop (the GIL is released there as always): grain is 16384
    elements for the array functions and 512 configurations for the methods of
    Chain, so a small batch never pays for a thread. Every element is computed
    by the same code as on one thread: results are bit for bit the same.

    The setting is the process's, shared by every Python thread. n: an int from
    1 to 1024 (ValueError outside, TypeError for a non-integer).
    """
    _core._set_num_threads(_count("set_num_threads(n)", n))


def _read_environment() -> None:
    """CHASLES_NUM_THREADS at import: a value that is not a thread count is
    named in a warning and the default (1) kept (a typo in the environment
    must not make the package fail to import)."""
    text = os.environ.get("CHASLES_NUM_THREADS", "")
    if not text:
        return
    try:
        n = int(text)
    except ValueError:
        warnings.warn(
            f"CHASLES_NUM_THREADS must be {_RANGE}, got {text!r}; using 1 thread", RuntimeWarning, stacklevel=3
        )
        return
    try:
        _core._set_num_threads(_count("CHASLES_NUM_THREADS", n))
    except ValueError as e:
        warnings.warn(f"{e}; using 1 thread", RuntimeWarning, stacklevel=3)
