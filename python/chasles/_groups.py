"""The table of the groups the generic families serve (means, random
samples): what each group's functions need to know about it, and the
sentences of their docstrings that are its own. The logic is written once
(``_mean.py``, ``_random.py``) and instantiated per row; the mathematics is
the C++ kernels' (``include/chasles/mean.hpp``, ``random.hpp``,
``group_parts.hpp``)."""

from __future__ import annotations

from typing import NamedTuple


class Group(NamedTuple):
    """One row of the table."""

    prefix: str
    """The prefix of the array functions: "so2", "se2", "sim3", "se23"."""
    cls: str
    """The class in chasles._core: "SO2", ..."""
    n: int
    """The matrix size."""
    dof: int
    """The tangent dimension."""
    kind: str
    """The word for one element: "rotation", "rigid motion", ..."""
    kinds: str
    """Its plural, for the titles."""
    matrix: str
    """The matrix layout."""
    tangent: str
    """The tangent's name and order."""
    chordal: str
    """What method="chordal" computes for this group."""
    example: str
    """The mean's docstring example (doctest lines)."""


SO2 = Group(
    "so2",
    "SO2",
    2,
    1,
    "rotation",
    "plane rotations",
    "2x2 rotation matrices [[cos t, -sin t], [sin t, cos t]]",
    "the angle theta (radians)",
    "the rotation of the normalized weighted average of the unit complex\n"
    "    numbers (cos t_i, sin t_i): the circular mean of the angles, the\n"
    "    rotation nearest (Frobenius) to sum_i w_i R_i",
    """        >>> import chasles
        >>> R = chasles.so2_exp([0.1, 0.3])
        >>> bool(np.isclose(chasles.so2_log(chasles.so2_mean(R)), 0.2))
        True""",
)
SE2 = Group(
    "se2",
    "SE2",
    3,
    3,
    "rigid motion",
    "plane rigid motions",
    "3x3 homogeneous matrices [[R, t], [0, 1]]",
    "the twist (vx, vy, w), linear part first",
    "per part, the chordal mean of the rotations (as so2_mean) and the\n"
    "    weighted average of the translations (left-invariant only)",
    """        >>> import chasles
        >>> g = chasles.se2_exp([[1.0, 0.0, 0.0], [3.0, 0.0, 0.0]])
        >>> np.allclose(chasles.se2_mean(g)[:2, 2], [2.0, 0.0])
        True""",
)
SIM3 = Group(
    "sim3",
    "Sim3",
    4,
    7,
    "similarity",
    "similarities",
    "4x4 matrices [[s R, t], [0, 1]], s > 0",
    "(v, w, sigma), s = exp(sigma) (Sophus' order)",
    "per part, the chordal mean of the rotations (as so3_mean), the\n"
    "    weighted geometric mean of the scales (the average of sigma = log s)\n"
    "    and the weighted average of the translations (left-invariant only;\n"
    "    not the Frobenius-nearest similarity, which weighs each rotation by\n"
    "    its scale)",
    """        >>> import chasles
        >>> g = chasles.sim3_exp([[0.0] * 6 + [0.1], [0.0] * 6 + [0.3]])
        >>> bool(np.isclose(np.cbrt(np.linalg.det(chasles.sim3_mean(g)[:3, :3])), np.exp(0.2)))
        True""",
)
SE23 = Group(
    "se23",
    "SE23",
    5,
    9,
    "extended pose",
    "extended poses",
    "5x5 matrices [[R, p, v], [0, 1, 0], [0, 0, 1]] (rotation, position, velocity)",
    "(rho, nu, w): position part, velocity part, rotation",
    "per part, the chordal mean of the rotations (as so3_mean) and the\n"
    "    weighted averages of the positions and of the velocities\n"
    "    (left-invariant only)",
    """        >>> import chasles
        >>> g = chasles.se23_exp([[1.0] + [0.0] * 8, [3.0] + [0.0] * 8])
        >>> np.allclose(chasles.se23_mean(g)[:3, 3], [2.0, 0.0, 0.0])
        True""",
)

GROUPS = (SO2, SE2, SIM3, SE23)
