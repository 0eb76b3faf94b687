"""Chain.inverse_kinematics and the Chain's dynamics methods on real arms of
the example-robot-data package (UR5, Panda, xArm7, Kinova Jaco2 j2s6s200),
loaded with Chain.from_urdf.

- Inverse kinematics: targets forward(q*) for random q* within the limits;
  from seeds 0.3 rad away every one converges, and the solution is checked
  by an independent forward kinematics, the product of scipy.linalg.expm of
  the 4x4 hat matrices; batches equal single solves; limits respected;
  random seeds with restarts; errors.
- Dynamics: inverse_dynamics, mass_matrix, gravity_torques, coriolis and
  forward_dynamics against the modern_robotics package on the same arms
  (screws to (w, v), link frames at each link's center of mass, inertias
  described there), to 1e-12 relative; gravity_torques = inverse_dynamics
  at rest; a chain without inertias refused.
"""

import importlib.metadata
import time

import modern_robotics as mr
import numpy as np
import pytest
from helpers import hat6
from scipy.linalg import expm

from chasles import SE3, Chain, SpatialInertia, _core

ARMS = {
    "ur5": ("ur_description/urdf/ur5_robot.urdf", "tool0"),
    "panda": ("panda_description/urdf/panda.urdf", "panda_hand"),
    "xarm7": ("xarm_description/urdf/xarm7.urdf", "link7"),
    "jaco2": ("kinova_description/robots/kinova.urdf", "j2s6s200_end_effector"),
}


def robots_dir():
    for f in importlib.metadata.files("example-robot-data") or []:
        if str(f).endswith("ur_description/urdf/ur5_robot.urdf"):
            return f.locate().parents[2]
    raise RuntimeError("example-robot-data has no ur5_robot.urdf")


@pytest.fixture(scope="module")
def arms():
    root = robots_dir()
    return {key: Chain.from_urdf(root / rel, tip) for key, (rel, tip) in ARMS.items()}


def reference_forward(chain, q):
    """The product of exponentials by scipy's expm of 4x4 hat matrices."""
    g = np.eye(4)
    for s, t in zip(chain.space_screws, q):
        g = g @ expm(hat6(s * t))
    return g @ np.asarray(chain.home)


def within_limits(chain, rng, margin=0.0):
    lo = np.maximum(chain.lower, -np.pi) + margin
    hi = np.minimum(chain.upper, np.pi) - margin
    return rng.uniform(lo, hi)


# ---- inverse kinematics --------------------------------------------------------


@pytest.mark.parametrize("key", list(ARMS))
def test_ik_from_nearby_seeds_reaches_every_target(arms, key):
    chain = arms[key]
    rng = np.random.default_rng(1)
    for _ in range(40):
        q_true = within_limits(chain, rng, margin=0.3)
        target = chain.forward(q_true)
        r = chain.inverse_kinematics(target, q_true + rng.uniform(-0.3, 0.3, chain.n_joints))
        assert r.converged, (key, r)
        assert isinstance(r.converged, bool) and isinstance(r.iterations, int)
        assert r.q.shape == (chain.n_joints,) and r.error.shape == (6,)
        assert np.all(r.q >= chain.lower) and np.all(r.q <= chain.upper)
        assert np.linalg.norm(r.error[:3]) <= 3.7e-11 and np.linalg.norm(r.error[3:]) <= 3.7e-11
        # Independent check: scipy's matrix exponentials reach the target, to
        # the tolerance on e (moving the tool frame by at most |e_w| |p| + |e_v|
        # for a tool |p| <= 1.5 m from the base) plus expm's own rounding.
        np.testing.assert_allclose(reference_forward(chain, r.q), target, rtol=0, atol=3 * 3.7e-11 + 1e-13)


def test_ik_result_is_a_named_tuple(arms):
    chain = arms["ur5"]
    r = chain.inverse_kinematics(chain.forward(np.full(6, 0.4)), np.full(6, 0.5))
    q, converged, status, iterations, total_iterations, attempts, error = r
    assert type(r).__name__ == "IKResult"
    assert r._fields == ("q", "converged", "status", "iterations", "total_iterations", "attempts", "error")
    assert converged and status == "converged" and iterations == r.iterations > 0
    assert total_iterations == iterations and attempts == 1
    assert np.array_equal(q, r.q) and error is r.error
    assert type(status) is str and type(iterations) is int and type(attempts) is int
    assert repr(r).startswith("IKResult(q=array([")


def test_ik_status_attempts_and_time_budget(arms):
    chain = arms["ur5"]
    far = np.asarray(chain.home).copy()
    far[:3, 3] += 5.0  # 8.7 m from a 1 m arm: unreachable
    r = chain.inverse_kinematics(far, np.zeros(6), max_iterations=20)
    assert r.status == "iteration_bound" and not r.converged and r.iterations == 20 and r.attempts == 1
    stalled = chain.inverse_kinematics(far, np.zeros(6), max_iterations=5000)
    assert stalled.status == "no_progress" and stalled.iterations < 5000
    # Restarts: iterations count the attempt returned, total_iterations all of them.
    # Every attempt but the last ends once it stalls (its cost above 0.9 of
    # its value 8 iterations before), the last runs to the bound: 56 here.
    again = chain.inverse_kinematics(far, np.zeros(6), max_iterations=20, restarts=3, seed=5)
    assert again.attempts == 4 and again.iterations <= 20 and 3 * 8 + 20 <= again.total_iterations < 80
    # The attempt with the smallest error is returned, with its own status.
    assert again.status == ("iteration_bound" if again.iterations == 20 else "no_progress")
    # A spent budget stops before the first step; a solution is still found at q0.
    spent = chain.inverse_kinematics(far, np.zeros(6), max_time=0.0)
    assert spent.status == "time_budget" and spent.iterations == 0 and spent.attempts == 1
    q = np.full(6, 0.3)
    assert chain.inverse_kinematics(chain.forward(q), q, max_time=0).status == "converged"
    # Unbounded restarts end with the budget, the field's protocol form (0.2 s:
    # restarts within it even on a loaded machine that pauses the process).
    t0 = time.perf_counter()
    timed = chain.inverse_kinematics(far, np.zeros(6), max_iterations=10, restarts=2**31 - 1, max_time=0.2)
    assert time.perf_counter() - t0 >= 0.2
    assert timed.status == "time_budget" and timed.attempts > 1 and timed.total_iterations >= timed.iterations
    # A batch: a status array of str, and each element its own budget.
    batch = chain.inverse_kinematics(np.stack([far, chain.forward(q)]), np.stack([np.zeros(6), q]), max_time=0.0)
    assert batch.status.tolist() == ["time_budget", "converged"] and batch.attempts.tolist() == [1, 1]


def test_ik_protocol_form_solves_random_targets(arms):
    # TRAC-IK's protocol on the Panda: seed at the middle of the limits,
    # restarts within a budget, tolerance 1e-10 (the script
    # bench/ik_protocols.py runs 10,000 targets with TRAC-IK's 5 ms beside
    # TRAC-IK and KDL; a test takes 1 s, which a loaded machine cannot spend
    # pausing the process: speed is the benchmark's to measure).
    chain = arms["panda"]
    rng = np.random.default_rng(4)
    q_true = np.array([within_limits(chain, rng) for _ in range(100)])
    middle = (chain.lower + chain.upper) / 2
    r = chain.inverse_kinematics(
        chain.forward(q_true),
        middle,
        position_tolerance=1e-10,
        orientation_tolerance=1e-10,
        restarts=2**31 - 1,
        max_time=1.0,
        seed=1,
    )
    assert r.converged.all(), r.status[~r.converged]
    assert np.all(r.q >= chain.lower) and np.all(r.q <= chain.upper)


def test_ik_batches_equal_single_solves(arms):
    chain = arms["panda"]
    rng = np.random.default_rng(2)
    q_true = np.array([within_limits(chain, rng, 0.3) for _ in range(6)]).reshape(2, 3, -1)
    targets = chain.forward(q_true)
    seeds = q_true + rng.uniform(-0.3, 0.3, q_true.shape)
    batch = chain.inverse_kinematics(targets, seeds)
    assert batch.q.shape == (2, 3, 7) and batch.converged.shape == (2, 3) and batch.error.shape == (2, 3, 6)
    assert batch.converged.dtype == bool and batch.iterations.dtype.kind == "i"
    for i in np.ndindex(2, 3):
        one = chain.inverse_kinematics(targets[i], seeds[i])
        np.testing.assert_array_equal(batch.q[i], one.q)
        np.testing.assert_array_equal(batch.error[i], one.error)
        assert batch.converged[i] == one.converged and batch.iterations[i] == one.iterations
        assert batch.status[i] == one.status and batch.attempts[i] == one.attempts
    # One seed broadcast against many targets, and an SE3 target.
    shared = chain.inverse_kinematics(targets, seeds[0, 0])
    assert shared.q.shape == (2, 3, 7)
    one = chain.inverse_kinematics(SE3.from_matrix(targets[0, 0]), seeds[0, 0])
    np.testing.assert_array_equal(one.q, shared.q[0, 0])


def test_ik_random_seeds_with_restarts(arms):
    chain = arms["ur5"]
    rng = np.random.default_rng(3)
    targets = chain.forward(np.array([within_limits(chain, rng) for _ in range(50)]))
    seeds = np.array([within_limits(chain, rng) for _ in range(50)])
    first = chain.inverse_kinematics(targets, seeds)
    again = chain.inverse_kinematics(targets, seeds, restarts=10, seed=7)
    assert again.converged.sum() >= 49 and again.converged.sum() > first.converged.sum()
    assert np.all(again.iterations <= 100) and np.all(again.total_iterations >= again.iterations)
    # The first attempt of a call with restarts is the single call's, cut short
    # if it stalls (a restart follows): one that fails alone fails there too,
    # and when it converges there, it is the single call's solution.
    assert np.all(again.attempts[~first.converged] > 1)
    alone = again.attempts == 1
    assert np.all(first.converged[alone]) and alone.sum() >= 25
    np.testing.assert_array_equal(again.q[alone], first.q[alone])
    np.testing.assert_array_equal(again.iterations[alone], first.iterations[alone])
    repeat = chain.inverse_kinematics(targets, seeds, restarts=10, seed=7)
    np.testing.assert_array_equal(repeat.q, again.q)


def test_ik_reports_an_unreachable_target_and_bounds_iterations(arms):
    chain = arms["ur5"]
    far = SE3.from_matrix(
        np.asarray(chain.home) + np.block([[np.zeros((3, 3)), np.full((3, 1), 5.0)], [np.zeros((1, 4))]])
    )
    r = chain.inverse_kinematics(far, np.zeros(6), max_iterations=20)
    assert not r.converged and r.iterations <= 20 and np.linalg.norm(r.error[:3]) > 3
    assert np.all(np.isfinite(r.q))
    r0 = chain.inverse_kinematics(far, np.zeros(6), max_iterations=0)
    assert r0.iterations == 0 and not r0.converged and r0.status == "iteration_bound"


@pytest.mark.parametrize(
    ("target", "q0", "kwargs", "message"),
    [
        (np.eye(3), np.zeros(6), {}, r"target\): expected an SE3 or shape \(4, 4\)"),
        (np.diag([2.0, 1, 1, 1]), np.zeros(6), {}, r"target\): not a rigid motion"),
        (np.eye(4), np.zeros(5), {}, r"q0\): expected shape \(6,\)"),
        (np.eye(4), np.full(6, np.nan), {}, r"q0\): expected finite"),
        (np.eye(4), np.zeros(6), {"restarts": -1}, r"restarts\): expected >= 0, got -1"),
        (np.eye(4), np.zeros(6), {"restarts": 2**31}, r"restarts\): expected at most 2147483647"),
        (np.eye(4), np.zeros(6), {"max_iterations": -1}, r"max_iterations\): expected >= 0"),
        (np.eye(4), np.zeros(6), {"seed": -1}, r"seed\): expected >= 0"),
        (np.eye(4), np.zeros(6), {"seed": 2**64}, r"seed\): expected at most 18446744073709551615"),
        (np.eye(4), np.zeros(6), {"position_tolerance": -1.0}, r"position_tolerance\): expected a tolerance >= 0"),
        (np.eye(4), np.zeros(6), {"orientation_tolerance": np.nan}, r"orientation_tolerance\): expected a tolerance"),
        (np.eye(4), np.zeros(6), {"max_time": -0.1}, r"max_time\): expected a time >= 0 in seconds, or None"),
        (np.eye(4), np.zeros(6), {"max_time": np.nan}, r"max_time\): expected a time >= 0"),
        (np.broadcast_to(np.eye(4), (2, 4, 4)), np.zeros((3, 6)), {}, r"do not broadcast"),
        (
            np.stack([np.eye(4), np.diag([2.0, 1, 1, 1])]),
            np.zeros(6),
            {},
            r"not a rigid motion \(defect 3 at index 1\)",
        ),
        ([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 2]], np.zeros(6), {}, r"target\): not a rigid motion"),
    ],
)
def test_ik_errors(arms, target, q0, kwargs, message):
    with pytest.raises(ValueError, match=message):
        arms["ur5"].inverse_kinematics(target, q0, **kwargs)


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"max_iterations": 2.5}, r"max_iterations\): expected an integer, got float"),
        ({"seed": "1"}, r"seed\): expected an integer, got str"),
        ({"position_tolerance": "x"}, r"position_tolerance\): expected real numbers \(float64\), got str"),
        ({"max_time": "1"}, r"max_time\): expected real numbers \(float64\), got str"),
    ],
)
def test_ik_type_errors(arms, kwargs, message):
    with pytest.raises(TypeError, match=message):
        arms["ur5"].inverse_kinematics(np.eye(4), np.zeros(6), **kwargs)


def test_ik_single_solve_paths_agree(arms):
    # One solve is computed without numpy for an SE3 or a float64 (4, 4)
    # target and a float64 (n,) or list seed; any other form goes through the
    # gufunc: the same kernel, the same bits, the same types for one solve.
    chain = arms["ur5"]
    q = np.array([0.3, -0.2, 0.5, 0.1, -0.4, 0.2])
    T = chain.forward(q)
    fast = chain.inverse_kinematics(T, q + 0.1, restarts=2, seed=3)
    for target, q0 in ((SE3.from_matrix(T), list(q + 0.1)), (T.tolist(), q + 0.1), (T, (q + 0.1).astype(np.float32))):
        other = chain.inverse_kinematics(target, q0, restarts=2, seed=3)
        assert type(other.converged) is bool and type(other.status) is str and type(other.attempts) is int
    slow = chain.inverse_kinematics(T.tolist(), q + 0.1, restarts=2, seed=3)
    np.testing.assert_array_equal(slow.q, fast.q)
    np.testing.assert_array_equal(slow.error, fast.error)
    assert slow[1:6] == fast[1:6]
    batch = chain.inverse_kinematics(T[None], (q + 0.1)[None], restarts=2, seed=3)
    np.testing.assert_array_equal(batch.q[0], fast.q)
    assert (batch.status[0], batch.iterations[0], batch.attempts[0]) == (fast.status, fast.iterations, fast.attempts)


# ---- dynamics --------------------------------------------------------------------

# (v, w) <-> (w, v)
SWAP = np.block([[np.zeros((3, 3)), np.eye(3)], [np.eye(3), np.zeros((3, 3))]])


def to_modern_robotics(chain):
    """(Slist, Mlist, Glist) of the chain: link frames {i} at each link's
    center of mass with the base's orientation, Glist[i] the inertia
    described in {i} in MR's (w, v) order."""
    frames, Glist = [], []
    for row in chain.link_inertias:
        m, com, (ixx, ixy, ixz, iyy, iyz, izz) = row[0], row[1:4], row[4:]
        body = SpatialInertia(m, com, [[ixx, ixy, ixz], [ixy, iyy, iyz], [ixz, iyz, izz]])
        T = np.eye(4)
        T[:3, 3] = com
        frames.append(T)
        Glist.append(SWAP @ body.transform(SE3.from_matrix(np.linalg.inv(T))).matrix @ SWAP)
    Mlist, previous = [], np.eye(4)
    for T in frames:
        Mlist.append(np.linalg.inv(previous) @ T)
        previous = T
    Mlist.append(np.linalg.inv(previous) @ np.asarray(chain.home))
    return chain.space_screws[:, [3, 4, 5, 0, 1, 2]].T, np.array(Mlist), np.array(Glist)


def assert_close(actual, expected, rtol=1e-12):
    scale = max(1.0, float(np.max(np.abs(expected))))
    np.testing.assert_allclose(actual, expected, rtol=0, atol=rtol * scale)


@pytest.mark.parametrize("key", list(ARMS))
def test_dynamics_against_modern_robotics(arms, key):
    chain = arms[key]
    assert chain.link_inertias is not None
    Slist, Mlist, Glist = to_modern_robotics(chain)
    gravity = chain.gravity
    rng = np.random.default_rng(4)
    n = chain.n_joints
    for _ in range(3):
        q, qd, qdd = within_limits(chain, rng), rng.uniform(-2, 2, n), rng.uniform(-2, 2, n)
        tip = rng.uniform(-5, 5, 6)
        ftip = np.r_[tip[3:], tip[:3]]
        tau = chain.inverse_dynamics(q, qd, qdd, tip_wrench=tip)
        assert_close(tau, mr.InverseDynamics(q, qd, qdd, gravity, ftip, Mlist, Glist, Slist))
        M = chain.mass_matrix(q)
        assert_close(M, mr.MassMatrix(q, Mlist, Glist, Slist))
        np.testing.assert_array_equal(M, M.T)
        assert np.all(np.linalg.eigvalsh(M) > 0)
        assert_close(chain.gravity_torques(q), mr.GravityForces(q, gravity, Mlist, Glist, Slist))
        assert_close(chain.coriolis(q, qd), mr.VelQuadraticForces(q, qd, Mlist, Glist, Slist))
        cond = np.linalg.cond(M)
        assert_close(chain.forward_dynamics(q, qd, tau, tip_wrench=tip), qdd, 1e-12 * cond)
        # gravity_torques sums the links' mass moments at rest instead of running
        # the Newton-Euler recursion: the torques of inverse_dynamics at rest,
        # to rounding (measured: 3.6e-15 on torques of 28 N m).
        assert_close(chain.gravity_torques(q), chain.inverse_dynamics(q, np.zeros(n), np.zeros(n)), 1e-14)


def test_dynamics_are_array_functions(arms):
    chain = arms["panda"]
    rng = np.random.default_rng(5)
    q, qd = rng.uniform(-1, 1, (4, 7)), rng.uniform(-1, 1, (4, 7))
    taus = chain.inverse_dynamics(q, qd, np.zeros(7))
    Ms = chain.mass_matrix(q)
    assert taus.shape == (4, 7) and Ms.shape == (4, 7, 7)
    for i in range(4):
        np.testing.assert_array_equal(taus[i], chain.inverse_dynamics(q[i], qd[i], np.zeros(7)))
        np.testing.assert_array_equal(Ms[i], chain.mass_matrix(q[i]))


def world_inertias(chain):
    """The (n, 6, 6) operand of the dynamics gufuncs: the chain's link inertias moved by its base frame."""
    out = []
    for row in chain.link_inertias:
        m, com, (ixx, ixy, ixz, iyy, iyz, izz) = row[0], row[1:4], row[4:]
        body = SpatialInertia(m, com, [[ixx, ixy, ixz], [ixy, iyy, iyz], [ixz, iyz, izz]])
        out.append(body.transform(chain.base).matrix)
    return np.array(out)


def test_dynamics_one_configuration_gives_the_bits_of_the_gufuncs(arms):
    """A single configuration of float64 (an (n,) array or a list) takes the
    methods' fast path (the chain's C++ Dynamics, no numpy dispatch): the
    same bits as the private gufuncs on the chain's operands; float32 and
    Wrench arguments go through the gufuncs."""
    from chasles import Wrench, _core

    ur5 = arms["ur5"]
    base = SE3.exp([0.3, -0.2, 0.5, 0.4, -0.7, 1.1])
    chain = Chain(ur5.space_screws, ur5.home, link_inertias=ur5.link_inertias, base=base, gravity=[0.1, -0.2, -9.7])
    S, M, G, g = chain.space_screws, np.asarray(chain.home), world_inertias(chain), chain.gravity
    rng = np.random.default_rng(8)
    q, qd, x = rng.uniform(-2, 2, (3, 6))
    tip = rng.uniform(-5, 5, 6)
    zero = np.zeros(6)
    for a, b, c in [(q, qd, x), (list(q), list(qd), list(x)), (q.astype(np.float32), qd, x)]:
        for t, t_op in [(None, zero), (tip, tip), (list(tip), tip), (Wrench(tip[:3], tip[3:]), tip)]:
            kw = {} if t is None else {"tip_wrench": t}
            np.testing.assert_array_equal(
                chain.inverse_dynamics(a, b, c, **kw), _core._inverse_dynamics(S, M, G, g, a, b, c, t_op)
            )
            np.testing.assert_array_equal(
                chain.forward_dynamics(a, b, c, **kw), _core._forward_dynamics(S, M, G, g, a, b, c, t_op)[0]
            )
        np.testing.assert_array_equal(chain.mass_matrix(a), _core._mass_matrix(S, M, G, a))
        np.testing.assert_array_equal(chain.gravity_torques(a), _core._gravity_torques(S, M, G, g, a))
        np.testing.assert_array_equal(chain.coriolis(a, b), _core._coriolis(S, M, G, a, b))
    out = chain.inverse_dynamics(list(q), q, q)
    assert type(out) is np.ndarray and out.shape == (6,) and out.dtype == np.float64
    assert chain.mass_matrix(q).shape == (6, 6)
    one = Chain(S[:1], M, link_inertias=ur5.link_inertias[:1])
    assert one.mass_matrix([0.3]).shape == (1, 1) and one.gravity_torques([0.3]).shape == (1,)
    # a NaN gives NaN, on the fast path as in the loop
    bad = q.copy()
    bad[2] = np.nan
    np.testing.assert_array_equal(chain.gravity_torques(bad), _core._gravity_torques(S, M, G, g, bad))


def test_dynamics_base_frame_moves_the_inertias(arms):
    """A chain on a base frame has the joint torques of the same chain
    without it under gravity rotated into the base frame."""
    ur5 = arms["ur5"]
    base = SE3.exp([0.3, -0.2, 0.5, 0.4, -0.7, 1.1])
    based = Chain(ur5.space_screws, ur5.home, link_inertias=ur5.link_inertias, base=base)
    rotated = base.rotation.as_matrix().T @ based.gravity
    plain = Chain(ur5.space_screws, ur5.home, link_inertias=ur5.link_inertias, gravity=rotated)
    rng = np.random.default_rng(9)
    q, qd, qdd = rng.uniform(-2, 2, (3, 4, 6))
    tip = rng.uniform(-5, 5, 6)
    assert_close(based.inverse_dynamics(q, qd, qdd, tip_wrench=tip), plain.inverse_dynamics(q, qd, qdd, tip_wrench=tip))
    assert_close(based.mass_matrix(q), plain.mass_matrix(q))
    assert_close(based.forward_dynamics(q, qd, qdd), plain.forward_dynamics(q, qd, qdd), 1e-10)
    # and not without rotating gravity
    unrotated = Chain(ur5.space_screws, ur5.home, link_inertias=ur5.link_inertias)
    assert not np.allclose(based.gravity_torques(q), unrotated.gravity_torques(q))


def test_a_massless_link_adds_nothing(arms):
    """A link of zero mass and inertia (as URDF links may be): the torques of
    the chain without it, and zero on its own joint (no NaN from its
    undefined center of mass)."""
    ur5 = arms["ur5"]
    inertias = ur5.link_inertias.copy()
    inertias[5] = 0.0
    chain = Chain(ur5.space_screws, ur5.home, link_inertias=inertias)
    shorter = Chain(ur5.space_screws[:5], ur5.home, link_inertias=inertias[:5])
    rng = np.random.default_rng(10)
    q, qd, qdd = rng.uniform(-2, 2, (3, 6))
    for single in (q, list(q)):  # the fast path
        tau = chain.inverse_dynamics(single, qd, qdd)
        assert tau[5] == 0.0
        assert_close(tau[:5], shorter.inverse_dynamics(q[:5], qd[:5], qdd[:5]))
    tau = chain.inverse_dynamics(q[None], qd, qdd)[0]  # the gufunc
    assert tau[5] == 0.0
    assert_close(tau[:5], shorter.inverse_dynamics(q[:5], qd[:5], qdd[:5]))


def test_dynamics_need_link_inertias_and_matching_shapes(arms):
    bare = Chain(arms["ur5"].space_screws, arms["ur5"].home)
    with pytest.raises(ValueError, match=r"Chain.gravity_torques: the chain has no link inertias"):
        bare.gravity_torques(np.zeros(6))
    with pytest.raises(ValueError, match=r"Chain.mass_matrix\(q\): expected shape \(6,\)"):
        arms["ur5"].mass_matrix(np.zeros(7))


# ---- forward dynamics where M(q) is not positive definite ---------------------------
#
# Each chain below made the Cholesky factorization of M(q) fail unnoticed before
# forward_dynamics checked it: inf, NaN or finite accelerations of 1e10 and more.

NOT_PD = r"Chain.forward_dynamics: the mass matrix M\(q\) is not positive definite"


def point_masses_on_axes(chain, offset=0.0):
    """The chain's link inertias as point masses (I_c = 0) of the same masses on
    their joints' axes (the point nearest the origin, 0.1 m along), `offset`
    off the axis along a normal."""
    rows = chain.link_inertias.copy()
    for i, s in enumerate(chain.space_screws):
        v, w = s[:3], s[3:]
        normal = np.cross(w, [1.0, 0.0, 0.0] if abs(w[0]) < 0.9 else [0.0, 1.0, 0.0])
        rows[i, 1:4] = np.cross(w, v) + 0.1 * w + offset * normal / np.linalg.norm(normal)
        rows[i, 4:] = 0.0
    return Chain(chain.space_screws, chain.home, link_inertias=rows)


# A two-link arm whose second link's I_zz has a sign error (principal moments
# 0.01, 0.01, -0.01: the triangle inequality broken, not positive definite),
# its center of mass on the joint's axis: Chain.from_urdf accepts it, and
# M_22 = I_zz < 0.
INDEFINITE_URDF = """<robot name="indefinite">
  <link name="base"/>
  <link name="upper"><inertial><origin xyz="0.2 0 0"/><mass value="2"/>
    <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.05" iyz="0" izz="0.05"/></inertial></link>
  <link name="hand"><inertial><origin xyz="0 0 0.1"/><mass value="0.5"/>
    <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="-0.01"/></inertial></link>
  <joint name="shoulder" type="revolute"><parent link="base"/><child link="upper"/>
    <axis xyz="0 0 1"/><limit lower="-3" upper="3" effort="10" velocity="2"/></joint>
  <joint name="wrist" type="revolute"><parent link="upper"/><child link="hand"/>
    <origin xyz="0.4 0 0"/><axis xyz="0 0 1"/><limit lower="-3" upper="3" effort="10" velocity="2"/></joint>
</robot>"""


def not_positive_definite_chains(arms):
    ur5 = arms["ur5"]
    massless_hand = ur5.link_inertias.copy()
    massless_hand[5] = 0.0
    return {
        "massless last link": (Chain(ur5.space_screws, ur5.home, link_inertias=massless_hand), 5),
        "point masses on the joint axes": (point_masses_on_axes(arms["panda"]), 6),
        # 1e-9 m off the axis: M_77 = m d^2 = 1e-18 kg m^2, rounding in the sums of its terms
        "nearly singular": (point_masses_on_axes(arms["panda"], 1e-9), 6),
        "indefinite inertia (URDF)": (Chain.from_urdf(INDEFINITE_URDF, "hand"), 1),
    }


@pytest.mark.parametrize(
    "case", ["massless last link", "point masses on the joint axes", "nearly singular", "indefinite inertia (URDF)"]
)
def test_forward_dynamics_raises_where_the_mass_matrix_is_not_positive_definite(arms, case):
    chain, joint = not_positive_definite_chains(arms)[case]
    n = chain.n_joints
    rng = np.random.default_rng(11)
    q, qd, tau = within_limits(chain, rng), rng.uniform(-1, 1, n), rng.uniform(-5, 5, n)
    # one configuration: the fast path (float64) and the gufunc (a list of ints)
    for args in [(q, qd, tau), (q[None], qd, tau), ([0] * n, [0] * n, [1] * n)]:
        with pytest.raises(ValueError, match=NOT_PD + r".*fails at joint " + str(joint)):
            chain.forward_dynamics(*args)
    # a batch: the first configuration named
    Q = np.array([within_limits(chain, rng) for _ in range(6)]).reshape(2, 3, n)
    with pytest.raises(ValueError, match=NOT_PD + r" at batch index \(0, 0\), the first of 6 of 6 configurations"):
        chain.forward_dynamics(Q, qd, tau)
    # on_failure="nan": NaN, no exception, on both paths
    assert np.isnan(chain.forward_dynamics(q, qd, tau, on_failure="nan")).all()
    assert np.isnan(chain.forward_dynamics(Q, qd, tau, on_failure="nan")).all()
    # the private gufunc says where (these chains have no base frame: their
    # link inertias are the gufunc's, as 6x6 matrices G, order (v, w))
    G = []
    for m, c, (ixx, ixy, ixz, iyy, iyz, izz) in zip(
        chain.link_inertias[:, 0], chain.link_inertias[:, 1:4], chain.link_inertias[:, 4:]
    ):
        C = np.array([[0, -c[2], c[1]], [c[2], 0, -c[0]], [-c[1], c[0], 0]])
        Ic = np.array([[ixx, ixy, ixz], [ixy, iyy, iyz], [ixz, iyz, izz]])
        G.append(np.block([[m * np.eye(3), -m * C], [m * C, Ic - m * C @ C]]))
    qdd, joints = _core._forward_dynamics(
        chain.space_screws, np.asarray(chain.home), np.array(G), chain.gravity, Q, qd, tau, np.zeros(6)
    )
    assert joints.dtype == np.int32 and joints.shape == (2, 3) and (joints == joint).all() and np.isnan(qdd).all()


def test_from_urdf_keeps_accepting_impossible_inertias():
    chain = Chain.from_urdf(INDEFINITE_URDF, "hand")
    assert chain.link_inertias[1, 9] == -0.01  # izz as given
    # inverse dynamics and the mass matrix are still computed (M is indefinite)
    M = chain.mass_matrix([0.3, -0.2])
    assert M[1, 1] == pytest.approx(-0.01) and np.linalg.eigvalsh(M)[0] < 0


def point_mass_pendulum():
    """Joint 1 about z, joint 2 about x, both through the origin; link 1
    massless, link 2 a point mass at (0, 1, 0) at home: M(q) = diag(cos^2 q2, 1),
    singular at q2 = +-pi/2 only (the mass on joint 1's axis)."""
    inertias = np.zeros((2, 10))
    inertias[1, :4] = [1.0, 0.0, 1.0, 0.0]
    return Chain([[0, 0, 0, 0, 0, 1], [0, 0, 0, 1, 0, 0]], np.eye(4), link_inertias=inertias)


def test_forward_dynamics_batch_names_the_first_bad_configuration_or_gives_nan_there(set_threads):
    chain = point_mass_pendulum()
    rng = np.random.default_rng(12)
    for threads, size in [(1, (4, 5)), (2, (3, 700))]:  # 2100 configurations: split across two threads
        set_threads(threads)
        q = rng.uniform(-1, 1, size + (2,))
        qd, tau = rng.uniform(-1, 1, (2,) + size + (2,))
        bad = [(1, 2), (size[0] - 1, size[1] - 1), (2, 3)]  # in C order: (1, 2) first
        for i in bad:
            q[i + (1,)] = np.pi / 2 if i[1] % 2 else -np.pi / 2
        index = r"\(1, 2\)"
        with pytest.raises(
            ValueError,
            match=NOT_PD
            + r" at batch index "
            + index
            + r", the first of 3 of "
            + str(q[..., 0].size)
            + r" configurations.*fails at joint 0",
        ):
            chain.forward_dynamics(q, qd, tau)
        qdd = chain.forward_dynamics(q, qd, tau, on_failure="nan")
        flagged = np.isnan(qdd).any(axis=-1)
        assert sorted(zip(*np.nonzero(flagged))) == sorted(bad)
        assert np.isnan(qdd[flagged]).all()
        ok = ~flagged
        M = chain.mass_matrix(q[ok])
        h = chain.inverse_dynamics(q[ok], qd[ok], np.zeros(2))
        np.testing.assert_allclose(
            qdd[ok], np.linalg.solve(M, (tau[ok] - h)[..., None])[..., 0], rtol=1e-12, atol=1e-12
        )
        # each element is the single call's
        for i in [(0, 0), (1, 2), (2, 4)]:
            one = chain.forward_dynamics(q[i], qd[i], tau[i], on_failure="nan")
            np.testing.assert_array_equal(one, qdd[i])


@pytest.fixture
def set_threads():
    """chasles.set_num_threads, the count restored after the test."""
    import chasles

    before = chasles.get_num_threads()
    yield chasles.set_num_threads
    chasles.set_num_threads(before)


def test_forward_dynamics_on_failure_is_raise_or_nan(arms):
    chain = arms["ur5"]
    q = np.zeros(6)
    for bad in ["ignore", None, 1, "NaN"]:
        with pytest.raises(ValueError, match=r"Chain.forward_dynamics\(on_failure\): expected \"raise\" or \"nan\""):
            chain.forward_dynamics(q, q, q, on_failure=bad)
    np.testing.assert_array_equal(chain.forward_dynamics(q, q, q, on_failure="raise"), chain.forward_dynamics(q, q, q))


@pytest.mark.parametrize("key", list(ARMS))
def test_forward_dynamics_of_real_arms_is_the_cholesky_solve(arms, key):
    """The real arms within their limits: no failure on 500 configurations,
    and qdd = M^-1 (tau - h) of numpy's solve to rounding (times cond(M))."""
    chain = arms[key]
    n = chain.n_joints
    rng = np.random.default_rng(13)
    q = np.array([within_limits(chain, rng) for _ in range(500)])
    qd, tau = rng.uniform(-2, 2, (2, 500, n))
    qdd = chain.forward_dynamics(q, qd, tau)
    M = chain.mass_matrix(q)
    h = chain.inverse_dynamics(q, qd, np.zeros(n))
    expected = np.linalg.solve(M, (tau - h)[..., None])[..., 0]
    cond = np.linalg.cond(M)
    err = np.abs(qdd - expected).max(axis=-1) / np.abs(expected).max(axis=-1)
    assert np.all(err <= 1e-13 * cond), (err / cond).max()
    np.testing.assert_array_equal(qdd[7], chain.forward_dynamics(q[7], qd[7], tau[7]))


# ---- derivatives of the dynamics ----------------------------------------------------------


def central(f, x, h=1e-6):
    """Central differences of f at x, one column per coordinate (truncation h^2, rounding eps / h)."""
    return np.stack([(f(x + h * e) - f(x - h * e)) / (2 * h) for e in np.eye(len(x))], axis=-1)


@pytest.mark.parametrize("key", sorted(ARMS))
def test_dynamics_derivatives_against_central_differences(arms, key):
    # On the real arms (Jaco2's continuous joints included), with a tip wrench: the analytic
    # derivatives against central differences of the methods themselves (1e-7 relative: the
    # differences' own error), d qdd / d tau against numpy's inverse of M(q), and
    # forward_dynamics_derivatives' first two against -M^-1 times inverse_dynamics_derivatives'.
    chain = arms[key]
    n = chain.n_joints
    rng = np.random.default_rng(12)
    for _ in range(3):
        q, (qd, qdd, tau), tip = within_limits(chain, rng, 0.01), rng.uniform(-2, 2, (3, n)), rng.uniform(-5, 5, 6)
        dq, dqd = chain.inverse_dynamics_derivatives(q, qd, qdd, tip_wrench=tip)
        assert_close(dq, central(lambda x: chain.inverse_dynamics(x, qd, qdd, tip_wrench=tip), q), 1e-7)
        assert_close(dqd, central(lambda x: chain.inverse_dynamics(q, x, qdd, tip_wrench=tip), qd), 1e-7)
        fq, fqd, ftau = chain.forward_dynamics_derivatives(q, qd, tau, tip_wrench=tip)
        M = chain.mass_matrix(q)
        cond = np.linalg.cond(M)
        fd = chain.forward_dynamics
        assert_close(fq, central(lambda x: fd(x, qd, tau, tip_wrench=tip), q), 1e-7 * cond)
        assert_close(fqd, central(lambda x: fd(q, x, tau, tip_wrench=tip), qd), 1e-7 * cond)
        assert_close(ftau, np.linalg.inv(M), 1e-13 * cond)
        np.testing.assert_array_equal(ftau, chain.mass_matrix_inverse(q))
        a = fd(q, qd, tau, tip_wrench=tip)
        dq_a, dqd_a = chain.inverse_dynamics_derivatives(q, qd, a, tip_wrench=tip)
        assert_close(fq, -ftau @ dq_a, 1e-12 * cond)
        assert_close(fqd, -ftau @ dqd_a, 1e-12 * cond)


def test_dynamics_derivatives_are_array_functions(arms):
    chain = arms["panda"]
    rng = np.random.default_rng(13)
    q, qd, x = rng.uniform(-1, 1, (3, 2, 3, 7))
    tip = rng.uniform(-1, 1, 6)
    dq, dqd = chain.inverse_dynamics_derivatives(q, qd, x, tip_wrench=tip)
    fq, fqd, ftau = chain.forward_dynamics_derivatives(q, qd, x, tip_wrench=tip)
    Minv = chain.mass_matrix_inverse(q)
    assert all(a.shape == (2, 3, 7, 7) for a in (dq, dqd, fq, fqd, ftau, Minv))
    for i in range(2):
        for j in range(3):
            one = chain.inverse_dynamics_derivatives(q[i, j], qd[i, j], x[i, j], tip_wrench=tip)
            np.testing.assert_array_equal(dq[i, j], one[0])
            np.testing.assert_array_equal(dqd[i, j], one[1])
            one = chain.forward_dynamics_derivatives(q[i, j], qd[i, j], x[i, j], tip_wrench=tip)
            for batched, single in zip((fq, fqd, ftau), one):
                np.testing.assert_array_equal(batched[i, j], single)
            np.testing.assert_array_equal(Minv[i, j], chain.mass_matrix_inverse(list(q[i, j])))
    assert isinstance(chain.inverse_dynamics_derivatives(q[0, 0], qd[0, 0], x[0, 0]), tuple)
    assert isinstance(chain.forward_dynamics_derivatives(q, qd, x), tuple)
    with pytest.raises(ValueError, match=r"Chain.inverse_dynamics_derivatives\(qd\): expected shape \(7,\)"):
        chain.inverse_dynamics_derivatives(q, qd[..., :6], x)
    with pytest.raises(ValueError, match=r"Chain.mass_matrix_inverse: the chain has no link inertias"):
        Chain(chain.space_screws, chain.home).mass_matrix_inverse(q)


def test_derivatives_and_inverse_fail_where_forward_dynamics_fails(arms):
    chain, joint = not_positive_definite_chains(arms)["massless last link"]
    rng = np.random.default_rng(14)
    q, qd, tau = within_limits(chain, rng), rng.uniform(-1, 1, 6), rng.uniform(-5, 5, 6)
    for method, args in (("forward_dynamics_derivatives", (q, qd, tau)), ("mass_matrix_inverse", (q,))):
        f = getattr(chain, method)
        with pytest.raises(
            ValueError,
            match=rf"Chain.{method}: the mass matrix M\(q\) is not positive definite.*"
            rf"joint {joint}",
        ):
            f(*args)
        with pytest.raises(ValueError, match=rf"Chain.{method}: .* at batch index \(0,\), the first of 2 of 2"):
            f(np.stack([q, q]), *args[1:])
        out = f(*args, on_failure="nan")
        assert all(np.isnan(a).all() for a in (out if isinstance(out, tuple) else (out,)))
        with pytest.raises(ValueError, match=rf"Chain.{method}\(on_failure\): expected \"raise\" or \"nan\""):
            f(*args, on_failure="ignore")
    # the inverse dynamics' derivatives need no factorization: finite there
    assert all(np.isfinite(a).all() for a in chain.inverse_dynamics_derivatives(q, qd, tau))


# ---- time derivatives of the Jacobians ------------------------------------------------------


@pytest.mark.parametrize("key", sorted(ARMS))
def test_jacobian_dots_against_central_differences(arms, key):
    # dJ/dt along q(t) = q + t qd + t^2 qdd / 2 by central differences (step 1e-5: 1e-9 relative),
    # and the tool's body acceleration J_b qdd + J_b_dot qd as d/dt (J_b(q(t)) q'(t)) (the body
    # twist's rate), space likewise.
    chain = arms[key]
    n = chain.n_joints
    rng = np.random.default_rng(15)
    h = 1e-5
    for _ in range(3):
        q, qd, qdd = within_limits(chain, rng, 0.01), rng.uniform(-2, 2, n), rng.uniform(-2, 2, n)

        def along(f, t):
            return f(q + t * qd + t * t / 2 * qdd)

        def rate(f):
            return (along(f, h) - along(f, -h)) / (2 * h)

        Js_dot, Jb_dot = chain.jacobian_space_dot(q, qd), chain.jacobian_body_dot(q, qd)
        assert_close(Js_dot, rate(chain.jacobian_space), 1e-8)
        assert_close(Jb_dot, rate(chain.jacobian_body), 1e-8)
        for jacobian, dot in ((chain.jacobian_space, Js_dot), (chain.jacobian_body, Jb_dot)):
            twist_rate = (
                jacobian(q + h * qd + h * h / 2 * qdd) @ (qd + h * qdd)
                - jacobian(q - h * qd + h * h / 2 * qdd) @ (qd - h * qdd)
            ) / (2 * h)
            assert_close(jacobian(q) @ qdd + dot @ qd, twist_rate, 1e-8)
    # array functions: a batch equals its single calls
    Q, QD = rng.uniform(-1, 1, (2, 3, n))
    batch = chain.jacobian_body_dot(Q, QD)
    assert batch.shape == (3, 6, n)
    for i in range(3):
        np.testing.assert_array_equal(batch[i], chain.jacobian_body_dot(Q[i], QD[i]))
    with pytest.raises(ValueError, match=rf"Chain.jacobian_space_dot\(theta_dot\): expected shape \({n},\)"):
        chain.jacobian_space_dot(q, qd[:-1])
