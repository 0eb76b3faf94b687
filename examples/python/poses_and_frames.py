"""Pose composition and frame changes.

A camera c is mounted on a robot base b, which stands somewhere in the world
w. g_ab is the pose of frame b in frame a: it maps coordinates in b to
coordinates in a (q_a = g_ab @ q_b), and poses compose along the frames,
g_wc = g_wb @ g_bc.

    python examples/python/poses_and_frames.py
"""

import numpy as np

from chasles import SE3, SO3

# The base: 2 m along x and 1 m along y of the world, turned 90 degrees about z.
g_wb = SE3(SO3.exp([0.0, 0.0, np.pi / 2]), [2.0, 1.0, 0.0])
# The camera: 0.5 m up the base's z axis, looking along the base's x axis
# (its optical axis z along the base's x, its x along the base's -y).
R_bc = SO3.from_matrix([[0.0, 0.0, 1.0], [-1.0, 0.0, 0.0], [0.0, -1.0, 0.0]])
g_bc = SE3(R_bc, [0.0, 0.0, 0.5])

g_wc = g_wb @ g_bc  # the camera in the world
print("camera in the world, g_wc =\n", np.round(g_wc.as_matrix(), 6))

# A point seen 3 m in front of the camera, in camera, base and world coordinates.
q_c = np.array([0.0, 0.0, 3.0])
q_b = g_bc @ q_c
q_w = g_wc @ q_c
print("the point in the base frame:", q_b, " in the world:", np.round(q_w, 6))
assert np.allclose(q_b, [3.0, 0.0, 0.5])  # 3 m along the base's x, at the camera's height
assert np.allclose(q_w, g_wb @ q_b)  # the same point, either way round
assert np.allclose(q_w, [2.0, 4.0, 0.5])  # the base's x is the world's y

# Back from the world to the camera with the inverse: g_cw = g_wc^-1.
assert np.allclose(g_wc.inverse() @ q_w, q_c)

# The same compositions on plain 4x4 matrices, as a check: g_wc is the product.
assert np.allclose(g_wc.as_matrix(), g_wb.as_matrix() @ g_bc.as_matrix())

# The pose of a second camera d relative to the first: g_cd = g_wc^-1 g_wd.
g_wd = g_wc @ SE3(SO3.exp([0.0, np.pi / 2, 0.0]), [1.0, 0.0, 3.0])
g_cd = g_wc.inverse() @ g_wd
print("camera d seen from camera c, g_cd =\n", np.round(g_cd.as_matrix(), 6))
assert (g_wc @ g_cd).is_approx(g_wd, 1e-12)
assert np.allclose(g_cd.translation, [1.0, 0.0, 3.0])
# The displacement from c to d as one screw motion (Chasles): g_cd = exp([xi]).
xi = g_cd.log()
assert SE3.exp(xi).is_approx(g_cd, 1e-12)
print("as a twist xi = (v, w):", np.round(xi, 6))
