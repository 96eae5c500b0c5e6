"""examples/dask_sweep.py on a cluster like a real one: a LocalCluster worker, a worker started in a subprocess with
shadelab on its path but not the example (so the example's functions must travel by value), and one started with a
bare interpreter that cannot import shadelab. The pre-flight names that worker and the sweep completes on the
others; each renderer's images equal the same renders made serially here; a scene file's models travel by content;
a failed task is reported while the others are written."""

import base64
import copy
import importlib.util
import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import shadelab
from conftest import SOURCE_DIR

EXAMPLES = SOURCE_DIR / "examples"
SIZE = (32, 24)

pytestmark = pytest.mark.filterwarnings("ignore:make_current is deprecated:DeprecationWarning")


@pytest.fixture(scope="module")
def sweep():
    with pytest.MonkeyPatch.context() as mp:
        mp.syspath_prepend(str(EXAMPLES))
        import dask_sweep

        yield dask_sweep


def start_worker(scheduler, name, folder, pythonpath):
    """A `dask-worker` process (no nanny, one thread) with PYTHONPATH `pythonpath` (None: none, so the
    interpreter sees only what is installed), run from `folder`; its log goes to folder/<name>.log."""
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    env["PYTHONNOUSERSITE"] = "1"
    if pythonpath:
        env["PYTHONPATH"] = pythonpath
    command = [sys.executable, "-m", "distributed.cli.dask_worker", scheduler, "--name", name, "--nthreads", "1",
               "--no-nanny", "--no-dashboard", "--local-directory", str(folder)]
    with open(folder / f"{name}.log", "wb") as log:  # the child keeps its own copy of the descriptor
        return subprocess.Popen(command, cwd=folder, env=env, stdout=log, stderr=subprocess.STDOUT)


@pytest.fixture(scope="module")
def cluster(sweep, tmp_path_factory):
    """(client, {"local", "plain", "bare"}: each worker's address). `plain` has shadelab (the build tree's) but not
    the examples folder; `bare` has neither."""
    from dask.distributed import Client

    folder = tmp_path_factory.mktemp("workers")
    package = str(Path(shadelab.__file__).parents[1])
    with sweep.local_cluster(1) as local, Client(local) as client:
        workers = [start_worker(local.scheduler_address, "plain", folder, package),
                   start_worker(local.scheduler_address, "bare", folder, None)]
        try:
            client.wait_for_workers(3, timeout=90)
            names = {str(w["name"]): a for a, w in client.scheduler_info()["workers"].items()}
            yield client, {"local": names.pop("0"), **names}
        finally:
            for worker in workers:
                worker.terminate()
                worker.wait(30)


def pixels_of(path):
    return shadelab.Image.open(path).to_uint8()


def test_preflight_names_the_worker_without_shadelab_and_the_sweep_completes(sweep, cluster, tmp_path, capsys):
    client, workers = cluster
    good, problems = sweep.preflight(client)
    assert good == sorted([workers["local"], workers["plain"]])
    assert list(problems) == [workers["bare"]]
    # The plain worker renders without the example on its path: the tasks' functions travel by value.
    assert client.run(importlib.util.find_spec, "dask_sweep", workers=[workers["plain"]]) == {workers["plain"]: None}

    rc = sweep.main(["--scheduler", client.scheduler.address, "--materials", "6", "--size", "32x24",
                     "--out", str(tmp_path)])
    out, err = capsys.readouterr()
    assert rc == 0, err
    lines = [line for line in err.splitlines() if line.startswith("dask_sweep:")]
    assert len(lines) == 1 and workers["bare"] in lines[0] and "(bare)" in lines[0], err
    assert "cannot import shadelab (ModuleNotFoundError: No module named 'shadelab')" in lines[0]
    assert f"install shadelab {shadelab.__version__} there" in lines[0]
    assert "6 of 6 renders of 32x24 (raster) on 2 workers" in out
    scenes = sweep.material_grid(6, shadelab.data.scene("default"))
    serial = sweep.render_serially(scenes, {"shipped": "default"}, SIZE)
    assert sorted(p.name for p in tmp_path.iterdir()) == [f"material-{i:04d}.png" for i in range(6)]
    for i, expected in enumerate(serial):
        assert np.array_equal(pixels_of(tmp_path / f"material-{i:04d}.png"), expected)
    assert not np.array_equal(serial[0], serial[-1])  # the grid does vary


def test_without_the_preflight_the_worker_without_shadelab_fails_tasks(sweep, cluster):
    # The control: the same tasks handed to every worker fail on the bare one with ModuleNotFoundError (the whole
    # sweep aborted with it before there was a pre-flight).
    client, workers = cluster
    scenes = sweep.material_grid(6, shadelab.data.scene("default"))
    images, failures = sweep.render_on(client, scenes, {"shipped": "default"}, SIZE, retries=0)
    assert failures, "the bare worker got no task"
    for i, (where, why) in failures.items():
        assert where == workers["bare"] and why.startswith("ModuleNotFoundError: No module named 'shadelab'")
        assert images[i] is None
    assert sum(image is not None for image in images) == 6 - len(failures)


@pytest.mark.parametrize("renderer, spp, seed", [("raster", None, None), ("trace", 4, None), ("path", 4, 7)])
def test_each_renderer_equals_a_serial_render(sweep, cluster, renderer, spp, seed):
    client, workers = cluster
    good = [workers["local"], workers["plain"]]
    scenes = sweep.material_grid(3, shadelab.data.scene("torus"))
    source = {"shipped": "torus"}
    images, failures = sweep.render_on(client, scenes, source, SIZE, renderer, spp, seed, workers=good)
    assert failures == {}
    for image, expected in zip(images, sweep.render_serially(scenes, source, SIZE, renderer, spp, seed)):
        assert image.dtype == np.uint8 and image.shape == (24, 32, 3) and np.array_equal(image, expected)
    if renderer == "path":  # the seed is what makes the noise reproducible: another one gives other bytes
        other, _ = sweep.render_on(client, scenes[:1], source, SIZE, renderer, spp, seed + 1, workers=good)
        assert not np.array_equal(other[0], images[0])


def test_a_scene_file_travels_with_its_files(sweep, cluster, tmp_path):
    client, workers = cluster
    good = [workers["local"], workers["plain"]]
    # A project on this machine only: a scene beside (not under) its model, whose buffer is an external file with
    # an escaped name, and an environment map.
    project = tmp_path / "project"
    for folder in ("scenes", "models", "sky"):
        (project / folder).mkdir(parents=True)
    model = json.loads((SOURCE_DIR / "assets" / "models" / "torus.gltf").read_text())
    (project / "models" / "torus data.bin").write_bytes(base64.b64decode(model["buffers"][0]["uri"].split(",")[1]))
    model["buffers"][0]["uri"] = "torus%20data.bin"
    (project / "models" / "torus.gltf").write_text(json.dumps(model))
    shutil.copy(SOURCE_DIR / "assets" / "environments" / "sky.hdr", project / "sky" / "sky.hdr")
    scene = json.loads((SOURCE_DIR / "assets" / "scenes" / "torus.json").read_text())
    scene["environment"] = {"hdr": "../sky/sky.hdr", "intensity": 0.5}
    (project / "scenes" / "lab.json").write_text(json.dumps(scene))

    base = shadelab.Scene.load(project / "scenes" / "lab.json")
    scenes = sweep.material_grid(3, base)
    serial = sweep.render_serially(scenes, base.base_dir, SIZE)
    portable, bundle = sweep.pack(scenes, base.base_dir)
    assert bundle["base"] == "scenes"
    assert sorted(bundle["files"]) == ["models/torus data.bin", "models/torus.gltf", "sky/sky.hdr"]
    assert [o["source"] for o in portable[0]["objects"] if o["type"] == "mesh"] == ["../models/torus.gltf"]
    # A model loaded by itself names its source by an absolute path: packed, it is relative.
    model_dicts, model_bundle = sweep.pack([shadelab.Scene.load(project / "models" / "torus.gltf").to_dict()],
                                           project / "models")
    assert model_dicts[0]["objects"][0]["source"] == "torus.gltf" and model_bundle["base"] == "."
    assert sorted(model_bundle["files"]) == ["torus data.bin", "torus.gltf"]

    shutil.rmtree(project)  # the workers cannot read the client's files: there are none left
    images, failures = sweep.render_on(client, portable, bundle, SIZE, workers=good)
    assert failures == {}
    for image, expected in zip(images, serial):
        assert np.array_equal(image, expected)
    # Each worker wrote the files once, into its own folder, which the end of the sweep removes.
    folders = client.run(sweep._bundle_folder, bundle["key"], workers=good)
    assert all(os.path.isdir(f) for f in folders.values())
    client.run(sweep._forget_bundle, bundle["key"], workers=good)
    assert not any(os.path.exists(f) for f in folders.values())


def test_a_failed_task_is_reported_and_the_others_are_written(sweep, cluster, tmp_path, capsys):
    client, workers = cluster
    scenes = sweep.material_grid(4, shadelab.data.scene("default"))
    scenes[2] = copy.deepcopy(scenes[2])
    scenes[2]["lights"][0]["color"] = [1, 2]
    (tmp_path / "material-0001.png").mkdir()  # and one image that cannot be written here
    good, failures = sweep.run_sweep(client, scenes, {"shipped": "default"}, SIZE, retries=1, out=tmp_path)
    err = capsys.readouterr().err
    assert sorted(failures) == [1, 2] and failures[2][0] in good
    assert failures[2][1] == "InputError: lights[0].color: expected 3 numbers, got 2"
    assert f"dask_sweep: material-0002 failed (on {failures[2][0]}): InputError: lights[0].color" in err
    assert failures[1][0] == "this client" and failures[1][1].startswith("OSError: ") and "material-0001" in err
    assert sorted(p.name for p in tmp_path.iterdir() if p.is_file()) == ["material-0000.png", "material-0003.png"]
    serial = sweep.render_serially([scenes[3]], {"shipped": "default"}, SIZE)[0]
    assert np.array_equal(pixels_of(tmp_path / "material-0003.png"), serial)

    # Every task failing the same way: one line for all of them, and exit status 1.
    rc = sweep.main(["--scheduler", client.scheduler.address, "--materials", "7", "--size", "32x24",
                     "--spp", "3", "--retries", "0"])
    err = capsys.readouterr().err
    assert rc == 1
    assert ("dask_sweep: material-0000, material-0001, material-0002, material-0003, material-0004 and 2 more "
            "failed (on ") in err
    assert "spp: expected a perfect square" in err


def test_no_usable_worker_is_a_clear_error(sweep, tmp_path, capsys):
    from dask.distributed import Client

    with sweep.local_cluster(0) as local, Client(local) as client:
        worker = start_worker(local.scheduler_address, "bare", tmp_path, None)
        try:
            client.wait_for_workers(1, timeout=90)
            rc = sweep.main(["--scheduler", local.scheduler_address, "--materials", "2", "--size", "32x24"])
        finally:
            worker.terminate()
            worker.wait(30)
    err = capsys.readouterr().err
    assert rc == 1
    assert "(bare) cannot import shadelab" in err
    assert f"no worker can render (1 connected, none with shadelab {shadelab.__version__})" in err


def test_help_and_a_local_cluster(sweep, tmp_path, capsys):
    with pytest.raises(SystemExit) as exit:
        sweep.main(["--help"])
    assert exit.value.code == 0
    text = capsys.readouterr().out
    for words in ("--renderer {raster,trace,path}", "--spp", "--seed", "--retries", "--scheduler", "--out",
                  "dask-scheduler", "dask-worker tcp://head:8786", "pip install .", "Pre-flight"):
        assert words in text
    # The default: a LocalCluster of its own.
    assert sweep.main(["--workers", "1", "--materials", "2", "--size", "32x24", "--renderer", "trace"]) == 0
    assert "2 of 2 renders of 32x24 (trace) on 1 worker in" in capsys.readouterr().out
