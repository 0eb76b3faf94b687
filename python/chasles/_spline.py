"""Interpolating C2 splines through key rotations and key poses.

The fit and the evaluation are C++ (include/chasles/spline.hpp, through
bindings/bind_splines.cpp): these classes check the arguments, hold the
spline's numbers as arrays (times, keys, the coefficients of each segment's
cubic, computed once by the private fit) and evaluate it with the private
gufuncs ``_so3_spline`` / ``_so3_spline_rates`` (``_se3_...``), whose
operands are those arrays and the times: numpy broadcasts the times and
runs the loop without the GIL. An evaluation is a binary search over the
times plus O(1) work: its cost does not grow with the number of keys (the
gufuncs read the arrays in place; nothing is copied or checked per call
but the times t). Everything is float64.

A spline is an immutable value: ``__init__`` runs once; it pickles (every
protocol) and copies as its constructor's arguments (times, keys, ends),
and unpickling fits again, after the constructor's checks.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from chasles import _core, _groups
from chasles._random import _asarray
from chasles._value import Value

ENDS = ("natural", "chord")

_MATH = """
    On segment i (t_i <= t <= t_{i+1}, tau = t - t_i) the spline is
    X(t) = X_i exp(r(tau)) with r a cubic in tau, r(0) = 0 and
    r(t_{i+1} - t_i) = log(X_i^-1 X_{i+1}): it passes through every key. The
    body velocity V = (X^-1 dX/dt)^vee = Jr(r) r' and the body acceleration
    dV/dt = Jr(r) r'' + (d/dt Jr(r)) r' (Jr the right Jacobian) are continuous
    at every key (C2); they are computed analytically. The rates at the keys
    solve the block-tridiagonal continuity equations, iterated to convergence
    (at most 30 iterations) because of the term quadratic in r'. With
    ``ends="natural"`` (the default) the acceleration is zero at the first and
    the last key; with ``ends="chord"`` the velocity there is the rate of the
    first / last segment's geodesic, log(X_0^-1 X_1) / (t_1 - t_0), as in
    scipy's ``RotationSpline``, which this spline then equals. Two keys give
    the geodesic at constant velocity; keys on one screw motion exp(t xi)
    give that motion. Outside [t_0, t_{N-1}] the first / last segment's cubic
    continues (as scipy's) up to 1e6 segment lengths from the end key
    (before t_0 - 1e6 (t_1 - t_0), after t_{N-1} + 1e6 (t_{N-1} - t_{N-2}));
    farther, for any finite t, the spline holds the element, velocity and
    acceleration it has there (the cubic grows as tau^3 and would leave
    float64's range). The time steps t_{i+1} - t_i must lie in
    [1e-100, 1e100], where the cubics' coefficients per unit of time
    (~ step / h^3) and the accelerations (~ step / h^2) stay within
    float64's range (a ValueError names the step otherwise). Everything is
    computed in float64.
"""


def _times(times: ArrayLike, name: str) -> np.ndarray:
    t = _asarray(times, f"{name}(times)")
    if t.ndim != 1 or t.shape[0] < 2:
        raise ValueError(f"{name}(times): expected shape (N,) with N >= 2, got {t.shape}")
    t = np.ascontiguousarray(t, dtype=np.float64)
    if not np.all(np.isfinite(t)):
        raise ValueError(f"{name}(times): expected finite times, got {t!r}")
    steps = np.diff(t)
    if not np.all(steps > 0):
        i = int(np.argmax(~(steps > 0)))
        raise ValueError(
            f"{name}(times): expected strictly increasing times, got times[{i}] = {float(t[i])!r} "
            f"and times[{i + 1}] = {float(t[i + 1])!r}"
        )
    return t


def _keys(keys: ArrayLike, n: int, core: int, name: str, what: str) -> np.ndarray:
    k = _asarray(keys, f"{name}({what})")
    if k.shape != (n, core, core):
        raise ValueError(f"{name}({what}): expected shape ({n}, {core}, {core}) (one per time), got {k.shape}")
    k = np.ascontiguousarray(k, dtype=np.float64)
    if not np.all(np.isfinite(k)):
        raise ValueError(f"{name}({what}): expected finite numbers")
    return k


def _spline_from(cls: type, times: np.ndarray, keys: np.ndarray, ends: str) -> Any:
    """A spline of class cls fitted through times and keys (unpickling, copies)."""
    return cls(times, keys, ends=ends)


class _Spline(Value):
    _state = ("_t", "_keys", "_coefficients", "_ends")
    _name = ""
    _what = ""
    _matrix = 0

    _fit_function = ""
    _element_ufunc = ""
    _rates_ufunc = ""

    def _fit(self, times: ArrayLike, keys: ArrayLike, ends: str) -> None:
        name = self._name
        if "_coefficients" in self.__dict__:
            raise TypeError(
                f"{name}.__init__: the spline is already initialized (splines are immutable; make a new {name})"
            )
        if not isinstance(ends, str) or ends not in ENDS:
            raise ValueError(f"{name}(ends): expected 'natural' or 'chord', got {ends!r}")
        t = _times(times, name)
        k = _keys(keys, t.shape[0], self._matrix, name, self._what).copy()  # the spline's own
        coefficients = getattr(_core, self._fit_function)(t, k, ends == "natural")
        for a in (t, k, coefficients):
            a.flags.writeable = False
        self._t, self._keys, self._coefficients = t, k, coefficients
        self._ends = ends

    def __reduce__(self) -> tuple[Any, ...]:
        """Pickle support (every protocol) and copy: the constructor's arguments."""
        return (_spline_from, (type(self), self._t, self._keys, self._ends))

    def __setstate__(self, state: Any) -> None:
        """Unpickling a state written by chasles 0.1.0 (whose pickles held the
        object's dict; pickles now hold the constructor's arguments, __reduce__):
        the spline is fitted again from the pickled times, keys
        and ends, through the constructor's checks (a pickle is data from
        outside: times that are not finite or do not increase, keys that are
        not rotations, are refused); the fit gives the same numbers bit for
        bit."""
        name = self._name
        if not isinstance(state, dict) or not {"_t", "_keys", "_ends"} <= state.keys():
            raise ValueError(
                f"{name}.__setstate__: expected a dict of the times '_t', the keys '_keys' and "
                f"the ends '_ends', got {type(state).__name__}"
            )
        try:
            self._fit(state["_t"], state["_keys"], state["_ends"])
        except (TypeError, ValueError) as e:
            raise type(e)(f"{name}.__setstate__: {e}") from None

    def _evaluate(self, t: ArrayLike, order: int) -> Any:
        a = _asarray(t, f"{self._name}(t)")
        a = np.asarray(a, dtype=np.float64)
        if not np.all(np.isfinite(a)):
            raise ValueError(f"{self._name}(t): expected finite times, got {a!r}")
        operands = (self._t, self._keys, self._coefficients, a)
        if order == 0:
            return getattr(_core, self._element_ufunc)(*operands)
        return getattr(_core, self._rates_ufunc)(*operands)[order]

    @property
    def times(self) -> np.ndarray:
        """The key times t_0 < ... < t_{N-1}, shape (N,) (read-only)."""
        return self._t

    @property
    def ends(self) -> str:
        """The end conditions: ``"natural"`` or ``"chord"``."""
        return self._ends

    def __len__(self) -> int:
        return int(self._t.shape[0])

    def __call__(self, t: ArrayLike) -> np.ndarray:
        """The elements at the times t (a float or an array of any shape (...)): (..., n, n) matrices, float64."""
        return self._evaluate(t, 0)

    def body_velocity(self, t: ArrayLike) -> np.ndarray:
        """The body velocity (X^-1 dX/dt)^vee = Jr(r) r' at the times t, in the tangent's order, float64."""
        return self._evaluate(t, 1)

    def body_acceleration(self, t: ArrayLike) -> np.ndarray:
        """The derivative of the body velocity, Jr(r) r'' + (d/dt Jr(r)) r', at the times t, float64."""
        return self._evaluate(t, 2)

    def __repr__(self) -> str:
        if "_coefficients" not in self.__dict__:
            return f"<uninitialized {type(self).__name__}>"
        return (
            f"{self._name}(N={len(self)}, times=[{float(self._t[0])!r}, ..., {float(self._t[-1])!r}], "
            f"ends={self._ends!r})"
        )


class SO3Spline(_Spline):
    __doc__ = (
        """Interpolating C2 spline through key rotations (scipy's ``RotationSpline``).

    Args:
        times: (N,) strictly increasing finite key times, N >= 2, steps
            between 1e-100 and 1e100.
        rotations: (N, 3, 3) rotation matrices, or a sequence of N ``SO3``.
        ends: ``"natural"`` (zero angular acceleration at both ends, the
            default) or ``"chord"`` (scipy's end rates: the spline of
            scipy's ``RotationSpline`` where scipy's solver converges. For
            steps between keys drawn as rotation vectors N(0, s^2 I), the
            two agree to 3e-10 at s = 0.4 rad (rotations, and the rates and
            accelerations relative to 1 + their norm), 5e-9 at 0.6, 7e-7 at
            0.8, 5e-6 at 1.0 and 2e-4 at 1.5: farther apart, scipy's
            fixed-point iteration stops unconverged at its 10 iterations,
            where chasles solves to 1e-12).
"""
        + _MATH
        + """
    Calling the spline at t (a float or an array of any shape) gives the
    rotation matrices (..., 3, 3); ``body_velocity(t)`` the angular rate in
    the body frame, w = (R^T dR/dt)^vee, shape (..., 3);
    ``body_acceleration(t)`` its derivative dw/dt, shape (..., 3). (scipy's
    ``RotationSpline(t, 1)`` and ``(t, 2)`` are these same body-frame
    vectors.)

    Example:
        >>> times = [0.0, 1.0, 3.0]
        >>> keys = [SO3.exp([0.0, 0.0, 0.0]), SO3.exp([0.0, 0.0, 1.0]), SO3.exp([0.5, 0.0, 1.0])]
        >>> spline = SO3Spline(times, keys)
        >>> bool(np.allclose(spline(1.0), keys[1].as_matrix()))
        True
        >>> spline(np.linspace(0.0, 3.0, 7)).shape, spline.body_velocity([[0.5, 2.0]]).shape
        ((7, 3, 3), (1, 2, 3))
    """
    )
    _name = "SO3Spline"
    _what = "rotations"
    _matrix = 3
    _fit_function = "_so3_spline_fit"
    _element_ufunc = "_so3_spline"
    _rates_ufunc = "_so3_spline_rates"

    def __init__(self, times: ArrayLike, rotations: ArrayLike, *, ends: str = "natural") -> None:
        self._fit(times, rotations, ends)

    @property
    def rotations(self) -> np.ndarray:
        """The key rotations, shape (N, 3, 3) (a copy)."""
        return self._keys.copy()

    def __call__(self, t: ArrayLike) -> np.ndarray:
        """Rotation matrices at the times t.

        Args:
            t: a float or an array of times of any shape (...).

        Returns:
            (..., 3, 3) rotation matrices, float64.
        """
        return self._evaluate(t, 0)

    def body_velocity(self, t: ArrayLike) -> np.ndarray:
        """Body angular velocity w = (R^T dR/dt)^vee = Jr(r) r' at the times t.

        Args:
            t: a float or an array of times of any shape (...).

        Returns:
            (..., 3) angular rates in the body frame, float64.
        """
        return self._evaluate(t, 1)

    def body_acceleration(self, t: ArrayLike) -> np.ndarray:
        """Body angular acceleration dw/dt = Jr(r) r'' + (d/dt Jr(r)) r' at the times t.

        Args:
            t: a float or an array of times of any shape (...).

        Returns:
            (..., 3) angular accelerations in the body frame, float64.
        """
        return self._evaluate(t, 2)


class SE3Spline(_Spline):
    __doc__ = (
        """Interpolating C2 spline through key poses.

    Args:
        times: (N,) strictly increasing finite key times, N >= 2, steps
            between 1e-100 and 1e100.
        poses: (N, 4, 4) rigid motions [[R, p], [0, 0, 0, 1]], or a sequence
            of N ``SE3``.
        ends: ``"natural"`` (zero body acceleration at both ends, the
            default) or ``"chord"``.
"""
        + _MATH
        + """
    Calling the spline at t (a float or an array of any shape) gives the
    poses (..., 4, 4); ``body_velocity(t)`` the body twist
    V = (g^-1 dg/dt)^vee = (v, w), linear part first, shape (..., 6);
    ``body_acceleration(t)`` its derivative, shape (..., 6). The spline of
    poses with zero translation is the ``SO3Spline`` of their rotations.

    Example:
        >>> times = [0.0, 1.0, 2.0]
        >>> keys = [SE3.exp([0.0, 0.0, 0.0, 0.0, 0.0, 0.0]), SE3.exp([1.0, 0.0, 0.0, 0.0, 0.0, 0.5]),
        ...         SE3.exp([2.0, 0.0, 0.0, 0.0, 0.0, 1.0])]
        >>> spline = SE3Spline(times, keys)
        >>> np.round(spline.body_velocity(0.5), 12) + 0.0
        array([1. , 0. , 0. , 0. , 0. , 0.5])
    """
    )
    _name = "SE3Spline"
    _what = "poses"
    _matrix = 4
    _fit_function = "_se3_spline_fit"
    _element_ufunc = "_se3_spline"
    _rates_ufunc = "_se3_spline_rates"

    def __init__(self, times: ArrayLike, poses: ArrayLike, *, ends: str = "natural") -> None:
        self._fit(times, poses, ends)

    @property
    def poses(self) -> np.ndarray:
        """The key poses, shape (N, 4, 4) (a copy)."""
        return self._keys.copy()

    def __call__(self, t: ArrayLike) -> np.ndarray:
        """Poses at the times t.

        Args:
            t: a float or an array of times of any shape (...).

        Returns:
            (..., 4, 4) rigid motions, float64.
        """
        return self._evaluate(t, 0)

    def body_velocity(self, t: ArrayLike) -> np.ndarray:
        """Body twist V = (g^-1 dg/dt)^vee = (v, w) = Jr(r) r' at the times t.

        Args:
            t: a float or an array of times of any shape (...).

        Returns:
            (..., 6) body twists (v, w), linear part first, float64.
        """
        return self._evaluate(t, 1)

    def body_acceleration(self, t: ArrayLike) -> np.ndarray:
        """Derivative of the body twist, Jr(r) r'' + (d/dt Jr(r)) r', at the times t.

        Args:
            t: a float or an array of times of any shape (...).

        Returns:
            (..., 6) body accelerations (linear, angular), float64.
        """
        return self._evaluate(t, 2)


class _GroupSpline(_Spline):
    """The interpolating spline of a group of the table (_groups.py): one
    class per row, made by ``_make_spline``; the keys are given as
    ``keys``. SO2's rates are floats (shape (...)), as its tangent."""

    _dof = 0

    def __init__(self, times: ArrayLike, keys: ArrayLike, *, ends: str = "natural") -> None:
        self._fit(times, keys, ends)

    @property
    def keys(self) -> np.ndarray:
        """The keys, shape (N, n, n) (a copy)."""
        return self._keys.copy()

    def _evaluate(self, t: ArrayLike, order: int) -> Any:
        out = super()._evaluate(t, order)
        return out[..., 0] if order > 0 and self._dof == 1 else out


_SPLINE_DOC = """Interpolating C2 spline through key {kinds}.

    Args:
        times: (N,) strictly increasing finite key times, N >= 2, steps
            between 1e-100 and 1e100.
        keys: (N, {n}, {n}) {matrix}, or a sequence of N ``{cls}``.
        ends: ``"natural"`` (zero body acceleration at both ends, the
            default) or ``"chord"``.
{math}
    Calling the spline at t (a float or an array of any shape) gives the
    matrices (..., {n}, {n}); ``body_velocity(t)`` the body velocity
    (X^-1 dX/dt)^vee in the tangent {tangent}, shape {rate};
    ``body_acceleration(t)`` its derivative, of the same shape.

    Example:
        >>> import chasles
        >>> keys = chasles.{prefix}_exp(np.linspace(0.0, 0.3, 3 * {dof}).reshape(3, {dof}){squeeze})
        >>> spline = chasles.{cls}Spline([0.0, 1.0, 2.0], keys)
        >>> bool(np.allclose(spline(1.0), keys[1]))
        True
    """


def _make_spline(group: _groups.Group) -> type:
    """The spline class of one group of the table, over the private
    ``_<prefix>_spline_fit``, ``_<prefix>_spline`` and ``_<prefix>_spline_rates``."""
    name = f"{group.cls}Spline"
    doc = _SPLINE_DOC.format(
        **group._asdict(),
        math=_MATH,
        rate="(...)" if group.dof == 1 else f"(..., {group.dof})",
        squeeze="[:, 0]" if group.dof == 1 else "",
    )
    attributes = {
        "__doc__": doc,
        "__module__": __name__,
        "__qualname__": name,
        "_name": name,
        "_what": "keys",
        "_matrix": group.n,
        "_dof": group.dof,
        "_fit_function": f"_{group.prefix}_spline_fit",
        "_element_ufunc": f"_{group.prefix}_spline",
        "_rates_ufunc": f"_{group.prefix}_spline_rates",
    }
    # the members of the API in the class's own dict, as SO3Spline's (api_spec lists them by class)
    for member in ("__init__", "keys", "__call__", "body_velocity", "body_acceleration"):
        attributes[member] = getattr(_GroupSpline, member)  # its own or _Spline's
    return type(name, (_GroupSpline,), attributes)


SO2Spline = _make_spline(_groups.SO2)
SE2Spline = _make_spline(_groups.SE2)
Sim3Spline = _make_spline(_groups.SIM3)
SE23Spline = _make_spline(_groups.SE23)
