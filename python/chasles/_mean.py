"""Weighted means of rotations and rigid motions.

A mean reduces over the batch axis, so it is not a generalized ufunc (whose
loops broadcast over that axis): these Python functions check the arguments
and call the C++ mean (chasles/mean.hpp) once over the whole (N, 3, 3) or
(N, 4, 4) array, without the GIL; the C++ side refuses an element that is
not one of the group (bindings/bind_statistics.cpp). The means of SO2, SE2,
Sim3 and SE23 are one function, ``_make_mean``, made for each row of the
group table (``_groups.py``).
"""

from __future__ import annotations

import numbers
import warnings
from typing import Any, NamedTuple, Optional

import numpy as np
from numpy.typing import ArrayLike

from chasles import _core, _groups
from chasles._random import _asarray

METHODS = ("geodesic", "chordal")


class MeanInfo(NamedTuple):
    """What the means (``so3_mean``, ``se3_mean``, ``so2_mean``, ...) return with ``return_info=True``."""

    mean: np.ndarray
    """The mean, of the shape of one element: (3, 3) for SO3, (4, 4) for SE3, ..."""
    converged: bool
    """The geodesic iteration converged (always True for ``method="chordal"``)."""
    iterations: int
    """The Newton steps taken (0 for ``method="chordal"``)."""


def _check_weights(name: str, w: np.ndarray) -> None:
    """Weights of a mean: finite, >= 0, not all 0 (their scale does not
    matter: the C++ mean divides them by the largest, chasles/mean.hpp)."""
    bad = ~np.isfinite(w)
    if bad.any():
        i = int(np.argmax(bad))
        raise ValueError(f"{name}(weights): expected finite weights, got weights[{i}] = {float(w[i])!r}")
    negative = w < 0
    if negative.any():
        i = int(np.argmax(negative))
        raise ValueError(f"{name}(weights): expected weights >= 0, got weights[{i}] = {float(w[i])!r}")
    if not w.max() > 0:
        raise ValueError(f"{name}(weights): expected at least one weight > 0, got all {w.shape[0]} weights 0")


def _mean(
    name: str,
    core: int,
    matrices: ArrayLike,
    weights: Optional[ArrayLike],
    method: Any,
    max_iterations: Any,
    return_info: bool,
    reduce,
) -> Any:
    if not isinstance(method, str) or method not in METHODS:
        raise ValueError(f"{name}(method): expected 'geodesic' or 'chordal', got {method!r}")
    if isinstance(max_iterations, (bool, np.bool_)) or not isinstance(max_iterations, (numbers.Integral, np.integer)):
        raise TypeError(f"{name}(max_iterations): expected an int, got {type(max_iterations).__name__}")
    if not 1 <= int(max_iterations) <= 1000:
        raise ValueError(f"{name}(max_iterations): expected 1 <= max_iterations <= 1000, got {max_iterations}")
    X = _asarray(matrices, f"{name}(matrices)")
    if X.ndim != 3 or X.shape[1:] != (core, core) or X.shape[0] == 0:
        hint = ""
        if name == "so3_mean" and X.ndim == 2 and X.shape[1] == 4:
            hint = "; quaternions (x, y, z, w) are rotations by chasles.so3_from_quat(quat)"
        raise ValueError(f"{name}(matrices): expected shape (N, {core}, {core}) with N >= 1, got {X.shape}{hint}")
    X = np.ascontiguousarray(X, dtype=np.float64)
    if not np.all(np.isfinite(X)):
        raise ValueError(f"{name}(matrices): expected finite numbers")
    n = X.shape[0]
    if weights is None:
        w = np.ones(n)
    else:
        w = np.ascontiguousarray(_asarray(weights, f"{name}(weights)"), dtype=np.float64)
        if w.shape != (n,):
            raise ValueError(f"{name}(weights): expected shape ({n},), got {w.shape}")
        _check_weights(name, w)
    mean, iterations, converged = reduce(X, w, method == "geodesic", int(max_iterations))
    if return_info:
        return MeanInfo(mean, bool(converged), int(iterations))
    if not converged:
        warnings.warn(
            f"{name}: the geodesic mean did not converge in {iterations} iterations "
            "(elements spread near pi apart have no unique mean); the last iterate is returned",
            RuntimeWarning,
            stacklevel=3,
        )
    return mean


def so3_mean(
    matrices: ArrayLike,
    weights: Optional[ArrayLike] = None,
    method: str = "geodesic",
    *,
    max_iterations: int = 20,
    return_info: bool = False,
) -> Any:
    """The weighted mean of rotations.

    ``method="geodesic"`` (default): the Karcher mean M with
    sum_i w_i log(M^T R_i) = 0, the minimizer of sum_i w_i d(M, R_i)^2 for
    the angle distance ``so3_distance``; Newton's method from the chordal
    mean, 2 or 3 steps at a 1 rad spread (at most ``max_iterations``; a
    RuntimeWarning if it did not converge). ``method="chordal"``: the
    rotation nearest to sum_i w_i R_i, the quaternion eigenvector mean that
    scipy's ``Rotation.mean`` computes. Both are invariant on both sides,
    mean(g R_i h) = g mean(R_i) h.

    A reduction over the batch axis, not a gufunc: one C++ call over the
    array, without the GIL.

    Args:
        matrices: array_like of shape (N, 3, 3), N >= 1: rotation matrices
            (a ValueError names the first whose defect exceeds sqrt(eps),
            as SO3.from_matrix).
        weights: array_like of shape (N,), finite, >= 0, not all 0; None
            for equal weights. Their scale does not matter (w and 1e300 w,
            or subnormal w, give the same mean).
        method: "geodesic" or "chordal".
        max_iterations: the bound on the Newton steps (geodesic).
        return_info: return a ``MeanInfo`` (mean, converged, iterations)
            instead of the mean alone, and no RuntimeWarning.

    Returns:
        numpy.ndarray of shape (3, 3): the mean rotation, float64; with
        return_info=True a ``MeanInfo`` named tuple.

    Example:
        >>> import chasles
        >>> R = chasles.so3_exp([[0.0, 0.0, 0.1], [0.0, 0.0, 0.3]])
        >>> np.allclose(chasles.so3_mean(R), chasles.so3_exp([0.0, 0.0, 0.2]))
        True
    """
    return _mean("so3_mean", 3, matrices, weights, method, max_iterations, return_info, _core._so3_mean)


def se3_mean(
    matrices: ArrayLike,
    weights: Optional[ArrayLike] = None,
    method: str = "geodesic",
    *,
    max_iterations: int = 20,
    return_info: bool = False,
) -> Any:
    """The weighted mean of rigid motions.

    ``method="geodesic"`` (default): the bi-invariant exponential barycenter
    M with sum_i w_i log(M^-1 g_i) = 0 in the twists (Pennec and Arsigny;
    manif's average), by Newton's method from the chordal mean. SE(3) has
    no bi-invariant metric, but this mean is invariant on both sides,
    mean(a g_i b) = a mean(g_i) b, which the per-part mean is not under
    g_i b. ``method="chordal"``: per part, the chordal mean of the rotations
    (as ``so3_mean``) and the weighted average of the translations
    (invariant on the left only). A RuntimeWarning if the geodesic mean did
    not converge in ``max_iterations`` steps.

    Args:
        matrices: array_like of shape (N, 4, 4), N >= 1: homogeneous matrices
            (a ValueError names the first whose rotation block's defect
            exceeds sqrt(eps)).
        weights: array_like of shape (N,), finite, >= 0, not all 0; None
            for equal weights. Their scale does not matter (w and 1e300 w,
            or subnormal w, give the same mean).
        method: "geodesic" or "chordal".
        max_iterations: the bound on the Newton steps (geodesic).
        return_info: return a ``MeanInfo`` (mean, converged, iterations)
            instead of the mean alone, and no RuntimeWarning.

    Returns:
        numpy.ndarray of shape (4, 4): the mean pose, float64; with
        return_info=True a ``MeanInfo`` named tuple.

    Example:
        >>> import chasles
        >>> g = chasles.se3_exp([[1.0, 0, 0, 0, 0, 0], [3.0, 0, 0, 0, 0, 0]])
        >>> np.allclose(chasles.se3_mean(g)[:3, 3], [2.0, 0.0, 0.0])
        True
    """
    return _mean("se3_mean", 4, matrices, weights, method, max_iterations, return_info, _core._se3_mean)


_MEAN_DOC = """The weighted mean of {kinds}.

    ``method="geodesic"`` (default): the Karcher mean (exponential
    barycenter) M with sum_i w_i log(M^-1 g_i) = 0 in the tangent
    {tangent}, by Newton's method from the chordal mean (at most
    ``max_iterations`` steps; a RuntimeWarning if it did not converge). It
    is invariant on both sides, mean(a g_i b) = a mean(g_i) b.
    ``method="chordal"``: {chordal}.

    A reduction over the batch axis, not a gufunc: one C++ call
    (chasles/mean.hpp) over the array, without the GIL.

    Args:
        matrices: array_like of shape (N, {n}, {n}), N >= 1: {matrix} (a
            ValueError names the first that {cls}.from_matrix would refuse).
        weights: array_like of shape (N,), finite, >= 0, not all 0; None
            for equal weights. Their scale does not matter.
        method: "geodesic" or "chordal".
        max_iterations: the bound on the Newton steps (geodesic), 1 to 1000.
        return_info: return a ``MeanInfo`` (mean, converged, iterations)
            instead of the mean alone, and no RuntimeWarning.

    Returns:
        numpy.ndarray of shape ({n}, {n}): the mean {kind}, float64; with
        return_info=True a ``MeanInfo`` named tuple.

    Example:
{example}
    """


def _make_mean(group: _groups.Group):
    """The mean function of one group of the table: ``_mean`` over
    ``_core._<prefix>_mean``."""
    name = f"{group.prefix}_mean"
    reduce = getattr(_core, f"_{name}")

    def mean(
        matrices: ArrayLike,
        weights: Optional[ArrayLike] = None,
        method: str = "geodesic",
        *,
        max_iterations: int = 20,
        return_info: bool = False,
    ) -> Any:
        return _mean(name, group.n, matrices, weights, method, max_iterations, return_info, reduce)

    mean.__name__ = mean.__qualname__ = name
    mean.__doc__ = _MEAN_DOC.format(**group._asdict())
    return mean


so2_mean = _make_mean(_groups.SO2)
se2_mean = _make_mean(_groups.SE2)
sim3_mean = _make_mean(_groups.SIM3)
se23_mean = _make_mean(_groups.SE23)
