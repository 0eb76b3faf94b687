"""Modern Robotics' own examples, run through chasles.Chain as written.

Every forward and inverse kinematics example of Lynch and Park's Modern
Robotics (the docstrings of the modern_robotics package: FKinBody, FKinSpace,
JacobianBody, JacobianSpace, IKinBody, IKinSpace) has a helical joint (a
screw of nonzero pitch), and the chapter 8 dynamics examples (InverseDynamics,
MassMatrix, VelQuadraticForces, GravityForces, EndEffectorForces,
ForwardDynamics: the first three links of a UR5) a joint screw of norm
sqrt(2). Each runs here through the one conversion the book's (w, v) order
needs, Twist.from_modern_robotics, and gives the numbers the docstrings print
(to their 8 or 9 digits), and the modern_robotics package's own result to
1e-12.
"""

import modern_robotics as mr
import numpy as np
import pytest

from chasles import SE3, Chain, SpatialInertia, Twist

PRINTED = 1e-8  # the docstrings print 8 or 9 significant digits


def screws_of(table):
    """Modern Robotics' 6 x n table (one column (w, v) per joint) as chasles' (n, 6) rows (v, w)."""
    return np.array([Twist.from_modern_robotics(column).vector for column in np.asarray(table, float).T])


def chain_of_body_screws(Blist, M, **kwargs):
    """The chain whose body screws are Blist's: S_i = Ad_M B_i."""
    g = SE3.from_matrix(np.asarray(M, float))
    return Chain([g.adjoint() @ b for b in screws_of(Blist)], M, **kwargs)


# FKinBody, FKinSpace, IKinBody, IKinSpace: a RPH arm (the third joint helical, pitch 0.1).
M = np.array([[-1, 0, 0, 0], [0, 1, 0, 6], [0, 0, -1, 2], [0, 0, 0, 1]], float)
BLIST = np.array([[0, 0, -1, 2, 0, 0], [0, 0, 0, 0, 1, 0], [0, 0, 1, 0, 0, 0.1]]).T
SLIST = np.array([[0, 0, 1, 4, 0, 0], [0, 0, 0, 0, 1, 0], [0, 0, -1, -6, 0, -0.1]]).T
THETA = np.array([np.pi / 2.0, 3, np.pi])
FK_PRINTED = np.array([[0, 1, 0, -5], [1, 0, 0, 4], [0, 0, -1, 1.68584073], [0, 0, 0, 1]])


def test_forward_kinematics_examples():
    body, space = chain_of_body_screws(BLIST, M), Chain(screws_of(SLIST), M)
    assert body.joint_types == space.joint_types == ("revolute", "prismatic", "helical")
    np.testing.assert_allclose(body.body_screws, screws_of(BLIST), rtol=0, atol=1e-15)
    np.testing.assert_allclose(space.space_screws, screws_of(SLIST), rtol=0, atol=0)
    for chain in (body, space):
        for g in (chain.forward(THETA), chain.forward_body(THETA)):
            np.testing.assert_allclose(g, FK_PRINTED, rtol=0, atol=PRINTED)
            np.testing.assert_allclose(g, mr.FKinBody(M, BLIST, THETA), rtol=0, atol=1e-12)
            np.testing.assert_allclose(g, mr.FKinSpace(M, SLIST, THETA), rtol=0, atol=1e-12)


# JacobianBody and JacobianSpace: four helical joints (pitches 0.2, 2, 2 and 0.2).
JLIST = np.array([[0, 0, 1, 0, 0.2, 0.2], [1, 0, 0, 2, 0, 3], [0, 1, 0, 0, 2, 1], [1, 0, 0, 0.2, 0.3, 0.4]]).T
JTHETA = np.array([0.2, 1.1, 0.1, 1.2])
JB_PRINTED = np.array(
    [
        [-0.04528405, 0.99500417, 0, 1],
        [0.74359313, 0.09304865, 0.36235775, 0],
        [-0.66709716, 0.03617541, -0.93203909, 0],
        [2.32586047, 1.66809, 0.56410831, 0.2],
        [-1.44321167, 2.94561275, 1.43306521, 0.3],
        [-2.06639565, 1.82881722, -1.58868628, 0.4],
    ]
)
JS_PRINTED = np.array(
    [
        [0, 0.98006658, -0.09011564, 0.95749426],
        [0, 0.19866933, 0.4445544, 0.28487557],
        [1, 0, 0.89120736, -0.04528405],
        [0, 1.95218638, -2.21635216, -0.51161537],
        [0.2, 0.43654132, -2.43712573, 2.77535713],
        [0.2, 2.96026613, 3.23573065, 2.22512443],
    ]
)
SWAP = np.r_[3, 4, 5, 0, 1, 2]  # rows (v, w) -> (w, v)


def test_jacobian_examples():
    # With M = 1 the body and space screws are the same table, as in the docstrings.
    chain = Chain(screws_of(JLIST), np.eye(4))
    assert chain.joint_types == ("helical",) * 4
    np.testing.assert_allclose(chain.jacobian_body(JTHETA)[SWAP], JB_PRINTED, rtol=0, atol=PRINTED)
    np.testing.assert_allclose(chain.jacobian_space(JTHETA)[SWAP], JS_PRINTED, rtol=0, atol=PRINTED)
    np.testing.assert_allclose(chain.jacobian_body(JTHETA)[SWAP], mr.JacobianBody(JLIST, JTHETA), rtol=0, atol=1e-12)
    np.testing.assert_allclose(chain.jacobian_space(JTHETA)[SWAP], mr.JacobianSpace(JLIST, JTHETA), rtol=0, atol=1e-12)


def test_inverse_kinematics_examples():
    # The target is printed to 5 digits (z = 1.6858), which no joint angles reach exactly (the pitch
    # ties z to the third joint, whose angle the orientation fixes): MR stops within eomg = 0.01 and
    # ev = 0.001 and prints IKinBody's (1.57073819, 2.999667, 3.14153913) and IKinSpace's
    # (1.57073783, 2.99966384, 3.1415342); chasles with the same tolerances stops there too (to those
    # tolerances). The exact target, forward(THETA), is solved to chasles' own tolerance.
    T = np.array([[0, 1, 0, -5], [1, 0, 0, 4], [0, 0, -1, 1.6858], [0, 0, 0, 1]], float)
    q0 = np.array([1.5, 2.5, 3])
    printed_body, printed_space = (
        np.array([1.57073819, 2.999667, 3.14153913]),
        np.array([1.57073783, 2.99966384, 3.1415342]),
    )
    for chain, printed in ((chain_of_body_screws(BLIST, M), printed_body), (Chain(screws_of(SLIST), M), printed_space)):
        result = chain.inverse_kinematics(T, q0, position_tolerance=0.001, orientation_tolerance=0.01)
        assert result.converged
        np.testing.assert_allclose(result.q, printed, rtol=0, atol=1e-3)
        assert np.linalg.norm(result.error[:3]) <= 0.001 and np.linalg.norm(result.error[3:]) <= 0.01
        exact = chain.inverse_kinematics(chain.forward(THETA), q0)
        assert exact.converged
        np.testing.assert_allclose(exact.q, THETA, rtol=0, atol=1e-10)
    for ik, table, printed in ((mr.IKinBody, BLIST, printed_body), (mr.IKinSpace, SLIST, printed_space)):
        q_mr, ok = ik(table, M, T, q0, 0.01, 0.001)
        assert ok
        np.testing.assert_allclose(q_mr, printed, rtol=0, atol=PRINTED)


# Chapter 8: the first three links of a UR5 (InverseDynamics' docstring and the five after it).
M01 = np.array([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0.089159], [0, 0, 0, 1]])
M12 = np.array([[0, 0, 1, 0.28], [0, 1, 0, 0.13585], [-1, 0, 0, 0], [0, 0, 0, 1]])
M23 = np.array([[1, 0, 0, 0], [0, 1, 0, -0.1197], [0, 0, 1, 0.395], [0, 0, 0, 1]])
M34 = np.array([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0.14225], [0, 0, 0, 1]])
MLIST = np.array([M01, M12, M23, M34], float)
GLIST = np.array(
    [
        np.diag([0.010267, 0.010267, 0.00666, 3.7, 3.7, 3.7]),
        np.diag([0.22689, 0.22689, 0.0151074, 8.393, 8.393, 8.393]),
        np.diag([0.0494433, 0.0494433, 0.004095, 2.275, 2.275, 2.275]),
    ]
)
DLIST = np.array([[1, 0, 1, 0, 1, 0], [0, 1, 0, -0.089, 0, 0], [0, 1, 0, -0.089, 0, 0.425]]).T
G = np.array([0, 0, -9.8])
FTIP = np.array([1.0, 1, 1, 1, 1, 1])  # (moment, force) in the end-effector frame
Q, QD, QDD, TAU = np.array([0.1, 0.1, 0.1]), np.array([0.1, 0.2, 0.3]), np.array([2, 1.5, 1]), np.array([0.5, 0.6, 0.7])


def ur5_three_links():
    """The chain of the chapter 8 examples: link i's inertia G_i, given at its frame {i} (the frame
    at its center of mass, M01 ... M0i at home, inertia order (w, v)), moved into the base frame."""
    frames, T = [], np.eye(4)
    for Mi in MLIST[:-1]:
        T = T @ Mi
        frames.append(T)
    bodies = [
        SpatialInertia(Gi[3, 3], [0, 0, 0], Gi[:3, :3]).transform(SE3.from_matrix(Ti)) for Gi, Ti in zip(GLIST, frames)
    ]
    # The first screw, w = (1, 0, 1), has norm sqrt(2): joint 1 turns sqrt(2) rad per unit of q_1.
    return Chain(screws_of(DLIST), T @ MLIST[-1], link_inertias=bodies, gravity=G, unit_screws=False)


def test_a_screw_of_norm_sqrt2_needs_unit_screws_false():
    with pytest.raises(
        ValueError, match=r"joint 0 is revolute but its angular part w is not a unit vector .*unit_screws"
    ):
        Chain(screws_of(DLIST), np.eye(4))
    chain = ur5_three_links()
    assert chain.joint_types == ("revolute",) * 3
    np.testing.assert_allclose(np.linalg.norm(chain.space_screws[0, 3:]), np.sqrt(2), rtol=1e-15)


def test_dynamics_examples():
    chain = ur5_three_links()
    tip = np.r_[FTIP[3:], FTIP[:3]]  # chasles' wrench order (f, tau)
    zero = np.zeros(3)
    cases = [
        (chain.inverse_dynamics(Q, QD, QDD, tip_wrench=tip), [74.69616155, -33.06766016, -3.23057314]),
        (
            chain.mass_matrix(Q),
            [
                [2.25433380e01, -3.07146754e-01, -7.18426391e-03],
                [-3.07146754e-01, 1.96850717e00, 4.32157368e-01],
                [-7.18426391e-03, 4.32157368e-01, 1.91630858e-01],
            ],
        ),
        (chain.coriolis(Q, QD), [0.26453118, -0.05505157, -0.00689132]),
        (chain.gravity_torques(Q), [28.40331262, -37.64094817, -5.4415892]),
        (
            chain.inverse_dynamics(Q, zero, zero, tip_wrench=tip) - chain.gravity_torques(Q),
            [1.40954608, 1.85771497, 1.392409],
        ),
        (chain.forward_dynamics(Q, QD, TAU, tip_wrench=tip), [-0.97392907, 25.58466784, -32.91499212]),
    ]
    for got, printed in cases:
        np.testing.assert_allclose(got, printed, rtol=PRINTED, atol=PRINTED)
    mr_values = [
        mr.InverseDynamics(Q, QD, QDD, G, FTIP, MLIST, GLIST, DLIST),
        mr.MassMatrix(Q, MLIST, GLIST, DLIST),
        mr.VelQuadraticForces(Q, QD, MLIST, GLIST, DLIST),
        mr.GravityForces(Q, G, MLIST, GLIST, DLIST),
        mr.EndEffectorForces(Q, FTIP, MLIST, GLIST, DLIST),
        mr.ForwardDynamics(Q, QD, TAU, G, FTIP, MLIST, GLIST, DLIST),
    ]
    for (got, _), expected in zip(cases, mr_values):
        np.testing.assert_allclose(got, expected, rtol=0, atol=1e-12 * max(1.0, np.max(np.abs(expected))))


def test_derivatives_of_the_examples_arm_against_central_differences():
    # The analytic derivatives on the sqrt(2) screw (and a tip wrench) against central differences
    # of the methods themselves (step 1e-6: truncation and rounding both below 1e-8).
    chain = ur5_three_links()
    tip = np.r_[FTIP[3:], FTIP[:3]]
    h, eye = 1e-6, np.eye(3)

    def central(f, x):
        return np.stack([(f(x + h * e) - f(x - h * e)) / (2 * h) for e in eye], axis=-1)

    dq, dqd = chain.inverse_dynamics_derivatives(Q, QD, QDD, tip_wrench=tip)
    np.testing.assert_allclose(dq, central(lambda q: chain.inverse_dynamics(q, QD, QDD, tip_wrench=tip), Q), atol=1e-7)
    np.testing.assert_allclose(dqd, central(lambda v: chain.inverse_dynamics(Q, v, QDD, tip_wrench=tip), QD), atol=1e-7)
    fq, fqd, ftau = chain.forward_dynamics_derivatives(Q, QD, TAU, tip_wrench=tip)
    fd = chain.forward_dynamics
    np.testing.assert_allclose(fq, central(lambda q: fd(q, QD, TAU, tip_wrench=tip), Q), atol=1e-6)
    np.testing.assert_allclose(fqd, central(lambda v: fd(Q, v, TAU, tip_wrench=tip), QD), atol=1e-6)
    np.testing.assert_allclose(ftau, np.linalg.inv(chain.mass_matrix(Q)), rtol=1e-12, atol=0)
    np.testing.assert_allclose(ftau, chain.mass_matrix_inverse(Q), rtol=0, atol=0)
