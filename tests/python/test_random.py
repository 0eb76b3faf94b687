"""Sampling: uniform rotations (so3_random, SO3.random, so3_from_uniforms),
random poses (se3_random, SE3.random) and Gaussian samples (so3_gaussian,
se3_gaussian), checked statistically at fixed seeds."""

from __future__ import annotations

import numpy as np
import pytest

import chasles

stats = pytest.importorskip("scipy.stats")
Rotation = pytest.importorskip("scipy.spatial.transform").Rotation


def haar_angle_cdf(t):
    return (t - np.sin(t)) / np.pi


def test_uniform_rotation_angles_follow_the_haar_cdf():
    R = chasles.so3_random(20000, rng=1)
    assert R.shape == (20000, 3, 3) and R.dtype == np.float64
    angles = chasles.so3_angle(R)
    assert stats.kstest(angles, haar_angle_cdf).pvalue > 1e-3
    # The test can fail: uniformly distributed angles are rejected.
    wrong = np.random.default_rng(1).uniform(0, np.pi, 20000)
    assert stats.kstest(wrong, haar_angle_cdf).pvalue < 1e-6


def test_uniform_rotations_are_rotations_with_mean_zero():
    R = chasles.so3_random(20000, rng=2)
    np.testing.assert_allclose(R @ np.swapaxes(R, -1, -2), np.broadcast_to(np.eye(3), R.shape), atol=1e-14)
    np.testing.assert_allclose(np.linalg.det(R), 1.0, atol=1e-14)
    # Each entry has variance 1/3: the mean is within 5 sigma of 0.
    assert np.abs(R.mean(axis=0)).max() < 5 * np.sqrt(1 / (3 * len(R)))


def test_quaternion_components_are_symmetric():
    q = chasles.so3_as_quat(chasles.so3_random(20000, rng=3))
    q = q * np.sign(q[:, 3:4])  # the w >= 0 hemisphere: x, y, z stay symmetric about 0
    for i in range(3):
        assert stats.ks_2samp(q[:, i], -q[:, i]).pvalue > 1e-3
    # |q_i| has the same distribution for the four components.
    a = np.abs(q)
    for i in range(3):
        assert stats.ks_2samp(a[:, i], a[:, 3]).pvalue > 1e-3


def test_same_distribution_as_scipy_random():
    ours = chasles.so3_angle(chasles.so3_random(10000, rng=4))
    theirs = Rotation.random(10000, rng=np.random.default_rng(5)).magnitude()
    assert stats.ks_2samp(ours, theirs).pvalue > 1e-3


def test_seeds_and_generators_as_scipy():
    a = chasles.so3_random(5, rng=42)
    np.testing.assert_array_equal(a, chasles.so3_random(5, rng=42))
    np.testing.assert_array_equal(a, chasles.so3_random(5, rng=np.random.default_rng(42)))
    # The map of the Generator's own uniforms: 3 per rotation, in order.
    u = np.random.default_rng(42).random((5, 3))
    np.testing.assert_array_equal(a, chasles.so3_from_uniforms(u))
    gen = np.random.default_rng(0)
    assert not np.array_equal(chasles.so3_random(2, rng=gen), chasles.so3_random(2, rng=gen))
    assert chasles.so3_random(rng=0).shape == (3, 3)
    assert chasles.so3_random((2, 3), rng=0).shape == (2, 3, 3, 3)
    assert chasles.so3_random(0, rng=0).shape == (0, 3, 3)
    assert chasles.so3_random().shape == (3, 3)


def test_objects_random():
    R = chasles.SO3.random(rng=7)
    assert isinstance(R, chasles.SO3)
    np.testing.assert_array_equal(R.as_matrix(), chasles.so3_random(rng=7))
    g = chasles.SE3.random(rng=8, low=[0, 1, 2], high=[0.5, 1.5, 2.5])
    assert isinstance(g, chasles.SE3)
    np.testing.assert_array_equal(g.as_matrix(), chasles.se3_random(rng=8, low=[0, 1, 2], high=[0.5, 1.5, 2.5]))
    assert isinstance(chasles.SO3.random(), chasles.SO3)


def test_so3_from_uniforms_at_known_points():
    np.testing.assert_allclose(chasles.so3_from_uniforms([1.0, 0.0, 0.0]), np.eye(3), atol=1e-15)
    np.testing.assert_allclose(chasles.so3_from_uniforms([0.0, 0.0, 0.0]), np.diag([-1.0, 1.0, -1.0]), atol=1e-15)
    np.testing.assert_allclose(
        chasles.so3_from_uniforms([0.5, 0.25, 0.0]),
        Rotation.from_rotvec([np.pi / 2, 0, 0]).as_matrix(),
        atol=1e-15,
    )
    assert chasles.so3_from_uniforms(np.float32([0.1, 0.2, 0.3])).dtype == np.float32


def test_se3_random_translation_in_the_box():
    low, high = np.array([-1.0, 2.0, 0.0]), np.array([1.0, 5.0, 0.5])
    g = chasles.se3_random(20000, rng=9, low=low, high=high)
    assert g.shape == (20000, 4, 4)
    p = g[:, :3, 3]
    assert np.all((low <= p) & (p <= high))
    np.testing.assert_array_equal(g[:, 3], np.broadcast_to([0.0, 0.0, 0.0, 1.0], (20000, 4)))
    for i in range(3):
        assert stats.kstest(p[:, i], stats.uniform(low[i], high[i] - low[i]).cdf).pvalue > 1e-3
    assert stats.kstest(chasles.so3_angle(g[:, :3, :3]), haar_angle_cdf).pvalue > 1e-3
    # The rotation uniforms are drawn first, then the translation's.
    gen = np.random.default_rng(9)
    u = gen.random((20000, 3))
    np.testing.assert_array_equal(g[:, :3, :3], chasles.so3_from_uniforms(u))
    np.testing.assert_array_equal(p, low + (high - low) * gen.random((20000, 3)))


def tangent_covariance(samples, mean, log, compose, inverse):
    e = log(compose(inverse(mean), samples))
    return e.T @ e / len(e)


def assert_covariance_matches(empirical, cov, n):
    # Each entry of a sample covariance has std sqrt((c_ii c_jj + c_ij^2) / n): 5 of them.
    d = np.diag(cov)
    sigma = np.sqrt((np.outer(d, d) + cov**2) / n)
    assert np.all(np.abs(empirical - cov) <= 5 * sigma), np.abs(empirical - cov) / sigma


def test_so3_gaussian_has_the_tangent_covariance_given():
    A = np.array([[0.3, 0.0, 0.0], [0.1, 0.2, 0.0], [-0.05, 0.1, 0.4]])
    cov = A @ A.T
    mean = chasles.so3_exp([0.3, -1.0, 2.0])
    n = 40000
    X = chasles.so3_gaussian(mean, cov, n, rng=10)
    assert X.shape == (n, 3, 3)
    emp = tangent_covariance(X, mean, chasles.so3_log, chasles.so3_compose, chasles.so3_inverse)
    assert_covariance_matches(emp, cov, n)
    # The mean of the tangent errors is 0 (5 sigma).
    e = chasles.so3_log(chasles.so3_compose(mean.T, X))
    assert np.all(np.abs(e.mean(axis=0)) < 5 * np.sqrt(np.diag(cov) / n))
    # An SO3 object as the mean is the same.
    np.testing.assert_array_equal(
        chasles.so3_gaussian(chasles.SO3.from_matrix(mean), cov, 3, rng=1), chasles.so3_gaussian(mean, cov, 3, rng=1)
    )


def test_se3_gaussian_has_the_tangent_covariance_given():
    A = np.tril(np.random.default_rng(11).uniform(-0.3, 0.3, (6, 6))) + np.diag([0.5, 0.4, 0.3, 0.2, 0.1, 0.3])
    cov = A @ A.T
    mean = chasles.se3_exp([1.0, -2.0, 3.0, 0.4, 0.5, -0.6])
    n = 40000
    X = chasles.se3_gaussian(mean, cov, n, rng=12)
    assert X.shape == (n, 4, 4)
    emp = tangent_covariance(X, mean, chasles.se3_log, chasles.se3_compose, chasles.se3_inverse)
    assert_covariance_matches(emp, cov, n)
    # The check can fail: a left perturbation exp(L z) mean has another covariance.
    L = np.linalg.cholesky(cov)
    z = np.random.default_rng(12).standard_normal((n, 6))
    left = chasles.se3_compose(chasles.se3_exp(z @ L.T), mean)
    emp_left = tangent_covariance(left, mean, chasles.se3_log, chasles.se3_compose, chasles.se3_inverse)
    with pytest.raises(AssertionError):
        assert_covariance_matches(emp_left, cov, n)


def test_gaussian_with_a_singular_covariance():
    cov = np.diag([0.0, 0.0, 0.04])  # rotations about z only
    X = chasles.so3_gaussian(np.eye(3), cov, 100, rng=13)
    w = chasles.so3_log(X)
    np.testing.assert_allclose(w[:, :2], 0.0, atol=1e-15)
    assert np.std(w[:, 2]) > 0.1


@pytest.mark.parametrize(
    "call, error, fragment",
    [
        (lambda: chasles.so3_random(-1), ValueError, "so3_random(n)"),
        (lambda: chasles.so3_random(2.5), TypeError, "so3_random(n)"),
        (lambda: chasles.so3_random(2, rng="seed"), TypeError, "so3_random(rng)"),
        (lambda: chasles.se3_random(2, low=[0, 0], high=1), ValueError, "se3_random(low)"),
        (lambda: chasles.se3_random(2, low=1.0, high=0.0), ValueError, "low <= high"),
        (lambda: chasles.so3_gaussian(np.eye(4), np.eye(3)), ValueError, "so3_gaussian(mean)"),
        (lambda: chasles.so3_gaussian(np.eye(3), np.eye(6)), ValueError, "so3_gaussian(cov)"),
        (lambda: chasles.so3_gaussian(np.eye(3), -np.eye(3)), ValueError, "positive semidefinite"),
        (lambda: chasles.so3_gaussian(np.eye(3), [[1, 1, 0], [0, 1, 0], [0, 0, 1]]), ValueError, "symmetric"),
        (lambda: chasles.se3_gaussian(np.eye(4), np.eye(3)), ValueError, "se3_gaussian(cov)"),
        (lambda: chasles.se3_gaussian(np.eye(4) * np.nan, np.eye(6)), ValueError, "finite"),
    ],
)
def test_bad_arguments_name_the_function(call, error, fragment):
    with pytest.raises(error) as e:
        call()
    assert fragment in str(e.value)


@pytest.mark.parametrize(
    "call, fragments",
    [
        (lambda: chasles.so3_gaussian(2 * np.eye(3), 0.01 * np.eye(3), 4, rng=0),
         ["so3_gaussian(mean): not a rotation matrix", "is 7 (det M = 8)", "tol = 1.49e-08",
          "SO3.from_matrix_projected"]),
        (lambda: chasles.so3_gaussian(np.diag([1.0, 1.0, -1.0]), 0.01 * np.eye(3)),
         ["so3_gaussian(mean): not a rotation matrix", "reflection"]),
        (lambda: chasles.so3_gaussian(np.diag([1.0, 1.0, 1.0 + 1e-7]), 0.01 * np.eye(3)),
         ["so3_gaussian(mean): not a rotation matrix", "2e-07"]),
        (lambda: chasles.se3_gaussian(np.diag([2.0, 2.0, 2.0, 1.0]), 0.01 * np.eye(6)),
         ["se3_gaussian(mean): not a rigid motion", "det R = 8", "SE3.from_matrix_projected"]),
        (lambda: chasles.se3_gaussian(np.diag([1.0, 1.0, 1.0, 2.0]), 0.01 * np.eye(6)),
         ["se3_gaussian(mean): not a rigid motion", "bottom row differs from (0, 0, 0, 1) by 1"]),
    ],
)  # fmt: skip
def test_gaussians_refuse_a_mean_that_is_not_a_group_element(call, fragments):
    """The mean is checked as SO3.from_matrix / SE3.from_matrix check a
    matrix (the library's tolerance, sqrt(eps)): a mean of 2 I gave samples
    of determinant 8."""
    with pytest.raises(ValueError) as e:
        call()
    for fragment in fragments:
        assert fragment in str(e.value)
    assert "from_matrix:" not in str(e.value) and "larger tol" not in str(e.value)


def test_gaussians_take_a_mean_within_the_tolerance_as_it_is():
    near = np.diag([1.0, 1.0, 1.0 + 1e-9])  # defect 2e-9 <= sqrt(eps)
    cov = 0.01 * np.eye(3)
    z = np.random.default_rng(1).standard_normal((3, 3))
    np.testing.assert_array_equal(
        chasles.so3_gaussian(near, cov, 3, rng=1),
        chasles.so3_compose(near, chasles.so3_exp(z @ np.linalg.cholesky(cov).T)),
    )
    g = chasles.SE3.exp([1.0, 2.0, 3.0, 0.1, 0.2, 0.3])
    cov6 = 0.01 * np.eye(6)
    np.testing.assert_array_equal(
        chasles.se3_gaussian(g, cov6, 2, rng=3), chasles.se3_gaussian(g.as_matrix(), cov6, 2, rng=3)
    )


def test_objects_random_do_not_import_the_python_samplers():
    """SO3.random and SE3.random draw from numpy's Generator in C++: they work
    with chasles._random unimportable (the extension imports no module of
    its package), with the bits of so3_random / se3_random."""
    import subprocess
    import sys

    code = (
        "import sys, numpy as np, chasles\n"
        "a, b = chasles.so3_random(rng=7), chasles.se3_random(rng=8, low=0.5, high=2.0)\n"
        "sys.modules['chasles._random'] = None\n"
        "assert np.array_equal(chasles.SO3.random(rng=7).as_matrix(), a)\n"
        "assert np.array_equal(chasles.SE3.random(rng=8, low=0.5, high=2.0).as_matrix(), b)\n"
    )
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=False)
    assert r.returncode == 0, r.stderr


@pytest.mark.parametrize("bad, error", [(-1, ValueError), ("seed", TypeError), (1.5, TypeError), (1j, TypeError)])
def test_objects_random_refuse_a_bad_rng_naming_the_sampler(bad, error):
    with pytest.raises(error, match=r"so3_random\(rng\)"):
        chasles.SO3.random(rng=bad)
    with pytest.raises(error, match=r"se3_random\(rng\)"):
        chasles.SE3.random(rng=bad)


def test_se3_random_box_errors_name_the_argument():
    with pytest.raises(ValueError, match=r"se3_random\(low\)"):
        chasles.SE3.random(rng=0, low=[0.0, np.nan, 0.0])
    with pytest.raises(ValueError, match=r"se3_random\(high\)"):
        chasles.SE3.random(rng=0, high=[1.0, 2.0])
    with pytest.raises(ValueError, match=r"se3_random: expected low <= high"):
        chasles.SE3.random(rng=0, low=1.0, high=0.0)
