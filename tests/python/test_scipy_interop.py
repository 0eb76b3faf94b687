"""scipy interop: SO3.from_scipy / to_scipy (scipy.spatial.transform.Rotation),
SE3.from_scipy / to_scipy (RigidTransform), scipy's own from_matrix on the
objects, and numpy's array protocol (np.asarray / np.array with dtype= and
copy=) that scipy goes through.

The references are scipy's own conversions (as_matrix, as_rotvec, apply),
independent of chasles' quaternion and matrix code. Tolerance 8 eps: a
conversion through a unit quaternion rounds each matrix entry a few times.
"""

from __future__ import annotations

import subprocess
import sys
import textwrap

import numpy as np
import pytest
from scipy.spatial.transform import RigidTransform, Rotation

import chasles
from chasles import SE3, SO3

EPS = np.finfo(np.float64).eps
TOL = 8 * EPS

ROTVECS = [
    np.zeros(3),
    np.array([1e-9, 0.0, 0.0]),
    np.array([0.1, -0.2, 0.3]),
    np.array([0.0, 0.0, np.pi - 1e-6]),
    np.array([np.pi, 0.0, 0.0]),
    np.array([1.0, 1.0, -1.0]) * (np.pi / np.sqrt(3.0)),
]


def random_rotvecs(n, seed):
    rng = np.random.default_rng(seed)
    axes = rng.normal(size=(n, 3))
    axes /= np.linalg.norm(axes, axis=1, keepdims=True)
    return axes * rng.uniform(0.0, np.pi, size=(n, 1))


SAMPLES = ROTVECS + list(random_rotvecs(16, 20261124))


# ---- SO3 <-> Rotation -------------------------------------------------------------------


@pytest.mark.parametrize("w", SAMPLES)
def test_so3_from_scipy_is_the_same_rotation(w):
    r = Rotation.from_rotvec(w)
    R = SO3.from_scipy(r)
    assert isinstance(R, SO3)
    np.testing.assert_allclose(R.as_matrix(), r.as_matrix(), rtol=0, atol=TOL)
    p = np.array([0.3, -1.5, 2.0])
    np.testing.assert_allclose(R @ p, r.apply(p), rtol=0, atol=4 * TOL)


@pytest.mark.parametrize("w", SAMPLES)
def test_so3_to_scipy_is_the_same_rotation(w):
    R = SO3.exp(w)
    r = R.to_scipy()
    assert isinstance(r, Rotation) and r.single
    np.testing.assert_allclose(r.as_matrix(), R.as_matrix(), rtol=0, atol=TOL)
    assert SO3.from_scipy(r).is_approx(R, TOL)


def test_so3_from_scipy_keeps_a_non_unit_quaternion_rotation():
    # scipy normalizes at construction; a rotation of 180 degrees about z.
    r = Rotation.from_quat([0.0, 0.0, 3.0, 0.0])
    np.testing.assert_allclose(SO3.from_scipy(r).as_matrix(), np.diag([-1.0, -1.0, 1.0]), atol=TOL)


def test_scipy_from_matrix_takes_a_list_of_objects():
    Rs = [SO3.exp(w) for w in random_rotvecs(4, 3)]
    r = Rotation.from_matrix(Rs)
    assert len(r) == 4
    np.testing.assert_allclose(r.as_matrix(), [R.as_matrix() for R in Rs], rtol=0, atol=TOL)


def test_scipy_from_matrix_takes_an_so3():
    R = SO3.exp([0.1, -0.2, 0.3])
    r = Rotation.from_matrix(R)
    assert r.single
    np.testing.assert_allclose(r.as_matrix(), R.as_matrix(), rtol=0, atol=TOL)
    np.testing.assert_allclose(r.as_rotvec(), R.log(), rtol=0, atol=TOL)


# ---- SE3 <-> RigidTransform -------------------------------------------------------------


@pytest.mark.parametrize("w", SAMPLES)
def test_se3_from_scipy_is_the_same_motion(w):
    t = np.array([1.0, -2.0, 30.0]) * float(np.linalg.norm(w) + 0.5)
    tf = RigidTransform.from_components(t, Rotation.from_rotvec(w))
    g = SE3.from_scipy(tf)
    assert isinstance(g, SE3)
    np.testing.assert_array_equal(g.translation, tf.translation)
    np.testing.assert_allclose(g.as_matrix(), tf.as_matrix(), rtol=0, atol=TOL)
    p = np.array([0.3, -1.5, 2.0])
    np.testing.assert_allclose(g @ p, tf.apply(p), rtol=0, atol=64 * TOL)


@pytest.mark.parametrize("w", SAMPLES)
def test_se3_to_scipy_is_the_same_motion(w):
    g = SE3(SO3.exp(w), [4.0, 0.5, -7.0])
    tf = g.to_scipy()
    assert isinstance(tf, RigidTransform) and tf.single
    np.testing.assert_allclose(tf.as_matrix(), g.as_matrix(), rtol=0, atol=TOL)
    np.testing.assert_array_equal(tf.translation, g.translation)
    assert SE3.from_scipy(tf).is_approx(g, TOL)


def test_scipy_from_matrix_takes_an_se3():
    g = SE3(SO3.exp([0.1, -0.2, 0.3]), [1.0, 2.0, 3.0])
    tf = RigidTransform.from_matrix(g)
    assert tf.single
    np.testing.assert_allclose(tf.as_matrix(), g.as_matrix(), rtol=0, atol=TOL)
    # and the rotation part of a motion, as scipy's Rotation
    np.testing.assert_allclose(Rotation.from_matrix(g.rotation).as_matrix(), g.rotation.as_matrix(), rtol=0, atol=TOL)


def test_se3_from_scipy_refuses_an_unnormalized_transform():
    M = np.eye(4)
    M[:3, :3] *= 1.1
    tf = RigidTransform(M, normalize=False)  # scipy keeps such a matrix as it is
    msg = r"SE3\.from_scipy\(tf\).*not a rigid motion.*from_matrix_projected"
    with pytest.raises(ValueError, match=msg):
        SE3.from_scipy(tf)


# ---- stacks, wrong types, no scipy --------------------------------------------------------


def test_a_stack_is_refused_with_the_array_route():
    stack = Rotation.from_rotvec(random_rotvecs(5, 1))
    msg = r"SO3\.from_scipy\(r\).*single Rotation.*\(5, 3, 3\).*so3_"
    with pytest.raises(ValueError, match=msg):
        SO3.from_scipy(stack)
    with pytest.raises(ValueError, match=r"stack"):
        SO3.from_scipy(Rotation.from_rotvec([[0.1, 0.2, 0.3]]))  # a stack of one is a stack
    tfs = RigidTransform.from_translation(np.ones((4, 3)))
    msg = r"SE3\.from_scipy\(tf\).*single RigidTransform.*\(4, 4, 4\).*se3_"
    with pytest.raises(ValueError, match=msg):
        SE3.from_scipy(tfs)
    # the routes the message names give the same numbers as the objects
    Rs = stack.as_matrix()
    np.testing.assert_allclose(chasles.so3_log(Rs), stack.as_rotvec(), rtol=0, atol=16 * EPS)
    np.testing.assert_allclose(chasles.so3_from_quat(stack.as_quat()), Rs, rtol=0, atol=TOL)
    assert all(SO3.from_scipy(stack[i]).is_approx(SO3.from_matrix(Rs[i]), TOL) for i in range(5))


@pytest.mark.parametrize(
    "call, arg, name",
    [
        (
            SO3.from_scipy,
            RigidTransform.identity(),
            r"SO3\.from_scipy\(r\).*Rotation.*RigidTransform",
        ),
        (SE3.from_scipy, Rotation.identity(), r"SE3\.from_scipy\(tf\).*RigidTransform.*Rotation"),
        (SO3.from_scipy, np.eye(3), r"SO3\.from_scipy\(r\).*Rotation.*ndarray"),
        (SE3.from_scipy, SE3(), r"SE3\.from_scipy\(tf\).*RigidTransform.*SE3"),
        (SO3.from_scipy, None, r"SO3\.from_scipy\(r\).*Rotation.*None"),
    ],
)
def test_other_types_are_a_type_error(call, arg, name):
    with pytest.raises(TypeError, match=name):
        call(arg)


def run_python(code):
    return subprocess.run([sys.executable, "-c", textwrap.dedent(code)], capture_output=True, text=True, check=False)


def test_import_chasles_does_not_import_scipy():
    out = run_python(
        """
        import sys
        import chasles
        R = chasles.SO3.exp([0.1, 0.2, 0.3])
        R.as_quat(), chasles.SE3().log(), chasles.rminus_jacobians(R, R)
        print(sorted(m for m in sys.modules if m == "scipy" or m.startswith("scipy.")))
        R.to_scipy()
        print("scipy.spatial.transform" in sys.modules)
        """
    )
    assert out.returncode == 0, out.stderr
    assert out.stdout.split("\n")[:2] == ["[]", "True"], out.stdout


def test_a_missing_scipy_is_a_clear_import_error():
    # sys.modules[name] = None makes `import name` raise ImportError, as when
    # scipy is not installed.
    out = run_python(
        """
        import sys
        sys.modules["scipy"] = None
        sys.modules["scipy.spatial"] = None
        sys.modules["scipy.spatial.transform"] = None
        import chasles
        for f in (chasles.SO3().to_scipy, chasles.SE3().to_scipy,
                  lambda: chasles.SO3.from_scipy(None), lambda: chasles.SE3.from_scipy(None)):
            try:
                f()
            except ImportError as e:
                print(type(e).__name__, "|", e, "|", type(e.__cause__).__name__)
            else:
                print("no error")
        """
    )
    assert out.returncode == 0, out.stderr
    lines = out.stdout.strip().split("\n")
    assert len(lines) == 4, out.stdout
    for line, what in zip(lines, ["SO3.to_scipy()", "SE3.to_scipy()", "SO3.from_scipy(r)", "SE3.from_scipy(tf)"]):
        kind, message, cause = line.split(" | ")
        assert kind == "ImportError"
        assert message.startswith(what + " needs scipy") and "pip install scipy" in message, line
        assert cause in ("ImportError", "ModuleNotFoundError"), line


# ---- numpy's array protocol (what scipy goes through) ------------------------------------


OBJECTS = [
    SO3.exp([0.1, -0.2, 0.3]),
    SE3(SO3.exp([0.1, -0.2, 0.3]), [1.0, 2.0, 3.0]),
    chasles.Twist(v=[1.0, 2.0, 3.0], w=[0.1, 0.2, 0.3]),
    chasles.Wrench(f=[1.0, 2.0, 3.0], tau=[0.1, 0.2, 0.3]),
]


def value_of(x):
    return x.as_matrix() if isinstance(x, (SO3, SE3)) else np.array(x.vector)


@pytest.mark.parametrize("x", OBJECTS, ids=lambda x: type(x).__name__)
def test_asarray_with_a_dtype(x):
    want = value_of(x)
    for dtype in (np.float64, np.float32, np.longdouble, "float32", np.dtype(np.float16)):
        a = np.asarray(x, dtype=dtype)
        assert a.dtype == np.dtype(dtype) and a.shape == want.shape
        np.testing.assert_array_equal(a, want.astype(dtype))
    a = np.asarray(x)
    assert a.dtype == np.float64
    np.testing.assert_array_equal(a, want)
    assert x.dtype == np.float64  # what numpy's and scipy's dtype discovery read
    assert np.result_type(x, np.float32) == np.float64


@pytest.mark.parametrize("x", OBJECTS, ids=lambda x: type(x).__name__)
def test_array_copy_keyword(x):
    want = value_of(x)
    for copy in (True, None):
        a = np.array(x, copy=copy)
        np.testing.assert_array_equal(a, want)
        a[...] = 0.0  # a fresh array: the object keeps its numbers
    np.testing.assert_array_equal(value_of(x), want)
    np.testing.assert_array_equal(np.array(x, dtype=np.float32, copy=True), want.astype(np.float32))
    # the numbers live in C++: there is no array without a copy (numpy 2's rule)
    with pytest.raises(ValueError, match=r"copy=False.*always a copy"):
        np.array(x, copy=False)
    with pytest.raises(ValueError, match=r"copy=False"):
        np.asarray(x, copy=False)
