"""Pickling and copying of every public class of chasles.

The public classes are found by introspection, not listed: every class that
``import chasles`` makes an attribute of the package under a public name (in
``chasles.__all__`` or in ``dir(chasles)`` without a leading underscore),
exceptions excluded (they are raised, not made by the user). So a class added
to the package is tested here as soon as it is exported, and the test fails
until an example instance of it is added to ``EXAMPLES``. (Classes that only
come back from calls, such as the NamedTuple ``IKResult`` of the private
module ``chasles._results`` or those of the optional ``chasles.plot``, are not
attributes of the package and not covered here.)

For each class and example:

- ``pickle.dumps`` / ``loads`` at every protocol 0 .. HIGHEST_PROTOCOL gives
  an object of the same type whose numbers are the same bit for bit (the
  bytes of every array it shows, and of its pickled state);
- ``copy.copy`` and ``copy.deepcopy`` give equal objects (bit for bit);
- a tampered state (a NaN put in place of its first number, and the
  tampering of ``TAMPERED``: a matrix that is not a rotation, a negative
  mass, ...) is refused when the pickle is loaded: a ValueError that names
  the class, the constructor's check;
- the pickles written by chasles 0.1.0 (tests/python/data/pickles, written
  by tests/python/data/write_pickles.py with that version) still load, equal
  to the same example made today.

The B-splines did not pickle in chasles 0.1.0 (protocols 0 and 1 aborted the
interpreter, the others raised TypeError): they have no legacy pickles.
"""

from __future__ import annotations

import copy
import inspect
import math
import os
import pickle

import numpy as np
import pytest

import chasles

HERE = os.path.dirname(os.path.abspath(__file__))
LEGACY = os.path.join(HERE, "data", "pickles")
PROTOCOLS = list(range(pickle.HIGHEST_PROTOCOL + 1))

# Classes that did not pickle in chasles 0.1.0 (or did not exist): no legacy pickles of them.
NOT_PICKLED_IN_0_1_0 = {
    "Gaussian",
    "PoseGraph",
    "SO3BSpline",
    "SE3BSpline",
    "SO2",
    "SE2",
    "Sim3",
    "SE23",
    "SO2Spline",
    "SE2Spline",
    "Sim3Spline",
    "SE23Spline",
    "SO2BSpline",
    "SE2BSpline",
    "Sim3BSpline",
    "SE23BSpline",
}


def public_classes():
    """The public classes of the package (see the module docstring)."""
    names = set(getattr(chasles, "__all__", ())) | {n for n in dir(chasles) if not n.startswith("_")}
    out = []
    for name in sorted(names):
        obj = getattr(chasles, name, None)
        if inspect.isclass(obj) and not issubclass(obj, BaseException):
            out.append(name)
    return out


def _chain_with_model():
    base = chasles.SE3(chasles.SO3.exp([0.0, 0.0, 0.25]), [0.5, -0.25, 1.0])
    tool = chasles.SE3(translation=[0.0, 0.0, 0.125])
    inertias = [[2.0, 0.1, 0.0, 0.2, 0.05, 0.0, 0.0, 0.06, 0.0, 0.07],
                [1.0, 0.0, 0.1, 0.0, 0.02, 0.0, 0.0, 0.03, 0.0, 0.04]]  # fmt: skip
    return chasles.Chain(
        [
            chasles.Chain.revolute_screw([0.0, 0.0, 0.0], [0.0, 0.0, 1.0]),
            chasles.Chain.prismatic_screw([1.0, 0.0, 0.0]),
        ],
        chasles.SE3(translation=[1.0 / 3.0, 0.0, 0.5]),
        joint_types=["revolute", "prismatic"],
        joint_names=["shoulder", "slide"],
        lower=[-1.5, 0.0],
        upper=[1.5, 0.25],
        velocity_limits=[2.0, 0.5],
        effort_limits=[10.0, 100.0],
        base=base,
        tool=tool,
        gravity=[0.0, 0.0, -9.80665],
        link_inertias=inertias,
    )


def _key_rotations():
    return chasles.so3_exp([[0.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.5, 0.0, 1.0], [0.5, -0.25, 1.5]])


def _key_poses():
    return chasles.se3_exp([[0.0, 0.0, 0.0, 0.0, 0.0, 0.0], [1.0, 0.0, 0.0, 0.0, 0.0, 0.5],
                            [2.0, 0.5, 0.0, 0.25, 0.0, 1.0], [2.5, 0.5, -0.5, 0.25, 0.0, 1.5]])  # fmt: skip


# Example instances of every public class, made from fixed numbers (the
# legacy pickles were written from these with chasles 0.1.0): name -> maker.
EXAMPLES = {
    "SO3": {"rotation": lambda: chasles.SO3.exp([0.1, -0.2, 1.0 / 3.0])},
    "SE3": {"pose": lambda: chasles.SE3.exp([1.0, -2.0, 1.0 / 3.0, 0.3, 0.2, -0.1])},
    "SO2": {"rotation": lambda: chasles.SO2.exp(1.0 / 3.0)},
    "SE2": {"pose": lambda: chasles.SE2.exp([1.0, -2.0, 1.0 / 3.0])},
    "Sim3": {"similarity": lambda: chasles.Sim3.exp([1.0, -2.0, 1.0 / 3.0, 0.3, 0.2, -0.1, 0.7])},
    "SE23": {"extended pose": lambda: chasles.SE23.exp([1.0, -2.0, 1.0 / 3.0, 4.0, 0.5, -6.0, 0.3, 0.2, -0.1])},
    "Twist": {"twist": lambda: chasles.Twist([0.1, 0.2, 1.0 / 3.0], [1e-300, -0.0, 5.0])},
    "Wrench": {"wrench": lambda: chasles.Wrench([1.0, 2.0, 3.0], [math.pi, 0.0, -1e10])},
    "Screw": {
        "screw": lambda: chasles.Screw([1.0, 0.5, 0.0], [0.0, 0.0, 1.0], 0.25, 2.0),
        "translation": lambda: chasles.Twist([1.0, 2.0, 3.0], [0.0, 0.0, 0.0]).screw(),
    },
    "SpatialInertia": {
        "body": lambda: chasles.SpatialInertia(
            2.5, [0.1, 0.0, 1.0 / 3.0], [[0.1, 0.01, 0.0], [0.01, 0.2, 0.0], [0.0, 0.0, 0.25]]
        )
    },
    "Chain": {
        "plain": lambda: chasles.Chain(
            [
                chasles.Chain.revolute_screw([1.0 / 3.0, 0.0, 0.0], [0.0, 0.0, 1.0]),
                chasles.Chain.prismatic_screw([1.0, 2.0, 3.0]),
            ],
            chasles.SE3.exp([1.0, -2.0, 1.0 / 3.0, 0.3, 0.2, -0.1]),
        ),
        "model": _chain_with_model,
    },
    "SO3Spline": {
        "natural": lambda: chasles.SO3Spline([0.0, 1.0, 3.0, 3.5], _key_rotations()),
        "chord": lambda: chasles.SO3Spline([0.0, 1.0, 3.0, 3.5], _key_rotations(), ends="chord"),
    },
    "SE3Spline": {"natural": lambda: chasles.SE3Spline([0.0, 1.0, 2.0, 4.0], _key_poses())},
    "SO2Spline": {"natural": lambda: chasles.SO2Spline([0.0, 1.0, 3.0], chasles.so2_exp([0.1, -0.4, 1.0 / 3.0]))},
    "SE2Spline": {
        "chord": lambda: chasles.SE2Spline(
            [0.0, 1.0, 3.0], chasles.se2_exp([[0.1, 0.2, 0.3], [1.0, -0.5, 1.0 / 3.0], [2.0, 0.0, -0.2]]), ends="chord"
        )
    },
    "Sim3Spline": {
        "natural": lambda: chasles.Sim3Spline(
            [0.0, 0.5, 2.0], chasles.sim3_exp(np.linspace(-0.3, 0.4, 21).reshape(3, 7) / 3.0)
        )
    },
    "SE23Spline": {
        "natural": lambda: chasles.SE23Spline(
            [0.0, 0.5, 2.0], chasles.se23_exp(np.linspace(-0.3, 0.4, 27).reshape(3, 9) / 3.0)
        )
    },
    "SO3BSpline": {"spline": lambda: chasles.SO3BSpline(0.0, 0.5, _key_rotations())},
    "SE3BSpline": {"spline": lambda: chasles.SE3BSpline(-1.0, 0.25, _key_poses())},
    "SO2BSpline": {"spline": lambda: chasles.SO2BSpline(0.0, 0.5, chasles.so2_exp([0.1, -0.2, 0.4, 1.0 / 3.0]))},
    "SE2BSpline": {"spline": lambda: chasles.SE2BSpline(0.0, 0.5, chasles.se2_exp(np.arange(12.0).reshape(4, 3) / 7))},
    "Sim3BSpline": {
        "spline": lambda: chasles.Sim3BSpline(1.0, 2.0, chasles.sim3_exp(np.arange(28.0).reshape(4, 7) / 30))
    },
    "SE23BSpline": {
        "spline": lambda: chasles.SE23BSpline(1.0, 2.0, chasles.se23_exp(np.arange(36.0).reshape(4, 9) / 40))
    },
    "PoseGraph": {"grid": lambda: chasles.pose_graph_grid(12, 3, seed=4)[0]},
    "Gaussian": {
        "se3": lambda: chasles.Gaussian(
            chasles.SE3.exp([1.0, 0.5, 0.0, 0.25, 0.0, 0.5]), np.diag(np.arange(1.0, 7.0)) / 8
        ),
        "so2": lambda: chasles.Gaussian(chasles.SO2.exp(0.75), [[0.125]]),
        "sim3": lambda: chasles.Gaussian(chasles.Sim3.exp(np.arange(7.0) / 8), np.eye(7) / 4),
    },
}

# States made invalid in the ways the constructors check, beyond the NaN of
# every class: (class, example) -> [(what, change(state) -> state)].


def _set(i, value):
    def change(state):
        s = list(state)
        s[i] = value
        return tuple(s)

    return change


def _not_rotation(state):
    return (2.0, 0.0, 0.0, 0.0, 2.0, 0.0, 0.0, 0.0, 2.0) + tuple(state[9:])


def _chain_screw(i, value):
    """A chain's state with entry i of its first screw (v, w) set to value."""

    def change(state):
        if isinstance(state[0], type):  # the constructor's arguments (class, screws, home, keywords)
            screws = np.array(state[1])
            screws.flat[i] = value
            return (state[0], screws) + tuple(state[2:])
        if isinstance(state[0], tuple):  # (numbers, names, inertias)
            return (_set(i, value)(state[0]),) + tuple(state[1:])
        return _set(i, value)(state)

    return change


def _spline_times(state):
    """Times that do not increase, in a legacy state dict or in the
    constructor's arguments (class, times, keys, ends)."""
    if isinstance(state, dict):
        s = dict(state)
        t = np.array(s["_t"])
        t[1] = t[0]
        s["_t"] = t
        return s
    cls, times, keys, ends = state
    t = np.array(times)
    t[1] = t[0]
    return (cls, t, keys, ends)


TAMPERED = {
    "SO3": [
        ("2 I, not a rotation", _not_rotation),
        ("a reflection", lambda s: (1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, -1.0)),
    ],
    "SE3": [("2 I, not a rotation", _not_rotation), ("an infinite translation", _set(11, math.inf))],
    "SO2": [("(2, 0), not a rotation", lambda s: (2.0, 0.0))],
    "Sim3": [
        ("2 I, not a rotation", _not_rotation),
        ("a zero scale", _set(12, 0.0)),
        ("a negative scale", _set(12, -1.0)),
    ],
    "SE23": [
        ("2 I, not a rotation", _not_rotation),
        ("a reflection", lambda s: (1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, -1.0) + tuple(s[9:])),
        ("an infinite velocity", _set(14, math.inf)),
    ],
    "SE2": [
        ("(0, 0), not a rotation", lambda s: (0.0, 0.0) + tuple(s[2:])),
        ("an infinite translation", _set(3, math.inf)),
    ],
    "Twist": [("inf", _set(5, -math.inf))],
    "Wrench": [("inf", _set(2, math.inf))],
    "Screw": [("a NaN pitch", _set(6, math.nan)), ("an infinite point", _set(1, math.inf))],
    "SpatialInertia": [
        ("a negative mass", _set(0, -1.0)),
        ("a zero mass", _set(0, 0.0)),
        ("an inertia that is not positive definite", _set(4, -0.1)),
    ],
    "Chain": [
        ("an infinite screw", _chain_screw(0, math.inf)),
        ("a revolute axis that is not a unit vector", _chain_screw(5, 0.5)),
    ],
    "SO3Spline": [("times that do not increase", _spline_times)],
    "SE3Spline": [("times that do not increase", _spline_times)],
    "SO2Spline": [("times that do not increase", _spline_times)],
    "SE2Spline": [("times that do not increase", _spline_times)],
    "Sim3Spline": [("times that do not increase", _spline_times)],
    "SE23Spline": [("times that do not increase", _spline_times)],
    "PoseGraph": [("a group that is not one", lambda args: ("so3",) + tuple(args[1:]))],
    "Gaussian": [("a covariance that is not positive semidefinite", lambda args: (args[0], -np.asarray(args[1])))],
}


def example(cls_name, key):
    return EXAMPLES[cls_name][key]()


def cases():
    out = []
    for name in public_classes():
        for key in EXAMPLES.get(name, {"(no example)": None}):
            out.append((name, key))
    return out


def params(extra=(None,)):
    """pytest params (class, example[, extra])."""
    out = []
    for name, key in cases():
        for x in extra:
            values = (name, key) if x is None else (name, key, x)
            out.append(pytest.param(*values, id="-".join(str(v) for v in values)))
    return out


# ---- what "the same object" means: its numbers, bit for bit -----------------------------------


def _canonical(value):
    """A comparable, bit-exact form of a value an object shows."""
    if isinstance(value, (str, bytes, bool, int)) or value is None:
        return value
    if isinstance(value, float):
        return ("float", np.float64(value).tobytes())
    if isinstance(value, (tuple, list)):
        return tuple(_canonical(v) for v in value)
    if isinstance(value, dict):
        return tuple((k, _canonical(v)) for k, v in value.items())
    if isinstance(value, np.ndarray) or hasattr(value, "__array__"):
        a = np.asarray(value)
        return ("array", str(a.dtype), a.shape, a.tobytes())
    return ("object", type(value).__name__, repr(value))


def snapshot(x):
    """Everything the object shows: its type, its array (np.asarray), each of
    its properties, and its pickled state, each bit for bit."""
    out = [("type", type(x).__qualname__, type(x).__module__)]
    if hasattr(x, "__array__"):
        out.append(("__array__", _canonical(np.asarray(x))))
    for name in sorted(dir(type(x))):
        if not name.startswith("__") and isinstance(getattr(type(x), name), property):
            out.append((name, _canonical(getattr(x, name))))
    if hasattr(x, "__getstate__"):
        out.append(("state", _canonical(x.__getstate__())))
    return out


def check_round_trip(name, key, protocol):
    x = example(name, key)
    y = pickle.loads(pickle.dumps(x, protocol=protocol))
    assert type(y) is type(x) and y is not x
    assert snapshot(y) == snapshot(x)
    if type(x).__eq__ is not object.__eq__:
        assert y == x


def check_copies(name, key):
    x = example(name, key)
    for y in (copy.copy(x), copy.deepcopy(x), copy.deepcopy([x, x])[0]):
        assert type(y) is type(x)
        assert snapshot(y) == snapshot(x)
        if type(x).__eq__ is not object.__eq__:
            assert y == x


class _Reduced:
    """Pickles as the given reduction: a hand-made pickle whose loading runs
    pickle's own path (the constructor, then __setstate__ with the state)."""

    def __init__(self, reduced):
        self.reduced = reduced

    def __reduce__(self):
        return self.reduced


def tampered_pickle(x, change):
    """A pickle of x with its state changed, or, for a class pickled as its
    constructor's arguments (no state: the splines), those arguments."""
    reduced = x.__reduce_ex__(2)
    # Protocol 1: pickle checks that copyreg.__newobj__'s class is the pickled
    # object's class from protocol 2 on; the loading path is the same.
    if len(reduced) < 3 or reduced[2] is None:
        return pickle.dumps(_Reduced((reduced[0], change(reduced[1]))), protocol=1)
    func, args, state = reduced[0], reduced[1], reduced[2]
    return pickle.dumps(_Reduced((func, args, change(state))), protocol=1)


def _first_number(value, new):
    """value with its first float (depth first) replaced by new, and whether one was."""
    if isinstance(value, float):
        return new, True
    if isinstance(value, np.ndarray) and value.dtype.kind == "f" and value.size:
        a = value.copy()
        a.flat[0] = new
        return a, True
    if isinstance(value, (tuple, list)):
        items = list(value)
        for i, v in enumerate(items):
            items[i], done = _first_number(v, new)
            if done:
                return type(value)(items), True
    if isinstance(value, dict):
        items = dict(value)
        for k, v in items.items():
            items[k], done = _first_number(v, new)
            if done:
                return items, True
    return value, False


def _nan_first(state):
    changed, done = _first_number(state, math.nan)
    assert done, f"no number in the state {state!r}"
    return changed


def check_tampered(name, key):
    x = example(name, key)
    changes = [("a NaN", _nan_first)] + TAMPERED.get(name, [])
    for what, change in changes:
        data = tampered_pickle(x, change)
        with pytest.raises(ValueError) as e:
            pickle.loads(data)
        # the constructor's check: __setstate__'s, or the constructor's own
        # for a class pickled as its constructor's arguments
        assert str(e.value).startswith((f"{name}.__setstate__", f"{name}(")), (what, str(e.value))


# ---- the tests ---------------------------------------------------------------------------------


def test_the_public_classes_are_found():
    """The introspection finds the classes the package documents, and no exception."""
    found = public_classes()
    for name in ("SO3", "SE3", "Twist", "Wrench", "Screw", "SpatialInertia", "Chain", "SO3Spline", "SE3Spline"):
        assert name in found
    assert all(not issubclass(getattr(chasles, n), BaseException) for n in found)


@pytest.mark.parametrize("name", public_classes())
def test_every_public_class_has_an_example(name):
    """A class exported without an example instance here fails (not skips)."""
    assert name in EXAMPLES, f"chasles.{name}: no example instance in test_pickle.EXAMPLES; add one"
    for key in EXAMPLES[name]:
        assert type(example(name, key)) is getattr(chasles, name)


@pytest.mark.parametrize("name, key, protocol", params(PROTOCOLS))
def test_pickle_round_trips_bit_for_bit(name, key, protocol):
    assert name in EXAMPLES, f"chasles.{name}: no example instance"
    check_round_trip(name, key, protocol)


@pytest.mark.parametrize("name, key", params())
def test_copy_and_deepcopy_are_equal(name, key):
    assert name in EXAMPLES, f"chasles.{name}: no example instance"
    check_copies(name, key)


@pytest.mark.parametrize("name, key", params())
def test_a_tampered_state_is_refused(name, key):
    assert name in EXAMPLES, f"chasles.{name}: no example instance"
    check_tampered(name, key)


def legacy_files():
    if not os.path.isdir(LEGACY):
        return []
    return sorted(f for f in os.listdir(LEGACY) if f.endswith(".pickle"))


def test_the_legacy_pickles_are_there():
    """One pickle at protocol 2 and one at the highest of every example that
    pickled when they were written (the B-splines did not)."""
    files = set(legacy_files())
    for name, examples in EXAMPLES.items():
        if name in NOT_PICKLED_IN_0_1_0:
            continue
        for key in examples:
            for protocol in (2, 5):
                assert f"{name}.{key}.protocol{protocol}.pickle" in files


@pytest.mark.parametrize("filename", legacy_files())
def test_pickles_of_version_0_1_0_still_load(filename):
    name, key, _ = filename.split(".", 2)
    with open(os.path.join(LEGACY, filename), "rb") as f:
        loaded = pickle.load(f)
    fresh = example(name, key)
    assert type(loaded) is type(fresh)
    assert snapshot(loaded) == snapshot(fresh)


@pytest.mark.parametrize("name", ["SO3Spline", "SE3Spline"])
def test_a_tampered_legacy_spline_state_is_refused(name):
    """chasles 0.1.0 pickled the splines as their dict (copyreg's path, then
    __setstate__): such a state is checked as the constructor checks."""
    import copyreg

    x = example(name, next(iter(EXAMPLES[name])))
    keys = x.rotations if name == "SO3Spline" else x.poses
    state = _spline_times({"_t": x.times, "_keys": keys, "_ends": x.ends})
    data = pickle.dumps(_Reduced((copyreg._reconstructor, (type(x), object, None), state)), protocol=1)
    with pytest.raises(ValueError, match=rf"^{name}\.__setstate__: "):
        pickle.loads(data)
    good = {"_t": x.times, "_keys": keys, "_ends": x.ends}
    data = pickle.dumps(_Reduced((copyreg._reconstructor, (type(x), object, None), good)), protocol=1)
    assert snapshot(pickle.loads(data)) == snapshot(x)


def test_a_chain_of_any_screw_norm_keeps_it_in_its_state():
    """__getstate__ of a chain made with unit_screws=False (which 0.1.0 could
    not make) ends in False, and __setstate__ rebuilds it bit for bit; without
    that flag (0.1.0's layout) the same numbers are refused, as the
    constructor refuses them. A chain of unit screws keeps 0.1.0's layouts."""
    screws = [[0.0, 0.0, 0.0, 1.0, 0.0, 1.0], [0.0, 0.0, 2.0, 0.0, 0.0, 0.0]]  # |w| = sqrt(2); |v| = 2
    x = chasles.Chain(screws, chasles.SE3(translation=[0.5, 0.0, 0.25]), unit_screws=False)
    state = x.__getstate__()
    assert len(state) == 4 and state[3] is False
    y = chasles.Chain.__new__(chasles.Chain)
    y.__setstate__(state)
    assert snapshot(y) == snapshot(x)
    np.testing.assert_array_equal(y.forward([0.3, 0.2]), x.forward([0.3, 0.2]))
    with pytest.raises(ValueError, match=r"^Chain\.__setstate__: .*not a unit vector"):
        chasles.Chain.__new__(chasles.Chain).__setstate__(state[:3])
    with pytest.raises(ValueError, match=r"^Chain\.__setstate__: expected a tuple"):
        chasles.Chain.__new__(chasles.Chain).__setstate__(state[:3] + (True,))
    assert [len(example("Chain", key).__getstate__()) for key in ("plain", "model")] == [6 * 2 + 12, 3]
