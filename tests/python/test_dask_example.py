"""examples/dask_sweep.py: 8 scenes rendered on a 2-worker LocalCluster equal the same scenes rendered serially
in this process."""

import os

import numpy as np
import pytest

import shadelab
from conftest import SOURCE_DIR

EXAMPLES = SOURCE_DIR / "examples"


@pytest.fixture
def sweep(monkeypatch):
    # The workers import the example by name (its functions are pickled by reference), as they import shadelab.
    monkeypatch.setenv("PYTHONPATH", f"{EXAMPLES}:{os.environ.get('PYTHONPATH', '')}")
    monkeypatch.syspath_prepend(str(EXAMPLES))
    import dask_sweep

    return dask_sweep


@pytest.mark.filterwarnings("ignore:make_current is deprecated:DeprecationWarning")
def test_local_cluster_equals_serial(sweep):
    from dask.distributed import Client

    base = shadelab.Scene.load(SOURCE_DIR / "assets" / "scenes" / "default.json")
    scenes = sweep.material_grid(8, base)
    assert len({str(s["objects"][0]["material"]) for s in scenes}) == 8
    serial = sweep.render_serially(scenes, base.base_dir, (64, 48))
    with sweep.local_cluster(2) as cluster, Client(cluster) as client:
        assert len(client.scheduler_info()["workers"]) == 2
        distributed = sweep.render_on(client, scenes, base.base_dir, (64, 48))
        traced = sweep.render_on(client, scenes[:2], base.base_dir, (64, 48), renderer="trace")
    assert len(distributed) == 8
    for a, b in zip(serial, distributed):
        assert a.dtype == np.uint8 and np.array_equal(a, b)
    assert not np.array_equal(serial[0], serial[-1])  # the grid does vary
    for a, d in zip(traced, scenes[:2]):
        assert np.array_equal(a, sweep.render_task(d, base.base_dir, (64, 48), renderer="trace"))
