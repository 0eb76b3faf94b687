"""The Jacobians (SO3/SE3 .right_jacobian, .left_jacobian and their inverses)
and chasles.rplus / rminus / lplus / lminus, against independent code:
central differences on the manifold through scipy.linalg.expm (exp) and
scipy's Rotation / scipy.linalg.logm (the log of a motion near the identity).

Right (local) convention: exp(x + dx) = exp(x) exp(J_r(x) dx + o(dx)).

Finite-difference tolerance: the central difference with step h = 1e-5 errs
by about h^2 |f'''| / 6 ~ 1e-10 (truncation) plus eps |x| / h ~ 2e-10 (rounding,
|x| <= 10 + pi here); 1e-7 relative to max(1, |J|) leaves a margin of about
a hundred, while any wrong term (a sign, a block, the (v, w) order) errs by
order 1.
"""

from __future__ import annotations

import doctest

import chasles
import numpy as np
import pytest
from chasles import SE3, SO3
from hypothesis import given
from scipy.linalg import expm, logm
from scipy.spatial.transform import Rotation
from strategies import PI, rotation_vectors, twist_vectors

H = 1e-5
FD_TOL = 1e-7


def hat3(w):
    return np.array([[0.0, -w[2], w[1]], [w[2], 0.0, -w[0]], [-w[1], w[0], 0.0]])


def hat6(xi):
    X = np.zeros((4, 4))
    X[:3, :3] = hat3(xi[3:])
    X[:3, 3] = xi[:3]
    return X


def log3_near_identity(R):
    return Rotation.from_matrix(R).as_rotvec()


def log6_near_identity(g):
    X = np.real(logm(g))
    return np.concatenate([X[:3, 3], [X[2, 1], X[0, 2], X[1, 0]]])


def fd_jacobian(exp, log, x, right):
    """Central differences of x -> exp(x) on the manifold, right or left."""
    n = len(x)
    E0inv = np.linalg.inv(exp(x))
    J = np.zeros((n, n))
    for k in range(n):
        e = np.zeros(n)
        e[k] = H

        def rel(s):
            E = exp(x + s * e)
            return log(E0inv @ E if right else E @ E0inv)

        J[:, k] = (rel(1.0) - rel(-1.0)) / (2 * H)
    return J


def exp3(w):
    return expm(hat3(w))


def exp6(xi):
    return expm(hat6(xi))


def assert_jacobian_close(J, ref):
    assert J.shape == ref.shape
    err = np.max(np.abs(J - ref)) / max(1.0, np.max(np.abs(ref)))
    assert err <= FD_TOL, f"relative error {err:.3e}"


@given(w=rotation_vectors())
def test_so3_jacobians_against_finite_differences(w):
    # Past pi - 1e-3 the step crosses pi for neither side: the relative log is near I.
    Jr = fd_jacobian(exp3, log3_near_identity, w, right=True)
    Jl = fd_jacobian(exp3, log3_near_identity, w, right=False)
    assert_jacobian_close(SO3.right_jacobian(w), Jr)
    assert_jacobian_close(SO3.left_jacobian(w), Jl)
    assert_jacobian_close(SO3.right_jacobian_inverse(w), np.linalg.inv(Jr))
    assert_jacobian_close(SO3.left_jacobian_inverse(w), np.linalg.inv(Jl))


@given(xi=twist_vectors())
def test_se3_jacobians_against_finite_differences(xi):
    Jr = fd_jacobian(exp6, log6_near_identity, xi, right=True)
    Jl = fd_jacobian(exp6, log6_near_identity, xi, right=False)
    assert_jacobian_close(SE3.right_jacobian(xi), Jr)
    assert_jacobian_close(SE3.left_jacobian(xi), Jl)
    # The inverse of a finite-difference matrix: its error grows with cond(J) ~ |v|^2.
    scale = max(1.0, np.max(np.abs(xi))) ** 2
    Jri, Jli = SE3.right_jacobian_inverse(xi), SE3.left_jacobian_inverse(xi)
    assert np.max(np.abs(Jri - np.linalg.inv(Jr))) <= FD_TOL * scale
    assert np.max(np.abs(Jli - np.linalg.inv(Jl))) <= FD_TOL * scale


@given(w=rotation_vectors())
def test_so3_identities(w):
    np.testing.assert_allclose(SO3.left_jacobian(w), SO3.right_jacobian(-w), atol=1e-15)
    R = SO3.exp(w).as_matrix()
    np.testing.assert_allclose(SO3.left_jacobian(w), R @ SO3.right_jacobian(w), atol=1e-14)
    np.testing.assert_allclose(SO3.right_jacobian(w) @ SO3.right_jacobian_inverse(w), np.eye(3), atol=1e-14)
    np.testing.assert_allclose(SO3.left_jacobian(w) @ SO3.left_jacobian_inverse(w), np.eye(3), atol=1e-14)


@given(xi=twist_vectors())
def test_se3_identities(xi):
    s = max(1.0, np.max(np.abs(xi)))
    np.testing.assert_allclose(SE3.left_jacobian(xi), SE3.right_jacobian(-xi), atol=1e-15 * s)
    Ad = SE3.exp(xi).adjoint()
    np.testing.assert_allclose(SE3.left_jacobian(xi), Ad @ SE3.right_jacobian(xi), atol=1e-13 * s)
    np.testing.assert_allclose(SE3.right_jacobian(xi) @ SE3.right_jacobian_inverse(xi), np.eye(6), atol=1e-13 * s * s)


def test_values_at_zero_and_pi():
    assert np.array_equal(SO3.right_jacobian([0.0, 0.0, 0.0]), np.eye(3))
    assert np.array_equal(SE3.left_jacobian_inverse(np.zeros(6)), np.eye(6))
    # J_r^-1(pi n) = I + pi/2 [n] + [n]^2: D = 1 / pi^2 at pi.
    n = np.array([1.0, 2.0, -2.0]) / 3
    N = hat3(n)
    np.testing.assert_allclose(SO3.right_jacobian_inverse(PI * n), np.eye(3) + PI / 2 * N + N @ N, atol=1e-14)


def test_shapes_are_validated():
    with pytest.raises(ValueError, match=r"SO3\.right_jacobian\(w\): expected shape \(3,\), got \(6,\)"):
        SO3.right_jacobian(np.zeros(6))
    with pytest.raises(ValueError, match=r"SE3\.left_jacobian_inverse\(xi\): expected shape \(6,\), got \(3,\)"):
        SE3.left_jacobian_inverse(np.zeros(3))
    with pytest.raises(ValueError, match="finite"):
        SO3.left_jacobian([np.nan, 0.0, 0.0])
    with pytest.raises(ValueError, match=r"rplus\(g, xi\): expected shape \(6,\), got \(3,\)"):
        chasles.rplus(SE3(), np.zeros(3))
    with pytest.raises(ValueError, match=r"lplus\(xi, g\): expected shape \(3,\), got \(6,\)"):
        chasles.lplus(np.zeros(6), SO3())
    with pytest.raises(TypeError):
        chasles.rminus(SO3(), SE3())


# ---- plus and minus ---------------------------------------------------------------


def test_argument_order_is_pinned():
    h = SO3.exp([0.0, 0.0, 0.5])
    g = h @ SO3.exp([0.3, 0.0, 0.0])
    np.testing.assert_allclose(chasles.rminus(g, h), [0.3, 0.0, 0.0], atol=1e-15)  # log(h^-1 g), manif's order
    np.testing.assert_allclose(chasles.rminus(h, g), [-0.3, 0.0, 0.0], atol=1e-15)
    g2 = SO3.exp([0.3, 0.0, 0.0]) @ h
    np.testing.assert_allclose(chasles.lminus(g2, h), [0.3, 0.0, 0.0], atol=1e-15)  # log(g h^-1)
    hs = SE3(SO3.exp([0.0, 0.0, PI / 2]), [1.0, 0.0, 0.0])
    y2 = [0.0, 2.0, 0.0, 0.0, 0.0, 0.0]
    np.testing.assert_allclose(chasles.rplus(hs, y2).translation(), [-1.0, 0.0, 0.0], atol=1e-15)  # h's frame
    np.testing.assert_allclose(chasles.lplus(y2, hs).translation(), [1.0, 2.0, 0.0], atol=1e-15)  # world frame


@given(a=rotation_vectors(), b=rotation_vectors())
def test_so3_round_trips(a, b):
    g, h = SO3.exp(a), SO3.exp(b)
    assert chasles.rplus(h, chasles.rminus(g, h)).is_approx(g, tol=1e-13)
    assert chasles.lplus(chasles.lminus(g, h), h).is_approx(g, tol=1e-13)
    np.testing.assert_allclose(chasles.rplus(h, a).as_matrix(), h.as_matrix() @ expm(hat3(a)), atol=1e-13)
    np.testing.assert_allclose(chasles.lplus(a, h).as_matrix(), expm(hat3(a)) @ h.as_matrix(), atol=1e-13)


@given(a=twist_vectors(), b=twist_vectors())
def test_se3_round_trips(a, b):
    g, h = SE3.exp(a), SE3.exp(b)
    assert chasles.rplus(h, chasles.rminus(g, h)).is_approx(g, tol=1e-11)
    assert chasles.lplus(chasles.lminus(g, h), h).is_approx(g, tol=1e-11)
    s = max(1.0, np.max(np.abs(a)), np.max(np.abs(b)))
    np.testing.assert_allclose(chasles.rplus(h, a).as_matrix(), h.as_matrix() @ expm(hat6(a)), atol=1e-12 * s * s)
    np.testing.assert_allclose(chasles.lplus(a, h).as_matrix(), expm(hat6(a)) @ h.as_matrix(), atol=1e-12 * s * s)


@pytest.mark.parametrize("name", ["rplus", "rminus", "lplus", "lminus"])
def test_module_functions_are_documented_and_examples_run(name):
    f = getattr(chasles, name)
    assert name in chasles.__all__
    doc = f.__doc__
    assert "Args:" in doc and "Returns:" in doc
    globs = {"np": np, "chasles": chasles}
    test = doctest.DocTestParser().get_doctest(doc, globs, name, None, 0)
    runner = doctest.DocTestRunner(optionflags=doctest.NORMALIZE_WHITESPACE)
    out = []
    runner.run(test, out=out.append)
    assert runner.failures == 0, "".join(out)
