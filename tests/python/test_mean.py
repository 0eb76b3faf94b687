"""so3_mean and se3_mean: the geodesic (Karcher) mean solves its equation,
is invariant on both sides and converges in a few Newton steps at a 1 rad
spread; the chordal mean is scipy's Rotation.mean."""

from __future__ import annotations

import warnings

import numpy as np
import pytest

import chasles

Rotation = pytest.importorskip("scipy.spatial.transform").Rotation


def cloud(n, spread, seed, centre=np.eye(3)):
    z = np.random.default_rng(seed).normal(size=(n, 3)) * spread
    return chasles.so3_compose(centre, chasles.so3_exp(z))


def residual(mean, R, w):
    e = chasles.so3_log(chasles.so3_compose(mean.T, R))
    return (w[:, None] * e).sum(axis=0) / w.sum()


def test_geodesic_mean_solves_the_karcher_equation_at_one_radian():
    R = cloud(1000, 1 / np.sqrt(3), 1, chasles.so3_exp([0.3, -2.0, 1.0]))  # rms angle 1 rad
    w = np.random.default_rng(2).uniform(0.1, 2.0, 1000)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        M = chasles.so3_mean(R, w, max_iterations=3)  # 3 Newton steps suffice
    assert np.linalg.norm(residual(M, R, w)) < 1e-14
    np.testing.assert_allclose(M @ M.T, np.eye(3), atol=1e-15)
    # Equal weights: the same equation with w = 1.
    assert np.linalg.norm(residual(chasles.so3_mean(R), R, np.ones(1000))) < 1e-14


def test_too_few_iterations_warn():
    R = cloud(200, 1 / np.sqrt(3), 3)
    with pytest.warns(RuntimeWarning, match="did not converge in 1 iterations"):
        chasles.so3_mean(R, max_iterations=1)


def test_geodesic_mean_is_invariant_on_both_sides():
    R = cloud(300, 0.6, 4)
    g = chasles.so3_exp([1.0, 2.0, -0.5])
    M = chasles.so3_mean(R)
    np.testing.assert_allclose(chasles.so3_mean(g @ R), g @ M, atol=1e-14)
    np.testing.assert_allclose(chasles.so3_mean(R @ g), M @ g, atol=1e-14)


def test_chordal_mean_is_scipys_mean():
    R = cloud(500, 0.8, 5, chasles.so3_exp([2.0, 0.0, 1.0]))
    w = np.random.default_rng(6).uniform(0.0, 3.0, 500)
    ours = chasles.so3_mean(R, w, method="chordal")
    theirs = Rotation.from_matrix(R).mean(weights=w).as_matrix()
    np.testing.assert_allclose(ours, theirs, atol=1e-14)
    np.testing.assert_allclose(
        chasles.so3_mean(R, method="chordal"), Rotation.from_matrix(R).mean().as_matrix(), atol=1e-14
    )
    # The geodesic mean is another mean: at this spread they differ.
    assert np.abs(chasles.so3_mean(R, w) - ours).max() > 1e-4


def test_single_element_and_identical_elements():
    R = chasles.so3_exp([[0.1, 0.2, 0.3]])
    np.testing.assert_allclose(chasles.so3_mean(R), R[0], atol=1e-15)
    np.testing.assert_allclose(chasles.so3_mean(np.repeat(R, 5, axis=0)), R[0], atol=1e-15)


def test_se3_geodesic_mean_is_bi_invariant():
    xi = np.random.default_rng(7).normal(size=(300, 6)) * 0.5
    G = chasles.se3_exp(xi)
    M = chasles.se3_mean(G)
    e = chasles.se3_log(chasles.se3_compose(chasles.se3_inverse(M), G))
    assert np.linalg.norm(e.mean(axis=0)) < 1e-14
    a = chasles.se3_exp([1.0, -1.0, 2.0, 0.3, 0.8, -0.2])
    b = chasles.se3_exp([-0.5, 0.2, 0.1, -1.0, 0.1, 0.4])
    np.testing.assert_allclose(chasles.se3_mean(chasles.se3_compose(a, G)), a @ M, atol=1e-13)
    np.testing.assert_allclose(chasles.se3_mean(chasles.se3_compose(G, b)), M @ b, atol=1e-13)


def test_se3_chordal_mean_is_per_part():
    G = chasles.se3_exp(np.random.default_rng(8).normal(size=(100, 6)))
    w = np.random.default_rng(9).uniform(0.5, 1.5, 100)
    M = chasles.se3_mean(G, w, method="chordal")
    np.testing.assert_allclose(M[:3, 3], (w[:, None] * G[:, :3, 3]).sum(axis=0) / w.sum(), rtol=1e-14)
    np.testing.assert_allclose(M[:3, :3], chasles.so3_mean(G[:, :3, :3], w, method="chordal"), atol=1e-15)
    np.testing.assert_array_equal(M[3], [0.0, 0.0, 0.0, 1.0])


@pytest.mark.parametrize(
    "call, error, fragment",
    [
        (lambda: chasles.so3_mean(np.eye(3)), ValueError, "so3_mean(matrices): expected shape (N, 3, 3)"),
        (lambda: chasles.so3_mean(np.zeros((0, 3, 3))), ValueError, "N >= 1"),
        (lambda: chasles.se3_mean(np.eye(3)[None]), ValueError, "se3_mean(matrices)"),
        (lambda: chasles.so3_mean(np.eye(3)[None], [1.0, 2.0]), ValueError, "so3_mean(weights)"),
        (lambda: chasles.so3_mean(np.eye(3)[None], [-1.0]), ValueError, ">= 0"),
        (lambda: chasles.so3_mean(np.eye(3)[None], method="median"), ValueError, "so3_mean(method)"),
        (lambda: chasles.so3_mean(np.eye(3)[None], max_iterations=0), ValueError, "max_iterations"),
        (lambda: chasles.so3_mean(np.eye(3)[None], max_iterations=2.5), TypeError, "max_iterations"),
        (lambda: chasles.so3_mean(np.full((1, 3, 3), np.nan)), ValueError, "finite"),
        (lambda: chasles.so3_mean("abc"), TypeError, "so3_mean(matrices)"),
        (lambda: chasles.so3_mean(np.stack([np.eye(3), 1.001 * np.eye(3)])), ValueError, "element 1 is not a rotation"),
        (lambda: chasles.se3_mean(np.stack([np.eye(4), np.diag([1.0, 1.0, -1.0, 1.0])])), ValueError, "element 1"),
    ],
)
def test_bad_arguments_name_the_function(call, error, fragment):
    with pytest.raises(error) as e:
        call()
    assert fragment in str(e.value)


def test_se3_chordal_mean_is_scipys_rigid_transform_mean():
    transform = pytest.importorskip("scipy.spatial.transform")
    if not hasattr(getattr(transform, "RigidTransform", None), "mean"):
        pytest.skip("this scipy has no RigidTransform.mean")
    G = chasles.se3_exp(np.random.default_rng(10).normal(size=(50, 6)))
    w = np.random.default_rng(11).uniform(0.5, 1.5, 50)
    theirs = transform.RigidTransform.from_matrix(G).mean(weights=w).as_matrix()
    np.testing.assert_allclose(chasles.se3_mean(G, w, method="chordal"), theirs, atol=1e-13)
