"""The array functions that take an argument a ufunc cannot: each picks one
of the generalized ufuncs of chasles._core, as numpy.linalg does, and passes
every other keyword (out=, axes=, dtype=, ...) through to it."""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from chasles import _core


def so3_from_quat(quat: ArrayLike, /, *, scalar_first: bool = False, **kwargs: Any) -> np.ndarray:
    """Rotation matrices of quaternions, as scipy's ``Rotation.from_quat``.

    Quaternions of any nonzero norm are normalized; a zero or non-finite
    quaternion gives a matrix of NaN.

    Args:
        quat: array_like of shape (..., 4): quaternions, scalar-last
            (x, y, z, w) by default, as scipy.
        scalar_first: if True, ``quat`` is read as (w, x, y, z).
        **kwargs: passed to the ufunc (``out=``, ``axes=``, ``dtype=``, ...).

    Returns:
        numpy.ndarray of shape (..., 3, 3): the rotation matrices.

    Example:
        >>> import chasles
        >>> chasles.so3_from_quat([0.0, 0.0, 0.0, 1.0])
        array([[1., 0., 0.],
               [0., 1., 0.],
               [0., 0., 1.]])
    """
    ufunc = _core._so3_from_quat_wxyz if scalar_first else _core._so3_from_quat_xyzw
    return ufunc(quat, **kwargs)


def so3_as_quat(R: ArrayLike, /, *, scalar_first: bool = False, **kwargs: Any) -> np.ndarray:
    """Unit quaternions of rotation matrices, as scipy's ``Rotation.as_quat``.

    Shepperd's method (no small divisor for any input). Of the two
    quaternions q and -q of a rotation, the one whose largest component is
    positive.

    Args:
        R: array_like of shape (..., 3, 3): rotation matrices.
        scalar_first: if True, return (w, x, y, z) instead of (x, y, z, w).
        **kwargs: passed to the ufunc (``out=``, ``axes=``, ``dtype=``, ...).

    Returns:
        numpy.ndarray of shape (..., 4): the quaternions, scalar-last
        (x, y, z, w) by default, as scipy.

    Example:
        >>> import chasles
        >>> chasles.so3_as_quat(np.eye(3), scalar_first=True)
        array([1., 0., 0., 0.])
    """
    ufunc = _core._so3_as_quat_wxyz if scalar_first else _core._so3_as_quat_xyzw
    return ufunc(R, **kwargs)
