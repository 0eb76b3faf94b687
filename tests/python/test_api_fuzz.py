"""Bad input to the whole public API, driven by api_spec.py.

Every public callable (enumerated from the module: chasles.__all__ and the
members of its classes, so that a new one cannot be forgotten) is called
with every argument in turn replaced by something else: random shapes
(zero-size axes included), every dtype numpy has (bool, integers, float16,
float32, float64, big-endian, long double, complex, object, strings,
datetimes, void), NaN, infinities, -0.0, subnormals and extremes, every
memory layout (Fortran, strided, negative strides, read-only, unaligned,
stride-0 broadcast views), ndarray subclasses (np.matrix, masked arrays, a
trivial subclass), lists, tuples, None, strings, numbers, objects of the
wrong class and uninitialized ones.

What must happen is decided by api_spec.py's model of the documented
contract (see its docstring), never by running the library: either the
error it predicts (TypeError or ValueError, whose message names the
argument and says what was expected and what came), or exactly (bit for
bit, NaN for NaN) what the same call gives with the canonical form of the
input (the plain C-contiguous float64 array of the same numbers, float32
kept for the array functions; a Python float; a base-class object).
Nothing else: no crash, no other exception type, no C++ text.

A systematic table (every argument x a fixed catalog of inputs) runs
first; hypothesis then searches combinations of shape, dtype, values and
layout per callable.
"""

from __future__ import annotations

import copy
import decimal
import fractions
import inspect
import math
import re
import warnings

import api_spec as A
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import chasles

NAMES = sorted(A.SPEC)
ALLOWED = (TypeError, ValueError)
# Text that only an implementation leak would put in a message.
LEAK = re.compile(r"std::|chasles::|Eigen|pybind11::|C\+\+ exception|Unable to cast|instance allocation")
# pybind11's refusal of an argument of the wrong Python type lists the
# accepted signatures (naming the expected types) and what came.
PYBIND_REFUSAL = "incompatible function arguments"


class Sub(np.ndarray):
    """A trivial ndarray subclass."""


def as_matrix(a):
    """np.matrix(a), without numpy's PendingDeprecationWarning."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", PendingDeprecationWarning)
        return np.matrix(a)


class Duck:
    """An object that has none of the protocols the API reads."""


def _uninitialized(cls):
    return cls.__new__(cls)


class SubSO3(chasles.SO3):
    pass


class SubSE3(chasles.SE3):
    pass


class SubTwist(chasles.Twist):
    pass


class SubWrench(chasles.Wrench):
    pass


class SubScrew(chasles.Screw):
    pass


class SubChain(chasles.Chain):
    pass


SUBCLASS = {
    chasles.SO3: SubSO3,
    chasles.SE3: SubSE3,
    chasles.Twist: SubTwist,
    chasles.Wrench: SubWrench,
    chasles.Screw: SubScrew,
    chasles.Chain: SubChain,
}


def subclass_instance(cls):
    """A valid instance of a Python subclass of cls (made as the base is)."""
    x = A.GOOD[cls]()
    y = SUBCLASS[cls].__new__(SUBCLASS[cls])
    y.__setstate__(x.__getstate__())
    return y


# ---- the check -----------------------------------------------------------------------


def show(value):
    """repr() for a failure message, cut short."""
    return repr(value)[:200]


def expected_class_names(arg):
    if isinstance(arg, A.Instance):
        return [c.__name__ for c in arg.classes]
    if isinstance(arg, A.Scalar):
        return [arg.label.split()[0]]
    return []


def check_message(message, fragments, arg):
    if message == "NotImplemented":  # see run()
        return
    assert message, "an empty message"
    assert not LEAK.search(message), message
    if PYBIND_REFUSAL in message:
        # Only where the argument is typed by pybind11 itself (objects, bools, ints).
        assert isinstance(arg, (A.Instance, A.Flag, A.Anything, A.Home, A.SO3Or, A.SE3Or)), message
        assert "Invoked with" in message, message
    for fragment in fragments:
        options = fragment if isinstance(fragment, tuple) else (fragment,)
        assert any(f in message for f in options), f"{fragment!r} not in {message!r}"


def check_refusal_names_the_type(message, arg):
    """A refused object: the message names the class that was expected."""
    names = expected_class_names(arg)
    if names and message != "NotImplemented" and "not initialized" not in message:
        assert any(n in message for n in names), (names, message)


def run(call, args):
    """A.outcome; a binary operator's dunder called directly may answer
    NotImplemented (Python's protocol: the operator then raises TypeError)."""
    got = A.outcome(call, args)
    if got == ("ok", A.canon(NotImplemented)):
        return ("raise", TypeError, "NotImplemented")
    return got


def broadcast_verdict(name, signature, args):
    """The array functions' cross-operand rules: batch shapes must broadcast;
    the result has the broadcast batch shape, float32 iff every operand that
    is not a Python int or float casts safely to float32 (NEP 50: a Python
    bool is numpy's bool, not a weak scalar; so2_exp(True) is float32)."""
    shapes, strong = [], []
    for arg, value in zip(signature, args):
        if isinstance(arg, A.Operand):
            a = np.asarray(value)
            shapes.append(a.shape[: a.ndim - len(arg.core)])
            if type(value) not in (float, int):
                strong.append(a.dtype)
    try:
        batch = np.broadcast_shapes(*shapes)
    except ValueError:
        return A.Refused(ValueError, ("could not be broadcast",)), None
    f32 = bool(strong) and all(A.castable_to_float32(d) for d in strong)
    return None, (batch, np.float32 if f32 else np.float64)


def check(name, signature_index, args, i):
    """Calls SPEC[name] with args (argument i under test) and checks the
    outcome against the model."""
    entry = A.SPEC[name]
    signature = entry.signatures[signature_index]
    arg = signature[i]
    if isinstance(args[i], np.ma.MaskedArray) and not entry.passes_arguments and not (entry.self_first and i == 0):
        # numpy.ma's operators do not defer to __array_ufunc__ = None: x + m
        # is m.__radd__(x), numpy's answer (a masked array), not the library's.
        return
    verdict = arg.judge(args[i])
    shape_rule = None
    if isinstance(verdict, A.Accepted) and A.is_array_function(entry):
        canonical_args = list(args)
        canonical_args[i] = verdict.value
        refusal, shape_rule = broadcast_verdict(name, signature, canonical_args)
        if refusal is not None:
            verdict = refusal

    # A wrong self reaches the library only through the method itself.
    call = entry.call_with_self if (entry.self_first and i == 0) else entry.call
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # a warning from inside the library is a failure too
        got = run(call, args)
    if got[0] == "raise":
        kind, message = got[1], got[2]
        allowed = ALLOWED + entry.extra_errors
        assert issubclass(kind, allowed), f"{name}: {arg.label} = {show(args[i])}: {kind.__name__}: {message}"
        check_message(message, (), arg)

    if isinstance(verdict, A.Refused):
        assert got[0] == "raise", f"{name}: accepted {show(args[i])} for {arg.label}; expected {verdict}"
        assert issubclass(got[1], verdict.error), (
            f"{name}: {arg.label} = {show(args[i])}: {got[1].__name__}: {got[2]}; expected {verdict}"
        )
        check_message(got[2], verdict.fragments, arg)
        check_refusal_names_the_type(got[2], arg)
    elif isinstance(verdict, A.Gives):
        assert got == ("ok", A.canon(verdict.value)), (
            f"{name}: {arg.label} = {show(args[i])}: {got}; expected {verdict.value!r}"
        )
    elif isinstance(verdict, A.Accepted):
        canonical_args = list(args)
        canonical_args[i] = verdict.value
        want = run(call, canonical_args)
        if want[0] == "raise":
            assert got[0] == "raise" and got[1] is want[1], f"{name}: {got} but canonically {want}"
        else:
            assert got == want, f"{name}: {arg.label} = {show(args[i])}: {got} != canonical {want}"
            if shape_rule is not None:
                batch, dtype = shape_rule
                out = call(*args)
                for result in out if isinstance(out, tuple) else (out,):  # a gufunc of several results
                    assert result.shape[: len(batch)] == batch and result.dtype == dtype, (
                        result.shape,
                        batch,
                    )
                    if isinstance(result, np.generic):
                        # a 0-d result is a numpy scalar, as numpy's ufuncs
                        # (np.linalg.det) give: nothing to write or share
                        assert result.shape == () and batch == ()
                        continue
                    # a fresh, writeable array, laid out as numpy's order="K"
                    # does: C-contiguous for C-contiguous operands
                    assert result.flags.writeable
                    assert not any(isinstance(a, np.ndarray) and np.shares_memory(result, a) for a in args)
                    if all(a.flags.c_contiguous for a in args if isinstance(a, np.ndarray)):
                        assert result.flags.c_contiguous


def good_args(entry, k=0):
    return [a.good() for a in entry.signatures[k]]


# ---- the public API and its specification -----------------------------------------------


def test_every_public_callable_has_a_specification():
    found = A.callables()
    assert len(found) > 150
    missing = sorted(set(found) - set(A.SPEC))
    stale = sorted(set(A.SPEC) - set(found))
    assert not missing, f"public callables without an argument specification in api_spec.py: {missing}"
    assert not stale, f"api_spec.py specifies callables that do not exist: {stale}"


@pytest.mark.parametrize("name", NAMES)
def test_valid_arguments_are_accepted(name):
    entry = A.SPEC[name]
    for k in range(len(entry.signatures)):
        entry.call(*good_args(entry, k))


def has_defaults(name):
    """Whether a parameter of the callable has a default (from pybind11's
    signature lines at the top of its docstring)."""
    obj = A.callables()[name]
    if isinstance(obj, staticmethod):
        obj = obj.__func__
    if inspect.isfunction(obj):  # a Python function (chasles._random): its own signature
        return any(p.default is not p.empty for p in inspect.signature(obj).parameters.values())
    doc = (obj.fget if isinstance(obj, property) else obj).__doc__ or ""
    short = name.split(".")[-1]
    lines = [ln for ln in doc.splitlines() if re.match(rf"^(\d+\. )?{re.escape(short)}\(", ln)]
    return any(" = " in ln for ln in lines)


# (Not the callables reached through an operator, a builtin or keywords:
# there the count would be checked by Python, not by the library.)
@pytest.mark.parametrize("name", [n for n in NAMES if A.SPEC[n].passes_arguments])
def test_missing_and_extra_arguments_are_type_errors(name):
    entry = A.SPEC[name]
    args = good_args(entry)
    wrong = [args + [0.5]]
    if args and not has_defaults(name):
        wrong.append(args[:-1])
    for w in wrong:
        with pytest.raises(TypeError):
            entry.call(*w)


# ---- a fixed catalog of inputs, for every argument ---------------------------------------


def layouts(a):
    """a, and the same numbers in other memory layouts and containers."""
    yield a
    yield np.asfortranarray(a)
    if a.ndim:
        big = np.repeat(a, 2, axis=0)[::2]
        yield big
        yield a[::-1].copy()[::-1]
        yield np.broadcast_to(a[:1], a.shape)  # stride 0, read-only
        yield a.tolist()
        yield tuple(map(tuple, a.tolist())) if a.ndim == 2 else tuple(a.tolist())
    ro = a.copy()
    ro.flags.writeable = False
    yield ro
    if a.dtype.kind in "fiu" and a.dtype.itemsize > 1:
        un = np.zeros(a.nbytes + 1, np.uint8)[1:].view(a.dtype).reshape(a.shape)
        un[...] = a
        yield un
    if a.ndim <= 2:
        yield as_matrix(a)
    yield a.view(Sub)
    yield np.ma.masked_array(a, mask=np.zeros(a.shape, bool))


def dtype_variants(a):
    a = np.asarray(a, dtype=np.float64)
    for dt in (
        np.float32,
        np.float16,
        np.int64,
        np.int8,
        np.uint16,
        np.bool_,
        ">f8",
        ">f4",
        np.longdouble,
        np.complex128,
        object,
        "U8",
        "S8",
    ):
        yield a.astype(dt)
    yield np.zeros(a.shape, "M8[s]")
    yield np.zeros(a.shape, "V8")


def value_variants(a):
    a = np.asarray(a, dtype=np.float64)
    for x in (
        math.nan,
        math.inf,
        -math.inf,
        -0.0,
        5e-324,
        1e-300,
        1e300,
        1.7976931348623157e308,
        -1e10,
    ):
        b = a.copy()
        b.flat[-1] = x
        yield b
    yield np.zeros_like(a)


def shape_variants(a):
    a = np.asarray(a)
    yield a[..., :0] if a.ndim else np.zeros(0)
    yield np.zeros((0,) + a.shape)
    yield np.zeros((2, 0) + a.shape)
    yield np.stack([a, a, a])
    yield np.stack([[a, a], [a, a]])
    yield a.ravel()[:-1] if a.size > 1 else np.zeros(2)
    yield np.concatenate([a.ravel(), [1.0]])
    yield a.reshape(-1)
    yield np.zeros(())
    if a.ndim:
        yield a[..., None]
        yield np.moveaxis(np.stack([a, a]), 0, -1)


SCALARS = [
    None,
    "abc",
    b"abc",
    1j,
    np.complex64(1),
    Duck(),
    {},
    set(),
    0.5,
    7,
    True,
    False,
    -0.0,
    5e-324,
    math.nan,
    math.inf,
    -math.inf,
    10**400,
    -(10**400),
    np.float32(0.25),
    np.float16(0.5),
    np.int8(3),
    np.uint64(2**63),
    np.bool_(True),
    np.array(0.5),
    np.array(3),
    np.array([0.5]),
    [0.5],
    (0.5,),
    [],
    np.array(0.5, dtype=object),
    fractions.Fraction(1, 3),
    fractions.Fraction(10**400),
    decimal.Decimal("0.25"),
    decimal.Decimal("1e400"),
    decimal.Decimal("sNaN"),
    decimal.Decimal("NaN"),
    np.datetime64(1, "s"),
    [[1.0, 2.0], [3.0]],
]


def objects_for(arg):
    """Objects of every class, initialized or not, and subclass instances."""
    out = [A.GOOD[c]() for c in A.BOUND] + [_uninitialized(c) for c in A.BOUND]
    classes = getattr(arg, "classes", None) or getattr(arg, "objects", None) or ()
    out += [subclass_instance(c) for c in classes if c in SUBCLASS]
    return out


def catalog(arg):
    """The fixed inputs tried for an argument."""
    out = list(SCALARS) + objects_for(arg)
    base = arg.good()
    if isinstance(base, A.BOUND):
        base = np.asarray(base) if hasattr(base, "__array__") else None
    if isinstance(base, (np.ndarray, list, tuple)):
        base = np.asarray(base, dtype=np.float64)
        out += list(layouts(base)) + list(dtype_variants(base)) + list(value_variants(base))
        out += list(shape_variants(base))
        out += [
            np.array([base.tolist(), base.tolist()[:1]], dtype=object),
            [base.tolist(), base.tolist()[:-1]],
        ]
    elif isinstance(arg, A.ScalingKind):
        out += arg.variants()
    elif isinstance(arg, A.State):
        good = arg.good()
        out += [good, list(good), good[:-1], good + (0.0,)]
        for x in (math.nan, -0.0, 5e-324, 1, "a", None, np.float64(2.0), np.float32(2.0)):
            out.append(good[:-1] + (x,))
    return out


@pytest.mark.parametrize("name", NAMES)
def test_catalog_of_bad_inputs(name):
    entry = A.SPEC[name]
    for k, signature in enumerate(entry.signatures):
        for i, arg in enumerate(signature):
            for value in catalog(arg):
                args = good_args(entry, k)
                args[i] = value
                check(name, k, args, i)


# ---- hypothesis: combinations of shape, dtype, values and layout --------------------------

# The real dtypes first (drawn more often: they are accepted, and the
# result must then be right), then the others.
DTYPES = [
    np.float64,
    np.float32,
    np.float16,
    np.int64,
    np.int32,
    np.int8,
    np.uint8,
    np.uint64,
    np.bool_,
    ">f8",
    ">f4",
    np.longdouble,
    np.complex128,
    np.complex64,
    object,
    "U6",
    "S6",
    "M8[s]",
    "m8[s]",
]
SPECIAL = [
    0.0,
    -0.0,
    5e-324,
    2.2250738585072014e-308,
    1e-300,
    1e-20,
    1e-8,
    1.0,
    -1.0,
    math.pi,
    1e8,
    1e300,
    1.7976931348623157e308,
    math.nan,
    -math.nan,
    math.inf,
    -math.inf,
]


@st.composite
def shapes_near(draw, core):
    core = tuple(core)
    small = st.integers(0, 3)
    return draw(
        st.one_of(
            st.just(core),
            st.just(core),
            st.lists(small, max_size=2).map(lambda b: tuple(b) + core),
            st.lists(small, max_size=4).map(tuple),
            st.sampled_from([core[1:], core[:-1], core + (1,), (1,) + core, tuple(reversed(core))]),
            st.integers(0, len(core) - 1 if core else 0).flatmap(
                lambda j: st.sampled_from([-1, 1, -100]).map(
                    lambda d: tuple(max(0, c + d) if k == j else c for k, c in enumerate(core))
                )
            ),
        )
    )


@st.composite
def arrays_near(draw, base):
    """An array-like close to `base`: its shape or another, any dtype, its
    numbers or special ones, any layout or container."""
    base = np.asarray(base, dtype=np.float64)
    shape = draw(shapes_near(base.shape))
    size = math.prod(shape)
    values = np.resize(base.ravel(), size) if base.size else np.zeros(size)
    values = values.astype(np.float64)
    for _ in range(draw(st.integers(0, 3)) if size else 0):
        values[draw(st.integers(0, size - 1))] = draw(
            st.one_of(st.sampled_from(SPECIAL), st.floats(allow_nan=True, allow_infinity=True))
        )
    a = values.reshape(shape)
    dtype = np.dtype(draw(st.one_of(st.sampled_from(DTYPES[:12]), st.sampled_from(DTYPES))))
    with warnings.catch_warnings(), np.errstate(all="ignore"):
        warnings.simplefilter("ignore")
        if dtype.kind in "Mm":
            a = np.zeros(shape, dtype)
        elif dtype == object and draw(st.booleans()):  # noqa: E721 (a numpy dtype, compared by value)
            a = np.array([float(x) for x in values] + [None], dtype=object)[:-1].reshape(shape)
        else:
            a = a.astype(dtype)
    form = draw(
        st.sampled_from(
            [
                "plain",
                "fortran",
                "strided",
                "reversed",
                "readonly",
                "unaligned",
                "broadcast",
                "matrix",
                "subclass",
                "masked",
                "list",
                "tuple",
                "scalar0d",
            ]
        )
    )
    if form == "fortran":
        return np.asfortranarray(a)
    if form == "strided" and a.ndim:
        return np.repeat(a, 2, axis=0)[::2]
    if form == "reversed" and a.ndim:
        return a[::-1].copy()[::-1]
    if form == "readonly":
        a = a.copy()
        a.flags.writeable = False
        return a
    if form == "unaligned" and a.dtype.kind in "fiuc" and a.dtype.itemsize > 1:
        un = np.zeros(a.nbytes + 1, np.uint8)[1:].view(a.dtype).reshape(a.shape)
        un[...] = a
        return un
    if form == "broadcast" and a.ndim and a.shape[0]:
        return np.broadcast_to(a[:1], a.shape)
    if form == "matrix" and a.ndim <= 2 and a.dtype.kind in "biufc":
        return as_matrix(a)
    if form == "subclass":
        return a.view(Sub)
    if form == "masked" and a.dtype.kind in "biuf":
        return np.ma.masked_array(a, mask=np.zeros(a.shape, bool))
    if form == "list" and a.dtype.kind in "biufO":
        return a.tolist()
    if form == "tuple" and a.ndim == 1 and a.dtype.kind in "biuf":
        return tuple(a.tolist())
    if form == "scalar0d" and a.size:
        return a.ravel()[:1].reshape(())
    return a


def reals():
    return st.one_of(
        st.floats(allow_nan=True, allow_infinity=True),
        st.sampled_from(SPECIAL),
        st.integers(-(2**70), 2**70),
        st.sampled_from(SCALARS),
        st.floats(allow_nan=True, width=32).map(np.float32),
        st.floats(allow_nan=True).map(np.array),
        st.floats(allow_nan=True).map(lambda x: [x]),
        st.fractions(),
    )


FLAGS = [None, True, False, 0, 1, 2, 0.5, math.nan, "yes", np.bool_(True), np.array([1, 2]),
         np.array(1), [], [1], Duck()]  # fmt: skip
ANYTHING = [None, 0, 1, 2, 5, -1, 10**30, "f8", np.float32, "float32", "foo", np.dtype("c16"), object,
            {}, np.array([1, 2]), True, 1.5]  # fmt: skip


class StrSubclass(str):
    pass


# Euler sequences: valid ones, near misses, and str subclasses.
SEQUENCES = ["xyz", "ZYX", "zxz", "XYX", "xxy", "xYz", "XYz", "xy", "xyzx", "", "abc", "x y",
             "XYZ ", "xyz\0", np.str_("zyz"), np.str_("zzy"), StrSubclass("yxz"), StrSubclass("yy"),
             b"xyz", ["x", "y", "z"], ("x", "y", "z"), np.array("xyz")]  # fmt: skip


def values_for(arg):
    """A hypothesis strategy of inputs for an argument kind."""
    others = st.sampled_from(objects_for(arg) + list(SCALARS))
    if isinstance(arg, A.Sequence):
        return st.one_of(st.sampled_from(SEQUENCES), others)
    if isinstance(arg, (A.Real, A.Scalar)):
        return st.one_of(reals(), others)
    if isinstance(arg, A.Flag):
        return st.one_of(st.sampled_from(FLAGS), others)
    if isinstance(arg, A.Anything):
        return st.one_of(st.sampled_from(ANYTHING), others)
    if isinstance(arg, A.State):
        good = arg.good()
        return st.one_of(
            st.lists(
                st.one_of(st.floats(allow_nan=True), st.sampled_from(SPECIAL)),
                min_size=len(good),
                max_size=len(good),
            ).map(tuple),
            st.lists(st.floats(), max_size=len(good) + 2).map(tuple),
            st.tuples(*[st.one_of(st.just(x), st.sampled_from([1, "a", None, np.float64(1.0)])) for x in good]),
            others,
        )
    if isinstance(arg, (A.ScipyElement, A.ScalingKind)):
        return st.one_of(st.sampled_from(arg.variants()), others)
    if isinstance(arg, A.Instance):
        return others
    base = arg.good()
    if isinstance(base, A.BOUND):
        base = np.asarray(base)
    return st.one_of(arrays_near(base), arrays_near(base), others)


def fuzz_settings():
    """Half the profile's examples per callable (there are 200 of them)."""
    return settings(max_examples=max(10, settings.default.max_examples // 2))


@pytest.mark.parametrize("name", NAMES)
@fuzz_settings()
@given(data=st.data())
def test_hypothesis_bad_inputs(name, data):
    entry = A.SPEC[name]
    k = data.draw(st.integers(0, len(entry.signatures) - 1), label="signature")
    signature = entry.signatures[k]
    if not signature:
        entry.call()
        return
    i = data.draw(st.integers(0, len(signature) - 1), label="argument")
    args = good_args(entry, k)
    if A.is_array_function(entry) and data.draw(st.booleans(), label="batched others"):
        # Other operands with a batch axis of 2, so that broadcasting can fail.
        args = [
            np.stack([a, a]) if isinstance(s, A.Operand) and j != i else a
            for j, (s, a) in enumerate(zip(signature, args))
        ]
    args[i] = data.draw(values_for(signature[i]), label=signature[i].label)
    check(name, k, args, i)


# ---- decisions, stated once more where a reader looks for them -----------------------------


def test_integers_and_float16_are_converted_by_numpys_casting_rules():
    """The objects read any real dtype as float64; the array functions are
    ufuncs, so numpy's casting decides: int16 and float16 run in the float32
    loop, int64 in the float64 one, long double (which neither loop takes
    safely) is refused."""
    w = np.array([1, 0, 2], dtype=np.int16)
    assert np.array_equal(chasles.SO3.exp(w).as_matrix(), chasles.SO3.exp(w.astype(float)).as_matrix())
    assert np.array_equal(
        chasles.SO3.exp(w.astype(np.float16)).as_matrix(),
        chasles.SO3.exp(w.astype(float)).as_matrix(),
    )
    for dt in (np.int16, np.float16):
        got = chasles.so3_exp(w.astype(dt))
        assert got.dtype == np.float32
        assert np.array_equal(got, chasles.so3_exp(w.astype(np.float32)))
    assert chasles.so3_exp(w.astype(np.int64)).dtype == np.float64
    if np.dtype(np.longdouble).itemsize > 8:
        with pytest.raises(TypeError, match=r"ufunc 'so3_exp' not supported for the input types"):
            chasles.so3_exp(w.astype(np.longdouble))


def test_nan_is_refused_by_constructors_and_carried_by_the_others():
    """The class docstrings' rule, argument by argument from the
    specification: an argument marked finite refuses NaN and infinities
    (ValueError, "finite"); the others (hat, vee, the defects, points) give
    NaN where the input had it, or inf for the defects."""
    refused, carried = 0, 0
    for name in NAMES:
        entry = A.SPEC[name]
        for k, signature in enumerate(entry.signatures):
            for i, arg in enumerate(signature):
                if not isinstance(arg, (A.Array, A.Points)) or isinstance(arg, A.TwistOr):
                    continue
                for bad in (math.nan, math.inf):
                    args = good_args(entry, k)
                    value = np.array(arg.good(), dtype=float)
                    # an entry every function reads (vee: off the diagonal)
                    value[(0, 1)[: value.ndim]] = bad
                    args[i] = value
                    if getattr(arg, "finite", False):
                        with pytest.raises(ValueError, match="finite"):
                            entry.call(*args)
                        refused += 1
                        continue
                    out = np.asarray(entry.call(*args), dtype=float)
                    if "defect" in name:
                        assert out == math.inf, name
                    elif math.isnan(bad):
                        assert np.isnan(out).any(), name
                    else:
                        assert not np.isfinite(out).all(), name
                    carried += 1
    assert refused > 50 and carried >= 14, (refused, carried)


def test_zero_size_batches_give_empty_results_everywhere():
    assert chasles.se3_exp(np.zeros((0, 6))).shape == (0, 4, 4)
    assert chasles.se3_act(np.eye(4), np.zeros((2, 0, 3))).shape == (2, 0, 3)
    assert chasles.SE3().act(np.zeros((0, 3))).shape == (0, 3)
    arm = A.GOOD[chasles.Chain]()
    assert arm.forward(np.zeros((0, 2))).shape == (0, 4, 4)
    assert arm.jacobian_space(np.zeros((0, 2))).shape == (0, 6, 2)
    with pytest.raises(ValueError, match=r"SO3.exp\(w\): expected shape \(3,\), got \(0,\)"):
        chasles.SO3.exp(np.zeros(0))


def test_huge_results_are_a_memory_error_not_a_crash():
    """The one exception beyond TypeError and ValueError: a result too large
    for memory (stride-0 inputs make that cheap to ask for) is numpy's
    MemoryError, raised before any work."""
    a = np.broadcast_to(np.eye(4), (2**22, 1, 4, 4))
    b = np.broadcast_to(np.eye(4), (1, 2**22, 4, 4))
    with pytest.raises(MemoryError):
        chasles.se3_compose(a, b)  # 2^44 poses: 2^51 bytes, past any address space
    with pytest.raises(ValueError):
        chasles.se3_compose(np.broadcast_to(np.eye(4), (2**40, 1, 4, 4)), np.broadcast_to(np.eye(4), (2**40, 4, 4)))


def test_subclass_instances_are_accepted_as_their_base():
    g = subclass_instance(chasles.SE3)
    assert isinstance(g, chasles.SE3) and type(g) is SubSE3
    h = A.GOOD[chasles.SE3]()
    assert (g @ h).is_approx(h @ h, 0.0)
    assert copy.copy(g).is_approx(h, 0.0)
