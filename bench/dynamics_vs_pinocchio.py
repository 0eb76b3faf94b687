"""chasles' kinematics and dynamics against Pinocchio on real arms.

For each arm of example-robot-data, the chain from the URDF's root to its
tool link is loaded twice: by chasles.Chain.from_urdf, and by Pinocchio
(pin.buildModelFromUrdf, every joint off the chain locked at zero with
pin.buildReducedModel). At 100 random states (q uniform within the limits,
clipped to [-pi, pi]; qd, qdd, tau uniform in [-2, 2]) it reports the
largest relative difference (max |a - b| / max(1, max |b|)) of
- forward kinematics (Pinocchio: the tool frame's oMf),
- inverse dynamics (pin.rnea), the mass matrix (pin.crba, both triangles),
  gravity torques (pin.computeGeneralizedGravity), the Coriolis terms
  (pin.nonLinearEffects minus gravity) and forward dynamics (pin.aba),
- the derivatives of inverse dynamics (pin.computeRNEADerivatives: d tau / d q
  and d tau / d qd) and of forward dynamics (pin.computeABADerivatives: d qdd /
  d q, d qd, d tau), M(q)^-1 (pin.computeMinverse, both triangles), and
  the time derivatives of the tool's Jacobians
  (pin.getFrameJacobianTimeVariation, WORLD and LOCAL),
and the time of each side's Python call: one configuration per call (the
median and the minimum over 15 rounds of 1000 calls), and chasles' batched
call on N = 1000 configurations ((N, n) arrays) per configuration
(Pinocchio's Python API has no batched call: a loop costs its per-call
time), the three interleaved round by round (chasles, Pinocchio, the batch,
then again), so that a disturbance of the machine falls on both libraries
alike; with the floor of a
chasles method that returns a new (n,) array and computes nothing
(Chain.lower), the cost of the pybind11 call and the array alone.

Pinocchio (pip install pin, about 480 MB) is not a test dependency: this
script runs where it is installed.

    python bench/dynamics_vs_pinocchio.py
"""

from __future__ import annotations

import importlib.metadata
import time

import numpy as np
import pinocchio as pin

from chasles import Chain

ARMS = {
    "UR3": ("ur_description/urdf/ur3_robot.urdf", "tool0"),
    "UR5": ("ur_description/urdf/ur5_robot.urdf", "tool0"),
    "UR10": ("ur_description/urdf/ur10_robot.urdf", "tool0"),
    "Panda": ("panda_description/urdf/panda.urdf", "panda_hand"),
    "xArm7": ("xarm_description/urdf/xarm7.urdf", "link7"),
    "Z1": ("z1_description/urdf/z1.urdf", "link06"),
    "Jaco2": ("kinova_description/robots/kinova.urdf", "j2s6s200_end_effector"),
}
STATES = 100


def robots_dir():
    for f in importlib.metadata.files("example-robot-data") or []:
        if str(f).endswith("ur_description/urdf/ur5_robot.urdf"):
            return f.locate().parents[2]
    raise SystemExit("example-robot-data is not installed (pip install example-robot-data)")


def reduced_model(path, chain: Chain):
    """Pinocchio's model of the URDF with every joint not in the chain locked at 0."""
    full = pin.buildModelFromUrdf(str(path))
    keep = set(chain.joint_names)
    lock = [i for i in range(1, full.njoints) if full.names[i] not in keep]
    model = pin.buildReducedModel(full, lock, pin.neutral(full))
    assert list(model.names)[1:] == list(chain.joint_names), (list(model.names), chain.joint_names)
    return model


def pin_configuration(model, q):
    """Pinocchio's configuration of joint angles q: (cos, sin) for a continuous joint (nq = 2)."""
    out = []
    for joint, t in zip(list(model.joints)[1:], q):
        out += [np.cos(t), np.sin(t)] if joint.nq == 2 else [t]
    return np.array(out)


def rel(a, b) -> float:
    return float(np.max(np.abs(np.asarray(a) - np.asarray(b))) / max(1.0, float(np.max(np.abs(b)))))


def interleaved(*calls, runs=15) -> list[tuple[float, float]]:
    """Each of `calls`, pairs (fn, repeats), timed round by round: in each of
    `runs` rounds every fn runs its `repeats` calls in turn, so that a
    disturbance of the machine falls on all of them alike. Per fn, the
    median and the minimum over the rounds of the mean time of one call (the
    minimum: the least-disturbed round)."""
    times = [[] for _ in calls]
    for _ in range(runs):
        for k, (fn, repeats) in enumerate(calls):
            t0 = time.perf_counter()
            for _ in range(repeats):
                fn()
            times[k].append((time.perf_counter() - t0) / repeats)
    return [(float(np.median(t)), float(np.min(t))) for t in times]


BATCH = 1000
REPEATS = 1000


def timings(chain: Chain, model, data, rng):
    """{operation: (chasles per call, Pinocchio per call, chasles batched per configuration)}
    in seconds, the three interleaved round by round."""
    n = chain.n_joints
    q, qd, qdd = rng.uniform(-1, 1, (3, n))
    qp = pin_configuration(model, q)
    Q, QD, QDD = rng.uniform(-1, 1, (3, BATCH, n))
    ops = {
        "rnea": (
            lambda: chain.inverse_dynamics(q, qd, qdd),
            lambda: pin.rnea(model, data, qp, qd, qdd),
            lambda: chain.inverse_dynamics(Q, QD, QDD),
        ),
        "crba": (
            lambda: chain.mass_matrix(q),
            lambda: pin.crba(model, data, qp),
            lambda: chain.mass_matrix(Q),
        ),
        "gravity": (
            lambda: chain.gravity_torques(q),
            lambda: pin.computeGeneralizedGravity(model, data, qp),
            lambda: chain.gravity_torques(Q),
        ),
        # Pinocchio's C(q, qd) qd: nonLinearEffects (with gravity; no call without it)
        "coriolis": (
            lambda: chain.coriolis(q, qd),
            lambda: pin.nonLinearEffects(model, data, qp, qd),
            lambda: chain.coriolis(Q, QD),
        ),
        "aba": (
            lambda: chain.forward_dynamics(q, qd, qdd),
            lambda: pin.aba(model, data, qp, qd, qdd),
            lambda: chain.forward_dynamics(Q, QD, QDD),
        ),
        "d_rnea": (
            lambda: chain.inverse_dynamics_derivatives(q, qd, qdd),
            lambda: pin.computeRNEADerivatives(model, data, qp, qd, qdd),
            lambda: chain.inverse_dynamics_derivatives(Q, QD, QDD),
        ),
        "d_aba": (
            lambda: chain.forward_dynamics_derivatives(q, qd, qdd),
            lambda: pin.computeABADerivatives(model, data, qp, qd, qdd),
            lambda: chain.forward_dynamics_derivatives(Q, QD, QDD),
        ),
        "minv": (
            lambda: chain.mass_matrix_inverse(q),
            lambda: pin.computeMinverse(model, data, qp),
            lambda: chain.mass_matrix_inverse(Q),
        ),
    }
    out = {}
    for op, (mine, theirs, batched) in ops.items():
        a, b, c = interleaved((mine, REPEATS), (theirs, REPEATS), (batched, 3))
        out[op] = (a, b, (c[0] / BATCH, c[1] / BATCH))
    out["floor"] = (interleaved((lambda: chain.lower, REPEATS))[0], (np.nan, np.nan), (np.nan, np.nan))
    return out


def main() -> None:
    root = robots_dir()
    print(f"pinocchio {pin.__version__}; largest relative difference over {STATES} states")
    columns = ("forward", "rnea", "crba", "gravity", "coriolis", "aba", "d_rnea", "d_aba", "minv", "jdot")
    print(f"{'arm':6} {'n':>2} " + " ".join(f"{c:>8}" for c in columns))
    timing = {}
    for name, (rel_path, tip) in ARMS.items():
        path = root / rel_path
        if not path.exists():
            print(f"{name:6} (not in this example-robot-data)")
            continue
        chain = Chain.from_urdf(path, tip)
        model = reduced_model(path, chain)
        data = model.createData()
        frame = model.getFrameId(tip)
        rng = np.random.default_rng(0)
        n = chain.n_joints
        worst = dict.fromkeys(columns, 0.0)
        for _ in range(STATES):
            q = rng.uniform(np.maximum(chain.lower, -np.pi), np.minimum(chain.upper, np.pi))
            qd, qdd, tau = rng.uniform(-2, 2, (3, n))
            qp, q = pin_configuration(model, q), q
            pin.framesForwardKinematics(model, data, qp)
            worst["forward"] = max(worst["forward"], rel(chain.forward(q), data.oMf[frame].homogeneous))
            worst["rnea"] = max(
                worst["rnea"], rel(chain.inverse_dynamics(q, qd, qdd), pin.rnea(model, data, qp, qd, qdd))
            )
            M = pin.crba(model, data, qp)
            M = np.triu(M) + np.triu(M, 1).T
            worst["crba"] = max(worst["crba"], rel(chain.mass_matrix(q), M))
            g = pin.computeGeneralizedGravity(model, data, qp)
            worst["gravity"] = max(worst["gravity"], rel(chain.gravity_torques(q), g))
            worst["coriolis"] = max(
                worst["coriolis"], rel(chain.coriolis(q, qd), pin.nonLinearEffects(model, data, qp, qd) - g)
            )
            worst["aba"] = max(worst["aba"], rel(chain.forward_dynamics(q, qd, tau), pin.aba(model, data, qp, qd, tau)))
            dq, dqd, _ = pin.computeRNEADerivatives(model, data, qp, qd, qdd)
            mine = chain.inverse_dynamics_derivatives(q, qd, qdd)
            worst["d_rnea"] = max(worst["d_rnea"], rel(mine[0], dq), rel(mine[1], dqd))
            theirs = pin.computeABADerivatives(model, data, qp, qd, tau)
            mine = chain.forward_dynamics_derivatives(q, qd, tau)
            worst["d_aba"] = max(worst["d_aba"], *(rel(a, b) for a, b in zip(mine, theirs)))
            Minv = pin.computeMinverse(model, data, qp)
            Minv = np.triu(Minv) + np.triu(Minv, 1).T
            worst["minv"] = max(worst["minv"], rel(chain.mass_matrix_inverse(q), Minv))
            pin.computeJointJacobiansTimeVariation(model, data, qp, qd)
            pin.updateFramePlacements(model, data)
            Jw = pin.getFrameJacobianTimeVariation(model, data, frame, pin.WORLD)
            Jl = pin.getFrameJacobianTimeVariation(model, data, frame, pin.LOCAL)
            worst["jdot"] = max(
                worst["jdot"], rel(chain.jacobian_space_dot(q, qd), Jw), rel(chain.jacobian_body_dot(q, qd), Jl)
            )
        print(f"{name:6} {n:>2} " + " ".join(f"{worst[k]:8.1e}" for k in worst))
        if name in ("UR5", "Panda", "xArm7"):  # the arms of the speed targets
            timing[name] = timings(chain, model, data, rng)
    print("\nTime from Python, microseconds, median (minimum) of 15 interleaved rounds: one configuration per call,")
    print(f"chasles and Pinocchio and their ratio; chasles batched on N = {BATCH} configurations, per configuration")
    print(f"{'arm':6} {'operation':9} {'chasles':>14} {'pinocchio':>14} {'ratio':>12} {'batched':>14}")
    for name, rows in timing.items():
        for op, (a, b, c) in rows.items():
            if op == "floor":
                print(
                    f"{name:6} {'floor':9} {1e6 * a[0]:6.2f} ({1e6 * a[1]:5.2f})"
                    "  (Chain.lower: a pybind11 call returning a new (n,) array)"
                )
            else:
                print(
                    f"{name:6} {op:9} {1e6 * a[0]:6.2f} ({1e6 * a[1]:5.2f}) {1e6 * b[0]:6.2f} ({1e6 * b[1]:5.2f})"
                    f" {a[0] / b[0]:5.2f} ({a[1] / b[1]:4.2f}) {1e6 * c[0]:6.3f} ({1e6 * c[1]:5.3f})"
                )


if __name__ == "__main__":
    main()
