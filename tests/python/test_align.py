"""so3_align, se3_align and sim3_align: so3_align against scipy's
Rotation.align_vectors (rotation, rssd, sensitivity, weights, one pair, the
primary vector, what it warns about and what it refuses); se3_align and
sim3_align against Kabsch and Umeyama written here with numpy's SVD
(independent of chasles' quaternion method) and against scipy's
align_vectors of the centred points; exact on noise-free data; never a
reflection; every error message."""

from __future__ import annotations

import warnings

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

import chasles

Rotation = pytest.importorskip("scipy.spatial.transform").Rotation

EPS = np.finfo(np.float64).eps


def scipy_align(a, b, weights=None, sensitivity=True):
    """scipy's answer, its UserWarning for an undetermined rotation silenced."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)
        out = Rotation.align_vectors(a, b, weights, return_sensitivity=sensitivity)
    return (out[0].as_matrix(),) + tuple(out[1:])


def signed_singular_values(a, b, w):
    """s1 >= s2 >= |s3| of sum_i w_i a_i b_i^T, s3 < 0 where the best orthogonal map is a reflection."""
    U, s, Vt = np.linalg.svd((w[:, None] * a).T @ b)
    if np.linalg.det(U @ Vt) < 0:
        s[2] = -s[2]
    return s


def direct_rssd(g, a, b, w):
    """sqrt(sum_i w_i |a_i - g b_i|^2) from the residuals, the infinite weights left out."""
    g = np.asarray(g)
    r = a - (b @ g[:3, :3].T + (g[:3, 3] if g.shape == (4, 4) else 0.0))
    finite = np.isfinite(w)
    return float(np.sqrt(np.sum(w[finite] * np.sum(r[finite] ** 2, axis=1))))


def umeyama(a, b, w, scale):
    """Umeyama's solution (TPAMI 1991, eq. 38-42) with weights, by numpy's SVD: g with a_i ~ g b_i."""
    w = w / w.sum()
    ma, mb = w @ a, w @ b
    da, db = a - ma, b - mb
    U, d, Vt = np.linalg.svd((w[:, None] * da).T @ db)
    S = np.diag([1.0, 1.0, np.sign(np.linalg.det(U) * np.linalg.det(Vt))])
    R = U @ S @ Vt
    c = np.trace(np.diag(d) @ S) / (w @ np.sum(db**2, axis=1)) if scale else 1.0
    g = np.eye(4)
    g[:3, :3] = c * R
    g[:3, 3] = ma - c * R @ mb
    return g


def vector_set(seed, n, noise, weighted, scale=1.0):
    """n vectors b (normal, times `scale`), a = R b + noise, weights in [0, 3] or None."""
    rng = np.random.default_rng(seed)
    b = scale * rng.normal(size=(n, 3))
    R = chasles.so3_exp(rng.normal(size=3))
    a = b @ R.T + noise * scale * rng.normal(size=(n, 3))
    w = rng.uniform(0.0, 3.0, n) if weighted else None
    return a, b, w


sets = st.tuples(
    st.integers(0, 2**32 - 1),
    st.integers(2, 40),
    st.sampled_from([0.0, 1e-6, 0.01, 0.3, 1.0]),
    st.booleans(),
    st.sampled_from([1e-3, 1.0, 1e3]),
)


# ---- so3_align against scipy ---------------------------------------------------------------


@given(sets)
def test_so3_align_is_scipys_align_vectors(case):
    seed, n, noise, weighted, scale = case
    a, b, w = vector_set(seed, n, noise, weighted, scale)
    w1 = np.ones(n) if w is None else w
    s = signed_singular_values(a, b, w1)
    condition = s[0] / (s[1] + s[2])
    if condition > 1e6:  # not determined to 1e-10 (the other tests take those)
        return
    ours = chasles.so3_align(a, b, w)
    R, rssd, sensitivity = scipy_align(a, b, w)
    np.testing.assert_allclose(ours.matrix, R, atol=1e-13 * condition)
    # rssd: ours is summed from the residuals, each known to eps |a| (their
    # rounding); scipy's subtracts 2 tr(R^T B) from sum w (|a|^2 + |b|^2),
    # off by eps times that sum
    total = np.sum(w1 * np.sum(a**2 + b**2, axis=1))
    assert ours.rssd == pytest.approx(direct_rssd(ours.matrix, a, b, w1), rel=1e-13, abs=8 * EPS * np.sqrt(total))
    assert abs(ours.rssd**2 - rssd**2) <= 64 * EPS * total
    np.testing.assert_allclose(ours.sensitivity, sensitivity, rtol=1e-12 * condition**2, atol=0)
    # the unpacking of scipy's (rotation, rssd, sensitivity)
    R2, rssd2, sensitivity2 = ours
    assert R2 is ours.matrix and rssd2 == ours.rssd and sensitivity2 is ours.sensitivity


def test_so3_align_of_scipys_own_examples():
    # the docstring examples and tests of scipy's align_vectors, compared with scipy at run time
    cases = [
        ([[0, 1, 0], [0, 1, 1], [0, 1, 1]], [[1, 0, 0], [1, 1.1, 0], [1, 0.9, 0]], None),
        ([[0, 1, 0], [0, 1, 1]], [[1, 0, 0], [1, 1, 0]], [np.inf, 1]),
        ([[0, 1, 0], [0, 1, 1]], [[1, 0, 0], [1, 2, 0]], [np.inf, 1]),
        ([[-1.0, 3, 2], [1, -1, 2]], [[1, 2, 3], [-2, 3, -1]], [np.inf, 1]),
        ([1, 0, 0], [0, 1, 0], None),
        # the secondary vector along the primary one: not determined (scipy returns the shortest rotation)
        ([[1.0, 0, 0], [0, 1, 0]], [[0.0, 1, 0], [0, 1, 0]], [np.inf, 1]),
        ([[1.0, 0, 0], [0, 1, 0]], [[-1.0, 0, 0], [0, 1, 0]], [np.inf, 1]),
        ([[0, 1.0, 0], [1, 0, 0]], [[0, -1.0, 0], [1, 0, 0]], [np.inf, 1]),
        (
            [[0.89299824, -0.44372674, 0.0752378], [0.60221789, -0.47564102, -0.6411702]],
            [[0.02386536, -0.82176463, 0.5693271], [-0.27654929, -0.95191427, -0.1318321]],
            None,
        ),
    ]
    for a, b, w in cases:
        primary = w is not None or np.ndim(a) == 1
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            ours = chasles.so3_align(a, b, w)
        assert len(caught) == (a == [[1.0, 0, 0], [0, 1, 0]] and b == [[0.0, 1, 0], [0, 1, 0]])
        theirs = scipy_align(a, b, w, sensitivity=not primary)
        np.testing.assert_allclose(ours.matrix, theirs[0], atol=1e-14)
        a2, b2 = np.atleast_2d(a), np.atleast_2d(b)
        w1 = np.ones(len(a2)) if w is None else np.asarray(w, dtype=float)
        total = np.sum(np.where(np.isinf(w1), 0.0, w1) * np.sum(a2**2 + b2**2, axis=1))
        assert ours.rssd == pytest.approx(direct_rssd(ours.matrix, a2, b2, w1), abs=8 * EPS * np.sqrt(total))
        assert abs(ours.rssd**2 - theirs[1] ** 2) <= 64 * EPS * total
        if primary:
            assert ours.sensitivity is None
        else:
            np.testing.assert_allclose(ours.sensitivity, theirs[2], rtol=1e-12)


@given(st.integers(0, 2**32 - 1), st.integers(1, 8), st.sampled_from([0.0, 0.1, 1.0]))
def test_the_primary_vector_is_scipys(seed, n, noise):
    rng = np.random.default_rng(seed)
    a, b, w = vector_set(seed, n, noise, True)
    p = int(rng.integers(n))
    w[p] = np.inf
    ours = chasles.so3_align(a, b, w)
    R, rssd = scipy_align(a, b, w, sensitivity=False)
    assert ours.sensitivity is None
    # the primary directions aligned exactly
    np.testing.assert_allclose(ours.matrix @ b[p] / np.linalg.norm(b[p]), a[p] / np.linalg.norm(a[p]), atol=1e-14)
    # scipy's rotation where its half turn is not near pi (there it misses: see below)
    u, v = a[p] / np.linalg.norm(a[p]), b[p] / np.linalg.norm(b[p])
    if np.dot(u, v) > -0.99:
        np.testing.assert_allclose(ours.matrix, R, atol=1e-12)
        assert ours.rssd == pytest.approx(rssd, rel=1e-12, abs=1e-14)
    finite = np.isfinite(w)
    total = np.sum(w[finite] * np.sum(a[finite] ** 2 + b[finite] ** 2, axis=1))
    assert ours.rssd == pytest.approx(direct_rssd(ours.matrix, a, b, w), rel=1e-13, abs=8 * EPS * np.sqrt(total))
    # a large weight in its place: the limit. The primary pair then pulls
    # w_p |a_p| |b_p| against the others' sum_i w_i |a_i| |b_i| = W, so the
    # rotations differ by about their ratio, here 1e-6 (w_p = 1e6 W / (|a_p| |b_p|))
    if n > 1:
        others = np.sum(np.delete(w * np.linalg.norm(a, axis=1) * np.linalg.norm(b, axis=1), p))
        large = w.copy()
        large[p] = 1e6 * others / (np.linalg.norm(a[p]) * np.linalg.norm(b[p]))
        np.testing.assert_allclose(chasles.so3_align(a, b, large).matrix, ours.matrix, atol=4e-6)


def test_one_pair_is_the_shortest_rotation_also_nearly_opposite():
    # (scipy 1.17 turns by pi about b x a where that is rounding, and misses a there)
    rng = np.random.default_rng(7)
    for _ in range(200):
        a = rng.normal(size=3)
        for b in (-2.5 * a, -a + 1e-9 * rng.normal(size=3), rng.normal(size=3)):
            R, rssd, sensitivity = chasles.so3_align(a, b)
            u, v = a / np.linalg.norm(a), b / np.linalg.norm(b)
            np.testing.assert_allclose(R @ v, u, atol=4 * EPS)
            # shortest: the angle between them, about an axis orthogonal to both
            angle = np.arctan2(np.linalg.norm(np.cross(v, u)), np.dot(u, v))
            assert chasles.so3_angle(R) == pytest.approx(angle, abs=1e-14)
            # the axis, orthogonal to both, is known to eps / |v x u| (not at all for opposite vectors)
            assert abs(np.dot(chasles.so3_log(R), u)) <= 8 * EPS / max(np.linalg.norm(np.cross(v, u)), EPS)
            assert rssd == pytest.approx(abs(np.linalg.norm(a) - np.linalg.norm(b)), abs=1e-14)
            assert sensitivity is None


def test_a_weight_of_one_pair_enters_rssd_only():
    a, b = [1.0, 2.0, 3.0], [2.0, 4.0, 6.0]
    one = chasles.so3_align(a, b)
    for w in ([0.25], [4.0]):
        ours, theirs = chasles.so3_align(a, b, w), scipy_align([a], [b], w, sensitivity=False)
        np.testing.assert_array_equal(ours.matrix, one.matrix)
        assert ours.rssd == pytest.approx(np.sqrt(w[0]) * one.rssd, rel=1e-15)
        assert ours.rssd == pytest.approx(theirs[1], rel=1e-14)
    assert chasles.so3_align([a], [b], [np.inf]).rssd == 0.0  # the primary term is left out


def test_weights_scale_out_of_the_rotation_and_the_sensitivity():
    a, b, w = vector_set(3, 10, 0.2, True)
    r1, r2 = chasles.so3_align(a, b, w), chasles.so3_align(a, b, 1e200 * w)
    np.testing.assert_allclose(r2.matrix, r1.matrix, atol=1e-15)
    np.testing.assert_allclose(r2.sensitivity, r1.sensitivity, rtol=1e-13)
    assert r2.rssd == pytest.approx(1e100 * r1.rssd, rel=1e-14)


def test_float32_and_integer_input_are_float64():
    a, b, _ = vector_set(4, 6, 0.1, False)
    a32, b32 = a.astype(np.float32), b.astype(np.float32)
    ours = chasles.so3_align(a32, b32)
    ref = chasles.so3_align(a32.astype(np.float64), b32.astype(np.float64))
    assert ours.matrix.dtype == np.float64
    np.testing.assert_array_equal(ours.matrix, ref.matrix)
    ints = chasles.se3_align([[0, 0, 0], [1, 0, 0], [0, 2, 0]], [[0, 0, 0], [0, 1, 0], [-2, 0, 0]])
    np.testing.assert_allclose(ints.matrix[:3, :3], chasles.so3_exp([0, 0, -np.pi / 2]), atol=1e-15)


# ---- what so3_align warns about, as scipy ------------------------------------------------------


def test_parallel_vectors_warn_as_scipy_and_still_fit():
    a = np.array([[1.0, 2.0, 3.0], [-2.0, -4.0, -6.0]])
    R = chasles.so3_exp([0.3, -0.2, 1.0])
    b = a @ R  # b = R^T a: a = R b
    with pytest.warns(UserWarning, match="Optimal rotation is not uniquely"):
        Rotation.align_vectors(a, b)
    with pytest.warns(UserWarning, match=r"so3_align: the rotation is not determined by these vectors"):
        ours = chasles.so3_align(a, b)
    assert ours.sensitivity is None
    assert ours.rssd <= 1e-14
    np.testing.assert_allclose(ours.matrix @ b.T, a.T, atol=1e-14)  # one of the minimizers


def test_the_warning_threshold_is_half_the_digits():
    # two vectors at an angle d: s2 / s1 is about d^2 / 4 here, sqrt(eps) at d ~ 2.4e-4
    for d, warns in ((3e-3, False), (1e-5, True)):
        b = np.array([[1.0, 0.0, 0.0], [np.cos(d), np.sin(d), 0.0]])
        with warnings.catch_warnings():
            warnings.simplefilter("error" if not warns else "ignore")
            chasles.so3_align(b, b)
        if warns:
            with pytest.warns(UserWarning, match=r"s2 \+ s3 = .* <= 1.49e-08 s1"):
                chasles.so3_align(b, b)


def test_all_weights_zero_warn_and_give_scipys_identity():
    a, b, _ = vector_set(5, 4, 0.1, False)
    with pytest.warns(UserWarning, match="not determined"):
        ours = chasles.so3_align(a, b, np.zeros(4))
    np.testing.assert_array_equal(ours.matrix, scipy_align(a, b, np.zeros(4))[0])
    assert ours.rssd == 0.0


def test_a_primary_vector_with_the_others_along_it_warns():
    a = np.array([[0.0, 0.0, 1.0], [0.0, 0.0, 2.0]])
    with pytest.warns(UserWarning, match="the rotation about the primary vector is not determined"):
        ours = chasles.so3_align(a, a, [np.inf, 1.0])
    np.testing.assert_array_equal(ours.matrix, scipy_align(a, a, [np.inf, 1.0], sensitivity=False)[0])


# ---- se3_align and sim3_align --------------------------------------------------------------------


def point_set(seed, n, noise, weighted, similarity):
    rng = np.random.default_rng(seed)
    b = rng.normal(size=(n, 3)) * [3.0, 2.0, 1.0] + rng.normal(size=3) * 10
    xi = np.concatenate([rng.normal(size=3) * 10, rng.normal(size=3), [rng.uniform(-2, 2) if similarity else 0.0]])
    g = chasles.sim3_exp(xi)
    a = chasles.sim3_act(g, b) + noise * rng.normal(size=(n, 3))
    w = rng.uniform(0.0, 3.0, n) if weighted else None
    if weighted:
        w[:3] += 0.5  # at least 3 points of weight > 0
    return a, b, w, g


@given(st.integers(0, 2**32 - 1), st.integers(3, 40), st.sampled_from([0.0, 0.01, 0.5]), st.booleans())
def test_se3_and_sim3_align_are_kabsch_and_umeyama(seed, n, noise, weighted):
    a, b, w, _ = point_set(seed, n, noise, weighted, True)
    w1 = np.ones(n) if w is None else w
    mb = w1 @ b / w1.sum()
    s = signed_singular_values(a - w1 @ a / w1.sum(), b - mb, w1)
    condition = s[0] / (s[1] + s[2])
    if condition > 1e6:
        return
    for align, scale in ((chasles.se3_align, False), (chasles.sim3_align, True)):
        ours = align(a, b, w)
        ref = umeyama(a, b, w1, scale)
        np.testing.assert_allclose(ours.matrix, ref, atol=1e-12 * condition * (1 + np.abs(ref).max()))
        assert ours.rssd == pytest.approx(
            direct_rssd(ours.matrix, a, b, w1), rel=1e-12, abs=8 * EPS * np.sqrt(np.sum(w1 * np.sum(a**2, axis=1)))
        )
    # the rotation is scipy's align_vectors of the centred points
    R = scipy_align(a - w1 @ a / w1.sum(), b - mb, w1, sensitivity=False)[0]
    np.testing.assert_allclose(chasles.se3_align(a, b, w).matrix[:3, :3], R, atol=1e-13 * condition)


def test_noise_free_points_give_their_transform():
    for seed in range(50):
        a, b, _, g = point_set(seed, 3 + seed % 10, 0.0, False, True)
        fit = chasles.sim3_align(a, b)
        # the data carry rounding of eps |a|, relative eps |a| / s to the scaled spread
        s = chasles.Sim3.from_matrix(g).scale
        tol = 64 * EPS * (np.abs(a).max() / s)
        np.testing.assert_allclose(fit.matrix[:3, :3] / s, g[:3, :3] / s, atol=tol)
        np.testing.assert_allclose(fit.matrix[:3, 3], g[:3, 3], atol=tol * s * (1 + np.abs(b).max()))
        assert fit.rssd <= 16 * EPS * np.abs(a).max() * np.sqrt(len(a))
        rigid = g.copy()
        rigid[:3, :3] /= s
        a_rigid = chasles.se3_act(rigid, b)
        tol = 64 * EPS * np.abs(a_rigid).max()
        np.testing.assert_allclose(chasles.se3_align(a_rigid, b).matrix, rigid, atol=tol * (1 + np.abs(b).max()))


def test_a_reflected_set_gives_a_rotation():
    rng = np.random.default_rng(9)
    b = rng.normal(size=(10, 3)) * [3.0, 2.0, 1.0]
    Q = chasles.so3_exp(rng.normal(size=3))
    a = b @ np.diag([1.0, 1.0, -1.0]) @ Q.T  # a = Q P b, P a mirror: the best orthogonal map is Q P
    U, _, Vt = np.linalg.svd((a - a.mean(0)).T @ (b - b.mean(0)))
    assert np.linalg.det(U @ Vt) < 0
    for fit in (chasles.se3_align(a, b), chasles.sim3_align(a, b)):
        assert np.linalg.det(fit.matrix[:3, :3]) > 0
    np.testing.assert_allclose(chasles.se3_align(a, b).matrix, umeyama(a, b, np.ones(10), False), atol=1e-13)
    np.testing.assert_allclose(chasles.sim3_align(a, b).matrix, umeyama(a, b, np.ones(10), True), atol=1e-13)
    R = chasles.so3_align(a, b).matrix
    assert np.linalg.det(R) > 0
    np.testing.assert_allclose(R, scipy_align(a, b, sensitivity=False)[0], atol=1e-13)


def test_integer_weights_are_the_points_repeated():
    a, b, _, _ = point_set(10, 8, 0.3, False, True)
    k = np.array([1, 2, 0, 3, 1, 0, 2, 1])
    for align in (chasles.se3_align, chasles.sim3_align, chasles.so3_align):
        weighted, repeated = align(a, b, k.astype(float)), align(np.repeat(a, k, 0), np.repeat(b, k, 0))
        np.testing.assert_allclose(weighted.matrix, repeated.matrix, atol=1e-13)
        assert weighted.rssd == pytest.approx(repeated.rssd, rel=1e-13)


# ---- errors ----------------------------------------------------------------------------------------------

B3 = np.array([[0.0, 0, 0], [1, 0, 0], [0, 2, 0], [0, 0, 3]])
ALIGNS = [chasles.so3_align, chasles.se3_align, chasles.sim3_align]


@pytest.mark.parametrize("align", ALIGNS, ids=lambda f: f.__name__)
@pytest.mark.parametrize(
    ("a", "b", "weights", "error", "message"),
    [
        (B3[:, :2], B3, None, ValueError, r"\(a\): expected shape .*\(N, 3\).*, got \(4, 2\)"),
        (B3, B3[None], None, ValueError, r"\(b\): expected shape .*\(N, 3\).*, got \(1, 4, 3\)"),
        (B3, B3[:3], None, ValueError, r"\(a, b\): expected the same shape, got \(4, 3\) and \(3, 3\)"),
        (np.zeros((0, 3)), np.zeros((0, 3)), None, ValueError, r"\(a\): expected shape .*, got \(0, 3\)"),
        (B3 + 0j, B3, None, TypeError, r"\(a\): expected real numbers \(float64\), got dtype complex128"),
        (None, B3, None, TypeError, r"\(a\): expected real numbers \(float64\), got NoneType"),
        (B3, "abc", None, TypeError, r"\(b\): expected real numbers \(float64\), got str"),
        (B3, [[1, 2, 3], [4, 5]], None, ValueError, r"\(b\): could not convert to an array"),
        (np.where(B3 == 3, np.nan, B3), B3, None, ValueError, r"\(a\): expected finite numbers, got a\[3, 2\] = nan"),
        (B3, np.where(B3 == 2, np.inf, B3), None, ValueError, r"\(b\): expected finite numbers, got b\[2, 1\] = inf"),
        (B3, B3, [1.0, 2.0], ValueError, r"\(weights\): expected shape \(4,\), one weight per row, got \(2,\)"),
        (B3, B3, [[1.0, 2.0, 3.0, 4.0]], ValueError, r"\(weights\): expected shape \(4,\).*, got \(1, 4\)"),
        (B3, B3, ["a", "b", "c", "d"], TypeError, r"\(weights\): expected real numbers"),
        (B3, B3, [1.0, -1.0, 1.0, 1.0], ValueError, r"\(weights\): expected .*weights >= 0.*, got weights\[1\] = -1.0"),
        (B3, B3, [1.0, 1.0, np.nan, 1.0], ValueError, r"\(weights\): expected .*, got weights\[2\] = nan"),
        (B3 * 1e200, B3 * 1e200, None, ValueError, r"\(a, b\): the weighted sums overflowed"),
    ],
)
def test_refusals_name_the_argument_and_what_came(align, a, b, weights, error, message):
    with pytest.raises(error, match=rf"^{align.__name__}{message}"):
        align(a, b, weights)


@pytest.mark.parametrize(
    ("call", "message"),
    [
        (
            lambda: chasles.so3_align(B3, B3, [np.inf, 1.0, np.inf, 1.0]),
            r"so3_align\(weights\): expected at most one infinite weight \(the primary vector\), "
            r"got weights\[0\] and weights\[2\] infinite",
        ),
        (lambda: chasles.so3_align(B3, B3[::-1], [np.inf, 1, 1, 1]), r"so3_align\(a\): the primary vector"),
        (
            lambda: chasles.so3_align(B3[::-1], B3, [np.inf, 1, 1, 1]),
            r"so3_align\(b\): the primary vector \(weights\[0\] = inf\) b\[0\] has length 0",
        ),
        (
            lambda: chasles.so3_align([0.0, 0.0, 0.0], [1.0, 0.0, 0.0]),
            r"so3_align\(a\): the single vector a\[0\] has length 0",
        ),
        (lambda: chasles.so3_align(B3[1:2], B3[1:2] * 0), r"so3_align\(b\): the single vector b\[0\] has length 0"),
        (
            lambda: chasles.se3_align(B3[:2], B3[:2]),
            r"se3_align\(a\): expected shape \(N, 3\) with N >= 3 points, got \(2, 3\)",
        ),
        (
            lambda: chasles.sim3_align(B3, B3, [1.0, np.inf, 1, 1]),
            r"sim3_align\(weights\): expected finite weights >= 0, got weights\[1\] = inf",
        ),
        (
            lambda: chasles.se3_align(B3, B3, np.zeros(4)),
            r"se3_align\(weights\): expected at least one weight > 0, got all 4 weights 0",
        ),
        (
            lambda: chasles.se3_align(B3[:, [0, 0, 0]], B3),
            r"se3_align\(a, b\): the points do not determine the rotation: they are collinear "
            r".* s2 \+ s3 = .* <= 1.49e-08 s1",
        ),
        (
            lambda: chasles.sim3_align(B3, B3, [1.0, 1.0, 0.0, 0.0]),
            r"sim3_align\(a, b\): the points do not determine the rotation",
        ),
    ],
)
def test_special_refusals(call, message):
    with pytest.raises(ValueError, match=rf"^{message}"):
        call()


def test_scipys_refusals_are_refusals():
    for a, b, w in ((B3, B3, [np.inf, 1, np.inf, 1]), (B3, B3[::-1], [np.inf, 1, 1, 1]), (B3, B3, [-1.0, 1, 1, 1])):
        with pytest.raises(ValueError):
            Rotation.align_vectors(a, b, w)
        with pytest.raises(ValueError):
            chasles.so3_align(a, b, w)
