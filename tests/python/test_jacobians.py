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

import math

import numpy as np
import pytest
from helpers import hat3, hat6
from hypothesis import given
from hypothesis import strategies as st
from scipy.linalg import expm, logm
from scipy.spatial.transform import Rotation
from strategies import PI, elements, points, rotation_vectors, tangents, twist_vectors

import chasles
from chasles import SE3, SO3

H = 1e-5
FD_TOL = 1e-7


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
def test_module_functions_are_documented(name):
    # (their examples run in test_docs.py, with every docstring's)
    f = getattr(chasles, name)
    assert name in chasles.__all__
    doc = f.__doc__
    assert "Args:" in doc and "Returns:" in doc


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
def test_operation_jacobians_are_documented(name):
    test_module_functions_are_documented(name)
    assert "right-local" in getattr(chasles, name).__doc__.lower()


# ---- Jacobians of rplus, rminus, lplus, lminus, between (both arguments) ----
#
# Central differences as above, right-local in every group argument, plain in
# a tangent argument; rminus and lminus follow the branch log returned (near
# and at pi). Then manif's first-order check with a random small step w:
# f(X rplus w) ~ f(X) rplus (J w), error O(|w|^2).


def fd_tangent_map(f, xi):
    """Central differences of the group-valued xi -> f(xi) in the plain tangent xi."""
    f0 = f(xi)
    cols = []
    for k in range(len(xi)):
        e = H * unit(len(xi), k)
        cols.append((chasles.rminus(f(xi + e), f0) - chasles.rminus(f(xi - e), f0)) / (2 * H))
    return np.column_stack(cols)


def check_plus_minus_between_jacobians(g, h, xi):
    J_g, J_xi = chasles.rplus_jacobians(g, xi)
    assert_jacobian_close(J_g, fd_group_map(lambda x: chasles.rplus(x, xi), g))
    assert_jacobian_close(J_xi, fd_tangent_map(lambda t: chasles.rplus(g, t), xi))
    J_xi, J_g = chasles.lplus_jacobians(xi, g)
    assert_jacobian_close(J_xi, fd_tangent_map(lambda t: chasles.lplus(t, g), xi))
    assert_jacobian_close(J_g, fd_group_map(lambda x: chasles.lplus(xi, x), g))
    J_a, J_b = chasles.between_jacobians(g, h)
    assert_jacobian_close(J_a, fd_group_map(lambda x: chasles.between(x, h), g))
    assert_jacobian_close(J_b, fd_group_map(lambda x: chasles.between(g, x), h))
    ref = chasles.rminus(g, h)
    J_g, J_h = chasles.rminus_jacobians(g, h)
    assert_jacobian_close(J_g, fd_vector_map(lambda x: log_branch_near(h.inverse() @ x, ref), g))
    assert_jacobian_close(J_h, fd_vector_map(lambda x: log_branch_near(x.inverse() @ g, ref), h))
    ref = chasles.lminus(g, h)
    J_g, J_h = chasles.lminus_jacobians(g, h)
    assert_jacobian_close(J_g, fd_vector_map(lambda x: log_branch_near(x @ h.inverse(), ref), g))
    assert_jacobian_close(J_h, fd_vector_map(lambda x: log_branch_near(g @ x.inverse(), ref), h))


@pytest.mark.parametrize("g", list(named_elements()))
def test_plus_minus_between_jacobians_at_named_points(g):
    G = type(g)
    n = tangent_dim(g)
    others = [G(), G.exp(np.linspace(0.2, 0.7, n)), g @ G.exp(1e-9 * np.ones(n))]
    for h in others:
        # xi: 0, tiny, generic and near pi (the named rotation vectors of g's own log).
        for xi in (np.zeros(n), 1e-9 * np.ones(n), np.linspace(-0.7, 0.4, n), g.log()):
            check_plus_minus_between_jacobians(g, h, xi)
            check_plus_minus_between_jacobians(h, g, xi)


@pytest.mark.parametrize("group", [SO3, SE3], ids=["SO3", "SE3"])
@given(data=st.data())
def test_plus_minus_between_jacobians_against_finite_differences(group, data):
    g, h = data.draw(elements(group)), data.draw(elements(group))
    check_plus_minus_between_jacobians(g, h, data.draw(tangents(group)))


@pytest.mark.parametrize("group", [SO3, SE3], ids=["SO3", "SE3"])
def test_plus_minus_between_jacobians_first_order(group):
    # manif's check: f(X rplus w) rminus (f(X) rplus J w) = O(|w|^2), here
    # with |w| = 1e-4 below 2e-7 (|f''| <~ 10 for these |x| <~ 3, 8 |w|^2 s);
    # a wrong Jacobian errs by about |w| = 1e-4.
    rng = np.random.default_rng(20261124)
    n = 3 if group is SO3 else 6
    d = 1e-4
    for _ in range(50):
        g = group.exp(rng.uniform(-1.0, 1.0, n) * (PI / np.sqrt(3)))
        h = group.exp(rng.uniform(-1.0, 1.0, n) * (PI / np.sqrt(3)))
        xi = rng.uniform(-1.0, 1.0, n)
        w = rng.normal(size=n)
        w *= d / np.linalg.norm(w)
        s = max(1.0, np.max(np.abs(np.asarray(g)[:3, 3:])) if n == 6 else 1.0)
        bound = 8 * d * d * s * 10

        def group_err(got, base, J):
            return np.max(np.abs(chasles.rminus(got, chasles.rplus(base, J @ w))))

        J_g, J_xi = chasles.rplus_jacobians(g, xi)
        assert group_err(chasles.rplus(chasles.rplus(g, w), xi), chasles.rplus(g, xi), J_g) <= bound
        assert group_err(chasles.rplus(g, xi + w), chasles.rplus(g, xi), J_xi) <= bound
        J_xi, J_g = chasles.lplus_jacobians(xi, g)
        assert group_err(chasles.lplus(xi + w, g), chasles.lplus(xi, g), J_xi) <= bound
        assert group_err(chasles.lplus(xi, chasles.rplus(g, w)), chasles.lplus(xi, g), J_g) <= bound
        J_a, J_b = chasles.between_jacobians(g, h)
        assert group_err(chasles.between(chasles.rplus(g, w), h), chasles.between(g, h), J_a) <= bound
        assert group_err(chasles.between(g, chasles.rplus(h, w)), chasles.between(g, h), J_b) <= bound
        # the minus maps are vector-valued: f(X rplus w) ~ f(X) + J w, away
        # from pi, where log's second derivative grows (the finite-difference
        # tests above reach pi)
        for minus, jac in ((chasles.rminus, chasles.rminus_jacobians), (chasles.lminus, chasles.lminus_jacobians)):
            x0 = minus(g, h)
            if np.linalg.norm(x0[-3:]) > PI - 0.3:
                continue
            J_g, J_h = jac(g, h)
            assert np.max(np.abs(minus(chasles.rplus(g, w), h) - (x0 + J_g @ w))) <= bound
            assert np.max(np.abs(minus(g, chasles.rplus(h, w)) - (x0 + J_h @ w))) <= bound


def test_plus_minus_between_jacobians_values():
    a = SE3(SO3.exp([0.0, 0.0, PI / 2]), [1.0, 2.0, 3.0])
    b = SE3(SO3.exp([0.4, 0.0, 0.0]), [0.0, -1.0, 0.5])
    J_a, J_b = chasles.between_jacobians(a, b)
    np.testing.assert_allclose(J_a, -(b.inverse() @ a).adjoint(), rtol=0, atol=1e-15)
    np.testing.assert_array_equal(J_b, np.eye(6))
    assert chasles.between(a, b).is_approx(a.inverse() @ b, 1e-15)
    xi = np.array([0.3, -0.2, 0.1, 0.5, 0.1, -0.4])
    J_g, J_xi = chasles.rplus_jacobians(a, xi)
    np.testing.assert_allclose(J_g, SE3.exp(-xi).adjoint(), rtol=0, atol=1e-15)
    np.testing.assert_array_equal(J_xi, SE3.right_jacobian(xi))
    J_xi, J_g = chasles.lplus_jacobians(xi, a)
    np.testing.assert_allclose(J_xi, a.inverse().adjoint() @ SE3.right_jacobian(xi), rtol=0, atol=1e-14)
    np.testing.assert_array_equal(J_g, np.eye(6))
    J_g, J_h = chasles.rminus_jacobians(a, b)
    x = chasles.rminus(a, b)
    np.testing.assert_array_equal(J_g, SE3.right_jacobian_inverse(x))
    np.testing.assert_array_equal(J_h, -SE3.left_jacobian_inverse(x))
    J_g, J_h = chasles.lminus_jacobians(a, b)
    np.testing.assert_allclose(J_g, SE3.right_jacobian_inverse(chasles.lminus(a, b)) @ b.adjoint(), rtol=0, atol=1e-14)
    np.testing.assert_array_equal(J_h, -J_g)


def test_plus_minus_between_jacobians_validate_their_arguments():
    with pytest.raises(ValueError, match=r"rplus_jacobians\(g, xi\): expected shape \(6,\), got \(3,\)"):
        chasles.rplus_jacobians(SE3(), np.zeros(3))
    with pytest.raises(ValueError, match=r"lplus_jacobians\(xi, g\): expected finite numbers"):
        chasles.lplus_jacobians([np.inf, 0.0, 0.0], SO3())
    for f in (chasles.rminus_jacobians, chasles.lminus_jacobians, chasles.between, chasles.between_jacobians):
        with pytest.raises(TypeError):
            f(SO3(), SE3())
        with pytest.raises(TypeError):
            f(np.eye(3), SO3())


@pytest.mark.parametrize(
    "name", ["rplus_jacobians", "rminus_jacobians", "lplus_jacobians", "lminus_jacobians", "between_jacobians"]
)
def test_plus_minus_between_jacobians_are_documented(name):
    test_module_functions_are_documented(name)
    assert "right-local" in getattr(chasles, name).__doc__.lower()


def test_between_is_documented():
    test_module_functions_are_documented("between")


# ---- the point-action Jacobian for many points (array functions) ----


@pytest.mark.parametrize("group", [SO3, SE3], ids=["SO3", "SE3"])
def test_act_jacobian_array_functions_match_act_jacobians(group):
    rng = np.random.default_rng(7)
    n = 3 if group is SO3 else 6
    f = chasles.so3_act_jacobian if group is SO3 else chasles.se3_act_jacobian
    gs = [group.exp(rng.uniform(-1.0, 1.0, n) * 2.0) for _ in range(5)] + [
        group(),
        group.exp(np.r_[np.zeros(n - 3), PI, 0.0, 0.0]),
    ]
    pts = rng.normal(size=(9, 3)) * 5.0
    for g in gs:
        M = np.asarray(g)
        J = f(M, pts)  # one element, many points
        assert J.shape == (9, 3, n) and J.dtype == np.float64
        for p, Jp in zip(pts, J):
            np.testing.assert_array_equal(Jp, chasles.act_jacobians(g, p)[0])
            # and against central differences of the action
            assert_jacobian_close(Jp, fd_vector_map(lambda x: x @ p, g))
    # broadcasting: N elements with N points, and every pair
    Ms = np.stack([np.asarray(g) for g in gs])
    J = f(Ms, pts[: len(gs)])
    assert J.shape == (len(gs), 3, n)
    for k, g in enumerate(gs):
        np.testing.assert_array_equal(J[k], chasles.act_jacobians(g, pts[k])[0])
    assert f(Ms[:, None], pts).shape == (len(gs), 9, 3, n)
    # float32 in, float32 out, the float32 kernel within a few float32 eps
    J32 = f(Ms.astype(np.float32), pts[: len(gs)].astype(np.float32))
    assert J32.dtype == np.float32
    np.testing.assert_allclose(J32, J, rtol=0, atol=64 * np.finfo(np.float32).eps * 5.0)
    # the Jacobian in the point is the rotation block
    np.testing.assert_array_equal(chasles.act_jacobians(gs[0], pts[0])[1], Ms[0][:3, :3])


def test_act_jacobian_array_functions_are_documented():
    for name in ("so3_act_jacobian", "se3_act_jacobian"):
        f = getattr(chasles, name)
        assert isinstance(f, np.ufunc) and name in chasles.__all__
        doc = " ".join(f.__doc__.split())
        assert "Args:" in doc and "right-local" in doc
        assert "d(R p)/dp, is R itself" in doc or "d(g p)/dp, is the rotation block R" in doc
    assert chasles.so3_act_jacobian.signature == "(3,3),(3)->(3,3)"
    assert chasles.se3_act_jacobian.signature == "(4,4),(3)->(3,6)"


@pytest.mark.parametrize("group", [chasles.SO2, chasles.SE2, chasles.SO3, chasles.SE3, chasles.Sim3, chasles.SE23])
def test_batched_jacobians_are_the_objects_ones(group):
    """<g>_compose_jacobians, <g>_between_jacobians, <g>_rminus_jacobians over a
    batch: each pair's Jacobians are those of the object functions (to 1e-13:
    the objects' matrices round anew), near them in float32; broadcasting as
    numpy's."""
    rng = np.random.default_rng(3)
    d = np.atleast_2d(group.identity().adjoint()).shape[0]
    tangent = (lambda: float(rng.normal())) if d == 1 else (lambda: rng.normal(size=d))
    A = [group.exp(tangent()) for _ in range(4)]
    B = [group.exp(tangent()) for _ in range(4)]
    MA, MB = np.stack([np.asarray(x) for x in A]), np.stack([np.asarray(x) for x in B])
    p = group.__name__.lower()
    for f in ("compose", "between", "rminus"):
        batched = getattr(chasles, f"{p}_{f}_jacobians")
        one = getattr(chasles, f"{f}_jacobians")
        ja, jb = batched(MA, MB)
        assert ja.shape == jb.shape == (4, d, d)
        for i in range(4):
            wa, wb = one(A[i], B[i])
            np.testing.assert_allclose(ja[i], np.atleast_2d(wa), rtol=0, atol=1e-13)
            np.testing.assert_allclose(jb[i], np.atleast_2d(wb), rtol=0, atol=1e-13)
        ja1, _ = batched(MA[0], MB)  # one a against the batch
        assert ja1.shape == (4, d, d) and np.array_equal(ja1[2], batched(MA[0], MB[2])[0])
        j32, _ = batched(MA.astype(np.float32), MB.astype(np.float32))
        assert j32.dtype == np.float32 and np.abs(j32 - ja).max() < 1e-4 * max(1.0, np.abs(ja).max())
