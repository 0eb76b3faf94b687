#!/usr/bin/env python3
"""The polynomials of exp's coefficients (include/chasles/detail/series.hpp,
ExpPolynomials): fits them and measures them.

    pip install mpmath numpy
    python tests/tools/fit_exp_polynomials.py           # fit, print C++ arrays and errors
    python tests/tools/fit_exp_polynomials.py --check   # the arrays in series.hpp: errors only

    A = sin(theta) / theta, B = (1 - cos(theta)) / theta^2, C = (theta - sin(theta)) / theta^3

Each is a polynomial in u = t - CENTER, t = theta^2, on t in [0, T] (T =
exp_polynomial_theta2 in constants.hpp, CENTER = exp_polynomial_center):
the near-minimax Chebyshev fit (mpmath.chebyfit, 50 digits) rounded to the
type. The error is measured as the C++ code evaluates the polynomial
(Estrin's scheme, in the type: numpy float32 or float64 scalars) against
40-digit values, at 6200 points: uniform on [0, T], random, and geometric
from 1e-12 to 1; both the absolute error and the error as it reaches the
rotation matrix (times theta for A, which multiplies [w]; times t for B and
C, which multiply [w]^2).
"""

from __future__ import annotations

import argparse
import re
from pathlib import Path

import mpmath as mp
import numpy as np

T = 10.0
CENTER = 7.0
SERIES = Path(__file__).resolve().parents[2] / "include" / "chasles" / "detail" / "series.hpp"
# A and B are evaluated side by side (two lanes of one vector), so they share a degree.
DEGREES = {"double": {"a": 10, "b": 10, "c": 9}, "float": {"a": 6, "b": 6, "c": 5}}
DTYPES = {"double": np.float64, "float": np.float32}


def f(name: str, t):
    """A, B or C at t, in mpmath."""
    t = mp.mpf(t)
    if t == 0:
        return {"a": mp.mpf(1), "b": mp.mpf(1) / 2, "c": mp.mpf(1) / 6}[name]
    th = mp.sqrt(t)
    return {"a": mp.sin(th) / th, "b": (1 - mp.cos(th)) / t, "c": (th - mp.sin(th)) / (th * t)}[name]


def fit(name: str, degree: int) -> list:
    mp.mp.dps = 50
    poly = mp.chebyfit(lambda u: f(name, u + CENTER), [-CENTER, T - CENTER], degree + 1)  # highest power first
    return list(poly[::-1])


def estrin(c: list, t):
    """series.hpp's polynomial(): pairs c[2i] + c[2i+1] x, x = t, t^2, t^4, ..."""
    v, x, n = list(c), t, len(c)
    while n > 1:
        for i in range(n // 2):
            v[i] = v[2 * i] + v[2 * i + 1] * x
        if n % 2:
            v[n // 2] = v[n - 1]
        if n > 2:
            x = x * x
        n = (n + 1) // 2
    return v[0]


def worst_errors(name: str, coefficients: list, dtype) -> tuple[float, float]:
    """The largest absolute error of the evaluation in dtype, and of it times
    theta (A) or t (B, C), in eps of dtype."""
    mp.mp.dps = 40
    c = [dtype(x) for x in coefficients]
    rng = np.random.default_rng(0)
    ts = np.concatenate([np.linspace(0, T, 3001), rng.uniform(0, T, 3000), np.geomspace(1e-12, 1, 200)])
    worst = reached = 0.0
    for t in ts.astype(dtype):
        e = float(abs(mp.mpf(float(estrin(c, t - dtype(CENTER)))) - f(name, float(t))))
        worst = max(worst, e)
        reached = max(reached, e * (float(np.sqrt(t)) if name == "a" else float(t)))
    eps = float(np.finfo(dtype).eps)
    return worst / eps, reached / eps


def committed(real: str, name: str) -> list:
    """The coefficients of A, B (the columns of ab) or C in series.hpp."""
    text = SERIES.read_text()
    block = text[text.index(f"struct ExpPolynomials<{real}> {{") :]
    if name == "c":
        values = re.search(r"\bc\[\] = \{(.*?)\};", block, re.S).group(1)
        return [float(x.strip().rstrip("f")) for x in values.split(",")]
    rows = re.search(r"\bab\[\]\[2\] = \{(.*?)\};", block, re.S).group(1)
    pairs = re.findall(r"\{([^{}]*)\}", rows)
    return [float(p.split(",")[0 if name == "a" else 1].strip().rstrip("f")) for p in pairs]


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--check", action="store_true", help="measure the arrays committed in series.hpp")
    args = ap.parse_args()
    for real, degrees in DEGREES.items():
        dtype = DTYPES[real]
        suffix = "f" if real == "float" else ""
        fitted = {}
        for name, degree in degrees.items():
            c = committed(real, name) if args.check else [float(dtype(float(x))) for x in fit(name, degree)]
            fitted[name] = c
            worst, reached = worst_errors(name, c, dtype)
            print(
                f"  {real} {name.upper()}: degree {len(c) - 1}, worst absolute error {worst:.2f} eps, "
                f"times {'theta' if name == 'a' else 't'}: {reached:.2f} eps"
            )
        if not args.check:
            pairs = ", ".join(f"{{{a!r}{suffix}, {b!r}{suffix}}}" for a, b in zip(fitted["a"], fitted["b"]))
            print(f"{real} ab[][2] = {{{pairs}}};")
            print(f"{real} c[] = {{" + ", ".join(f"{x!r}{suffix}" for x in fitted["c"]) + "};")


if __name__ == "__main__":
    main()
