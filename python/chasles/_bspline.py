"""The uniform cumulative cubic B-splines on SO(3) and SE(3), and on SO(2),
SE(2), Sim(3) and SE_2(3) (classes made by ``_make_bspline``).

The checks of the control elements and the evaluation are C++
(include/chasles/bspline.hpp, through bindings/bind_splines.cpp): these
classes hold the start time, the spacing and the checked control elements (a
read-only (N, k, k) float64 array made by the private ``_so3_bspline_new`` /
``_se3_bspline_new``, which raise the constructor's errors), check the times
of an evaluation to lie in [start_time, end_time] and evaluate them with the
private gufuncs ``_so3_bspline`` / ``_so3_bspline_rates`` (``_se3_...``): one
loop without the GIL, each evaluation O(1) whatever N. They are values:
immutable (``__init__`` runs once), pickled by ``__reduce__`` as the
constructor's arguments (every protocol; unpickling runs the constructor's
checks), copied the same way.
"""

from __future__ import annotations

import math
from typing import Any, NamedTuple, NoReturn, Optional

import numpy as np
from numpy.typing import ArrayLike

from chasles import _core
from chasles._least_squares import check_iterations, import_scipy, information_factor, levenberg_marquardt
from chasles._least_squares import splu as _splu
from chasles._random import _asarray
from chasles._value import Value

# What the docstrings say of each group: the matrix size, the tangent size,
# the matrices, the body velocity and one element (SO2's rates are floats).
_GROUPS = {
    "SO3": (3, 3, "rotation matrices", "the angular velocity w in the body frame", "a rotation"),
    "SE3": (4, 6, "rigid motions [[R, p], [0, 0, 0, 1]]", "the body twist (v, w), linear part first", "a rigid motion"),
    "SO2": (2, 1, "rotation matrices", "the angular rate", "a rotation"),
    "SE2": (
        3,
        3,
        "rigid motions [[R, t], [0, 0, 1]]",
        "the body twist (vx, vy, w), linear part first",
        "a rigid motion",
    ),
    "Sim3": (4, 7, "similarities [[s R, t], [0, 0, 0, 1]]", "the body velocity (v, w, sigma)", "a similarity"),
    "SE23": (
        5,
        9,
        "extended poses [[R, p, v], [0, 1, 0], [0, 0, 1]]",
        "the body velocity (rho, nu, w)",
        "an extended pose",
    ),
}


def _rate_shape(group: str) -> str:
    dof = _GROUPS[group][1]
    return "t.shape" if dof == 1 else f"t.shape + ({dof},)"


def _class_doc(group: str, name: str) -> str:
    if group not in ("SO3", "SE3"):
        return _generic_class_doc(group, name)
    so3 = group == "SO3"
    m, k = ("3, 3", "3") if so3 else ("4, 4", "6")
    rates = (
        "they are angular velocities w (rad per unit of time)."
        if so3
        else "twists (v, w), linear part first (Murray, Li and Sastry)."
    )
    example_w = "" if so3 else " + [0.0] * 3"
    velocity = "0. , 0. , 0.2" if so3 else "0. , 0. , 0.2, 0. , 0. , 0. "
    return f"""The uniform cumulative cubic B-spline on {"SO(3)" if so3 else "SE(3)"} (Kim, Kim and Shin 1995;
Lovegrove, Patron-Perez and Sibley 2013), the curve of continuous-time
estimation, with analytic body velocity and acceleration (Sommer et al.
2020, "Efficient derivative computation for cumulative B-splines on Lie
groups").

Control elements X_0 .. X_{{N-1}} (N >= 4), start time t0 and knot spacing dt.
At t = t0 + (i + u) dt, u in [0, 1], segment i uses X_i .. X_{{i+3}}:

    X(t) = X_i exp(B1(u) d_1) exp(B2(u) d_2) exp(B3(u) d_3),
    d_j = log(X_{{i+j-1}}^-1 X_{{i+j}}),
    B1 = (5 + 3u - 3u^2 + u^3)/6, B2 = (1 + 3u + 3u^2 - 2u^3)/6, B3 = u^3/6.

The curve is C2 and smooths rather than interpolates: it does not pass
through the control elements. It is defined on [start_time, end_time],
end_time = t0 + (N - 3) dt; other times are a ValueError (NaN gives NaN).
Body velocity (X^-1 X')^vee and body acceleration, its time derivative,
come from the recursion over the three factors, not from differences;
{rates}

Evaluation takes a time or an array of times of any shape and runs one
C++ loop over them with the GIL released, O(1) per time whatever N.
Values are float64. A spline is an immutable value: it pickles (every
protocol) and copies as its constructor's arguments, and unpickling runs
the constructor's checks.

Example:
    >>> control = [{group}.exp([0.0, 0.0, 0.1 * k]{example_w}) for k in range(6)]
    >>> spline = {name}(0.0, 0.5, control)
    >>> spline.end_time
    1.5
    >>> spline([0.0, 0.7]).shape
    (2, {m})
    >>> np.round(spline.body_velocity(0.7), 12) + 0.0
    array([{velocity}])
"""


def _generic_class_doc(group: str, name: str) -> str:
    """The class docstring of the B-spline on a group other than SO3 and SE3:
    SO3's text, with the group's rates and an example of its own."""
    n, dof, _, velocity, _ = _GROUPS[group]
    text = _class_doc("SO3", "SO3BSpline")
    text = text.replace("on SO(3)", f"on {group}", 1)
    text = text.replace(
        "they are angular velocities w (rad per unit of time).",
        f"they are {velocity}, in the order of {group}'s tangent" + (" (floats)." if dof == 1 else "."),
    )
    head = text[: text.index("Example:")]
    squeeze = "[:, 0]" if dof == 1 else ""
    return (
        head
        + f"""Example:
    >>> import chasles
    >>> control = chasles.{group.lower()}_exp(np.outer(0.1 * np.arange(6), np.ones({dof})){squeeze})
    >>> spline = chasles.{name}(0.0, 0.5, control)
    >>> spline.end_time
    1.5
    >>> spline([0.0, 0.7]).shape
    (2, {n}, {n})
"""
    )


def _init_doc(group: str) -> str:
    k, _, matrices, _, _ = _GROUPS[group]
    return f"""A spline from its start time, knot spacing and control elements.

Args:
    start_time: t0, finite.
    spacing: dt > 0, finite, the time between knots.
    control: N >= 4 control elements: a sequence of {group}, or an array-like of
        shape (N, {k}, {k}) of {matrices} (checked as
        {group}.from_matrix does; a float32 array with float32's tolerance,
        3.5e-4, then projected to the nearest rotation). The spline keeps
        its own float64 copy.

Raises:
    ValueError: fewer than 4 control elements, a wrong shape, a matrix
        that is not {_GROUPS[group][4]}, a start time that is not finite or a spacing that
        is not finite and > 0.
    TypeError: a sequence holding something other than {group}; __init__
        called again on a spline (splines are immutable).
"""


_TIMES = "t: a time or an array_like of times of any shape, in [start_time, end_time]."
_RAISES = """Raises:
    ValueError: a time outside [start_time, end_time].
    TypeError: times that are not real numbers."""


class _BSpline(Value):
    """What SO3BSpline and SE3BSpline share: the state, immutability, pickling
    and copying (the members the API lists are defined by each class)."""

    _state = ("_start_time", "_spacing", "_control")
    _name = ""
    _new = ""  # the private C++ constructor (in chasles._core)
    __array_ufunc__ = None  # numpy defers to the spline (no ufunc on a spline)

    _start_time: float
    _spacing: float
    _control: np.ndarray

    def _init(self, start_time: Any, spacing: Any, control: Any) -> None:
        if "_control" in self.__dict__:
            raise TypeError(
                f"{self._name}.__init__: the spline is already initialized (splines are immutable; "
                f"make a new {self._name})"
            )
        if isinstance(control, (list, tuple)) and control and isinstance(control[0], _BSpline):
            group = self._name[: -len("BSpline")]
            raise TypeError(
                f"{self._name}(control): element 0 is a {type(control[0]).__name__}, expected an {group} "
                f"(a sequence of them, or an array of matrices)"
            )
        start, step, array = getattr(_core, self._new)(start_time, spacing, control)
        self._start_time, self._spacing, self._control = start, step, array

    def __reduce__(self) -> tuple[Any, ...]:
        """Pickle support (every protocol) and copy: the constructor's arguments."""
        return (type(self), (self._start_time, self._spacing, self._control))


_CLASSES: dict[str, type] = {}  # "SO3" / "SE3": the class, once defined


def _self(self: Any, group: str, member: str) -> Any:
    """self, when it is a B-spline of `group` (TypeError otherwise, as a method of a bound class)."""
    cls = _CLASSES[group]
    if not isinstance(self, cls):
        raise TypeError(f"{cls.__name__}.{member}: expected a {cls.__name__} as self, got {type(self).__name__}")
    return self


def _type_name(x: Any) -> str:
    """The name of x's type as the extension's messages give it ("list", "numpy.ndarray")."""
    t = type(x)
    if t.__module__ == "builtins" or (t.__flags__ & (1 << 9) and type(t).__name__ != "pybind11_type"):
        return t.__name__  # a builtin, or a class defined in Python
    return f"{t.__module__}.{t.__qualname__}"


def _reraise(e: Exception, text: str) -> NoReturn:
    """The failure e of numpy's conversion or ufunc as the extension re-raises
    it: a TypeError (or a ValueError for any other Exception) whose text is
    `text` and e's, chained; MemoryError as it is."""
    if isinstance(e, MemoryError):
        raise e
    raise (TypeError if isinstance(e, TypeError) else ValueError)(f"{text}: {e}") from e


def _times(t: Any, what: str, start: float, end: float) -> Any:
    """The times t of an evaluation as a float64 operand, checked to lie in
    [start, end] (NaN passes: NaN results); an array of another library that
    implements __array_ufunc__ (dask) as it is (numpy dispatches to it; its
    times are clamped, unchecked)."""
    if type(t) is float:  # the common scalar call, without an array
        if t < start or t > end:
            raise ValueError(f"{what}: expected times in [start_time, end_time] = [{start!r}, {end!r}], got {t!r}")
        return t
    if not isinstance(t, np.ndarray) and getattr(t, "__array_ufunc__", None) is not None:
        return t
    if t is None or isinstance(t, (str, bytes)):
        raise TypeError(f"{what}: expected real numbers (float64), got {'None' if t is None else _type_name(t)}")
    try:
        a = np.asarray(t)
    except Exception as e:
        _reraise(
            e,
            f"{what}: expected an array-like of real numbers (float64), could not convert {_type_name(t)} to an array",
        )
    if a.dtype.kind not in "biuf":
        raise TypeError(f"{what}: expected real numbers (float64), got dtype {a.dtype} ({_type_name(t)})")
    a = a.astype(np.float64, copy=False)
    out = (a < start) | (a > end)
    if out.any():
        raise ValueError(
            f"{what}: expected times in [start_time, end_time] = [{start!r}, {end!r}], got {float(a[out][0])!r}"
        )
    return a


def _evaluation(group: str, order: int, name: str, doc: str) -> Any:
    """The method `name` of a B-spline class: the element (order 0) or a rate (1, 2)."""
    ufunc = getattr(_core, f"_{group.lower()}_bspline" + ("_rates" if order else ""))
    what = f"{group}BSpline(t)" if order == 0 else f"{group}BSpline.{name}(t)"

    def method(self: _BSpline, t: ArrayLike) -> np.ndarray:
        s = _self(self, group, name)
        start, step, control = s._start_time, s._spacing, s._control
        times = _times(t, what, start, start + float(control.shape[0] - 3) * step)
        try:
            r = ufunc(start, step, control, times)
        except Exception as e:
            _reraise(e, what)
        if not order:
            return r
        return r[order][..., 0] if _GROUPS[group][1] == 1 else r[order]

    method.__name__ = name
    method.__qualname__ = name
    method.__doc__ = doc
    return method


def _methods(group: str) -> tuple[Any, Any, Any]:
    """__call__, body_velocity and body_acceleration of the B-spline on `group`."""
    n, _, matrices, velocity, _ = _GROUPS[group]
    core, k = f"{n}, {n}", _rate_shape(group)
    what = {"SO3": "the rotation matrices", "SE3": "the homogeneous matrices"}.get(group, f"the {matrices}")
    return (
        _evaluation(
            group,
            0,
            "__call__",
            f"""The elements X(t).

Args:
    {_TIMES}

Returns:
    numpy.ndarray: shape t.shape + ({core}), {what}.

{_RAISES}
""",
        ),
        _evaluation(
            group,
            1,
            "body_velocity",
            f"""The body velocity (X^-1 X')^vee at the times t, per unit of time.

omega_j = Ad_{{A_j^-1}} omega_{{j-1}} + B_j' d_j over the factors A_j = exp(B_j d_j).

Args:
    {_TIMES}

Returns:
    numpy.ndarray: shape {k}, {velocity}.

{_RAISES}
""",
        ),
        _evaluation(
            group,
            2,
            "body_acceleration",
            f"""The body acceleration, the time derivative of body_velocity, at the times t.

omega_j' = Ad_{{A_j^-1}} omega_{{j-1}}' + B_j'' d_j + [omega_j, B_j' d_j].

Args:
    {_TIMES}

Returns:
    numpy.ndarray: shape {k}, per unit of time squared.

{_RAISES}
""",
        ),
    )


def _properties(group: str) -> tuple[property, property, property, property, Any]:
    """start_time, spacing, end_time, control and __repr__ of the B-spline on `group`."""
    k = _GROUPS[group][0]

    def start_time(self: _BSpline) -> float:
        """float: t0, the start of the first segment."""
        return _self(self, group, "start_time")._start_time

    def spacing(self: _BSpline) -> float:
        """float: dt, the time between knots."""
        return _self(self, group, "spacing")._spacing

    def end_time(self: _BSpline) -> float:
        """float: t0 + (N - 3) dt, the last valid time."""
        s = _self(self, group, "end_time")
        return s._start_time + float(s._control.shape[0] - 3) * s._spacing

    def control(self: _BSpline) -> np.ndarray:
        return _self(self, group, "control")._control.copy()

    control.__doc__ = f"numpy.ndarray: shape (N, {k}, {k}), the control elements (a copy)."

    def __repr__(self: _BSpline) -> str:
        s = _self(self, group, "__repr__")
        if "_control" not in s.__dict__:
            return f"<uninitialized {type(s).__name__}>"
        return f"{type(s)._name}(start_time={s._start_time!r}, spacing={s._spacing!r}, n_control={s._control.shape[0]})"

    return property(start_time), property(spacing), property(end_time), property(control), __repr__


class BSplineFit(NamedTuple):
    """What ``<Group>BSpline.fit`` returns."""

    spline: Any
    """The fitted B-spline (of the class ``fit`` was called on)."""
    residuals: np.ndarray
    """(K, DoF): rminus(X(t_k), Z_k) = log(Z_k^-1 X(t_k)) of every pose at the fit."""
    initial_chi2: float
    """sum_k r_k^T Omega_k r_k at the start (control elements taken from the poses)."""
    final_chi2: float
    """The same at the fit."""
    iterations: int
    converged: bool


def _fit(group: str) -> Any:
    """The classmethod ``fit`` of the B-spline on `group`."""
    n, dof = _GROUPS[group][:2]
    name, lower = f"{group}BSpline", group.lower()
    where = f"{name}.fit"

    def fit(
        cls: type,
        times: ArrayLike,
        poses: ArrayLike,
        spacing: float,
        *,
        start_time: Optional[float] = None,
        information: Optional[ArrayLike] = None,
        max_iterations: int = 100,
        tolerance: float = 1e-12,
    ) -> BSplineFit:
        max_iterations, tolerance = check_iterations(max_iterations, tolerance, where)
        import_scipy(where)
        import scipy.sparse as sparse

        t = _real_array(times, f"{where}(times)")
        if t.ndim != 1 or t.shape[0] < 4:
            raise ValueError(f"{where}(times): expected shape (K,) with K >= 4, got {t.shape}")
        k = t.shape[0]
        Z = _real_array(poses, f"{where}(poses)")
        if Z.shape != (k, n, n):
            raise ValueError(f"{where}(poses): expected shape ({k}, {n}, {n}) (one pose per time), got {Z.shape}")
        try:  # the constructor's check of the control elements, for the poses
            Z = getattr(_core, f"_{lower}_bspline_new")(0.0, 1.0, Z)[2]
        except (TypeError, ValueError) as e:
            raise type(e)(str(e).replace(f"{name}(control)", f"{where}(poses)")) from None
        t0 = float(t.min()) if start_time is None else _finite_real(start_time, f"{where}(start_time)")
        dt = _finite_real(spacing, f"{where}(spacing)")
        if not dt > 0:
            raise ValueError(f"{where}(spacing): expected a positive spacing (> 0), got {dt!r}")
        if t.min() < t0:
            raise ValueError(f"{where}(times): expected times >= start_time = {t0!r}, got {float(t.min())!r}")
        # the fewest control elements whose end_time = t0 + (count - 3) dt reaches the last time
        # (a time within 1e-9 spacings past a knot counts as on it), at most one per pose
        span = (float(t.max()) - t0) / dt
        if not span + 3 <= k:
            raise ValueError(
                f"{where}: a spacing of {dt!r} over [{t0!r}, {float(t.max())!r}] needs {span + 3:.6g} control "
                f"elements, more than the {k} poses determine: use a larger spacing"
            )
        count = max(4, math.ceil(span - 1e-9) + 3)
        Lt = _information_factor(information, k, dof, where)
        # Control element j sits near t0 + (j - 1) dt (X(t0 + i dt) is X_{i+1} to first order): the
        # start takes the pose nearest that time. Every control element needs a pose in its support.
        segment = np.minimum(np.floor((t - t0) / dt), count - 4).astype(np.int64)
        touched = np.zeros(count, bool)
        for m in range(4):
            touched[segment + m] = True
        if not touched.all():
            j = int(np.argmin(touched))
            raise ValueError(
                f"{where}: no pose in the support of control element {j} (times "
                f"[{t0 + (j - 3) * dt!r}, {t0 + (j + 1) * dt!r}]): use a larger spacing"
            )
        order = np.argsort(t, kind="stable")
        ts = t[order]
        knots = t0 + (np.arange(count) - 1.0) * dt
        nearest = np.clip(np.searchsorted(ts, knots), 1, k - 1)
        nearest -= (knots - ts[nearest - 1]) < (ts[nearest] - knots)
        control = Z[order[nearest]]

        undetermined = (
            f"{where}: the poses do not determine every control element (too few poses in some segments): "
            "use a larger spacing"
        )
        jacobians = getattr(_core, f"_{lower}_bspline_jacobians")
        rminus_jacobians, log = getattr(_core, f"{lower}_rminus_jacobians"), getattr(_core, f"{lower}_log")
        compose, exp = getattr(_core, f"{lower}_compose"), getattr(_core, f"{lower}_exp")
        inverse_Z = getattr(_core, f"{lower}_inverse")(Z)
        rows = np.broadcast_to(np.arange(k * dof).reshape(k, 1, dof, 1), (k, 4, dof, dof))
        cols = (segment[:, None, None, None] + np.arange(4)[None, :, None, None]) * dof + np.arange(dof)
        cols = np.broadcast_to(cols, (k, 4, dof, dof))

        def residuals(X: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
            value, J, _ = jacobians(t0, dt, X, t)
            return value, J, log(compose(inverse_Z, value)).reshape(k, dof)

        def cost(X: np.ndarray) -> float:
            r = residuals(X)[2]
            return float(np.sum((Lt @ r[..., None]) ** 2))

        def linearize(X: np.ndarray) -> tuple[np.ndarray, Any]:
            value, J, r = residuals(X)
            dlog = rminus_jacobians(value, Z)[0].reshape(k, 1, dof, dof)  # J_r(r)^-1
            blocks = Lt[:, None] @ dlog @ J.reshape(k, 4, dof, dof)
            matrix = sparse.coo_matrix((blocks.ravel(), (rows.ravel(), cols.ravel())), shape=(k * dof, count * dof))
            return (Lt @ r[..., None]).ravel(), matrix.tocsr()

        def step(X: np.ndarray, dx: np.ndarray) -> np.ndarray:
            delta = dx.reshape(count, dof)
            return compose(X, exp(delta[:, 0] if dof == 1 else delta))

        X, initial, final, iterations, converged = levenberg_marquardt(
            control,
            cost,
            linearize,
            step,
            max_iterations=max_iterations,
            tolerance=tolerance,
            singular=undetermined,
        )
        # Determined: J^T J at the fit regular (a pivot of its factorization
        # not below 1e-12 of the largest; the damping made every step regular).
        _, J = linearize(X)
        pivots = np.abs(_splu((J.T @ J).tocsc(), undetermined).U.diagonal())
        if not pivots.min() > 1e-12 * pivots.max():
            raise ValueError(undetermined)
        spline = cls(t0, dt, X)
        return BSplineFit(spline, residuals(spline.control)[2], initial, final, iterations, converged)

    fit.__name__ = "fit"
    fit.__qualname__ = f"{name}.fit"
    fit.__doc__ = f"""The B-spline of spacing ``spacing`` nearest to timestamped poses, by least squares.

Minimizes chi2 = sum_k r_k^T Omega_k r_k over the control elements, with
r_k = rminus(X(t_k), Z_k) = log(Z_k^-1 X(t_k)) ({dof} numbers each, in the
order of the group's tangent): Levenberg-Marquardt with the analytic
Jacobians of X(t) with respect to the four control elements of its segment
(right perturbations), one sparse system per iteration (scipy). The spline
starts at ``start_time`` (default: the first time) and has the fewest
control elements whose end_time reaches the last time; they start at the
poses nearest their knots.

Args:
    times: array_like (K,), K >= 4, the poses' times (any order), >= start_time.
    poses: array_like (K, {n}, {n}), the measured elements Z_k.
    spacing: the knot spacing (> 0).
    start_time: the spline's start (default: min(times)).
    information: None (the identity), ({dof}, {dof}) for every pose or
        (K, {dof}, {dof}): Omega_k, symmetric positive definite (the inverse
        of a pose's covariance in the right perturbation Z_k exp(e)).
    max_iterations: at most this many iterations (default 100).
    tolerance: stop when a step lowers chi2 by less than this, relative.

Returns:
    BSplineFit: (spline, residuals (K, {dof}), initial_chi2, final_chi2,
    iterations, converged).

Raises:
    ValueError: wrong shapes, numbers that are not finite, a pose that is
        not an element of the group, a spacing <= 0, times before
        start_time, more control elements than poses, a control element
        with no pose in its support or poses that do not determine the
        control elements, an information matrix that is not symmetric
        positive definite.
    TypeError: arguments of the wrong type.
"""
    return classmethod(fit)


def _real_array(a: Any, what: str) -> np.ndarray:
    """A float64 array of finite real numbers (TypeError / ValueError naming `what`)."""
    m = _asarray(a, what).astype(np.float64)
    if not np.all(np.isfinite(m)):
        raise ValueError(f"{what}: expected finite numbers")
    return m


def _finite_real(x: Any, what: str) -> float:
    if isinstance(x, (bool, np.bool_)) or not isinstance(x, (int, float, np.integer, np.floating)):
        raise TypeError(f"{what}: expected a real number, got {_type_name(x)}")
    try:
        value = float(x)
    except OverflowError:  # an int beyond float's range
        value = math.inf
    if not math.isfinite(value):
        raise ValueError(f"{what}: expected a finite number, got {x!r}")
    return value


def _information_factor(information: Any, k: int, dof: int, where: str) -> np.ndarray:
    """(K, dof, dof) L^T with L L^T = Omega_k (the identity for None)."""
    if information is None:
        return np.broadcast_to(np.eye(dof), (k, dof, dof))
    omega = _real_array(information, f"{where}(information)")
    if omega.shape not in ((dof, dof), (k, dof, dof)):
        raise ValueError(
            f"{where}(information): expected shape ({dof}, {dof}) or ({k}, {dof}, {dof}), got {omega.shape}"
        )
    L = information_factor(omega, f"{where}(information)")
    return np.broadcast_to(np.swapaxes(L, -1, -2), (k, dof, dof))


class SO3BSpline(_BSpline):
    __doc__ = _class_doc("SO3", "SO3BSpline")
    _name = "SO3BSpline"
    _new = "_so3_bspline_new"

    def __init__(self, start_time: float, spacing: float, control: ArrayLike) -> None:
        self._init(start_time, spacing, control)

    __init__.__doc__ = _init_doc("SO3")
    __call__, body_velocity, body_acceleration = _methods("SO3")
    start_time, spacing, end_time, control, __repr__ = _properties("SO3")
    fit = _fit("SO3")


class SE3BSpline(_BSpline):
    __doc__ = _class_doc("SE3", "SE3BSpline")
    _name = "SE3BSpline"
    _new = "_se3_bspline_new"

    def __init__(self, start_time: float, spacing: float, control: ArrayLike) -> None:
        self._init(start_time, spacing, control)

    __init__.__doc__ = _init_doc("SE3")
    __call__, body_velocity, body_acceleration = _methods("SE3")
    start_time, spacing, end_time, control, __repr__ = _properties("SE3")
    fit = _fit("SE3")


def _make_bspline(group: str) -> type:
    """The B-spline class of `group` (SO2, SE2, Sim3, SE23), with SO3BSpline's members."""
    name = f"{group}BSpline"

    def __init__(self: _BSpline, start_time: float, spacing: float, control: ArrayLike) -> None:
        self._init(start_time, spacing, control)

    __init__.__doc__ = _init_doc(group)
    __init__.__qualname__ = f"{name}.__init__"
    members: dict[str, Any] = {"__doc__": _class_doc(group, name), "__module__": __name__, "__qualname__": name}
    members.update(_name=name, _new=f"_{group.lower()}_bspline_new", __init__=__init__)
    members.update(zip(("__call__", "body_velocity", "body_acceleration"), _methods(group)))
    members.update(zip(("start_time", "spacing", "end_time", "control", "__repr__"), _properties(group)))
    members["fit"] = _fit(group)
    return type(name, (_BSpline,), members)


SO2BSpline = _make_bspline("SO2")
SE2BSpline = _make_bspline("SE2")
Sim3BSpline = _make_bspline("Sim3")
SE23BSpline = _make_bspline("SE23")

_CLASSES.update(SO3=SO3BSpline, SE3=SE3BSpline, SO2=SO2BSpline, SE2=SE2BSpline, Sim3=Sim3BSpline, SE23=SE23BSpline)
