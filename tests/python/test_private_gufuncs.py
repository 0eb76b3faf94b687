"""The private gufuncs behind Chain's methods, its dynamics and inverse
kinematics, the splines' evaluation, the Gaussians' propagation and the
time scalings:
registered by the same mechanism as
the public array functions (bindings/ufunc.hpp), with a core dimension n
bound at run time and several results. What numpy gives every gufunc (out=,
broadcasting of every operand, casting to the float64 loop, errors for core
sizes that disagree, dask's apply_gufunc) holds for them."""

from __future__ import annotations

import numpy as np
import pytest

import chasles
from chasles import _core

ARM = chasles.Chain(
    [chasles.Chain.revolute_screw([0.1 * i, 0.0, 0.2 * i], [0.0, i % 2, 1.0 - i % 2]) for i in range(5)],
    chasles.SE3(translation=[0.6, 0.0, 0.3]),
    link_inertias=[[1.0 + i, 0.1, 0.0, 0.05 * i, 0.02, 0.0, 0.0, 0.02, 0.0, 0.01] for i in range(5)],
)
S, M = ARM.space_screws, np.asarray(ARM.home)

PRIVATE = {
    "_chain_forward": ("(n,6),(4,4),(n)->(4,4)", ["ddd->d"]),
    "_chain_forward_body": ("(n,6),(4,4),(n)->(4,4)", ["ddd->d"]),
    "_chain_jacobian_space": ("(n,6),(4,4),(n)->(6,n)", ["ddd->d"]),
    "_chain_jacobian_body": ("(n,6),(4,4),(n)->(6,n)", ["ddd->d"]),
    "_chain_jacobian_space_dot": ("(n,6),(4,4),(n),(n)->(6,n)", ["dddd->d"]),
    "_chain_jacobian_body_dot": ("(n,6),(4,4),(n),(n)->(6,n)", ["dddd->d"]),
    "_inverse_dynamics": ("(n,6),(4,4),(n,6,6),(3),(n),(n),(n),(6)->(n)", ["dddddddd->d"]),
    "_forward_dynamics": ("(n,6),(4,4),(n,6,6),(3),(n),(n),(n),(6)->(n),()", ["dddddddd->di"]),
    "_mass_matrix": ("(n,6),(4,4),(n,6,6),(n)->(n,n)", ["dddd->d"]),
    "_gravity_torques": ("(n,6),(4,4),(n,6,6),(3),(n)->(n)", ["ddddd->d"]),
    "_coriolis": ("(n,6),(4,4),(n,6,6),(n),(n)->(n)", ["ddddd->d"]),
    "_inverse_dynamics_derivatives": ("(n,6),(4,4),(n,6,6),(3),(n),(n),(n),(6)->(n,n),(n,n)", ["dddddddd->dd"]),
    "_forward_dynamics_derivatives": (
        "(n,6),(4,4),(n,6,6),(3),(n),(n),(n),(6)->(n,n),(n,n),(n,n),()",
        ["dddddddd->dddi"],
    ),
    "_mass_matrix_inverse": ("(n,6),(4,4),(n,6,6),(n)->(n,n),()", ["dddd->di"]),
    "_inverse_kinematics": (
        "(n,6),(4,4),(n),(n),(),(),(),(),(4,4),(n),(),()->(n),(),(),(),(),(),(6)",
        ["ddddddidddi" + np.dtype(np.uint64).char + "->d?iiiid"],
    ),
    "_so3_spline": ("(n),(n,3,3),(n,9),()->(3,3)", ["dddd->d"]),
    "_so3_spline_rates": ("(n),(n,3,3),(n,9),()->(3,3),(3),(3)", ["dddd->ddd"]),
    "_se3_spline": ("(n),(n,4,4),(n,18),()->(4,4)", ["dddd->d"]),
    "_se3_spline_rates": ("(n),(n,4,4),(n,18),()->(4,4),(6),(6)", ["dddd->ddd"]),
    "_so3_bspline": ("(),(),(n,3,3),()->(3,3)", ["dddd->d"]),
    "_so3_bspline_rates": ("(),(),(n,3,3),()->(3,3),(3),(3)", ["dddd->ddd"]),
    "_se3_bspline": ("(),(),(n,4,4),()->(4,4)", ["dddd->d"]),
    "_se3_bspline_rates": ("(),(),(n,4,4),()->(4,4),(6),(6)", ["dddd->ddd"]),
    # time_scaling's kernel: scalar cores only, so numpy reports no core signature
    "_time_scaling": (None, ["iddd->ddd"]),
    "_joint_trajectory": ("(n),(n),(),(),(),()->(n),(n),(n)", ["ddiddd->ddd"]),
}

# Gaussian's kernels, on every group: (prefix, matrix size, tangent dimension, point size)
for _p, _n, _d, _k in (
    ("so2", 2, 1, 2),
    ("se2", 3, 3, 2),
    ("so3", 3, 3, 3),
    ("se3", 4, 6, 3),
    ("sim3", 4, 7, 3),
    ("se23", 5, 9, 3),
):
    _M, _C = f"({_n},{_n})", f"({_d},{_d})"
    PRIVATE.update(
        {
            f"_{_p}_compose_cov_cross": (f"{_M},{_C},{_M},{_C},{_C}->{_M},{_C}", ["ddddd->dd"]),
            f"_{_p}_between_cov_cross": (f"{_M},{_C},{_M},{_C},{_C}->{_M},{_C}", ["ddddd->dd"]),
            f"_{_p}_interpolate_cov": (f"{_M},{_C},{_M},{_C},()->{_M},{_C}", ["ddddd->dd"]),
            f"_{_p}_act_cov": (f"{_M},{_C},({_k}),({_k},{_k})->({_k}),({_k},{_k})", ["dddd->dd"]),
            f"_{_p}_log_cov": (f"{_M},{_C}->({_d}),{_C}", ["dd->dd"]),
            f"_{_p}_left_cov": (f"{_M},{_C}->{_C}", ["dd->d"]),
            f"_{_p}_mahalanobis": (f"{_M},{_C},{_M}->()", ["ddd->d"]),
        }
    )
PRIVATE["_se3_compose_cov4"] = ("(4,4),(6,6),(4,4),(6,6)->(4,4),(6,6)", ["dddd->dd"])


@pytest.mark.parametrize("name", sorted(PRIVATE))
def test_each_is_a_documented_gufunc_with_its_signature_and_float64_loop(name):
    u = getattr(_core, name)
    assert isinstance(u, np.ufunc)
    assert (u.signature, u.types) == PRIVATE[name]
    assert u.__doc__ and "private" in u.__doc__
    assert name not in chasles.__all__


def test_a_run_time_core_size_that_disagrees_is_numpys_error():
    theta = np.zeros(ARM.n_joints - 1)
    with pytest.raises(ValueError, match="mismatch in its core dimension"):
        _core._chain_forward(S, M, theta)
    with pytest.raises(ValueError, match="mismatch in its core dimension"):
        _core._chain_jacobian_body(S, M, np.zeros((3, ARM.n_joints + 1)))
    # the methods name themselves and n first
    with pytest.raises(ValueError, match=r"Chain.forward\(theta\): expected shape \(5,\) or \(\.\.\., 5\)"):
        ARM.forward(theta)


def test_the_run_time_size_sets_the_result_shapes():
    rng = np.random.default_rng(1)
    theta = rng.normal(size=(2, 3, ARM.n_joints))
    assert _core._chain_jacobian_space(S, M, theta).shape == (2, 3, 6, ARM.n_joints)
    q = rng.normal(size=(4, ARM.n_joints))
    assert ARM.mass_matrix(q).shape == (4, ARM.n_joints, ARM.n_joints)
    assert _core._so3_spline(np.arange(7.0), np.broadcast_to(np.eye(3), (7, 3, 3)), np.zeros((7, 9)), 2.5).shape == (
        3,
        3,
    )


def test_out_fills_the_given_array_with_the_same_bits():
    rng = np.random.default_rng(2)
    theta = rng.normal(size=(7, ARM.n_joints))
    out = np.empty((7, 6, ARM.n_joints))
    r = _core._chain_jacobian_body(S, M, theta, out=out)
    assert r is out
    np.testing.assert_array_equal(out, ARM.jacobian_body(theta))
    # a strided result (every other row of a bigger array) and strided operands
    big = np.zeros((7, 12, ARM.n_joints))
    _core._chain_jacobian_body(S.T.copy().T, M, np.asfortranarray(theta), out=big[:, ::2])
    np.testing.assert_array_equal(big[:, ::2], ARM.jacobian_body(theta))
    assert not big[:, 1::2].any()
    pose = np.empty((7, 4, 4))
    _core._chain_forward(S, M, theta, out=pose)
    np.testing.assert_array_equal(pose, ARM.forward(theta))


def test_float32_operands_run_in_the_float64_loop():
    rng = np.random.default_rng(3)
    theta = rng.normal(size=(5, ARM.n_joints)).astype(np.float32)
    r = _core._chain_forward(S, M, theta)
    assert r.dtype == np.float64
    np.testing.assert_array_equal(r, ARM.forward(theta.astype(np.float64)))
    np.testing.assert_array_equal(ARM.forward(theta), r)


def test_several_results_with_their_own_dtypes_and_out():
    rng = np.random.default_rng(4)
    q_true = rng.uniform(-1, 1, size=(3, ARM.n_joints))
    targets = ARM.forward(q_true)
    seeds = q_true + rng.uniform(-0.2, 0.2, q_true.shape)
    args = (S, M, ARM.lower, ARM.upper, 1e-10, 1e-10, np.int32(100), np.inf, targets, seeds, np.int32(0), np.uint64(0))
    q, converged, status, iterations, total, attempts, error = _core._inverse_kinematics(*args)
    assert (q.dtype, converged.dtype, iterations.dtype, error.dtype) == (np.float64, np.bool_, np.int32, np.float64)
    assert status.dtype == total.dtype == attempts.dtype == np.int32
    assert q.shape == (3, ARM.n_joints) and converged.shape == iterations.shape == (3,) and error.shape == (3, 6)
    assert (status == 0).all() and (attempts == 1).all() and (total == iterations).all()
    r = ARM.inverse_kinematics(
        targets, seeds, position_tolerance=1e-10, orientation_tolerance=1e-10, max_iterations=100
    )
    np.testing.assert_array_equal(q, r.q)
    np.testing.assert_array_equal(converged, r.converged)
    np.testing.assert_array_equal(iterations, r.iterations)
    np.testing.assert_array_equal(error, r.error)
    assert converged.all()
    outs = (np.empty((3, ARM.n_joints)), np.empty(3, bool)) + tuple(np.empty(3, np.int32) for _ in range(4))
    outs += (np.empty((3, 6)),)
    got = _core._inverse_kinematics(*args, out=outs)
    assert all(a is b for a, b in zip(got, outs))
    np.testing.assert_array_equal(outs[0], q)
    np.testing.assert_array_equal(outs[3], iterations)


def test_ik_batch_element_i_draws_its_restarts_from_seed_plus_i():
    rng = np.random.default_rng(5)
    targets = ARM.forward(rng.uniform(-2, 2, size=(6, ARM.n_joints)))
    seeds = rng.uniform(-3, 3, size=(6, ARM.n_joints))
    batch = ARM.inverse_kinematics(targets, seeds, max_iterations=3, restarts=4, seed=11)
    assert (batch.attempts > 1).any()  # some elements restarted
    for i in range(6):
        one = ARM.inverse_kinematics(targets[i], seeds[i], max_iterations=3, restarts=4, seed=11 + i)
        np.testing.assert_array_equal(batch.q[i], one.q)
        assert batch.iterations[i] == one.iterations and batch.converged[i] == one.converged
        assert batch.total_iterations[i] == one.total_iterations and batch.attempts[i] == one.attempts
    again = ARM.inverse_kinematics(
        targets.reshape(2, 3, 4, 4), seeds.reshape(2, 3, -1), max_iterations=3, restarts=4, seed=11
    )
    np.testing.assert_array_equal(again.q.reshape(6, -1), batch.q)


def test_more_joints_than_the_bound_give_nan_results_in_every_output():
    n = 33
    outs = _core._inverse_kinematics(
        np.zeros((n, 6)),
        np.eye(4),
        np.zeros(n),
        np.zeros(n),
        0.0,
        0.0,
        np.int32(1),
        np.inf,
        np.eye(4),
        np.zeros(n),
        np.int32(0),
        np.uint64(0),
    )
    assert np.isnan(outs[0]).all() and not outs[1] and np.isnan(outs[6]).all()
    assert outs[2] == outs[3] == outs[4] == outs[5] == 0
    assert np.isnan(_core._mass_matrix(np.zeros((n, 6)), np.eye(4), np.zeros((n, 6, 6)), np.zeros(n))).all()


def test_spline_gufuncs_take_the_spline_arrays_and_broadcast_times():
    rng = np.random.default_rng(6)
    times = np.array([0.0, 0.5, 1.5, 2.0])
    keys = chasles.se3_exp(0.4 * rng.normal(size=(4, 6)))
    spline = chasles.SE3Spline(times, keys)
    t = rng.uniform(0, 2, size=(3, 5))
    coefficients = _core._se3_spline_fit(times, keys, True)
    assert coefficients.shape == (4, 18) and not coefficients[-1].any()
    g, v, a = _core._se3_spline_rates(times, keys, coefficients, t)
    assert g.shape == (3, 5, 4, 4) and v.shape == a.shape == (3, 5, 6)
    np.testing.assert_array_equal(g, spline(t))
    np.testing.assert_array_equal(v, spline.body_velocity(t))
    np.testing.assert_array_equal(a, spline.body_acceleration(t))
    out = np.empty((3, 5, 4, 4))
    assert _core._se3_spline(times, keys, coefficients, t, out=out) is out
    np.testing.assert_array_equal(out, spline(t))
    # fewer than two keys: NaN, never a read past the arrays
    assert np.isnan(_core._se3_spline(times[:1], keys[:1], coefficients[:1], 0.5)[:3]).all()  # R and p


def test_bspline_gufuncs_take_the_control_array():
    rng = np.random.default_rng(7)
    control = chasles.so3_exp(rng.normal(size=(6, 3)))
    spline = chasles.SO3BSpline(0.5, 0.25, control)
    t = rng.uniform(0.5, spline.end_time, size=9)
    R, w, dw = _core._so3_bspline_rates(0.5, 0.25, control, t)
    np.testing.assert_array_equal(R, spline(t))
    np.testing.assert_array_equal(w, spline.body_velocity(t))
    np.testing.assert_array_equal(dw, spline.body_acceleration(t))
    # two splines at once: the control operand broadcasts too
    both = _core._so3_bspline(0.5, 0.25, np.stack([control, control[::-1]]), t[:2])
    np.testing.assert_array_equal(both[1], chasles.SO3BSpline(0.5, 0.25, control[::-1])(t[1]))
    # fewer than 4 control elements or a spacing that is not > 0: NaN
    assert np.isnan(_core._so3_bspline(0.5, 0.25, control[:3], 0.6)).all()
    assert np.isnan(_core._so3_bspline(0.5, 0.0, control, 0.6)).all()


dask_array = pytest.importorskip("dask.array")


def test_dask_maps_a_run_time_core_gufunc_over_chunks():
    rng = np.random.default_rng(8)
    theta = rng.normal(size=(500, ARM.n_joints))
    d = dask_array.from_array(theta, chunks=(120, ARM.n_joints))
    lazy = dask_array.apply_gufunc(
        _core._chain_jacobian_space,
        _core._chain_jacobian_space.signature,
        S,
        M,
        d,
        output_dtypes=np.float64,
        output_sizes={"n": ARM.n_joints},
    )
    assert isinstance(lazy, dask_array.Array) and lazy.shape == (500, 6, ARM.n_joints)
    np.testing.assert_array_equal(lazy.compute(), ARM.jacobian_space(theta))


def test_dask_maps_a_gufunc_of_several_results():
    rng = np.random.default_rng(9)
    times = np.array([0.0, 1.0, 3.0])
    keys = chasles.so3_exp(rng.normal(size=(3, 3)))
    spline = chasles.SO3Spline(times, keys)
    coefficients = _core._so3_spline_fit(times, keys, True)
    t = dask_array.from_array(rng.uniform(0, 3, size=400), chunks=100)
    R, w, dw = dask_array.apply_gufunc(
        _core._so3_spline_rates,
        _core._so3_spline_rates.signature,
        times,
        keys,
        coefficients,
        t,
        output_dtypes=(np.float64,) * 3,
    )
    assert isinstance(w, dask_array.Array)
    np.testing.assert_array_equal(R.compute(), spline(t.compute()))
    np.testing.assert_array_equal(w.compute(), spline.body_velocity(t.compute()))
    np.testing.assert_array_equal(dw.compute(), spline.body_acceleration(t.compute()))
