"""The tree passes its formatters and linter (.clang-format, pyproject.toml's
[tool.ruff]), with the versions .pre-commit-config.yaml pins (the test extras
install the same ones): what CONTRIBUTING.md tells a contributor to run is
what CI checks."""

from __future__ import annotations

import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
PINNED = dict(re.findall(r'"(clang-format|ruff)==([0-9.]+)"', (ROOT / ".pre-commit-config.yaml").read_text()))


def tool(name: str) -> str:
    """The executable of the pinned tool, beside this interpreter (the venv's) or on PATH."""
    here = Path(sys.executable).parent / name
    found = str(here) if here.exists() else shutil.which(name)
    assert found, f"{name} is not installed: pip install {name}=={PINNED[name]} (the test extras do)"
    version = subprocess.run([found, "--version"], capture_output=True, text=True, check=True).stdout
    assert PINNED[name] in version, f"{name} {PINNED[name]} is pinned, {version.strip()} is installed"
    return found


def tracked(*patterns: str) -> list[str]:
    out = subprocess.run(["git", "ls-files", *patterns], cwd=ROOT, capture_output=True, text=True)
    if out.returncode != 0:
        pytest.skip("not a git checkout: the formatters check the repository's files")
    return out.stdout.split()


def test_both_tools_are_pinned():
    assert set(PINNED) == {"clang-format", "ruff"}


def test_cpp_is_clang_formatted():
    files = tracked("*.hpp", "*.cpp", "*.h")
    assert len(files) > 50
    r = subprocess.run([tool("clang-format"), "--dry-run", "-Werror", *files], cwd=ROOT, capture_output=True, text=True)
    assert r.returncode == 0, "clang-format -i would change:\n" + r.stderr[:4000]


def test_python_passes_ruff_check():
    r = subprocess.run([tool("ruff"), "check", "--no-cache", "."], cwd=ROOT, capture_output=True, text=True)
    assert r.returncode == 0, r.stdout[-4000:]


def test_python_is_ruff_formatted():
    r = subprocess.run([tool("ruff"), "format", "--check", "--no-cache", "."], cwd=ROOT, capture_output=True, text=True)
    assert r.returncode == 0, r.stdout[-4000:]
