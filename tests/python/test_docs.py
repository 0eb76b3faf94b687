"""The documentation runs as written: every docstring example of the package,
and README.md, docs/*.md, examples/README.md and CONTRIBUTING.md. On each
page the fenced ```python blocks run in order in one namespace (a later
block may use what an earlier one defined), as a reader would run them, and
a block with ``print(...)  # -> text`` lines prints one line per print, the
marked ones exactly their text. (The C++ and CMake blocks are built by the
install_and_consume ctest.) The links between the pages lead to files that
are there, and the pictures they show are the ones of docs/images."""

from __future__ import annotations

import contextlib
import doctest
import importlib.util
import io
import re
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[2]
DOCS = ROOT / "docs"
PAGES = [ROOT / "README.md", *sorted(DOCS.glob("*.md")), ROOT / "examples" / "README.md", ROOT / "CONTRIBUTING.md"]


def page_id(page: Path) -> str:
    return str(page.relative_to(ROOT))


def python_blocks(page: Path) -> list[str]:
    return re.findall(r"```python\n(.*?)```", page.read_text(encoding="utf-8"), flags=re.S)


def test_the_pages_are_there():
    assert {p.name for p in DOCS.glob("*.md")} >= {
        "conventions.md",
        "coming_from.md",
        "estimation.md",
        "formulas.md",
        "numerics.md",
        "performance.md",
        "python.md",
        "realtime.md",
        "robots.md",
    }
    assert all(p.is_file() for p in PAGES)


def test_the_readme_reads_in_five_minutes():
    lines = (ROOT / "README.md").read_text(encoding="utf-8").splitlines()
    assert len(lines) <= 300, f"README.md has {len(lines)} lines: move the details to docs/"


@pytest.mark.parametrize("page", PAGES, ids=page_id)
def test_python_blocks_run_and_print_what_their_comments_say(page):
    namespace = {"__name__": f"docs.{page.stem}"}
    for i, block in enumerate(python_blocks(page), start=1):
        code = compile(block, f"{page} (python block {i})", "exec")
        out = io.StringIO()
        with contextlib.redirect_stdout(out):
            exec(code, namespace)
        if "# -> " not in block:
            continue
        prints = [line for line in block.splitlines() if line.startswith("print(")]
        lines = out.getvalue().splitlines()
        assert len(lines) == len(prints), (page.name, i, prints, lines)
        for statement, line in zip(prints, lines):
            if "# -> " in statement:
                assert line == statement.split("# -> ", 1)[1].rstrip(), (page.name, i, statement, line)


def test_the_readme_robot_quick_start_states_what_it_prints():
    claimed = [b for b in python_blocks(ROOT / "README.md") if "# -> " in b]
    assert any("Chain.from_urdf" in b for b in claimed), "the robot arm quick start has no claims"


@pytest.mark.parametrize("page", PAGES, ids=page_id)
def test_relative_links_lead_to_files_that_are_there(page):
    text = page.read_text(encoding="utf-8")
    for target in re.findall(r"\]\(([^)#\s]+)(?:#[^)]*)?\)", text):
        if re.match(r"[a-z]+:", target):
            continue  # a web address
        assert (page.parent / target).exists(), f"{page_id(page)} links to {target}, which is not there"


def test_scipy_rigid_transform_takes_modern_robotics_exp_coords():
    """docs/conventions.md: RigidTransform's exponential coordinates are (w, v)."""
    transform = pytest.importorskip("scipy.spatial.transform")
    if not hasattr(transform, "RigidTransform"):
        pytest.skip("scipy < 1.16 has no RigidTransform")
    from chasles import SE3, Twist

    xi = Twist(v=[1.0, -2.0, 0.5], w=[0.3, 0.2, -0.9])
    g = transform.RigidTransform.from_exp_coords(xi.to_modern_robotics())
    assert np.allclose(g.as_matrix(), SE3.exp(xi).as_matrix(), atol=1e-14)
    assert np.allclose(g.as_exp_coords(), xi.to_modern_robotics(), atol=1e-14)


def test_every_picture_is_there_and_used():
    """The pictures that the pages show are PNG files of docs/images (made by
    the commands written beside them: ``python -m chasles --png ...``,
    ``python examples/python/robot_arm.py --png ...``), and each is shown."""
    shown = set()
    for page in PAGES:
        for target in re.findall(r"!\[[^\]]*\]\(([^)]+)\)", page.read_text(encoding="utf-8")):
            path = (page.parent / target).resolve()
            assert path.is_file(), f"{page.name} shows {target}, which is not there"
            head = path.read_bytes()[:24]
            assert head[:8] == b"\x89PNG\r\n\x1a\n" and head[12:16] == b"IHDR", target
            width, height = int.from_bytes(head[16:20], "big"), int.from_bytes(head[20:24], "big")
            assert width >= 400 and height >= 300, (target, width, height)
            shown.add(path)
    assert {p.resolve() for p in (DOCS / "images").iterdir()} == shown
    assert "python -m chasles --png docs/images/chasles_demo.png" in (ROOT / "README.md").read_text(encoding="utf-8")
    robots = (DOCS / "robots.md").read_text(encoding="utf-8")
    assert "python examples/python/robot_arm.py --png docs/images/robot_arm.png" in robots


def load_report():
    spec = importlib.util.spec_from_file_location("bench_report", ROOT / "bench" / "report.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_the_performance_page_is_what_bench_report_writes(tmp_path):
    """docs/performance.md is bench/report.py's page: its text, then the
    tables of a run (edit PAGE_HEADER in report.py, not the page)."""
    report = load_report()
    page = (DOCS / "performance.md").read_text(encoding="utf-8")
    assert page.startswith(report.PAGE_HEADER + "\n## The run\n\n")
    tables = page[len(report.PAGE_HEADER + "\n## The run\n\n") :]
    assert re.search(r"^\| op \| .*\n\| --- \|", tables, flags=re.M), "the page has no table"
    written = tmp_path / "performance.md"
    report.write_page(written, tables)
    assert written.read_text(encoding="utf-8") == page


def test_the_stages_of_tests_run_sh_are_the_documented_ones():
    """tests/run.sh takes the stages CONTRIBUTING.md lists, `all` by default,
    which is what .ci/run runs (the README's test command); its pytest run
    requires the C++ URDF cross-check (a failure, not a skip, when the
    program or example-robot-data is missing)."""
    run_sh = (ROOT / "tests" / "run.sh").read_text(encoding="utf-8")
    stages = re.search(r'case "\$STAGE" in\n  ([a-z |]+)\) ;;', run_sh)
    assert stages, "tests/run.sh does not check its stage argument"
    assert sorted(s.strip() for s in stages.group(1).split("|")) == ["all", "cpp", "fuzz", "python"]
    assert "STAGE=${1:-all}" in run_sh
    contributing = (ROOT / "CONTRIBUTING.md").read_text(encoding="utf-8")
    for stage in ("cpp", "fuzz", "python"):
        assert f"`bash tests/run.sh {stage}`" in contributing, stage
    ci = (ROOT / ".ci" / "run").read_text(encoding="utf-8")
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    assert "exec bash tests/run.sh\n" in ci and "bash tests/run.sh\n" in readme
    pytest_call = run_sh[run_sh.index('(cd "$VENV"') : run_sh.index("-m pytest")]
    assert "CHASLES_REQUIRE_URDF_DUMP=1" in pytest_call and "CHASLES_URDF_DUMP=" in pytest_call


# ---- the docstrings' examples ------------------------------------------------


def docstrings() -> list[tuple[str, str, dict]]:
    """(name, docstring, namespace) of every docstring of the package with an
    example: the modules chasles and chasles.plot, each public name and each
    public member of a public class (__init__ and the operators included). The
    examples of chasles run with numpy as np and chasles' public names, those
    of chasles.plot in (a copy of) its own namespace."""
    import chasles
    import chasles.plot

    public = {k: getattr(chasles, k) for k in chasles.__all__}
    found = []
    for module, names, globs in (
        (chasles, chasles.__all__, {"np": np, "chasles": chasles, **public}),
        (chasles.plot, [k for k in vars(chasles.plot) if not k.startswith("_")], dict(vars(chasles.plot))),
    ):
        found.append((module.__name__, module.__doc__, globs))
        for name in names:
            value = getattr(module, name)
            if module is chasles.plot and getattr(value, "__module__", None) != "chasles.plot":
                continue  # what chasles.plot imports (chasles' classes, numpy, typing)
            found.append((f"{module.__name__}.{name}", getattr(value, "__doc__", None), globs))
            if isinstance(value, type):
                for member in vars(value):
                    if member.startswith("_") and member not in ("__init__", "__matmul__", "__call__"):
                        continue
                    attribute = getattr(value, member)  # a static method's function, a property itself
                    doc = getattr(attribute, "__doc__", None) or getattr(
                        getattr(attribute, "fget", None), "__doc__", None
                    )
                    found.append((f"{module.__name__}.{name}.{member}", doc, globs))
    unique = {name: (name, doc, globs) for name, doc, globs in found if isinstance(doc, str) and ">>>" in doc}
    return list(unique.values())


def test_the_docstrings_with_examples_are_found():
    names = {name for name, _, _ in docstrings()}
    for expected in (
        "chasles",
        "chasles.SO3.exp",
        "chasles.SE3.act",
        "chasles.rplus",
        "chasles.between",
        "chasles.Chain.__init__",
        "chasles.SpatialInertia.momentum",
        "chasles.SO3BSpline",
        "chasles.plot",
        "chasles.plot.frame",
        "chasles.plot.frames",
        "chasles.plot.screw",
        "chasles.plot.chain",
    ):
        assert expected in names


@pytest.mark.parametrize(
    "name,doc,globs", docstrings(), ids=lambda x: x if isinstance(x, str) and "\n" not in x else ""
)
def test_docstring_examples_run(name, doc, globs):
    test = doctest.DocTestParser().get_doctest(doc, dict(globs), name, None, 0)
    runner = doctest.DocTestRunner(optionflags=doctest.NORMALIZE_WHITESPACE)
    out: list[str] = []
    runner.run(test, out=out.append)
    assert runner.failures == 0, "".join(out)
