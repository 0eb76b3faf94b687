"""What chasles' Python classes over private C++ kernels share (the splines,
the B-splines): an immutable value, pickled and copied as its constructor's
arguments (``__reduce__``, every protocol; unpickling runs the constructor's
checks), and a clear error for an object made by ``__new__`` alone."""

from __future__ import annotations

from typing import Any


class Value:
    """Base of the value classes: a subclass names its state's attributes in
    ``_state`` and defines ``__reduce__`` as (callable, constructor arguments)."""

    _state: tuple[str, ...] = ()

    def __getattr__(self, name: str) -> Any:
        # Only reached when an attribute is missing: the state of an object
        # made by __new__ alone, whose __init__ has not run.
        if name in type(self)._state:
            raise TypeError(
                f"{type(self).__name__} object is not initialized: it was made by __new__ alone, without __init__"
            )
        raise AttributeError(f"{type(self).__name__!r} object has no attribute {name!r}")

    def __copy__(self) -> Any:
        make, arguments = self.__reduce__()[:2]
        return make(*arguments)

    def __deepcopy__(self, memo: dict[int, Any]) -> Any:
        return self.__copy__()  # immutable: its arrays are read-only and its own
