"""Hypothesis strategies for chasles tests, shared by every test module
(conftest.py puts this directory on sys.path: ``from strategies import ...``).

Every strategy reaches the places where exp and log change branch, because
round trips at generic angles alone do not catch threshold bugs:

- angle 0 exactly, tiny angles (1e-300 to 1e-9) and both sides of the Taylor
  cutoff theta^2 = eps^(1/3) (theta = 2.46e-3 in double);
- pi/2 (where the so(3) log switches to the symmetric part);
- near pi (pi - 1e-6, pi - 1e-9, the float before pi) and exactly pi, about
  the coordinate axes (where the rotation vector is exactly (pi, 0, 0)) and
  about generic axes.
"""

from __future__ import annotations

import math

import numpy as np
from hypothesis import strategies as st

import chasles

PI = math.pi
TAYLOR_THETA = math.sqrt(6.0554544523933395e-06)  # the double cutoff, on theta

SPECIAL_ANGLES = (
    0.0,
    5e-324,
    1e-300,
    1e-12,
    1e-9,
    1e-6,
    math.nextafter(TAYLOR_THETA, 0.0),
    TAYLOR_THETA,
    math.nextafter(TAYLOR_THETA, 1.0),
    0.1,
    1.0,
    PI / 2 - 1e-9,
    PI / 2,
    PI / 2 + 1e-9,
    2.0,
    3.0,
    PI - 1e-6,
    PI - 1e-9,
    math.nextafter(PI, 0.0),
    PI,
)

COORDINATE_AXES = tuple(tuple(float(s * (i == j)) for j in range(3)) for i in range(3) for s in (1.0, -1.0))


def angles() -> st.SearchStrategy[float]:
    """Rotation angles in [0, pi]: the special ones, near pi, and uniform."""
    return st.one_of(
        st.sampled_from(SPECIAL_ANGLES),
        st.floats(PI - 1e-4, PI),
        st.floats(0.0, 1e-3),
        st.floats(0.0, PI),
    )


@st.composite
def unit_vectors(draw) -> np.ndarray:
    """Unit 3-vectors: the coordinate axes and generic directions."""
    if draw(st.booleans()):
        return np.array(draw(st.sampled_from(COORDINATE_AXES)))
    c = st.floats(-1.0, 1.0)
    u = np.array([draw(c), draw(c), draw(c)])
    n = float(np.linalg.norm(u))
    if n < 0.1:
        u, n = np.array([1.0, 1.0, 1.0]), math.sqrt(3.0)
    return u / n


@st.composite
def rotation_vectors(draw) -> np.ndarray:
    """w = axis * angle with |w| in [0, pi]; exactly (pi, 0, 0) and its kin included."""
    axis = draw(unit_vectors())
    theta = draw(angles())
    w = axis * theta
    if theta == PI and np.count_nonzero(axis) == 1:
        assert np.linalg.norm(w) == PI
    return w


def vectors3(scale: float = 10.0) -> st.SearchStrategy[np.ndarray]:
    """Finite 3-vectors in [-scale, scale]^3, zero and tiny entries included."""
    x = st.one_of(st.floats(-scale, scale), st.sampled_from((0.0, 1e-12, -1e-9, 1.0)))
    return st.tuples(x, x, x).map(np.array)


@st.composite
def twist_vectors(draw, scale: float = 10.0) -> np.ndarray:
    """xi = (v, w), linear part first, |w| in [0, pi] (so log(exp(xi)) = xi)."""
    return np.concatenate([draw(vectors3(scale)), draw(rotation_vectors())])


def wrench_vectors(scale: float = 10.0) -> st.SearchStrategy[np.ndarray]:
    """F = (f, tau), force first."""
    return st.tuples(vectors3(scale), vectors3(scale)).map(np.concatenate)


def so3s() -> st.SearchStrategy[chasles.SO3]:
    return rotation_vectors().map(chasles.SO3.exp)


def se3s(scale: float = 10.0) -> st.SearchStrategy[chasles.SE3]:
    return st.builds(lambda w, p: chasles.SE3(chasles.SO3.exp(w), p), rotation_vectors(), vectors3(scale))


def twists(scale: float = 10.0) -> st.SearchStrategy[chasles.Twist]:
    return twist_vectors(scale).map(chasles.Twist.from_vector)


def wrenches(scale: float = 10.0) -> st.SearchStrategy[chasles.Wrench]:
    return wrench_vectors(scale).map(chasles.Wrench.from_vector)


def elements(group) -> st.SearchStrategy:
    """Elements of chasles.SO3 or chasles.SE3."""
    return so3s() if group is chasles.SO3 else se3s()


def tangents(group) -> st.SearchStrategy[np.ndarray]:
    """Tangent vectors of chasles.SO3 (w) or chasles.SE3 ((v, w)), angle in [0, pi]."""
    return rotation_vectors() if group is chasles.SO3 else twist_vectors()


def points(scale: float = 10.0) -> st.SearchStrategy[np.ndarray]:
    return vectors3(scale)
