"""The rotation, rigid motion or similarity that best aligns two sets of
vectors or points (least squares): ``so3_align`` (Wahba's problem, as
scipy's ``Rotation.align_vectors``), ``se3_align`` (Kabsch) and
``sim3_align`` (Umeyama).

Like a mean, an alignment reduces over the rows, so it is not a generalized
ufunc: these Python functions check the arguments and call the C++ kernel
(chasles/align.hpp) once over the (N, 3) arrays, without the GIL; the status
it reports becomes a ValueError (or, for vectors that do not determine the
rotation, scipy's choice: a UserWarning).
"""

from __future__ import annotations

import warnings
from typing import NamedTuple, Optional

import numpy as np
from numpy.typing import ArrayLike

from chasles import _core
from chasles._random import _asarray

# constants.hpp, Thresholds<double>::align_tolerance (sqrt(eps))
_TOLERANCE = 1.4901161193847656e-08


class VectorAlignment(NamedTuple):
    """What ``so3_align`` returns: unpacks as scipy's
    ``Rotation.align_vectors(a, b, weights, return_sensitivity=True)``."""

    matrix: np.ndarray
    """The rotation R, shape (3, 3): a_i ~ R b_i."""
    rssd: float
    """sqrt(sum_i w_i |a_i - R b_i|^2), the primary vector's term left out."""
    sensitivity: Optional[np.ndarray]
    """scipy's sensitivity matrix, shape (3, 3); None where scipy gives none
    (one pair, an infinite weight) and where the rotation is not determined."""


class PointAlignment(NamedTuple):
    """What ``se3_align`` and ``sim3_align`` return."""

    matrix: np.ndarray
    """The transform g, shape (4, 4): [[R, t], [0, 1]] (se3_align) or
    [[s R, t], [0, 1]] (sim3_align), with A_i ~ g B_i."""
    rssd: float
    """sqrt(sum_i w_i |A_i - g B_i|^2)."""


def _rows(name: str, label: str, x: ArrayLike, single: bool, least: int) -> np.ndarray:
    """x as a C-contiguous float64 (N, 3) array (a (3,) one as (1, 3) where
    `single`), N >= least."""
    m = _asarray(x, f"{name}({label})")
    if single and m.shape == (3,):
        m = m.reshape(1, 3)
    elif m.ndim != 2 or m.shape[1] != 3 or m.shape[0] < least:
        expected = "(3,) or (N, 3) with N >= 1" if single else f"(N, 3) with N >= {least} points"
        raise ValueError(f"{name}({label}): expected shape {expected}, got {m.shape}")
    return np.ascontiguousarray(m, dtype=np.float64)


def _weights(name: str, weights: Optional[ArrayLike], n: int) -> Optional[np.ndarray]:
    if weights is None:
        return None
    w = _asarray(weights, f"{name}(weights)")
    if w.shape != (n,):
        raise ValueError(f"{name}(weights): expected shape ({n},), one weight per row, got {w.shape}")
    return np.ascontiguousarray(w, dtype=np.float64)


def _first(mask: np.ndarray) -> int:
    return int(np.argmax(mask))


def _refusal(name: str, status: str, a: np.ndarray, b: np.ndarray, w: Optional[np.ndarray], vectors: bool) -> str:
    """The message of a refused call (the C++ status, explained)."""
    if status == "weights_not_valid":
        assert w is not None
        bad = ~(w >= 0)  # negative or NaN
        if bad.any():
            i = _first(bad)
            expected = "weights >= 0 (one may be inf)" if vectors else "finite weights >= 0"
            return f"{name}(weights): expected {expected}, got weights[{i}] = {float(w[i])!r}"
        infinite = np.flatnonzero(np.isinf(w))
        if vectors:
            i, j = int(infinite[0]), int(infinite[1])
            return (
                f"{name}(weights): expected at most one infinite weight (the primary vector), "
                f"got weights[{i}] and weights[{j}] infinite"
            )
        if infinite.size:
            i = int(infinite[0])
            return (
                f"{name}(weights): expected finite weights >= 0, got weights[{i}] = inf "
                "(a primary vector is so3_align's)"
            )
        return f"{name}(weights): expected at least one weight > 0, got all {w.shape[0]} weights 0"
    if status == "not_finite":
        for label, x in (("a", a), ("b", b)):
            bad = ~np.isfinite(x)
            if bad.any():
                i, k = divmod(_first(bad.ravel()), 3)
                return f"{name}({label}): expected finite numbers, got {label}[{i}, {k}] = {float(x[i, k])!r}"
        return f"{name}(a, b): the weighted sums overflowed (finite numbers whose products do not fit a float64)"
    if status == "zero_primary":
        i = 0 if w is None or a.shape[0] == 1 else int(np.flatnonzero(np.isinf(w))[0])
        label = "a" if not np.any(a[i]) else "b"
        what = "the single vector" if a.shape[0] == 1 else f"the primary vector (weights[{i}] = inf)"
        return f"{name}({label}): {what} {label}[{i}] has length 0: it has no direction to align"
    return f"{name}: refused ({status})"


def so3_align(a: ArrayLike, b: ArrayLike, weights: Optional[ArrayLike] = None) -> VectorAlignment:
    """The rotation that best maps the vectors b onto the vectors a (Wahba's problem).

    R minimizes sum_i w_i |a_i - R b_i|^2 (a_i seen in frame A, b_i in frame
    B: R = R_ab), as scipy's ``Rotation.align_vectors(a, b, weights,
    return_sensitivity=True)``: the same rotation, rssd and sensitivity
    matrix, and scipy's special cases and refusals:

    - one pair (a and b of shape (3,) or (1, 3)): the shortest rotation
      taking b's direction to a's;
    - one infinite weight: that pair is primary, aligned exactly (whatever
      the lengths; its term is left out of rssd), and the others are best
      fitted by a rotation about it (the limit of a growing weight);
    - vectors that do not determine the rotation (all parallel, or fewer
      than two of weight > 0 that are not; with a primary vector, the
      others all parallel to it): a UserWarning, as scipy's, and one of the
      best rotations (scipy's choice), without a sensitivity. chasles warns
      where the data fix the rotation to fewer than half the digits
      (s2 + s3 <= sqrt(eps) s1 for the signed singular values of
      sum_i w_i a_i b_i^T), scipy only below 1e-16 s1.

    The rotation is the nearest to B = sum_i w_i a_i b_i^T, from Horn's
    quaternion matrix of B: a rotation by construction, never a reflection.
    rssd = sqrt(sum_i w_i |a_i - R b_i|^2) is summed from the residuals
    (scipy's subtracts 2 tr(R^T B) from sum_i w_i (|a_i|^2 + |b_i|^2), which
    loses half the digits of a close fit). The sensitivity is scipy's:
    mean(w) / zeta (kappa I + B B^T), zeta = (s1 + s2)(s2 + s3)(s3 + s1),
    kappa = s1 s2 + s2 s3 + s3 s1; times the variance of the measurement
    errors it is the covariance of the rotation error, a rotation vector of
    frame A (scipy's Notes). Unlike scipy's, the shortest rotation is exact
    also for nearly opposite vectors (scipy 1.17 misses there by up to 2).

    Args:
        a: array_like of shape (3,) or (N, 3), N >= 1: vectors in frame A,
            finite.
        b: array_like of the same shape: the vectors in frame B.
        weights: array_like of shape (N,), >= 0, at most one of them inf;
            None for all 1. The vectors' lengths weigh too (normalize them
            for directions alone).

    Returns:
        VectorAlignment: (matrix, rssd, sensitivity), float64, unpacking as
        ``R, rssd, sensitivity = so3_align(a, b)``; matrix of shape (3, 3),
        sensitivity of shape (3, 3) or None (one pair, an infinite weight,
        a rotation not determined).

    Raises:
        ValueError: a shape, a number that is not finite, a negative or NaN
            weight, two infinite weights, a primary vector of length 0, sums
            that overflow.

    Example:
        >>> import numpy as np
        >>> import chasles
        >>> b = np.array([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]])
        >>> R = chasles.so3_exp([0.0, 0.0, np.pi / 2])
        >>> fit = chasles.so3_align(b @ R.T, b)
        >>> np.allclose(fit.matrix, R), round(fit.rssd, 12) + 0.0
        (True, 0.0)
    """
    name = "so3_align"
    A = _rows(name, "a", a, True, 1)
    B = _rows(name, "b", b, True, 1)
    if A.shape != B.shape:
        raise ValueError(f"{name}(a, b): expected the same shape, got {np.shape(a)} and {np.shape(b)}")
    w = _weights(name, weights, A.shape[0])
    matrix, rssd, s, sensitivity, status = _core._so3_align(A, B, w)
    if status == "not_determined":
        if np.isnan(s[0]):
            what = (
                "the rotation about the primary vector is not determined (the others are parallel to it, "
                "or of weight 0)"
            )
        else:
            what = (
                "the rotation is not determined by these vectors to half the digits (all parallel, fewer than two "
                "of weight > 0 that are not, or some outweighing the others by about 1e8): "
                f"s2 + s3 = {s[1] + s[2]:.3g} <= {_TOLERANCE:.3g} s1 = {_TOLERANCE * s[0]:.3g}, "
                "s the signed singular values of sum_i w_i a_i b_i^T"
            )
        warnings.warn(f"{name}: {what}; one of the best rotations is returned", UserWarning, stacklevel=2)
    elif status != "ok":
        raise ValueError(_refusal(name, status, A, B, w, vectors=True))
    return VectorAlignment(matrix, float(rssd), sensitivity)


def _point_align(name: str, core, a: ArrayLike, b: ArrayLike, weights: Optional[ArrayLike]) -> PointAlignment:
    A = _rows(name, "a", a, False, 3)
    B = _rows(name, "b", b, False, 3)
    if A.shape != B.shape:
        raise ValueError(f"{name}(a, b): expected the same shape, got {A.shape} and {B.shape}")
    w = _weights(name, weights, A.shape[0])
    matrix, rssd, s, status = core(A, B, w)
    if status == "not_determined":
        raise ValueError(
            f"{name}(a, b): the points do not determine the rotation: they are collinear (or fewer than 3 "
            f"of weight > 0 are not): s2 + s3 = {s[1] + s[2]:.3g} <= {_TOLERANCE:.3g} s1 = {_TOLERANCE * s[0]:.3g}, "
            "s the signed singular values of the centred cross-covariance"
        )
    if status != "ok":
        raise ValueError(_refusal(name, status, A, B, w, vectors=False))
    return PointAlignment(matrix, float(rssd))


def se3_align(a: ArrayLike, b: ArrayLike, weights: Optional[ArrayLike] = None) -> PointAlignment:
    """The rigid motion that best maps the points b onto the points a (Kabsch).

    g = (R, t) minimizes sum_i w_i |a_i - g b_i|^2, g b = R b + t: R aligns
    the points centred on their weighted means (the rotation nearest to
    sum_i w_i (a_i - mean a)(b_i - mean b)^T, by Horn's quaternion matrix:
    never a reflection, also where the best orthogonal map is one), and
    t = mean a - R mean b. Exact to rounding on noise-free data; equal to
    ``Eigen::umeyama(b, a, false)`` without weights.

    Args:
        a: array_like of shape (N, 3), N >= 3: points in frame A, finite.
        b: array_like of shape (N, 3): the same points in frame B.
        weights: array_like of shape (N,), finite, >= 0, not all 0; None
            for all 1.

    Returns:
        PointAlignment: (matrix, rssd), matrix of shape (4, 4), float64,
        [[R, t], [0, 1]] (chasles.SE3.from_matrix takes it), rssd =
        sqrt(sum_i w_i |a_i - g b_i|^2).

    Raises:
        ValueError: a shape (fewer than 3 points), a number that is not
            finite, a weight that is negative, NaN or infinite, all weights
            0, points that do not determine the rotation (collinear, or
            fewer than 3 of weight > 0 off a line), sums that overflow.

    Example:
        >>> import numpy as np
        >>> import chasles
        >>> b = np.array([[0.0, 0, 0], [1, 0, 0], [0, 2, 0], [0, 0, 3]])
        >>> g = chasles.se3_exp([1.0, 2.0, 3.0, 0.1, 0.2, 0.3])
        >>> fit = chasles.se3_align(chasles.se3_act(g, b), b)
        >>> np.allclose(fit.matrix, g)
        True
    """
    return _point_align("se3_align", _core._se3_align, a, b, weights)


def sim3_align(a: ArrayLike, b: ArrayLike, weights: Optional[ArrayLike] = None) -> PointAlignment:
    """The similarity that best maps the points b onto the points a (Umeyama).

    g = (R, t, s) minimizes sum_i w_i |a_i - g b_i|^2, g b = s R b + t
    (Umeyama 1991, with weights): R as in ``se3_align``, s = tr(R^T H) /
    sum_i w_i |b_i - mean b|^2 for the centred cross-covariance H, and
    t = mean a - s R mean b. Never a reflection; exact to rounding on
    noise-free data; equal to ``Eigen::umeyama(b, a)`` without weights.

    Args:
        a: array_like of shape (N, 3), N >= 3: points in frame A, finite.
        b: array_like of shape (N, 3): the same points in frame B.
        weights: array_like of shape (N,), finite, >= 0, not all 0; None
            for all 1.

    Returns:
        PointAlignment: (matrix, rssd), matrix of shape (4, 4), float64,
        [[s R, t], [0, 1]] (chasles.Sim3.from_matrix takes it), rssd =
        sqrt(sum_i w_i |a_i - g b_i|^2).

    Raises:
        ValueError: as ``se3_align``.

    Example:
        >>> import numpy as np
        >>> import chasles
        >>> b = np.array([[0.0, 0, 0], [1, 0, 0], [0, 2, 0], [0, 0, 3]])
        >>> g = chasles.sim3_exp([1.0, 2.0, 3.0, 0.1, 0.2, 0.3, np.log(2.0)])
        >>> fit = chasles.sim3_align(chasles.sim3_act(g, b), b)
        >>> np.allclose(fit.matrix, g), round(chasles.Sim3.from_matrix(fit.matrix).scale, 12)
        (True, 2.0)
    """
    return _point_align("sim3_align", _core._sim3_align, a, b, weights)
