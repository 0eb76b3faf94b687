"""Point-to-point motions: the time scalings of a rest-to-rest motion (cubic,
quintic, trapezoidal) and the straight-line joint trajectory they time
(Lynch and Park, "Modern Robotics", ch. 9.2).

The mathematics is C++ (include/chasles/time_scaling.hpp): these functions
check the arguments, make them float64 and call the private gufuncs
``_time_scaling`` and ``_joint_trajectory`` (bindings/bind_trajectory.cpp),
which broadcast the times, durations, ratios and joint vectors as numpy does
and run without the GIL.
"""

from __future__ import annotations

from typing import Any, Optional

import numpy as np
from numpy.typing import ArrayLike

from chasles import _core
from chasles._random import _asarray
from chasles._results import JointTrajectoryResult, TimeScalingResult

# The kinds, in the order of chasles::TimeScalingKind: the index is the gufuncs' `kind` operand.
KINDS = ("cubic", "quintic", "trapezoidal")
_TRAPEZOIDAL = KINDS.index("trapezoidal")
# The most joints of a joint vector: a Chain's (bindings/bind_trajectory.cpp).
MAX_JOINTS = 32


def _kind(kind: Any, name: str) -> np.intc:
    """The index of `kind` in KINDS, or the error naming `name`."""
    if not isinstance(kind, str):
        raise TypeError(f"{name}(kind): expected a str, 'cubic', 'quintic' or 'trapezoidal', got {type(kind).__name__}")
    if kind not in KINDS:
        raise ValueError(f"{name}(kind): expected 'cubic', 'quintic' or 'trapezoidal', got {kind!r}")
    return np.intc(KINDS.index(str(kind)))  # typed: numpy casts a Python int to int64


def _reals(x: Any, what: str) -> np.ndarray:
    """x as a float64 array of its own shape (0-d kept); its failures name `what`."""
    return np.asarray(_asarray(x, what), dtype=np.float64, order="C")


def _first(a: np.ndarray, bad: np.ndarray, what: str) -> str:
    """'what[i, j] = x' for the first True of `bad` (the number alone for a 0-d array)."""
    if a.ndim == 0:
        return repr(float(a))
    i = np.unravel_index(int(np.argmax(bad)), bad.shape)
    return f"{what}[{', '.join(str(int(k)) for k in i)}] = {float(a[i])!r}"


def _scaling_operands(
    name: str, t: ArrayLike, duration: ArrayLike, code: np.intc, peak_velocity_ratio: Optional[ArrayLike]
) -> tuple:
    """The checked times, durations and ratios (NaN, not read, but for the trapezoid)."""
    times = _reals(t, f"{name}(t)")
    nan = np.isnan(times)
    if nan.any():
        raise ValueError(
            f"{name}(t): expected times that are not NaN (before 0 and after the duration the motion is at "
            f"rest), got {_first(times, nan, 't')}"
        )
    T = _reals(duration, f"{name}(duration)")
    bad = ~(np.isfinite(T) & (T > 0))
    if bad.any():
        raise ValueError(
            f"{name}(duration): expected durations that are finite and > 0, got {_first(T, bad, 'duration')}"
        )
    if code != _TRAPEZOIDAL:
        return times, T, np.float64(np.nan)
    if peak_velocity_ratio is None:
        raise ValueError(
            f"{name}(peak_velocity_ratio): required for kind='trapezoidal': the peak velocity over the "
            "average velocity, in (1, 2]"
        )
    k = _reals(peak_velocity_ratio, f"{name}(peak_velocity_ratio)")
    bad = ~((k > 1) & (k <= 2))
    if bad.any():
        raise ValueError(
            f"{name}(peak_velocity_ratio): expected ratios of the peak velocity to the average velocity in "
            f"(1, 2] (2: the triangle profile), got {_first(k, bad, 'peak_velocity_ratio')}"
        )
    return times, T, k


def _check_broadcast(name: str, arrays: dict) -> None:
    """A ValueError naming the arguments whose shapes (a joint vector's,
    q_start's and q_end's, without its last axis) do not broadcast together."""
    joints = [k for k in arrays if k.startswith("q_")]
    try:
        np.broadcast_shapes(*(a.shape[:-1] if k in joints else a.shape for k, a in arrays.items()))
    except ValueError:
        given = ", ".join(f"{k} {a.shape}" for k, a in arrays.items())
        leading = " (the joint vectors' leading axes: all but the last)" if joints else ""
        raise ValueError(
            f"{name}({', '.join(arrays)}): expected shapes that broadcast together{leading}, got {given}"
        ) from None


def time_scaling(
    t: ArrayLike, duration: ArrayLike, kind: str = "quintic", peak_velocity_ratio: Optional[ArrayLike] = None
) -> TimeScalingResult:
    """The time scaling s(t) of a rest-to-rest motion: cubic, quintic or trapezoidal.

    A motion of duration T from s = 0 to s = 1 (Lynch and Park, "Modern
    Robotics", ch. 9.2.2): s = f(r) with r = t / T, so s_dot = f'(r) / T and
    s_ddot = f''(r) / T^2.

    - ``"cubic"``: s = 3 r^2 - 2 r^3, zero velocity at both ends (Modern
      Robotics' ``CubicTimeScaling(Tf, t)`` is ``time_scaling(t, Tf,
      "cubic").s``);
    - ``"quintic"`` (the default): s = 10 r^3 - 15 r^4 + 6 r^5, zero velocity
      and acceleration at both ends (``QuinticTimeScaling``);
    - ``"trapezoidal"``: constant acceleration a, a cruise at the peak
      velocity v, constant deceleration -a. The peak velocity is given as
      k = v T, its ratio to the average velocity 1 / T
      (``peak_velocity_ratio``), in (1, 2]; then a = v^2 / (v T - 1) (Modern
      Robotics' formula), a T^2 = k^2 / (k - 1), for T (k - 1) / k at each
      end. k = 2 is the triangle profile (no cruise); k -> 1 the rectangle.
      At the two switching instants s_ddot is 0 (the cruise's).

    Before t = 0 the motion is at rest at s = 0, after t = T at s = 1, both
    derivatives 0. t, duration and peak_velocity_ratio broadcast together,
    as numpy's; the C++ kernel runs without the GIL.

    Args:
        t: array_like of real numbers, any shape: the times; any number but
            NaN (infinities included: at rest).
        duration: array_like of real numbers, finite and > 0: the durations T.
        kind: ``"cubic"``, ``"quintic"`` or ``"trapezoidal"``.
        peak_velocity_ratio: array_like of real numbers in (1, 2]: k = v T.
            Required for ``"trapezoidal"``; the other kinds do not read it.

    Returns:
        TimeScalingResult: the named tuple ``(s, s_dot, s_ddot)``, float64,
        each of the broadcast shape of the arguments (numpy float64 scalars
        when they are all scalars).

    Raises:
        TypeError: kind is not a str, or t, duration or peak_velocity_ratio
            are not real numbers.
        ValueError: an unknown kind; a NaN time; a duration that is not
            finite and > 0; a ratio outside (1, 2], or none for
            ``"trapezoidal"``; shapes that do not broadcast together.

    Example:
        >>> s, s_dot, s_ddot = chasles.time_scaling([0.0, 0.5, 1.0, 2.0, 3.0], 2.0, "cubic")
        >>> s
        array([0.     , 0.15625, 0.5    , 1.     , 1.     ])
        >>> s_dot  # 3/2 of the average velocity 1/2 at mid-motion, at rest at both ends
        array([0.    , 0.5625, 0.75  , 0.    , 0.    ])
        >>> float(chasles.time_scaling(1.0, 2.0, "trapezoidal", 1.5).s_dot)  # the cruise: 1.5 / 2
        0.75
    """
    name = "time_scaling"
    code = _kind(kind, name)
    times, T, k = _scaling_operands(name, t, duration, code, peak_velocity_ratio)
    arrays = {"t": times, "duration": T}
    if code == _TRAPEZOIDAL:
        arrays["peak_velocity_ratio"] = k
    _check_broadcast(name, arrays)
    return TimeScalingResult(*_core._time_scaling(code, T, k, times))


def _joints(q: ArrayLike, name: str, argument: str) -> np.ndarray:
    """A joint vector or a batch of them, (n,) or (..., n), n <= MAX_JOINTS, finite, float64."""
    what = f"{name}({argument})"
    a = _reals(q, what)
    if a.ndim < 1:
        raise ValueError(f"{what}: expected shape (n,) or (..., n), got {a.shape}")
    if a.shape[-1] > MAX_JOINTS:
        raise ValueError(f"{what}: expected at most {MAX_JOINTS} joints (a Chain's bound), got {a.shape[-1]}")
    bad = ~np.isfinite(a)
    if bad.any():
        raise ValueError(f"{what}: expected finite numbers, got {_first(a, bad, argument)}")
    return a


def joint_trajectory(
    q_start: ArrayLike,
    q_end: ArrayLike,
    t: ArrayLike,
    duration: ArrayLike,
    kind: str = "quintic",
    peak_velocity_ratio: Optional[ArrayLike] = None,
) -> JointTrajectoryResult:
    """The straight-line joint trajectory from q_start to q_end, timed by a time scaling.

    q = q_start + s d, qd = s_dot d, qdd = s_ddot d, with d = q_end - q_start
    and (s, s_dot, s_ddot) = ``time_scaling(t, duration, kind,
    peak_velocity_ratio)`` (Lynch and Park, "Modern Robotics", ch. 9.2.1): q
    is exactly q_start at and before t = 0 and exactly q_end at and after
    t = duration (q is computed from the nearer end), at rest there. Modern
    Robotics' ``JointTrajectory(thetastart, thetaend, Tf, N, method)`` is
    ``joint_trajectory(thetastart, thetaend, np.linspace(0, Tf, N), Tf,
    "cubic").q`` for method 3 (``"quintic"`` for 5).

    The joint vectors' leading axes broadcast with the times, durations and
    ratios, as numpy's: one start and end and N times give N points; the C++
    kernel runs without the GIL.

    Args:
        q_start: array_like of shape (n,) or (..., n), n <= 32 (a Chain's
            bound): the joint positions at the start, finite.
        q_end: array_like of shape (n,) or (..., n), the same n: the joint
            positions at the end, finite.
        t: array_like of real numbers, any shape: the times; any number but
            NaN (before 0 and after the duration: at rest).
        duration: array_like of real numbers, finite and > 0: the durations.
        kind: ``"cubic"``, ``"quintic"`` or ``"trapezoidal"`` (``time_scaling``).
        peak_velocity_ratio: array_like of real numbers in (1, 2], the peak
            velocity over the average velocity (the joints' peak velocity is
            k d / duration). Required for ``"trapezoidal"``; the other kinds
            do not read it.

    Returns:
        JointTrajectoryResult: the named tuple ``(q, qd, qdd)``, float64
        arrays of shape (..., n), (...) the broadcast of the times', the
        durations' (and ratios') shapes and the joint vectors' leading axes.

    Raises:
        TypeError: kind is not a str, or an argument is not real numbers.
        ValueError: a joint vector of no axis, of more than 32 joints or not
            finite; q_start and q_end of different lengths; as
            ``time_scaling`` for t, duration, kind and peak_velocity_ratio;
            shapes that do not broadcast together.

    Example:
        >>> q, qd, qdd = chasles.joint_trajectory([0.0, 1.0], [1.0, 3.0], np.linspace(0.0, 2.0, 5), 2.0)
        >>> q
        array([[0.        , 1.        ],
               [0.10351562, 1.20703125],
               [0.5       , 2.        ],
               [0.89648438, 2.79296875],
               [1.        , 3.        ]])
        >>> qd[2]  # the quintic's peak: 15/8 of the average velocity d / 2
        array([0.9375, 1.875 ])
    """
    name = "joint_trajectory"
    code = _kind(kind, name)
    q0 = _joints(q_start, name, "q_start")
    q1 = _joints(q_end, name, "q_end")
    if q0.shape[-1] != q1.shape[-1]:
        raise ValueError(
            f"{name}(q_start, q_end): expected the same number of joints, got {q0.shape[-1]} and {q1.shape[-1]}"
        )
    times, T, k = _scaling_operands(name, t, duration, code, peak_velocity_ratio)
    arrays = {"q_start": q0, "q_end": q1, "t": times, "duration": T}
    if code == _TRAPEZOIDAL:
        arrays["peak_velocity_ratio"] = k
    _check_broadcast(name, arrays)
    return JointTrajectoryResult(*_core._joint_trajectory(q0, q1, code, T, k, times))
