"""The type aliases of the package's signatures that name no shadelab class: the words each string argument
accepts and the shapes of sizes and paths. Published as shadelab.typing, with SceneLike and ImageLike.

The package's own modules import this one only for the type checker (under TYPE_CHECKING), so `import
shadelab` does not import `typing` (import costs count: bench/README.md).
"""

import os
from typing import Literal, Sequence, SupportsInt, Union

# A file's path, as open() takes it.
StrPath = Union[str, os.PathLike[str]]

# An image size: (width, height), two numbers int() takes, or the binary's "WxH" text ("640x360").
Size = Union[str, Sequence[SupportsInt]]

# render(max_memory=...): a number of bytes, or a size as the binary's --max-memory writes it ("512M", "2G";
# a bare number in a string is MiB, as on the command line).
MemorySize = Union[int, str]

# render(renderer=...): the rasterizer (OpenGL), the Whitted ray tracer, the path tracer (the binary's --renderer).
RendererName = Literal["raster", "trace", "path"]

# render(estimator=...): how the path tracer samples emitters' light (the binary's --estimator).
EstimatorName = Literal["mis", "bsdf", "light"]

# render(light_paths=...): which light the path tracer lets reach the image (the binary's --light-paths).
LightPathsName = Literal["all", "direct", "indirect"]

# render(sampler=...): where the path tracer's random numbers come from (the binary's --sampler).
SamplerName = Literal["sobol", "independent"]

# How the 8-bit pixels and the PNG encode the linear floats (the binary's --encoding).
EncodingName = Literal["srgb", "linear"]

# Image.save("x.exr", exr_precision=...): 32-bit float samples (exact) or 16-bit half (the binary's --exr-precision).
ExrPrecisionName = Literal["half", "float"]
# render(view_transform=...): how linear values map into [0, 1] before the encoding: "standard" clamps,
# "filmic" is Narkowicz's ACES fit (the binary's --view-transform).
ViewTransformName = Literal["standard", "filmic"]

# Renderer(backend=...): the headless GL context to make; "auto" tries them in this order, honouring
# SHADELAB_GL_BACKEND (the binary's --gl-backend).
BackendName = Literal["auto", "egl-device", "egl-surfaceless", "osmesa"]

# A shading model as scene files name it; "blinn" is accepted for "blinn-phong".
ModelName = Literal["phong", "blinn-phong", "blinn", "pbr", "disney"]
