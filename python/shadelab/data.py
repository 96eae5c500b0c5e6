"""shadelab.data: the scenes that ship with the package, and the models and sky they reference.

    scene = shadelab.data.scene("default")      # assets/scenes/default.json, loaded
    shadelab.data.scenes()                      # ['cornell', 'default', ...]: every name scene() takes
    shadelab.data.path("torus")                 # the scene file itself, a pathlib.Path

The files lie inside the package (shadelab/assets/: scenes/, models/, environments/, as in the repository's
assets/ folder, so the scenes' relative paths to their models and sky hold), copied there by the build tree's
CMake and by `pip install .`. Code that uses them runs from any folder.
"""

from __future__ import annotations

import os

from .scene import Scene

# The package's copy of the repository's assets/: src/python/CMakeLists.txt and setup.py copy the same folders.
_ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "assets")
_SCENES = os.path.join(_ROOT, "scenes")

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing; mypy treats the name as True
if TYPE_CHECKING:
    from pathlib import Path


def folder() -> Path:
    """The package's assets folder: scenes/, models/ (torus.gltf, textures/), environments/ (sky.hdr)."""
    from pathlib import Path

    return Path(_ROOT)


def scenes() -> list[str]:
    """The names of the shipped scenes, sorted: each scene file's name without .json."""
    try:
        files = os.listdir(_SCENES)
    except FileNotFoundError:
        raise FileNotFoundError(f"shadelab.data: the package has no scenes folder ({_SCENES}); reinstall it "
                                f"(pip install .) or rebuild the build tree") from None
    return sorted(f[:-len(".json")] for f in files if f.endswith(".json") and not f.startswith("."))


def path(name: str) -> Path:
    """The shipped scene file `name` (a name from scenes(), e.g. "default"). An unknown name is a ValueError
    that lists the names; a name that is no string, a TypeError."""
    from pathlib import Path

    if not isinstance(name, str):
        raise TypeError(f"shadelab.data: a scene name must be a string, got {type(name).__name__}")
    names = scenes()
    if name not in names:  # also refuses "../x", "default.json" and "": only the listed names are files
        hint = f"; without .json: {name[:-len('.json')]!r}" if name.endswith(".json") else ""
        raise ValueError(f"shadelab.data: no shipped scene {name!r}{hint}; the scenes are {', '.join(names)}")
    return Path(_SCENES, name + ".json")


def scene(name: str) -> Scene:
    """The shipped scene `name`, loaded (Scene.load of path(name)): a new, independent Scene on each call."""
    return Scene.load(path(name))
