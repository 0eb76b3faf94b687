"""Gaussians on the groups: ``Gaussian(mean, cov)``, with the propagation of
the covariance through composition, inverse, relative motion, action on
points, log and interpolation.

The mathematics is C++ (include/chasles/gaussian.hpp): each method calls
one private gufunc of bindings/bind_gaussian.cpp (``_core._se3_act_cov``,
...) or one array function (``se3_compose_cov``, ``se3_between_cov``,
``se3_inverse_cov``) on the mean's matrix and the covariance; sampling is
the group's ``<g>_gaussian``. This class checks the arguments and holds the
mean (a group object) and the covariance (a read-only float64 array). It is
a value: immutable, pickled and copied as its constructor's arguments.
"""

from __future__ import annotations

import numbers
from typing import Any, NamedTuple, Optional, Union

import numpy as np
from numpy.typing import ArrayLike

from chasles import _core, _random
from chasles._value import Value

# The group classes, and for each the prefix of its functions, the size of
# the points it acts on and its tangent dimension.
_GROUPS = {
    _core.SO2: ("so2", 2, 1),
    _core.SE2: ("se2", 2, 3),
    _core.SO3: ("so3", 3, 3),
    _core.SE3: ("se3", 3, 6),
    _core.Sim3: ("sim3", 3, 7),
    _core.SE23: ("se23", 3, 9),
}
_NAMES = "SO2, SE2, SO3, SE3, Sim3 or SE23"
Element = Union[_core.SO2, _core.SE2, _core.SO3, _core.SE3, _core.Sim3, _core.SE23]


class VectorGaussian(NamedTuple):
    """A Gaussian on R^n: what ``Gaussian.act`` (the points) and ``Gaussian.log`` (the tangent) return."""

    mean: np.ndarray
    """The mean, shape (..., n)."""
    cov: np.ndarray
    """The covariance, shape (..., n, n)."""


def _finite(a: ArrayLike, what: str, shape: tuple, batch: bool = False) -> np.ndarray:
    """a as float64, of the shape (batch: (..., *shape)), finite."""
    m = _random._asarray(a, what).astype(np.float64)
    k = len(shape)
    if (m.ndim < k or m.shape[m.ndim - k :] != shape) if batch else m.shape != shape:
        want = f"(..., {', '.join(map(str, shape))})" if batch else str(shape)
        raise ValueError(f"{what}: expected shape {want}, got {m.shape}")
    if not np.all(np.isfinite(m)):
        raise ValueError(f"{what}: expected finite numbers, got {m!r}")
    return m


def _real(t: Any, what: str) -> float:
    """A finite real number, taken as the library's functions of a float take
    one: a Python or numpy real (bool and int included), a 0-d array, an
    object with __float__."""
    if isinstance(t, (int, float)):  # bool included
        try:
            x = float(t)
        except OverflowError:
            raise ValueError(f"{what}: {t} is too large for a float") from None
    elif t is None or isinstance(t, (complex, np.complexfloating, str, bytes)):
        raise TypeError(f"{what}: expected a real number (float64), got {type(t).__name__}")
    elif isinstance(t, (np.ndarray, np.generic, list, tuple)):
        a = _random._asarray(t, what)
        if a.ndim != 0:
            raise ValueError(f"{what}: expected shape (), got shape {a.shape}")
        x = float(a.astype(np.float64))
    elif hasattr(type(t), "__float__"):
        try:
            x = float(t)
        except TypeError:
            raise TypeError(f"{what}: expected a real number, got {type(t).__name__}") from None
        except (ValueError, OverflowError) as e:
            raise ValueError(f"{what}: {e}") from None
    else:
        raise TypeError(f"{what}: expected a real number (float64), got {type(t).__name__}")
    if not np.isfinite(x):
        raise ValueError(f"{what}: expected a finite number, got {x!r}")
    return x


def _group(x: Any) -> Any:
    """The group class of x (of a subclass's instance too), or None."""
    return next((cls for cls in _GROUPS if isinstance(x, cls)), None)


def _checked(mean: Any, cov: ArrayLike, what: str) -> tuple:
    """(the mean's matrix, cov as a new float64 array), after the checks of
    Gaussian(mean, cov)."""
    if _group(mean) is None:
        hint = ""
        if isinstance(mean, (np.ndarray, list, tuple)):
            hint = "; a matrix is an element by chasles.SE3.from_matrix(m) (or its group's class)"
        raise TypeError(f"{what}(mean): expected {_NAMES}, got {type(mean).__name__}{hint}")
    m = np.array(mean)  # TypeError for an element that is not initialized
    _random._covariance_factor(cov, _GROUPS[_group(mean)][2], what)  # shape, finite, symmetric, PSD
    return m, np.array(cov, dtype=np.float64)


def _made(mean_cls: type, m: np.ndarray, cov: np.ndarray, mean: Any = None) -> Gaussian:
    """A Gaussian of checked parts (a kernel's results), without the checks."""
    g = Gaussian.__new__(Gaussian)
    g._mean = mean_cls.from_matrix_unchecked(m) if mean is None else mean
    m.flags.writeable = False
    cov.flags.writeable = False
    g._m, g._cov = m, cov
    return g


def _me(self: Any, member: str) -> Gaussian:
    """self, when it is a Gaussian (TypeError otherwise, as a method of a bound class)."""
    if not isinstance(self, Gaussian):
        raise TypeError(f"Gaussian.{member}: expected a Gaussian as self, got {type(self).__name__}")
    return self


def _kernel(g: Gaussian, what: str) -> Any:
    """The array function <g>_`what` of g's group: "compose_cov", ..."""
    return getattr(_core, f"{_GROUPS[_group(g.mean)][0]}_{what}")


def _private(g: Gaussian, what: str) -> Any:
    """The private gufunc _<g>_`what` of g's group: "act_cov", ..."""
    return getattr(_core, f"_{_GROUPS[_group(g.mean)][0]}_{what}")


def _operand(a: Gaussian, b: Any, what: str) -> Gaussian:
    """b as a Gaussian of a's group (a group element: zero covariance)."""
    group = _group(a.mean)
    if isinstance(b, group):
        return _made(group, np.array(b), np.zeros_like(a.cov), b)
    if isinstance(b, Gaussian) and "_cov" in b.__dict__ and _group(b.mean) is group:
        return b
    if isinstance(b, Gaussian) and "_cov" in b.__dict__:
        got = f"a Gaussian on {_group(b.mean).__name__}"
    else:
        got = "a Gaussian that is not initialized" if isinstance(b, Gaussian) else type(b).__name__
    group = group.__name__
    raise TypeError(f"Gaussian.{what}: expected a Gaussian on {group} or an {group}, got {got}")


def _cross(a: Gaussian, cross_cov: Any, what: str) -> np.ndarray:
    return _finite(cross_cov, f"Gaussian.{what}(cross_cov)", a.cov.shape)


class Gaussian(Value):
    """A Gaussian on a group: X = mean exp(e), e ~ N(0, cov).

    The mean is an element of SO2, SE2, SO3, SE3, Sim3 or SE23; the
    covariance is that of the perturbation e in the mean's own (local,
    right) frame, in the order of the group's tangent: (v, w) for SE3,
    (v, w, sigma) for Sim3, (rho, nu, w) for SE23, the convention of the
    Jacobians (``compose_jacobians``, ...) and of Barfoot and Furgale's
    "concentrated Gaussian" written on the right (Sola et al. 2018, manif).
    The left perturbation X = exp(e_l) mean has cov_l = Ad cov Ad^T
    (``left_cov``, ``from_left``).

    Each operation f carries the covariance by its Jacobians to first order,
    f(X) = f(mean) exp(J e), cov' = J cov J^T (two operands: the sum of
    theirs, with a cross-covariance if given); ``compose(order=4)`` on SE3
    adds Barfoot and Furgale's fourth-order terms, which matter once the
    rotations' standard deviations reach a tenth of a radian.

    ``a @ b`` composes independent Gaussians; b may be a group element (a
    Gaussian of zero covariance). A Gaussian is an immutable value: it
    pickles and copies as its constructor's arguments.

    Example:
        >>> import chasles
        >>> a = chasles.Gaussian(chasles.SE3.exp([1.0, 0, 0, 0, 0, 0.5]), 1e-4 * np.eye(6))
        >>> b = a @ a
        >>> b.cov.shape
        (6, 6)
        >>> bool(np.allclose(b.mean.translation, (a.mean @ a.mean).translation))
        True
        >>> b.sample(1000, rng=0).shape
        (1000, 4, 4)
    """

    _state = ("_mean", "_m", "_cov")
    __array_ufunc__ = None  # numpy defers to the Gaussian: g @ array is a TypeError, not numpy's matmul

    def __init__(self, mean: Element, cov: ArrayLike) -> None:
        """A Gaussian from its mean and covariance.

        Args:
            mean: SO2, SE2, SO3, SE3, Sim3 or SE23: the mean.
            cov: array_like of shape (D, D), D the group's tangent dimension
                (1 for SO2, 3 for SE2 and SO3, 6 for SE3, 7 for Sim3, 9 for
                SE23): symmetric positive semidefinite, finite.

        Raises:
            TypeError: mean is not an element of one of the groups.
            ValueError: cov has the wrong shape, is not finite, not
                symmetric or not positive semidefinite.
        """
        if "_cov" in self.__dict__:
            raise TypeError("Gaussian.__init__: the Gaussian is already initialized (Gaussians are immutable)")
        m, cov = _checked(mean, cov, "Gaussian")
        m.flags.writeable = cov.flags.writeable = False
        self._mean, self._m, self._cov = mean, m, cov

    @staticmethod
    def from_left(mean: Element, cov: ArrayLike) -> Gaussian:
        """The Gaussian X = exp(e_l) mean, e_l ~ N(0, cov): cov is that of the left perturbation.

        In the right perturbation, Ad_mean^-1 cov Ad_mean^-T. Arguments as for ``Gaussian(mean, cov)``.
        """
        m, c = _checked(mean, cov, "Gaussian.from_left")
        prefix = _GROUPS[_group(mean)][0]
        cov = getattr(_core, f"_{prefix}_left_cov")(np.array(mean.inverse()), c)
        return _made(_group(mean), m, cov, mean)

    @staticmethod
    def from_ros(mean: _core.SE3, cov: ArrayLike) -> Gaussian:
        """The Gaussian on SE3 of a ROS geometry_msgs/PoseWithCovariance.

        ROS's covariance is that of (x, y, z, roll, pitch, yaw): the position
        in the fixed frame and the roll, pitch and yaw about the fixed axes
        (R = Rz(yaw) Ry(pitch) Rx(roll), ``SO3.as_rpy``), row-major in the
        message. To first order, (dp, d rpy) = J e with dp = R v and
        d rpy = E^-1 R w, E the matrix of the angles' rates to the angular
        velocity: this is J^-1 cov J^-T (``to_ros_covariance``'s
        inverse).

        Args:
            mean: SE3, the pose (``SE3(SO3.from_quat(q), p)`` from the message).
            cov: array_like of shape (6, 6) or (36,) (the message's row-major
                list): symmetric positive semidefinite, finite.

        Example:
            >>> import chasles
            >>> ros = 0.01 * np.eye(6)
            >>> g = chasles.Gaussian.from_ros(chasles.SE3.exp([1.0, 2, 0, 0.1, 0.2, 0.3]), ros.ravel())
            >>> bool(np.allclose(g.to_ros_covariance(), ros))
            True
        """
        if not isinstance(mean, _core.SE3):
            raise TypeError(f"Gaussian.from_ros(mean): expected an SE3, got {type(mean).__name__}")
        c = _random._asarray(cov, "Gaussian.from_ros(cov)")
        if c.shape == (36,):
            c = c.reshape(6, 6)
        m, c = _checked(mean, c, "Gaussian.from_ros")
        return _made(_core.SE3, m, _core._se3_cov_from_ros(m, c), mean)

    def to_ros_covariance(self) -> np.ndarray:
        """The covariance of ROS's PoseWithCovariance, (6, 6): of (x, y, z, roll, pitch, yaw) (see ``from_ros``).

        ``.ravel()`` gives the message's 36 numbers, row-major.

        Raises:
            TypeError: the Gaussian is not on SE3.
            ValueError: the mean is at the gimbal lock (pitch +-pi/2), where
                roll and yaw are one angle and no covariance of the three is
                defined.
        """
        _me(self, "to_ros_covariance")
        if not isinstance(self._mean, _core.SE3):
            raise TypeError(
                f"Gaussian.to_ros_covariance: ROS's pose covariance is of a Gaussian on SE3, "
                f"got one on {_group(self._mean).__name__}"
            )
        c = _core._se3_cov_to_ros(self._m, self._cov)
        if not np.all(np.isfinite(c)):
            raise ValueError(
                "Gaussian.to_ros_covariance: the mean is at the gimbal lock (pitch +-pi/2), where roll and yaw "
                "are one angle: the covariance of (x, y, z, roll, pitch, yaw) is not defined"
            )
        return c

    @property
    def mean(self) -> Element:
        """The mean: an SO2, SE2, SO3, SE3, Sim3 or SE23."""
        _me(self, "mean")
        return self._mean

    @property
    def cov(self) -> np.ndarray:
        """The covariance of the right perturbation, (D, D), float64 (read-only)."""
        _me(self, "cov")
        return self._cov

    @property
    def left_cov(self) -> np.ndarray:
        """The covariance of the left perturbation X = exp(e_l) mean: Ad_mean cov Ad_mean^T."""
        _me(self, "left_cov")
        return _private(self, "left_cov")(self._m, self._cov)

    def __reduce__(self) -> tuple[Any, ...]:
        """Pickle support (every protocol) and copy: the constructor's arguments."""
        _me(self, "__reduce__")
        return (Gaussian, (self._mean, self._cov))

    def __repr__(self) -> str:
        _me(self, "__repr__")
        if "_cov" not in self.__dict__:
            return "<uninitialized Gaussian>"
        return f"Gaussian(mean={self._mean!r}, cov={self._cov!r})"

    def compose(self, b: Union[Gaussian, Element], cross_cov: Optional[ArrayLike] = None, order: int = 1) -> Gaussian:
        """X_a X_b (a = self): mean a b, covariance Ad_{b^-1} cov_a Ad_{b^-1}^T + cov_b.

        Args:
            b: a Gaussian on the same group, or an element of it (known
                exactly: zero covariance).
            cross_cov: None for independent operands, or E[e_a e_b^T],
                (D, D): adds J_a C + (J_a C)^T, J_a = Ad_{b^-1}.
            order: 1 (first order), or 4 on SE3 for the fourth-order
                compounding of Barfoot and Furgale (2014, section III.C),
                independent operands only.

        Returns:
            Gaussian: the composition.

        Raises:
            TypeError: b is not a Gaussian on (or an element of) the same
                group; order is not an int.
            ValueError: cross_cov has the wrong shape or is not finite; order
                is not 1 or 4, or 4 off SE3 or with a cross_cov.
        """
        _me(self, "compose")
        g = _operand(self, b, "compose(b)")
        if isinstance(order, (bool, np.bool_)) or not isinstance(order, (numbers.Integral, np.integer)):
            raise TypeError(f"Gaussian.compose(order): expected 1 or 4, got {type(order).__name__}")
        if order not in (1, 4):
            raise ValueError(f"Gaussian.compose(order): expected 1 or 4, got {order}")
        cls = _group(self._mean)
        if order == 4:
            if cls is not _core.SE3 or cross_cov is not None:
                where = "with a cross_cov" if cls is _core.SE3 else f"on {cls.__name__}"
                raise ValueError(
                    "Gaussian.compose(order=4): the fourth-order compounding is of independent Gaussians on SE3, "
                    f"got one {where}"
                )
            return _made(cls, *_core._se3_compose_cov4(self._m, self._cov, g._m, g._cov))
        if cross_cov is None:
            return _made(cls, *_kernel(self, "compose_cov")(self._m, self._cov, g._m, g._cov))
        c = _cross(self, cross_cov, "compose")
        return _made(cls, *_private(self, "compose_cov_cross")(self._m, self._cov, g._m, g._cov, c))

    def __matmul__(self, b: Any) -> Gaussian:
        """a @ b: ``a.compose(b)``, independent operands (b a Gaussian or a group element)."""
        _me(self, "__matmul__")
        if not isinstance(b, (_group(self._mean), Gaussian)):
            return NotImplemented
        return self.compose(b)

    def inverse(self) -> Gaussian:
        """X^-1: mean^-1, covariance Ad_mean cov Ad_mean^T (the left covariance)."""
        _me(self, "inverse")
        return _made(_group(self._mean), *_kernel(self, "inverse_cov")(self._m, self._cov))

    def between(self, b: Union[Gaussian, Element], cross_cov: Optional[ArrayLike] = None) -> Gaussian:
        """X_a^-1 X_b (a = self), the motion from X_a to X_b: covariance J cov_a J^T + cov_b, J = -Ad_{b^-1 a}.

        Args:
            b: a Gaussian on the same group, or an element of it.
            cross_cov: None for independent operands, or E[e_a e_b^T], (D, D).

        Returns:
            Gaussian: the relative motion.
        """
        _me(self, "between")
        g = _operand(self, b, "between(b)")
        cls = _group(self._mean)
        if cross_cov is None:
            return _made(cls, *_kernel(self, "between_cov")(self._m, self._cov, g._m, g._cov))
        c = _cross(self, cross_cov, "between")
        return _made(cls, *_private(self, "between_cov_cross")(self._m, self._cov, g._m, g._cov, c))

    def act(self, points: ArrayLike, cov: Optional[ArrayLike] = None) -> VectorGaussian:
        """The points X p: their means and covariances.

        Args:
            points: array_like of shape (..., P), P = 2 for SO2 and SE2,
                3 for the others: points known exactly, or the means of
                uncertain ones.
            cov: None, or array_like of shape (..., P, P): the points'
                covariances (independent of X), broadcast against points.

        Returns:
            VectorGaussian: mean (..., P), the points mean p; cov (..., P, P),
            J cov J^T (+ R cov_p R^T), J = d(X p)/dX.
        """
        _me(self, "act")
        n = _GROUPS[_group(self._mean)][1]
        p = _finite(points, "Gaussian.act(points)", (n,), batch=True)
        c = np.zeros((n, n)) if cov is None else _finite(cov, "Gaussian.act(cov)", (n, n), batch=True)
        return VectorGaussian(*_private(self, "act_cov")(self._m, self._cov, p, c))

    def log(self) -> VectorGaussian:
        """log(X): the tangent Gaussian, mean log(mean) (shape (D,), (1,) for SO2), cov J cov J^T, J = Jr^-1."""
        _me(self, "log")
        return VectorGaussian(*_private(self, "log_cov")(self._m, self._cov))

    def interpolate(self, b: Union[Gaussian, Element], t: float) -> Gaussian:
        """X_a exp(t log(X_a^-1 X_b)) (a = self), X_a and X_b independent: t = 0 gives X_a, 1 gives X_b.

        Args:
            b: a Gaussian on the same group, or an element of it.
            t: a finite real number.
        """
        _me(self, "interpolate")
        g = _operand(self, b, "interpolate(b)")
        x = _real(t, "Gaussian.interpolate(t)")
        return _made(_group(self._mean), *_private(self, "interpolate_cov")(self._m, self._cov, g._m, g._cov, x))

    def mahalanobis(self, x: Union[Element, ArrayLike]) -> Any:
        """The squared Mahalanobis distance e^T cov^-1 e, e = rminus(x, mean) = log(mean^-1 x).

        Args:
            x: an element of the mean's group, or array_like of shape
                (..., n, n) of its matrices (taken as given).

        Returns:
            float for an element, numpy.ndarray of shape (...) for matrices.
            NaN where the covariance is singular (no distance is defined
            along a direction of zero variance).
        """
        _me(self, "mahalanobis")
        f = _private(self, "mahalanobis")
        if isinstance(x, _group(self._mean)):
            return float(f(self._m, self._cov, np.array(x)))
        n = self._m.shape[0]
        m = _finite(x, "Gaussian.mahalanobis(x)", (n, n), batch=True)
        return f(self._m, self._cov, m)

    def sample(self, n: _random.Size = None, rng: Any = None) -> np.ndarray:
        """Samples mean exp(L z), L L^T = cov, z standard normal (the group's ``<g>_gaussian``).

        Args:
            n: None for one sample, an int or a tuple for a batch.
            rng: None, an int seed or a numpy Generator.

        Returns:
            numpy.ndarray of shape (k, k), (n, k, k) or n + (k, k): the
            samples' matrices.
        """
        _me(self, "sample")
        _random._batch(n, "Gaussian.sample")
        generator = _random._generator(rng, "Gaussian.sample")
        prefix = _GROUPS[_group(self._mean)][0]
        return getattr(_random, f"{prefix}_gaussian")(self._m, self._cov, n, generator)
