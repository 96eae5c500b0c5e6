"""The render call under Renderer.render, shadelab.render and Scene.render, and the process-wide compiled
renderer that shadelab.render and Scene.render share.

It works on the compiled module's scene handles, never on shadelab.Scene, so that scene.py (Scene.render)
and render.py (Renderer, which takes a Scene, a path or a dict) both build on it and neither imports the
other.
"""

from __future__ import annotations

import _thread
import atexit

from . import _shadelab
from ._warnings import warn

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing; mypy treats the name as True
if TYPE_CHECKING:
    from ._types import EncodingName, EstimatorName, LightPathsName, RendererName, Size

# The binary's default --size.
DEFAULT_SIZE = (1280, 720)


def parse_size(size: Size) -> tuple[int, int]:
    """(width, height) from (width, height) or "WxH"; the ranges are the compiled renderer's to check."""
    if isinstance(size, str):
        w, sep, h = size.lower().partition("x")
        if not sep or not w.isdigit() or not h.isdigit():
            raise ValueError(f"size: expected WxH (e.g. 640x360) or (width, height), got {size!r}")
        return int(w), int(h)
    try:
        width, height = size
        return int(width), int(height)
    except (TypeError, ValueError):
        raise ValueError(f"size: expected (width, height) or 'WxH', got {size!r}") from None


def render_handle(core: _shadelab._Renderer, handle: _shadelab._Scene, size: Size, renderer: RendererName,
                  spp: int | None, encoding: EncodingName, depth: int | None, threads: int, coverage: bool,
                  time_limit: float | None, estimator: EstimatorName | None,
                  light_paths: LightPathsName | None) -> _shadelab.Image:
    """Renders the scene behind `handle` with `core`; the arguments are Renderer.render's. The compiled renderer
    holds them to the render request's limits, the command line's (docs/design.md §5)."""
    width, height = parse_size(size)
    image = core.render(handle, width, height, renderer, spp, encoding, depth, threads, coverage, time_limit,
                        estimator, light_paths)
    if image.non_finite_pixels:
        # The command line's warning, in the same words: no image goes black in silence.
        warn([f"{renderer}: {image._non_finite_message}"], stacklevel=3)
    return image


_default: _shadelab._Renderer | None = None
_default_lock = _thread.allocate_lock()  # _thread, not threading: import costs count (bench/README.md)


def default_core() -> _shadelab._Renderer:
    """The compiled renderer behind shadelab.default_renderer(), made on first use (with backend "auto")."""
    global _default
    with _default_lock:
        if _default is None:
            _default = _shadelab._Renderer("auto")
        return _default


@atexit.register
def _close_default() -> None:
    # Tear the context down while the interpreter (and Mesa) are whole, not at module teardown.
    if _default is not None:
        _default.close()
