"""The argument specification of every public callable of chasles, for the
bad-input tests (test_api_fuzz.py) and the thread and leak tests.

``callables()`` enumerates the public API from the module itself: every
name of ``chasles.__all__`` and every method, static method and property
of its classes (``SO3``, ``SE3``, ``Twist``, ``Wrench``, ``Screw``,
``Chain``), so that a function added to the package without an entry in
``SPEC`` fails ``test_every_public_callable_has_a_specification``.

``SPEC`` maps each of them to its signatures (one per overload that takes
different arguments), each a list of argument kinds. An argument kind
knows

- a valid value (``good()``);
- how the library must answer any other value (``judge(value)``): either
  the error it must raise (``Refused``: TypeError or ValueError, and text
  the message must contain: the argument's name, the expected shape or
  dtype and what came), or the canonical value it must treat the input as
  (``Accepted``): the plain C-contiguous float64 array of the same numbers
  (float32 kept for the array functions), a Python float, an object of the
  base class. The call with the input must then give exactly (bit for bit)
  what the call with the canonical value gives.

That judgement is the documented contract of the Python layer, written
independently of the bindings:

- objects (SO3, SE3, Twist, Wrench, Screw, Chain) are float64: array-like
  arguments of any real dtype (bool, integers, float16, float32, float64,
  longdouble) are converted to float64, whatever their layout (strided,
  Fortran, negative strides, read-only, unaligned), container (list,
  tuple, nested) or ndarray subclass (np.matrix, user subclasses); the
  shape must be exactly the documented one (an empty array is a wrong
  shape: ValueError); constructors refuse NaN and infinities (ValueError),
  functions that return the numbers given, rearranged (hat, vee, the
  actions on points), carry them through, and the defects are inf;
- array functions (so3_*, se3_*) are numpy generalized ufuncs with a
  float32 and a float64 loop, so numpy's rules decide: an operand's dtype
  must cast safely to float64 (complex, object, string, datetime and long
  double arrays are a TypeError naming the function), and the float32 loop
  runs when every operand casts safely to float32 (float16, bool and small
  integers included); core shapes are checked by numpy (ValueError naming
  the function and the sizes); a zero-size batch gives an empty result of
  the right shape; NaN stays in its own element;
- the objects' actions on points and Chain's batch methods call those
  ufuncs, so the same rules hold, and their errors name the call;
- complex numbers, None, strings, bytes and arbitrary objects are a
  TypeError; a ragged nested list is a ValueError; an object where an
  SO3 (...) is expected must be one, initialized (TypeError otherwise).
"""

from __future__ import annotations

import collections.abc
import math
import operator
import warnings
from dataclasses import dataclass
from typing import Any, Callable

import numpy as np

import chasles

# ---- verdicts -------------------------------------------------------------------------


@dataclass
class Refused:
    """The call must raise `error` with a message containing every fragment."""

    error: type
    fragments: tuple = ()


@dataclass
class Accepted:
    """The call must behave exactly as with `value` in place of the input."""

    value: Any


@dataclass
class Gives:
    """The call must return `value` (a comparison with an object of another type)."""

    value: Any


# The cubic B-spline classes, one per group (test_threads evaluates each).
BSPLINES = (
    chasles.SO3BSpline,
    chasles.SE3BSpline,
    chasles.SO2BSpline,
    chasles.SE2BSpline,
    chasles.Sim3BSpline,
    chasles.SE23BSpline,
)

BOUND = (
    chasles.SO3,
    chasles.SE3,
    chasles.SO2,
    chasles.SE2,
    chasles.Sim3,
    chasles.SE23,
    chasles.Twist,
    chasles.Wrench,
    chasles.Screw,
    chasles.Chain,
    chasles.SpatialInertia,
)


def is_initialized(x) -> bool:
    """Whether a bound object holds a value (its __init__ or __setstate__ ran)."""
    return not repr(x).startswith("<uninitialized ")


def shape_text(shape) -> str:
    """A shape as Python prints it: "(3,)", "(2, 3)", "()"."""
    return str(tuple(int(d) for d in shape))


def _asarray(value):
    """np.asarray(value), or the Refused verdict numpy's own failure implies."""
    try:
        return np.asarray(value)
    except ValueError:
        return Refused(ValueError, ("could not convert",))
    except TypeError:
        return Refused(TypeError, ("could not convert",))


REAL_KINDS = "biuf"


def plain(a, dtype):
    """The same numbers as a fresh C-contiguous, aligned, native-endian array
    of `dtype`, of the same shape (np.ascontiguousarray would make a 0-d
    array 1-d)."""
    return np.array(a, dtype=dtype, order="C", copy=True)


# ---- argument kinds ---------------------------------------------------------------------


@dataclass
class Arg:
    """An argument: `label` is how error messages name it. Each kind below
    has good() (a valid value) and judge(value) (a Refused, an Accepted, or
    None where there is no model: any outcome but a crash or an exception
    other than TypeError and ValueError)."""

    label: str


@dataclass
class Array(Arg):
    """An array-like of one fixed shape for an object method (float64)."""

    shape: tuple = (3,)
    finite: bool = True
    valid: Callable[[], Any] | None = None

    def good(self):
        if self.valid is not None:
            return self.valid()
        return np.linspace(0.1, 0.1 * math.prod(self.shape), math.prod(self.shape)).reshape(self.shape)

    def judge(self, value):
        return judge_fixed_array(value, self.label, (self.shape,), self.finite)


def real_array(value, label):
    """The ndarray an object method reads an array-like argument as, or the
    refusal: None, str and bytes, what numpy cannot convert, and what is
    not of a real dtype."""
    if value is None or isinstance(value, (str, bytes)):
        return Refused(TypeError, (label, "float64"))
    a = _asarray(value)
    if isinstance(a, Refused):
        return Refused(a.error, (label,) + a.fragments)
    if a.dtype.kind not in REAL_KINDS:
        return Refused(TypeError, (label, "float64", str(a.dtype)))
    return a


def finite_or_refused(a, label, finite=True):
    """Accepted as float64, unless `finite` and a number is not."""
    c = plain(a, np.float64)
    if finite and not np.isfinite(c).all():
        return Refused(ValueError, (label, "finite"))
    return Accepted(c)


def judge_fixed_array(value, label, shapes, finite):
    a = real_array(value, label)
    if isinstance(a, Refused):
        return a
    if a.shape not in shapes:
        return Refused(ValueError, (label, "expected shape", f"got {shape_text(a.shape)}"))
    return finite_or_refused(a, label, finite)


@dataclass
class GroupMatrix(Array):
    """The mean of so3_gaussian / se3_gaussian: a finite (3, 3) rotation or
    (4, 4) rigid motion (an SO3 or SE3 through np.asarray), checked as
    SO3.from_matrix / SE3.from_matrix check one (rotation defect and bottom
    row within sqrt(eps))."""

    def judge(self, value):
        verdict = super().judge(value)
        if not isinstance(verdict, Accepted):
            return verdict
        m = verdict.value
        defect = _rotation_defect(m[:3, :3])
        if m.shape == (4, 4):
            defect = max(defect, float(np.abs(m[3] - [0.0, 0.0, 0.0, 1.0]).max()))
        if not defect <= 1.4901161193847656e-08:
            what = "not a rotation matrix" if m.shape == (3, 3) else "not a rigid motion"
            return Refused(ValueError, (self.label, what))
        return verdict


@dataclass
class TwistOr(Array):
    """SE3.exp's argument: a Twist, or an array-like of shape (6,)."""

    def judge(self, value):
        if isinstance(value, chasles.Twist):
            return Instance(self.label, (chasles.Twist,)).judge(value)
        return super().judge(value)


@dataclass
class Points(Arg):
    """Points of an object's action: the array function so3_act, se3_act,
    so2_act or se2_act with the object's float64 matrix (float32 for a
    float32 ndarray: float32 points give float32), so shape (..., n) (n = 3,
    or 2 in the plane), any dtype numpy casts safely to float64, NaN allowed;
    errors name the call."""

    n: int = 3

    def good(self):
        return np.array([[0.5, -1.0, 2.0], [1.0, 0.0, 0.25]])[:, : self.n]

    def judge(self, value):
        if isinstance(value, BOUND):
            return Refused(TypeError, (self.label,))
        if beyond_numpy_scalars(value):
            return None
        a = _asarray(value)
        if isinstance(a, Refused):
            return Refused(a.error, (self.label,))
        if not castable_to_float64(a.dtype):
            return Refused(TypeError, (self.label, "not supported for the input types"))
        shape = core_shape_refusal(a.shape, (self.n,))
        if shape:
            return Refused(ValueError, (self.label,) + shape)
        float32 = isinstance(value, np.ndarray) and value.dtype.type is np.float32
        return Accepted(plain(a, np.float32 if float32 else np.float64))


@dataclass
class JointArray(Arg):
    """Joint positions of a chain of n joints, for its array-function
    methods: shape (..., n), any dtype numpy casts safely to float64, NaN
    allowed (NaN results); errors name the call."""

    n: int = 2

    def good(self):
        return np.array([0.3, -0.7])[: self.n]

    def judge(self, value):
        n = self.n
        a = _asarray(value)
        if isinstance(a, Refused):
            return Refused(a.error, (self.label, "could not convert"))
        if a.ndim < 1 or a.shape[-1] != n:
            return Refused(ValueError, (self.label, f"({n},) or (..., {n})", f"got {shape_text(a.shape)}"))
        if not castable_to_float64(a.dtype):
            return Refused(TypeError, (self.label, "not supported for the input types"))
        return Accepted(plain(a, np.float64))


@dataclass
class IKTarget(Arg):
    """Chain.inverse_kinematics' target: an SE3 or an array-like of shape
    (4, 4) or (..., 4, 4) of real numbers, each a rigid motion (defect at most
    1.49e-8; NaN is not one)."""

    def good(self):
        return np.asarray(CHAIN_HOME)

    def judge(self, value):
        if isinstance(value, chasles.SE3) and not is_initialized(value):
            return Refused(TypeError, (self.label, "not initialized"))
        a = real_array(value, self.label)
        if isinstance(a, Refused):
            return a
        if a.ndim < 2 or a.shape[-2:] != (4, 4):
            return Refused(ValueError, (self.label, "expected an SE3 or shape (4, 4)"))
        c = plain(a, np.float64).reshape(-1, 4, 4)
        with np.errstate(all="ignore"):
            R = c[:, :3, :3]
            defect = np.maximum(
                np.abs(np.swapaxes(R, -1, -2) @ R - np.eye(3)).max(axis=(-1, -2)),
                np.abs(np.linalg.det(R) - 1.0) if c.size else np.zeros(0),
            )
            defect = np.maximum(defect, np.abs(c[:, 3, :] - [0.0, 0.0, 0.0, 1.0]).max(axis=-1))
        if not np.all(defect <= 1.4901161193847656e-08):
            return Refused(ValueError, (self.label, "not a rigid motion"))
        return Accepted(plain(a, np.float64))


@dataclass
class IKSeed(Arg):
    """Chain.inverse_kinematics' q0: real numbers of shape (n,) or (..., n), finite."""

    n: int = 2

    def good(self):
        return np.array([0.3, -0.7])[: self.n]

    def judge(self, value):
        a = real_array(value, self.label)
        if isinstance(a, Refused):
            return a
        if a.ndim < 1 or a.shape[-1] != self.n:
            return Refused(ValueError, (self.label, f"({self.n},) or (..., {self.n})", f"got {shape_text(a.shape)}"))
        return finite_or_refused(a, self.label)


@dataclass
class ScrewRows(Arg):
    """The screws of a chain: shape (n, 6), 1 <= n <= 32, finite."""

    def good(self):
        return np.array([[0.0, 0.0, 0.0, 0.0, 0.0, 1.0], [0.0, -1.0, 0.0, 0.0, 0.0, 1.0]])

    def judge(self, value):
        a = real_array(value, self.label)
        if isinstance(a, Refused):
            return a
        if a.ndim != 2 or a.shape[1] != 6 or a.shape[0] < 1:
            return Refused(ValueError, (self.label, "(n, 6)", f"got {shape_text(a.shape)}"))
        if a.shape[0] > 32:
            return Refused(ValueError, (self.label, "at most 32 joints"))
        judged = finite_or_refused(a, self.label)
        if isinstance(judged, Refused):
            return judged
        # the joint types inferred (prismatic where w = 0, helical where the
        # pitch is not zero, revolute elsewhere), each screw checked against
        # its type (Chain::validate, tolerance sqrt(eps) =
        # 1.4901161193847656e-08): |w| = 1 (a pitch makes the joint helical),
        # or |v| = 1 for a prismatic joint
        tol = 1.4901161193847656e-08
        for v, w in zip(judged.value[:, :3], judged.value[:, 3:]):
            # as the C++ computes them: norms as sqrt of the sum of squares
            # (a subnormal w squares to 0: a prismatic joint; a huge one to inf)
            with np.errstate(over="ignore", invalid="ignore"):
                ww, vv = float(w @ w), float(v @ v)
            if ww > 0:
                ok = abs(math.sqrt(ww) - 1) <= tol
            else:
                ok = abs(math.sqrt(vv) - 1) <= tol
            if not ok:
                return Refused(ValueError, (self.label, "joint"))
        return judged


@dataclass
class Operand(Arg):
    """An operand of an array function (a numpy generalized ufunc with a
    float32 and a float64 loop): shape (..., *core)."""

    core: tuple = (3,)
    valid: Callable[[], Any] | None = None

    def good(self):
        if self.valid is not None:
            return self.valid()
        size = math.prod(self.core)
        return np.linspace(0.1, 0.1 * size, size).reshape(self.core) if self.core else 0.5

    def judge(self, value):
        fname, _ = self.label.split(":")
        if beyond_numpy_scalars(value):
            return None
        if isinstance(value, (np.matrix, np.ma.MaskedArray)):
            # numpy's subclass rules (subok, __array_wrap__): np.matrix keeps
            # two axes, numpy.ma maps masks as for an elementwise ufunc
            return None
        if getattr(type(value), "__array_ufunc__", False) is None:
            # SO3, SE3, Twist and Wrench opt out of ufuncs (numpy then defers operators to them)
            return Refused(TypeError, ("does not support ufuncs",))
        a = _asarray(value)
        if isinstance(a, Refused):
            return Refused(a.error)  # numpy's own conversion error
        if not castable_to_float64(a.dtype):
            return Refused(TypeError, (fname, "not supported for the input types"))
        shape = core_shape_refusal(a.shape, self.core)
        if shape:
            return Refused(ValueError, (fname,) + shape)
        if type(value) in (float, int, bool):  # a weak Python scalar, as it is
            return Accepted(value)
        return Accepted(plain(a, np.float32 if castable_to_float32(a.dtype) else np.float64))


# numpy's own errors for Python numbers its ufuncs cannot take as they are.
NUMPY_SCALAR_ERRORS = (OverflowError, RuntimeWarning)


def beyond_numpy_scalars(value) -> bool:
    """A Python int beyond 64 bits or a Python float beyond float32's range,
    given alone: numpy's NEP 50 handling of such a weak scalar depends on the
    other operands (an OverflowError, a RuntimeWarning from its cast, or a
    conversion to an object array refused as any other), so there is no
    model beyond 'no crash and no other exception'."""
    if type(value) is int:
        return not -(2**63) <= value < 2**64
    if type(value) is float:
        return math.isfinite(value) and abs(value) > float(np.finfo(np.float32).max)
    return False


def sample_operand(arg: Operand, shape, rng, dtype=np.float64):
    """Valid values of an operand with a batch of `shape`: rotations and
    poses where a 3x3 or 4x4 core is read as one, random numbers otherwise."""
    n = int(np.prod(shape))
    if arg.core == (3, 3):
        x = chasles.so3_exp(rng.normal(size=(n, 3)))
    elif arg.core == (4, 4):
        x = chasles.se3_exp(rng.normal(size=(n, 6)))
    elif arg.core == ():
        x = rng.uniform(-0.5, 1.5, size=n)
    else:
        x = rng.normal(size=(n,) + arg.core)
    return x.reshape(tuple(shape) + arg.core).astype(dtype)


def castable_to_float64(dtype) -> bool:
    """Whether numpy casts the dtype safely to float64 (the ufuncs' wider loop)."""
    return np.can_cast(dtype, np.float64, casting="safe")


def castable_to_float32(dtype) -> bool:
    """Whether numpy casts the dtype safely to float32: numpy then picks the
    float32 loop (the first one registered)."""
    return np.can_cast(dtype, np.float32, casting="safe")


def core_shape_refusal(shape, core) -> tuple:
    """The fragments of numpy's message for an operand whose trailing axes
    do not match the core shape of the signature, or () if they do."""
    nc = len(core)
    if len(shape) < nc:
        return ("does not have enough dimensions",)
    for got, want in zip(shape[len(shape) - nc :], core):
        if got != want:
            return (f"size {got} is different from {want}",)
    return ()


@dataclass
class Real(Arg):
    """A real number: float, int, bool, numpy real scalar or 0-d array, or
    an object with __float__. `rule`: 'finite', 'tolerance' (>= 0, inf
    allowed), 'pitch' (finite or +inf)."""

    rule: str = "finite"
    valid: float = 0.5

    def good(self):
        return self.valid

    def judge(self, value):
        x = _real(value, self.label)
        if isinstance(x, Refused):
            return x
        return _rule(x, self.label, self.rule)


def _real(value, label):
    if isinstance(value, int):  # bool included
        try:
            return float(value)
        except OverflowError:
            return Refused(ValueError, (label, "too large"))
    if isinstance(value, float):
        return float(value)
    if value is None or isinstance(value, (complex, np.complexfloating)):
        return Refused(TypeError, (label,))
    if isinstance(value, (str, bytes)):
        return Refused(TypeError, (label, "float64"))
    if isinstance(value, (np.ndarray, np.generic, collections.abc.Sequence)):
        a = _asarray(value)
        if isinstance(a, Refused):
            return Refused(a.error, (label,))
        if a.dtype.kind not in REAL_KINDS:
            return Refused(TypeError, (label, "float64", str(a.dtype)))
        if a.ndim != 0:
            return Refused(ValueError, (label, "shape ()", f"got shape {shape_text(a.shape)}"))
        return float(a.astype(np.float64))
    if hasattr(type(value), "__float__"):
        try:
            return float(value)
        except TypeError:
            return Refused(TypeError, (label,))
        except (ValueError, OverflowError):  # Fraction(10**400), Decimal("sNaN")
            return Refused(ValueError, (label,))
    return Refused(TypeError, (label,))


def _rule(x, label, rule):
    if rule == "positive" and math.isfinite(x) and not x > 0.0:
        return Refused(ValueError, (label, "positive"))
    if rule == "positive" and not math.isfinite(x):
        return Refused(ValueError, (label, "finite"))
    if rule == "finite" and not math.isfinite(x):
        return Refused(ValueError, (label, "finite"))
    if rule == "tolerance" and not x >= 0.0:
        return Refused(ValueError, (label, "tolerance >= 0"))
    if rule == "pitch" and (math.isnan(x) or x == -math.inf):
        return Refused(ValueError, (label, "pitch"))
    return Accepted(x)


@dataclass
class Angle(Arg):
    """SO2's tangent, the angle theta: a real number (Real), or an
    array-like of shape (1,) (Array); finite unless `finite` is False."""

    finite: bool = True

    def good(self):
        return 0.5

    def judge(self, value):
        if isinstance(value, (np.ndarray, list, tuple)) or (
            hasattr(value, "__array__") and not isinstance(value, (np.generic, *BOUND))
        ):
            a = _asarray(value)
            if not isinstance(a, Refused) and a.ndim >= 1:
                return judge_fixed_array(value, self.label, ((1,),), self.finite)
        return Real(self.label, "finite" if self.finite else "any").judge(value)


@dataclass
class Scalar(Arg):
    """The number of ``x * s``, ``s * x``, ``x / s`` (Twist, Wrench): a real
    scalar; anything else is not a number the operator knows (TypeError,
    from Python, when the operator returns NotImplemented)."""

    def good(self):
        return 2.0

    def judge(self, value):
        if isinstance(value, np.ndarray) and value.ndim != 0:
            return Refused(TypeError, ())
        if value is None or isinstance(value, (*BOUND, complex, str, bytes, collections.abc.Sequence)):
            return Refused(TypeError, ())
        x = _real(value, self.label)
        if isinstance(x, Refused):
            return Refused(TypeError, ()) if x.error is TypeError else x
        return _rule(x, self.label, "finite")


@dataclass
class Flag(Arg):
    """A bool option: anything with a truth value pybind11 reads, as bool()."""

    def good(self):
        return False

    def judge(self, value):
        if value is None or isinstance(value, (bool, np.bool_)):
            return Accepted(bool(value))
        if isinstance(value, (int, float, np.integer, np.floating)):
            return Accepted(bool(value))
        return None  # pybind11's truth test: any outcome but a crash, checked as is


EULER_SEQUENCES = tuple(
    s
    for b in ("xyz", "xzy", "yxz", "yzx", "zxy", "zyx", "xyx", "xzx", "yxy", "yzy", "zxz", "zyz")
    for s in (b, b.upper())
)


@dataclass
class Sequence(Arg):
    """An Euler axis sequence: a str (subclasses included), one of scipy's 24
    (lowercase extrinsic, uppercase intrinsic); another str is a ValueError,
    anything else a TypeError, both naming the argument."""

    def good(self):
        return "ZYX"

    def judge(self, value):
        if not isinstance(value, str):
            return Refused(TypeError, (self.label, "str"))
        if value not in EULER_SEQUENCES:
            return Refused(ValueError, (self.label, "three axes", "got"))
        return Accepted(str(value))


@dataclass
class Instance(Arg):
    """An object of one of `classes`, initialized (TypeError for anything else)."""

    classes: tuple = (chasles.SO3,)
    valid: Callable[[], Any] | None = None
    uninitialized_ok: bool = False  # __repr__ shows an uninitialized object
    refused: tuple = ()  # what the message of a refused other object must say

    def good(self):
        return self.valid() if self.valid is not None else GOOD[self.classes[0]]()

    def judge(self, value):
        if isinstance(value, self.classes):
            if self.uninitialized_ok and not is_initialized(value):
                return Accepted(value)
            if not is_initialized(value):
                # (pybind11's own refusal when another argument rules out the overload first)
                return Refused(TypeError, (("not initialized", "incompatible function arguments"),))
            return Accepted(base_copy(value))
        return Refused(TypeError, self.refused)


@dataclass
class Comparand(Instance):
    """The right operand of ``==`` and ``!=``: an object of the same class is
    compared (an uninitialized one refused, TypeError); anything else is
    another value, so ``==`` gives False and ``!=`` True (the operator
    returns NotImplemented and Python falls back to identity; numpy arrays
    and scalars defer to the objects, whose __array_ufunc__ is None)."""

    other_gives: bool = False

    def judge(self, value):
        if isinstance(value, self.classes):
            return super().judge(value)
        if isinstance(value, BOUND) and not is_initialized(value):
            # its own __eq__, tried in turn, refuses it as every method does
            return Refused(TypeError, ("not initialized",))
        return Gives(self.other_gives)


@dataclass
class Home(Arg):
    """A chain's home pose: an SE3, or a (4, 4) array-like rigid motion."""

    def good(self):
        return chasles.SE3(translation=[2.0, 0.0, 0.0])

    def judge(self, value):
        if isinstance(value, chasles.SE3):
            return Instance(self.label, (chasles.SE3,)).judge(value)
        return judge_fixed_array(value, self.label, ((4, 4),), True)


@dataclass
class RotationalInertia(Arg):
    """SpatialInertia's I_c: shape (3, 3), finite, and the inertia of a
    rigid body (symmetric to 1.49e-8 of its largest entry, positive definite,
    principal moments satisfying the triangle inequality to 1.49e-8 of the
    trace): otherwise ValueError naming the argument."""

    def good(self):
        return np.array([[0.1, 0.01, 0.0], [0.01, 0.2, 0.0], [0.0, 0.0, 0.25]])

    def judge(self, value):
        verdict = judge_fixed_array(value, self.label, ((3, 3),), True)
        if not isinstance(verdict, Accepted):
            return verdict
        scale = np.max(np.abs(verdict.value))
        if not scale > 0:
            return Refused(ValueError, (self.label, "positive definite"))
        inertia = verdict.value / scale  # the conditions are scale-invariant; no overflow
        tol = 1.4901161193847656e-08
        if not np.max(np.abs(inertia - inertia.T)) <= tol:
            return Refused(ValueError, (self.label, "not symmetric"))
        moments = np.linalg.eigvalsh((inertia + inertia.T) / 2)
        if not moments.min() > 0:
            return Refused(ValueError, (self.label, "positive definite"))
        if not 2 * moments.max() <= moments.sum() * (1 + 2 * tol):
            return Refused(ValueError, (self.label, "triangle inequality"))
        return verdict


def _rotation_defect(R):
    """max(|R^T R - I|, |det R - 1|), inf for a matrix that is not finite."""
    R = np.asarray(R, dtype=np.float64)
    if not np.all(np.isfinite(R)):
        return math.inf
    with np.errstate(all="ignore"):
        return float(max(np.abs(R.T @ R - np.eye(3)).max(), abs(np.linalg.det(R) - 1.0)))


def _valid_state(cls_name, state):
    """Whether a tuple of floats of the right size is a state the class's
    constructor would take (its checks: finite numbers, rotations within
    sqrt(eps), a screw pitch that is not NaN or -inf, a rigid body's inertia,
    a chain's screws that match their inferred types)."""
    x = np.array(state, dtype=np.float64)
    tol = 1.4901161193847656e-08
    if cls_name == "Screw":
        return bool(np.all(np.isfinite(x[[0, 1, 2, 3, 4, 5, 7]]))) and not (math.isnan(x[6]) or x[6] == -math.inf)
    if not np.all(np.isfinite(x)):
        return False
    if cls_name in ("SO3", "SE3", "SE23"):
        return _rotation_defect(x[:9].reshape(3, 3)) <= tol
    if cls_name == "Sim3":
        return _rotation_defect(x[:9].reshape(3, 3)) <= tol and x[12] > 0
    if cls_name in ("SO2", "SE2"):
        c, s = x[0], x[1]
        R = np.array([[c, -s], [s, c]])
        with np.errstate(all="ignore"):
            return max(np.abs(R.T @ R - np.eye(2)).max(), abs(np.linalg.det(R) - 1.0)) <= tol
    if cls_name == "SpatialInertia":
        return x[0] > 0 and isinstance(RotationalInertia("I").judge(x[4:].reshape(3, 3)), Accepted)
    if cls_name == "Chain":
        n = (len(x) - 12) // 6
        return _rotation_defect(x[6 * n : 6 * n + 9].reshape(3, 3)) <= tol and isinstance(
            ScrewRows("S").judge(x[: 6 * n].reshape(n, 6)), Accepted
        )
    return True  # Twist, Wrench: finite


@dataclass
class State(Arg):
    """A pickled state: a tuple of Python floats, of one of `sizes`, that
    the class's constructor would take (`cls_name`, _valid_state): otherwise
    ValueError naming the class's __setstate__."""

    sizes: tuple = (9,)
    valid: Callable[[], Any] | None = None
    cls_name: str = ""

    def good(self):
        return self.valid()

    def judge(self, value):
        if not isinstance(value, tuple) or len(value) not in self.sizes:
            return Refused(ValueError, ("__setstate__", "tuple of"))
        if not all(isinstance(x, float) for x in value):
            return Refused(TypeError, ("__setstate__", "floats"))
        if self.cls_name and not _valid_state(self.cls_name, value):
            return Refused(ValueError, (f"{self.cls_name}.__setstate__",))
        return Accepted(tuple(float(x) for x in value))


@dataclass
class Anything(Arg):
    """An argument the callable takes as any object (memo, dtype, copy, protocol)."""

    valid: Any = None

    def good(self):
        return self.valid

    def judge(self, value):
        return None  # no model: any outcome but a crash or an unlisted exception


@dataclass
class ScipyElement(Arg):
    """One scipy.spatial.transform object of class `kind` ("Rotation" or
    "RigidTransform"): a single one is taken as it is; a stack is a
    ValueError naming the array functions; anything else a TypeError naming
    the expected class. (scipy is imported here only when judged.)"""

    kind: str = "Rotation"

    def _cls(self):
        from scipy.spatial import transform

        return getattr(transform, self.kind)

    def good(self):
        from scipy.spatial.transform import Rotation

        r = Rotation.from_rotvec([0.1, 0.2, 0.3])
        return r if self.kind == "Rotation" else self._cls().from_components([1.0, 2.0, 3.0], r)

    def variants(self):
        """Values to try: the good one, stacks (of one too), the other
        scipy class, its matrix as an array."""
        from scipy.spatial.transform import RigidTransform, Rotation

        r = Rotation.from_rotvec([[0.1, 0.2, 0.3], [0.0, 0.0, 3.0], [np.pi, 0.0, 0.0]])
        tf = RigidTransform.from_components(np.ones((3, 3)), r)
        good = self.good()
        return [good, r, r[:1], r[2], tf, tf[:1], tf[1], good.as_matrix(), [good]]

    def judge(self, value):
        if isinstance(value, self._cls()):
            if value.single:
                return Accepted(value)
            return Refused(ValueError, (self.label, f"single {self.kind}", "stack", "as_matrix()"))
        return Refused(TypeError, (self.label, f"scipy.spatial.transform.{self.kind}"))


class Size(Arg):
    """The number of samples of the samplers (so3_random, ...): None, an int
    >= 0 or a tuple of them (a batch shape)."""

    def good(self):
        return 3

    def judge(self, value):
        if value is None:
            return Accepted(None)
        if isinstance(value, (bool, np.bool_)):
            return Refused(TypeError, (self.label,))
        if isinstance(value, (int, np.integer)):
            if value < 0:
                return Refused(ValueError, (self.label, ">= 0"))
            return Accepted(int(value))
        if isinstance(value, (float, complex, str, bytes, np.floating)):
            return Refused(TypeError, (self.label,))
        return None  # sequences and other objects: no model


class ThreadCount(Arg):
    """The n of set_num_threads: an int from 1 to 1024."""

    def good(self):
        return 1

    def judge(self, value):
        if isinstance(value, (bool, np.bool_)):
            return Refused(TypeError, (self.label, "1 to 1024"))
        if isinstance(value, (int, np.integer)):
            if not 1 <= value <= 1024:
                return Refused(ValueError, (self.label, "1 to 1024"))
            return Accepted(int(value))
        if isinstance(value, (float, complex, str, bytes, np.floating)):
            return Refused(TypeError, (self.label, "1 to 1024"))
        return None  # other objects with __index__: no model


@dataclass
class Rng(Arg):
    """The rng of the samplers, as scipy and numpy.random.default_rng take
    it; an int seed is the one value whose outcome is reproducible."""

    def good(self):
        return 1234

    def judge(self, value):
        if isinstance(value, (int, np.integer)) and not isinstance(value, (bool, np.bool_)):
            if value < 0:
                return Refused(ValueError, (self.label,))
            return Accepted(int(value))
        if isinstance(value, (str, bytes, complex)):
            return Refused(TypeError, (self.label,))
        return None  # None (fresh entropy), generators (advanced): no model


@dataclass
class Control(Arg):
    """The control elements of a B-spline (`group` SO3, SE3, SO2, SE2, Sim3 or SE23):
    a list or tuple of initialized objects of the group (TypeError for
    anything else in it), or an array-like of shape (N, k, k) whose
    matrices each pass the group's checked ``from_matrix`` (with float32's
    tolerance for a float32 or float16 ndarray); N >= 4."""

    group: type = chasles.SO3

    def good(self):
        return spline_control(self.group)

    def judge(self, value):
        k = np.asarray(self.group.identity()).shape[0]
        if isinstance(value, (list, tuple)) and value and isinstance(value[0], BOUND + BSPLINES):
            for x in value:  # in order: the first one refused is named
                if not isinstance(x, self.group):
                    return Refused(TypeError, (self.label, "element"))
                if not is_initialized(x):
                    return Refused(TypeError, ("not initialized",))
            n = len(value)
        else:
            a = real_array(value, self.label)
            if isinstance(a, Refused):
                return a
            if a.ndim != 3 or a.shape[1:] != (k, k):
                return Refused(ValueError, (self.label, "expected shape", f"got {shape_text(a.shape)}"))
            # float32 (and float16) arrays: checked with float32's tolerance
            single = isinstance(value, np.ndarray) and value.dtype.kind == "f" and value.dtype.itemsize <= 4
            tol = 3.4526698e-04 if single else 1.4901161193847656e-08
            for m in plain(a, np.float64):
                try:
                    self.group.from_matrix(m, tol)
                except ValueError:
                    return Refused(ValueError, (self.label, "element", "is not a"))
            n = a.shape[0]
        if n < 4:
            return Refused(ValueError, (self.label, "N >= 4"))
        return Accepted(value)


@dataclass
class Times(Arg):
    """The times of a B-spline's evaluation: real numbers of any shape, each
    in [lo, hi] (the good spline's start and end times) or NaN."""

    lo: float = 0.0
    hi: float = 1.0

    def good(self):
        return np.array([0.2, 0.9])

    def judge(self, value):
        a = real_array(value, self.label)
        if isinstance(a, Refused):
            return a
        c = plain(a, np.float64)
        if np.any((c < self.lo) | (c > self.hi)):
            return Refused(ValueError, (self.label, "[start_time, end_time]", "got"))
        return Accepted(c)


@dataclass
class SplineSelf(Instance):
    """The self of a B-spline's method: an initialized instance (the
    splines do not pickle, so it is taken as it is)."""

    def judge(self, value):
        if isinstance(value, self.classes):
            if is_initialized(value) or self.uninitialized_ok:
                return Accepted(value)
            return Refused(TypeError, (("not initialized", "incompatible function arguments"),))
        return Refused(TypeError, ())


@dataclass
class Covariance(Arg):
    """A Gaussian's covariance: shape (d, d), finite, symmetric and positive
    semidefinite within 1e-12 of its largest entry."""

    shape: tuple = (6, 6)
    flat: bool = False  # the row-major entries, shape (d * d,), are taken too

    def good(self):
        return 0.01 * np.eye(self.shape[0])

    def judge(self, value):
        n = math.prod(self.shape)
        verdict = judge_fixed_array(value, self.label, (self.shape, (n,)) if self.flat else (self.shape,), True)
        if isinstance(verdict, Accepted):
            verdict = Accepted(verdict.value.reshape(self.shape))
        if not isinstance(verdict, Accepted):
            return verdict
        c = verdict.value
        tol = 1e-12 * max(float(np.abs(c).max()), np.finfo(np.float64).tiny)
        if np.abs(c - c.T).max() > tol:
            return Refused(ValueError, (self.label, "symmetric"))
        if np.linalg.eigvalsh(c).min() < -tol:
            return Refused(ValueError, (self.label, "positive semidefinite"))
        return verdict


@dataclass
class GaussianOperand(Instance):
    """The other operand of a Gaussian on SE3: a Gaussian on SE3 or an SE3."""

    def good(self):
        return GOOD[chasles.Gaussian]()

    def judge(self, value):
        if isinstance(value, chasles.Gaussian):
            if not is_initialized(value):
                return Refused(TypeError, ("not initialized",))
            if not isinstance(value.mean, chasles.SE3):
                return Refused(TypeError, ("Gaussian on SE3", "got a Gaussian on"))
            return Accepted(value)
        if isinstance(value, chasles.SE3):
            return Instance(self.label, (chasles.SE3,)).judge(value)
        return Refused(TypeError, ())


@dataclass
class OptionalArray(Arg):
    """None, or a finite array-like of the shape (batch=True: (..., *shape))."""

    shape: tuple = (6, 6)
    batch: bool = False

    def good(self):
        return None

    def judge(self, value):
        if value is None:
            return Accepted(None)
        a = real_array(value, self.label)
        if isinstance(a, Refused):
            return a
        k = len(self.shape)
        if (a.shape[a.ndim - k :] != self.shape or a.ndim < k) if self.batch else a.shape != self.shape:
            return Refused(ValueError, (self.label, "expected shape", f"got {shape_text(a.shape)}"))
        return finite_or_refused(a, self.label)


@dataclass
class GaussianPoints(Arg):
    """Gaussian.act's points (..., 3) or Gaussian.mahalanobis's matrices
    (..., 4, 4), finite; `element`: an object of that class is taken too."""

    shape: tuple = (3,)
    element: Any = None

    def good(self):
        return np.array([[1.0, 2.0, 3.0], [0.5, -1.0, 0.0]]) if self.shape == (3,) else np.stack([pose(), np.eye(4)])

    def judge(self, value):
        if self.element is not None and isinstance(value, self.element):
            return Instance(self.label, (self.element,)).judge(value)
        a = real_array(value, self.label)
        if isinstance(a, Refused):
            return a
        k = len(self.shape)
        if a.ndim < k or a.shape[a.ndim - k :] != self.shape:
            return Refused(ValueError, (self.label, "expected", f"got {shape_text(a.shape)}"))
        return finite_or_refused(a, self.label)


@dataclass
class G2oPath(Anything):
    """A g2o file's path: a str or a pathlib.Path (written with `text` for
    the reader, a fresh one for the writer); anything else a TypeError."""

    text: Any = None

    def good(self):
        import pathlib
        import tempfile

        path = pathlib.Path(tempfile.mkdtemp()) / "graph.g2o"
        if self.text is not None:
            path.write_text(self.text)
        return str(path)

    def judge(self, value):
        import pathlib

        if isinstance(value, (str, pathlib.Path)):
            return None  # a file of the system: no model
        return Refused(TypeError, (self.label, "str"))


class Order(Arg):
    """Gaussian.compose's order: the int 1 or 4 (4 for a Gaussian on SE3)."""

    def good(self):
        return 1

    def judge(self, value):
        if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, np.integer)):
            return Refused(TypeError, (self.label, "expected 1 or 4"))
        if value not in (1, 4):
            return Refused(ValueError, (self.label, "expected 1 or 4"))
        return Accepted(int(value))


def spline_control(group):
    """Five control elements for the B-spline entries: (5, 3, 3) or (5, 4, 4)."""
    k = np.arange(5.0)[:, None]
    if group is chasles.SO3:
        return chasles.so3_exp(np.hstack([0.1 * k, -0.05 * k, 0.2 + 0 * k]))
    if group is chasles.SE3:
        return chasles.se3_exp(np.hstack([0.3 * k, 0 * k, -k, 0.1 * k, -0.05 * k, 0.2 + 0 * k]))
    # SO2, SE2, Sim3, SE23: steps of 0.1 k along a fixed tangent
    dof = {chasles.SO2: 1, chasles.SE2: 3, chasles.Sim3: 7, chasles.SE23: 9}[group]
    x = 0.1 * k * np.linspace(-1.0, 1.0, dof) + 0.05
    return getattr(chasles, f"{group.__name__.lower()}_exp")(x[:, 0] if dof == 1 else x)


# ---- valid values ---------------------------------------------------------------------

R0 = chasles.SO3.exp([0.1, 0.2, 0.3])
G0 = chasles.SE3(R0, [1.0, 2.0, 3.0])
XI0 = chasles.Twist(v=[1.0, 0.0, 0.5], w=[0.0, 0.2, 1.0])
CHAIN_SCREWS = np.array([[0.0, 0.0, 0.0, 0.0, 0.0, 1.0], [0.0, -1.0, 0.0, 0.0, 0.0, 1.0]])
CHAIN_HOME = chasles.SE3(translation=[2.0, 0.0, 0.0])
# Per joint: mass, center of mass (3), ixx, ixy, ixz, iyy, iyz, izz.
CHAIN_INERTIAS = np.array(
    [[1.0, 0.5, 0.0, 0.0, 0.01, 0.0, 0.0, 0.02, 0.0, 0.02], [0.5, 1.5, 0.0, 0.0, 0.01, 0.0, 0.0, 0.01, 0.0, 0.01]]
)
URDF_TEXT = (
    '<robot name="r"><link name="a"/><link name="b"/><joint name="j" type="revolute">'
    '<parent link="a"/><child link="b"/><axis xyz="0 0 1"/>'
    '<limit lower="-1" upper="1" effort="1" velocity="1"/></joint></robot>'
)

GOOD = {  # a fresh valid object of each class
    chasles.SO3: lambda: chasles.SO3.exp([0.1, 0.2, 0.3]),
    chasles.SE3: lambda: chasles.SE3(chasles.SO3.exp([0.1, 0.2, 0.3]), [1.0, 2.0, 3.0]),
    chasles.SO2: lambda: chasles.SO2.exp(0.4),
    chasles.SE2: lambda: chasles.SE2(chasles.SO2.exp(0.4), [1.0, 2.0]),
    chasles.Sim3: lambda: chasles.Sim3(chasles.SO3.exp([0.1, 0.2, 0.3]), [1.0, 2.0, 3.0], 1.5),
    chasles.SE23: lambda: chasles.SE23(chasles.SO3.exp([0.1, 0.2, 0.3]), [1.0, 2.0, 3.0], [-0.5, 0.4, 2.0]),
    chasles.Twist: lambda: chasles.Twist(v=[1.0, 0.0, 0.5], w=[0.0, 0.2, 1.0]),
    chasles.Wrench: lambda: chasles.Wrench(f=[0.0, 1.0, 1.0], tau=[0.5, 0.0, 0.0]),
    chasles.Screw: lambda: chasles.Screw([0.0, 1.0, 0.0], [0.0, 0.0, 1.0], 0.5, 1.0),
    chasles.Chain: lambda: chasles.Chain(CHAIN_SCREWS, CHAIN_HOME),
    chasles.SO3BSpline: lambda: chasles.SO3BSpline(0.0, 0.5, spline_control(chasles.SO3)),
    chasles.SE3BSpline: lambda: chasles.SE3BSpline(0.0, 0.5, spline_control(chasles.SE3)),
    chasles.SO2BSpline: lambda: chasles.SO2BSpline(0.0, 0.5, spline_control(chasles.SO2)),
    chasles.SE2BSpline: lambda: chasles.SE2BSpline(0.0, 0.5, spline_control(chasles.SE2)),
    chasles.Sim3BSpline: lambda: chasles.Sim3BSpline(0.0, 0.5, spline_control(chasles.Sim3)),
    chasles.SE23BSpline: lambda: chasles.SE23BSpline(0.0, 0.5, spline_control(chasles.SE23)),
    chasles.Gaussian: lambda: chasles.Gaussian(GOOD[chasles.SE3](), 0.01 * np.eye(6)),
    chasles.PoseGraph: lambda: chasles.pose_graph_grid(20, 4, seed=1)[0],
    chasles.SpatialInertia: lambda: chasles.SpatialInertia(
        2.0, [0.1, 0.2, 0.3], [[0.1, 0.01, 0.0], [0.01, 0.2, 0.0], [0.0, 0.0, 0.25]]
    ),
}


def base_copy(x):
    """An object of the base class with x's value (x may be a subclass instance)."""
    cls = next(c for c in BOUND if isinstance(x, c))
    y = cls.__new__(cls)
    y.__setstate__(x.__getstate__())
    return y


def rotation():
    return R0.as_matrix()


def pose():
    return G0.as_matrix()


def quat():
    return np.array([0.1, -0.2, 0.3, 0.9])


def g_dot():
    return G0.as_matrix() @ XI0.hat()


# ---- the specification ----------------------------------------------------------------


# ---- the alignments (so3_align, se3_align, sim3_align) --------------------------------

# Four points / vectors, none of length 0, not on a line, and their images.
ALIGN_B = np.array([[1.0, 0.5, 0.25], [2.0, 0.0, 0.5], [0.0, 2.0, 0.0], [0.5, 0.0, 3.0]])
ALIGN_R = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
ALIGN_A = {"so3_align": ALIGN_B @ ALIGN_R.T, "se3_align": ALIGN_B @ ALIGN_R.T + [1.0, 2.0, 3.0]}
ALIGN_A["sim3_align"] = 2.0 * ALIGN_B @ ALIGN_R.T + [1.0, 2.0, 3.0]
# constants.hpp, Thresholds<double>::align_tolerance
ALIGN_TOLERANCE = 1.4901161193847656e-08


def _align_determined(name, a, b, w):
    """Whether the data determine the rotation (True / False), or None near
    the threshold (a factor 100 either side of align_tolerance) or where the
    sums could overflow or lose their digits to underflow (no model)."""
    for x in (a, b) + ((w,) if w is not None else ()):
        big = np.abs(x[np.isfinite(x)])
        if big.size and (big.max() > 1e100 or (big[big > 0].size and big[big > 0].min() < 1e-100)):
            return None
    w = np.ones(len(a)) if w is None else w
    if name != "so3_align":
        a = a - w @ a / w.sum()
        b = b - w @ b / w.sum()
    U, s, Vt = np.linalg.svd((w[:, None] * a).T @ b)
    s3 = s[2] if np.linalg.det(U @ Vt) >= 0 else -s[2]
    ratio = (s[1] + s3) / s[0] if s[0] > 0 else 0.0
    if ratio > 100 * ALIGN_TOLERANCE:
        return True
    if ratio < ALIGN_TOLERANCE / 100:
        return False
    return None


@dataclass
class AlignRows(Arg):
    """a or b of so3_align / se3_align / sim3_align (`name`): real numbers of
    shape (N, 3), N >= 1 (so3_align; also (3,) for one pair) or N >= 3, the
    same shape as the other's (ALIGN_B: 4 rows), finite; read as float64
    whatever the dtype and layout. With valid numbers: se3_align and
    sim3_align refuse points that do not determine the rotation, so3_align
    warns (its UserWarning let through by the call: _undetermined_allowed)."""

    name: str = "so3_align"
    first: bool = True

    def good(self):
        return ALIGN_A[self.name] if self.first else ALIGN_B

    def judge(self, value):
        a = real_array(value, self.label)
        if isinstance(a, Refused):
            return a
        vectors = self.name == "so3_align"
        least = 1 if vectors else 3
        shape = a.shape
        if vectors and shape == (3,):
            shape = (1, 3)
        elif len(shape) != 2 or shape[1] != 3 or shape[0] < least:
            return Refused(ValueError, (self.label, "expected shape", f"got {shape_text(a.shape)}"))
        if shape != ALIGN_B.shape:
            return Refused(ValueError, (f"{self.name}(a, b)", "expected the same shape"))
        c = finite_or_refused(a, self.label)
        if isinstance(c, Refused) or vectors:
            return c
        x = c.value
        determined = _align_determined(self.name, *((x, ALIGN_B) if self.first else (ALIGN_A[self.name], x)), None)
        if determined is None:
            return None
        return c if determined else Refused(ValueError, (f"{self.name}(a, b)", "do not determine the rotation"))


@dataclass
class AlignWeights(Arg):
    """The weights of so3_align / se3_align / sim3_align (`name`): None, or
    real numbers of shape (4,) (one per row of ALIGN_B), none negative or
    NaN; so3_align takes at most one inf (the primary vector), se3_align
    and sim3_align none, and not all 0. With valid weights, se3_align and
    sim3_align refuse points they leave undetermined (fewer than 3 of
    weight > 0 off a line)."""

    name: str = "so3_align"

    def good(self):
        return None

    def judge(self, value):
        if value is None:
            return Accepted(None)
        a = real_array(value, self.label)
        if isinstance(a, Refused):
            return a
        if a.shape != (4,):
            return Refused(ValueError, (self.label, "expected shape (4,)", f"got {shape_text(a.shape)}"))
        w = plain(a, np.float64)
        if not np.all(w >= 0):
            return Refused(ValueError, (self.label, "weights >= 0"))
        infinite = int(np.isinf(w).sum())
        if self.name == "so3_align":
            if infinite > 1:
                return Refused(ValueError, (self.label, "at most one infinite weight"))
            if w[np.isfinite(w)].max(initial=0.0) > 1e100:
                return None  # the sums may overflow
            return Accepted(w)
        if infinite:
            return Refused(ValueError, (self.label, "finite weights"))
        if not w.max() > 0:
            return Refused(ValueError, (self.label, "at least one weight > 0"))
        determined = _align_determined(self.name, ALIGN_A[self.name], ALIGN_B, w)
        if determined is None:
            return None
        return Accepted(w) if determined else Refused(ValueError, (f"{self.name}(a, b)", "do not determine"))


def _undetermined_allowed(call):
    """`call` with so3_align's UserWarning for vectors that do not determine
    the rotation (documented, as scipy's) let through, and every other
    warning still an error."""

    def wrapped(*a):
        with warnings.catch_warnings():
            warnings.filterwarnings("ignore", message="so3_align: the rotation", category=UserWarning)
            return call(*a)

    return wrapped


@dataclass
class Entry:
    """How to call one public callable.

    `signatures`: argument lists (one per overload that takes other kinds of
    arguments). `call(*args)` calls it (keyword-only parameters, such as
    scalar_first, are passed by keyword). `self_first`: the first argument
    is the instance a method is called on. `extra_errors`: exceptions other
    than TypeError and ValueError the callable documents (ZeroDivisionError
    for x / 0). `passes_arguments`: `call` hands its positional arguments
    to the callable as they are (so a wrong count reaches the library)."""

    signatures: list
    call: Callable | None = None
    self_first: bool = False
    extra_errors: tuple = ()
    passes_arguments: bool = True
    direct: Callable | None = None

    def call_with_self(self, *args):
        """The method called on its class with args[0] as self (Twist.__mul__(x, s)
        rather than x * s, so that a wrong self reaches the library)."""
        return (self.direct or self.call)(*args)


def _self(cls):
    return Instance("self", (cls,))


def _method(cls, name, *args, **kw):
    return Entry([[_self(cls), *args]], call=lambda *a: getattr(cls, name)(*a), self_first=True, **kw)


def _direct(cls, name):
    return lambda *a: getattr(cls, name)(*a)


def _prop(cls, name):
    return Entry(
        [[_self(cls)]],
        call=lambda x: getattr(cls, name).fget(x),
        self_first=True,
        passes_arguments=False,
    )


def _static(cls, name, *args, **kw):
    return Entry([list(args)], call=lambda *a: getattr(cls, name)(*a), **kw)


def _binop(cls, op, other, dunder, **kw):
    return Entry(
        [[_self(cls), other]],
        call=op,
        self_first=True,
        passes_arguments=False,
        direct=_direct(cls, dunder),
        **kw,
    )


def _protocols(cls, n_state):
    """__repr__, __array__, copy, deepcopy and pickle of a bound class."""
    name = cls.__name__
    out = {
        f"{name}.__repr__": Entry(
            [[Instance("self", (cls,), uninitialized_ok=True)]],
            call=repr,
            self_first=True,
            passes_arguments=False,
            direct=_direct(cls, "__repr__"),
        ),
        f"{name}.__copy__": _method(cls, "__copy__"),
        f"{name}.__deepcopy__": _method(cls, "__deepcopy__", Anything("memo", {})),
        f"{name}.__getstate__": _method(cls, "__getstate__"),
        f"{name}.__setstate__": Entry(
            [[State("state", tuple(n_state), lambda: GOOD[cls]().__getstate__(), name)]],
            call=lambda s: _setstate(cls, s),
            passes_arguments=False,
        ),
        f"{name}.__reduce__": _method(cls, "__reduce__"),
        f"{name}.__eq__": _binop(cls, operator.eq, Comparand("other", (cls,)), "__eq__"),
        f"{name}.__ne__": _binop(cls, operator.ne, Comparand("other", (cls,), other_gives=True), "__ne__"),
        f"{name}.__reduce_ex__": _method(cls, "__reduce_ex__", Anything("protocol", 2)),
    }
    if hasattr(cls, "__array__"):
        out[f"{name}.__array__"] = _method(cls, "__array__", Anything("dtype", None), Anything("copy", None))
    return out


def _setstate(cls, state):
    x = cls.__new__(cls)
    x.__setstate__(state)
    return x


def _in_a_fresh_directory(call):
    """`call` run in a new temporary directory (a relative path the fuzzing
    passes is written there, not into the tree the tests run from)."""
    import os
    import tempfile

    def wrapped(*a):
        here = os.getcwd()
        with tempfile.TemporaryDirectory() as directory:
            os.chdir(directory)
            try:
                return call(*a)
            finally:
                os.chdir(here)

    return wrapped


def _gimbal_lock_allowed(call):
    """`call` with scipy's gimbal lock warning of the Euler angle functions
    (documented; any operand, zeros included, may be at the lock) let
    through, and every other warning still an error."""

    def wrapped(*a):
        with warnings.catch_warnings():
            warnings.filterwarnings("ignore", message="Gimbal lock detected", category=UserWarning)
            return call(*a)

    return wrapped


def _array_function(name, operands, kw=()):
    """An array function: operands (name, core, valid) and keyword-only flags."""
    args = [Operand(f"{name}:{p}", tuple(core), valid) for p, core, valid in operands]
    args += [Flag(k) for k in kw]
    f = getattr(chasles, name)
    n = len(operands)

    def call(*a):
        return f(*a[:n], **dict(zip(kw, a[n:])))

    return Entry(
        [args],
        call=call if kw else f,
        passes_arguments=not kw,
        extra_errors=NUMPY_SCALAR_ERRORS,
    )


# tangent, point
GROUPS = {
    chasles.SO2: (1, 2),
    chasles.SE2: (3, 2),
    chasles.SO3: (3, 3),
    chasles.Sim3: (7, 3),
    chasles.SE23: (9, 3),
    chasles.SE3: (6, 3),
}


def _group_function(name, make, **kw):
    """A module function overloaded on SO2, SE2, SO3 and SE3:
    make(group, tangent_size). Its group arguments take any group (the
    overload is picked by them)."""
    f = getattr(chasles, name)
    return Entry([make(G, n) for G, (n, _) in GROUPS.items()], call=f, **kw)


def _element(label, group):
    """A group argument of a function overloaded on the groups: any is
    taken (and picks the overload), its valid value being of `group`."""
    return Instance(label, tuple(GROUPS), valid=GOOD[group])


def _tangent(label, n, finite=True):
    """A tangent argument of size n: SO2's angle for n = 1."""
    return Angle(label, finite) if n == 1 else Array(label, (n,), finite)


def _build_spec():
    SO3, SE3, _, _, _, _, Twist, Wrench, Screw, Chain, _ = BOUND
    spec: dict[str, Entry] = {}

    # SO3
    spec["SO3.__init__"] = Entry([[]], call=SO3)
    spec["SO3.identity"] = _static(SO3, "identity")
    spec["SO3.exp"] = _static(SO3, "exp", Array("SO3.exp(w)", (3,)))
    spec["SO3.log"] = _method(SO3, "log")
    spec["SO3.angle"] = _method(SO3, "angle")
    spec["SO3.hat"] = _static(SO3, "hat", Array("SO3.hat(w)", (3,), finite=False))
    spec["SO3.vee"] = _static(SO3, "vee", Array("SO3.vee(matrix)", (3, 3), finite=False))
    spec["SO3.inverse"] = _method(SO3, "inverse")
    spec["SO3.__matmul__"] = _binop(SO3, operator.matmul, SO3Or("SO3 @ points"), "__matmul__")
    spec["SO3.act"] = _method(SO3, "act", Points("SO3.act(points)"))
    spec["SO3.adjoint"] = _method(SO3, "adjoint")
    spec["SO3.as_matrix"] = _method(SO3, "as_matrix")
    spec["SO3.from_matrix"] = _static(
        SO3,
        "from_matrix",
        Array("SO3.from_matrix(matrix)", (3, 3), valid=rotation),
        Real("SO3.from_matrix(tol)", "tolerance", 1e-6),
    )
    for form in ("projected", "unchecked"):
        label = f"SO3.from_matrix_{form}(matrix)"
        spec[f"SO3.from_matrix_{form}"] = _static(SO3, f"from_matrix_{form}", Array(label, (3, 3), valid=rotation))
    spec["SO3.rotation_defect"] = _static(
        SO3,
        "rotation_defect",
        Array("SO3.rotation_defect(matrix)", (3, 3), finite=False, valid=rotation),
    )
    spec["SO3.from_quat"] = Entry(
        [[Array("SO3.from_quat(quat)", (4,), valid=quat), Flag("scalar_first")]],
        call=lambda q, f: SO3.from_quat(q, scalar_first=f),
        passes_arguments=False,
    )
    spec["SO3.as_quat"] = Entry(
        [[_self(SO3), Flag("scalar_first")]],
        call=lambda x, f: SO3.as_quat(x, scalar_first=f),
        self_first=True,
        passes_arguments=False,
    )
    spec["SO3.from_euler"] = Entry(
        [[Sequence("SO3.from_euler(seq)"), Array("SO3.from_euler(angles)", (3,)), Flag("degrees")]],
        call=lambda q, a, d: SO3.from_euler(q, a, degrees=d),
        passes_arguments=False,
    )
    spec["SO3.as_euler"] = Entry(
        [[_self(SO3), Sequence("SO3.as_euler(seq)"), Flag("degrees")]],
        call=lambda x, q, d: SO3.as_euler(x, q, degrees=d),
        self_first=True,
        passes_arguments=False,
    )
    spec["SO3.from_rpy"] = Entry(
        [[Array("SO3.from_rpy(rpy)", (3,)), Flag("degrees")]],
        call=lambda a, d: SO3.from_rpy(a, degrees=d),
        passes_arguments=False,
    )
    spec["SO3.as_rpy"] = Entry(
        [[_self(SO3), Flag("degrees")]],
        call=lambda x, d: SO3.as_rpy(x, degrees=d),
        self_first=True,
        passes_arguments=False,
    )
    spec["SO3.normalized"] = _method(SO3, "normalized")
    spec["SO3.__pow__"] = _binop(SO3, operator.pow, Real("SO3 ** t"), "__pow__")
    spec["SO3.interpolate"] = _static(
        SO3, "interpolate", Instance("a", (SO3,)), Instance("b", (SO3,)), Real("SO3.interpolate(t)")
    )
    spec["SO3.is_approx"] = _method(
        SO3, "is_approx", Instance("other", (SO3,)), Real("SO3.is_approx(tol)", "tolerance", 1e-6)
    )
    for jac in (
        "right_jacobian",
        "left_jacobian",
        "right_jacobian_inverse",
        "left_jacobian_inverse",
    ):
        spec[f"SO3.{jac}"] = _static(SO3, jac, Array(f"SO3.{jac}(w)", (3,)))
        spec[f"SE3.{jac}"] = _static(SE3, jac, Array(f"SE3.{jac}(xi)", (6,)))
    spec.update(_protocols(SO3, [9]))

    # SE3
    # SE3(matrix) and the like: a TypeError naming what came and the
    # constructors of raw data (test_bad_input.py checks each case).
    rotation_arg = Instance(
        "rotation",
        (SO3,),
        refused=(
            "SE3(rotation): expected an SO3, got",
            ("SO3.from_matrix(matrix)", "SE3.from_matrix(matrix)"),
        ),
    )
    spec["SE3.__init__"] = Entry([[rotation_arg, Array("SE3(translation)", (3,))]], call=SE3)
    spec["SE3.identity"] = _static(SE3, "identity")
    spec["SE3.exp"] = _static(SE3, "exp", TwistOr("SE3.exp(xi)", (6,)))
    spec["SE3.log"] = _method(SE3, "log")
    spec["SE3.hat"] = _static(SE3, "hat", Array("SE3.hat(xi)", (6,), finite=False))
    spec["SE3.vee"] = _static(SE3, "vee", Array("SE3.vee(matrix)", (4, 4), finite=False))
    spec["SE3.inverse"] = _method(SE3, "inverse")
    spec["SE3.__matmul__"] = _binop(SE3, operator.matmul, SE3Or("SE3 @ points", (SE3,)), "__matmul__")
    spec["SE3.act"] = _method(SE3, "act", SE3Or("SE3.act(points)", (Twist, Wrench)))
    spec["SE3.act_inv"] = _method(SE3, "act_inv", SE3Or("SE3.act_inv(points)", (Twist, Wrench)))
    for m in ("adjoint", "as_matrix", "normalized"):
        spec[f"SE3.{m}"] = _method(SE3, m)
    for p in ("rotation", "translation"):
        spec[f"SE3.{p}"] = _prop(SE3, p)
    spec["SE3.from_matrix"] = _static(
        SE3,
        "from_matrix",
        Array("SE3.from_matrix(matrix)", (4, 4), valid=pose),
        Real("SE3.from_matrix(tol)", "tolerance", 1e-6),
    )
    for form in ("projected", "unchecked"):
        label = f"SE3.from_matrix_{form}(matrix)"
        spec[f"SE3.from_matrix_{form}"] = _static(SE3, f"from_matrix_{form}", Array(label, (4, 4), valid=pose))
    spec["SE3.transform_defect"] = _static(
        SE3,
        "transform_defect",
        Array("SE3.transform_defect(matrix)", (4, 4), finite=False, valid=pose),
    )
    spec["SE3.__pow__"] = _binop(SE3, operator.pow, Real("SE3 ** t"), "__pow__")
    spec["SE3.interpolate"] = _static(
        SE3, "interpolate", Instance("a", (SE3,)), Instance("b", (SE3,)), Real("SE3.interpolate(t)")
    )
    spec["SE3.is_approx"] = _method(
        SE3, "is_approx", Instance("other", (SE3,)), Real("SE3.is_approx(tol)", "tolerance", 1e-6)
    )
    spec.update(_protocols(SE3, [12]))

    # SO2 and SE2
    SO2, SE2 = chasles.SO2, chasles.SE2
    for G, name, n, N, t in ((SO2, "SO2", 1, 2, "theta"), (SE2, "SE2", 3, 3, "xi")):
        matrix = lambda G=G: GOOD[G]().as_matrix()  # noqa: E731
        spec[f"{name}.identity"] = _static(G, "identity")
        spec[f"{name}.exp"] = _static(G, "exp", _tangent(f"{name}.exp({t})", n))
        spec[f"{name}.hat"] = _static(G, "hat", _tangent(f"{name}.hat({t})", n, finite=False))
        spec[f"{name}.vee"] = _static(G, "vee", Array(f"{name}.vee(matrix)", (N, N), finite=False))
        for m in ("log", "inverse", "adjoint", "as_matrix", "normalized"):
            spec[f"{name}.{m}"] = _method(G, m)
        spec[f"{name}.__matmul__"] = _binop(G, operator.matmul, PlanarOr(f"{name} @ points", (G,)), "__matmul__")
        spec[f"{name}.act"] = _method(G, "act", Points(f"{name}.act(points)", 2))
        spec[f"{name}.from_matrix"] = _static(
            G,
            "from_matrix",
            Array(f"{name}.from_matrix(matrix)", (N, N), valid=matrix),
            Real(f"{name}.from_matrix(tol)", "tolerance", 1e-6),
        )
        for form in ("projected", "unchecked"):
            label = f"{name}.from_matrix_{form}(matrix)"
            spec[f"{name}.from_matrix_{form}"] = _static(G, f"from_matrix_{form}", Array(label, (N, N), valid=matrix))
        spec[f"{name}.__pow__"] = _binop(G, operator.pow, Real(f"{name} ** t"), "__pow__")
        spec[f"{name}.interpolate"] = _static(
            G, "interpolate", Instance("a", (G,)), Instance("b", (G,)), Real(f"{name}.interpolate(t)")
        )
        spec[f"{name}.is_approx"] = _method(
            G, "is_approx", Instance("other", (G,)), Real(f"{name}.is_approx(tol)", "tolerance", 1e-6)
        )
        for jac in ("right_jacobian", "left_jacobian", "right_jacobian_inverse", "left_jacobian_inverse"):
            spec[f"{name}.{jac}"] = _static(G, jac, _tangent(f"{name}.{jac}({t})", n))
        spec.update(_protocols(G, [2 if G is SO2 else 4]))
    spec["SO2.__init__"] = Entry([[]], call=SO2)
    spec["SO2.rotation_defect"] = _static(
        SO2, "rotation_defect", Array("SO2.rotation_defect(matrix)", (2, 2), finite=False)
    )
    spec["SE2.__init__"] = Entry([[Instance("rotation", (SO2,)), Array("SE2(translation)", (2,))]], call=SE2)
    for p in ("rotation", "translation"):
        spec[f"SE2.{p}"] = _prop(SE2, p)
    spec["SE2.transform_defect"] = _static(
        SE2, "transform_defect", Array("SE2.transform_defect(matrix)", (3, 3), finite=False)
    )

    # Sim3 and SE23: (class, name, tangent size, matrix size, state size, constructor, properties)
    Sim3, SE23 = chasles.Sim3, chasles.SE23
    for G, name, n, N, state, init, props in (
        (
            Sim3,
            "Sim3",
            7,
            4,
            13,
            [Instance("rotation", (SO3,)), Array("Sim3(translation)", (3,)), Real("Sim3(scale)", "positive", 1.5)],
            ("rotation", "translation", "scale"),
        ),
        (
            SE23,
            "SE23",
            9,
            5,
            15,
            [Instance("rotation", (SO3,)), Array("SE23(translation)", (3,)), Array("SE23(velocity)", (3,))],
            ("rotation", "translation", "velocity"),
        ),
    ):
        matrix = lambda G=G: GOOD[G]().as_matrix()  # noqa: E731
        spec[f"{name}.__init__"] = Entry([init], call=G)
        spec[f"{name}.identity"] = _static(G, "identity")
        spec[f"{name}.exp"] = _static(G, "exp", Array(f"{name}.exp(xi)", (n,)))
        spec[f"{name}.hat"] = _static(G, "hat", Array(f"{name}.hat(xi)", (n,), finite=False))
        spec[f"{name}.vee"] = _static(G, "vee", Array(f"{name}.vee(matrix)", (N, N), finite=False))
        for m in ("log", "inverse", "adjoint", "as_matrix", "normalized"):
            spec[f"{name}.{m}"] = _method(G, m)
        for p in props:
            spec[f"{name}.{p}"] = _prop(G, p)
        spec[f"{name}.__matmul__"] = _binop(G, operator.matmul, SE3Or(f"{name} @ points", (G,)), "__matmul__")
        spec[f"{name}.act"] = _method(G, "act", Points(f"{name}.act(points)"))
        spec[f"{name}.from_matrix"] = _static(
            G,
            "from_matrix",
            Array(f"{name}.from_matrix(matrix)", (N, N), valid=matrix),
            Real(f"{name}.from_matrix(tol)", "tolerance", 1e-6),
        )
        for form in ("projected", "unchecked"):
            label = f"{name}.from_matrix_{form}(matrix)"
            spec[f"{name}.from_matrix_{form}"] = _static(G, f"from_matrix_{form}", Array(label, (N, N), valid=matrix))
        spec[f"{name}.transform_defect"] = _static(
            G, "transform_defect", Array(f"{name}.transform_defect(matrix)", (N, N), finite=False)
        )
        spec[f"{name}.__pow__"] = _binop(G, operator.pow, Real(f"{name} ** t"), "__pow__")
        spec[f"{name}.interpolate"] = _static(
            G, "interpolate", Instance("a", (G,)), Instance("b", (G,)), Real(f"{name}.interpolate(t)")
        )
        spec[f"{name}.is_approx"] = _method(
            G, "is_approx", Instance("other", (G,)), Real(f"{name}.is_approx(tol)", "tolerance", 1e-6)
        )
        for jac in ("right_jacobian", "left_jacobian", "right_jacobian_inverse", "left_jacobian_inverse"):
            spec[f"{name}.{jac}"] = _static(G, jac, Array(f"{name}.{jac}(xi)", (n,)))
        spec.update(_protocols(G, [state]))

    # from_screw of SE3, Twist, Wrench, and Screw itself
    for owner, cls, amount in (
        ("SE3", SE3, "theta"),
        ("Twist", Twist, "theta"),
        ("Wrench", Wrench, "magnitude"),
    ):
        spec[f"{owner}.from_screw"] = _static(
            cls,
            "from_screw",
            Array(f"{owner}.from_screw(point)", (3,)),
            Array(f"{owner}.from_screw(direction)", (3,), valid=lambda: np.array([0.0, 0.0, 1.0])),
            Real(f"{owner}.from_screw(pitch)", "pitch"),
            Real(f"{owner}.from_screw({amount})"),
        )
    spec["Screw.__init__"] = Entry(
        [
            [
                Array("Screw(point)", (3,)),
                Array("Screw(direction)", (3,), valid=lambda: np.array([0.0, 0.0, 1.0])),
                Real("Screw(pitch)", "pitch"),
                Real("Screw(magnitude)"),
            ]
        ],
        call=Screw,
    )
    for p in ("point", "direction", "pitch", "magnitude"):
        spec[f"Screw.{p}"] = _prop(Screw, p)
    spec["Screw.is_approx"] = _method(
        Screw,
        "is_approx",
        Instance("other", (Screw,)),
        Real("Screw.is_approx(tol)", "tolerance", 1e-6),
    )
    spec["Screw.__iter__"] = Entry(
        [[_self(Screw)]],
        call=lambda x: list(iter(x)),
        self_first=True,
        passes_arguments=False,
        direct=lambda x: list(Screw.__iter__(x)),
    )
    spec["Screw.__len__"] = Entry(
        [[_self(Screw)]],
        call=len,
        self_first=True,
        passes_arguments=False,
        direct=_direct(Screw, "__len__"),
    )
    spec.update(_protocols(Screw, [8]))

    # Twist and Wrench
    for cls, (a, b), vec, other in (
        (Twist, ("v", "w"), "xi", Wrench),
        (Wrench, ("f", "tau"), "F", Twist),
    ):
        n = cls.__name__
        spec[f"{n}.__init__"] = Entry([[Array(f"{n}({a})", (3,)), Array(f"{n}({b})", (3,))]], call=cls)
        spec[f"{n}.from_vector"] = _static(cls, "from_vector", Array(f"{n}.from_vector({vec})", (6,)))
        spec[f"{n}.__add__"] = _binop(cls, operator.add, Instance("other", (cls,)), "__add__")
        spec[f"{n}.__sub__"] = _binop(cls, operator.sub, Instance("other", (cls,)), "__sub__")
        for dunder, op in (("__neg__", operator.neg), ("__pos__", operator.pos)):
            spec[f"{n}.{dunder}"] = Entry(
                [[_self(cls)]],
                call=op,
                self_first=True,
                passes_arguments=False,
                direct=_direct(cls, dunder),
            )
        spec[f"{n}.__mul__"] = _binop(cls, operator.mul, Scalar(f"{n} * scalar"), "__mul__")
        spec[f"{n}.__rmul__"] = _binop(cls, lambda x, s: s * x, Scalar(f"{n} * scalar"), "__rmul__")
        spec[f"{n}.__truediv__"] = _binop(
            cls,
            operator.truediv,
            Scalar(f"{n} / scalar"),
            "__truediv__",
            extra_errors=(ZeroDivisionError,),
        )
        spec[f"{n}.is_approx"] = _method(
            cls,
            "is_approx",
            Instance("other", (cls,)),
            Real(f"{n}.is_approx(tol)", "tolerance", 1e-6),
        )
        spec[f"{n}.power"] = _method(cls, "power", Instance(other.__name__.lower(), (other,)))
        spec[f"{n}.screw"] = _method(cls, "screw")
        spec[f"{n}.pitch"] = _method(cls, "pitch")
        spec[f"{n}.vector"] = _prop(cls, "vector")
        spec.update(_protocols(cls, [6]))
    spec["Twist.linear"] = _prop(Twist, "linear")
    spec["Twist.angular"] = _prop(Twist, "angular")
    spec["Wrench.force"] = _prop(Wrench, "force")
    spec["Wrench.torque"] = _prop(Wrench, "torque")
    spec["Twist.to_modern_robotics"] = _method(Twist, "to_modern_robotics")
    spec["Twist.from_modern_robotics"] = _static(
        Twist, "from_modern_robotics", Array("Twist.from_modern_robotics(wv)", (6,))
    )
    spec["Twist.hat"] = _method(Twist, "hat")
    spec["Twist.vee"] = _static(Twist, "vee", Array("Twist.vee(matrix)", (4, 4), valid=lambda: XI0.hat()))
    spec["Twist.ad"] = _method(Twist, "ad")
    spec["Twist.bracket"] = _method(Twist, "bracket", Instance("other", (Twist,)))
    for frame in ("spatial", "body"):
        spec[f"Twist.{frame}"] = _static(
            Twist, frame, Instance("g", (SE3,)), Array(f"Twist.{frame}(g_dot)", (4, 4), valid=g_dot)
        )

    # Chain
    spec["Chain.__init__"] = Entry([[ScrewRows("Chain(screws)"), Home("Chain(home)")]], call=Chain)
    spec["Chain.revolute_screw"] = _static(
        Chain,
        "revolute_screw",
        Array("Chain.revolute_screw(point)", (3,)),
        Array("Chain.revolute_screw(direction)", (3,)),
    )
    spec["Chain.prismatic_screw"] = _static(Chain, "prismatic_screw", Array("Chain.prismatic_screw(direction)", (3,)))
    for m in ("forward", "forward_body", "jacobian_space", "jacobian_body"):
        spec[f"Chain.{m}"] = _method(Chain, m, JointArray(f"Chain.{m}(theta)", 2))
    for m in ("jacobian_space_dot", "jacobian_body_dot"):
        # (a shape error names the argument, numpy's dtype error only the call)
        spec[f"Chain.{m}"] = _method(Chain, m, JointArray(f"Chain.{m}", 2), JointArray(f"Chain.{m}", 2))
    spec["Chain.inverse_kinematics"] = _method(
        Chain,
        "inverse_kinematics",
        IKTarget("Chain.inverse_kinematics(target)"),
        IKSeed("Chain.inverse_kinematics(q0)", 2),
    )
    # The dynamics: a chain with link inertias (GOOD's has none: refused, tested in test_robot.py).
    inertial = Instance("self", (Chain,), valid=lambda: Chain(CHAIN_SCREWS, CHAIN_HOME, link_inertias=CHAIN_INERTIAS))
    for m, names in (
        ("inverse_dynamics", ("q", "qd", "qdd")),
        ("forward_dynamics", ("q", "qd", "tau")),
        ("mass_matrix", ("q",)),
        ("gravity_torques", ("q",)),
        ("coriolis", ("q", "qd")),
        ("inverse_dynamics_derivatives", ("q", "qd", "qdd")),
        ("forward_dynamics_derivatives", ("q", "qd", "tau")),
        ("mass_matrix_inverse", ("q",)),
    ):
        spec[f"Chain.{m}"] = Entry(
            # (a shape error names the argument, numpy's dtype error only the call)
            [[inertial, *(JointArray(f"Chain.{m}", 2) for a in names)]],
            call=lambda *a, m=m: getattr(Chain, m)(*a),
            self_first=True,
        )
    for p in (
        "space_screws",
        "body_screws",
        "home",
        "n_joints",
        "joint_types",
        "joint_names",
        "lower",
        "upper",
        "velocity_limits",
        "effort_limits",
        "base",
        "tool",
        "gravity",
        "link_inertias",
    ):
        spec[f"Chain.{p}"] = _prop(Chain, p)
    spec["Chain.from_urdf"] = Entry(
        [[Anything("source", URDF_TEXT), Anything("tip_link", "b"), Anything("base_link", None)]],
        call=Chain.from_urdf,
        extra_errors=(OSError,),
    )
    spec.update(_protocols(Chain, [6 * n + 12 for n in range(1, 33)]))

    # B-splines (start time 0, spacing 0.5, five control elements: times in [0, 1])
    for cls, group in (
        (chasles.SO3BSpline, SO3),
        (chasles.SE3BSpline, SE3),
        (chasles.SO2BSpline, chasles.SO2),
        (chasles.SE2BSpline, chasles.SE2),
        (chasles.Sim3BSpline, chasles.Sim3),
        (chasles.SE23BSpline, chasles.SE23),
    ):
        n = cls.__name__
        me = SplineSelf("self", (cls,))
        spec[f"{n}.__init__"] = Entry(
            [[Real(f"{n}(start_time)"), Real(f"{n}(spacing)", "positive"), Control(f"{n}(control)", group)]],
            call=cls,
        )
        for m, what in (("__call__", f"{n}(t)"), ("body_velocity", None), ("body_acceleration", None)):
            spec[f"{n}.{m}"] = Entry(
                [[me, Times(what or f"{n}.{m}(t)", 0.0, 1.0)]],
                call=lambda x, t, m=m, cls=cls: getattr(cls, m)(x, t),
                self_first=True,
            )
        for p in ("start_time", "spacing", "end_time", "control"):
            spec[f"{n}.{p}"] = Entry(
                [[me]],
                call=lambda x, p=p, cls=cls: getattr(cls, p).fget(x),
                self_first=True,
                passes_arguments=False,
            )
        spec[f"{n}.__repr__"] = Entry(
            [[SplineSelf("self", (cls,), uninitialized_ok=True)]],
            call=repr,
            self_first=True,
            passes_arguments=False,
            direct=_direct(cls, "__repr__"),
        )
        times = np.linspace(0.0, 1.0, 8)
        spec[f"{n}.fit"] = Entry(
            [[Anything("times", times), Anything("poses", GOOD[cls]()(times)), Anything("spacing", 0.5)]],
            call=cls.fit,
        )
    # Gaussian (on SE3: its self; every group's mean in the constructor)
    Gaussian = chasles.Gaussian
    me = SplineSelf("self", (Gaussian,))
    spec["Gaussian.__init__"] = Entry(
        [[_element("mean", G), Covariance("Gaussian(cov)", (n, n))] for G, (n, _) in GROUPS.items()], call=Gaussian
    )
    spec["Gaussian.from_left"] = Entry(
        [[_element("mean", G), Covariance("Gaussian.from_left(cov)", (n, n))] for G, (n, _) in GROUPS.items()],
        call=Gaussian.from_left,
    )
    spec["Gaussian.from_ros"] = Entry(
        [[Instance("mean", (SE3,)), Covariance("Gaussian.from_ros(cov)", (6, 6), flat=True)]],
        call=Gaussian.from_ros,
    )
    operand = GaussianOperand("b", (Gaussian, SE3))
    cross = OptionalArray("cross_cov", (6, 6))
    calls = {
        "compose": [operand, cross, Order("Gaussian.compose(order)")],
        "between": [operand, cross],
        "inverse": [],
        "log": [],
        "act": [GaussianPoints("Gaussian.act(points)", (3,)), OptionalArray("Gaussian.act(cov)", (3, 3), batch=True)],
        "interpolate": [operand, Real("Gaussian.interpolate(t)")],
        "mahalanobis": [GaussianPoints("Gaussian.mahalanobis(x)", (4, 4), element=SE3)],
        "sample": [Size("Gaussian.sample(n)"), Rng("Gaussian.sample(rng)")],
        "__reduce__": [],
        "to_ros_covariance": [],
    }
    for m, args in calls.items():
        spec[f"Gaussian.{m}"] = Entry(
            [[me, *args]], call=lambda *a, m=m: getattr(Gaussian, m)(*a), self_first=True, passes_arguments=False
        )
    spec["Gaussian.__matmul__"] = _binop(Gaussian, operator.matmul, operand, "__matmul__")
    for p in ("mean", "cov", "left_cov"):
        spec[f"Gaussian.{p}"] = Entry(
            [[me]], call=lambda x, p=p: getattr(Gaussian, p).fget(x), self_first=True, passes_arguments=False
        )
    spec["Gaussian.__repr__"] = Entry(
        [[SplineSelf("self", (Gaussian,), uninitialized_ok=True)]],
        call=repr,
        self_first=True,
        passes_arguments=False,
        direct=_direct(Gaussian, "__repr__"),
    )
    # pose graphs (the g2o reader's refusals: test_pose_graph.py)
    graph = GOOD[chasles.PoseGraph]()
    spec["PoseGraph.__init__"] = Entry(
        [
            [
                Anything("group", "se2"),
                Anything("ids", graph.ids),
                Anything("poses", graph.poses),
                Anything("edges", graph.edges),
                Anything("measurements", graph.measurements),
                Anything("information", graph.information),
            ]
        ],
        call=chasles.PoseGraph,
    )
    pg = SplineSelf("self", (chasles.PoseGraph,))
    for m, args in {
        "with_poses": [Anything("poses", graph.poses)],
        "residuals": [],
        "chi2": [],
        "solve": [Anything("max_iterations", 20), Anything("tolerance", 1e-10)],
        "__reduce__": [],
    }.items():
        spec[f"PoseGraph.{m}"] = Entry(
            [[pg, *args]],
            call=lambda *a, m=m: getattr(chasles.PoseGraph, m)(*a),
            self_first=True,
            passes_arguments=False,
        )
    spec["PoseGraph.__repr__"] = Entry(
        [[SplineSelf("self", (chasles.PoseGraph,), uninitialized_ok=True)]],
        call=repr,
        self_first=True,
        passes_arguments=False,
        direct=_direct(chasles.PoseGraph, "__repr__"),
    )
    g2o = f"VERTEX_SE2 0 0 0 0\nVERTEX_SE2 1 1 0 0\nEDGE_SE2 0 1 1 0 0 {' '.join(['1', '0', '0', '1', '0', '1'])}\n"
    spec["read_g2o"] = Entry([[G2oPath("read_g2o(path)", text=g2o)]], call=chasles.read_g2o, extra_errors=(OSError,))
    spec["write_g2o"] = Entry(
        [[G2oPath("write_g2o(path)", None), Anything("graph", graph)]],
        call=_in_a_fresh_directory(chasles.write_g2o),
        extra_errors=(OSError,),
    )
    spec["pose_graph_sphere"] = Entry([[Anything("rings", 3), Anything("per_ring", 4)]], call=chasles.pose_graph_sphere)
    spec["pose_graph_grid"] = Entry([[Anything("poses", 30), Anything("size", 5)]], call=chasles.pose_graph_grid)
    # SpatialInertia
    Inertia = chasles.SpatialInertia
    spec["SpatialInertia.__init__"] = Entry(
        [
            [
                Real("SpatialInertia(mass)", "positive", 2.0),
                Array("SpatialInertia(com)", (3,)),
                RotationalInertia("SpatialInertia(inertia)"),
            ]
        ],
        call=Inertia,
    )
    for p in ("mass", "com", "inertia", "matrix"):
        spec[f"SpatialInertia.{p}"] = _prop(Inertia, p)
    spec["SpatialInertia.transform"] = _method(Inertia, "transform", Instance("g", (SE3,)))
    for m in ("momentum", "kinetic_energy"):
        spec[f"SpatialInertia.{m}"] = _method(Inertia, m, TwistOr(f"SpatialInertia.{m}(twist)", (6,)))
    spec["SpatialInertia.__add__"] = _binop(Inertia, operator.add, Instance("other", (Inertia,)), "__add__")
    spec["SpatialInertia.is_approx"] = _method(
        Inertia,
        "is_approx",
        Instance("other", (Inertia,)),
        Real("SpatialInertia.is_approx(tol)", "tolerance", 1e-6),
    )
    spec.update(_protocols(Inertia, [13]))

    # module functions on objects, overloaded for SO3 and SE3
    E = _element
    spec["rplus"] = _group_function("rplus", lambda G, n: [E("g", G), _tangent("rplus(g, xi)", n)])
    spec["lplus"] = _group_function("lplus", lambda G, n: [_tangent("lplus(xi, g)", n), E("g", G)])
    for f in ("rminus", "lminus"):
        spec[f] = _group_function(f, lambda G, n: [E("g", G), E("h", G)])
    for f in ("log_jacobian", "inverse_jacobian"):
        spec[f] = _group_function(f, lambda G, n: [E("g", G)])
    spec["compose_jacobians"] = _group_function("compose_jacobians", lambda G, n: [E("a", G), E("b", G)])
    spec["act_jacobians"] = _group_function(
        "act_jacobians", lambda G, n: [E("g", G), Array("act_jacobians(g, p)", (GROUPS[G][1],))]
    )
    spec["rplus_jacobians"] = _group_function(
        "rplus_jacobians", lambda G, n: [E("g", G), _tangent("rplus_jacobians(g, xi)", n)]
    )
    spec["lplus_jacobians"] = _group_function(
        "lplus_jacobians", lambda G, n: [_tangent("lplus_jacobians(xi, g)", n), E("g", G)]
    )
    for f in ("rminus_jacobians", "lminus_jacobians"):
        spec[f] = _group_function(f, lambda G, n: [E("g", G), E("h", G)])
    for f in ("between", "between_jacobians"):
        spec[f] = _group_function(f, lambda G, n: [E("a", G), E("b", G)])
    spec["SO3.from_scipy"] = _static(SO3, "from_scipy", ScipyElement("SO3.from_scipy(r)", "Rotation"))
    spec["SE3.from_scipy"] = _static(SE3, "from_scipy", ScipyElement("SE3.from_scipy(tf)", "RigidTransform"))
    spec["SO3.to_scipy"] = _method(SO3, "to_scipy")
    spec["SE3.to_scipy"] = _method(SE3, "to_scipy")
    spec["interpolate"] = _group_function("interpolate", lambda G, n: [E("a", G), E("b", G), Real("interpolate(t)")])
    spec["interpolate_jacobian_t"] = _group_function(
        "interpolate_jacobian_t",
        lambda G, n: [E("a", G), E("b", G), Real("interpolate_jacobian_t(t)")],
    )

    # array functions
    R3, G4 = ((3, 3), rotation), ((4, 4), pose)
    R2, G3 = ((2, 2), lambda: GOOD[chasles.SO2]().as_matrix()), ((3, 3), lambda: GOOD[chasles.SE2]().as_matrix())
    v2, v3 = ((2,), None), ((3,), None)
    S4 = ((4, 4), lambda: GOOD[chasles.Sim3]().as_matrix())
    X5 = ((5, 5), lambda: GOOD[chasles.SE23]().as_matrix())
    six = ((6,), None)
    arrays = {
        "so3_exp": [("w",) + v3],
        "so3_log": [("R",) + R3],
        "so3_compose": [("a",) + R3, ("b",) + R3],
        "so3_inverse": [("R",) + R3],
        "so3_act": [("R",) + R3, ("points",) + v3],
        "so3_act_jacobian": [("R",) + R3, ("points",) + v3],
        "so3_hat": [("w",) + v3],
        "so3_vee": [("matrix", (3, 3), None)],
        "so3_interpolate": [("a",) + R3, ("b",) + R3, ("t", (), None)],
        "so3_normalize": [("R", (3, 3), None)],
        "se3_exp": [("xi",) + six],
        "se3_log": [("g",) + G4],
        "se3_compose": [("a",) + G4, ("b",) + G4],
        "se3_inverse": [("g",) + G4],
        "se3_act": [("g",) + G4, ("points",) + v3],
        "se3_act_jacobian": [("g",) + G4, ("points",) + v3],
        "se3_adjoint": [("g",) + G4],
        "se3_act_twist": [("g",) + G4, ("xi",) + six],
        "se3_act_wrench": [("g",) + G4, ("F",) + six],
        "se3_interpolate": [("a",) + G4, ("b",) + G4, ("t", (), None)],
        "se3_normalize": [("g", (4, 4), None)],
        "se3_hat": [("xi",) + six],
        "se3_vee": [("matrix", (4, 4), lambda: XI0.hat())],
        "so2_exp": [("theta", (), None)],
        "so2_log": [("R",) + R2],
        "so2_compose": [("a",) + R2, ("b",) + R2],
        "so2_inverse": [("R",) + R2],
        "so2_act": [("R",) + R2, ("points",) + v2],
        "so2_hat": [("theta", (), None)],
        "so2_vee": [("matrix", (2, 2), None)],
        "so2_interpolate": [("a",) + R2, ("b",) + R2, ("t", (), None)],
        "so2_normalize": [("R", (2, 2), None)],
        "se2_exp": [("xi",) + v3],
        "se2_log": [("g",) + G3],
        "se2_compose": [("a",) + G3, ("b",) + G3],
        "se2_inverse": [("g",) + G3],
        "se2_act": [("g",) + G3, ("points",) + v2],
        "se2_hat": [("xi",) + v3],
        "se2_vee": [("matrix", (3, 3), None)],
        "se2_interpolate": [("a",) + G3, ("b",) + G3, ("t", (), None)],
        "se2_normalize": [("g", (3, 3), None)],
        "sim3_exp": [("xi", (7,), None)],
        "sim3_log": [("g",) + S4],
        "sim3_compose": [("a",) + S4, ("b",) + S4],
        "sim3_inverse": [("g",) + S4],
        "sim3_act": [("g",) + S4, ("points",) + v3],
        "sim3_hat": [("xi", (7,), None)],
        "sim3_vee": [("matrix", (4, 4), None)],
        "sim3_interpolate": [("a",) + S4, ("b",) + S4, ("t", (), None)],
        "sim3_normalize": [("g", (4, 4), None)],
        "se23_exp": [("xi", (9,), None)],
        "se23_log": [("X",) + X5],
        "se23_compose": [("a",) + X5, ("b",) + X5],
        "se23_inverse": [("X",) + X5],
        "se23_act": [("X",) + X5, ("points",) + v3],
        "se23_hat": [("xi", (9,), None)],
        "se23_vee": [("matrix", (5, 5), None)],
        "se23_interpolate": [("a",) + X5, ("b",) + X5, ("t", (), None)],
        "se23_normalize": [("X", (5, 5), None)],
        "so3_angle": [("R",) + R3],
        "so3_distance": [("a",) + R3, ("b",) + R3],
        "se3_distance": [("a",) + G4, ("b",) + G4],
        "so2_distance": [("a",) + R2, ("b",) + R2],
        "se2_distance": [("a",) + G3, ("b",) + G3],
        "sim3_distance": [("a",) + S4, ("b",) + S4],
        "se23_distance": [("a",) + X5, ("b",) + X5],
    }
    # the Gaussians' propagation (means and covariances)
    for prefix, mean, d in (
        ("so2", R2, 1),
        ("se2", G3, 3),
        ("so3", R3, 3),
        ("se3", G4, 6),
        ("sim3", S4, 7),
        ("se23", X5, 9),
    ):
        cov = ((d, d), lambda d=d: 0.01 * np.eye(d))
        for f in ("compose_cov", "between_cov"):
            arrays[f"{prefix}_{f}"] = [("a",) + mean, ("cov_a",) + cov, ("b",) + mean, ("cov_b",) + cov]
        arrays[f"{prefix}_inverse_cov"] = [("a",) + mean, ("cov_a",) + cov]
        for f, (x, y) in (("compose", "ab"), ("between", "ab"), ("rminus", "gh")):
            arrays[f"{prefix}_{f}_jacobians"] = [(x,) + mean, (y,) + mean]
    for name, ops in arrays.items():
        spec[name] = _array_function(name, ops)
    spec["so3_from_quat"] = _array_function("so3_from_quat", [("quat", (4,), quat)], kw=("scalar_first",))
    spec["so3_as_quat"] = _array_function("so3_as_quat", [("R",) + R3], kw=("scalar_first",))
    spec["se3_from_quat"] = _array_function(
        "se3_from_quat", [("quat", (4,), quat), ("translation",) + v3], kw=("scalar_first",)
    )

    # the threads of the array functions' loops
    spec["set_num_threads"] = Entry([[ThreadCount("set_num_threads(n)")]], call=chasles.set_num_threads)
    spec["get_num_threads"] = Entry([[]], call=chasles.get_num_threads)

    # samplers (numpy's Generator draws, C++ kernels map)
    spec["so3_from_uniforms"] = _array_function("so3_from_uniforms", [("u", (3,), None)])
    spec["so3_random"] = Entry([[Size("so3_random(n)"), Rng("so3_random(rng)")]], call=chasles.so3_random)
    spec["se3_random"] = Entry([[Size("se3_random(n)"), Rng("se3_random(rng)")]], call=chasles.se3_random)
    for name, n, group in (("so3_gaussian", 3, SO3), ("se3_gaussian", 6, SE3)):
        k = 3 if n == 3 else 4
        spec[name] = Entry(
            [
                [
                    GroupMatrix(f"{name}(mean)", (k, k), valid=lambda G=group: np.asarray(GOOD[G]())),
                    Anything("cov", 0.01 * np.eye(n)),
                    Size(f"{name}(n)"),
                    Rng(f"{name}(rng)"),
                ]
            ],
            call=getattr(chasles, name),
        )
    # the samplers and means of SO2, SE2, Sim3 and SE23 (one generic function each, _random.py / _mean.py)
    for prefix, k, dof in (("so2", 2, 1), ("se2", 3, 3), ("sim3", 4, 7), ("se23", 5, 9)):
        spec[f"{prefix}_random"] = Entry(
            [[Size(f"{prefix}_random(n)"), Rng(f"{prefix}_random(rng)")]], call=getattr(chasles, f"{prefix}_random")
        )
        spec[f"{prefix}_gaussian"] = Entry(
            [
                [
                    Anything("mean", np.eye(k)),
                    Anything("cov", 0.01 * np.eye(dof)),
                    Size(f"{prefix}_gaussian(n)"),
                    Rng(f"{prefix}_gaussian(rng)"),
                ]
            ],
            call=getattr(chasles, f"{prefix}_gaussian"),
        )
    for name, k in (
        ("so3_mean", 3),
        ("se3_mean", 4),
        ("so2_mean", 2),
        ("se2_mean", 3),
        ("sim3_mean", 4),
        ("se23_mean", 5),
    ):
        spec[name] = Entry(
            [
                [
                    Anything("matrices", np.stack([np.eye(k), np.eye(k)])),
                    Anything("weights", None),
                    Anything("method", "geodesic"),
                ]
            ],
            call=getattr(chasles, name),
        )
    for name in ("so3_align", "se3_align", "sim3_align"):
        spec[name] = Entry(
            [
                [
                    AlignRows(f"{name}(a)", name, True),
                    AlignRows(f"{name}(b)", name, False),
                    AlignWeights(f"{name}(weights)", name),
                ]
            ],
            call=_undetermined_allowed(getattr(chasles, name)),
        )
    spec["SO3.random"] = _static(SO3, "random", Rng("so3_random(rng)"))
    spec["SE3.random"] = _static(SE3, "random", Rng("se3_random(rng)"))
    # Euler angles and RPY: the sequence picks the ufunc
    for name, core, valid in (("so3_from_euler", (3,), None), ("so3_as_euler", (3, 3), rotation)):
        operand = "angles" if name == "so3_from_euler" else "R"
        spec[name] = Entry(
            [
                [
                    Sequence(f"{name}(seq)"),
                    Operand(f"{name}:{operand}", core, valid),
                    Flag("degrees"),
                ]
            ],
            call=_gimbal_lock_allowed(lambda q, a, d, f=getattr(chasles, name): f(q, a, degrees=d)),
            passes_arguments=False,
            extra_errors=NUMPY_SCALAR_ERRORS,
        )
    spec["so3_from_rpy"] = _array_function("so3_from_rpy", [("rpy",) + v3], kw=("degrees",))
    spec["so3_as_rpy"] = _array_function("so3_as_rpy", [("R",) + R3], kw=("degrees",))
    spec["so3_as_rpy"].call = _gimbal_lock_allowed(spec["so3_as_rpy"].call)
    # Splines: the constructor (checked through an evaluation of what it built) and the evaluations
    for cls, what, k, keys in (
        (chasles.SO3Spline, "rotations", 3, lambda: np.stack([np.eye(3), rotation()])),
        (chasles.SE3Spline, "poses", 4, lambda: np.stack([np.eye(4), pose()])),
        (chasles.SO2Spline, "keys", 2, lambda: np.stack([np.eye(2), GOOD[chasles.SO2]().as_matrix()])),
        (chasles.SE2Spline, "keys", 3, lambda: np.stack([np.eye(3), GOOD[chasles.SE2]().as_matrix()])),
        (chasles.Sim3Spline, "keys", 4, lambda: np.stack([np.eye(4), GOOD[chasles.Sim3]().as_matrix()])),
        (chasles.SE23Spline, "keys", 5, lambda: np.stack([np.eye(5), GOOD[chasles.SE23]().as_matrix()])),
    ):
        name = cls.__name__
        spec[f"{name}.__init__"] = Entry(
            [[KeyTimes(f"{name}(times)"), SplineKeys(f"{name}({what})", (2, k, k), keys, cls)]],
            call=lambda t, x, c=cls: c(t, x)(0.7),
            passes_arguments=False,
        )
        spline = cls([0.0, 1.5], keys())
        for method in ("__call__", "body_velocity", "body_acceleration"):
            spec[f"{name}.{method}"] = Entry(
                [[EvalTimes(f"{name}(t)")]],
                call=lambda t, f=getattr(spline, method): f(t),
                passes_arguments=False,
            )
        spec[f"{name}.{what}"] = Entry([[]], call=lambda s=spline, w=what: getattr(s, w), passes_arguments=False)
    spec.update(_trajectory_spec())
    return spec


@dataclass
class KeyTimes(Arg):
    """The key times of a spline of two keys: shape (2,), finite, increasing."""

    def good(self):
        return np.array([0.0, 1.5])

    def judge(self, value):
        a = real_array(value, self.label)
        if isinstance(a, Refused):
            return a
        if a.ndim != 1 or a.shape[0] < 2:
            return Refused(ValueError, (self.label, "expected shape", f"got {shape_text(a.shape)}"))
        c = finite_or_refused(a, self.label)
        if isinstance(c, Refused):
            return c
        if not np.all(np.diff(c.value) > 0):
            return Refused(ValueError, (self.label, "strictly increasing"))
        if a.shape != (2,):
            # the times are checked first; then the keys must have one element per time
            return Refused(ValueError, ("expected shape", "one per time"))
        return c


@dataclass
class SplineKeys(Arg):
    """Two keys of a spline of class `spline`: an array-like (or sequence of
    objects) of shape (2, k, k), each accepted by the group's from_matrix
    (its defect at most sqrt(eps))."""

    shape: tuple = (2, 3, 3)
    valid: Callable[[], Any] | None = None
    spline: Any = None

    def good(self):
        return self.valid()

    def judge(self, value):
        a = real_array(value, self.label)
        if isinstance(a, Refused):
            return a
        if a.shape != self.shape:
            return Refused(ValueError, (self.label, "expected shape", f"got {shape_text(a.shape)}"))
        c = finite_or_refused(a, self.label)
        if isinstance(c, Refused):
            return c
        group = getattr(chasles, self.spline.__name__[: -len("Spline")])
        check = getattr(group, "rotation_defect", None) or group.transform_defect
        for m in c.value:
            defect = check(m)
            if not defect <= 1.4901161193847656e-08:
                return Refused(ValueError, (self.label, "not a"))
        return c


@dataclass
class EvalTimes(Arg):
    """Times to evaluate a spline at: a real array-like of any shape, finite."""

    def good(self):
        return np.array([[0.25, 1.0]])

    def judge(self, value):
        a = real_array(value, self.label)
        if isinstance(a, Refused):
            return a
        return finite_or_refused(a, self.label)


# ---- time scalings and joint trajectories (time_scaling, joint_trajectory) -------------------

SCALING_KINDS = ("cubic", "quintic", "trapezoidal")
# Times before, during and after a motion of 1.5 s; two joints.
TRAJECTORY_T = np.array([-0.5, 0.0, 0.3, 1.0, 1.5, 2.0])
TRAJECTORY_Q = (np.array([0.3, -0.7]), np.array([1.0, 0.5]))
MAX_TRAJECTORY_JOINTS = 32  # a Chain's bound


def _broadcast_refusal(label, shapes):
    """The refusal (naming the function) of shapes that do not broadcast together, or None."""
    try:
        np.broadcast_shapes(*shapes)
    except ValueError:
        return Refused(ValueError, (label.split("(")[0], "broadcast together"))
    return None


@dataclass
class ScalingKind(Arg):
    """The kind of time_scaling / joint_trajectory: a str (subclasses
    included), 'cubic', 'quintic' or 'trapezoidal'; another str is a
    ValueError, anything else a TypeError, both naming the argument.
    `ratio_given`: the call passes a peak_velocity_ratio, which
    'trapezoidal' requires (a ValueError naming peak_velocity_ratio)."""

    valid: str = "quintic"
    ratio_given: bool = False

    def good(self):
        return self.valid

    def variants(self):
        """Values to try: the kinds, near misses, str subclasses and other types."""
        return [*SCALING_KINDS, "Cubic", "QUINTIC", "quintic ", "trapezoid", "linear", "", "cubic\0",
                np.str_("cubic"), np.str_("trapezoid"), StrKind("quintic"), StrKind("septic"), b"cubic",
                ["cubic"], np.array("quintic"), 3, 5]  # fmt: skip

    def judge(self, value):
        if not isinstance(value, str):
            return Refused(TypeError, (self.label, "str"))
        if value not in SCALING_KINDS:
            return Refused(ValueError, (self.label, "'cubic', 'quintic' or 'trapezoidal'", "got"))
        if value == "trapezoidal" and not self.ratio_given:
            return Refused(ValueError, (self.label.replace("(kind)", "(peak_velocity_ratio)"), "required"))
        return Accepted(str(value))


class StrKind(str):
    """A str subclass (a kind is taken as the plain str)."""


@dataclass
class ScalingArray(Arg):
    """t, duration or peak_velocity_ratio of time_scaling / joint_trajectory:
    real numbers of any shape (any real dtype, layout or container), read as
    float64; each number checked by `rule` ('time': not NaN, infinities
    allowed; 'duration': finite and > 0; 'ratio': in (1, 2], None refused
    as the trapezoid requires one); the shape broadcasting together with
    `others`, the shapes of the other arguments' valid values (a joint
    vector's without its last axis). `ignored`: the peak_velocity_ratio of
    a kind that does not read it: anything is the same as None."""

    rule: str = "time"
    valid: Callable[[], Any] | None = None
    others: tuple = ()
    ignored: bool = False

    def good(self):
        return self.valid()

    def judge(self, value):
        if self.ignored:
            return Accepted(None)
        if self.rule == "ratio" and value is None:
            return Refused(ValueError, (self.label, "required", "trapezoidal"))
        a = real_array(value, self.label)
        if isinstance(a, Refused):
            return a
        c = plain(a, np.float64)
        if self.rule == "time" and np.isnan(c).any():
            return Refused(ValueError, (self.label, "not NaN"))
        if self.rule == "duration" and not (np.isfinite(c) & (c > 0)).all():
            return Refused(ValueError, (self.label, "finite and > 0"))
        if self.rule == "ratio" and not ((c > 1) & (c <= 2)).all():
            return Refused(ValueError, (self.label, "(1, 2]"))
        return _broadcast_refusal(self.label, (c.shape, *self.others)) or Accepted(c)


@dataclass
class TrajectoryJoints(Arg):
    """q_start or q_end of joint_trajectory: real numbers of shape (n,) or
    (..., n), n <= 32, finite, read as float64; n the other vector's (2),
    the leading axes broadcasting together with `others` (the shapes of
    the other arguments' valid values, the joint vector's without its last
    axis)."""

    valid: Callable[[], Any] | None = None
    others: tuple = ()

    def good(self):
        return self.valid()

    def judge(self, value):
        a = real_array(value, self.label)
        if isinstance(a, Refused):
            return a
        if a.ndim < 1:
            return Refused(ValueError, (self.label, "(n,) or (..., n)", "got ()"))
        if a.shape[-1] > MAX_TRAJECTORY_JOINTS:
            return Refused(ValueError, (self.label, f"at most {MAX_TRAJECTORY_JOINTS} joints"))
        c = finite_or_refused(a, self.label)
        if isinstance(c, Refused):
            return c
        if a.shape[-1] != TRAJECTORY_Q[0].shape[0]:
            return Refused(ValueError, ("joint_trajectory(q_start, q_end)", "same number of joints"))
        return _broadcast_refusal(self.label, (a.shape[:-1], *self.others)) or c


def _trajectory_spec():
    """time_scaling and joint_trajectory: a signature of a kind that does not
    read the ratio (quintic, given None), and one of the trapezoid ([1.5]);
    durations [1.5] (shape (1,): every catalog variant of an array)."""
    spec = {}
    t_shape = TRAJECTORY_T.shape
    for name in ("time_scaling", "joint_trajectory"):
        signatures = []
        for kind, ratio in (("quintic", None), ("trapezoidal", 1.5)):
            trapezoid = ratio is not None
            # the valid arguments and their (batch) shapes: (q_start, q_end), t, duration, ratio
            joints = [(f"{name}(q_start)", 0), (f"{name}(q_end)", 1)] if name == "joint_trajectory" else []
            shapes = {"t": t_shape, "duration": (1,), **({"ratio": (1,)} if trapezoid else {})}
            shapes.update({label: () for label, _ in joints})

            def others(skip, shapes=shapes):
                return tuple(v for k, v in shapes.items() if k != skip)

            signature = [
                TrajectoryJoints(label, valid=lambda i=i: TRAJECTORY_Q[i].copy(), others=others(label))
                for label, i in joints
            ]
            signature += [
                ScalingArray(f"{name}(t)", "time", lambda: TRAJECTORY_T.copy(), others("t")),
                ScalingArray(f"{name}(duration)", "duration", lambda: np.array([1.5]), others("duration")),
                ScalingKind(f"{name}(kind)", kind, trapezoid),
                ScalingArray(
                    f"{name}(peak_velocity_ratio)",
                    "ratio",
                    lambda r=ratio: None if r is None else np.array([r]),
                    others("ratio"),
                    ignored=not trapezoid,
                ),
            ]
            signatures.append(signature)
        spec[name] = Entry(signatures, call=getattr(chasles, name))
    return spec


@dataclass
class SO3Or(Arg):
    """The right operand of ``R @ x``: an SO3 (composition) or points."""

    def good(self):
        return np.array([[0.5, -1.0, 2.0]])

    def judge(self, value):
        if isinstance(value, chasles.SO3):
            return Instance(self.label, (chasles.SO3,)).judge(value)
        return Points(self.label).judge(value)


@dataclass
class PlanarOr(Arg):
    """The right operand of ``g @ x`` for SO2 and SE2: one of `objects`
    (composition) or points of the plane."""

    objects: tuple = ()

    def good(self):
        return np.array([[0.5, -1.0]])

    def judge(self, value):
        if isinstance(value, self.objects):
            return Instance(self.label, self.objects).judge(value)
        return Points(self.label, 2).judge(value)


@dataclass
class SE3Or(Arg):
    """The argument of ``g @ x``, ``g.act(x)``, ``g.act_inv(x)``: one of
    `objects` (initialized), or points."""

    objects: tuple = ()

    def good(self):
        return np.array([[0.5, -1.0, 2.0]])

    def judge(self, value):
        if isinstance(value, self.objects):
            return Instance(self.label, self.objects).judge(value)
        return Points(self.label).judge(value)


SPEC = _build_spec()


def array_arguments() -> list[tuple]:
    """Every fixed-shape array argument of SPEC's callables (``Array``, and
    ``TwistOr``, which takes a Twist too), each once: ``(label, call, valid,
    shape text, finite)``, where ``call(x)`` calls the callable with x in
    that argument and valid values in the others. test_bad_input.py puts
    each through its bad inputs. (``GroupMatrix`` is left out: a matrix that
    must be a rotation or a rigid motion, of which integer forms are not.)"""
    found: dict[str, tuple] = {}
    for entry in SPEC.values():
        for signature in entry.signatures:
            for k, arg in enumerate(signature):
                if type(arg) not in (Array, TwistOr) or arg.label in found:
                    continue

                def call(x, entry=entry, signature=signature, k=k):
                    return entry.call(*(x if j == k else a.good() for j, a in enumerate(signature)))

                found[arg.label] = (arg.label, call, np.asarray(arg.good()), shape_text(arg.shape), arg.finite)
    return list(found.values())


def is_array_function(entry) -> bool:
    """An array function (so3_*, se3_*): its arguments are operands, flags and
    an Euler sequence."""
    args = [a for s in entry.signatures for a in s]
    return any(isinstance(a, Operand) for a in args) and all(isinstance(a, (Operand, Flag, Sequence)) for a in args)


ARRAY_FUNCTIONS = sorted(name for name, entry in SPEC.items() if is_array_function(entry))

# Members of the bound classes that are not part of the API to specify:
# pybind11's own hook, and attributes that are not callables.
NOT_API = {
    "_pybind11_conduit_v1_",
    "__doc__",
    "__module__",
    "__dict__",
    "__weakref__",
    "__array_ufunc__",
    "__hash__",  # None: the objects are unhashable (test_objects.py checks it)
}


def callables() -> dict[str, Any]:
    """Every public callable of chasles, by name ("so3_exp", "SO3.exp",
    "Chain.screws" for a property), found from the module: __all__ and the
    members each class defines itself (inherited object methods excluded)."""
    out = {}
    for name in chasles.__all__:
        obj = getattr(chasles, name)
        if isinstance(obj, type):
            for member, value in vars(obj).items():
                if member in NOT_API or value is None:
                    continue
                if callable(value) or isinstance(value, (property, staticmethod, classmethod)):
                    out[f"{name}.{member}"] = value
        elif callable(obj):
            out[name] = obj
    return out


# ---- comparing outcomes ------------------------------------------------------------------


def canon(result):
    """A comparable, bit-exact form of a result (arrays by dtype, shape and
    bits, NaN payloads folded: every NaN compares equal to every NaN)."""
    if isinstance(result, np.ndarray) and type(result) is not np.ndarray and result.ndim == 0:
        # numpy gives a scalar for a 0-d ufunc result, but a 0-d array of
        # an ndarray subclass operand's type (__array_wrap__): the same outcome
        return canon(result[()])
    if isinstance(result, np.ndarray):
        a = np.ascontiguousarray(result)
        bits = a.copy()
        if a.dtype.kind == "f":
            bits[np.isnan(a)] = np.nan
        return ("ndarray", a.dtype.str, a.shape, bits.tobytes())
    if isinstance(result, BOUND):
        return (type(result).__name__, canon(np.array(result.__getstate__(), dtype=np.float64)))
    if isinstance(result, float):
        return ("float", canon(np.array([result])))
    if isinstance(result, (tuple, list)):
        return (type(result).__name__, tuple(canon(x) for x in result))
    if isinstance(result, (bool, int, str, bytes)) or result is None:
        return (type(result).__name__, result)
    if isinstance(result, np.generic):
        return canon(np.asarray(result))
    return ("object", type(result).__name__)


def outcome(call, args):
    """("ok", canon(result)) or ("raise", exception type, message)."""
    try:
        return ("ok", canon(call(*args)))
    except Exception as e:  # noqa: BLE001 - the caller checks the type
        return ("raise", type(e), str(e))
