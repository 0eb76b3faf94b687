"""chasles.SpatialInertia and the private dynamics array functions
(chasles._core._inverse_dynamics, _mass_matrix, _gravity_torques, _coriolis,
_forward_dynamics) against the modern_robotics package (InverseDynamics,
MassMatrix, GravityForces, VelQuadraticForces, ForwardDynamics) on random arms
of revolute, helical and prismatic joints with random inertias and on MR's own
3-link example (the first links of a UR5, from MR's docstrings), to 1e-12
relative; SpatialInertia against the 6x6 formulas; batches against single
calls; errors and docstring examples.

Conversion to MR: screws (v, w) -> (w, v); each link gets a frame {i} at home
(random here: the answers must not depend on it), Mlist[i] = T_{i-1}^-1 T_i
with T_0 = 1 and Mlist[n] = T_n^-1 M; Glist[i] is the link's inertia
described in {i}, as the 6x6 matrix in MR's order (w, v); Ftip (tau, f).
"""

import copy
import pickle

import modern_robotics as mr
import numpy as np
import pytest
from helpers import hat3 as hat

import chasles
from chasles import SE3, Chain, SpatialInertia, Twist, Wrench, _core

RTOL = 1e-12

# (v, w) <-> (w, v): the same permutation both ways.
SWAP = np.block([[np.zeros((3, 3)), np.eye(3)], [np.eye(3), np.zeros((3, 3))]])


def adjoint(g):
    R, p = g[:3, :3], g[:3, 3]
    A = np.zeros((6, 6))
    A[:3, :3] = R
    A[:3, 3:] = hat(p) @ R
    A[3:, 3:] = R
    return A


def random_rotation(rng):
    q, r = np.linalg.qr(rng.normal(size=(3, 3)))
    q = q * np.sign(np.diag(r))
    return q if np.linalg.det(q) > 0 else -q


def random_pose(rng):
    g = np.eye(4)
    g[:3, :3] = random_rotation(rng)
    g[:3, 3] = rng.uniform(-1, 1, 3)
    return g


def random_body(rng, center):
    m = rng.uniform(0.5, 3.0)
    x, y, z = rng.uniform(0.05, 0.5, 3)
    moments = m / 12 * np.array([y * y + z * z, x * x + z * z, x * x + y * y])
    R = random_rotation(rng)
    return SpatialInertia(m, center + 0.3 * rng.uniform(-1, 1, 3), R @ np.diag(moments) @ R.T)


def random_arm(rng, n):
    """(screws (n, 6), home (4, 4), inertias [SpatialInertia] in the base frame at home)."""
    screws, bodies = [], []
    for _ in range(n):
        point, direction = rng.uniform(-1, 1, 3), rng.uniform(-1, 1, 3)
        if rng.uniform() < 0.75:
            screws.append(Chain.revolute_screw(point, direction))
            if rng.uniform() < 0.3:  # helical: pitch h in [-0.3, 0.3] m/rad
                screws[-1][:3] += rng.uniform(-0.3, 0.3) * screws[-1][3:]
        else:
            screws.append(Chain.prismatic_screw(direction))
        bodies.append(random_body(rng, point))
    return np.array(screws), random_pose(rng), bodies


def to_mr(screws, home, bodies, rng):
    """MR's (Slist, Mlist, Glist) of the same arm, with random link frames."""
    frames = [random_pose(rng) for _ in bodies]
    Mlist, previous = [], np.eye(4)
    for T in frames:
        Mlist.append(np.linalg.inv(previous) @ T)
        previous = T
    Mlist.append(np.linalg.inv(previous) @ home)
    # The inertia described in {i}: transform by g_{i,base} = T_i^-1.
    Glist = [SWAP @ b.transform(SE3.from_matrix(np.linalg.inv(T))).matrix @ SWAP for b, T in zip(bodies, frames)]
    return screws[:, [3, 4, 5, 0, 1, 2]].T, np.array(Mlist), np.array(Glist)


def from_mr(Slist, Mlist, Glist):
    """chasles' (screws, home, inertias (n, 6, 6)) of an MR arm."""
    T = np.eye(4)
    inertias = []
    for Mi, Gi in zip(Mlist[:-1], Glist):
        T = T @ Mi
        inertias.append(np.linalg.inv(adjoint(T)).T @ (SWAP @ Gi @ SWAP) @ np.linalg.inv(adjoint(T)))
    return np.asarray(Slist).T[:, [3, 4, 5, 0, 1, 2]], T @ Mlist[-1], np.array(inertias)


def assert_close(actual, expected, rtol=RTOL):
    scale = max(1.0, float(np.max(np.abs(expected))))
    np.testing.assert_allclose(actual, expected, rtol=0, atol=rtol * scale)


# 30 and 32 joints: forward_dynamics by the articulated-body algorithm
# (chasles::articulated_body_min_joints), 29 and fewer by the composite inertias.
ARMS = [(seed, n) for seed, n in zip(range(15), [1, 2, 3, 4, 5, 6, 6, 7, 7, 8, 10, 12, 29, 30, 32])]


@pytest.mark.parametrize(("seed", "n"), ARMS)
def test_against_modern_robotics_on_random_arms(seed, n):
    rng = np.random.default_rng(seed)
    screws, home, bodies = random_arm(rng, n)
    G = np.array([b.matrix for b in bodies])
    Slist, Mlist, Glist = to_mr(screws, home, bodies, rng)
    gravity = np.array([0.0, 0.0, -9.81]) if seed % 2 == 0 else rng.normal(size=3)
    for _ in range(3):
        q, qd, qdd = rng.uniform(-3, 3, n), rng.uniform(-2, 2, n), rng.uniform(-2, 2, n)
        tip = rng.uniform(-5, 5, 6)
        ftip_mr = np.r_[tip[3:], tip[:3]]
        tau = _core._inverse_dynamics(screws, home, G, gravity, q, qd, qdd, tip)
        assert_close(tau, mr.InverseDynamics(q, qd, qdd, gravity, ftip_mr, Mlist, Glist, Slist))
        assert_close(_core._mass_matrix(screws, home, G, q), mr.MassMatrix(q, Mlist, Glist, Slist))
        assert_close(
            _core._gravity_torques(screws, home, G, gravity, q), mr.GravityForces(q, gravity, Mlist, Glist, Slist)
        )
        assert_close(_core._coriolis(screws, home, G, q, qd), mr.VelQuadraticForces(q, qd, Mlist, Glist, Slist))
        expected = mr.ForwardDynamics(q, qd, tau, gravity, ftip_mr, Mlist, Glist, Slist)
        # The solve multiplies the rounding of tau by cond(M).
        cond = np.linalg.cond(mr.MassMatrix(q, Mlist, Glist, Slist))
        qdd_back, joint = _core._forward_dynamics(screws, home, G, gravity, q, qd, tau, tip)
        assert joint == -1
        assert_close(qdd_back, expected, RTOL * cond)
        assert_close(expected, qdd, RTOL * cond)


def mr_three_link_example():
    """The 3-link arm of MR's InverseDynamics docstring (a UR5's first three links)."""
    M01 = np.array([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0.089159], [0, 0, 0, 1]])
    M12 = np.array([[0, 0, 1, 0.28], [0, 1, 0, 0.13585], [-1, 0, 0, 0], [0, 0, 0, 1]])
    M23 = np.array([[1, 0, 0, 0], [0, 1, 0, -0.1197], [0, 0, 1, 0.395], [0, 0, 0, 1]])
    M34 = np.array([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0.14225], [0, 0, 0, 1]])
    G1 = np.diag([0.010267, 0.010267, 0.00666, 3.7, 3.7, 3.7])
    G2 = np.diag([0.22689, 0.22689, 0.0151074, 8.393, 8.393, 8.393])
    G3 = np.diag([0.0494433, 0.0494433, 0.004095, 2.275, 2.275, 2.275])
    Slist = np.array([[1, 0, 1, 0, 1, 0], [0, 1, 0, -0.089, 0, 0], [0, 1, 0, -0.089, 0, 0.425]]).T
    return Slist, np.array([M01, M12, M23, M34]), np.array([G1, G2, G3])


def test_against_modern_robotics_on_its_example():
    Slist, Mlist, Glist = mr_three_link_example()
    screws, home, G = from_mr(Slist, Mlist, Glist)
    q, qd, qdd = np.array([0.1, 0.1, 0.1]), np.array([0.1, 0.2, 0.3]), np.array([2, 1.5, 1])
    g = np.array([0, 0, -9.8])
    ftip = np.array([1.0, 1, 1, 1, 1, 1])
    tip = np.r_[ftip[3:], ftip[:3]]
    assert_close(
        _core._inverse_dynamics(screws, home, G, g, q, qd, qdd, tip),
        mr.InverseDynamics(q, qd, qdd, g, ftip, Mlist, Glist, Slist),
    )
    assert_close(_core._mass_matrix(screws, home, G, q), mr.MassMatrix(q, Mlist, Glist, Slist))
    assert_close(_core._gravity_torques(screws, home, G, g, q), mr.GravityForces(q, g, Mlist, Glist, Slist))
    assert_close(_core._coriolis(screws, home, G, q, qd), mr.VelQuadraticForces(q, qd, Mlist, Glist, Slist))
    tau = np.array([0.5, 0.6, 0.7])
    assert_close(
        _core._forward_dynamics(screws, home, G, g, q, qd, tau, tip)[0],
        mr.ForwardDynamics(q, qd, tau, g, ftip, Mlist, Glist, Slist),
    )


def test_batches_equal_single_calls():
    rng = np.random.default_rng(40)
    screws, home, bodies = random_arm(rng, 7)
    G = np.array([b.matrix for b in bodies])
    g = np.array([0.0, 0.0, -9.81])
    q, qd, qdd = rng.uniform(-3, 3, (3, 4, 7)), rng.uniform(-2, 2, (3, 4, 7)), rng.uniform(-2, 2, (3, 4, 7))
    tip = rng.uniform(-1, 1, (4, 6))
    tau = _core._inverse_dynamics(screws, home, G, g, q, qd, qdd, tip)
    M = _core._mass_matrix(screws, home, G, q)
    assert tau.shape == (3, 4, 7) and M.shape == (3, 4, 7, 7)
    for i in range(3):
        for j in range(4):
            np.testing.assert_array_equal(
                tau[i, j], _core._inverse_dynamics(screws, home, G, g, q[i, j], qd[i, j], qdd[i, j], tip[j])
            )
            np.testing.assert_array_equal(M[i, j], _core._mass_matrix(screws, home, G, q[i, j]))
    # A batch of arms (the model read per element) gives the same bits too.
    screws2, home2, bodies2 = random_arm(rng, 7)
    G2 = np.array([b.matrix for b in bodies2])
    both = _core._gravity_torques(np.stack([screws, screws2]), np.stack([home, home2]), np.stack([G, G2]), g, q[0, :2])
    np.testing.assert_array_equal(both[1], _core._gravity_torques(screws2, home2, G2, g, q[0, 1]))
    # Non-contiguous operands: the same numbers.
    qT = np.asfortranarray(q[0])
    np.testing.assert_array_equal(
        _core._coriolis(screws, home, G, qT, qd[0]), _core._coriolis(screws, home, G, q[0].copy(), qd[0])
    )


def test_private_functions_are_documented_gufuncs():
    for name in [
        "_inverse_dynamics",
        "_forward_dynamics",
        "_mass_matrix",
        "_gravity_torques",
        "_coriolis",
        "_inverse_dynamics_derivatives",
        "_forward_dynamics_derivatives",
        "_mass_matrix_inverse",
    ]:
        u = getattr(_core, name)
        assert isinstance(u, np.ufunc)
        assert u.signature.startswith("(n,6),(4,4),(n,6,6)")
        assert "screws" in u.__doc__ and "inertias" in u.__doc__
        assert name not in chasles.__all__


# ---- SpatialInertia ---------------------------------------------------------------


def test_matrix_and_parallel_axis():
    rng = np.random.default_rng(41)
    for _ in range(20):
        body = random_body(rng, rng.uniform(-1, 1, 3))
        m, c, Ic = body.mass, body.com, body.inertia
        G = body.matrix
        np.testing.assert_array_equal(np.asarray(body), G)
        # Momentum of a point cloud would be the oracle in C++; here the formula with
        # the parallel-axis theorem: inertia about the origin I_c + m (|c|^2 1 - c c^T).
        assert_close(G[3:, 3:], Ic + m * (c @ c * np.eye(3) - np.outer(c, c)), 1e-14)
        assert_close(G[:3, :3], m * np.eye(3), 0)
        assert_close(G[3:, :3], m * hat(c), 1e-15)
        assert_close(G[:3, 3:], -m * hat(c), 1e-15)
        V = rng.normal(size=6)
        assert_close(np.asarray(body.momentum(Twist.from_vector(V))), G @ V, 1e-14)
        assert abs(body.kinetic_energy(V) - 0.5 * V @ G @ V) <= 1e-14 * max(1, 0.5 * V @ G @ V)


def test_transform_is_the_adjoint_product_and_keeps_the_energy():
    rng = np.random.default_rng(42)
    for _ in range(20):
        body = random_body(rng, rng.uniform(-1, 1, 3))
        g = SE3.exp(rng.normal(size=6))
        Ad_inv = np.linalg.inv(g.adjoint())
        assert_close(body.transform(g).matrix, Ad_inv.T @ body.matrix @ Ad_inv, 1e-13)
        V = Twist.from_vector(rng.normal(size=6))
        assert abs(body.transform(g).kinetic_energy(g.act(V)) - body.kinetic_energy(V)) <= 1e-13
        assert body.transform(g).momentum(g.act(V)).is_approx(g.act(body.momentum(V)), 1e-13)
        joined = body + body.transform(g)
        assert_close(joined.matrix, body.matrix + body.transform(g).matrix, 1e-14)


def test_protocols():
    body = SpatialInertia(2.0, [0.1, 0.2, 0.3], np.diag([0.1, 0.2, 0.25]))
    assert repr(body).startswith("SpatialInertia(mass=2.0, com=[0.1, 0.2, 0.3], inertia=[[0.1")
    assert pickle.loads(pickle.dumps(body)) == body
    assert copy.copy(body) == body and copy.deepcopy(body) == body
    assert body != SpatialInertia(2.0, [0.1, 0.2, 0.3], np.diag([0.1, 0.2, 0.26]))
    assert body.is_approx(SpatialInertia(2.0, [0.1, 0.2, 0.3], np.diag([0.1, 0.2, 0.25 + 1e-12])))
    assert not body.is_approx(SpatialInertia(2.0, [0.1, 0.2, 0.3], np.diag([0.1, 0.2, 0.25 + 1e-6])))
    assert np.asarray(body, dtype=np.float32).dtype == np.float32
    assert (body == 3) is False


@pytest.mark.parametrize(
    ("mass", "com", "inertia", "message"),
    [
        (0.0, [0, 0, 0], np.eye(3), "positive mass"),
        (-1.0, [0, 0, 0], np.eye(3), "positive mass"),
        (float("nan"), [0, 0, 0], np.eye(3), "mass"),
        (1.0, [0, 0, float("inf")], np.eye(3), "com"),
        (1.0, [0, 0], np.eye(3), r"com.*\(3,\)"),
        (1.0, [0, 0, 0], np.eye(2), r"inertia.*\(3, 3\)"),
        (1.0, [0, 0, 0], [[1, 0.5, 0], [0, 1, 0], [0, 0, 1]], "not symmetric"),
        (1.0, [0, 0, 0], np.diag([0.0, 1, 1]), "not positive definite"),
        (1.0, [0, 0, 0], np.diag([1.0, 1, 3]), "triangle inequality"),
    ],
)
def test_errors_name_the_condition(mass, com, inertia, message):
    with pytest.raises(ValueError, match=message):
        SpatialInertia(mass, com, inertia)


def test_type_errors():
    body = SpatialInertia(1.0, [0, 0, 0], np.eye(3))
    with pytest.raises(TypeError):
        body.transform(np.eye(4))
    with pytest.raises(ValueError, match=r"momentum.*\(6,\)"):
        body.momentum([1.0, 2.0])
    assert body.momentum(Twist(v=[1.0, 0.0, 0.0])) == Wrench(f=[1.0, 0.0, 0.0])


def test_thin_plate_is_accepted_on_both_sides_of_the_tolerance():
    # I_3 = I_1 + I_2 (a thin plate) is physical; beyond the tolerance it is not.
    SpatialInertia(1.0, [0, 0, 0], np.diag([1.0, 1.0, 2.0]))
    SpatialInertia(1.0, [0, 0, 0], np.diag([1.0, 1.0, 2.0 + 4 * 1.49e-8]))
    with pytest.raises(ValueError, match="triangle"):
        SpatialInertia(1.0, [0, 0, 0], np.diag([1.0, 1.0, 2.0 + 16 * 1.49e-8]))
