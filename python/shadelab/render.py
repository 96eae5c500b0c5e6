"""Rendering: shadelab.Renderer keeps one headless GL context and the rasterizer's programs for many renders;
shadelab.render() uses a process-wide default Renderer. Also the lighting probe.

Renders run in the compiled module with the GIL released, so other Python threads keep running. A
Renderer may be called from any thread (renders through one Renderer take turns); one process has one GL
context, shared by all its Renderers (EGL device, EGL surfaceless, then OSMesa, as the binary picks;
SHADELAB_GL_BACKEND or backend= forces one). A process that forks after its first raster render must not
render in the child: use spawned processes (Dask and multiprocessing's "spawn" do).
"""

from __future__ import annotations

import _thread
import os

from . import _checks, _rendering, _shadelab
from ._rendering import DEFAULT_SIZE, parse_size
from .scene import Scene, _plain

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing; mypy treats the name as True
if TYPE_CHECKING:
    from typing import Any, Sequence, SupportsInt

    from ._types import (BackendName, EncodingName, EstimatorName, LightPathsName, MemorySize, RendererName,
                         SamplerName, Size, ViewTransformName)
    from .typing import SceneLike


def _scene(scene: SceneLike, max_memory: int = 0) -> Scene:
    """The Scene to render. A path or a dict is read here, its environment map's load held to `max_memory`
    (bytes; 0: none), as `shadelab render --max-memory` holds it, refused from the .hdr's header."""
    if isinstance(scene, Scene):
        return scene
    if isinstance(scene, dict):
        handle, lines = _shadelab._Scene.from_document(_plain(scene), os.getcwd(), False, max_memory)
        return Scene._from_handle(handle, lines)
    if isinstance(scene, (str, os.PathLike)):
        handle, lines = _shadelab._Scene.load(os.fspath(scene), False, max_memory)
        return Scene._from_handle(handle, lines)
    raise TypeError(f"scene: expected a shadelab.Scene, a scene file's path or a dict, got {type(scene).__name__}")


class Renderer:
    """Renders scenes with one GL context and one set of compiled programs, kept for its lifetime.

    >>> with shadelab.Renderer() as r:
    ...     images = [r.render(scene, (64, 64)) for scene in scenes]

    backend: "auto" (default; honours SHADELAB_GL_BACKEND), "egl-device", "egl-surfaceless" or "osmesa".
    """

    _core: _shadelab._Renderer

    def __init__(self, backend: BackendName = "auto") -> None:
        self._core = _shadelab._Renderer(_checks.word("backend", backend))

    @classmethod
    def _around(cls, core: _shadelab._Renderer) -> Renderer:
        # The default Renderer: around the compiled renderer that Scene.render uses too (_rendering.py).
        renderer = object.__new__(cls)
        renderer._core = core
        return renderer

    def render(self, scene: SceneLike, size: Size = DEFAULT_SIZE, *, renderer: RendererName = "raster",
               spp: int | None = None, encoding: EncodingName = "srgb", depth: int | None = None, threads: int = 0,
               coverage: bool = False, time_limit: float | None = None, estimator: EstimatorName | None = None,
               light_paths: LightPathsName | None = None, sampler: SamplerName | None = None, denoise: bool = False,
               max_memory: MemorySize | None = None, exposure: float | None = None,
               view_transform: ViewTransformName | None = None, seed: int | None = None) -> _shadelab.Image:
        """Renders `scene` to a shadelab.Image with this Renderer's GL context and programs.

        scene: a Scene, a scene file's path (.json, or a .gltf / .glb model framed and lit as the binary does)
            or a dict in the scene file's schema.
        size: (width, height) or "WxH", each side 1..16384 pixels; default (1280, 720), the binary's --size.
        renderer: "raster" (default: OpenGL), "trace" (the CPU Whitted ray tracer, the reference) or "path" (the
            path tracer: global illumination, ambient term off). The binary's --renderer.
        spp: samples per pixel; default None: 1, and 16 for "path", as the binary. For "raster" and "trace" a
            perfect square from 1 to 64 (1, 4, 9, ..., the k x k grid both share); for "path" any count from 1 to
            1048576. The binary's --spp.
        encoding: "srgb" (default) or "linear": how the 8-bit pixels (image.to_uint8(), save(), the PNG) encode
            the linear floats; np.asarray(image) is linear either way. The binary's --encoding.
        depth: the tracers' secondary-ray depth, 0..64 (0: primary rays only; for "path" the bounces after the
            camera hit, 0: direct light only); default None, the scene's maxDepth. The rasterizer reflects once
            and ignores it. The binary's --depth.
        threads: the tracers' worker threads, 0..1024; default 0, every core. The path tracer's image is the same
            for any count; the rasterizer ignores it. The binary's --threads.
        coverage: also record per-pixel object ids (image.coverage, uint32, 0 = background), which compare()
            uses to mask silhouettes; default False.
        time_limit: "path" only: stop after the last whole sample pass begun within this many seconds, 0.001..1e7;
            default None, no limit. The binary's --time-limit.
        estimator: "path" only: how emitters' light is sampled, "mis", "bsdf" or "light" (all converge to the
            same image, with different noise); default None, "mis". The binary's --estimator.
        light_paths: "path" only: which light reaches the image, "all", "direct" or "indirect" (what the ambient
            term stands in for); default None, "all". The binary's --light-paths.
        sampler: "path" only: where the random numbers come from, "sobol" (Owen-scrambled Sobol points,
            stratified in each pixel: less noise at equal samples) or "independent" (plain Monte Carlo); both
            converge to the same image; default None, "sobol". The binary's --sampler.
        denoise: "path" only: the denoised preview instead of the raw estimate (an edge-avoiding filter
            guided by the first hit's albedo, normal and depth; the binary's --denoise); default False.
        seed: "path" only: the random numbers' variation, a whole number 0..4294967295: the same seed gives the
            same image byte for byte, another seed another noise; default None, 0 (the image without a seed).
            The binary's --seed. Given to another renderer, any of these six raises ValueError.
        max_memory: the most memory the render may take: an int of bytes, or a string as the binary's
            --max-memory reads it ("512M", "2G"; a bare number in a string is MiB); default None, the binary's
            default, half of physical memory (within ulimit -v). A render estimated to need more raises
            shadelab.InputError before any pixel is drawn, as does the environment map of a scene given as a
            path or a dict; a limit below what any render of this size and renderer needs raises ValueError.
        exposure: stops, -16..16: the 8-bit pixels show the linear values times 2^exposure; default None, the
            scene's display.exposure (0 when it has none). The binary's --exposure.
        view_transform: "standard" (clamp to [0, 1]) or "filmic" (Narkowicz's ACES fit: highlights roll off
            instead of clipping), applied after the exposure and before the encoding; default None, the scene's
            display.viewTransform ("standard"). The binary's --view-transform. Both change only the 8-bit
            pixels; np.asarray(image) and probe() read the linear floats, and compare() compares the 8-bit
            pixels as they are, so compare renderers with the default display.

        With the same options the pixels equal `shadelab render`'s PNG, byte for byte. A value out of range
        raises ValueError naming the argument, a value of the wrong type TypeError naming it; an unknown keyword
        raises TypeError.
        """
        limit = _rendering.memory_limit(max_memory)  # the default too: a path's environment map is held to it
        return _rendering.render_handle(self._core, _scene(scene, limit)._handle, size, renderer, spp, encoding,
                                        depth, threads, coverage, time_limit, estimator, light_paths, sampler, denoise,
                                        None if max_memory is None else limit, exposure, view_transform, seed)

    @property
    def info(self) -> dict[str, str]:
        """The GL context: backend, device, gl_renderer (GL_RENDERER) and gl_version (creates it if needed)."""
        return self._core.context_info()

    @property
    def busy(self) -> bool:
        """True while a render runs (readable from other threads: the GIL is released meanwhile)."""
        return self._core.busy

    def close(self) -> None:
        """Frees the GL objects now; a later render starts afresh."""
        self._core.close()

    def __enter__(self) -> Renderer:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


_default: Renderer | None = None
_default_lock = _thread.allocate_lock()  # _thread, not threading: import costs count (bench/README.md)


def default_renderer() -> Renderer:
    """The Renderer that shadelab.render() and Scene.render use, made on first use."""
    global _default
    with _default_lock:
        if _default is None:
            _default = Renderer._around(_rendering.default_core())
        return _default


def render(scene: SceneLike, size: Size = DEFAULT_SIZE, *, renderer: RendererName = "raster",
           spp: int | None = None, encoding: EncodingName = "srgb", depth: int | None = None, threads: int = 0,
           coverage: bool = False, time_limit: float | None = None, estimator: EstimatorName | None = None,
           light_paths: LightPathsName | None = None, sampler: SamplerName | None = None, denoise: bool = False,
           max_memory: MemorySize | None = None, exposure: float | None = None,
           view_transform: ViewTransformName | None = None, seed: int | None = None) -> _shadelab.Image:
    """Renders `scene` with the default Renderer (default_renderer()) to a shadelab.Image.

    scene: a Scene, a scene file's path (.json, or a .gltf / .glb model framed and lit as the binary does)
        or a dict in the scene file's schema.
    size: (width, height) or "WxH", each side 1..16384 pixels; default (1280, 720), the binary's --size.
    renderer: "raster" (default: OpenGL), "trace" (the CPU Whitted ray tracer, the reference) or "path" (the
        path tracer: global illumination, ambient term off). The binary's --renderer.
    spp: samples per pixel; default None: 1, and 16 for "path", as the binary. For "raster" and "trace" a
        perfect square from 1 to 64 (1, 4, 9, ..., the k x k grid both share); for "path" any count from 1 to
        1048576. The binary's --spp.
    encoding: "srgb" (default) or "linear": how the 8-bit pixels (image.to_uint8(), save(), the PNG) encode
        the linear floats; np.asarray(image) is linear either way. The binary's --encoding.
    depth: the tracers' secondary-ray depth, 0..64 (0: primary rays only; for "path" the bounces after the
        camera hit, 0: direct light only); default None, the scene's maxDepth. The rasterizer reflects once
        and ignores it. The binary's --depth.
    threads: the tracers' worker threads, 0..1024; default 0, every core. The path tracer's image is the same
        for any count; the rasterizer ignores it. The binary's --threads.
    coverage: also record per-pixel object ids (image.coverage, uint32, 0 = background), which compare()
        uses to mask silhouettes; default False.
    time_limit: "path" only: stop after the last whole sample pass begun within this many seconds, 0.001..1e7;
        default None, no limit. The binary's --time-limit.
    estimator: "path" only: how emitters' light is sampled, "mis", "bsdf" or "light" (all converge to the
        same image, with different noise); default None, "mis". The binary's --estimator.
    light_paths: "path" only: which light reaches the image, "all", "direct" or "indirect" (what the ambient
        term stands in for); default None, "all". The binary's --light-paths.
    sampler: "path" only: where the random numbers come from, "sobol" (Owen-scrambled Sobol points,
        stratified in each pixel: less noise at equal samples) or "independent" (plain Monte Carlo); both
        converge to the same image; default None, "sobol". The binary's --sampler.
    denoise: "path" only: the denoised preview instead of the raw estimate (an edge-avoiding filter guided by
        the first hit's albedo, normal and depth; the binary's --denoise); default False.
    seed: "path" only: the random numbers' variation, a whole number 0..4294967295: the same seed gives the
        same image byte for byte, another seed another noise; default None, 0 (the image without a seed). The
        binary's --seed. Given to another renderer, any of these six raises ValueError.
    max_memory: the most memory the render may take: an int of bytes, or a string as the binary's --max-memory
        reads it ("512M", "2G"; a bare number in a string is MiB); default None, the binary's default, half of
        physical memory (within ulimit -v). A render estimated to need more raises shadelab.InputError before
        any pixel is drawn, as does the environment map of a scene given as a path or a dict; a limit below
        what any render of this size and renderer needs raises ValueError.
    exposure: stops, -16..16: the 8-bit pixels show the linear values times 2^exposure; default None, the scene's
        display.exposure (0 when it has none). The binary's --exposure.
    view_transform: "standard" (clamp to [0, 1]) or "filmic" (Narkowicz's ACES fit: highlights roll off instead
        of clipping), applied after the exposure and before the encoding; default None, the scene's
        display.viewTransform ("standard"). The binary's --view-transform. Both change only the 8-bit pixels;
        np.asarray(image) and probe() read the linear floats, and compare() compares the 8-bit pixels as they
        are, so compare renderers with the default display.

    With the same options the pixels equal `shadelab render`'s PNG, byte for byte. A value out of range
    raises ValueError naming the argument, a value of the wrong type TypeError naming it; an unknown keyword
    raises TypeError.
    """
    return default_renderer().render(scene, size, renderer=renderer, spp=spp, encoding=encoding, depth=depth,
                                     threads=threads, coverage=coverage, time_limit=time_limit,
                                     estimator=estimator, light_paths=light_paths, sampler=sampler, denoise=denoise,
                                     max_memory=max_memory, exposure=exposure, view_transform=view_transform,
                                     seed=seed)


def probe(
    scene: SceneLike, pixel: Sequence[SupportsInt], size: Size = DEFAULT_SIZE, ray_tree: bool = False
) -> dict[str, Any]:
    """The lighting probe at `pixel` = (x, y) (row 0 at the top) of a `size` image: what the primary ray hits,
    N, V, and per light L, R, H, every dot product and term for Phong and Blinn-Phong, as a dict (the viewer's
    probe report, docs/viewer.md). With `ray_tree`, also the Whitted ray tree the reference traces from the
    pixel (report["ray_tree"]["rays"]: each ray's kind, parent, origin, direction, t and hit object, and for a
    shadow ray its light and whether it is blocked). Asks the tracer; needs no GL context."""
    handle = _scene(scene)._handle
    width, height = parse_size(size)
    try:
        x, y = (int(v) for v in pixel)
    except (TypeError, ValueError, OverflowError):
        raise ValueError(f"pixel: expected (x, y), two numbers int() takes, got {pixel!r}") from None
    clamp = _checks.Clamp()  # in the order the probe words them: size, then the pixel
    width, height = clamp(width), clamp(height)
    report: dict[str, Any] = _checks.call(
        clamp, _shadelab._probe, handle, clamp(x), clamp(y), width, height, bool(ray_tree)
    )
    return report
