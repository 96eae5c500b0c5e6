"""Rendering: shadelab.Renderer keeps one headless GL context and the rasterizer's programs for many renders;
shadelab.render() uses a process-wide default Renderer. Also the lighting probe.

Renders run in the compiled module with the GIL released, so other Python threads keep running. A
Renderer may be called from any thread (renders through one Renderer take turns); one process has one GL
context, shared by all its Renderers (EGL device, EGL surfaceless, then OSMesa, as the binary picks;
SHADELAB_GL_BACKEND or backend= forces one). A process that forks after its first raster render must not
render in the child: use spawned processes (Dask and multiprocessing's "spawn" do).
"""

import _thread
import atexit
import os

from . import _shadelab
from .scene import Scene


def _scene(scene):
    if isinstance(scene, Scene):
        return scene
    if isinstance(scene, dict):
        return Scene.from_dict(scene)
    if isinstance(scene, (str, os.PathLike)):
        return Scene.load(scene)
    raise TypeError(f"expected a shadelab.Scene, a scene file's path or a dict, got {type(scene).__name__}")


def _size(size):
    if isinstance(size, str):
        w, sep, h = size.lower().partition("x")
        if not sep or not w.isdigit() or not h.isdigit():
            raise ValueError(f"size: expected WxH (e.g. 640x360) or (width, height), got {size!r}")
        return int(w), int(h)
    try:
        w, h = size
        return int(w), int(h)
    except (TypeError, ValueError):
        raise ValueError(f"size: expected (width, height) or 'WxH', got {size!r}") from None


class Renderer:
    """Renders scenes with one GL context and one set of compiled programs, kept for its lifetime.

    >>> with shadelab.Renderer() as r:
    ...     images = [r.render(scene, (64, 64)) for scene in scenes]

    backend: "auto" (default; honours SHADELAB_GL_BACKEND), "egl-device", "egl-surfaceless" or "osmesa".
    """

    def __init__(self, backend="auto"):
        self._core = _shadelab._Renderer(backend)

    def render(self, scene, size=(1280, 720), *, renderer="raster", spp=1, encoding="srgb", depth=None,
               threads=0, coverage=False):
        """Renders `scene` (a Scene, a scene file's path or a dict) to a shadelab.Image.

        size: (width, height) or "WxH", each 1..16384 (the binary's default 1280x720).
        renderer: "raster" (OpenGL), "trace" (the CPU Whitted reference) or "path" (the path tracer: global
            illumination, ambient off; spp may be any count, and the image is the same for any thread count).
        spp: samples per pixel, a perfect square (1, 4, 9, ...), the same grid in raster and trace; any count
            from 1 for path.
        encoding: "srgb" (default) or "linear": how to_uint8(), save() and the PNG encode the linear floats.
        depth: the tracer's secondary-ray depth (default: the scene's maxDepth); threads: tracer workers
        (0 = every core); coverage: also return per-pixel object ids (image.coverage), which compare() uses.
        The pixels equal `shadelab render scene.json --size WxH --renderer R --spp N --encoding E`'s PNG.
        """
        scene = _scene(scene)
        width, height = _size(size)
        return self._core.render(scene._handle, width, height, renderer, spp, encoding, depth, threads, coverage)

    @property
    def info(self):
        """The GL context: backend, device, gl_renderer (GL_RENDERER) and gl_version (creates it if needed)."""
        return self._core.context_info()

    @property
    def busy(self):
        """True while a render runs (readable from other threads: the GIL is released meanwhile)."""
        return self._core.busy

    def close(self):
        """Frees the GL objects now; a later render starts afresh."""
        self._core.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()


_default = None
_default_lock = _thread.allocate_lock()  # _thread, not threading: import costs count (bench/README.md)


def default_renderer():
    """The Renderer that shadelab.render() uses, made on first use."""
    global _default
    with _default_lock:
        if _default is None:
            _default = Renderer()
        return _default


@atexit.register
def _close_default():
    # Tear the context down while the interpreter (and Mesa) are whole, not at module teardown.
    if _default is not None:
        _default.close()


def render(scene, size=(1280, 720), **options):
    """Renders with the default Renderer; see Renderer.render for the options."""
    return default_renderer().render(scene, size, **options)


def probe(scene, pixel, size=(1280, 720)):
    """The lighting probe at `pixel` = (x, y) (row 0 at the top) of a `size` image: what the primary ray hits,
    N, V, and per light L, R, H, every dot product and term for Phong and Blinn-Phong, as a dict (the viewer's
    probe report, docs/viewer.md). Asks the tracer; needs no GL context."""
    scene = _scene(scene)
    width, height = _size(size)
    x, y = pixel
    return _shadelab._probe(scene._handle, int(x), int(y), width, height)
