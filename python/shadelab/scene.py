"""shadelab.Scene: a scene as the scene file describes it (docs/scene-format.md), editable by attribute.

Every edit builds the whole document anew and hands it to the compiled scene reader, the one that reads
scene files: the same schema, the same name tables (``scene.model = "blinn"`` reads back "blinn-phong") and
the same messages, raised as ``ValueError`` naming the JSON path (``lights[2].color: expected 3 numbers,
got 2``). A rejected edit leaves the scene as it was. Meshes whose source, transform and material are
unchanged keep their imported triangles.

Objects are listed as the scene file is saved: spheres, then planes, then meshes (``to_dict()`` shows the
order). ``scene.objects[0]`` and friends are views by position, not copies: they read the current scene.
"""

import os
import warnings
from collections.abc import MutableSequence

from . import _shadelab

# Lists of objects in the document; every other list is a vector or a matrix and reads as a tuple.
_CONTAINERS = ("lights", "objects")


class ShadelabWarning(UserWarning):
    """A scene reader's warning (an unknown field in a dict, something skipped in a glTF file)."""


def _warn(lines, stacklevel):
    for line in lines:
        warnings.warn(line, ShadelabWarning, stacklevel=stacklevel + 1)


def _plain(value):
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


def _path_text(path):
    text = ""
    for key in path:
        text += f"[{key}]" if isinstance(key, int) else (("." if text else "") + key)
    return text or "scene"


def _deepcopy(value):
    import copy  # on first edit: `import shadelab` stays quick for a fresh process's first render

    return copy.deepcopy(value)


def _walk(doc, path):
    for key in path:
        doc = doc[key]
    return doc


class _Node:
    """A view of one object in the scene's document (the camera, a light, a material, ...), by path."""

    __slots__ = ("_scene", "_path")

    def __init__(self, scene, path):
        object.__setattr__(self, "_scene", scene)
        object.__setattr__(self, "_path", path)

    def _value(self):
        return _walk(self._scene._document(), self._path)

    def __getattr__(self, name):
        if name.startswith("_"):
            raise AttributeError(name)
        value = self._value()
        if name not in value:
            raise AttributeError(f"{_path_text(self._path)} has no field '{name}'; it has: {', '.join(value)}")
        return self._scene._wrap(self._path + (name,), value[name])

    def __setattr__(self, name, value):
        if name.startswith("_"):
            raise AttributeError(f"cannot set {name}")
        self._scene._set(self._path + (name,), value)

    __getitem__ = __getattr__
    __setitem__ = __setattr__

    def __delattr__(self, name):
        self._scene._edit(self._path, lambda node: node.pop(name))

    def __contains__(self, name):
        return name in self._value()

    def __dir__(self):
        return list(self._value())

    def keys(self):
        return list(self._value())

    def to_dict(self):
        """A copy of this part of the document."""
        return _deepcopy(self._value())

    def __eq__(self, other):
        if isinstance(other, (_Node, dict)):
            return self.to_dict() == _plain(other)
        return NotImplemented

    __hash__ = None

    def __repr__(self):
        import json

        return f"<shadelab {_path_text(self._path)}: {json.dumps(self._value())}>"


class _List(MutableSequence):
    """A view of the scene's lights or objects: indexing gives views, edits re-read the whole scene."""

    __slots__ = ("_scene", "_path")

    def __init__(self, scene, path):
        self._scene = scene
        self._path = path

    def _value(self):
        return _walk(self._scene._document(), self._path)

    def _index(self, i):
        n = len(self)
        if not isinstance(i, int):
            raise TypeError(f"{_path_text(self._path)} indices must be integers, not {type(i).__name__}")
        if i < -n or i >= n:
            raise IndexError(f"{_path_text(self._path)}[{i}]: there are {n}")
        return i % n

    def __len__(self):
        return len(self._value())

    def __getitem__(self, i):
        if isinstance(i, slice):
            return [self[k] for k in range(*i.indices(len(self)))]
        i = self._index(i)
        return self._scene._wrap(self._path + (i,), self._value()[i])

    def __setitem__(self, i, value):
        self._scene._set(self._path + (self._index(i),), value)

    def __delitem__(self, i):
        if isinstance(i, slice):
            self._scene._edit(self._path, lambda items: items.__delitem__(i))
        else:
            i = self._index(i)
            self._scene._edit(self._path, lambda items: items.pop(i))

    def insert(self, i, value):
        value = _plain(value)
        self._scene._edit(self._path, lambda items: items.insert(i, value))

    def to_list(self):
        return _deepcopy(self._value())

    def __eq__(self, other):
        if isinstance(other, (_List, list)):
            return self.to_list() == _plain(list(other) if isinstance(other, _List) else other)
        return NotImplemented

    __hash__ = None

    def __repr__(self):
        return f"<shadelab {_path_text(self._path)}: {len(self)} entries>"


class Scene:
    """A scene: load it from a file or a dict, edit it by attribute, render it.

    >>> scene = Scene.load("assets/scenes/default.json")
    >>> scene.model = "blinn-phong"
    >>> scene.terms.shadows = False
    >>> scene.lights.append({"type": "point", "position": [0, 4, 2], "color": [1, 1, 1]})
    """

    __slots__ = ("_handle", "_doc")

    def __init__(self, *args, **kwargs):
        raise TypeError("use Scene.load(path) or Scene.from_dict(d)")

    @classmethod
    def _from_handle(cls, handle, lines=()):
        scene = object.__new__(cls)
        object.__setattr__(scene, "_handle", handle)
        object.__setattr__(scene, "_doc", None)
        _warn(lines, stacklevel=3)  # the caller of load() or from_dict()
        return scene

    @classmethod
    def load(cls, path, *, allow_external_paths=False):
        """Reads a scene file (.json) or a glTF model (.gltf, .glb: framed and lit, as the binary does)."""
        handle, lines = _shadelab._Scene.load(os.fspath(path), allow_external_paths)
        return cls._from_handle(handle, lines)

    @classmethod
    def from_dict(cls, document, *, base_dir=None, allow_external_paths=False):
        """A scene from a dict in the scene file's schema. Mesh sources are relative to `base_dir` (default:
        the current folder). Raises ValueError naming the JSON path, as the scene file's errors do."""
        base = os.fspath(base_dir) if base_dir is not None else os.getcwd()
        handle, lines = _shadelab._Scene.from_document(_plain(document), base, allow_external_paths)
        return cls._from_handle(handle, lines)

    def to_dict(self):
        """The whole description, every field written (as `save` writes it): from_dict(to_dict()) is exact."""
        return _deepcopy(self._document())

    def save(self, path):
        """Writes the scene file atomically. Mesh sources are written as they are (relative to base_dir)."""
        self._handle.save(os.fspath(path))

    def copy(self):
        """An independent copy (mesh triangles are shared, never copied)."""
        return Scene._from_handle(self._handle.copy())

    __copy__ = copy

    def __deepcopy__(self, memo):
        return self.copy()

    def __reduce__(self):
        return (_scene_from_state, (self.to_dict(), self._handle.base_dir, self._handle.allow_external_paths))

    @property
    def base_dir(self):
        """The folder mesh sources are relative to."""
        return self._handle.base_dir

    @property
    def triangle_count(self):
        return self._handle.triangles

    def render(self, size=(1280, 720), **options):
        """shadelab.render(self, size, **options)."""
        from .render import render

        return render(self, size, **options)

    # -- the document and its edits -------------------------------------------------------------------------

    def _document(self):
        if self._doc is None:
            object.__setattr__(self, "_doc", self._handle.to_document())
        return self._doc

    def _wrap(self, path, value):
        if isinstance(value, dict):
            return _Node(self, path)
        if isinstance(value, list):
            return _List(self, path) if len(path) == 1 and path[0] in _CONTAINERS else tuple(value)
        return value

    def _commit(self, document, strict):
        replaced, lines = self._handle.replace(document, strict)
        if not replaced:
            unknown = next(line for line in lines if "unknown field '" in line)
            raise AttributeError(unknown.replace(" (ignored)", ""))
        object.__setattr__(self, "_doc", None)
        _warn(lines, stacklevel=4)  # the statement that made the edit

    def _edit(self, path, change):
        """Applies change(node) to a copy of the node at `path` of the document, then re-reads the scene."""
        document = _deepcopy(self._document())
        change(_walk(document, path))
        self._commit(document, strict=False)

    def _set(self, path, value):
        document = _deepcopy(self._document())
        _walk(document, path[:-1])[path[-1]] = _plain(value)
        self._commit(document, strict=True)

    # The top level reads and writes as any view does.
    _path = ()

    @property
    def _scene(self):
        return self

    _value = _Node._value
    __getattr__ = _Node.__getattr__
    __getitem__ = _Node.__getattr__
    __contains__ = _Node.__contains__
    __dir__ = _Node.__dir__
    keys = _Node.keys

    def __setattr__(self, name, value):
        if name.startswith("_") or name in ("base_dir", "triangle_count"):
            raise AttributeError(f"cannot set {name}")
        self._set((name,), value)

    __setitem__ = __setattr__

    def __eq__(self, other):
        if isinstance(other, Scene):
            return self.to_dict() == other.to_dict()
        return NotImplemented

    __hash__ = None

    def __repr__(self):
        d = self._document()
        return (f"<shadelab.Scene {d.get('title', '')!r}: {d['model']}, {len(d['lights'])} light(s), "
                f"{len(d['objects'])} object(s)>")


def _scene_from_state(document, base_dir, allow_external_paths):
    return Scene.from_dict(document, base_dir=base_dir, allow_external_paths=allow_external_paths)
