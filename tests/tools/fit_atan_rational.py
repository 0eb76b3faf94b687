#!/usr/bin/env python3
"""The rational approximation of atan used by the SO(3) log
(include/chasles/detail/series.hpp, AtanRational; evaluated by detail::so3_log
in include/chasles/so3.hpp): fits it and measures it.

    pip install mpmath numpy
    python tests/tools/fit_atan_rational.py           # fit, print the C++ structs and errors
    python tests/tools/fit_atan_rational.py --check   # the arrays in series.hpp: errors only
    python tests/tools/fit_atan_rational.py --check --header PATH   # ... in another copy

The function is g(z) = atan(sqrt(z)) / sqrt(z) on z in [0, 1], written as

    g(z) = 1 - z h(z),   h(z) = (1 - g(z)) / z,   h(0) = 1/3,  h(1) = 1 - pi/4,

and it is h that is fitted: h(z) ~ P(z) / Q(z), P and Q both with N
coefficients (degree N - 1), lowest power first, normalized by Q(0) = 1.
The fit is the minimax one in relative error of h: a rational Remez
exchange in mpmath at 50 digits (the linear system on 2N reference points
with the level E, iterated in the E Q(x) term, then the 2N new extrema
between the zeros of the error), run until the extrema are level to 1e-6.
A relative error e of h is an error z h e of g, relative z h / g e, and
z h / g = 1 / g - 1 grows to 4/pi - 1 = 0.273 at z = 1. For each type N is
the smallest in 3..9 whose fit error of h times 0.273 is below 1% of the
type's eps (2^-52 for double, 2^-23 for float), unless --n-double /
--n-float say otherwise; the table of fit errors per N is printed, then the
coefficients rounded to each type as C++ structs, compared with the arrays
committed in the header. --check reads those arrays instead (each literal
rounded once to its type, as the compiler does).

so3_log has u_v2 = |u_v|^2 > 0 and u_w >= 0, both rounded values of the
type (u the unit-free quaternion, |u| up to about 16), and forms

    uw2   = u_w u_w
    acute = u_v2 < uw2                                   (theta < pi/2)
    A = acute ? u_v2 : uw2,  B = acute ? uw2 : u_v2      (A <= B, z = A / B)

and never z itself: homogeneous_estrin evaluates P and Q homogeneously by
Estrin's scheme on their N coefficients,

    v = coef;  X, Y = A, B;  n = N
    while n > 1:
        v[i] = v[2i] Y + v[2i+1] X      for 2i + 1 < n
        v[n/2] = v[n-1] Y               if n is odd (the odd one out, as if paired with a zero)
        X, Y = X X, Y Y                 if n > 2 (another level follows)
        n = (n + 1) / 2
    -> v[0] = B^(N'-1) P(A / B),  N' = N rounded up to a power of two    (p; and q, of Q)

and then, with PI the double literal of pi converted to the type,

    bq    = B q
    g2    = 2 (bq - A p)                          g2 / (2 bq) = g(A / B)
    n     = sqrt(u_v2)
    ratio = (acute ? g2 : u_w g2) / ((acute ? u_w : n) bq)
    f     = acute ? ratio : (PI - ratio) / n

acute: f = 2 atan(n / u_w) / n; obtuse: ratio = 2 atan(u_w / n) and f =
(pi - ratio) / n, the angle theta formed first and divided by n once.
Dividing PI and the rest by n apart erred more, pi / n being twice f just
past pi/2 (an earlier version of this script, its Estrin steps fused:
PI (1/n) - 2 u_w G / (u_v2 B q), G = bq - A p, gave a worst obtuse f of 2.65
eps in double, 2.47 with that difference one fused multiply-add, against
1.87 for this form); so did multiplying by a precomputed 1/n instead of
dividing by n (test_accuracy's SO3 log error went from 2.2 to 4.05 eps).
f is what the log uses (w = f u_v, theta^2 = f^2 u_v2); theta is taken
here as fl(f n).

This script mirrors that evaluation operation by operation in the type
(numpy float32 or float64 scalars), in two rounding modes for each x y + z
(the Estrin steps and bq - A p): "separate roundings (portable)", the
product rounded and then the sum, as the x86-64 baseline build (no FMA
instructions: the Python wheel and the portable benchmarks) computes it; and
"fused (contracted, -march=native)", the one rounding of the fused
multiply-add that GCC contracts it into, computed exactly with
fractions.Fraction and rounded once, correctly, to the type. Of the two
products of an Estrin step one is fused and the other rounded first: GCC
fuses the product it forms first, taken here to be v[2i+1] X (Eigen's
evaluators pass the two products to the sum as call arguments, which GCC on
x86-64 evaluates last to first); fusing v[2i] Y instead moved none of the
worst errors reported by more than 0.16 eps (measured on the committed arrays).

It measures f and theta against 40-digit values of f = 2 atan2(sqrt(u_v2),
u_w) / sqrt(u_v2) and theta = 2 atan2(sqrt(u_v2), u_w) from the rounded
inputs, at 20000 samples of the half angle theta / 2 (called h here and in
the report: not the h(z) above) and of |u| (log-uniform on [1, 16]; u_v2 =
(|u| sin h)^2 and u_w = |u| cos h, each rounded once; 12000, 4000, 2000 and
2000 in the four sets): h uniform on (0, pi/2]; h geometric from 1e-4 to
pi/4 (below about 1e-3 in double and 0.035 in float the log uses a series
instead); h within 1e-6 of pi/2, and u_w = 0; and h at pi/4, with u_v2
equal to uw2 and one ulp either side, and h within 1e-6 of pi/4. It
reports, per type, rounding mode and branch (acute or obtuse as each method
chooses it), the worst relative error of f and the worst absolute error of
theta, both in eps of the type, and the h where they occur. For comparison
it measures the libm method so3_log uses for the other real types, in the
type: n = sqrt(u_v2), a = atan(small / large) of n and u_w (numpy's arctan),
theta/2 = a or fl(PI/2 - a) past pi/4 (n >= u_w), f = (2 theta/2) / n; it
has no x y + z, so one measurement serves both modes. It also bounds the
intermediate values (exact arithmetic, |coef|, A = B, u_w^2 and u_v2 <= B)
for |u| <= 16 (B <= 256) and gives the largest B for which they stay below
the type's largest finite value.
"""

from __future__ import annotations

import argparse
import re
from fractions import Fraction
from pathlib import Path

import mpmath as mp
import numpy as np

SERIES = Path(__file__).resolve().parents[2] / "include" / "chasles" / "detail" / "series.hpp"
BUDGET = 0.01  # the fit error of g may be at most this fraction of the type's eps
GAIN = 4 / np.pi - 1  # the largest z h / g (at z = 1): scales h's relative error into g's
DTYPES = {"double": np.float64, "float": np.float32}
DIGITS = {"double": 17, "float": 9}
FIT_NS = range(3, 10)
U_RANGE = (1.0, 16.0)  # the values |u| takes
SAMPLES = {"uniform": 12000, "geometric": 4000, "pi": 2000, "pi/4": 2000}
H_GEOMETRIC = (1e-4, np.pi / 4)
NEAR = 1e-6  # how close to pi/2 (and pi/4) the "pi" (and "pi/4") samples come


# ---------------------------------------------------------------- the fit


def h(z):
    """(1 - atan(sqrt(z)) / sqrt(z)) / z, in mpmath; its series
    1/3 - z/5 + z^2/7 - ... near 0, where 1 - g would cancel."""
    z = mp.mpf(z)
    if z < mp.mpf(10) ** -4:
        r, term, k = mp.mpf(0), mp.mpf(1), 0
        while abs(term) > mp.eps * mp.mpf(10) ** -5:
            term = (-z) ** k / (2 * k + 3)
            r += term
            k += 1
        return r
    s = mp.sqrt(z)
    return (1 - mp.atan(s) / s) / z


def poly(c: list, z):
    """sum c[i] z^i, in mpmath."""
    r = mp.mpf(0)
    for x in reversed(c):
        r = r * z + x
    return r


def rel_error(p: list, q: list, z):
    """P(z) / Q(z) / h(z) - 1."""
    return poly(p, z) / (poly(q, z) * h(z)) - 1


def _level(ref: list, n: int) -> tuple[list, list]:
    """P, Q (Q(0) = 1) with P(x_i) / Q(x_i) = h(x_i) (1 + (-1)^i E) at the 2n
    reference points: linear in P, Q and E once E Q(x_i) takes the previous
    Q, iterated to a fixed point (E is tiny, so it converges at once)."""
    hs = [h(x) for x in ref]
    q_old = [mp.mpf(1)] * len(ref)
    e_old = mp.mpf(0)
    for _ in range(30):
        m = mp.matrix(2 * n, 2 * n)
        rhs = mp.matrix(2 * n, 1)
        for i, x in enumerate(ref):
            for k in range(n):
                m[i, k] = x**k
            for k in range(1, n):
                m[i, n - 1 + k] = -hs[i] * x**k
            m[i, 2 * n - 1] = -((-1) ** i) * hs[i] * q_old[i]
            rhs[i] = hs[i]
        sol = mp.lu_solve(m, rhs)
        p = [sol[k] for k in range(n)]
        q = [mp.mpf(1)] + [sol[n - 1 + k] for k in range(1, n)]
        e = sol[2 * n - 1]
        q_old = [poly(q, x) for x in ref]
        if abs(e - e_old) <= abs(e) * mp.mpf(10) ** -20:
            break
        e_old = e
    return p, q


def _argmax(f, a, b, iterations: int = 70):
    """The maximum of a unimodal f on [a, b], by golden-section search."""
    r = (mp.sqrt(5) - 1) / 2
    c, d = b - r * (b - a), a + r * (b - a)
    fc, fd = f(c), f(d)
    for _ in range(iterations):
        if fc > fd:
            b, d, fd = d, c, fc
            c = b - r * (b - a)
            fc = f(c)
        else:
            a, c, fc = c, d, fd
            d = a + r * (b - a)
            fd = f(d)
    return (a + b) / 2


def remez(n: int) -> tuple[list, list]:
    """The minimax P/Q (n coefficients each) of h on [0, 1] in relative error."""
    mp.mp.dps = 50
    m = 2 * n
    ref = [(1 - mp.cos(mp.pi * i / (m - 1))) / 2 for i in range(m)]  # Chebyshev extrema
    for _ in range(40):
        p, q = _level(ref, n)

        def err(z, p=p, q=q):
            return rel_error(p, q, z)

        zeros = [mp.findroot(err, (ref[i], ref[i + 1]), solver="anderson") for i in range(m - 1)]
        edges = [mp.mpf(0)] + zeros + [mp.mpf(1)]
        ref = []
        for i in range(m):
            candidates = [_argmax(lambda z: abs(err(z)), edges[i], edges[i + 1])]
            candidates += [edges[i]] if i == 0 else []
            candidates += [edges[i + 1]] if i == m - 1 else []
            ref.append(max(candidates, key=lambda z: abs(err(z))))
        levels = [abs(err(x)) for x in ref]
        if max(levels) / min(levels) - 1 < 1e-6:
            break
    return p, q


def fit_error(p: list, q: list) -> float:
    """max |P/Q / h - 1| on [0, 1] (exact arithmetic), at 2001 Chebyshev points
    and 200 geometric ones from 1e-12."""
    mp.mp.dps = 50
    zs = [(1 - mp.cos(mp.pi * i / 2000)) / 2 for i in range(2001)]
    zs += [mp.mpf(float(z)) for z in np.geomspace(1e-12, 1, 200)]
    return float(max(abs(rel_error(p, q, z)) for z in zs))


# ---------------------------------------------------------------- the type


MODES = {"separate": "separate roundings (portable)", "fused": "fused (contracted, -march=native)"}


def exact(x) -> Fraction:
    """x (Fraction, mpmath, numpy or Python number) as an exact fraction."""
    if isinstance(x, Fraction):
        return x
    if isinstance(x, mp.mpf):
        sign, man, exp, _ = x._mpf_
        return Fraction((-1) ** sign * man) * Fraction(2) ** exp
    return Fraction(float(x))


def to_type(x, dtype):
    """x rounded once, to nearest even, to dtype. float() of a Fraction rounds
    correctly to double; rounding that to float could round twice only when
    it landed on a float midpoint, which is then settled by the exact value."""
    x = exact(x)
    y = float(x)
    r = dtype(y)
    if dtype is np.float64 or Fraction(y) == x or float(r) == y:
        return r
    other = np.nextafter(r, dtype(np.inf) if float(r) < y else dtype(-np.inf))
    if (exact(r) + exact(other)) / 2 == Fraction(y) and (x > Fraction(y)) == (float(other) > y):
        return other
    return r


def mul_add(x, y, t, dtype, fused: bool):
    """x y + t in dtype: rounded once (a fused multiply-add), or x y rounded and then the sum."""
    return to_type(exact(x) * exact(y) + exact(t), dtype) if fused else x * y + t


def homogeneous_estrin(c: list, a, b, dtype, fused: bool):
    """series.hpp's homogeneous_estrin with X = a, Y = b: B^(N'-1) P(A / B);
    and the largest |v|, |X|, |Y| it forms. v[2i] Y + v[2i+1] X is
    mul_add(v[2i+1], X, v[2i] Y): fused, v[2i+1] X is the product fused."""
    v = list(c)
    x, y = a, b
    biggest = max(abs(float(a)), abs(float(b)))
    n = len(v)
    while n > 1:
        for i in range(n // 2):
            v[i] = mul_add(v[2 * i + 1], x, v[2 * i] * y, dtype, fused)
        if n % 2 == 1:
            v[n // 2] = v[n - 1] * y
        biggest = max([biggest] + [abs(float(t)) for t in v[: (n + 1) // 2]])
        if n > 2:
            x, y = x * x, y * y
            biggest = max(biggest, abs(float(x)), abs(float(y)))
        n = (n + 1) // 2
    return v[0], biggest


def rational(p: list, q: list, uv2, uw, dtype, fused: bool) -> dict:
    """so3_log's f from u_v2 and u_w: the branch, f, and the largest intermediate."""
    uw2 = uw * uw
    acute = bool(uv2 < uw2)
    a, b = (uv2, uw2) if acute else (uw2, uv2)
    pv, top_p = homogeneous_estrin(p, a, b, dtype, fused)
    qv, top_q = homogeneous_estrin(q, a, b, dtype, fused)
    bq = b * qv
    g2 = dtype(2) * mul_add(-a, pv, bq, dtype, fused)
    n = np.sqrt(uv2)
    num, den = (g2, uw * bq) if acute else (uw * g2, n * bq)
    ratio = num / den
    f = ratio if acute else (PI[dtype] - ratio) / n
    terms = [bq, g2, num, den] + ([] if fused else [a * pv])
    return {"acute": acute, "f": f, "biggest": max([top_p, top_q] + [abs(float(t)) for t in terms])}


def libm(uv2, uw, dtype) -> dict:
    """so3_log's libm method: theta/2 = atan(small / large) or PI/2 minus it."""
    n = np.sqrt(uv2)
    acute = bool(n < uw)
    small, large = (n, uw) if acute else (uw, n)
    a = np.arctan(small / large)
    half = a if acute else HALF_PI[dtype] - a
    return {"acute": acute, "f": (dtype(2) * half) / n}


# so3.hpp's Scalar(3.14159265358979323846) and Scalar(0.5 * 3.14159265358979323846): double literals
PI = {dtype: dtype(3.14159265358979323846) for dtype in DTYPES.values()}
HALF_PI = {dtype: dtype(0.5 * 3.14159265358979323846) for dtype in DTYPES.values()}


def samples(dtype) -> list:
    """(u_v2, u_w, set) in dtype, u_v2 > 0, u_w >= 0, from h and |u| log-uniform
    on U_RANGE: h uniform on (0, pi/2], geometric on H_GEOMETRIC, within NEAR
    of pi/2 (and u_w = 0), and at pi/4 (u_v2 = uw2, one ulp either side, and
    within NEAR)."""
    mp.mp.dps = 40
    rng = np.random.default_rng(0)
    counts = SAMPLES
    lo, hi = np.log(U_RANGE[0]), np.log(U_RANGE[1])
    us = np.exp(rng.uniform(lo, hi, sum(counts.values())))
    us[:2] = U_RANGE  # the ends of the range
    us = iter(us)
    half_pi, quarter_pi = mp.pi / 2, mp.pi / 4
    hs = [("uniform", mp.mpf(float(x))) for x in rng.uniform(0, np.pi / 2, counts["uniform"] - 1)]
    hs += [("uniform", half_pi)]
    hs += [("geometric", mp.mpf(float(x))) for x in np.geomspace(*H_GEOMETRIC, counts["geometric"])]
    k = counts["pi"] // 10  # u_w = 0
    m = (counts["pi"] - k) // 2
    ds = list(rng.uniform(0, NEAR, m)) + list(np.geomspace(1e-30, NEAR, counts["pi"] - k - m))
    hs += [("pi", half_pi - mp.mpf(float(d))) for d in ds] + [("pi", None)] * k
    m = counts["pi/4"] // 4
    ds = rng.uniform(-NEAR, NEAR, counts["pi/4"] - 3 * m)
    hs += [("pi/4", quarter_pi + mp.mpf(float(d))) for d in ds]
    hs += [("pi/4", step) for step in (-1, 0, 1) for _ in range(m)]
    out = []
    for name, x in hs:
        u = mp.mpf(float(next(us)))
        if x is None:  # u_w = 0 exactly
            uv2, uw = to_type(u * u, dtype), dtype(0)
        elif name == "pi/4" and not isinstance(x, mp.mpf):  # u_v2 = uw2 + x ulp
            uw = to_type(u * mp.cos(quarter_pi), dtype)
            uv2 = uw * uw
            for _ in range(abs(x)):
                uv2 = np.nextafter(uv2, dtype(np.inf) if x > 0 else dtype(0))
        else:
            uv2, uw = to_type((u * mp.sin(x)) ** 2, dtype), to_type(u * mp.cos(x), dtype)
        if uv2 > 0:
            out.append((uv2, uw, name))
    return out


def where(half, name: str) -> str:
    """The half angle h (as pi/2 - d near pi/2) and its sample set."""
    d = mp.pi / 2 - half
    at = f"h = pi/2 - {float(d):.3g}" if d < 1e-3 else f"h = {float(half):.9g}"
    return f"{at} ({name})"


def measure(p: list, q: list, dtype) -> dict:
    """The worst relative error of f and absolute error of theta = f n, in eps
    of dtype, per method (the rational one in each rounding mode, libm) and
    branch, with where they occur; the largest intermediate of the rational one."""
    p = [dtype(x) for x in p]
    q = [dtype(x) for x in q]
    eps = float(np.finfo(dtype).eps)
    pts = samples(dtype)
    mp.mp.dps = 40
    methods = list(MODES) + ["libm"]
    keys = [(m, b, k) for m in methods for b in ("acute", "obtuse") for k in ("f", "theta")]
    worst = dict.fromkeys(keys, (0.0, ""))
    biggest = 0.0
    with np.errstate(over="raise", invalid="raise", divide="raise"):
        for uv2, uw, name in pts:
            s = mp.sqrt(exact(uv2))
            half = mp.atan2(s, exact(uw))
            f_true, theta_true = 2 * half / s, 2 * half
            got = {}
            for mode in MODES:
                r = rational(p, q, uv2, uw, dtype, fused=mode == "fused")
                biggest = max(biggest, r["biggest"])
                got[mode] = (r["acute"], r["f"])
            c = libm(uv2, uw, dtype)
            got["libm"] = (c["acute"], c["f"])
            n = np.sqrt(uv2)
            for m, (acute, f) in got.items():
                branch = "acute" if acute else "obtuse"
                errors = {
                    "f": float(abs(exact(f) / f_true - 1)) / eps,
                    "theta": float(abs(exact(f * n) - theta_true)) / eps,
                }
                for k, e in errors.items():
                    if e > worst[(m, branch, k)][0]:
                        worst[(m, branch, k)] = (e, where(half, name))
    return {"methods": methods, "worst": worst, "biggest": biggest, "samples": len(pts)}


def intermediate_bound(p: list, q: list, b2) -> float:
    """The largest magnitude the rational method forms for any A <= B = b2
    (exact arithmetic: |coef| and A = B bound every Estrin term; u_w^2 and
    u_v2 <= B): |v|, |X|, |Y|, B q, A p, |g2|, u_w |g2|, u_w B q, n B q."""
    mp.mp.dps = 50
    b2 = mp.mpf(b2)
    worst = b2
    tops = []
    for c in (p, q):
        v = [abs(mp.mpf(float(x))) for x in c]
        x = b2  # X = Y = B
        n = len(v)
        while n > 1:
            odd = [v[n - 1] * x] if n % 2 == 1 else []
            v = [(v[2 * i] + v[2 * i + 1]) * x for i in range(n // 2)] + odd
            worst = max([worst] + v)
            if n > 2:
                x = x * x
                worst = max(worst, x)
            n = (n + 1) // 2
        tops.append(v[0])
    pt, qt = tops
    bq, ap = b2 * qt, b2 * pt
    g2 = 2 * (bq + ap)
    return max(worst, bq, ap, g2, mp.sqrt(b2) * g2, mp.sqrt(b2) * bq)


def safe_b2(p: list, q: list, dtype) -> float:
    """The largest B whose intermediates stay below the largest finite dtype."""
    top = mp.mpf(float(np.finfo(dtype).max))
    lo, hi = mp.mpf(1), mp.mpf(2) ** 1200
    for _ in range(200):
        mid = mp.sqrt(lo * hi)
        lo, hi = (mid, hi) if intermediate_bound(p, q, mid) <= top else (lo, mid)
    return float(lo)


# ---------------------------------------------------------------- C++


def literal(x: float, real: str) -> str:
    s = f"{x:.{DIGITS[real]}g}"
    if not any(ch in s for ch in ".en"):
        s += ".0"
    return s + ("f" if real == "float" else "")


def cpp_struct(real: str, p: list, q: list) -> str:
    """The struct as series.hpp has it, one value a line (clang-format packs them)."""
    lines = ["template <>", f"struct AtanRational<{real}> {{", "  static constexpr bool available = true;"]
    for name, c in (("p", p), ("q", q)):
        head = f"  static constexpr {real} {name}[] = {{"
        body = (",\n" + " " * len(head)).join(literal(x, real) for x in c)
        lines.append(head + body + "};")
    lines.append("};")
    return "\n".join(lines)


def committed(real: str, header: Path) -> tuple[list, list]:
    """p and q of AtanRational<real> in header, as the compiler reads them
    (each decimal literal, any number a line, rounded once to the type)."""
    text = header.read_text()
    start = text.find(f"struct AtanRational<{real}> {{")
    if start < 0:
        raise SystemExit(f"{header} has no struct AtanRational<{real}>: pass --header")
    block = text[start : text.find("\n};", start)]

    def array(name):
        found = re.search(rf"\b{name}\[\]\s*=\s*\{{(.*?)\}};", block, re.S)
        if found is None:
            raise SystemExit(f"{header}: AtanRational<{real}> has no array {name}[]")
        values = [x.strip() for x in found.group(1).split(",") if x.strip()]
        suffix = "f" if real == "float" else ""
        for x in values:
            if not re.fullmatch(rf"[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?{suffix}", x):
                raise SystemExit(f"{header}: AtanRational<{real}>::{name}[]: not a {real} literal: {x}")
        return [float(to_type(Fraction(x.removesuffix(suffix)), DTYPES[real])) for x in values]

    p, q = array("p"), array("q")
    if len(p) != len(q):
        raise SystemExit(f"{header}: AtanRational<{real}> has {len(p)} p and {len(q)} q")
    return p, q


# ---------------------------------------------------------------- main


def report(real: str, p: list, q: list) -> None:
    dtype = DTYPES[real]
    n = len(p)
    e = fit_error([mp.mpf(x) for x in p], [mp.mpf(x) for x in q])
    eps = float(np.finfo(dtype).eps)
    print(
        f"{real}: N = {n} (N' = {1 << (n - 1).bit_length()}), fit error of h with the "
        f"coefficients in {real}: {e:.3g}, of g at most {e * GAIN:.3g} "
        f"= {e * GAIN / eps:.2g} eps"
    )
    m = measure(p, q, dtype)
    print(
        f"  worst errors in eps of {real} over {m['samples']} samples "
        f"(f relative, theta = f n absolute; branch as each method chooses it):"
    )
    for method in m["methods"]:
        print(f"    {MODES.get(method, 'libm atan (for comparison)')}:")
        for branch in ("acute", "obtuse"):
            ef, wf = m["worst"][(method, branch, "f")]
            et, wt = m["worst"][(method, branch, "theta")]
            print(f"      {branch:6s}  f {ef:5.2f} at {wf};  theta {et:5.2f} at {wt}")
    top = float(np.finfo(dtype).max)
    b2_max = U_RANGE[1] ** 2
    safe = safe_b2(p, q, dtype)
    bound = float(intermediate_bound(p, q, b2_max))
    print(
        f"  largest intermediate over the samples {m['biggest']:.3g}; bound for B <= {b2_max:g} "
        f"(|u| <= {U_RANGE[1]:g}): {bound:.3g}; finite in {real} for B <= {safe:.4g} "
        f"(|u| <= {np.sqrt(safe):.4g}; the largest finite {real} is {top:.4g})"
    )


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--check", action="store_true", help="measure the arrays committed in the header")
    ap.add_argument("--header", type=Path, default=SERIES, help="the header to read (default: series.hpp)")
    for real in DTYPES:
        ap.add_argument(f"--n-{real}", type=int, help=f"N for {real} (default: the smallest fitting g to 1%% of eps)")
    args = ap.parse_args()
    if args.check:
        for real in DTYPES:
            report(real, *committed(real, args.header))
        return
    eps = {real: float(np.finfo(dtype).eps) for real, dtype in DTYPES.items()}
    fits, errors = {}, {}
    print(f"N   fit error of h (relative, exact coefficients); times {GAIN:.4f} (the largest z h / g) = of g")
    for n in FIT_NS:
        fits[n] = remez(n)
        errors[n] = fit_error(*fits[n])
        e = errors[n] * GAIN
        print(
            f"{n:<3d} {errors[n]:.3e}   of g {e:.3e} = {e / eps['double']:.2e} double eps, "
            f"{e / eps['float']:.2e} float eps"
        )
    chosen = {"double": args.n_double, "float": args.n_float}
    for real in DTYPES:
        if chosen[real] is None:
            chosen[real] = next(n for n in FIT_NS if errors[n] * GAIN < BUDGET * eps[real])
        if chosen[real] not in fits:
            fits[chosen[real]] = remez(chosen[real])
            errors[chosen[real]] = fit_error(*fits[chosen[real]])
        print(
            f"{real}: N = {chosen[real]} (fit error of g {errors[chosen[real]] * GAIN:.3g}, "
            f"budget {BUDGET:g} eps = {BUDGET * eps[real]:.3g})"
        )
    print()
    rounded = {}
    for real, dtype in DTYPES.items():
        p, q = fits[chosen[real]]
        rounded[real] = tuple([float(to_type(x, dtype)) for x in c] for c in (p, q))
        print(cpp_struct(real, *rounded[real]))
        same = "no struct there"
        if f"struct AtanRational<{real}> {{" in args.header.read_text():
            same = "equal" if committed(real, args.header) == rounded[real] else "NOT equal"
        print(f"// {same} to the arrays committed in {args.header}")
        print()
    for real in DTYPES:
        report(real, *rounded[real])


if __name__ == "__main__":
    main()
