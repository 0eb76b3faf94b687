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
and the time per call of each side's Python call.

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
    keep = set(chain.names)
    lock = [i for i in range(1, full.njoints) if full.names[i] not in keep]
    model = pin.buildReducedModel(full, lock, pin.neutral(full))
    assert list(model.names)[1:] == list(chain.names), (list(model.names), chain.names)
    return model


def pin_configuration(model, q):
    """Pinocchio's configuration of joint angles q: (cos, sin) for a continuous joint (nq = 2)."""
    out = []
    for joint, t in zip(list(model.joints)[1:], q):
        out += [np.cos(t), np.sin(t)] if joint.nq == 2 else [t]
    return np.array(out)


def rel(a, b) -> float:
    return float(np.max(np.abs(np.asarray(a) - np.asarray(b))) / max(1.0, float(np.max(np.abs(b)))))


def per_call(fn, repeats=2000) -> float:
    t0 = time.perf_counter()
    for _ in range(repeats):
        fn()
    return (time.perf_counter() - t0) / repeats


def main() -> None:
    root = robots_dir()
    print(f"pinocchio {pin.__version__}; largest relative difference over {STATES} states")
    print(f"{'arm':6} {'n':>2} {'forward':>8} {'rnea':>8} {'crba':>8} {'gravity':>8} {'coriolis':>8} {'aba':>8}")
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
        worst = dict.fromkeys(("forward", "rnea", "crba", "gravity", "coriolis", "aba"), 0.0)
        for _ in range(STATES):
            q = rng.uniform(np.maximum(chain.lower, -np.pi), np.minimum(chain.upper, np.pi))
            qd, qdd, tau = rng.uniform(-2, 2, (3, n))
            qp, q = pin_configuration(model, q), q
            pin.framesForwardKinematics(model, data, qp)
            worst["forward"] = max(worst["forward"], rel(chain.forward(q), data.oMf[frame].homogeneous))
            worst["rnea"] = max(worst["rnea"], rel(chain.inverse_dynamics(q, qd, qdd), pin.rnea(model, data, qp, qd, qdd)))
            M = pin.crba(model, data, qp)
            M = np.triu(M) + np.triu(M, 1).T
            worst["crba"] = max(worst["crba"], rel(chain.mass_matrix(q), M))
            g = pin.computeGeneralizedGravity(model, data, qp)
            worst["gravity"] = max(worst["gravity"], rel(chain.gravity_torques(q), g))
            worst["coriolis"] = max(worst["coriolis"], rel(chain.coriolis(q, qd), pin.nonLinearEffects(model, data, qp, qd) - g))
            worst["aba"] = max(worst["aba"], rel(chain.forward_dynamics(q, qd, tau), pin.aba(model, data, qp, qd, tau)))
        print(f"{name:6} {n:>2} " + " ".join(f"{worst[k]:8.1e}" for k in worst))
        if name == "Panda":
            q, qd, qdd = rng.uniform(-1, 1, (3, n))
            qp = pin_configuration(model, q)
            timing = {
                "inverse dynamics": (per_call(lambda: chain.inverse_dynamics(q, qd, qdd)),
                                     per_call(lambda: pin.rnea(model, data, qp, qd, qdd))),
                "mass matrix": (per_call(lambda: chain.mass_matrix(q)), per_call(lambda: pin.crba(model, data, qp))),
                "forward dynamics": (per_call(lambda: chain.forward_dynamics(q, qd, qdd)),
                                     per_call(lambda: pin.aba(model, data, qp, qd, qdd))),
            }
    print("\nPanda, one call from Python (microseconds): chasles / Pinocchio")
    for k, (a, b) in timing.items():
        print(f"  {k:17} {1e6 * a:6.2f} / {1e6 * b:6.2f}")


if __name__ == "__main__":
    main()
