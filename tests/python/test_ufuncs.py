"""The array functions are numpy generalized ufuncs: what numpy gives every
ufunc (out=, axes=, dtype=, casting, the signature, inspect.signature,
__array_ufunc__ dispatch) holds for them, and the objects' point actions and
Chain's methods answer exactly as the array functions do."""

from __future__ import annotations

import inspect

import api_spec as A
import numpy as np
import pytest

import chasles

SIGNATURES = {
    "so3_exp": "(3)->(3,3)",
    "so3_log": "(3,3)->(3)",
    "so3_compose": "(3,3),(3,3)->(3,3)",
    "so3_inverse": "(3,3)->(3,3)",
    "so3_act": "(3,3),(3)->(3)",
    "so3_hat": "(3)->(3,3)",
    "so3_vee": "(3,3)->(3)",
    "so3_interpolate": "(3,3),(3,3),()->(3,3)",
    "se3_exp": "(6)->(4,4)",
    "se3_log": "(4,4)->(6)",
    "se3_compose": "(4,4),(4,4)->(4,4)",
    "se3_inverse": "(4,4)->(4,4)",
    "se3_act": "(4,4),(3)->(3)",
    "se3_adjoint": "(4,4)->(6,6)",
    "se3_act_twist": "(4,4),(6)->(6)",
    "se3_act_wrench": "(4,4),(6)->(6)",
    "se3_interpolate": "(4,4),(4,4),()->(4,4)",
    "se3_hat": "(6)->(4,4)",
    "se3_vee": "(4,4)->(6)",
}


def operands(name, batch, rng, dtype=np.float64):
    """Valid operands of the array function `name` with a batch shape."""
    return [
        A.sample_operand(arg, batch, rng, dtype) for arg in A.SPEC[name].signatures[0] if isinstance(arg, A.Operand)
    ]


@pytest.mark.parametrize("name", sorted(SIGNATURES))
def test_each_is_a_gufunc_with_its_core_signature_and_two_loops(name):
    f = getattr(chasles, name)
    assert isinstance(f, np.ufunc)
    assert f.signature == SIGNATURES[name]
    assert f.nout == 1
    assert f.types == ["f" * f.nin + "->f", "d" * f.nin + "->d"]


@pytest.mark.parametrize("name", sorted(SIGNATURES))
def test_signature_and_first_docstring_line_name_the_operands(name):
    f = getattr(chasles, name)
    params = list(inspect.signature(f).parameters)
    labels = [a.label.split(":")[1] for a in A.SPEC[name].signatures[0]]
    assert params[: f.nin] == labels
    assert "out" in params
    first = f.__doc__.splitlines()[0]
    assert first.startswith(f"{name}({', '.join(labels)}, /, out=None")
    assert "Args:" in f.__doc__ and "Returns:" in f.__doc__


@pytest.mark.parametrize("name", sorted(SIGNATURES))
@pytest.mark.parametrize("dtype", [np.float64, np.float32])
def test_out_writes_into_the_callers_buffer_and_returns_it(name, dtype):
    rng = np.random.default_rng(1)
    args = operands(name, (5,), rng, dtype)
    f = getattr(chasles, name)
    expected = f(*args)
    out = np.full_like(expected, np.nan)
    got = f(*args, out=out)
    assert got is out
    np.testing.assert_array_equal(out, expected)
    # a strided view of a larger buffer: written in place, the rest untouched
    big = np.full((10,) + expected.shape[1:] + (2,), -7.0, dtype=dtype)
    view = big[::2, ..., 0]
    assert f(*args, out=view) is view
    np.testing.assert_array_equal(big[::2, ..., 0], expected)
    assert (big[1::2] == -7.0).all() and (big[..., 1] == -7.0).all()


def test_out_of_another_dtype_follows_numpys_casting():
    w = np.random.default_rng(2).normal(size=(4, 3))
    out32 = np.empty((4, 3, 3), np.float32)
    with pytest.raises(TypeError, match="same_kind|Cannot cast"):
        chasles.so3_exp(w, out=np.empty((4, 3, 3), np.int64))
    chasles.so3_exp(w, out=out32, casting="same_kind")
    np.testing.assert_array_equal(out32, chasles.so3_exp(w).astype(np.float32))


def test_axes_picks_the_core_axes():
    rng = np.random.default_rng(3)
    w = rng.normal(size=(3, 7))  # the vectors along axis 0
    np.testing.assert_array_equal(chasles.so3_exp(w, axes=[(0,), (1, 2)]), chasles.so3_exp(w.T))
    R = chasles.so3_exp(w.T)
    Rt = np.moveaxis(R, 0, -1)  # (3, 3, 7): the matrices in the first two axes
    np.testing.assert_array_equal(chasles.so3_log(Rt, axes=[(0, 1), (0,)]), chasles.so3_log(R).T)


def test_objects_point_actions_equal_the_array_functions_bit_for_bit():
    rng = np.random.default_rng(4)
    g = chasles.SE3.exp(rng.normal(size=6))
    R = chasles.SO3.exp(rng.normal(size=3))
    for points in (
        rng.normal(size=3),
        rng.normal(size=(5, 3)),
        rng.normal(size=(2, 4, 3)),
        rng.normal(size=(5, 3)).astype(np.float32),
        np.arange(6).reshape(2, 3),
        rng.normal(size=(3, 5)).T,
        [1.0, 2.0, 3.0],
    ):
        # the pose is float64, rounded to float32 once for float32 points (float32 results)
        dtype = np.float32 if np.asarray(points).dtype == np.float32 else np.float64
        mine = chasles.se3_act(np.asarray(g, dtype=dtype), points)
        assert (g @ points).dtype == mine.dtype == dtype
        np.testing.assert_array_equal(g @ points, mine)
        np.testing.assert_array_equal(g.act(points), mine)
        np.testing.assert_array_equal(g.act_inv(points), chasles.se3_act(np.asarray(g.inverse(), dtype=dtype), points))
        np.testing.assert_array_equal(R @ points, chasles.so3_act(np.asarray(R, dtype=dtype), points))
        np.testing.assert_array_equal(R.act(points), chasles.so3_act(np.asarray(R, dtype=dtype), points))


def test_chain_methods_equal_their_gufuncs():
    arm = chasles.Chain(A.GOOD[chasles.Chain]().space_screws, A.GOOD[chasles.Chain]().home)
    theta = np.random.default_rng(5).normal(size=(4, 3, arm.n_joints))
    S, M = arm.space_screws, np.asarray(arm.home)
    core = chasles._core
    np.testing.assert_array_equal(arm.forward(theta), core._chain_forward(S, M, theta))
    np.testing.assert_array_equal(arm.forward_body(theta), core._chain_forward_body(S, M, theta))
    np.testing.assert_array_equal(arm.jacobian_space(theta), core._chain_jacobian_space(S, M, theta))
    np.testing.assert_array_equal(arm.jacobian_body(theta), core._chain_jacobian_body(S, M, theta))
    # one configuration (the methods' fast path) gives the bits of the ufunc's loop
    for one in (theta[1, 2], list(theta[1, 2]), theta[1, 2].astype(np.float32)):
        np.testing.assert_array_equal(arm.forward(one), core._chain_forward(S, M, one))
        np.testing.assert_array_equal(arm.jacobian_body(one), core._chain_jacobian_body(S, M, one))
    # several chains at once: the chain operands broadcast too
    S2 = np.stack([S, S[::-1]])
    both = core._chain_forward(S2, M, theta[0, 0])
    assert both.shape == (2, 4, 4)
    np.testing.assert_array_equal(both[0], arm.forward(theta[0, 0]))
    np.testing.assert_array_equal(both[1], chasles.Chain(S[::-1], arm.home).forward(theta[0, 0]))


def test_chain_gufuncs_never_read_past_32_joints():
    """Only Chain calls them (1 <= n <= 32); called with more joints they
    give NaN rather than read past the chain's fixed capacity."""
    out = chasles._core._chain_forward(np.zeros((33, 6)), np.eye(4), np.zeros(33))
    assert out.shape == (4, 4) and np.isnan(out).all()


def test_no_floating_point_warnings_from_the_kernels():
    """numpy turns flags left by a loop into RuntimeWarnings; the kernels
    handle NaN and huge inputs themselves, so there are none (the test
    suite turns warnings into errors)."""
    w = np.array([[np.nan, 0, 0], [3e38, -3e38, 1e38], [0, 0, 0]], np.float32)
    chasles.so3_exp(w)
    chasles.so3_log(np.full((3, 3), np.nan))
    chasles.se3_log(np.array([[1e300, 1e300, 0, 1e300], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]))


dask_array = pytest.importorskip("dask.array")


def test_dask_maps_the_gufunc_over_chunks_lazily_with_the_same_numbers():
    rng = np.random.default_rng(6)
    w = rng.normal(size=(1000, 3))
    d = dask_array.from_array(w, chunks=(300, 3))
    calls = []

    def counted(x):
        calls.append(x.shape)
        return chasles.so3_exp(x)

    lazy = dask_array.apply_gufunc(counted, chasles.so3_exp.signature, d, output_dtypes=np.float64)
    assert isinstance(lazy, dask_array.Array) and lazy.shape == (1000, 3, 3)
    assert calls == []  # nothing computed yet
    np.testing.assert_array_equal(lazy.compute(), chasles.so3_exp(w))
    assert sorted(calls) == [(100, 3), (300, 3), (300, 3), (300, 3)]
    # two operands, one of them a plain array that broadcasts
    pts = dask_array.from_array(rng.normal(size=(1000, 3)), chunks=(250, 3))
    g = chasles.se3_exp(rng.normal(size=6))
    moved = dask_array.apply_gufunc(chasles.se3_act, chasles.se3_act.signature, g, pts, output_dtypes=np.float64)
    np.testing.assert_array_equal(moved.compute(), chasles.se3_act(g, pts.compute()))


@pytest.mark.xfail(
    strict=True,
    raises=ValueError,
    reason="dask's __array_ufunc__ infers the result dtype by calling the gufunc on arrays of "
    "size 1 in every axis, which a fixed core size (3) refuses (dask issue 5097); "
    "dask.array.apply_gufunc with output_dtypes works",
)
def test_a_dask_array_dispatches_through_array_ufunc():
    d = dask_array.from_array(np.zeros((10, 3)), chunks=(5, 3))
    lazy = chasles.so3_exp(d)
    assert isinstance(lazy, dask_array.Array)
