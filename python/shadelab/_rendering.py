"""The render call under Renderer.render, shadelab.render and Scene.render, and the process-wide compiled
renderer that shadelab.render and Scene.render share.

It works on the compiled module's scene handles, never on shadelab.Scene, so that scene.py (Scene.render)
and render.py (Renderer, which takes a Scene, a path or a dict) both build on it and neither imports the
other.
"""

from __future__ import annotations

import _thread
import atexit

from . import _checks, _shadelab
from ._warnings import warn

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing; mypy treats the name as True
if TYPE_CHECKING:
    from ._types import (EncodingName, EstimatorName, LightPathsName, MemorySize, RendererName, SamplerName, Size,
                         ViewTransformName)

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
    except (TypeError, ValueError):
        raise ValueError(f"size: expected (width, height) or 'WxH', got {size!r}") from None
    # Whole numbers only (ints, numpy integers): int() would make 32.5 a silent 32, and True a 1.
    return _checks.whole("size: width", width), _checks.whole("size: height", height)


def memory_limit(max_memory: MemorySize | None) -> int:
    """The bytes render(max_memory=...) means: None, the command line's default (half of physical memory, within
    ulimit -v); an int, bytes; a string, as --max-memory reads it ("512M", "2G", a bare number of MiB)."""
    return _shadelab._memory_limit(max_memory)


def render_handle(core: _shadelab._Renderer, handle: _shadelab._Scene, size: Size, renderer: RendererName,
                  spp: int | None, encoding: EncodingName, depth: int | None, threads: int, coverage: bool,
                  time_limit: float | None, estimator: EstimatorName | None, light_paths: LightPathsName | None,
                  sampler: SamplerName | None, denoise: bool, max_memory: int | None, exposure: float | None = None,
                  view_transform: ViewTransformName | None = None, seed: int | None = None) -> _shadelab.Image:
    """Renders the scene behind `handle` with `core`; the arguments are Renderer.render's, max_memory in bytes
    (memory_limit()) or None for the default, as the command line without --max-memory. Their types are
    checked here, each refused in one line naming it; the compiled renderer holds them to the render request's
    limits, the command line's (docs/design.md §5), and the render to its memory budget (render/memory_budget.h)."""
    width, height = parse_size(size)
    clamp = _checks.Clamp()  # in the order the request checks them: size, spp, depth, threads
    args = (handle, clamp(width), clamp(height), _checks.word("renderer", renderer),
            _clamped(clamp, _checks.optional_whole("spp", spp)), _checks.word("encoding", encoding),
            _clamped(clamp, _checks.optional_whole("depth", depth)), clamp(_checks.whole("threads", threads)),
            _checks.flag("coverage", coverage), _checks.optional_real("time_limit", time_limit),
            _checks.optional_word("estimator", estimator), _checks.optional_word("light_paths", light_paths),
            _checks.optional_word("sampler", sampler), _checks.flag("denoise", denoise), max_memory,
            _checks.optional_real("exposure", exposure),
            _checks.optional_word("view_transform", view_transform),
            clamp.int64(_checks.optional_whole("seed", seed)))
    image: _shadelab.Image = _checks.call(clamp, core.render, *args)
    layers = handle.layers_not_shown()
    if layers:
        # The command line's note: glTF's layers vanish without a word under another model than pbr.
        verb = "shade" if "," in layers else "shades"
        warn([f"glTF's {layers} {verb} only under pbr, not under the model this render gives the objects that carry "
              f"it (scene.model = \"pbr\" shows it)"], stacklevel=3)
    if image.non_finite_pixels:
        # The command line's warning, in the same words: no image goes black in silence.
        warn([f"{renderer}: {image._non_finite_message}"], stacklevel=3)
    return image


def _clamped(clamp: _checks.Clamp, value: int | None) -> int | None:
    return None if value is None else clamp(value)


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
