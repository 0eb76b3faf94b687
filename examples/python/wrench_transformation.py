"""Moving a wrench from a force sensor to a tool tip, and why power checks it.

A force-torque sensor s measures the wrench F_s = (f, tau) (force first) in its
own frame. The tool tip t sits at g_st (the pose of t in s). The same physical
wrench in the tool frame is F_t = Ad_{g_st}^T F_s (``g_st.act_inv(F_s)``):
wrenches change frame by the transpose of the adjoint, not by the adjoint as
twists do, and that is what keeps the power V . F the same in every frame.

    python examples/python/wrench_transformation.py
"""

import numpy as np

from chasles import SE3, SO3, Twist, Wrench

# The tool tip is 0.2 m along the sensor's z axis, turned 30 degrees about it.
g_st = SE3(SO3.exp([0.0, 0.0, np.pi / 6]), [0.0, 0.0, 0.2])

# The tip pushes sideways on a surface: the surface pushes back on the tip with
# 5 N along the tool's x axis and no torque at the tip. The sensor, 0.2 m
# away, reads that force and its moment.
F_t_true = Wrench(f=[5.0, 0.0, 0.0], tau=[0.0, 0.0, 0.0])
F_s = g_st.act(F_t_true)  # what the sensor measures: Ad_{g_st}^-T F_t
print("sensor reading (f, tau):", np.round(F_s.vector, 6))
f_s = g_st.rotation @ [5.0, 0.0, 0.0]
assert np.allclose(F_s.torque, np.cross([0.0, 0.0, 0.2], f_s))  # tau = p x f

# From the reading back to the tool frame.
F_t = g_st.act_inv(F_s)
print("at the tool tip (f, tau):", np.round(F_t.vector, 6))
assert F_t.is_approx(F_t_true, 1e-12)

# Power invariance: any velocity of the tool, written in either frame, does
# the same work on the wrench.
rng = np.random.default_rng(0)
for _ in range(5):
    V_t = Twist.from_vector(rng.normal(size=6))  # a tool velocity (v, w), tool frame
    V_s = g_st.act(V_t)  # the same velocity in the sensor frame: Ad_{g_st} V_t
    assert np.isclose(V_s.power(F_s), V_t.power(F_t), rtol=1e-12, atol=1e-12)
print("power V . F is the same in both frames:", round(V_s.power(F_s), 9), "W")

# Mixing the two laws up (moving the wrench with the adjoint, as if it were a
# twist) gives a wrong torque at the tip and breaks the power balance.
wrong = Wrench.from_vector(g_st.inverse().adjoint() @ F_s.vector)
print("with the twist law instead, the tip torque would be", np.round(wrong.torque, 6))
assert not wrong.is_approx(F_t_true, 1e-3)

# The screw of the wrench (Poinsot): a pure force along a line through the tip.
screw = F_s.screw()
print("line of action through", np.round(screw.point, 6), "along", np.round(screw.direction, 6))
assert np.isclose(screw.pitch, 0.0, atol=1e-12)
assert np.allclose(np.cross(screw.point - [0.0, 0.0, 0.2], screw.direction), 0.0, atol=1e-12)
