"""Forward kinematics of a SCARA arm by the product of exponentials.

Joints (screws at the home configuration, in the base frame, (v, w)):
revolute about z through the base, revolute about z at distance l1,
prismatic along -z (the quill), revolute about z at distance l1 + l2 (the
wrist). g(theta) = exp([S_1] th_1) ... exp([S_4] th_4) M, checked against
the arm's closed form and its space Jacobian against finite differences.

    python examples/python/arm_kinematics.py
"""

import numpy as np

import chasles
from chasles import SE3, Chain

l1, l2, h = 0.4, 0.3, 0.5  # link lengths and the tool's height at home (m)
z = [0.0, 0.0, 1.0]
screws = [
    Chain.revolute_screw([0.0, 0.0, 0.0], z),
    Chain.revolute_screw([l1, 0.0, 0.0], z),
    Chain.prismatic_screw([0.0, 0.0, -1.0]),
    Chain.revolute_screw([l1 + l2, 0.0, 0.0], z),
]
home = SE3(translation=[l1 + l2, 0.0, h])  # the tool frame at theta = 0
arm = Chain(screws, home)

theta = np.array([0.3, -0.8, 0.1, 1.2])
g = SE3.from_matrix(arm.forward(theta))  # forward is an array function: a 4x4 matrix
print("tool pose at theta =", theta, "\n", np.round(g.as_matrix(), 6))

# The closed form of a SCARA: planar 2R position, the quill's depth, and a
# rotation about z by the sum of the revolute angles.
t1, t2, d3, t4 = theta
x = l1 * np.cos(t1) + l2 * np.cos(t1 + t2)
y = l1 * np.sin(t1) + l2 * np.sin(t1 + t2)
assert np.allclose(g.translation, [x, y, h - d3], atol=1e-14)
a = t1 + t2 + t4
Rz = np.array([[np.cos(a), -np.sin(a), 0.0], [np.sin(a), np.cos(a), 0.0], [0.0, 0.0, 1.0]])
assert np.allclose(g.rotation.as_matrix(), Rz, atol=1e-14)

# The space Jacobian maps joint speeds to the spatial twist (g' g^-1)^vee.
theta_dot = np.array([0.2, -0.1, 0.05, 0.3])
J = arm.jacobian_space(theta)  # (6, 4), rows (v, w)
eps = 1e-6
g_plus = SE3.from_matrix(arm.forward(theta + eps * theta_dot))
g_minus = SE3.from_matrix(arm.forward(theta - eps * theta_dot))
numeric = (g_plus @ g_minus.inverse()).log() / (2 * eps)  # log(g(t+e) g(t-e)^-1) / 2e
print("spatial twist J_s theta' =", np.round(J @ theta_dot, 6))
assert np.allclose(J @ theta_dot, numeric, atol=1e-8)

# A batch of configurations in one call: the reachable annulus of the 2R part.
rng = np.random.default_rng(0)
thetas = rng.uniform(-np.pi, np.pi, size=(10_000, 4))
poses = arm.forward(thetas)  # (10000, 4, 4)
radius = np.hypot(poses[:, 0, 3], poses[:, 1, 3])
print(f"10000 configurations: the tool stays between {radius.min():.3f} and {radius.max():.3f} m")
assert np.all(radius <= l1 + l2 + 1e-12) and np.all(radius >= abs(l1 - l2) - 1e-12)
assert np.array_equal(poses[0], arm.forward(thetas[0]))
# The body form gives the same poses.
assert np.allclose(chasles.se3_inverse(poses[:5]) @ arm.forward_body(thetas[:5]), np.eye(4), atol=1e-13)
