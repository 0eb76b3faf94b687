"""No leaks: memory stays flat over 1e6 object creations and 1e6 array
calls, and over 3e4 refused calls (error paths: every kind of refusal) and
5e4 pickles and kinematics calls, measured two ways:

- tracemalloc: the Python heap, numpy's array buffers included (numpy
  reports them to tracemalloc), to the byte;
- the resident set size from /proc/self/statm: everything, the C++ heap
  included (a value made by __init__ or __setstate__, and every value of
  the classes other than SO3, SE3, Twist and Wrench, is allocated by
  pybind11 with operator new, which tracemalloc does not see; the values
  those four classes return live inside their Python objects).

The harness is checked before it is trusted: a Python list that keeps one
small object per call, and a C buffer (malloc through ctypes) never freed,
must both be reported as leaks, the first by both measures and the second by
the RSS alone.
"""

from __future__ import annotations

import ctypes
import gc
import os
import pickle
import tracemalloc
from dataclasses import dataclass

import api_spec as A
import numpy as np
import pytest

import chasles

PAGE = os.sysconf("SC_PAGE_SIZE")
# Growth allowed over a measured run (after a warm-up of a tenth of it):
# allocator caches, arenas and tracemalloc's own tables. One leaked object
# per call is 16 bytes or more: over 9e5 calls, 14 MB; over 9e4, 1.4 MB.
TRACED_LIMIT = 256 * 1024
RSS_LIMIT = 4 * 1024 * 1024


_LIBC = ctypes.CDLL(None)


def rss_bytes() -> int:
    """The resident set size, after handing the free heap back to the system
    (glibc's malloc_trim): memory freed earlier in the process and still
    resident would otherwise absorb a leak without any growth."""
    gc.collect()
    if hasattr(_LIBC, "malloc_trim"):
        _LIBC.malloc_trim(0)
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * PAGE


@dataclass
class Growth:
    traced: int
    rss: int
    calls: int

    def flat(self) -> bool:
        return self.traced < TRACED_LIMIT and self.rss < RSS_LIMIT

    def __str__(self):
        return f"over {self.calls} calls: traced {self.traced / 1024:.1f} KiB, RSS {self.rss / 1024:.1f} KiB"


def growth(step, n: int) -> Growth:
    """Memory growth over n calls of step(i), after n // 10 warm-up calls,
    with tracemalloc on (it sees the Python heap) and the RSS (all of it)."""
    warm = max(1, n // 10)
    gc.collect()
    tracemalloc.start()
    try:
        for i in range(warm):
            step(i)
        rss0 = rss_bytes()
        traced0 = tracemalloc.get_traced_memory()[0]
        for i in range(warm, n):
            step(i)
        rss1 = rss_bytes()
        traced1 = tracemalloc.get_traced_memory()[0]
    finally:
        tracemalloc.stop()
    return Growth(traced1 - traced0, rss1 - rss0, n - warm)


# ---- the harness can fail -----------------------------------------------------------------


def test_the_harness_sees_a_python_leak():
    kept = []
    g = growth(lambda i: kept.append(float(i) + 0.5), 200_000)
    assert not g.flat(), f"a list growing by a float per call was not seen: {g}"
    assert g.traced > 4_000_000, g


def test_the_harness_sees_a_c_leak_that_tracemalloc_cannot():
    malloc = _LIBC.malloc
    malloc.restype = ctypes.c_void_p
    malloc.argtypes = [ctypes.c_size_t]

    def step(i):
        p = malloc(64)
        ctypes.memset(p, 1, 64)  # touched, so resident

    g = growth(step, 200_000)
    assert g.traced < TRACED_LIMIT, g
    assert not g.flat() and g.rss > 8_000_000, f"malloc(64) never freed, 2e5 times, was not seen: {g}"


# ---- the library ------------------------------------------------------------------------------

R = chasles.SO3.exp([0.1, 0.2, 0.3])
G = chasles.SE3(R, [1.0, 2.0, 3.0])
W = np.array([0.3, -0.2, 0.1])
XI = np.array([1.0, 0.0, 0.5, 0.0, 0.2, 1.0])


def make_objects(i):
    k = i % 8
    if k == 0:
        chasles.SO3.exp(W)
    elif k == 1:
        chasles.SE3.exp(XI)
    elif k == 2:
        chasles.Twist(v=W, w=W)
    elif k == 3:
        chasles.Wrench.from_vector(XI)
    elif k == 4:
        chasles.Screw(W, [0.0, 0.0, 1.0], 0.5, 1.0)
    elif k == 5:
        G @ G
    elif k == 6:
        chasles.Twist.from_vector(XI).screw()
    else:
        R.inverse()


@pytest.mark.slow
def test_a_million_object_creations_leave_memory_flat():
    g = growth(make_objects, 1_000_000)
    assert g.flat(), g


ARRAY_CALLS = []
for _name in A.ARRAY_FUNCTIONS:
    _entry = A.SPEC[_name]
    _args = [
        np.stack([a.good()] * 4) if isinstance(a, A.Operand) and np.ndim(a.good()) else a.good()
        for a in _entry.signatures[0]
    ]
    ARRAY_CALLS.append((_entry.call, _args))


def array_calls(i):
    f, args = ARRAY_CALLS[i % len(ARRAY_CALLS)]
    f(*args)


@pytest.mark.slow
def test_a_million_array_calls_leave_memory_flat():
    g = growth(array_calls, 1_000_000)
    assert g.flat(), g


def test_large_array_calls_leave_memory_flat():
    """100 calls on 1e5 elements, with and without the GIL-free loop's
    conversions (float32, strided input): 8 MB results freed each time."""
    w = np.random.default_rng(1).normal(size=(100_000, 3))
    variants = [w, w.astype(np.float32), np.repeat(w, 2, axis=0)[::2], w.astype(np.int32)]

    def step(i):
        chasles.se3_exp(np.concatenate([variants[i % 4], variants[i % 4]], axis=1)[:, :6].astype(float))
        chasles.so3_exp(variants[i % 4])

    g = growth(step, 100)
    assert g.flat(), g


BAD = [
    (chasles.SO3.exp, ([1.0, 2.0],)),  # wrong shape
    (chasles.SO3.exp, (np.zeros(3, complex),)),  # wrong dtype
    (chasles.SO3.exp, ([[1.0, 2.0, 3.0], [1.0]],)),  # ragged: a conversion error with a cause
    (chasles.SO3.exp, ([np.nan, 0.0, 0.0],)),  # not finite
    (chasles.SO3.from_matrix, (2.0 * np.eye(3),)),  # not a rotation
    (chasles.so3_exp, (np.zeros((2, 4)),)),
    (chasles.so3_exp, ([[1.0, 2.0, 3.0], [1.0]],)),
    (chasles.so3_exp, (np.zeros(3, np.complex64),)),  # no loop (numpy's refusal)
    (chasles.SE3().act, (np.zeros((2, 4)),)),  # the ufunc's refusal, re-raised naming the call
    (chasles.Chain([[0, 0, 0, 0, 0, 1.0]], np.eye(4)).forward, (np.zeros(1, complex),)),
    (chasles.se3_compose, (np.zeros((2, 4, 4)), np.zeros((3, 4, 4)))),
    (chasles.SO3.interpolate, (R, G, 0.5)),  # pybind11's overload refusal
    (chasles.SO3.log, (chasles.SO3.__new__(chasles.SO3),)),  # uninitialized
    (chasles.SO3.interpolate, (R, R, 10**400)),
    (lambda: chasles.Twist() * [1.0], ()),
]


def bad_calls(i):
    f, args = BAD[i % len(BAD)]
    try:
        f(*args)
    except (TypeError, ValueError):
        pass
    else:
        raise AssertionError("a bad call succeeded")


def test_refused_calls_leave_memory_flat():
    g = growth(bad_calls, 30_000)
    assert g.flat(), g


CHAIN = A.GOOD[chasles.Chain]()
THETAS = np.random.default_rng(2).normal(size=(8, 2))


def pickles_and_chains(i):
    x = A.GOOD[A.BOUND[i % len(A.BOUND)]]()
    pickle.loads(pickle.dumps(x))
    CHAIN.forward(THETAS[i % 8])
    CHAIN.jacobian_body(THETAS)
    _ = CHAIN.space_screws, CHAIN.home


def test_pickles_and_kinematics_leave_memory_flat():
    g = growth(pickles_and_chains, 50_000)
    assert g.flat(), g


ALIGN_B = np.random.default_rng(3).normal(size=(20, 3))
ALIGN_A = ALIGN_B @ chasles.so3_exp([0.3, -0.2, 1.0]).T + 0.01
ALIGN_W = np.linspace(0.5, 2.0, 20)
ALIGN_INF = np.where(np.arange(20) == 4, np.inf, ALIGN_W)
ALIGN_LINE = np.outer(np.arange(20.0), [1.0, 2.0, 3.0])


def align_calls(i):
    """so3_align (plain, weighted, a primary vector, one warned), se3_align and
    sim3_align, and their refusals (the C++ status read back, the message built)."""
    k = i % 8
    if k == 0:
        chasles.so3_align(ALIGN_A, ALIGN_B, ALIGN_W)
    elif k == 1:
        chasles.so3_align(ALIGN_A, ALIGN_B, ALIGN_INF)
    elif k == 2:
        chasles.se3_align(ALIGN_A, ALIGN_B)
    elif k == 3:
        chasles.sim3_align(ALIGN_A, ALIGN_B, ALIGN_W)
    elif k == 4:
        with pytest.warns(UserWarning):
            chasles.so3_align(ALIGN_LINE, ALIGN_LINE)
    else:
        bad = {5: (ALIGN_LINE, ALIGN_LINE, None), 6: (ALIGN_A, ALIGN_B, -ALIGN_W), 7: (ALIGN_A, ALIGN_B * np.nan, None)}
        with pytest.raises(ValueError):
            chasles.se3_align(*bad[k])


def test_alignments_leave_memory_flat():
    g = growth(align_calls, 40_000)
    assert g.flat(), g
