"""shadelab's warning category and how the package raises it, in a module of its own so that every part of
the package (scene.py, the render call in _rendering.py) can raise it without importing each other."""

from __future__ import annotations

import warnings

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing; mypy treats the name as True
if TYPE_CHECKING:
    from collections.abc import Iterable


class ShadelabWarning(UserWarning):
    """A problem that does not stop the work: a scene reader's warning (an unknown field in a dict, something
    skipped in a glTF file), or a rendered image with pixels that have no finite value."""


def warn(lines: Iterable[str], stacklevel: int) -> None:
    """Each line as a ShadelabWarning, attributed `stacklevel` frames above the caller."""
    for line in lines:
        warnings.warn(line, ShadelabWarning, stacklevel=stacklevel + 1)
