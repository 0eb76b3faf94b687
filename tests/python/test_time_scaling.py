"""chasles.time_scaling and chasles.joint_trajectory: the cubic, quintic and
trapezoidal time scalings of a rest-to-rest motion and the straight-line
joint trajectory they time (include/chasles/time_scaling.hpp, Modern
Robotics ch. 9.2).

Checked against the modern_robotics package (CubicTimeScaling,
QuinticTimeScaling, JointTrajectory and their docstrings' printed numbers),
against Modern Robotics' trapezoid formulas (eq. 9.16-9.18, written here
from the book), the derivatives against numpy's finite differences, the
boundary conditions, the peaks, broadcasting, and every error message.
"""

from __future__ import annotations

import math
from fractions import Fraction

import modern_robotics as mr
import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

import chasles
from chasles import _core

EPS = np.finfo(np.float64).eps
KINDS = ("cubic", "quintic", "trapezoidal")

durations = st.floats(1e-3, 1e3)
fractions = st.floats(0.0, 1.0)
ratios = st.floats(1.0, 2.0, exclude_min=True)


def scaling(t, T, kind, k=None):
    """time_scaling as a tuple of float64 arrays."""
    return tuple(np.asarray(x) for x in chasles.time_scaling(t, T, kind, k))


# ---- Modern Robotics ---------------------------------------------------------------------


def test_modern_robotics_docstring_examples():
    assert math.isclose(chasles.time_scaling(0.6, 2.0, "cubic").s, 0.216, rel_tol=1e-15)
    assert math.isclose(chasles.time_scaling(0.6, 2.0, "quintic").s, 0.16308, rel_tol=1e-15)
    start = np.array([1, 0, 0, 1, 1, 0.2, 0, 1])
    end = np.array([1.2, 0.5, 0.6, 1.1, 2, 2, 0.9, 1])
    printed = np.array(
        [
            [1, 0, 0, 1, 1, 0.2, 0, 1],
            [1.0208, 0.052, 0.0624, 1.0104, 1.104, 0.3872, 0.0936, 1],
            [1.0704, 0.176, 0.2112, 1.0352, 1.352, 0.8336, 0.3168, 1],
            [1.1296, 0.324, 0.3888, 1.0648, 1.648, 1.3664, 0.5832, 1],
            [1.1792, 0.448, 0.5376, 1.0896, 1.896, 1.8128, 0.8064, 1],
            [1.2, 0.5, 0.6, 1.1, 2, 2, 0.9, 1],
        ]
    )
    # the documented equivalent of JointTrajectory(thetastart, thetaend, Tf, N, 3)
    q = chasles.joint_trajectory(start, end, np.linspace(0, 4, 6), 4, "cubic").q
    np.testing.assert_allclose(q, printed, rtol=0, atol=4 * EPS)
    np.testing.assert_allclose(q, mr.JointTrajectory(start, end, 4, 6, 3), rtol=0, atol=4 * EPS)
    assert np.array_equal(q[0], start) and np.array_equal(q[-1], end)


@given(T=durations, u=fractions)
def test_cubic_and_quintic_equal_modern_robotics(T, u):
    """To the rounding of both: a few ulps (MR's powers lose up to 12 ulps
    near r = 1, where the quintic's terms cancel; chasles' Horner form 6:
    test_polynomials_to_their_rounding)."""
    t = u * T
    assert abs(chasles.time_scaling(t, T, "cubic").s - mr.CubicTimeScaling(T, t)) <= 4 * EPS
    assert abs(chasles.time_scaling(t, T, "quintic").s - mr.QuinticTimeScaling(T, t)) <= 24 * EPS


@given(r=st.lists(fractions, min_size=1, max_size=20))
def test_polynomials_to_their_rounding(r):
    """s, s_dot and s_ddot at T = 1 against exact rational arithmetic:
    within an ulp or two of 1 for the cubic, 8 for the quintic (Horner's
    form, whose terms cancel near r = 1 to a sum of 1)."""
    exact = {
        "cubic": lambda q: (3 * q**2 - 2 * q**3, 6 * q * (1 - q), 6 * (1 - 2 * q)),
        "quintic": lambda q: (
            10 * q**3 - 15 * q**4 + 6 * q**5,
            30 * q**2 * (1 - q) ** 2,
            60 * q * (1 - q) * (1 - 2 * q),
        ),
    }
    for kind, ulps in (("cubic", 2), ("quintic", 8)):
        got = scaling(np.array(r), 1.0, kind)
        for i, x in enumerate(r):
            want = exact[kind](Fraction(x))
            for j, scale in enumerate((1, 2, 6)):  # (the bounds of |s|, |s_dot|, |s_ddot|)
                assert abs(got[j][i] - float(want[j])) <= ulps * scale * EPS, (kind, x, j)


@given(
    start=st.lists(st.floats(-10, 10), min_size=1, max_size=8),
    shift=st.floats(-10, 10),
    T=durations,
    N=st.integers(2, 50),
    method=st.sampled_from([3, 5]),
)
def test_joint_trajectory_equals_modern_robotics(start, shift, T, N, method):
    start = np.array(start)
    end = start[::-1] + shift
    expected = mr.JointTrajectory(start, end, T, N, method)
    kind = "cubic" if method == 3 else "quintic"
    times = np.arange(N) * (T / (N - 1.0))  # JointTrajectory's times, timegap * i
    scale = max(1.0, np.abs(start).max(), np.abs(end).max())
    # s to a few ulps (above) times |end - start| <= 2 scale, and the interpolations' rounding
    tolerance = (2 * (4 if kind == "cubic" else 24) + 4) * EPS * scale
    q = chasles.joint_trajectory(start, end, times, T, kind).q
    assert q.shape == (N, len(start))
    np.testing.assert_allclose(q, expected, rtol=0, atol=tolerance)
    # np.linspace(0, T, N), the documented equivalent: the same times to an ulp
    q = chasles.joint_trajectory(start, end, np.linspace(0, T, N), T, kind).q
    np.testing.assert_allclose(q, expected, rtol=0, atol=tolerance + 4 * EPS * scale)


# ---- the polynomials and the trapezoid ------------------------------------------------------


def trapezoid_modern_robotics(t, T, k):
    """Modern Robotics eq. 9.16-9.18 for the peak velocity v = k / T and
    a = v^2 / (v T - 1): s, s_dot, s_ddot."""
    v = k / T
    a = v * v / (v * T - 1)
    if t <= v / a:
        return a * t * t / 2, a * t, a
    if t <= T - v / a:
        return v * t - v * v / (2 * a), v, 0.0
    return (2 * a * v * T - 2 * v * v - a * a * (t - T) ** 2) / (2 * a), a * (T - t), -a


@given(T=durations, u=fractions, k=st.floats(1.01, 2.0))
def test_trapezoid_equals_modern_robotics_formulas(T, u, k):
    """(k >= 1.01: MR's v T - 1 = k - 1 loses digits as k -> 1.)"""
    t = u * T
    s, s_dot, s_ddot = scaling(t, T, "trapezoidal", k)
    want = trapezoid_modern_robotics(t, T, k)
    v, a = k / T, k * k / ((k - 1) * T * T)
    assert abs(s - want[0]) <= 1e-14
    assert abs(s_dot - want[1]) <= 1e-13 * v
    switching = min(abs(u - (k - 1) / k), abs(u - 1 / k)) < 1e-12
    if not switching:  # (where MR's branches and chasles' may pick either side of the jump)
        assert abs(s_ddot - want[2]) <= 1e-13 * a


@given(T=durations, k=st.floats(1.001, 2.0))
def test_trapezoid_peak_velocity_and_acceleration(T, k):
    """The cruise at v = k / T, the acceleration a = k^2 / ((k - 1) T^2)
    for T (k - 1) / k at each end (MR's a = v^2 / (v T - 1)). (k >= 1.001:
    the times below are then on their side of the switching instants after
    rounding.)"""
    ramp = T * (k - 1) / k
    t = np.array([0.0, ramp / 2, ramp * 0.999, (ramp + T - ramp) / 2, T - ramp / 2, T])
    s, s_dot, s_ddot = scaling(t, T, "trapezoidal", k)
    v, a = k / T, k * k / ((k - 1) * T * T)
    np.testing.assert_allclose(s_dot.max(), v, rtol=1e-12)
    np.testing.assert_allclose(s_ddot[[0, 1, 2]], a, rtol=1e-12)
    np.testing.assert_allclose(s_ddot[[4, 5]], -a, rtol=1e-12)
    np.testing.assert_allclose(a, v * v / (v * T - 1), rtol=1e-12)
    assert s[0] == 0 and s[-1] == 1 and s_dot[0] == 0 and s_dot[-1] == 0
    # the middle of the motion cruises at v (for k < 2; k = 2 is the triangle)
    if k < 2 - 1e-9:
        assert s_ddot[3] == 0 and math.isclose(s_dot[3], v, rel_tol=1e-12)


def test_triangle_profile():
    T = 2.0
    s, s_dot, s_ddot = scaling(np.array([0.0, 0.5, 1.0, 1.5, 2.0]), T, "trapezoidal", 2.0)
    np.testing.assert_allclose(s, [0.0, 0.125, 0.5, 0.875, 1.0], rtol=0, atol=EPS)
    np.testing.assert_allclose(s_dot, [0.0, 0.5, 1.0, 0.5, 0.0], rtol=0, atol=EPS)  # peak 2 / T at T / 2
    np.testing.assert_allclose(s_ddot, [1.0, 1.0, 0.0, -1.0, -1.0], rtol=0, atol=EPS)  # a = 4 / T^2


@pytest.mark.parametrize("kind", KINDS)
def test_boundary_conditions_and_rest_outside(kind):
    T, k = 3.0, 1.25
    t = np.array([-np.inf, -1e300, -1.0, -0.0, 0.0, T, 4.0, 1e300, np.inf])
    s, s_dot, s_ddot = scaling(t, T, kind, k)
    np.testing.assert_array_equal(s, [0, 0, 0, 0, 0, 1, 1, 1, 1])
    np.testing.assert_array_equal(s_dot, 0)
    outside = [0, 1, 2, 6, 7, 8]
    np.testing.assert_array_equal(s_ddot[outside], 0)
    if kind == "quintic":
        np.testing.assert_array_equal(s_ddot, 0)  # zero acceleration at both ends too
    if kind == "cubic":
        np.testing.assert_array_equal(s_ddot[[4, 5]], [6 / T**2, -6 / T**2])


@pytest.mark.parametrize("kind,peak", [("cubic", 1.5), ("quintic", 1.875), ("trapezoidal", 1.7)])
def test_monotone_symmetric_and_peak_at_mid_motion(kind, peak):
    T = 2.5
    t = np.linspace(0.0, T, 1001)  # (no point at the trapezoid's switching instants, T 0.7 / 1.7 and T / 1.7)
    s, s_dot, s_ddot = scaling(t, T, kind, 1.7)
    assert np.all(np.diff(s) >= 0) and np.all(s_dot >= 0) and s.min() == 0 and s.max() == 1
    np.testing.assert_allclose(s + s[::-1], 1.0, rtol=0, atol=16 * EPS)  # s(T - t) = 1 - s(t)
    np.testing.assert_allclose(s_dot, s_dot[::-1], rtol=0, atol=1e-14)
    np.testing.assert_allclose(s_ddot[1:-1], -s_ddot[1:-1][::-1], rtol=0, atol=1e-13)
    assert math.isclose(s_dot[500], peak / T, rel_tol=1e-15) and math.isclose(s[500], 0.5, rel_tol=1e-15)
    assert math.isclose(s_dot.max(), peak / T, rel_tol=1e-15)


@given(T=st.floats(0.1, 100.0), u=st.floats(0.001, 0.999), kind=st.sampled_from(KINDS), k=st.floats(1.05, 2.0))
def test_derivatives_equal_finite_differences(T, u, kind, k):
    """Central differences of s and s_dot at h = 1e-6 T: O(h^2) truncation
    plus rounding eps / h (away from the trapezoid's switching instants,
    where s_ddot jumps)."""
    t, h = u * T, 1e-6 * T
    if kind == "trapezoidal" and min(abs(u - (k - 1) / k), abs(u - 1 / k)) < 2e-6:
        return
    s, s_dot, s_ddot = scaling(np.array([t - h, t, t + h]), T, kind, k)
    dsdt = (s[2] - s[0]) / (2 * h)
    dsdt2 = (s_dot[2] - s_dot[0]) / (2 * h)
    scale = 1 / T if kind != "trapezoidal" else k * k / (k - 1) / T
    np.testing.assert_allclose(dsdt, s_dot[1], rtol=0, atol=1e-8 * scale)
    np.testing.assert_allclose(dsdt2, s_ddot[1], rtol=0, atol=1e-8 * scale / T)


@pytest.mark.parametrize("kind", KINDS)
def test_gradients_on_a_grid(kind):
    """numpy.gradient of s on a fine grid is s_dot, of s_dot is s_ddot
    (second-order differences, one-sided at the ends)."""
    T, k = 2.0, 1.5
    t = np.linspace(0.0, T, 20001)
    s, s_dot, s_ddot = scaling(t, T, kind, k)
    smooth = np.ones(t.shape, bool)
    smooth[[0, -1]] = False
    if kind == "trapezoidal":  # s_ddot jumps at T (k - 1) / k and T / k
        for switch in (T * (k - 1) / k, T / k):
            smooth &= np.abs(t - switch) > 2 * (t[1] - t[0])
    np.testing.assert_allclose(np.gradient(s, t)[smooth], s_dot[smooth], rtol=0, atol=1e-7)
    np.testing.assert_allclose(np.gradient(s_dot, t)[smooth], s_ddot[smooth], rtol=0, atol=1e-6)


# ---- joint trajectories ---------------------------------------------------------------------


@given(
    q0=st.lists(st.floats(-100, 100), min_size=1, max_size=7),
    T=durations,
    u=st.floats(-0.5, 1.5),
    kind=st.sampled_from(KINDS),
    k=ratios,
)
def test_joint_trajectory_is_the_time_scaling_of_the_straight_line(q0, T, u, kind, k):
    q0 = np.array(q0)
    q1 = np.cos(q0) * 3
    d = q1 - q0
    t = u * T
    s, s_dot, s_ddot = chasles.time_scaling(t, T, kind, k)
    q, qd, qdd = chasles.joint_trajectory(q0, q1, t, T, kind, k)
    np.testing.assert_array_equal(qd, s_dot * d)
    np.testing.assert_array_equal(qdd, s_ddot * d)
    np.testing.assert_allclose(q, q0 + s * d, rtol=0, atol=4 * EPS * np.abs([q0, q1]).max())
    if u <= 0:
        np.testing.assert_array_equal(q, q0)
    if u >= 1:
        np.testing.assert_array_equal(q, q1)


def test_joint_trajectory_ends_exactly_at_its_ends():
    q0, q1 = np.array([0.1, -2.0, 1e-17, 3.0]), np.array([0.7, 1.0 / 3.0, -5.0, 3.0])
    for kind in KINDS:
        q, qd, qdd = chasles.joint_trajectory(q0, q1, [-1.0, 0.0, 1.7, 2.0], 1.7, kind, 1.5)
        assert np.array_equal(q[:2], [q0, q0]) and np.array_equal(q[2:], [q1, q1])
        assert np.array_equal(qd[[0, 1, 3]], np.zeros((3, 4)))
        assert np.all(qd[:, 3] == 0) and np.all(qdd[:, 3] == 0)  # a joint that does not move


def test_broadcasting():
    t = np.linspace(0.0, 2.0, 5)
    r = chasles.time_scaling(t[:, None], np.array([1.0, 2.0, 4.0]), "quintic")
    assert all(x.shape == (5, 3) for x in r)
    np.testing.assert_array_equal(r.s[:, 1], chasles.time_scaling(t, 2.0).s)
    r = chasles.time_scaling(t, 2.0, "trapezoidal", np.array([[1.25], [2.0]]))
    assert all(x.shape == (2, 5) for x in r)
    np.testing.assert_array_equal(r.s_dot[1], chasles.time_scaling(t, 2.0, "trapezoidal", 2.0).s_dot)
    # scalars give numpy float64 scalars, as a ufunc
    s = chasles.time_scaling(0.5, 1)
    assert type(s) is chasles._results.TimeScalingResult and all(type(x) is np.float64 for x in s)
    # joint vectors (2, 1, n) against times (5,): (2, 5, n)
    q0 = np.array([[[0.0, 1.0, 2.0]], [[3.0, 4.0, 5.0]]])
    r = chasles.joint_trajectory(q0, np.zeros(3), t, 2.0)
    assert type(r) is chasles._results.JointTrajectoryResult and all(x.shape == (2, 5, 3) for x in r)
    np.testing.assert_array_equal(r.q[1], chasles.joint_trajectory(q0[1, 0], np.zeros(3), t, 2.0).q)
    # zero-size batches and zero joints
    assert all(x.shape == (0, 3) for x in chasles.joint_trajectory(q0[0, 0], np.ones(3), np.zeros(0), 1.0))
    assert all(x.shape == (5, 0) for x in chasles.joint_trajectory(np.zeros(0), np.zeros(0), t, 1.0))
    assert all(x.shape == (2, 0) for x in chasles.time_scaling(np.zeros((2, 0)), 1.0))


def test_any_real_dtype_is_read_as_float64():
    t = np.array([0, 1, 2, 3], dtype=np.int16)
    want = chasles.time_scaling(t.astype(float), 3.0, "cubic")
    for x in (t, t.astype(np.float32), t.tolist(), np.asfortranarray(t.reshape(2, 2)).reshape(4)):
        got = chasles.time_scaling(x, np.float32(3.0), "cubic")
        for a, b in zip(got, want):
            assert a.dtype == np.float64
            np.testing.assert_array_equal(a, b)
    q = chasles.joint_trajectory(np.array([0, 1], np.int8), [True, False], np.float16(0.5), 1)
    assert q.q.dtype == np.float64 and np.array_equal(q.q, chasles.joint_trajectory([0.0, 1.0], [1.0, 0.0], 0.5, 1.0).q)


def test_the_trapezoid_reads_its_ratio_the_others_do_not():
    t = np.linspace(0, 1, 7)
    assert not np.array_equal(chasles.time_scaling(t, 1.0, "trapezoidal", 1.2).s, chasles.time_scaling(t, 1.0).s)
    for kind in ("cubic", "quintic"):
        np.testing.assert_array_equal(
            chasles.time_scaling(t, 1.0, kind, "not read").s, chasles.time_scaling(t, 1.0, kind).s
        )
    assert chasles.time_scaling(t, 1.0, peak_velocity_ratio=5.0).s.shape == (7,)


# ---- errors ----------------------------------------------------------------------------------

T7 = np.linspace(0.0, 1.0, 7)
Q0, Q1 = np.zeros(3), np.ones(3)

ERRORS = [
    # time_scaling: kind, t, duration, peak_velocity_ratio, shapes
    (lambda: chasles.time_scaling(T7, 1.0, "septic"), ValueError,
     r"^time_scaling\(kind\): expected 'cubic', 'quintic' or 'trapezoidal', got 'septic'$"),
    (lambda: chasles.time_scaling(T7, 1.0, 5), TypeError,
     r"^time_scaling\(kind\): expected a str, 'cubic', 'quintic' or 'trapezoidal', got int$"),
    (lambda: chasles.time_scaling(T7, 1.0, None), TypeError, r"^time_scaling\(kind\): expected a str, .*got NoneType$"),
    (lambda: chasles.time_scaling([0.0, np.nan], 1.0), ValueError,
     r"^time_scaling\(t\): expected times that are not NaN .*, got t\[1\] = nan$"),
    (lambda: chasles.time_scaling(np.nan, 1.0), ValueError,
     r"^time_scaling\(t\): expected times that are not NaN .*got nan$"),
    (lambda: chasles.time_scaling("0.5", 1.0), TypeError,
     r"^time_scaling\(t\): expected real numbers \(float64\), got str$"),
    (lambda: chasles.time_scaling([1j], 1.0), TypeError,
     r"^time_scaling\(t\): expected real numbers \(float64\), got dtype complex128$"),
    (lambda: chasles.time_scaling([[0.0], [0.0, 1.0]], 1.0), ValueError,
     r"^time_scaling\(t\): could not convert to an array"),
    (lambda: chasles.time_scaling(T7, 0.0), ValueError,
     r"^time_scaling\(duration\): expected durations that are finite and > 0, got 0.0$"),
    (lambda: chasles.time_scaling(T7, [1.0, -2.0]), ValueError,
     r"^time_scaling\(duration\): expected durations that are finite and > 0, got duration\[1\] = -2.0$"),
    (lambda: chasles.time_scaling(T7, np.inf), ValueError, r"^time_scaling\(duration\): .*finite and > 0, got inf$"),
    (lambda: chasles.time_scaling(T7, np.nan), ValueError, r"^time_scaling\(duration\): .*finite and > 0, got nan$"),
    (lambda: chasles.time_scaling(T7, None), TypeError, r"^time_scaling\(duration\): expected real numbers"),
    (lambda: chasles.time_scaling(T7, 1.0, "trapezoidal"), ValueError,
     r"^time_scaling\(peak_velocity_ratio\): required for kind='trapezoidal': .*in \(1, 2\]$"),
    (lambda: chasles.time_scaling(T7, 1.0, "trapezoidal", 1.0), ValueError,
     r"^time_scaling\(peak_velocity_ratio\): expected ratios .* in \(1, 2\] .*got 1.0$"),
    (lambda: chasles.time_scaling(T7, 1.0, "trapezoidal", [1.5, 2.5]), ValueError,
     r"^time_scaling\(peak_velocity_ratio\): .*got peak_velocity_ratio\[1\] = 2.5$"),
    (lambda: chasles.time_scaling(T7, 1.0, "trapezoidal", np.nan), ValueError,
     r"^time_scaling\(peak_velocity_ratio\): .*got nan$"),
    (lambda: chasles.time_scaling(T7, 1.0, "trapezoidal", "1.5"), TypeError,
     r"^time_scaling\(peak_velocity_ratio\): expected real numbers \(float64\), got str$"),
    (lambda: chasles.time_scaling(T7, [1.0, 2.0]), ValueError,
     r"^time_scaling\(t, duration\): expected shapes that broadcast together, got t \(7,\), duration \(2,\)$"),
    (lambda: chasles.time_scaling(T7, 1.0, "trapezoidal", [1.5, 2.0]), ValueError,
     r"^time_scaling\(t, duration, peak_velocity_ratio\): expected shapes that broadcast together, "
     r"got t \(7,\), duration \(\), peak_velocity_ratio \(2,\)$"),
    # joint_trajectory: the joint vectors, then as time_scaling
    (lambda: chasles.joint_trajectory(0.0, 1.0, T7, 1.0), ValueError,
     r"^joint_trajectory\(q_start\): expected shape \(n,\) or \(\.\.\., n\), got \(\)$"),
    (lambda: chasles.joint_trajectory(Q0, 1.0, T7, 1.0), ValueError,
     r"^joint_trajectory\(q_end\): expected shape \(n,\) or \(\.\.\., n\), got \(\)$"),
    (lambda: chasles.joint_trajectory(np.zeros(33), np.zeros(33), T7, 1.0), ValueError,
     r"^joint_trajectory\(q_start\): expected at most 32 joints \(a Chain's bound\), got 33$"),
    (lambda: chasles.joint_trajectory(Q0, [[0.0, 1.0, np.inf]], T7, 1.0), ValueError,
     r"^joint_trajectory\(q_end\): expected finite numbers, got q_end\[0, 2\] = inf$"),
    (lambda: chasles.joint_trajectory([np.nan, 0, 0], Q1, T7, 1.0), ValueError,
     r"^joint_trajectory\(q_start\): expected finite numbers, got q_start\[0\] = nan$"),
    (lambda: chasles.joint_trajectory(Q0, np.ones(2), T7, 1.0), ValueError,
     r"^joint_trajectory\(q_start, q_end\): expected the same number of joints, got 3 and 2$"),
    (lambda: chasles.joint_trajectory(["a", "b", "c"], Q1, T7, 1.0), TypeError,
     r"^joint_trajectory\(q_start\): expected real numbers \(float64\), got dtype <U1$"),
    (lambda: chasles.joint_trajectory(np.zeros((2, 3)), Q1, T7, 1.0), ValueError,
     r"^joint_trajectory\(q_start, q_end, t, duration\): expected shapes that broadcast together \(the joint "
     r"vectors' leading axes: all but the last\), got q_start \(2, 3\), q_end \(3,\), t \(7,\), duration \(\)$"),
    (lambda: chasles.joint_trajectory(Q0, Q1, [np.nan], 1.0), ValueError,
     r"^joint_trajectory\(t\): expected times that are not NaN"),
    (lambda: chasles.joint_trajectory(Q0, Q1, T7, -1.0), ValueError,
     r"^joint_trajectory\(duration\): expected durations that are finite and > 0, got -1.0$"),
    (lambda: chasles.joint_trajectory(Q0, Q1, T7, 1.0, "Cubic"), ValueError,
     r"^joint_trajectory\(kind\): expected 'cubic', 'quintic' or 'trapezoidal', got 'Cubic'$"),
    (lambda: chasles.joint_trajectory(Q0, Q1, T7, 1.0, b"cubic"), TypeError,
     r"^joint_trajectory\(kind\): expected a str, .*got bytes$"),
    (lambda: chasles.joint_trajectory(Q0, Q1, T7, 1.0, "trapezoidal"), ValueError,
     r"^joint_trajectory\(peak_velocity_ratio\): required for kind='trapezoidal'"),
    (lambda: chasles.joint_trajectory(Q0, Q1, T7, 1.0, "trapezoidal", 3.0), ValueError,
     r"^joint_trajectory\(peak_velocity_ratio\): expected ratios .*in \(1, 2\] .*got 3.0$"),
    (lambda: chasles.joint_trajectory(Q0, Q1, T7, 1.0, "trapezoidal", np.full(3, 1.5)), ValueError,
     r"^joint_trajectory\(q_start, q_end, t, duration, peak_velocity_ratio\): expected shapes that broadcast"),
    # Python's own refusals of the call
    (lambda: chasles.time_scaling(T7), TypeError, r"duration"),
    (lambda: chasles.joint_trajectory(Q0, Q1, T7, 1.0, "cubic", None, 1), TypeError, r"positional"),
]  # fmt: skip


@pytest.mark.parametrize("call,error,message", ERRORS, ids=[m[:60] for _, _, m in ERRORS])
def test_errors_name_the_function_and_the_argument(call, error, message):
    with pytest.raises(error, match=message):
        call()


# ---- the private gufuncs ---------------------------------------------------------------------


def test_private_gufuncs_give_nan_for_what_the_python_functions_refuse():
    nan3 = np.full(3, np.nan)
    for kind in (np.intc(-1), np.intc(3)):
        assert np.isnan(_core._time_scaling(kind, 1.0, 1.5, 0.5)).all()
    for duration in (0.0, -1.0, np.inf, np.nan):
        assert np.isnan(_core._time_scaling(np.intc(1), duration, np.nan, 0.5)).all()
    for ratio in (1.0, 2.5, np.nan):
        assert np.isnan(_core._time_scaling(np.intc(2), 1.0, ratio, 0.5)).all()
    assert np.isnan(_core._time_scaling(np.intc(0), 1.0, np.nan, np.nan)).all()
    q, qd, qdd = _core._joint_trajectory(np.zeros(33), np.ones(33), np.intc(1), 1.0, np.nan, 0.5)
    assert np.isnan(q).all() and np.isnan(qd).all() and np.isnan(qdd).all()
    q, qd, qdd = _core._joint_trajectory(np.zeros(3), np.ones(3), np.intc(7), 1.0, np.nan, 0.5)
    assert np.array_equal(q, nan3, equal_nan=True) and np.array_equal(qdd, nan3, equal_nan=True)


def test_private_gufuncs_run_each_kind_once_per_run_of_equal_codes():
    """The kind operand broadcasts as any other: a batch of mixed kinds gives
    each element its own kind's scaling."""
    kinds = np.array([0, 1, 2, 2, 0, 1], dtype=np.intc)
    t = np.linspace(0.1, 0.9, 6)
    s = _core._time_scaling(kinds, 1.0, 1.5, t)[0]
    for i, code in enumerate(kinds):
        assert s[i] == chasles.time_scaling(t[i], 1.0, KINDS[code], 1.5).s
