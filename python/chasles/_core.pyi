"""
chasles C++ kernels (use the chasles package, which re-exports them).
"""
from __future__ import annotations
from chasles._chain import Chain
import chasles._results
import collections.abc
import numpy
import numpy.dtypes
import numpy.typing
import typing
__all__: list[str] = ['Chain', 'SE2', 'SE23', 'SE3', 'SO2', 'SO3', 'Screw', 'Sim3', 'SpatialInertia', 'Twist', 'Wrench', 'act_jacobians', 'between', 'between_jacobians', 'compose_jacobians', 'get_num_threads', 'interpolate', 'interpolate_jacobian_t', 'inverse_jacobian', 'lminus', 'lminus_jacobians', 'log_jacobian', 'lplus', 'lplus_jacobians', 'rminus', 'rminus_jacobians', 'rplus', 'rplus_jacobians', 'se23_act', 'se23_between_cov', 'se23_between_jacobians', 'se23_compose', 'se23_compose_cov', 'se23_compose_jacobians', 'se23_distance', 'se23_exp', 'se23_hat', 'se23_interpolate', 'se23_inverse', 'se23_inverse_cov', 'se23_log', 'se23_normalize', 'se23_rminus_jacobians', 'se23_vee', 'se2_act', 'se2_between_cov', 'se2_between_jacobians', 'se2_compose', 'se2_compose_cov', 'se2_compose_jacobians', 'se2_distance', 'se2_exp', 'se2_hat', 'se2_interpolate', 'se2_inverse', 'se2_inverse_cov', 'se2_log', 'se2_normalize', 'se2_rminus_jacobians', 'se2_vee', 'se3_act', 'se3_act_jacobian', 'se3_act_twist', 'se3_act_wrench', 'se3_adjoint', 'se3_between_cov', 'se3_between_jacobians', 'se3_compose', 'se3_compose_cov', 'se3_compose_jacobians', 'se3_distance', 'se3_exp', 'se3_hat', 'se3_interpolate', 'se3_inverse', 'se3_inverse_cov', 'se3_log', 'se3_normalize', 'se3_rminus_jacobians', 'se3_vee', 'sim3_act', 'sim3_between_cov', 'sim3_between_jacobians', 'sim3_compose', 'sim3_compose_cov', 'sim3_compose_jacobians', 'sim3_distance', 'sim3_exp', 'sim3_hat', 'sim3_interpolate', 'sim3_inverse', 'sim3_inverse_cov', 'sim3_log', 'sim3_normalize', 'sim3_rminus_jacobians', 'sim3_vee', 'so2_act', 'so2_between_cov', 'so2_between_jacobians', 'so2_compose', 'so2_compose_cov', 'so2_compose_jacobians', 'so2_distance', 'so2_exp', 'so2_hat', 'so2_interpolate', 'so2_inverse', 'so2_inverse_cov', 'so2_log', 'so2_normalize', 'so2_rminus_jacobians', 'so2_vee', 'so3_act', 'so3_act_jacobian', 'so3_angle', 'so3_between_cov', 'so3_between_jacobians', 'so3_compose', 'so3_compose_cov', 'so3_compose_jacobians', 'so3_distance', 'so3_exp', 'so3_from_uniforms', 'so3_hat', 'so3_interpolate', 'so3_inverse', 'so3_inverse_cov', 'so3_log', 'so3_normalize', 'so3_rminus_jacobians', 'so3_vee']

_Name = typing.TypeVar("_Name", bound=str)
_Signature = typing.TypeVar("_Signature", bound=str)

class _GUFunc_Nin1_Nout1(numpy.ufunc, typing.Generic[_Name, _Signature]):
    """A numpy generalized ufunc of 1 operand(s) and one result."""
    @property
    def __name__(self) -> _Name: ...
    @property
    def signature(self) -> _Signature: ...
    @property
    def nin(self) -> typing.Literal[1]: ...
    @property
    def nout(self) -> typing.Literal[1]: ...
    def __call__(
        self,
        x1: numpy.typing.ArrayLike,
        /,
        out: numpy.ndarray | tuple[numpy.ndarray] | None = ...,
        *,
        where: numpy.typing.ArrayLike = ...,
        axes: list[tuple[int, ...]] = ...,
        axis: int = ...,
        keepdims: bool = ...,
        casting: typing.Literal["no", "equiv", "safe", "same_kind", "unsafe"] = ...,
        order: typing.Literal["K", "A", "C", "F"] = ...,
        dtype: numpy.typing.DTypeLike = ...,
        subok: bool = ...,
        signature: typing.Any = ...,
    ) -> numpy.typing.NDArray[numpy.floating[typing.Any]]: ...

class _GUFunc_Nin2_Nout1(numpy.ufunc, typing.Generic[_Name, _Signature]):
    """A numpy generalized ufunc of 2 operand(s) and one result."""
    @property
    def __name__(self) -> _Name: ...
    @property
    def signature(self) -> _Signature: ...
    @property
    def nin(self) -> typing.Literal[2]: ...
    @property
    def nout(self) -> typing.Literal[1]: ...
    def __call__(
        self,
        x1: numpy.typing.ArrayLike, x2: numpy.typing.ArrayLike,
        /,
        out: numpy.ndarray | tuple[numpy.ndarray] | None = ...,
        *,
        where: numpy.typing.ArrayLike = ...,
        axes: list[tuple[int, ...]] = ...,
        axis: int = ...,
        keepdims: bool = ...,
        casting: typing.Literal["no", "equiv", "safe", "same_kind", "unsafe"] = ...,
        order: typing.Literal["K", "A", "C", "F"] = ...,
        dtype: numpy.typing.DTypeLike = ...,
        subok: bool = ...,
        signature: typing.Any = ...,
    ) -> numpy.typing.NDArray[numpy.floating[typing.Any]]: ...

class _GUFunc_Nin2_Nout2(numpy.ufunc, typing.Generic[_Name, _Signature]):
    """A numpy generalized ufunc of 2 operand(s) and 2 results."""
    @property
    def __name__(self) -> _Name: ...
    @property
    def signature(self) -> _Signature: ...
    @property
    def nin(self) -> typing.Literal[2]: ...
    @property
    def nout(self) -> typing.Literal[2]: ...
    def __call__(
        self,
        x1: numpy.typing.ArrayLike, x2: numpy.typing.ArrayLike,
        /,
        out: tuple[numpy.ndarray, numpy.ndarray] | None = ...,
        *,
        where: numpy.typing.ArrayLike = ...,
        axes: list[tuple[int, ...]] = ...,
        axis: int = ...,
        keepdims: bool = ...,
        casting: typing.Literal["no", "equiv", "safe", "same_kind", "unsafe"] = ...,
        order: typing.Literal["K", "A", "C", "F"] = ...,
        dtype: numpy.typing.DTypeLike = ...,
        subok: bool = ...,
        signature: typing.Any = ...,
    ) -> tuple[numpy.typing.NDArray[numpy.floating[typing.Any]], numpy.typing.NDArray[numpy.floating[typing.Any]]]: ...

class _GUFunc_Nin3_Nout1(numpy.ufunc, typing.Generic[_Name, _Signature]):
    """A numpy generalized ufunc of 3 operand(s) and one result."""
    @property
    def __name__(self) -> _Name: ...
    @property
    def signature(self) -> _Signature: ...
    @property
    def nin(self) -> typing.Literal[3]: ...
    @property
    def nout(self) -> typing.Literal[1]: ...
    def __call__(
        self,
        x1: numpy.typing.ArrayLike, x2: numpy.typing.ArrayLike, x3: numpy.typing.ArrayLike,
        /,
        out: numpy.ndarray | tuple[numpy.ndarray] | None = ...,
        *,
        where: numpy.typing.ArrayLike = ...,
        axes: list[tuple[int, ...]] = ...,
        axis: int = ...,
        keepdims: bool = ...,
        casting: typing.Literal["no", "equiv", "safe", "same_kind", "unsafe"] = ...,
        order: typing.Literal["K", "A", "C", "F"] = ...,
        dtype: numpy.typing.DTypeLike = ...,
        subok: bool = ...,
        signature: typing.Any = ...,
    ) -> numpy.typing.NDArray[numpy.floating[typing.Any]]: ...

class _GUFunc_Nin4_Nout2(numpy.ufunc, typing.Generic[_Name, _Signature]):
    """A numpy generalized ufunc of 4 operand(s) and 2 results."""
    @property
    def __name__(self) -> _Name: ...
    @property
    def signature(self) -> _Signature: ...
    @property
    def nin(self) -> typing.Literal[4]: ...
    @property
    def nout(self) -> typing.Literal[2]: ...
    def __call__(
        self,
        x1: numpy.typing.ArrayLike, x2: numpy.typing.ArrayLike, x3: numpy.typing.ArrayLike, x4: numpy.typing.ArrayLike,
        /,
        out: tuple[numpy.ndarray, numpy.ndarray] | None = ...,
        *,
        where: numpy.typing.ArrayLike = ...,
        axes: list[tuple[int, ...]] = ...,
        axis: int = ...,
        keepdims: bool = ...,
        casting: typing.Literal["no", "equiv", "safe", "same_kind", "unsafe"] = ...,
        order: typing.Literal["K", "A", "C", "F"] = ...,
        dtype: numpy.typing.DTypeLike = ...,
        subok: bool = ...,
        signature: typing.Any = ...,
    ) -> tuple[numpy.typing.NDArray[numpy.floating[typing.Any]], numpy.typing.NDArray[numpy.floating[typing.Any]]]: ...
class SO3:
    """
    A rotation of R^3: an element of SO(3), stored as its 3x3 matrix (float64).
    
    ``R_ab`` maps coordinates in frame b to frame a: ``p_a = R_ab @ p_b``; its
    columns are b's axes written in a. Composition follows the frames:
    ``R_ac = R_ab @ R_bc``. The tangent space is R^3 (angular velocity, rotation
    vector w), with ``hat(w) @ p = w x p``.
    
    Build one with ``SO3()`` / ``SO3.identity()``, ``SO3.exp(w)``,
    ``SO3.from_quat(q)`` or from a matrix in one of three explicit forms:
    ``from_matrix`` (checked: refuses a matrix that is not a rotation and says by
    how much), ``from_matrix_projected`` (the nearest rotation) and
    ``from_matrix_unchecked`` (no check, for data known to be valid).
    
    Example:
        >>> R = SO3.exp([0.0, 0.0, np.pi / 2])
        >>> np.round(R @ [1.0, 0.0, 0.0], 12) + 0.0
        array([0., 1., 0.])
        >>> np.allclose(R.inverse() @ R @ [1.0, 2.0, 3.0], [1.0, 2.0, 3.0])
        True
    
    Conventions (the same in C++, in README.md and in every docstring):
        - twists xi = (v, w), linear part first (Murray, Li and Sastry); the
          Modern Robotics order (w, v) only through Twist.to_modern_robotics /
          Twist.from_modern_robotics;
        - wrenches F = (f, tau), force first, so power is the dot product V . F;
        - g_ab maps frame b to frame a: q_a = g_ab q_b, g_ac = g_ab @ g_bc;
          twists change frame by Ad_g = [[R, [p]R], [0, R]], wrenches by Ad_g^-T;
        - hat(w) = [w] with [w] p = w x p; [xi] = [[ [w], v ], [0, 0]];
        - quaternions are (x, y, z, w), scalar last, as in scipy; pass
          scalar_first=True for (w, x, y, z); angles are in radians.
    
    Numbers may be given as lists, tuples or arrays of any real dtype (bool,
    integers and floats are converted to float64), in any memory layout; a wrong
    shape is a ValueError naming the expected and the given shape, a value that
    is not real (complex, object, str, None) a TypeError. Constructors refuse NaN
    and infinities (ValueError); functions that return the numbers given,
    rearranged (hat, SO3.vee, SE3.vee, actions on points), carry a NaN through,
    and the defects are inf for a matrix that is not finite.
    
    Values are float64 and immutable. ``==`` is the exact equality of the stored
    numbers, compared as floats (-0.0 == 0.0; a NaN is unequal to everything,
    itself included), ``!=`` its negation, and objects are unhashable; compare
    within a tolerance with ``is_approx(other, tol)``. Objects pickle and copy
    bit-exactly, and ``np.asarray(x)`` gives their matrix or vector.
    """
    _GIMBAL_LOCK_WARNING: typing.ClassVar[str] = 'Gimbal lock detected. Setting third angle to zero since it is not possible to uniquely determine all angles.'
    __array_ufunc__ = None
    __hash__: typing.ClassVar[None] = None
    dtype: typing.ClassVar[numpy.dtypes.Float64DType]
    @staticmethod
    def exp(w: numpy.typing.ArrayLike) -> SO3:
        """
        The rotation exp([w]) of a rotation vector, by Rodrigues' formula.
        
        R = I + (sin theta / theta) [w] + ((1 - cos theta) / theta^2) [w]^2 with
        theta = |w|, exact to a few ulps for every w (Taylor series near 0).
        
        Args:
            w: rotation vector, shape (3,): unit axis times angle in radians.
        
        Returns:
            SO3: exp([w]).
        
        Raises:
            ValueError: w is not of shape (3,), or not finite.
            TypeError: w is not real (complex, object, str, None).
        
        Example:
            >>> R = SO3.exp([0.0, 0.0, np.pi / 2])
            >>> np.round(R.as_matrix(), 12) + 0.0
            array([[ 0., -1.,  0.],
                   [ 1.,  0.,  0.],
                   [ 0.,  0.,  1.]])
        """
    @staticmethod
    def from_euler(seq: str, angles: numpy.typing.ArrayLike, degrees: bool = False) -> SO3:
        """
        The rotation of Euler angles, as scipy's ``Rotation.from_euler``.
        
        ``seq`` is one of the 12 axis sequences, lowercase for extrinsic (fixed
        axes) or uppercase for intrinsic (moving axes). Extrinsic ``"xyz"`` with
        angles (a, b, c) is R = Rz(c) Ry(b) Rx(a); intrinsic ``"XYZ"`` is
        R = Rx(a) Ry(b) Rz(c). Tait-Bryan: xyz, xzy, yxz, yzx, zxy, zyx; proper
        Euler: xyx, xzx, yxy, yzy, zxz, zyz (and their uppercase forms).
        
        Args:
            seq: the sequence, e.g. ``"xyz"``, ``"ZYX"``, ``"zxz"``.
            angles: shape (3,), finite, in the order of ``seq``'s letters.
            degrees: the angles are in degrees (default radians).
        
        Returns:
            SO3: the rotation.
        
        Raises:
            TypeError: seq is not a str.
            ValueError: seq is not one of the 24 sequences; angles of a wrong shape
                or not finite.
        
        Example:
            >>> R = SO3.from_euler("xyz", [90.0, 0.0, 0.0], degrees=True)
            >>> np.round(R.as_matrix(), 12) + 0.0
            array([[ 1.,  0.,  0.],
                   [ 0.,  0., -1.],
                   [ 0.,  1.,  0.]])
        """
    @staticmethod
    def from_matrix(matrix: numpy.typing.ArrayLike, tol: float = 1.4901161193847656e-08) -> SO3:
        """
        Checked construction from a rotation matrix.
        
        Accepts M when its rotation defect max(|M^T M - I|_max, |det M - 1|) is at
        most tol (default sqrt(eps) = 1.49e-08: data printed with about 9 significant
        digits passes). Keeps M as it is (no projection).
        
        Args:
            matrix: shape (3, 3), finite.
            tol: the largest accepted defect.
        
        Returns:
            SO3: the rotation M.
        
        Raises:
            ValueError: M is not a rotation within tol (the message gives the defect
                and det M; use ``SO3.from_matrix_projected`` for the nearest
                rotation), or M is not finite, or not of shape (3, 3).
        
        Example:
            >>> R = SO3.from_matrix([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
            >>> np.round(R.log(), 12) + 0.0
            array([0.        , 0.        , 1.57079633])
        """
    @staticmethod
    def from_matrix_projected(matrix: numpy.typing.ArrayLike) -> SO3:
        """
        The rotation nearest to a matrix in the Frobenius norm.
        
        For det M > 0 this is the orthogonal polar factor; it is defined for every
        finite M, reflections and singular matrices included.
        
        Args:
            matrix: shape (3, 3), finite.
        
        Returns:
            SO3: the nearest rotation.
        
        Example:
            >>> M = SO3.exp([0.1, 0.2, 0.3]).as_matrix() + 1e-4
            >>> SO3.from_matrix_projected(M).is_approx(SO3.exp([0.1, 0.2, 0.3]), tol=1e-3)
            True
        """
    @staticmethod
    def from_matrix_unchecked(matrix: numpy.typing.ArrayLike) -> SO3:
        """
        Construction without a check, for data known to be a rotation.
        
        Only the shape and finiteness are checked. Operations on an SO3 built from a
        matrix that is not a rotation give meaningless results.
        
        Args:
            matrix: shape (3, 3), finite.
        
        Returns:
            SO3: the matrix as it is.
        """
    @staticmethod
    def from_quat(quat: numpy.typing.ArrayLike, *, scalar_first: bool = False) -> SO3:
        """
        The rotation of a quaternion of any nonzero norm (it is normalized).
        
        Args:
            quat: shape (4,): (x, y, z, w), scalar last, as in scipy; or
                (w, x, y, z) with scalar_first=True. Finite and nonzero.
            scalar_first: whether the scalar part comes first.
        
        Returns:
            SO3: the rotation.
        
        Raises:
            ValueError: the zero quaternion, a non-finite one, or a wrong shape.
        
        Example:
            >>> s = np.sqrt(0.5)
            >>> np.round(SO3.from_quat([0.0, 0.0, s, s]).log(), 12) + 0.0
            array([0.        , 0.        , 1.57079633])
            >>> SO3.from_quat([1.0, 0.0, 0.0, 0.0], scalar_first=True).is_approx(SO3())
            True
        """
    @staticmethod
    def from_rpy(rpy: numpy.typing.ArrayLike, degrees: bool = False) -> SO3:
        """
        The rotation of roll, pitch and yaw, URDF's ``rpy`` and ROS tf's setRPY.
        
        About the fixed axes x, y and z in that order: R = Rz(yaw) Ry(pitch)
        Rx(roll), i.e. ``SO3.from_euler("xyz", rpy)`` (scipy's extrinsic "xyz").
        
        Args:
            rpy: shape (3,), (roll, pitch, yaw), finite.
            degrees: the angles are in degrees (default radians).
        
        Returns:
            SO3: the rotation.
        
        Example:
            >>> SO3.from_rpy([0.1, 0.2, 0.3]) == SO3.from_euler("xyz", [0.1, 0.2, 0.3])
            True
        """
    @staticmethod
    def from_scipy(r: typing.Any) -> SO3:
        """
        The rotation of a single scipy.spatial.transform.Rotation.
        
        scipy is imported by this call (it is not needed by ``import chasles``).
        The rotation is read from scipy's unit quaternion, as ``SO3.from_quat``.
        For a stack of rotations use the array functions on ``r.as_matrix()``
        (shape (N, 3, 3)), or ``chasles.so3_from_quat(r.as_quat())``.
        
        Args:
            r: a single scipy.spatial.transform.Rotation.
        
        Returns:
            SO3: the same rotation.
        
        Raises:
            TypeError: r is not a Rotation.
            ValueError: r is a stack of rotations.
            ImportError: scipy is not installed.
        
        Example:
            >>> from scipy.spatial.transform import Rotation
            >>> R = SO3.from_scipy(Rotation.from_rotvec([0.0, 0.0, 0.5]))
            >>> np.round(R.log(), 12) + 0.0
            array([0. , 0. , 0.5])
        """
    @staticmethod
    def hat(w: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
        """
        The skew-symmetric matrix [w] of w, so that [w] @ p = w x p.
        
        Args:
            w: vector, shape (3,).
        
        Returns:
            ndarray: [w] = [[0, -w3, w2], [w3, 0, -w1], [-w2, w1, 0]], shape (3, 3).
        
        Example:
            >>> SO3.hat([1.0, 2.0, 3.0])
            array([[ 0., -3.,  2.],
                   [ 3.,  0., -1.],
                   [-2.,  1.,  0.]])
        """
    @staticmethod
    def identity() -> SO3:
        """
        The identity rotation.
        
        Returns:
            SO3: the identity.
        
        Example:
            >>> SO3.identity().is_approx(SO3.exp([0.0, 0.0, 0.0]))
            True
        """
    @staticmethod
    def interpolate(a: SO3, b: SO3, t: float) -> SO3:
        """
        Geodesic interpolation a exp(t log(a^-1 b)).
        
        t = 0 gives a, t = 1 gives b, in between, the rotation about one fixed axis
        (slerp). Values outside [0, 1] extrapolate.
        
        Args:
            a: SO3, the start.
            b: SO3, the end.
            t: the fraction, finite.
        
        Returns:
            SO3: the interpolated rotation.
        
        Example:
            >>> a, b = SO3(), SO3.exp([0.3, 0.2, 0.1])
            >>> SO3.interpolate(a, b, 0.5).is_approx(a @ SO3.exp(0.5 * np.array([0.3, 0.2, 0.1])))
            True
        """
    @staticmethod
    def left_jacobian(w: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
        """
        The left Jacobian J_l of SO(3) at the rotation vector w, shape (3, 3).
        
        Right (local) convention, as manif and Pinocchio:
        exp(w + dw) = exp(w) exp(J_r(w) dw + o(dw)) and
        exp(w + dw) = exp(J_l(w) dw + o(dw)) exp(w), with
        J_r(w) = I - B [w] + C [w]^2, J_l(w) = J_r(-w) = I + B [w] + C [w]^2,
        B = (1 - cos theta) / theta^2, C = (theta - sin theta) / theta^3;
        J_r^-1 = I + 1/2 [w] + D [w]^2, J_l^-1 = I - 1/2 [w] + D [w]^2,
        D = (1 - (theta/2) cot(theta/2)) / theta^2 (finite for |w| < 2 pi).
        
        Args:
            w: rotation vector, shape (3,), finite.
        
        Returns:
            ndarray: shape (3, 3), float64.
        
        Raises:
            ValueError: w is not of shape (3,), or not finite.
            TypeError: w is not real.
        """
    @staticmethod
    def left_jacobian_inverse(w: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
        """
        The inverse left Jacobian J_l^-1 of SO(3) at the rotation vector w, shape (3, 3).
        
        Right (local) convention, as manif and Pinocchio:
        exp(w + dw) = exp(w) exp(J_r(w) dw + o(dw)) and
        exp(w + dw) = exp(J_l(w) dw + o(dw)) exp(w), with
        J_r(w) = I - B [w] + C [w]^2, J_l(w) = J_r(-w) = I + B [w] + C [w]^2,
        B = (1 - cos theta) / theta^2, C = (theta - sin theta) / theta^3;
        J_r^-1 = I + 1/2 [w] + D [w]^2, J_l^-1 = I - 1/2 [w] + D [w]^2,
        D = (1 - (theta/2) cot(theta/2)) / theta^2 (finite for |w| < 2 pi).
        
        Args:
            w: rotation vector, shape (3,), finite.
        
        Returns:
            ndarray: shape (3, 3), float64.
        
        Raises:
            ValueError: w is not of shape (3,), or not finite.
            TypeError: w is not real.
        """
    @staticmethod
    def random(rng: typing.Any = None) -> SO3:
        """
        A uniform random rotation (the Haar measure), as scipy's Rotation.random().
        
        Shoemake's method over three uniforms drawn from ``rng``: one element of
        ``chasles.so3_random``.
        
        Args:
            rng: None (a fresh ``numpy.random.default_rng()``), an int seed or a
                numpy Generator.
        
        Returns:
            SO3: the rotation.
        
        Example:
            >>> SO3.random(rng=7).is_approx(SO3.random(rng=7), 0.0)
            True
        """
    @staticmethod
    def right_jacobian(w: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
        """
        The right Jacobian J_r of SO(3) at the rotation vector w, shape (3, 3).
        
        Right (local) convention, as manif and Pinocchio:
        exp(w + dw) = exp(w) exp(J_r(w) dw + o(dw)) and
        exp(w + dw) = exp(J_l(w) dw + o(dw)) exp(w), with
        J_r(w) = I - B [w] + C [w]^2, J_l(w) = J_r(-w) = I + B [w] + C [w]^2,
        B = (1 - cos theta) / theta^2, C = (theta - sin theta) / theta^3;
        J_r^-1 = I + 1/2 [w] + D [w]^2, J_l^-1 = I - 1/2 [w] + D [w]^2,
        D = (1 - (theta/2) cot(theta/2)) / theta^2 (finite for |w| < 2 pi).
        
        Args:
            w: rotation vector, shape (3,), finite.
        
        Returns:
            ndarray: shape (3, 3), float64.
        
        Raises:
            ValueError: w is not of shape (3,), or not finite.
            TypeError: w is not real.
        """
    @staticmethod
    def right_jacobian_inverse(w: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
        """
        The inverse right Jacobian J_r^-1 of SO(3) at the rotation vector w, shape (3, 3).
        
        Right (local) convention, as manif and Pinocchio:
        exp(w + dw) = exp(w) exp(J_r(w) dw + o(dw)) and
        exp(w + dw) = exp(J_l(w) dw + o(dw)) exp(w), with
        J_r(w) = I - B [w] + C [w]^2, J_l(w) = J_r(-w) = I + B [w] + C [w]^2,
        B = (1 - cos theta) / theta^2, C = (theta - sin theta) / theta^3;
        J_r^-1 = I + 1/2 [w] + D [w]^2, J_l^-1 = I - 1/2 [w] + D [w]^2,
        D = (1 - (theta/2) cot(theta/2)) / theta^2 (finite for |w| < 2 pi).
        
        Args:
            w: rotation vector, shape (3,), finite.
        
        Returns:
            ndarray: shape (3, 3), float64.
        
        Raises:
            ValueError: w is not of shape (3,), or not finite.
            TypeError: w is not real.
        """
    @staticmethod
    def rotation_defect(matrix: numpy.typing.ArrayLike) -> float:
        """
        How far a matrix is from a rotation: max(|M^T M - I|_max, |det M - 1|).
        
        0 for a rotation, about 2d for a rotation whose entries are off by d, 2 for
        a reflection, inf for a matrix that is not finite.
        
        Args:
            matrix: shape (3, 3).
        
        Returns:
            float: the defect.
        
        Example:
            >>> SO3.rotation_defect(np.diag([1.0, 1.0, -1.0]))
            2.0
        """
    @staticmethod
    def vee(matrix: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
        """
        The vector w of a skew-symmetric matrix [w]: the inverse of hat.
        
        Reads the antisymmetric part (W - W^T)/2, so a matrix that is not exactly
        skew gives the w of its nearest skew matrix.
        
        Args:
            matrix: shape (3, 3).
        
        Returns:
            ndarray: w, shape (3,).
        
        Example:
            >>> SO3.vee(SO3.hat([1.0, 2.0, 3.0]))
            array([1., 2., 3.])
        """
    def __array__(self, dtype: numpy.typing.DTypeLike = None, copy: bool | None = None) -> numpy.ndarray:
        """
        The rotation matrix, shape (3, 3), for np.asarray (numpy's dtype and copy keywords).
        """
    def __copy__(self) -> SO3:
        ...
    def __deepcopy__(self, memo: typing.Any) -> SO3:
        ...
    def __eq__(self, other: typing.Any) -> bool:
        """
        Exact equality of the stored numbers: SO3s are values, compared as floats
        (-0.0 == 0.0; a NaN is unequal to everything, itself included).
        
        For a tolerance, use ``is_approx(other, tol)``. An object of another type gives
        NotImplemented, so ``==`` is False. SO3s are unhashable.
        
        Args:
            other: any object.
        
        Returns:
            bool.
        """
    def __getstate__(self) -> tuple:
        ...
    def __init__(self) -> None:
        """
        The identity rotation.
        
        Example:
            >>> SO3().as_matrix()
            array([[1., 0., 0.],
                   [0., 1., 0.],
                   [0., 0., 1.]])
        """
    @typing.overload
    def __matmul__(self, other: SO3) -> SO3:
        """
        Composition: g_ab @ g_bc = g_ac.
        
        Args:
            other: SO3.
        
        Returns:
            SO3: the composed rotation.
        """
    @typing.overload
    def __matmul__(self, points: numpy.typing.ArrayLike) -> typing.Any:
        """
        Action on points or vectors: p_a = R_ab p_b.
        
        The array function so3_act with this rotation: numpy's rules for dtypes and
        broadcasting.
        
        Args:
            points: array_like of shape (..., 3).
        
        Returns:
            ndarray: the rotated points, shape (..., 3).
        """
    def __ne__(self, other: typing.Any) -> bool:
        """
        The negation of ``==``: some stored number differs (or is NaN), or other is not a SO3.
        
        Args:
            other: any object.
        
        Returns:
            bool.
        """
    def __pow__(self, t: float) -> SO3:
        """
        The power exp(t log g): t = 0 gives the identity, t = 1
        this rotation, t = -1 its inverse, t = 0.5 the rotation half way along its
        geodesic from the identity (the one whose square it is, for angles below pi),
        as scipy's ``Rotation.__pow__``.
        
        Args:
            t: the exponent, finite (not only an integer).
        
        Returns:
            SO3: the power.
        
        Example:
            >>> g = SO3.exp([0.3, 0.2, 0.1])
            >>> ((g ** 0.5) @ (g ** 0.5)).is_approx(g) and (g ** -1).is_approx(g.inverse())
            True
        """
    def __reduce__(self) -> tuple[typing.Any, tuple[typing.Any], typing.Any]:
        """
        Pickle support: (copyreg.__newobj__, (cls,), state).
        """
    def __reduce_ex__(self, protocol: typing.SupportsInt | typing.SupportsIndex) -> tuple[typing.Any, tuple[typing.Any], typing.Any]:
        """
        Pickle support (every protocol): (copyreg.__newobj__, (cls,), state).
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: typing.Any) -> None:
        ...
    def act(self, points: numpy.typing.ArrayLike) -> typing.Any:
        """
        Action on points or vectors: p_a = R_ab p_b (the same as ``R @ points``).
        
        The array function so3_act with this rotation: numpy's rules for dtypes and
        broadcasting.
        
        Args:
            points: array_like of shape (..., 3).
        
        Returns:
            ndarray: the rotated points, shape (..., 3).
        
        Example:
            >>> R = SO3.exp([0.0, 0.0, np.pi])
            >>> np.round(R.act([[1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]), 12) + 0.0
            array([[-1.,  0.,  0.],
                   [ 0.,  0.,  1.]])
        """
    def adjoint(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        The adjoint Ad_R = R (3x3), so that R exp([w]) R^T = exp([R w]).
        
        Returns:
            ndarray: shape (3, 3).
        """
    def angle(self) -> float:
        """
        The rotation angle theta = |log()| in [0, pi], radians.
        
        From the halves of the quaternion, theta = 2 atan2(|q_v|, |q_w|), accurate
        to a few ulps near 0 and near pi (acos of the trace loses half the digits
        there). scipy: ``Rotation.magnitude()``.
        
        Returns:
            float: the angle.
        
        Example:
            >>> round(SO3.exp([0.0, 0.0, 0.5]).angle(), 12)
            0.5
        """
    def as_euler(self, seq: str, degrees: bool = False, *, return_gimbal_lock: bool = False) -> typing.Any:
        """
        Euler angles of the rotation, as scipy's ``Rotation.as_euler``.
        
        scipy's ranges: the middle angle in [-pi/2, pi/2] for Tait-Bryan sequences
        (three distinct axes), [0, pi] for proper Euler sequences (first axis =
        last), the others in [-pi, pi]. At the gimbal lock (middle angle +-pi/2, or
        0 or pi, to working precision) only the sum or difference of the outer
        angles is defined, and the third angle is zero, with scipy's UserWarning
        (not with return_gimbal_lock=True, which returns the flag). Robust there:
        ``SO3.from_euler(seq, R.as_euler(seq))`` reproduces R to a few ulps for
        every rotation (atan2 of well-conditioned pairs of entries; scipy declares
        the lock within 1e-7 of it and loses up to 1e-7 there).
        
        Args:
            seq: the sequence, e.g. ``"xyz"``, ``"ZYX"``, ``"zxz"`` (see from_euler).
            degrees: return degrees (default radians).
            return_gimbal_lock: also return whether the rotation is at the gimbal
                lock (the third angle was set to zero).
        
        Returns:
            ndarray: shape (3,), the angles in the order of ``seq``'s letters; with
            return_gimbal_lock=True the tuple (angles, gimbal_lock: bool).
        
        Example:
            >>> R = SO3.from_euler("ZYX", [0.3, -0.2, 0.1])
            >>> np.round(R.as_euler("ZYX"), 12)
            array([ 0.3, -0.2,  0.1])
        """
    def as_matrix(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        The rotation matrix R.
        
        Returns:
            ndarray: shape (3, 3), float64 (a new array).
        """
    def as_quat(self, *, scalar_first: bool = False) -> numpy.typing.NDArray[numpy.float64]:
        """
        The unit quaternion of the rotation (Shepperd's method).
        
        q and -q are the same rotation; the sign returned makes the component of
        largest magnitude positive.
        
        Args:
            scalar_first: False (default) for (x, y, z, w), as in scipy; True for
                (w, x, y, z).
        
        Returns:
            ndarray: shape (4,), unit norm.
        
        Example:
            >>> SO3().as_quat()
            array([0., 0., 0., 1.])
            >>> SO3().as_quat(scalar_first=True)
            array([1., 0., 0., 0.])
        """
    def as_rpy(self, degrees: bool = False, *, return_gimbal_lock: bool = False) -> typing.Any:
        """
        Roll, pitch and yaw of the rotation (URDF, ROS tf's getRPY).
        
        ``R.as_euler("xyz")``: R = Rz(yaw) Ry(pitch) Rx(roll), pitch in
        [-pi/2, pi/2], roll and yaw in [-pi, pi]; at the gimbal lock (pitch +-pi/2)
        yaw is zero, with scipy's UserWarning (not with return_gimbal_lock=True).
        
        Args:
            degrees: return degrees (default radians).
            return_gimbal_lock: also return whether pitch is at +-pi/2 (yaw was set
                to zero).
        
        Returns:
            ndarray: shape (3,), (roll, pitch, yaw); with return_gimbal_lock=True the
            tuple (rpy, gimbal_lock: bool).
        
        Example:
            >>> np.round(SO3.from_rpy([0.1, 0.2, 0.3]).as_rpy(), 12)
            array([0.1, 0.2, 0.3])
        """
    def inverse(self) -> SO3:
        """
        The inverse rotation R^-1 = R^T.
        
        Returns:
            SO3: the inverse.
        
        Example:
            >>> g = SO3.exp([0.3, 0.2, 0.1])
            >>> (g @ g.inverse()).is_approx(SO3.identity())
            True
        """
    def is_approx(self, other: SO3, tol: float = 1e-09) -> bool:
        """
        Whether two rotations are equal within tol: max |R_a - R_b| <= tol.
        
        ``==`` is the exact comparison (every stored number equal).
        
        Args:
            other: SO3.
            tol: the largest accepted difference of matrix entries (>= 0).
        
        Returns:
            bool.
        """
    def log(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        The rotation vector w with exp([w]) = R and |w| in [0, pi].
        
        At exactly pi both axis signs are correct; one of them is returned, never
        NaN. Accurate to a few ulps, and to O(d) for a matrix off SO(3) by d.
        
        Returns:
            ndarray: w, shape (3,), float64.
        
        Example:
            >>> SO3.exp([0.1, -0.2, 0.3]).log()
            array([ 0.1, -0.2,  0.3])
        """
    def normalized(self) -> SO3:
        """
        The same rotation with the nearest rotation.
        
        Removes the drift that accumulates over many compositions.
        
        Returns:
            SO3: the projected rotation.
        """
    def to_scipy(self) -> typing.Any:
        """
        This rotation as a scipy.spatial.transform.Rotation.
        
        scipy is imported by this call (it is not needed by ``import chasles``).
        scipy's ``Rotation.from_matrix(R)`` works too (``np.asarray(R)`` is the
        matrix); for many rotations, ``Rotation.from_matrix`` of an array of shape
        (N, 3, 3).
        
        Returns:
            scipy.spatial.transform.Rotation: a single rotation, from the unit
            quaternion of ``as_quat()``.
        
        Raises:
            ImportError: scipy is not installed.
        
        Example:
            >>> SO3.exp([0.0, 0.0, 0.5]).to_scipy().as_rotvec().round(12) + 0.0
            array([0. , 0. , 0.5])
        """
class SE3:
    """
    A rigid motion of R^3: an element of SE(3), stored as a rotation R (an SO3)
    and a translation p (float64). Its 4x4 matrix is g = [[R, p], [0, 1]].
    
    ``g_ab`` maps coordinates in frame b to frame a: ``q_a = R_ab q_b + p_ab``
    (``g @ q``), and composes along the frames: ``g_ac = g_ab @ g_bc``. The
    tangent space is the space of twists xi = (v, w), linear part first (Murray,
    Li and Sastry); exp([xi]) is the screw motion of Chasles' theorem. Twists
    change frame by Ad_g = [[R, [p] R], [0, R]] (``g.act(twist)``); wrenches by
    Ad_g^-T (``g.act(wrench)``), so power is invariant.
    
    Example:
        >>> g = SE3(SO3.exp([0.0, 0.0, np.pi / 2]), [1.0, 2.0, 3.0])
        >>> np.round(g @ [1.0, 0.0, 0.0], 12) + 0.0
        array([1., 3., 3.])
        >>> SE3.exp(g.log()).is_approx(g)
        True
    
    Conventions (the same in C++, in README.md and in every docstring):
        - twists xi = (v, w), linear part first (Murray, Li and Sastry); the
          Modern Robotics order (w, v) only through Twist.to_modern_robotics /
          Twist.from_modern_robotics;
        - wrenches F = (f, tau), force first, so power is the dot product V . F;
        - g_ab maps frame b to frame a: q_a = g_ab q_b, g_ac = g_ab @ g_bc;
          twists change frame by Ad_g = [[R, [p]R], [0, R]], wrenches by Ad_g^-T;
        - hat(w) = [w] with [w] p = w x p; [xi] = [[ [w], v ], [0, 0]];
        - quaternions are (x, y, z, w), scalar last, as in scipy; pass
          scalar_first=True for (w, x, y, z); angles are in radians.
    
    Numbers may be given as lists, tuples or arrays of any real dtype (bool,
    integers and floats are converted to float64), in any memory layout; a wrong
    shape is a ValueError naming the expected and the given shape, a value that
    is not real (complex, object, str, None) a TypeError. Constructors refuse NaN
    and infinities (ValueError); functions that return the numbers given,
    rearranged (hat, SO3.vee, SE3.vee, actions on points), carry a NaN through,
    and the defects are inf for a matrix that is not finite.
    
    Values are float64 and immutable. ``==`` is the exact equality of the stored
    numbers, compared as floats (-0.0 == 0.0; a NaN is unequal to everything,
    itself included), ``!=`` its negation, and objects are unhashable; compare
    within a tolerance with ``is_approx(other, tol)``. Objects pickle and copy
    bit-exactly, and ``np.asarray(x)`` gives their matrix or vector.
    """
    __array_ufunc__ = None
    __hash__: typing.ClassVar[None] = None
    dtype: typing.ClassVar[numpy.dtypes.Float64DType]
    @staticmethod
    def exp(xi: numpy.typing.ArrayLike) -> SE3:
        """
        The screw motion exp([xi]) of a twist xi = (v, w), linear part first.
        
        In closed form, with theta = |w|: R = exp([w]), p = V v,
        V = I + ((1 - cos theta) / theta^2) [w] + ((theta - sin theta) / theta^3) [w]^2;
        w = 0 (pure translation) and tiny w included, exact to a few ulps.
        
        Args:
            xi: twist coordinates (v, w), shape (6,), finite; or a Twist.
        
        Returns:
            SE3: exp([xi]).
        
        Example:
            >>> g = SE3.exp([1.0, 0.0, 0.0, 0.0, 0.0, np.pi / 2])
            >>> np.round(g.translation, 12) + 0.0
            array([0.63661977, 0.63661977, 0.        ])
        """
    @staticmethod
    def from_matrix(matrix: numpy.typing.ArrayLike, tol: float = 1.4901161193847656e-08) -> SE3:
        """
        Checked construction from a 4x4 homogeneous matrix [[R, p], [0, 1]].
        
        Accepts M when the rotation defect of its top-left block,
        max(|R^T R - I|_max, |det R - 1|), and the deviation of its bottom row from
        (0, 0, 0, 1) are both at most tol (default sqrt(eps) = 1.49e-08).
        
        Args:
            matrix: shape (4, 4), finite.
            tol: the largest accepted defect.
        
        Returns:
            SE3: the motion.
        
        Raises:
            ValueError: M is not a rigid motion within tol (the message gives both
                defects; use ``SE3.from_matrix_projected`` for the nearest rotation),
                or M is not finite, or not of shape (4, 4).
        
        Example:
            >>> SE3.from_matrix(np.eye(4)).is_approx(SE3())
            True
        """
    @staticmethod
    def from_matrix_projected(matrix: numpy.typing.ArrayLike) -> SE3:
        """
        The nearest rotation to the top-left block, and the translation column.
        
        The bottom row is not read.
        
        Args:
            matrix: shape (4, 4), finite.
        
        Returns:
            SE3: the projected motion.
        """
    @staticmethod
    def from_matrix_unchecked(matrix: numpy.typing.ArrayLike) -> SE3:
        """
        Construction without a check from [[R, p], [*, *]], for valid data.
        
        Only the shape and finiteness are checked; the bottom row is not read.
        
        Args:
            matrix: shape (4, 4), finite.
        
        Returns:
            SE3: the motion.
        """
    @staticmethod
    def from_scipy(tf: typing.Any) -> SE3:
        """
        The motion of a single scipy.spatial.transform.RigidTransform.
        
        scipy (1.16 or later) is imported by this call (it is not needed by
        ``import chasles``). The motion is read from scipy's 4x4 matrix, checked as
        by ``SE3.from_matrix``. For a stack of transforms use the array functions on
        ``tf.as_matrix()`` (shape (N, 4, 4)).
        
        Args:
            tf: a single scipy.spatial.transform.RigidTransform.
        
        Returns:
            SE3: the same motion.
        
        Raises:
            TypeError: tf is not a RigidTransform.
            ValueError: tf is a stack of transforms, or its matrix is not a rigid
                motion (a transform built with normalize=False).
            ImportError: scipy (or RigidTransform, scipy < 1.16) is missing.
        
        Example:
            >>> from scipy.spatial.transform import RigidTransform
            >>> SE3.from_scipy(RigidTransform.from_translation([1.0, 2.0, 3.0])).translation
            array([1., 2., 3.])
        """
    @staticmethod
    def from_screw(point: numpy.typing.ArrayLike, direction: numpy.typing.ArrayLike, pitch: float, theta: float) -> SE3:
        """
        The screw motion about an axis: exp(theta * (-d x q + h d, d)).
        
        Rotates by theta about the line through q along d (normalized here) while
        translating by h * theta along it; pitch = inf is the pure translation
        theta * d. A zero direction gives the identity (the screw of the zero
        twist).
        
        Args:
            point: q, a point of the axis, shape (3,).
            direction: d, the axis direction, shape (3,) (any nonzero length).
            pitch: h, translation per radian; ``math.inf`` for a translation.
            theta: the rotation angle in radians (the distance for pitch = inf).
        
        Returns:
            SE3: the screw motion.
        
        Example:
            >>> g = SE3.from_screw([0.0, 2.0, 0.0], [0.0, 0.0, 1.0], 0.0, np.pi / 2)
            >>> np.round(g.translation, 12) + 0.0
            array([2., 2., 0.])
            >>> np.round(g @ [0.0, 2.0, 5.0], 12) + 0.0
            array([0., 2., 5.])
        """
    @staticmethod
    def hat(xi: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
        """
        The 4x4 matrix [xi] = [[ [w], v ], [0, 0]] of a twist xi = (v, w).
        
        Args:
            xi: shape (6,), (v, w).
        
        Returns:
            ndarray: shape (4, 4).
        
        Example:
            >>> SE3.hat([1.0, 2.0, 3.0, 0.0, 0.0, 1.0]) + 0.0
            array([[ 0., -1.,  0.,  1.],
                   [ 1.,  0.,  0.,  2.],
                   [ 0.,  0.,  0.,  3.],
                   [ 0.,  0.,  0.,  0.]])
        """
    @staticmethod
    def identity() -> SE3:
        """
        The identity motion.
        
        Returns:
            SE3: the identity.
        """
    @staticmethod
    def interpolate(a: SE3, b: SE3, t: float) -> SE3:
        """
        Geodesic interpolation a exp(t log(a^-1 b)).
        
        t = 0 gives a, t = 1 gives b, and the motion in between is one screw motion.
        
        Args:
            a: SE3, the start.
            b: SE3, the end.
            t: the fraction, finite.
        
        Returns:
            SE3: the interpolated rigid motion.
        
        Example:
            >>> a, b = SE3(), SE3.exp([0.1, 0.2, 0.3, 0.4, 0.5, 0.6])
            >>> SE3.interpolate(a, b, 0.5).is_approx(a @ SE3.exp(0.5 * np.array([0.1, 0.2, 0.3, 0.4, 0.5, 0.6])))
            True
        """
    @staticmethod
    def left_jacobian(xi: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
        """
        The left Jacobian J_l of SE(3) at the twist xi = (v, w), shape (6, 6).
        
        Linear part first. Right (local) convention, as manif and Pinocchio:
        exp(xi + dxi) = exp(xi) exp(J_r(xi) dxi + o(dxi)) and
        exp(xi + dxi) = exp(J_l(xi) dxi + o(dxi)) exp(xi), with
        J_l(xi) = [[J_l(w), Q(v, w)], [0, J_l(w)]] (Barfoot; Sola et al. 2018,
        eq. 180), J_r(xi) = J_l(-xi), and the inverses by the block formula
        [[J^-1, -J^-1 Q J^-1], [0, J^-1]].
        
        Args:
            xi: twist (v, w), shape (6,), finite.
        
        Returns:
            ndarray: shape (6, 6), float64.
        
        Raises:
            ValueError: xi is not of shape (6,), or not finite.
            TypeError: xi is not real.
        """
    @staticmethod
    def left_jacobian_inverse(xi: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
        """
        The inverse left Jacobian J_l^-1 of SE(3) at the twist xi = (v, w), shape (6, 6).
        
        Linear part first. Right (local) convention, as manif and Pinocchio:
        exp(xi + dxi) = exp(xi) exp(J_r(xi) dxi + o(dxi)) and
        exp(xi + dxi) = exp(J_l(xi) dxi + o(dxi)) exp(xi), with
        J_l(xi) = [[J_l(w), Q(v, w)], [0, J_l(w)]] (Barfoot; Sola et al. 2018,
        eq. 180), J_r(xi) = J_l(-xi), and the inverses by the block formula
        [[J^-1, -J^-1 Q J^-1], [0, J^-1]].
        
        Args:
            xi: twist (v, w), shape (6,), finite.
        
        Returns:
            ndarray: shape (6, 6), float64.
        
        Raises:
            ValueError: xi is not of shape (6,), or not finite.
            TypeError: xi is not real.
        """
    @staticmethod
    def random(rng: typing.Any = None, *, low: typing.Any = -1.0, high: typing.Any = 1.0) -> SE3:
        """
        A random rigid motion: a uniform rotation and a translation uniform in a box.
        
        One element of ``chasles.se3_random``: the rotation as SO3.random, then the
        translation uniform in [low, high] componentwise.
        
        Args:
            rng: None (a fresh ``numpy.random.default_rng()``), an int seed or a
                numpy Generator.
            low: float or array_like of shape (3,): the box's lower corner.
            high: float or array_like of shape (3,): the box's upper corner.
        
        Returns:
            SE3: the pose.
        
        Example:
            >>> g = SE3.random(rng=1, low=0.0, high=0.5)
            >>> bool(np.all((0.0 <= g.translation) & (g.translation <= 0.5)))
            True
        """
    @staticmethod
    def right_jacobian(xi: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
        """
        The right Jacobian J_r of SE(3) at the twist xi = (v, w), shape (6, 6).
        
        Linear part first. Right (local) convention, as manif and Pinocchio:
        exp(xi + dxi) = exp(xi) exp(J_r(xi) dxi + o(dxi)) and
        exp(xi + dxi) = exp(J_l(xi) dxi + o(dxi)) exp(xi), with
        J_l(xi) = [[J_l(w), Q(v, w)], [0, J_l(w)]] (Barfoot; Sola et al. 2018,
        eq. 180), J_r(xi) = J_l(-xi), and the inverses by the block formula
        [[J^-1, -J^-1 Q J^-1], [0, J^-1]].
        
        Args:
            xi: twist (v, w), shape (6,), finite.
        
        Returns:
            ndarray: shape (6, 6), float64.
        
        Raises:
            ValueError: xi is not of shape (6,), or not finite.
            TypeError: xi is not real.
        """
    @staticmethod
    def right_jacobian_inverse(xi: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
        """
        The inverse right Jacobian J_r^-1 of SE(3) at the twist xi = (v, w), shape (6, 6).
        
        Linear part first. Right (local) convention, as manif and Pinocchio:
        exp(xi + dxi) = exp(xi) exp(J_r(xi) dxi + o(dxi)) and
        exp(xi + dxi) = exp(J_l(xi) dxi + o(dxi)) exp(xi), with
        J_l(xi) = [[J_l(w), Q(v, w)], [0, J_l(w)]] (Barfoot; Sola et al. 2018,
        eq. 180), J_r(xi) = J_l(-xi), and the inverses by the block formula
        [[J^-1, -J^-1 Q J^-1], [0, J^-1]].
        
        Args:
            xi: twist (v, w), shape (6,), finite.
        
        Returns:
            ndarray: shape (6, 6), float64.
        
        Raises:
            ValueError: xi is not of shape (6,), or not finite.
            TypeError: xi is not real.
        """
    @staticmethod
    def transform_defect(matrix: numpy.typing.ArrayLike) -> float:
        """
        How far a 4x4 matrix is from a rigid motion.
        
        The rotation defect of its top-left block (SO3.rotation_defect) or the
        largest deviation of its bottom row from (0, 0, 0, 1), whichever is larger.
        
        Args:
            matrix: shape (4, 4).
        
        Returns:
            float: the defect.
        """
    @staticmethod
    def vee(matrix: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
        """
        The twist (v, w) of a 4x4 matrix [[S, v], [*, *]]: the inverse of hat.
        
        w is read from the antisymmetric part of S; the bottom row is ignored.
        
        Args:
            matrix: shape (4, 4).
        
        Returns:
            ndarray: xi = (v, w), shape (6,).
        """
    def __array__(self, dtype: numpy.typing.DTypeLike = None, copy: bool | None = None) -> numpy.ndarray:
        """
        The homogeneous matrix, shape (4, 4), for np.asarray (numpy's dtype and copy keywords).
        """
    def __copy__(self) -> SE3:
        ...
    def __deepcopy__(self, memo: typing.Any) -> SE3:
        ...
    def __eq__(self, other: typing.Any) -> bool:
        """
        Exact equality of the stored numbers: SE3s are values, compared as floats
        (-0.0 == 0.0; a NaN is unequal to everything, itself included).
        
        For a tolerance, use ``is_approx(other, tol)``. An object of another type gives
        NotImplemented, so ``==`` is False. SE3s are unhashable.
        
        Args:
            other: any object.
        
        Returns:
            bool.
        """
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, rotation: SO3 = ..., translation: numpy.typing.ArrayLike = (0.0, 0.0, 0.0)) -> None:
        """
        The rigid motion g = [[R, p], [0, 1]] of a rotation and a translation.
        
        Args:
            rotation: SO3, R (default: the identity).
            translation: shape (3,), p, finite (default: 0).
        
        Example:
            >>> SE3(translation=[1.0, 2.0, 3.0]).translation
            array([1., 2., 3.])
        """
    @typing.overload
    def __matmul__(self, other: SE3) -> SE3:
        """
        Composition: g_ab @ g_bc = g_ac.
        
        Args:
            other: SE3.
        
        Returns:
            SE3: the composed rigid motion.
        """
    @typing.overload
    def __matmul__(self, points: numpy.typing.ArrayLike) -> typing.Any:
        """
        Action on points: q_a = R q_b + p.
        
        The array function se3_act with this rigid motion: numpy's rules for dtypes and
        broadcasting.
        
        Args:
            points: array_like of shape (..., 3).
        
        Returns:
            ndarray: the moved points, shape (..., 3).
        """
    def __ne__(self, other: typing.Any) -> bool:
        """
        The negation of ``==``: some stored number differs (or is NaN), or other is not a SE3.
        
        Args:
            other: any object.
        
        Returns:
            bool.
        """
    def __pow__(self, t: float) -> SE3:
        """
        The power exp(t log g): t = 0 gives the identity, t = 1
        this rigid motion, t = -1 its inverse, t = 0.5 the rigid motion half way along its
        geodesic from the identity (the one whose square it is, for angles below pi),
        as scipy's ``Rotation.__pow__``.
        
        Args:
            t: the exponent, finite (not only an integer).
        
        Returns:
            SE3: the power.
        
        Example:
            >>> g = SE3.exp([0.1, 0.2, 0.3, 0.4, 0.5, 0.6])
            >>> ((g ** 0.5) @ (g ** 0.5)).is_approx(g) and (g ** -1).is_approx(g.inverse())
            True
        """
    def __reduce__(self) -> tuple[typing.Any, tuple[typing.Any], typing.Any]:
        """
        Pickle support: (copyreg.__newobj__, (cls,), state).
        """
    def __reduce_ex__(self, protocol: typing.SupportsInt | typing.SupportsIndex) -> tuple[typing.Any, tuple[typing.Any], typing.Any]:
        """
        Pickle support (every protocol): (copyreg.__newobj__, (cls,), state).
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: typing.Any) -> None:
        ...
    @typing.overload
    def act(self, twist: Twist) -> Twist:
        """
        A twist from frame b to frame a: xi_a = Ad_g xi_b = (R v + p x R w, R w).
        
        Args:
            twist: Twist, xi_b.
        
        Returns:
            Twist: xi_a.
        """
    @typing.overload
    def act(self, wrench: Wrench) -> Wrench:
        """
        A wrench from frame b to frame a: F_a = Ad_g^-T F_b = (R f, p x R f + R tau).
        
        Args:
            wrench: Wrench, F_b.
        
        Returns:
            Wrench: F_a.
        """
    @typing.overload
    def act(self, points: numpy.typing.ArrayLike) -> typing.Any:
        """
        Action on points: q_a = R q_b + p (the same as ``g @ points``).
        
        The array function se3_act with this rigid motion: numpy's rules for dtypes and
        broadcasting.
        
        Args:
            points: array_like of shape (..., 3).
        
        Returns:
            ndarray: the moved points, shape (..., 3).
        
        Example:
            >>> g = SE3(translation=[1.0, 0.0, 0.0])
            >>> g.act([[0.0, 0.0, 0.0], [1.0, 1.0, 1.0]])
            array([[1., 0., 0.],
                   [2., 1., 1.]])
        """
    @typing.overload
    def act_inv(self, twist: Twist) -> Twist:
        """
        A twist from frame a to frame b: xi_b = Ad_g^-1 xi_a = (R^T (v - p x w), R^T w).
        
        Args:
            twist: Twist, xi_a.
        
        Returns:
            Twist: xi_b.
        """
    @typing.overload
    def act_inv(self, wrench: Wrench) -> Wrench:
        """
        A wrench from frame a to frame b: F_b = Ad_g^T F_a = (R^T f, R^T (tau - p x f)).
        
        Args:
            wrench: Wrench, F_a.
        
        Returns:
            Wrench: F_b.
        """
    @typing.overload
    def act_inv(self, points: numpy.typing.ArrayLike) -> typing.Any:
        """
        Inverse action on points: q_b = R^T (q_a - p), i.e. g^-1 @ q_a.
        
        The array function se3_act with g^-1: numpy's rules for dtypes and
        broadcasting.
        
        Args:
            points: array_like of shape (..., 3).
        
        Returns:
            ndarray: shape (..., 3).
        """
    def adjoint(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        The adjoint Ad_g = [[R, [p] R], [0, R]] (6x6, Murray-Li-Sastry order).
        
        g [xi] g^-1 = [Ad_g xi]: twists change frame by xi_a = Ad_g xi_b; wrenches
        by F_b = Ad_g^T F_a.
        
        Returns:
            ndarray: shape (6, 6).
        """
    def as_matrix(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        The homogeneous matrix g = [[R, p], [0, 1]].
        
        Returns:
            ndarray: shape (4, 4), float64 (a new array).
        """
    def inverse(self) -> SE3:
        """
        The inverse rigid motion g^-1 = [[R^T, -R^T p], [0, 1]].
        
        Returns:
            SE3: the inverse.
        
        Example:
            >>> g = SE3.exp([0.1, 0.2, 0.3, 0.4, 0.5, 0.6])
            >>> (g @ g.inverse()).is_approx(SE3.identity())
            True
        """
    def is_approx(self, other: SE3, tol: float = 1e-09) -> bool:
        """
        Whether two rigid motions are equal within tol: rotation matrices within tol (absolute), translations within
        tol * max(1, |p|_max) (relative beyond unit scale).
        
        ``==`` is the exact comparison (every stored number equal).
        
        Args:
            other: SE3.
            tol: the tolerance (>= 0).
        
        Returns:
            bool.
        """
    def log(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        The twist xi = (v, w) with exp([xi]) = g, rotation angle |w| in [0, pi].
        
        w = log(R); v = V^-1 p. At a rotation angle of exactly pi either axis sign is
        returned, never NaN.
        
        Returns:
            ndarray: xi = (v, w), shape (6,), linear part first.
        
        Example:
            >>> SE3(translation=[1.0, 2.0, 3.0]).log()
            array([1., 2., 3., 0., 0., 0.])
        """
    def normalized(self) -> SE3:
        """
        The same rigid motion with the nearest rotation.
        
        Removes the drift that accumulates over many compositions.
        
        Returns:
            SE3: the projected rigid motion.
        """
    def to_scipy(self) -> typing.Any:
        """
        This motion as a scipy.spatial.transform.RigidTransform.
        
        scipy (1.16 or later) is imported by this call (it is not needed by
        ``import chasles``). scipy's ``RigidTransform.from_matrix(g)`` works too
        (``np.asarray(g)`` is the 4x4 matrix); for many motions,
        ``RigidTransform.from_matrix`` of an array of shape (N, 4, 4).
        
        Returns:
            scipy.spatial.transform.RigidTransform: a single transform, from the
            homogeneous matrix of ``as_matrix()``.
        
        Raises:
            ImportError: scipy (or RigidTransform, scipy < 1.16) is missing.
        
        Example:
            >>> SE3(translation=[1.0, 2.0, 3.0]).to_scipy().translation
            array([1., 2., 3.])
        """
    @property
    def rotation(self) -> SO3:
        """
        SO3: the rotation R of g = [[R, p], [0, 1]] (a stored part; a copy).
        """
    @property
    def translation(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        ndarray: the translation p of g = [[R, p], [0, 1]], shape (3,) (a stored part; a new array).
        """
class SO2:
    """
    A rotation of the plane: an element of SO(2), stored as (cos theta, sin theta) (float64).
    
    Its matrix is R = [[c, -s], [s, c]]; ``R_ab`` maps frame b to frame a,
    ``R_ac = R_ab @ R_bc``. The tangent space is R: the angle theta (a float in
    Python; a 1-vector for the generic C++ code). The array functions so2_exp,
    so2_log, ... take angles of shape (...) and matrices of shape (..., 2, 2).
    
    Example:
        >>> R = SO2.exp(np.pi / 2)
        >>> np.round(R @ [1.0, 0.0], 12) + 0.0
        array([0., 1.])
        >>> (R @ R.inverse()).log()
        0.0
    """
    __array_ufunc__ = None
    __hash__: typing.ClassVar[None] = None
    dtype: typing.ClassVar[numpy.dtypes.Float64DType]
    @staticmethod
    def exp(theta: numpy.typing.ArrayLike) -> SO2:
        """
        The rotation by theta: exp(theta) = [[cos, -sin], [sin, cos]].
        
        One sincos, exact to the libm's rounding for every theta.
        
        Args:
            theta: the angle in radians, a float (or shape (1,)), finite.
        
        Returns:
            SO2: the rotation.
        
        Raises:
            ValueError: theta is not finite, or of another shape.
            TypeError: theta is not real.
        
        Example:
            >>> np.round(SO2.exp(np.pi / 2).as_matrix(), 12) + 0.0
            array([[ 0., -1.],
                   [ 1.,  0.]])
        """
    @staticmethod
    def from_matrix(matrix: numpy.typing.ArrayLike, tol: float = 1.4901161193847656e-08) -> SO2:
        """
        Checked construction from a 2x2 rotation matrix.
        
        Accepts M when max(|M^T M - I|_max, |det M - 1|) is at most tol (default
        sqrt(eps) = 1.49e-08).
        
        Args:
            matrix: shape (2, 2), finite.
            tol: the largest accepted defect.
        
        Returns:
            SO2: the rotation ((c, s) = ((M00 + M11) / 2, (M10 - M01) / 2)).
        
        Raises:
            ValueError: M is not a rotation within tol (the message gives the defect
                and det M), or M is not finite, or not of shape (2, 2).
        
        Example:
            >>> SO2.from_matrix([[0.0, -1.0], [1.0, 0.0]]).log() == np.pi / 2
            True
        """
    @staticmethod
    def from_matrix_projected(matrix: numpy.typing.ArrayLike) -> SO2:
        """
        The rotation nearest to a 2x2 matrix in the Frobenius norm.
        
        (c, s) along (M00 + M11, M10 - M01), made unit; defined for every finite M
        (the identity where that vector is 0).
        
        Args:
            matrix: shape (2, 2), finite.
        
        Returns:
            SO2: the nearest rotation.
        """
    @staticmethod
    def from_matrix_unchecked(matrix: numpy.typing.ArrayLike) -> SO2:
        """
        Construction without a check, for data known to be a rotation.
        
        (c, s) = ((M00 + M11) / 2, (M10 - M01) / 2): a rotation matrix's own numbers.
        
        Args:
            matrix: shape (2, 2), finite.
        
        Returns:
            SO2: the rotation.
        """
    @staticmethod
    def hat(theta: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
        """
        The skew-symmetric matrix of an angle: [[0, -theta], [theta, 0]].
        
        Args:
            theta: a float (or shape (1,)).
        
        Returns:
            ndarray: shape (2, 2).
        """
    @staticmethod
    def identity() -> SO2:
        """
        The identity rotation.
        """
    @staticmethod
    def interpolate(a: SO2, b: SO2, t: float) -> SO2:
        """
        Geodesic interpolation a exp(t log(a^-1 b)).
        
        t = 0 gives a, t = 1 gives b, in between, the rotation at constant angular velocity.
        
        Args:
            a: SO2, the start.
            b: SO2, the end.
            t: the fraction, finite.
        
        Returns:
            SO2: the interpolated rotation.
        
        Example:
            >>> a, b = SO2(), SO2.exp(0.5)
            >>> SO2.interpolate(a, b, 0.5).is_approx(a @ SO2.exp(0.5 * np.array(0.5)))
            True
        """
    @staticmethod
    def left_jacobian(theta: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
        """
        The left Jacobian J_l of SO(2) at theta: [[1.]] for every theta.
        
        The plane's rotations commute, so exp(theta + d) = exp(theta) exp(d) exactly
        and every Jacobian of exp is the identity (shape (1, 1), for the generic
        code and for SE2's blocks).
        
        Args:
            theta: a float (or shape (1,)), finite.
        
        Returns:
            ndarray: [[1.]], shape (1, 1), float64.
        """
    @staticmethod
    def left_jacobian_inverse(theta: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
        """
        The inverse left Jacobian J_l^-1 of SO(2) at theta: [[1.]] for every theta.
        
        The plane's rotations commute, so exp(theta + d) = exp(theta) exp(d) exactly
        and every Jacobian of exp is the identity (shape (1, 1), for the generic
        code and for SE2's blocks).
        
        Args:
            theta: a float (or shape (1,)), finite.
        
        Returns:
            ndarray: [[1.]], shape (1, 1), float64.
        """
    @staticmethod
    def right_jacobian(theta: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
        """
        The right Jacobian J_r of SO(2) at theta: [[1.]] for every theta.
        
        The plane's rotations commute, so exp(theta + d) = exp(theta) exp(d) exactly
        and every Jacobian of exp is the identity (shape (1, 1), for the generic
        code and for SE2's blocks).
        
        Args:
            theta: a float (or shape (1,)), finite.
        
        Returns:
            ndarray: [[1.]], shape (1, 1), float64.
        """
    @staticmethod
    def right_jacobian_inverse(theta: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
        """
        The inverse right Jacobian J_r^-1 of SO(2) at theta: [[1.]] for every theta.
        
        The plane's rotations commute, so exp(theta + d) = exp(theta) exp(d) exactly
        and every Jacobian of exp is the identity (shape (1, 1), for the generic
        code and for SE2's blocks).
        
        Args:
            theta: a float (or shape (1,)), finite.
        
        Returns:
            ndarray: [[1.]], shape (1, 1), float64.
        """
    @staticmethod
    def rotation_defect(matrix: numpy.typing.ArrayLike) -> float:
        """
        How far a 2x2 matrix is from a rotation: max(|M^T M - I|_max, |det M - 1|).
        
        Args:
            matrix: shape (2, 2).
        
        Returns:
            float: the defect (inf when an entry is not finite).
        """
    @staticmethod
    def vee(matrix: numpy.typing.ArrayLike) -> float:
        """
        The angle of a skew-symmetric 2x2 matrix: (W[1, 0] - W[0, 1]) / 2.
        
        Args:
            matrix: shape (2, 2).
        
        Returns:
            float: theta.
        """
    def __array__(self, dtype: numpy.typing.DTypeLike = None, copy: bool | None = None) -> numpy.ndarray:
        """
        The rotation matrix, shape (2, 2), for np.asarray (numpy's dtype and copy keywords).
        """
    def __copy__(self) -> SO2:
        ...
    def __deepcopy__(self, memo: typing.Any) -> SO2:
        ...
    def __eq__(self, other: typing.Any) -> bool:
        """
        Exact equality of the stored numbers: SO2s are values, compared as floats
        (-0.0 == 0.0; a NaN is unequal to everything, itself included).
        
        For a tolerance, use ``is_approx(other, tol)``. An object of another type gives
        NotImplemented, so ``==`` is False. SO2s are unhashable.
        
        Args:
            other: any object.
        
        Returns:
            bool.
        """
    def __getstate__(self) -> tuple:
        ...
    def __init__(self) -> None:
        """
        The identity rotation.
        """
    @typing.overload
    def __matmul__(self, other: SO2) -> SO2:
        """
        Composition: g_ab @ g_bc = g_ac.
        
        Args:
            other: SO2.
        
        Returns:
            SO2: the composed rotation.
        """
    @typing.overload
    def __matmul__(self, points: numpy.typing.ArrayLike) -> typing.Any:
        """
        Action on points or vectors of the plane: p_a = R_ab p_b.
        
        The array function so2_act with this rotation: numpy's rules for dtypes and
        broadcasting.
        
        Args:
            points: array_like of shape (..., 2).
        
        Returns:
            ndarray: the rotated points, shape (..., 2).
        """
    def __ne__(self, other: typing.Any) -> bool:
        """
        The negation of ``==``: some stored number differs (or is NaN), or other is not a SO2.
        
        Args:
            other: any object.
        
        Returns:
            bool.
        """
    def __pow__(self, t: float) -> SO2:
        """
        The power exp(t log g): t = 0 gives the identity, t = 1
        this rotation, t = -1 its inverse, t = 0.5 the rotation half way along its
        geodesic from the identity (the one whose square it is, for angles below pi),
        as scipy's ``Rotation.__pow__``.
        
        Args:
            t: the exponent, finite (not only an integer).
        
        Returns:
            SO2: the power.
        
        Example:
            >>> g = SO2.exp(0.5)
            >>> ((g ** 0.5) @ (g ** 0.5)).is_approx(g) and (g ** -1).is_approx(g.inverse())
            True
        """
    def __reduce__(self) -> tuple[typing.Any, tuple[typing.Any], typing.Any]:
        """
        Pickle support: (copyreg.__newobj__, (cls,), state).
        """
    def __reduce_ex__(self, protocol: typing.SupportsInt | typing.SupportsIndex) -> tuple[typing.Any, tuple[typing.Any], typing.Any]:
        """
        Pickle support (every protocol): (copyreg.__newobj__, (cls,), state).
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: typing.Any) -> None:
        ...
    def act(self, points: numpy.typing.ArrayLike) -> typing.Any:
        """
        Action on points or vectors of the plane: p_a = R_ab p_b (the same as ``R @ points``).
        
        The array function so2_act with this rotation: numpy's rules for dtypes and
        broadcasting.
        
        Args:
            points: array_like of shape (..., 2).
        
        Returns:
            ndarray: the rotated points, shape (..., 2).
        
        Example:
            >>> np.round(SO2.exp(np.pi / 2).act([[1.0, 0.0], [0.0, 2.0]]), 12) + 0.0
            array([[ 0.,  1.],
                   [-2.,  0.]])
        """
    def adjoint(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        The adjoint Ad_R = 1 (1x1): the plane's rotations commute.
        
        Returns:
            ndarray: shape (1, 1).
        """
    def as_matrix(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        The rotation matrix R = [[c, -s], [s, c]].
        
        Returns:
            ndarray: shape (2, 2), float64 (a new array).
        """
    def inverse(self) -> SO2:
        """
        The inverse rotation R^-1 = R^T.
        
        Returns:
            SO2: the inverse.
        
        Example:
            >>> g = SO2.exp(0.5)
            >>> (g @ g.inverse()).is_approx(SO2.identity())
            True
        """
    def is_approx(self, other: SO2, tol: float = 1e-09) -> bool:
        """
        Whether two rotations are equal within tol: the stored (cos, sin) within tol.
        
        ``==`` is the exact comparison (every stored number equal).
        
        Args:
            other: SO2.
            tol: the largest accepted difference (>= 0).
        
        Returns:
            bool.
        """
    def log(self) -> float:
        """
        The angle theta = atan2(sin, cos) in [-pi, pi].
        
        Accurate to an ulp over the whole range (no acos).
        
        Returns:
            float: theta.
        
        Example:
            >>> SO2.exp(0.5).log()
            0.5
        """
    def normalized(self) -> SO2:
        """
        The same rotation with the nearest rotation.
        
        Removes the drift that accumulates over many compositions.
        
        Returns:
            SO2: the projected rotation.
        """
class SE2:
    """
    A rigid motion of the plane: an element of SE(2), stored as a rotation R (an SO2) and a translation t.
    
    Its matrix is g = [[R, t], [0, 1]] (3x3); ``g_ab`` maps frame b to frame a,
    ``q_a = R q_b + t`` (``g @ q``), ``g_ac = g_ab @ g_bc``. The tangent space is
    the planar twists xi = (vx, vy, w), linear part first (as SE3, manif and
    jaxlie).
    
    Example:
        >>> g = SE2(SO2.exp(np.pi / 2), [1.0, 2.0])
        >>> np.round(g @ [1.0, 0.0], 12) + 0.0
        array([1., 3.])
        >>> SE2.exp(g.log()).is_approx(g)
        True
    """
    __array_ufunc__ = None
    __hash__: typing.ClassVar[None] = None
    dtype: typing.ClassVar[numpy.dtypes.Float64DType]
    @staticmethod
    def exp(xi: numpy.typing.ArrayLike) -> SE2:
        """
        The motion exp([xi]) of a planar twist xi = (vx, vy, w), linear part first.
        
        R = exp(w), t = V (vx, vy) with V = [[a, -b], [b, a]], a = sin(w) / w,
        b = (1 - cos(w)) / w: one sincos, series below the cutoff, exact to a few
        ulps for every xi.
        
        Args:
            xi: (vx, vy, w), shape (3,), finite.
        
        Returns:
            SE2: exp([xi]).
        
        Example:
            >>> np.round(SE2.exp([1.0, 0.0, np.pi / 2]).translation, 12) + 0.0
            array([0.63661977, 0.63661977])
        """
    @staticmethod
    def from_matrix(matrix: numpy.typing.ArrayLike, tol: float = 1.4901161193847656e-08) -> SE2:
        """
        Checked construction from a 3x3 homogeneous matrix [[R, t], [0, 1]].
        
        Accepts M when the rotation defect of its top-left block and the deviation
        of its bottom row from (0, 0, 1) are both at most tol (default sqrt(eps)).
        
        Args:
            matrix: shape (3, 3), finite.
            tol: the largest accepted defect.
        
        Returns:
            SE2: the motion.
        
        Raises:
            ValueError: M is not a rigid motion within tol (the message gives both
                defects), or M is not finite, or not of shape (3, 3).
        
        Example:
            >>> SE2.from_matrix(np.eye(3)) == SE2()
            True
        """
    @staticmethod
    def from_matrix_projected(matrix: numpy.typing.ArrayLike) -> SE2:
        """
        The nearest rotation to the top-left block, and the translation column.
        
        The bottom row is not read.
        
        Args:
            matrix: shape (3, 3), finite.
        
        Returns:
            SE2: the projected motion.
        """
    @staticmethod
    def from_matrix_unchecked(matrix: numpy.typing.ArrayLike) -> SE2:
        """
        Construction without a check from [[R, t], [*, *]], for valid data.
        
        Args:
            matrix: shape (3, 3), finite.
        
        Returns:
            SE2: the motion.
        """
    @staticmethod
    def hat(xi: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
        """
        The 3x3 matrix [xi] = [[0, -w, vx], [w, 0, vy], [0, 0, 0]].
        
        Args:
            xi: (vx, vy, w), shape (3,).
        
        Returns:
            ndarray: shape (3, 3).
        """
    @staticmethod
    def identity() -> SE2:
        """
        The identity motion.
        """
    @staticmethod
    def interpolate(a: SE2, b: SE2, t: float) -> SE2:
        """
        Geodesic interpolation a exp(t log(a^-1 b)).
        
        t = 0 gives a, t = 1 gives b, and the motion in between is one rotation about a fixed point.
        
        Args:
            a: SE2, the start.
            b: SE2, the end.
            t: the fraction, finite.
        
        Returns:
            SE2: the interpolated rigid motion.
        
        Example:
            >>> a, b = SE2(), SE2.exp([0.1, 0.2, 0.3])
            >>> SE2.interpolate(a, b, 0.5).is_approx(a @ SE2.exp(0.5 * np.array([0.1, 0.2, 0.3])))
            True
        """
    @staticmethod
    def left_jacobian(xi: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
        """
        The left Jacobian J_l of SE(2) at xi = (vx, vy, w), shape (3, 3).
        
        Linear part first. Right (local) convention, as manif:
        exp(xi + dxi) = exp(xi) exp(J_r(xi) dxi + o(dxi)) and
        exp(xi + dxi) = exp(J_l(xi) dxi + o(dxi)) exp(xi), with
        J_l = [[a, -b, C vx + B vy], [b, a, -B vx + C vy], [0, 0, 1]],
        a = sin(w) / w, b = (1 - cos w) / w, B = b / w, C = (w - sin w) / w^2
        (Sola et al. 2018, appendix C), J_r(xi) = J_l(-xi), and the inverses by the
        block formula [[V^-1, -V^-1 u], [0, 1]] (finite for |w| < 2 pi).
        
        Args:
            xi: (vx, vy, w), shape (3,), finite.
        
        Returns:
            ndarray: shape (3, 3), float64.
        """
    @staticmethod
    def left_jacobian_inverse(xi: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
        """
        The inverse left Jacobian J_l^-1 of SE(2) at xi = (vx, vy, w), shape (3, 3).
        
        Linear part first. Right (local) convention, as manif:
        exp(xi + dxi) = exp(xi) exp(J_r(xi) dxi + o(dxi)) and
        exp(xi + dxi) = exp(J_l(xi) dxi + o(dxi)) exp(xi), with
        J_l = [[a, -b, C vx + B vy], [b, a, -B vx + C vy], [0, 0, 1]],
        a = sin(w) / w, b = (1 - cos w) / w, B = b / w, C = (w - sin w) / w^2
        (Sola et al. 2018, appendix C), J_r(xi) = J_l(-xi), and the inverses by the
        block formula [[V^-1, -V^-1 u], [0, 1]] (finite for |w| < 2 pi).
        
        Args:
            xi: (vx, vy, w), shape (3,), finite.
        
        Returns:
            ndarray: shape (3, 3), float64.
        """
    @staticmethod
    def right_jacobian(xi: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
        """
        The right Jacobian J_r of SE(2) at xi = (vx, vy, w), shape (3, 3).
        
        Linear part first. Right (local) convention, as manif:
        exp(xi + dxi) = exp(xi) exp(J_r(xi) dxi + o(dxi)) and
        exp(xi + dxi) = exp(J_l(xi) dxi + o(dxi)) exp(xi), with
        J_l = [[a, -b, C vx + B vy], [b, a, -B vx + C vy], [0, 0, 1]],
        a = sin(w) / w, b = (1 - cos w) / w, B = b / w, C = (w - sin w) / w^2
        (Sola et al. 2018, appendix C), J_r(xi) = J_l(-xi), and the inverses by the
        block formula [[V^-1, -V^-1 u], [0, 1]] (finite for |w| < 2 pi).
        
        Args:
            xi: (vx, vy, w), shape (3,), finite.
        
        Returns:
            ndarray: shape (3, 3), float64.
        """
    @staticmethod
    def right_jacobian_inverse(xi: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
        """
        The inverse right Jacobian J_r^-1 of SE(2) at xi = (vx, vy, w), shape (3, 3).
        
        Linear part first. Right (local) convention, as manif:
        exp(xi + dxi) = exp(xi) exp(J_r(xi) dxi + o(dxi)) and
        exp(xi + dxi) = exp(J_l(xi) dxi + o(dxi)) exp(xi), with
        J_l = [[a, -b, C vx + B vy], [b, a, -B vx + C vy], [0, 0, 1]],
        a = sin(w) / w, b = (1 - cos w) / w, B = b / w, C = (w - sin w) / w^2
        (Sola et al. 2018, appendix C), J_r(xi) = J_l(-xi), and the inverses by the
        block formula [[V^-1, -V^-1 u], [0, 1]] (finite for |w| < 2 pi).
        
        Args:
            xi: (vx, vy, w), shape (3,), finite.
        
        Returns:
            ndarray: shape (3, 3), float64.
        """
    @staticmethod
    def transform_defect(matrix: numpy.typing.ArrayLike) -> float:
        """
        How far a 3x3 matrix is from a rigid motion of the plane.
        
        The rotation defect of its top-left block or the deviation of its bottom
        row from (0, 0, 1), whichever is larger.
        
        Args:
            matrix: shape (3, 3).
        
        Returns:
            float: the defect.
        """
    @staticmethod
    def vee(matrix: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
        """
        The twist (vx, vy, w) of a 3x3 matrix: the inverse of hat.
        
        w is read from the antisymmetric part of the top-left block; the bottom row
        is ignored.
        
        Args:
            matrix: shape (3, 3).
        
        Returns:
            ndarray: shape (3,).
        """
    def __array__(self, dtype: numpy.typing.DTypeLike = None, copy: bool | None = None) -> numpy.ndarray:
        """
        The homogeneous matrix, shape (3, 3), for np.asarray (numpy's dtype and copy keywords).
        """
    def __copy__(self) -> SE2:
        ...
    def __deepcopy__(self, memo: typing.Any) -> SE2:
        ...
    def __eq__(self, other: typing.Any) -> bool:
        """
        Exact equality of the stored numbers: SE2s are values, compared as floats
        (-0.0 == 0.0; a NaN is unequal to everything, itself included).
        
        For a tolerance, use ``is_approx(other, tol)``. An object of another type gives
        NotImplemented, so ``==`` is False. SE2s are unhashable.
        
        Args:
            other: any object.
        
        Returns:
            bool.
        """
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, rotation: SO2 = ..., translation: numpy.typing.ArrayLike = (0.0, 0.0)) -> None:
        """
        The rigid motion g = [[R, t], [0, 1]] of a rotation and a translation.
        
        Args:
            rotation: SO2, R (default: the identity).
            translation: shape (2,), t, finite (default: 0).
        """
    @typing.overload
    def __matmul__(self, other: SE2) -> SE2:
        """
        Composition: g_ab @ g_bc = g_ac.
        
        Args:
            other: SE2.
        
        Returns:
            SE2: the composed rigid motion.
        """
    @typing.overload
    def __matmul__(self, points: numpy.typing.ArrayLike) -> typing.Any:
        """
        Action on points of the plane: q_a = R q_b + t.
        
        The array function se2_act with this rigid motion: numpy's rules for dtypes and
        broadcasting.
        
        Args:
            points: array_like of shape (..., 2).
        
        Returns:
            ndarray: the moved points, shape (..., 2).
        """
    def __ne__(self, other: typing.Any) -> bool:
        """
        The negation of ``==``: some stored number differs (or is NaN), or other is not a SE2.
        
        Args:
            other: any object.
        
        Returns:
            bool.
        """
    def __pow__(self, t: float) -> SE2:
        """
        The power exp(t log g): t = 0 gives the identity, t = 1
        this rigid motion, t = -1 its inverse, t = 0.5 the rigid motion half way along its
        geodesic from the identity (the one whose square it is, for angles below pi),
        as scipy's ``Rotation.__pow__``.
        
        Args:
            t: the exponent, finite (not only an integer).
        
        Returns:
            SE2: the power.
        
        Example:
            >>> g = SE2.exp([0.1, 0.2, 0.3])
            >>> ((g ** 0.5) @ (g ** 0.5)).is_approx(g) and (g ** -1).is_approx(g.inverse())
            True
        """
    def __reduce__(self) -> tuple[typing.Any, tuple[typing.Any], typing.Any]:
        """
        Pickle support: (copyreg.__newobj__, (cls,), state).
        """
    def __reduce_ex__(self, protocol: typing.SupportsInt | typing.SupportsIndex) -> tuple[typing.Any, tuple[typing.Any], typing.Any]:
        """
        Pickle support (every protocol): (copyreg.__newobj__, (cls,), state).
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: typing.Any) -> None:
        ...
    def act(self, points: numpy.typing.ArrayLike) -> typing.Any:
        """
        Action on points of the plane: q_a = R q_b + t (the same as ``g @ points``).
        
        The array function se2_act with this rigid motion: numpy's rules for dtypes and
        broadcasting.
        
        Args:
            points: array_like of shape (..., 2).
        
        Returns:
            ndarray: the moved points, shape (..., 2).
        
        Example:
            >>> SE2(translation=[1.0, 0.0]).act([[0.0, 0.0], [1.0, 1.0]])
            array([[1., 0.],
                   [2., 1.]])
        """
    def adjoint(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        The adjoint Ad_g = [[R, (t_y, -t_x)], [0, 1]] (3x3), so that g [xi] g^-1 = [Ad_g xi].
        
        Returns:
            ndarray: shape (3, 3).
        """
    def as_matrix(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        The homogeneous matrix g = [[R, t], [0, 1]] (3x3).
        
        Returns:
            ndarray: shape (3, 3), float64 (a new array).
        """
    def inverse(self) -> SE2:
        """
        The inverse rigid motion g^-1 = [[R^T, -R^T t], [0, 1]].
        
        Returns:
            SE2: the inverse.
        
        Example:
            >>> g = SE2.exp([0.1, 0.2, 0.3])
            >>> (g @ g.inverse()).is_approx(SE2.identity())
            True
        """
    def is_approx(self, other: SE2, tol: float = 1e-09) -> bool:
        """
        Whether two rigid motions are equal within tol: rotations within tol (absolute), translations within
        tol * max(1, |t|_max).
        
        ``==`` is the exact comparison (every stored number equal).
        
        Args:
            other: SE2.
            tol: the tolerance (>= 0).
        
        Returns:
            bool.
        """
    def log(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        The twist xi = (vx, vy, w) with exp([xi]) = g, w in [-pi, pi].
        
        w = atan2(sin, cos); (vx, vy) = V^-1 t with V^-1 = [[e, w/2], [-w/2, e]],
        e = (w/2) cot(w/2), without cancellation near 0 or pi.
        
        Returns:
            ndarray: xi = (vx, vy, w), shape (3,).
        
        Example:
            >>> SE2(translation=[1.0, 2.0]).log()
            array([1., 2., 0.])
        """
    def normalized(self) -> SE2:
        """
        The same rigid motion with the nearest rotation.
        
        Removes the drift that accumulates over many compositions.
        
        Returns:
            SE2: the projected rigid motion.
        """
    @property
    def rotation(self) -> SO2:
        """
        SO2: the rotation R of g = [[R, t], [0, 1]].
        """
    @property
    def translation(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        ndarray: the translation t of g = [[R, t], [0, 1]], shape (2,) (a new array).
        """
class Sim3:
    """
    A similarity transform of R^3: an element of Sim(3), stored as a rotation R (an SO3), a translation t and a scale s > 0.
    
    Its matrix is g = [[s R, t], [0, 1]]; it maps frame b to frame a as
    ``q_a = s R q_b + t`` (``g @ q``), and composes as
    ``(R1, t1, s1) @ (R2, t2, s2) = (R1 R2, s1 R1 t2 + t1, s1 s2)``. The tangent
    space is xi = (v, w, sigma) in Sophus' order, s = exp(sigma):
    [xi] = [[ [w] + sigma I, v ], [0, 0]]. Monocular SLAM's and point-set
    registration's group.
    
    Example:
        >>> g = Sim3(SO3.exp([0.0, 0.0, np.pi / 2]), [1.0, 0.0, 0.0], 2.0)
        >>> np.round(g @ [1.0, 0.0, 0.0], 12) + 0.0
        array([1., 2., 0.])
        >>> Sim3.exp(g.log()).is_approx(g)
        True
    """
    __array_ufunc__ = None
    __hash__: typing.ClassVar[None] = None
    dtype: typing.ClassVar[numpy.dtypes.Float64DType]
    @staticmethod
    def exp(xi: numpy.typing.ArrayLike) -> Sim3:
        """
        The similarity exp([xi]) of xi = (v, w, sigma) (Sophus' order).
        
        R = exp([w]), s = e^sigma, t = W v with W = A I + B [w] + C [w]^2 the
        integral of e^(sigma u) exp(u [w]) over [0, 1]; A, B and C without a 0/0 in
        either theta = |w| or sigma (a double series where both are small), a few
        ulps over the whole domain.
        
        Args:
            xi: (v, w, sigma), shape (7,), finite.
        
        Returns:
            Sim3: exp([xi]).
        
        Example:
            >>> g = Sim3.exp([1.0, 0.0, 0.0, 0.0, 0.0, 0.0, np.log(2.0)])
            >>> round(g.scale, 12), np.round(g.translation, 12) + 0.0
            (2.0, array([1.44269504, 0.        , 0.        ]))
        """
    @staticmethod
    def from_matrix(matrix: numpy.typing.ArrayLike, tol: float = 1.4901161193847656e-08) -> Sim3:
        """
        Checked construction from a 4x4 matrix [[s R, t], [0, 1]].
        
        s = |block|_F / sqrt(3); accepts M when the rotation defect of block / s and
        the deviation of the bottom row from (0, 0, 0, 1) are both at most tol
        (default sqrt(eps)).
        
        Args:
            matrix: shape (4, 4), finite.
            tol: the largest accepted defect.
        
        Returns:
            Sim3: the similarity.
        
        Raises:
            ValueError: M is not a similarity within tol (the message gives the
                defects), or M is not finite, or not of shape (4, 4).
        
        Example:
            >>> Sim3.from_matrix(np.diag([2.0, 2.0, 2.0, 1.0])).scale
            2.0
        """
    @staticmethod
    def from_matrix_projected(matrix: numpy.typing.ArrayLike) -> Sim3:
        """
        The nearest rotation to the top-left block, its least-squares scale, and the translation.
        
        s = tr(R^T block) / 3 for R the nearest rotation (1 when that is not
        positive); the bottom row is not read.
        
        Args:
            matrix: shape (4, 4), finite.
        
        Returns:
            Sim3: the projected similarity.
        """
    @staticmethod
    def from_matrix_unchecked(matrix: numpy.typing.ArrayLike) -> Sim3:
        """
        Construction without a check from [[s R, t], [*, *]], for valid data.
        
        s = |block|_F / sqrt(3), R = block / s.
        
        Args:
            matrix: shape (4, 4), finite.
        
        Returns:
            Sim3: the similarity.
        """
    @staticmethod
    def hat(xi: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
        """
        The 4x4 matrix [xi] = [[ [w] + sigma I, v ], [0, 0]] of xi = (v, w, sigma).
        
        Args:
            xi: shape (7,).
        
        Returns:
            ndarray: shape (4, 4).
        """
    @staticmethod
    def identity() -> Sim3:
        """
        The identity similarity.
        """
    @staticmethod
    def interpolate(a: Sim3, b: Sim3, t: float) -> Sim3:
        """
        Geodesic interpolation a exp(t log(a^-1 b)).
        
        t = 0 gives a, t = 1 gives b, and the similarity in between is one screw motion with a steady scaling.
        
        Args:
            a: Sim3, the start.
            b: Sim3, the end.
            t: the fraction, finite.
        
        Returns:
            Sim3: the interpolated similarity.
        
        Example:
            >>> a, b = Sim3(), Sim3.exp([0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7])
            >>> Sim3.interpolate(a, b, 0.5).is_approx(a @ Sim3.exp(0.5 * np.array([0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7])))
            True
        """
    @staticmethod
    def left_jacobian(xi: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
        """
        The left Jacobian J_l of Sim(3) at xi = (v, w, sigma), shape (7, 7).
        
        Right (local) convention, as for the other groups:
        exp(xi + dxi) = exp(xi) exp(J_r(xi) dxi + o(dxi)) and
        exp(xi + dxi) = exp(J_l(xi) dxi + o(dxi)) exp(xi). J_l = phi(ad_xi),
        phi(X) = (exp(X) - I) X^-1, by scaling and squaring of ad_xi, with the
        diagonal blocks (W and SO(3)'s J_l) in closed form; J_r(xi) = J_l(-xi); the
        inverses by the block formula. Accurate to about 10 eps for |v| and |sigma|
        below 2, and to a few hundred eps at |v| = 100, |sigma| = 5.
        
        Args:
            xi: (v, w, sigma), shape (7,), finite.
        
        Returns:
            ndarray: shape (7, 7), float64.
        """
    @staticmethod
    def left_jacobian_inverse(xi: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
        """
        The inverse left Jacobian J_l^-1 of Sim(3) at xi = (v, w, sigma), shape (7, 7).
        
        Right (local) convention, as for the other groups:
        exp(xi + dxi) = exp(xi) exp(J_r(xi) dxi + o(dxi)) and
        exp(xi + dxi) = exp(J_l(xi) dxi + o(dxi)) exp(xi). J_l = phi(ad_xi),
        phi(X) = (exp(X) - I) X^-1, by scaling and squaring of ad_xi, with the
        diagonal blocks (W and SO(3)'s J_l) in closed form; J_r(xi) = J_l(-xi); the
        inverses by the block formula. Accurate to about 10 eps for |v| and |sigma|
        below 2, and to a few hundred eps at |v| = 100, |sigma| = 5.
        
        Args:
            xi: (v, w, sigma), shape (7,), finite.
        
        Returns:
            ndarray: shape (7, 7), float64.
        """
    @staticmethod
    def right_jacobian(xi: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
        """
        The right Jacobian J_r of Sim(3) at xi = (v, w, sigma), shape (7, 7).
        
        Right (local) convention, as for the other groups:
        exp(xi + dxi) = exp(xi) exp(J_r(xi) dxi + o(dxi)) and
        exp(xi + dxi) = exp(J_l(xi) dxi + o(dxi)) exp(xi). J_l = phi(ad_xi),
        phi(X) = (exp(X) - I) X^-1, by scaling and squaring of ad_xi, with the
        diagonal blocks (W and SO(3)'s J_l) in closed form; J_r(xi) = J_l(-xi); the
        inverses by the block formula. Accurate to about 10 eps for |v| and |sigma|
        below 2, and to a few hundred eps at |v| = 100, |sigma| = 5.
        
        Args:
            xi: (v, w, sigma), shape (7,), finite.
        
        Returns:
            ndarray: shape (7, 7), float64.
        """
    @staticmethod
    def right_jacobian_inverse(xi: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
        """
        The inverse right Jacobian J_r^-1 of Sim(3) at xi = (v, w, sigma), shape (7, 7).
        
        Right (local) convention, as for the other groups:
        exp(xi + dxi) = exp(xi) exp(J_r(xi) dxi + o(dxi)) and
        exp(xi + dxi) = exp(J_l(xi) dxi + o(dxi)) exp(xi). J_l = phi(ad_xi),
        phi(X) = (exp(X) - I) X^-1, by scaling and squaring of ad_xi, with the
        diagonal blocks (W and SO(3)'s J_l) in closed form; J_r(xi) = J_l(-xi); the
        inverses by the block formula. Accurate to about 10 eps for |v| and |sigma|
        below 2, and to a few hundred eps at |v| = 100, |sigma| = 5.
        
        Args:
            xi: (v, w, sigma), shape (7,), finite.
        
        Returns:
            ndarray: shape (7, 7), float64.
        """
    @staticmethod
    def transform_defect(matrix: numpy.typing.ArrayLike) -> float:
        """
        How far a 4x4 matrix is from a similarity.
        
        The rotation defect of its top-left block divided by its scale, or the
        deviation of its bottom row from (0, 0, 0, 1), whichever is larger (inf for
        a non-finite matrix or a zero block).
        
        Args:
            matrix: shape (4, 4).
        
        Returns:
            float: the defect.
        """
    @staticmethod
    def vee(matrix: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
        """
        The (v, w, sigma) of a 4x4 matrix: the inverse of hat.
        
        w from the antisymmetric part of the top-left block, sigma the mean of its
        diagonal, v the last column's top; the bottom row is ignored.
        
        Args:
            matrix: shape (4, 4).
        
        Returns:
            ndarray: shape (7,).
        """
    def __array__(self, dtype: numpy.typing.DTypeLike = None, copy: bool | None = None) -> numpy.ndarray:
        """
        The homogeneous matrix, shape (4, 4), for np.asarray (numpy's dtype and copy keywords).
        """
    def __copy__(self) -> Sim3:
        ...
    def __deepcopy__(self, memo: typing.Any) -> Sim3:
        ...
    def __eq__(self, other: typing.Any) -> bool:
        """
        Exact equality of the stored numbers: Sim3s are values, compared as floats
        (-0.0 == 0.0; a NaN is unequal to everything, itself included).
        
        For a tolerance, use ``is_approx(other, tol)``. An object of another type gives
        NotImplemented, so ``==`` is False. Sim3s are unhashable.
        
        Args:
            other: any object.
        
        Returns:
            bool.
        """
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, rotation: SO3 = ..., translation: numpy.typing.ArrayLike = (0.0, 0.0, 0.0), scale: float = 1.0) -> None:
        """
        The similarity g = [[s R, t], [0, 1]] of a rotation, a translation and a scale.
        
        Args:
            rotation: SO3, R (default: the identity).
            translation: shape (3,), t, finite (default: 0).
            scale: s > 0, finite (default: 1).
        """
    @typing.overload
    def __matmul__(self, other: Sim3) -> Sim3:
        """
        Composition: g_ab @ g_bc = g_ac.
        
        Args:
            other: Sim3.
        
        Returns:
            Sim3: the composed similarity.
        """
    @typing.overload
    def __matmul__(self, points: numpy.typing.ArrayLike) -> typing.Any:
        """
        Action on points: q_a = s R q_b + t.
        
        The array function sim3_act with this similarity: numpy's rules for dtypes and
        broadcasting.
        
        Args:
            points: array_like of shape (..., 3).
        
        Returns:
            ndarray: the moved points, shape (..., 3).
        """
    def __ne__(self, other: typing.Any) -> bool:
        """
        The negation of ``==``: some stored number differs (or is NaN), or other is not a Sim3.
        
        Args:
            other: any object.
        
        Returns:
            bool.
        """
    def __pow__(self, t: float) -> Sim3:
        """
        The power exp(t log g): t = 0 gives the identity, t = 1
        this similarity, t = -1 its inverse, t = 0.5 the similarity half way along its
        geodesic from the identity (the one whose square it is, for angles below pi),
        as scipy's ``Rotation.__pow__``.
        
        Args:
            t: the exponent, finite (not only an integer).
        
        Returns:
            Sim3: the power.
        
        Example:
            >>> g = Sim3.exp([0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7])
            >>> ((g ** 0.5) @ (g ** 0.5)).is_approx(g) and (g ** -1).is_approx(g.inverse())
            True
        """
    def __reduce__(self) -> tuple[typing.Any, tuple[typing.Any], typing.Any]:
        """
        Pickle support: (copyreg.__newobj__, (cls,), state).
        """
    def __reduce_ex__(self, protocol: typing.SupportsInt | typing.SupportsIndex) -> tuple[typing.Any, tuple[typing.Any], typing.Any]:
        """
        Pickle support (every protocol): (copyreg.__newobj__, (cls,), state).
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: typing.Any) -> None:
        ...
    def act(self, points: numpy.typing.ArrayLike) -> typing.Any:
        """
        Action on points: q_a = s R q_b + t (the same as ``g @ points``).
        
        The array function sim3_act with this similarity: numpy's rules for dtypes and
        broadcasting.
        
        Args:
            points: array_like of shape (..., 3).
        
        Returns:
            ndarray: the moved points, shape (..., 3).
        
        Example:
            >>> Sim3(scale=2.0).act([[1.0, 0.0, 0.0], [0.0, 1.0, 1.0]])
            array([[2., 0., 0.],
                   [0., 2., 2.]])
        """
    def adjoint(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        The adjoint Ad_g = [[s R, [t] R, -t], [0, R, 0], [0, 0, 1]] (7x7), so that g [xi] g^-1 = [Ad_g xi].
        
        Returns:
            ndarray: shape (7, 7).
        """
    def as_matrix(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        The matrix g = [[s R, t], [0, 1]] (4x4).
        
        Returns:
            ndarray: shape (4, 4), float64 (a new array).
        """
    def inverse(self) -> Sim3:
        """
        The inverse similarity (R^T, -R^T t / s, 1 / s).
        
        Returns:
            Sim3: the inverse.
        
        Example:
            >>> g = Sim3.exp([0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7])
            >>> (g @ g.inverse()).is_approx(Sim3.identity())
            True
        """
    def is_approx(self, other: Sim3, tol: float = 1e-09) -> bool:
        """
        Whether two similaritys are equal within tol: rotations within tol (absolute), translations within
        tol * max(1, |t|_max), scales within tol * max(1, s).
        
        ``==`` is the exact comparison (every stored number equal).
        
        Args:
            other: Sim3.
            tol: the tolerance (>= 0).
        
        Returns:
            bool.
        """
    def log(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        The xi = (v, w, sigma) with exp([xi]) = g, rotation angle |w| in [0, pi].
        
        w = log(R) (SO3's), sigma = log(s), v = W^-1 t in closed form.
        
        Returns:
            ndarray: xi = (v, w, sigma), shape (7,).
        
        Example:
            >>> np.round(Sim3(translation=[1.0, 2.0, 3.0]).log(), 12) + 0.0
            array([1., 2., 3., 0., 0., 0., 0.])
        """
    def normalized(self) -> Sim3:
        """
        The same similarity with the nearest rotation.
        
        Removes the drift that accumulates over many compositions.
        
        Returns:
            Sim3: the projected similarity.
        """
    @property
    def rotation(self) -> SO3:
        """
        SO3: the rotation R of g = [[s R, t], [0, 1]].
        """
    @property
    def scale(self) -> float:
        """
        float: the scale s > 0.
        """
    @property
    def translation(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        ndarray: the translation t, shape (3,) (a new array).
        """
class SE23:
    """
    An extended pose: an element of SE_2(3), stored as a rotation R (an SO3), a position p and a velocity v.
    
    Its matrix is X = [[R, p, v], [0, 1, 0], [0, 0, 1]] (5x5, manif's layout);
    it composes as ``(R1, p1, v1) @ (R2, p2, v2) = (R1 R2, R1 p2 + p1, R1 v2 + v1)``
    and acts on points as ``q_a = R q_b + p`` (``X @ q``; the velocity moves no
    point). The tangent is xi = (rho, nu, w), in the order of the matrix's
    columns: [xi] = [[ [w], rho, nu ], [0, 0, 0], [0, 0, 0]]. manif orders it
    (rho, w, nu), gtsam's NavState (w, rho, nu). The state of IMU
    preintegration and of invariant Kalman filters.
    
    Example:
        >>> X = SE23(SO3.exp([0.0, 0.0, np.pi / 2]), [1.0, 0.0, 0.0], [0.0, 0.0, 2.0])
        >>> np.round(X @ [1.0, 0.0, 0.0], 12) + 0.0
        array([1., 1., 0.])
        >>> SE23.exp(X.log()).is_approx(X)
        True
    """
    __array_ufunc__ = None
    __hash__: typing.ClassVar[None] = None
    dtype: typing.ClassVar[numpy.dtypes.Float64DType]
    @staticmethod
    def exp(xi: numpy.typing.ArrayLike) -> SE23:
        """
        The extended pose exp([xi]) of xi = (rho, nu, w).
        
        R = exp([w]), p = V rho, v = V nu with V = J_l(w) = A I + B [w] + C w w^T:
        SE3's exp applied to both translations, one sincos, a few ulps over the
        whole domain. (manif orders its tangent (rho, w, nu), gtsam's NavState
        (w, rho, nu).)
        
        Args:
            xi: (rho, nu, w), shape (9,), finite.
        
        Returns:
            SE23: exp([xi]).
        
        Example:
            >>> X = SE23.exp([1.0, 0.0, 0.0, 0.0, 2.0, 0.0, 0.0, 0.0, 0.0])
            >>> X.translation, X.velocity
            (array([1., 0., 0.]), array([0., 2., 0.]))
        """
    @staticmethod
    def from_matrix(matrix: numpy.typing.ArrayLike, tol: float = 1.4901161193847656e-08) -> SE23:
        """
        Checked construction from a 5x5 matrix [[R, p, v], [0, 1, 0], [0, 0, 1]].
        
        Accepts M when the rotation defect of its top-left block and the deviation
        of its bottom rows from [[0, 1, 0], [0, 0, 1]] are both at most tol
        (default sqrt(eps)).
        
        Args:
            matrix: shape (5, 5), finite.
            tol: the largest accepted defect.
        
        Returns:
            SE23: the extended pose.
        
        Raises:
            ValueError: M is not an extended pose within tol (the message gives the
                defects), or M is not finite, or not of shape (5, 5).
        
        Example:
            >>> SE23.from_matrix(np.eye(5)).velocity
            array([0., 0., 0.])
        """
    @staticmethod
    def from_matrix_projected(matrix: numpy.typing.ArrayLike) -> SE23:
        """
        The nearest rotation to the top-left block, with the position and velocity columns.
        
        The bottom rows are not read.
        
        Args:
            matrix: shape (5, 5), finite.
        
        Returns:
            SE23: the projected extended pose.
        """
    @staticmethod
    def from_matrix_unchecked(matrix: numpy.typing.ArrayLike) -> SE23:
        """
        Construction without a check from [[R, p, v], [*]], for valid data.
        
        Args:
            matrix: shape (5, 5), finite.
        
        Returns:
            SE23: the extended pose.
        """
    @staticmethod
    def hat(xi: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
        """
        The 5x5 matrix [xi] = [[ [w], rho, nu ], [0, 0, 0], [0, 0, 0]] of xi = (rho, nu, w).
        
        Args:
            xi: shape (9,).
        
        Returns:
            ndarray: shape (5, 5).
        """
    @staticmethod
    def identity() -> SE23:
        """
        The identity extended pose.
        """
    @staticmethod
    def interpolate(a: SE23, b: SE23, t: float) -> SE23:
        """
        Geodesic interpolation a exp(t log(a^-1 b)).
        
        t = 0 gives a, t = 1 gives b, and the extended pose in between follows one screw motion, the velocity along the same rotation.
        
        Args:
            a: SE23, the start.
            b: SE23, the end.
            t: the fraction, finite.
        
        Returns:
            SE23: the interpolated extended pose.
        
        Example:
            >>> a, b = SE23(), SE23.exp([0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9])
            >>> SE23.interpolate(a, b, 0.5).is_approx(a @ SE23.exp(0.5 * np.array([0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9])))
            True
        """
    @staticmethod
    def left_jacobian(xi: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
        """
        The left Jacobian J_l of SE_2(3) at xi = (rho, nu, w), shape (9, 9).
        
        Right (local) convention, as for the other groups:
        exp(xi + dxi) = exp(xi) exp(J_r(xi) dxi + o(dxi)) and
        exp(xi + dxi) = exp(J_l(xi) dxi + o(dxi)) exp(xi). SE3's, block by block:
        J_l = [[J_l(w), 0, Q(rho, w)], [0, J_l(w), Q(nu, w)], [0, 0, J_l(w)]];
        J_r(xi) = J_l(-xi); the inverses by the block formula.
        
        Args:
            xi: (rho, nu, w), shape (9,), finite.
        
        Returns:
            ndarray: shape (9, 9), float64.
        """
    @staticmethod
    def left_jacobian_inverse(xi: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
        """
        The inverse left Jacobian J_l^-1 of SE_2(3) at xi = (rho, nu, w), shape (9, 9).
        
        Right (local) convention, as for the other groups:
        exp(xi + dxi) = exp(xi) exp(J_r(xi) dxi + o(dxi)) and
        exp(xi + dxi) = exp(J_l(xi) dxi + o(dxi)) exp(xi). SE3's, block by block:
        J_l = [[J_l(w), 0, Q(rho, w)], [0, J_l(w), Q(nu, w)], [0, 0, J_l(w)]];
        J_r(xi) = J_l(-xi); the inverses by the block formula.
        
        Args:
            xi: (rho, nu, w), shape (9,), finite.
        
        Returns:
            ndarray: shape (9, 9), float64.
        """
    @staticmethod
    def right_jacobian(xi: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
        """
        The right Jacobian J_r of SE_2(3) at xi = (rho, nu, w), shape (9, 9).
        
        Right (local) convention, as for the other groups:
        exp(xi + dxi) = exp(xi) exp(J_r(xi) dxi + o(dxi)) and
        exp(xi + dxi) = exp(J_l(xi) dxi + o(dxi)) exp(xi). SE3's, block by block:
        J_l = [[J_l(w), 0, Q(rho, w)], [0, J_l(w), Q(nu, w)], [0, 0, J_l(w)]];
        J_r(xi) = J_l(-xi); the inverses by the block formula.
        
        Args:
            xi: (rho, nu, w), shape (9,), finite.
        
        Returns:
            ndarray: shape (9, 9), float64.
        """
    @staticmethod
    def right_jacobian_inverse(xi: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
        """
        The inverse right Jacobian J_r^-1 of SE_2(3) at xi = (rho, nu, w), shape (9, 9).
        
        Right (local) convention, as for the other groups:
        exp(xi + dxi) = exp(xi) exp(J_r(xi) dxi + o(dxi)) and
        exp(xi + dxi) = exp(J_l(xi) dxi + o(dxi)) exp(xi). SE3's, block by block:
        J_l = [[J_l(w), 0, Q(rho, w)], [0, J_l(w), Q(nu, w)], [0, 0, J_l(w)]];
        J_r(xi) = J_l(-xi); the inverses by the block formula.
        
        Args:
            xi: (rho, nu, w), shape (9,), finite.
        
        Returns:
            ndarray: shape (9, 9), float64.
        """
    @staticmethod
    def transform_defect(matrix: numpy.typing.ArrayLike) -> float:
        """
        How far a 5x5 matrix is from an extended pose.
        
        The rotation defect of its top-left block or the deviation of its bottom
        rows from [[0, 0, 0, 1, 0], [0, 0, 0, 0, 1]], whichever is larger (inf for a
        non-finite matrix).
        
        Args:
            matrix: shape (5, 5).
        
        Returns:
            float: the defect.
        """
    @staticmethod
    def vee(matrix: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
        """
        The (rho, nu, w) of a 5x5 matrix: the inverse of hat.
        
        rho and nu are the top of the last two columns, w the antisymmetric part of
        the top-left block; the bottom rows are not read.
        
        Args:
            matrix: shape (5, 5).
        
        Returns:
            ndarray: shape (9,).
        """
    def __array__(self, dtype: numpy.typing.DTypeLike = None, copy: bool | None = None) -> numpy.ndarray:
        """
        The homogeneous matrix, shape (5, 5), for np.asarray (numpy's dtype and copy keywords).
        """
    def __copy__(self) -> SE23:
        ...
    def __deepcopy__(self, memo: typing.Any) -> SE23:
        ...
    def __eq__(self, other: typing.Any) -> bool:
        """
        Exact equality of the stored numbers: SE23s are values, compared as floats
        (-0.0 == 0.0; a NaN is unequal to everything, itself included).
        
        For a tolerance, use ``is_approx(other, tol)``. An object of another type gives
        NotImplemented, so ``==`` is False. SE23s are unhashable.
        
        Args:
            other: any object.
        
        Returns:
            bool.
        """
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, rotation: SO3 = ..., translation: numpy.typing.ArrayLike = (0.0, 0.0, 0.0), velocity: numpy.typing.ArrayLike = (0.0, 0.0, 0.0)) -> None:
        """
        The extended pose X = [[R, p, v], [0, 1, 0], [0, 0, 1]] of a rotation, a position and a velocity.
        
        Args:
            rotation: SO3, R (default: the identity).
            translation: shape (3,), the position p, finite (default: 0).
            velocity: shape (3,), v, finite (default: 0).
        """
    @typing.overload
    def __matmul__(self, other: SE23) -> SE23:
        """
        Composition: g_ab @ g_bc = g_ac.
        
        Args:
            other: SE23.
        
        Returns:
            SE23: the composed extended pose.
        """
    @typing.overload
    def __matmul__(self, points: numpy.typing.ArrayLike) -> typing.Any:
        """
        Action on points: q_a = R q_b + p.
        
        The array function se23_act with this extended pose: numpy's rules for dtypes and
        broadcasting.
        
        Args:
            points: array_like of shape (..., 3).
        
        Returns:
            ndarray: the moved points, shape (..., 3).
        """
    def __ne__(self, other: typing.Any) -> bool:
        """
        The negation of ``==``: some stored number differs (or is NaN), or other is not a SE23.
        
        Args:
            other: any object.
        
        Returns:
            bool.
        """
    def __pow__(self, t: float) -> SE23:
        """
        The power exp(t log g): t = 0 gives the identity, t = 1
        this extended pose, t = -1 its inverse, t = 0.5 the extended pose half way along its
        geodesic from the identity (the one whose square it is, for angles below pi),
        as scipy's ``Rotation.__pow__``.
        
        Args:
            t: the exponent, finite (not only an integer).
        
        Returns:
            SE23: the power.
        
        Example:
            >>> g = SE23.exp([0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9])
            >>> ((g ** 0.5) @ (g ** 0.5)).is_approx(g) and (g ** -1).is_approx(g.inverse())
            True
        """
    def __reduce__(self) -> tuple[typing.Any, tuple[typing.Any], typing.Any]:
        """
        Pickle support: (copyreg.__newobj__, (cls,), state).
        """
    def __reduce_ex__(self, protocol: typing.SupportsInt | typing.SupportsIndex) -> tuple[typing.Any, tuple[typing.Any], typing.Any]:
        """
        Pickle support (every protocol): (copyreg.__newobj__, (cls,), state).
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: typing.Any) -> None:
        ...
    def act(self, points: numpy.typing.ArrayLike) -> typing.Any:
        """
        Action on points: q_a = R q_b + p (the same as ``X @ points``).
        
        The array function se23_act with this extended pose: numpy's rules for dtypes and
        broadcasting.
        
        Args:
            points: array_like of shape (..., 3).
        
        Returns:
            ndarray: the moved points, shape (..., 3).
        
        Example:
            >>> SE23(translation=[1.0, 0.0, 0.0], velocity=[5.0, 5.0, 5.0]).act([[1.0, 0.0, 0.0]])
            array([[2., 0., 0.]])
        """
    def adjoint(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        The adjoint Ad_X = [[R, 0, [p] R], [0, R, [v] R], [0, 0, R]] (9x9), so that X [xi] X^-1 = [Ad_X xi].
        
        Returns:
            ndarray: shape (9, 9).
        """
    def as_matrix(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        The matrix X = [[R, p, v], [0, 1, 0], [0, 0, 1]] (5x5).
        
        Returns:
            ndarray: shape (5, 5), float64 (a new array).
        """
    def inverse(self) -> SE23:
        """
        The inverse extended pose (R^T, -R^T p, -R^T v).
        
        Returns:
            SE23: the inverse.
        
        Example:
            >>> g = SE23.exp([0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9])
            >>> (g @ g.inverse()).is_approx(SE23.identity())
            True
        """
    def is_approx(self, other: SE23, tol: float = 1e-09) -> bool:
        """
        Whether two extended poses are equal within tol: rotations within tol (absolute), positions and velocities within
        tol * max(1, |x|_max).
        
        ``==`` is the exact comparison (every stored number equal).
        
        Args:
            other: SE23.
            tol: the tolerance (>= 0).
        
        Returns:
            bool.
        """
    def log(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        The xi = (rho, nu, w) with exp([xi]) = X, rotation angle |w| in [0, pi].
        
        w = log(R) (SO3's), rho = V^-1 p, nu = V^-1 v with
        V^-1 = E I - 1/2 [w] + D w w^T, E = (theta/2) cot(theta/2).
        
        Returns:
            ndarray: xi = (rho, nu, w), shape (9,).
        
        Example:
            >>> SE23(translation=[1.0, 2.0, 3.0], velocity=[4.0, 5.0, 6.0]).log()
            array([1., 2., 3., 4., 5., 6., 0., 0., 0.])
        """
    def normalized(self) -> SE23:
        """
        The same extended pose with the nearest rotation.
        
        Removes the drift that accumulates over many compositions.
        
        Returns:
            SE23: the projected extended pose.
        """
    @property
    def rotation(self) -> SO3:
        """
        SO3: the rotation R of X.
        """
    @property
    def translation(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        ndarray: the position p, shape (3,) (a new array): the column that acts on points.
        """
    @property
    def velocity(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        ndarray: the velocity v, shape (3,) (a new array).
        """
class Twist:
    """
    A twist xi = (v, w) in se(3): linear part first, angular part second
    (Murray, Li and Sastry's order; Modern Robotics writes (w, v), see
    ``to_modern_robotics``). Its 4x4 matrix is [xi] = [[ [w], v ], [0, 0]].
    
    A twist is a velocity (spatial: (g' g^-1)^vee, body: (g^-1 g')^vee) or,
    scaled by theta, exponential coordinates of a rigid motion: SE3.exp(xi).
    Twists change frame by the adjoint, xi_a = Ad_{g_ab} xi_b (``g.act(xi)``);
    wrenches change frame by its inverse transpose. Twists add, subtract and
    scale by real numbers.
    
    Example:
        >>> xi = Twist(v=[1.0, 0.0, 0.0], w=[0.0, 0.0, 1.0])
        >>> xi.vector
        array([1., 0., 0., 0., 0., 1.])
        >>> xi.to_modern_robotics()
        array([0., 0., 1., 1., 0., 0.])
    
    Conventions (the same in C++, in README.md and in every docstring):
        - twists xi = (v, w), linear part first (Murray, Li and Sastry); the
          Modern Robotics order (w, v) only through Twist.to_modern_robotics /
          Twist.from_modern_robotics;
        - wrenches F = (f, tau), force first, so power is the dot product V . F;
        - g_ab maps frame b to frame a: q_a = g_ab q_b, g_ac = g_ab @ g_bc;
          twists change frame by Ad_g = [[R, [p]R], [0, R]], wrenches by Ad_g^-T;
        - hat(w) = [w] with [w] p = w x p; [xi] = [[ [w], v ], [0, 0]];
        - quaternions are (x, y, z, w), scalar last, as in scipy; pass
          scalar_first=True for (w, x, y, z); angles are in radians.
    
    Numbers may be given as lists, tuples or arrays of any real dtype (bool,
    integers and floats are converted to float64), in any memory layout; a wrong
    shape is a ValueError naming the expected and the given shape, a value that
    is not real (complex, object, str, None) a TypeError. Constructors refuse NaN
    and infinities (ValueError); functions that return the numbers given,
    rearranged (hat, SO3.vee, SE3.vee, actions on points), carry a NaN through,
    and the defects are inf for a matrix that is not finite.
    
    Values are float64 and immutable. ``==`` is the exact equality of the stored
    numbers, compared as floats (-0.0 == 0.0; a NaN is unequal to everything,
    itself included), ``!=`` its negation, and objects are unhashable; compare
    within a tolerance with ``is_approx(other, tol)``. Objects pickle and copy
    bit-exactly, and ``np.asarray(x)`` gives their matrix or vector.
    """
    __array_ufunc__ = None
    __hash__: typing.ClassVar[None] = None
    dtype: typing.ClassVar[numpy.dtypes.Float64DType]
    @staticmethod
    def body(g: SE3, g_dot: numpy.typing.ArrayLike) -> Twist:
        """
        The body twist of a trajectory at (g, g'): V^b = (g^-1 g')^vee.
        
        w^b = (R^T R')^vee, v^b = R^T p'.
        
        Args:
            g: SE3, the configuration.
            g_dot: its time derivative, shape (4, 4).
        
        Returns:
            Twist.
        """
    @staticmethod
    def from_modern_robotics(wv: numpy.typing.ArrayLike) -> Twist:
        """
        The twist of a 6-vector in the Modern Robotics order (w, v).
        
        Args:
            wv: shape (6,), angular part first.
        
        Returns:
            Twist.
        
        Example:
            >>> Twist.from_modern_robotics([0.0, 0.0, 1.0, 2.0, 0.0, 0.0]).vector
            array([2., 0., 0., 0., 0., 1.])
        """
    @staticmethod
    def from_screw(point: numpy.typing.ArrayLike, direction: numpy.typing.ArrayLike, pitch: float, theta: float) -> Twist:
        """
        The unit twist of a screw times theta: theta * (-d x q + h d, d).
        
        For the axis through q along d (normalized here), pitch h; with h = inf, the
        translation theta * (d, 0). A zero direction gives the zero twist.
        
        Args:
            point: q, shape (3,).
            direction: d, shape (3,).
            pitch: h; ``math.inf`` for a translation.
            theta: the magnitude.
        
        Returns:
            Twist.
        
        Example:
            >>> Twist.from_screw([0.0, 1.0, 0.0], [0.0, 0.0, 1.0], 0.0, 1.0).vector
            array([1., 0., 0., 0., 0., 1.])
        """
    @staticmethod
    def from_vector(xi: numpy.typing.ArrayLike) -> Twist:
        """
        The twist of a 6-vector (v, w), linear part first.
        
        Args:
            xi: shape (6,), finite.
        
        Returns:
            Twist.
        
        Example:
            >>> Twist.from_vector([1.0, 2.0, 3.0, 4.0, 5.0, 6.0]).angular
            array([4., 5., 6.])
        """
    @staticmethod
    def spatial(g: SE3, g_dot: numpy.typing.ArrayLike) -> Twist:
        """
        The spatial twist of a trajectory at (g, g'): V^s = (g' g^-1)^vee.
        
        w^s = (R' R^T)^vee, v^s = p' - w^s x p. V^s = Ad_g V^b.
        
        Args:
            g: SE3, the configuration.
            g_dot: its time derivative, shape (4, 4).
        
        Returns:
            Twist.
        """
    @staticmethod
    def vee(matrix: numpy.typing.ArrayLike) -> Twist:
        """
        The twist of a 4x4 matrix [[S, v], [*, *]]: v and the w of S's antisymmetric part.
        
        The bottom row is ignored.
        
        Args:
            matrix: shape (4, 4), finite.
        
        Returns:
            Twist.
        """
    def __add__(self, other: Twist) -> Twist:
        ...
    def __array__(self, dtype: numpy.typing.DTypeLike = None, copy: bool | None = None) -> numpy.ndarray:
        """
        The 6-vector, shape (6,), for np.asarray (numpy's dtype and copy keywords).
        """
    def __copy__(self) -> Twist:
        ...
    def __deepcopy__(self, memo: typing.Any) -> Twist:
        ...
    def __eq__(self, other: typing.Any) -> bool:
        """
        Exact equality of the stored numbers: Twists are values, compared as floats
        (-0.0 == 0.0; a NaN is unequal to everything, itself included).
        
        For a tolerance, use ``is_approx(other, tol)``. An object of another type gives
        NotImplemented, so ``==`` is False. Twists are unhashable.
        
        Args:
            other: any object.
        
        Returns:
            bool.
        """
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, v: numpy.typing.ArrayLike = (0.0, 0.0, 0.0), w: numpy.typing.ArrayLike = (0.0, 0.0, 0.0)) -> None:
        """
        The twist xi = (v, w) (the zero twist by default).
        
        Args:
            v: linear part, shape (3,), finite.
            w: angular part, shape (3,), finite.
        """
    def __mul__(self, scalar: float) -> Twist:
        ...
    def __ne__(self, other: typing.Any) -> bool:
        """
        The negation of ``==``: some stored number differs (or is NaN), or other is not a Twist.
        
        Args:
            other: any object.
        
        Returns:
            bool.
        """
    def __neg__(self) -> Twist:
        ...
    def __pos__(self) -> Twist:
        ...
    def __reduce__(self) -> tuple[typing.Any, tuple[typing.Any], typing.Any]:
        """
        Pickle support: (copyreg.__newobj__, (cls,), state).
        """
    def __reduce_ex__(self, protocol: typing.SupportsInt | typing.SupportsIndex) -> tuple[typing.Any, tuple[typing.Any], typing.Any]:
        """
        Pickle support (every protocol): (copyreg.__newobj__, (cls,), state).
        """
    def __repr__(self) -> str:
        ...
    def __rmul__(self, scalar: float) -> Twist:
        ...
    def __setstate__(self, arg0: typing.Any) -> None:
        ...
    def __sub__(self, other: Twist) -> Twist:
        ...
    def __truediv__(self, scalar: float) -> Twist:
        ...
    def ad(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        The adjoint of the algebra ad_xi = [[ [w], [v] ], [0, [w]]] (6x6).
        
        ad_xi eta = [xi, eta] (``xi.bracket(eta)``).
        
        Returns:
            ndarray: shape (6, 6).
        """
    def bracket(self, other: Twist) -> Twist:
        """
        The Lie bracket [xi, eta] = ([xi][eta] - [eta][xi])^vee = (w1 x v2 + v1 x w2, w1 x w2).
        
        Args:
            other: Twist, eta.
        
        Returns:
            Twist.
        """
    def hat(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        The 4x4 matrix [xi] = [[ [w], v ], [0, 0]].
        
        Returns:
            ndarray: shape (4, 4).
        """
    def is_approx(self, other: Twist, tol: float = 1e-09) -> bool:
        """
        Whether two 6-vectors are equal within tol: max |x - y| <= tol * max(1, max |x|, max |y|).
        
        ``==`` is the exact comparison (every stored number equal).
        
        Args:
            other: the same type.
            tol: the tolerance (>= 0).
        
        Returns:
            bool.
        """
    def pitch(self) -> float:
        """
        The pitch of the twist's screw: w.v / |w|^2 (a computation, as ``screw().pitch``).
        
        Returns:
            float: the pitch; inf for w = 0 (a translation), 0 for the zero twist.
        
        Example:
            >>> Twist(v=[0.0, 0.0, 0.5], w=[0.0, 0.0, 1.0]).pitch()
            0.5
        """
    def power(self, wrench: Wrench) -> float:
        """
        The power V . F = v.f + w.tau of this twist on a wrench (same frame).
        
        Args:
            wrench: Wrench, F.
        
        Returns:
            float.
        
        Example:
            >>> Twist(v=[1.0, 0.0, 0.0]).power(Wrench(f=[2.0, 0.0, 0.0]))
            2.0
        """
    def screw(self) -> Screw:
        """
        The screw of the twist (Chasles).
        
        With w != 0: pitch w.v / |w|^2, axis through w x v / |w|^2 along w / |w|,
        magnitude |w|; with w = 0: pitch inf, direction v / |v|, magnitude |v|.
        
        Returns:
            Screw.
        
        Example:
            >>> s = Twist(v=[0.0, 0.0, 0.5], w=[0.0, 0.0, 1.0]).screw()
            >>> s.pitch, s.magnitude
            (0.5, 1.0)
        """
    def to_modern_robotics(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        The 6-vector in the Modern Robotics order (w, v), angular part first.
        
        Returns:
            ndarray: shape (6,).
        """
    @property
    def angular(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        ndarray: w, shape (3,).
        """
    @property
    def linear(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        ndarray: v, shape (3,).
        """
    @property
    def vector(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        ndarray: the 6-vector (v, w), linear part first, shape (6,).
        """
class Wrench:
    """
    A wrench F = (f, tau): force first, torque second, so that the power of a
    twist V = (v, w) on it is the plain dot product V . F = v.f + w.tau.
    
    Wrenches change frame by the transpose of the adjoint: F_b = Ad_{g_ab}^T F_a
    (``g.act_inv(F)``), F_a = Ad_{g_ab}^-T F_b (``g.act(F)``), which is what keeps
    the power V . F the same in every frame. Wrenches add, subtract and scale by
    real numbers.
    
    Example:
        >>> F = Wrench(f=[0.0, 0.0, -9.81], tau=[0.0, 0.0, 0.0])
        >>> F.power(Twist(v=[0.0, 0.0, -1.0], w=[0.0, 0.0, 0.0]))
        9.81
    
    Conventions (the same in C++, in README.md and in every docstring):
        - twists xi = (v, w), linear part first (Murray, Li and Sastry); the
          Modern Robotics order (w, v) only through Twist.to_modern_robotics /
          Twist.from_modern_robotics;
        - wrenches F = (f, tau), force first, so power is the dot product V . F;
        - g_ab maps frame b to frame a: q_a = g_ab q_b, g_ac = g_ab @ g_bc;
          twists change frame by Ad_g = [[R, [p]R], [0, R]], wrenches by Ad_g^-T;
        - hat(w) = [w] with [w] p = w x p; [xi] = [[ [w], v ], [0, 0]];
        - quaternions are (x, y, z, w), scalar last, as in scipy; pass
          scalar_first=True for (w, x, y, z); angles are in radians.
    
    Numbers may be given as lists, tuples or arrays of any real dtype (bool,
    integers and floats are converted to float64), in any memory layout; a wrong
    shape is a ValueError naming the expected and the given shape, a value that
    is not real (complex, object, str, None) a TypeError. Constructors refuse NaN
    and infinities (ValueError); functions that return the numbers given,
    rearranged (hat, SO3.vee, SE3.vee, actions on points), carry a NaN through,
    and the defects are inf for a matrix that is not finite.
    
    Values are float64 and immutable. ``==`` is the exact equality of the stored
    numbers, compared as floats (-0.0 == 0.0; a NaN is unequal to everything,
    itself included), ``!=`` its negation, and objects are unhashable; compare
    within a tolerance with ``is_approx(other, tol)``. Objects pickle and copy
    bit-exactly, and ``np.asarray(x)`` gives their matrix or vector.
    """
    __array_ufunc__ = None
    __hash__: typing.ClassVar[None] = None
    dtype: typing.ClassVar[numpy.dtypes.Float64DType]
    @staticmethod
    def from_screw(point: numpy.typing.ArrayLike, direction: numpy.typing.ArrayLike, pitch: float, magnitude: float) -> Wrench:
        """
        The wrench of a screw: magnitude * (d, q x d + h d).
        
        For the line through q along d (normalized here), pitch h; with h = inf, the
        couple (0, magnitude * d). A zero direction gives the zero wrench.
        
        Args:
            point: q, shape (3,).
            direction: d, shape (3,).
            pitch: h; ``math.inf`` for a pure couple.
            magnitude: the force size (the torque for h = inf).
        
        Returns:
            Wrench.
        
        Example:
            >>> Wrench.from_screw([0.0, 1.0, 0.0], [1.0, 0.0, 0.0], 0.0, 2.0).vector
            array([ 2.,  0.,  0.,  0.,  0., -2.])
        """
    @staticmethod
    def from_vector(F: numpy.typing.ArrayLike) -> Wrench:
        """
        The wrench of a 6-vector (f, tau), force first.
        
        Args:
            F: shape (6,), finite.
        
        Returns:
            Wrench.
        
        Example:
            >>> Wrench.from_vector([1.0, 2.0, 3.0, 4.0, 5.0, 6.0]).torque
            array([4., 5., 6.])
        """
    def __add__(self, other: Wrench) -> Wrench:
        ...
    def __array__(self, dtype: numpy.typing.DTypeLike = None, copy: bool | None = None) -> numpy.ndarray:
        """
        The 6-vector, shape (6,), for np.asarray (numpy's dtype and copy keywords).
        """
    def __copy__(self) -> Wrench:
        ...
    def __deepcopy__(self, memo: typing.Any) -> Wrench:
        ...
    def __eq__(self, other: typing.Any) -> bool:
        """
        Exact equality of the stored numbers: Wrenchs are values, compared as floats
        (-0.0 == 0.0; a NaN is unequal to everything, itself included).
        
        For a tolerance, use ``is_approx(other, tol)``. An object of another type gives
        NotImplemented, so ``==`` is False. Wrenchs are unhashable.
        
        Args:
            other: any object.
        
        Returns:
            bool.
        """
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, f: numpy.typing.ArrayLike = (0.0, 0.0, 0.0), tau: numpy.typing.ArrayLike = (0.0, 0.0, 0.0)) -> None:
        """
        The wrench F = (f, tau) (the zero wrench by default).
        
        Args:
            f: force, shape (3,), finite.
            tau: torque, shape (3,), finite.
        """
    def __mul__(self, scalar: float) -> Wrench:
        ...
    def __ne__(self, other: typing.Any) -> bool:
        """
        The negation of ``==``: some stored number differs (or is NaN), or other is not a Wrench.
        
        Args:
            other: any object.
        
        Returns:
            bool.
        """
    def __neg__(self) -> Wrench:
        ...
    def __pos__(self) -> Wrench:
        ...
    def __reduce__(self) -> tuple[typing.Any, tuple[typing.Any], typing.Any]:
        """
        Pickle support: (copyreg.__newobj__, (cls,), state).
        """
    def __reduce_ex__(self, protocol: typing.SupportsInt | typing.SupportsIndex) -> tuple[typing.Any, tuple[typing.Any], typing.Any]:
        """
        Pickle support (every protocol): (copyreg.__newobj__, (cls,), state).
        """
    def __repr__(self) -> str:
        ...
    def __rmul__(self, scalar: float) -> Wrench:
        ...
    def __setstate__(self, arg0: typing.Any) -> None:
        ...
    def __sub__(self, other: Wrench) -> Wrench:
        ...
    def __truediv__(self, scalar: float) -> Wrench:
        ...
    def is_approx(self, other: Wrench, tol: float = 1e-09) -> bool:
        """
        Whether two 6-vectors are equal within tol: max |x - y| <= tol * max(1, max |x|, max |y|).
        
        ``==`` is the exact comparison (every stored number equal).
        
        Args:
            other: the same type.
            tol: the tolerance (>= 0).
        
        Returns:
            bool.
        """
    def pitch(self) -> float:
        """
        The pitch of the wrench's screw: f.tau / |f|^2 (a computation, as ``screw().pitch``).
        
        Returns:
            float: the pitch; inf for f = 0 (a pure couple), 0 for the zero wrench.
        """
    def power(self, twist: Twist) -> float:
        """
        The power V . F = v.f + w.tau of a twist on this wrench (same frame).
        
        Args:
            twist: Twist, V.
        
        Returns:
            float.
        """
    def screw(self) -> Screw:
        """
        The screw of the wrench (Poinsot).
        
        With f != 0, a force along the line through f x tau / |f|^2 with direction
        f / |f|, magnitude |f|, plus a torque pitch * f about it,
        pitch = f.tau / |f|^2; with f = 0, a pure couple: pitch inf, direction
        tau / |tau|, magnitude |tau|.
        
        Returns:
            Screw.
        """
    @property
    def force(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        ndarray: f, shape (3,).
        """
    @property
    def torque(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        ndarray: tau, shape (3,).
        """
    @property
    def vector(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        ndarray: the 6-vector (f, tau), force first, shape (6,).
        """
class Screw:
    """
    A screw: a directed line in space (through ``point``, along the unit
    ``direction``), a ``pitch`` and a ``magnitude``.
    
    For a twist it is Chasles' screw motion: rotate by ``magnitude`` about the
    line while translating ``pitch * magnitude`` along it; pitch = inf is a pure
    translation of length ``magnitude`` along ``direction``. For a wrench it is
    Poinsot's wrench: a force of size ``magnitude`` along the line plus a torque
    ``pitch * magnitude`` about it; pitch = inf is a pure couple. ``point`` is
    the point of the line nearest the origin (0 for infinite pitch). The zero
    twist or wrench has magnitude 0, pitch 0, direction 0.
    
    A Screw unpacks as ``point, direction, pitch, magnitude = screw``, so
    ``SE3.from_screw(*twist.screw())`` rebuilds the motion.
    
    Example:
        >>> s = Twist(v=[2.0, 0.0, 0.0], w=[0.0, 0.0, 1.0]).screw()
        >>> s.point, s.direction, s.pitch, s.magnitude
        (array([0., 2., 0.]), array([0., 0., 1.]), 0.0, 1.0)
    """
    __array_ufunc__ = None
    __hash__: typing.ClassVar[None] = None
    def __copy__(self) -> Screw:
        ...
    def __deepcopy__(self, memo: typing.Any) -> Screw:
        ...
    def __eq__(self, other: typing.Any) -> bool:
        """
        Exact equality of the stored numbers: Screws are values, compared as floats
        (-0.0 == 0.0; a NaN is unequal to everything, itself included).
        
        For a tolerance, use ``is_approx(other, tol)``. An object of another type gives
        NotImplemented, so ``==`` is False. Screws are unhashable.
        
        Args:
            other: any object.
        
        Returns:
            bool.
        """
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, point: numpy.typing.ArrayLike, direction: numpy.typing.ArrayLike, pitch: float, magnitude: float) -> None:
        """
        A screw from its parameters (stored as given).
        
        Args:
            point: a point of the axis, shape (3,), finite.
            direction: the axis direction, shape (3,), finite (unit length by
                convention; from_screw normalizes it).
            pitch: translation (or torque) per unit of magnitude; inf allowed.
            magnitude: rotation angle (twist) or force size (wrench), finite.
        """
    def __iter__(self) -> collections.abc.Iterator:
        ...
    def __len__(self) -> int:
        ...
    def __ne__(self, other: typing.Any) -> bool:
        """
        The negation of ``==``: some stored number differs (or is NaN), or other is not a Screw.
        
        Args:
            other: any object.
        
        Returns:
            bool.
        """
    def __reduce__(self) -> tuple[typing.Any, tuple[typing.Any], typing.Any]:
        """
        Pickle support: (copyreg.__newobj__, (cls,), state).
        """
    def __reduce_ex__(self, protocol: typing.SupportsInt | typing.SupportsIndex) -> tuple[typing.Any, tuple[typing.Any], typing.Any]:
        """
        Pickle support (every protocol): (copyreg.__newobj__, (cls,), state).
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: typing.Any) -> None:
        ...
    def is_approx(self, other: Screw, tol: float = 1e-09) -> bool:
        """
        Whether two screws have the same parameters within tol (relative beyond unit scale).
        
        Args:
            other: Screw.
            tol: the tolerance (>= 0).
        
        Returns:
            bool.
        """
    @property
    def direction(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        ndarray: the unit direction of the axis, shape (3,).
        """
    @property
    def magnitude(self) -> float:
        """
        float: the magnitude.
        """
    @property
    def pitch(self) -> float:
        """
        float: the pitch (inf for a translation or a couple).
        """
    @property
    def point(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        ndarray: the point of the axis nearest the origin, shape (3,).
        """
class SpatialInertia:
    """
    The inertia of a rigid body described in some frame: mass m, center of mass c
    and rotational inertia I_c about the center of mass, both in that frame.
    
    Its 6x6 matrix is in the twist order (v, w), so that the momentum of the body
    moving with the twist V = (v, w) is the wrench h = G V = (f, tau) (linear
    momentum, then angular momentum about the frame's origin) and its kinetic
    energy is 1/2 V^T G V:
    
        G = [[ m 1,     -m [c]         ],
             [ m [c],    I_c - m [c]^2 ]]
    
    (Murray, Li and Sastry, ch. 4.2; Lynch and Park, Modern Robotics, ch. 8.2,
    where the order is (w, v); Pinocchio's ``Inertia`` in the order (v, w)). The
    same body described in frame a, given in frame b: ``I.transform(g_ab)``, with
    c_a = R c_b + p, I_a = R I_c R^T and G_a = Ad_g^-T G_b Ad_g^-1.
    
    The constructor accepts only inertias that a rigid body has. Chain's
    link_inertias and Chain.from_urdf accept any (real robot descriptions have
    some that break the triangle inequality); Chain.forward_dynamics raises
    where they leave the mass matrix not positive definite.
    
    Example:
        >>> body = SpatialInertia(2.0, [0.0, 0.0, 0.5], np.diag([0.1, 0.1, 0.02]))
        >>> body.momentum(Twist(v=[1.0, 0.0, 0.0], w=[0.0, 0.0, 0.0])).force
        array([2., 0., 0.])
        >>> body.kinetic_energy(Twist(v=[1.0, 0.0, 0.0], w=[0.0, 0.0, 0.0]))
        1.0
    
    Conventions (the same in C++, in README.md and in every docstring):
        - twists xi = (v, w), linear part first (Murray, Li and Sastry); the
          Modern Robotics order (w, v) only through Twist.to_modern_robotics /
          Twist.from_modern_robotics;
        - wrenches F = (f, tau), force first, so power is the dot product V . F;
        - g_ab maps frame b to frame a: q_a = g_ab q_b, g_ac = g_ab @ g_bc;
          twists change frame by Ad_g = [[R, [p]R], [0, R]], wrenches by Ad_g^-T;
        - hat(w) = [w] with [w] p = w x p; [xi] = [[ [w], v ], [0, 0]];
        - quaternions are (x, y, z, w), scalar last, as in scipy; pass
          scalar_first=True for (w, x, y, z); angles are in radians.
    
    Numbers may be given as lists, tuples or arrays of any real dtype (bool,
    integers and floats are converted to float64), in any memory layout; a wrong
    shape is a ValueError naming the expected and the given shape, a value that
    is not real (complex, object, str, None) a TypeError. Constructors refuse NaN
    and infinities (ValueError); functions that return the numbers given,
    rearranged (hat, SO3.vee, SE3.vee, actions on points), carry a NaN through,
    and the defects are inf for a matrix that is not finite.
    
    Values are float64 and immutable. ``==`` is the exact equality of the stored
    numbers, compared as floats (-0.0 == 0.0; a NaN is unequal to everything,
    itself included), ``!=`` its negation, and objects are unhashable; compare
    within a tolerance with ``is_approx(other, tol)``. Objects pickle and copy
    bit-exactly, and ``np.asarray(x)`` gives their matrix or vector.
    """
    __array_ufunc__ = None
    __hash__: typing.ClassVar[None] = None
    dtype: typing.ClassVar[numpy.dtypes.Float64DType]
    def __add__(self, other: SpatialInertia) -> SpatialInertia:
        """
        The two bodies rigidly joined (both described in the same frame): the matrices add.
        """
    def __array__(self, dtype: numpy.typing.DTypeLike = None, copy: bool | None = None) -> numpy.ndarray:
        """
        The matrix G, shape (6, 6), for np.asarray (numpy's dtype and copy keywords).
        """
    def __copy__(self) -> SpatialInertia:
        ...
    def __deepcopy__(self, memo: typing.Any) -> SpatialInertia:
        ...
    def __eq__(self, other: typing.Any) -> bool:
        """
        Exact equality of the stored numbers: SpatialInertias are values, compared as floats
        (-0.0 == 0.0; a NaN is unequal to everything, itself included).
        
        For a tolerance, use ``is_approx(other, tol)``. An object of another type gives
        NotImplemented, so ``==`` is False. SpatialInertias are unhashable.
        
        Args:
            other: any object.
        
        Returns:
            bool.
        """
    def __getstate__(self) -> tuple:
        ...
    def __init__(self, mass: float, com: numpy.typing.ArrayLike, inertia: numpy.typing.ArrayLike) -> None:
        """
        A rigid body's inertia from its mass, center of mass and rotational inertia about it.
        
        Args:
            mass: m > 0, finite.
            com: shape (3,), c, the center of mass in the frame of description.
            inertia: shape (3, 3), I_c, the rotational inertia about the center of
                mass (axes of that frame): symmetric, positive definite, with
                principal moments that satisfy the triangle inequality
                I_1 + I_2 >= I_3 (each to a relative 1.5e-8).
        
        Raises:
            ValueError: a wrong shape, a non-finite number, m <= 0, or an inertia
                that no rigid body has (the message says which condition fails).
        
        Example:
            >>> SpatialInertia(1.0, [0.0, 0.0, 0.0], np.eye(3)).mass
            1.0
        """
    def __ne__(self, other: typing.Any) -> bool:
        """
        The negation of ``==``: some stored number differs (or is NaN), or other is not a SpatialInertia.
        
        Args:
            other: any object.
        
        Returns:
            bool.
        """
    def __reduce__(self) -> tuple[typing.Any, tuple[typing.Any], typing.Any]:
        """
        Pickle support: (copyreg.__newobj__, (cls,), state).
        """
    def __reduce_ex__(self, protocol: typing.SupportsInt | typing.SupportsIndex) -> tuple[typing.Any, tuple[typing.Any], typing.Any]:
        """
        Pickle support (every protocol): (copyreg.__newobj__, (cls,), state).
        """
    def __repr__(self) -> str:
        ...
    def __setstate__(self, arg0: typing.Any) -> None:
        ...
    def is_approx(self, other: SpatialInertia, tol: float = 1e-09) -> bool:
        """
        Whether m, c and I_c agree within tol (>= 0): max difference <= tol * max(1, their largest magnitude).
        
        ``==`` is the exact comparison.
        """
    def kinetic_energy(self, twist: numpy.typing.ArrayLike) -> float:
        """
        T = 1/2 V^T G V = 1/2 (m |v_c|^2 + w . I_c w), a float; twist: a Twist or shape (6,).
        
        Example:
            >>> SpatialInertia(2.0, [0.0, 0.0, 0.0], np.eye(3)).kinetic_energy([1.0, 0.0, 0.0, 0.0, 0.0, 0.0])
            1.0
        """
    def momentum(self, twist: numpy.typing.ArrayLike) -> Wrench:
        """
        The momentum wrench h = G V = (m v_c, c x m v_c + I_c w), v_c = v + w x c.
        
        twist: a Twist or shape (6,), V = (v, w) in the frame of description. Returns a
        Wrench: (linear momentum, angular momentum about the frame's origin).
        
        Example:
            >>> body = SpatialInertia(2.0, [0.0, 0.0, 0.0], np.eye(3))
            >>> body.momentum(Twist(w=[0.0, 0.0, 3.0])).torque
            array([0., 0., 3.])
        """
    def transform(self, g: SE3) -> SpatialInertia:
        """
        The same body described in frame a, this one describing it in frame b; g = g_ab (SE3).
        
        c_a = R c + p, I_a = R I_c R^T, G_a = Ad_g^-T G Ad_g^-1: the kinetic energy of
        a motion is the same in both frames. Returns a SpatialInertia.
        
        Example:
            >>> body = SpatialInertia(1.0, [0.0, 0.0, 0.0], np.eye(3))
            >>> body.transform(SE3(translation=[1.0, 2.0, 3.0])).com
            array([1., 2., 3.])
        """
    @property
    def com(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        ndarray: c, the center of mass, shape (3,).
        """
    @property
    def inertia(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        ndarray: I_c, the rotational inertia about the center of mass, shape (3, 3).
        """
    @property
    def mass(self) -> float:
        """
        float: m, the mass.
        """
    @property
    def matrix(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        ndarray: G, shape (6, 6), order (v, w): [[m 1, -m [c]], [m [c], I_c - m [c]^2]].
        """
class _Chain:
    """
    The private model of chasles.Chain (python/chasles/_chain.py): the C++ chain (include/chasles/kinematics.hpp) and the methods that compute.
    """
    __array_ufunc__ = None
    @staticmethod
    def _set_ik_result(type: typing.Any) -> None:
        """
        Hands over chasles._results.IKResult, the result type of inverse_kinematics (called by chasles._chain).
        """
    @staticmethod
    def prismatic_screw(direction: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
        """
        The screw (v, 0) of a prismatic joint, v = direction / |direction| (shape (3,), nonzero).
        """
    @staticmethod
    def revolute_screw(point: numpy.typing.ArrayLike, direction: numpy.typing.ArrayLike) -> numpy.typing.NDArray[numpy.float64]:
        """
        The screw (-w x q, w) of a revolute joint about the axis through point q along direction w.
        
        The point comes first, as in ``SE3.from_screw``; both shape (3,), w nonzero (normalized here).
        Returns shape (6,), (v, w).
        """
    def __init__(self, screws: numpy.typing.ArrayLike, home: typing.Any, joint_types: typing.Any, lower: typing.Any, upper: typing.Any, velocity_limits: typing.Any, effort_limits: typing.Any, base: typing.Any, tool: typing.Any, gravity: typing.Any, link_inertias: typing.Any, home_as_given: bool, unit_screws: bool) -> None:
        """
        The model from chasles.Chain's arguments (joint types as codes 0, 1, 2, 3 or None).
        """
    def _arrays(self) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64], tuple, numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64], SE3, SE3, numpy.typing.NDArray[numpy.float64]]:
        """
        (space screws, body screws, type codes, lower, upper, velocity and effort limits, base, tool, gravity).
        """
    def _check(self) -> tuple[int, int]:
        """
        Chain::validate(): (ChainStatus as an int, joint).
        """
    def coriolis(self, q: typing.Any, qd: typing.Any) -> typing.Any:
        """
        The Coriolis and centrifugal torques C(q, qd) qd (no gravity).
        
        q, qd: array_like (..., n); returns (..., n).
        
        An array function: (n,) gives one result, (..., n) one per configuration,
        by numpy's rules (broadcasting, dtypes, the GIL released; NaN gives NaN). ValueError: a chain without link inertias, shapes that do not match.
        """
    def forward(self, theta: numpy.typing.ArrayLike) -> typing.Any:
        """
        Forward kinematics, space form: g(theta) = exp([S_1] th_1) ... exp([S_n] th_n) M.
        
        theta: array_like (..., n), joint positions; returns (..., 4, 4), the tool frame's matrices.
        
        An array function: (n,) gives one result, (..., n) one per configuration,
        by numpy's rules (broadcasting, dtypes, the GIL released; NaN gives NaN).
        """
    def forward_body(self, theta: numpy.typing.ArrayLike) -> typing.Any:
        """
        Forward kinematics, body form: g(theta) = M exp([B_1] th_1) ... exp([B_n] th_n).
        
        Equal to ``forward`` up to rounding. theta: array_like (..., n); returns (..., 4, 4).
        
        An array function: (n,) gives one result, (..., n) one per configuration,
        by numpy's rules (broadcasting, dtypes, the GIL released; NaN gives NaN).
        """
    def forward_dynamics(self, q: typing.Any, qd: typing.Any, tau: typing.Any, *, tip_wrench: typing.Any = None, on_failure: typing.Any = 'raise') -> typing.Any:
        """
        Forward dynamics: qdd = M(q)^-1 (tau - C(q, qd) qd - g(q) - J_b^T F_tip).
        
        By the composite inertias and a Cholesky factorization of M(q), or from 30 joints on by the
        articulated-body algorithm, O(n) (the faster of the two; they agree to rounding).
        q, qd, tau: array_like (..., n); tip_wrench as in inverse_dynamics. Where M(q) is not
        positive definite (a massless link, a point mass on its axis, an inertia no rigid body has:
        chasles::DynamicsStatus) there are no accelerations: ValueError naming the joint (and the
        first such batch index), or with on_failure="nan" NaN there only. Returns (..., n).
        
        An array function: (n,) gives one result, (..., n) one per configuration,
        by numpy's rules (broadcasting, dtypes, the GIL released; NaN gives NaN). ValueError: a chain without link inertias, shapes that do not match.
        """
    def forward_dynamics_derivatives(self, q: typing.Any, qd: typing.Any, tau: typing.Any, *, tip_wrench: typing.Any = None, on_failure: typing.Any = 'raise') -> typing.Any:
        """
        The partial derivatives (dqdd_dq, dqdd_dqd, dqdd_dtau) of forward_dynamics at (q, qd, tau).
        
        With qdd = forward_dynamics(q, qd, tau): dqdd_dq = -M^-1 dtau_dq, dqdd_dqd = -M^-1 dtau_dqd
        (inverse_dynamics_derivatives at (q, qd, qdd)) and dqdd_dtau = M(q)^-1, analytic, O(n^3).
        Fails where forward_dynamics fails (ValueError, or NaN with on_failure="nan").
        q, qd, tau: array_like (..., n); tip_wrench as in inverse_dynamics. Returns three arrays of
        shape (..., n, n).
        
        An array function: (n,) gives one result, (..., n) one per configuration,
        by numpy's rules (broadcasting, dtypes, the GIL released; NaN gives NaN). ValueError: a chain without link inertias, shapes that do not match.
        """
    def gravity_torques(self, q: numpy.typing.ArrayLike) -> typing.Any:
        """
        The torques g(q) that hold the chain still against gravity: inverse_dynamics(q, 0, 0).
        
        q: array_like (..., n); returns (..., n).
        
        An array function: (n,) gives one result, (..., n) one per configuration,
        by numpy's rules (broadcasting, dtypes, the GIL released; NaN gives NaN). ValueError: a chain without link inertias, shapes that do not match.
        """
    def inverse_dynamics(self, q: typing.Any, qd: typing.Any, qdd: typing.Any, *, tip_wrench: typing.Any = None) -> typing.Any:
        """
        Inverse dynamics: tau = M(q) qdd + C(q, qd) qd + g(q) + J_b(q)^T F_tip (Newton-Euler).
        
        q, qd, qdd: array_like (..., n); tip_wrench: (..., 6) or a Wrench, (f, tau) that the tool
        applies on the environment, in the tool frame (Modern Robotics' F_tip); None: zero.
        Returns (..., n), N m for revolute joints and N for prismatic ones.
        
        An array function: (n,) gives one result, (..., n) one per configuration,
        by numpy's rules (broadcasting, dtypes, the GIL released; NaN gives NaN). ValueError: a chain without link inertias, shapes that do not match.
        """
    def inverse_dynamics_derivatives(self, q: typing.Any, qd: typing.Any, qdd: typing.Any, *, tip_wrench: typing.Any = None) -> typing.Any:
        """
        The partial derivatives (dtau_dq, dtau_dqd) of inverse_dynamics at (q, qd, qdd), analytic.
        
        dtau_dq[i, j] = d tau_i / d q_j, likewise for qd; d tau / d qdd is mass_matrix(q). The
        recursion of inverse dynamics differentiated in closed form (base frame; Carpentier and
        Mansard, RSS 2018), O(n^2): what an optimal-control or MPC solver linearizes with.
        q, qd, qdd: array_like (..., n); tip_wrench as in inverse_dynamics. Returns two arrays of
        shape (..., n, n).
        
        An array function: (n,) gives one result, (..., n) one per configuration,
        by numpy's rules (broadcasting, dtypes, the GIL released; NaN gives NaN). ValueError: a chain without link inertias, shapes that do not match.
        """
    def inverse_kinematics(self, target: numpy.typing.ArrayLike, q0: numpy.typing.ArrayLike, *, position_tolerance: float = 3.666852862501036e-11, orientation_tolerance: float = 3.666852862501036e-11, max_iterations: typing.SupportsIndex = 100, restarts: typing.SupportsIndex = 0, seed: typing.SupportsIndex = 0, max_time: float | None = None) -> chasles._results.IKResult:
        """
        Inverse kinematics: joint positions q with forward(q) = target, within the joint limits.
        
        Levenberg-Marquardt on the body error e(q) = log(forward(q)^-1 target)
        (twist (v, w) in the tool frame) with its exact Jacobian -J_l(e)^-1 J_b(q),
        each step projected onto [lower, upper], at most max_iterations iterations
        per attempt; then, while not converged, up to ``restarts`` more attempts
        from seeds uniform within the limits ([-pi, pi] where a limit is infinite),
        drawn from a 64-bit Mersenne twister seeded with ``seed`` (an attempt that
        a restart follows ends as soon as it stalls, |e|^2 above 0.9 of its value
        8 iterations before; the last runs on); all within
        ``max_time`` seconds when given (checked before each iteration). The C++
        solver (chasles/inverse_kinematics.hpp) runs with the GIL released.
        
        The field's protocols (TRAC-IK's: 5 ms per solve) read
        ``inverse_kinematics(T, q0, restarts=2**31 - 1, max_time=0.005)``: restart
        until solved or out of time.
        
        Targets and seeds broadcast: one target (an SE3 or (4, 4)) and q0 (n,) give
        one solve; (..., 4, 4) targets and/or (..., n) seeds give a batch (the
        private gufunc ``chasles._core._inverse_kinematics``). Element i of a batch
        (in C order) draws its restarts from a generator seeded with ``seed + i``
        and has a budget of its own: it equals the single solve with that seed.
        
        Args:
            target: SE3 or array_like of shape (4, 4) or (..., 4, 4), the tool pose(s).
            q0: array_like of shape (n,) or (..., n), the seed(s) (clamped into the limits).
            position_tolerance: |e_v| at a solution (the chain's length unit); default 3.7e-11.
            orientation_tolerance: |e_w| at a solution (radians); default 3.7e-11.
            max_iterations: iterations per attempt (>= 0).
            restarts: further attempts from random seeds while not converged (>= 0).
            seed: the seed of those random seeds (0 <= seed < 2**64; seed + i for
                element i of a batch).
            max_time: the time budget of a solve in seconds, restarts included
                (None: none). A solve ends at most one iteration after it.
        
        Returns:
            IKResult: a named tuple (q, converged, status, iterations,
            total_iterations, attempts, error): q of shape (n,); converged a bool;
            status why it stopped, a str: "converged", "iteration_bound" (the last
            attempt ran max_iterations iterations), "time_budget" (max_time ran out)
            or "no_progress" (stalled at a local minimum of |e|: its step below
            rounding, or, when a restart followed, |e|^2 above 0.9 of its value 8
            iterations before);
            iterations of the attempt that gave q; total_iterations of all
            attempts; attempts made (1 + the restarts taken); the body error twist e
            of shape (6,). For a batch, arrays of shapes (..., n), (...) (status:
            str), and (..., 6).
        
        Raises:
            ValueError: a target that is not a rigid motion, shapes that do not
                match or broadcast, a non-finite seed, negative counts, tolerances
                or time.
            TypeError: an argument of the wrong type.
        
        Example:
            >>> arm = Chain([Chain.revolute_screw([0, 0, 0], [0, 0, 1]),
            ...              Chain.revolute_screw([1, 0, 0], [0, 0, 1])], SE3(SO3(), [2, 0, 0]))
            >>> r = arm.inverse_kinematics(arm.forward([0.3, -0.5]), [0.0, -0.2])
            >>> r.converged, r.status, np.round(r.q, 12) + 0.0
            (True, 'converged', array([ 0.3, -0.5]))
        """
    def jacobian_body(self, theta: numpy.typing.ArrayLike) -> typing.Any:
        """
        The body Jacobian J_b: (g^-1 g')^vee = J_b theta'.
        
        Column i is Ad_{(exp([B_{i+1}] th_{i+1}) ... exp([B_n] th_n))^-1} B_i, rows (v, w).
        theta: array_like (..., n); returns (..., 6, n).
        
        An array function: (n,) gives one result, (..., n) one per configuration,
        by numpy's rules (broadcasting, dtypes, the GIL released; NaN gives NaN).
        """
    def jacobian_body_dot(self, theta: typing.Any, theta_dot: typing.Any) -> typing.Any:
        """
        The time derivative of the body Jacobian, dJ_b/dt, at joint positions and velocities.
        
        Column i is Ad_{g^-1} [V_{i-1} - V^s, S_i(theta)] (V^s = J_s theta_dot). The tool's body
        acceleration is J_b theta_ddot + J_b_dot theta_dot: what a task-space controller feeds forward.
        theta, theta_dot: array_like (..., n); returns (..., 6, n).
        
        An array function: (n,) gives one result, (..., n) one per configuration,
        by numpy's rules (broadcasting, dtypes, the GIL released; NaN gives NaN).
        """
    def jacobian_space(self, theta: numpy.typing.ArrayLike) -> typing.Any:
        """
        The space Jacobian J_s: (g' g^-1)^vee = J_s theta'.
        
        Column i is Ad_{exp([S_1] th_1) ... exp([S_{i-1}] th_{i-1})} S_i, rows (v, w); J_s = Ad_g J_b.
        theta: array_like (..., n); returns (..., 6, n).
        
        An array function: (n,) gives one result, (..., n) one per configuration,
        by numpy's rules (broadcasting, dtypes, the GIL released; NaN gives NaN).
        """
    def jacobian_space_dot(self, theta: typing.Any, theta_dot: typing.Any) -> typing.Any:
        """
        The time derivative of the space Jacobian, dJ_s/dt, at joint positions and velocities.
        
        Column i is [V_{i-1}, S_i(theta)]: the bracket of the twist of the link before joint i
        (sum_{j<i} S_j(theta) theta_dot_j) with joint i's screw. The tool's spatial acceleration
        (the time derivative of V^s) is J_s theta_ddot + J_s_dot theta_dot.
        theta, theta_dot: array_like (..., n); returns (..., 6, n).
        
        An array function: (n,) gives one result, (..., n) one per configuration,
        by numpy's rules (broadcasting, dtypes, the GIL released; NaN gives NaN).
        """
    def mass_matrix(self, q: numpy.typing.ArrayLike) -> typing.Any:
        """
        The joint-space mass matrix M(q), symmetric positive definite (composite rigid bodies).
        
        q: array_like (..., n); returns (..., n, n).
        
        An array function: (n,) gives one result, (..., n) one per configuration,
        by numpy's rules (broadcasting, dtypes, the GIL released; NaN gives NaN). ValueError: a chain without link inertias, shapes that do not match.
        """
    def mass_matrix_inverse(self, q: typing.Any, *, on_failure: typing.Any = 'raise') -> typing.Any:
        """
        M(q)^-1, by the Cholesky factorization of forward_dynamics (Pinocchio's computeMinverse).
        
        Fails where forward_dynamics fails (ValueError, or NaN with on_failure="nan").
        q: array_like (..., n); returns (..., n, n).
        
        An array function: (n,) gives one result, (..., n) one per configuration,
        by numpy's rules (broadcasting, dtypes, the GIL released; NaN gives NaN). ValueError: a chain without link inertias, shapes that do not match.
        """
    @property
    def home(self) -> SE3:
        """
        SE3: the home pose M = g(0).
        """
def _se23_bspline_new(start_time: float, spacing: float, control: numpy.typing.ArrayLike) -> tuple[float, float, numpy.ndarray]:
    """
    The checked arguments of SE23BSpline(start_time, spacing, control): (start_time, spacing, the control elements as a new read-only (N, 5, 5) float64 array of keys), or the SE23BSpline constructor's ValueError / TypeError. A private function of chasles.SE23BSpline (python/chasles/_bspline.py).
    """
def _se23_mean(matrices: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], weights: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], geodesic: bool, max_iterations: typing.SupportsInt | typing.SupportsIndex) -> tuple:
    """
    The C++ mean behind chasles.se23_mean, on checked (N, 5, 5) float64 elements and (N,) weights: (mean, iterations, converged).
    """
def _se23_spline_fit(times: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], keys: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], natural: bool) -> numpy.ndarray:
    """
    The coefficients (n, 27) of the spline through checked (n,) float64 times and (n, 5, 5) keys (row i: c1, c2, c3 of segment i; the last row zero).
    """
def _se2_bspline_new(start_time: float, spacing: float, control: numpy.typing.ArrayLike) -> tuple[float, float, numpy.ndarray]:
    """
    The checked arguments of SE2BSpline(start_time, spacing, control): (start_time, spacing, the control elements as a new read-only (N, 3, 3) float64 array of keys), or the SE2BSpline constructor's ValueError / TypeError. A private function of chasles.SE2BSpline (python/chasles/_bspline.py).
    """
def _se2_mean(matrices: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], weights: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], geodesic: bool, max_iterations: typing.SupportsInt | typing.SupportsIndex) -> tuple:
    """
    The C++ mean behind chasles.se2_mean, on checked (N, 3, 3) float64 elements and (N,) weights: (mean, iterations, converged).
    """
def _se2_spline_fit(times: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], keys: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], natural: bool) -> numpy.ndarray:
    """
    The coefficients (n, 9) of the spline through checked (n,) float64 times and (n, 3, 3) keys (row i: c1, c2, c3 of segment i; the last row zero).
    """
def _se3_align(a: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], b: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], weights: typing.Any) -> tuple:
    """
    The C++ se3_align behind chasles.se3_align, on (N, 3) float64 points a, b and (N,) weights or None: (matrix, rssd, singular_values, status).
    """
def _se3_bspline_new(start_time: float, spacing: float, control: numpy.typing.ArrayLike) -> tuple[float, float, numpy.ndarray]:
    """
    The checked arguments of SE3BSpline(start_time, spacing, control): (start_time, spacing, the control elements as a new read-only (N, 4, 4) float64 array of poses), or the SE3BSpline constructor's ValueError / TypeError. A private function of chasles.SE3BSpline (python/chasles/_bspline.py).
    """
def _se3_mean(matrices: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], weights: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], geodesic: bool, max_iterations: typing.SupportsInt | typing.SupportsIndex) -> tuple:
    """
    The C++ mean behind chasles.se3_mean, on checked (N, 4, 4) float64 elements and (N,) weights: (mean, iterations, converged).
    """
def _se3_spline_fit(times: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], keys: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], natural: bool) -> numpy.ndarray:
    """
    The coefficients (n, 18) of the spline through checked (n,) float64 times and (n, 4, 4) poses (row i: c1, c2, c3 of segment i; the last row zero).
    """
def _set_num_threads(n: typing.SupportsInt | typing.SupportsIndex) -> None:
    """
    The setter behind chasles.set_num_threads (python/chasles/_threads.py, which checks n and names the errors).
    """
def _sim3_align(a: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], b: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], weights: typing.Any) -> tuple:
    """
    The C++ sim3_align behind chasles.sim3_align, on (N, 3) float64 points a, b and (N,) weights or None: (matrix, rssd, singular_values, status).
    """
def _sim3_bspline_new(start_time: float, spacing: float, control: numpy.typing.ArrayLike) -> tuple[float, float, numpy.ndarray]:
    """
    The checked arguments of Sim3BSpline(start_time, spacing, control): (start_time, spacing, the control elements as a new read-only (N, 4, 4) float64 array of keys), or the Sim3BSpline constructor's ValueError / TypeError. A private function of chasles.Sim3BSpline (python/chasles/_bspline.py).
    """
def _sim3_mean(matrices: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], weights: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], geodesic: bool, max_iterations: typing.SupportsInt | typing.SupportsIndex) -> tuple:
    """
    The C++ mean behind chasles.sim3_mean, on checked (N, 4, 4) float64 elements and (N,) weights: (mean, iterations, converged).
    """
def _sim3_spline_fit(times: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], keys: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], natural: bool) -> numpy.ndarray:
    """
    The coefficients (n, 21) of the spline through checked (n,) float64 times and (n, 4, 4) keys (row i: c1, c2, c3 of segment i; the last row zero).
    """
def _so2_bspline_new(start_time: float, spacing: float, control: numpy.typing.ArrayLike) -> tuple[float, float, numpy.ndarray]:
    """
    The checked arguments of SO2BSpline(start_time, spacing, control): (start_time, spacing, the control elements as a new read-only (N, 2, 2) float64 array of keys), or the SO2BSpline constructor's ValueError / TypeError. A private function of chasles.SO2BSpline (python/chasles/_bspline.py).
    """
def _so2_mean(matrices: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], weights: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], geodesic: bool, max_iterations: typing.SupportsInt | typing.SupportsIndex) -> tuple:
    """
    The C++ mean behind chasles.so2_mean, on checked (N, 2, 2) float64 elements and (N,) weights: (mean, iterations, converged).
    """
def _so2_spline_fit(times: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], keys: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], natural: bool) -> numpy.ndarray:
    """
    The coefficients (n, 3) of the spline through checked (n,) float64 times and (n, 2, 2) keys (row i: c1, c2, c3 of segment i; the last row zero).
    """
def _so3_align(a: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], b: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], weights: typing.Any) -> tuple:
    """
    The C++ so3_align behind chasles.so3_align, on (N, 3) float64 vectors a, b and (N,) weights or None: (rotation, rssd, singular_values, sensitivity or None, status).
    """
def _so3_bspline_new(start_time: float, spacing: float, control: numpy.typing.ArrayLike) -> tuple[float, float, numpy.ndarray]:
    """
    The checked arguments of SO3BSpline(start_time, spacing, control): (start_time, spacing, the control elements as a new read-only (N, 3, 3) float64 array of rotations), or the SO3BSpline constructor's ValueError / TypeError. A private function of chasles.SO3BSpline (python/chasles/_bspline.py).
    """
def _so3_mean(matrices: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], weights: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], geodesic: bool, max_iterations: typing.SupportsInt | typing.SupportsIndex) -> tuple:
    """
    The C++ mean behind chasles.so3_mean, on checked (N, 3, 3) float64 elements and (N,) weights: (mean, iterations, converged).
    """
def _so3_spline_fit(times: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], keys: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], natural: bool) -> numpy.ndarray:
    """
    The coefficients (n, 9) of the spline through checked (n,) float64 times and (n, 3, 3) rotations (row i: c1, c2, c3 of segment i; the last row zero).
    """
def _threads_started() -> int:
    """
    For the tests: how many threads the array functions' loops have started since import.
    """
@typing.overload
def act_jacobians(g: SO2, p: numpy.typing.ArrayLike) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
    ...
@typing.overload
def act_jacobians(g: SE2, p: numpy.typing.ArrayLike) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
    ...
@typing.overload
def act_jacobians(g: SO3, p: numpy.typing.ArrayLike) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
    ...
@typing.overload
def act_jacobians(g: Sim3, p: numpy.typing.ArrayLike) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
    ...
@typing.overload
def act_jacobians(g: SE23, p: numpy.typing.ArrayLike) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
    ...
@typing.overload
def act_jacobians(g: SE3, p: numpy.typing.ArrayLike) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
    """
    The Jacobians (J_g, J_p) of (g, p) -> g p (the action on a point).
    
    Right-local in g: (g exp(dx)) (p + dp) = g p + J_g dx + J_p dp + o(dx, dp).
    SO3: J_g = -R [p], J_p = R; SE3: J_g = [R, -R [p]] (columns (v, w), linear
    part first), J_p = R (Sola et al. 2018, appendices B and D). SO2:
    J_g = R (-p_y, p_x); SE2: J_g = [R, R (-p_y, p_x)] (columns (vx, vy, w)).
    Sim3: J_g = [s R, -s R [p], s R p] (columns (v, w, sigma)), J_p = s R.
    SE23: J_g = [R, 0, -R [p]] (columns (rho, nu, w)), J_p = R.
    
    Args:
        g: SO2, SE2, SO3, SE3, Sim3 or SE23.
        p: point, shape (2,) for SO2 and SE2, (3,) for SO3 and SE3, finite.
    
    Returns:
        tuple[ndarray, ndarray]: (J_g, J_p); J_g of shape (2, 1) for SO2, (2, 3)
        for SE2, (3, 3) for SO3, (3, 6) for SE3, (3, 7) for Sim3, (3, 9) for
        SE23; J_p = R (s R for Sim3), shape (2, 2) or (3, 3); float64.
    
    Raises:
        ValueError: p is not of g's point shape, or not finite.
    
    Example:
        >>> g = chasles.SE3(translation=[1.0, 0.0, 0.0])
        >>> J_g, J_p = chasles.act_jacobians(g, [0.0, 0.0, 1.0])
        >>> J_g + 0.0
        array([[ 1.,  0.,  0.,  0.,  1.,  0.],
               [ 0.,  1.,  0., -1.,  0.,  0.],
               [ 0.,  0.,  1.,  0.,  0.,  0.]])
    """
@typing.overload
def between(a: SO2, b: SO2) -> SO2:
    ...
@typing.overload
def between(a: SE2, b: SE2) -> SE2:
    ...
@typing.overload
def between(a: SO3, b: SO3) -> SO3:
    ...
@typing.overload
def between(a: Sim3, b: Sim3) -> Sim3:
    ...
@typing.overload
def between(a: SE23, b: SE23) -> SE23:
    ...
@typing.overload
def between(a: SE3, b: SE3) -> SE3:
    """
    between(a, b) = a^-1 b: b seen from a (manif's a.between(b)).
    
    Args:
        a: SO2, SE2, SO3, SE3, Sim3 or SE23.
        b: of the same group as a.
    
    Returns:
        SO2, SE2, SO3, SE3, Sim3 or SE23: a^-1 b.
    
    Raises:
        TypeError: a and b are not of the same group.
    
    Example:
        >>> a = chasles.SE3(translation=[1.0, 0.0, 0.0])
        >>> b = chasles.SE3(translation=[1.0, 2.0, 0.0])
        >>> chasles.between(a, b).translation
        array([0., 2., 0.])
    """
@typing.overload
def between_jacobians(a: SO2, b: SO2) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
    ...
@typing.overload
def between_jacobians(a: SE2, b: SE2) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
    ...
@typing.overload
def between_jacobians(a: SO3, b: SO3) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
    ...
@typing.overload
def between_jacobians(a: Sim3, b: Sim3) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
    ...
@typing.overload
def between_jacobians(a: SE23, b: SE23) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
    ...
@typing.overload
def between_jacobians(a: SE3, b: SE3) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
    """
    The Jacobians (J_a, J_b) of (a, b) -> between(a, b) = a^-1 b.
    
    Right-local: between(a exp(da), b exp(db)) = between(a, b) exp(J_a da +
    J_b db + o), with J_a = -Ad_{b^-1 a} and J_b = I (Sola et al. 2018,
    section IV; manif's between Jacobians).
    
    Args:
        a: SO2, SE2, SO3, SE3, Sim3 or SE23.
        b: of the same group as a.
    
    Returns:
        tuple[ndarray, ndarray]: (J_a, J_b), each of shape (D, D): (1, 1) for SO2,
        (3, 3) for SE2 and SO3, (6, 6) for SE3 (twists (v, w)), (7, 7) for Sim3, (9, 9) for SE23, float64.
    
    Raises:
        TypeError: a and b are not of the same group.
    
    Example:
        >>> a = chasles.SO3.exp([0.0, 0.0, np.pi / 2])
        >>> J_a, J_b = chasles.between_jacobians(a, chasles.SO3())
        >>> bool(np.allclose(J_a, -a.as_matrix())), bool(np.array_equal(J_b, np.eye(3)))
        (True, True)
    """
@typing.overload
def compose_jacobians(a: SO2, b: SO2) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
    ...
@typing.overload
def compose_jacobians(a: SE2, b: SE2) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
    ...
@typing.overload
def compose_jacobians(a: SO3, b: SO3) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
    ...
@typing.overload
def compose_jacobians(a: Sim3, b: Sim3) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
    ...
@typing.overload
def compose_jacobians(a: SE23, b: SE23) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
    ...
@typing.overload
def compose_jacobians(a: SE3, b: SE3) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
    """
    The Jacobians (J_a, J_b) of (a, b) -> a b, in the right-local convention.
    
    Right-local: (a exp(da)) (b exp(db)) = a b exp(J_a da + J_b db + o(da, db)),
    with J_a = Ad_{b^-1} and J_b = I (Sola et al. 2018, section IV).
    
    Args:
        a: SO2, SE2, SO3, SE3, Sim3 or SE23.
        b: of the same group as a.
    
    Returns:
        tuple[ndarray, ndarray]: (J_a, J_b), each of shape (D, D): (1, 1) for SO2,
        (3, 3) for SE2 and SO3, (6, 6) for SE3 (twists (v, w)), (7, 7) for Sim3, (9, 9) for SE23, float64.
    
    Raises:
        TypeError: a and b are not of the same group.
    
    Example:
        >>> a, b = chasles.SO3(), chasles.SO3.exp([0.0, 0.0, np.pi / 2])
        >>> J_a, J_b = chasles.compose_jacobians(a, b)
        >>> bool(np.allclose(J_a, b.inverse().as_matrix())), bool(np.array_equal(J_b, np.eye(3)))
        (True, True)
    """
def get_num_threads() -> int:
    """
    The number of threads an array function may split a large batch across (set_num_threads).
    """
@typing.overload
def interpolate(a: SO2, b: SO2, t: float) -> SO2:
    ...
@typing.overload
def interpolate(a: SE2, b: SE2, t: float) -> SE2:
    ...
@typing.overload
def interpolate(a: SO3, b: SO3, t: float) -> SO3:
    """
    Geodesic interpolation of rotations a exp(t log(a^-1 b)) (as SO3.interpolate).
    
    Args:
        a: SO3, the start (t = 0).
        b: SO3, the end (t = 1).
        t: the fraction, finite.
    
    Returns:
        SO3: the interpolated rotation.
    """
@typing.overload
def interpolate(a: Sim3, b: Sim3, t: float) -> Sim3:
    ...
@typing.overload
def interpolate(a: SE23, b: SE23, t: float) -> SE23:
    ...
@typing.overload
def interpolate(a: SE3, b: SE3, t: float) -> SE3:
    """
    Screw interpolation of rigid motions a exp(t log(a^-1 b)) (as SE3.interpolate).
    
    Args:
        a: SE3, the start (t = 0).
        b: SE3, the end (t = 1).
        t: the fraction, finite.
    
    Returns:
        SE3: the interpolated motion.
    
    Example:
        >>> m = chasles.interpolate(SE3(), SE3(translation=[0.0, 0.0, 4.0]), 0.25)
        >>> m.translation
        array([0., 0., 1.])
    """
@typing.overload
def interpolate_jacobian_t(a: SO2, b: SO2, t: float) -> float:
    ...
@typing.overload
def interpolate_jacobian_t(a: SE2, b: SE2, t: float) -> numpy.typing.NDArray[numpy.float64]:
    ...
@typing.overload
def interpolate_jacobian_t(a: SO3, b: SO3, t: float) -> numpy.typing.NDArray[numpy.float64]:
    ...
@typing.overload
def interpolate_jacobian_t(a: Sim3, b: Sim3, t: float) -> numpy.typing.NDArray[numpy.float64]:
    ...
@typing.overload
def interpolate_jacobian_t(a: SE23, b: SE23, t: float) -> numpy.typing.NDArray[numpy.float64]:
    ...
@typing.overload
def interpolate_jacobian_t(a: SE3, b: SE3, t: float) -> numpy.typing.NDArray[numpy.float64]:
    """
    The derivative in t of interpolate(a, b, t) = a exp(t log(a^-1 b)).
    
    Right-local: interpolate(a, b, t + dt) = interpolate(a, b, t) exp(J dt + o(dt)),
    and J = J_r(t xi) xi = xi = rminus(b, a) = log(a^-1 b), the same for every t
    (the geodesic has constant body velocity).
    
    Args:
        a: SO2, SE2, SO3, SE3, Sim3 or SE23, the start.
        b: of the same group as a, the end.
        t: the fraction, finite.
    
    Returns:
        float or ndarray: SO2's angle, shape (3,) for SE2 and SO3, (6,) for
        SE3 ((v, w), linear part first), (7,) for Sim3, (9,) for SE23.
    
    Raises:
        ValueError: t is not finite.
        TypeError: a and b are not of the same group.
    
    Example:
        >>> a, b = chasles.SE3(), chasles.SE3(translation=[2.0, 0.0, 0.0])
        >>> chasles.interpolate_jacobian_t(a, b, 0.5)
        array([2., 0., 0., 0., 0., 0.])
    """
@typing.overload
def inverse_jacobian(g: SO2) -> numpy.typing.NDArray[numpy.float64]:
    ...
@typing.overload
def inverse_jacobian(g: SE2) -> numpy.typing.NDArray[numpy.float64]:
    ...
@typing.overload
def inverse_jacobian(g: SO3) -> numpy.typing.NDArray[numpy.float64]:
    ...
@typing.overload
def inverse_jacobian(g: Sim3) -> numpy.typing.NDArray[numpy.float64]:
    ...
@typing.overload
def inverse_jacobian(g: SE23) -> numpy.typing.NDArray[numpy.float64]:
    ...
@typing.overload
def inverse_jacobian(g: SE3) -> numpy.typing.NDArray[numpy.float64]:
    """
    The Jacobian of g -> g^-1, in the right-local convention: -Ad_g.
    
    Right-local: f(g exp(dx)) = f(g) exp(J dx + o(dx)); here
    (g exp(dx))^-1 = g^-1 exp(-Ad_g dx), so J = -Ad_g (Sola et al. 2018,
    section IV).
    
    Args:
        g: SO2, SE2, SO3, SE3, Sim3 or SE23.
    
    Returns:
        ndarray: shape (D, D): (1, 1) for SO2 (-1), (3, 3) for SE2 and SO3
        (-R), (6, 6) for SE3 (-Ad_g, twists (v, w)), (7, 7) for Sim3,
        (9, 9) for SE23,
        float64.
    
    Example:
        >>> g = chasles.SO3.exp([0.0, 0.0, np.pi / 2])
        >>> np.round(chasles.inverse_jacobian(g), 12) + 0.0
        array([[ 0.,  1.,  0.],
               [-1.,  0.,  0.],
               [ 0.,  0., -1.]])
    """
@typing.overload
def lminus(g: SO2, h: SO2) -> float:
    ...
@typing.overload
def lminus(g: SE2, h: SE2) -> numpy.typing.NDArray[numpy.float64]:
    ...
@typing.overload
def lminus(g: SO3, h: SO3) -> numpy.typing.NDArray[numpy.float64]:
    ...
@typing.overload
def lminus(g: Sim3, h: Sim3) -> numpy.typing.NDArray[numpy.float64]:
    ...
@typing.overload
def lminus(g: SE23, h: SE23) -> numpy.typing.NDArray[numpy.float64]:
    ...
@typing.overload
def lminus(g: SE3, h: SE3) -> numpy.typing.NDArray[numpy.float64]:
    """
    g lminus h = log(g h^-1): the xi with lplus(xi, h) == g.
    
    Args:
        g: SO2, SE2, SO3, SE3, Sim3 or SE23.
        h: of the same group as g.
    
    Returns:
        float or ndarray: SO2's angle, shape (3,) for SE2 ((vx, vy, w)) and
        SO3, (6,) for SE3 ((v, w)), (7,) for Sim3, (9,) for SE23.
    """
@typing.overload
def lminus_jacobians(g: SO2, h: SO2) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
    ...
@typing.overload
def lminus_jacobians(g: SE2, h: SE2) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
    ...
@typing.overload
def lminus_jacobians(g: SO3, h: SO3) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
    ...
@typing.overload
def lminus_jacobians(g: Sim3, h: Sim3) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
    ...
@typing.overload
def lminus_jacobians(g: SE23, h: SE23) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
    ...
@typing.overload
def lminus_jacobians(g: SE3, h: SE3) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
    """
    The Jacobians (J_g, J_h) of (g, h) -> lminus(g, h) = log(g h^-1).
    
    Right-local in the arguments: lminus(g exp(dg), h exp(dh)) = lminus(g, h) +
    J_g dg + J_h dh + o, with xi = lminus(g, h), J_g = J_r(xi)^-1 Ad_h and
    J_h = -J_g (Sola et al. 2018, section IV). Finite up to the angle pi, where
    log jumps between w and -w.
    
    Args:
        g: SO2, SE2, SO3, SE3, Sim3 or SE23.
        h: of the same group as g.
    
    Returns:
        tuple[ndarray, ndarray]: (J_g, J_h), each of shape (D, D): (1, 1) for SO2,
        (3, 3) for SE2 and SO3, (6, 6) for SE3 (twists (v, w)), (7, 7) for Sim3, (9, 9) for SE23, float64.
    
    Raises:
        TypeError: g and h are not of the same group.
    
    Example:
        >>> h = chasles.SO3.exp([0.0, 0.0, np.pi / 2])
        >>> J_g, J_h = chasles.lminus_jacobians(h, h)
        >>> bool(np.allclose(J_g, h.as_matrix())), bool(np.array_equal(J_h, -J_g))
        (True, True)
    """
@typing.overload
def log_jacobian(g: SO2) -> numpy.typing.NDArray[numpy.float64]:
    ...
@typing.overload
def log_jacobian(g: SE2) -> numpy.typing.NDArray[numpy.float64]:
    ...
@typing.overload
def log_jacobian(g: SO3) -> numpy.typing.NDArray[numpy.float64]:
    ...
@typing.overload
def log_jacobian(g: Sim3) -> numpy.typing.NDArray[numpy.float64]:
    ...
@typing.overload
def log_jacobian(g: SE23) -> numpy.typing.NDArray[numpy.float64]:
    ...
@typing.overload
def log_jacobian(g: SE3) -> numpy.typing.NDArray[numpy.float64]:
    """
    The Jacobian of g -> log(g), in the right-local convention.
    
    For a map f to the tangent space the right-local Jacobian J is defined by
    f(g exp(dx)) = f(g) + J dx + o(dx); here J = J_r(log g)^-1 (Sola et al.
    2018, section IV), finite up to the angle pi, where log itself jumps between
    w and -w (J is that of the branch log returns).
    
    Args:
        g: SO2, SE2, SO3, SE3, Sim3 or SE23.
    
    Returns:
        ndarray: shape (D, D), D the tangent size: (1, 1) for SO2, (3, 3) for
        SE2 and SO3, (6, 6) for SE3 (rows and columns (v, w)), (7, 7) for Sim3,
        (9, 9) for SE23,
        float64.
    
    Example:
        >>> g = chasles.SO3.exp([0.0, 0.0, 0.5])
        >>> dx = np.array([1e-7, 0.0, 0.0])
        >>> bool(np.allclose(chasles.rplus(g, dx).log() - g.log(),
        ...                  chasles.log_jacobian(g) @ dx, atol=1e-13))
        True
    """
@typing.overload
def lplus(xi: numpy.typing.ArrayLike, g: SO2) -> SO2:
    ...
@typing.overload
def lplus(xi: numpy.typing.ArrayLike, g: SE2) -> SE2:
    ...
@typing.overload
def lplus(xi: numpy.typing.ArrayLike, g: SO3) -> SO3:
    ...
@typing.overload
def lplus(xi: numpy.typing.ArrayLike, g: Sim3) -> Sim3:
    ...
@typing.overload
def lplus(xi: numpy.typing.ArrayLike, g: SE23) -> SE23:
    ...
@typing.overload
def lplus(xi: numpy.typing.ArrayLike, g: SE3) -> SE3:
    """
    xi lplus g = exp(xi) g: a perturbation in the fixed (global, left) frame.
    
    Args:
        xi: tangent vector of g's group, finite (as for rplus).
        g: SO2, SE2, SO3, SE3, Sim3 or SE23.
    
    Returns:
        SO2, SE2, SO3, SE3, Sim3 or SE23: exp(xi) g.
    
    Raises:
        ValueError: xi has the wrong shape for g, or is not finite.
    """
@typing.overload
def lplus_jacobians(xi: numpy.typing.ArrayLike, g: SO2) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
    ...
@typing.overload
def lplus_jacobians(xi: numpy.typing.ArrayLike, g: SE2) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
    ...
@typing.overload
def lplus_jacobians(xi: numpy.typing.ArrayLike, g: SO3) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
    ...
@typing.overload
def lplus_jacobians(xi: numpy.typing.ArrayLike, g: Sim3) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
    ...
@typing.overload
def lplus_jacobians(xi: numpy.typing.ArrayLike, g: SE23) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
    ...
@typing.overload
def lplus_jacobians(xi: numpy.typing.ArrayLike, g: SE3) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
    """
    The Jacobians (J_xi, J_g) of (xi, g) -> lplus(xi, g) = exp(xi) g.
    
    Right-local in the result and in g: lplus(xi + dxi, g exp(dg)) =
    lplus(xi, g) exp(J_xi dxi + J_g dg + o), with J_xi = Ad_{g^-1} J_r(xi) and
    J_g = I (Sola et al. 2018, sections III and IV).
    
    Args:
        xi: tangent vector of g's group, finite (as for rplus).
        g: SO2, SE2, SO3, SE3, Sim3 or SE23.
    
    Returns:
        tuple[ndarray, ndarray]: (J_xi, J_g), each of shape (D, D): (1, 1) for SO2,
        (3, 3) for SE2 and SO3, (6, 6) for SE3, (7, 7) for Sim3,
        (9, 9) for SE23,
        float64.
    
    Raises:
        ValueError: xi has the wrong shape for g, or is not finite.
    
    Example:
        >>> g = chasles.SO3.exp([0.0, 0.0, np.pi / 2])
        >>> J_xi, J_g = chasles.lplus_jacobians([0.0, 0.0, 0.0], g)
        >>> bool(np.allclose(J_xi, g.inverse().as_matrix())), bool(np.array_equal(J_g, np.eye(3)))
        (True, True)
    """
@typing.overload
def rminus(g: SO2, h: SO2) -> float:
    ...
@typing.overload
def rminus(g: SE2, h: SE2) -> numpy.typing.NDArray[numpy.float64]:
    ...
@typing.overload
def rminus(g: SO3, h: SO3) -> numpy.typing.NDArray[numpy.float64]:
    ...
@typing.overload
def rminus(g: Sim3, h: Sim3) -> numpy.typing.NDArray[numpy.float64]:
    ...
@typing.overload
def rminus(g: SE23, h: SE23) -> numpy.typing.NDArray[numpy.float64]:
    ...
@typing.overload
def rminus(g: SE3, h: SE3) -> numpy.typing.NDArray[numpy.float64]:
    """
    g rminus h = log(h^-1 g): the xi with rplus(h, xi) == g ("g minus h").
    
    The order is manif's g.rminus(h); jaxlie's rminus(a, b) = log(a^-1 b) takes
    the arguments the other way round.
    
    Args:
        g: SO2, SE2, SO3, SE3, Sim3 or SE23.
        h: of the same group as g.
    
    Returns:
        float or ndarray: SO2's angle, shape (3,) for SE2 ((vx, vy, w)) and
        SO3, (6,) for SE3 ((v, w)), (7,) for Sim3, (9,) for SE23.
    
    Example:
        >>> h = chasles.SO3.exp([0.0, 0.0, 0.5])
        >>> g = h @ chasles.SO3.exp([0.3, 0.0, 0.0])
        >>> np.round(chasles.rminus(g, h), 12) + 0.0
        array([0.3, 0. , 0. ])
    """
@typing.overload
def rminus_jacobians(g: SO2, h: SO2) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
    ...
@typing.overload
def rminus_jacobians(g: SE2, h: SE2) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
    ...
@typing.overload
def rminus_jacobians(g: SO3, h: SO3) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
    ...
@typing.overload
def rminus_jacobians(g: Sim3, h: Sim3) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
    ...
@typing.overload
def rminus_jacobians(g: SE23, h: SE23) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
    ...
@typing.overload
def rminus_jacobians(g: SE3, h: SE3) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
    """
    The Jacobians (J_g, J_h) of (g, h) -> rminus(g, h) = log(h^-1 g).
    
    Right-local: rminus(g exp(dg), h exp(dh)) = rminus(g, h) + J_g dg + J_h dh
    + o, with xi = rminus(g, h), J_g = J_r(xi)^-1 and J_h = -J_l(xi)^-1 (Sola et
    al. 2018, section IV; manif's rminus Jacobians). They are those of the branch
    log returns: finite up to the angle pi, where log jumps between w and -w.
    
    Args:
        g: SO2, SE2, SO3, SE3, Sim3 or SE23.
        h: of the same group as g.
    
    Returns:
        tuple[ndarray, ndarray]: (J_g, J_h), each of shape (D, D): (1, 1) for SO2,
        (3, 3) for SE2 and SO3, (6, 6) for SE3 (twists (v, w)), (7, 7) for Sim3, (9, 9) for SE23, float64.
    
    Raises:
        TypeError: g and h are not of the same group.
    
    Example:
        >>> J_g, J_h = chasles.rminus_jacobians(chasles.SE3(), chasles.SE3())
        >>> bool(np.array_equal(J_g, np.eye(6))), bool(np.array_equal(J_h, -np.eye(6)))
        (True, True)
    """
@typing.overload
def rplus(g: SO2, xi: numpy.typing.ArrayLike) -> SO2:
    ...
@typing.overload
def rplus(g: SE2, xi: numpy.typing.ArrayLike) -> SE2:
    ...
@typing.overload
def rplus(g: SO3, xi: numpy.typing.ArrayLike) -> SO3:
    ...
@typing.overload
def rplus(g: Sim3, xi: numpy.typing.ArrayLike) -> Sim3:
    ...
@typing.overload
def rplus(g: SE23, xi: numpy.typing.ArrayLike) -> SE23:
    ...
@typing.overload
def rplus(g: SE3, xi: numpy.typing.ArrayLike) -> SE3:
    """
    g rplus xi = g exp(xi): a perturbation in g's own (local, right) frame.
    
    Args:
        g: SO2, SE2, SO3, SE3, Sim3 or SE23.
        xi: tangent vector of g's group, finite: SO2's angle theta (a float),
            shape (3,) for SE2 ((vx, vy, w)) and SO3 (rotation vector w), (6,)
            for SE3 (twist (v, w)), (7,) for Sim3 ((v, w, sigma)),
            (9,) for SE23 ((rho, nu, w)).
    
    Returns:
        SO2, SE2, SO3, SE3, Sim3 or SE23: g exp(xi).
    
    Raises:
        ValueError: xi has the wrong shape for g, or is not finite.
    
    Example:
        >>> g = chasles.SE3(translation=[1.0, 0.0, 0.0])
        >>> chasles.rplus(g, [0.0, 2.0, 0.0, 0.0, 0.0, 0.0]).translation
        array([1., 2., 0.])
    """
@typing.overload
def rplus_jacobians(g: SO2, xi: numpy.typing.ArrayLike) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
    ...
@typing.overload
def rplus_jacobians(g: SE2, xi: numpy.typing.ArrayLike) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
    ...
@typing.overload
def rplus_jacobians(g: SO3, xi: numpy.typing.ArrayLike) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
    ...
@typing.overload
def rplus_jacobians(g: Sim3, xi: numpy.typing.ArrayLike) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
    ...
@typing.overload
def rplus_jacobians(g: SE23, xi: numpy.typing.ArrayLike) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
    ...
@typing.overload
def rplus_jacobians(g: SE3, xi: numpy.typing.ArrayLike) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
    """
    The Jacobians (J_g, J_xi) of (g, xi) -> rplus(g, xi) = g exp(xi).
    
    Right-local: rplus(g exp(dg), xi + dxi) = rplus(g, xi) exp(J_g dg + J_xi dxi
    + o), with J_g = Ad_{exp(xi)}^-1 = Ad_{exp(-xi)} and J_xi = J_r(xi) (Sola et
    al. 2018, section IV; manif's rplus Jacobians).
    
    Args:
        g: SO2, SE2, SO3, SE3, Sim3 or SE23.
        xi: tangent vector of g's group, finite (as for rplus).
    
    Returns:
        tuple[ndarray, ndarray]: (J_g, J_xi), each of shape (D, D): (1, 1) for SO2,
        (3, 3) for SE2 and SO3, (6, 6) for SE3, (7, 7) for Sim3,
        (9, 9) for SE23,
        float64.
    
    Raises:
        ValueError: xi has the wrong shape for g, or is not finite.
    
    Example:
        >>> J_g, J_xi = chasles.rplus_jacobians(chasles.SO3(), [0.0, 0.0, 0.0])
        >>> bool(np.array_equal(J_g, np.eye(3))), bool(np.array_equal(J_xi, np.eye(3)))
        (True, True)
    """
__version__: str = '0.1.0'
_chain_forward: numpy.ufunc
_chain_forward_body: numpy.ufunc
_chain_jacobian_body: numpy.ufunc
_chain_jacobian_body_dot: numpy.ufunc
_chain_jacobian_space: numpy.ufunc
_chain_jacobian_space_dot: numpy.ufunc
_coriolis: numpy.ufunc
_forward_dynamics: numpy.ufunc
_forward_dynamics_derivatives: numpy.ufunc
_gravity_torques: numpy.ufunc
_inverse_dynamics: numpy.ufunc
_inverse_dynamics_derivatives: numpy.ufunc
_inverse_kinematics: numpy.ufunc
_joint_trajectory: numpy.ufunc
_mass_matrix: numpy.ufunc
_mass_matrix_inverse: numpy.ufunc
_max_threads: int = 1024
_se23_act_cov: numpy.ufunc
_se23_between_cov_cross: numpy.ufunc
_se23_bspline: numpy.ufunc
_se23_bspline_jacobians: numpy.ufunc
_se23_bspline_rates: numpy.ufunc
_se23_compose_cov_cross: numpy.ufunc
_se23_from_uniforms: numpy.ufunc
_se23_interpolate_cov: numpy.ufunc
_se23_left_cov: numpy.ufunc
_se23_log_cov: numpy.ufunc
_se23_mahalanobis: numpy.ufunc
_se23_spline: numpy.ufunc
_se23_spline_rates: numpy.ufunc
_se2_act_cov: numpy.ufunc
_se2_between_cov_cross: numpy.ufunc
_se2_bspline: numpy.ufunc
_se2_bspline_jacobians: numpy.ufunc
_se2_bspline_rates: numpy.ufunc
_se2_compose_cov_cross: numpy.ufunc
_se2_from_uniforms: numpy.ufunc
_se2_interpolate_cov: numpy.ufunc
_se2_left_cov: numpy.ufunc
_se2_log_cov: numpy.ufunc
_se2_mahalanobis: numpy.ufunc
_se2_spline: numpy.ufunc
_se2_spline_rates: numpy.ufunc
_se3_act_cov: numpy.ufunc
_se3_between_cov_cross: numpy.ufunc
_se3_bspline: numpy.ufunc
_se3_bspline_jacobians: numpy.ufunc
_se3_bspline_rates: numpy.ufunc
_se3_compose_cov4: numpy.ufunc
_se3_compose_cov_cross: numpy.ufunc
_se3_cov_from_ros: numpy.ufunc
_se3_cov_to_ros: numpy.ufunc
_se3_from_quat_wxyz: numpy.ufunc
_se3_from_quat_xyzw: numpy.ufunc
_se3_interpolate_cov: numpy.ufunc
_se3_left_cov: numpy.ufunc
_se3_log_cov: numpy.ufunc
_se3_mahalanobis: numpy.ufunc
_se3_spline: numpy.ufunc
_se3_spline_rates: numpy.ufunc
_sim3_act_cov: numpy.ufunc
_sim3_between_cov_cross: numpy.ufunc
_sim3_bspline: numpy.ufunc
_sim3_bspline_jacobians: numpy.ufunc
_sim3_bspline_rates: numpy.ufunc
_sim3_compose_cov_cross: numpy.ufunc
_sim3_from_uniforms: numpy.ufunc
_sim3_interpolate_cov: numpy.ufunc
_sim3_left_cov: numpy.ufunc
_sim3_log_cov: numpy.ufunc
_sim3_mahalanobis: numpy.ufunc
_sim3_spline: numpy.ufunc
_sim3_spline_rates: numpy.ufunc
_so2_act_cov: numpy.ufunc
_so2_between_cov_cross: numpy.ufunc
_so2_bspline: numpy.ufunc
_so2_bspline_jacobians: numpy.ufunc
_so2_bspline_rates: numpy.ufunc
_so2_compose_cov_cross: numpy.ufunc
_so2_from_uniforms: numpy.ufunc
_so2_interpolate_cov: numpy.ufunc
_so2_left_cov: numpy.ufunc
_so2_log_cov: numpy.ufunc
_so2_mahalanobis: numpy.ufunc
_so2_spline: numpy.ufunc
_so2_spline_rates: numpy.ufunc
_so3_act_cov: numpy.ufunc
_so3_as_euler: numpy.ufunc
_so3_as_euler_lock: numpy.ufunc
_so3_as_quat_wxyz: numpy.ufunc
_so3_as_quat_xyzw: numpy.ufunc
_so3_as_rpy: numpy.ufunc
_so3_as_rpy_lock: numpy.ufunc
_so3_between_cov_cross: numpy.ufunc
_so3_bspline: numpy.ufunc
_so3_bspline_jacobians: numpy.ufunc
_so3_bspline_rates: numpy.ufunc
_so3_compose_cov_cross: numpy.ufunc
_so3_from_euler: numpy.ufunc
_so3_from_quat_wxyz: numpy.ufunc
_so3_from_quat_xyzw: numpy.ufunc
_so3_from_rpy: numpy.ufunc
_so3_interpolate_cov: numpy.ufunc
_so3_left_cov: numpy.ufunc
_so3_log_cov: numpy.ufunc
_so3_mahalanobis: numpy.ufunc
_so3_spline: numpy.ufunc
_so3_spline_rates: numpy.ufunc
_time_scaling: numpy.ufunc
# se23_act(X, points): (5,5),(3)->(3)
se23_act: _GUFunc_Nin2_Nout1[typing.Literal["se23_act"], typing.Literal["(5,5),(3)->(3)"]]
# se23_between_cov(a, cov_a, b, cov_b): (5,5),(9,9),(5,5),(9,9)->(5,5),(9,9)
se23_between_cov: _GUFunc_Nin4_Nout2[typing.Literal["se23_between_cov"], typing.Literal["(5,5),(9,9),(5,5),(9,9)->(5,5),(9,9)"]]
# se23_between_jacobians(a, b): (5,5),(5,5)->(9,9),(9,9)
se23_between_jacobians: _GUFunc_Nin2_Nout2[typing.Literal["se23_between_jacobians"], typing.Literal["(5,5),(5,5)->(9,9),(9,9)"]]
# se23_compose(a, b): (5,5),(5,5)->(5,5)
se23_compose: _GUFunc_Nin2_Nout1[typing.Literal["se23_compose"], typing.Literal["(5,5),(5,5)->(5,5)"]]
# se23_compose_cov(a, cov_a, b, cov_b): (5,5),(9,9),(5,5),(9,9)->(5,5),(9,9)
se23_compose_cov: _GUFunc_Nin4_Nout2[typing.Literal["se23_compose_cov"], typing.Literal["(5,5),(9,9),(5,5),(9,9)->(5,5),(9,9)"]]
# se23_compose_jacobians(a, b): (5,5),(5,5)->(9,9),(9,9)
se23_compose_jacobians: _GUFunc_Nin2_Nout2[typing.Literal["se23_compose_jacobians"], typing.Literal["(5,5),(5,5)->(9,9),(9,9)"]]
# se23_distance(a, b): (5,5),(5,5)->(3)
se23_distance: _GUFunc_Nin2_Nout1[typing.Literal["se23_distance"], typing.Literal["(5,5),(5,5)->(3)"]]
# se23_exp(xi): (9)->(5,5)
se23_exp: _GUFunc_Nin1_Nout1[typing.Literal["se23_exp"], typing.Literal["(9)->(5,5)"]]
# se23_hat(xi): (9)->(5,5)
se23_hat: _GUFunc_Nin1_Nout1[typing.Literal["se23_hat"], typing.Literal["(9)->(5,5)"]]
# se23_interpolate(a, b, t): (5,5),(5,5),()->(5,5)
se23_interpolate: _GUFunc_Nin3_Nout1[typing.Literal["se23_interpolate"], typing.Literal["(5,5),(5,5),()->(5,5)"]]
# se23_inverse(X): (5,5)->(5,5)
se23_inverse: _GUFunc_Nin1_Nout1[typing.Literal["se23_inverse"], typing.Literal["(5,5)->(5,5)"]]
# se23_inverse_cov(a, cov_a): (5,5),(9,9)->(5,5),(9,9)
se23_inverse_cov: _GUFunc_Nin2_Nout2[typing.Literal["se23_inverse_cov"], typing.Literal["(5,5),(9,9)->(5,5),(9,9)"]]
# se23_log(X): (5,5)->(9)
se23_log: _GUFunc_Nin1_Nout1[typing.Literal["se23_log"], typing.Literal["(5,5)->(9)"]]
# se23_normalize(X): (5,5)->(5,5)
se23_normalize: _GUFunc_Nin1_Nout1[typing.Literal["se23_normalize"], typing.Literal["(5,5)->(5,5)"]]
# se23_rminus_jacobians(g, h): (5,5),(5,5)->(9,9),(9,9)
se23_rminus_jacobians: _GUFunc_Nin2_Nout2[typing.Literal["se23_rminus_jacobians"], typing.Literal["(5,5),(5,5)->(9,9),(9,9)"]]
# se23_vee(matrix): (5,5)->(9)
se23_vee: _GUFunc_Nin1_Nout1[typing.Literal["se23_vee"], typing.Literal["(5,5)->(9)"]]
# se2_act(g, points): (3,3),(2)->(2)
se2_act: _GUFunc_Nin2_Nout1[typing.Literal["se2_act"], typing.Literal["(3,3),(2)->(2)"]]
# se2_between_cov(a, cov_a, b, cov_b): (3,3),(3,3),(3,3),(3,3)->(3,3),(3,3)
se2_between_cov: _GUFunc_Nin4_Nout2[typing.Literal["se2_between_cov"], typing.Literal["(3,3),(3,3),(3,3),(3,3)->(3,3),(3,3)"]]
# se2_between_jacobians(a, b): (3,3),(3,3)->(3,3),(3,3)
se2_between_jacobians: _GUFunc_Nin2_Nout2[typing.Literal["se2_between_jacobians"], typing.Literal["(3,3),(3,3)->(3,3),(3,3)"]]
# se2_compose(a, b): (3,3),(3,3)->(3,3)
se2_compose: _GUFunc_Nin2_Nout1[typing.Literal["se2_compose"], typing.Literal["(3,3),(3,3)->(3,3)"]]
# se2_compose_cov(a, cov_a, b, cov_b): (3,3),(3,3),(3,3),(3,3)->(3,3),(3,3)
se2_compose_cov: _GUFunc_Nin4_Nout2[typing.Literal["se2_compose_cov"], typing.Literal["(3,3),(3,3),(3,3),(3,3)->(3,3),(3,3)"]]
# se2_compose_jacobians(a, b): (3,3),(3,3)->(3,3),(3,3)
se2_compose_jacobians: _GUFunc_Nin2_Nout2[typing.Literal["se2_compose_jacobians"], typing.Literal["(3,3),(3,3)->(3,3),(3,3)"]]
# se2_distance(a, b): (3,3),(3,3)->(2)
se2_distance: _GUFunc_Nin2_Nout1[typing.Literal["se2_distance"], typing.Literal["(3,3),(3,3)->(2)"]]
# se2_exp(xi): (3)->(3,3)
se2_exp: _GUFunc_Nin1_Nout1[typing.Literal["se2_exp"], typing.Literal["(3)->(3,3)"]]
# se2_hat(xi): (3)->(3,3)
se2_hat: _GUFunc_Nin1_Nout1[typing.Literal["se2_hat"], typing.Literal["(3)->(3,3)"]]
# se2_interpolate(a, b, t): (3,3),(3,3),()->(3,3)
se2_interpolate: _GUFunc_Nin3_Nout1[typing.Literal["se2_interpolate"], typing.Literal["(3,3),(3,3),()->(3,3)"]]
# se2_inverse(g): (3,3)->(3,3)
se2_inverse: _GUFunc_Nin1_Nout1[typing.Literal["se2_inverse"], typing.Literal["(3,3)->(3,3)"]]
# se2_inverse_cov(a, cov_a): (3,3),(3,3)->(3,3),(3,3)
se2_inverse_cov: _GUFunc_Nin2_Nout2[typing.Literal["se2_inverse_cov"], typing.Literal["(3,3),(3,3)->(3,3),(3,3)"]]
# se2_log(g): (3,3)->(3)
se2_log: _GUFunc_Nin1_Nout1[typing.Literal["se2_log"], typing.Literal["(3,3)->(3)"]]
# se2_normalize(g): (3,3)->(3,3)
se2_normalize: _GUFunc_Nin1_Nout1[typing.Literal["se2_normalize"], typing.Literal["(3,3)->(3,3)"]]
# se2_rminus_jacobians(g, h): (3,3),(3,3)->(3,3),(3,3)
se2_rminus_jacobians: _GUFunc_Nin2_Nout2[typing.Literal["se2_rminus_jacobians"], typing.Literal["(3,3),(3,3)->(3,3),(3,3)"]]
# se2_vee(matrix): (3,3)->(3)
se2_vee: _GUFunc_Nin1_Nout1[typing.Literal["se2_vee"], typing.Literal["(3,3)->(3)"]]
# se3_act(g, points): (4,4),(3)->(3)
se3_act: _GUFunc_Nin2_Nout1[typing.Literal["se3_act"], typing.Literal["(4,4),(3)->(3)"]]
# se3_act_jacobian(g, points): (4,4),(3)->(3,6)
se3_act_jacobian: _GUFunc_Nin2_Nout1[typing.Literal["se3_act_jacobian"], typing.Literal["(4,4),(3)->(3,6)"]]
# se3_act_twist(g, xi): (4,4),(6)->(6)
se3_act_twist: _GUFunc_Nin2_Nout1[typing.Literal["se3_act_twist"], typing.Literal["(4,4),(6)->(6)"]]
# se3_act_wrench(g, F): (4,4),(6)->(6)
se3_act_wrench: _GUFunc_Nin2_Nout1[typing.Literal["se3_act_wrench"], typing.Literal["(4,4),(6)->(6)"]]
# se3_adjoint(g): (4,4)->(6,6)
se3_adjoint: _GUFunc_Nin1_Nout1[typing.Literal["se3_adjoint"], typing.Literal["(4,4)->(6,6)"]]
# se3_between_cov(a, cov_a, b, cov_b): (4,4),(6,6),(4,4),(6,6)->(4,4),(6,6)
se3_between_cov: _GUFunc_Nin4_Nout2[typing.Literal["se3_between_cov"], typing.Literal["(4,4),(6,6),(4,4),(6,6)->(4,4),(6,6)"]]
# se3_between_jacobians(a, b): (4,4),(4,4)->(6,6),(6,6)
se3_between_jacobians: _GUFunc_Nin2_Nout2[typing.Literal["se3_between_jacobians"], typing.Literal["(4,4),(4,4)->(6,6),(6,6)"]]
# se3_compose(a, b): (4,4),(4,4)->(4,4)
se3_compose: _GUFunc_Nin2_Nout1[typing.Literal["se3_compose"], typing.Literal["(4,4),(4,4)->(4,4)"]]
# se3_compose_cov(a, cov_a, b, cov_b): (4,4),(6,6),(4,4),(6,6)->(4,4),(6,6)
se3_compose_cov: _GUFunc_Nin4_Nout2[typing.Literal["se3_compose_cov"], typing.Literal["(4,4),(6,6),(4,4),(6,6)->(4,4),(6,6)"]]
# se3_compose_jacobians(a, b): (4,4),(4,4)->(6,6),(6,6)
se3_compose_jacobians: _GUFunc_Nin2_Nout2[typing.Literal["se3_compose_jacobians"], typing.Literal["(4,4),(4,4)->(6,6),(6,6)"]]
# se3_distance(a, b): (4,4),(4,4)->(2)
se3_distance: _GUFunc_Nin2_Nout1[typing.Literal["se3_distance"], typing.Literal["(4,4),(4,4)->(2)"]]
# se3_exp(xi): (6)->(4,4)
se3_exp: _GUFunc_Nin1_Nout1[typing.Literal["se3_exp"], typing.Literal["(6)->(4,4)"]]
# se3_hat(xi): (6)->(4,4)
se3_hat: _GUFunc_Nin1_Nout1[typing.Literal["se3_hat"], typing.Literal["(6)->(4,4)"]]
# se3_interpolate(a, b, t): (4,4),(4,4),()->(4,4)
se3_interpolate: _GUFunc_Nin3_Nout1[typing.Literal["se3_interpolate"], typing.Literal["(4,4),(4,4),()->(4,4)"]]
# se3_inverse(g): (4,4)->(4,4)
se3_inverse: _GUFunc_Nin1_Nout1[typing.Literal["se3_inverse"], typing.Literal["(4,4)->(4,4)"]]
# se3_inverse_cov(a, cov_a): (4,4),(6,6)->(4,4),(6,6)
se3_inverse_cov: _GUFunc_Nin2_Nout2[typing.Literal["se3_inverse_cov"], typing.Literal["(4,4),(6,6)->(4,4),(6,6)"]]
# se3_log(g): (4,4)->(6)
se3_log: _GUFunc_Nin1_Nout1[typing.Literal["se3_log"], typing.Literal["(4,4)->(6)"]]
# se3_normalize(g): (4,4)->(4,4)
se3_normalize: _GUFunc_Nin1_Nout1[typing.Literal["se3_normalize"], typing.Literal["(4,4)->(4,4)"]]
# se3_rminus_jacobians(g, h): (4,4),(4,4)->(6,6),(6,6)
se3_rminus_jacobians: _GUFunc_Nin2_Nout2[typing.Literal["se3_rminus_jacobians"], typing.Literal["(4,4),(4,4)->(6,6),(6,6)"]]
# se3_vee(matrix): (4,4)->(6)
se3_vee: _GUFunc_Nin1_Nout1[typing.Literal["se3_vee"], typing.Literal["(4,4)->(6)"]]
# sim3_act(g, points): (4,4),(3)->(3)
sim3_act: _GUFunc_Nin2_Nout1[typing.Literal["sim3_act"], typing.Literal["(4,4),(3)->(3)"]]
# sim3_between_cov(a, cov_a, b, cov_b): (4,4),(7,7),(4,4),(7,7)->(4,4),(7,7)
sim3_between_cov: _GUFunc_Nin4_Nout2[typing.Literal["sim3_between_cov"], typing.Literal["(4,4),(7,7),(4,4),(7,7)->(4,4),(7,7)"]]
# sim3_between_jacobians(a, b): (4,4),(4,4)->(7,7),(7,7)
sim3_between_jacobians: _GUFunc_Nin2_Nout2[typing.Literal["sim3_between_jacobians"], typing.Literal["(4,4),(4,4)->(7,7),(7,7)"]]
# sim3_compose(a, b): (4,4),(4,4)->(4,4)
sim3_compose: _GUFunc_Nin2_Nout1[typing.Literal["sim3_compose"], typing.Literal["(4,4),(4,4)->(4,4)"]]
# sim3_compose_cov(a, cov_a, b, cov_b): (4,4),(7,7),(4,4),(7,7)->(4,4),(7,7)
sim3_compose_cov: _GUFunc_Nin4_Nout2[typing.Literal["sim3_compose_cov"], typing.Literal["(4,4),(7,7),(4,4),(7,7)->(4,4),(7,7)"]]
# sim3_compose_jacobians(a, b): (4,4),(4,4)->(7,7),(7,7)
sim3_compose_jacobians: _GUFunc_Nin2_Nout2[typing.Literal["sim3_compose_jacobians"], typing.Literal["(4,4),(4,4)->(7,7),(7,7)"]]
# sim3_distance(a, b): (4,4),(4,4)->(3)
sim3_distance: _GUFunc_Nin2_Nout1[typing.Literal["sim3_distance"], typing.Literal["(4,4),(4,4)->(3)"]]
# sim3_exp(xi): (7)->(4,4)
sim3_exp: _GUFunc_Nin1_Nout1[typing.Literal["sim3_exp"], typing.Literal["(7)->(4,4)"]]
# sim3_hat(xi): (7)->(4,4)
sim3_hat: _GUFunc_Nin1_Nout1[typing.Literal["sim3_hat"], typing.Literal["(7)->(4,4)"]]
# sim3_interpolate(a, b, t): (4,4),(4,4),()->(4,4)
sim3_interpolate: _GUFunc_Nin3_Nout1[typing.Literal["sim3_interpolate"], typing.Literal["(4,4),(4,4),()->(4,4)"]]
# sim3_inverse(g): (4,4)->(4,4)
sim3_inverse: _GUFunc_Nin1_Nout1[typing.Literal["sim3_inverse"], typing.Literal["(4,4)->(4,4)"]]
# sim3_inverse_cov(a, cov_a): (4,4),(7,7)->(4,4),(7,7)
sim3_inverse_cov: _GUFunc_Nin2_Nout2[typing.Literal["sim3_inverse_cov"], typing.Literal["(4,4),(7,7)->(4,4),(7,7)"]]
# sim3_log(g): (4,4)->(7)
sim3_log: _GUFunc_Nin1_Nout1[typing.Literal["sim3_log"], typing.Literal["(4,4)->(7)"]]
# sim3_normalize(g): (4,4)->(4,4)
sim3_normalize: _GUFunc_Nin1_Nout1[typing.Literal["sim3_normalize"], typing.Literal["(4,4)->(4,4)"]]
# sim3_rminus_jacobians(g, h): (4,4),(4,4)->(7,7),(7,7)
sim3_rminus_jacobians: _GUFunc_Nin2_Nout2[typing.Literal["sim3_rminus_jacobians"], typing.Literal["(4,4),(4,4)->(7,7),(7,7)"]]
# sim3_vee(matrix): (4,4)->(7)
sim3_vee: _GUFunc_Nin1_Nout1[typing.Literal["sim3_vee"], typing.Literal["(4,4)->(7)"]]
# so2_act(R, points): (2,2),(2)->(2)
so2_act: _GUFunc_Nin2_Nout1[typing.Literal["so2_act"], typing.Literal["(2,2),(2)->(2)"]]
# so2_between_cov(a, cov_a, b, cov_b): (2,2),(1,1),(2,2),(1,1)->(2,2),(1,1)
so2_between_cov: _GUFunc_Nin4_Nout2[typing.Literal["so2_between_cov"], typing.Literal["(2,2),(1,1),(2,2),(1,1)->(2,2),(1,1)"]]
# so2_between_jacobians(a, b): (2,2),(2,2)->(1,1),(1,1)
so2_between_jacobians: _GUFunc_Nin2_Nout2[typing.Literal["so2_between_jacobians"], typing.Literal["(2,2),(2,2)->(1,1),(1,1)"]]
# so2_compose(a, b): (2,2),(2,2)->(2,2)
so2_compose: _GUFunc_Nin2_Nout1[typing.Literal["so2_compose"], typing.Literal["(2,2),(2,2)->(2,2)"]]
# so2_compose_cov(a, cov_a, b, cov_b): (2,2),(1,1),(2,2),(1,1)->(2,2),(1,1)
so2_compose_cov: _GUFunc_Nin4_Nout2[typing.Literal["so2_compose_cov"], typing.Literal["(2,2),(1,1),(2,2),(1,1)->(2,2),(1,1)"]]
# so2_compose_jacobians(a, b): (2,2),(2,2)->(1,1),(1,1)
so2_compose_jacobians: _GUFunc_Nin2_Nout2[typing.Literal["so2_compose_jacobians"], typing.Literal["(2,2),(2,2)->(1,1),(1,1)"]]
# so2_distance(a, b): (2,2),(2,2)->()
so2_distance: _GUFunc_Nin2_Nout1[typing.Literal["so2_distance"], typing.Literal["(2,2),(2,2)->()"]]
# so2_exp(theta): ()->(2,2)
so2_exp: _GUFunc_Nin1_Nout1[typing.Literal["so2_exp"], typing.Literal["()->(2,2)"]]
# so2_hat(theta): ()->(2,2)
so2_hat: _GUFunc_Nin1_Nout1[typing.Literal["so2_hat"], typing.Literal["()->(2,2)"]]
# so2_interpolate(a, b, t): (2,2),(2,2),()->(2,2)
so2_interpolate: _GUFunc_Nin3_Nout1[typing.Literal["so2_interpolate"], typing.Literal["(2,2),(2,2),()->(2,2)"]]
# so2_inverse(R): (2,2)->(2,2)
so2_inverse: _GUFunc_Nin1_Nout1[typing.Literal["so2_inverse"], typing.Literal["(2,2)->(2,2)"]]
# so2_inverse_cov(a, cov_a): (2,2),(1,1)->(2,2),(1,1)
so2_inverse_cov: _GUFunc_Nin2_Nout2[typing.Literal["so2_inverse_cov"], typing.Literal["(2,2),(1,1)->(2,2),(1,1)"]]
# so2_log(R): (2,2)->()
so2_log: _GUFunc_Nin1_Nout1[typing.Literal["so2_log"], typing.Literal["(2,2)->()"]]
# so2_normalize(R): (2,2)->(2,2)
so2_normalize: _GUFunc_Nin1_Nout1[typing.Literal["so2_normalize"], typing.Literal["(2,2)->(2,2)"]]
# so2_rminus_jacobians(g, h): (2,2),(2,2)->(1,1),(1,1)
so2_rminus_jacobians: _GUFunc_Nin2_Nout2[typing.Literal["so2_rminus_jacobians"], typing.Literal["(2,2),(2,2)->(1,1),(1,1)"]]
# so2_vee(matrix): (2,2)->()
so2_vee: _GUFunc_Nin1_Nout1[typing.Literal["so2_vee"], typing.Literal["(2,2)->()"]]
# so3_act(R, points): (3,3),(3)->(3)
so3_act: _GUFunc_Nin2_Nout1[typing.Literal["so3_act"], typing.Literal["(3,3),(3)->(3)"]]
# so3_act_jacobian(R, points): (3,3),(3)->(3,3)
so3_act_jacobian: _GUFunc_Nin2_Nout1[typing.Literal["so3_act_jacobian"], typing.Literal["(3,3),(3)->(3,3)"]]
# so3_angle(R): (3,3)->()
so3_angle: _GUFunc_Nin1_Nout1[typing.Literal["so3_angle"], typing.Literal["(3,3)->()"]]
# so3_between_cov(a, cov_a, b, cov_b): (3,3),(3,3),(3,3),(3,3)->(3,3),(3,3)
so3_between_cov: _GUFunc_Nin4_Nout2[typing.Literal["so3_between_cov"], typing.Literal["(3,3),(3,3),(3,3),(3,3)->(3,3),(3,3)"]]
# so3_between_jacobians(a, b): (3,3),(3,3)->(3,3),(3,3)
so3_between_jacobians: _GUFunc_Nin2_Nout2[typing.Literal["so3_between_jacobians"], typing.Literal["(3,3),(3,3)->(3,3),(3,3)"]]
# so3_compose(a, b): (3,3),(3,3)->(3,3)
so3_compose: _GUFunc_Nin2_Nout1[typing.Literal["so3_compose"], typing.Literal["(3,3),(3,3)->(3,3)"]]
# so3_compose_cov(a, cov_a, b, cov_b): (3,3),(3,3),(3,3),(3,3)->(3,3),(3,3)
so3_compose_cov: _GUFunc_Nin4_Nout2[typing.Literal["so3_compose_cov"], typing.Literal["(3,3),(3,3),(3,3),(3,3)->(3,3),(3,3)"]]
# so3_compose_jacobians(a, b): (3,3),(3,3)->(3,3),(3,3)
so3_compose_jacobians: _GUFunc_Nin2_Nout2[typing.Literal["so3_compose_jacobians"], typing.Literal["(3,3),(3,3)->(3,3),(3,3)"]]
# so3_distance(a, b): (3,3),(3,3)->()
so3_distance: _GUFunc_Nin2_Nout1[typing.Literal["so3_distance"], typing.Literal["(3,3),(3,3)->()"]]
# so3_exp(w): (3)->(3,3)
so3_exp: _GUFunc_Nin1_Nout1[typing.Literal["so3_exp"], typing.Literal["(3)->(3,3)"]]
# so3_from_uniforms(u): (3)->(3,3)
so3_from_uniforms: _GUFunc_Nin1_Nout1[typing.Literal["so3_from_uniforms"], typing.Literal["(3)->(3,3)"]]
# so3_hat(w): (3)->(3,3)
so3_hat: _GUFunc_Nin1_Nout1[typing.Literal["so3_hat"], typing.Literal["(3)->(3,3)"]]
# so3_interpolate(a, b, t): (3,3),(3,3),()->(3,3)
so3_interpolate: _GUFunc_Nin3_Nout1[typing.Literal["so3_interpolate"], typing.Literal["(3,3),(3,3),()->(3,3)"]]
# so3_inverse(R): (3,3)->(3,3)
so3_inverse: _GUFunc_Nin1_Nout1[typing.Literal["so3_inverse"], typing.Literal["(3,3)->(3,3)"]]
# so3_inverse_cov(a, cov_a): (3,3),(3,3)->(3,3),(3,3)
so3_inverse_cov: _GUFunc_Nin2_Nout2[typing.Literal["so3_inverse_cov"], typing.Literal["(3,3),(3,3)->(3,3),(3,3)"]]
# so3_log(R): (3,3)->(3)
so3_log: _GUFunc_Nin1_Nout1[typing.Literal["so3_log"], typing.Literal["(3,3)->(3)"]]
# so3_normalize(R): (3,3)->(3,3)
so3_normalize: _GUFunc_Nin1_Nout1[typing.Literal["so3_normalize"], typing.Literal["(3,3)->(3,3)"]]
# so3_rminus_jacobians(g, h): (3,3),(3,3)->(3,3),(3,3)
so3_rminus_jacobians: _GUFunc_Nin2_Nout2[typing.Literal["so3_rminus_jacobians"], typing.Literal["(3,3),(3,3)->(3,3),(3,3)"]]
# so3_vee(matrix): (3,3)->(3)
so3_vee: _GUFunc_Nin1_Nout1[typing.Literal["so3_vee"], typing.Literal["(3,3)->(3)"]]
