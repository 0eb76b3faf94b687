"""SO3Spline and SE3Spline: through the keys; body velocity and acceleration
against central differences of the evaluated elements; continuous at the
keys; natural ends; two keys give the geodesic; keys on a screw motion give
that motion; the SE3 spline of pure rotations is the SO3 spline; with
ends="chord" the SO3 spline is scipy's RotationSpline; shapes, float32 and
bad inputs."""

from __future__ import annotations

import copy
import pickle
import re
import time

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

import chasles
from chasles import SE3Spline, SO3Spline, _core

transform = pytest.importorskip("scipy.spatial.transform")
Rotation, RotationSpline = transform.Rotation, transform.RotationSpline


def random_times(rng, n):
    return np.cumsum(np.concatenate([[rng.uniform(-1, 1)], rng.uniform(0.3, 1.0, n - 1)]))


def random_rotations(rng, n, step=0.35):
    """A walk: each step exp(w), w ~ N(0, step^2 I) (about 0.6 rad for 0.35)."""
    R = [chasles.so3_exp(rng.normal(size=3))]
    for _ in range(n - 1):
        R.append(R[-1] @ chasles.so3_exp(rng.normal(scale=step, size=3)))
    return np.array(R)


def random_poses(rng, n):
    g = [chasles.se3_exp(rng.normal(size=6))]
    for _ in range(n - 1):
        xi = np.concatenate([rng.normal(scale=0.3, size=3), rng.normal(scale=0.35, size=3)])
        g.append(g[-1] @ chasles.se3_exp(xi))
    return np.array(g)


def relative_log(a, b, group):
    """log(a^-1 b), broadcasting."""
    if group == 3:
        return chasles.so3_log(chasles.so3_compose(np.swapaxes(a, -1, -2), b))
    return chasles.se3_log(chasles.se3_compose(chasles.se3_inverse(a), b))


def make(group, rng, n, ends="natural"):
    t = random_times(rng, n)
    if group == 3:
        return SO3Spline(t, random_rotations(rng, n), ends=ends)
    return SE3Spline(t, random_poses(rng, n), ends=ends)


def keys_of(spline):
    return spline.rotations if isinstance(spline, SO3Spline) else spline.poses


@pytest.mark.parametrize("group", [3, 4])
@pytest.mark.parametrize("ends", ["natural", "chord"])
def test_passes_through_the_keys(group, ends):
    rng = np.random.default_rng(1)
    for n in (2, 3, 8):
        s = make(group, rng, n, ends)
        d = np.linalg.norm(relative_log(s(s.times), keys_of(s), group), axis=-1)
        assert d.max() < 1e-14


@pytest.mark.parametrize("group", [3, 4])
def test_rates_against_central_differences(group):
    # y(d) = log(X(t)^-1 X(t + d)) = V d + V' d^2 / 2 + O(d^3): V ~ (y(d) - y(-d)) / 2d and
    # V' ~ (y(d) + y(-d)) / d^2, errors O(d^2) times derivatives of order 10 plus rounding eps / d and
    # eps / d^2: with d = 1e-4 both are ~ 1e-7, the bounds 1e-6 and 1e-5 (relative to 1 + |V|, 1 + |V'|).
    rng = np.random.default_rng(2)
    s = make(group, rng, 9)
    t = rng.uniform(s.times[0], s.times[-1], 200)
    d = 1e-4
    X = s(t)
    yp, ym = relative_log(X, s(t + d), group), relative_log(X, s(t - d), group)
    V, A = s.body_velocity(t), s.body_acceleration(t)
    err_v = np.linalg.norm(V - (yp - ym) / (2 * d), axis=-1) / (1 + np.linalg.norm(V, axis=-1))
    err_a = np.linalg.norm(A - (yp + ym) / d**2, axis=-1) / (1 + np.linalg.norm(A, axis=-1))
    assert err_v.max() < 1e-6
    assert err_a.max() < 1e-5


@pytest.mark.parametrize("group", [3, 4])
def test_velocity_and_acceleration_are_continuous_at_the_keys(group):
    # One-sided values a distance d = 1e-7 either side of each interior key differ by at most d times the
    # jerk (of order 10): bound 1e-5; the velocity by d times the acceleration.
    rng = np.random.default_rng(3)
    s = make(group, rng, 10)
    d = 1e-7
    inner = s.times[1:-1]
    for f in (s.body_velocity, s.body_acceleration):
        left, right = f(inner - d), f(inner + d)
        assert np.abs(left - right).max() < 1e-5
    # and the jump of the acceleration across a key is not hidden by the bound: a C1 spline would fail
    # (the acceleration changes by O(1) over one segment, the bound is 1e-5)
    a = s.body_acceleration(s.times)
    assert np.abs(np.diff(a, axis=0)).max() > 1e-2


@pytest.mark.parametrize("group", [3, 4])
def test_natural_ends_have_no_acceleration(group):
    rng = np.random.default_rng(4)
    s = make(group, rng, 6)
    a = s.body_acceleration(s.times[[0, -1]])
    assert np.abs(a).max() < 1e-9
    c = make(group, np.random.default_rng(4), 6, ends="chord")
    assert np.abs(c.body_acceleration(c.times[[0, -1]])).max() > 1e-3  # the other end condition


@pytest.mark.parametrize("group", [3, 4])
@pytest.mark.parametrize("ends", ["natural", "chord"])
def test_two_keys_give_the_geodesic(group, ends):
    rng = np.random.default_rng(5)
    s = make(group, rng, 2, ends)
    keys = keys_of(s)
    h = s.times[1] - s.times[0]
    D = relative_log(keys[0], keys[1], group)
    t = np.linspace(s.times[0] - 0.5, s.times[1] + 0.5, 23)
    exp = chasles.so3_exp if group == 3 else chasles.se3_exp
    geodesic = keys[0] @ exp(((t - s.times[0]) / h)[:, None] * D)
    np.testing.assert_allclose(s(t), geodesic, atol=1e-14)
    np.testing.assert_allclose(s.body_velocity(t), np.broadcast_to(D / h, (23, D.size)), atol=1e-14)
    np.testing.assert_allclose(s.body_acceleration(t), 0, atol=1e-14)


@pytest.mark.parametrize("group", [3, 4])
def test_keys_on_a_screw_motion_give_that_motion(group):
    rng = np.random.default_rng(6)
    exp = chasles.so3_exp if group == 3 else chasles.se3_exp
    for _ in range(5):
        xi = rng.normal(size=3 if group == 3 else 6)
        xi[-3:] *= min(1.0, 2.5 / np.linalg.norm(xi[-3:]))  # steps <= 1 s: each step turns less than pi
        start = exp(rng.normal(size=xi.size))
        times = random_times(rng, 7)
        keys = start @ exp(times[:, None] * xi)
        s = (SO3Spline if group == 3 else SE3Spline)(times, keys)
        t = rng.uniform(times[0], times[-1], 50)
        np.testing.assert_allclose(s(t), start @ exp(t[:, None] * xi), atol=1e-13)
        np.testing.assert_allclose(s.body_velocity(t), np.broadcast_to(xi, (50, xi.size)), atol=1e-13)
        np.testing.assert_allclose(s.body_acceleration(t), 0, atol=1e-13)


@pytest.mark.parametrize("ends", ["natural", "chord"])
def test_se3_spline_of_pure_rotations_is_the_so3_spline(ends):
    rng = np.random.default_rng(7)
    times, R = random_times(rng, 8), random_rotations(rng, 8)
    g = np.zeros((8, 4, 4))
    g[:, :3, :3], g[:, 3, 3] = R, 1
    a, b = SO3Spline(times, R, ends=ends), SE3Spline(times, g, ends=ends)
    t = np.linspace(times[0] - 0.3, times[-1] + 0.3, 101)
    np.testing.assert_allclose(b(t)[:, :3, :3], a(t), atol=1e-14)
    assert np.all(b(t)[:, :3, 3] == 0)
    np.testing.assert_allclose(b.body_velocity(t)[:, 3:], a.body_velocity(t), atol=1e-13)
    np.testing.assert_allclose(b.body_acceleration(t)[:, 3:], a.body_acceleration(t), atol=1e-12)
    assert np.all(b.body_velocity(t)[:, :3] == 0) and np.all(b.body_acceleration(t)[:, :3] == 0)


# scipy's RotationSpline fixes the end rates to the chord rates (ends="chord") and stops its fixed-point
# iteration after a step below 1e-9 (1 + |w|), or silently after 10 iterations. Measured over 400 random key
# sets per band (steps exp(z), z ~ N(0, sigma^2 I), 0.3 to 1 s apart; worst relative difference of rotations,
# rates, accelerations): sigma <= 0.2: 1e-12, 5e-12, 2e-11; 0.2 to 0.4: 1e-11, 3e-11, 9e-11; 0.4 to 0.6: 1e-8,
# 1e-8, 6e-8; 0.6 to 0.8: 1e-7, 1e-7, 1e-6 (there scipy stops at its 10 iterations unconverged, while chasles
# iterates to 1.8e-12). Hence the bound 1e-9 for steps up to sigma = 0.4. Its angular rate and acceleration are
# in the body frame (X_i exp(r), Jr(r) r'), as chasles' body_velocity.
SCIPY_TOL = 1e-9


def check_against_scipy(times, R, t):
    ours = SO3Spline(times, R, ends="chord")
    ref = RotationSpline(times, Rotation.from_matrix(R))
    angle = np.linalg.norm(
        chasles.so3_log(chasles.so3_compose(np.swapaxes(ours(t), -1, -2), ref(t).as_matrix())), axis=-1
    )
    assert angle.max() < SCIPY_TOL
    for order, f in ((1, ours.body_velocity), (2, ours.body_acceleration)):
        a, b = f(t), ref(t, order)
        err = np.linalg.norm(a - b, axis=-1) / (1 + np.linalg.norm(b, axis=-1))
        assert err.max() < SCIPY_TOL, (order, err.max())
    return ours, ref


def test_chord_ends_equal_scipys_rotation_spline():
    rng = np.random.default_rng(8)
    for n in (2, 3, 5, 20):
        times, R = random_times(rng, n), random_rotations(rng, n)
        t = np.concatenate([times, rng.uniform(times[0] - 0.5, times[-1] + 0.5, 100)])
        check_against_scipy(times, R, t)


def test_scipys_example():
    times = [0, 10, 20, 40]
    angles = [[-10, 20, 30], [0, 15, 40], [-30, 45, 30], [20, 45, 90]]
    R = Rotation.from_euler("XYZ", angles, degrees=True).as_matrix()
    check_against_scipy(np.array(times, float), R, np.linspace(-5, 45, 101))


@given(
    seed=st.integers(0, 2**32 - 1),
    n=st.integers(2, 12),
    step=st.floats(0.01, 0.4),
)
def test_random_keys_hypothesis(seed, n, step):
    rng = np.random.default_rng(seed)
    times, R = random_times(rng, n), random_rotations(rng, n, step)
    t = np.concatenate([times, rng.uniform(times[0], times[-1], 20)])
    check_against_scipy(times, R, t)
    s = SO3Spline(times, R)
    d = np.linalg.norm(chasles.so3_log(chasles.so3_compose(np.swapaxes(s(times), -1, -2), R)), axis=-1)
    assert d.max() < 1e-14
    for f in (s.body_velocity, s.body_acceleration):
        assert np.all(np.abs(f(times[1:-1] - 1e-7) - f(times[1:-1] + 1e-7)) < 1e-4)
    assert np.abs(s.body_acceleration(times[[0, -1]])).max() < 1e-8


def test_shapes_properties_and_repr():
    rng = np.random.default_rng(9)
    times, R, g = random_times(rng, 4), random_rotations(rng, 4), random_poses(rng, 4)
    s, p = SO3Spline(times, R), SE3Spline(times, g)
    assert s(0.5).shape == (3, 3) and p(0.5).shape == (4, 4)
    assert s(np.zeros((2, 5))).shape == (2, 5, 3, 3) and p(np.zeros((2, 5))).shape == (2, 5, 4, 4)
    assert s.body_velocity(0.5).shape == (3,) and p.body_velocity([0.5]).shape == (1, 6)
    assert s.body_acceleration(np.zeros((0, 2))).shape == (0, 2, 3) and p.body_acceleration(0.1).shape == (6,)
    np.testing.assert_array_equal(s.times, times)
    assert not s.times.flags.writeable
    np.testing.assert_array_equal(s.rotations, R)
    np.testing.assert_array_equal(p.poses, g)
    assert len(s) == 4 and s.ends == "natural" and SO3Spline(times, R, ends="chord").ends == "chord"
    assert repr(s).startswith("SO3Spline(N=4, times=[") and "ends='natural'" in repr(s)
    assert repr(p).startswith("SE3Spline(N=4")
    # one evaluation is the same number as the same time inside an array
    np.testing.assert_array_equal(s(times[1] + 0.1), s(np.array([0.0, times[1] + 0.1]))[1])


def test_sequences_of_objects_and_float32():
    rng = np.random.default_rng(10)
    times, R, g = random_times(rng, 4), random_rotations(rng, 4), random_poses(rng, 4)
    a = SO3Spline(list(times), [chasles.SO3.from_matrix(r) for r in R])
    np.testing.assert_array_equal(a(times), SO3Spline(times, R)(times))
    b = SE3Spline(times, [chasles.SE3.from_matrix(x) for x in g])
    np.testing.assert_array_equal(b.body_velocity(times), SE3Spline(times, g).body_velocity(times))
    # float32 times (key and evaluation) are the same numbers in float64; the results are float64
    t32 = times.astype(np.float32)
    c = SO3Spline(t32, R)
    np.testing.assert_array_equal(c(t32), SO3Spline(t32.astype(np.float64), R)(t32.astype(np.float64)))
    assert c(t32).dtype == np.float64
    # float32 rotations exactly on the manifold are accepted (90 degree turns); rounded ones are refused
    # (their defect ~ 1e-7 exceeds the float64 tolerance 1.5e-8), as SO3.from_matrix refuses them
    quarter = chasles.so3_exp(np.pi / 2 * np.eye(3)).round().astype(np.float32)
    np.testing.assert_allclose(SO3Spline([0, 1, 2], quarter)([0, 1, 2]), quarter.astype(np.float64), atol=1e-15)
    with pytest.raises(ValueError, match=r"SO3Spline\(rotations\): key \d is not a rotation.*from_matrix_projected"):
        SO3Spline(times, R.astype(np.float32) * np.float32(1 + 1e-6))


@pytest.mark.parametrize(
    "times, keys, match",
    [
        ([0.0], np.eye(3)[None], r"SO3Spline\(times\): expected shape \(N,\) with N >= 2, got \(1,\)"),
        (0.0, np.eye(3)[None], r"SO3Spline\(times\): expected shape \(N,\) with N >= 2, got \(\)"),
        (
            [0.0, 0.0],
            np.stack([np.eye(3)] * 2),
            r"SO3Spline\(times\): expected strictly increasing times, got times\[0\]",
        ),
        ([0.0, 2.0, 1.0], np.stack([np.eye(3)] * 3), r"strictly increasing.*times\[1\] = 2.0"),
        ([0.0, np.nan], np.stack([np.eye(3)] * 2), r"SO3Spline\(times\): expected finite times"),
        ([0.0, np.inf], np.stack([np.eye(3)] * 2), r"SO3Spline\(times\): expected finite times"),
        (
            [0.0, 1.0],
            np.stack([np.eye(3)] * 3),
            r"SO3Spline\(rotations\): expected shape \(2, 3, 3\) \(one per time\), got \(3, 3, 3\)",
        ),
        ([0.0, 1.0], np.eye(3), r"SO3Spline\(rotations\): expected shape \(2, 3, 3\).*got \(3, 3\)"),
        (
            [0.0, 1.0],
            np.stack([np.eye(3), 2 * np.eye(3)]),
            r"SO3Spline\(rotations\): key 1 is not a rotation: defect = 7",
        ),
        ([0.0, 1.0], np.stack([np.eye(3), np.full((3, 3), np.nan)]), r"SO3Spline\(rotations\): expected finite"),
    ],
)
def test_bad_inputs_so3(times, keys, match):
    with pytest.raises(ValueError, match=match):
        SO3Spline(times, keys)


def test_bad_inputs_other():
    g = np.stack([np.eye(4)] * 2)
    bad = g.copy()
    bad[1, 3, 0] = 0.5
    with pytest.raises(ValueError, match=r"SE3Spline\(poses\): key 1 is not a rigid motion"):
        SE3Spline([0, 1], bad)
    with pytest.raises(ValueError, match=r"SE3Spline\(poses\): expected shape \(2, 4, 4\)"):
        SE3Spline([0, 1], np.stack([np.eye(3)] * 2))
    with pytest.raises(ValueError, match=r"SE3Spline\(ends\): expected 'natural' or 'chord', got 'clamped'"):
        SE3Spline([0, 1], g, ends="clamped")
    with pytest.raises(TypeError, match=r"SO3Spline\(times\): expected real numbers \(float64\), got str"):
        SO3Spline("01", np.stack([np.eye(3)] * 2))
    with pytest.raises(
        TypeError, match=r"SO3Spline\(rotations\): expected real numbers \(float64\), got dtype complex"
    ):
        SO3Spline([0, 1], np.stack([np.eye(3)] * 2).astype(complex))
    s = SE3Spline([0, 1], g)
    with pytest.raises(ValueError, match=r"SE3Spline\(t\): expected finite times"):
        s.body_velocity([0.5, np.nan])
    with pytest.raises(TypeError, match=r"SE3Spline\(t\): expected real numbers \(float64\), got NoneType"):
        s(None)


# ---- hostile input ------------------------------------------------------------------


def best_time(f, repeats=7):
    """The best of `repeats` timings of one call of f, in seconds."""
    f()
    out = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        f()
        out.append(time.perf_counter() - t0)
    return min(out)


@pytest.mark.parametrize("group", [3, 4])
def test_one_evaluation_does_not_grow_with_the_number_of_keys(group):
    """An evaluation is a binary search plus O(1) work: at 2 10^5 keys it costs
    what it costs at 10 (it copied the 2 10^5 keys per call: ~20 ms, 1000 times
    more). The bound, 20 times, leaves room for a loaded machine and the
    cache misses of the search."""
    rng = np.random.default_rng(30)
    costs = []
    for n in (10, 200_000):
        t = np.cumsum(rng.uniform(0.3, 1.0, n))
        steps = rng.normal(scale=0.3, size=(n, 6))
        if group == 3:
            spline = SO3Spline(t, chasles.so3_exp(np.cumsum(steps[:, 3:], axis=0)))
        else:
            spline = SE3Spline(t, chasles.se3_exp(np.cumsum(steps, axis=0)))
        x = float(t[n // 2] + 0.1)
        costs.append(min(best_time(lambda: spline(x)), best_time(lambda: spline.body_acceleration(x))))
    assert costs[1] < 20 * costs[0], costs


def test_private_gufuncs_read_the_arrays_in_place():
    """10^9 keys as broadcast views (no memory behind them): an evaluation reads
    the key times of its binary search and one key, it does not copy the 10^9."""
    n = 10**9
    times = np.broadcast_to(np.array(0.0), (n,))
    keys = np.broadcast_to(np.eye(3), (n, 3, 3))
    coefficients = np.broadcast_to(np.zeros(9), (n, 9))
    np.testing.assert_array_equal(_core._so3_spline(times, keys, coefficients, 5.5), np.eye(3))
    g = _core._se3_spline_rates(
        times, np.broadcast_to(np.eye(4), (n, 4, 4)), np.broadcast_to(np.zeros(18), (n, 18)), 1.0
    )
    np.testing.assert_array_equal(g[0], np.eye(4))


@pytest.mark.parametrize("fit, k", [("_so3_spline_fit", 3), ("_se3_spline_fit", 4)])
def test_private_fits_refuse_inconsistent_operands(fit, k):
    """n is the times' length: keys of another length (or shape) are refused, not read past their end."""
    f = getattr(_core, fit)
    eye = np.eye(k)
    for times, keys in (
        (np.arange(5.0), np.broadcast_to(eye, (3, k, k))),  # fewer keys than times
        (np.arange(2.0), np.broadcast_to(eye, (3, k, k))),
        (np.arange(5.0), eye),  # one matrix
        (np.arange(5.0), np.zeros((5, k + 1, k + 1))),
        (np.arange(5.0), np.zeros(5 * k * k)),
        (np.arange(6.0).reshape(2, 3), np.broadcast_to(eye, (2, k, k))),
        (np.arange(1.0), np.broadcast_to(eye, (1, k, k))),
    ):
        shapes = rf"got times {re.escape(str(times.shape))} and keys {re.escape(str(keys.shape))}"
        with pytest.raises(
            ValueError, match=rf"{fit}: expected times of shape \(n,\) and keys of shape \(n, {k}, {k}\).*{shapes}"
        ):
            f(times, np.ascontiguousarray(keys), True)


@pytest.mark.parametrize("cls, k", [(SO3Spline, 3), (SE3Spline, 4)])
@pytest.mark.parametrize("h", [1e-160, 1e200, 1e-101])
def test_steps_beyond_the_range_are_refused_naming_the_step(cls, k, h):
    keys = np.stack([np.eye(k)] * 4)
    with pytest.raises(
        ValueError,
        match=rf"{cls.__name__}\(times\): expected time steps between 1e-100 and 1e\+100 "
        rf".*got times\[1\] - times\[0\] = {re.escape(repr(h))}",
    ):
        cls(np.array([0.0, 1.0, 2.0, 3.0]) * h, keys)


@pytest.mark.parametrize("group", [3, 4])
def test_steps_at_the_ends_of_the_range_are_fitted(group):
    rng = np.random.default_rng(31)
    keys = random_rotations(rng, 4) if group == 3 else random_poses(rng, 4)
    cls = SO3Spline if group == 3 else SE3Spline
    for h in (1.5e-100, 1e100 / 1.5):
        t = np.arange(4.0) * h
        s = cls(t, keys)
        assert np.allclose(s(t), keys, rtol=0, atol=1e-12)
        v, a = s.body_velocity(t + h / 2), s.body_acceleration(t + h / 2)
        assert np.isfinite(v).all() and np.isfinite(a).all()
        # the rates scale as 1/h and 1/h^2: the same spline in units of h
        unit = cls(np.arange(4.0), keys)
        assert np.allclose(v * h, unit.body_velocity(np.arange(4.0) + 0.5), rtol=1e-9, atol=1e-9)
        assert np.allclose(a * h * h, unit.body_acceleration(np.arange(4.0) + 0.5), rtol=1e-9, atol=1e-9)


@pytest.mark.parametrize("group", [3, 4])
def test_extrapolation_is_finite_for_every_finite_time(group):
    """The cubic continues 1e6 segment lengths past the end keys, then holds: at
    t = 1e110 the element is a rotation (it was NaN) and the rates are finite."""
    rng = np.random.default_rng(32)
    s = make(group, rng, 5)
    t = s.times
    far = np.array([1e110, -1e110, 1e300, -1e300, np.finfo(float).max, -np.finfo(float).max])
    g, v, a = s(far), s.body_velocity(far), s.body_acceleration(far)
    assert np.isfinite(g).all() and np.isfinite(v).all() and np.isfinite(a).all()
    R = g[..., :3, :3]
    assert np.allclose(R @ np.swapaxes(R, -1, -2), np.eye(3), rtol=0, atol=1e-9)
    # beyond the bound: the values at the bound
    hold_after = t[-1] + 1e6 * (t[-1] - t[-2])
    hold_before = t[0] - 1e6 * (t[1] - t[0])
    np.testing.assert_array_equal(g[0], s(2 * hold_after))
    np.testing.assert_array_equal(v[1], s.body_velocity(2 * hold_before - t[0]))
    # within it the cubic continues (the spline moves on), continuous with the last segment
    x = t[-1] + np.array([1e-9, 1.0, 1.5]) * (t[-1] - t[-2])
    assert not np.array_equal(s(x[1]), s(x[2]))
    assert np.allclose(s(x[0]), s(t[-1]), rtol=0, atol=1e-7)


@pytest.mark.parametrize("cls", [SO3Spline, SE3Spline])
def test_init_again_is_refused(cls):
    rng = np.random.default_rng(33)
    s = make(3 if cls is SO3Spline else 4, rng, 4)
    before = s(s.times)
    with pytest.raises(TypeError, match=rf"{cls.__name__}.__init__: the spline is already initialized"):
        s.__init__(s.times[:2], (s.rotations if cls is SO3Spline else s.poses)[:2])
    assert len(s) == 4
    np.testing.assert_array_equal(s(s.times), before)
    blank = cls.__new__(cls)
    with pytest.raises(TypeError, match=rf"{cls.__name__} object is not initialized"):
        blank(0.5)
    assert repr(blank) == f"<uninitialized {cls.__name__}>"


@pytest.mark.parametrize("ends", ["natural", "chord"])
@pytest.mark.parametrize("group", [3, 4])
def test_pickle_and_copy_bit_for_bit(group, ends):
    rng = np.random.default_rng(34)
    s = make(group, rng, 6, ends=ends)
    t = np.concatenate([s.times, rng.uniform(s.times[0] - 1, s.times[-1] + 1, 20)])
    want = [s(t), s.body_velocity(t), s.body_acceleration(t)]
    copies = [pickle.loads(pickle.dumps(s, protocol=p)) for p in range(pickle.HIGHEST_PROTOCOL + 1)]
    copies += [copy.copy(s), copy.deepcopy(s)]
    for c in copies:
        assert type(c) is type(s) and c is not s and c.ends == ends
        np.testing.assert_array_equal(c.times, s.times)
        for got, w in zip([c(t), c.body_velocity(t), c.body_acceleration(t)], want):
            assert got.tobytes() == w.tobytes()


@pytest.mark.parametrize("cls", [SO3Spline, SE3Spline])
def test_tampered_pickles_are_refused_by_the_constructors_checks(cls):
    rng = np.random.default_rng(35)
    s = make(3 if cls is SO3Spline else 4, rng, 4)
    for attribute, value, match in (
        ("_t", s.times[::-1].copy(), "strictly increasing"),
        ("_t", np.array([0.0, np.nan, 2.0, 3.0]), "finite"),
        ("_keys", np.full_like(s._keys, np.nan), "finite"),
        ("_keys", 2 * s._keys, "is not a"),
        ("_keys", s._keys[:3].copy(), "one per time"),
        ("_ends", "clamped", "natural"),
    ):
        bad = copy.copy(s)
        bad.__dict__[attribute] = value
        for protocol in (0, pickle.HIGHEST_PROTOCOL):
            data = pickle.dumps(bad, protocol=protocol)
            with pytest.raises(ValueError, match=match):
                pickle.loads(data)
