"""The generic families of SO2, SE2, Sim3 and SE23 (issue 23): means
(so2_mean, ...), distances (so2_distance, ...) and random samples
(so2_random, so2_gaussian, ...), parametrized over the groups and checked
against references computed here with numpy and scipy from the matrices
(scipy.linalg's expm / logm, SVD projections, per-part formulas), not with
the functions under test."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import chasles

linalg = pytest.importorskip("scipy.linalg")
stats = pytest.importorskip("scipy.stats")

GROUPS = ("so2", "se2", "sim3", "se23")
N = {"so2": 2, "se2": 3, "sim3": 4, "se23": 5}
DOF = {"so2": 1, "se2": 3, "sim3": 7, "se23": 9}


def skew3(w):
    return np.array([[0.0, -w[2], w[1]], [w[2], 0.0, -w[0]], [-w[1], w[0], 0.0]])


def hat(group: str, x) -> np.ndarray:
    """The Lie algebra matrix of a tangent, from the layouts of the issue."""
    x = np.atleast_1d(np.asarray(x, dtype=float))
    if group == "so2":
        return np.array([[0.0, -x[0]], [x[0], 0.0]])
    M = np.zeros((N[group], N[group]))
    if group == "se2":
        M[:2, :2] = [[0.0, -x[2]], [x[2], 0.0]]
        M[:2, 2] = x[:2]
    elif group == "sim3":
        M[:3, :3] = skew3(x[3:6]) + x[6] * np.eye(3)
        M[:3, 3] = x[:3]
    else:  # se23: (rho, nu, w)
        M[:3, :3] = skew3(x[6:9])
        M[:3, 3] = x[:3]
        M[:3, 4] = x[3:6]
    return M


def vee(group: str, M) -> np.ndarray:
    if group == "so2":
        return np.array([M[1, 0]])
    if group == "se2":
        return np.array([M[0, 2], M[1, 2], M[1, 0]])
    w = np.array([M[2, 1], M[0, 2], M[1, 0]])
    if group == "sim3":
        return np.concatenate([M[:3, 3], w, [np.trace(M[:3, :3]) / 3]])
    return np.concatenate([M[:3, 3], M[:3, 4], w])


def expm(group, x):
    return np.real(linalg.expm(hat(group, x)))


def logm(group, M):
    return vee(group, np.real(linalg.logm(M)))


def cloud(group: str, n: int, spread: float, seed: int, center=None) -> np.ndarray:
    """n elements exp(x_i) about `center` (x_i normal, `spread` per
    coordinate), built with scipy's expm."""
    rng = np.random.default_rng(seed)
    c = np.eye(N[group]) if center is None else center
    return np.stack([c @ expm(group, spread * rng.standard_normal(DOF[group])) for _ in range(n)])


def random_element(group: str, seed: int) -> np.ndarray:
    rng = np.random.default_rng(seed)
    return expm(group, rng.uniform(-1.0, 1.0, DOF[group]))


def karcher_reference(group: str, X, w) -> np.ndarray:
    """The Karcher mean by the plain fixed-point (gradient) iteration in
    scipy's logm / expm: M <- M expm(sum_i w_i logm(M^-1 X_i) / sum_i w_i),
    from X_0, until the step is below 1e-14."""
    M = X[0].copy()
    for _ in range(500):
        step = sum(wi * logm(group, np.linalg.solve(M, Xi)) for wi, Xi in zip(w, X)) / np.sum(w)
        M = M @ expm(group, step)
        if np.linalg.norm(step) < 1e-13:
            break
    return M


def nearest_rotation(S):
    """The rotation nearest to S (Frobenius), by the SVD."""
    U, _, Vt = np.linalg.svd(S)
    D = np.eye(len(S))
    D[-1, -1] = np.sign(np.linalg.det(U @ Vt))
    return U @ D @ Vt


def parts(group: str, X):
    """(R, Euclidean vector) per element, read from the matrices."""
    X = np.asarray(X)
    if group == "so2":
        return X, np.zeros(X.shape[:-2] + (0,))
    if group == "se2":
        return X[..., :2, :2], X[..., :2, 2]
    if group == "sim3":
        s = np.cbrt(np.linalg.det(X[..., :3, :3]))
        return X[..., :3, :3] / s[..., None, None], np.concatenate([X[..., :3, 3], np.log(s)[..., None]], -1)
    return X[..., :3, :3], np.concatenate([X[..., :3, 3], X[..., :3, 4]], -1)


def chordal_reference(group: str, X, w) -> np.ndarray:
    R, v = parts(group, X)
    Rm = nearest_rotation(np.einsum("i,ijk->jk", w, R))
    vm = np.einsum("i,ij->j", w, v) / np.sum(w)
    M = np.eye(N[group])
    if group == "so2":
        return Rm
    if group == "se2":
        M[:2, :2], M[:2, 2] = Rm, vm
    elif group == "sim3":
        M[:3, :3], M[:3, 3] = np.exp(vm[3]) * Rm, vm[:3]
    else:
        M[:3, :3], M[:3, 3], M[:3, 4] = Rm, vm[:3], vm[3:]
    return M


def mean_of(group):
    return getattr(chasles, f"{group}_mean")


# ---- means --------------------------------------------------------------------


@pytest.mark.parametrize("group", GROUPS)
@pytest.mark.parametrize("spread", [0.05, 0.5])
def test_geodesic_mean_is_the_karcher_mean_of_a_reference_iteration(group, spread):
    X = cloud(group, 12, spread, seed=1, center=random_element(group, 2))
    w = np.random.default_rng(3).uniform(0.1, 2.0, len(X))
    info = mean_of(group)(X, w, return_info=True)
    assert info.converged and info.mean.shape == (N[group], N[group])
    ref = karcher_reference(group, X, w)
    np.testing.assert_allclose(info.mean, ref, rtol=0, atol=1e-10)
    # and it solves the Karcher equation, in scipy's logm
    residual = sum(wi * logm(group, np.linalg.solve(info.mean, Xi)) for wi, Xi in zip(w, X))
    assert np.abs(residual).max() < 1e-10


@pytest.mark.parametrize("group", GROUPS)
def test_chordal_mean_is_the_per_part_closed_form(group):
    X = cloud(group, 15, 0.6, seed=4, center=random_element(group, 5))
    w = np.random.default_rng(6).uniform(0.0, 3.0, len(X))
    got = mean_of(group)(X, w, method="chordal")
    np.testing.assert_allclose(got, chordal_reference(group, X, w), rtol=0, atol=1e-12)


def test_so2_means_are_the_circular_and_arithmetic_means_of_the_angles():
    rng = np.random.default_rng(7)
    t = 2.5 + rng.uniform(-0.6, 0.6, 40)  # an arc about 2.5, away from the cut at pi
    w = rng.uniform(0.5, 1.5, 40)
    R = chasles.so2_exp(t)
    geodesic = chasles.so2_log(chasles.so2_mean(R, w))
    chordal = chasles.so2_log(chasles.so2_mean(R, w, method="chordal"))
    assert abs(geodesic - np.sum(w * t) / np.sum(w)) < 1e-13
    assert abs(chordal - np.arctan2(np.sum(w * np.sin(t)), np.sum(w * np.cos(t)))) < 1e-13
    # the two differ at this spread: each check tells them apart
    assert abs(geodesic - chordal) > 1e-5


def test_se23_chordal_mean_averages_positions_and_velocities():
    X = cloud("se23", 30, 0.4, seed=8)
    got = chasles.se23_mean(X, method="chordal")
    np.testing.assert_allclose(got[:3, 3], X[:, :3, 3].mean(0), rtol=0, atol=1e-14)
    np.testing.assert_allclose(got[:3, 4], X[:, :3, 4].mean(0), rtol=0, atol=1e-14)
    np.testing.assert_allclose(got[3:], np.eye(5)[3:], rtol=0, atol=0)


def test_sim3_chordal_scale_is_the_weighted_geometric_mean():
    X = cloud("sim3", 20, 0.5, seed=9)
    w = np.random.default_rng(10).uniform(0.1, 1.0, 20)
    s = np.cbrt(np.linalg.det(X[:, :3, :3]))
    got = chasles.sim3_mean(X, w, method="chordal")
    assert abs(np.cbrt(np.linalg.det(got[:3, :3])) - np.exp(np.sum(w * np.log(s)) / np.sum(w))) < 1e-13


@pytest.mark.parametrize("group", GROUPS)
def test_geodesic_mean_is_invariant_on_both_sides(group):
    X = cloud(group, 10, 0.4, seed=11)
    a, b = random_element(group, 12), random_element(group, 13)
    M = mean_of(group)(X)
    np.testing.assert_allclose(mean_of(group)(a @ X @ b), a @ M @ b, rtol=0, atol=1e-11)


@pytest.mark.parametrize("group", GROUPS)
def test_chordal_mean_is_invariant_on_the_left(group):
    X = cloud(group, 10, 0.4, seed=14)
    a = random_element(group, 15)
    M = mean_of(group)(X, method="chordal")
    np.testing.assert_allclose(mean_of(group)(a @ X, method="chordal"), a @ M, rtol=0, atol=1e-12)


@pytest.mark.parametrize("group", GROUPS)
def test_mean_info_and_warning(group):
    X = cloud(group, 50, 0.5, seed=16)
    short = mean_of(group)(X, max_iterations=1, return_info=True)
    assert short.converged is False and short.iterations == 1
    with pytest.warns(RuntimeWarning, match=rf"{group}_mean: the geodesic mean did not converge in 1 iterations"):
        mean_of(group)(X, max_iterations=1)
    chordal = mean_of(group)(X, method="chordal", return_info=True)
    assert chordal.converged is True and chordal.iterations == 0


@pytest.mark.parametrize("group", GROUPS)
def test_mean_refusals_name_the_function_and_the_shapes(group):
    n = N[group]
    mean = mean_of(group)
    with pytest.raises(ValueError, match=rf"^{group}_mean\(matrices\): expected shape \(N, {n}, {n}\) with N >= 1, "):
        mean(np.eye(n + 1)[None])
    with pytest.raises(ValueError, match=rf"^{group}_mean\(weights\): expected shape \(2,\), got \(3,\)$"):
        mean(np.stack([np.eye(n)] * 2), [1.0, 1.0, 1.0])
    bad = np.stack([np.eye(n), np.eye(n)])
    bad[1, 0, 0] = 1.5 if group != "sim3" else -2.0  # not an element (Sim3: a reflection)
    cls = {"so2": "SO2", "se2": "SE2", "sim3": "Sim3", "se23": "SE23"}[group]
    with pytest.raises(
        ValueError, match=rf"^{group}_mean\(matrices\): element 1 is not a .*{cls}.from_matrix_projected"
    ):
        mean(bad)
    with pytest.raises(ValueError, match=rf"^{group}_mean\(weights\): expected weights >= 0, got weights\[0\] = -1.0"):
        mean(np.stack([np.eye(n)] * 2), [-1.0, 1.0])
    with pytest.raises(ValueError, match=rf"^_{group}_mean\(weights\): expected finite weights >= 0, not all 0$"):
        getattr(chasles._core, f"_{group}_mean")(np.stack([np.eye(n)] * 2), np.zeros(2), True, 20)


# ---- distances ----------------------------------------------------------------


def rotation_angle(R) -> np.ndarray:
    """The angle of rotation matrices (2x2 or 3x3), by atan2 of the sine
    (the axial part) and the cosine (the trace), in long double."""
    R = np.asarray(R, dtype=np.longdouble)
    if R.shape[-1] == 2:
        return np.abs(np.arctan2(R[..., 1, 0] - R[..., 0, 1], R[..., 0, 0] + R[..., 1, 1]))
    axial = 0.5 * np.stack([R[..., 2, 1] - R[..., 1, 2], R[..., 0, 2] - R[..., 2, 0], R[..., 1, 0] - R[..., 0, 1]], -1)
    return np.arctan2(np.linalg.norm(axial.astype(float), axis=-1), (np.trace(R, axis1=-2, axis2=-1) - 1) / 2)


def distance_reference(group, a, b) -> np.ndarray:
    Ra, va = parts(group, a)
    Rb, vb = parts(group, b)
    angle = rotation_angle(np.swapaxes(Ra, -1, -2) @ Rb).astype(float)
    if group == "so2":
        return angle
    d = vb - va
    if group == "se2":
        blocks = [np.linalg.norm(d, axis=-1)]
    elif group == "sim3":
        blocks = [np.linalg.norm(d[..., :3], axis=-1), np.abs(d[..., 3])]
    else:
        blocks = [np.linalg.norm(d[..., :3], axis=-1), np.linalg.norm(d[..., 3:], axis=-1)]
    return np.stack([angle] + blocks, -1)


OUT = {"so2": (), "se2": (2,), "sim3": (3,), "se23": (3,)}


@pytest.mark.parametrize("group", GROUPS)
def test_distance_matches_numpy_from_the_matrices(group):
    rng = np.random.default_rng(17)
    a = np.stack([expm(group, rng.uniform(-2, 2, DOF[group])) for _ in range(50)])
    b = np.stack([expm(group, rng.uniform(-2, 2, DOF[group])) for _ in range(50)])
    d = getattr(chasles, f"{group}_distance")(a, b)
    assert d.shape == (50,) + OUT[group] and d.dtype == np.float64
    np.testing.assert_allclose(d, distance_reference(group, a, b), rtol=1e-13, atol=1e-14)
    # broadcasting one against many, symmetric, zero on the diagonal
    np.testing.assert_allclose(
        getattr(chasles, f"{group}_distance")(a[0], b), distance_reference(group, a[0], b), atol=1e-14
    )
    np.testing.assert_allclose(getattr(chasles, f"{group}_distance")(b, a), d, rtol=0, atol=1e-14)
    assert np.all(getattr(chasles, f"{group}_distance")(a, a) <= 1e-15)


@pytest.mark.parametrize("group", GROUPS)
def test_distance_float32_loop(group):
    rng = np.random.default_rng(18)
    a = np.stack([expm(group, rng.uniform(-2, 2, DOF[group])) for _ in range(20)])
    b = np.stack([expm(group, rng.uniform(-2, 2, DOF[group])) for _ in range(20)])
    a32, b32 = a.astype(np.float32), b.astype(np.float32)
    d = getattr(chasles, f"{group}_distance")(a32, b32)
    assert d.dtype == np.float32
    np.testing.assert_allclose(d, distance_reference(group, a32.astype(float), b32.astype(float)), rtol=0, atol=2e-6)


@pytest.mark.parametrize("group", GROUPS)
def test_distance_is_invariant_under_a_rigid_change_of_the_fixed_frame(group):
    rng = np.random.default_rng(19)
    x = rng.uniform(-1, 1, DOF[group])
    if group == "sim3":
        x[6] = 0.0  # a rigid motion: the distances of Sim3 scale with a scaling
    g = expm(group, x)
    a, b = cloud(group, 10, 1.0, seed=20), cloud(group, 10, 1.0, seed=21)
    f = getattr(chasles, f"{group}_distance")
    np.testing.assert_allclose(f(g @ a, g @ b), f(a, b), rtol=1e-12, atol=1e-13)


@settings(max_examples=40, deadline=None)
@given(t=st.floats(-3.14159, 3.14159), u=st.floats(-3.14159, 3.14159))
def test_so2_distance_is_the_wrapped_difference_of_the_angles(t, u):
    d = chasles.so2_distance(chasles.so2_exp(t), chasles.so2_exp(u))
    expected = abs((u - t + np.pi) % (2 * np.pi) - np.pi)
    assert abs(d - expected) <= 4e-15


# ---- random samples -----------------------------------------------------------


def test_so2_random_angles_are_uniform():
    R = chasles.so2_random(20000, rng=1)
    assert R.shape == (20000, 2, 2)
    t = np.arctan2(R[:, 1, 0], R[:, 0, 0])
    assert stats.kstest(t, stats.uniform(-np.pi, 2 * np.pi).cdf).pvalue > 1e-3
    # the check can fail: angles squeezed to [-pi/2, pi/2) are rejected
    assert stats.kstest(t / 2, stats.uniform(-np.pi, 2 * np.pi).cdf).pvalue < 1e-6


def haar_so3_cdf(t):
    return (t - np.sin(t)) / np.pi


@pytest.mark.parametrize("group", ["sim3", "se23"])
def test_rotations_of_the_3d_groups_are_haar(group):
    X = getattr(chasles, f"{group}_random")(20000, rng=2)
    R, _ = parts(group, X)
    assert stats.kstest(rotation_angle(R).astype(float), haar_so3_cdf).pvalue > 1e-3


def test_se2_random_rotation_is_uniform_and_translation_in_the_box():
    lo, hi = np.array([-2.0, 0.5]), np.array([1.0, 0.75])
    g = chasles.se2_random(20000, rng=3, low=lo, high=hi)
    assert g.shape == (20000, 3, 3)
    np.testing.assert_array_equal(g[:, 2], np.broadcast_to([0.0, 0.0, 1.0], (20000, 3)))
    t = g[:, :2, 2]
    assert np.all((t >= lo) & (t <= hi))
    for k in range(2):
        assert stats.kstest(t[:, k], stats.uniform(lo[k], hi[k] - lo[k]).cdf).pvalue > 1e-3
    angle = np.arctan2(g[:, 1, 0], g[:, 0, 0])
    assert stats.kstest(angle, stats.uniform(-np.pi, 2 * np.pi).cdf).pvalue > 1e-3


def test_sim3_random_scale_is_log_uniform_and_translation_in_the_box():
    X = chasles.sim3_random(20000, rng=4, low=[0.0, -1.0, 2.0], high=[1.0, 1.0, 3.0], scale_low=0.25, scale_high=4.0)
    R, v = parts("sim3", X)
    assert np.all((v[:, :3] >= [0.0, -1.0, 2.0]) & (v[:, :3] <= [1.0, 1.0, 3.0]))
    s = np.exp(v[:, 3])
    assert np.all((s >= 0.25 * (1 - 1e-14)) & (s <= 4.0 * (1 + 1e-14)))
    assert stats.kstest(v[:, 3], stats.uniform(np.log(0.25), np.log(16.0)).cdf).pvalue > 1e-3
    np.testing.assert_allclose(np.swapaxes(R, -1, -2) @ R, np.broadcast_to(np.eye(3), R.shape), atol=1e-14)
    # a fixed scale
    assert np.allclose(
        np.cbrt(np.linalg.det(chasles.sim3_random(5, rng=0, scale_low=2.0, scale_high=2.0)[:, :3, :3])), 2.0
    )


def test_se23_random_position_and_velocity_in_their_boxes():
    X = chasles.se23_random(
        20000, rng=5, low=-0.5, high=0.5, velocity_low=[1.0, 2.0, 3.0], velocity_high=[2.0, 3.0, 4.0]
    )
    p, v = X[:, :3, 3], X[:, :3, 4]
    assert np.all((p >= -0.5) & (p <= 0.5))
    assert np.all((v >= [1.0, 2.0, 3.0]) & (v <= [2.0, 3.0, 4.0]))
    for k in range(3):
        assert stats.kstest(v[:, k], stats.uniform(1.0 + k, 1.0).cdf).pvalue > 1e-3
    np.testing.assert_array_equal(X[:, 3:], np.broadcast_to(np.eye(5)[3:], (20000, 2, 5)))


@pytest.mark.parametrize("group", GROUPS)
def test_random_is_the_map_of_the_generators_uniforms(group):
    """A seed gives the same samples; the samples are the C++ map of the
    Generator's uniforms, rotation first (so2: the angle pi (2u - 1))."""
    f = getattr(chasles, f"{group}_random")
    a = f(6, rng=42)
    np.testing.assert_array_equal(a, f(6, rng=np.random.default_rng(42)))
    assert f(rng=1).shape == (N[group], N[group]) and f((2, 3), rng=1).shape == (2, 3, N[group], N[group])
    u = np.random.default_rng(42).random((6, 1 if group in ("so2", "se2") else 3))
    R, _ = parts(group, a)
    if group in ("so2", "se2"):
        np.testing.assert_allclose(np.arctan2(R[:, 1, 0], R[:, 0, 0]), np.pi * (2 * u[:, 0] - 1), rtol=0, atol=1e-14)
    else:
        np.testing.assert_allclose(R, chasles.so3_from_uniforms(u), rtol=0, atol=1e-14)


@pytest.mark.parametrize(
    "call, error, fragment",
    [(lambda: chasles.se2_random(low=[0, 0, 0]), ValueError,
      r"se2_random\(low\): expected shape \(\) or \(2,\), got \(3,\)"),
     (lambda: chasles.se2_random(low=1.0, high=0.0), ValueError, r"se2_random: expected low <= high"),
     (lambda: chasles.sim3_random(scale_low=0.0), ValueError, r"sim3_random\(scale_low\): expected a scale > 0"),
     (lambda: chasles.sim3_random(scale_low=3.0), ValueError, r"sim3_random: expected scale_low <= scale_high"),
     (lambda: chasles.se23_random(velocity_high=[1, 2]), ValueError,
      r"se23_random\(velocity_high\): expected shape \(\) or \(3,\), got \(2,\)"),
     (lambda: chasles.se23_random(speed=1.0), TypeError, r"se23_random\(\) got an unexpected keyword argument 'speed'"),
     (lambda: chasles.so2_random(-1), ValueError, r"so2_random\(n\): expected a size >= 0"),
     (lambda: chasles.so2_gaussian(np.eye(2), np.eye(2)), ValueError, r"so2_gaussian\(cov\): expected shape \(1, 1\)"),
     (lambda: chasles.se2_gaussian(2 * np.eye(3), np.eye(3)), ValueError, r"se2_gaussian\(mean\): "),
     (lambda: chasles.sim3_gaussian(np.eye(4), -np.eye(7)), ValueError, r"sim3_gaussian\(cov\): expected a positive"),
     (lambda: chasles.se23_gaussian(np.eye(4), np.eye(9)), ValueError,
      r"se23_gaussian\(mean\): expected shape \(5, 5\)")],
)  # fmt: skip
def test_sampler_refusals_name_the_argument(call, error, fragment):
    with pytest.raises(error, match=fragment):
        call()


def random_covariance(dof: int, seed: int) -> np.ndarray:
    rng = np.random.default_rng(seed)
    A = rng.standard_normal((dof, dof))
    C = A @ A.T + 0.5 * np.eye(dof)
    return 0.01 * C / np.abs(C).max()  # small: every sample stays within log's domain


@pytest.mark.parametrize("group", GROUPS)
def test_gaussian_tangent_covariance_is_cov(group):
    """The right perturbation: log(mean^-1 X) (by scipy's logm of one in
    every 100, and all of them by the group's log) has the covariance cov.
    Each sample covariance entry S_ij of n samples has the standard
    deviation sqrt((C_ii C_jj + C_ij^2) / n); 5 of them is the tolerance (a
    false alarm about once in 1.7e6 per entry)."""
    n = 100_000
    dof = DOF[group]
    C = random_covariance(dof, 22)
    mean = random_element(group, 23)
    X = getattr(chasles, f"{group}_gaussian")(mean, C, n, rng=24)
    assert X.shape == (n, N[group], N[group])
    E = np.linalg.solve(mean, X)
    e = getattr(chasles, f"{group}_log")(E).reshape(n, dof)
    for i in range(0, n, 10_000):
        np.testing.assert_allclose(e[i], logm(group, E[i]), rtol=0, atol=1e-12)
    S = e.T @ e / n  # the mean is 0: not subtracted
    sigma = np.sqrt((np.outer(np.diag(C), np.diag(C)) + C**2) / n)
    assert np.all(np.abs(S - C) <= 5 * sigma), np.abs(S - C).max() / sigma.max()
    assert np.all(np.abs(e.mean(0)) <= 5 * np.sqrt(np.diag(C) / n))


@pytest.mark.parametrize("group", GROUPS)
def test_gaussian_accepts_objects_and_a_singular_cov(group):
    cls = getattr(chasles, {"so2": "SO2", "se2": "SE2", "sim3": "Sim3", "se23": "SE23"}[group])
    m = cls.from_matrix(random_element(group, 25))
    C = np.zeros((DOF[group], DOF[group]))
    C[0, 0] = 0.04  # only the first tangent coordinate varies
    X = getattr(chasles, f"{group}_gaussian")(m, C, 200, rng=26)
    e = getattr(chasles, f"{group}_log")(np.linalg.solve(np.asarray(m), X)).reshape(200, DOF[group])
    assert np.all(np.abs(e[:, 1:]) < 1e-12) and 0.1 < e[:, 0].std() < 0.3


# ---- splines ------------------------------------------------------------------


def spline_of(group):
    return getattr(chasles, {"so2": "SO2", "se2": "SE2", "sim3": "Sim3", "se23": "SE23"}[group] + "Spline")


def spline_keys(group, n, seed):
    """n keys a random walk apart (steps of 0.4 per coordinate), by scipy's expm."""
    rng = np.random.default_rng(seed)
    X = [expm(group, rng.uniform(-1, 1, DOF[group]))]
    for _ in range(n - 1):
        X.append(X[-1] @ expm(group, 0.4 * rng.standard_normal(DOF[group])))
    return np.stack(X)


@pytest.mark.parametrize("group", GROUPS)
@pytest.mark.parametrize("ends", ["natural", "chord"])
def test_spline_passes_through_the_keys_and_its_rates_are_the_derivatives(group, ends):
    times = np.array([0.0, 0.7, 1.5, 2.0, 3.2])
    keys = spline_keys(group, 5, 27)
    s = spline_of(group)(times, keys, ends=ends)
    np.testing.assert_allclose(s(times), keys, rtol=0, atol=1e-12)
    np.testing.assert_array_equal(s.keys, keys)
    t = np.array([0.2, 0.69, 1.1, 1.9, 2.6, 3.0])
    h = 1e-5
    X = s(t)
    # the body velocity (X^-1 dX/dt)^vee by central differences of the matrices, in the layout
    dX = (s(t + h) - s(t - h)) / (2 * h)
    V = np.stack([vee(group, np.linalg.solve(Xi, dXi)) for Xi, dXi in zip(X, dX)])
    v = s.body_velocity(t)
    assert v.shape == ((6,) if group == "so2" else (6, DOF[group]))
    np.testing.assert_allclose(v.reshape(6, -1), V, rtol=0, atol=1e-7 * (1 + np.abs(V).max()))
    a = s.body_acceleration(t)
    A = (s.body_velocity(t + h) - s.body_velocity(t - h)) / (2 * h)
    np.testing.assert_allclose(a, A, rtol=0, atol=1e-6 * (1 + np.abs(A).max()))
    if ends == "natural":
        np.testing.assert_allclose(s.body_acceleration(times[[0, -1]]), 0.0, atol=1e-9)


@pytest.mark.parametrize("group", GROUPS)
def test_chord_ends_have_the_rates_of_the_first_and_last_chords(group):
    """ends="chord": the body velocity at the first and the last key is that segment's chord rate,
    log(X_0^-1 X_1) / (t_1 - t_0) and log(X_n-2^-1 X_n-1) / (t_n-1 - t_n-2) (scipy's logm)."""
    times = np.array([0.0, 0.7, 1.5, 2.0, 3.2])
    keys = spline_keys(group, 5, 31)
    s = spline_of(group)(times, keys, ends="chord")
    first = logm(group, np.linalg.solve(keys[0], keys[1])) / (times[1] - times[0])
    last = logm(group, np.linalg.solve(keys[-2], keys[-1])) / (times[-1] - times[-2])
    np.testing.assert_allclose(np.reshape(s.body_velocity(times[0]), -1), first, rtol=0, atol=1e-12)
    np.testing.assert_allclose(np.reshape(s.body_velocity(times[-1]), -1), last, rtol=0, atol=1e-12)


def test_so2_spline_is_the_natural_cubic_spline_of_the_angles():
    """SO(2) is abelian: its spline is scipy's natural cubic spline of the unwrapped angles."""
    interpolate = pytest.importorskip("scipy.interpolate")
    times = np.array([0.0, 1.0, 1.5, 3.0, 4.0, 6.0])
    angles = np.array([0.0, 1.0, 2.5, 3.5, 5.0, 4.0])  # past pi: the key steps are below pi
    s = chasles.SO2Spline(times, chasles.so2_exp(angles))
    reference = interpolate.CubicSpline(times, angles, bc_type="natural")
    t = np.linspace(-0.5, 6.5, 57)
    R = s(t)
    np.testing.assert_allclose(R[:, 0, 0], np.cos(reference(t)), rtol=0, atol=1e-12)
    np.testing.assert_allclose(R[:, 1, 0], np.sin(reference(t)), rtol=0, atol=1e-12)
    np.testing.assert_allclose(s.body_velocity(t), reference(t, 1), rtol=0, atol=1e-11)
    np.testing.assert_allclose(s.body_acceleration(t), reference(t, 2), rtol=0, atol=1e-10)


@pytest.mark.parametrize("group", GROUPS)
def test_two_keys_give_the_geodesic(group):
    a, b = spline_keys(group, 2, 28)
    s = spline_of(group)([1.0, 3.0], np.stack([a, b]))
    x = logm(group, np.linalg.solve(a, b))
    for t in (1.0, 1.5, 2.2, 3.0):
        np.testing.assert_allclose(s(t), a @ expm(group, (t - 1.0) / 2.0 * x), rtol=0, atol=1e-12)
    np.testing.assert_allclose(np.reshape(s.body_velocity(2.0), -1), x / 2.0, rtol=0, atol=1e-12)


@pytest.mark.parametrize("group", GROUPS)
def test_spline_refuses_keys_that_are_not_elements(group):
    keys = spline_keys(group, 3, 29)
    keys[1, 0, 0] += 0.5
    cls = spline_of(group)
    with pytest.raises(ValueError, match=rf"^{cls.__name__}\(keys\): key 1 is not a .*from_matrix_projected"):
        cls([0.0, 1.0, 2.0], keys)
    with pytest.raises(ValueError, match=rf"^{cls.__name__}\(keys\): expected shape \(3, {N[group]}, {N[group]}\)"):
        cls([0.0, 1.0, 2.0], keys[:2])


# ---- the B-spline kernels (bound for every group; the Python classes are SO3's and SE3's so far) ----


@pytest.mark.parametrize("group", GROUPS)
def test_bspline_kernels_follow_the_cumulative_formula(group):
    """_<g>_bspline_new checks the control elements; _<g>_bspline(_rates) is
    X_i exp(B1 d_1) exp(B2 d_2) exp(B3 d_3), d_j = log(X_{i+j-1}^-1 X_{i+j}),
    here by scipy's expm / logm, and its rates the central differences."""
    core = chasles._core
    control = spline_keys(group, 6, 30)
    t0, dt, checked = getattr(core, f"_{group}_bspline_new")(0.5, 0.25, control)
    assert (t0, dt) == (0.5, 0.25) and not checked.flags.writeable
    np.testing.assert_allclose(checked, control, rtol=0, atol=1e-15)  # the stored form (SO2: cos, sin)
    evaluate = getattr(core, f"_{group}_bspline")
    rates = getattr(core, f"_{group}_bspline_rates")
    for t in (0.5, 0.61, 0.8, 1.2, 1.25):
        i = min(int((t - t0) // dt), len(control) - 4)
        u = (t - t0) / dt - i
        B = [(5 + 3 * u - 3 * u**2 + u**3) / 6, (1 + 3 * u + 3 * u**2 - 2 * u**3) / 6, u**3 / 6]
        X = control[i].copy()
        for j in range(1, 4):
            X = X @ expm(group, B[j - 1] * logm(group, np.linalg.solve(control[i + j - 1], control[i + j])))
        np.testing.assert_allclose(evaluate(t0, dt, checked, t), X, rtol=0, atol=1e-12)
        if 0.5 < t < 1.25:
            h = 1e-6
            element, velocity, acceleration = rates(t0, dt, checked, t)
            dX = (evaluate(t0, dt, checked, t + h) - evaluate(t0, dt, checked, t - h)) / (2 * h)
            np.testing.assert_allclose(velocity, vee(group, np.linalg.solve(element, dX)), rtol=0, atol=1e-6)
            dV = (rates(t0, dt, checked, t + h)[1] - rates(t0, dt, checked, t - h)[1]) / (2 * h)
            np.testing.assert_allclose(acceleration, dV, rtol=0, atol=1e-4)
    bad = control.copy()
    bad[2, 0, 0] += 0.5
    cls = {"so2": "SO2", "se2": "SE2", "sim3": "Sim3", "se23": "SE23"}[group]
    with pytest.raises(ValueError, match=rf"^{cls}BSpline\(control\): element 2 is not a "):
        getattr(core, f"_{group}_bspline_new")(0.5, 0.25, bad)
    with pytest.raises(ValueError, match=rf"^{cls}BSpline\(control\): a cubic B-spline needs N >= 4"):
        getattr(core, f"_{group}_bspline_new")(0.5, 0.25, control[:3])


@pytest.mark.parametrize("group", GROUPS)
def test_bspline_classes_evaluate_the_kernels(group):
    core = chasles._core
    name = {"so2": "SO2", "se2": "SE2", "sim3": "Sim3", "se23": "SE23"}[group]
    cls = getattr(chasles, f"{name}BSpline")
    control = spline_keys(group, 6, 31)
    s = cls(0.5, 0.25, control)
    assert (s.start_time, s.spacing, s.end_time) == (0.5, 0.25, 1.25)
    np.testing.assert_array_equal(s.control, getattr(core, f"_{group}_bspline_new")(0.5, 0.25, control)[2])
    t = np.array([[0.5, 0.7], [1.0, 1.25]])
    np.testing.assert_array_equal(s(t), getattr(core, f"_{group}_bspline")(0.5, 0.25, s.control, t))
    _, v, a = getattr(core, f"_{group}_bspline_rates")(0.5, 0.25, s.control, t)
    if group == "so2":  # SO2's rates are floats
        v, a = v[..., 0], a[..., 0]
    np.testing.assert_array_equal(s.body_velocity(t), v)
    np.testing.assert_array_equal(s.body_acceleration(t), a)
    assert s.body_velocity(t).shape == t.shape + (() if group == "so2" else (DOF[group],))
    with pytest.raises(ValueError, match=rf"^{name}BSpline\(t\): expected times in \[start_time, end_time\]"):
        s(1.3)
    with pytest.raises(TypeError, match=rf"^{name}BSpline\(control\): element 0 is a "):
        cls(0.0, 1.0, [chasles.SO3()] * 4)
