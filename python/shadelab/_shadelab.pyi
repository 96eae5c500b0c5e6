# The compiled module's interface for type checkers (PEP 561): every class, function and attribute that
# src/python/module.cpp and bind_*.cpp define, with the signatures pybind11 gives them. Functions bound without
# named arguments take theirs by position only (pybind11 calls them arg0, arg1, ...); defaults are the bindings'.
# tests/python/test_typing.py checks this file against the built module (stubtest, and every name and signature
# of its __doc__ lines). Names starting with _ are the package's plumbing; use the shadelab package.

from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ._types import EncodingName, ExrPrecisionName, MemorySize, StrPath

class InputError(ValueError):
    """Bad input (a scene field, a file): the message names the file and the JSON path, as the binary's."""

class ContextError(RuntimeError):
    """No headless GL context could be made: the message lists every backend tried and why it failed."""

# The build: version, build_type (CMAKE_BUILD_TYPE) and sanitize (e.g. "address,undefined"; "" for none).
build_info: dict[str, str]

# design.md §4's gates under the JSON report's names: threshold 3, max_fraction_over 0.001, hard_max 16,
# max_silhouette_fraction 0.02, max_mean None (no gate).
default_gates: dict[str, float | None]

class Image:
    """A rendered (or read) image: linear floats (np.asarray, read-only float32 (H, W, 3)) and 8-bit pixels."""

    @property
    def width(self) -> int: ...
    @property
    def height(self) -> int: ...
    @property
    def size(self) -> tuple[int, int]:
        """(width, height), as render(size=...) takes it."""
    @property
    def shape(self) -> tuple[int, int, int]:
        """(H, W, 3): the shape of np.asarray(image)."""
    @property
    def encoding(self) -> EncodingName: ...
    @property
    def source(self) -> str:
        """'raster', 'trace', 'path', 'file' or 'array'."""
    @property
    def coverage(self) -> NDArray[np.uint32] | None:
        """Per-pixel object ids (uint32, (H, W); 0 = background) when rendered with coverage=True, else None."""
    @property
    def timings(self) -> dict[str, float]:
        """draw_ms and read_ms: milliseconds of the render and of its readback and conversion."""
    @property
    def non_finite_pixels(self) -> int:
        """Pixels whose linear value had a NaN or an infinity (written black or white); render warns when > 0."""
    @property
    def _non_finite_message(self) -> str: ...
    @property
    def exposure(self) -> float:
        """Stops the 8-bit pixels were exposed by (the render's exposure, else the scene's; 0 for a file)."""
    @property
    def view_transform(self) -> str:
        """The view transform the 8-bit pixels were made with: 'standard' or 'filmic'."""
    def to_uint8(self) -> NDArray[np.uint8]:
        """The 8-bit pixels, shape (H, W, 3) (or 4 for an RGBA file), a new array."""
    def to_srgb(self) -> NDArray[np.float32]:
        """Display-ready sRGB floats in [0, 1], float32 (H, W, 3), a new array: the linear floats through the
        image's exposure and view transform, the clamp and the sRGB curve, the PNG's steps before rounding."""
    def to_png(self) -> bytes:
        """The PNG file's bytes."""
    def _repr_png_(self) -> bytes: ...
    def __repr__(self) -> str: ...
    def save(self, path: StrPath, exr_precision: ExrPrecisionName | None = None) -> None:
        """Writes atomically: a path ending in .exr the linear floats as OpenEXR (exr_precision "float", the
        default, or "half"), any other the PNG (the bytes `shadelab render -o` writes); OSError naming the file."""
    @staticmethod
    def open(path: StrPath, encoding: EncodingName = "srgb") -> Image:
        """Reads a PNG (np.asarray: its pixels decoded with `encoding`'s curve) or an OpenEXR file (.exr:
        np.asarray its linear floats; the 8-bit pixels encoded with `encoding`)."""
    @staticmethod
    def from_array(array: ArrayLike, encoding: EncodingName = "srgb") -> Image:
        """uint8 (H, W, 3|4): the pixels as they are; float (H, W, 3|4): linear RGB, encoded with `encoding`."""
    def __getstate__(self) -> tuple[int, int, int, bytes, bytes, str, str, bytes, float, float, float, str]: ...
    def __setstate__(self, state: tuple[int, int, int, bytes, bytes, str, str, bytes, float, float, float, str], /
                     ) -> None:
        """Checks every field (sizes 1..16384, 3 or 4 channels, each buffer's exact length, the encoding,
        source and view transform words, the exposure's range) and raises ValueError, one line, for a state no
        Image could have written. A 10-item state (without the display) is read as Standard."""

class _Scene:
    """A scene as the compiled scene reader holds it (shadelab.Scene's handle)."""

    @staticmethod
    def load(path: str, allow_external_paths: bool = False, max_memory: int = 0) -> tuple[_Scene, list[str]]:
        """A scene file or glTF model, with the reader's warnings; max_memory (bytes, 0: none) holds its
        environment map's load to render(max_memory=...)'s limit."""
    @staticmethod
    def from_document(document: dict[str, Any], base_dir: str, allow_external_paths: bool = False,
                      max_memory: int = 0) -> tuple[_Scene, list[str]]:
        """A scene from a document in the scene file's schema, with the reader's warnings."""
    def replace(self, document: dict[str, Any], reject_unknown_fields: bool = False) -> tuple[bool, list[str]]:
        """Parses `document` as a scene file: (replaced, warnings); the scene is unchanged when it raises."""
    def to_json(self) -> str: ...
    def to_document(self) -> dict[str, Any]: ...
    def save(self, path: str, /) -> None: ...
    def copy(self) -> _Scene: ...
    def layers_not_shown(self) -> str:
        """glTF's layers that objects carry but their model does not shade (only pbr does), "" for none."""
    @property
    def base_dir(self) -> str: ...
    @property
    def allow_external_paths(self) -> bool: ...
    @property
    def triangles(self) -> int: ...

class _Renderer:
    """The compiled renderer behind shadelab.Renderer: one GL context's programs and the tracers' caches."""

    def __init__(self, backend: str = "auto") -> None: ...
    def render(self, scene: _Scene, width: int, height: int, renderer: str = "raster", spp: int | None = None,
               encoding: str = "srgb", depth: int | None = None, threads: int = 0, coverage: bool = False,
               time_limit: float | None = None, estimator: str | None = None, light_paths: str | None = None,
               sampler: str | None = None, denoise: bool = False, max_memory: int | None = None,
               exposure: float | None = None, view_transform: str | None = None, seed: int | None = None) -> Image: ...
    def context_info(self) -> dict[str, str]: ...
    def close(self) -> None: ...
    @property
    def busy(self) -> bool: ...

def _probe(scene: _Scene, x: int, y: int, width: int, height: int, ray_tree: bool = False) -> dict[str, Any]: ...
def _memory_limit(max_memory: MemorySize | None) -> int:
    """The limit in bytes that render(max_memory=...) means: None, the command line's default; bytes; "512M"."""
def _compare(a: Image, b: Image, threshold: int = 3, max_fraction_over: float = 0.001, hard_max: int = 16,
             max_silhouette_fraction: float = 0.02, max_mean: float | None = None, gain: int = 16, name_a: str = "",
             name_b: str = "") -> tuple[dict[str, Any], str, Image, bool]: ...

# Files the package writes, under the binary's output rules (atomic, never over an input, no device stems).
def _write_file(path: str, data: bytes) -> None: ...
def _derived_output(stem: str, suffix: str) -> str: ...

# The lighting equations over rows: vectors (n, 3), scalars (n,), float32 (shadelab.lighting broadcasts).
def _phong(N: ArrayLike, L: ArrayLike, V: ArrayLike, s: ArrayLike, /) -> NDArray[np.float32]: ...
def _blinn_phong(N: ArrayLike, L: ArrayLike, V: ArrayLike, s: ArrayLike, /) -> NDArray[np.float32]: ...
def _reflect_light(N: ArrayLike, L: ArrayLike, /) -> NDArray[np.float32]: ...
def _pbr(N: ArrayLike, L: ArrayLike, V: ArrayLike, base_color: ArrayLike, metallic: ArrayLike, roughness: ArrayLike,
         /) -> NDArray[np.float32]: ...
def _shade(N: ArrayLike, L: ArrayLike, V: ArrayLike, Il: ArrayLike, md: ArrayLike, ms: ArrayLike, s: ArrayLike,
           model: str, diffuse: bool, specular: bool, /) -> NDArray[np.float32]: ...
def _disney(N: ArrayLike, L: ArrayLike, V: ArrayLike, Il: ArrayLike, base_color: ArrayLike, metallic: ArrayLike,
            roughness: ArrayLike, params: list[NDArray[np.float32]], diffuse: bool, specular: bool,
            /) -> NDArray[np.float32]: ...
