"""SE23 (SE_2(3), extended poses) from Python: exp against the matrix
exponential of the 5x5 hat matrix in 50-digit arithmetic (mpmath) over a grid
of rotation angles that crosses the series cutoff and reaches pi, with
position and velocity parts of four sizes; log against exp; the objects
against the array functions (the same bits); the group laws against numpy;
the Jacobians against finite differences; float32 batches; the value
protocol and the errors."""

import copy
import math
import pickle

import mpmath
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import chasles
from chasles import SE3, SE23, SO3

EPS = float(np.finfo(np.float64).eps)
PI = math.pi
CUT = math.sqrt(6.0554544523933395e-06)  # sqrt(taylor_theta2) in double (constants.hpp)

mpmath.mp.dps = 50

THETAS = [0.0, 1e-300, 1e-12, 1e-8, 1e-4, CUT * (1 - 1e-15), CUT * (1 + 1e-15), 0.1, 1.0, PI / 2]
THETAS += [PI - 1e-4, PI - 1e-8, PI, 4.0, 10.0]
SIZES = [0.0, 1e-6, 1.0, 100.0]


def grid():
    rng = np.random.default_rng(20261127)
    out = []
    for i, theta in enumerate(THETAS):
        for j, size in enumerate(SIZES):
            axis = [1.0, 0.0, 0.0] if (i + j) % 3 == 0 else rng.normal(size=3)
            rho, nu = rng.normal(size=3), rng.normal(size=3)
            rho *= size / np.linalg.norm(rho)
            nu *= SIZES[(j + 1) % 4] / np.linalg.norm(nu)
            out.append([*rho, *nu, *(theta * np.asarray(axis) / np.linalg.norm(axis))])
    return np.array(out)


def hat_mp(xi):
    rho, nu, w = ([mpmath.mpf(float(x)) for x in xi[k : k + 3]] for k in (0, 3, 6))
    return mpmath.matrix(
        [
            [0, -w[2], w[1], rho[0], nu[0]],
            [w[2], 0, -w[0], rho[1], nu[1]],
            [-w[1], w[0], 0, rho[2], nu[2]],
            [0, 0, 0, 0, 0],
            [0, 0, 0, 0, 0],
        ]
    )


def expm_mp(xi):
    E = mpmath.expm(hat_mp(xi))
    return np.array([[float(E[i, j]) for j in range(5)] for i in range(5)])


def scale_of(x):
    return max(1.0, float(np.max(np.abs(x))))


@pytest.mark.parametrize("xi", grid().tolist())
def test_exp_is_the_matrix_exponential(xi):
    ref = expm_mp(xi)
    X = chasles.se23_exp(np.array(xi))
    assert np.max(np.abs(X[:3, :3] - ref[:3, :3])) <= 4 * EPS
    for col in (3, 4):  # the position and the velocity, relative to their size
        assert np.max(np.abs(X[:3, col] - ref[:3, col])) <= 8 * EPS * scale_of(ref[:3, col])
    assert np.array_equal(X[3:], np.eye(5)[3:])
    assert np.array_equal(SE23.exp(xi).as_matrix(), X)


@pytest.mark.parametrize("xi", grid().tolist())
def test_log_inverts_exp(xi):
    X = SE23.exp(xi)
    back = X.log()
    assert np.array_equal(chasles.se23_log(X.as_matrix()), back)
    assert SE23.exp(back).is_approx(X, 16 * EPS * scale_of(xi))
    if np.linalg.norm(xi[6:]) < PI - 1e-9:  # inside the principal range: xi itself
        assert np.max(np.abs(back - xi)) <= 16 * EPS * scale_of(xi)


@pytest.mark.parametrize("xi", grid().tolist())
def test_each_half_is_se3(xi):
    """(R, p) is SE3's exp of (rho, w) and (R, v) of (nu, w), to the bit: the
    same kernel, applied to both translations."""
    X = SE23.exp(xi)
    g_p, g_v = SE3.exp([*xi[0:3], *xi[6:9]]), SE3.exp([*xi[3:6], *xi[6:9]])
    assert np.array_equal(X.rotation.as_matrix(), g_p.rotation.as_matrix())
    assert np.array_equal(X.translation, g_p.translation) and np.array_equal(X.velocity, g_v.translation)
    assert np.array_equal(X.log()[[0, 1, 2, 6, 7, 8]], g_p.log())


coords = st.floats(-10.0, 10.0)
angles = st.floats(-3.0, 3.0)
tangents = st.tuples(*([coords] * 6), *([angles] * 3)).map(np.array)


@settings(max_examples=60, deadline=None)
@given(tangents, tangents, st.tuples(coords, coords, coords).map(np.array))
def test_group_laws_against_numpy(x, y, p):
    a, b = SE23.exp(x), SE23.exp(y)
    A, B = a.as_matrix(), b.as_matrix()
    scale = np.max(np.abs(A)) * np.max(np.abs(B)) + np.max(np.abs(A)) + 1.0
    assert np.allclose((a @ b).as_matrix(), A @ B, rtol=0, atol=16 * EPS * scale)
    assert np.array_equal(chasles.se23_compose(A, B), (a @ b).as_matrix())
    assert np.allclose(a.inverse().as_matrix(), np.linalg.inv(A), rtol=0, atol=1e-12 * scale)
    assert np.array_equal(chasles.se23_inverse(A), a.inverse().as_matrix())
    assert np.allclose(a @ p, (A @ [*p, 1.0, 0.0])[:3], rtol=0, atol=16 * EPS * scale * (1 + np.max(np.abs(p))))
    assert np.array_equal(chasles.se23_act(A, p), a @ p)
    assert (a @ SE23.exp(y) @ a.inverse()).is_approx(SE23.exp(a.adjoint() @ y), 1e-9 * scale)
    assert np.array_equal(chasles.se23_vee(chasles.se23_hat(x)), x)
    assert np.array_equal(chasles.se23_hat(x), SE23.hat(x))


def test_jacobians_against_finite_differences():
    rng = np.random.default_rng(3)
    h = 1e-6
    for _ in range(10):
        xi = np.concatenate([rng.normal(size=6), rng.uniform(-1.5, 1.5, 3)])
        X = SE23.exp(xi)
        cols = [
            (chasles.rminus(SE23.exp(xi + h * e), X) - chasles.rminus(SE23.exp(xi - h * e), X)) / (2 * h)
            for e in np.eye(9)
        ]
        assert np.allclose(SE23.right_jacobian(xi), np.column_stack(cols), rtol=0, atol=1e-8)
        cols = [
            (chasles.lminus(SE23.exp(xi + h * e), X) - chasles.lminus(SE23.exp(xi - h * e), X)) / (2 * h)
            for e in np.eye(9)
        ]
        assert np.allclose(SE23.left_jacobian(xi), np.column_stack(cols), rtol=0, atol=1e-8)
        assert np.allclose(SE23.right_jacobian(xi) @ SE23.right_jacobian_inverse(xi), np.eye(9), rtol=0, atol=1e-12)
        assert np.allclose(SE23.left_jacobian(xi) @ SE23.left_jacobian_inverse(xi), np.eye(9), rtol=0, atol=1e-12)
        p = np.array([0.5, -1.0, 2.0])
        J_g, J_p = chasles.act_jacobians(X, p)
        fd = np.column_stack(
            [(chasles.rplus(X, h * e) @ p - chasles.rplus(X, -h * e) @ p) / (2 * h) for e in np.eye(9)]
        )
        assert np.allclose(J_g, fd, rtol=0, atol=1e-8) and np.array_equal(J_p, X.as_matrix()[:3, :3])


def test_float32_batches():
    xs = grid()
    X32 = chasles.se23_exp(xs.astype(np.float32))
    X64 = chasles.se23_exp(xs)
    assert X32.dtype == np.float32 and X32.shape == (len(xs), 5, 5)
    scale = np.maximum(1.0, np.max(np.abs(X64), axis=(1, 2)))
    assert np.all(np.max(np.abs(X32 - X64), axis=(1, 2)) <= 64 * np.finfo(np.float32).eps * scale)
    assert chasles.se23_log(X32).dtype == np.float32


def test_construction_and_protocol():
    R = SO3.exp([0.0, 0.0, PI / 2])
    X = SE23(R, [1.0, 0.0, 0.0], [0.0, 0.0, 2.0])
    assert np.allclose(X @ [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], rtol=0, atol=1e-15)
    assert np.array_equal(X.velocity, [0.0, 0.0, 2.0]) and np.array_equal(X.translation, [1.0, 0.0, 0.0])
    assert X.rotation == R
    M = X.as_matrix()
    assert np.array_equal(M[:3, 3], [1.0, 0.0, 0.0]) and np.array_equal(M[:3, 4], [0.0, 0.0, 2.0])
    assert SE23.from_matrix(M) == X
    assert pickle.loads(pickle.dumps(X)) == X and copy.deepcopy(X) == X
    assert SE23.from_matrix_projected(M + 1e-9).is_approx(X, 1e-8)
    assert chasles.between(X, X).is_approx(SE23(), 4 * EPS)
    assert np.allclose(chasles.se23_normalize(M * [[1.0 + 1e-6], [1.0], [1.0], [1.0], [1.0]]), M, atol=2e-6)
    assert SE23.transform_defect(M) <= 4 * EPS
    assert math.isinf(SE23.transform_defect(np.full((5, 5), np.nan)))
    assert chasles.interpolate(SE23(), X, 1.0).is_approx(X, 8 * EPS)
    assert (X**2).is_approx(X @ X, 8 * EPS)
    with pytest.raises(ValueError, match="not an extended pose"):
        SE23.from_matrix(np.diag([1.0, 2.0, 3.0, 1.0, 1.0]))
    with pytest.raises(ValueError, match="bottom rows differ"):
        SE23.from_matrix(np.eye(5) + np.eye(5, k=1) * [0, 0, 0, 0, 1])
    with pytest.raises(ValueError, match=r"SE23.exp\(xi\): expected shape \(9,\)"):
        SE23.exp(np.zeros(6))
    with pytest.raises(ValueError, match=r"SE23\(velocity\)"):
        SE23(R, [0.0, 0.0, 0.0], [0.0, math.inf, 0.0])
    with pytest.raises(TypeError, match="SE23.from_matrix"):
        SE23(np.eye(5))
    with pytest.raises(TypeError):
        chasles.rminus(SE23(), chasles.SE3())
