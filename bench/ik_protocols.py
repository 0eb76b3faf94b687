"""Inverse kinematics under the field's two published protocols: chasles beside TRAC-IK and KDL.

Panda (panda_link0 -> panda_hand), UR5 (world -> tool0) and xArm7 (world ->
link7) of example-robot-data, by chasles.Chain.from_urdf (base: the URDF's
root); the peers get the same URDF, base, tip, targets and seeds, in one run.

(a) TRAC-IK's (Beeson and Ames 2015, trac_ik_examples ik_tests.cpp): N
    configurations uniform within the limits (numpy default_rng(0)), target =
    forward(q), seed = the middle of the limits for every solve, tolerance
    1e-5, 5 ms per solve; chasles at 1e-10 too. KDL: ChainIkSolverPos_NR_JL
    from that seed with the iterations that fit 5 ms (timed first), as
    ik_tests loops NR_JL from its last iterate until the time is out.
(b) PickNik's ik_benchmarking (github.com/PickNikRobotics/ik_benchmarking,
    src/ik_benchmarking.cpp gather_data(); settings in the MoveIt blog post
    "GSoC 2023: MoveIt Servo and IK Benchmarking", 2023-11-21: sample_size
    10000, random_seed 12345, ik_timeout 0.1, Panda's panda_arm). Per sample,
    RobotState::setToRandomPositions(group, generator_) makes the target (the
    tip link's pose), a second call on the same generator the seed state, then
    setFromIK(group, pose, 0.1): success is the plugin's own answer (KDL and
    TRAC-IK plugins: epsilon 1e-5), the mean time over all samples. (There,
    initialize() declares a local `RandomNumberGenerator generator_{seed}`
    that shadows the member, so 12345 may never reach the sampling.) Here:
    default_rng(12345) draws target then seed per sample, uniform within the
    limits; 1e-5, 0.1 s. KDL stands in for MoveIt's KDL plugin: NR_JL
    attempts of 500 iterations from the seed, then from random seeds, to 0.1 s.

Peers, when installed: TRAC-IK (`pip install pytracik`; Speed, eps = tol,
timeout = the budget; its limits set to chasles' by set_joint_limits, as its
URDF parser reads the Panda's <safety_controller> soft limits as 0 and all
limits as float32); KDL (`apt-get install python3-pykdl`, for /usr/bin/python3:
this file runs itself there with --kdl-worker on .npz files; the KDL chain
is built from the URDF's joints as kdl_parser does). Both are checked against
chasles' forward kinematics (<= 1e-12) first. chasles restarts until solved
or out of time: restarts=2**31 - 1, max_time = the budget.

Success, judged here alike for all: the body error twist e = log(g(q)^-1 T)
has max_i |e_i| <= tol (infinity norm over (v, w): TRAC-IK's own test, which
bounds each component in the target frame) and q is within the limits (TRAC-IK
now and then returns a joint 2 pi past its limit); a TRAC-IK failure returns
no q. 'self' is the solver's own verdict: KDL's NR_JL
tests the components in the base frame, so a KDL answer just under 1e-5 there
can fail here. Times: time.perf_counter around each Python call (its overhead
included), over all solves. TRAC-IK runs two threads: on a loaded 2-core
machine its times vary with the load.

    python bench/ik_protocols.py --n 1000 [--arms Panda UR5] [--protocol a|b|both]

(about 45 s here at --n 1000, KDL's failures most of it; the default 10000, ten times that.)
"""

from __future__ import annotations

import argparse
import contextlib
import importlib.metadata
import os
import subprocess
import sys
import tempfile
import time
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np

ARMS = {
    "Panda": ("panda_description/urdf/panda.urdf", "panda_hand"),
    "UR5": ("ur_description/urdf/ur5_robot.urdf", "tool0"),
    "xArm7": ("xarm_description/urdf/xarm7.urdf", "link7"),
}
KDL_PYTHON = "/usr/bin/python3"


def robots_dir() -> Path:
    for f in importlib.metadata.files("example-robot-data") or []:
        if str(f).endswith("ur_description/urdf/ur5_robot.urdf"):
            return f.locate().parents[2]
    raise SystemExit("example-robot-data is not installed (pip install example-robot-data)")


def urdf_chain(urdf) -> tuple:
    """(root link, joint elements by child link name) of a URDF: the root is Chain.from_urdf's default base."""
    joints = {j.find("child").get("link"): j for j in ET.parse(urdf).getroot().findall("joint")}
    return ({j.find("parent").get("link") for j in joints.values()} - set(joints)).pop(), joints


def floats(element, attribute: str, default: str = "0 0 0") -> list:
    return [float(x) for x in (default if element is None else element.get(attribute, default)).split()]


def timed_call(f) -> float:
    t0 = time.perf_counter()
    f()
    return time.perf_counter() - t0


def kdl_worker(inp: str, out: str) -> None:
    """Runs under /usr/bin/python3 (PyKDL, numpy; no chasles): solves the targets of inp, writes out."""
    import PyKDL as kdl

    d = np.load(inp)
    base, joints = urdf_chain(str(d["urdf"]))
    path, link = [], str(d["tip"])
    while link != base:
        path.insert(0, joints[link])
        link = path[0].find("parent").get("link")
    chain = kdl.Chain()
    kinds = {"revolute": kdl.Joint.RotAxis, "continuous": kdl.Joint.RotAxis, "prismatic": kdl.Joint.TransAxis}
    for j in path:
        o = j.find("origin")  # as kdl_parser: the joint at the origin's place, its axis in the parent's frame
        F = kdl.Frame(kdl.Rotation.RPY(*floats(o, "rpy")), kdl.Vector(*floats(o, "xyz")))
        axis = F.M * kdl.Vector(*floats(j.find("axis"), "xyz", "1 0 0"))
        kind = kinds.get(j.get("type"))
        joint = kdl.Joint(j.get("name"), kdl.Joint.Fixed) if kind is None else kdl.Joint(j.get("name"), F.p, axis, kind)
        chain.addSegment(kdl.Segment(j.find("child").get("link"), joint, F))
    lo, hi, eps, budget = d["lower"], d["upper"], float(d["eps"]), float(d["budget"])

    def jnt(q):
        a = kdl.JntArray(len(q))
        for i, x in enumerate(q):
            a[i] = float(x)
        return a

    def frame(T):
        return kdl.Frame(kdl.Rotation(*T[:3, :3].ravel()), kdl.Vector(*T[:3, 3]))

    fk, vel = kdl.ChainFkSolverPos_recursive(chain), kdl.ChainIkSolverVel_pinv(chain)
    check = []
    for q in d["q_check"]:
        f = kdl.Frame()
        fk.JntToCart(jnt(q), f)
        check.append([[f.M[r, c] for c in range(3)] + [f.p[r]] for r in range(3)] + [[0, 0, 0, 1]])
    per_attempt = 500  # MoveIt's KDL plugin: 500 iterations per attempt
    if not d["restarts"]:  # the iterations that fit the budget, timed on the first targets with eps 0
        timed, probe = kdl.ChainIkSolverPos_NR_JL(chain, jnt(lo), jnt(hi), fk, vel, 200, 0.0), kdl.JntArray(len(lo))
        calls = [(jnt(q0), frame(T)) for T, q0 in zip(d["targets"][:20], d["seeds"][:20])]
        per_iteration = timed_call(lambda: [timed.CartToJnt(q0, T, probe) for q0, T in calls]) / (200 * len(calls))
        per_attempt = max(1, int(budget / per_iteration))
    solver = kdl.ChainIkSolverPos_NR_JL(chain, jnt(lo), jnt(hi), fk, vel, per_attempt, eps)
    rng, n = np.random.default_rng(0), len(lo)
    qs, oks, times = [], [], []
    for T, q0 in zip(d["targets"], d["seeds"]):
        q, target = kdl.JntArray(n), frame(T)
        t0 = time.perf_counter()
        rc = solver.CartToJnt(jnt(q0), target, q)
        while d["restarts"] and rc < 0 and time.perf_counter() - t0 < budget:
            rc = solver.CartToJnt(jnt(rng.uniform(lo, hi)), target, q)
        times.append(time.perf_counter() - t0)
        qs.append([q[i] for i in range(n)])
        oks.append(rc >= 0)
    np.savez(out, q=qs, ok=oks, times=times, check=check, maxiter=per_attempt)


def check_configurations(chain) -> np.ndarray:
    return np.random.default_rng(1).uniform(chain.lower, chain.upper, (100, chain.n_joints))


def same_model(name: str, poses, chain) -> None:
    """Refuses a peer whose forward kinematics differ from chasles' by more than 1e-12."""
    mismatch = np.abs(np.asarray(poses) - chain.forward(check_configurations(chain))).max()
    if not mismatch <= 1e-12:
        raise RuntimeError(f"{name}'s chain differs from chasles' by {mismatch:.2e} in forward kinematics")


def run_kdl(urdf, base, tip, chain, targets, seeds, tol, budget, restarts):
    with tempfile.TemporaryDirectory() as tmp:
        inp, out = os.path.join(tmp, "in.npz"), os.path.join(tmp, "out.npz")
        data = {"urdf": str(urdf), "tip": tip, "targets": targets, "seeds": seeds, "eps": tol, "budget": budget}
        np.savez(
            inp, lower=chain.lower, upper=chain.upper, restarts=restarts, q_check=check_configurations(chain), **data
        )
        subprocess.run([KDL_PYTHON, __file__, "--kdl-worker", inp, out], check=True)
        r = dict(np.load(out))
    same_model("KDL", r["check"], chain)
    return r["q"], r["ok"], r["times"], f"NR_JL {int(r['maxiter'])} iterations{'/attempt' if restarts else ''}"


@contextlib.contextmanager
def quiet():
    """Mutes C++'s stdout (TRAC-IK's parser warns that the Panda's root link has an inertia)."""
    sys.stdout.flush()
    saved, null = os.dup(1), os.open(os.devnull, os.O_WRONLY)
    os.dup2(null, 1)
    try:
        yield
    finally:
        os.dup2(saved, 1)
        os.close(saved)
        os.close(null)


def run_tracik(urdf, base, tip, chain, targets, seeds, tol, budget, restarts):
    import pytracik

    from chasles import so3_as_quat

    with quiet():
        solver = pytracik.TRAC_IK(base, tip, Path(urdf).read_text(), budget, tol, pytracik.SolveType.Speed)
    pytracik.set_joint_limits(solver, chain.lower.tolist(), chain.upper.tolist())
    same_model("TRAC-IK", [pytracik.fk(solver, q) for q in check_configurations(chain)], chain)
    quats, q, ok, times = so3_as_quat(targets[:, :3, :3]), np.full(seeds.shape, np.nan), [], []
    for i, (T, q0) in enumerate(zip(targets, seeds)):
        t0 = time.perf_counter()
        r = pytracik.ik(solver, q0, *T[:3, 3], *quats[i])
        times.append(time.perf_counter() - t0)
        ok.append(r[0] >= 0)
        if ok[-1]:
            q[i] = r[1:]
    return q, np.array(ok), np.array(times), "Speed"


def run_chasles(urdf, base, tip, chain, targets, seeds, tol, budget, restarts):
    """Restarts until solved or out of time: restarts=2**31 - 1, max_time=budget, seed i for target i."""
    kw = {"position_tolerance": tol, "orientation_tolerance": tol, "max_time": budget, "restarts": 2**31 - 1}
    q, ok, times, attempts = np.array(seeds), [], [], []
    for i, (T, q0) in enumerate(zip(targets, seeds)):
        t0 = time.perf_counter()
        r = chain.inverse_kinematics(T, q0, seed=i, **kw)
        times.append(time.perf_counter() - t0)
        q[i] = r.q
        ok.append(r.converged)
        attempts.append(r.attempts)
    return q, np.array(ok), np.array(times), f"attempts mean {np.mean(attempts):.2f} max {max(attempts)}"


def judge(chain, targets, q, tol):
    """max_i |e_i| <= tol and q within the limits; a NaN row (TRAC-IK returned no q) fails."""
    from chasles import se3_compose, se3_inverse, se3_log

    returned = np.isfinite(q).all(axis=-1)
    q = np.where(returned[:, None], q, chain.lower)
    e = se3_log(se3_compose(se3_inverse(chain.forward(q)), targets))
    inside = ((q >= chain.lower - 1e-9) & (q <= chain.upper + 1e-9)).all(axis=-1)
    return returned & (np.abs(e).max(axis=-1) <= tol) & inside


def samples(chain, protocol: str, n: int):
    """(targets, seeds): (a) uniform within the limits, the middle as seed; (b) target then seed per sample."""
    lo, hi = chain.lower, chain.upper
    lo, hi = np.where(np.isfinite(lo), lo, -np.pi), np.where(np.isfinite(hi), hi, np.pi)
    if protocol == "a":
        q = np.random.default_rng(0).uniform(lo, hi, (n, chain.n_joints))
        return chain.forward(q), np.broadcast_to((lo + hi) / 2, q.shape)
    draws = np.random.default_rng(12345).uniform(lo, hi, (n, 2, chain.n_joints))
    return chain.forward(draws[:, 0]), draws[:, 1]


def kdl_version() -> str:
    """PyKDL's version under KDL_PYTHON (with numpy), or '' where it cannot import them."""
    if not os.path.exists(KDL_PYTHON):
        return ""
    probe = "import numpy, PyKDL; print(PyKDL.__version__)"
    return subprocess.run([KDL_PYTHON, "-c", probe], capture_output=True, text=True).stdout.strip()


def main() -> None:
    import chasles
    from chasles import Chain

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=10000, help="targets per arm (default 10000)")
    parser.add_argument("--arms", nargs="+", choices=list(ARMS), default=list(ARMS))
    parser.add_argument("--protocol", choices=["a", "b", "both"], default="both")
    args = parser.parse_args()
    solvers = {"chasles": run_chasles}
    versions = [f"chasles {chasles.__version__}", f"numpy {np.__version__}"]
    try:
        versions.append(f"pytracik {importlib.metadata.version('pytracik')}")
        solvers["TRAC-IK"] = run_tracik
    except importlib.metadata.PackageNotFoundError:
        versions.append("pytracik not installed")
    kdl = kdl_version()
    versions.append(f"PyKDL {kdl} ({KDL_PYTHON})" if kdl else f"PyKDL: not importable by {KDL_PYTHON}")
    if kdl:
        solvers["KDL"] = run_kdl
    print("; ".join(versions))
    root = robots_dir()
    for protocol in ["a", "b"] if args.protocol == "both" else [args.protocol]:
        budget = 0.005 if protocol == "a" else 0.1
        name = "(a) TRAC-IK: seed mid-limits" if protocol == "a" else "(b) PickNik: random seed, rng 12345"
        print(f"\n{name}, {args.n} targets per arm, {1e3 * budget:g} ms per solve; success: max|e_i| <= tol")
        print(f"{'arm':6} {'solver':8} {'tol':>6} {'success':>8} {'self':>7} {'median ms':>10} {'mean ms':>8}  notes")
        for arm in args.arms:
            rel, tip = ARMS[arm]
            urdf = root / rel
            base = urdf_chain(urdf)[0]
            chain = Chain.from_urdf(urdf, tip)
            targets, seeds = samples(chain, protocol, args.n)
            runs = [(s, 1e-5) for s in solvers] + ([("chasles", 1e-10)] if protocol == "a" else [])
            medians = {}
            for solver, tol in runs:
                try:
                    q, ok, t, note = solvers[solver](
                        urdf, base, tip, chain, targets, seeds, tol, budget, protocol == "b"
                    )
                except Exception as exc:  # noqa: BLE001 - a peer that fails is reported, the others still run
                    print(f"{arm:6} {solver:8} {tol:6.0e} failed: {exc}")
                    continue
                good = judge(chain, targets, q, tol)
                medians[solver, tol] = float(np.median(t))
                print(
                    f"{arm:6} {solver:8} {tol:6.0e} {100 * good.mean():7.2f}% {100 * ok.mean():6.2f}% "
                    f"{1e3 * np.median(t):10.3f} {1e3 * t.mean():8.3f}  {note}"
                )
            if ("TRAC-IK", 1e-5) in medians:
                ratio = medians["chasles", 1e-5] / medians["TRAC-IK", 1e-5]
                print(f"{arm:6} median time at 1e-5, chasles / TRAC-IK: {ratio:.3f}")


if __name__ == "__main__":
    if len(sys.argv) == 4 and sys.argv[1] == "--kdl-worker":
        kdl_worker(sys.argv[2], sys.argv[3])
    else:
        main()
