"""Velocities from a sampled trajectory of poses.

Between two samples g_k and g_k+1, dt apart, the body motion is
g_k^-1 g_k+1 = exp([xi_k]), so xi_k / dt is the constant body twist that
takes g_k to g_k+1 in dt: a finite-difference velocity that stays on SE(3)
(no matrix subtraction). Its error against the true body twist at the
midpoint is O(dt^2). The spatial twist is Ad_g times the body twist.

    python examples/python/twist_from_trajectory.py
"""

import numpy as np

import chasles
from chasles import SE3, Twist

# A trajectory with a known velocity: a screw motion at a constant body twist
# V0, followed by a rotation at a growing rate, g(t) = exp([V0] t) exp([V1] t^2).
V0 = np.array([0.5, 0.0, 0.1, 0.0, 0.0, 0.8])  # (v, w): linear part first
V1 = np.array([0.0, 0.2, 0.0, 0.3, 0.0, 0.0])


def pose(t: np.ndarray) -> np.ndarray:
    """g(t) for every t, shape (N, 4, 4)."""
    t = np.asarray(t)[:, None]
    return chasles.se3_compose(chasles.se3_exp(t * V0), chasles.se3_exp(t**2 * V1))


def body_twist(t: float) -> np.ndarray:
    """The exact body twist (g^-1 g')^vee at t, from the product rule:
    Ad_{exp([V1] t^2)}^-1 V0 + 2 t V1."""
    inner = SE3.exp(t**2 * V1)
    return inner.act_inv(Twist.from_vector(V0)).vector + 2.0 * t * V1


dt = 0.01
times = np.arange(0.0, 2.0 + dt / 2, dt)
G = pose(times)  # (N, 4, 4), e.g. from a motion-capture system

# One batched call each: the relative motions and their logs.
relative = chasles.se3_compose(chasles.se3_inverse(G[:-1]), G[1:])
body = chasles.se3_log(relative) / dt  # (N - 1, 6): body twists between samples

midpoints = times[:-1] + dt / 2
exact = np.array([body_twist(t) for t in midpoints])
error = np.max(np.abs(body - exact))
print(f"{len(body)} body twists from {len(G)} poses, dt = {dt}")
print("at t = 1.0: finite difference", np.round(body[100], 5))
print("            exact at t + dt/2", np.round(exact[100], 5))
print(f"worst error over the trajectory: {error:.2e} (O(dt^2) = {dt**2:.0e})")
assert error < dt**2

# The constant part alone is recovered exactly (to rounding): no O(dt) bias.
G0 = chasles.se3_exp(times[:, None] * V0)
constant = chasles.se3_log(chasles.se3_compose(chasles.se3_inverse(G0[:-1]), G0[1:])) / dt
assert np.allclose(constant, V0, atol=1e-12, rtol=0)

# The spatial twists, from g_k+1 g_k^-1 = exp([xi_k^s]), are the body ones
# moved by the adjoint: g_k exp([xi]) g_k^-1 = exp([Ad_g_k xi]), so V^s = Ad_g V^b.
spatial = chasles.se3_log(chasles.se3_compose(G[1:], chasles.se3_inverse(G[:-1]))) / dt
assert np.allclose(spatial, chasles.se3_act_twist(G[:-1], body), atol=1e-12, rtol=0)
print("speed of the body origin at t = 1.0 (m/s):", round(float(np.linalg.norm(body[100, :3])), 5))
