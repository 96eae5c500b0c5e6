"""docs/notebooks/phong-lab.ipynb executes top to bottom under `jupyter nbconvert --execute` (with the Debian 12
widget-protocol shim, docs/notebooks/nbconvert_config.py) from a temporary folder outside the repository (its
scene comes from shadelab.data), and its outputs hold the rendered images and the log-scale slider's settings.
The folder is the system's temporary one, not build/test-output/, which lies inside the repository; the
executed notebook is copied to the test's output folder."""

import json
import os
import shutil
import subprocess
import tempfile
from pathlib import Path

import pytest

from conftest import SOURCE_DIR

NOTEBOOKS = SOURCE_DIR / "docs" / "notebooks"


def execute(notebook, folder, config=NOTEBOOKS / "nbconvert_config.py"):
    """Runs `notebook` (a path inside `folder`, where its kernel starts) headlessly; the completed process."""
    jupyter = shutil.which("jupyter")
    if not jupyter:
        pytest.skip("jupyter is not installed (scripts/install-deps.sh installs jupyter-nbconvert)")
    env = dict(os.environ)
    # The kernel starts in the notebook's folder: the package path must be absolute.
    env["PYTHONPATH"] = os.pathsep.join(os.path.abspath(p) for p in env.get("PYTHONPATH", "").split(os.pathsep) if p)
    env["PYDEVD_DISABLE_FILE_VALIDATION"] = "1"
    return subprocess.run([jupyter, "nbconvert", "--to", "notebook", "--execute", "--config",
                           str(config), "--ExecutePreprocessor.timeout=300",
                           "--output-dir", str(folder / "executed"), str(notebook)],
                          capture_output=True, text=True, env=env, cwd=folder)


@pytest.fixture
def outside(out_dir):
    """A new folder outside the repository, removed afterwards; what it holds is copied to out_dir first."""
    with tempfile.TemporaryDirectory(prefix="shadelab-notebook-") as folder:
        path = Path(folder)
        # No repository around it to find scenes in.
        assert not any((p / "assets" / "scenes" / "default.json").exists() for p in [path, *path.parents])
        yield path
        shutil.copytree(path, out_dir, dirs_exist_ok=True)


def test_phong_lab_executes_from_a_temporary_folder(outside):
    notebook = outside / "phong-lab.ipynb"
    shutil.copyfile(NOTEBOOKS / "phong-lab.ipynb", notebook)
    p = execute(notebook, outside)
    assert p.returncode == 0, p.stderr[-3000:]
    executed = json.loads((outside / "executed" / "phong-lab.ipynb").read_text())
    outputs = [o for c in executed["cells"] if c["cell_type"] == "code" for o in c["outputs"]]
    assert not [o for o in outputs if o["output_type"] == "error"]
    pngs = [o for o in outputs if "image/png" in o.get("data", {})]
    assert len(pngs) >= 2  # the scene and the lobe plot
    text = "".join("".join(o.get("text", "")) for o in outputs)
    assert "bytes of PNG for the scene" in text and "N·L" in text
    assert "shininess slider: log2(s) from 0 to 10, continuous_update=False" in text
    assert "the shininess slider changes the picture under phong, blinn-phong, pbr, disney" in text
    # The slider cell's pictures are saved with the notebook (display outputs, updated in place), so nbviewer and
    # HTML exports show the last picture and lobe. The last render is disney at s = 512 (the test cell's last move),
    # not the first one the cell displayed: the saved outputs follow the updates.
    slider = next(c for c in executed["cells"] if "FloatSlider" in "".join(c["source"]))
    shown = [o["data"]["image/png"] for o in slider["outputs"] if "image/png" in o.get("data", {})]
    assert len(shown) == 2, [o["output_type"] for o in slider["outputs"]]
    words = "".join("".join(o["data"]["text/markdown"]) for o in slider["outputs"] if "text/markdown" in o.get("data", {}))
    assert words == "shininess **s = 512** (log2 s = 9), model **disney**", words
    # The widgets' own state is saved too (metadata.widgets, in nbclient's format): the slider at its last value.
    state = executed["metadata"]["widgets"]["application/vnd.jupyter.widget-state+json"]["state"]
    sliders = [m["state"] for m in state.values() if m["model_name"] == "FloatSliderModel"]
    assert [(s["value"], s["min"], s["max"], s["continuous_update"]) for s in sliders] == [(9, 0, 10, False)], sliders
    first = [o for o in outputs if "image/png" in o.get("data", {})]
    assert all(png not in [f["data"]["image/png"] for f in first[:1]] for png in shown)


def test_a_repository_path_fails_from_there(outside):
    # The negative control: the notebook as it was, loading the repository's relative path, fails from a
    # temporary folder, so the test above does run outside the repository.
    source = json.loads((NOTEBOOKS / "phong-lab.ipynb").read_text())
    cell = next(c for c in source["cells"] if 'shadelab.data.scene("default")' in "".join(c["source"]))
    cell["source"] = "".join(cell["source"]).replace('shadelab.data.scene("default")',
                                                     'shadelab.Scene.load("assets/scenes/default.json")')
    notebook = outside / "phong-lab.ipynb"
    notebook.write_text(json.dumps(source))
    p = execute(notebook, outside)
    assert p.returncode != 0 and "default.json" in p.stderr, p.stderr[-3000:]


def test_without_the_configs_state_hand_over_no_widget_state_is_saved(outside):
    # The negative control of the saved widget state: the same config with its old-protocol hand-over undone.
    config = outside / "config_without_state.py"
    config.write_text(f"exec(open({str(NOTEBOOKS / 'nbconvert_config.py')!r}).read())\n"
                      "nbclient.client.NotebookClient.handle_comm_msg = _handle_comm_msg\n")
    notebook = outside / "phong-lab.ipynb"
    shutil.copyfile(NOTEBOOKS / "phong-lab.ipynb", notebook)
    p = execute(notebook, outside, config)
    assert p.returncode == 0, p.stderr[-3000:]
    executed = json.loads((outside / "executed" / "phong-lab.ipynb").read_text())
    state = executed["metadata"].get("widgets", {}).get("application/vnd.jupyter.widget-state+json", {})
    assert not [m for m in state.get("state", {}).values() if m["model_name"] == "FloatSliderModel"]
