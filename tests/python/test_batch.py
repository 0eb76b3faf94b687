"""The array functions (so3_*, se3_*, twist_*): values against independent
references (scipy.linalg.expm, scipy.spatial.transform.Rotation, numpy
matmul), broadcasting, dtypes, memory layouts, NaN and errors (the GIL and
threads: test_threads.py)."""

import numpy as np
import pytest
from helpers import hat3, hat6
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.linalg import expm
from scipy.spatial.transform import Rotation

import chasles

PI = np.pi
EPS32 = float(np.finfo(np.float32).eps)

# Angles at and around every branch of exp and log: 0, the Taylor cutoffs
# (theta^2 = eps^(1/3): 1.8e-3 in double, 7e-2 in float), pi/2 (log's switch
# to the symmetric part), near pi and exactly pi.
SPECIAL_ANGLES = np.array(
    [0.0, 1e-12, 1e-9, 1e-6, 1e-4, 2.46e-3, 7.02e-2, 0.5, 1.0, PI / 2, 2.0, 3.0, PI - 1e-4, PI - 1e-6, PI - 1e-9, PI]
)


# ---- references, written from the definitions --------------------------------


def adjoint_ref(g):
    R, p = g[:3, :3], g[:3, 3]
    A = np.zeros((6, 6))
    A[:3, :3] = R
    A[:3, 3:] = hat3(p) @ R
    A[3:, 3:] = R
    return A


# ---- samples ----------------------------------------------------------------


def unit_vectors(n, rng):
    u = rng.normal(size=(n, 3))
    return u / np.linalg.norm(u, axis=1, keepdims=True)


def rotvecs(n, rng):
    """n rotation vectors: every special angle, exactly pi about each
    coordinate axis (R = diag(1, -1, -1), ...), then uniform angles in [0, pi]."""
    k = len(SPECIAL_ANGLES)
    angles = np.concatenate([SPECIAL_ANGLES, rng.uniform(0, PI, max(0, n - k))])[:n]
    w = unit_vectors(n, rng) * angles[:, None]
    if n >= k + 3:
        w[k : k + 3] = PI * np.eye(3)
    return w


def rotations(n, rng):
    return Rotation.from_rotvec(rotvecs(n, rng)).as_matrix()


def twists(n, rng):
    return np.concatenate([rng.normal(scale=3.0, size=(n, 3)), rotvecs(n, rng)], axis=1)


def poses(n, rng):
    g = np.zeros((n, 4, 4))
    g[:, :3, :3] = rotations(n, rng)
    g[:, :3, 3] = rng.normal(scale=3.0, size=(n, 3))
    g[:, 3, 3] = 1.0
    return g


def sample(kind, batch, rng):
    """float64 operands of a kind, of batch shape `batch`."""
    n = int(np.prod(batch, dtype=int))
    out = {
        "rotvec": lambda: rotvecs(n, rng),
        "rot": lambda: rotations(n, rng),
        "point": lambda: rng.normal(scale=3.0, size=(n, 3)),
        "quat": lambda: rng.normal(size=(n, 4)),
        "twist": lambda: twists(n, rng),
        "wrench": lambda: rng.normal(size=(n, 6)),
        "pose": lambda: poses(n, rng),
        "skew": lambda: np.array([hat3(w) for w in rng.normal(size=(n, 3))]).reshape(n, 3, 3),
        "twistmat": lambda: np.array([hat6(x) for x in rng.normal(size=(n, 6))]).reshape(n, 4, 4),
        "t": lambda: rng.uniform(-0.5, 1.5, size=n),
    }[kind]()
    return out.reshape(tuple(batch) + out.shape[1:])


# name: (operand kinds, output core shape)
FUNCS = {
    "so3_exp": (("rotvec",), (3, 3)),
    "so3_log": (("rot",), (3,)),
    "so3_compose": (("rot", "rot"), (3, 3)),
    "so3_inverse": (("rot",), (3, 3)),
    "so3_act": (("rot", "point"), (3,)),
    "so3_hat": (("rotvec",), (3, 3)),
    "so3_vee": (("skew",), (3,)),
    "so3_from_quat": (("quat",), (3, 3)),
    "so3_as_quat": (("rot",), (4,)),
    "so3_interpolate": (("rot", "rot", "t"), (3, 3)),
    "so3_normalize": (("rot",), (3, 3)),
    "se3_exp": (("twist",), (4, 4)),
    "se3_log": (("pose",), (6,)),
    "se3_compose": (("pose", "pose"), (4, 4)),
    "se3_inverse": (("pose",), (4, 4)),
    "se3_act": (("pose", "point"), (3,)),
    "se3_adjoint": (("pose",), (6, 6)),
    "se3_act_twist": (("pose", "twist"), (6,)),
    "se3_act_wrench": (("pose", "wrench"), (6,)),
    "se3_interpolate": (("pose", "pose", "t"), (4, 4)),
    "se3_normalize": (("pose",), (4, 4)),
    "se3_hat": (("twist",), (4, 4)),
    "se3_vee": (("twistmat",), (6,)),
    "se3_from_quat": (("quat", "point"), (4, 4)),
}
NAMES = sorted(FUNCS)
CORE_NDIM = {"rot": 2, "pose": 2, "skew": 2, "twistmat": 2, "t": 0}


def core_ndim(kind):
    return CORE_NDIM.get(kind, 1)


def operands(name, batch, rng):
    return [sample(k, batch, rng) for k in FUNCS[name][0]]


def test_every_documented_function_exists():
    required = [
        "so3_exp",
        "so3_log",
        "so3_compose",
        "so3_inverse",
        "so3_act",
        "so3_hat",
        "so3_vee",
        "so3_from_quat",
        "so3_as_quat",
        "se3_exp",
        "se3_log",
        "se3_compose",
        "se3_inverse",
        "se3_act",
        "se3_adjoint",
        "se3_hat",
        "se3_vee",
    ]
    for name in required + NAMES:
        f = getattr(chasles, name)
        assert "Args:" in f.__doc__ and "Returns:" in f.__doc__, name


# ---- values against independent references (float64) ------------------------


def test_so3_exp_equals_expm_of_hat():
    w = rotvecs(60, np.random.default_rng(1))
    R = chasles.so3_exp(w)
    assert R.shape == (60, 3, 3) and R.dtype == np.float64
    for i in range(60):
        np.testing.assert_allclose(R[i], expm(hat3(w[i])), rtol=0, atol=4e-15)
    np.testing.assert_allclose(R, Rotation.from_rotvec(w).as_matrix(), rtol=0, atol=2e-15)


def test_so3_log_equals_scipy_rotvec():
    rng = np.random.default_rng(2)
    w = rotvecs(200, rng)
    R = Rotation.from_rotvec(w).as_matrix()
    got = chasles.so3_log(R)
    angle = np.linalg.norm(got, axis=1)
    assert np.all(angle <= PI * (1 + 2e-16))
    ref = Rotation.from_matrix(R).as_rotvec()
    # At (and within rounding of) pi, w and -w are the same rotation.
    flip = (np.sum(got * ref, axis=1) < 0) & (angle > PI - 1e-6)
    ref[flip] = -ref[flip]
    np.testing.assert_allclose(got, ref, rtol=0, atol=1e-14)
    # and exp(log(R)) is R again, through an independent exp
    for i in range(0, 200, 7):
        np.testing.assert_allclose(expm(hat3(got[i])), R[i], rtol=0, atol=4e-15)


def test_so3_log_at_exactly_pi_is_finite_and_valid():
    R = np.array([np.diag([1.0, -1.0, -1.0]), np.diag([-1.0, 1.0, -1.0]), np.diag([-1.0, -1.0, 1.0])])
    w = chasles.so3_log(R)
    assert np.all(np.isfinite(w))
    np.testing.assert_allclose(np.linalg.norm(w, axis=1), PI, rtol=1e-15)
    np.testing.assert_allclose(np.abs(w), PI * np.eye(3), atol=1e-15)
    np.testing.assert_allclose(chasles.so3_exp(w), R, atol=1e-15)


def test_so3_tiny_angles_keep_every_digit():
    w = np.array([[1e-9, -2e-9, 3e-9], [1e-12, 0.0, 0.0], [0.0, 0.0, 0.0]])
    R = chasles.so3_exp(w)
    off = ~np.eye(3, dtype=bool)
    for i in range(2):
        K = hat3(w[i])
        # exp([w]) - I = [w] + [w]^2 / 2 + O(theta^3): off the diagonal, every digit
        np.testing.assert_allclose((R[i] - np.eye(3))[off], (K + K @ K / 2)[off], rtol=1e-15, atol=0)
    np.testing.assert_array_equal(R[2], np.eye(3))
    np.testing.assert_allclose(chasles.so3_log(R), w, rtol=1e-15, atol=0)


def test_so3_compose_inverse_act_equal_matmul():
    rng = np.random.default_rng(3)
    a, b = rotations(50, rng), rotations(50, rng)
    p = rng.normal(size=(50, 3))
    np.testing.assert_allclose(chasles.so3_compose(a, b), a @ b, rtol=0, atol=1e-15)
    np.testing.assert_array_equal(chasles.so3_inverse(a), np.swapaxes(a, -1, -2))
    np.testing.assert_allclose(chasles.so3_act(a, p), np.einsum("nij,nj->ni", a, p), rtol=0, atol=1e-14)


def test_so3_hat_vee():
    w = np.random.default_rng(4).normal(size=(20, 3))
    W = chasles.so3_hat(w)
    np.testing.assert_array_equal(W, np.array([hat3(x) for x in w]))
    np.testing.assert_array_equal(chasles.so3_vee(W), w)
    p = np.random.default_rng(5).normal(size=(20, 3))
    np.testing.assert_allclose(np.einsum("nij,nj->ni", W, p), np.cross(w, p), atol=1e-15)


def test_quaternions_match_scipy_in_both_orders():
    rng = np.random.default_rng(6)
    q = rng.normal(size=(100, 4))  # any nonzero norm: normalized
    np.testing.assert_allclose(chasles.so3_from_quat(q), Rotation.from_quat(q).as_matrix(), atol=2e-15)
    q_first = q[:, [3, 0, 1, 2]]
    np.testing.assert_array_equal(chasles.so3_from_quat(q_first, scalar_first=True), chasles.so3_from_quat(q))

    R = rotations(100, rng)
    got = chasles.so3_as_quat(R)
    ref = Rotation.from_matrix(R).as_quat()
    sign = np.sign(np.sum(got * ref, axis=1))[:, None]  # q and -q: the same rotation
    np.testing.assert_allclose(got, sign * ref, atol=2e-15)
    np.testing.assert_allclose(np.linalg.norm(got, axis=1), 1.0, rtol=2e-16 * 4)
    np.testing.assert_array_equal(chasles.so3_as_quat(R, scalar_first=True), got[:, [3, 0, 1, 2]])


def test_poses_of_quaternions_and_translations_match_scipy():
    from scipy.spatial.transform import RigidTransform

    rng = np.random.default_rng(7)
    q, t = rng.normal(size=(100, 4)), rng.normal(size=(100, 3))
    want = RigidTransform.from_components(t, Rotation.from_quat(q)).as_matrix()
    np.testing.assert_allclose(chasles.se3_from_quat(q, t), want, atol=2e-15)
    np.testing.assert_array_equal(
        chasles.se3_from_quat(q[:, [3, 0, 1, 2]], t, scalar_first=True), chasles.se3_from_quat(q, t)
    )
    # rotation block: so3_from_quat's, bit for bit; broadcasting: one translation for every quaternion
    g = chasles.se3_from_quat(q, t[0])
    np.testing.assert_array_equal(g[:, :3, :3], chasles.so3_from_quat(q))
    np.testing.assert_array_equal(g[:, :3, 3], np.broadcast_to(t[0], (100, 3)))
    np.testing.assert_array_equal(g[:, 3], np.broadcast_to([0.0, 0.0, 0.0, 1.0], (100, 4)))
    bad = chasles.se3_from_quat([[0.0, 0, 0, 0], [0, 0, 0, 1]], [1.0, 2, 3])
    assert np.all(np.isnan(bad[0, :3, :3])) and np.array_equal(
        bad[1], chasles.se3_from_quat([0, 0, 0, 1.0], [1.0, 2, 3])
    )


def test_zero_or_non_finite_quaternion_gives_nan():
    q = np.array([[0.0, 0, 0, 0], [np.inf, 0, 0, 1], [0, 0, 0, 1]])
    R = chasles.so3_from_quat(q)
    assert np.all(np.isnan(R[:2]))
    np.testing.assert_array_equal(R[2], np.eye(3))


def test_se3_exp_equals_expm_of_hat():
    xi = twists(60, np.random.default_rng(7))
    g = chasles.se3_exp(xi)
    assert g.shape == (60, 4, 4)
    for i in range(60):
        ref = expm(hat6(xi[i]))
        np.testing.assert_allclose(g[i], ref, rtol=0, atol=1e-14 * max(1.0, np.abs(ref).max()))
    np.testing.assert_array_equal(g[:, 3], np.tile([0.0, 0, 0, 1], (60, 1)))


def test_se3_log_inverts_expm():
    rng = np.random.default_rng(8)
    g = poses(100, rng)
    xi = chasles.se3_log(g)
    assert np.all(np.linalg.norm(xi[:, 3:], axis=1) <= PI * (1 + 2e-16))
    ref_w = Rotation.from_matrix(g[:, :3, :3]).as_rotvec()
    flip = (np.sum(xi[:, 3:] * ref_w, axis=1) < 0) & (np.linalg.norm(ref_w, axis=1) > PI - 1e-6)
    ref_w[flip] = -ref_w[flip]
    np.testing.assert_allclose(xi[:, 3:], ref_w, atol=1e-14)
    for i in range(100):
        np.testing.assert_allclose(expm(hat6(xi[i])), g[i], rtol=0, atol=1e-13)


def test_se3_compose_inverse_act_equal_matmul():
    rng = np.random.default_rng(9)
    a, b = poses(50, rng), poses(50, rng)
    p = rng.normal(size=(50, 3))
    np.testing.assert_allclose(chasles.se3_compose(a, b), a @ b, rtol=0, atol=1e-14)
    np.testing.assert_allclose(chasles.se3_inverse(a), np.linalg.inv(a), rtol=0, atol=1e-13)
    ph = np.concatenate([p, np.ones((50, 1))], axis=1)
    np.testing.assert_allclose(chasles.se3_act(a, p), np.einsum("nij,nj->ni", a, ph)[:, :3], rtol=0, atol=1e-14)


def test_se3_adjoint_and_frame_changes():
    rng = np.random.default_rng(10)
    g = poses(30, rng)
    xi = rng.normal(size=(30, 6))
    F = rng.normal(size=(30, 6))
    Ad = chasles.se3_adjoint(g)
    np.testing.assert_allclose(Ad, np.array([adjoint_ref(x) for x in g]), atol=1e-14)
    for i in range(30):  # g [xi] g^-1 = [Ad_g xi]
        lhs = g[i] @ hat6(xi[i]) @ np.linalg.inv(g[i])
        np.testing.assert_allclose(lhs, hat6(Ad[i] @ xi[i]), atol=1e-12)
    xi_a = chasles.se3_act_twist(g, xi)
    F_a = chasles.se3_act_wrench(g, F)
    np.testing.assert_allclose(xi_a, np.einsum("nij,nj->ni", Ad, xi), atol=1e-13)
    np.testing.assert_allclose(F_a, np.einsum("nji,nj->ni", np.linalg.inv(Ad), F), atol=1e-12)
    # the power xi . F is the same in both frames
    np.testing.assert_allclose(np.sum(xi_a * F_a, axis=1), np.sum(xi * F, axis=1), rtol=1e-12, atol=1e-12)


def test_se3_hat_vee():
    xi = np.random.default_rng(11).normal(size=(20, 6))
    X = chasles.se3_hat(xi)
    np.testing.assert_array_equal(X, np.array([hat6(x) for x in xi]))
    np.testing.assert_array_equal(chasles.se3_vee(X), xi)


def test_interpolate_ends_and_middle():
    rng = np.random.default_rng(12)
    a, b = rotations(20, rng), rotations(20, rng)
    np.testing.assert_allclose(chasles.so3_interpolate(a, b, 0.0), a, atol=1e-15)
    np.testing.assert_allclose(chasles.so3_interpolate(a, b, 1.0), b, atol=1e-12)
    axis = unit_vectors(1, rng)[0]
    half = chasles.so3_interpolate(np.eye(3), chasles.so3_exp(2.0 * axis), 0.5)
    np.testing.assert_allclose(half, chasles.so3_exp(1.0 * axis), atol=1e-15)
    ga, gb = poses(20, rng), poses(20, rng)
    np.testing.assert_allclose(chasles.se3_interpolate(ga, gb, 0.0), ga, atol=1e-14)
    np.testing.assert_allclose(chasles.se3_interpolate(ga, gb, 1.0), gb, atol=1e-11)
    t = np.linspace(0, 1, 5)
    out = chasles.se3_interpolate(ga[0], gb[0], t)
    assert out.shape == (5, 4, 4)
    np.testing.assert_array_equal(out[2], chasles.se3_interpolate(ga[0], gb[0], t[2]))


def nearest_rotation_svd(M):
    """The rotation nearest to M in the Frobenius norm, by SVD (an oracle
    independent of chasles' Jacobi iteration on a quaternion)."""
    U, _, Vt = np.linalg.svd(M)
    D = np.eye(3)
    D[2, 2] = np.sign(np.linalg.det(U @ Vt))
    return U @ D @ Vt


def rotation_drift(R):
    """max |R^T R - I|: how far matrices are from orthonormal."""
    return float(np.abs(np.swapaxes(R, -1, -2) @ R - np.eye(3)).max())


def test_normalize_is_the_nearest_rotation():
    rng = np.random.default_rng(21)
    R = rotations(200, rng)
    np.testing.assert_allclose(chasles.so3_normalize(R), R, atol=1e-15)  # rotations stay
    M = R + rng.normal(scale=0.2, size=R.shape)  # far off SO(3)
    M[:5] *= -1  # reflections
    M[5] = np.outer([1.0, 2.0, 3.0], [0.5, -1.0, 2.0])  # rank one: its nearest rotation is not unique
    N = chasles.so3_normalize(M)
    assert rotation_drift(N) <= 1e-15 and np.allclose(np.linalg.det(N), 1.0, atol=1e-15)
    for k in range(6, 200):
        np.testing.assert_allclose(N[k], nearest_rotation_svd(M[k]), atol=1e-13)
        assert np.array_equal(N[k], chasles.SO3.from_matrix_projected(M[k]).as_matrix())
    # and no closer one: the distance to the SVD's rotation is the minimum
    assert np.linalg.norm(M[5] - N[5]) <= np.linalg.norm(M[5] - nearest_rotation_svd(M[5])) + 1e-12
    # poses: the rotation block projected, the translation kept, the bottom row (0, 0, 0, 1)
    G = poses(50, rng)
    G[:, :3, :3] += rng.normal(scale=0.1, size=(50, 3, 3))
    G[:, 3, :] = 7.0
    H = chasles.se3_normalize(G)
    np.testing.assert_array_equal(H[:, :3, :3], chasles.so3_normalize(G[:, :3, :3]))
    np.testing.assert_array_equal(H[:, :3, 3], G[:, :3, 3])
    np.testing.assert_array_equal(H[:, 3, :], np.tile([0.0, 0.0, 0.0, 1.0], (50, 1)))
    # float32 in, float32 out, as orthonormal as float32 allows
    N32 = chasles.so3_normalize(M[6:].astype(np.float32))
    assert N32.dtype == np.float32 and rotation_drift(N32.astype(np.float64)) <= 1e-6


def test_normalize_gives_nan_for_non_finite_matrices():
    M = np.stack([np.eye(3), np.eye(3)])
    M[1, 0, 2] = np.nan
    N = chasles.so3_normalize(M)
    assert np.array_equal(N[0], np.eye(3)) and np.isnan(N[1]).all()
    G = np.stack([np.eye(4)] * 2)
    G[1, 1, 1] = np.inf
    assert np.isnan(chasles.se3_normalize(G)[1, :3, :3]).all()


def test_drift_builds_up_in_products_that_feed_on_themselves():
    """scipy's test_multiplication_stability, as scipy sets it up: 1000
    rotations rs, and for each of 50 rotations q, rs = rs @ q @ rs. Each
    product is off SO(3) by an ulp or so, and the error of rs is squared
    into the next round: the matrices end far from rotations (max
    |R^T R - I| = 1.05). One so3_normalize per round keeps them rotations,
    to the rounding of their entries: computed in long double, max
    |R^T R - I| is 4.5 eps here and 5.2 eps on scipy's own random rotation
    matrices (in double, 5.0 for both). The bound is 8 eps."""
    qs = Rotation.random(50, random_state=0).as_matrix()
    drifting = normalized = Rotation.random(1000, random_state=1).as_matrix()
    for q in qs:
        drifting = chasles.so3_compose(chasles.so3_compose(drifting, q), drifting)
        normalized = chasles.so3_normalize(chasles.so3_compose(chasles.so3_compose(normalized, q), normalized))
    assert rotation_drift(drifting) > 0.5
    assert rotation_drift(normalized) <= 8 * np.finfo(float).eps
    assert rotation_drift(Rotation.random(1000, random_state=1).as_matrix()) >= 4 * np.finfo(float).eps


@settings(max_examples=200, deadline=None)
@given(
    axis=st.tuples(*[st.floats(-1, 1)] * 3).filter(lambda a: np.linalg.norm(a) > 1e-3),
    angle=st.one_of(st.sampled_from(list(SPECIAL_ANGLES)), st.floats(0, PI)),
    v=st.tuples(*[st.floats(-100, 100)] * 3),
)
def test_exp_log_against_references_hypothesis(axis, angle, v):
    w = angle * np.asarray(axis) / np.linalg.norm(axis)
    R = chasles.so3_exp(w)
    np.testing.assert_allclose(R, expm(hat3(w)), rtol=0, atol=4e-15)
    back = chasles.so3_log(R)
    if angle < PI - 1e-7:  # away from pi the log is unique
        np.testing.assert_allclose(back, w, rtol=0, atol=1e-14 + 1e-13 * (angle > 3))
    else:
        np.testing.assert_allclose(expm(hat3(back)), R, atol=1e-14)
    xi = np.concatenate([v, w])
    g = chasles.se3_exp(xi)
    np.testing.assert_allclose(g, expm(hat6(xi)), rtol=0, atol=2e-14 * max(1.0, np.abs(v).max()))
    np.testing.assert_allclose(expm(hat6(chasles.se3_log(g))), g, rtol=0, atol=3e-14 * max(1.0, np.abs(v).max()))


# ---- float32: the float kernels, eps-scaled tolerances -----------------------


@pytest.mark.parametrize("name", NAMES)
def test_float32_close_to_float64(name):
    """float32 in: the float kernels, within a few float eps of the float64
    result of the same (rounded) inputs."""
    rng = np.random.default_rng(13)
    args32 = [a.astype(np.float32) for a in operands(name, (64,), rng)]
    args64 = [a.astype(np.float64) for a in args32]
    out32 = getattr(chasles, name)(*args32)
    assert out32.dtype == np.float32
    ref = getattr(chasles, name)(*args64)
    if name in ("so3_log", "se3_log", "so3_interpolate", "se3_interpolate"):
        # Within ~1e-3 of pi the log of a rounded matrix is ill-conditioned
        # (w and -w at pi): compare the other elements.
        R = args64[0][..., :3, :3]
        if "interpolate" in name:
            R = chasles.so3_compose(chasles.so3_inverse(R), args64[1][..., :3, :3])
        keep = np.linalg.norm(chasles.so3_log(R), axis=-1) < PI - 1e-2
        assert keep.sum() > 40
        out32, ref = out32[keep], ref[keep]
    scale = max(1.0, float(np.abs(ref).max()))
    np.testing.assert_allclose(out32, ref, rtol=0, atol=64 * EPS32 * scale)


def test_float32_exp_log_against_references():
    w = rotvecs(40, np.random.default_rng(14)).astype(np.float32)
    R = chasles.so3_exp(w)
    assert R.dtype == np.float32
    for i in range(40):
        np.testing.assert_allclose(R[i], expm(hat3(w[i].astype(np.float64))), atol=4 * EPS32)
    xi = twists(40, np.random.default_rng(15)).astype(np.float32)
    g = chasles.se3_exp(xi)
    for i in range(40):
        ref = expm(hat6(xi[i].astype(np.float64)))
        np.testing.assert_allclose(g[i], ref, atol=8 * EPS32 * max(1.0, np.abs(ref).max()))
    # log: exp(log(R)) returns to R (the float32 rounding of R moves log near pi)
    back = chasles.so3_exp(chasles.so3_log(R))
    np.testing.assert_allclose(back, R, atol=16 * EPS32)


# ---- broadcasting -----------------------------------------------------------


@pytest.mark.parametrize("name", NAMES)
@pytest.mark.parametrize("batch", [(), (5,), (3, 4)])
def test_batch_equals_per_element(name, batch):
    rng = np.random.default_rng(16)
    args = operands(name, batch, rng)
    f = getattr(chasles, name)
    out = f(*args)
    assert out.shape == tuple(batch) + FUNCS[name][1]
    assert out.flags.c_contiguous and out.flags.writeable and out.flags.owndata
    for idx in np.ndindex(*batch):
        np.testing.assert_array_equal(out[idx], f(*[a[idx] for a in args]))


@pytest.mark.parametrize("name", [n for n in NAMES if len(FUNCS[n][0]) >= 2])
def test_broadcast_outer_product(name):
    """(1, M) x (N, 1) gives (N, M), element (i, j) from a[j] and b[i]."""
    rng = np.random.default_rng(17)
    kinds = FUNCS[name][0]
    a = sample(kinds[0], (1, 4), rng)
    b = sample(kinds[1], (3, 1), rng)
    rest = [sample(k, (), rng) for k in kinds[2:]]  # a shared t
    f = getattr(chasles, name)
    out = f(a, b, *rest)
    assert out.shape == (3, 4) + FUNCS[name][1]
    for i in range(3):
        for j in range(4):
            np.testing.assert_array_equal(out[i, j], f(a[0, j], b[i, 0], *rest))


def test_one_pose_many_points_and_n_by_n():
    rng = np.random.default_rng(18)
    g = poses(1, rng)[0]
    p = rng.normal(size=(1000, 3))
    out = chasles.se3_act(g, p)
    np.testing.assert_allclose(out, p @ g[:3, :3].T + g[:3, 3], atol=1e-13)
    gs = poses(1000, rng)
    np.testing.assert_allclose(
        chasles.se3_act(gs, p), np.einsum("nij,nj->ni", gs[:, :3, :3], p) + gs[:, :3, 3], atol=1e-13
    )
    # many poses, one point; and every pose with every point
    np.testing.assert_allclose(chasles.se3_act(gs, p[0]), gs[:, :3, :3] @ p[0] + gs[:, :3, 3], atol=1e-13)
    every = chasles.se3_act(gs[:7, None], p[None, :5])
    assert every.shape == (7, 5, 3)
    np.testing.assert_array_equal(every[6, 4], chasles.se3_act(gs[6], p[4]))
    np.testing.assert_array_equal(chasles.so3_act(gs[0, :3, :3], p), chasles.so3_act(gs[0, :3, :3][None], p))


def test_operands_that_stay_put_in_any_layout():
    """An operand constant along the inner axis is read once per run: check
    it in every layout, and stride-0 batch axes (np.broadcast_to)."""
    rng = np.random.default_rng(29)
    g = poses(1, rng)[0]
    p = rng.normal(size=(50, 3))
    want = chasles.se3_act(g, p)
    for label, alt in layouts(g[None]):
        np.testing.assert_array_equal(chasles.se3_act(alt[0], p), want, err_msg=label)
    np.testing.assert_array_equal(chasles.se3_act(np.broadcast_to(g, (50, 4, 4)), p), want)
    w = rng.normal(size=3)
    R = chasles.so3_exp(np.broadcast_to(w, (7, 3)))
    np.testing.assert_array_equal(R, np.broadcast_to(chasles.so3_exp(w), (7, 3, 3)))
    # the second operand stays put, the first moves
    gs = poses(50, rng)
    np.testing.assert_array_equal(
        chasles.se3_compose(gs, np.asfortranarray(g)), chasles.se3_compose(gs, g[None].copy())
    )


def test_broadcast_of_different_batch_ranks():
    rng = np.random.default_rng(19)
    a = poses(5, rng)  # (5, 4, 4)
    b = poses(2, rng).reshape(2, 1, 4, 4)  # (2, 1, 4, 4)
    out = chasles.se3_compose(a, b)
    assert out.shape == (2, 5, 4, 4)
    np.testing.assert_allclose(out, a[None] @ b, atol=1e-14)
    assert chasles.se3_compose(a[0], b).shape == (2, 1, 4, 4)


@pytest.mark.parametrize("name", NAMES)
def test_zero_size_batches(name):
    rng = np.random.default_rng(20)
    f = getattr(chasles, name)
    core = FUNCS[name][1]
    for batch in [(0,), (2, 0), (0, 3)]:
        out = f(*operands(name, batch, rng))
        assert out.shape == batch + core and out.dtype == np.float64
    kinds = FUNCS[name][0]
    if len(kinds) >= 2:
        # (0,) broadcasts with (1,) and with (), not with (2,)
        args = [sample(kinds[0], (0,), rng)] + [sample(k, (1,), rng) for k in kinds[1:]]
        assert f(*args).shape == (0,) + core
        args = [sample(kinds[0], (0,), rng)] + [sample(k, (), rng) for k in kinds[1:]]
        assert f(*args).shape == (0,) + core
        with pytest.raises(ValueError, match="broadcast"):
            f(sample(kinds[0], (0,), rng), *[sample(k, (2,), rng) for k in kinds[1:]])
    assert f(*[a.astype(np.float32) for a in operands(name, (0,), rng)]).dtype == np.float32


# ---- dtypes -----------------------------------------------------------------


@pytest.mark.parametrize("name", NAMES)
def test_dtype_preserved_and_mixed_promotes(name):
    rng = np.random.default_rng(21)
    args = operands(name, (4,), rng)
    f = getattr(chasles, name)
    assert f(*args).dtype == np.float64
    assert f(*[a.astype(np.float32) for a in args]).dtype == np.float32
    if len(args) >= 2:
        mixed = [args[0].astype(np.float32)] + list(args[1:])
        out = f(*mixed)
        assert out.dtype == np.float64
        np.testing.assert_array_equal(out, f(*[a.astype(np.float64) for a in mixed]))


def test_integer_bool_and_list_inputs_follow_numpys_casting():
    """numpy picks the first loop (float32, then float64) to which every
    operand casts safely: bool, int8, uint8, int16, uint16 and float16 run
    in float32, wider integers and lists of Python numbers in float64."""
    w = np.array([[1, 0, 0], [0, 2, 0]])
    out = chasles.so3_exp(w)
    assert out.dtype == np.float64
    np.testing.assert_array_equal(out, chasles.so3_exp(w.astype(np.float64)))
    for dt in (np.int8, np.uint8, np.int16, np.uint16, np.bool_, np.float16):
        got = chasles.so3_hat(w.astype(dt))
        assert got.dtype == np.float32, dt
        np.testing.assert_array_equal(got, chasles.so3_hat(w.astype(dt).astype(np.float32)))
    for dt in (np.int32, np.uint32, np.int64, np.uint64):
        got = chasles.so3_hat(w.astype(dt))
        assert got.dtype == np.float64, dt
        np.testing.assert_array_equal(got, chasles.so3_hat(w.astype(dt).astype(np.float64)))
    np.testing.assert_array_equal(
        chasles.se3_exp([0, 0, 1, 0, 0, 0.5]), chasles.se3_exp(np.array([0, 0, 1, 0, 0, 0.5]))
    )
    assert chasles.so3_log(np.eye(3, dtype=int)).dtype == np.float64
    # int64 with float32: float64, the first loop both cast to safely
    assert chasles.so3_act(np.eye(3, dtype=np.float32), np.array([1, 2, 3])).dtype == np.float64
    # casting= and dtype= choose otherwise, as for any ufunc
    assert chasles.so3_exp(w, dtype=np.float32).dtype == np.float32
    np.testing.assert_array_equal(chasles.so3_exp(w, dtype=np.float32), chasles.so3_exp(w.astype(np.float32)))


def test_python_scalars_do_not_change_the_dtype():
    a = np.eye(3, dtype=np.float32)
    b = chasles.so3_exp(np.array([0, 0, 1], np.float32))
    assert chasles.so3_interpolate(a, b, 0.5).dtype == np.float32
    assert chasles.so3_interpolate(a, b, 1).dtype == np.float32
    assert chasles.so3_interpolate(a, b, np.float64(0.5)).dtype == np.float64
    assert chasles.so3_interpolate(a, b, np.array([0.5])).dtype == np.float64


def test_non_native_byte_order_is_read():
    R = rotations(5, np.random.default_rng(22))
    np.testing.assert_array_equal(chasles.so3_log(R.astype(">f8")), chasles.so3_log(R))
    out = chasles.so3_log(R.astype(">f4"))
    assert out.dtype == np.float32
    np.testing.assert_array_equal(out, chasles.so3_log(R.astype(np.float32)))


@pytest.mark.parametrize(
    "bad",
    [
        np.zeros(3, np.complex128),
        np.zeros(3, object),
        np.array(["a", "b", "c"]),
        np.zeros(3, "datetime64[s]"),
        np.zeros(3, np.longdouble) if np.dtype(np.longdouble).itemsize > 8 else np.zeros(3, np.complex64),
    ],
)
def test_bad_dtype_is_a_type_error(bad):
    with pytest.raises(TypeError, match=r"ufunc 'so3_exp' not supported for the input types"):
        chasles.so3_exp(bad)


def test_bad_dtype_names_the_function():
    with pytest.raises(TypeError, match=r"ufunc 'se3_act' not supported for the input types"):
        chasles.se3_act(np.eye(4), np.zeros((2, 3), complex))
    # an explicit unsafe cast is the caller's choice, as for any ufunc
    with pytest.warns(np.exceptions.ComplexWarning):
        out = chasles.so3_exp(np.zeros(3, np.complex128), casting="unsafe", dtype=np.float64)
    np.testing.assert_array_equal(out, np.eye(3))


# ---- shapes -----------------------------------------------------------------


def test_wrong_core_shape_messages_name_the_function_and_the_sizes():
    with pytest.raises(
        ValueError,
        match=r"^se3_exp: Input operand 0 has a mismatch in its core dimension 0, "
        r"with gufunc signature \(6\)->\(4,4\) \(size 3 is different from 6\)$",
    ):
        chasles.se3_exp(np.zeros((5, 3)))
    with pytest.raises(
        ValueError,
        match=r"so3_log: Input operand 0 does not have enough dimensions \(has 1, "
        r"gufunc core with signature \(3,3\)->\(3\) requires 2\)",
    ):
        chasles.so3_log(np.zeros(3))
    with pytest.raises(ValueError, match=r"so3_exp: Input operand 0 does not have enough dimensions \(has 0"):
        chasles.so3_exp(1.0)
    with pytest.raises(ValueError, match=r"se3_act: Input operand 1 has a mismatch .*\(size 4 is different from 3\)"):
        chasles.se3_act(np.eye(4), np.zeros((10, 4)))
    with pytest.raises(ValueError, match=r"so3_interpolate: Input operand 1 has a mismatch in its core dimension 0"):
        chasles.so3_interpolate(np.eye(3), np.eye(4), 0.5)


def test_non_broadcastable_batches_name_both_shapes():
    with pytest.raises(ValueError, match=r"could not be broadcast .*\(2,4,4\).* \(3,4,4\)"):
        chasles.se3_compose(np.zeros((2, 4, 4)), np.zeros((3, 4, 4)))
    with pytest.raises(ValueError, match=r"could not be broadcast .*\(4,2,4,4\).* \(3,3\)"):
        chasles.se3_act(np.zeros((4, 2, 4, 4)), np.zeros((3, 3)))


def test_ragged_input_is_a_value_error():
    with pytest.raises(ValueError):
        chasles.so3_exp([[1.0, 2.0, 3.0], [1.0, 2.0]])


# ---- memory layouts ---------------------------------------------------------


def layouts(a):
    """The same values in other memory layouts."""
    yield "strided", np.repeat(a, 2, axis=0)[::2]
    yield "reversed", a[::-1].copy()[::-1]
    yield "fortran", np.asfortranarray(a)
    yield "transposed", np.ascontiguousarray(np.moveaxis(a, 0, -1)).transpose((a.ndim - 1,) + tuple(range(a.ndim - 1)))
    ro = a.copy()
    ro.flags.writeable = False
    yield "read-only", ro
    un = np.zeros(a.nbytes + 1, np.uint8)[1:].view(a.dtype).reshape(a.shape)
    un[...] = a
    assert not un.flags.aligned
    yield "unaligned", un


@pytest.mark.parametrize("name", NAMES)
@pytest.mark.parametrize("dtype", [np.float64, np.float32])
def test_any_layout_gives_the_same_result(name, dtype):
    rng = np.random.default_rng(23)
    args = [a.astype(dtype) for a in operands(name, (6,), rng)]
    f = getattr(chasles, name)
    want = f(*args)
    for i, a in enumerate(args):
        for label, alt in layouts(a):
            np.testing.assert_array_equal(alt, a)
            got = f(*args[:i], alt, *args[i + 1 :])
            assert got.flags.c_contiguous and got.dtype == dtype, label
            np.testing.assert_array_equal(got, want, err_msg=f"{label} operand {i}")


def test_inputs_are_not_modified_and_views_of_one_buffer():
    R = rotations(10, np.random.default_rng(24))
    R.flags.writeable = False
    before = R.copy()
    chasles.so3_log(R)
    np.testing.assert_array_equal(R, before)
    # a slice of the 3x3 block of 4x4 poses: an operand with column stride 8
    g = poses(10, np.random.default_rng(25))
    np.testing.assert_array_equal(chasles.so3_log(g[:, :3, :3]), chasles.so3_log(g[:, :3, :3].copy()))
    np.testing.assert_array_equal(
        chasles.so3_log(g[:, :3, :3].transpose(0, 2, 1)),
        chasles.so3_log(np.ascontiguousarray(g[:, :3, :3].transpose(0, 2, 1))),
    )


# ---- NaN --------------------------------------------------------------------


@pytest.mark.parametrize(("name", "operand"), [(n, i) for n in NAMES for i in range(len(FUNCS[n][0]))])
def test_nan_stays_in_its_element(name, operand):
    kinds = FUNCS[name][0]
    rng = np.random.default_rng(26)
    args = operands(name, (5,), rng)
    f = getattr(chasles, name)
    clean = f(*args)
    # one entry of element 2, one that every function reads
    entry = {0: (2,), 1: (2, 0), 2: (2, 0, 1)}[core_ndim(kinds[operand])]
    args[operand][entry] = np.nan
    out = f(*args)
    assert np.isnan(out[2]).any()
    keep = [0, 1, 3, 4]
    np.testing.assert_array_equal(out[keep], clean[keep])


# ---- the object API ---------------------------------------------------------


def test_batch_equals_objects():
    rng = np.random.default_rng(28)
    w = rotvecs(20, rng)
    xi = twists(20, rng)
    p = rng.normal(size=(20, 3))
    R = chasles.so3_exp(w)
    g = chasles.se3_exp(xi)
    for i in range(0, 20, 3):
        r = chasles.SO3.exp(w[i])
        np.testing.assert_array_equal(np.asarray(r.as_matrix()), R[i])
        np.testing.assert_array_equal(np.asarray(r.log()), chasles.so3_log(R[i]))
        np.testing.assert_array_equal(np.asarray(r @ p[i]), chasles.so3_act(R[i], p[i]))
        h = chasles.SE3.exp(xi[i])
        np.testing.assert_array_equal(np.asarray(h.as_matrix()), g[i])
        np.testing.assert_array_equal(np.asarray(h.log()).ravel(), chasles.se3_log(g[i]))
        np.testing.assert_array_equal(np.asarray(h.inverse().as_matrix()), chasles.se3_inverse(g[i]))
        np.testing.assert_array_equal(np.asarray((h @ h).as_matrix()), chasles.se3_compose(g[i], g[i]))
        np.testing.assert_array_equal(np.asarray(h @ p[i]), chasles.se3_act(g[i], p[i]))
        np.testing.assert_array_equal(np.asarray(h.adjoint()), chasles.se3_adjoint(g[i]))
