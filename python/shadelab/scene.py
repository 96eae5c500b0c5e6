"""shadelab.Scene: a scene as the scene file describes it (docs/scene-format.md), editable by attribute.

Every edit builds the whole document anew and hands it to the compiled scene reader, the one that reads
scene files: the same schema, the same name tables (``scene.model = "blinn"`` reads back "blinn-phong") and
the same messages, raised as ``ValueError`` naming the JSON path (``lights[2].color: expected 3 numbers,
got 2``). A rejected edit leaves the scene as it was. Meshes whose source, transform and material are
unchanged keep their imported triangles.

Objects are listed as the scene file is saved: spheres, then planes, then meshes (``to_dict()`` shows the
order). ``scene.objects[0]`` and friends are views by position, not copies: they read the current scene.
"""

from __future__ import annotations

import os
from collections.abc import MutableSequence

from . import _checks, _rendering, _shadelab, _warnings
from ._rendering import DEFAULT_SIZE

TYPE_CHECKING = False  # typing.TYPE_CHECKING without importing typing; mypy treats the name as True
if TYPE_CHECKING:
    from typing import Any, Callable, ClassVar, Iterable, Union

    from ._types import (EncodingName, EstimatorName, LightPathsName, MemorySize, RendererName, SamplerName, Size,
                         StrPath, ViewTransformName)

    # Where a value sits in the document: field names and list indices from the top ("lights", 2, "color").
    _Path = tuple[Union[str, int], ...]
    _ListBase = MutableSequence[Any]
else:
    _ListBase = MutableSequence

# Lists of objects in the document; every other list is a vector or a matrix and reads as a tuple.
_CONTAINERS = ("lights", "objects")


def _warn(lines: Iterable[str], stacklevel: int) -> None:
    _warnings.warn(lines, stacklevel + 1)


def _plain(value: Any) -> Any:
    """A value as JSON data: views become their dicts, numpy arrays and scalars plain lists and numbers."""
    if isinstance(value, (_Node, Scene)):
        return value.to_dict()
    if isinstance(value, (list, tuple)):
        return [_plain(v) for v in value]
    if isinstance(value, dict):
        return {k: _plain(v) for k, v in value.items()}
    tolist = getattr(value, "tolist", None)  # numpy arrays and scalars
    if tolist is not None and not isinstance(value, (str, bytes)):
        return _plain(tolist())
    return value


def _path_text(path: _Path) -> str:
    text = ""
    for key in path:
        text += f"[{key}]" if isinstance(key, int) else (("." if text else "") + key)
    return text or "scene"


def _deepcopy(value: Any) -> Any:
    import copy  # on first edit: `import shadelab` stays quick for a fresh process's first render

    return copy.deepcopy(value)


def _walk(doc: Any, path: _Path) -> Any:
    for key in path:
        doc = doc[key]
    return doc


class _View:
    """What the scene and the views of its parts share: the fields of their part of the document read as
    attributes and as items, under their JSON names."""

    __slots__ = ()

    if TYPE_CHECKING:
        _path: _Path

        @property
        def _scene(self) -> Scene: ...

    def _value(self) -> Any:
        return _walk(self._scene._document(), self._path)

    def __getattr__(self, name: str) -> Any:
        if name.startswith("_"):
            raise AttributeError(name)
        value = self._value()
        if name not in value:
            raise AttributeError(f"{_path_text(self._path)} has no field '{name}'; it has: {', '.join(value)}")
        return self._scene._wrap(self._path + (name,), value[name])

    __getitem__ = __getattr__

    def __contains__(self, name: object) -> bool:
        return bool(name in self._value())

    def __dir__(self) -> list[str]:
        return list(self._value())

    def keys(self) -> list[str]:
        """The field names, as the scene file writes them."""
        return list(self._value())


class _Node(_View):
    """A view of one object in the scene's document (the camera, a light, a material, ...), by path."""

    __slots__ = ("_scene", "_path")

    _scene: Scene  # a slot here; Scene is its own view, through a property

    def __init__(self, scene: Scene, path: _Path) -> None:
        object.__setattr__(self, "_scene", scene)
        object.__setattr__(self, "_path", path)

    def __setattr__(self, name: str, value: Any) -> None:
        if name.startswith("_"):
            raise AttributeError(f"cannot set {name}")
        self._scene._set(self._path + (name,), value)

    __setitem__ = __setattr__

    def __delattr__(self, name: str) -> None:
        self._scene._edit(self._path, lambda node: node.pop(name))

    def to_dict(self) -> dict[str, Any]:
        """A copy of this part of the document."""
        return _deepcopy(self._value())  # type: ignore[no-any-return]

    def __eq__(self, other: object) -> bool:
        if isinstance(other, (_Node, dict)):
            return bool(self.to_dict() == _plain(other))
        return NotImplemented

    __hash__: ClassVar[None] = None  # type: ignore[assignment]

    def __repr__(self) -> str:
        import json

        return f"<shadelab {_path_text(self._path)}: {json.dumps(self._value())}>"


class _List(_ListBase):
    """A view of the scene's lights or objects: indexing gives views, edits re-read the whole scene."""

    __slots__ = ("_scene", "_path")

    def __init__(self, scene: Scene, path: _Path) -> None:
        self._scene = scene
        self._path = path

    def _value(self) -> list[Any]:
        return _walk(self._scene._document(), self._path)  # type: ignore[no-any-return]

    def _index(self, i: Any) -> int:
        n = len(self)
        if not isinstance(i, int):
            raise TypeError(f"{_path_text(self._path)} indices must be integers, not {type(i).__name__}")
        if i < -n or i >= n:
            raise IndexError(f"{_path_text(self._path)}[{i}]: there are {n}")
        return i % n

    def __len__(self) -> int:
        return len(self._value())

    # Any, not MutableSequence's overloads on int and slice: a slice gives a list of views.
    def __getitem__(self, i: Any) -> Any:
        if isinstance(i, slice):
            return [self[k] for k in range(*i.indices(len(self)))]
        i = self._index(i)
        return self._scene._wrap(self._path + (i,), self._value()[i])

    def __setitem__(self, i: Any, value: Any) -> None:
        self._scene._set(self._path + (self._index(i),), value)

    def __delitem__(self, i: Any) -> None:
        if isinstance(i, slice):
            self._scene._edit(self._path, lambda items: items.__delitem__(i))
        else:
            i = self._index(i)
            self._scene._edit(self._path, lambda items: items.pop(i))

    def insert(self, i: int, value: Any) -> None:
        value = _plain(value)
        self._scene._edit(self._path, lambda items: items.insert(i, value))

    # MutableSequence's pop, reverse and clear work through views by position, which an edit moves: its pop
    # returned a view of the entry that slid into the removed one's place (or of none, for the last), and its
    # reverse copied views it had already overwritten. These edit the list in one step instead.
    def pop(self, index: int = -1) -> Any:
        """Removes the entry at `index` (default: the last) and returns it as a dict: a copy that stays
        valid, as to_dict() gives (append or insert it to put it back)."""
        i = self._index(index)
        removed = _deepcopy(self._value()[i])
        self._scene._edit(self._path, lambda items: items.pop(i))
        return removed

    def reverse(self) -> None:
        self._scene._edit(self._path, lambda items: items.reverse())

    def clear(self) -> None:
        self._scene._edit(self._path, lambda items: items.clear())

    def to_list(self) -> list[Any]:
        """A copy of the list."""
        return _deepcopy(self._value())  # type: ignore[no-any-return]

    def __eq__(self, other: object) -> bool:
        if isinstance(other, (_List, list)):
            return bool(self.to_list() == _plain(list(other) if isinstance(other, _List) else other))
        return NotImplemented

    __hash__: ClassVar[None] = None  # type: ignore[assignment]

    def __repr__(self) -> str:
        return f"<shadelab {_path_text(self._path)}: {len(self)} entries>"


class Scene(_View):
    """A scene: load it from a file or a dict, edit it by attribute, render it.

    >>> scene = Scene.load("assets/scenes/default.json")
    >>> scene.model = "blinn-phong"
    >>> scene.terms.shadows = False
    >>> scene.lights.append({"type": "point", "position": [0, 4, 2], "color": [1, 1, 1]})

    Fields read and write as attributes (and items) typed Any: the scene file's schema decides them at run
    time (docs/scene-format.md).
    """

    __slots__ = ("_handle", "_doc")

    _handle: _shadelab._Scene
    _doc: dict[str, Any] | None

    def __init__(self, *args: object, **kwargs: object) -> None:
        raise TypeError("use Scene.load(path) or Scene.from_dict(d)")

    @classmethod
    def _from_handle(cls, handle: _shadelab._Scene, lines: Iterable[str] = ()) -> Scene:
        scene = object.__new__(cls)
        object.__setattr__(scene, "_handle", handle)
        object.__setattr__(scene, "_doc", None)
        _warn(lines, stacklevel=3)  # the caller of load() or from_dict()
        return scene

    @classmethod
    def load(cls, path: StrPath, *, allow_external_paths: bool = False) -> Scene:
        """Reads a scene file (.json) or a glTF model (.gltf, .glb: framed and lit, as the binary does).
        allow_external_paths: let glTF buffer URIs point outside the model's folder (the binary's
        --allow-external-paths; default False, so that a model from elsewhere cannot read arbitrary files)."""
        handle, lines = _shadelab._Scene.load(_checks.path("path", path),
                                              _checks.flag("allow_external_paths", allow_external_paths))
        return cls._from_handle(handle, lines)

    @classmethod
    def from_dict(cls, document: dict[str, Any], *, base_dir: StrPath | None = None,
                  allow_external_paths: bool = False) -> Scene:
        """A scene from a dict in the scene file's schema. Mesh sources are relative to `base_dir` (default:
        the current folder). Raises ValueError naming the JSON path, as the scene file's errors do."""
        base = _checks.path("base_dir", base_dir) if base_dir is not None else os.getcwd()
        handle, lines = _shadelab._Scene.from_document(_plain(document), base,
                                                       _checks.flag("allow_external_paths", allow_external_paths))
        return cls._from_handle(handle, lines)

    def to_dict(self) -> dict[str, Any]:
        """The whole description, every field written (as `save` writes it): from_dict(to_dict()) is exact."""
        return _deepcopy(self._document())  # type: ignore[no-any-return]

    def save(self, path: StrPath) -> None:
        """Writes the scene file atomically. Mesh sources are written as they are (relative to base_dir)."""
        self._handle.save(os.fspath(path))

    def copy(self) -> Scene:
        """An independent copy (mesh triangles are shared, never copied)."""
        return Scene._from_handle(self._handle.copy())

    __copy__ = copy

    def __deepcopy__(self, memo: object) -> Scene:
        return self.copy()

    def __reduce__(self) -> tuple[Callable[[dict[str, Any], str, bool], Scene], tuple[dict[str, Any], str, bool]]:
        return (_scene_from_state, (self.to_dict(), self._handle.base_dir, self._handle.allow_external_paths))

    @property
    def base_dir(self) -> str:
        """The folder mesh sources are relative to."""
        return self._handle.base_dir

    @property
    def triangle_count(self) -> int:
        """The triangles of all the scene's meshes."""
        return self._handle.triangles

    def render(self, size: Size = DEFAULT_SIZE, *, renderer: RendererName = "raster", spp: int | None = None,
               encoding: EncodingName = "srgb", depth: int | None = None, threads: int = 0,
               coverage: bool = False, time_limit: float | None = None, estimator: EstimatorName | None = None,
               light_paths: LightPathsName | None = None, sampler: SamplerName | None = None, denoise: bool = False,
               max_memory: MemorySize | None = None, exposure: float | None = None,
               view_transform: ViewTransformName | None = None, seed: int | None = None) -> _shadelab.Image:
        """shadelab.render(self, size, ...): renders this scene with the default Renderer. The keywords, their
        ranges and defaults are shadelab.render's: renderer="raster" ("trace", "path"), spp=None (1; 16 for
        path), encoding="srgb" ("linear"), depth=None (the scene's maxDepth), threads=0 (every core),
        coverage=False, for path time_limit=None, estimator=None ("mis"), light_paths=None ("all"), sampler=None
        ("sobol"), denoise=False and seed=None (0), max_memory=None (the binary's --max-memory default; bytes, or "512M"), and
        exposure=None and view_transform=None (the scene's display: -16..16 stops, "standard" or "filmic")."""
        return _rendering.render_handle(_rendering.default_core(), self._handle, size, renderer, spp, encoding,
                                        depth, threads, coverage, time_limit, estimator, light_paths, sampler, denoise,
                                        None if max_memory is None else _rendering.memory_limit(max_memory),
                                        exposure, view_transform, seed)

    # -- the document and its edits -------------------------------------------------------------------------

    def _document(self) -> dict[str, Any]:
        doc = self._doc
        if doc is None:
            doc = self._handle.to_document()
            object.__setattr__(self, "_doc", doc)
        return doc

    def _wrap(self, path: _Path, value: Any) -> Any:
        if isinstance(value, dict):
            return _Node(self, path)
        if isinstance(value, list):
            return _List(self, path) if len(path) == 1 and path[0] in _CONTAINERS else tuple(value)
        return value

    def _commit(self, document: dict[str, Any], strict: bool) -> None:
        replaced, lines = self._handle.replace(document, strict)
        if not replaced:
            unknown = next(line for line in lines if "unknown field '" in line)
            raise AttributeError(unknown.replace(" (ignored)", ""))
        object.__setattr__(self, "_doc", None)
        _warn(lines, stacklevel=4)  # the statement that made the edit

    def _edit(self, path: _Path, change: Callable[[Any], object]) -> None:
        """Applies change(node) to a copy of the node at `path` of the document, then re-reads the scene."""
        document = _deepcopy(self._document())
        change(_walk(document, path))
        self._commit(document, strict=False)

    def _set(self, path: _Path, value: Any) -> None:
        document = _deepcopy(self._document())
        parent = _walk(document, path[:-1])
        parent[path[-1]] = _plain(value)
        # A material's field derived from the other model's (its "derived" list) is given once it is set: the
        # fields derived from it then follow it (docs/scene-format.md, "Materials under each model").
        derived = parent.get("derived") if len(path) >= 2 and path[-2] == "material" else None
        if isinstance(derived, list) and path[-1] in derived:
            derived.remove(path[-1])
        self._commit(document, strict=True)

    # The top level reads and writes as any view does.
    _path = ()

    @property
    def _scene(self) -> Scene:
        return self

    def __setattr__(self, name: str, value: Any) -> None:
        if name.startswith("_") or name in ("base_dir", "triangle_count"):
            raise AttributeError(f"cannot set {name}")
        self._set((name,), value)

    __setitem__ = __setattr__

    def __eq__(self, other: object) -> bool:
        if isinstance(other, Scene):
            return self.to_dict() == other.to_dict()
        return NotImplemented

    __hash__: ClassVar[None] = None  # type: ignore[assignment]

    def __repr__(self) -> str:
        d = self._document()
        return (f"<shadelab.Scene {d.get('title', '')!r}: {d['model']}, {len(d['lights'])} light(s), "
                f"{len(d['objects'])} object(s)>")


def _scene_from_state(document: dict[str, Any], base_dir: str, allow_external_paths: bool) -> Scene:
    return Scene.from_dict(document, base_dir=base_dir, allow_external_paths=allow_external_paths)
