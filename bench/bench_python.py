#!/usr/bin/env python3
"""Python benchmarks of chasles beside the peers a Python user has, in one run.

    python bench/bench_python.py [--repeats 7] [--sizes 100000 1000000] [--splines-only] [--align-only]

Needs chasles (pip install .) and numpy; scipy, pin (Pinocchio),
pytransform3d and modern_robotics are measured when installed and skipped
otherwise. Prints markdown tables: per-call latency of the object API
(microseconds), per-element time of the array functions (nanoseconds) at
each N, and the kinematics of a UR5 and a 7-joint arm per configuration
(chasles.Chain batched over N joint vectors, and per call), with the ratio of
chasles to the best peer measured in the same run (< 1: chasles is faster)
and the target of the benchmark issue. Every figure is the median of
--repeats timings.
"""

from __future__ import annotations

import argparse
import importlib
import statistics
import sys
import time
from collections.abc import Callable
from typing import Any

import numpy as np

import chasles

# Targets of the speed issues (double precision): every SO3 and SE3 object
# operation per call, and the array functions per element.
CALL_TARGET_US = 0.13
ARRAY_TARGET_NS = {
    "SO3 exp": 25,
    "SO3 log": 30,
    "SE3 exp": 45,
    "SE3 log": 60,
    "SE3 compose": 15,
    "SE3 act (1 pose, N points)": 5,
}


def optional(name: str) -> Any:
    try:
        return importlib.import_module(name)
    except Exception:  # noqa: BLE001 - any failure to import means "not available"
        return None


def median_time(fn: Callable[[], object], repeats: int, budget: float = 0.05) -> float:
    """Median seconds per call of fn, each repeat running about `budget` seconds."""
    fn()  # warm up (and fail here, not in the loop)
    number = 1
    while True:
        t0 = time.perf_counter()
        for _ in range(number):
            fn()
        dt = time.perf_counter() - t0
        if dt > budget / 4 or number > 1 << 24:
            break
        number *= 4
    number = max(1, int(number * budget / max(dt, 1e-9)))
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        for _ in range(number):
            fn()
        times.append((time.perf_counter() - t0) / number)
    return statistics.median(times)


def measure(fn: Callable[[], object] | None, repeats: int, budget: float = 0.05) -> float | None:
    """As median_time, or None when the peer lacks the operation (or fails on it)."""
    if fn is None:
        return None
    try:
        return median_time(fn, repeats, budget)
    except Exception as e:  # noqa: BLE001 - a peer's API drift must not stop the run
        print(f"<!-- skipped: {e!r} -->", file=sys.stderr)
        return None


def row(op: str, ours: float | None, peers: dict[str, float | None], scale: float, target: float | None) -> str:
    cells = [f"{t * scale:.3g}" if t is not None else "" for t in peers.values()]
    present = [(t, name) for name, t in peers.items() if t is not None]
    best = min(present) if present else None
    ratio = f"{ours / best[0]:.2f} ({best[1]})" if best and ours else ""
    return "| {} | {} | {} | {} | {} |".format(
        op, f"{ours * scale:.3g}" if ours else "", " | ".join(cells), ratio, f"{target:g}" if target else ""
    )


# ---------------------------------------------------------------------------
# Numpy by hand: what a user writes without a library.


def np_so3_exp(w: np.ndarray) -> np.ndarray:
    """Vectorized Rodrigues: R = I + sin(t)/t [w] + (1 - cos(t))/t^2 [w]^2."""
    t = np.linalg.norm(w, axis=-1)[..., None, None]
    K = np.zeros(w.shape[:-1] + (3, 3))
    K[..., 0, 1], K[..., 0, 2], K[..., 1, 2] = -w[..., 2], w[..., 1], -w[..., 0]
    K[..., 1, 0], K[..., 2, 0], K[..., 2, 1] = w[..., 2], -w[..., 1], w[..., 0]
    with np.errstate(invalid="ignore", divide="ignore"):
        a = np.where(t > 0, np.sin(t) / t, 1.0)
        b = np.where(t > 0, (1 - np.cos(t)) / t**2, 0.5)
    return np.eye(3) + a * K + b * (K @ K)


def np_so3_log(R: np.ndarray) -> np.ndarray:
    """The textbook log: theta = arccos((tr R - 1)/2), w = theta / (2 sin theta) vee(R - R^T).
    (Loses half the digits near 0 and fails near pi: what the accuracy contract avoids.)"""
    c = np.clip((np.trace(R, axis1=-2, axis2=-1) - 1) / 2, -1, 1)
    t = np.arccos(c)
    s = np.stack([R[..., 2, 1] - R[..., 1, 2], R[..., 0, 2] - R[..., 2, 0], R[..., 1, 0] - R[..., 0, 1]], -1)
    with np.errstate(invalid="ignore", divide="ignore"):
        f = np.where(t > 1e-8, t / (2 * np.sin(t)), 0.5)
    return f[..., None] * s


# ---------------------------------------------------------------------------
# Kinematics: a UR5 (Modern Robotics, example 4.5; the screws of
# tests/python/test_kinematics.py) and the same arm on a linear rail (7 joints).

_W1, _W2, _L1, _L2, _H1, _H2 = 0.109, 0.082, 0.425, 0.392, 0.089, 0.095
# Space screws (v, w), one row per joint (Modern Robotics lists (w, v)).
UR5_SCREWS = np.array(
    [
        [0, 0, 0, 0, 0, 1],
        [-_H1, 0, 0, 0, 1, 0],
        [-_H1, 0, _L1, 0, 1, 0],
        [-_H1, 0, _L1 + _L2, 0, 1, 0],
        [-_W1, _L1 + _L2, 0, 0, 0, -1],
        [_H2 - _H1, 0, _L1 + _L2, 0, 1, 0],
    ],
    dtype=float,
)
UR5_HOME = np.array([[-1, 0, 0, _L1 + _L2], [0, 0, 1, _W1 + _W2], [0, 1, 0, _H1 - _H2], [0, 0, 0, 1]], dtype=float)
RAIL_SCREWS = np.vstack([[1 / np.sqrt(5), 2 / np.sqrt(5), 0, 0, 0, 0], UR5_SCREWS])
CHAIN_N = 10_000


def np_hat6(xi: np.ndarray) -> np.ndarray:
    v, w = xi[:3], xi[3:]
    return np.array([[0, -w[2], w[1], v[0]], [w[2], 0, -w[0], v[1]], [-w[1], w[0], 0, v[2]], [0, 0, 0, 0]])


def np_act_jacobian(g: np.ndarray, P: np.ndarray) -> np.ndarray:
    """d(g p)/dg = [R, -R [p]] for many points, in numpy (the peer of se3_act_jacobian)."""
    R = g[:3, :3]
    H = np.zeros((len(P), 3, 3))
    H[:, 0, 1], H[:, 0, 2], H[:, 1, 2] = -P[:, 2], P[:, 1], -P[:, 0]
    H[:, 1, 0], H[:, 2, 0], H[:, 2, 1] = P[:, 2], -P[:, 1], P[:, 0]
    J = np.empty((len(P), 3, 6))
    J[:, :, :3] = R
    J[:, :, 3:] = -(R @ H)
    return J


def np_adjoint(g: np.ndarray) -> np.ndarray:
    """Ad_g = [[R, [p] R], [0, R]] for twists (v, w)."""
    R, p = g[:3, :3], g[:3, 3]
    P = np.array([[0, -p[2], p[1]], [p[2], 0, -p[0]], [-p[1], p[0], 0]])
    A = np.zeros((6, 6))
    A[:3, :3] = A[3:, 3:] = R
    A[:3, 3:] = P @ R
    return A


def expm_forward(
    expm: Callable[[np.ndarray], np.ndarray], screws: np.ndarray, home: np.ndarray, theta: np.ndarray
) -> np.ndarray:
    """The naive product of exponentials: a loop of scipy.linalg.expm of 4x4 hat matrices."""
    g = np.eye(4)
    for s, t in zip(screws, theta):
        g = g @ expm(np_hat6(s * t))
    return g @ home


def expm_jacobian_space(expm: Callable[[np.ndarray], np.ndarray], screws: np.ndarray, theta: np.ndarray) -> np.ndarray:
    J = np.empty((6, len(screws)))
    g = np.eye(4)
    for i, (s, t) in enumerate(zip(screws, theta)):
        J[:, i] = np_adjoint(g) @ s
        g = g @ expm(np_hat6(s * t))
    return J


def fig(x: float) -> str:
    """Three significant digits, without an exponent up to 1e6."""
    return f"{x:.3g}" if x < 1000 else f"{x:.0f}"


def kinematics_table(rep: int) -> None:
    """chasles.Chain against modern_robotics and scipy.linalg.expm, per configuration."""
    mr = optional("modern_robotics")
    expm = getattr(optional("scipy.linalg"), "expm", None)
    rng = np.random.default_rng(2)
    peer_names = ["modern_robotics", "numpy + scipy expm"]
    print(f"### Python kinematics, per configuration (median of {rep})\n")
    print(
        f"chasles batched over N = {CHAIN_N} joint vectors (ns per configuration) and per call for one "
        "configuration (us). The peers have no batch form: a loop over N costs N of their calls, so their "
        "per-call figure is also their per-configuration cost (1 us = 1000 ns). Ratios: chasles per call, "
        "and chasles batched, to the best peer's call (< 1: chasles is faster).\n"
    )
    print(
        "| arm | op | chasles batch ns | chasles call us | "
        + " | ".join(f"{n} call us" for n in peer_names)
        + " | ratio per call | ratio batch |"
    )
    print("| --- | --- | ---: | ---: | " + " | ".join("---:" for _ in peer_names) + " | ---: | ---: |")
    for arm_name, screws in (("UR5 (6 joints)", UR5_SCREWS), ("UR5 on a rail (7 joints)", RAIL_SCREWS)):
        n = len(screws)
        arm = chasles.Chain(screws, UR5_HOME)
        TH = rng.uniform(-np.pi, np.pi, size=(CHAIN_N, n))
        th = TH[0].copy()
        # Modern Robotics: screw axes as columns (w, v).
        Slist = np.concatenate([screws[:, 3:], screws[:, :3]], axis=1).T.copy()
        if mr is not None:  # same pose, and the same Jacobian up to the (w, v) order of its rows
            try:
                assert np.allclose(mr.FKinSpace(UR5_HOME, Slist, th), arm.forward(th), atol=1e-9)
                Jmr = mr.JacobianSpace(Slist, th)
                assert np.allclose(np.vstack([Jmr[3:], Jmr[:3]]), arm.jacobian_space(th), atol=1e-9)
            except Exception as e:  # noqa: BLE001 - a peer's API drift must not stop the run
                print(f"<!-- modern_robotics skipped: {e!r} -->", file=sys.stderr)
                mr = None
        if expm is not None:
            assert np.allclose(expm_forward(expm, screws, UR5_HOME, th), arm.forward(th), atol=1e-9)
            assert np.allclose(expm_jacobian_space(expm, screws, th), arm.jacobian_space(th), atol=1e-9)
        ops = {
            "forward": (
                lambda: arm.forward(TH),
                lambda: arm.forward(th),
                {
                    "modern_robotics": (lambda: mr.FKinSpace(UR5_HOME, Slist, th)) if mr else None,
                    "numpy + scipy expm": (lambda: expm_forward(expm, screws, UR5_HOME, th)) if expm else None,
                },
            ),
            "jacobian_space": (
                lambda: arm.jacobian_space(TH),
                lambda: arm.jacobian_space(th),
                {
                    "modern_robotics": (lambda: mr.JacobianSpace(Slist, th)) if mr else None,
                    "numpy + scipy expm": (lambda: expm_jacobian_space(expm, screws, th)) if expm else None,
                },
            ),
        }
        for op, (batch, call, peer_fns) in ops.items():
            ours_batch = measure(batch, rep, 0.2)
            ours_call = measure(call, rep)
            peers = {k: measure(peer_fns.get(k), rep) for k in peer_names}
            present = [(t, k) for k, t in peers.items() if t is not None]
            best = min(present) if present else None
            cells = [fig(peers[k] * 1e6) if peers[k] is not None else "" for k in peer_names]
            r_call = f"{ours_call / best[0]:.3g} ({best[1]})" if best and ours_call else ""
            r_batch = f"{ours_batch / CHAIN_N / best[0]:.3g} ({best[1]})" if best and ours_batch else ""
            print(
                f"| {arm_name} | {op} | {fig(ours_batch / CHAIN_N * 1e9)} | {fig(ours_call * 1e6)} | "
                + " | ".join(cells)
                + f" | {r_call} | {r_batch} |"
            )
    print()


THREADS_TARGET_SPEEDUP = 1.7  # 2 threads against 1 at N = 1e6 (the speed issue)
ONE_THREAD_TARGET_NS = {"SO3 exp": 15, "SE3 exp": 22}  # per element at N = 1e5, one thread


def threads_table(rep: int) -> None:
    """set_num_threads: per element on 1 and 2 threads (N = 1e5 and 1e6),
    the speedup, and at N = 2 grains (32768: the smallest batch split) that
    the split does not cost more than it gains."""
    rng = np.random.default_rng(3)
    before = chasles.get_num_threads()
    print(f"### Python array functions on threads (set_num_threads; ns per element, median of {rep})\n")
    print("| op | N | 1 thread | 2 threads | speedup | target speedup | target ns (1 thread) |")
    print("| --- | ---: | ---: | ---: | ---: | ---: | ---: |")
    for n in (32_768, 100_000, 1_000_000):
        W = rng.normal(size=(n, 3))
        XI = np.concatenate([rng.normal(size=(n, 3)), W], axis=1)
        Rs, Gs = chasles.so3_exp(W), chasles.se3_exp(XI)
        ops = {
            "SO3 exp": lambda: chasles.so3_exp(W),
            "SO3 log": lambda: chasles.so3_log(Rs),
            "SE3 exp": lambda: chasles.se3_exp(XI),
            "SE3 log": lambda: chasles.se3_log(Gs),
            "SE3 compose": lambda: chasles.se3_compose(Gs, Gs),
        }
        for op, fn in ops.items():
            times = []
            for k in (1, 2):
                chasles.set_num_threads(k)
                times.append(median_time(fn, rep, 0.2) / n)
            chasles.set_num_threads(before)
            target = ONE_THREAD_TARGET_NS.get(op, "") if n == 100_000 else ""
            speedup_target = THREADS_TARGET_SPEEDUP if n == 1_000_000 and op != "SE3 compose" else ""
            print(
                f"| {op} | {n:.0e} | {times[0] * 1e9:.3g} | {times[1] * 1e9:.3g} | {times[0] / times[1]:.2f} | "
                f"{speedup_target} | {target} |"
            )
    print()


def spline_keys_table(rep: int, keys: list[int]) -> None:
    """One evaluation (one time per call) of each spline against its number of
    keys / control elements: a binary search plus O(1) work, flat in N."""
    print(f"### Python spline evaluation, one time per call, against the number of keys (us, median of {rep})\n")
    print("| op | " + " | ".join(f"{n:.0e} keys" for n in keys) + " |")
    print("| --- |" + " ---: |" * len(keys))
    rng = np.random.default_rng(11)
    rows: dict[str, list[str]] = {}
    for n in keys:
        t = np.cumsum(rng.uniform(0.3, 1.0, n))
        steps = rng.normal(scale=0.35, size=(n, 6))
        R = chasles.so3_exp(np.cumsum(steps[:, 3:], axis=0))
        G = chasles.se3_exp(np.cumsum(steps, axis=0))
        s3, s6 = chasles.SO3Spline(t, R), chasles.SE3Spline(t, G)
        b3, b6 = chasles.SO3BSpline(0.0, 1.0, R), chasles.SE3BSpline(0.0, 1.0, G)
        x, xb = float(t[n // 3] + 0.1), (n - 3) / 3 + 0.1
        for op, fn in (
            ("SO3Spline(t)", lambda: s3(x)),
            ("SO3Spline.body_acceleration(t)", lambda: s3.body_acceleration(x)),
            ("SE3Spline(t)", lambda: s6(x)),
            ("SE3Spline.body_acceleration(t)", lambda: s6.body_acceleration(x)),
            ("SO3BSpline(t)", lambda: b3(xb)),
            ("SE3BSpline.body_acceleration(t)", lambda: b6.body_acceleration(xb)),
        ):
            rows.setdefault(op, []).append(fig(median_time(fn, rep) * 1e6))
    for op, cells in rows.items():
        print(f"| {op} | " + " | ".join(cells) + " |")
    print()


def np_umeyama(a: np.ndarray, b: np.ndarray, scale: bool) -> np.ndarray:
    """Kabsch / Umeyama by numpy's SVD, as a user writes them: g with a ~ g b."""
    ma, mb = a.mean(axis=0), b.mean(axis=0)
    U, d, Vt = np.linalg.svd((a - ma).T @ (b - mb))
    S = np.array([1.0, 1.0, np.sign(np.linalg.det(U @ Vt))])
    R = (U * S) @ Vt
    c = (d @ S) / np.sum((b - mb) ** 2) if scale else 1.0
    g = np.eye(4)
    g[:3, :3] = c * R
    g[:3, 3] = ma - c * R @ mb
    return g


def align_table(rep: int, sizes: tuple[int, ...] = (10, 1_000, 100_000)) -> None:
    """so3_align beside scipy's Rotation.align_vectors (with its sensitivity,
    which so3_align returns too), se3_align and sim3_align beside Kabsch and
    Umeyama in numpy: microseconds per call at each N, interleaved rounds, the
    best round of each kept (bench_groups.interleaved)."""
    from bench_groups import interleaved

    Rotation = getattr(optional("scipy.spatial.transform"), "Rotation", None)
    rng = np.random.default_rng(3)
    print(f"### Alignment of N vectors / points, per call (us, best of {rep} interleaved rounds)\n")
    print("| op | N | chasles | scipy | numpy | ratio to best peer |")
    print("| --- | ---: | ---: | ---: | ---: | ---: |")
    for n in sizes:
        b = rng.normal(size=(n, 3)) * [3.0, 2.0, 1.0]
        a = chasles.se3_act(chasles.se3_exp(rng.normal(size=6)), b) + 0.01 * rng.normal(size=(n, 3))
        rows = {
            "so3_align / align_vectors": {
                "chasles": lambda: chasles.so3_align(a, b),
                "scipy": (lambda: Rotation.align_vectors(a, b, return_sensitivity=True)) if Rotation else None,
                "numpy": None,
            },
            "se3_align / Kabsch": {
                "chasles": lambda: chasles.se3_align(a, b),
                "scipy": None,
                "numpy": lambda: np_umeyama(a, b, False),
            },
            "sim3_align / Umeyama": {
                "chasles": lambda: chasles.sim3_align(a, b),
                "scipy": None,
                "numpy": lambda: np_umeyama(a, b, True),
            },
        }
        for op, fns in rows.items():
            t = interleaved(fns, rep, 0.05)
            peers = [(v, k) for k, v in t.items() if k != "chasles" and v is not None]
            best = min(peers) if peers else None
            ratio = f"{t['chasles'] / best[0]:.3g} ({best[1]})" if best else ""
            cells = " | ".join(fig(v * 1e6) if v is not None else "" for v in t.values())
            print(f"| {op} | {n} | {cells} | {ratio} |")
    print()


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--repeats", type=int, default=7)
    ap.add_argument("--sizes", type=int, nargs="+", default=[100_000, 1_000_000])
    ap.add_argument(
        "--spline-keys",
        type=int,
        nargs="+",
        default=[10, 1_000, 100_000, 1_000_000],
        help="the numbers of keys of the spline evaluation table",
    )
    ap.add_argument("--splines-only", action="store_true", help="only the spline evaluation table")
    ap.add_argument("--align-only", action="store_true", help="only the alignment table")
    args = ap.parse_args()
    rep = args.repeats
    if args.splines_only:
        spline_keys_table(rep, args.spline_keys)
        return 0
    if args.align_only:
        align_table(rep)
        return 0

    scipy_rot = optional("scipy.spatial.transform")
    Rotation = getattr(scipy_rot, "Rotation", None)
    RigidTransform = getattr(scipy_rot, "RigidTransform", None)  # scipy >= 1.16
    RotationSpline = getattr(scipy_rot, "RotationSpline", None)
    pin = optional("pinocchio")
    pt3r = optional("pytransform3d.rotations")
    pt3t = optional("pytransform3d.transformations")
    pt3b = optional("pytransform3d.batch_rotations")
    pt3j = optional("pytransform3d.trajectories")
    scipy_version = getattr(optional("scipy"), "__version__", None)
    print(
        f"chasles {chasles.__version__}, numpy {np.__version__}, scipy {scipy_version or 'absent'}, "
        f"pinocchio {getattr(pin, '__version__', 'absent')}, "
        f"pytransform3d {getattr(optional('pytransform3d'), '__version__', 'absent')}, "
        f"modern_robotics {getattr(optional('modern_robotics'), '__version__', 'absent')}, "
        f"Python {sys.version.split()[0]}\n"
    )

    rng = np.random.default_rng(1)
    w = rng.normal(size=3)
    w *= 1.3 / np.linalg.norm(w)
    xi = np.concatenate([rng.normal(size=3), w])  # (v, w)
    p = rng.normal(size=3)
    R, R2 = chasles.SO3.exp(w), chasles.SO3.exp(0.7 * w[::-1])
    g, g2 = chasles.SE3.exp(xi), chasles.SE3.exp(0.5 * xi[::-1])
    Rm, gm = R.as_matrix(), g.as_matrix()

    # ---- per call -----------------------------------------------------------
    peers_call: dict[str, dict[str, Callable[[], object] | None]] = {}
    sr = Rotation.from_rotvec(w) if Rotation else None
    sr2 = Rotation.from_rotvec(0.7 * w[::-1]) if Rotation else None
    st = RigidTransform.from_exp_coords(np.concatenate([w, xi[:3]])) if RigidTransform else None
    st2 = (
        RigidTransform.from_exp_coords(np.concatenate([0.5 * xi[::-1][3:], 0.5 * xi[::-1][:3]]))
        if RigidTransform
        else None
    )
    pR, pR2 = (pin.exp3(w), pin.exp3(0.7 * w[::-1])) if pin else (None, None)
    pg = pin.exp6(pin.Motion(xi[:3], xi[3:])) if pin else None
    pg2 = pin.exp6(pin.Motion(0.5 * xi[::-1][:3], 0.5 * xi[::-1][3:])) if pin else None
    S6 = np.concatenate([w, xi[:3]])  # pytransform3d's exponential coordinates: (omega, v)
    T2 = gm @ gm

    peers_call["SO3 exp"] = {
        "scipy": (lambda: Rotation.from_rotvec(w).as_matrix()) if Rotation else None,
        "pin": (lambda: pin.exp3(w)) if pin else None,
        "pytransform3d": (lambda: pt3r.matrix_from_compact_axis_angle(w)) if pt3r else None,
    }
    peers_call["SO3 log"] = {
        "scipy": (lambda: Rotation.from_matrix(Rm).as_rotvec()) if Rotation else None,
        "pin": (lambda: pin.log3(Rm)) if pin else None,
        "pytransform3d": (lambda: pt3r.compact_axis_angle_from_matrix(Rm)) if pt3r else None,
    }
    peers_call["SO3 compose"] = {
        "scipy": (lambda: sr * sr2) if Rotation else None,
        "pin": (lambda: pR @ pR2) if pin else None,
        "pytransform3d": None,
    }
    peers_call["SO3 inverse"] = {
        "scipy": (lambda: sr.inv()) if Rotation else None,
        "pin": (lambda: pR.T) if pin else None,
        "pytransform3d": None,
    }
    peers_call["SO3 act"] = {
        "scipy": (lambda: sr.apply(p)) if Rotation else None,
        "pin": (lambda: pR @ p) if pin else None,
        "pytransform3d": None,
    }
    peers_call["SE3 exp"] = {
        "scipy": (lambda: RigidTransform.from_exp_coords(S6)) if RigidTransform else None,
        "pin": (lambda: pin.exp6(xi)) if pin else None,
        "pytransform3d": (lambda: pt3t.transform_from_exponential_coordinates(S6)) if pt3t else None,
    }
    peers_call["SE3 log"] = {
        "scipy": (lambda: st.as_exp_coords()) if RigidTransform else None,
        "pin": (lambda: pin.log6(gm)) if pin else None,
        "pytransform3d": (lambda: pt3t.exponential_coordinates_from_transform(gm)) if pt3t else None,
    }
    peers_call["SE3 compose"] = {
        "scipy": (lambda: st * st2) if RigidTransform else None,
        "pin": (lambda: pg * pg2) if pin else None,
        "pytransform3d": (lambda: pt3t.concat(gm, T2)) if pt3t else None,
    }
    peers_call["SE3 inverse"] = {
        "scipy": (lambda: st.inv()) if RigidTransform else None,
        "pin": (lambda: pg.inverse()) if pin else None,
        "pytransform3d": (lambda: pt3t.invert_transform(gm)) if pt3t else None,
    }
    peers_call["SE3 act"] = {
        "scipy": (lambda: st.apply(p)) if RigidTransform else None,
        "pin": (lambda: pg.act(p)) if pin else None,
        "pytransform3d": (lambda: pt3t.transform(gm, np.append(p, 1.0))) if pt3t else None,
    }
    peers_call["SE3 adjoint"] = {
        "scipy": None,
        "pin": (lambda: pg.action) if pin else None,
        "pytransform3d": (lambda: pt3t.adjoint_from_transform(gm)) if pt3t else None,
    }
    eul = R.as_euler("xyz")
    peers_call["SO3 from_euler"] = {
        "scipy": (lambda: Rotation.from_euler("xyz", eul).as_matrix()) if Rotation else None,
        "pin": (lambda: pin.rpy.rpyToMatrix(eul)) if pin else None,
        "pytransform3d": None,
    }
    peers_call["SO3 as_euler"] = {
        "scipy": (lambda: sr.as_euler("xyz")) if Rotation else None,
        "pin": (lambda: pin.rpy.matrixToRpy(pR)) if pin else None,
        "pytransform3d": None,
    }
    # B-splines: 64 control elements (random steps), one time per call
    bs_rng = np.random.default_rng(5)
    bs_so3 = chasles.SO3BSpline(0.0, 1.0, chasles.so3_exp(np.cumsum(0.3 * bs_rng.normal(size=(64, 3)), axis=0)))
    bs_se3 = chasles.SE3BSpline(0.0, 1.0, chasles.se3_exp(np.cumsum(0.3 * bs_rng.normal(size=(64, 6)), axis=0)))
    for op in ("SO3 B-spline value", "SO3 B-spline velocity", "SE3 B-spline value", "SE3 B-spline acceleration"):
        peers_call[op] = {"scipy": None, "pin": None, "pytransform3d": None}
    # The floors: a method that returns a new object and does no math, on
    # SE3 (its value built inside the Python object, bindings/instance.hpp),
    # and on Screw, which keeps pybind11's own instance path (the value
    # allocated with operator new, the instance registered in pybind11's map).
    screw = chasles.Screw([0.0, 0.0, 1.0], [0.0, 0.0, 0.0], 0.5, 1.0)
    peers_call["floor: new SE3, no math"] = {
        "scipy": None,
        "pin": (lambda: pg.copy()) if pin else None,
        "pytransform3d": None,
    }
    peers_call["floor: pybind11's own path"] = {"scipy": None, "pin": None, "pytransform3d": None}
    ours_call: dict[str, Callable[[], object]] = {
        "SO3 B-spline value": lambda: bs_so3(30.3),
        "SO3 B-spline velocity": lambda: bs_so3.body_velocity(30.3),
        "SE3 B-spline value": lambda: bs_se3(30.3),
        "SE3 B-spline acceleration": lambda: bs_se3.body_acceleration(30.3),
        "SO3 exp": lambda: chasles.SO3.exp(w),
        "SO3 log": lambda: R.log(),
        "SO3 compose": lambda: R @ R2,
        "SO3 inverse": lambda: R.inverse(),
        "SO3 act": lambda: R @ p,
        "SE3 exp": lambda: chasles.SE3.exp(xi),
        "SE3 log": lambda: g.log(),
        "SE3 compose": lambda: g @ g2,
        "SE3 inverse": lambda: g.inverse(),
        "SE3 act": lambda: g @ p,
        "SE3 adjoint": lambda: g.adjoint(),
        "SO3 from_euler": lambda: chasles.SO3.from_euler("xyz", eul),
        "SO3 as_euler": lambda: R.as_euler("xyz"),
        "floor: new SE3, no math": lambda: g.__copy__(),
        "floor: pybind11's own path": lambda: screw.__copy__(),
    }
    names = ["scipy", "pin", "pytransform3d"]
    # The harness's own cost per call (the loop and the call of a lambda),
    # measured the same way and subtracted from every figure, chasles' and
    # the peers': what remains is what the call costs in a user's code.
    harness = median_time(lambda: None, rep)
    print(f"### Python objects, per call (us, median of {rep})\n")
    print(
        f"Each figure less the harness's own cost per call (a loop calling an empty lambda), "
        f"{harness * 1e9:.0f} ns in this run.\n"
    )
    print("| op | chasles | " + " | ".join(names) + " | ratio to best peer | target us |")
    print("| --- | ---: | " + " | ".join("---:" for _ in names) + " | ---: | ---: |")

    def net(t: float | None) -> float | None:
        return None if t is None else t - harness

    for op, fn in ours_call.items():
        ours = net(measure(fn, rep))
        peers = {n: net(measure(peers_call[op].get(n), rep)) for n in names}
        group_op = op.startswith(("SO3 ", "SE3 ")) and "B-spline" not in op
        print(row(op, ours, peers, 1e6, CALL_TARGET_US if group_op else None))
    print()

    # ---- arrays -------------------------------------------------------------
    for n in args.sizes:
        W = rng.normal(size=(n, 3))
        W *= (rng.uniform(0.1, 3.0, size=n) / np.linalg.norm(W, axis=1))[:, None]
        XI = np.concatenate([rng.normal(size=(n, 3)), W], axis=1)
        Rs = chasles.so3_exp(W)
        Gs = chasles.se3_exp(XI)
        Gs2 = chasles.se3_exp(XI[::-1].copy())
        P = rng.normal(size=(n, 3))
        S6s = np.concatenate([W, XI[:, :3]], axis=1)
        srs = Rotation.from_matrix(Rs) if Rotation else None
        Rc = chasles.so3_exp(0.5 * rng.normal(size=(n, 3)))  # a cloud for the means (0.87 rad rms)
        TB = rng.uniform(0.0, 61.0, size=n)  # times on the 64-element B-splines
        E = chasles.so3_as_euler("xyz", Rs)
        sts = RigidTransform.from_matrix(Gs) if RigidTransform else None
        sts2 = RigidTransform.from_matrix(Gs2) if RigidTransform else None
        st1 = RigidTransform.from_matrix(gm) if RigidTransform else None
        # splines through 100 keys (steps ~0.6 rad, 0.3 to 1 s apart), evaluated at n times inside their range
        key_t = np.cumsum(rng.uniform(0.3, 1.0, 100))
        key_R = chasles.so3_compose(
            chasles.so3_exp(rng.normal(size=3)),
            chasles.so3_exp(np.cumsum(rng.normal(scale=0.35, size=(100, 3)), axis=0)),
        )
        key_G = chasles.se3_exp(np.cumsum(rng.normal(scale=0.35, size=(100, 6)), axis=0))
        spline_so3, spline_se3 = chasles.SO3Spline(key_t, key_R), chasles.SE3Spline(key_t, key_G)
        spline_scipy = RotationSpline(key_t, Rotation.from_matrix(key_R)) if RotationSpline else None
        ts = rng.uniform(key_t[0], key_t[-1], n)
        ops: dict[str, tuple[Callable[[], object], dict[str, Callable[[], object] | None]]] = {
            "SO3 exp": (
                lambda: chasles.so3_exp(W),
                {
                    "scipy": (lambda: Rotation.from_rotvec(W).as_matrix()) if Rotation else None,
                    "numpy": lambda: np_so3_exp(W),
                    "pytransform3d": (lambda: pt3b.matrices_from_compact_axis_angles(W)) if pt3b else None,
                },
            ),
            "SO3 log": (
                lambda: chasles.so3_log(Rs),
                {
                    "scipy": (lambda: Rotation.from_matrix(Rs).as_rotvec()) if Rotation else None,
                    "numpy": lambda: np_so3_log(Rs),
                    "pytransform3d": (lambda: pt3b.axis_angles_from_matrices(Rs)) if pt3b else None,
                },
            ),
            "SO3 compose": (
                lambda: chasles.so3_compose(Rs, Rs),
                {
                    "scipy": (lambda: srs * srs) if Rotation else None,
                    "numpy": lambda: np.matmul(Rs, Rs),
                    "pytransform3d": None,
                },
            ),
            "SO3 from_euler": (
                lambda: chasles.so3_from_euler("xyz", E),
                {
                    "scipy": (lambda: Rotation.from_euler("xyz", E).as_matrix()) if Rotation else None,
                    "numpy": None,
                    "pytransform3d": None,
                },
            ),
            "SO3 as_euler": (
                lambda: chasles.so3_as_euler("xyz", Rs),
                {"scipy": (lambda: srs.as_euler("xyz")) if Rotation else None, "numpy": None, "pytransform3d": None},
            ),
            "SE3 exp": (
                lambda: chasles.se3_exp(XI),
                {
                    "scipy": (lambda: RigidTransform.from_exp_coords(S6s).as_matrix()) if RigidTransform else None,
                    "numpy": None,
                    "pytransform3d": (lambda: pt3j.transforms_from_exponential_coordinates(S6s)) if pt3j else None,
                },
            ),
            "SE3 log": (
                lambda: chasles.se3_log(Gs),
                {
                    "scipy": (lambda: RigidTransform.from_matrix(Gs).as_exp_coords()) if RigidTransform else None,
                    "numpy": None,
                    "pytransform3d": (lambda: pt3j.exponential_coordinates_from_transforms(Gs)) if pt3j else None,
                },
            ),
            "SE3 compose": (
                lambda: chasles.se3_compose(Gs, Gs2),
                {
                    "scipy": (lambda: sts * sts2) if RigidTransform else None,
                    "numpy": lambda: np.matmul(Gs, Gs2),
                    "pytransform3d": (lambda: pt3j.concat_many_to_many(Gs, Gs2)) if pt3j else None,
                },
            ),
            "SO3 random (uniform)": (
                lambda: chasles.so3_random(n, rng=7),
                {
                    "scipy": (lambda: Rotation.random(n, rng=np.random.default_rng(7)).as_matrix())
                    if Rotation
                    else None,
                    "numpy": None,
                    "pytransform3d": None,
                },
            ),
            "SO3 angle": (
                lambda: chasles.so3_angle(Rs),
                {
                    "scipy": (lambda: Rotation.from_matrix(Rs).magnitude()) if Rotation else None,
                    "numpy": lambda: np.arccos(np.clip((np.trace(Rs, axis1=1, axis2=2) - 1) / 2, -1, 1)),
                    "pytransform3d": None,
                },
            ),
            "SO3 distance": (
                lambda: chasles.so3_distance(Rs, Rs[::-1]),
                {
                    "scipy": (lambda: (srs.inv() * srs[::-1]).magnitude()) if Rotation else None,
                    "numpy": None,
                    "pytransform3d": None,
                },
            ),
            "SO3 mean (chordal)": (
                lambda: chasles.so3_mean(Rc, method="chordal"),
                {
                    # from the matrices, as chasles takes them (with the quaternions held: ~8 ns)
                    "scipy": (lambda: Rotation.from_matrix(Rc).mean()) if Rotation else None,
                    "numpy": None,
                    "pytransform3d": None,
                },
            ),
            "SO3 mean (geodesic)": (
                lambda: chasles.so3_mean(Rc),
                {"scipy": None, "numpy": None, "pytransform3d": None},
            ),
            "SO3 spline at N times (100 keys)": (
                lambda: spline_so3(ts),
                {
                    "scipy": (lambda: spline_scipy(ts).as_matrix()) if spline_scipy else None,
                    "numpy": None,
                    "pytransform3d": None,
                },
            ),
            "SO3 spline body velocity": (
                lambda: spline_so3.body_velocity(ts),
                {
                    "scipy": (lambda: spline_scipy(ts, 1)) if spline_scipy else None,
                    "numpy": None,
                    "pytransform3d": None,
                },
            ),
            "SO3 spline body acceleration": (
                lambda: spline_so3.body_acceleration(ts),
                {
                    "scipy": (lambda: spline_scipy(ts, 2)) if spline_scipy else None,
                    "numpy": None,
                    "pytransform3d": None,
                },
            ),
            "SE3 spline at N times (100 keys)": (
                lambda: spline_se3(ts),
                {"scipy": None, "numpy": None, "pytransform3d": None},
            ),
            "SE3 act (1 pose, N points)": (
                lambda: chasles.se3_act(gm, P),
                {
                    "scipy": (lambda: st1.apply(P)) if RigidTransform else None,
                    "numpy": lambda: P @ gm[:3, :3].T + gm[:3, 3],
                    "pytransform3d": None,
                },
            ),
            "SE3 act Jacobian (1 pose, N points)": (
                lambda: chasles.se3_act_jacobian(gm, P),
                {"scipy": None, "numpy": lambda: np_act_jacobian(gm, P), "pytransform3d": None},
            ),
            "SO3 B-spline value (N times)": (lambda: bs_so3(TB), {}),
            "SO3 B-spline velocity (N times)": (lambda: bs_so3.body_velocity(TB), {}),
            "SE3 B-spline value (N times)": (lambda: bs_se3(TB), {}),
            "SE3 B-spline acceleration (N times)": (lambda: bs_se3.body_acceleration(TB), {}),
        }
        names = ["scipy", "numpy", "pytransform3d"]
        print(f"### Python array functions, N = {n:.0e}, per element (ns, median of {rep})\n")
        print("| op | chasles | " + " | ".join(names) + " | ratio to best peer | target ns |")
        print("| --- | ---: | " + " | ".join("---:" for _ in names) + " | ---: | ---: |")
        budget = 0.2
        for op, (fn, peer_fns) in ops.items():
            ours = measure(fn, rep, budget)
            peers = {k: measure(peer_fns.get(k), rep, budget) for k in names}
            print(
                row(
                    op,
                    ours and ours / n,
                    {k: (t / n if t else None) for k, t in peers.items()},
                    1e9,
                    ARRAY_TARGET_NS.get(op) if n == 100_000 or op.startswith("SE3 act") else None,
                )
            )
        print()

    # ---- spline fits ---------------------------------------------------------
    rng = np.random.default_rng(5)
    key_t = np.cumsum(rng.uniform(0.3, 1.0, 100))
    key_R = chasles.so3_exp(np.cumsum(rng.normal(scale=0.35, size=(100, 3)), axis=0))
    key_G = chasles.se3_exp(np.cumsum(rng.normal(scale=0.35, size=(100, 6)), axis=0))
    print(f"### Spline fits through 100 keys (us, median of {rep})\n")
    print("| op | chasles | scipy | ratio |")
    print("| --- | ---: | ---: | ---: |")
    for op, ours_fn, peer_fn in (
        (
            "SO3Spline / RotationSpline",
            lambda: chasles.SO3Spline(key_t, key_R),
            (lambda: RotationSpline(key_t, Rotation.from_matrix(key_R))) if RotationSpline else None,
        ),
        ("SE3Spline", lambda: chasles.SE3Spline(key_t, key_G), None),
    ):
        ours, peer = measure(ours_fn, rep), measure(peer_fn, rep)
        ratio = f"{ours / peer:.2f}" if ours and peer else ""
        print(f"| {op} | {fig(ours * 1e6)} | {fig(peer * 1e6) if peer else ''} | {ratio} |")
    print()

    spline_keys_table(rep, args.spline_keys)
    align_table(rep)

    # ---- threads and kinematics ----------------------------------------------
    threads_table(rep)
    kinematics_table(rep)
    return 0


if __name__ == "__main__":
    sys.exit(main())
