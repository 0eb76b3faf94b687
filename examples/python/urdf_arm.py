"""Load a real arm from its URDF and check chasles' forward kinematics.

The UR5 of the example-robot-data package (pip install example-robot-data)
is loaded with Chain.from_urdf; its names, types and limits are printed, and
forward kinematics at random joint positions within the limits is checked
against the product of the URDF's own joint transforms, composed here with
numpy (origin, then the rotation about the joint axis).
"""

import importlib.metadata
import math
import xml.etree.ElementTree as ET

import numpy as np

import chasles


def ur5_path():
    for f in importlib.metadata.files("example-robot-data") or []:
        if str(f).endswith("ur_description/urdf/ur5_robot.urdf"):
            return f.locate()
    raise SystemExit("example-robot-data has no UR5")


def rpy(r, p, y):
    return chasles.SO3.from_rpy([r, p, y]).as_matrix()


def joint_transform(joint, q):
    o = joint.find("origin")
    T = np.eye(4)
    T[:3, :3] = rpy(*map(float, o.get("rpy", "0 0 0").split()))
    T[:3, 3] = [float(x) for x in o.get("xyz", "0 0 0").split()]
    if joint.get("type") in ("revolute", "continuous"):
        axis = np.array([float(x) for x in joint.find("axis").get("xyz").split()])
        R = chasles.SO3.exp(q * axis / np.linalg.norm(axis)).as_matrix()
        T = T @ np.block([[R, np.zeros((3, 1))], [np.zeros((1, 3)), np.ones((1, 1))]])
    return T


def main():
    path = ur5_path()
    arm = chasles.Chain.from_urdf(path, "tool0")
    print(arm)
    for name, kind, lo, hi in zip(arm.joint_names, arm.joint_types, arm.lower, arm.upper):
        print(f"  {name:22s} {kind:10s} [{lo:+.3f}, {hi:+.3f}] rad")
    joints = {j.find("child").get("link"): j for j in ET.parse(path).getroot().findall("joint")}
    chain, link = [], "tool0"
    while link in joints:
        chain.append(joints[link])
        link = joints[link].find("parent").get("link")
    chain.reverse()
    rng = np.random.default_rng(0)
    qs = rng.uniform(np.maximum(arm.lower, -math.pi), np.minimum(arm.upper, math.pi), (1000, arm.n_joints))
    poses = arm.forward(qs)  # one call for the 1000 configurations
    worst = 0.0
    for q, g in zip(qs, poses):
        T, k = np.eye(4), 0
        for j in chain:
            T = T @ joint_transform(j, q[k] if j.get("type") != "fixed" else 0.0)
            k += j.get("type") != "fixed"
        worst = max(worst, np.abs(T - g).max())
    assert worst < 1e-12, worst
    print(f"1000 configurations: forward kinematics within {worst:.1e} of the URDF's transforms")
    mass = arm.link_inertias[:, 0]
    print(f"link masses (kg): {np.array2string(mass, precision=3)}")


if __name__ == "__main__":
    main()
