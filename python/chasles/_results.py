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
            "time_budget" (max_time ran out first) or "no_progress" (stalled
            at a local minimum of |e|: its step below rounding, or, when a
            restart followed, |e|^2 above 0.9 of its value 8 iterations
            before).
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


class TimeScalingResult(NamedTuple):
    """The result of ``time_scaling``: the path parameter and its time
    derivatives, each of the broadcast shape of the times and durations
    (a numpy float64 when all are scalars).

    Attributes:
        s: the path parameter s(t) in [0, 1]: 0 at and before t = 0, 1 at
            and after t = duration.
        s_dot: ds/dt, per unit of time.
        s_ddot: d^2s/dt^2, per unit of time squared.
    """

    s: Union[float, np.ndarray]
    s_dot: Union[float, np.ndarray]
    s_ddot: Union[float, np.ndarray]


class JointTrajectoryResult(NamedTuple):
    """The result of ``joint_trajectory``: joint positions, velocities and
    accelerations, each of shape (..., n), the batch shape (...) the
    broadcast of the times' and the joint vectors' leading axes.

    Attributes:
        q: the joint positions q_start + s (q_end - q_start).
        qd: the joint velocities s_dot (q_end - q_start).
        qdd: the joint accelerations s_ddot (q_end - q_start).
    """

    q: np.ndarray
    qd: np.ndarray
    qdd: np.ndarray
