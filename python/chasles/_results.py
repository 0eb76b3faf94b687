"""Result types of chasles' solvers."""

from __future__ import annotations

from typing import NamedTuple, Union

import numpy as np


class IKResult(NamedTuple):
    """The result of ``Chain.inverse_kinematics``: one solve, or a batch
    (arrays with the batch shape of the targets and seeds).

    Attributes:
        q: shape (n,) or (..., n): the configuration returned, within the joint limits.
        converged: bool (or bool array): |e_v| and |e_w| within their tolerances.
        status: str (or str array): why it stopped: "converged",
            "iteration_bound" (the last attempt ran max_iterations iterations),
            "time_budget" (max_time ran out first) or "no_progress" (a step
            below rounding: a local minimum of |e|).
        iterations: int (or int array): iterations of the attempt that gave q.
        total_iterations: int (or int array): iterations of every attempt.
        attempts: int (or int array): attempts made, 1 + the restarts taken.
        error: shape (6,) or (..., 6): the body error twist
            e = log(g(q)^-1 target), (v, w), in the tool frame.
    """

    q: np.ndarray
    converged: Union[bool, np.ndarray]
    status: Union[str, np.ndarray]
    iterations: Union[int, np.ndarray]
    total_iterations: Union[int, np.ndarray]
    attempts: Union[int, np.ndarray]
    error: np.ndarray
