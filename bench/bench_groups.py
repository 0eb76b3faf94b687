#!/usr/bin/env python3
"""The groups of chasles beyond SO3/SE3 (SO2, SE2, Sim3, SE23) beside their peers on PyPI, timed in one run.

    python bench/bench_groups.py [--rounds 7] [--sizes 100000] [--groups so2 se2] [--loop-size 10000]
                                 [--samples 1000] [--budget 0.02] [--no-accuracy]

Needs numpy; chasles, gtsam (Rot2, Pose2, Similarity3, NavState), jaxlie
(SO2, SE2, on jax for CPU) and mpmath are each used when importable and
skipped otherwise (a group a library lacks prints "n/a" in its cells). Prints markdown tables, with
a header line naming the version of each contender:

1. Per call (us): one element at a time through each library's object API,
   from Python. Columns: one per contender, then "ratio": chasles divided by
   the fastest peer of the row, and which peer that is (< 1: chasles is
   faster). jaxlie is timed jitted (jax.jit of the operation, compiled
   first, the output blocked on): without jit one call costs milliseconds.
2. Per element of a batch (ns), at each N of --sizes: chasles' array
   functions (numpy generalized ufuncs), jaxlie's jax.jit(jax.vmap(op)), and
   gtsam as a Python loop over its objects (it has no batch form) run over
   min(N, --loop-size) elements only. Same columns and ratio as table 1.
3. Worst error (in eps = 2^-52) of exp and log, per contender, on hard inputs
   (theta = 0, 1e-300, 1e-12, 1e-8, 1e-4, 0.1, 1, pi/2, pi - 1e-6,
   pi - 1e-12, pi; for SE2 each with translations of size 1e-6, 1 and 1e3)
   and on --samples random ones, against mpmath at 50 digits, with the input
   that gave the worst. exp: max over the matrix entries of
   |entry - reference| / max(1, |reference|), |reference| the largest entry
   of the entry's block (rotation entries and angles: absolute; translation
   entries: relative to the translation's size). log: the same over the
   tangent entries, of the log of the double matrix nearest the exact exp (the
   reference being the exact log of that rounded matrix), accepting either
   branch at theta = +-pi. "exp(log)": the exact exp of the returned tangent
   against the matrix given, which holds whatever the branch.

Timing: for each operation every contender runs once per round (a loop of
about --budget seconds), in a rotating order, for --rounds rounds, and keeps
its best round: machines are shared and noisy, so the least disturbed round
is the one closest to the cost of the code, and contenders measured in the
same rounds see the same machine.

For Sim3 the hard inputs add the log-scales sigma = 0, 1e-12, 1e-8, 1e-4, 1
and -5 to each angle (random axes); for SE23 each angle has position parts
of size 1e-6, 1 and 1e3. Adding a group: one more GroupSpec in GROUPS, with
its mpmath exp and log, its hard inputs and its contenders (chasles_impl /
gtsam_impl / jaxlie_impl are generic over the class; gtsam_impl converts the
tangent order and the matrix).
"""

from __future__ import annotations

import argparse
import gc
import importlib
import importlib.metadata
import math
import sys
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

Thunk = Callable[[], object]
ManyFn = Callable[[np.ndarray], np.ndarray]

OPS = ("exp", "log", "compose")
EPS = float(np.finfo(np.float64).eps)
MP_DIGITS = 50


def optional(name: str) -> Any:
    try:
        return importlib.import_module(name)
    except Exception:  # noqa: BLE001 - any failure to import means "not available"
        return None


chasles = optional("chasles")
gtsam = optional("gtsam")
jax = optional("jax")
if jax is not None:
    # chasles and gtsam compute in float64: so must jaxlie, or it is timed and
    # measured in float32. (Set before jaxlie makes any array.)
    jax.config.update("jax_enable_x64", True)
    jax.config.update("jax_platforms", "cpu")  # chasles runs on the CPU: so does jax, even where a GPU is
jnp = optional("jax.numpy") if jax is not None else None
jaxlie = optional("jaxlie") if jax is not None else None
mpmath = optional("mpmath")


def version(dist: str, module: Any) -> str:
    if module is None:
        return "absent"
    try:
        return importlib.metadata.version(dist)
    except Exception:  # noqa: BLE001 - an uninstalled (in-tree) build has no metadata
        return str(getattr(module, "__version__", "?"))


# ---------------------------------------------------------------------------
# Timing: interleaved rounds, best round kept.


def calibrate(fn: Thunk, budget: float) -> int:
    """How many calls of fn take about `budget` seconds (after one warm-up call,
    which also compiles the jitted functions and fails here, not in the rounds)."""
    fn()
    number = 1
    while True:
        t0 = time.perf_counter()
        for _ in range(number):
            fn()
        dt = time.perf_counter() - t0
        if dt > budget / 4 or number > 1 << 22:
            break
        number *= 4
    return max(1, int(number * budget / max(dt, 1e-9)))


def interleaved(fns: dict[str, Thunk | None], rounds: int, budget: float) -> dict[str, float | None]:
    """Seconds per call of each fn: every fn runs once per round (in an order
    that rotates from round to round), and keeps its best round. None for an
    absent fn, or one that fails."""
    live: dict[str, tuple[Thunk, int]] = {}
    for name, fn in fns.items():
        if fn is None:
            continue
        try:
            live[name] = (fn, calibrate(fn, budget))
        except Exception as e:  # noqa: BLE001 - a peer's API drift must not stop the run
            print(f"<!-- {name} skipped: {e!r} -->", file=sys.stderr)
    best = dict.fromkeys(live, math.inf)
    names = list(live)
    if not names:
        return dict.fromkeys(fns)
    enabled = gc.isenabled()
    gc.disable()  # as timeit: no collection of another round's garbage inside a timed loop
    try:
        for r in range(rounds):
            for name in names[r % len(names) :] + names[: r % len(names)]:
                fn, number = live[name]
                t0 = time.perf_counter()
                for _ in range(number):
                    fn()
                best[name] = min(best[name], (time.perf_counter() - t0) / number)
            gc.collect()
    finally:
        if enabled:
            gc.enable()
    return {name: best.get(name) for name in fns}


def fig(x: float) -> str:
    """Three significant digits, without an exponent up to 1e6."""
    return f"{x:.3g}" if x < 1000 else f"{x:.0f}"


def ratio_cell(times: dict[str, float | None]) -> str:
    """chasles / the fastest peer, and which peer that is."""
    ours = times.get("chasles")
    peers = [(t, name) for name, t in times.items() if name != "chasles" and t is not None]
    if not ours or not peers:
        return ""
    best = min(peers)
    return f"{ours / best[0]:.3g} ({best[1]})"


# ---------------------------------------------------------------------------
# Contenders. An Impl is one library on one group: its per-call and batch
# thunks (on inputs given as tangents, each library building its own elements
# from them, outside the timed thunk), and its exp / log over many elements for
# the accuracy table.


@dataclass
class Impl:
    calls: Callable[[np.ndarray, np.ndarray], dict[str, Thunk]]  # (xi1, xi2) -> op -> one call
    batch: Callable[[np.ndarray, np.ndarray], dict[str, Thunk]]  # (X1, X2) of shape (N, dim) -> op -> N elements
    # label -> (exp: tangents (k, dim) -> matrices (k, n, n), log: matrices -> tangents, or None)
    accuracy: dict[str, tuple[ManyFn, ManyFn | None]] = field(default_factory=dict)
    loop: bool = False  # the batch is a Python loop: run over at most --loop-size elements


def chasles_impl(cls_name: str, prefix: str, scalar: bool) -> Impl | None:
    """chasles.<cls_name> objects and the chasles.<prefix>_exp / _log / _compose
    gufuncs. `scalar`: the tangent is one number (SO2), given to the object as a
    float and to the gufuncs as an array of shape (...) rather than (..., 1)."""
    if chasles is None or not hasattr(chasles, cls_name):
        return None
    G = getattr(chasles, cls_name)
    g_exp, g_log, g_compose = (getattr(chasles, f"{prefix}_{op}") for op in OPS)

    def arg(x: np.ndarray) -> Any:
        return float(x[0]) if scalar else x

    def calls(x1: np.ndarray, x2: np.ndarray) -> dict[str, Thunk]:
        t1 = arg(x1)
        a, b = G.exp(t1), G.exp(arg(x2))
        return {"exp": lambda: G.exp(t1), "log": lambda: a.log(), "compose": lambda: a @ b}

    def batch(X1: np.ndarray, X2: np.ndarray) -> dict[str, Thunk]:
        T1 = np.ascontiguousarray(X1[:, 0] if scalar else X1)
        A, B = g_exp(T1), g_exp(np.ascontiguousarray(X2[:, 0] if scalar else X2))
        return {"exp": lambda: g_exp(T1), "log": lambda: g_log(A), "compose": lambda: g_compose(A, B)}

    def arr_exp(X: np.ndarray) -> np.ndarray:
        return np.asarray(g_exp(np.ascontiguousarray(X[:, 0] if scalar else X)))

    def arr_log(M: np.ndarray) -> np.ndarray:
        return np.asarray(g_log(M)).reshape(len(M), -1)

    def obj_exp(X: np.ndarray) -> np.ndarray:
        return np.stack([np.asarray(G.exp(arg(x)).as_matrix()) for x in X])

    # The object from a matrix, by whichever constructor the class has (the
    # brief of the API names none): without one, the object log is not measured.
    from_matrix = getattr(G, "from_matrix_unchecked", None) or getattr(G, "from_matrix", None)

    def obj_log(M: np.ndarray) -> np.ndarray:
        return np.stack([np.asarray(from_matrix(m).log(), dtype=float).reshape(-1) for m in M])

    return Impl(
        calls,
        batch,
        {
            "chasles (array functions)": (arr_exp, arr_log),
            "chasles (objects)": (obj_exp, obj_log if from_matrix else None),
        },
    )


def gtsam_impl(
    cls_name: str,
    from_matrix: Callable[[np.ndarray], Any],
    order: Sequence[int] | None = None,
    matrix: Callable[[Any], np.ndarray] | None = None,
) -> Impl | None:
    """gtsam.<cls_name>: Expmap / Logmap (static, on numpy vectors) and compose.
    gtsam has no batch form: its batch is a Python loop over a list of its objects.
    `order`: gtsam's tangent is chasles' x[order] (converted outside the timed
    calls; its logs are put back in chasles' order for the accuracy table);
    `matrix`: chasles' matrix of a gtsam element (default: its .matrix())."""
    if gtsam is None or not hasattr(gtsam, cls_name):
        return None
    G = getattr(gtsam, cls_name)
    perm = None if order is None else np.asarray(order)
    back = slice(None) if perm is None else np.argsort(perm)
    to_matrix = matrix or (lambda g: g.matrix())

    def ours(x: np.ndarray) -> np.ndarray:  # chasles' tangent -> gtsam's
        return np.array(np.asarray(x, dtype=float)[..., perm] if perm is not None else x, dtype=float)

    def calls(x1: np.ndarray, x2: np.ndarray) -> dict[str, Thunk]:
        v1 = ours(x1)  # Expmap takes a vector, even of one entry (Rot2)
        a, b = G.Expmap(v1), G.Expmap(ours(x2))
        return {"exp": lambda: G.Expmap(v1), "log": lambda: G.Logmap(a), "compose": lambda: a.compose(b)}

    def batch(X1: np.ndarray, X2: np.ndarray) -> dict[str, Thunk]:
        V1 = list(ours(X1))
        A, B = [G.Expmap(v) for v in V1], [G.Expmap(v) for v in ours(X2)]
        return {
            "exp": lambda: [G.Expmap(v) for v in V1],
            "log": lambda: [G.Logmap(a) for a in A],
            "compose": lambda: [a.compose(b) for a, b in zip(A, B)],
        }

    def exp_many(X: np.ndarray) -> np.ndarray:
        return np.stack([to_matrix(G.Expmap(v)) for v in ours(X)])

    def log_many(M: np.ndarray) -> np.ndarray:
        return np.stack([np.asarray(G.Logmap(from_matrix(m)), dtype=float).reshape(-1)[back] for m in M])

    return Impl(calls, batch, {"gtsam": (exp_many, log_many)}, loop=True)


def jaxlie_impl(cls_name: str) -> Impl | None:
    """jaxlie.<cls_name> in float64 on the CPU. Per call: jax.jit(op) on one
    element (the time of a jitted call from Python, dispatch included, the
    output blocked on); batch: jax.jit(jax.vmap(op)) on N elements stored as
    jaxlie stores them (unit complex numbers and translations, not matrices),
    compiled for that N before the rounds. The accuracy is that of the
    vmapped, jitted functions: what the batch table times."""
    if jaxlie is None or not hasattr(jaxlie, cls_name):
        return None
    G = getattr(jaxlie, cls_name)
    block = jax.block_until_ready

    def log_fn(g: Any) -> Any:
        return g.log()

    def mul_fn(a: Any, b: Any) -> Any:
        return a @ b

    exp1, log1, mul1 = jax.jit(G.exp), jax.jit(log_fn), jax.jit(mul_fn)
    expn, logn, muln = (jax.jit(jax.vmap(f)) for f in (G.exp, log_fn, mul_fn))
    exp_matrix = jax.jit(jax.vmap(lambda x: G.exp(x).as_matrix()))
    log_matrix = jax.jit(jax.vmap(lambda m: G.from_matrix(m).log()))  # from_matrix only slices the matrix

    def calls(x1: np.ndarray, x2: np.ndarray) -> dict[str, Thunk]:
        j1 = jnp.asarray(x1, dtype=jnp.float64)
        a, b = block(exp1(j1)), block(exp1(jnp.asarray(x2, dtype=jnp.float64)))
        return {
            "exp": lambda: block(exp1(j1)),
            "log": lambda: block(log1(a)),
            "compose": lambda: block(mul1(a, b)),
        }

    def batch(X1: np.ndarray, X2: np.ndarray) -> dict[str, Thunk]:
        J1 = jnp.asarray(X1, dtype=jnp.float64)
        A, B = block(expn(J1)), block(expn(jnp.asarray(X2, dtype=jnp.float64)))
        return {
            "exp": lambda: block(expn(J1)),
            "log": lambda: block(logn(A)),
            "compose": lambda: block(muln(A, B)),
        }

    def exp_many(X: np.ndarray) -> np.ndarray:
        return np.asarray(exp_matrix(jnp.asarray(X, dtype=jnp.float64)))

    def log_many(M: np.ndarray) -> np.ndarray:
        return np.asarray(log_matrix(jnp.asarray(M, dtype=jnp.float64)))

    return Impl(calls, batch, {"jaxlie (vmap+jit)": (exp_many, log_many)})


def gtsam_rot2(m: np.ndarray) -> Any:
    # fromCosSin keeps (c, s) as given when c^2 + s^2 is within 1e-10 of 1:
    # the element holds exactly the matrix given.
    return gtsam.Rot2.fromCosSin(m[0, 0], m[1, 0])


def gtsam_pose2(m: np.ndarray) -> Any:
    return gtsam.Pose2(gtsam_rot2(m), np.array(m[:2, 2]))


# gtsam's Similarity3 matrix is [[R, t'], [0, 1/s]]: the same projective element
# as chasles' [[s R, t], [0, 1]] with t = s t' (docs/coming_from.md).
def gtsam_similarity3(m: np.ndarray) -> Any:
    s = float(np.linalg.norm(m[:3, :3]) / math.sqrt(3.0))
    return gtsam.Similarity3(gtsam.Rot3(m[:3, :3] / s), np.array(m[:3, 3]) / s, s)


def chasles_matrix_of_similarity3(g: Any) -> np.ndarray:
    m = np.asarray(g.matrix(), dtype=float)
    return m / m[3, 3]


def gtsam_navstate(m: np.ndarray) -> Any:
    return gtsam.NavState(gtsam.Rot3(m[:3, :3]), np.array(m[:3, 3]), np.array(m[:3, 4]))


# ---------------------------------------------------------------------------
# Groups: tangent order, references in mpmath, hard and random inputs.


@dataclass
class GroupSpec:
    key: str  # the name in --groups
    name: str  # the name in the tables
    dim: int  # of the tangent
    size: int  # of the matrix
    hard: Callable[[], list[tuple[str, np.ndarray]]]  # labelled tangents
    sample: Callable[[np.random.Generator, int], np.ndarray]  # random tangents, shape (k, dim)
    mp_exp: Callable[[np.ndarray], list[list[Any]]]  # exact exp of a double tangent: size x size mpf
    mp_logs: Callable[[np.ndarray], list[list[Any]]]  # exact log(s) of a double matrix: every accepted branch
    # Blocks of the flattened matrix and of the tangent, each scaled by max(1, its largest reference entry)
    # in the errors: rotations absolute, translations relative to the size of the translation.
    exp_blocks: list[list[int]]
    log_blocks: list[list[int]]
    contenders: dict[str, Callable[[], Impl | None]]


HARD_ANGLES: list[tuple[str, float]] = [
    ("0", 0.0),
    ("1e-300", 1e-300),
    ("1e-12", 1e-12),
    ("1e-8", 1e-8),
    ("1e-4", 1e-4),
    ("0.1", 0.1),
    ("1", 1.0),
    ("pi/2", math.pi / 2),
    ("pi-1e-6", math.pi - 1e-6),
    ("pi-1e-12", math.pi - 1e-12),
    ("pi", math.pi),  # the double nearest pi, 1.2e-16 below it
]
HARD_TRANSLATIONS: list[tuple[str, float]] = [("1e-6", 1e-6), ("1", 1.0), ("1e3", 1e3)]
TRANSLATION_DIRECTION = np.array([0.6, -0.8])
HARD_SIGMAS: list[tuple[str, float]] = [
    ("0", 0.0),
    ("1e-12", 1e-12),
    ("1e-8", 1e-8),
    ("1e-4", 1e-4),
    ("1", 1.0),
    ("-5", -5.0),
]


def mp_rot2(theta: Any) -> tuple[Any, Any]:
    return mpmath.cos(theta), mpmath.sin(theta)


def mp_theta_branches(c: float, s: float) -> list[Any]:
    """The angle of (c, s) in (-pi, pi], and, near +-pi, the other branch too
    (a log may return -pi for pi: both are logs of the same rotation)."""
    theta = mpmath.atan2(mpmath.mpf(s), mpmath.mpf(c))
    if abs(theta) > 3:
        return [theta, theta - 2 * mpmath.pi * mpmath.sign(theta)]
    return [theta]


def so2_mp_exp(x: np.ndarray) -> list[list[Any]]:
    c, s = mp_rot2(mpmath.mpf(float(x[0])))
    return [[c, -s], [s, c]]


def so2_mp_logs(m: np.ndarray) -> list[list[Any]]:
    return [[t] for t in mp_theta_branches(m[0, 0], m[1, 0])]


def so2_hard() -> list[tuple[str, np.ndarray]]:
    return [(f"theta={label}", np.array([t])) for label, t in HARD_ANGLES]


def so2_sample(rng: np.random.Generator, k: int) -> np.ndarray:
    return rng.uniform(-math.pi, math.pi, size=(k, 1))


def se2_mp_exp(x: np.ndarray) -> list[list[Any]]:
    """exp of xi = (vx, vy, w): [[R, V v], [0, 1]] with V = [[A, -B], [B, A]],
    A = sin(w)/w and B = (1 - cos w)/w = 2 sin^2(w/2)/w (no cancellation)."""
    vx, vy, w = (mpmath.mpf(float(e)) for e in x)
    c, s = mp_rot2(w)
    A, B = (1, 0) if w == 0 else (mpmath.sin(w) / w, 2 * mpmath.sin(w / 2) ** 2 / w)
    return [[c, -s, A * vx - B * vy], [s, c, B * vx + A * vy], [0, 0, 1]]


def se2_mp_logs(m: np.ndarray) -> list[list[Any]]:
    """log of [[R, t], [0, 1]]: w = the angle of R, v = V(w)^-1 t with
    V^-1 = [[a, w/2], [-w/2, a]], a = (w/2) cot(w/2); for each branch of w."""
    tx, ty = mpmath.mpf(m[0, 2]), mpmath.mpf(m[1, 2])
    logs = []
    for w in mp_theta_branches(m[0, 0], m[1, 0]):
        a = 1 if w == 0 else (w / 2) * mpmath.cot(w / 2)
        logs.append([a * tx + w / 2 * ty, -w / 2 * tx + a * ty, w])
    return logs


def se2_hard() -> list[tuple[str, np.ndarray]]:
    return [
        (f"theta={la}, v={lv}", np.concatenate([v * TRANSLATION_DIRECTION, [t]]))
        for la, t in HARD_ANGLES
        for lv, v in HARD_TRANSLATIONS
    ]


def se2_sample(rng: np.random.Generator, k: int) -> np.ndarray:
    v = rng.normal(size=(k, 2)) * 10.0 ** rng.uniform(-3, 3, size=(k, 1))
    return np.concatenate([v, rng.uniform(-math.pi, math.pi, size=(k, 1))], axis=1)


# The 3D groups: references from mpmath's expm of the hat matrix; logs of a
# double matrix from its rotation's exact log (the quaternion of the double
# block, normalized: within an ulp of any other reading of a block that is
# off SO(3) by an ulp) and the integral W = int_0^1 exp(u A) du of the
# translation part, from one 6x6 expm ([[A, I], [0, 0]] has W top right).


def mp_hat(w: Sequence[Any]) -> Any:
    return mpmath.matrix([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])


def mp_rows(E: Any, n: int) -> list[list[Any]]:
    return [[E[i, j] for j in range(n)] for i in range(n)]


def mp_rotation_logs(R: np.ndarray) -> list[list[Any]]:
    """The rotation vectors of the double matrix R (up to a rounding, its
    quaternion's), and near pi the other branch, (theta - 2 pi) n, too."""
    r = [[mpmath.mpf(float(R[i, j])) for j in range(3)] for i in range(3)]
    t = r[0][0] + r[1][1] + r[2][2]
    # Shepperd: the largest of 1 + t, 1 + 2 r_ii - t, for a well-conditioned quaternion (w, x, y, z).
    k = max(range(4), key=lambda i: [t, r[0][0], r[1][1], r[2][2]][i] * (1 if i == 0 else 2) - (0 if i == 0 else t))
    if k == 0:
        q = [1 + t, r[2][1] - r[1][2], r[0][2] - r[2][0], r[1][0] - r[0][1]]
    elif k == 1:
        q = [r[2][1] - r[1][2], 1 + 2 * r[0][0] - t, r[0][1] + r[1][0], r[0][2] + r[2][0]]
    elif k == 2:
        q = [r[0][2] - r[2][0], r[0][1] + r[1][0], 1 + 2 * r[1][1] - t, r[1][2] + r[2][1]]
    else:
        q = [r[1][0] - r[0][1], r[0][2] + r[2][0], r[1][2] + r[2][1], 1 + 2 * r[2][2] - t]
    if q[0] < 0:
        q = [-e for e in q]
    nv = mpmath.sqrt(q[1] ** 2 + q[2] ** 2 + q[3] ** 2)
    if nv == 0:
        return [[mpmath.mpf(0)] * 3]
    theta = 2 * mpmath.atan2(nv, q[0])
    n = [e / nv for e in q[1:]]
    logs = [[theta * e for e in n]]
    if theta > 3:
        logs.append([(theta - 2 * mpmath.pi) * e for e in n])
    return logs


def mp_integral_exp(A: Any) -> Any:
    """int_0^1 exp(u A) du of a 3x3 mp matrix A (exact at A = 0 too)."""
    B = mpmath.zeros(6, 6)
    for i in range(3):
        B[i, 3 + i] = 1
        for j in range(3):
            B[i, j] = A[i, j]
    E = mpmath.expm(B)
    return mpmath.matrix([[E[i, 3 + j] for j in range(3)] for i in range(3)])


def sim3_mp_exp(x: np.ndarray) -> list[list[Any]]:
    """exp of xi = (v, w, sigma): expm of [[ [w] + sigma I, v ], [0, 0]]."""
    v, w, (sigma,) = ([mpmath.mpf(float(e)) for e in x[k : k + n]] for k, n in ((0, 3), (3, 3), (6, 1)))
    H = mpmath.zeros(4, 4)
    W = mp_hat(w)
    for i in range(3):
        H[i, 3] = v[i]
        for j in range(3):
            H[i, j] = W[i, j] + (sigma if i == j else 0)
    return mp_rows(mpmath.expm(H), 4)


def sim3_mp_logs(m: np.ndarray) -> list[list[Any]]:
    """log of [[s R, t], [0, 1]]: s = |block|_F / sqrt(3), sigma = log s, w = log R,
    v = W^-1 t with W = int_0^1 exp(u (sigma I + [w])) du."""
    block = np.asarray(m[:3, :3], dtype=float)
    s = mpmath.sqrt(mpmath.fsum(mpmath.mpf(float(e)) ** 2 for e in block.ravel()) / 3)
    sigma = mpmath.log(s)
    R = np.array([[float(mpmath.mpf(float(block[i, j])) / s) for j in range(3)] for i in range(3)])
    t = mpmath.matrix([mpmath.mpf(float(e)) for e in m[:3, 3]])
    logs = []
    for w in mp_rotation_logs(R):
        A = mp_hat(w) + sigma * mpmath.eye(3)
        v = mpmath.lu_solve(mp_integral_exp(A), t)
        logs.append([v[0], v[1], v[2], *w, sigma])
    return logs


def sim3_hard() -> list[tuple[str, np.ndarray]]:
    rng = np.random.default_rng(11)
    out = []
    for i, (la, theta) in enumerate(HARD_ANGLES):
        for j, (ls, sigma) in enumerate(HARD_SIGMAS):
            lv, size = HARD_TRANSLATIONS[(i + j) % len(HARD_TRANSLATIONS)]
            axis = rng.normal(size=3)
            v = rng.normal(size=3)
            out.append(
                (
                    f"theta={la}, sigma={ls}, v={lv}",
                    np.concatenate([size * v / np.linalg.norm(v), theta * axis / np.linalg.norm(axis), [sigma]]),
                )
            )
    return out


def sim3_sample(rng: np.random.Generator, k: int) -> np.ndarray:
    v = rng.normal(size=(k, 3)) * 10.0 ** rng.uniform(-3, 3, size=(k, 1))
    return np.concatenate([v, ball3(rng, k), rng.uniform(-3, 3, size=(k, 1))], axis=1)


def ball3(rng: np.random.Generator, k: int) -> np.ndarray:
    """Rotation vectors of random axes and angles uniform in (0, pi)."""
    n = rng.normal(size=(k, 3))
    return n / np.linalg.norm(n, axis=1, keepdims=True) * rng.uniform(0, math.pi, size=(k, 1))


def se23_mp_exp(x: np.ndarray) -> list[list[Any]]:
    """exp of xi = (rho, nu, w): expm of [[ [w], rho, nu ], [0, 0, 0], [0, 0, 0]]."""
    rho, nu, w = ([mpmath.mpf(float(e)) for e in x[k : k + 3]] for k in (0, 3, 6))
    H = mpmath.zeros(5, 5)
    W = mp_hat(w)
    for i in range(3):
        H[i, 3], H[i, 4] = rho[i], nu[i]
        for j in range(3):
            H[i, j] = W[i, j]
    return mp_rows(mpmath.expm(H), 5)


def se23_mp_logs(m: np.ndarray) -> list[list[Any]]:
    """log of [[R, p, v], [0, 1, 0], [0, 0, 1]]: w = log R, rho = V^-1 p,
    nu = V^-1 v with V = int_0^1 exp(u [w]) du."""
    p = mpmath.matrix([mpmath.mpf(float(e)) for e in m[:3, 3]])
    v = mpmath.matrix([mpmath.mpf(float(e)) for e in m[:3, 4]])
    logs = []
    for w in mp_rotation_logs(np.asarray(m[:3, :3], dtype=float)):
        V = mp_integral_exp(mp_hat(w))
        rho, nu = mpmath.lu_solve(V, p), mpmath.lu_solve(V, v)
        logs.append([*rho, *nu, *w])
    return logs


def se23_hard() -> list[tuple[str, np.ndarray]]:
    rng = np.random.default_rng(12)
    out = []
    for i, (la, theta) in enumerate(HARD_ANGLES):
        for lv, size in HARD_TRANSLATIONS:
            axis = np.array([1.0, 0.0, 0.0]) if i % 2 else rng.normal(size=3)
            rho, nu = rng.normal(size=3), rng.normal(size=3)
            x = np.concatenate(
                [size * rho / np.linalg.norm(rho), nu / np.linalg.norm(nu), theta * axis / np.linalg.norm(axis)]
            )
            out.append((f"theta={la}, rho={lv}", x))
    return out


def se23_sample(rng: np.random.Generator, k: int) -> np.ndarray:
    rho = rng.normal(size=(k, 3)) * 10.0 ** rng.uniform(-3, 3, size=(k, 1))
    nu = rng.normal(size=(k, 3)) * 10.0 ** rng.uniform(-3, 3, size=(k, 1))
    return np.concatenate([rho, nu, ball3(rng, k)], axis=1)


# Tangent orders: chasles, gtsam (Pose2::Expmap / Logmap, checked: the
# translation of Expmap([1, 2, 0.5]) is V(0.5) (1, 2)) and jaxlie (SE2.exp reads
# the angle from tangent[..., 2]) all order the SE2 tangent (vx, vy, w).
# gtsam's Similarity3 tangent is (w, v, lambda) = chasles' (v, w, sigma)
# reordered (its hat [[ [w], v ], [0, -lambda]] is chasles' minus lambda I: the
# same projective element), and NavState's (w, rho, nu) = chasles' (rho, nu, w)
# reordered (checked: Expmap against scipy's expm of chasles' hat).
GROUPS: dict[str, GroupSpec] = {
    g.key: g
    for g in (
        GroupSpec(
            "so2",
            "SO2",
            1,
            2,
            so2_hard,
            so2_sample,
            so2_mp_exp,
            so2_mp_logs,
            [[0, 1, 2, 3]],
            [[0]],
            {
                "chasles": lambda: chasles_impl("SO2", "so2", scalar=True),
                "gtsam": lambda: gtsam_impl("Rot2", gtsam_rot2),
                "jaxlie": lambda: jaxlie_impl("SO2"),
            },
        ),
        GroupSpec(
            "se2",
            "SE2",
            3,
            3,
            se2_hard,
            se2_sample,
            se2_mp_exp,
            se2_mp_logs,
            [[0, 1, 3, 4], [2, 5], [6, 7, 8]],  # R, t, the last row
            [[0, 1], [2]],  # v, w
            {
                "chasles": lambda: chasles_impl("SE2", "se2", scalar=False),
                "gtsam": lambda: gtsam_impl("Pose2", gtsam_pose2),
                "jaxlie": lambda: jaxlie_impl("SE2"),
            },
        ),
        GroupSpec(
            "sim3",
            "Sim3",
            7,
            4,
            sim3_hard,
            sim3_sample,
            sim3_mp_exp,
            sim3_mp_logs,
            [[0, 1, 2, 4, 5, 6, 8, 9, 10], [3, 7, 11], [12, 13, 14, 15]],  # s R, t, the last row
            [[0, 1, 2], [3, 4, 5], [6]],  # v, w, sigma
            {
                "chasles": lambda: chasles_impl("Sim3", "sim3", scalar=False),
                "gtsam": lambda: gtsam_impl(
                    "Similarity3", gtsam_similarity3, [3, 4, 5, 0, 1, 2, 6], chasles_matrix_of_similarity3
                ),
            },
        ),
        GroupSpec(
            "se23",
            "SE23",
            9,
            5,
            se23_hard,
            se23_sample,
            se23_mp_exp,
            se23_mp_logs,
            [[0, 1, 2, 5, 6, 7, 10, 11, 12], [3, 8, 13], [4, 9, 14], list(range(15, 25))],  # R, p, v, rows
            [[0, 1, 2], [3, 4, 5], [6, 7, 8]],  # rho, nu, w
            {
                "chasles": lambda: chasles_impl("SE23", "se23", scalar=False),
                "gtsam": lambda: gtsam_impl("NavState", gtsam_navstate, [6, 7, 8, 0, 1, 2, 3, 4, 5]),
            },
        ),
    )
}


# ---------------------------------------------------------------------------
# Accuracy: references as double-doubles (hi + lo), errors in eps.


def hi_lo(values: Sequence[Any]) -> tuple[np.ndarray, np.ndarray]:
    hi = np.array([float(v) for v in values])
    lo = np.array([float(mpmath.mpf(v) - mpmath.mpf(h)) for v, h in zip(values, hi)])
    return hi, lo


def rel_error(x: np.ndarray, hi: np.ndarray, lo: np.ndarray, blocks: list[list[int]]) -> float:
    """max_i |x_i - ref_i| / max(1, |ref_block(i)|) in eps, |ref_block| the largest
    reference entry of i's block; inf if x has a NaN or an infinity."""
    x = np.asarray(x, dtype=float).reshape(hi.shape)
    if not np.all(np.isfinite(x)):
        return math.inf
    scale = np.ones_like(hi)
    for b in blocks:
        scale[b] = max(1.0, float(np.max(np.abs(hi[b]))))
    return float(np.max(np.abs((x - hi) - lo) / scale)) / EPS


def accuracy_table(specs: list[GroupSpec], impls: dict[str, dict[str, Impl | None]], samples: int) -> None:
    mpmath.mp.dps = MP_DIGITS
    print(f"### Worst error of exp and log (eps = 2^-52, against mpmath at {MP_DIGITS} digits)\n")
    print(
        "Hard inputs and their worst; then the worst over random inputs (angles uniform in (-pi, pi), "
        "translations of size 1e-3 to 1e3, Sim3's sigma uniform in (-3, 3)). Each entry relative to "
        "max(1, |reference|) of its block "
        "(rotation entries and angles absolute, translations relative to the largest reference entry of "
        "the translation); log of the double matrix nearest the exact exp, either branch accepted at "
        "theta = +-pi; exp(log): the exact exp of the returned tangent against the matrix given. NaN: the "
        "output was not finite.\n"
    )
    print("| group | op | contender | worst, hard inputs | at | worst, random inputs |")
    print("| --- | --- | --- | ---: | --- | ---: |")
    for spec in specs:
        hard = spec.hard()
        rng = np.random.default_rng(7)
        labels = [label for label, _ in hard]
        X = np.concatenate([np.array([x for _, x in hard]), spec.sample(rng, samples)])
        n_hard = len(hard)
        exact = [spec.mp_exp(x) for x in X]
        ref_exp = [hi_lo([e for r in m for e in r]) for m in exact]
        M = np.stack([h.reshape(spec.size, spec.size) for h, _ in ref_exp])  # the log inputs
        ref_logs = [[hi_lo(b) for b in spec.mp_logs(m)] for m in M]

        def exp_errors(E: np.ndarray) -> list[float]:
            return [rel_error(E[i], *ref_exp[i], spec.exp_blocks) for i in range(len(X))]

        def log_errors(L: np.ndarray) -> list[float]:
            return [min(rel_error(L[i], h, lo, spec.log_blocks) for h, lo in ref_logs[i]) for i in range(len(X))]

        def roundtrip_errors(L: np.ndarray) -> list[float]:
            """The matrix given against the exact exp of the returned tangent."""
            return [
                rel_error(M[i], *hi_lo([e for r in spec.mp_exp(L[i]) for e in r]), spec.exp_blocks)
                if np.all(np.isfinite(L[i]))
                else math.inf
                for i in range(len(X))
            ]

        for name, impl in impls[spec.key].items():
            if impl is None:
                print(f"| {spec.name} | exp, log | {name} | n/a | | n/a |")
                continue
            for label, (exp_many, log_many) in impl.accuracy.items():
                results: list[tuple[str, Callable[[], list[float]]]] = [
                    ("exp", lambda f=exp_many: exp_errors(np.asarray(f(X), dtype=float).reshape(len(X), -1)))
                ]
                if log_many is not None:
                    logs: list[np.ndarray] = []  # log_many(M), computed once for both rows

                    def log_of_m(f: ManyFn = log_many, memo: list[np.ndarray] = logs) -> np.ndarray:
                        if not memo:
                            memo.append(np.asarray(f(M), dtype=float).reshape(len(M), spec.dim))
                        return memo[0]

                    results.append(("log", lambda g=log_of_m: log_errors(g())))
                    results.append(("exp(log)", lambda g=log_of_m: roundtrip_errors(g())))
                for op, errors_fn in results:
                    try:
                        errs = np.array(errors_fn())
                    except Exception as e:  # noqa: BLE001 - a peer's API drift must not stop the run
                        print(f"<!-- {label} {spec.name} {op} skipped: {e!r} -->", file=sys.stderr)
                        print(f"| {spec.name} | {op} | {label} | failed | | |")
                        continue
                    worst = int(np.argmax(errs[:n_hard]))
                    print(
                        f"| {spec.name} | {op} | {label} | {err_cell(errs[worst])} | {labels[worst]} | "
                        f"{err_cell(errs[n_hard:].max()) if len(errs) > n_hard else ''} |"
                    )
    print()


def err_cell(e: float) -> str:
    return "NaN" if not math.isfinite(e) else f"{e:.2g}"


# ---------------------------------------------------------------------------


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--rounds", "--repeats", type=int, default=7, help="rounds; each contender keeps its best")
    ap.add_argument("--sizes", type=int, nargs="+", default=[100_000], help="batch sizes N")
    ap.add_argument("--groups", nargs="+", choices=list(GROUPS), default=list(GROUPS))
    ap.add_argument("--loop-size", type=int, default=10_000, help="elements of the Python loops (gtsam) at most")
    ap.add_argument("--samples", type=int, default=1000, help="random inputs of the accuracy table")
    ap.add_argument("--budget", type=float, default=0.02, help="seconds of one contender in one round")
    ap.add_argument("--no-accuracy", action="store_true", help="skip the accuracy table")
    args = ap.parse_args()
    specs = [GROUPS[k] for k in args.groups]

    ours = version("chasles", chasles)
    threads = f", {chasles.get_num_threads()} threads" if hasattr(chasles, "get_num_threads") else ""
    backend = f", {jax.default_backend()}, float64" if jax is not None else ""
    print(
        f"chasles {ours}{threads}, gtsam {version('gtsam', gtsam)}, jaxlie {version('jaxlie', jaxlie)} "
        f"(jax {version('jax', jax)}, jaxlib {version('jaxlib', optional('jaxlib'))}{backend}), "
        f"numpy {np.__version__}, mpmath {version('mpmath', mpmath)}, Python {sys.version.split()[0]}\n"
    )

    impls: dict[str, dict[str, Impl | None]] = {}
    for spec in specs:
        impls[spec.key] = {}
        for name, build in spec.contenders.items():
            try:
                impls[spec.key][name] = build()
            except Exception as e:  # noqa: BLE001 - a peer's API drift must not stop the run
                print(f"<!-- {name} {spec.name} skipped: {e!r} -->", file=sys.stderr)
                impls[spec.key][name] = None
    names = list(dict.fromkeys(n for spec in specs for n in spec.contenders))
    rng = np.random.default_rng(1)

    def cells(times: dict[str, float | None], present: dict[str, Impl | None], scale: float) -> str:
        return " | ".join(
            "n/a" if present.get(n) is None else (fig(times[n] * scale) if times.get(n) is not None else "failed")
            for n in names
        )

    # ---- per call --------------------------------------------------------------
    print(f"### Per call, one element (us, best of {args.rounds} rounds)\n")
    print("jaxlie: jax.jit of each operation, compiled before the rounds, its output blocked on.\n")
    print("| op | " + " | ".join(names) + " | ratio chasles / best peer |")
    print("| --- | " + " | ".join("---:" for _ in names) + " | ---: |")
    for spec in specs:
        x1, x2 = spec.sample(rng, 2)
        present = impls[spec.key]
        thunks: dict[str, dict[str, Thunk]] = {}
        for name, impl in present.items():
            try:
                thunks[name] = impl.calls(x1, x2) if impl else {}
            except Exception as e:  # noqa: BLE001 - a peer's API drift must not stop the run
                print(f"<!-- {name} {spec.name} calls skipped: {e!r} -->", file=sys.stderr)
                thunks[name] = {}
        for op in OPS:
            times = interleaved({n: thunks.get(n, {}).get(op) for n in names}, args.rounds, args.budget)
            print(f"| {spec.name} {op} | {cells(times, present, 1e6)} | {ratio_cell(times)} |")
    print()

    # ---- batches ---------------------------------------------------------------
    for n in args.sizes:
        loop_n = min(n, args.loop_size)
        print(f"### Batches, N = {n:.0e}, per element (ns, best of {args.rounds} rounds)\n")
        print(
            "chasles: its array functions (numpy gufuncs) on N matrices; jaxlie: jax.jit(jax.vmap(op)) on its "
            f"own storage of N elements (compiled for N before the rounds); gtsam: a Python loop (a list "
            f"comprehension) over {loop_n:.0e} of its objects{'' if loop_n == n else ', not N'}.\n"
        )
        print("| op | " + " | ".join(names) + " | ratio chasles / best peer |")
        print("| --- | " + " | ".join("---:" for _ in names) + " | ---: |")
        for spec in specs:
            X1, X2 = spec.sample(rng, n), spec.sample(rng, n)
            present = impls[spec.key]
            thunks, counts = {}, {}
            for name, impl in present.items():
                if impl is None:
                    continue
                k = loop_n if impl.loop else n
                try:
                    thunks[name], counts[name] = impl.batch(X1[:k], X2[:k]), k
                except Exception as e:  # noqa: BLE001 - a peer's API drift must not stop the run
                    print(f"<!-- {name} {spec.name} batch skipped: {e!r} -->", file=sys.stderr)
            for op in OPS:
                times = interleaved(
                    {name: thunks.get(name, {}).get(op) for name in names}, args.rounds, max(args.budget, 0.05)
                )
                times = {name: (t / counts[name] if t is not None else None) for name, t in times.items()}
                print(f"| {spec.name} {op} | {cells(times, present, 1e9)} | {ratio_cell(times)} |")
            del thunks
        print()

    # ---- accuracy --------------------------------------------------------------
    if args.no_accuracy:
        return 0
    if mpmath is None:
        print("(mpmath absent: no accuracy table)\n")
        return 0
    accuracy_table(specs, impls, args.samples)
    return 0


if __name__ == "__main__":
    sys.exit(main())
