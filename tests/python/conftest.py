"""pytest configuration of the chasles Python tests.

The hypothesis strategies live in strategies.py and the reference formulas
(hat3, hat6) in helpers.py, beside this file; with ``--import-mode=importlib``
the test directory is not on sys.path, so it is added here and test modules
do ``from strategies import ...``, ``from helpers import ...``.

Hypothesis profiles (select with HYPOTHESIS_PROFILE): "chasles", the default (100
examples, derandomized so that every run of the suite, in CI too, tries the same
examples; no deadline: the machines that run the suite are shared) and
"thorough" (2000 random examples per test, to look for new failures).
"""

from __future__ import annotations

import os
import sys

from hypothesis import HealthCheck, settings

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

settings.register_profile(
    "chasles",
    max_examples=100,
    derandomize=True,
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow],
)
settings.register_profile("thorough", max_examples=2000, deadline=None, suppress_health_check=[HealthCheck.too_slow])
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "chasles"))
