"""Averaging noisy poses, then a smooth trajectory through the averages.

Five true key poses at known times are each measured 50 times with Gaussian
noise: g = g_true exp([L z]), z standard normal, L L^T = COV, the covariance
of the twist log(g_true^-1 g) (right perturbation, twist order (v, w)). The
geodesic mean M of each batch solves sum_i log(M^-1 g_i) = 0 (the
bi-invariant barycenter; its error shrinks as 1/sqrt(50) against one
measurement's). Through the five means:

- SE3Spline: the interpolating C2 spline, X(t) = X_i exp(r(t - t_i)) with
  r a cubic, through every mean, with analytic body velocity and
  acceleration;
- SE3BSpline: the uniform cumulative cubic B-spline with the five means as
  its control poses, X_k placed at time t_k (start time t_1, knot spacing
  1 s, so it is defined on [t_1, t_3]). It smooths: at t_k it is near the
  weighted average (X_{k-1} + 4 X_k + X_{k+1}) / 6, not at X_k.

    python examples/python/average_and_spline.py
"""

import numpy as np

import chasles
from chasles import SE3

# The truth: g(t) = exp([V0] t) exp([V1] t^2), key poses at t = 0, 1, 2, 3, 4 s.
V0 = np.array([0.4, 0.0, 0.05, 0.0, 0.0, 0.3])  # (v, w): linear part first
V1 = np.array([0.0, 0.02, 0.0, 0.02, 0.0, 0.0])
times = np.arange(5.0)
truth = chasles.se3_compose(chasles.se3_exp(times[:, None] * V0), chasles.se3_exp(times[:, None] ** 2 * V1))

# The noise: 2 cm per axis in position, 0.05 rad (2.9 deg) per axis in rotation.
SIGMA_P, SIGMA_R = 0.02, 0.05
COV = np.diag([SIGMA_P**2] * 3 + [SIGMA_R**2] * 3)
N = 50
rng = np.random.default_rng(2024)  # a fixed seed: the same numbers every run

print(f"{N} noisy measurements per key pose (sigma {SIGMA_P} m, {SIGMA_R} rad per axis);")
print("errors against the truth:")
print("   t |  mean: angle (rad)  position (m) |  one measurement: angle  position")
means = np.empty_like(truth)
errors_mean, errors_one = [], []
for k, t in enumerate(times):
    measured = chasles.se3_gaussian(truth[k], COV, N, rng=rng)  # (50, 4, 4)
    means[k] = chasles.se3_mean(measured)  # geodesic (Karcher) mean, Newton's method
    e_mean = chasles.se3_distance(truth[k], means[k])  # (angle, translation distance)
    e_one = chasles.se3_distance(truth[k], measured[0])
    errors_mean.append(e_mean)
    errors_one.append(e_one)
    print(
        f"{t:4.1f} |         {e_mean[0]:.4f}        {e_mean[1]:.4f} |                  {e_one[0]:.4f}    {e_one[1]:.4f}"
    )
errors_mean, errors_one = np.array(errors_mean), np.array(errors_one)
# The mean's tangent error has the covariance COV / N: per axis sigma / sqrt(N),
# so its norm stays below 4 sqrt(3) sigma / sqrt(N) (a 4-sigma bound per axis).
assert np.all(errors_mean[:, 0] < 4 * np.sqrt(3) * SIGMA_R / np.sqrt(N))
assert np.all(errors_mean[:, 1] < 4 * np.sqrt(3) * SIGMA_P / np.sqrt(N))
assert np.all(errors_mean.mean(axis=0) < errors_one.mean(axis=0))
print(
    f"average over the keys: mean {errors_mean[:, 0].mean():.4f} rad "
    f"{errors_mean[:, 1].mean():.4f} m, one measurement {errors_one[:, 0].mean():.4f} rad "
    f"{errors_one[:, 1].mean():.4f} m (expected ratio sqrt({N}) = {np.sqrt(N):.1f})"
)

# The interpolating spline through the means (natural ends: zero acceleration at t_0 and t_4).
spline = chasles.SE3Spline(times, means)
through = chasles.se3_distance(spline(times), means)  # (5, 2)
print(f"the spline passes through the means: worst {through[:, 0].max():.1e} rad, {through[:, 1].max():.1e} m")
assert np.all(through < 1e-12)


def fixed(x, digits):
    """A vector with a fixed number of digits and a space for the sign."""
    return np.array2string(x, precision=digits, floatmode="fixed", sign=" ")


def table(name, curve, at):
    """Position, body velocity (v, w) and body acceleration at the times `at`."""
    g, V, A = curve(at), curve.body_velocity(at), curve.body_acceleration(at)
    print(f"{name}:")
    print(f"   t | {'position (m)':^22} | {'body velocity v (m/s), w (rad/s)':^43} | body acceleration (/s^2)")
    for t, gk, Vk, Ak in zip(at, g, V, A):
        print(f"{t:4.2f} | {fixed(gk[:3, 3], 3)} | {fixed(Vk, 3)} | {fixed(Ak, 2)}")
    # The body velocity is (g^-1 dg/dt)^vee: check it against a central
    # difference on the group, log(g(t - h)^-1 g(t + h)) / (2 h), error O(h^2)
    # (the times stay h inside the B-spline's [t_1, t_3]: it is not extrapolated).
    h = 1e-4
    relative = chasles.se3_compose(chasles.se3_inverse(curve(at - h)), curve(at + h))
    fd = chasles.se3_log(relative) / (2 * h)
    assert np.allclose(V, fd, atol=1e-6, rtol=0), np.abs(V - fd).max()


table("interpolating spline (SE3Spline) through the means", spline, np.array([0.5, 1.0, 2.0, 2.5, 3.5]))
# The truth's body twist, Ad_{exp([V1] t^2)}^-1 V0 + 2 t V1, at t = 2 for comparison.
exact = SE3.exp(4.0 * V1).act_inv(chasles.Twist.from_vector(V0)).vector + 4.0 * V1
print(f"(the true body twist at t = 2.0: {fixed(exact, 3)})")

# The B-spline: the means are its control poses, X_k at time t_k. With start
# time t_1 and spacing 1 s its segments run over [t_1, t_2] (controls X_0..X_3)
# and [t_2, t_3] (X_1..X_4).
bspline = chasles.SE3BSpline(times[1], 1.0, means)
table("cumulative B-spline (SE3BSpline), the means as control poses", bspline, np.array([1.25, 1.5, 2.0, 2.5, 2.75]))
off = chasles.se3_distance(bspline(times[1:4]), means[1:4])
print(f"the B-spline smooths: at t_1, t_2, t_3 it is {off[:, 1].max():.3f} m at most from the means, not on them")
