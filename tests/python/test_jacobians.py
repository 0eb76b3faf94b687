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
import math

import chasles
import numpy as np
import pytest
from chasles import SE3, SO3
from hypothesis import given
from hypothesis import strategies as st
from scipy.linalg import expm, logm
from scipy.spatial.transform import Rotation
from strategies import PI, elements, points, rotation_vectors, twist_vectors

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
    np.testing.assert_allclose(chasles.rplus(hs, y2).translation, [-1.0, 0.0, 0.0], atol=1e-15)  # h's frame
    np.testing.assert_allclose(chasles.lplus(y2, hs).translation, [1.0, 2.0, 0.0], atol=1e-15)  # world frame


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


# ---- Jacobians of the group operations (log, inverse, compose, act, interpolate) ----
#
# Each against central differences on the manifold computed with the objects
# (rplus, rminus, @, interpolate), in the right-local sense: for a map f to a
# group, f(X exp(dx)) = f(X) exp(J dx + o(dx)), so column k of J is
# (rminus(f(X rplus h e_k), f(X)) - rminus(f(X rplus -h e_k), f(X))) / 2h; for
# a map to a vector space (log, the action on a point) the difference is the
# plain one, f(X exp(dx)) - f(X) = J dx + o(dx).
#
# Tolerance FD_TOL = 1e-7 relative to max(1, |J|), as above: truncation
# h^2 |f'''| / 6 ~ 1e-10 |J|, rounding eps |f| / h with |f| <= ~70 here (SE3
# translations up to 10, logs up to ~25 near pi, interpolation t in [-1, 2])
# ~ 1.4e-9; a margin of about a hundred, while a wrong term (a sign, Ad_b
# for Ad_b^-1, the (v, w) order) errs by order 1.


def tangent_dim(g):
    return 3 if isinstance(g, SO3) else 6


def unit(n, k):
    e = np.zeros(n)
    e[k] = 1.0
    return e


def log_branch_near(g, ref):
    """log(g) on the branch nearest ref.

    Past the angle pi, log jumps from w to the other representative
    w - 2 pi w / |w| of the same rotation; the finite difference of log at a
    point near pi must follow the branch that log returned there.
    """
    u = g.log()
    w = u if isinstance(g, SO3) else u[3:]
    theta = np.linalg.norm(w)
    if theta == 0.0:
        return u
    w2 = w - 2 * PI * w / theta
    if isinstance(g, SO3):
        alt = w2
    else:  # v = J_l(w)^-1 p on either branch
        alt = np.concatenate([SO3.left_jacobian_inverse(w2) @ g.translation, w2])
    return u if np.max(np.abs(u - ref)) <= np.max(np.abs(alt - ref)) else alt


def fd_group_map(f, x):
    """Central differences of the group-valued x -> f(x), right-local in x."""
    n = tangent_dim(x)
    f0 = f(x)
    cols = []
    for k in range(n):
        e = H * unit(n, k)
        up = chasles.rminus(f(chasles.rplus(x, e)), f0)
        down = chasles.rminus(f(chasles.rplus(x, -e)), f0)
        cols.append((up - down) / (2 * H))
    return np.column_stack(cols)


def fd_vector_map(f, x):
    """Central differences of the vector-valued x -> f(x), right-local in x."""
    n = tangent_dim(x)
    cols = []
    for k in range(n):
        e = H * unit(n, k)
        cols.append((f(chasles.rplus(x, e)) - f(chasles.rplus(x, -e))) / (2 * H))
    return np.column_stack(cols)


def check_log_jacobian(g):
    ref = g.log()
    J = fd_vector_map(lambda x: log_branch_near(x, ref), g)
    assert_jacobian_close(chasles.log_jacobian(g), J)


def check_inverse_jacobian(g):
    assert_jacobian_close(chasles.inverse_jacobian(g), fd_group_map(lambda x: x.inverse(), g))


def check_compose_jacobians(a, b):
    J_a, J_b = chasles.compose_jacobians(a, b)
    assert_jacobian_close(J_a, fd_group_map(lambda x: x @ b, a))
    assert_jacobian_close(J_b, fd_group_map(lambda x: a @ x, b))


def check_act_jacobians(g, p):
    J_g, J_p = chasles.act_jacobians(g, p)
    assert J_g.shape == (3, tangent_dim(g))
    assert_jacobian_close(J_g, fd_vector_map(lambda x: x @ p, g))
    fd_p = np.column_stack([(g @ (p + H * unit(3, k)) - g @ (p - H * unit(3, k))) / (2 * H) for k in range(3)])
    assert_jacobian_close(J_p, fd_p)


def check_interpolate_jacobian_t(a, b, t):
    J = chasles.interpolate_jacobian_t(a, b, t)
    assert J.shape == (tangent_dim(a),)
    interp = type(a).interpolate
    f0 = interp(a, b, t)
    fd = (chasles.rminus(interp(a, b, t + H), f0) - chasles.rminus(interp(a, b, t - H), f0)) / (2 * H)
    err = np.max(np.abs(J - fd)) / max(1.0, np.max(np.abs(J)))
    assert err <= FD_TOL, f"relative error {err:.3e}"
    assert np.array_equal(J, chasles.rminus(b, a))  # the constant body velocity log(a^-1 b)


N_PI = np.array([1.0, 2.0, -2.0]) / 3
NAMED_ROTATION_VECTORS = {
    "identity": np.zeros(3),
    "small": np.array([1e-9, -2e-9, 0.5e-9]),
    "taylor cutoff": np.array([0.0, 0.0, math.sqrt(6.0554544523933395e-06)]),
    "generic": np.array([0.3, -1.1, 0.7]),
    "pi - 1e-6": (PI - 1e-6) * N_PI,
    "pi about x": np.array([PI, 0.0, 0.0]),
    "pi about a generic axis": PI * N_PI,
}
NAMED_POINT = np.array([0.5, -2.0, 3.0])


def named_elements():
    for name, w in NAMED_ROTATION_VECTORS.items():
        yield pytest.param(SO3.exp(w), id=f"SO3 {name}")
        yield pytest.param(SE3(SO3.exp(w), [1.0, -2.0, 0.5]), id=f"SE3 {name}")
    yield pytest.param(SE3(), id="SE3 identity exactly")


@pytest.mark.parametrize("g", list(named_elements()))
def test_operation_jacobians_at_named_points(g):
    h = type(g).exp(np.linspace(0.2, 0.7, tangent_dim(g)))
    check_log_jacobian(g)
    check_inverse_jacobian(g)
    check_compose_jacobians(g, h)
    check_compose_jacobians(h, g)
    check_act_jacobians(g, NAMED_POINT)
    for t in (0.0, 0.5, 1.0, -0.5, 2.0):
        check_interpolate_jacobian_t(h, g, t)
        check_interpolate_jacobian_t(g, h, t)


@pytest.mark.parametrize("group", [SO3, SE3], ids=["SO3", "SE3"])
@given(data=st.data())
def test_log_and_inverse_jacobians_against_finite_differences(group, data):
    g = data.draw(elements(group))
    check_log_jacobian(g)
    check_inverse_jacobian(g)


@pytest.mark.parametrize("group", [SO3, SE3], ids=["SO3", "SE3"])
@given(data=st.data())
def test_compose_and_act_jacobians_against_finite_differences(group, data):
    a, b = data.draw(elements(group)), data.draw(elements(group))
    check_compose_jacobians(a, b)
    check_act_jacobians(a, data.draw(points()))


@pytest.mark.parametrize("group", [SO3, SE3], ids=["SO3", "SE3"])
@given(data=st.data())
def test_interpolate_jacobian_t_against_finite_differences(group, data):
    a, b = data.draw(elements(group)), data.draw(elements(group))
    t = data.draw(st.one_of(st.sampled_from((0.0, 0.5, 1.0)), st.floats(-1.0, 2.0)))
    check_interpolate_jacobian_t(a, b, t)


def test_operation_jacobians_values():
    g = SE3(SO3.exp([0.0, 0.0, PI / 2]), [1.0, 2.0, 3.0])
    np.testing.assert_array_equal(chasles.inverse_jacobian(g), -g.adjoint())
    J_a, J_b = chasles.compose_jacobians(SE3(), g)
    np.testing.assert_array_equal(J_a, g.inverse().adjoint())
    np.testing.assert_array_equal(J_b, np.eye(6))
    J_g, J_p = chasles.act_jacobians(g, [0.0, 0.0, 1.0])
    R = g.rotation.as_matrix()
    np.testing.assert_array_equal(J_g[:, :3], R)  # (v, w): linear columns first
    np.testing.assert_allclose(J_g[:, 3:], -R @ hat3([0.0, 0.0, 1.0]), atol=1e-16)
    np.testing.assert_array_equal(J_p, R)
    assert np.array_equal(chasles.log_jacobian(SO3()), np.eye(3))
    assert np.array_equal(chasles.log_jacobian(SE3()), np.eye(6))


def test_operation_jacobians_validate_their_arguments():
    with pytest.raises(ValueError, match=r"act_jacobians\(g, p\): expected shape \(3,\), got \(4,\)"):
        chasles.act_jacobians(SO3(), np.zeros(4))
    with pytest.raises(ValueError, match=r"act_jacobians\(g, p\): expected shape \(3,\), got \(6,\)"):
        chasles.act_jacobians(SE3(), np.zeros(6))
    with pytest.raises(ValueError, match=r"act_jacobians\(g, p\): expected finite numbers"):
        chasles.act_jacobians(SE3(), [np.nan, 0.0, 0.0])
    with pytest.raises(ValueError, match=r"interpolate_jacobian_t\(t\): expected a finite number, got inf"):
        chasles.interpolate_jacobian_t(SO3(), SO3(), np.inf)
    msg = r"interpolate_jacobian_t\(t\): expected a real number \(shape \(\)\), got shape \(2,\)"
    with pytest.raises(ValueError, match=msg):
        chasles.interpolate_jacobian_t(SE3(), SE3(), [0.5, 0.5])
    with pytest.raises(TypeError):
        chasles.compose_jacobians(SO3(), SE3())
    with pytest.raises(TypeError):
        chasles.interpolate_jacobian_t(SE3(), SO3(), 0.5)
    with pytest.raises(TypeError):
        chasles.log_jacobian(np.eye(3))
    with pytest.raises(TypeError):
        chasles.inverse_jacobian(np.eye(4))


@pytest.mark.parametrize(
    "name", ["log_jacobian", "inverse_jacobian", "compose_jacobians", "act_jacobians", "interpolate_jacobian_t"]
)
def test_operation_jacobians_are_documented_and_examples_run(name):
    test_module_functions_are_documented_and_examples_run(name)
    assert "right-local" in getattr(chasles, name).__doc__.lower()
