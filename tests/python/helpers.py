"""Reference formulas shared by the chasles Python tests, written from the
definitions with numpy alone, independent of the library (conftest.py puts
this directory on sys.path: ``from helpers import hat3, hat6``)."""

from __future__ import annotations

import numpy as np


def hat3(w) -> np.ndarray:
    """[w], the 3x3 skew matrix with [w] p = w x p."""
    return np.array([[0.0, -w[2], w[1]], [w[2], 0.0, -w[0]], [-w[1], w[0], 0.0]])


def hat6(xi) -> np.ndarray:
    """[xi] = [[ [w], v ], [0, 0]], the 4x4 matrix of a twist xi = (v, w)."""
    X = np.zeros((4, 4))
    X[:3, :3] = hat3(xi[3:])
    X[:3, 3] = xi[:3]
    return X
