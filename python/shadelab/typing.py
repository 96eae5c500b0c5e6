"""Type aliases for annotating code that uses shadelab (mypy, pyright); the package's own signatures use them.

    from shadelab.typing import RendererName, SceneLike

    def render_all(scenes: list[SceneLike], renderer: RendererName = "trace") -> list[shadelab.Image]: ...

The string arguments are Literal types of the words they accept, so a checker catches `renderer="trac"`; a
plain `str` variable needs one of these aliases (or typing.cast) to be passed on. Importing this module
imports typing and numpy.typing; `import shadelab` imports neither.
"""

from typing import Any, Dict, Union

import numpy.typing as npt

from ._shadelab import Image
from ._types import (BackendName, EncodingName, EstimatorName, ExrPrecisionName, LightPathsName, MemorySize, ModelName,
                     RendererName, SamplerName, Size, StrPath, ViewTransformName)
from .scene import Scene

# What render(), Renderer.render() and probe() take as a scene: a Scene, a scene file's or glTF model's path,
# or a dict in the scene file's schema.
SceneLike = Union[Scene, StrPath, Dict[str, Any]]

# What compare() and the pytest plugin's check() take as an image: an Image, a PNG file's path, or an array
# (uint8 levels as they are, floats as linear RGB).
ImageLike = Union[Image, StrPath, npt.ArrayLike]

__all__ = ["BackendName", "EncodingName", "EstimatorName", "ExrPrecisionName", "ImageLike", "LightPathsName",
           "MemorySize", "ModelName", "RendererName", "SamplerName", "SceneLike", "Size", "StrPath",
           "ViewTransformName"]
