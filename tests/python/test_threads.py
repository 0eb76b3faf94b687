"""Threads: every array function (and the objects' actions on many points,
which also run without the GIL) gives, from 8 threads at once on shared
read-only input, results bit-identical to a single thread; and releases the
GIL, so that other Python threads run during a long call.

How the GIL test can tell: a counter thread increments a Python integer
and hands the GIL back after every step (time.sleep(0)), and the switch
interval is raised to 100 s, so that the interpreter never takes the GIL
from the thread that holds it. The counter can then advance only while the
main thread has let go of the GIL, i.e. only inside a call that released
it. The same measurement around a call that keeps the GIL (sum(range(n)),
as long as the library call) must read exactly 0: that is checked first,
so a broken measurement fails rather than passes.
"""

from __future__ import annotations

import os
import subprocess
import sys
import threading
import time

import api_spec as A
import numpy as np
import pytest

import chasles
from chasles import _core

ARRAY_FUNCTIONS = A.ARRAY_FUNCTIONS

# A 6-joint arm: its screws as rows (v, w), unit axes.
ARM_SCREWS = np.array(
    [
        [0.0, 0.0, 0.0, 0.0, 0.0, 1.0],
        [-0.089, 0.0, 0.0, 0.0, 1.0, 0.0],
        [-0.089, 0.0, 0.425, 0.0, 1.0, 0.0],
        [-0.089, 0.0, 0.817, 0.0, 1.0, 0.0],
        [-0.109, 0.817, 0.0, 0.0, 0.0, -1.0],
        [0.006, 0.0, 0.817, 0.0, 1.0, 0.0],
    ]
)


def test_the_array_functions_are_all_here():
    prefixes = ("so2_", "se2_", "so3_", "se3_", "sim3_", "se23_")
    # the samplers, the means and the alignments take a size, a generator or a reduction axis:
    # Python functions over the ufuncs / C++, not array functions themselves
    not_ufuncs = {
        *(f"{g}_{f}" for g in ("so2", "se2", "so3", "se3", "sim3", "se23") for f in ("random", "gaussian", "mean")),
        "so3_align",
        "se3_align",
        "sim3_align",
    }
    public = sorted(n for n in chasles.__all__ if n.startswith(prefixes) and n not in not_ufuncs)
    assert ARRAY_FUNCTIONS == public and len(public) == 110


def as_bytes(result) -> bytes:
    """A call's result as bytes (the results of a gufunc of several, joined)."""
    return b"".join(r.tobytes() for r in result) if isinstance(result, tuple) else result.tobytes()


def operand(arg: A.Operand, shape, rng, dtype):
    """A.sample_operand, shared and read-only."""
    x = A.sample_operand(arg, shape, rng, dtype)
    x.flags.writeable = False
    return x


def calls(n, rng):
    """(label, function, args) for every array function in float64 and
    float32, and the objects' actions on n points."""
    out = []
    for name in ARRAY_FUNCTIONS:
        entry = A.SPEC[name]
        for dtype in (np.float64, np.float32):
            args = [
                operand(a, (n,), rng, dtype)
                if isinstance(a, A.Operand)
                else (a.good() if isinstance(a, A.Sequence) else True)
                for a in entry.signatures[0]
            ]
            out.append((f"{name} {np.dtype(dtype).name}", entry.call, args))
    points = rng.normal(size=(n, 3))
    points.flags.writeable = False
    g = chasles.SE3.exp(rng.normal(size=6))
    out += [
        ("SE3.act", chasles.SE3.act, [g, points]),
        ("SE3.act_inv", chasles.SE3.act_inv, [g, points]),
        ("SO3.act", chasles.SO3.act, [g.rotation, points]),
    ]
    # A 6-joint arm and n joint configurations.
    arm = chasles.Chain(ARM_SCREWS, np.eye(4))
    thetas = rng.uniform(-np.pi, np.pi, size=(n, 6))
    thetas.flags.writeable = False
    for method in ("forward", "forward_body", "jacobian_space", "jacobian_body"):
        out.append((f"Chain.{method}", getattr(chasles.Chain, method), [arm, thetas]))
    # The B-splines' evaluation at n times (one C++ loop without the GIL).
    times = rng.uniform(0.0, 1.0, size=n)
    times.flags.writeable = False
    for cls in A.BSPLINES:
        spline = A.GOOD[cls]()
        for method in ("__call__", "body_velocity", "body_acceleration"):
            out.append((f"{cls.__name__}.{method}", getattr(cls, method), [spline, times]))
    return out


def test_eight_threads_give_bit_identical_results():
    rng = np.random.default_rng(5)
    work = calls(6_000, rng)  # above the GIL threshold of every call (500 and 4096 elements)
    reference = [as_bytes(f(*args)) for _, f, args in work]
    n_threads, rounds = 8, 3
    barrier = threading.Barrier(n_threads)
    results = [[] for _ in range(n_threads)]
    errors = []

    def worker(k):
        try:
            barrier.wait()
            for r in range(rounds):
                order = work if (k + r) % 2 == 0 else work[::-1]  # not in lockstep
                results[k].append({label: as_bytes(f(*args)) for label, f, args in order})
        except BaseException as e:  # noqa: BLE001 - reported below
            errors.append(e)

    threads = [threading.Thread(target=worker, args=(k,)) for k in range(n_threads)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert not errors, errors
    for k in range(n_threads):
        assert len(results[k]) == rounds
        for got in results[k]:
            for (label, _, _), want in zip(work, reference):
                assert got[label] == want, f"thread {k}: {label} differs from the single-threaded result"


# ---- the GIL ---------------------------------------------------------------------------


class Counter:
    """A thread that counts while it can get the GIL, handing it back after
    every step; the switch interval is raised so that it never gets the GIL
    by preemption."""

    def __init__(self):
        self.count = 0
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._run, daemon=True)

    def _run(self):
        while not self._stop.is_set():
            self.count += 1
            time.sleep(0)

    def __enter__(self):
        self._old = sys.getswitchinterval()
        sys.setswitchinterval(100.0)
        self._thread.start()
        while self.count == 0:  # running
            time.sleep(0.001)
        return self

    def __exit__(self, *exc):
        self._stop.set()
        sys.setswitchinterval(self._old)
        self._thread.join()

    def steps_during(self, call):
        """How far the counter advances while call() runs, and how long it takes."""
        time.sleep(0.002)  # the counter runs here, then waits for the GIL
        start, before = time.perf_counter(), self.count
        call()
        steps, seconds = self.count - before, time.perf_counter() - start
        return steps, seconds


_RATE = []


def holds_the_gil_for(seconds):
    """A call that keeps the GIL about that long: pure bytecode, sum(range(n))
    with n from a measured rate."""
    if not _RATE:
        start = time.perf_counter()
        sum(range(1_000_000))
        _RATE.append(1_000_000 / max(time.perf_counter() - start, 1e-6))
    n = max(1000, int(seconds * _RATE[0]))
    return lambda: sum(range(n))


def steps_while_releasing(counter, call, enough=1, attempts=5):
    """The most steps the counter makes during call(), over up to `attempts`
    measurements (until one reaches `enough`): a loaded machine that does not
    schedule the counter in time gets another chance, each one 4 times longer
    (1, 4, 16, ... calls in a row: a call of 50,000 elements lasts about a
    millisecond, less than a loaded machine may take to schedule the counter;
    between the calls the GIL stays with this thread, switchinterval 100 s).
    The control: a call of the same length that keeps the GIL must see
    exactly 0 steps."""
    best, seconds = 0, 0.0
    for attempt in range(attempts):
        repeats = 4**attempt

        def repeated(call=call, repeats=repeats):
            for _ in range(repeats):
                call()

        steps, seconds = counter.steps_during(repeated)
        control, _ = counter.steps_during(holds_the_gil_for(seconds))
        assert control == 0, f"the measurement is broken: {control} steps while the GIL was held"
        best = max(best, steps)
        if best >= enough:
            break
    return best, seconds


@pytest.mark.parametrize(
    "label,call",
    [(label, (f, args)) for label, f, args in calls(50_000, np.random.default_rng(6))],
    ids=lambda x: x if isinstance(x, str) else "",
)
def test_every_array_call_releases_the_gil(label, call):
    f, args = call
    with Counter() as counter:
        steps, _ = steps_while_releasing(counter, lambda: f(*args))
    assert steps > 0, f"{label}: no other thread ran during the call"


def test_a_long_call_lets_another_thread_run_all_along():
    """so3_log on 4e6 rotations (0.15 to 0.3 s here; a stride-0 view: no
    input memory; 48 MB out in float32): the counter makes at least a tenth
    of the steps it makes in a sleep as long (2000 to 4000 steps here), and
    at least 100, i.e. it runs throughout the call, not once at its start or
    end."""
    R = np.broadcast_to(chasles.so3_exp(np.array([0.1, -2.0, 0.3], np.float32)), (4_000_000, 3, 3))
    with Counter() as counter:
        steps = baseline = seconds = 0
        for _ in range(5):
            got, seconds = steps_while_releasing(counter, lambda: chasles.so3_log(R), attempts=1)
            # The free-running rate of the counter, over a GIL-free wait as long.
            baseline, _ = counter.steps_during(lambda s=seconds: time.sleep(s))
            steps = max(steps, got)
            if steps >= max(100, baseline / 10):
                break
    assert steps >= max(100, baseline / 10), f"{steps} steps in {seconds:.3f} s; in a sleep as long: {baseline}"


# ---- set_num_threads: a large batch split across threads inside the loop --------------

ELEMENTWISE_GRAIN, MODEL_GRAIN = 1 << 14, 1 << 9  # bindings/parallel.hpp


@pytest.fixture
def set_threads():
    """chasles.set_num_threads, the count restored after the test."""
    before = chasles.get_num_threads()
    yield chasles.set_num_threads
    chasles.set_num_threads(before)


def test_split_batches_are_bit_identical_and_start_threads(set_threads):
    """Every array function, the objects' actions, Chain's kinematics and the
    B-splines on 2 grains + 3 elements (uneven ranges), on 1, 2, 3 and 7
    threads: the same bytes, and threads were started."""
    work = calls(2 * ELEMENTWISE_GRAIN + 3, np.random.default_rng(7))
    set_threads(1)
    started = _core._threads_started()
    reference = [as_bytes(f(*args)) for _, f, args in work]
    assert _core._threads_started() == started  # one thread: none started
    for n in (2, 3, 7):
        set_threads(n)
        for (label, f, args), want in zip(work, reference):
            before = _core._threads_started()
            assert as_bytes(f(*args)) == want, f"{label} on {n} threads"
            assert _core._threads_started() > before, f"{label}: no thread started on {n}"


def test_a_batch_below_two_grains_starts_no_thread(set_threads):
    set_threads(2)
    for size, grain in ((2 * ELEMENTWISE_GRAIN - 1, ELEMENTWISE_GRAIN), (2 * MODEL_GRAIN - 1, MODEL_GRAIN)):
        w = np.zeros((size, 3))
        before = _core._threads_started()
        if grain == ELEMENTWISE_GRAIN:
            chasles.so3_exp(w)
        else:
            chasles.Chain(np.array([[0.0, 0, 0, 0, 0, 1]]), np.eye(4)).forward(w[:, :1])
        assert _core._threads_started() == before, size
    before = _core._threads_started()
    chasles.so3_exp(np.zeros((2 * ELEMENTWISE_GRAIN, 3)))
    assert _core._threads_started() == before + 1  # 2 threads: the caller and one started


def test_strided_operands_and_out_split_alike(set_threads):
    """Non-contiguous operands, a broadcast operand and a strided out=: each
    thread's range starts at its own offset of every operand."""
    rng = np.random.default_rng(8)
    n = 3 * ELEMENTWISE_GRAIN + 1
    w = rng.normal(size=(2 * n, 3))[::2]
    g = chasles.se3_exp(rng.normal(size=(n, 6)))
    h = chasles.se3_exp(rng.normal(size=6))  # broadcast: outer stride 0
    results = []
    for k in (1, 2):
        set_threads(k)
        out = np.full((n, 4, 4, 2), np.nan)[..., 1]
        chasles.se3_compose(np.swapaxes(np.swapaxes(g, 1, 2).copy(), 1, 2), h, out=out)
        results.append((chasles.so3_exp(w).tobytes(), out.tobytes(), chasles.se3_act(h, w).tobytes()))
    assert results[0] == results[1]


def test_inverse_kinematics_and_dynamics_split_alike(set_threads):
    """Chain's inverse kinematics (four results) and dynamics (a model of
    inertias) on 2 model grains + 5 configurations."""
    rng = np.random.default_rng(9)
    home = np.array([[-1.0, 0, 0, 0.817], [0, 0, 1, 0.191], [0, 1, 0, -0.006], [0, 0, 0, 1]])
    # (mass, com, ixx, ixy, ixz, iyy, iyz, izz) per joint
    inertias = np.array([[1.0 + i, 0.1 * i, 0.05, -0.02, 0.1, 0.0, 0.0, 0.2, 0.0, 0.3] for i in range(6)])
    arm = chasles.Chain(ARM_SCREWS, home, link_inertias=inertias)
    n = 2 * MODEL_GRAIN + 5
    q = rng.uniform(-np.pi, np.pi, (n, 6))
    targets = arm.forward(q)
    seeds = q + rng.uniform(-0.3, 0.3, (n, 6))
    qd, qdd = rng.uniform(-2, 2, (2, n, 6))
    outcomes = []
    for k in (1, 2):
        set_threads(k)
        before = _core._threads_started()
        ik = arm.inverse_kinematics(targets, seeds)
        dyn = (arm.inverse_dynamics(q, qd, qdd), arm.mass_matrix(q), arm.forward_dynamics(q, qd, qdd))
        assert (_core._threads_started() > before) == (k > 1)
        outcomes.append([np.asarray(x).tobytes() for x in (*ik, *dyn)])
    assert outcomes[0] == outcomes[1]
    assert np.mean(ik.converged) > 0.99


@pytest.mark.parametrize("n", [1, 2, 5, 1024, np.int64(3)])
def test_set_and_get_num_threads(set_threads, n):
    set_threads(n)
    assert chasles.get_num_threads() == n and type(chasles.get_num_threads()) is int


@pytest.mark.parametrize(
    "n,error",
    [
        (0, ValueError),
        (-1, ValueError),
        (1025, ValueError),
        (2**70, ValueError),
        (2.0, TypeError),
        ("2", TypeError),
        (True, TypeError),
        (None, TypeError),
    ],
)
def test_set_num_threads_refuses_what_is_not_a_thread_count(set_threads, n, error):
    set_threads(3)
    with pytest.raises(error, match=r"set_num_threads\(n\) must be an int from 1 to 1024, got"):
        set_threads(n)
    assert chasles.get_num_threads() == 3  # unchanged


@pytest.mark.parametrize(
    "value,expected,warns",
    [("3", 3, False), (" 2 ", 2, False), ("", 1, False), ("0", 1, True), ("two", 1, True), ("1.5", 1, True)],
)
def test_the_environment_variable_sets_the_count_at_import(value, expected, warns):
    env = dict(os.environ, CHASLES_NUM_THREADS=value)
    r = subprocess.run(
        [sys.executable, "-c", "import chasles; print(chasles.get_num_threads())"],
        env=env,
        capture_output=True,
        text=True,
        timeout=120,
        check=True,
    )
    assert r.stdout.strip() == str(expected)
    assert ("RuntimeWarning: CHASLES_NUM_THREADS must be an int from 1 to 1024" in r.stderr) == warns, r.stderr
