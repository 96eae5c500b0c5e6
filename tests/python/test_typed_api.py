"""The typed API: render()'s keywords spelled out (the same defaults and behaviour as the **options they replace),
no import cycles in the package, `mypy --strict` over the package and an example program (and a mistyped one
that must fail: the negative control), and the compiled module's stub (_shadelab.pyi) against the built module:
stubtest, then every name and pybind11 signature (its __doc__ lines) checked here."""

import ast
import inspect
import re
import subprocess
import sys
from pathlib import Path

import pytest

import shadelab
from shadelab import _shadelab

HERE = Path(__file__).resolve().parent
PACKAGE = Path(shadelab.__file__).resolve().parent  # build/python/shadelab: the sources, copied, and the module
STUB = PACKAGE / "_shadelab.pyi"
SIZE = (24, 16)

KEYWORDS = {"renderer": "raster", "spp": None, "encoding": "srgb", "depth": None, "threads": 0, "coverage": False,
            "time_limit": None, "estimator": None, "light_paths": None, "sampler": None, "denoise": False,
            "max_memory": None, "exposure": None, "view_transform": None, "seed": None}


@pytest.fixture(scope="module")
def scene(source_dir):
    return shadelab.Scene.load(source_dir / "assets" / "scenes" / "default.json")


# -- render()'s keywords -----------------------------------------------------------------------------------------

@pytest.mark.parametrize("function", [shadelab.render, shadelab.Renderer.render, shadelab.Scene.render],
                         ids=["render", "Renderer.render", "Scene.render"])
def test_keywords_are_spelled_out(function):
    parameters = list(inspect.signature(function).parameters.values())
    positional = [p.name for p in parameters if p.kind is inspect.Parameter.POSITIONAL_OR_KEYWORD]
    assert positional[-1] == "size" and parameters[len(positional) - 1].default == (1280, 720)
    keywords = {p.name: p.default for p in parameters if p.kind is inspect.Parameter.KEYWORD_ONLY}
    assert keywords == KEYWORDS
    assert not any(p.kind in (inspect.Parameter.VAR_KEYWORD, inspect.Parameter.VAR_POSITIONAL) for p in parameters)
    for name in KEYWORDS:  # each keyword's meaning, range and default are written down
        assert f"{name}:" in shadelab.render.__doc__ and f"{name}:" in shadelab.Renderer.render.__doc__


def test_every_keyword_reaches_the_renderer(scene):
    options = {"renderer": "trace", "spp": 4, "encoding": "linear", "depth": 0, "threads": 2, "coverage": True}
    image = shadelab.render(scene, SIZE, **options)  # a dict of options, as callers of **options passed them
    assert (image.source, image.encoding, image.coverage.shape) == ("trace", "linear", (SIZE[1], SIZE[0]))
    with shadelab.Renderer() as r:
        assert r.render(scene, SIZE, **options).to_png() == image.to_png()
    assert scene.render(SIZE, **options).to_png() == image.to_png()
    # Each keyword changes what it should: against the same render with that one keyword at its default.
    for name, default in KEYWORDS.items():
        other = shadelab.render(scene, SIZE, **{**options, name: default})
        if name == "renderer":
            assert other.source == "raster"
        elif name == "encoding":
            assert other.encoding == "srgb" and other.to_png() != image.to_png()
        elif name == "coverage":
            assert other.coverage is None
        elif name == "spp" or name == "depth":
            assert other.to_png() != image.to_png(), name
        else:  # threads: the same image for any count
            assert other.to_png() == image.to_png()


def test_defaults_are_the_old_defaults(scene):
    assert shadelab.render(scene, SIZE).to_png() == shadelab.render(scene, SIZE, **KEYWORDS).to_png()
    assert shadelab.render(scene).size == (1280, 720)


def test_unknown_keywords_are_refused_by_name(scene):
    # Python's own TypeError for an unknown keyword names it (as Renderer.render's did behind **options).
    for call, word in [(lambda: shadelab.render(scene, SIZE, sppp=4), "sppp"),
                       (lambda: shadelab.Renderer().render(scene, SIZE, samples=4), "samples"),
                       (lambda: scene.render(SIZE, gpu=True), "gpu")]:
        with pytest.raises(TypeError, match=f"unexpected keyword argument '{word}'"):
            call()
    with pytest.raises(TypeError, match="multiple values for argument 'size'"):
        shadelab.render(scene, SIZE, size=SIZE)
    for call in (lambda: shadelab.render(scene, SIZE, "trace"), lambda: scene.render(SIZE, "trace")):
        with pytest.raises(TypeError, match="positional argument"):  # the keywords are keyword-only, as before
            call()


def test_bad_values_are_still_value_errors(scene):
    for options in ({"spp": 2}, {"renderer": "photon"}, {"encoding": "gamma"}, {"depth": 65, "renderer": "trace"},
                    {"threads": -1}):
        with pytest.raises(ValueError):
            shadelab.render(scene, (8, 8), **options)


def test_one_default_renderer(scene):
    from shadelab import _rendering

    assert shadelab.default_renderer() is shadelab.default_renderer()
    assert shadelab.default_renderer()._core is _rendering.default_core()  # the one Scene.render uses


# -- the package's imports ---------------------------------------------------------------------------------------

def _package_imports(path):
    """The package's modules that `path` imports, anywhere in it (functions and TYPE_CHECKING blocks too)."""
    imported = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.ImportFrom) and node.level == 1:
            if node.module:
                imported.add(node.module.split(".")[0])
            else:
                imported.update(alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom) and (node.module or "").startswith("shadelab."):
            imported.add(node.module.split(".")[1])
        elif isinstance(node, ast.Import):
            imported.update(a.name.split(".")[1] for a in node.names if a.name.startswith("shadelab."))
    return imported


def test_no_import_cycles(source_dir):
    sources = {p.stem: p for p in (source_dir / "python" / "shadelab").glob("*.py")}
    graph = {name: _package_imports(path) & set(sources) for name, path in sources.items() if name != "__init__"}
    # render.py builds on scene.py; scene.py (Scene.render) reaches the default renderer through _rendering.py.
    assert "scene" in graph["render"] and "render" not in graph["scene"]
    done, path = set(), []

    def visit(name):
        assert name not in path, f"import cycle: {' -> '.join(path[path.index(name):] + [name])}"
        if name in done:
            return
        path.append(name)
        for other in sorted(graph.get(name, ())):
            visit(other)
        path.pop()
        done.add(name)

    for name in sorted(graph):
        visit(name)


def test_import_stays_light():
    # The annotations cost nothing at import: typing (and numpy) are imported for the type checker only.
    code = "import sys, shadelab; print(sorted({'typing', 'numpy'} & set(sys.modules)))"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "[]"


# -- mypy --------------------------------------------------------------------------------------------------------

@pytest.fixture(scope="module")
def mypy_cache(tmp_path_factory):
    pytest.importorskip("mypy", reason="python3-mypy (scripts/install-deps.sh)")
    return tmp_path_factory.mktemp("mypy-cache")  # inside the test's output folder, never in the source tree


@pytest.fixture(scope="module")
def mypy(mypy_cache):
    def run(*args):
        p = subprocess.run([sys.executable, "-m", "mypy", "--strict", "--cache-dir", str(mypy_cache),
                            "--no-error-summary", *map(str, args)], capture_output=True, text=True)
        return p.returncode, p.stdout + p.stderr

    return run


def test_package_and_example_pass_strict(mypy, source_dir, out_dir):
    # The package as built (PYTHONPATH: build/python, the sources copied beside the module and its stub).
    example = HERE / "typed" / "api_example.py"
    rc, out = mypy(PACKAGE, example)
    assert rc == 0, out
    # The example is a real program.
    run = subprocess.run([sys.executable, example, source_dir / "assets" / "scenes" / "default.json", out_dir],
                         capture_output=True, text=True)
    assert run.returncode == 0, run.stderr


def test_mistyped_example_fails(mypy):
    # The negative control: mypy must report each marked line with its code, and nothing else.
    example = HERE / "typed" / "mistyped_example.py"
    expected = {(n, m.group(1)) for n, line in enumerate(example.read_text().splitlines(), 1)
                if (m := re.search(r"# error: ([a-z-]+)$", line))}
    assert len(expected) >= 10
    rc, out = mypy(example)
    assert rc == 1, out
    reported = {(int(m.group(1)), m.group(2)) for m in re.finditer(r"^\S+:(\d+): error: .*\[([a-z-]+)\]$", out, re.M)}
    assert reported == expected, out


def test_stubtest(mypy_cache):
    # stubtest takes neither --cache-dir nor MYPY_CACHE_DIR: a config file keeps its cache out of the working
    # folder (the sources).
    config = mypy_cache / "stubtest.ini"
    config.write_text(f"[mypy]\ncache_dir = {mypy_cache / 'stubtest'}\n")
    p = subprocess.run([sys.executable, "-m", "mypy.stubtest", "shadelab._shadelab", "--mypy-config-file", config,
                        "--allowlist", HERE / "typed" / "stubtest_allowlist.txt"], capture_output=True, text=True)
    assert p.returncode == 0, p.stdout + p.stderr


# -- the stub against the module's own signatures ----------------------------------------------------------------

MODULE_ATTRIBUTES = {"__doc__", "__file__", "__loader__", "__name__", "__package__", "__spec__"}
CLASS_ATTRIBUTES = {"__doc__", "__module__", "__weakref__", "__dict__"}


def _stub():
    """{name: node} for the stub's module level, and {class: {name: node}} for its classes."""
    tree = ast.parse(STUB.read_text())
    top, classes = {}, {}
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            top[node.name] = node
        elif isinstance(node, ast.AnnAssign):
            top[node.target.id] = node
        if isinstance(node, ast.ClassDef):
            classes[node.name] = {n.name if not isinstance(n, ast.AnnAssign) else n.target.id: n for n in node.body
                                  if isinstance(n, (ast.FunctionDef, ast.AnnAssign))}
    return top, classes


def _runtime_members(cls):
    # A class bound without a constructor has pybind11's refusing __init__, a slot wrapper: not in the stub.
    return {name for name, value in vars(cls).items() if name not in CLASS_ATTRIBUTES
            and not (name == "__init__" and type(value).__name__ == "wrapper_descriptor")}


def test_stub_names_match_the_module():
    top, classes = _stub()
    runtime = {n for n in dir(_shadelab) if n not in MODULE_ATTRIBUTES}
    assert set(top) == runtime  # private names too: stubtest skips the runtime's
    for name, members in classes.items():
        assert set(members) == _runtime_members(getattr(_shadelab, name)), name


def _split(text):
    """Splits "a: X, b: Dict[str, int] = {}" at its top-level commas."""
    parts, depth, start = [], 0, 0
    for i, c in enumerate(text):
        depth += c in "[(" and 1 or c in "])" and -1 or 0
        if c == "," and depth == 0:
            parts.append(text[start:i].strip())
            start = i + 1
    if text[start:].strip():
        parts.append(text[start:].strip())
    return parts


def _doc_signature(obj, name):
    """(parameters [(name, type, default or ...)], return type) from pybind11's first __doc__ line."""
    line = (obj.__doc__ or "").splitlines()[0]
    m = re.fullmatch(rf"{re.escape(name)}\((.*)\) -> (.+)", line)
    assert m, f"{name}: no signature in {line!r}"
    parameters = []
    for part in _split(m.group(1)):
        pname, _, rest = part.partition(": ")
        ptype, _, default = rest.partition(" = ")
        parameters.append((pname, ptype, ast.literal_eval(default) if default else ...))
    return parameters, m.group(2)


# pybind11's names for the C++ types, and the stub annotations each may be written as: the same type, or (for
# arguments) the wider one the caster converts from, or (for results) the narrower one the bindings return.
_TYPES = {
    "int": {"int"}, "float": {"float"}, "bool": {"bool"}, "bytes": {"bytes"}, "None": {"None"},
    "str": {"str", "EncodingName"}, "os.PathLike": {"StrPath"},
    "Optional[int]": {"int | None"}, "Optional[float]": {"float | None"}, "Optional[str]": {"str | None"},
    "numpy.ndarray": {"ArrayLike", "NDArray[np.uint8]"},
    "numpy.ndarray[numpy.float32]": {"ArrayLike", "NDArray[np.float32]"},
    "shadelab._shadelab.Image": {"Image"}, "shadelab._shadelab._Scene": {"_Scene"},
    "tuple": {"tuple[...]"}, "dict": {"dict[...]"}, "handle": {"dict[...]"},
    "List[numpy.ndarray[numpy.float32]]": {"list[...]"},
    # What the binding returns as a py::object, or takes as one to check its type itself (a one-line TypeError).
    "object": {"dict[...]", "NDArray[np.uint32] | None", "StrPath", "EncodingName", "MemorySize | None",
               "ExrPrecisionName | None", "tuple[...]", "ArrayLike"},
}


def _type_matches(pybind, stub):
    if stub is None:
        return pybind.startswith("shadelab._shadelab.")  # self
    text = re.sub(r"^(tuple|dict|list)\[.*\]$", r"\1[...]", ast.unparse(stub))
    return text in _TYPES.get(pybind, {pybind})


def _check_function(where, obj, name, node, method):
    parameters, result = _doc_signature(obj, name)
    args = node.args
    stub_parameters = [(a, True) for a in args.posonlyargs] + [(a, False) for a in args.args]
    is_static = any(isinstance(d, ast.Name) and d.id == "staticmethod" for d in node.decorator_list)
    assert len(stub_parameters) == len(parameters) and not args.kwonlyargs and not args.vararg, where
    defaults = [...] * (len(stub_parameters) - len(args.defaults)) + [ast.literal_eval(d) for d in args.defaults]
    for i, ((pname, ptype, default), (stub_arg, positional_only), stub_default) in enumerate(
            zip(parameters, stub_parameters, defaults)):
        if i == 0 and method and not is_static:
            assert stub_arg.arg == "self", where
            continue
        if re.fullmatch(r"arg\d+", pname):  # bound without py::arg: position only
            assert positional_only, f"{where}: {pname} takes no keyword; mark it positional-only (/)"
        else:
            assert (stub_arg.arg, positional_only) == (pname, False), f"{where}: {stub_arg.arg} against {pname}"
        assert stub_default == default, f"{where}: {pname}'s default"
        assert _type_matches(ptype, stub_arg.annotation), f"{where}: {pname}: {ptype}"
    assert _type_matches(result, node.returns), f"{where}: returns {result}, stub {ast.unparse(node.returns)}"


def test_stub_signatures_match_the_docstrings():
    top, classes = _stub()
    checked = 0
    for name, node in top.items():
        if isinstance(node, ast.FunctionDef):
            _check_function(name, getattr(_shadelab, name), name, node, method=False)
            checked += 1
    for cls_name, members in classes.items():
        cls = getattr(_shadelab, cls_name)
        for name, node in members.items():
            value = vars(cls)[name]
            where = f"{cls_name}.{name}"
            if isinstance(value, property):
                assert any(isinstance(d, ast.Name) and d.id == "property" for d in node.decorator_list), where
                _, result = _doc_signature(value.fget, "")
                assert _type_matches(result, node.returns), f"{where}: {result}"
            else:
                _check_function(where, getattr(cls, name), name, node, method=True)
            checked += 1
    assert checked >= 30
