"""shadelab for Python: scenes, both renderers, comparisons, the probe and the lighting maths.

A thin package over the compiled module ``shadelab._shadelab``, which links the same libraries as the
``shadelab`` binary: renders are byte-identical to the binary's PNGs and scene errors read as the scene
file's. It holds no rendering code of its own (design.md §5). See docs/python.md.

    import shadelab
    scene = shadelab.data.scene("default")      # a shipped scene; Scene.load(path) reads your own
    scene.objects[0].material.s = 64
    image = shadelab.render(scene, size=(640, 360))
    image.save("out.png")

Importing the package does not import numpy; np.asarray(image) and shadelab.lighting do. The package is
typed (py.typed; the compiled module's signatures are in _shadelab.pyi); shadelab.typing has the aliases
its signatures use, for annotating code that calls it.
"""

from __future__ import annotations

from . import _shadelab
from ._shadelab import ContextError, Image, InputError
from ._warnings import ShadelabWarning
from .compare import CompareReport, compare, default_gates
from .render import Renderer, default_renderer, probe, render
from .scene import Scene

__version__ = _shadelab.build_info["version"]
build_info: dict[str, str] = dict(_shadelab.build_info)

__all__ = [
    "CompareReport",
    "ContextError",
    "Image",
    "InputError",
    "Renderer",
    "Scene",
    "ShadelabWarning",
    "build_info",
    "compare",
    "data",
    "default_gates",
    "default_renderer",
    "lighting",
    "plots",
    "probe",
    "render",
]


TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing; mypy treats the name as True
if TYPE_CHECKING:
    from types import ModuleType


def __getattr__(name: str) -> ModuleType:
    # shadelab.lighting and shadelab.plots import numpy, shadelab.typing imports typing, shadelab.data lists
    # the shipped scenes: each is loaded on first use, so `import shadelab` stays light. (shadelab.typing stays
    # out of __all__: a star import would shadow the standard library's typing.)
    if name in ("data", "lighting", "plots", "typing"):
        import importlib

        return importlib.import_module("." + name, __name__)
    raise AttributeError(f"module 'shadelab' has no attribute '{name}'")
