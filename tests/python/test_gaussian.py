"""chasles.Gaussian and the array functions <g>_compose_cov, <g>_between_cov,
<g>_inverse_cov, on every group.

Three oracles, none of them the code under test:
- the first-order formulas, J cov J^T, written here with the Jacobians of
  the group functions (compose_jacobians, ...), and finite differences for
  the interpolation;
- Monte Carlo: 10^6 samples of each operand through each operation, the
  sample covariance of the result's perturbation log(mean^-1 X) against the
  propagated one, entry by entry within 5 standard deviations of the
  sampling error (sd_ij = sqrt((S_ii S_jj + S_ij^2) / n) for a Gaussian);
  at small uncertainty (standard deviations 0.01), where first order is
  accurate;
- Barfoot and Furgale's compounding at large uncertainty (SE3), where first
  order visibly fails and fourth order does better.
"""

from __future__ import annotations

import copy
import pickle

import numpy as np
import pytest

import chasles

# group, tangent dimension, point size
GROUPS = [
    (chasles.SO2, 1, 2),
    (chasles.SE2, 3, 2),
    (chasles.SO3, 3, 3),
    (chasles.SE3, 6, 3),
    (chasles.Sim3, 7, 3),
    (chasles.SE23, 9, 3),
]
IDS = [G.__name__ for G, _, _ in GROUPS]


def prefix(G) -> str:
    return G.__name__.lower()


def element(G, rng, scale=1.0):
    d = next(d for H, d, _ in GROUPS if H is G)
    xi = scale * rng.uniform(-1.0, 1.0, size=d)
    return G.exp(float(xi[0])) if d == 1 else G.exp(xi)


def spd(d, rng, scale):
    """A random covariance of standard deviations about sqrt(scale), well conditioned."""
    A = rng.normal(size=(d, d))
    return scale * (A @ A.T / d + 0.2 * np.eye(d))


def congruence(J, S):
    return J @ S @ J.T


def close(a, b, rel=1e-12):
    scale = max(np.abs(b).max(), 1e-300)
    assert np.abs(np.asarray(a) - b).max() <= rel * scale, (a, b)


# ---- first order: the Jacobians' formulas ---------------------------------------------


@pytest.mark.parametrize("G, d, k", GROUPS, ids=IDS)
def test_first_order_is_the_jacobians_congruence(G, d, k):
    rng = np.random.default_rng(1)
    a, b = element(G, rng), element(G, rng)
    Sa, Sb, C = spd(d, rng, 1e-2), spd(d, rng, 2e-2), 1e-3 * rng.normal(size=(d, d))
    ga, gb = chasles.Gaussian(a, Sa), chasles.Gaussian(b, Sb)

    Ja, Jb = chasles.compose_jacobians(a, b)
    ab = ga @ gb
    assert ab.mean.is_approx(a @ b, 1e-15)
    close(ab.cov, congruence(Ja, Sa) + congruence(Jb, Sb))
    K = Ja @ C @ Jb.T
    close(ga.compose(gb, cross_cov=C).cov, congruence(Ja, Sa) + congruence(Jb, Sb) + K + K.T)

    Ja, Jb = chasles.between_jacobians(a, b)
    close(ga.between(gb).cov, congruence(Ja, Sa) + congruence(Jb, Sb))
    K = Ja @ C @ Jb.T
    close(ga.between(gb, cross_cov=C).cov, congruence(Ja, Sa) + congruence(Jb, Sb) + K + K.T)
    assert ga.between(gb).mean.is_approx(chasles.between(a, b), 1e-15)

    close(ga.inverse().cov, congruence(chasles.inverse_jacobian(a), Sa))
    assert ga.inverse().mean.is_approx(a.inverse(), 1e-15)

    p, Sp = rng.normal(size=k), spd(k, rng, 1e-2)
    Jg, Jp = chasles.act_jacobians(a, p)
    q = ga.act(p, Sp)
    close(q.mean, a @ p)
    close(q.cov, congruence(Jg, Sa) + congruence(Jp, Sp))
    close(ga.act(p).cov, congruence(Jg, Sa))

    log = ga.log()
    close(log.mean, np.atleast_1d(a.log()))
    close(log.cov, congruence(np.atleast_2d(chasles.log_jacobian(a)), Sa))

    Ad = np.atleast_2d(a.adjoint())
    close(ga.left_cov, congruence(Ad, Sa))
    close(chasles.Gaussian.from_left(a, congruence(Ad, Sa)).cov, Sa, 1e-11)
    # the inverse's covariance is the left one: X^-1 = exp(-e) mean^-1
    close(ga.inverse().cov, ga.left_cov)


@pytest.mark.parametrize("G, d, k", GROUPS, ids=IDS)
def test_interpolation_against_finite_differences(G, d, k):
    rng = np.random.default_rng(2)
    a, b = element(G, rng), element(G, rng)
    Sa, Sb, t = spd(d, rng, 1e-2), spd(d, rng, 1e-2), 0.3
    mid = chasles.interpolate(a, b, t)

    def jacobian(f):
        h, J = 1e-6, np.zeros((d, d))
        for i in range(d):
            e = np.zeros(d)
            e[i] = h
            de = e if d > 1 else float(e[0])
            ne = -e if d > 1 else -float(e[0])
            J[:, i] = (np.atleast_1d(chasles.rminus(f(de), mid)) - np.atleast_1d(chasles.rminus(f(ne), mid))) / (2 * h)
        return J

    Ja = jacobian(lambda e: chasles.interpolate(chasles.rplus(a, e), b, t))
    Jb = jacobian(lambda e: chasles.interpolate(a, chasles.rplus(b, e), t))
    got = chasles.Gaussian(a, Sa).interpolate(chasles.Gaussian(b, Sb), t)
    assert got.mean.is_approx(mid, 1e-14)
    close(got.cov, congruence(Ja, Sa) + congruence(Jb, Sb), 1e-7)
    # the ends: t = 0 is a, t = 1 is b (to first order, exactly)
    close(chasles.Gaussian(a, Sa).interpolate(chasles.Gaussian(b, Sb), 0.0).cov, Sa)
    close(chasles.Gaussian(a, Sa).interpolate(chasles.Gaussian(b, Sb), 1).cov, Sb, 1e-10)


@pytest.mark.parametrize("G, d, k", GROUPS, ids=IDS)
def test_mahalanobis(G, d, k):
    rng = np.random.default_rng(3)
    a, S = element(G, rng), spd(d, rng, 1e-2)
    g = chasles.Gaussian(a, S)
    xs = [element(G, rng) for _ in range(4)]
    want = []
    for x in xs:
        e = np.atleast_1d(chasles.rminus(x, a))
        want.append(e @ np.linalg.solve(S, e))
    assert g.mahalanobis(xs[0]) == pytest.approx(want[0], rel=1e-12)
    close(g.mahalanobis(np.stack([np.asarray(x) for x in xs])), np.array(want))
    assert 0.0 <= g.mahalanobis(a) < 1e-25  # rounding of log(a^-1 a) only
    # a singular covariance (one coordinate held fixed): no distance
    S0 = S.copy()
    S0[0, :] = S0[:, 0] = 0.0
    assert np.isnan(chasles.Gaussian(a, S0).mahalanobis(xs[0]))


@pytest.mark.parametrize("G, d, k", GROUPS, ids=IDS)
def test_array_functions_over_batches(G, d, k):
    rng = np.random.default_rng(4)
    p = prefix(G)
    A = [element(G, rng) for _ in range(5)]
    B = [element(G, rng) for _ in range(5)]
    SA = np.stack([spd(d, rng, 1e-2) for _ in range(5)])
    SB = np.stack([spd(d, rng, 1e-2) for _ in range(5)])
    MA, MB = np.stack([np.asarray(x) for x in A]), np.stack([np.asarray(x) for x in B])
    for name, method in (("compose_cov", "compose"), ("between_cov", "between")):
        f = getattr(chasles, f"{p}_{name}")
        assert f.signature == f"({MA.shape[1]},{MA.shape[1]}),({d},{d}),({MA.shape[1]},{MA.shape[1]}),({d},{d})->" + (
            f"({MA.shape[1]},{MA.shape[1]}),({d},{d})"
        )
        means, covs = f(MA, SA, MB, SB)
        for i in range(5):
            want = getattr(chasles.Gaussian(A[i], SA[i]), method)(chasles.Gaussian(B[i], SB[i]))
            # (the mean object holds Sim3's scale and rotation apart: its matrix rounds anew)
            close(means[i], np.asarray(want.mean), 1e-15)
            assert np.array_equal(covs[i], want.cov)
        # broadcasting: one a against the batch of b
        m1, c1 = f(MA[0], SA[0], MB, SB)
        assert m1.shape == MB.shape and c1.shape == SB.shape
        assert np.array_equal(c1[3], f(MA[0], SA[0], MB[3], SB[3])[1])
        # float32 in, float32 out, near the float64 numbers
        m32, c32 = f(MA.astype(np.float32), SA.astype(np.float32), MB.astype(np.float32), SB.astype(np.float32))
        assert m32.dtype == c32.dtype == np.float32
        assert np.abs(c32 - covs).max() <= 1e-5 * np.abs(covs).max()
    means, covs = getattr(chasles, f"{p}_inverse_cov")(MA, SA)
    for i in range(5):
        assert np.array_equal(covs[i], chasles.Gaussian(A[i], SA[i]).inverse().cov)


# ---- Monte Carlo ---------------------------------------------------------------------------


def perturbations(G, mean, X):
    """log(mean^-1 X) of a batch of matrices X: (n, D)."""
    p = prefix(G)
    inv = getattr(chasles, f"{p}_inverse")(np.asarray(mean))
    e = getattr(chasles, f"{p}_log")(getattr(chasles, f"{p}_compose")(inv, X))
    return e.reshape(len(X), -1)


def expect_covariance(samples, S, what):
    """The sample covariance of (n, D) samples within 5 sampling standard deviations of S, entry by entry."""
    n = samples.shape[0]
    C = np.cov(samples, rowvar=False).reshape(S.shape)
    sd = np.sqrt((np.outer(np.diag(S), np.diag(S)) + S**2) / n)
    z = np.abs(C - S) / sd
    assert z.max() < 5.0, f"{what}: {z.max():.2f} standard deviations at {np.unravel_index(z.argmax(), z.shape)}"


@pytest.mark.parametrize("G, d, k", GROUPS, ids=IDS)
def test_monte_carlo_of_every_operation(G, d, k):
    rng = np.random.default_rng(5)
    n = 1_000_000
    p = prefix(G)
    f = {name: getattr(chasles, f"{p}_{name}") for name in ("compose", "inverse", "interpolate", "act", "log")}
    a, b = element(G, rng), element(G, rng)
    ga, gb = chasles.Gaussian(a, spd(d, rng, 1e-4)), chasles.Gaussian(b, spd(d, rng, 1e-4))
    Xa, Xb = ga.sample(n, rng), gb.sample(n, rng)

    for what, X, want in (
        ("compose", f["compose"](Xa, Xb), ga @ gb),
        ("between", f["compose"](f["inverse"](Xa), Xb), ga.between(gb)),
        ("inverse", f["inverse"](Xa), ga.inverse()),
        ("interpolate", f["interpolate"](Xa, Xb, 0.3), ga.interpolate(gb, 0.3)),
    ):
        expect_covariance(perturbations(G, want.mean, X), want.cov, what)

    point, Sp = rng.normal(size=k), spd(k, rng, 1e-4)
    P = point + rng.standard_normal((n, k)) @ np.linalg.cholesky(Sp).T
    want = ga.act(point, Sp)
    expect_covariance(f["act"](Xa, P), want.cov, "act")
    assert np.abs(f["act"](Xa, P).mean(axis=0) - want.mean).max() < 1e-3

    want = ga.log()
    expect_covariance(f["log"](Xa).reshape(n, -1), want.cov, "log")


def test_monte_carlo_of_correlated_operands():
    """compose and between with a cross-covariance: X_b = X_a exp(D e_a + f), correlated with X_a."""
    rng = np.random.default_rng(6)
    n, d = 1_000_000, 6
    a, b = element(chasles.SE3, rng), element(chasles.SE3, rng)
    Sa, Sf, D = spd(d, rng, 1e-4), spd(d, rng, 1e-4), 0.5 * rng.normal(size=(d, d))
    ea = rng.standard_normal((n, d)) @ np.linalg.cholesky(Sa).T
    eb = ea @ D.T + rng.standard_normal((n, d)) @ np.linalg.cholesky(Sf).T
    Xa = chasles.se3_compose(np.asarray(a), chasles.se3_exp(ea))
    Xb = chasles.se3_compose(np.asarray(b), chasles.se3_exp(eb))
    ga, gb = chasles.Gaussian(a, Sa), chasles.Gaussian(b, D @ Sa @ D.T + Sf)
    cross = Sa @ D.T  # E[e_a e_b^T]
    want = ga.compose(gb, cross_cov=cross)
    expect_covariance(perturbations(chasles.SE3, want.mean, chasles.se3_compose(Xa, Xb)), want.cov, "compose")
    want = ga.between(gb, cross_cov=cross)
    expect_covariance(
        perturbations(chasles.SE3, want.mean, chasles.se3_compose(chasles.se3_inverse(Xa), Xb)), want.cov, "between"
    )
    # ignoring the correlation is visibly wrong
    with pytest.raises(AssertionError):
        expect_covariance(perturbations(chasles.SE3, want.mean, chasles.se3_compose(Xa, Xb)), (ga @ gb).cov, "x")


def test_fourth_order_compounding_of_large_uncertainty():
    """Barfoot and Furgale (2014), the figure on compounding: the first-order
    covariance of X_a X_a drifts from the Monte Carlo one as the uncertainty
    grows (standard deviations of 0.7 rad and 2 m here: 7.7 % off, in the
    Frobenius norm), the fourth-order one much less (0.8 %: the terms beyond
    fourth order; it falls as alpha^2, 0.2 % at alpha = 0.25). At small
    uncertainty both are within the sampling noise."""
    rng = np.random.default_rng(7)
    n = 1_000_000
    mean = chasles.SE3.exp([1.0, 0.5, -0.3, 0.2, -0.4, 0.6])
    shape = np.array([10.0, 5.0, 5.0, 0.5, 1.0, 0.5])
    for alpha in (1e-3, 0.5):
        a = chasles.Gaussian(mean, alpha * np.diag(shape))
        first, fourth = a @ a, a.compose(a, order=4)
        assert np.array_equal(np.asarray(first.mean), np.asarray(fourth.mean))
        X = chasles.se3_compose(a.sample(n, rng), a.sample(n, rng))
        mc = np.cov(perturbations(chasles.SE3, first.mean, X), rowvar=False)
        e1 = np.linalg.norm(first.cov - mc) / np.linalg.norm(mc)
        e4 = np.linalg.norm(fourth.cov - mc) / np.linalg.norm(mc)
        # the sampling error of the covariance in the Frobenius norm, relative
        noise = np.sqrt((np.trace(mc) ** 2 + np.sum(mc**2)) / n) / np.linalg.norm(mc)
        if alpha < 0.1:
            assert max(e1, e4) < 3 * noise, (e1, e4, noise)
        else:
            assert e1 > 10 * noise, (e1, noise)  # first order visibly off
            assert e4 < e1 / 5, (e1, e4)


def test_ros_pose_covariance_against_monte_carlo():
    """ROS's covariance of (x, y, z, roll, pitch, yaw) about the fixed axes,
    against the sample covariance of samples' translations and so3_as_rpy."""
    rng = np.random.default_rng(8)
    n = 1_000_000
    g = chasles.SE3(chasles.SO3.from_rpy([0.4, -1.1, 2.5]), [1.0, -2.0, 0.5])
    x = chasles.Gaussian(g, spd(6, rng, 1e-4))
    X = x.sample(n, rng)
    u = np.concatenate([X[:, :3, 3], chasles.so3_as_rpy(X[:, :3, :3])], axis=1)
    want = x.to_ros_covariance()
    expect_covariance(u, want, "ros")
    back = chasles.Gaussian.from_ros(g, want.ravel())
    close(back.cov, x.cov, 1e-12)
    with pytest.raises(ValueError, match="gimbal lock"):
        chasles.Gaussian(chasles.SE3(chasles.SO3.from_rpy([0.4, np.pi / 2, 2.5]), [0, 0, 0]), x.cov).to_ros_covariance()
    with pytest.raises(TypeError, match="on SE3, got one on SO3"):
        chasles.Gaussian(chasles.SO3(), np.eye(3)).to_ros_covariance()
    with pytest.raises(TypeError, match="from_ros\\(mean\\): expected an SE3"):
        chasles.Gaussian.from_ros(chasles.SO3(), np.eye(6))


# ---- the class -------------------------------------------------------------------------------


def test_sampling_is_the_groups_sampler():
    g = chasles.Gaussian(chasles.Sim3.exp([0.1] * 7), 0.01 * np.eye(7))
    assert np.array_equal(g.sample(4, rng=9), chasles.sim3_gaussian(np.asarray(g.mean), g.cov, 4, rng=9))
    assert g.sample(rng=1).shape == (4, 4) and g.sample((2, 3), rng=1).shape == (2, 3, 4, 4)


def test_value_semantics():
    g = chasles.Gaussian(chasles.SE2.exp([1.0, 2.0, 0.3]), np.diag([1.0, 2.0, 0.1]))
    for h in (pickle.loads(pickle.dumps(g, protocol)) for protocol in range(pickle.HIGHEST_PROTOCOL + 1)):
        assert h.mean == g.mean and np.array_equal(h.cov, g.cov)
    for h in (copy.copy(g), copy.deepcopy(g)):
        assert h.mean == g.mean and np.array_equal(h.cov, g.cov)
    with pytest.raises(ValueError):
        g.cov[0, 0] = 5.0  # read-only
    cov = np.diag([1.0, 2.0, 0.1])
    h = chasles.Gaussian(g.mean, cov)
    cov[0, 0] = 9.0  # the Gaussian holds its own copy
    assert h.cov[0, 0] == 1.0
    with pytest.raises(TypeError, match="already initialized"):
        g.__init__(g.mean, cov)
    assert repr(g).startswith("Gaussian(mean=SE2(")
    assert repr(chasles.Gaussian.__new__(chasles.Gaussian)) == "<uninitialized Gaussian>"
    with pytest.raises(TypeError, match="not initialized"):
        chasles.Gaussian.__new__(chasles.Gaussian).cov  # noqa: B018
    # a group element composes as a Gaussian of zero covariance
    e = chasles.SE2.exp([0.0, 1.0, 0.5])
    assert np.array_equal((g @ e).cov, g.compose(chasles.Gaussian(e, np.zeros((3, 3)))).cov)


def test_bad_arguments_are_named():
    g = chasles.Gaussian(chasles.SE3(), 0.01 * np.eye(6))
    cases = [
        (lambda: chasles.Gaussian(np.eye(4), np.eye(6)), TypeError, r"Gaussian\(mean\).*SE3.from_matrix"),
        (lambda: chasles.Gaussian(chasles.SE3(), np.eye(3)), ValueError, r"Gaussian\(cov\): expected shape \(6, 6\)"),
        (lambda: chasles.Gaussian(chasles.SO2(), [[np.nan]]), ValueError, "finite"),
        (lambda: chasles.Gaussian(chasles.SO2(), [[-1.0]]), ValueError, "positive semidefinite"),
        (lambda: chasles.Gaussian(chasles.SE2(), [[1, 1, 0], [0, 1, 0], [0, 0, 1]]), ValueError, "symmetric"),
        (lambda: g @ chasles.Gaussian(chasles.SO3(), np.eye(3)), TypeError, "Gaussian on SE3 or an SE3, got a"),
        (lambda: g @ 2.0, TypeError, "unsupported operand"),
        (lambda: g.compose(g, order=2), ValueError, "expected 1 or 4"),
        (lambda: g.compose(g, order=4.0), TypeError, "expected 1 or 4"),
        (lambda: g.compose(g, cross_cov=np.eye(6), order=4), ValueError, "independent Gaussians on SE3"),
        (
            lambda: chasles.Gaussian(chasles.SO3(), np.eye(3)).compose(
                chasles.Gaussian(chasles.SO3(), np.eye(3)), order=4
            ),
            ValueError,
            "on SO3",
        ),
        (lambda: g.compose(g, cross_cov=np.eye(3)), ValueError, r"cross_cov\): expected shape \(6, 6\)"),
        (lambda: g.between(g, cross_cov="x"), TypeError, "cross_cov"),
        (lambda: g.act([1.0, 2.0]), ValueError, r"act\(points\): expected shape \(..., 3\)"),
        (lambda: g.act([1.0, 2.0, 3.0], np.eye(2)), ValueError, r"act\(cov\): expected shape \(..., 3, 3\)"),
        (lambda: g.interpolate(g, np.nan), ValueError, "finite"),
        (lambda: g.interpolate(g, [0.1, 0.2]), ValueError, r"shape \(\)"),
        (lambda: g.mahalanobis(np.eye(3)), ValueError, r"mahalanobis\(x\): expected shape \(..., 4, 4\)"),
        (lambda: g.sample(-1), ValueError, r"Gaussian.sample\(n\)"),
        (lambda: g.sample(2, rng="x"), TypeError, r"Gaussian.sample\(rng\)"),
        (lambda: chasles.Gaussian.from_left(chasles.SO3(), np.eye(6)), ValueError, r"from_left\(cov\)"),
    ]
    for call, error, pattern in cases:
        with pytest.raises(error, match=pattern):
            call()
