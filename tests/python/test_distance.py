"""Rotation angles and distances (SO3.angle, so3_angle, so3_distance,
se3_distance) against scipy and against an independent long double formula,
near 0, near pi and at pi."""

from __future__ import annotations

import numpy as np
import pytest

import chasles

Rotation = pytest.importorskip("scipy.spatial.transform").Rotation

PI = np.pi


def angle_reference(R) -> np.ndarray:
    """The angle of each (rounded) matrix in long double, by a formula chasles
    does not use: atan2 of sin(theta) = |axial part of R| (the vee of
    (R - R^T) / 2) and cos(theta) = (tr R - 1) / 2. Accurate in long double
    at both ends (relative near 0, absolute near pi)."""
    M = np.asarray(R, dtype=np.longdouble)
    axial = 0.5 * np.stack(
        [M[..., 2, 1] - M[..., 1, 2], M[..., 0, 2] - M[..., 2, 0], M[..., 1, 0] - M[..., 0, 1]],
        axis=-1,
    )
    s = np.sqrt(np.sum(axial * axial, axis=-1))
    c = (np.trace(M, axis1=-2, axis2=-1) - 1) / 2
    return np.arctan2(s, c)


def rotations_with_angles(angles, seed):
    rng = np.random.default_rng(seed)
    axes = rng.normal(size=(len(angles), 3))
    axes /= np.linalg.norm(axes, axis=-1, keepdims=True)
    return Rotation.from_rotvec(axes * np.asarray(angles)[:, None]).as_matrix()


ANGLES = [0.0, 1e-300, 1e-160, 1e-30, 1e-12, 1e-8, 1e-4, 0.1, 1.0, 2.0, 3.0, PI - 1e-4, PI - 1e-8, PI - 1e-12, PI]


def test_so3_angle_matches_scipy_magnitude():
    R = Rotation.random(500, rng=np.random.default_rng(1))
    got = chasles.so3_angle(R.as_matrix())
    assert got.shape == (500,) and got.dtype == np.float64
    np.testing.assert_allclose(got, R.magnitude(), rtol=0, atol=4e-15)


def test_so3_angle_is_accurate_near_zero_and_near_pi():
    R = rotations_with_angles(ANGLES, seed=2)
    got = chasles.so3_angle(R)
    ref = angle_reference(R)
    err = np.abs(got.astype(np.longdouble) - ref)
    eps = np.finfo(np.float64).eps
    bound = 4 * eps * np.where(ref < 1, ref, PI)
    assert np.all(err <= bound), (err / np.maximum(ref, 1e-300)).max()
    assert got[0] == 0.0 and got[-1] <= PI


def test_acos_of_the_trace_would_not_pass_the_same_check():
    """The check above can fail: the textbook formula loses half the digits."""
    R = rotations_with_angles([1e-6, PI - 1e-6], seed=3)
    naive = np.arccos(np.clip((np.trace(R, axis1=-2, axis2=-1) - 1) / 2, -1, 1))
    ref = angle_reference(R)
    eps = np.finfo(np.float64).eps
    assert np.abs(naive[0] - ref[0]) > 4 * eps * ref[0]
    assert np.abs(naive[1] - ref[1]) > 4 * eps * PI
    assert np.all(np.abs(chasles.so3_angle(R) - ref) <= 4 * eps * np.array([ref[0], PI]))


def test_so3_angle_float32_loop():
    R = rotations_with_angles([1e-20, 1e-3, 1.0, PI - 1e-3, PI], seed=4).astype(np.float32)
    got = chasles.so3_angle(R)
    assert got.dtype == np.float32
    ref = angle_reference(R)
    eps = np.finfo(np.float32).eps
    assert np.all(np.abs(got - ref) <= 4 * eps * np.where(ref < 1, ref, PI))


def test_object_angle_is_the_array_function():
    R = rotations_with_angles([0.0, 1e-9, 1.0, PI], seed=5)
    for M in R:
        g = chasles.SO3.from_matrix(M)
        assert g.angle() == chasles.so3_angle(M)
        assert isinstance(g.angle(), float)


def test_so3_distance_matches_scipy_and_is_bi_invariant():
    rng = np.random.default_rng(6)
    a, b, g = (Rotation.random(300, rng=rng) for _ in range(3))
    d = chasles.so3_distance(a.as_matrix(), b.as_matrix())
    np.testing.assert_allclose(d, (a.inv() * b).magnitude(), rtol=0, atol=1e-14)
    np.testing.assert_allclose(chasles.so3_distance(b.as_matrix(), a.as_matrix()), d, atol=1e-14)
    np.testing.assert_allclose(chasles.so3_distance((g * a).as_matrix(), (g * b).as_matrix()), d, atol=1e-14)
    np.testing.assert_allclose(chasles.so3_distance((a * g).as_matrix(), (b * g).as_matrix()), d, atol=1e-14)


def test_so3_distance_near_zero_and_pi_against_the_reference():
    a = Rotation.random(len(ANGLES), rng=np.random.default_rng(7)).as_matrix()
    rel = rotations_with_angles(ANGLES, seed=8)
    b = a @ rel
    # The reference is the angle of a^T b formed in long double from the rounded a, b.
    ref = angle_reference(np.swapaxes(a.astype(np.longdouble), -1, -2) @ b.astype(np.longdouble))
    got = chasles.so3_distance(a, b)
    # a^T b in double is off by a few ulps of 1: absolute accuracy.
    assert np.all(np.abs(got - ref) <= 16 * np.finfo(np.float64).eps)
    assert chasles.so3_distance(a[3], a[3]) == 0.0 or chasles.so3_distance(a[3], a[3]) < 1e-15


def test_so3_distance_broadcasts():
    a = Rotation.random(4, rng=np.random.default_rng(9)).as_matrix()
    d = chasles.so3_distance(a[:, None], a[None, :])
    assert d.shape == (4, 4)
    np.testing.assert_allclose(d, d.T, atol=1e-15)
    assert np.all(np.diag(d) < 1e-7)


def test_se3_distance_is_the_rotation_angle_and_the_distance_of_the_origins():
    rng = np.random.default_rng(10)
    n = 200
    ga = chasles.se3_exp(rng.normal(size=(n, 6)) * 2)
    gb = chasles.se3_exp(rng.normal(size=(n, 6)) * 2)
    d = chasles.se3_distance(ga, gb)
    assert d.shape == (n, 2)
    ra = Rotation.from_matrix(ga[:, :3, :3])
    rb = Rotation.from_matrix(gb[:, :3, :3])
    np.testing.assert_allclose(d[:, 0], (ra.inv() * rb).magnitude(), rtol=0, atol=1e-14)
    np.testing.assert_allclose(d[:, 1], np.linalg.norm(gb[:, :3, 3] - ga[:, :3, 3], axis=-1), rtol=1e-15, atol=0)
    # |p_b - p_a| is the length of the translation of a^-1 b ...
    rel = chasles.se3_compose(chasles.se3_inverse(ga), gb)
    np.testing.assert_allclose(d[:, 1], np.linalg.norm(rel[:, :3, 3], axis=-1), rtol=1e-13)
    # ... and both parts are unchanged by a change of the fixed frame.
    g = chasles.se3_exp(rng.normal(size=6))
    dg = chasles.se3_distance(chasles.se3_compose(g, ga), chasles.se3_compose(g, gb))
    np.testing.assert_allclose(dg, d, rtol=1e-13, atol=1e-14)


def test_se3_distance_float32():
    rng = np.random.default_rng(11)
    ga = chasles.se3_exp(rng.normal(size=(10, 6))).astype(np.float32)
    gb = chasles.se3_exp(rng.normal(size=(10, 6))).astype(np.float32)
    d = chasles.se3_distance(ga, gb)
    assert d.dtype == np.float32
    np.testing.assert_allclose(d, chasles.se3_distance(ga.astype(np.float64), gb.astype(np.float64)), atol=2e-6)
