"""chasles: Lie groups of rigid-body motion."""

from chasles._core import __version__

__all__ = ["__version__"]
