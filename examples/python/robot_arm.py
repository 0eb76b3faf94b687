"""A real arm from its URDF: inverse kinematics, joint torques along a trajectory, a picture.

The Franka Panda of the example-robot-data package (pip install
example-robot-data) is loaded with Chain.from_urdf, from its base to the point
between its fingers (panda_hand_tcp). Then:

1. inverse kinematics to a target pose, the hand pointing down, from
   Franka's "ready" configuration: the solution reaches the target (checked
   with forward kinematics) within the joint limits;
2. the joint torques along a quintic time scaling from "ready" to the
   solution (chasles.joint_trajectory), q(t) = q_ready + s(t / T) (q_ik - q_ready)
   with s(u) = 10 u^3 - 15 u^4 + 6 u^5 (Lynch and Park, Modern Robotics, 9.2.2:
   zero velocity and acceleration at both ends), by inverse dynamics batched
   over the trajectory's samples in one call; checked: at both ends, where
   the arm is at rest, they are the gravity torques, and everywhere
   tau = M(q) qdd + C(q, qd) qd + g(q); the peak torque of each joint is
   printed beside the URDF's effort limit;
3. a picture of the arm at the solution (chasles.plot.chain), the target
   and the path of the tool, written to the file given with --png
   (without it, to a temporary file that is removed at the end).

    python examples/python/robot_arm.py [--png PATH] [--duration T]

docs/images/robot_arm.png is ``--png docs/images/robot_arm.png``. Needs
matplotlib (``pip install chasles[plot]``) for the picture.
"""

import argparse
import importlib.metadata
import tempfile
import time
from pathlib import Path

import numpy as np

import chasles
from chasles import SE3, SO3

# Franka's "ready" configuration (radians): elbow up, the hand pointing down.
Q_READY = np.array([0.0, -np.pi / 4, 0.0, -3 * np.pi / 4, 0.0, np.pi / 2, np.pi / 4])

# The target: the hand pointing down (its z axis along -z), 0.5 m in front of
# the base, 0.2 m to its left and 0.25 m above it.
TARGET = SE3(SO3.from_rpy([np.pi, 0.0, 0.0]), [0.5, 0.2, 0.25])


def panda_path():
    for f in importlib.metadata.files("example-robot-data") or []:
        if str(f).endswith("panda_description/urdf/panda.urdf"):
            return f.locate()
    raise SystemExit("example-robot-data has no Panda")


def draw(arm, q, trajectory, path):
    """The arm at q, the target and the tool's path, written to path."""
    from matplotlib.figure import Figure

    from chasles import plot

    fig = Figure(figsize=(7, 6), dpi=100)
    ax = fig.add_subplot(projection="3d")
    drawn = plot.chain(arm, q, ax=ax)
    tool_path = arm.forward(trajectory)[:, :3, 3]
    ax.plot(*tool_path.T, color="tab:purple", linestyle=":", linewidth=1.5)
    ax.plot(*TARGET.translation, color="tab:purple", marker="*", markersize=14, linestyle="none")
    ax.set_aspect("equal", adjustable="datalim")
    ax.view_init(elev=20, azim=-60)
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_zlabel("z (m)")
    ax.set_title(
        "Panda at the inverse kinematics solution, its tool at the target (star);\n"
        "dotted: the tool's path from 'ready'; orange: the joint axes",
        fontsize=10,
    )
    fig.savefig(path, bbox_inches="tight")
    return drawn


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--png", help="where to write the picture (default: a temporary file)")
    parser.add_argument("--duration", type=float, default=2.0, help="the motion's duration T (s)")
    args = parser.parse_args()

    arm = chasles.Chain.from_urdf(panda_path(), "panda_hand_tcp")
    print(arm)
    print(f"  mass of the moving links: {arm.link_inertias[:, 0].sum():.3f} kg")

    # 1. Inverse kinematics.
    start = time.perf_counter()
    ik = arm.inverse_kinematics(TARGET, Q_READY)
    elapsed = time.perf_counter() - start
    assert ik.converged, ik
    reached = SE3.from_matrix(arm.forward(ik.q))
    position_error = np.linalg.norm(reached.translation - TARGET.translation)
    angle_error = (reached.inverse() @ TARGET).rotation.angle()
    assert position_error < 1e-10 and angle_error < 1e-10, (position_error, angle_error)
    assert np.all((arm.lower <= ik.q) & (ik.q <= arm.upper))
    print(f"1. IK from 'ready' to the target: converged in {ik.iterations} iterations ({elapsed * 1e6:.0f} us)")
    print(
        f"   |error twist| = {np.linalg.norm(ik.error):.1e}; forward kinematics of the "
        f"solution is {position_error:.1e} m and {angle_error:.1e} rad from the target"
    )
    print(f"   q = {np.array2string(ik.q, precision=4)} rad, within the joint limits")

    # 2. Joint torques along the trajectory, in one batched call.
    t = np.linspace(0.0, args.duration, 201)
    q, qd, qdd = chasles.joint_trajectory(Q_READY, ik.q, t, args.duration, "quintic")  # (201, 7) each
    start = time.perf_counter()
    tau = arm.inverse_dynamics(q, qd, qdd)  # (201, 7)
    elapsed = time.perf_counter() - start
    gravity = arm.gravity_torques(q[[0, -1]])
    at_ends = np.abs(tau[[0, -1]] - gravity).max()
    assert at_ends < 1e-12, at_ends  # at rest: tau = g(q)
    assembled = np.einsum("kij,kj->ki", arm.mass_matrix(q), qdd) + arm.coriolis(q, qd)
    assembled += arm.gravity_torques(q)
    identity = np.abs(tau - assembled).max()
    assert identity < 1e-9, identity
    print(
        f"2. Inverse dynamics of {len(t)} samples of a {args.duration:g} s quintic motion "
        f"in one call ({elapsed * 1e6:.0f} us)"
    )
    print(
        f"   at rest at both ends tau equals the gravity torques (to {at_ends:.1e} N m); "
        f"tau = M qdd + C qd + g to {identity:.1e} N m"
    )
    peak = np.abs(tau).max(axis=0)
    print("   joint           peak |tau|   effort limit   peak / limit")
    for name, p, limit in zip(arm.joint_names, peak, arm.effort_limits):
        print(f"   {name:13s} {p:8.3f} N m   {limit:8.1f} N m   {p / limit:8.1%}")
    within = bool(np.all(peak <= arm.effort_limits))
    assert within, "the motion needs more torque than the motors give: make it slower"
    print(f"   peak torque within the effort limits of every joint: {within}")

    # 3. The picture.
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        print("3. No picture: it needs matplotlib, pip install chasles[plot]")
        return
    if args.png:
        drawn = draw(arm, ik.q, q, args.png)
        print(f"3. Picture of the arm at the solution written to {args.png}")
    else:
        with tempfile.TemporaryDirectory() as tmp:
            png = Path(tmp) / "robot_arm.png"
            drawn = draw(arm, ik.q, q, png)
            size = png.stat().st_size
        print(f"3. Picture of the arm at the solution drawn ({size} bytes, to a temporary file; --png PATH keeps it)")
    tool = drawn.points[-1]
    assert np.allclose(tool, TARGET.translation, atol=1e-10, rtol=0)
    print(f"   the drawn tool is at {np.array2string(tool, precision=4)}, the target")


if __name__ == "__main__":
    main()
