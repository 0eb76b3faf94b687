"""Bad input to the objects (SO3, SE3, Twist, Wrench, Screw): every
constructor and method that takes numbers refuses wrong shapes (ValueError
naming the expected and the received shape), non-real dtypes and None
(TypeError naming float64), NaN and infinities where it builds an object
(ValueError), and matrices that are not rotations (ValueError saying by how
much and pointing at from_matrix_projected). Never a crash, never a C++
exception text. The array arguments come from the specification of every
public callable (api_spec.py), so that a new one is checked here too."""

from __future__ import annotations

import decimal
import fractions
import math
import pickle
import re

import api_spec
import numpy as np
import pytest

import chasles
from chasles import SE3, SO3, Chain, Screw, Twist, Wrench

R0 = SO3.exp([0.1, 0.2, 0.3])
G0 = SE3(R0, [1.0, 2.0, 3.0])
XI0 = Twist(v=[1.0, 0.0, 0.0], w=[0.0, 0.0, 1.0])
CHAIN = chasles.Chain([chasles.Chain.prismatic_screw([1.0, 0.0, 0.0])], np.eye(4))
F0 = Wrench(f=[0.0, 0.0, 1.0])
GDOT = G0.as_matrix() @ XI0.hat()


# Every fixed-shape array argument of the specification (api_spec.py): (name,
# call taking the argument under test, a valid value, the expected shape text,
# whether NaN/inf is refused). The valid value is the specification's, but
# where the tests below need one whose integer and boolean forms are valid
# too (an identity, the zero twist matrix, a motion's derivative).
VALID = {
    "SO3.from_matrix(matrix)": np.eye(3),
    "SO3.from_matrix_projected(matrix)": np.eye(3),
    "SO3.from_matrix_unchecked(matrix)": np.eye(3),
    "SO3.rotation_defect(matrix)": np.eye(3),
    "SO3.from_quat(quat)": np.array([0.0, 0.0, 0.0, 1.0]),
    "SE3.vee(matrix)": np.zeros((4, 4)),
    "SE3.from_matrix(matrix)": np.eye(4),
    "SE3.from_matrix_projected(matrix)": np.eye(4),
    "SE3.from_matrix_unchecked(matrix)": np.eye(4),
    "SE3.transform_defect(matrix)": np.eye(4),
    "Twist.vee(matrix)": np.zeros((4, 4)),
    "SO2.from_matrix(matrix)": np.eye(2),
    "SO2.from_matrix_projected(matrix)": np.eye(2),
    "SO2.from_matrix_unchecked(matrix)": np.eye(2),
    "SE2.from_matrix(matrix)": np.eye(3),
    "SE2.from_matrix_projected(matrix)": np.eye(3),
    "SE2.from_matrix_unchecked(matrix)": np.eye(3),
    "Sim3.from_matrix(matrix)": np.eye(4),
    "Sim3.from_matrix_projected(matrix)": np.eye(4),
    "Sim3.from_matrix_unchecked(matrix)": np.eye(4),
    "SE23.from_matrix(matrix)": np.eye(5),
    "SE23.from_matrix_projected(matrix)": np.eye(5),
    "SE23.from_matrix_unchecked(matrix)": np.eye(5),
    "Twist.spatial(g_dot)": GDOT,
    "Twist.body(g_dot)": GDOT,
}
ARRAY_ARGUMENTS = [
    (name, call, VALID.get(name, good), shape, finite) for name, call, good, shape, finite in api_spec.array_arguments()
]

POINT_ARGUMENTS = [
    ("SO3 @ points", lambda x: R0 @ x),
    ("SO3.act(points)", lambda x: R0.act(x)),
    ("SE3 @ points", lambda x: G0 @ x),
    ("SE3.act(points)", lambda x: G0.act(x)),
    ("SE3.act_inv(points)", lambda x: G0.act_inv(x)),
]

C_PLUS_PLUS = re.compile(r"std::|chasles::|Eigen|pybind11::|C\+\+ exception|incompatible function")


def name_of(case):
    return case[0]


def check_message(excinfo, *fragments):
    msg = str(excinfo.value)
    assert not C_PLUS_PLUS.search(msg), msg
    for fragment in fragments:
        assert fragment in msg, f"{fragment!r} not in {msg!r}"


@pytest.mark.parametrize("case", ARRAY_ARGUMENTS, ids=name_of)
def test_valid_value_is_accepted_in_every_array_like_form(case):
    _, call, good, _, _ = case
    call(good)
    call(good.tolist())
    call(good.astype(np.float32))
    call(np.asfortranarray(good))
    if good.ndim == 1:
        call(tuple(good.tolist()))
        call(np.repeat(good, 2)[::2])  # strided
    call(good.astype(">f8"))  # big-endian


@pytest.mark.parametrize("case", ARRAY_ARGUMENTS, ids=name_of)
def test_integer_and_bool_arrays_are_converted(case):
    _, call, good, _, _ = case
    call(np.zeros_like(good, dtype=np.int64) + (good != 0).astype(np.int64))
    call(good != 0)  # bool


@pytest.mark.parametrize("case", ARRAY_ARGUMENTS, ids=name_of)
def test_wrong_shape_is_a_value_error_naming_both_shapes(case):
    name, call, good, shape, _ = case
    wrong = [
        np.zeros(good.size + 1),
        np.zeros((1,) + good.shape),
        np.zeros(()),
        np.zeros(good.shape[:-1] + (0,)),
    ]
    for bad in wrong:
        with pytest.raises(ValueError) as e:
            call(bad)
        got = str(tuple(bad.shape)) if bad.ndim != 1 else f"({bad.shape[0]},)"
        check_message(e, name, f"expected shape {shape}, got {got}")


@pytest.mark.parametrize("case", ARRAY_ARGUMENTS, ids=name_of)
@pytest.mark.parametrize(
    "bad",
    [
        None,
        "abc",
        b"abc",
        1j,
        object(),
        lambda: None,
    ],
    ids=["None", "str", "bytes", "complex", "object", "function"],
)
def test_non_real_scalars_are_type_errors(case, bad):
    name, call, _, _, _ = case
    with pytest.raises(TypeError) as e:
        call(bad)
    check_message(e, name, "float64")


@pytest.mark.parametrize("case", ARRAY_ARGUMENTS, ids=name_of)
def test_non_real_arrays_are_type_errors_naming_the_dtype(case):
    name, call, good, _, _ = case
    for bad, dtype in [
        (good.astype(np.complex128), "complex128"),
        (good.astype(object), "object"),
        (good.astype(str), "<U"),
        (np.array([None] * good.size).reshape(good.shape), "object"),
    ]:
        with pytest.raises(TypeError) as e:
            call(bad)
        check_message(e, name, "float64", dtype)
    with pytest.raises(TypeError) as e:
        call([str(x) for x in good.ravel()] if good.ndim == 1 else good.astype(str).tolist())
    check_message(e, name, "float64")


@pytest.mark.parametrize("case", ARRAY_ARGUMENTS, ids=name_of)
def test_ragged_input_is_a_value_error(case):
    name, call, _, _, _ = case
    with pytest.raises(ValueError) as e:
        call([[1.0, 2.0], [3.0]])
    check_message(e, name)


def test_failed_conversions_name_the_argument_and_keep_the_cause():
    """numpy's refusal (a ragged list, an __array__ that raises) and a
    __float__ that fails (Fraction(10**400) overflows, Decimal("sNaN") has
    no float) become a ValueError naming the argument, with numpy's or the
    object's reason, in the objects' methods. The array functions are
    ufuncs: numpy's own error comes as numpy raises it for any ufunc."""

    class Broken:
        def __array__(self, *args, **kwargs):
            raise RuntimeError("no array for you")

    ragged = [[1.0, 2.0, 3.0], [1.0]]
    for call, text in (
        (SO3.exp, "SO3.exp(w): expected an array-like of real numbers (float64), could not convert list"),
        (lambda p: G0 @ p, "SE3 @ points: could not convert list to an array"),
        (CHAIN.forward, "Chain.forward(theta): could not convert list to an array"),
    ):
        with pytest.raises(ValueError) as e:
            call(ragged)
        check_message(e, text, "inhomogeneous")
        assert isinstance(e.value.__cause__, ValueError)
        with pytest.raises(ValueError) as e:
            call(Broken())
        check_message(e, "no array for you")
        assert isinstance(e.value.__cause__, RuntimeError)
    with pytest.raises(ValueError, match="inhomogeneous"):
        chasles.so3_exp(ragged)
    with pytest.raises(RuntimeError, match="no array for you"):
        chasles.so3_exp(Broken())
    for bad, reason in (
        (fractions.Fraction(10**400), "too large"),
        (decimal.Decimal("sNaN"), "signaling NaN"),
    ):
        for call, name in (
            (lambda t: SO3.interpolate(R0, R0, t), "SO3.interpolate(t)"),
            (lambda t: XI0 * t, "Twist * scalar"),
        ):
            with pytest.raises(ValueError) as e:
                call(bad)
            check_message(e, f"{name}: could not convert", reason)


@pytest.mark.parametrize("case", [c for c in ARRAY_ARGUMENTS if c[4]], ids=name_of)
@pytest.mark.parametrize("value", [math.nan, math.inf, -math.inf])
def test_non_finite_input_to_constructors_is_a_value_error(case, value):
    name, call, good, _, _ = case
    bad = good.astype(float).copy()
    bad.flat[-1] = value
    with pytest.raises(ValueError) as e:
        call(bad)
    check_message(e, name, "finite")


@pytest.mark.parametrize("case", POINT_ARGUMENTS, ids=name_of)
def test_bad_points(case):
    name, call = case
    for bad, sizes in [
        (np.zeros(4), "size 4 is different from 3"),
        (np.zeros((5, 2)), "size 2 is different from 3"),
        (np.zeros(()), "does not have enough dimensions (has 0"),
        ([1.0, 2.0], "size 2 is different from 3"),
    ]:
        with pytest.raises(ValueError) as e:
            call(bad)
        check_message(e, name, sizes)
    for bad in (None, "abc", np.zeros(3, dtype=complex), np.array([1, "a", None], dtype=object)):
        with pytest.raises(TypeError) as e:
            call(bad)
        check_message(e, name, "not supported for the input types")
    with pytest.raises(ValueError):
        call([[1.0, 2.0, 3.0], [1.0, 2.0]])


def test_points_may_hold_nan_which_propagates_to_their_own_row():
    out = G0 @ np.array([[1.0, 2.0, 3.0], [np.nan, 0.0, 0.0]])
    assert np.all(np.isfinite(out[0])) and np.all(np.isnan(out[1]))


# ---- matrices that are not rotations ------------------------------------------------


def test_from_matrix_says_by_how_much_and_what_to_do():
    M = np.eye(3)
    M[0, 1] = 1e-3
    with pytest.raises(ValueError) as e:
        SO3.from_matrix(M)
    check_message(
        e,
        "SO3.from_matrix",
        "not a rotation",
        "defect",
        "0.001",
        "tol = 1.49e-08",
        "SO3.from_matrix_projected",
    )
    assert SO3.from_matrix(M, tol=2e-3).as_matrix()[0, 1] == 1e-3  # kept as is
    with pytest.raises(ValueError) as e:
        SO3.from_matrix(np.diag([1.0, 1.0, -1.0]))
    check_message(e, "det M = -1", "reflection")
    with pytest.raises(ValueError) as e:
        SO3.from_matrix(2.0 * np.eye(3))
    check_message(e, "det M = 8")


def test_se3_from_matrix_checks_the_block_and_the_bottom_row():
    M = np.eye(4)
    M[3, :] = [0.0, 0.0, 0.5, 1.0]
    with pytest.raises(ValueError) as e:
        SE3.from_matrix(M)
    check_message(e, "SE3.from_matrix", "bottom row", "0.5", "SE3.from_matrix_projected")
    M = np.eye(4)
    M[:3, :3] = np.diag([1.0, -1.0, 1.0])
    with pytest.raises(ValueError) as e:
        SE3.from_matrix(M)
    check_message(e, "defect", "reflection")
    assert SE3.from_matrix(np.eye(4) + 1e-10).is_approx(SE3(), 1e-9)  # within the default tolerance


def test_projection_accepts_any_finite_matrix():
    for M in (np.zeros((3, 3)), np.diag([1.0, 1.0, -1.0]), np.ones((3, 3)), 1e200 * np.eye(3)):
        R = SO3.from_matrix_projected(M)
        assert SO3.rotation_defect(R.as_matrix()) < 1e-14


def test_zero_quaternion_is_refused():
    with pytest.raises(ValueError) as e:
        SO3.from_quat([0.0, 0.0, 0.0, 0.0])
    check_message(e, "SO3.from_quat", "zero quaternion")


# ---- scalar arguments --------------------------------------------------------------

SCALAR_ARGUMENTS = [
    ("SO3.from_matrix(tol)", lambda x: SO3.from_matrix(np.eye(3), tol=x), 1e-6, "tolerance"),
    ("SE3.from_matrix(tol)", lambda x: SE3.from_matrix(np.eye(4), tol=x), 1e-6, "tolerance"),
    ("SO3.is_approx(tol)", lambda x: R0.is_approx(R0, tol=x), 1e-6, "tolerance"),
    ("SE3.is_approx(tol)", lambda x: G0.is_approx(G0, tol=x), 1e-6, "tolerance"),
    ("Twist.is_approx(tol)", lambda x: XI0.is_approx(XI0, tol=x), 1e-6, "tolerance"),
    ("Wrench.is_approx(tol)", lambda x: F0.is_approx(F0, tol=x), 1e-6, "tolerance"),
    ("SO3.interpolate(t)", lambda x: SO3.interpolate(R0, SO3(), x), 0.5, "finite"),
    ("SE3.interpolate(t)", lambda x: SE3.interpolate(G0, SE3(), x), 0.5, "finite"),
    ("interpolate(t)", lambda x: __import__("chasles").interpolate(G0, SE3(), x), 0.5, "finite"),
    ("SE3.from_screw(pitch)", lambda x: SE3.from_screw([0, 0, 0], [0, 0, 1], x, 1.0), 0.5, "pitch"),
    (
        "SE3.from_screw(theta)",
        lambda x: SE3.from_screw([0, 0, 0], [0, 0, 1], 0.0, x),
        0.5,
        "finite",
    ),
    (
        "Twist.from_screw(pitch)",
        lambda x: Twist.from_screw([0, 0, 0], [0, 0, 1], x, 1.0),
        0.5,
        "pitch",
    ),
    (
        "Twist.from_screw(theta)",
        lambda x: Twist.from_screw([0, 0, 0], [0, 0, 1], 0.0, x),
        0.5,
        "finite",
    ),
    (
        "Wrench.from_screw(pitch)",
        lambda x: Wrench.from_screw([0, 0, 0], [0, 0, 1], x, 1.0),
        0.5,
        "pitch",
    ),
    (
        "Wrench.from_screw(magnitude)",
        lambda x: Wrench.from_screw([0, 0, 0], [0, 0, 1], 0.0, x),
        0.5,
        "finite",
    ),
    ("Screw(pitch)", lambda x: Screw([0, 0, 0], [0, 0, 1], x, 1.0), 0.5, "pitch"),
    ("Screw(magnitude)", lambda x: Screw([0, 0, 0], [0, 0, 1], 0.0, x), 0.5, "finite"),
]


@pytest.mark.parametrize("case", SCALAR_ARGUMENTS, ids=name_of)
def test_scalar_arguments(case):
    name, call, good, refusal = case
    for ok in (
        good,
        int(good) if float(int(good)) == good else good,
        np.float32(good),
        np.float64(good),
        np.array(good),
        np.int64(1),
        True,
    ):
        call(ok)
    for bad in (None, "0.5", 1j, np.complex128(1), object(), [good]):
        with pytest.raises((TypeError, ValueError)) as e:
            call(bad)
        check_message(e, name)
        assert isinstance(e.value, TypeError) == (not isinstance(bad, list)), (bad, e.value)
    with pytest.raises(ValueError) as e:
        call(math.nan)
    check_message(e, name, refusal)
    with pytest.raises(ValueError) as e:
        call(-math.inf)
    check_message(e, name, refusal)
    with pytest.raises(ValueError) as e:
        call(np.array([good, good]))
    check_message(e, name, "got shape (2,)")


def test_tolerances_refuse_negative_and_accept_inf():
    with pytest.raises(ValueError, match="tolerance >= 0"):
        SO3.from_matrix(np.eye(3), tol=-1.0)
    assert SO3.from_matrix(2.0 * np.eye(3), tol=math.inf).as_matrix()[0, 0] == 2.0


def test_positive_infinite_pitch_is_a_translation_everywhere():
    assert SE3.from_screw([0, 0, 0], [1, 0, 0], math.inf, 2.0).is_approx(SE3(translation=[2, 0, 0]), 0.0)
    assert Twist.from_screw([0, 0, 0], [1, 0, 0], math.inf, 2.0).is_approx(Twist(v=[2, 0, 0]), 0.0)
    assert Wrench.from_screw([0, 0, 0], [1, 0, 0], math.inf, 2.0).is_approx(Wrench(tau=[2, 0, 0]), 0.0)
    assert Screw([0, 0, 0], [1, 0, 0], math.inf, 2.0).pitch == math.inf
    for call in (lambda: SE3.from_screw([0, 0, 0], [1, 0, 0], 0.0, math.inf),):
        with pytest.raises(ValueError):
            call()


def test_huge_integers_are_a_value_error():
    with pytest.raises(ValueError) as e:
        SO3.interpolate(R0, R0, 10**400)
    check_message(e, "too large")


# ---- objects where numbers are expected, and the reverse ------------------------------


# ---- constructors given raw data say what to call instead ----------------------------

MATRIX_FORMS = (
    "from_matrix(matrix)",
    "from_matrix_projected(matrix)",
    "from_matrix_unchecked(matrix)",
)


@pytest.mark.parametrize(
    "make",
    [np.eye(3), np.eye(3).tolist(), np.zeros(3), [0.0, 0.0, 0.0, 1.0], R0],
    ids=["matrix", "nested-list", "vector", "quaternion", "SO3"],
)
def test_so3_takes_no_arguments_and_names_its_constructors(make):
    for call in (lambda: SO3(make), lambda: SO3(matrix=make)):
        with pytest.raises(TypeError) as e:
            call()
        check_message(e, "SO3(", "SO3() takes no arguments", "SO3.exp(w)", "SO3.from_quat(quat)")
        for form in MATRIX_FORMS:
            check_message(e, f"SO3.{form}")
    with pytest.raises(TypeError) as e:
        SO3(np.eye(3))
    check_message(e, "SO3(numpy.ndarray of shape (3, 3))")


def test_se3_takes_a_rotation_and_a_translation_and_names_the_matrix_constructors():
    p = [1.0, 2.0, 3.0]
    g = SE3(R0, p)  # design.md: from (R, p)
    assert g.rotation == R0 and np.array_equal(g.translation, p)
    assert g == SE3(rotation=R0, translation=p) == SE3.from_matrix(g.as_matrix())
    for rotation in (np.eye(3), np.eye(3).tolist(), R0.as_matrix()):
        for call in (lambda: SE3(rotation, p), lambda: SE3(rotation=rotation, translation=p)):
            with pytest.raises(TypeError) as e:
                call()
            check_message(e, "SE3(rotation): expected an SO3, got", "of shape (3, 3)")
            check_message(e, "SE3(SO3.from_matrix(R), p)", *(f"SO3.{f}" for f in MATRIX_FORMS))
    for matrix in (np.eye(4), np.eye(4).tolist(), G0.as_matrix()):
        with pytest.raises(TypeError) as e:
            SE3(matrix)
        check_message(e, "SE3(rotation): expected an SO3, got", "of shape (4, 4)")
        check_message(e, *(f"SE3.{f}" for f in MATRIX_FORMS))
        assert "SO3.from_matrix" not in str(e.value)
    with pytest.raises(TypeError) as e:
        SE3(p)
    check_message(e, "got list of shape (3,)", "SE3(translation=p)")
    with pytest.raises(TypeError) as e:
        SE3(np.zeros(6))
    check_message(e, "SE3.exp(xi)")
    for bad in (None, G0, XI0, "abc"):
        with pytest.raises(TypeError) as e:
            SE3(bad, p)
        check_message(e, "SE3(rotation): expected an SO3, got", "SO3.from_matrix(matrix)")
    with pytest.raises(TypeError) as e:
        SE3(R0, p, p)
    check_message(e, "at most 2 arguments", "got 3")
    with pytest.raises(TypeError) as e:
        SE3(R0, scale=2.0)
    check_message(e, "unexpected keyword argument 'scale'")
    with pytest.raises(TypeError) as e:
        SE3(R0, rotation=R0)
    check_message(e, "rotation given by position and by keyword")
    with pytest.raises(TypeError) as e:
        SE3(SO3.__new__(SO3), p)
    check_message(e, "SO3 object is not initialized")


@pytest.mark.parametrize(
    "cls,parts,vector",
    [(Twist, ("v", "w"), "Twist.from_vector(xi)"), (Wrench, ("f", "tau"), "Wrench.from_vector(F)")],
)
def test_twist_and_wrench_given_six_numbers_name_from_vector(cls, parts, vector):
    six = np.arange(6.0)
    for part in parts:
        with pytest.raises(ValueError) as e:
            cls(**{part: six})
        check_message(e, f"{cls.__name__}({part}): expected shape (3,), got (6,)", vector)
    with pytest.raises(ValueError) as e:
        cls(six)
    check_message(e, vector)
    assert np.array_equal(cls.from_vector(six).vector, six)  # what the message names
    with pytest.raises(ValueError) as e:
        cls(np.zeros(4))
    assert "from_vector" not in str(e.value)  # the hint is for six numbers only


# (the call with the argument under test, its name, the shape of one element,
# a batch of them, the array function the message names: the first of these
# names the package has)
BATCHES = [
    (SO3.exp, "SO3.exp(w)", (3,), np.zeros((5, 3)), ["so3_exp"]),
    (SO3.hat, "SO3.hat(w)", (3,), np.zeros((2, 3)), ["so3_hat"]),
    (SO3.vee, "SO3.vee(matrix)", (3, 3), np.zeros((2, 3, 3)), ["so3_vee"]),
    (SO3.from_quat, "SO3.from_quat(quat)", (4,), np.ones((5, 4)), ["so3_from_quat"]),
    (SE3.exp, "SE3.exp(xi)", (6,), np.zeros((10, 6)), ["se3_exp"]),
    (SE3.hat, "SE3.hat(xi)", (6,), np.zeros((4, 6)), ["se3_hat", "twist_hat"]),
    (SE3.vee, "SE3.vee(matrix)", (4, 4), np.zeros((3, 4, 4)), ["se3_vee", "twist_vee"]),
    (Twist.vee, "Twist.vee(matrix)", (4, 4), np.zeros((2, 1, 4, 4)), ["se3_vee", "twist_vee"]),
]


@pytest.mark.parametrize("case", BATCHES, ids=lambda c: c[1])
def test_a_batch_given_to_a_method_names_the_array_function(case):
    call, name, core, batch, candidates = case
    function = next(f for f in candidates if hasattr(chasles, f))
    with pytest.raises(ValueError) as e:
        call(batch)
    check_message(e, f"{name}: expected shape {core}, got {batch.shape}")
    check_message(e, f"for a batch, call the array function chasles.{function}")
    leading = batch.shape[: batch.ndim - len(core)]
    assert getattr(chasles, function)(batch).shape[: len(leading)] == leading  # it takes the batch
    with pytest.raises(ValueError) as e:
        call(np.zeros((5, 7)))  # not a batch of elements: no hint
    assert "array function" not in str(e.value)


def test_many_fractions_given_to_interpolate_name_the_array_functions():
    ts = np.linspace(0.0, 1.0, 5)
    for call, name, functions in (
        (lambda t: SO3.interpolate(R0, R0, t), "SO3.interpolate(t)", ["chasles.so3_interpolate"]),
        (lambda t: SE3.interpolate(G0, G0, t), "SE3.interpolate(t)", ["chasles.se3_interpolate"]),
        (
            lambda t: chasles.interpolate(G0, G0, t),
            "interpolate(t)",
            ["chasles.so3_interpolate", "chasles.se3_interpolate"],
        ),
    ):
        with pytest.raises(ValueError) as e:
            call(ts)
        check_message(e, name, "expected a real number (shape ()), got shape (5,)", *functions)
    assert chasles.se3_interpolate(G0.as_matrix(), G0.as_matrix(), ts).shape == (5, 4, 4)


def test_wrong_object_types_are_type_errors():
    with pytest.raises(TypeError):
        SE3(np.eye(3), [0, 0, 0])  # rotation must be an SO3
    with pytest.raises(TypeError):
        SE3(None)
    with pytest.raises(TypeError) as e:
        G0 @ XI0
    check_message(e, "SE3 @ points", "g.act(x)")
    with pytest.raises(TypeError) as e:
        G0 @ F0
    check_message(e, "g.act(x)")
    with pytest.raises(TypeError) as e:
        R0 @ G0
    check_message(e, "SO3 @ points", "SE3")
    with pytest.raises(TypeError):
        G0 @ R0
    with pytest.raises(TypeError):
        R0.act(XI0)
    with pytest.raises(TypeError):
        G0.act(R0)
    with pytest.raises(TypeError):
        G0.act_inv(G0)
    with pytest.raises(TypeError):
        R0.is_approx(G0)
    with pytest.raises(TypeError):
        G0.is_approx(None)
    with pytest.raises(TypeError):
        SE3.interpolate(G0, R0, 0.5)
    with pytest.raises(TypeError):
        XI0.power(XI0)
    with pytest.raises(TypeError):
        F0.power(F0)
    with pytest.raises(TypeError):
        XI0.bracket(F0)
    with pytest.raises(TypeError):
        Twist.spatial(G0.as_matrix(), GDOT)


def test_arithmetic_with_the_wrong_operands():
    with pytest.raises(TypeError):
        XI0 + F0
    with pytest.raises(TypeError):
        XI0 - 1.0
    with pytest.raises(TypeError):
        XI0 * XI0
    with pytest.raises(TypeError):
        XI0 * "2"
    with pytest.raises(TypeError):
        XI0 * [1.0, 2.0]
    with pytest.raises(TypeError):
        XI0 * np.ones(6)
    with pytest.raises(TypeError):
        XI0 * 1j
    with pytest.raises(TypeError):
        G0 * G0  # composition is @
    with pytest.raises(ValueError, match="finite"):
        XI0 * math.nan
    with pytest.raises(ValueError, match="finite"):
        math.inf * F0
    with pytest.raises(ZeroDivisionError):
        XI0 / 0.0
    with pytest.raises(TypeError):
        1.0 / XI0
    big = Twist(v=[1e300, 0.0, 0.0])
    with pytest.raises(ValueError, match="overflows"):
        big * 1e10
    with pytest.raises(ValueError, match="overflows"):
        big / 1e-10
    with pytest.raises(ValueError, match="overflows"):
        Twist(v=[1.7e308, 0, 0]) + Twist(v=[1.7e308, 0, 0])


@pytest.mark.parametrize("cls,n", [(SO3, 9), (SE3, 12), (Twist, 6), (Wrench, 6), (Screw, 8)])
def test_setstate_refuses_bad_states(cls, n):
    x = cls.__new__(cls)
    with pytest.raises(ValueError, match="tuple of"):
        x.__setstate__((1.0,) * (n + 1))
    with pytest.raises(ValueError, match="tuple of"):
        x.__setstate__([1.0] * n)
    with pytest.raises(TypeError, match="floats"):
        x.__setstate__(("a",) + (1.0,) * (n - 1))


def test_uninitialized_objects_are_refused_not_crashed():
    raw = SE3.__new__(SE3)
    with pytest.raises(TypeError):
        G0 @ raw
    with pytest.raises(TypeError):
        SE3.interpolate(raw, G0, 0.5)


def test_uninitialized_objects_are_never_read():
    """An instance made by cls.__new__(cls) alone holds no value. Methods
    that once took it through pybind11's generic caster were handed freshly
    allocated, uninitialized memory (a Chain reported billions of joints,
    SE3.exp of such a Twist returned garbage); every one of them refuses it
    now, and so do Chain(home=...) and SE3.exp(twist). Its repr says what
    it is instead of raising."""
    calls = [
        (SO3, lambda x: x.normalized()),
        (SE3, lambda x: x.normalized()),
        (Twist, lambda x: x.screw()),
        (Twist, lambda x: x.pitch()),
        (Wrench, lambda x: x.screw()),
        (Wrench, lambda x: x.pitch()),
        (Screw, lambda x: x.point),
        (Screw, lambda x: x.direction),
        (Screw, lambda x: x.pitch),
        (Screw, lambda x: x.magnitude),
        (Screw, lambda x: list(x)),
        (Screw, len),
        (Screw, lambda x: x.is_approx(x)),
        (Screw, lambda x: x.__copy__()),
        (Screw, lambda x: x.__getstate__()),
        (Chain, lambda x: x.n_joints),
        (Chain, lambda x: x.space_screws),
        (Chain, lambda x: x.body_screws),
        (Chain, lambda x: x.home),
        (Chain, lambda x: x.__reduce_ex__(2)),
        (Chain, lambda x: x.forward([0.0])),
        (Chain, lambda x: x.jacobian_body([0.0])),
        (SE3, lambda x: Chain([[0.0, 0.0, 0.0, 0.0, 0.0, 1.0]], x)),
        (Twist, SE3.exp),
    ]
    for cls, call in calls:
        for _ in range(2):  # a first refused call must not leave storage behind to read
            with pytest.raises(TypeError) as e:
                call(cls.__new__(cls))
            check_message(e, f"{cls.__name__} object is not initialized")
        raw = cls.__new__(cls)
        with pytest.raises(TypeError):
            call(raw)
        with pytest.raises(TypeError):
            call(raw)
    for cls in (SO3, SE3, Twist, Wrench, Screw, Chain):
        assert repr(cls.__new__(cls)) == f"<uninitialized {cls.__name__}>"


def test_no_exception_leaks_from_pickle_of_the_wrong_thing():
    with pytest.raises(Exception) as e:
        pickle.loads(pickle.dumps(G0).replace(b"SE3", b"SO3"))
    check_message(e)
