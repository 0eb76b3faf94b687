"""SO2 and SE2 from Python: exp and log against the matrix exponential and
logarithm of the hat matrix in 50-digit arithmetic (mpmath), on both sides of
every threshold; the objects against the array functions (the same bits); the
group laws against numpy; the Jacobians against finite differences; float32,
the value protocol and the errors."""

import copy
import math
import pickle

import mpmath
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import chasles
from chasles import SE2, SO2

EPS = float(np.finfo(np.float64).eps)
EPS32 = float(np.finfo(np.float32).eps)
PI = math.pi
CUT = math.sqrt(6.0554544523933395e-06)  # sqrt(taylor_theta2) in double (constants.hpp)

# Angles at and around every branch: 0, tiny, both sides of the series'
# cutoff, pi/2 (c changes sign: 1 - cos switches form), near and at pi, and
# past pi (exp wraps; log answers in [-pi, pi]).
ANGLES = [0.0, 1e-300, 1e-12, 1e-8, 1e-4, math.nextafter(CUT, 0), math.nextafter(CUT, 1), 0.1, 1.0]
ANGLES += [PI / 2 - 1e-9, PI / 2 + 1e-9, 2.0, 3.0, PI - 1e-6, PI - 1e-12, PI, 4.0, 100.0]
ANGLES += [-a for a in ANGLES]
SIZES = [0.0, 1e-6, 1.0, 1e3]

mpmath.mp.dps = 50


def se2_hat_mp(xi):
    vx, vy, w = (mpmath.mpf(float(x)) for x in xi)
    return mpmath.matrix([[0, -w, vx], [w, 0, vy], [0, 0, 0]])


def to_np(m):
    return np.array([[float(m[i, j]) for j in range(m.cols)] for i in range(m.rows)])


def twists():
    rng = np.random.default_rng(20261127)
    out = []
    for k, a in enumerate(ANGLES):
        d = rng.normal(size=2)
        out.append([*(SIZES[k % 4] * d / np.linalg.norm(d)), a])
    out += [[*rng.normal(size=2) * 10, rng.uniform(-PI, PI)] for _ in range(40)]
    return np.array(out)


def block_error(a, ref, blocks):
    """The largest error of a against ref over blocks of entries, each
    relative to max(1, |ref| over the block), in units of eps."""
    return max(np.max(np.abs(a[b] - ref[b])) / max(1.0, np.max(np.abs(ref[b]))) for b in blocks) / EPS


ROT = (slice(0, 2), slice(0, 2))
TRANS = (slice(0, 2), 2)


@pytest.mark.parametrize("xi", twists().tolist())
def test_se2_exp_is_the_matrix_exponential(xi):
    ref = to_np(mpmath.expm(se2_hat_mp(xi)))
    g = chasles.se2_exp(np.array(xi))
    assert block_error(g, ref, [ROT, TRANS]) <= 4
    assert np.array_equal(g[2], [0.0, 0.0, 1.0])
    assert np.array_equal(SE2.exp(xi).as_matrix(), g)  # the object, the same bits


@pytest.mark.parametrize("theta", ANGLES)
def test_so2_exp_is_the_matrix_exponential(theta):
    w = mpmath.mpf(theta)
    ref = to_np(mpmath.expm(mpmath.matrix([[0, -w], [w, 0]])))
    R = chasles.so2_exp(theta)
    assert np.max(np.abs(R - ref)) <= 1 * EPS
    assert np.array_equal(SO2.exp(theta).as_matrix(), R)


def se2_log_mp(g):
    """vee(log g) of a 3x3 matrix [[A, t], [0, 1]], A = [[c, -s], [s, c]], in
    50 digits: the principal logarithm X = log(r) I + theta J of A (r = |(c, s)|,
    theta = atan2(s, c)) and, since exp([[X, u], [0, 0]]) = [[e^X, (e^X - I) X^-1 u],
    [0, 1]], u = X (A - I)^-1 t. (mpmath.logm takes the wrong branch near
    pi; this is the same matrix function, evaluated exactly.)"""
    c, s, tx, ty = (mpmath.mpf(float(x)) for x in (g[0, 0], g[1, 0], g[0, 2], g[1, 2]))
    theta, rho = mpmath.atan2(s, c), mpmath.log(mpmath.hypot(c, s))
    X = mpmath.matrix([[rho, -theta], [theta, rho]])
    u = X * mpmath.inverse(mpmath.matrix([[c - 1, -s], [s, c - 1]])) * mpmath.matrix([tx, ty])
    return np.array([float(u[0]), float(u[1]), float(theta)])


@pytest.mark.parametrize("xi", twists().tolist())
def test_se2_log_is_the_matrix_logarithm(xi):
    g = chasles.se2_exp(np.array(xi))
    if g[0, 0] == 1.0 and g[1, 0] == 0.0:
        ref = np.array([g[0, 2], g[1, 2], 0.0])  # A = I: log is the translation
    else:
        ref = se2_log_mp(g)
    got = chasles.se2_log(g)
    # 8 eps: SE2's angle and e come from a rational atan of the half angle
    # (include/chasles/so2.hpp, planar_log: within 4.0 eps over 2e6 angles).
    assert np.max(np.abs(got - ref)) / max(1.0, np.max(np.abs(ref))) <= 8 * EPS
    assert np.array_equal(SE2.from_matrix_unchecked(g).log(), got)
    if abs(xi[2]) < PI - 1e-9:  # inside the principal range, log gives back xi itself
        assert np.max(np.abs(got - xi)) / max(1.0, np.max(np.abs(xi))) <= 8 * EPS


def test_log_at_pi():
    R = np.array([[-1.0, 0.0], [0.0, -1.0]])
    assert chasles.so2_log(R) == PI
    g = np.eye(3)
    g[:2, :2] = R
    g[:2, 2] = [3.0, -4.0]
    xi = chasles.se2_log(g)
    assert xi[2] == PI and np.all(np.isfinite(xi))
    assert np.allclose(chasles.se2_exp(xi), g, rtol=0, atol=8 * EPS * 4)


def test_tangent_order_and_hat():
    # (vx, vy, w), linear part first, as SE3 (and manif, jaxlie, gtsam's Pose2).
    assert np.array_equal(SE2.exp([1.0, 2.0, 0.0]).translation, [1.0, 2.0])
    assert np.array_equal(SE2.hat([1.0, 2.0, 3.0]), [[0.0, -3.0, 1.0], [3.0, 0.0, 2.0], [0.0, 0.0, 0.0]])
    assert SO2.hat(0.5).tolist() == [[0.0, -0.5], [0.5, 0.0]]
    assert SO2.vee(SO2.hat(0.5)) == 0.5
    assert np.array_equal(chasles.se2_vee(chasles.se2_hat([1.0, 2.0, 3.0])), [1.0, 2.0, 3.0])
    assert chasles.so2_hat(np.zeros(4)).shape == (4, 2, 2)
    assert chasles.so2_vee(chasles.so2_hat(np.arange(4.0))).tolist() == [0.0, 1.0, 2.0, 3.0]


angles = st.floats(-10.0, 10.0)
coords = st.floats(-100.0, 100.0)
planar_twists = st.tuples(coords, coords, angles).map(np.array)


@settings(max_examples=60, deadline=None)
@given(planar_twists, planar_twists, st.tuples(coords, coords).map(np.array))
def test_group_laws_against_numpy(x, y, p):
    a, b = SE2.exp(x), SE2.exp(y)
    A, B = a.as_matrix(), b.as_matrix()
    scale = 1.0 + np.max(np.abs(A)) + np.max(np.abs(B))
    assert np.allclose((a @ b).as_matrix(), A @ B, rtol=0, atol=16 * EPS * scale * scale)
    assert np.allclose(chasles.se2_compose(A, B), A @ B, rtol=0, atol=16 * EPS * scale * scale)
    assert np.allclose(a.inverse().as_matrix(), np.linalg.inv(A), rtol=0, atol=16 * EPS * scale * scale)
    assert np.allclose(a @ p, (A @ [*p, 1.0])[:2], rtol=0, atol=16 * EPS * scale * (1 + np.max(np.abs(p))))
    assert np.array_equal(chasles.se2_act(A, p), a @ p)
    # The adjoint: a exp(y) a^-1 = exp(Ad_a y).
    lhs = a @ SE2.exp(y) @ a.inverse()
    assert lhs.is_approx(SE2.exp(a.adjoint() @ y), tol=1e-9 * scale)
    # SO2 is the rotation part: composition adds angles.
    r, s = SO2.exp(x[2]), SO2.exp(y[2])
    assert (
        math.isclose((r @ s).log(), math.remainder(x[2] + y[2], 2 * PI), abs_tol=1e-13)
        or abs(abs((r @ s).log()) - PI) < 1e-12
    )
    assert np.array_equal(a.rotation.as_matrix(), A[:2, :2])


def test_jacobians_against_finite_differences():
    rng = np.random.default_rng(3)
    h = 1e-6
    for _ in range(20):
        xi = np.array([*rng.normal(size=2) * 2, rng.uniform(-3, 3)])
        g = SE2.exp(xi)
        Jr = np.column_stack(
            [
                (chasles.rminus(SE2.exp(xi + h * e), g) - chasles.rminus(SE2.exp(xi - h * e), g)) / (2 * h)
                for e in np.eye(3)
            ]
        )
        Jl = np.column_stack(
            [
                (chasles.lminus(SE2.exp(xi + h * e), g) - chasles.lminus(SE2.exp(xi - h * e), g)) / (2 * h)
                for e in np.eye(3)
            ]
        )
        assert np.allclose(SE2.right_jacobian(xi), Jr, atol=1e-8)
        assert np.allclose(SE2.left_jacobian(xi), Jl, atol=1e-8)
        assert np.allclose(SE2.right_jacobian(xi) @ SE2.right_jacobian_inverse(xi), np.eye(3), atol=1e-13)
        assert np.allclose(SE2.left_jacobian(xi) @ SE2.left_jacobian_inverse(xi), np.eye(3), atol=1e-13)
        J_g, J_p = chasles.act_jacobians(g, [0.5, -1.0])
        fd = np.column_stack(
            [
                (chasles.rplus(g, h * e) @ [0.5, -1.0] - chasles.rplus(g, -h * e) @ [0.5, -1.0]) / (2 * h)
                for e in np.eye(3)
            ]
        )
        assert np.allclose(J_g, fd, atol=1e-8) and np.array_equal(J_p, g.as_matrix()[:2, :2])
    assert SO2.right_jacobian(0.7).tolist() == [[1.0]]
    assert chasles.log_jacobian(SO2.exp(1.0)).tolist() == [[1.0]]


def test_generic_functions_take_the_planar_groups():
    a, b = SE2.exp([1.0, 2.0, 0.5]), SE2.exp([-0.3, 0.1, -2.0])
    assert chasles.rplus(b, chasles.rminus(a, b)).is_approx(a, 1e-14)
    assert chasles.lplus(chasles.lminus(a, b), b).is_approx(a, 1e-14)
    assert chasles.between(a, b).is_approx(a.inverse() @ b, 0)
    assert chasles.interpolate(a, b, 1.0).is_approx(b, 1e-14)
    assert (a**0.5 @ a**0.5).is_approx(a, 1e-14)
    r = SO2.exp(3.0)
    assert isinstance(chasles.rminus(r, SO2()), float) and chasles.rminus(r, SO2()) == r.log()
    assert chasles.rplus(SO2(), 0.25).log() == 0.25 and chasles.rplus(SO2(), [0.25]).log() == 0.25
    assert np.array_equal(chasles.interpolate_jacobian_t(a, b, 0.3), chasles.rminus(b, a))


def test_array_functions_broadcast_and_keep_float32():
    rng = np.random.default_rng(5)
    xi = np.column_stack([rng.normal(size=(50, 2)), rng.uniform(-PI, PI, 50)])
    g64 = chasles.se2_exp(xi)
    g32 = chasles.se2_exp(xi.astype(np.float32))
    assert g32.dtype == np.float32 and np.max(np.abs(g32 - g64)) <= 16 * EPS32 * 4
    assert chasles.se2_log(g32).dtype == np.float32
    assert chasles.so2_exp(np.float32(0.5)).dtype == np.float32
    assert chasles.so2_act(chasles.so2_exp(np.zeros((3, 1))), np.ones((4, 2))).shape == (3, 4, 2)
    assert np.array_equal(chasles.se2_inverse(g64), np.array([SE2.exp(x).inverse().as_matrix() for x in xi]))
    assert np.allclose(chasles.se2_interpolate(g64[0], g64[1], 1.0), g64[1], atol=1e-13)
    noisy = g64 + 1e-3 * rng.normal(size=g64.shape)
    fixed = chasles.se2_normalize(noisy)
    assert np.allclose(np.einsum("nji,njk->nik", fixed[:, :2, :2], fixed[:, :2, :2]), np.eye(2), atol=1e-15)
    assert np.array_equal(fixed[:, 2], np.tile([0.0, 0.0, 1.0], (50, 1)))
    assert np.isnan(chasles.so2_normalize(np.full((2, 2), np.nan))).all()


def test_value_protocol():
    g = SE2(SO2.exp(0.3), [1.0, -2.0])
    assert pickle.loads(pickle.dumps(g)) == g and copy.deepcopy(g) == g
    assert pickle.loads(pickle.dumps(SO2.exp(2.0))) == SO2.exp(2.0)
    assert SE2.exp([0.0, 0.0, 1e-20]) != SE2()  # == is exact
    assert repr(SO2.exp(0.5)) == "SO2(theta=0.5)"
    assert repr(SE2(translation=[1.0, 2.0])) == "SE2(rotation=SO2(theta=0.0), translation=[1., 2.])"
    assert np.array_equal(np.asarray(g), g.as_matrix())


def test_errors_name_the_shape():
    with pytest.raises(ValueError, match=r"SO2.exp\(theta\).*shape"):
        SO2.exp([1.0, 2.0])
    with pytest.raises(ValueError, match="finite"):
        SO2.exp(float("nan"))
    with pytest.raises(TypeError, match="real"):
        SO2.exp("a")
    with pytest.raises(ValueError, match=r"SE2.exp\(xi\): expected shape \(3,\)"):
        SE2.exp([1.0, 2.0])
    with pytest.raises(ValueError, match=r"SE2\(translation\): expected shape \(2,\)"):
        SE2(SO2(), [1.0, 2.0, 3.0])
    with pytest.raises(TypeError, match="SE2.from_matrix"):
        SE2(np.eye(3))
    with pytest.raises(ValueError, match="reflection"):
        SO2.from_matrix([[1.0, 0.0], [0.0, -1.0]])
    with pytest.raises(ValueError, match=r"bottom row differs from \(0, 0, 1\)"):
        SE2.from_matrix([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 1.0, 1.0]])
    with pytest.raises(TypeError):
        SE2() @ SO2()
    with pytest.raises(TypeError):
        chasles.rminus(SE2(), SO2())
    with pytest.raises(ValueError, match=r"SE2 @ points: se2_act.*\(3,3\),\(2\)->\(2\)"):
        SE2() @ [1.0, 2.0, 3.0]
    with pytest.raises(ValueError):
        chasles.so2_log(np.eye(3))
