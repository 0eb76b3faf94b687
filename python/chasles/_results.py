"""Result types of chasles' solvers."""

from __future__ import annotations

from typing import NamedTuple, Union

import numpy as np


class IKResult(NamedTuple):
    """The result of ``Chain.inverse_kinematics``: one solve, or a batch
    (arrays with the batch shape of the targets and seeds).

    Attributes:
        q: shape (n,) or (..., n): the last configuration, within the joint limits.
        converged: bool (or bool array): |e_v| and |e_w| within their tolerances.
        iterations: int (or int array): iterations taken, restarts included.
        error: shape (6,) or (..., 6): the body error twist
            e = log(g(q)^-1 target), (v, w), in the tool frame.
    """

    q: np.ndarray
    converged: Union[bool, np.ndarray]
    iterations: Union[int, np.ndarray]
    error: np.ndarray
