"""SO3BSpline and SE3BSpline: the uniform cumulative cubic B-spline.

References: scipy's Rotation (exp, log and composition, independent of
chasles) for the explicit formula on SO(3); central differences of the
evaluated elements for the body velocity, and of the analytic velocity for
the acceleration; one-parameter subgroups, whose spline is known in closed
form. The C++ suite (tests/cpp/test_bspline.cpp) adds a long double
reference and automatic differentiation.
"""

from __future__ import annotations

import copy
import pickle
import time

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import chasles
from chasles import SE3, SO3, SE3BSpline, SO3BSpline

SPLINES = {SO3BSpline: 3, SE3BSpline: 6}


def control(cls, n, step, seed):
    """n control elements, each a random step (uniform in +-step per tangent
    coordinate) from the one before."""
    rng = np.random.default_rng(seed)
    dof = SPLINES[cls]
    exp = chasles.so3_exp if dof == 3 else chasles.se3_exp
    steps = exp(rng.uniform(-step, step, size=(n, dof)))
    out = [exp(rng.uniform(-2, 2, size=dof))]
    for s in steps[1:]:
        out.append(out[-1] @ s)
    return np.array(out)


def log_of(cls):
    return chasles.so3_log if cls is SO3BSpline else chasles.se3_log


def inverse(m):
    return chasles.so3_inverse(m) if m.shape[-1] == 3 else chasles.se3_inverse(m)


def exp_of(cls):
    return chasles.so3_exp if cls is SO3BSpline else chasles.se3_exp


@pytest.mark.parametrize("cls", SPLINES)
def test_times_properties_and_shapes(cls):
    X = control(cls, 7, 0.8, 1)
    s = cls(-1.0, 0.25, X)
    k = X.shape[-1]
    dof = SPLINES[cls]
    assert (s.start_time, s.spacing, s.end_time) == (-1.0, 0.25, 0.0)
    assert np.array_equal(s.control, X)
    assert repr(s) == f"{cls.__name__}(start_time=-1.0, spacing=0.25, n_control=7)"
    assert s(-0.5).shape == (k, k)
    assert s.body_velocity(-0.5).shape == (dof,)
    t = np.linspace(-1.0, 0.0, 12).reshape(3, 4)
    for f, core in ((s, (k, k)), (s.body_velocity, (dof,)), (s.body_acceleration, (dof,))):
        batch = f(t)
        assert batch.shape == (3, 4) + core and batch.dtype == np.float64
        # one loop over the times: element by element, the same bits
        assert np.array_equal(batch, np.array([f(x) for x in t.ravel()]).reshape(batch.shape))
    assert s(np.zeros((0, 2)) - 0.5).shape == (0, 2, k, k)
    # a NaN time gives NaN in its own element
    r = s.body_velocity([np.nan, -0.5])
    assert np.isnan(r[0]).all() and np.isfinite(r[1]).all()


def test_so3_matches_the_explicit_formula_with_scipy():
    Rotation = pytest.importorskip("scipy.spatial.transform").Rotation
    X = control(SO3BSpline, 8, 1.2, 2)
    s = SO3BSpline(0.5, 0.2, X)
    rng = np.random.default_rng(3)
    for t in rng.uniform(0.5, 0.5 + 5 * 0.2, size=30):
        i = min(int((t - 0.5) / 0.2), 4)
        u = (t - 0.5) / 0.2 - i
        # the ordinary basis b_l(u) (Qin's blending matrix), summed from l = j
        b = np.array([(1 - u) ** 3, 3 * u**3 - 6 * u**2 + 4, -3 * u**3 + 3 * u**2 + 3 * u + 1, u**3]) / 6
        r = Rotation.from_matrix(X[i])
        for j in (1, 2, 3):
            d = (Rotation.from_matrix(X[i + j - 1]).inv() * Rotation.from_matrix(X[i + j])).as_rotvec()
            r = r * Rotation.from_rotvec(b[j:].sum() * d)
        assert np.allclose(s(t), r.as_matrix(), rtol=0, atol=1e-14)


@pytest.mark.parametrize("cls", SPLINES)
def test_rates_match_central_differences(cls):
    X = control(cls, 9, 1.0, 4)
    dt, t0 = 0.4, 2.0
    s = cls(t0, dt, X)
    log = log_of(cls)
    # Times 0.05 dt away from the knots, where the third derivative jumps.
    rng = np.random.default_rng(5)
    t = t0 + dt * (rng.integers(0, 6, size=50) + rng.uniform(0.05, 0.95, size=50))
    h = 1e-5
    Xt, Xp, Xm = s(t), s(t + h), s(t - h)
    Xi = inverse(Xt)
    v_fd = (log(Xi @ Xp) - log(Xi @ Xm)) / (2 * h)
    a_fd = (s.body_velocity(t + h) - s.body_velocity(t - h)) / (2 * h)
    # Central differences: truncation h^2 |f'''| / 6 with |f'''| <~ |d| / dt^3
    # to |d| / dt^4 ~ 300 here (steps |d| <= 1.7, dt = 0.4), so 5e-9, and
    # rounding eps / h ~ 2e-11 times the size of the values (~10): both far
    # below 1e-6; a missing term of the recursion is of order 1.
    assert np.allclose(s.body_velocity(t), v_fd, rtol=0, atol=1e-6)
    assert np.allclose(s.body_acceleration(t), a_fd, rtol=0, atol=1e-6)


@pytest.mark.parametrize("cls", SPLINES)
def test_continuous_to_second_order_across_the_knots(cls):
    X = control(cls, 7, 1.5, 6)
    s = cls(0.0, 0.1, X)
    for k in (1, 2, 3):
        knot = 0.1 * k
        left, right = knot - 1e-9, knot + 1e-9  # 2e-9 apart: values move by ~2e-9 |rate|
        assert np.allclose(s(left), s(right), rtol=0, atol=1e-7)
        assert np.allclose(s.body_velocity(left), s.body_velocity(right), rtol=0, atol=1e-5)
        # the acceleration is continuous too (the jerk jumps: 2e-9 * |jerk| ~ 1e-4 at most)
        assert np.allclose(s.body_acceleration(left), s.body_acceleration(right), rtol=0, atol=1e-3)
        assert not np.allclose(s.body_acceleration(knot - 0.03), s.body_acceleration(knot + 0.03), atol=1e-3)


@pytest.mark.parametrize("cls", SPLINES)
def test_constant_control_is_constant_at_rest(cls):
    X = control(cls, 1, 0.0, 7)
    s = cls(0.0, 1.0, np.repeat(X, 5, axis=0))
    t = np.linspace(0.0, 2.0, 9)
    assert np.allclose(s(t), X[0], rtol=0, atol=1e-14)
    assert np.allclose(s.body_velocity(t), 0, rtol=0, atol=1e-14)
    assert np.allclose(s.body_acceleration(t), 0, rtol=0, atol=1e-14)


@pytest.mark.parametrize(
    "cls, xi",
    [
        (SO3BSpline, [0.8, -1.1, 0.5]),
        (SE3BSpline, chasles.Twist.from_screw([1.0, -2.0, 0.5], [0.3, 0.4, -1.0], 0.37, 1.3).vector),
        (SE3BSpline, [1.5, -0.5, 2.0, 0.0, 0.0, 0.0]),
    ],
)
def test_one_parameter_subgroup_is_that_motion_at_constant_velocity(cls, xi):
    """X_k = X_0 exp(k dt xi): X(t) = X_0 exp((t - t0 + dt) xi), velocity xi,
    acceleration 0 (the cumulative basis sums to u + 1)."""
    xi = np.asarray(xi, dtype=float)
    exp = exp_of(cls)
    X0 = control(cls, 1, 0.0, 8)[0]
    dt, t0 = 0.3, -1.0
    X = X0 @ exp(np.arange(8.0)[:, None] * dt * xi)
    s = cls(t0, dt, X)
    t = np.linspace(t0, s.end_time, 41)
    assert np.allclose(s(t), X0 @ exp((t - t0 + dt)[:, None] * xi), rtol=0, atol=1e-13)
    assert np.allclose(s.body_velocity(t), xi, rtol=0, atol=1e-13)
    assert np.allclose(s.body_acceleration(t), 0, rtol=0, atol=1e-12)


def test_pose_spline_of_pure_rotations_is_the_rotation_spline():
    R = control(SO3BSpline, 6, 1.3, 9)
    g = np.zeros((6, 4, 4))
    g[:, :3, :3], g[:, 3, 3] = R, 1.0
    a, b = SO3BSpline(1.0, 0.3, R), SE3BSpline(1.0, 0.3, g)
    t = np.linspace(1.0, 1.9, 20)
    assert np.allclose(b(t)[:, :3, :3], a(t), rtol=0, atol=1e-15)
    assert np.allclose(b(t)[:, :3, 3], 0, rtol=0, atol=1e-15)
    assert np.allclose(b.body_velocity(t)[:, 3:], a.body_velocity(t), rtol=0, atol=1e-14)
    assert np.allclose(b.body_acceleration(t)[:, 3:], a.body_acceleration(t), rtol=0, atol=1e-13)
    assert np.allclose(b.body_velocity(t)[:, :3], 0, rtol=0, atol=1e-14)


@pytest.mark.parametrize("cls, group", [(SO3BSpline, SO3), (SE3BSpline, SE3)])
def test_control_as_objects_equals_control_as_matrices(cls, group):
    X = control(cls, 5, 1.0, 10)
    objects = [group.from_matrix(m) for m in X]
    a, b = cls(0.0, 1.0, X), cls(0.0, 1.0, objects)
    assert np.array_equal(a.control, b.control)
    assert np.array_equal(a([0.3, 1.7]), b([0.3, 1.7]))


@pytest.mark.parametrize("cls", SPLINES)
def test_float32_input(cls):
    X = control(cls, 6, 1.0, 11)
    s64 = cls(0.0, 0.5, X)
    # float32 matrices hold a rotation to float32's precision only: taken
    # with float32's tolerance and projected to the nearest rotation
    s32 = cls(np.float32(0.0), np.float32(0.5), X.astype(np.float32))
    assert np.abs(s32.control - X).max() < 1e-6
    t = np.linspace(0.0, 1.5, 7)
    assert s32(t).dtype == np.float64
    assert np.allclose(s32(t), s64(t), rtol=0, atol=1e-6)
    assert np.allclose(s32.body_velocity(t), s64.body_velocity(t), rtol=0, atol=1e-5)
    # float32 times: the same numbers in float64
    t32 = t.astype(np.float32)
    assert np.array_equal(s64.body_acceleration(t32), s64.body_acceleration(t32.astype(np.float64)))
    # the same matrices in float64 are held to float64's tolerance
    with pytest.raises(ValueError, match="element 0 is not a"):
        cls(0.0, 0.5, X.astype(np.float32).astype(np.float64) + 1e-6)


@pytest.mark.parametrize("cls", SPLINES)
def test_bad_input(cls):
    name = cls.__name__
    X = control(cls, 5, 1.0, 12)
    k = X.shape[-1]
    with pytest.raises(ValueError, match=rf"{name}\(control\): a cubic B-spline needs N >= 4 control elements, got 3"):
        cls(0.0, 1.0, X[:3])
    with pytest.raises(ValueError, match=rf"{name}\(control\): expected shape \(N, {k}, {k}\).*got \(5, 3\)"):
        cls(0.0, 1.0, np.ones((5, 3)))
    bad = X.copy()
    bad[2, 0, 0] += 0.1
    with pytest.raises(ValueError, match=rf"{name}\(control\): element 2 is not a .*defect 0.1"):
        cls(0.0, 1.0, bad)
    bad[2, 0, 0] = np.nan
    with pytest.raises(ValueError, match="element 2"):
        cls(0.0, 1.0, bad)
    for spacing in (0.0, -1.0):
        with pytest.raises(ValueError, match=rf"{name}\(spacing\): expected a positive spacing \(> 0\)"):
            cls(0.0, spacing, X)
    for spacing in (np.inf, np.nan):
        with pytest.raises(ValueError, match=rf"{name}\(spacing\).*finite"):
            cls(0.0, spacing, X)
    with pytest.raises(ValueError, match=rf"{name}\(start_time\).*finite"):
        cls(np.nan, 1.0, X)
    with pytest.raises(TypeError, match=rf"{name}\(control\): element 1 is a"):
        cls(0.0, 1.0, [SE3() if k == 4 else SO3(), SO3() if k == 4 else SE3()] * 2)
    with pytest.raises(TypeError, match=rf"{name}\(control\)"):
        cls(0.0, 1.0, "abc")
    s = cls(0.0, 1.0, X)
    for f, what in ((s, f"{name}(t)"), (s.body_velocity, f"{name}.body_velocity(t)")):
        with pytest.raises(
            ValueError,
            match=rf"{what}: expected times in \[start_time, end_time\] = \[0.0, 2.0\], got 2.5".replace(
                "(", r"\("
            ).replace(")", r"\)"),
        ):
            f([0.5, 2.5])
        with pytest.raises(ValueError, match="got -inf"):
            f(-np.inf)
        with pytest.raises(TypeError, match=what.replace("(", r"\(").replace(")", r"\)")):
            f(1j)
        with pytest.raises(TypeError):
            f(None)


@pytest.mark.parametrize("cls", SPLINES)
@settings(max_examples=40, deadline=None)
@given(
    seed=st.integers(0, 2**32 - 1),
    step=st.floats(0.0, 2.5),
    spacing=st.floats(1e-3, 1e3),
    u=st.floats(0.0, 1.0),
)
def test_hypothesis_random_control(cls, seed, step, spacing, u):
    """Any control elements (steps up to 2.5 per coordinate, through angles
    near pi): the elements are group elements, the rates finite, and the
    velocity is the difference quotient of the elements at a scale-free step."""
    X = control(cls, 5, step, seed)
    s = cls(10.0, spacing, X)
    t = 10.0 + spacing * 2 * u
    g = s(t)
    R = g[:3, :3]
    assert np.allclose(R.T @ R, np.eye(3), rtol=0, atol=1e-13)
    v, a = s.body_velocity(t), s.body_acceleration(t)
    assert np.isfinite(v).all() and np.isfinite(a).all()
    # The difference quotient over h = 1e-5 spacing, one-sided at the ends.
    h = 1e-5 * spacing
    lo, hi = max(t - h, s.start_time), min(t + h, s.end_time)
    if hi > lo:
        log = log_of(cls)
        gi = inverse(g)
        v_fd = (log(gi @ s(hi)) - log(gi @ s(lo))) / (hi - lo)
        # scale: rates ~ |d| / spacing; first-order error when one-sided
        # (h |a| ~ 1e-5 |d| / spacing) and second-order otherwise
        scale = max(1.0, np.abs(log_of(cls)(inverse(X[:-1]) @ X[1:])).max()) / spacing
        assert np.allclose(v, v_fd, rtol=0, atol=1e-3 * scale)


# ---- hostile input ------------------------------------------------------------------


@pytest.mark.parametrize("cls", SPLINES)
def test_pickle_and_copy_bit_for_bit_with_every_protocol(cls):
    X = control(cls, 7, 1.0, 20)
    s = cls(-0.3, 0.37, X)
    t = np.linspace(s.start_time, s.end_time, 23)
    want = [s(t), s.body_velocity(t), s.body_acceleration(t)]
    copies = [pickle.loads(pickle.dumps(s, protocol=p)) for p in range(pickle.HIGHEST_PROTOCOL + 1)]
    copies += [copy.copy(s), copy.deepcopy(s), copy.deepcopy([s, s])[1]]
    for c in copies:
        assert type(c) is cls and c is not s
        assert (c.start_time, c.spacing, c.end_time) == (s.start_time, s.spacing, s.end_time)
        assert c.control.tobytes() == s.control.tobytes() and repr(c) == repr(s)
        for got, w in zip([c(t), c.body_velocity(t), c.body_acceleration(t)], want):
            assert got.tobytes() == w.tobytes()


class SubSpline(SO3BSpline):
    pass


def test_a_subclass_pickles_as_itself():
    s = SubSpline(0.0, 1.0, control(SO3BSpline, 5, 1.0, 21))
    c = pickle.loads(pickle.dumps(s, protocol=0))
    assert type(c) is SubSpline and c(1.5).tobytes() == s(1.5).tobytes()


@pytest.mark.parametrize("cls", SPLINES)
def test_tampered_pickles_are_refused_by_the_constructors_checks(cls):
    name = cls.__name__
    X = control(cls, 6, 1.0, 22)
    s = cls(0.0, 0.5, X)
    nan = X.copy()
    nan[3, 1, 1] = np.nan
    skew = X.copy()
    skew[2, 0, 0] += 0.1
    for attribute, value, error, match in (
        ("_control", nan, ValueError, rf"{name}\(control\): element 3"),
        ("_control", skew, ValueError, rf"{name}\(control\): element 2 is not a"),
        ("_control", X[:3].copy(), ValueError, "N >= 4"),
        ("_control", X[:, :2], ValueError, "expected shape"),
        ("_spacing", -0.5, ValueError, rf"{name}\(spacing\): expected a positive spacing"),
        ("_spacing", np.nan, ValueError, rf"{name}\(spacing\).*finite"),
        ("_start_time", np.inf, ValueError, rf"{name}\(start_time\).*finite"),
        ("_start_time", "0", TypeError, rf"{name}\(start_time\)"),
    ):
        bad = copy.copy(s)
        bad.__dict__[attribute] = value
        for protocol in range(pickle.HIGHEST_PROTOCOL + 1):
            data = pickle.dumps(bad, protocol=protocol)
            with pytest.raises(error, match=match):
                pickle.loads(data)


@pytest.mark.parametrize("cls", SPLINES)
def test_init_again_is_refused(cls):
    X = control(cls, 5, 1.0, 23)
    s = cls(0.0, 1.0, X)
    with pytest.raises(TypeError, match=rf"{cls.__name__}.__init__: the spline is already initialized"):
        s.__init__(5.0, 2.0, X[::-1])
    assert (s.start_time, s.spacing) == (0.0, 1.0)
    assert np.array_equal(s.control, X)
    blank = cls.__new__(cls)
    assert repr(blank) == f"<uninitialized {cls.__name__}>"
    for f in (lambda: blank(0.5), lambda: blank.body_velocity(0.5), lambda: blank.start_time, lambda: blank.control):
        with pytest.raises(TypeError, match=rf"{cls.__name__} object is not initialized"):
            f()
    blank.__init__(0.0, 1.0, X)  # the first __init__ of an object made by __new__
    assert blank(1.5).tobytes() == s(1.5).tobytes()


@pytest.mark.parametrize("cls", SPLINES)
def test_one_evaluation_does_not_grow_with_the_number_of_control_elements(cls):
    """An evaluation reads the four control elements of its segment: at 2 10^5
    elements it costs what it costs at 10 (it copied them all per call, ~5 ms)."""
    costs = []
    for n in (10, 200_000):
        s = cls(0.0, 1.0, control(cls, n, 0.3, 24))
        x = n / 2 + 0.1

        def one():
            return s.body_acceleration(x)

        one()
        out = []
        for _ in range(7):
            t0 = time.perf_counter()
            one()
            out.append(time.perf_counter() - t0)
        costs.append(min(out))
    assert costs[1] < 20 * costs[0], costs


@pytest.mark.parametrize("name, k", [("so3", 3), ("se3", 4)])
def test_private_gufuncs_refuse_inconsistent_operands(name, k):
    element = getattr(chasles._core, f"_{name}_bspline")
    rates = getattr(chasles._core, f"_{name}_bspline_rates")
    good = np.ascontiguousarray(np.broadcast_to(np.eye(k), (5, k, k)))
    assert element(0.0, 1.0, good, 0.5).shape == (k, k)
    # operands that make no spline (N < 4, a spacing that is not finite and > 0): NaN results, nothing read
    for spacing, control in ((1.0, good[:3]), (0.0, good), (-1.0, good), (np.inf, good), (np.nan, good)):
        assert np.isnan(element(0.0, spacing, control, 0.5)).all()
        assert all(np.isnan(r).all() for r in rates(0.0, spacing, control, 0.5))
    # numpy checks that the operands agree on their core dimensions
    for bad in (good[:, :2], good[0], np.zeros((5, k + 1, k + 1))):
        with pytest.raises(ValueError):
            element(0.0, 1.0, bad, 0.5)
