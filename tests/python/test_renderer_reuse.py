"""One Renderer for many renders: memory stays flat, and rendering releases the GIL so other Python threads run.
Renders from several threads through one Renderer take turns and stay correct."""

import os
import threading

import pytest

import shadelab
from conftest import sanitized


def rss_bytes():
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * os.sysconf("SC_PAGE_SIZE")


@pytest.fixture(scope="module")
def scene(source_dir):
    return shadelab.Scene.load(source_dir / "assets" / "scenes" / "default.json")


@pytest.mark.skipif(sanitized(), reason="ASan's quarantine holds freed memory on purpose; RSS says nothing there")
@pytest.mark.parametrize("renderer", ["raster", "trace"])
def test_hundred_renders_do_not_grow_memory(scene, renderer):
    r = shadelab.Renderer()
    first = None
    rss = []
    for i in range(100):
        scene.objects[0].material.s = 8.0 + i  # a new scene each time, as a sweep makes them
        image = r.render(scene, (128, 96), renderer=renderer)
        if first is None:
            first = image.to_png()
        rss.append(rss_bytes())
    after10, after100 = rss[9], rss[99]
    assert after100 <= after10 * 1.05, f"RSS grew from {after10 >> 20} MiB after 10 renders to {after100 >> 20} MiB"
    r.close()


def test_other_threads_run_while_rendering(scene):
    """The main thread watches Renderer.busy, which it can only read holding the GIL: seeing it True proves the
    GIL was free while a render ran. It also counts pure-Python work done meanwhile."""
    r = shadelab.Renderer()
    r.render(scene, (32, 32), renderer="trace")  # warm
    done = threading.Event()

    def work():
        try:
            for _ in range(3):
                r.render(scene, (320, 180), renderer="trace", threads=1)
        finally:
            done.set()

    worker = threading.Thread(target=work)
    worker.start()
    seen_busy = 0
    while not done.is_set():
        if r.busy:
            seen_busy += 1
    worker.join()
    assert seen_busy > 100, f"the main thread ran only {seen_busy} loop(s) while renders were in progress"


def test_threads_share_one_renderer(scene):
    r = shadelab.Renderer()
    scenes = []
    for s in (4.0, 64.0, 512.0):
        copy = scene.copy()
        copy.objects[0].material.s = s
        scenes.append(copy)
    expected = [r.render(s, (64, 48)).to_png() for s in scenes]
    results = {}

    def work(k):
        for i in range(4):
            results[(k, i)] = r.render(scenes[(k + i) % 3], (64, 48)).to_png()

    threads = [threading.Thread(target=work, args=(k,)) for k in range(3)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for (k, i), png in results.items():
        assert png == expected[(k + i) % 3]
