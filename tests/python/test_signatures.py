"""help() and inspect.signature on every public callable of chasles.

pybind11 writes each function's typed signature as the first line(s) of its
docstring; bindings/signatures.hpp adds the __text_signature__ CPython reads
(names, kinds, defaults) and makes the module the functions' __self__, so
that help() titles them "exp(w)" instead of "exp(...) method of
pybind11_detail_function_record_... instance". The callables are found as
api_spec.py finds them (chasles.__all__ and the members of the classes), so a
new one is checked without being listed here; the expected parameters are
read from pybind11's typed lines, an independent rendering of the same
record.
"""

from __future__ import annotations

import ast
import inspect
import pickle
import pydoc
import re

import api_spec as A
import numpy as np
import pytest

import chasles
from chasles import SE3, SO3, Chain, Twist, Wrench

CORE = "chasles._core"


def function_of(value):
    """The function behind a class attribute (static method, property getter)."""
    if isinstance(value, staticmethod):
        return value.__func__
    if isinstance(value, property):
        return value.fget
    return value


def is_pybind11_function(f) -> bool:
    """A function of the extension: a builtin function, or pybind11's
    instancemethod wrapper of one (an array function that is a numpy ufunc
    or a Python function has signatures of its own)."""
    return type(f).__name__ in ("builtin_function_or_method", "instancemethod") and (
        getattr(f, "__module__", None) == CORE
    )


FUNCTIONS = {
    name: function_of(value) for name, value in A.callables().items() if is_pybind11_function(function_of(value))
}
PROPERTIES = {name for name, value in A.callables().items() if isinstance(value, property)}


def test_the_public_callables_are_found():
    assert len(FUNCTIONS) > 150
    for name in ("SO3.exp", "SE3.rotation", "SE3.__init__", "Twist.vector", "rplus", "Chain.home"):
        assert name in FUNCTIONS, name


def split_top_level(text: str) -> list[str]:
    """ "a: int, b: tuple[int, int] = (1, 2)" -> ["a: int", "b: tuple[int, int] = (1, 2)"]."""
    parts, depth, current = [], 0, ""
    for c in text:
        if c in "([{":
            depth += 1
        elif c in ")]}":
            depth -= 1
        if c == "," and depth == 0:
            parts.append(current.strip())
            current = ""
        else:
            current += c
    if current.strip():
        parts.append(current.strip())
    return parts


def typed_signatures(name: str, f) -> list[list[tuple[str, str | None]]]:
    """pybind11's typed signature lines of f, each as [(parameter, default text)]
    ("/" and "*" markers left out)."""
    short = "" if name in PROPERTIES else name.split(".")[-1]
    lines = f.__doc__.splitlines()
    if len(lines) > 1 and lines[1] == "Overloaded function.":
        pattern = re.compile(rf"^\d+\. {re.escape(short)}\((.*)\)(?: -> .*)?$")
    else:
        pattern = re.compile(rf"^{re.escape(short)}\((.*)\)(?: -> .*)?$")
        lines = lines[:1]
    out = []
    for line in lines:
        m = pattern.match(line)
        if m is None:
            continue
        params = []
        for part in split_top_level(m.group(1)):
            if part in ("/", "*"):
                continue
            head, _, default = part.partition(" = ")
            params.append((head.split(":")[0].strip().lstrip("*"), default or None))
        out.append(params)
    assert out, f"{name}: no typed signature line in {lines[:3]}"
    return out


def expected_parameters(name: str, f) -> list[tuple[str, object]]:
    """The (name, default) pairs inspect must give, from the typed lines: one
    signature as it is; overloads merged position by position (different
    names joined by "_or_"), or (*args, **kwargs) when their shapes differ."""
    overloads = typed_signatures(name, f)
    if name in PROPERTIES:
        overloads = [[("self", None)] + o[1:] for o in overloads]  # pybind11 calls it arg0
    first = overloads[0]
    if any(len(o) != len(first) for o in overloads):
        head = [("self", inspect.Parameter.empty)] if first and first[0][0] == "self" else []
        return head + [("args", inspect.Parameter.empty), ("kwargs", inspect.Parameter.empty)]
    out = []
    for i, (_, default) in enumerate(first):
        names = []
        for o in overloads:
            if o[i][0] not in names:
                names.append(o[i][0])
        if default is None:
            value = inspect.Parameter.empty
        else:
            try:
                value = ast.literal_eval(default)
            except ValueError:  # an object: SO3()
                value = ...
        out.append(("_or_".join(names), value))
    return out


@pytest.mark.parametrize("name", sorted(FUNCTIONS))
def test_inspect_signature_gives_the_parameters(name):
    f = FUNCTIONS[name]
    sig = inspect.signature(f)
    got = [(p.name, p.default) for p in sig.parameters.values()]
    assert got == expected_parameters(name, f), (name, str(sig))
    for p in sig.parameters.values():
        assert p.annotation is inspect.Parameter.empty  # the types are in the typed lines


@pytest.mark.parametrize("name", sorted(FUNCTIONS))
def test_help_titles_each_function_with_its_signature(name):
    f = FUNCTIONS[name]
    short = name.split(".")[-1]
    assert f.__name__ == short
    text = pydoc.render_doc(f, renderer=pydoc.plaintext)
    title = text.splitlines()[2]
    assert title == f"{short}{inspect.signature(f)}", title
    assert "function_record" not in text and "PyCapsule" not in text
    # the typed line still opens the docstring under the title (the stub reads it)
    assert text.splitlines()[3].strip().startswith((f"{short}(", "(", f"{short}(*args"))


@pytest.mark.parametrize("cls", A.BOUND, ids=lambda c: c.__name__)
def test_help_of_a_class_shows_every_signature(cls):
    text = pydoc.render_doc(cls, renderer=pydoc.plaintext)
    assert "function_record" not in text and "PyCapsule" not in text
    assert not re.search(r"^ \|  \w+\(\.\.\.\)", text, flags=re.M), "a routine without signature"
    for member, value in vars(cls).items():
        f = function_of(value)
        if member.startswith("_pybind11"):
            continue  # pybind11's own hook (hidden by help: a private name)
        if is_pybind11_function(f) and not isinstance(value, property):
            assert f" |  {member}{inspect.signature(f)}" in text, member


def test_help_of_the_package_shows_every_signature():
    text = pydoc.render_doc(chasles._core, renderer=pydoc.plaintext)
    assert "function_record" not in text
    assert not re.search(r"^    \w+\(\.\.\.\)", text, flags=re.M), "a function without signature"
    assert "    rplus(g, xi)" in text and "    interpolate(a, b, t)" in text


@pytest.mark.parametrize(
    "f,expected",
    [
        (SO3.exp, "(w)"),
        (SE3.exp, "(xi)"),
        (SE3.from_screw, "(point, direction, pitch, theta)"),
        (Twist.from_screw, "(point, direction, pitch, theta)"),
        (Wrench.from_screw, "(point, direction, pitch, magnitude)"),
        (SO3.from_matrix, "(matrix, tol=1.4901161193847656e-08)"),
        (SO3.from_quat, "(quat, *, scalar_first=False)"),
        (SO3.as_quat, "(self, *, scalar_first=False)"),
        (SO3.log, "(self, /)"),
        (SO3.is_approx, "(self, other, tol=1e-09)"),
        (SO3.__init__, "(self, /)"),
        (SE3.__init__, "(self, rotation=Ellipsis, translation=(0.0, 0.0, 0.0))"),
        (Twist.__init__, "(self, v=(0.0, 0.0, 0.0), w=(0.0, 0.0, 0.0))"),
        (SE3.rotation.fget, "(self, /)"),
        (SO3.__eq__, "(self, other)"),
        (
            Chain.__init__,
            "(self, screws, home, *, joint_types=None, joint_names=None, lower=None, upper=None, "
            "velocity_limits=None, effort_limits=None, base=None, tool=None, gravity=None, "
            "link_inertias=None, unit_screws=True, names=None)",
        ),
        (chasles.rplus, "(g, xi)"),
        (chasles.interpolate, "(a, b, t)"),
    ],
    ids=lambda x: getattr(x, "__qualname__", x) if not isinstance(x, str) else "",
)
def test_signatures_read_as_the_documentation_writes_them(f, expected):
    assert str(inspect.signature(f)) == expected


@pytest.mark.parametrize("name", sorted(FUNCTIONS))
def test_overloads_that_name_a_parameter_differently_take_it_by_position(name):
    """act(self, twist) / act(self, wrench) / act(self, points) is
    act(self, twist_or_wrench_or_points, /): no keyword reaches that parameter
    in every overload, so it and the ones before it are positional-only."""
    f = FUNCTIONS[name]
    params = list(inspect.signature(f).parameters.values())
    renamed = [i for i, p in enumerate(params) if "_or_" in p.name]
    for p in params[: max(renamed) + 1] if renamed else []:
        assert p.kind is inspect.Parameter.POSITIONAL_ONLY, (name, p)


def test_bound_methods_drop_self():
    R = SO3.exp([0.1, 0.2, 0.3])
    assert str(inspect.signature(R.is_approx)) == "(other, tol=1e-09)"
    assert str(inspect.signature(R.log)) == "()"
    assert inspect.signature(SO3.is_approx).bind(R, R, tol=1e-3)  # a call inspect accepts


def test_the_functions_belong_to_the_module_and_still_work():
    """__self__ is the module (as for functions written in C); the calls go
    through a trampoline to pybind11's dispatcher: positional, keyword,
    bound, overloaded, NotImplemented and errors, and the specialized calls
    of a hot loop."""
    core = chasles._core
    for f in (SO3.exp, chasles.rplus, SE3.rotation.fget, Twist.vector.fget):
        assert f.__self__ is core and f.__module__ == CORE
    R = SO3.exp(w=[0.0, 0.0, 0.5])
    assert R.is_approx(other=SO3.exp([0.0, 0.0, 0.5]), tol=0.0)
    g = SE3(R, translation=[1.0, 2.0, 3.0])
    assert np.array_equal(g.translation, [1.0, 2.0, 3.0]) and g.rotation == R
    assert isinstance(g.act(Twist()), Twist) and isinstance(g.act(Wrench()), Wrench)
    assert Twist.__add__(Twist(), 3) is NotImplemented
    with pytest.raises(ValueError, match=r"SO3.exp\(w\): expected shape \(3,\)"):
        SO3.exp([1.0])
    total = 0.0
    for k in range(3000):  # long enough for the interpreter to specialize the calls
        total += SO3.exp([0.0, 0.0, 1e-4 * k]).log()[2] + (R @ R).as_quat()[3] + g.translation[0]
    assert np.isfinite(total)


def test_module_functions_pickle_by_name():
    for f in (chasles.rplus, chasles.interpolate, chasles.log_jacobian):
        assert pickle.loads(pickle.dumps(f)) is f


def test_the_docstring_keeps_pybind11s_typed_lines():
    assert SO3.exp.__doc__.splitlines()[0] == "exp(w: numpy.typing.ArrayLike) -> chasles._core.SO3"
    assert SO3.exp.__text_signature__ == "(w)"
    assert SE3.act.__doc__.splitlines()[:2] == ["act(*args, **kwargs)", "Overloaded function."]
