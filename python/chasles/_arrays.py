"""The array functions that take an argument a ufunc cannot: each picks one
of the generalized ufuncs of chasles._core, as numpy.linalg does, and passes
every other keyword (out=, axes=, dtype=, ...) through to it."""

from __future__ import annotations

import warnings
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


def se3_from_quat(
    quat: ArrayLike, translation: ArrayLike, /, *, scalar_first: bool = False, **kwargs: Any
) -> np.ndarray:
    """Poses of quaternions and translations, as scipy's ``RigidTransform.from_components``.

    The rotations are ``so3_from_quat``'s: quaternions of any nonzero norm
    are normalized; a zero or non-finite quaternion gives a rotation block of
    NaN. ``quat`` and ``translation`` broadcast against each other, as the
    other array functions' operands do.

    Args:
        quat: array_like of shape (..., 4): quaternions, scalar-last
            (x, y, z, w) by default, as scipy.
        translation: array_like of shape (..., 3).
        scalar_first: if True, ``quat`` is read as (w, x, y, z).
        **kwargs: passed to the ufunc (``out=``, ``dtype=``, ...).

    Returns:
        numpy.ndarray of shape (..., 4, 4): the poses [[R, t], [0, 1]].

    Example:
        >>> import chasles
        >>> chasles.se3_from_quat([[0.0, 0.0, 1.0, 0.0]], [1.0, 2.0, 3.0])[0]
        array([[-1.,  0.,  0.,  1.],
               [ 0., -1.,  0.,  2.],
               [ 0.,  0.,  1.,  3.],
               [ 0.,  0.,  0.,  1.]])
    """
    ufunc = _core._se3_from_quat_wxyz if scalar_first else _core._se3_from_quat_xyzw
    return ufunc(quat, translation, **kwargs)


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


# The 24 Euler sequences, as scipy (lowercase extrinsic, uppercase intrinsic),
# in the order of chasles::EulerSequence: the index is the ufuncs' operand.
_EULER_SEQUENCES = (
    "xyz",
    "xzy",
    "yxz",
    "yzx",
    "zxy",
    "zyx",
    "xyx",
    "xzx",
    "yxy",
    "yzy",
    "zxz",
    "zyz",
    "XYZ",
    "XZY",
    "YXZ",
    "YZX",
    "ZXY",
    "ZYX",
    "XYX",
    "XZX",
    "YXY",
    "YZY",
    "ZXZ",
    "ZYZ",
)


def _euler_sequence(seq: Any, name: str) -> np.intc:
    """The index of `seq` in _EULER_SEQUENCES, or the error naming `name`."""
    if not isinstance(seq, str):
        raise TypeError(f"{name}(seq): expected a str of three axes such as 'xyz' or 'ZYX', got {type(seq).__name__}")
    if seq not in _EULER_SEQUENCES:
        raise ValueError(
            f"{name}(seq): expected three axes of 'xyz', all lowercase (extrinsic) or all "
            "uppercase (intrinsic), no two consecutive equal, as 'xyz', 'ZYX' or 'zxz'; "
            f"got {seq!r}"
        )
    return np.intc(_EULER_SEQUENCES.index(str(seq)))  # typed: numpy casts a Python int to int64


def _with_scalars(kwargs: dict, scalars: int, flags: int = 0) -> dict:
    """kwargs for a private ufunc whose `scalars` operands (the code of the
    sequence and unit) follow the one array operand, and whose result is
    followed by `flags` more (the gimbal lock): axes= gets () for each
    scalar, and dtype= becomes the signature of the array operand and of the
    result (numpy's loop search needs both when the loop's operands are not
    all of one type)."""
    axes = kwargs.get("axes")
    if axes is not None and isinstance(axes, (list, tuple)):
        axes = list(axes)
        kwargs = dict(kwargs, axes=axes[:1] + [()] * scalars + axes[1:])
    if kwargs.get("dtype") is not None:
        kwargs = dict(kwargs)
        dtype = kwargs.pop("dtype")
        kwargs["signature"] = (dtype,) + (None,) * scalars + (dtype,) + (None,) * flags
    return kwargs


def _angles_and_flag(ufunc: np.ufunc, operands: tuple, kwargs: dict, return_gimbal_lock: bool) -> Any:
    """Calls an as_euler `_lock` ufunc, whose second result is the gimbal lock
    flag (an out= array is the angles'; numpy makes the flags): returns the
    angles and the flags with return_gimbal_lock, else the angles, with
    scipy's UserWarning when a rotation is at the lock (SO3.as_euler's)."""
    kwargs = _with_scalars(kwargs, 1, 1)
    out = kwargs.get("out")
    if out is not None and not isinstance(out, tuple):
        kwargs = dict(kwargs, out=(out, None))
    elif isinstance(out, tuple) and len(out) == 1:
        kwargs = dict(kwargs, out=(out[0], None))
    angles, lock = ufunc(*operands, **kwargs)
    if return_gimbal_lock:
        return angles, lock
    if np.any(lock):
        warnings.warn(_core.SO3._GIMBAL_LOCK_WARNING, UserWarning, stacklevel=3)
    return angles


def so3_from_euler(seq: str, angles: ArrayLike, /, degrees: bool = False, **kwargs: Any) -> np.ndarray:
    """Rotation matrices of Euler angles, as scipy's ``Rotation.from_euler``.

    ``seq`` is one of the 12 axis sequences, lowercase for extrinsic (fixed
    axes) or uppercase for intrinsic (moving axes): extrinsic ``"xyz"`` with
    angles (a, b, c) is R = Rz(c) Ry(b) Rx(a), intrinsic ``"XYZ"`` is
    R = Rx(a) Ry(b) Rz(c). Any finite angles; the product of the three
    elementary rotations, each entry to a few ulps.

    Args:
        seq: the sequence, e.g. ``"xyz"``, ``"ZYX"``, ``"zxz"`` (not an array).
        angles: array_like of shape (..., 3): the angles, in the order of
            ``seq``'s letters.
        degrees: the angles are in degrees (default radians); converted as
            numpy's deg2rad, x * (pi / 180), inside the loop.
        **kwargs: passed to the ufunc (``out=``, ``axes=``, ``dtype=``, ...).

    Returns:
        numpy.ndarray of shape (..., 3, 3): the rotation matrices.

    Raises:
        TypeError: seq is not a str.
        ValueError: seq is not one of the 24 sequences.

    Example:
        >>> import chasles
        >>> np.round(chasles.so3_from_euler("xyz", [0.0, 0.0, 90.0], degrees=True), 12) + 0.0
        array([[ 0., -1.,  0.],
               [ 1.,  0.,  0.],
               [ 0.,  0.,  1.]])
    """
    code = _euler_sequence(seq, "so3_from_euler") + np.intc(24 if degrees else 0)
    return _core._so3_from_euler(angles, code, **_with_scalars(kwargs, 1))


def so3_as_euler(
    seq: str, R: ArrayLike, /, degrees: bool = False, *, return_gimbal_lock: bool = False, **kwargs: Any
) -> Any:
    """Euler angles of rotation matrices, as scipy's ``Rotation.as_euler``.

    scipy's ranges: the middle angle in [-pi/2, pi/2] for Tait-Bryan
    sequences (three distinct axes), [0, pi] for proper Euler sequences
    (first axis = last), the others in [-pi, pi]. At the gimbal lock (the
    middle angle +-pi/2, or 0 or pi, to working precision) only the sum or
    difference of the outer angles is defined and the third angle is zero,
    with scipy's UserWarning (once per call; not with
    return_gimbal_lock=True, which returns the flags). Robust at and next to the lock:
    ``so3_from_euler(seq, so3_as_euler(seq, R))`` reproduces R to a few ulps
    for every rotation (atan2 of well-conditioned pairs of entries).

    Args:
        seq: the sequence, e.g. ``"xyz"``, ``"ZYX"``, ``"zxz"``.
        R: array_like of shape (..., 3, 3): rotation matrices.
        degrees: return degrees (default radians), as numpy's rad2deg.
        return_gimbal_lock: also return, for each rotation, whether it is at
            the gimbal lock (the third angle was set to zero).
        **kwargs: passed to the ufunc (``out=``, ``axes=``, ``dtype=``, ...;
            ``out=`` and ``dtype=`` are the angles').

    Returns:
        numpy.ndarray of shape (..., 3): the angles, in the order of
        ``seq``'s letters; with return_gimbal_lock=True the tuple (angles,
        gimbal_lock), gimbal_lock a bool array of shape (...).

    Raises:
        TypeError: seq is not a str.
        ValueError: seq is not one of the 24 sequences.

    Example:
        >>> import chasles
        >>> R = chasles.so3_from_euler("ZYX", [0.3, -0.2, 0.1])
        >>> np.round(chasles.so3_as_euler("ZYX", R), 12)
        array([ 0.3, -0.2,  0.1])
    """
    code = _euler_sequence(seq, "so3_as_euler") + np.intc(24 if degrees else 0)
    return _angles_and_flag(_core._so3_as_euler_lock, (R, code), kwargs, return_gimbal_lock)


def so3_from_rpy(rpy: ArrayLike, /, degrees: bool = False, **kwargs: Any) -> np.ndarray:
    """Rotation matrices of roll, pitch, yaw: URDF's ``rpy``, ROS tf's setRPY.

    About the fixed axes x, y and z in that order, R = Rz(yaw) Ry(pitch)
    Rx(roll): ``so3_from_euler("xyz", rpy)``.

    Args:
        rpy: array_like of shape (..., 3): (roll, pitch, yaw).
        degrees: the angles are in degrees (default radians).
        **kwargs: passed to the ufunc (``out=``, ``axes=``, ``dtype=``, ...).

    Returns:
        numpy.ndarray of shape (..., 3, 3): the rotation matrices.

    Example:
        >>> import chasles
        >>> rpy = [0.1, 0.2, 0.3]
        >>> bool((chasles.so3_from_rpy(rpy) == chasles.so3_from_euler("xyz", rpy)).all())
        True
    """
    return _core._so3_from_rpy(rpy, np.intc(1 if degrees else 0), **_with_scalars(kwargs, 1))


def so3_as_rpy(R: ArrayLike, /, degrees: bool = False, *, return_gimbal_lock: bool = False, **kwargs: Any) -> Any:
    """Roll, pitch, yaw of rotation matrices (URDF, ROS tf's getRPY).

    ``so3_as_euler("xyz", R)``: R = Rz(yaw) Ry(pitch) Rx(roll), pitch in
    [-pi/2, pi/2], roll and yaw in [-pi, pi]; at the gimbal lock (pitch
    +-pi/2) yaw is zero, with scipy's UserWarning (not with
    return_gimbal_lock=True).

    Args:
        R: array_like of shape (..., 3, 3): rotation matrices.
        degrees: return degrees (default radians).
        return_gimbal_lock: also return, for each rotation, whether pitch is
            at +-pi/2 (yaw was set to zero).
        **kwargs: passed to the ufunc (``out=``, ``axes=``, ``dtype=``, ...;
            ``out=`` and ``dtype=`` are the angles').

    Returns:
        numpy.ndarray of shape (..., 3): (roll, pitch, yaw); with
        return_gimbal_lock=True the tuple (rpy, gimbal_lock), gimbal_lock a
        bool array of shape (...).

    Example:
        >>> import chasles
        >>> np.round(chasles.so3_as_rpy(chasles.so3_from_rpy([0.1, 0.2, 0.3])), 12)
        array([0.1, 0.2, 0.3])
    """
    return _angles_and_flag(_core._so3_as_rpy_lock, (R, np.intc(1 if degrees else 0)), kwargs, return_gimbal_lock)
