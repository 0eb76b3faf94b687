"""Sim3 from Python: exp against the matrix exponential of the hat matrix in
50-digit arithmetic (mpmath) over a grid of rotation angles and log-scales
that crosses every cutoff, the two small together included; log against exp;
the objects against the array functions (the same bits); the group laws
against numpy; the Jacobians against finite differences; the value protocol
and the errors."""

import copy
import math
import pickle

import mpmath
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import chasles
from chasles import SO3, Sim3

EPS = float(np.finfo(np.float64).eps)
PI = math.pi
CUT = math.sqrt(6.0554544523933395e-06)  # sqrt(taylor_theta2) in double (constants.hpp)

mpmath.mp.dps = 50

THETAS = [0.0, 1e-12, 1e-8, 1e-4, CUT * (1 - 1e-15), CUT * (1 + 1e-15), 0.1, 1.0, PI / 2, PI - 1e-6, PI]
SIGMAS = [0.0, 1e-12, 1e-8, 1e-4, CUT * (1 - 1e-15), CUT * (1 + 1e-15), 0.1, 1.0, -1.0, 5.0, -5.0]


def grid():
    rng = np.random.default_rng(20261127)
    out = []
    for i, theta in enumerate(THETAS):
        for j, sigma in enumerate(SIGMAS):
            axis = rng.normal(size=3)
            v = rng.normal(size=3)
            v *= [0.0, 1.0, 100.0][(i + j) % 3] / np.linalg.norm(v)
            out.append([*v, *(theta * axis / np.linalg.norm(axis)), sigma])
    return np.array(out)


def expm_mp(xi):
    v, w, s = (mpmath.mpf(float(x)) for x in xi[:3]), [mpmath.mpf(float(x)) for x in xi[3:6]], xi[6]
    v = list(v)
    s = mpmath.mpf(float(s))
    H = mpmath.matrix([[s, -w[2], w[1], v[0]], [w[2], s, -w[0], v[1]], [-w[1], w[0], s, v[2]], [0, 0, 0, 0]])
    E = mpmath.expm(H)
    return np.array([[float(E[i, j]) for j in range(4)] for i in range(4)])


@pytest.mark.parametrize("xi", grid().tolist())
def test_exp_is_the_matrix_exponential(xi):
    ref = expm_mp(xi)
    g = chasles.sim3_exp(np.array(xi))
    # the s R block relative to s, the translation relative to its size
    scale = max(1.0, np.max(np.abs(ref[:3, :3])))
    assert np.max(np.abs(g[:3, :3] - ref[:3, :3])) <= 8 * EPS * scale
    assert np.max(np.abs(g[:3, 3] - ref[:3, 3])) <= 8 * EPS * max(1.0, np.max(np.abs(ref[:3, 3])))
    assert np.array_equal(Sim3.exp(xi).as_matrix(), g)


@pytest.mark.parametrize("xi", grid().tolist())
def test_log_inverts_exp(xi):
    g = Sim3.exp(xi)
    back = g.log()
    assert np.array_equal(chasles.sim3_log(g.as_matrix()), chasles.sim3_log(np.asarray(g)))
    assert Sim3.exp(back).is_approx(g, 16 * EPS * max(1.0, np.max(np.abs(xi))))
    if np.linalg.norm(xi[3:6]) < PI - 1e-9:  # inside the principal range: xi itself
        assert np.max(np.abs(back - xi)) <= 16 * EPS * max(1.0, np.max(np.abs(xi)))


coords = st.floats(-10.0, 10.0)
similarities = st.tuples(*([coords] * 3), *([st.floats(-3.0, 3.0)] * 3), st.floats(-3.0, 3.0)).map(np.array)


@settings(max_examples=60, deadline=None)
@given(similarities, similarities, st.tuples(coords, coords, coords).map(np.array))
def test_group_laws_against_numpy(x, y, p):
    a, b = Sim3.exp(x), Sim3.exp(y)
    A, B = a.as_matrix(), b.as_matrix()
    scale = np.max(np.abs(A)) * np.max(np.abs(B)) + np.max(np.abs(A)) + 1.0
    assert np.allclose((a @ b).as_matrix(), A @ B, rtol=0, atol=32 * EPS * scale)
    assert np.allclose(a.inverse().as_matrix(), np.linalg.inv(A), rtol=1e-12, atol=1e-12 * scale)
    assert np.allclose(a @ p, (A @ [*p, 1.0])[:3], rtol=0, atol=32 * EPS * scale * (1 + np.max(np.abs(p))))
    # The array function reads s and R back from the matrix (s = |s R|_F / sqrt(3)): within an ulp or two
    # of the object's own s and R.
    assert np.allclose(chasles.sim3_act(A, p), a @ p, rtol=0, atol=8 * EPS * scale * (1 + np.max(np.abs(p))))
    assert math.isclose(a.scale, math.exp(x[6]), rel_tol=4 * EPS)
    assert (a @ Sim3.exp(y) @ a.inverse()).is_approx(Sim3.exp(a.adjoint() @ y), 1e-9 * scale)


def test_jacobians_against_finite_differences():
    rng = np.random.default_rng(3)
    h = 1e-6
    for _ in range(10):
        xi = np.concatenate([rng.normal(size=3), rng.uniform(-1, 1, 3), rng.uniform(-1, 1, 1)])
        g = Sim3.exp(xi)
        cols = [
            (chasles.rminus(Sim3.exp(xi + h * e), g) - chasles.rminus(Sim3.exp(xi - h * e), g)) / (2 * h)
            for e in np.eye(7)
        ]
        assert np.allclose(Sim3.right_jacobian(xi), np.column_stack(cols), atol=1e-8)
        assert np.allclose(Sim3.right_jacobian(xi) @ Sim3.right_jacobian_inverse(xi), np.eye(7), atol=1e-12)
        assert np.allclose(Sim3.left_jacobian(xi) @ Sim3.left_jacobian_inverse(xi), np.eye(7), atol=1e-12)
        p = np.array([0.5, -1.0, 2.0])
        J_g, J_p = chasles.act_jacobians(g, p)
        fd = np.column_stack(
            [(chasles.rplus(g, h * e) @ p - chasles.rplus(g, -h * e) @ p) / (2 * h) for e in np.eye(7)]
        )
        assert np.allclose(J_g, fd, atol=1e-8) and np.allclose(J_p, g.as_matrix()[:3, :3], rtol=0, atol=0)


def test_construction_and_protocol():
    R = SO3.exp([0.0, 0.0, PI / 2])
    g = Sim3(R, [1.0, 0.0, 0.0], 2.0)
    assert np.allclose(g @ [1.0, 0.0, 0.0], [1.0, 2.0, 0.0], atol=1e-15)
    assert g.scale == 2.0 and np.array_equal(g.translation, [1.0, 0.0, 0.0]) and g.rotation == R
    assert Sim3.from_matrix(g.as_matrix()).is_approx(g, 4 * EPS)
    assert pickle.loads(pickle.dumps(g)) == g and copy.deepcopy(g) == g
    assert Sim3.from_matrix_projected(g.as_matrix() + 1e-9).is_approx(g, 1e-8)
    assert chasles.between(g, g).is_approx(Sim3(), 4 * EPS)
    assert np.allclose(
        chasles.sim3_normalize(g.as_matrix() * [[1.0 + 1e-6], [1.0], [1.0], [1.0]]), g.as_matrix(), atol=1e-5
    )
    with pytest.raises(ValueError, match=r"Sim3\(scale\): expected a positive scale"):
        Sim3(R, [0.0, 0.0, 0.0], -1.0)
    with pytest.raises(ValueError, match="not a similarity"):
        Sim3.from_matrix(np.diag([1.0, 2.0, 3.0, 1.0]))
    with pytest.raises(ValueError, match=r"Sim3.exp\(xi\): expected shape \(7,\)"):
        Sim3.exp(np.zeros(6))
    with pytest.raises(TypeError, match="Sim3.from_matrix"):
        Sim3(np.eye(4))
    with pytest.raises(TypeError):
        chasles.rminus(Sim3(), chasles.SE3())
