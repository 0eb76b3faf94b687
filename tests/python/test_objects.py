"""The object API (SO3, SE3, Twist, Wrench, Screw, Chain): the laws the C++ suite
checks, parametrized over [SO3, SE3] with hypothesis strategies that reach
angle 0, tiny angles, the Taylor cutoff, near pi and exactly pi; cross-checks
against independent code (scipy.linalg.expm, scipy's Rotation and
RigidTransform, the seed's worked example); and the Python protocols
(pickle, copy, repr, np.asarray, operators, docstrings)."""

from __future__ import annotations

import copy
import math
import pickle
import struct
import sys

import numpy as np
import pytest
from helpers import hat3
from hypothesis import given
from hypothesis import strategies as st
from scipy.linalg import expm
from scipy.spatial.transform import Rotation
from strategies import (
    PI,
    SPECIAL_ANGLES,
    angles,
    elements,
    points,
    rotation_vectors,
    se3s,
    tangents,
    twist_vectors,
    twists,
    unit_vectors,
    vectors3,
    wrench_vectors,
    wrenches,
)

import chasles
from chasles import SE3, SO3, Chain, Screw, Twist, Wrench

GROUPS = [SO3, SE3]
TOL = 1e-9


def ids(group):
    return group.__name__


def angle_of(xi) -> float:
    """The rotation angle of a tangent vector of SO3 (w) or SE3 ((v, w))."""
    return float(np.linalg.norm(np.asarray(xi)[-3:]))


def hat_ref(group, xi):
    if group is SO3:
        return hat3(xi)
    X = np.zeros((4, 4))
    X[:3, :3] = hat3(xi[3:])
    X[:3, 3] = xi[:3]
    return X


def adjoint_ref(g: SE3) -> np.ndarray:
    R, p = g.rotation.as_matrix(), g.translation
    A = np.zeros((6, 6))
    A[:3, :3] = R
    A[:3, 3:] = hat3(p) @ R
    A[3:, 3:] = R
    return A


def assert_same(a, b, tol=TOL):
    assert a.is_approx(b, tol), f"\n{a!r}\n!=\n{b!r}"


def close(a, b, tol=TOL):
    """Entries equal within tol, relative beyond unit scale (like is_approx)."""
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    scale = max(1.0, float(np.max(np.abs(a), initial=0.0)), float(np.max(np.abs(b), initial=0.0)))
    return bool(np.all(np.abs(a - b) <= tol * scale))


# ---- group axioms -------------------------------------------------------------


@pytest.mark.parametrize("G", GROUPS, ids=ids)
def test_identity_constructions_agree(G):
    assert np.array_equal(G().as_matrix(), np.eye(G().as_matrix().shape[0]))
    assert np.array_equal(G.identity().as_matrix(), G().as_matrix())
    assert np.array_equal(G.exp(np.zeros(3 if G is SO3 else 6)).as_matrix(), G().as_matrix())
    assert np.array_equal(G().log(), np.zeros(3 if G is SO3 else 6))


@pytest.mark.parametrize("G", GROUPS, ids=ids)
@given(data=st.data())
def test_group_axioms(G, data):
    a, b, c = (data.draw(elements(G)) for _ in range(3))
    assert_same((a @ b) @ c, a @ (b @ c))
    assert_same(a @ G.identity(), a, 0.0)
    assert_same(G.identity() @ a, a, 0.0)
    assert_same(a @ a.inverse(), G.identity())
    assert_same(a.inverse() @ a, G.identity())
    assert_same(a.inverse().inverse(), a, 1e-14)
    assert_same((a @ b).inverse(), b.inverse() @ a.inverse())


@pytest.mark.parametrize("G", GROUPS, ids=ids)
@given(data=st.data())
def test_powers_are_exp_of_t_log(G, data):
    g = data.draw(elements(G))
    t = data.draw(st.floats(-3.0, 3.0))
    # the definition, through an independent matrix exponential
    assert close((g**t).as_matrix(), expm(t * hat_ref(G, g.log())), 1e-9)
    assert_same(g**0, G.identity(), 0.0)
    assert_same(g**1, g, 1e-12)
    assert_same(g ** (-1), g.inverse(), 1e-12)
    assert_same(g**2, g @ g, 1e-9)
    half = g**0.5
    assert_same(half @ half, g, 1e-9)
    assert_same(g ** np.float32(2.0), g @ g, 1e-9)  # any real: numpy scalars, ints


@pytest.mark.parametrize("G", GROUPS, ids=ids)
@given(data=st.data())
def test_powers_equal_scipys(G, data):
    g = data.draw(elements(G))
    # exponents exact in float32: scipy 1.17's RigidTransform ** t rounds t to
    # float32 (g ** -0.3 moves a unit translation by -0.30000001)
    t = data.draw(st.floats(-3.0, 3.0, width=32))
    if angle_of(g.log()) > 3.0:  # near pi the two logs may pick opposite axes
        return
    if G is SO3:
        theirs = Rotation.from_matrix(g.as_matrix()) ** t
    else:
        from scipy.spatial.transform import RigidTransform  # scipy >= 1.16 (the test extras)

        theirs = RigidTransform.from_matrix(g.as_matrix()) ** t
    assert close((g**t).as_matrix(), theirs.as_matrix(), 1e-9)


@pytest.mark.parametrize("G", GROUPS, ids=ids)
@given(data=st.data())
def test_matrices_multiply_like_the_group(G, data):
    a, b = data.draw(elements(G)), data.draw(elements(G))
    assert close((a @ b).as_matrix(), a.as_matrix() @ b.as_matrix(), 1e-12)
    assert close(a.inverse().as_matrix(), np.linalg.inv(a.as_matrix()), 1e-12)
    R = a.as_matrix()[:3, :3]
    assert close(R.T @ R, np.eye(3), 1e-14)
    assert math.isclose(np.linalg.det(R), 1.0, abs_tol=1e-14)


@pytest.mark.parametrize("G", GROUPS, ids=ids)
@given(data=st.data())
def test_action_on_points(G, data):
    g = data.draw(elements(G))
    p = data.draw(points())
    M = g.as_matrix()
    expected = M[:3, :3] @ p + (M[:3, 3] if G is SE3 else 0.0)
    assert close(g @ p, expected, 1e-13)
    assert np.array_equal(g.act(p), g @ p)
    cloud = np.stack([p, 2.0 * p, -p, np.zeros(3)])
    out = g @ cloud
    assert out.shape == (4, 3)
    for k in range(4):
        assert np.array_equal(out[k], g @ cloud[k])


# ---- exp and log --------------------------------------------------------------


@pytest.mark.parametrize("G", GROUPS, ids=ids)
@given(data=st.data())
def test_exp_equals_expm_of_hat(G, data):
    xi = data.draw(tangents(G))
    assert close(G.exp(xi).as_matrix(), expm(hat_ref(G, xi))[: 3 if G is SO3 else 4], 1e-12)
    assert np.array_equal(G.hat(xi), hat_ref(G, xi))
    assert close(G.vee(G.hat(xi)), xi, 1e-15)  # vee halves before subtracting: subnormals may round


@pytest.mark.parametrize("G", GROUPS, ids=ids)
@given(data=st.data())
def test_exp_log_round_trips(G, data):
    xi = data.draw(tangents(G))
    g = G.exp(xi)
    back = g.log()
    assert 0.0 <= angle_of(back) <= PI * (1.0 + 4e-16)  # the angle is <= pi; its vector's norm rounds
    assert np.all(np.isfinite(back))
    assert_same(G.exp(back), g, 1e-12)
    if angle_of(xi) < PI - 1e-6:  # at pi, either axis sign is a correct log
        assert close(back, xi, 1e-12), (xi, back)


@pytest.mark.parametrize("G", GROUPS, ids=ids)
@given(data=st.data())
def test_chasles_every_element_is_the_exp_of_its_log(G, data):
    g = data.draw(elements(G))
    assert_same(G.exp(g.log()), g, 1e-12)


@pytest.mark.parametrize("theta", SPECIAL_ANGLES)
@pytest.mark.parametrize("axis", [(1.0, 0.0, 0.0), (0.0, -1.0, 0.0), (0.0, 0.0, 1.0), (1.0, 2.0, -2.0)])
def test_special_angles_exactly(theta, axis):
    u = np.array(axis) / np.linalg.norm(axis)
    w = theta * u
    R = SO3.exp(w)
    assert close(R.as_matrix(), Rotation.from_rotvec(w).as_matrix(), 1e-15)
    back = R.log()
    assert np.all(np.isfinite(back))
    if theta < PI - 1e-6:
        assert close(back, w, 1e-15) or np.allclose(back, w, rtol=1e-13, atol=0.0)
    else:
        assert math.isclose(np.linalg.norm(back), theta, rel_tol=1e-9)
        assert_same(SO3.exp(back), R, 1e-15)


def test_tiny_angles_keep_their_digits():
    for theta in (1e-300, 1e-100, 1e-20, 1e-12, 1e-9):
        w = np.array([theta, -2.0 * theta, 0.5 * theta])
        assert np.allclose(SO3.exp(w).log(), w, rtol=1e-15, atol=0.0)
        xi = np.concatenate([[1.0, 2.0, 3.0], w])
        assert np.allclose(SE3.exp(xi).log(), xi, rtol=1e-15, atol=0.0)


@given(w=rotation_vectors())
def test_so3_log_against_scipy_rotvec(w):
    R = SO3.exp(w)
    ref = Rotation.from_matrix(R.as_matrix()).as_rotvec()
    ours = R.log()
    assert math.isclose(np.linalg.norm(ours), np.linalg.norm(ref), rel_tol=1e-9, abs_tol=1e-15)
    if angle_of(w) < PI - 1e-6:
        assert close(ours, ref, 1e-12)
    assert close(Rotation.from_rotvec(ours).as_matrix(), R.as_matrix(), 1e-12)


@given(w=rotation_vectors(), scalar_first=st.booleans())
def test_quaternions_against_scipy(w, scalar_first):
    R = SO3.exp(w)
    q = R.as_quat(scalar_first=scalar_first)
    ref = Rotation.from_matrix(R.as_matrix()).as_quat(scalar_first=scalar_first)
    assert close(q, ref, 1e-12) or close(q, -ref, 1e-12)  # q and -q are one rotation
    assert math.isclose(np.linalg.norm(q), 1.0, rel_tol=1e-15)
    assert np.max(np.abs(q)) == np.max(q)  # the sign rule: largest component positive
    assert_same(SO3.from_quat(ref, scalar_first=scalar_first), R, 1e-12)
    assert_same(SO3.from_quat(-3.5 * q, scalar_first=scalar_first), R, 1e-12)
    assert close(Rotation.from_quat(q, scalar_first=scalar_first).as_matrix(), R.as_matrix(), 1e-12)


def test_quaternion_order_is_scalar_last_by_default_like_scipy():
    s = math.sqrt(0.5)
    R = SO3.from_quat([0.0, 0.0, s, s])  # 90 degrees about z, scalar last
    assert close(R.log(), [0.0, 0.0, PI / 2], 1e-15)
    assert close(R.as_quat(), Rotation.from_rotvec([0.0, 0.0, PI / 2]).as_quat(), 1e-15)
    assert close(SO3.from_quat([s, s, 0.0, 0.0], scalar_first=True).log(), [PI / 2, 0.0, 0.0], 1e-15)
    assert close(SO3.from_quat([s, 0.0, 0.0, s], scalar_first=True).log(), [0.0, 0.0, PI / 2], 1e-15)


@pytest.mark.parametrize("scale", [1e-200, 1e-160, 1.0, 1e160, 1e200])
def test_quaternions_of_any_finite_norm(scale):
    q = np.array([0.1, -0.7, 0.2, 0.5])
    assert_same(SO3.from_quat(scale * q), SO3.from_quat(q), 1e-15)


@given(xi=twist_vectors())
def test_se3_against_scipy_rigid_transform(xi):
    rt = pytest.importorskip("scipy.spatial.transform").__dict__.get("RigidTransform")
    if rt is None:
        pytest.skip("scipy has no RigidTransform")
    twist = Twist.from_vector(xi)
    g = SE3.exp(xi)
    # scipy's exponential coordinates are (rotation vector, translation part):
    # the Modern Robotics order (w, v), not chasles' (v, w).
    ref = rt.from_exp_coords(twist.to_modern_robotics())
    assert close(g.as_matrix(), ref.as_matrix(), 1e-12)
    back = rt.from_matrix(g.as_matrix()).as_exp_coords()
    if angle_of(xi) < PI - 1e-6:
        assert close(Twist.from_modern_robotics(back).vector, g.log(), 1e-9)


# ---- adjoint --------------------------------------------------------------------


@pytest.mark.parametrize("G", GROUPS, ids=ids)
@given(data=st.data())
def test_adjoint_is_a_homomorphism(G, data):
    a, b = data.draw(elements(G)), data.draw(elements(G))
    assert close((a @ b).adjoint(), a.adjoint() @ b.adjoint(), 1e-12)
    assert close(a.inverse().adjoint(), np.linalg.inv(a.adjoint()), 1e-11)


@pytest.mark.parametrize("G", GROUPS, ids=ids)
@given(data=st.data())
def test_conjugation_is_exp_of_adjoint(G, data):
    g = data.draw(elements(G))
    xi = data.draw(tangents(G))
    assert_same(g @ G.exp(xi) @ g.inverse(), G.exp(g.adjoint() @ xi), 1e-10)
    X = hat_ref(G, xi)
    M = g.as_matrix()
    assert close(M @ X @ np.linalg.inv(M), G.hat(g.adjoint() @ xi), 1e-11)


@given(g=se3s())
def test_se3_adjoint_matches_its_definition(g):
    assert close(g.adjoint(), adjoint_ref(g), 1e-15)
    assert np.array_equal(g.rotation.adjoint(), g.rotation.as_matrix())


# ---- twists, wrenches and frames ------------------------------------------------


@given(g=se3s(), V=twists(), F=wrenches())
def test_power_is_frame_independent(g, V, F):
    p = V.power(F)
    assert p == F.power(V)
    # Power can cancel to 0: compare with |V| |F| (times the lever arm |p|), from
    # max-norms, which do not underflow for tiny vectors as |x|^2 does.
    lever = 1.0 + float(np.max(np.abs(g.translation)))
    scale = 6.0 * float(np.max(np.abs(V.vector))) * float(np.max(np.abs(F.vector))) * lever
    assert abs(g.act(V).power(g.act(F)) - p) <= 1e-13 * scale + 1e-300
    assert abs(g.act_inv(V).power(g.act_inv(F)) - p) <= 1e-13 * scale + 1e-300
    assert abs(p - float(np.dot(V.vector, F.vector))) <= 1e-15 * scale


@given(g=se3s(), V=twists(), F=wrenches())
def test_twists_change_frame_by_ad_and_wrenches_by_its_inverse_transpose(g, V, F):
    Ad = adjoint_ref(g)
    assert close(g.act(V).vector, Ad @ V.vector, 1e-12)
    assert close(g.act_inv(V).vector, np.linalg.solve(Ad, V.vector), 1e-10)
    assert close(g.act(F).vector, np.linalg.solve(Ad.T, F.vector), 1e-10)
    assert close(g.act_inv(F).vector, Ad.T @ F.vector, 1e-12)
    assert_same(g.act_inv(g.act(V)), V, 1e-10)
    assert_same(g.act_inv(g.act(F)), F, 1e-10)


@given(g=se3s(), Vb=twists())
def test_spatial_and_body_twists(g, Vb):
    g_dot = g.as_matrix() @ Vb.hat()  # g' = g [V^b]
    assert_same(Twist.body(g, g_dot), Vb, 1e-10)
    Vs = Twist.spatial(g, g_dot)
    assert_same(Vs, g.act(Vb), 1e-10)  # V^s = Ad_g V^b
    assert close(Vs.hat(), g_dot @ np.linalg.inv(g.as_matrix()), 1e-10)


@given(a=twists(), b=twists())
def test_bracket_is_the_matrix_commutator_and_ad(a, b):
    c = a.bracket(b)
    assert close(c.hat(), a.hat() @ b.hat() - b.hat() @ a.hat(), 1e-12)
    assert close(a.ad() @ b.vector, c.vector, 1e-12)
    assert_same(b.bracket(a), -c, 1e-15)


@given(a=twists(), b=twists(), k=st.floats(-10, 10))
def test_twist_arithmetic(a, b, k):
    assert np.array_equal((a + b).vector, a.vector + b.vector)
    assert np.array_equal((a - b).vector, a.vector - b.vector)
    assert np.array_equal((-a).vector, -a.vector)
    assert np.array_equal((+a).vector, a.vector)
    assert np.array_equal((a * k).vector, a.vector * k)
    assert np.array_equal((k * a).vector, a.vector * k)
    assert np.array_equal((np.float64(k) * a).vector, a.vector * k)
    assert isinstance(np.float32(2.0) * a, Twist)
    assert isinstance(np.int64(2) * a, Twist)
    assert np.array_equal((a * np.array(2.0)).vector, 2.0 * a.vector)
    if abs(k) >= 1e-6:
        assert np.array_equal((a / k).vector, a.vector / k)


@given(F=wrenches(), G=wrenches())
def test_wrench_arithmetic(F, G):
    assert np.array_equal((F + G).vector, F.vector + G.vector)
    assert np.array_equal((F - G).vector, F.vector - G.vector)
    assert np.array_equal((2 * F).vector, 2.0 * F.vector)
    assert np.array_equal((-F).vector, -F.vector)


def test_parts_and_orders():
    xi = Twist(v=[1.0, 2.0, 3.0], w=[4.0, 5.0, 6.0])
    assert np.array_equal(xi.vector, [1, 2, 3, 4, 5, 6])
    assert np.array_equal(xi.linear, [1, 2, 3])
    assert np.array_equal(xi.angular, [4, 5, 6])
    assert np.array_equal(xi.to_modern_robotics(), [4, 5, 6, 1, 2, 3])
    assert np.array_equal(Twist.from_modern_robotics([4, 5, 6, 1, 2, 3]).vector, xi.vector)
    assert np.array_equal(Twist.from_vector(xi.vector).vector, xi.vector)
    assert np.array_equal(Twist().vector, np.zeros(6))
    assert np.array_equal(Twist.vee(xi.hat()).vector, xi.vector)
    F = Wrench(f=[1.0, 2.0, 3.0], tau=[4.0, 5.0, 6.0])
    assert np.array_equal(F.force, [1, 2, 3])
    assert np.array_equal(F.torque, [4, 5, 6])
    assert np.array_equal(Wrench.from_vector(F.vector).vector, F.vector)
    assert np.array_equal(Wrench().vector, np.zeros(6))


# The vocabulary: what an object stores is a read-only property, what it
# computes is a method. Every property and method of every class is listed
# here, so that a new one has to be placed on one side or the other.
STORED = {
    SO3: set(),
    SE3: {"rotation", "translation"},
    Twist: {"vector", "linear", "angular"},
    Wrench: {"vector", "force", "torque"},
    Screw: {"point", "direction", "pitch", "magnitude"},
    Chain: {
        "space_screws",
        "body_screws",
        "home",
        "n_joints",
        "joint_types",
        "joint_names",
        "lower",
        "upper",
        "velocity_limits",
        "effort_limits",
        "base",
        "tool",
        "gravity",
        "link_inertias",
    },
}
COMPUTED = {
    SO3: {
        "log",
        "angle",
        "inverse",
        "act",
        "adjoint",
        "as_matrix",
        "as_quat",
        "as_euler",
        "as_rpy",
        "normalized",
        "is_approx",
        "to_scipy",
    },
    SE3: {"log", "inverse", "act", "act_inv", "adjoint", "as_matrix", "normalized", "is_approx", "to_scipy"},
    Twist: {"to_modern_robotics", "hat", "ad", "bracket", "screw", "pitch", "power", "is_approx"},
    Wrench: {"power", "screw", "pitch", "is_approx"},
    Screw: {"is_approx"},
    Chain: {
        "forward",
        "forward_body",
        "jacobian_space",
        "jacobian_body",
        "inverse_kinematics",
        "inverse_dynamics",
        "forward_dynamics",
        "mass_matrix",
        "gravity_torques",
        "coriolis",
        "jacobian_space_dot",
        "jacobian_body_dot",
        "inverse_dynamics_derivatives",
        "forward_dynamics_derivatives",
        "mass_matrix_inverse",
    },
}


@pytest.mark.parametrize("cls", list(STORED), ids=lambda c: c.__name__)
def test_stored_parts_are_properties_and_computations_are_methods(cls):
    members = {n: v for n, v in vars(cls).items() if not n.startswith("_")}
    properties = {n for n, v in members.items() if isinstance(v, property)}
    methods = {n for n, v in members.items() if callable(v) and not isinstance(v, staticmethod)}
    assert properties == STORED[cls]
    assert methods == COMPUTED[cls]
    from api_spec import GOOD

    x = GOOD[cls]()
    for name in STORED[cls]:
        value = getattr(x, name)
        assert not callable(value), f"{cls.__name__}.{name} is a {type(value).__name__}"
        with pytest.raises(AttributeError):
            setattr(x, name, value)  # read-only: the objects are values
    for name in COMPUTED[cls]:
        assert callable(getattr(x, name)), f"{cls.__name__}.{name}"


def test_se3_rotation_and_translation_are_properties():
    R = SO3.exp([0.1, 0.2, 0.3])
    g = SE3(R, [1.0, 2.0, 3.0])
    assert isinstance(g.rotation, SO3) and g.rotation.is_approx(R, 0.0)
    assert isinstance(g.translation, np.ndarray) and g.translation.shape == (3,)
    assert np.array_equal(g.translation, [1.0, 2.0, 3.0])
    with pytest.raises(TypeError, match="not callable"):
        g.translation()  # the old method form fails loudly, never a bound method
    with pytest.raises(TypeError, match="not callable"):
        g.rotation()
    xi = Twist(v=[0.0, 0.0, 0.5], w=[0.0, 0.0, 2.0])
    assert xi.pitch() == 0.25 == xi.screw().pitch
    F = Wrench(f=[0.0, 0.0, 2.0], tau=[0.0, 0.0, 1.0])
    assert F.pitch() == 0.5 == F.screw().pitch


# ---- screws (Chasles and Poinsot) -----------------------------------------------


@given(g=se3s())
def test_from_screw_of_the_screw_of_log_gives_g_back(g):
    s = Twist.from_vector(g.log()).screw()
    assert_same(SE3.from_screw(s.point, s.direction, s.pitch, s.magnitude), g, 1e-9)
    assert_same(SE3.from_screw(*s), g, 1e-9)


SUBNORMAL_SPACING = 5e-324  # the gap between adjacent subnormal doubles


def unit(x):
    """x / |x| to full precision for every nonzero x, subnormal included:
    scaled by its largest entry first (x / |x| of a subnormal x loses bits)."""
    m = float(np.max(np.abs(x)))
    if m == 0.0:
        return x
    y = x / m
    return y / math.hypot(*y)


@given(xi=twists())
def test_screw_of_a_twist(xi):
    s = xi.screw()
    w, v = xi.angular, xi.linear
    # |w| without forming |w|^2 (which underflows below 1e-154): the screw is
    # representable whenever its pitch and point are, however small w is.
    nw = np.float64(math.hypot(*w))
    u = unit(w)
    with np.errstate(over="ignore", divide="ignore", invalid="ignore"):
        pitch, point = (u @ v) / nw, np.cross(u, v) / nw
    if nw > 0 and np.isfinite(pitch) and np.isfinite(point).all():
        # A subnormal |w| is only known to its spacing, 2^-1074: the pitch
        # and point, divided by it, inherit that relative error.
        rel = max(1e-12, 4 * SUBNORMAL_SPACING / nw)
        assert math.isclose(s.magnitude, nw, rel_tol=1e-15, abs_tol=2 * SUBNORMAL_SPACING)
        assert close(s.direction, u, 1e-15)
        assert math.isclose(s.pitch, pitch, rel_tol=rel, abs_tol=1e-12)
        assert close(s.point, point, rel)
        assert xi.pitch() == s.pitch
    elif math.hypot(*v) > 0:
        # w = 0, or so small that the axis is beyond the largest finite
        # distance: a pure translation.
        assert s.pitch == math.inf and xi.pitch() == math.inf
        assert math.isclose(s.magnitude, math.hypot(*v), rel_tol=1e-15)
    assert_same(Twist.from_screw(*s), xi, 1e-9)


def test_screw_of_a_pure_translation_and_of_zero():
    s = Twist(v=[0.0, 3.0, 4.0]).screw()
    assert s.pitch == math.inf and s.magnitude == 5.0
    assert np.array_equal(s.direction, [0.0, 0.6, 0.8]) and np.array_equal(s.point, np.zeros(3))
    g = SE3.from_screw([1.0, 2.0, 3.0], [0.0, 0.0, 2.0], math.inf, 1.5)
    assert_same(g, SE3(translation=[0.0, 0.0, 1.5]), 0.0)
    z = Twist().screw()
    assert (z.pitch, z.magnitude) == (0.0, 0.0) and np.array_equal(z.direction, np.zeros(3))
    assert_same(SE3.from_screw(*z), SE3(), 0.0)


@given(F=wrenches())
def test_screw_of_a_wrench(F):
    s = F.screw()
    f, tau = F.force, F.torque
    nf = np.float64(math.hypot(*f))  # |f| without |f|^2, as the library
    u = unit(f)
    with np.errstate(over="ignore", divide="ignore", invalid="ignore"):
        pitch, point = (u @ tau) / nf, np.cross(u, tau) / nf
    if nf > 0 and np.isfinite(pitch) and np.isfinite(point).all():
        rel = max(1e-12, 4 * SUBNORMAL_SPACING / nf)  # as for twists
        assert math.isclose(s.magnitude, nf, rel_tol=1e-15, abs_tol=2 * SUBNORMAL_SPACING)
        assert math.isclose(s.pitch, pitch, rel_tol=rel, abs_tol=1e-12)
        assert F.pitch() == s.pitch
    elif math.hypot(*tau) > 0:
        # f = 0, or so small that the line is beyond the largest finite
        # distance: a pure couple.
        assert s.pitch == math.inf and math.isclose(s.magnitude, math.hypot(*tau), rel_tol=1e-15)
    assert_same(Wrench.from_screw(*s), F, 1e-9)


@given(q=vectors3(), d=unit_vectors(), h=st.floats(-5, 5), theta=angles())
def test_from_screw_formula(q, d, h, theta):
    expected = theta * np.concatenate([-np.cross(d, q) + h * d, d])
    assert close(Twist.from_screw(q, d, h, theta).vector, expected, 1e-14)
    assert close(Twist.from_screw(q, 3.0 * d, h, theta).vector, expected, 1e-14)  # d is normalized
    assert_same(SE3.from_screw(q, d, h, theta), SE3.exp(expected), 1e-14)
    F = Wrench.from_screw(q, d, h, theta)
    assert close(F.vector, theta * np.concatenate([d, np.cross(q, d) + h * d]), 1e-14)


@given(l1=st.floats(-10, 10), theta=st.one_of(st.sampled_from(SPECIAL_ANGLES), st.floats(-10, 10)))
def test_seed_worked_example(l1, theta):
    """Rotation by theta about z through (0, l1, 0), pitch 0 (the seed's last section)."""
    xi = Twist.from_screw([0.0, l1, 0.0], [0.0, 0.0, 1.0], 0.0, 1.0)
    assert np.array_equal(xi.vector, [l1, 0.0, 0.0, 0.0, 0.0, 1.0]) or np.array_equal(
        xi.vector, [l1, -0.0, 0.0, 0.0, 0.0, 1.0]
    )
    assert np.array_equal(xi.hat(), [[0, -1, 0, l1], [1, 0, 0, 0], [0, 0, 0, 0], [0, 0, 0, 0]])
    c, s = math.cos(theta), math.sin(theta)
    closed_form = np.array([[c, -s, 0, l1 * s], [s, c, 0, l1 * (1 - c)], [0, 0, 1, 0], [0, 0, 0, 1]])
    g = SE3.exp(theta * xi.vector)
    assert close(g.as_matrix(), closed_form, 1e-13)
    axis = np.array([[0.0, l1, z] for z in (-3.0, 0.0, 2.5)])
    assert close(g @ axis, axis, 1e-13)


# ---- construction from matrices, normalization, interpolation ------------------


@pytest.mark.parametrize("G", GROUPS, ids=ids)
@given(data=st.data())
def test_from_matrix_forms(G, data):
    g = data.draw(elements(G))
    M = g.as_matrix()
    assert_same(G.from_matrix(M), g, 0.0)
    assert_same(G.from_matrix_unchecked(M), g, 0.0)
    assert_same(G.from_matrix_projected(M), g, 1e-14)
    n = M.shape[0]
    noisy = M.copy()
    noisy[:3, :3] += 1e-6 * np.arange(9.0).reshape(3, 3) / 9.0
    with pytest.raises(ValueError, match="from_matrix_projected"):
        G.from_matrix(noisy)
    assert_same(G.from_matrix(noisy, tol=1e-4), G.from_matrix_unchecked(noisy), 0.0)
    assert_same(G.from_matrix_projected(noisy), g, 1e-5)
    assert_same(G.from_matrix_unchecked(noisy).normalized(), G.from_matrix_projected(noisy), 1e-14)
    assert n in (3, 4)


def test_rotation_and_transform_defects():
    assert SO3.rotation_defect(np.eye(3)) == 0.0
    assert SO3.rotation_defect(np.diag([1.0, 1.0, -1.0])) == 2.0
    assert math.isclose(SO3.rotation_defect(np.eye(3) * (1 + 1e-6)), 3e-6, rel_tol=1e-3)
    M = np.eye(4)
    M[3, 0] = 0.25
    assert SE3.transform_defect(M) == 0.25
    assert SO3.rotation_defect(np.full((3, 3), np.nan)) == math.inf
    assert SE3.transform_defect(np.full((4, 4), np.inf)) == math.inf


@pytest.mark.parametrize("G", GROUPS, ids=ids)
@given(data=st.data(), t=st.floats(0.0, 1.0))
def test_interpolation(G, data, t):
    a, b = data.draw(elements(G)), data.draw(elements(G))
    assert_same(G.interpolate(a, b, 0.0), a, 1e-12)
    assert_same(G.interpolate(a, b, 1.0), b, 1e-9)
    m = G.interpolate(a, b, t)
    assert_same(chasles.interpolate(a, b, t), m, 0.0)
    assert_same(m, a @ G.exp(t * (a.inverse() @ b).log()), 1e-12)


def test_se3_parts():
    R = SO3.exp([0.1, 0.2, 0.3])
    g = SE3(R, [1.0, 2.0, 3.0])
    assert_same(g.rotation, R, 0.0)
    assert np.array_equal(g.translation, [1.0, 2.0, 3.0])
    assert np.array_equal(g.as_matrix()[3], [0.0, 0.0, 0.0, 1.0])
    assert_same(SE3(rotation=R), SE3(R, (0, 0, 0)), 0.0)
    assert_same(SE3(translation=[1, 2, 3]).rotation, SO3(), 0.0)
    assert close(g.act_inv(g @ [4.0, 5.0, 6.0]), [4.0, 5.0, 6.0], 1e-15)


# ---- points: shapes, layouts, dtypes ----------------------------------------------


@pytest.mark.parametrize("G", GROUPS, ids=ids)
def test_points_of_any_leading_shape_layout_and_dtype(G):
    rng = np.random.default_rng(7)
    g = G.exp(rng.normal(size=3 if G is SO3 else 6))
    base = rng.normal(size=(2, 5, 3))
    ref = (g.as_matrix()[:3, :3] @ base.reshape(-1, 3).T).T.reshape(2, 5, 3)
    if G is SE3:
        ref = ref + g.translation
    assert close(g @ base, ref, 1e-14) and (g @ base).shape == (2, 5, 3)
    flat = base.reshape(-1, 3)
    assert np.array_equal(g @ flat, (g @ base).reshape(-1, 3))
    assert np.array_equal(g @ np.asfortranarray(flat), g @ flat)
    strided = np.zeros((10, 6))
    strided[:, ::2] = flat
    assert np.array_equal(g @ strided[:, ::2], g @ flat)
    assert np.array_equal(g @ flat[::-1], (g @ flat)[::-1])
    assert np.array_equal(g @ flat.astype(">f8"), g @ flat)
    # float32 points give float32: the pose rounded to float32 once, then the
    # float32 kernel (the bits of the array function on float32 operands)
    f32 = flat.astype(np.float32)
    act = chasles.so3_act if G is SO3 else chasles.se3_act
    assert (g @ f32).dtype == np.float32 and g.act(f32).dtype == np.float32
    assert np.array_equal(g @ f32, act(g.as_matrix().astype(np.float32), f32))
    assert np.array_equal(g.act(f32), g @ f32)
    assert np.array_equal(g @ [1, 2, 3], g @ np.array([1.0, 2.0, 3.0]))
    assert np.array_equal(g @ (1, 2, 3), g @ np.array([1.0, 2.0, 3.0]))
    assert np.array_equal(g @ [[1, 2, 3]], g @ np.array([[1.0, 2.0, 3.0]]))
    assert (g @ np.zeros((0, 3))).shape == (0, 3)
    out = g @ flat
    assert out.dtype == np.float64 and out.flags.c_contiguous and out.flags.writeable
    many = rng.normal(size=(10000, 3))  # large enough to release the GIL
    assert np.array_equal((g @ many)[1234], g @ many[1234])
    before = flat.copy()
    g @ flat
    assert np.array_equal(flat, before)  # the input is not modified


def test_results_are_fresh_arrays():
    g = SE3.exp([1.0, 2.0, 3.0, 0.1, 0.2, 0.3])
    m = g.as_matrix()
    m[0, 0] = 42.0
    assert g.as_matrix()[0, 0] != 42.0
    t = g.translation
    t[0] = 42.0
    assert g.translation[0] != 42.0
    xi = Twist(v=[1.0, 2.0, 3.0])
    v = xi.vector
    v[0] = 42.0
    assert xi.vector[0] == 1.0


# ---- Python protocols ---------------------------------------------------------------


def all_kinds():
    g = SE3(SO3.exp([0.1, -0.2, 0.3]), [1.0 / 3.0, 2.0, -7.25])
    return [
        g.rotation,
        g,
        Twist(v=[0.1, 0.2, 1.0 / 3.0], w=[1e-300, -0.0, 5.0]),
        Wrench(f=[1.0, 2.0, 3.0], tau=[math.pi, 0.0, -1e10]),
        Twist(v=[1.0, 2.0, 3.0], w=[0.0, 0.0, 1.0]).screw(),
        Twist(v=[1.0, 2.0, 3.0]).screw(),
        Chain(
            [Chain.revolute_screw([1.0 / 3.0, 0, 0], [0, 0, 1]), Chain.prismatic_screw([1, 2, 3])],
            g,
        ),
    ]


def state_of(x):
    return x.__getstate__()


def bits(x) -> bytes:
    return np.array(state_of(x), dtype=np.float64).tobytes()


@pytest.mark.parametrize("x", all_kinds(), ids=lambda x: type(x).__name__)
@pytest.mark.parametrize("protocol", range(pickle.HIGHEST_PROTOCOL + 1))
def test_pickle_is_bit_exact(x, protocol):
    y = pickle.loads(pickle.dumps(x, protocol=protocol))
    assert type(y) is type(x) and y is not x
    assert bits(y) == bits(x)


@pytest.mark.parametrize("x", all_kinds(), ids=lambda x: type(x).__name__)
def test_copy_and_deepcopy_are_exact_and_distinct(x):
    for y in (copy.copy(x), copy.deepcopy(x), copy.deepcopy([x, x])[0]):
        assert type(y) is type(x) and y is not x
        assert bits(y) == bits(x)


# ---- pickling of special values, bit for bit --------------------------------------------

MAX = 1.7976931348623157e308
SPECIAL_VALUES = [
    -0.0,
    5e-324,
    -5e-324,
    2.2250738585072014e-308 / 3,
    2.2250738585072014e-308,
    1e-300,
    MAX,
    -MAX,
    1.0 / 3.0,
    math.pi,
]


def from_bits(bits: int) -> float:
    return struct.unpack("<d", struct.pack("<Q", bits))[0]


def to_bits(x: float) -> int:
    return struct.unpack("<Q", struct.pack("<d", x))[0]


# NaNs of other signs and payloads than the default one (quiet, positive, 0):
# no object holds one (every constructor, and every __setstate__, refuses NaN).
NAN_PAYLOADS = [
    from_bits(b)
    for b in (0x7FF8000000000000, 0x7FF8000000000001, 0xFFF8000000000000, 0x7FFC0000DEADBEEF, 0xFFFFFFFFFFFFFFFF)
]

IDENTITY = (1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0)
OFF_DIAGONAL = (1, 2, 3, 5, 6, 7)


def free_positions(x):
    """(state, positions): a valid state of x's class and where in it any
    finite number ("any") or any number of magnitude <= 1e-300 ("tiny")
    keeps it valid: the off-diagonal entries of an identity rotation, the
    translations, twists, wrenches and screw parameters, the first joint's
    linear part and the home pose of the chain of all_kinds()."""
    state = list(x.__getstate__())
    if isinstance(x, SO3):
        return IDENTITY, [(i, "tiny") for i in OFF_DIAGONAL]
    if isinstance(x, SE3):
        return IDENTITY + tuple(state[9:]), [(i, "tiny") for i in OFF_DIAGONAL] + [(i, "any") for i in (9, 10, 11)]
    if isinstance(x, (Twist, Wrench, Screw)):
        return tuple(state), [(i, "any") for i in range(len(state))]
    assert isinstance(x, Chain) and x.n_joints == 2  # joint 0 revolute about z: (v_x, v_y, ~0, 0, 0, 1)
    home = 6 * x.n_joints
    state[home : home + 9] = IDENTITY
    positions = [(0, "any"), (1, "any"), (2, "tiny")] + [(home + i, "tiny") for i in OFF_DIAGONAL]
    return tuple(state), positions + [(home + i, "any") for i in (9, 10, 11)]


def special_objects(values):
    """Objects of every class whose numbers cycle through `values` where
    they can (free_positions; set through their state: constructors keep no
    -0.0 of a norm)."""
    tiny = [v for v in values if abs(v) <= 1e-300]
    finite = [v for v in values if math.isfinite(v)]
    out = []
    for x in all_kinds():
        state, positions = free_positions(x)
        state = list(state)
        for k, (i, kind) in enumerate(positions):
            pool = tiny if kind == "tiny" else finite
            state[i] = pool[k % len(pool)]
        y = type(x).__new__(type(x))
        y.__setstate__(tuple(state))
        out.append(y)
    return out


def arrays_of(x):
    """Every array the object shows (its matrix, vectors, screws, home)."""
    out = {}
    for name in ("as_matrix", "to_modern_robotics", "log"):
        if hasattr(x, name) and not isinstance(x, Chain):
            with np.errstate(all="ignore"):
                out[name] = getattr(x, name)()
    for name in ("translation", "vector", "point", "direction", "space_screws", "body_screws"):
        if hasattr(type(x), name):
            out[name] = np.asarray(getattr(x, name))
    if isinstance(x, Chain):
        out["home"] = x.home.as_matrix()
    if isinstance(x, Screw):
        out["pitch, magnitude"] = np.array([x.pitch, x.magnitude])
    return out


def state_bits(x):
    return [to_bits(v) for v in x.__getstate__()]


@pytest.mark.parametrize("protocol", range(pickle.HIGHEST_PROTOCOL + 1))
@pytest.mark.parametrize(
    "values",
    [SPECIAL_VALUES, SPECIAL_VALUES[::-1], SPECIAL_VALUES[3:] + SPECIAL_VALUES[:3]],
    ids=["special", "special-reversed", "special-rotated"],
)
def test_pickle_of_special_values_is_bit_exact(protocol, values):
    """-0.0, subnormals and the extremes survive a pickle round trip bit for
    bit, in the state and in every array the object shows (the bytes of the
    arrays compared)."""
    for x in special_objects(values):
        y = pickle.loads(pickle.dumps(x, protocol=protocol))
        assert type(y) is type(x)
        assert state_bits(y) == state_bits(x), type(x).__name__
        ax, ay = arrays_of(x), arrays_of(y)
        assert ax.keys() == ay.keys()
        for name in ax:
            assert ax[name].tobytes() == ay[name].tobytes(), f"{type(x).__name__}.{name}"
        for z in (copy.copy(x), copy.deepcopy(x)):
            assert state_bits(z) == state_bits(x)


@pytest.mark.parametrize("x", all_kinds(), ids=lambda x: type(x).__name__)
def test_a_state_with_a_nan_or_an_infinity_is_refused(x):
    """Every constructor refuses NaN, and so does __setstate__ (a pickle is
    data from outside), whatever the NaN's sign and payload and wherever it
    is; and an infinity, except as a screw's pitch. The error names the
    class's __setstate__."""
    name = type(x).__name__
    state = x.__getstate__()
    for i in range(len(state)):
        for bad in NAN_PAYLOADS + [-math.inf] + ([] if isinstance(x, Screw) and i == 6 else [math.inf]):
            y = type(x).__new__(type(x))
            with pytest.raises(ValueError, match=rf"^{name}\.__setstate__"):
                y.__setstate__(tuple(bad if k == i else v for k, v in enumerate(state)))


def test_chain_pickles_its_screws_and_home_and_rebuilds_the_rest():
    arm = all_kinds()[-1]
    state = arm.__getstate__()
    assert len(state) == 6 * arm.n_joints + 12
    assert np.array_equal(np.array(state[:12]).reshape(2, 6), arm.space_screws)
    back = pickle.loads(pickle.dumps(arm))
    assert back.body_screws.tobytes() == arm.body_screws.tobytes()
    assert back.forward([0.3, -0.2]).tobytes() == arm.forward([0.3, -0.2]).tobytes()
    for bad in ((1.0,) * 17, (1.0,) * 12, (1.0,) * (6 * 33 + 12), [1.0] * 18, None):
        with pytest.raises(ValueError, match=r"Chain.__setstate__: expected a tuple of 6 n \+ 12 floats"):
            Chain.__new__(Chain).__setstate__(bad)
    with pytest.raises(TypeError, match="floats"):
        Chain.__new__(Chain).__setstate__(("a",) + (1.0,) * 17)


def test_pickle_keeps_data_within_the_tolerance_and_negative_zero():
    """A rotation off SO(3) by less than the tolerance of SO3.from_matrix
    pickles as it is; one beyond it (made by from_matrix_unchecked) does not
    load: __setstate__ checks as from_matrix does."""
    M = np.diag([1.0, 1.0, 1.0 + 1e-9])
    R = SO3.from_matrix_unchecked(M)
    assert np.array_equal(pickle.loads(pickle.dumps(R)).as_matrix(), M)
    t = Twist(v=[-0.0, 0.0, 0.0])
    assert math.copysign(1.0, pickle.loads(pickle.dumps(t)).vector[0]) == -1.0
    far = pickle.dumps(SO3.from_matrix_unchecked(np.diag([1.0, 1.0, 1.0 + 1e-3])))
    with pytest.raises(ValueError, match=r"^SO3.__setstate__: not a rotation matrix: its rotation defect"):
        pickle.loads(far)


@pytest.mark.parametrize("x", all_kinds()[:4], ids=lambda x: type(x).__name__)
def test_asarray(x):
    expected = x.as_matrix() if hasattr(x, "as_matrix") else x.vector
    a = np.asarray(x)
    assert a.dtype == np.float64 and np.array_equal(a, expected)
    assert np.array_equal(np.array(x), expected)
    assert np.array_equal(np.array(x, copy=True), expected)
    f = np.asarray(x, dtype=np.float32)
    assert f.dtype == np.float32 and np.array_equal(f, expected.astype(np.float32))
    with pytest.raises(ValueError, match="copy"):
        np.array(x, copy=False)
    assert np.asarray([x, x]).shape == (2,) + expected.shape


def test_repr_shows_the_numbers():
    assert repr(SO3()) == "SO3(matrix=[[1., 0., 0.], [0., 1., 0.], [0., 0., 1.]])"
    assert repr(SE3(translation=[1.0, 2.0, 3.5])) == (
        "SE3(rotation=[[1., 0., 0.], [0., 1., 0.], [0., 0., 1.]], translation=[1. , 2. , 3.5])"
    )
    assert repr(Twist(v=[1.0, 2.0, 3.0], w=[0.0, 0.0, 1.0])) == "Twist(v=[1., 2., 3.], w=[0., 0., 1.])"
    assert repr(Wrench(f=[0.0, 0.0, -9.81])) == "Wrench(f=[ 0.  ,  0.  , -9.81], tau=[0., 0., 0.])"
    assert repr(Twist(v=[1.0, 0.0, 0.0]).screw()) == (
        "Screw(point=[0., 0., 0.], direction=[1., 0., 0.], pitch=inf, magnitude=1.0)"
    )
    assert "0.12345679" in repr(SE3(translation=[0.123456789, 0.0, 0.0]))  # numpy's print options


def with_state(x, change):
    """A fresh object of x's class whose state is x's, changed by `change(list)`."""
    state = list(x.__getstate__())
    change(state)
    y = type(x).__new__(type(x))
    y.__setstate__(tuple(state))
    return y


@pytest.mark.parametrize("x", all_kinds(), ids=lambda x: type(x).__name__)
def test_equality_is_exact_on_the_stored_numbers(x):
    """== is a value comparison: equal numbers are equal objects, a difference
    of one ulp in any stored number is not; != is its negation."""
    y = copy.copy(x)
    assert y is not x
    assert (x == y) is True and (x != y) is False
    assert x == pickle.loads(pickle.dumps(x)) == copy.deepcopy(x)
    n = len(x.__getstate__())
    for k in range(n):
        # the next float (toward 0 from inf: an infinite pitch is stored too)
        z = with_state(x, lambda s, k=k: s.__setitem__(k, float(np.nextafter(s[k], -s[k] or 1.0))))
        assert (x == z) is False and (z == x) is False, k
        assert (x != z) is True and (z != x) is True, k
        if hasattr(z, "is_approx") and not isinstance(x, Screw):
            assert z.is_approx(x, 1e-9), k  # the tolerance comparison is is_approx


def test_equality_compares_as_floats_negative_zero_and_nan():
    a, b = Twist(v=[0.0, 1.0, 2.0]), Twist(v=[-0.0, 1.0, 2.0])
    assert a == b and not (a != b)  # -0.0 == 0.0, as floats
    assert math.copysign(1.0, a.vector[0]) == 1.0 and math.copysign(1.0, b.vector[0]) == -1.0
    # Every constructor and __setstate__ refuse NaN: a NaN comes from an
    # overflow, the translation inf + (-inf) of a composition.
    big = SE3(translation=[1.7e308, 0.0, 0.0])
    nan = (big @ big) @ (big.inverse() @ big.inverse())
    assert np.isnan(nan.translation[0])
    assert (nan == nan) is False and (nan != nan) is True  # NaN equals nothing, itself included
    assert nan != copy.copy(nan)


@pytest.mark.parametrize("x", all_kinds(), ids=lambda x: type(x).__name__)
def test_objects_are_unhashable(x):
    assert type(x).__hash__ is None
    with pytest.raises(TypeError, match="unhashable"):
        hash(x)
    with pytest.raises(TypeError):
        {x}  # noqa: B018


def test_comparing_with_another_type_is_not_implemented():
    R, g = SO3(), SE3()
    assert SO3.__eq__(R, 3) is NotImplemented and SO3.__ne__(R, 3) is NotImplemented
    assert (R == 3) is False and (R != 3) is True
    assert (R == g) is False and (g != R) is True
    assert (Twist() == Wrench()) is False  # the same six zeros, different quantities
    assert (R == np.eye(3)) is False and (np.eye(3) == R) is False
    assert (R == R.as_matrix().tolist()) is False and (R == None) is False  # noqa: E711
    assert (g == "SE3") is False and g != [0.0] * 12
    from api_spec import GOOD

    for x in (GOOD[Screw](), GOOD[Chain]()):  # numpy defers to every class
        assert (np.float64(1.0) == x) is False and (np.array(1.0) != x) is True
    assert R in [g, 3, SO3()] and R not in [g, 3]  # containers compare with ==
    raw = SO3.__new__(SO3)
    with pytest.raises(TypeError, match="not initialized"):
        R == raw  # noqa: B015


def test_subclass_instances_compare_by_value():
    class Sub(SE3):
        pass

    g = SE3.exp([0.1, 0.2, 0.3, 0.4, 0.5, 0.6])
    h = Sub.__new__(Sub)
    h.__setstate__(g.__getstate__())
    assert g == h and h == g and not (g != h)


def test_numpy_operands_defer_to_the_objects():
    R = SO3.exp([0.0, 0.0, 1.0])
    with pytest.raises(TypeError):
        np.ones(3) @ R  # would silently be p R (R^T acting) if numpy converted R
    with pytest.raises(TypeError):
        np.matmul(np.ones(3), R)
    xi = Twist(v=[1.0, 0.0, 0.0])
    assert isinstance(np.float64(2.0) * xi, Twist)
    with pytest.raises(TypeError):
        np.ones(6) + xi


def test_python_subclasses_are_accepted():
    class Pose(SE3):
        pass

    p = Pose(SO3(), [1.0, 2.0, 3.0])
    assert isinstance(p @ SE3(), SE3)
    assert np.array_equal(SE3() @ p @ [0.0, 0.0, 0.0], [1.0, 2.0, 3.0])


@pytest.mark.parametrize("cls", [SO3, SE3, Twist, Wrench])
def test_values_made_by_calls_and_by_pybind11_live_side_by_side(cls):
    """A value returned by a call lives inside its Python object (its class's
    instances are made large enough to hold it, bindings/instance.hpp); one
    made by __init__, __setstate__ or a Python subclass lives where pybind11
    puts it. Both kinds mix in every operation, survive their makers, and
    are freed by the same deallocation (test_leaks counts the memory)."""
    x = np.linspace(0.1, 0.6, 6)
    made = {SO3: lambda: SO3.exp(x[:3]), SE3: lambda: SE3.exp(x)}.get(cls, lambda: cls(x[:3], x[3:]))()
    value_bytes = {SO3: 72, SE3: 96, Twist: 48, Wrench: 48}[cls]
    assert sys.getsizeof(made) >= value_bytes + 3 * 8  # object header, value pointer and holder, value
    restored = cls.__new__(cls)
    restored.__setstate__(made.__getstate__())  # pybind11's own path: the value on the heap

    class Sub(cls):
        pass

    sub = Sub.__new__(Sub)
    sub.__setstate__(made.__getstate__())
    sub.note = "a Python attribute"  # the subclass's __dict__ lies past the enlarged instance
    for x in (restored, sub, copy.copy(made), copy.deepcopy(made), pickle.loads(pickle.dumps(made))):
        assert x == made and made == x
    assert sub.note == "a Python attribute"
    if cls in (SO3, SE3):
        products = [a @ b.inverse() for a in (made, restored, sub) for b in (made, restored, sub)]
        for g in products:
            assert type(g) is cls and g.is_approx(cls.identity(), 1e-15)
        del made, restored, sub
        assert all(g.is_approx(cls.identity(), 1e-15) for g in products)  # the results own their values


def test_is_approx_tolerances():
    a = SE3(translation=[1000.0, 0.0, 0.0])
    b = SE3(translation=[1000.0 + 1e-7, 0.0, 0.0])
    assert a.is_approx(b, 1e-9)  # translations relative beyond unit scale
    assert not a.is_approx(b, 1e-11)
    assert SO3.exp([1e-10, 0, 0]).is_approx(SO3(), 1e-9)
    assert not SO3.exp([1e-8, 0, 0]).is_approx(SO3(), 1e-9)
    assert Twist(v=[1.0, 0, 0]).is_approx(Twist(v=[1.0 + 1e-12, 0, 0]))
    assert math.inf > 0 and SO3().is_approx(SO3.exp([3, 0, 0]), tol=math.inf)


# ---- docstrings ----------------------------------------------------------------------

CLASSES = [SO3, SE3, Twist, Wrench, Screw]
CONVENTION = "twists xi = (v, w), linear part first (Murray, Li and Sastry)"


@pytest.mark.parametrize("cls", CLASSES, ids=lambda c: c.__name__)
def test_class_docstrings_state_the_conventions(cls):
    doc = cls.__doc__
    if cls is Screw:
        assert "pitch" in doc and "magnitude" in doc
        return
    assert CONVENTION in doc
    assert "wrenches F = (f, tau), force first, so power is the dot product V . F" in doc
    assert "Ad_g = [[R, [p]R], [0, R]]" in doc
    assert "(x, y, z, w), scalar last" in doc
    assert "is_approx" in doc


def public_members(cls):
    for name, value in vars(cls).items():
        if name.startswith("_") and name not in ("__init__", "__matmul__"):
            continue
        yield name, value


@pytest.mark.parametrize("cls", CLASSES, ids=lambda c: c.__name__)
def test_every_member_is_documented_with_named_arguments(cls):
    for name, value in public_members(cls):
        doc = getattr(value, "__doc__", None) or getattr(getattr(value, "fget", None), "__doc__", None)
        assert doc and doc.strip(), f"{cls.__name__}.{name} has no docstring"
        assert "arg0" not in doc, f"{cls.__name__}.{name} has an unnamed argument"


def test_version_and_exports():
    assert chasles.__version__ == chasles._core.__version__
    assert isinstance(chasles.__version__, str) and chasles.__version__.count(".") == 2
    for name in chasles.__all__:
        assert hasattr(chasles, name), name
    assert {"SO3", "SE3", "Twist", "Wrench", "Screw", "interpolate"} <= set(chasles.__all__)


@given(w=rotation_vectors(), p=points())
def test_objects_agree_with_the_array_functions(w, p):
    R = SO3.exp(w)
    assert np.array_equal(chasles.so3_exp(w), R.as_matrix())
    assert np.array_equal(chasles.so3_act(R.as_matrix(), p), R @ p)


@given(xi=twist_vectors(), F=wrench_vectors())
def test_objects_agree_with_the_se3_array_functions(xi, F):
    g = SE3.exp(xi)
    assert np.array_equal(chasles.se3_exp(xi), g.as_matrix())
    assert np.array_equal(chasles.se3_log(g.as_matrix()), g.log())
    assert np.array_equal(chasles.se3_adjoint(g.as_matrix()), g.adjoint())
    assert np.array_equal(chasles.se3_act_wrench(g.as_matrix(), F), g.act(Wrench.from_vector(F)).vector)
    assert np.array_equal(chasles.se3_act_twist(g.as_matrix(), xi), g.act(Twist.from_vector(xi)).vector)


def live_objects():
    """Objects of every bound class, each made by its __init__ (which
    pybind11 registers) and by a call (which builds the value inside the
    object, bindings/instance.hpp), with the arguments of a second __init__."""
    g = SE3.exp([1.0, 2.0, 3.0, 0.1, 0.2, 0.3])
    screw = [[0.0, 0.0, 0.0, 0.0, 0.0, 1.0]]
    body = ([2.0, [0.0, 0.0, 0.0], np.eye(3)], {})
    return [
        (SO3(), ((), {})),
        (SO3.exp([0.1, 0.2, 0.3]), ((), {})),
        (SE3(translation=[1.0, 2.0, 3.0]), ((), {})),
        (g, ((), {"translation": [0.0, 0.0, 0.0]})),
        (Twist([1.0, 2.0, 3.0]), (([0.0] * 3, [0.0] * 3), {})),
        (Twist([1.0, 2.0, 3.0]) + Twist(), ((), {})),
        (Wrench([1.0, 2.0, 3.0]), ((), {})),
        (-Wrench([1.0, 2.0, 3.0]), ((), {})),
        (Screw([0.0, 0.0, 0.0], [0.0, 0.0, 1.0], 0.5, 1.0), (([1.0, 0.0, 0.0], [1.0, 0.0, 0.0], 0.0, 2.0), {})),
        (chasles.SpatialInertia(1.0, [0.0, 0.0, 0.0], np.eye(3)), body),
        (chasles.SpatialInertia(1.0, [0.0, 0.0, 0.0], np.eye(3)).transform(g), body),
        (Chain(screw, np.eye(4)), ((screw * 2, np.eye(4)), {})),
        (Chain(screw, np.eye(4)).__copy__(), ((screw, np.eye(4)), {"joint_names": ["j"]})),
    ]


@pytest.mark.parametrize("x, arguments", live_objects(), ids=lambda v: "" if isinstance(v, tuple) else type(v).__name__)
def test_init_and_setstate_again_on_a_live_object_are_refused(x, arguments):
    """The classes are values: calling __init__ (or __setstate__) again on an
    object is a TypeError, and the object keeps its value. (pybind11 ignored
    such a call on an object its __init__ made, Chain's included, and ran it
    on one a call made, replacing its value.)"""
    name = type(x).__name__
    before = x.__getstate__()
    args, kwargs = arguments
    with pytest.raises(TypeError, match=rf"^{name}\.__init__: the {name} is already initialized"):
        x.__init__(*args, **kwargs)
    with pytest.raises(TypeError, match=rf"^{name}\.__setstate__: the {name} is already initialized"):
        x.__setstate__(before)
    assert x.__getstate__() == before
    fresh = type(x).__new__(type(x))
    fresh.__setstate__(before)  # a fresh object takes its state once
    assert fresh == x
    with pytest.raises(TypeError, match="already initialized"):
        fresh.__setstate__(before)
