"""Writes the pickles of tests/python/data/pickles: one per example of
tests/python/test_pickle.py (EXAMPLES) and protocol (2 and 5), with the
installed chasles. They were written with chasles 0.1.0, and are kept so
that test_pickle checks that pickles of that version still load; run this
only to add the examples of a new class (an existing file is not rewritten).

    python tests/python/data/write_pickles.py
"""

from __future__ import annotations

import os
import pickle
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))

import test_pickle  # noqa: E402

import chasles  # noqa: E402


def main() -> None:
    out = os.path.join(HERE, "pickles")
    os.makedirs(out, exist_ok=True)
    for name, examples in test_pickle.EXAMPLES.items():
        for key, make in examples.items():
            for protocol in (2, 5):
                path = os.path.join(out, f"{name}.{key}.protocol{protocol}.pickle")
                if os.path.exists(path):
                    continue
                try:
                    data = pickle.dumps(make(), protocol=protocol)
                except TypeError as e:  # a class that does not pickle in this version
                    print(f"skipped {name}.{key}: {e}")
                    continue
                with open(path, "wb") as f:
                    f.write(data)
                print(f"wrote {path} (chasles {chasles.__version__})")


if __name__ == "__main__":
    main()
