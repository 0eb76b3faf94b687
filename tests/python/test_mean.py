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


# ---- the scale of the weights and of the translations, invalid weights, the private cores ----

TWO = chasles.so3_exp([[0.0, 0.0, 0.2], [0.0, 0.0, 0.6]])
TINY = 5e-324  # the smallest subnormal
BIG = np.finfo(np.float64).max


@pytest.mark.parametrize("method", ["geodesic", "chordal"])
@pytest.mark.parametrize(
    "weights, reference",
    [([BIG, BIG], [1.0, 1.0]), ([1e308, 1e308], [1.0, 1.0]), ([TINY, TINY], [1.0, 1.0]),
     ([1e-310, 1e-310], [1.0, 1.0]), ([BIG, BIG / 3], [3.0, 1.0]), ([3 * TINY, TINY], [3.0, 1.0])],
)  # fmt: skip
def test_means_are_unchanged_by_the_scale_of_the_weights(method, weights, reference):
    """Weights whose sum overflows, or whose products with the matrices
    underflow, give the mean of the same weights scaled to 1 (to rounding),
    for rotations and for poses; and no warning (the suite turns warnings
    into errors)."""
    expected = chasles.so3_mean(TWO, reference, method)
    np.testing.assert_allclose(chasles.so3_mean(TWO, weights, method), expected, rtol=0, atol=4e-16)
    if weights[0] == weights[1]:
        np.testing.assert_allclose(chasles.so3_log(expected), [0.0, 0.0, 0.4], rtol=0, atol=4e-16)
    G = np.stack([np.eye(4), np.eye(4)])
    G[:, :3, :3] = TWO
    G[:, :3, 3] = [[1.0, 2.0, 3.0], [-1.0, 0.5, 7.0]]
    np.testing.assert_allclose(
        chasles.se3_mean(G, weights, method), chasles.se3_mean(G, reference, method), rtol=0, atol=4e-15
    )


@pytest.mark.parametrize("method", ["geodesic", "chordal"])
def test_a_mean_of_translations_near_the_largest_float_does_not_overflow(method):
    """Two poses at x = 1e308 (and at the largest finite float) average to
    that x, finite, not inf (chordal) or NaN (geodesic); at -x and x to 0."""
    for x in (1e308, BIG):
        G = np.stack([np.eye(4), np.eye(4)])
        G[:, :3, :3] = TWO
        G[:, :3, 3] = [[x, 0.0, 1.0], [x, 0.0, 3.0]]
        for weights in (None, [BIG, BIG]):
            M = chasles.se3_mean(G, weights, method)
            assert M[0, 3] == x
            np.testing.assert_allclose(M[1:3, 3], [0.0, 2.0], rtol=0, atol=1e-15)
            np.testing.assert_allclose(chasles.so3_log(M[:3, :3]), [0.0, 0.0, 0.4], rtol=0, atol=4e-16)
    G = np.stack([np.eye(4), np.eye(4)])
    G[:, 0, 3] = [-BIG, BIG]
    np.testing.assert_array_equal(chasles.se3_mean(G, method="chordal")[:3, 3], [0.0, 0.0, 0.0])


@pytest.mark.parametrize("function", [chasles.so3_mean, chasles.se3_mean], ids=lambda f: f.__name__)
@pytest.mark.parametrize(
    "weights, fragment",
    [([-1.0, 2.0], "expected weights >= 0, got weights[0] = -1.0"),
     ([1.0, -5e-324], "expected weights >= 0, got weights[1] = -5e-324"),
     ([np.nan, 1.0], "expected finite weights, got weights[0] = nan"),
     ([1.0, np.inf], "expected finite weights, got weights[1] = inf"),
     ([0.0, 0.0], "expected at least one weight > 0, got all 2 weights 0")],
)  # fmt: skip
def test_invalid_weights_are_refused_and_say_which(function, weights, fragment):
    X = TWO if function is chasles.so3_mean else np.stack([np.eye(4), np.eye(4)])
    for method in ("geodesic", "chordal"):
        with pytest.raises(ValueError) as e:
            function(X, weights, method)
        assert str(e.value) == f"{function.__name__}(weights): {fragment}"


@pytest.mark.parametrize(
    "core, matrices, weights, shapes",
    [("_so3_mean", np.repeat(np.eye(3)[None], 1000, axis=0), np.ones(1), "(1000, 3, 3) and (1,)"),
     ("_so3_mean", np.eye(3)[None], np.ones(1000), "(1, 3, 3) and (1000,)"),
     ("_so3_mean", np.repeat(np.eye(4)[None], 2, axis=0), np.ones(2), "(2, 4, 4) and (2,)"),
     ("_so3_mean", np.eye(3), np.ones(3), "(3, 3) and (3,)"),
     ("_so3_mean", np.zeros((0, 3, 3)), np.ones(0), "(0, 3, 3) and (0,)"),
     ("_so3_mean", np.eye(3)[None], np.ones((1, 1)), "(1, 3, 3) and (1, 1)"),
     ("_se3_mean", np.repeat(np.eye(4)[None], 1000, axis=0), np.ones(2), "(1000, 4, 4) and (2,)"),
     ("_se3_mean", np.repeat(np.eye(3)[None], 2, axis=0), np.ones(2), "(2, 3, 3) and (2,)"),
     ("_se3_mean", np.eye(4)[None], 1.0, "(1, 4, 4) and ()")],
)  # fmt: skip
def test_the_private_cores_check_the_shapes_they_read(core, matrices, weights, shapes):
    """_so3_mean and _se3_mean read N elements and N weights: shapes that do
    not agree are a ValueError naming the function and the shapes (they read
    past the weights' buffer before)."""
    n = 3 if core == "_so3_mean" else 4
    with pytest.raises(ValueError) as e:
        getattr(chasles._core, core)(matrices, weights, True, 20)
    assert str(e.value) == (
        f"{core}(matrices, weights): expected shapes (N, {n}, {n}) with N >= 1 and (N,), got {shapes}"
    )


@pytest.mark.parametrize("core", ["_so3_mean", "_se3_mean"])
@pytest.mark.parametrize(
    "weights", [[-1.0, 2.0], [2.0, -1.0], [np.nan, 1.0], [1.0, np.nan], [0.0, 0.0], [np.inf, 1.0], [1.0, np.inf]]
)
@pytest.mark.parametrize("geodesic", [True, False])
def test_the_private_cores_refuse_the_weights_the_cpp_mean_reports(core, weights, geodesic):
    n = 3 if core == "_so3_mean" else 4
    X = np.repeat(np.eye(n)[None], 2, axis=0)
    with pytest.raises(ValueError, match=rf"^{core}\(weights\): expected finite weights >= 0, not all 0$"):
        getattr(chasles._core, core)(X, np.array(weights), geodesic, 20)


@pytest.mark.parametrize("mean", [chasles.so3_mean, chasles.se3_mean])
def test_the_convergence_and_iteration_count_reach_python(mean):
    """return_info=True gives what the C++ mean reports (mean, converged,
    iterations) without a warning; the default return is the mean alone."""
    R = cloud(200, 1 / np.sqrt(3), 3)
    X = R if mean is chasles.so3_mean else chasles.se3_exp(np.concatenate([np.ones((200, 3)), chasles.so3_log(R)], -1))
    info = mean(X, return_info=True)
    assert np.array_equal(info.mean, mean(X)) and info.converged is True and 1 <= info.iterations <= 20
    mean_, converged, iterations = info
    assert iterations == info.iterations
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        short = mean(X, max_iterations=1, return_info=True)
    assert short.converged is False and short.iterations == 1
    chordal = mean(X, method="chordal", return_info=True)
    assert chordal.converged is True and chordal.iterations == 0
    assert np.array_equal(chordal.mean, mean(X, method="chordal"))


def test_quaternions_given_to_so3_mean_name_so3_from_quat():
    q = np.tile([0.0, 0.0, 0.0, 1.0], (5, 1))
    with pytest.raises(ValueError, match=r"so3_mean\(matrices\).*\(N, 3, 3\).*got \(5, 4\).*so3_from_quat"):
        chasles.so3_mean(q)
    assert np.allclose(chasles.so3_mean(chasles.so3_from_quat(q)), np.eye(3))
