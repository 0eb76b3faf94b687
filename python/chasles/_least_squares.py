"""Levenberg-Marquardt over group elements, shared by ``PoseGraph.solve`` and
the B-splines' ``fit`` (with the check of their information matrices): the caller gives the cost (chi2), the whitened
residuals and their sparse Jacobian at a state, and how a step moves the
state (X_i <- X_i exp(dx_i), right-local as every Jacobian of the library).
Each iteration solves the damped normal equations

    (J^T J + lambda diag(J^T J)) dx = -J^T r

with scipy's sparse LU (symmetric mode, minimum degree ordering); a step
that lowers chi2 is taken and lambda shrinks tenfold, else lambda grows
tenfold. It stops when a step lowers chi2 by less than ``tolerance``
relative, or by less than the rounding of the initial chi2 (eps times it:
data that the model fits exactly) (converged), when no step lowers it any more (lambda past 1e12:
a minimum to working precision, converged), or after ``max_iterations``.
"""

from __future__ import annotations

import math
from typing import Any, Callable

import numpy as np


def levenberg_marquardt(
    x: np.ndarray,
    cost: Callable[[np.ndarray], float],
    linearize: Callable[[np.ndarray], tuple[np.ndarray, Any]],
    step: Callable[[np.ndarray, np.ndarray], np.ndarray],
    *,
    max_iterations: int,
    tolerance: float,
    singular: str,
) -> tuple[np.ndarray, float, float, int, bool]:
    """(x, initial chi2, final chi2, iterations, converged) from the state x.

    ``linearize(x)`` returns the whitened residuals r (m,) and their Jacobian
    J (a scipy.sparse (m, n) matrix); ``step(x, dx)`` the moved state for the
    (n,) step dx. A singular system raises ValueError(``singular``).
    """
    import scipy.sparse as sparse

    chi2 = initial = cost(x)
    lam, converged, iterations = 1e-4, False, 0
    r, J = linearize(x)
    H, g = (J.T @ J).tocsc(), J.T @ r
    while iterations < max_iterations:
        iterations += 1
        lu = splu((H + sparse.diags(lam * np.maximum(H.diagonal(), 1e-12))).tocsc(), singular)
        trial = step(x, lu.solve(-g))
        new = cost(trial)
        if new < chi2:
            # relative to chi2, or, as chi2 nears 0 (data the model fits
            # exactly), to the rounding of the start's chi2
            small = chi2 - new < max(tolerance * chi2, np.finfo(float).eps * initial)
            x, chi2, lam = trial, new, max(lam / 10, 1e-12)
            if small:
                converged = True
                break
            r, J = linearize(x)
            H, g = (J.T @ J).tocsc(), J.T @ r
        else:
            lam *= 10
            if lam > 1e12:
                converged = True  # no step lowers chi2: a minimum to working precision
                break
    return x, initial, chi2, iterations, converged


def splu(H: Any, singular: str) -> Any:
    """SuperLU's factorization of the positive (semi)definite H in symmetric
    mode (the minimum degree ordering of H, no pivoting): 0.13 s for
    sphere2500's 15000 unknowns, where spsolve's default (COLAMD, pivoting)
    takes 0.55 s. An exactly singular H raises ValueError(``singular``)."""
    import scipy.sparse.linalg as linalg

    try:
        return linalg.splu(H, permc_spec="MMD_AT_PLUS_A", diag_pivot_thresh=0.0, options={"SymmetricMode": True})
    except RuntimeError:  # SuperLU: "Factor is exactly singular"
        raise ValueError(singular) from None


def information_factor(omega: np.ndarray, what: str) -> np.ndarray:
    """L with L L^T = Omega for each information matrix of omega (..., d, d),
    or the ValueError of one that is not symmetric positive definite, naming `what`."""
    if omega.size and np.abs(omega - np.swapaxes(omega, -1, -2)).max() > 1e-9 * np.abs(omega).max():
        raise ValueError(f"{what}: expected symmetric matrices")
    try:
        return np.linalg.cholesky(omega)
    except np.linalg.LinAlgError:
        raise ValueError(f"{what}: expected positive definite matrices") from None


def check_iterations(max_iterations: Any, tolerance: Any, where: str) -> tuple[int, float]:
    """max_iterations and tolerance as an int and a float, or the TypeError /
    ValueError of bad ones, naming `where` (an int tolerance too large for a
    float is +inf: any step ends the solve)."""
    if isinstance(max_iterations, (bool, np.bool_)) or not isinstance(max_iterations, (int, np.integer)):
        raise TypeError(f"{where}(max_iterations): expected an int, got {type(max_iterations).__name__}")
    if max_iterations < 1:
        raise ValueError(f"{where}(max_iterations): expected an int >= 1, got {max_iterations}")
    if isinstance(tolerance, (bool, np.bool_)) or not isinstance(tolerance, (int, float, np.integer, np.floating)):
        raise TypeError(f"{where}(tolerance): expected a float, got {type(tolerance).__name__}")
    if not tolerance >= 0:
        raise ValueError(f"{where}(tolerance): expected a float >= 0, got {tolerance!r}")
    try:
        return int(max_iterations), float(tolerance)
    except OverflowError:
        return int(max_iterations), math.inf


def import_scipy(where: str) -> None:
    """An ImportError that says how to install scipy, when it is missing."""
    try:
        import scipy.sparse.linalg  # noqa: F401
    except ImportError:  # pragma: no cover - scipy is installed with the tests
        raise ImportError(f"{where} needs scipy: pip install chasles[estimation]") from None
