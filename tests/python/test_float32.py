"""float32 arrays: the accuracy contract of the core (docs/numerics.md, "Measured errors";
tests/cpp/test_accuracy.cpp) for the array functions on float32 input, the
double thresholds carried to float32 as the same number of ulps
(tol32 = tol64 * eps32 / eps64); and no NaN or inf from any finite float32
input, at and near angle 0, near and at pi, tiny and huge.

The oracle is chasles' float64 path on the same numbers (the float32
inputs, widened exactly), itself held to 1e-15 against scipy.linalg.expm
in test_batch.py, and scipy.linalg.expm directly for exp. A float32 result
is compared with the true value for its float32 input: the rounding of the
input to float32 is not counted against the kernel.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from helpers import hat3 as hat
from helpers import hat6
from scipy.linalg import expm

import chasles

EPS32 = float(np.finfo(np.float32).eps)
EPS64 = float(np.finfo(np.float64).eps)
PI = math.pi
PI32_BELOW = float(np.nextafter(np.float32(PI), np.float32(0)))  # float32(pi) is above pi


def tol(double_tol: float) -> float:
    """A double threshold carried to float32: the same number of ulps."""
    return double_tol * EPS32 / EPS64


STRICT_PI_GAP = tol(1e-12)  # 5.4e-4: closer to pi, w and -w are both the log of the rounded matrix
TAYLOR_THETA32 = math.sqrt(4.9215667e-03)  # the float cutoff, on theta (constants.hpp)


def contract_angles():
    """The angles of the C++ contract, as float32, from 0 to pi."""
    a = [0.0, 1e-45, 1e-38, 1e-36] + [10.0**-k for k in (35, 25, 20, 15, 12, 10, 8, 6, 5, 4, 3, 2, 1)]
    a += [
        float(np.nextafter(np.float32(TAYLOR_THETA32), np.float32(0))),
        TAYLOR_THETA32,
        float(np.nextafter(np.float32(TAYLOR_THETA32), np.float32(1))),
    ]
    a += [0.03, 0.1, 0.3, 0.5, 1.0, 1.5, PI / 2, 2.0, 2.5, 3.0]
    gap = 1e-1
    while gap >= STRICT_PI_GAP * 0.99:
        a.append(PI - gap)
        gap /= 10
    a += [PI - STRICT_PI_GAP, PI32_BELOW]
    return sorted({float(np.float32(x)) for x in a})


def contract_axes(n_random=6, seed=1):
    rng = np.random.default_rng(seed)
    axes = [np.eye(3)[i] * s for i in range(3) for s in (1.0, -1.0)]
    axes += [np.array([1.0, 1.0, 0.0]) / math.sqrt(2), np.array([1.0, 1.0, 1.0]) / math.sqrt(3)]
    for u in rng.normal(size=(n_random, 3)):
        axes.append(u / np.linalg.norm(u))
    return [u.astype(np.float32) for u in axes]


def rotation_vectors32():
    """Every contract angle along every contract axis, float32, |w| <= pi."""
    out = [np.float32(a) * u for a in contract_angles() for u in contract_axes()]
    w = np.array(out, dtype=np.float32)
    return w[np.linalg.norm(w.astype(np.float64), axis=1) <= PI]


def widened(x):
    return np.asarray(x, dtype=np.float64)


def angle_of(w):
    return np.linalg.norm(widened(w), axis=-1)


# ---- SO(3) -----------------------------------------------------------------------------


def test_so3_exp_contract():
    w = rotation_vectors32()
    R = chasles.so3_exp(w)
    assert R.dtype == np.float32 and np.isfinite(R).all()
    err = np.abs(widened(R) - chasles.so3_exp(widened(w))).max(axis=(1, 2))
    worst = int(np.argmax(err))
    assert err[worst] <= tol(1e-15), f"{err[worst]:.3g} = {err[worst] / EPS32:.2f} eps32 at w = {w[worst]}"
    # and the oracle against scipy's expm, on a sample
    for i in range(0, len(w), 17):
        np.testing.assert_allclose(chasles.so3_exp(widened(w[i])), expm(hat(widened(w[i]))), rtol=0, atol=4e-15)


def rounded_rotations(w):
    """exp(w) computed in float64, rounded to float32: the float32 rotations
    of the contract (slightly off SO(3), as any float32 data is)."""
    return chasles.so3_exp(widened(w)).astype(np.float32)


def test_so3_log_contract():
    w = rotation_vectors32()
    w = w[angle_of(w) > 0]
    R = rounded_rotations(w)
    got = chasles.so3_log(R)
    assert got.dtype == np.float32 and np.isfinite(got).all()
    ref = chasles.so3_log(widened(R))  # the log of the very same float32 numbers
    theta = angle_of(w)
    strict = PI - theta >= 0.5 * STRICT_PI_GAP
    err_strict = np.abs(widened(got) - ref).max(axis=1)
    err_either = np.minimum(err_strict, np.abs(widened(got) + ref).max(axis=1))
    worst = int(np.argmax(np.where(strict, err_strict, err_either)))
    err = err_strict[worst] if strict[worst] else err_either[worst]
    assert err <= tol(1e-15), f"{err:.3g} = {err / EPS32:.2f} eps32 at w = {w[worst]} (angle {theta[worst]!r})"
    # near pi, the answer is a log of R: exp of it gives R back
    back = chasles.so3_exp(widened(got[~strict]))
    assert np.abs(back - widened(R[~strict])).max() <= tol(1e-15) + 2 * EPS32
    # and the angle never exceeds pi
    assert (angle_of(got) <= PI * (1 + 4 * EPS32)).all()


def test_so3_log_tiny_angles_relative():
    axes = contract_axes(10, seed=2)
    a = 1e-36
    w = []
    while a <= 1.0001e-4:
        w += [np.float32(a) * u for u in axes]
        a *= 3.1
    w = np.array(w, dtype=np.float32)
    R = rounded_rotations(w)
    got = chasles.so3_log(R)
    ref = chasles.so3_log(widened(R))
    scale = np.abs(ref).max(axis=1)
    assert (scale > 0).all()
    rel = np.abs(widened(got) - ref).max(axis=1) / scale
    worst = int(np.argmax(rel))
    assert rel[worst] <= 4 * EPS32, f"{rel[worst] / EPS32:.2f} eps32 at w = {w[worst]}"


@pytest.mark.parametrize(
    "angle",
    [0.0, 1e-20, 1e-8, PI - 1e-3, PI - 1e-6, PI32_BELOW, PI],
    ids=["0", "1e-20", "1e-8", "pi-1e-3", "pi-1e-6", "below-pi", "pi"],
)
def test_so3_log_is_never_nan_at_0_and_pi(angle):
    """At angle 0, 1e-20 and 1e-8 the float32 matrix is the identity or
    next to it; near pi and at pi (pi rounded to float32 is above pi) it is
    a rotation by pi, up to rounding. The log is finite, at most pi, and
    exp of it gives the matrix back."""
    axes = contract_axes()
    w = np.array([angle * widened(u) for u in axes])
    R = chasles.so3_exp(w).astype(np.float32)
    got = chasles.so3_log(R)
    assert np.isfinite(got).all(), got
    assert (angle_of(got) <= PI * (1 + 4 * EPS32)).all()
    assert np.abs(chasles.so3_exp(widened(got)) - widened(R)).max() <= tol(1e-15) + 2 * EPS32
    if angle <= 1e-8:
        np.testing.assert_allclose(widened(got), chasles.so3_log(widened(R)), rtol=4 * EPS32, atol=1e-45)


def test_so3_log_of_exact_pi_rotations():
    n111 = np.ones(3) / math.sqrt(3)
    cases = [
        (np.diag([1.0, -1.0, -1.0]), np.array([1.0, 0, 0])),
        (np.diag([-1.0, 1.0, -1.0]), np.array([0, 1.0, 0])),
        (np.diag([-1.0, -1.0, 1.0]), np.array([0, 0, 1.0])),
        (np.array([[0.0, 1, 0], [1, 0, 0], [0, 0, -1]]), np.array([1.0, 1, 0]) / math.sqrt(2)),
        (np.array([[-1.0, 0, 0], [0, 0, 1], [0, 1, 0]]), np.array([0, 1.0, 1]) / math.sqrt(2)),
        (np.array([[0.0, -1, 0], [-1, 0, 0], [0, 0, -1]]), np.array([1.0, -1, 0]) / math.sqrt(2)),
        (2 * np.outer(n111, n111) - np.eye(3), n111),
    ]
    R = np.array([c[0] for c in cases], dtype=np.float32)
    got = widened(chasles.so3_log(R))
    assert np.isfinite(got).all()
    for g, (_, n), r in zip(got, cases, R):
        err_axis = min(np.abs(g - PI * n).max(), np.abs(g + PI * n).max())
        assert err_axis <= tol(1e-15), (g, n)
        assert abs(np.linalg.norm(g) - PI) <= tol(1e-15)
        assert np.abs(expm(hat(g)) - widened(r)).max() <= tol(1e-15) + EPS32


# ---- SE(3) -----------------------------------------------------------------------------


def twists32(seed=3):
    rng = np.random.default_rng(seed)
    out, k = [], 0
    for a in contract_angles():
        for u in contract_axes(2, seed=seed):
            for s in (0.0, 1e-6, 1.0, 100.0, 1e6):
                d = rng.normal(size=3)
                d /= np.linalg.norm(d)
                if k % 2 == 0 and a > 0:  # orthogonal to w: where (1/2)[w] v is largest
                    d = np.cross(widened(u), d)
                    d /= np.linalg.norm(d)
                k += 1
                out.append(np.concatenate([s * d, a * widened(u)]))
    xi = np.array(out).astype(np.float32)
    return xi[angle_of(xi[:, 3:]) <= PI]


FLT_MIN = float(np.finfo(np.float32).tiny)  # the smallest normal float32


def relative(got, ref):
    """The error relative to the largest reference entry, or to the smallest
    normal float32 below it (subnormal results have an absolute spacing)."""
    scale = np.maximum(np.abs(ref).max(axis=-1), FLT_MIN)
    return np.abs(got - ref).max(axis=-1) / scale


def test_se3_exp_contract():
    xi = twists32()
    g = chasles.se3_exp(xi)
    assert g.dtype == np.float32 and np.isfinite(g).all()
    ref = chasles.se3_exp(widened(xi))
    rot = np.abs(widened(g[:, :3, :3]) - ref[:, :3, :3]).max(axis=(1, 2))
    trans = relative(widened(g[:, :3, 3]), ref[:, :3, 3])
    assert rot.max() <= tol(2e-15), f"{rot.max() / EPS32:.2f} eps32 at xi = {xi[np.argmax(rot)]}"
    assert trans.max() <= tol(2e-15), f"{trans.max() / EPS32:.2f} eps32 at xi = {xi[np.argmax(trans)]}"
    for i in range(0, len(xi), 41):
        X = expm(hat6(widened(xi[i])))
        np.testing.assert_allclose(ref[i], X, rtol=0, atol=1e-14 * max(1.0, np.abs(X).max()))


def test_se3_log_contract():
    xi = twists32(seed=4)
    g = chasles.se3_exp(widened(xi)).astype(np.float32)
    got = chasles.se3_log(g)
    assert got.dtype == np.float32 and np.isfinite(got).all()
    ref = chasles.se3_log(widened(g))
    near_pi = PI - angle_of(xi[:, 3:]) < 0.5 * STRICT_PI_GAP
    flip = near_pi & (np.sum(widened(got[:, 3:]) * ref[:, 3:], axis=1) < 0)
    for i in np.flatnonzero(flip):  # the other log at pi: -w, and the v that goes with it
        ref[i, 3:] = -ref[i, 3:]
        # p = V(w) v with V(w) = J_l(w), the left Jacobian of SO(3)
        ref[i, :3] = np.linalg.solve(chasles.SO3.left_jacobian(ref[i, 3:]), widened(g[i, :3, 3]))
    rot = np.abs(widened(got[:, 3:]) - ref[:, 3:]).max(axis=1)
    trans = relative(widened(got[:, :3]), ref[:, :3])
    exact_zero = np.abs(ref[:, :3]).max(axis=1) == 0
    assert (got[exact_zero, :3] == 0).all()
    assert rot.max() <= tol(2e-15), f"{rot.max() / EPS32:.2f} eps32 at xi = {xi[np.argmax(rot)]}"
    worst = int(np.argmax(np.where(exact_zero, 0, trans)))
    assert trans[worst] <= tol(2e-15), f"{trans[worst] / EPS32:.2f} eps32 at xi = {xi[worst]}"


# ---- tiny and huge ---------------------------------------------------------------------

FLT_MAX = float(np.finfo(np.float32).max)
HUGE = [1e10, 1e20, 1e30, 1e38, FLT_MAX]
TINY = [1e-45, 1e-40, 1e-38, 1e-30, 1e-20]


@pytest.mark.parametrize("size", TINY + HUGE)
def test_exp_is_finite_and_a_rotation_at_tiny_and_huge(size):
    """No NaN or inf, and a rotation (R^T R = I to a few eps32), for rotation
    vectors of any finite float32 size; exactly the float64 result along a
    coordinate axis (where the float32 angle is exact), and for tiny ones."""
    axes = contract_axes()
    w = np.array([np.float32(size) * u for u in axes], dtype=np.float32)
    R = chasles.so3_exp(w)
    assert np.isfinite(R).all(), (size, R)
    Rd = widened(R)
    assert np.abs(np.swapaxes(Rd, 1, 2) @ Rd - np.eye(3)).max() <= 8 * EPS32
    ref = chasles.so3_exp(widened(w))
    exact = [i for i, u in enumerate(axes) if np.count_nonzero(u) == 1] if size > 1 else range(len(axes))
    assert np.abs(Rd[exact] - ref[exact]).max() <= tol(1e-15) + EPS32 * (size > 1)
    xi = np.concatenate([np.full((len(axes), 3), 0.5, np.float32), w], axis=1)
    g = chasles.se3_exp(xi)
    assert np.isfinite(g).all(), (size, g)
    np.testing.assert_array_equal(g[:, :3, :3], R)


@pytest.mark.parametrize("size", TINY + HUGE)
def test_se3_exp_with_tiny_and_huge_translations(size):
    xi = np.array(
        [
            [size, -size, size / 2, 0.0, 0.0, 0.0],
            [size, 0.0, 0.0, 0.0, 0.0, 1.0],
            [size, size, 0.0, 1e-3, 0.0, 0.0],
        ],
        dtype=np.float32,
    )
    g = chasles.se3_exp(xi)
    assert np.isfinite(g).all(), (size, g)
    ref = chasles.se3_exp(widened(xi))
    assert (relative(widened(g[:, :3, 3]), ref[:, :3, 3]) <= tol(2e-15)).all()


def test_logs_of_arbitrary_finite_float32_matrices_are_finite():
    """Not rotations at all (zero, huge, tiny, reflections, random): the log
    is some finite vector (the log of the nearest rotation, up to rounding)."""
    rng = np.random.default_rng(7)
    M = [
        np.zeros((3, 3)),
        np.eye(3) * FLT_MAX,
        np.eye(3) * 1e-45,
        np.diag([1.0, 1.0, -1.0]),
        -np.eye(3),
        np.full((3, 3), FLT_MAX),
        np.full((3, 3), -1e-38),
    ]
    M += list(rng.normal(size=(50, 3, 3)) * 10.0 ** rng.uniform(-40, 38, size=(50, 1, 1)))
    M = np.array(M).astype(np.float32)
    assert np.isfinite(M).all()
    w = chasles.so3_log(M)
    assert np.isfinite(w).all() and (angle_of(w) <= PI * (1 + 4 * EPS32)).all()
    g = np.zeros((len(M), 4, 4), np.float32)
    g[:, :3, :3] = M
    g[:, :3, 3] = np.float32(1e30)
    g[:, 3, 3] = 1
    xi = chasles.se3_log(g)
    assert np.isfinite(xi).all()


@pytest.mark.parametrize("group", ["SO3", "SE3"])
def test_objects_act_on_float32_points_in_float32(group):
    """g @ points of float32 is float32 (not float64: half the memory), the
    pose rounded to float32 once and the float32 kernel run: as accurate as
    the array function on float32 operands, measured against the float64
    oracle on the same points (the pose's and the kernel's roundings, a few
    float32 ulps of the result's scale)."""
    rng = np.random.default_rng(11)
    G = getattr(chasles, group)
    g = G.exp(rng.normal(size=3 if group == "SO3" else 6))
    p = (rng.normal(size=(1000, 3)) * 10.0).astype(np.float32)
    for out in (g @ p, g.act(p), g.act_inv(p) if group == "SE3" else g.inverse() @ p):
        assert out.dtype == np.float32 and out.shape == (1000, 3)
    oracle = g @ p.astype(np.float64)
    scale = np.abs(p.astype(np.float64)).max() + (np.abs(g.translation).max() if group == "SE3" else 0.0)
    assert np.abs((g @ p) - oracle).max() <= 8 * EPS32 * scale
    act = chasles.so3_act if group == "SO3" else chasles.se3_act
    M32 = np.asarray(g, dtype=np.float32)
    assert np.array_equal(g @ p, act(M32, p))
    assert np.abs(act(M32, p) - oracle).max() <= 8 * EPS32 * scale
