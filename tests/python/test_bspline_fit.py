"""<Group>BSpline.fit: a B-spline fitted to timestamped poses by least squares.

Oracles: poses sampled without noise from a known B-spline are fitted back
to that spline (its control elements are the unique optimum, chi2 = 0);
noisy samples of a known smooth motion give chi2 per degree of freedom
within its statistical range of 1 and a curve closer to the motion than the
samples; the Jacobians behind the fit (the private ``_<g>_bspline_jacobians``)
against central differences of the evaluated spline; chi2 written out with
the object API.
"""

from __future__ import annotations

import numpy as np
import pytest

import chasles

# class, group, prefix, DoF
GROUPS = [
    (chasles.SO2BSpline, chasles.SO2, "so2", 1),
    (chasles.SE2BSpline, chasles.SE2, "se2", 3),
    (chasles.SO3BSpline, chasles.SO3, "so3", 3),
    (chasles.SE3BSpline, chasles.SE3, "se3", 6),
    (chasles.Sim3BSpline, chasles.Sim3, "sim3", 7),
    (chasles.SE23BSpline, chasles.SE23, "se23", 9),
]
IDS = [g[2] for g in GROUPS]


def fn(prefix, name):
    return getattr(chasles, f"{prefix}_{name}")


def exp(prefix, x):
    return fn(prefix, "exp")(x[..., 0] if x.shape[-1] == 1 else x)


def known_spline(cls, prefix, dof, seed=0):
    """A spline of 8 control elements, each a step of about 0.3 from the last."""
    rng = np.random.default_rng(seed)
    control = [exp(prefix, rng.normal(size=dof))]
    for _ in range(7):
        control.append(fn(prefix, "compose")(control[-1], exp(prefix, 0.3 * rng.normal(size=dof))))
    return cls(1.0, 0.5, np.array(control))


def rminus(prefix, a, b):
    return np.asarray(fn(prefix, "log")(fn(prefix, "compose")(fn(prefix, "inverse")(b), a))).reshape(
        np.shape(a)[:-2] + (-1,)
    )


@pytest.mark.parametrize("cls, group, prefix, dof", GROUPS, ids=IDS)
def test_poses_on_a_spline_fit_back_to_that_spline(cls, group, prefix, dof):
    truth = known_spline(cls, prefix, dof)
    times = np.linspace(truth.start_time, truth.end_time, 101)
    fit = cls.fit(times, truth(times), 0.5)
    assert isinstance(fit.spline, cls) and fit.converged and fit.iterations < 20
    assert fit.spline.start_time == truth.start_time and fit.spline.control.shape == truth.control.shape
    assert fit.final_chi2 < 1e-20 < fit.initial_chi2
    assert np.abs(rminus(prefix, fit.spline.control, truth.control)).max() < 1e-8
    assert fit.residuals.shape == (101, dof) and np.abs(fit.residuals).max() < 1e-9


def test_the_jacobians_behind_the_fit_match_central_differences():
    for cls, _, prefix, dof in GROUPS:
        spline = known_spline(cls, prefix, dof, seed=1)
        ufunc = getattr(chasles._core, f"_{prefix}_bspline_jacobians")
        for t in (1.0, 1.7, 2.0, spline.end_time):
            value, J, segment = ufunc(spline.start_time, spline.spacing, spline.control, t)
            np.testing.assert_allclose(value, spline(t), atol=1e-14)
            i = int(segment)
            for k in range(4):
                for axis in range(dof):
                    e = np.zeros(dof)
                    e[axis] = 1e-6
                    moved = []
                    for sign in (1, -1):
                        control = spline.control.copy()
                        control[i + k] = fn(prefix, "compose")(control[i + k], exp(prefix, sign * e))
                        moved.append(rminus(prefix, cls(spline.start_time, spline.spacing, control)(t), value))
                    fd = (moved[0] - moved[1]) / 2e-6
                    np.testing.assert_allclose(J.reshape(4, dof, dof)[k][:, axis], fd, atol=1e-8)


def helix(t):
    """A smooth SE(3) motion that is not a spline."""
    g = np.zeros(t.shape + (4, 4))
    g[..., :3, :3] = chasles.so3_compose(
        chasles.so3_exp(np.stack([0 * t, 0 * t, 0.6 * t], -1)),
        chasles.so3_exp(np.stack([0.4 * np.sin(0.9 * t), 0 * t, 0 * t], -1)),
    )
    g[..., :3, 3] = np.stack([2 * np.cos(0.6 * t), 2 * np.sin(0.6 * t), 0.3 * t], -1)
    g[..., 3, 3] = 1
    return g


def test_noisy_poses_give_chi2_per_dof_near_one_and_a_curve_nearer_the_truth():
    rng = np.random.default_rng(2)
    times = np.sort(rng.uniform(0, 10, 300))
    sigma = np.array([0.05, 0.05, 0.05, 0.02, 0.02, 0.02])
    noise = rng.normal(size=(300, 6)) * sigma
    poses = chasles.se3_compose(helix(times), chasles.se3_exp(noise))
    fit = chasles.SE3BSpline.fit(times, poses, 0.5, information=np.diag(1 / sigma**2))
    assert fit.converged
    dof = 300 * 6 - fit.spline.control.shape[0] * 6
    assert abs(fit.final_chi2 / dof - 1) < 5 * np.sqrt(2 / dof)
    # chi2 is the sum written out with the objects
    by_hand = sum(
        e @ np.diag(1 / sigma**2) @ e
        for e in (
            np.asarray((chasles.SE3.from_matrix(z).inverse() @ chasles.SE3.from_matrix(x)).log())
            for z, x in zip(poses, fit.spline(times))
        )
    )
    assert fit.final_chi2 == pytest.approx(by_hand, rel=1e-10)
    error = rminus("se3", fit.spline(times), helix(times))
    assert np.sqrt(np.mean(error[:, :3] ** 2)) < 0.5 * sigma[0] and np.sqrt(np.mean(error[:, 3:] ** 2)) < 0.5 * sigma[3]
    # the information's scale scales chi2 and leaves the fit
    scaled = chasles.SE3BSpline.fit(times, poses, 0.5, information=4 * np.diag(1 / sigma**2))
    assert scaled.final_chi2 == pytest.approx(4 * fit.final_chi2, rel=1e-6)
    assert np.abs(scaled.spline.control - fit.spline.control).max() < 1e-6


def test_per_pose_information_and_start_time():
    truth = known_spline(chasles.SO3BSpline, "so3", 3, seed=3)
    times = np.linspace(1.2, truth.end_time, 60)
    info = np.broadcast_to(np.diag([1.0, 2.0, 3.0]), (60, 3, 3))
    fit = chasles.SO3BSpline.fit(times, truth(times), 0.5, start_time=1.0, information=info)
    assert fit.spline.start_time == 1.0 and fit.final_chi2 < 1e-20


@pytest.mark.parametrize(
    "kwargs, error, message",
    [
        (
            {"times": np.zeros(3), "poses": np.zeros((3, 4, 4))},
            ValueError,
            r"fit\(times\): expected shape \(K,\) with K >= 4, got \(3,\)",
        ),
        ({"times": [0, 1, 2, np.nan, 4, 5, 6, 7, 8, 9, 10, 11]}, ValueError, r"fit\(times\): expected finite numbers"),
        ({"times": "abc"}, TypeError, r"fit\(times\): expected real numbers"),
        ({"poses": np.zeros((12, 3, 3))}, ValueError, r"fit\(poses\): expected shape \(12, 4, 4\)"),
        ({"poses": np.zeros((12, 4, 4))}, ValueError, r"fit\(poses\): element 0"),
        ({"spacing": 0.0}, ValueError, r"fit\(spacing\): expected a positive spacing"),
        ({"spacing": "1"}, TypeError, r"fit\(spacing\): expected a real number, got str"),
        (
            {"spacing": 0.1},
            ValueError,
            r"fit: a spacing of 0.1 over \[0.0, 2.5\] needs 28 control elements, more than the 12",
        ),
        ({"times": np.r_[np.linspace(0, 0.4, 11), 4.0]}, ValueError, r"fit: no pose in the support of control elem"),
        ({"times": np.r_[np.linspace(0, 0.4, 11), 2.5]}, ValueError, r"fit: the poses do not determine every control"),
        ({"start_time": 1.0}, ValueError, r"fit\(times\): expected times >= start_time = 1.0, got 0.0"),
        ({"information": np.eye(3)}, ValueError, r"fit\(information\): expected shape \(6, 6\) or \(12, 6, 6\)"),
        ({"information": -np.eye(6)}, ValueError, r"fit\(information\): expected positive definite"),
        ({"information": np.triu(np.ones((6, 6)))}, ValueError, r"fit\(information\): expected symmetric"),
        ({"max_iterations": 0}, ValueError, r"fit\(max_iterations\): expected an int >= 1"),
        ({"tolerance": -1.0}, ValueError, r"fit\(tolerance\): expected a float >= 0"),
    ],
)
def test_bad_arguments_are_refused_with_their_name(kwargs, error, message):
    times = np.linspace(0.0, 2.5, 12)
    args = {"times": times, "poses": chasles.se3_exp(np.outer(times, [0.1, 0, 0, 0, 0, 0.2])), "spacing": 0.5}
    args.update(kwargs)
    positional = [args.pop(k) for k in ("times", "poses", "spacing")]
    with pytest.raises(error, match=r"SE3BSpline\." + message):
        chasles.SE3BSpline.fit(*positional, **args)
