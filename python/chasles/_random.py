"""Random rotations and rigid motions, and the elements of the other groups.

numpy's Generator is the only source of randomness: these functions draw
uniforms or standard normals with it and map them with the C++ kernels
(``so3_from_uniforms``, Shoemake's map; ``so3_exp`` / ``se3_exp`` and the
compositions for the Gaussian perturbations), so the maps are testable on
their own and a seed gives the same samples on every platform numpy
supports. ``rng`` is taken as scipy takes it: None (a fresh
``numpy.random.default_rng()``), an int seed, a SeedSequence, a BitGenerator
or a Generator (used, and advanced, as is).

The samplers of SO2, SE2, Sim3 and SE23 are written once, over the group
table (``_groups.py``): ``_make_random`` (the uniform rotation of
``_core._<g>_from_uniforms`` and a box on the Euclidean part, whose
coordinates each group names) and ``_make_gaussian`` (mean exp(L z) by the
group's ``_exp`` and ``_compose``).
"""

from __future__ import annotations

import inspect
import numbers
from collections.abc import Sequence
from typing import Any, Union

import numpy as np
from numpy.typing import ArrayLike

from chasles import _core, _groups

Size = Union[None, int, Sequence[int]]


def _generator(rng: Any, name: str) -> np.random.Generator:
    if not (
        rng is None
        or isinstance(rng, (numbers.Integral, np.random.Generator, np.random.BitGenerator, np.random.SeedSequence))
    ):
        # A sequence of ints is a seed too; given to numpy as a plain array
        # (numpy's SeedSequence recurses without end on an np.matrix).
        try:
            seed = np.asarray(rng).view(np.ndarray)
        except (TypeError, ValueError):
            seed = None
        if seed is None or seed.dtype.kind not in "iu" or seed.ndim != 1:
            raise TypeError(
                f"{name}(rng): expected None, an int seed >= 0 (or a sequence of them), a SeedSequence, "
                f"a BitGenerator or a numpy.random.Generator, got {type(rng).__name__}"
            )
        rng = seed
    try:
        return np.random.default_rng(rng)
    except (TypeError, ValueError) as e:
        raise type(e)(
            f"{name}(rng): expected None, an int seed >= 0, a SeedSequence, a BitGenerator or a "
            f"numpy.random.Generator, got {rng!r} ({e})"
        ) from None


def _batch(n: Size, name: str) -> tuple:
    """The batch shape: () for None, (n,) for an int, a tuple of ints as is."""
    if n is None:
        return ()
    if isinstance(n, (str, bytes)):
        raise TypeError(f"{name}(n): expected None, an int or a tuple of ints, got {type(n).__name__}")
    items = (n,) if isinstance(n, numbers.Integral) or (isinstance(n, np.ndarray) and n.ndim == 0) else n
    try:
        shape = tuple(items)
    except TypeError:
        raise TypeError(f"{name}(n): expected None, an int or a tuple of ints, got {type(n).__name__}") from None
    for k in shape:
        if (
            isinstance(k, (bool, np.bool_))
            or not isinstance(k, (numbers.Integral, np.integer))
            and not (isinstance(k, np.ndarray) and k.ndim == 0 and k.dtype.kind in "iu")
        ):
            raise TypeError(f"{name}(n): expected None, an int or a tuple of ints, got {n!r}")
        if int(k) < 0:
            raise ValueError(f"{name}(n): expected a size >= 0, got {n!r}")
    return tuple(int(k) for k in shape)


def _asarray(a: ArrayLike, what: str) -> np.ndarray:
    """np.asarray(a) of a real dtype; its failures name `what`."""
    if a is None or isinstance(a, (str, bytes)):
        raise TypeError(f"{what}: expected real numbers (float64), got {type(a).__name__}")
    try:
        m = np.asarray(a)
    except (TypeError, ValueError) as e:
        raise type(e)(f"{what}: could not convert to an array: {e}") from None
    if m.dtype.kind not in "biuf":
        raise TypeError(f"{what}: expected real numbers (float64), got dtype {m.dtype}")
    return m


def _matrix(a: ArrayLike, shape: tuple, what: str) -> np.ndarray:
    m = _asarray(a, what).astype(np.float64)
    if m.shape != shape:
        raise ValueError(f"{what}: expected shape {shape}, got {m.shape}")
    if not np.all(np.isfinite(m)):
        raise ValueError(f"{what}: expected finite numbers, got {m!r}")
    return m


def _group_element(a: ArrayLike, group: Any, what: str) -> np.ndarray:
    """A finite (3, 3) rotation or (4, 4) rigid motion, checked as
    ``SO3.from_matrix`` / ``SE3.from_matrix`` check one (their tolerance,
    sqrt(eps) on the rotation defect max(|R^T R - I|, |det R - 1|) and on the
    bottom row); the refusal is theirs, naming ``what``."""
    n = np.asarray(group.identity()).shape[0]
    m = _matrix(a, (n, n), what)
    try:
        group.from_matrix(m)
    except ValueError as e:
        text = str(e)
        prefix = f"{group.__name__}.from_matrix: "
        text = text[len(prefix) :] if text.startswith(prefix) else text
        raise ValueError(f"{what}: {text.replace(', or pass a larger tol.', '.')}") from None
    return m


def _covariance_factor(cov: ArrayLike, n: int, name: str) -> np.ndarray:
    """L with L L^T = cov: the Cholesky factor, or for a positive
    semidefinite cov that is singular, V sqrt(lambda) from its eigenvectors."""
    c = _matrix(cov, (n, n), f"{name}(cov)")
    scale = max(float(np.abs(c).max()), np.finfo(np.float64).tiny)
    if not np.allclose(c, c.T, rtol=0, atol=1e-12 * scale):
        raise ValueError(f"{name}(cov): expected a symmetric matrix, got {c!r}")
    try:
        return np.linalg.cholesky(c)
    except np.linalg.LinAlgError:
        lam, V = np.linalg.eigh(c)
        if lam.min() < -1e-12 * scale:
            raise ValueError(f"{name}(cov): expected a positive semidefinite matrix, got eigenvalues {lam!r}") from None
        return V * np.sqrt(np.clip(lam, 0.0, None))


def so3_random(n: Size = None, rng: Any = None) -> np.ndarray:
    """Uniform random rotations (the Haar measure), as scipy's ``Rotation.random``.

    Shoemake's method: three uniforms u from ``rng``, mapped by
    ``so3_from_uniforms`` to a unit quaternion uniform on S^3. The angle of
    the rotations has the density (1 - cos t) / pi on [0, pi] (CDF
    (t - sin t) / pi).

    Args:
        n: None for one rotation, an int or a tuple for a batch.
        rng: None (a fresh ``numpy.random.default_rng()``), an int seed or a
            numpy Generator (advanced by 3 uniforms per rotation).

    Returns:
        numpy.ndarray of shape (3, 3), (n, 3, 3) or n + (3, 3): the rotation
        matrices, float64.

    Example:
        >>> import chasles
        >>> chasles.so3_random(4, rng=0).shape
        (4, 3, 3)
    """
    shape = _batch(n, "so3_random")
    u = _generator(rng, "so3_random").random(shape + (3,))
    return _core.so3_from_uniforms(u)


def se3_random(n: Size = None, rng: Any = None, *, low: ArrayLike = -1.0, high: ArrayLike = 1.0) -> np.ndarray:
    """Random rigid motions: a uniform rotation and a translation uniform in a box.

    The rotation as ``so3_random`` (its 3 uniforms drawn first), then the
    translation uniform in [low, high] componentwise (3 more uniforms),
    independent of the rotation.

    Args:
        n: None for one pose, an int or a tuple for a batch.
        rng: None (a fresh ``numpy.random.default_rng()``), an int seed or a
            numpy Generator.
        low: array_like of shape () or (3,): the box's lower corner.
        high: array_like of shape () or (3,): the box's upper corner.

    Returns:
        numpy.ndarray of shape (4, 4), (n, 4, 4) or n + (4, 4): the
        homogeneous matrices [[R, p], [0, 1]], float64.

    Example:
        >>> import chasles
        >>> g = chasles.se3_random(rng=0, low=[0, 0, 0], high=[1, 2, 3])
        >>> bool(np.all((0 <= g[:3, 3]) & (g[:3, 3] <= [1, 2, 3])))
        True
    """
    shape = _batch(n, "se3_random")
    lo = np.broadcast_to(_box(low, "se3_random(low)"), (3,))
    hi = np.broadcast_to(_box(high, "se3_random(high)"), (3,))
    if np.any(hi < lo):
        raise ValueError(f"se3_random: expected low <= high, got low={lo!r}, high={hi!r}")
    gen = _generator(rng, "se3_random")
    R = _core.so3_from_uniforms(gen.random(shape + (3,)))
    p = lo + (hi - lo) * gen.random(shape + (3,))
    return _pose(R, p)


def _box(a: ArrayLike, what: str, k: int = 3) -> np.ndarray:
    b = _asarray(a, what)
    if b.shape not in ((), (k,)):
        raise ValueError(f"{what}: expected shape () or ({k},), got {b.shape}")
    b = b.astype(np.float64)
    if not np.all(np.isfinite(b)):
        raise ValueError(f"{what}: expected finite numbers, got {b!r}")
    return b


def _pose(R: np.ndarray, p: np.ndarray) -> np.ndarray:
    g = np.zeros(R.shape[:-2] + (4, 4))
    g[..., :3, :3] = R
    g[..., :3, 3] = p
    g[..., 3, 3] = 1.0
    return g


def so3_gaussian(mean: ArrayLike, cov: ArrayLike, n: Size = None, rng: Any = None) -> np.ndarray:
    """Gaussian random rotations about a mean, with a tangent covariance.

    R = mean exp([L z]) with z standard normal and L L^T = cov (L the
    Cholesky factor): the right (local) perturbation of the Jacobians'
    convention, so that log(mean^-1 R) has the covariance ``cov``.

    Args:
        mean: array_like of shape (3, 3) or an SO3: the mean rotation,
            checked as ``SO3.from_matrix`` checks one (a ValueError if its
            rotation defect exceeds sqrt(eps)).
        cov: array_like of shape (3, 3): the covariance of the rotation
            vector, symmetric positive semidefinite (radians^2).
        n: None for one rotation, an int or a tuple for a batch.
        rng: None, an int seed or a numpy Generator (3 normals per sample).

    Returns:
        numpy.ndarray of shape (3, 3), (n, 3, 3) or n + (3, 3): the rotations.

    Example:
        >>> import chasles
        >>> chasles.so3_gaussian(np.eye(3), 0.01 * np.eye(3), 5, rng=0).shape
        (5, 3, 3)
    """
    R0 = _group_element(mean, _core.SO3, "so3_gaussian(mean)")
    L = _covariance_factor(cov, 3, "so3_gaussian")
    shape = _batch(n, "so3_gaussian")
    z = _generator(rng, "so3_gaussian").standard_normal(shape + (3,))
    return _core.so3_compose(R0, _core.so3_exp(z @ L.T))


def se3_gaussian(mean: ArrayLike, cov: ArrayLike, n: Size = None, rng: Any = None) -> np.ndarray:
    """Gaussian random rigid motions about a mean, with a tangent covariance.

    g = mean exp([L z]) with z standard normal in the twist order (v, w) and
    L L^T = cov (L the Cholesky factor): the right (local) perturbation of
    the Jacobians' convention, so that the twist log(mean^-1 g) has the
    covariance ``cov``.

    Args:
        mean: array_like of shape (4, 4) or an SE3: the mean pose, checked
            as ``SE3.from_matrix`` checks one (a ValueError if its rotation
            block's defect, or its bottom row's distance to (0, 0, 0, 1),
            exceeds sqrt(eps)).
        cov: array_like of shape (6, 6): the covariance of the twist (v, w),
            linear part first, symmetric positive semidefinite.
        n: None for one pose, an int or a tuple for a batch.
        rng: None, an int seed or a numpy Generator (6 normals per sample).

    Returns:
        numpy.ndarray of shape (4, 4), (n, 4, 4) or n + (4, 4): the poses.

    Example:
        >>> import chasles
        >>> chasles.se3_gaussian(np.eye(4), 0.01 * np.eye(6), 5, rng=0).shape
        (5, 4, 4)
    """
    g0 = _group_element(mean, _core.SE3, "se3_gaussian(mean)")
    L = _covariance_factor(cov, 6, "se3_gaussian")
    shape = _batch(n, "se3_gaussian")
    z = _generator(rng, "se3_gaussian").standard_normal(shape + (6,))
    return _core.se3_compose(g0, _core.se3_exp(z @ L.T))


def _bounds(name: str, pairs: Sequence[tuple], values: dict) -> tuple:
    """low and high of the Euclidean part, from the keyword pairs
    (low name, high name, size, transform) of a sampler: each bound of
    shape () or (size,), low <= high, then transformed (the scale's
    bounds to their logarithms)."""
    lows, highs = [], []
    for low_name, high_name, k, transform in pairs:
        lo = np.broadcast_to(_box(values[low_name], f"{name}({low_name})", k), (k,))
        hi = np.broadcast_to(_box(values[high_name], f"{name}({high_name})", k), (k,))
        if np.any(hi < lo):
            raise ValueError(f"{name}: expected {low_name} <= {high_name}, got {low_name}={lo!r}, {high_name}={hi!r}")
        lows.append(transform(lo, f"{name}({low_name})"))
        highs.append(transform(hi, f"{name}({high_name})"))
    return np.concatenate(lows), np.concatenate(highs)


def _same(b: np.ndarray, what: str) -> np.ndarray:
    return b


def _log_positive(b: np.ndarray, what: str) -> np.ndarray:
    if np.any(b <= 0):
        raise ValueError(f"{what}: expected a scale > 0, got {b!r}")
    return np.log(b)


# For each group with a Euclidean part, its keyword bounds (low, high, size,
# transform) in the order of the C++ GroupParts vector, their defaults and
# the docstring's sentences.
_BOXES = {
    "se2": (
        (("low", "high", 2, _same),),
        {"low": -1.0, "high": 1.0},
        """        low: array_like of shape () or (2,): the translation box's lower corner.
        high: array_like of shape () or (2,): its upper corner.""",
        "the translation uniform in [low, high] componentwise",
    ),
    "sim3": (
        (("low", "high", 3, _same), ("scale_low", "scale_high", 1, _log_positive)),
        {"low": -1.0, "high": 1.0, "scale_low": 0.5, "scale_high": 2.0},
        """        low: array_like of shape () or (3,): the translation box's lower corner.
        high: array_like of shape () or (3,): its upper corner.
        scale_low: the smallest scale, > 0 (a float, or an array of shape (1,)).
        scale_high: the largest scale, >= scale_low.""",
        "the translation uniform in [low, high] componentwise and the scale\n"
        "    log-uniform in [scale_low, scale_high] (sigma = log s uniform in\n"
        "    [log scale_low, log scale_high]; scale_low = scale_high fixes it)",
    ),
    "se23": (
        (("low", "high", 3, _same), ("velocity_low", "velocity_high", 3, _same)),
        {"low": -1.0, "high": 1.0, "velocity_low": -1.0, "velocity_high": 1.0},
        """        low: array_like of shape () or (3,): the position box's lower corner.
        high: array_like of shape () or (3,): its upper corner.
        velocity_low: array_like of shape () or (3,): the velocity box's lower corner.
        velocity_high: array_like of shape () or (3,): its upper corner.""",
        "the position uniform in [low, high] and the velocity uniform in\n"
        "    [velocity_low, velocity_high] componentwise",
    ),
}

_UNIFORMS = {"so2": 1, "se2": 1, "sim3": 3, "se23": 3}

_RANDOM_DOC = """Random {kinds}: a uniform (Haar) rotation{box_title}.

    numpy's Generator draws {u} per element for the rotation
    first{then}, and ``_core._{prefix}_from_uniforms`` (the C++
    ``element_from_uniforms``) maps them: {what}.

    Args:
        n: None for one element, an int or a tuple for a batch.
        rng: None (a fresh ``numpy.random.default_rng()``), an int seed, a
            SeedSequence, a BitGenerator or a numpy Generator (advanced).
{box_args}
    Returns:
        numpy.ndarray of shape ({n}, {n}), (n, {n}, {n}) or n + ({n}, {n}):
        {matrix}, float64.

    Example:
        >>> import chasles
        >>> chasles.{prefix}_random(4, rng=0).shape
        (4, {n}, {n})
    """


def _make_random(group: _groups.Group):
    """The uniform sampler of one group of the table."""
    name = f"{group.prefix}_random"
    u_size = _UNIFORMS[group.prefix]
    mapping = getattr(_core, f"_{group.prefix}_from_uniforms")
    box = _BOXES.get(group.prefix)

    if box is None:

        def sample(n: Size = None, rng: Any = None) -> np.ndarray:
            shape = _batch(n, name)
            return mapping(_generator(rng, name).random(shape + (u_size,)))

        fields = {"box_title": "", "then": "", "box_args": ""}
        fields["what"] = "the angle pi (2u - 1), uniform in [-pi, pi)"
    else:
        pairs, defaults, args, what = box
        k = sum(p[2] for p in pairs)

        def sample(n: Size = None, rng: Any = None, **bounds: ArrayLike) -> np.ndarray:
            unknown = set(bounds) - set(defaults)
            if unknown:
                raise TypeError(f"{name}() got an unexpected keyword argument {sorted(unknown)[0]!r}")
            shape = _batch(n, name)
            lo, hi = _bounds(name, pairs, {**defaults, **bounds})
            gen = _generator(rng, name)
            u = gen.random(shape + (u_size,))
            v = gen.random(shape + (k,))
            return mapping(u, v, lo, hi)

        params = [
            inspect.Parameter("n", inspect.Parameter.POSITIONAL_OR_KEYWORD, default=None, annotation="Size"),
            inspect.Parameter("rng", inspect.Parameter.POSITIONAL_OR_KEYWORD, default=None, annotation="Any"),
        ] + [
            inspect.Parameter(key, inspect.Parameter.KEYWORD_ONLY, default=value, annotation="ArrayLike")
            for key, value in defaults.items()
        ]
        sample.__signature__ = inspect.Signature(params, return_annotation="np.ndarray")
        fields = {
            "box_title": " and a Euclidean part uniform in a box",
            "then": f", then {k} for the Euclidean part",
            "box_args": args + "\n",
            "what": "a uniform rotation, " + what,
        }
    sample.__name__ = sample.__qualname__ = name
    fields["u"] = "one uniform" if u_size == 1 else f"{u_size} uniforms"
    sample.__doc__ = _RANDOM_DOC.format(**group._asdict(), **fields)
    return sample


_GAUSSIAN_DOC = """Gaussian random {kinds} about a mean, with a tangent covariance.

    g = mean exp(L z) with z standard normal in the tangent order
    {tangent} and L L^T = cov (L the Cholesky factor, or V sqrt(lambda)
    for a singular cov): the right (local) perturbation of the Jacobians'
    convention, so that log(mean^-1 g) has the covariance ``cov``. The
    group's exp and compose array functions map the draws.

    Args:
        mean: array_like of shape ({n}, {n}) or a {cls}: the mean, checked as
            ``{cls}.from_matrix`` checks one.
        cov: array_like of shape ({dof}, {dof}): the tangent covariance,
            symmetric positive semidefinite.
        n: None for one element, an int or a tuple for a batch.
        rng: None, an int seed or a numpy Generator ({dof} normals per sample).

    Returns:
        numpy.ndarray of shape ({n}, {n}), (n, {n}, {n}) or n + ({n}, {n}):
        {matrix}.

    Example:
        >>> import chasles
        >>> chasles.{prefix}_gaussian(np.eye({n}), 0.01 * np.eye({dof}), 5, rng=0).shape
        (5, {n}, {n})
    """


def _make_gaussian(group: _groups.Group):
    """The Gaussian sampler of one group of the table."""
    name = f"{group.prefix}_gaussian"
    cls = getattr(_core, group.cls)
    exp = getattr(_core, f"{group.prefix}_exp")
    compose = getattr(_core, f"{group.prefix}_compose")

    def gaussian(mean: ArrayLike, cov: ArrayLike, n: Size = None, rng: Any = None) -> np.ndarray:
        g0 = _group_element(mean, cls, f"{name}(mean)")
        L = _covariance_factor(cov, group.dof, name)
        shape = _batch(n, name)
        x = _generator(rng, name).standard_normal(shape + (group.dof,)) @ L.T
        return compose(g0, exp(x[..., 0] if group.dof == 1 else x))

    gaussian.__name__ = gaussian.__qualname__ = name
    gaussian.__doc__ = _GAUSSIAN_DOC.format(**group._asdict())
    return gaussian


so2_random = _make_random(_groups.SO2)
se2_random = _make_random(_groups.SE2)
sim3_random = _make_random(_groups.SIM3)
se23_random = _make_random(_groups.SE23)
so2_gaussian = _make_gaussian(_groups.SO2)
se2_gaussian = _make_gaussian(_groups.SE2)
sim3_gaussian = _make_gaussian(_groups.SIM3)
se23_gaussian = _make_gaussian(_groups.SE23)
