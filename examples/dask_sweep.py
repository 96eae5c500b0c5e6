#!/usr/bin/env python3
"""Render a grid of materials on a Dask cluster: each task is one (scene, size) → image, each worker process keeps
its own shadelab Renderer (its GL context and compiled programs) for all the tasks it runs.

    python3 examples/dask_sweep.py                       # a LocalCluster: 2 workers on this machine
    python3 examples/dask_sweep.py --workers 8 --materials 1000 --out out/sweep
    python3 examples/dask_sweep.py --scheduler tcp://head:8786   # an existing cluster (dask-scheduler,
                                                                 # dask-ssh, dask-jobqueue, dask-kubernetes, ...)

Rendering is a pure function (design.md §10), so Dask only has to hand out tasks: shadelab has no scheduler of
its own. On a real cluster every worker needs the shadelab package (`pip install .` from this repository) and
the files the scene names (glTF meshes) at the same paths; the scenes shadelab ships (--scene torus) come with
the package, so for them a package installed at the same path is enough. Workers render through their
process's default Renderer: EGL on a GPU node, llvmpipe elsewhere, as the binary would.
"""

import argparse
import itertools
import os
import sys
import time
from pathlib import Path

def material_grid(count, base_scene):
    """`count` scene dicts: the base scene with its first object's shininess and colour (md = ma) swept over a
    grid (shininess on a log scale from 1 to 1024, hue around the colour wheel)."""
    import colorsys

    side = max(1, int(round(count ** 0.5)))
    shininess = [2.0 ** (10.0 * i / max(side - 1, 1)) for i in range(side)]
    hues = [j / side for j in range(max(1, (count + side - 1) // side))]
    scenes = []
    for s, h in itertools.islice(itertools.product(shininess, hues), count):
        scene = base_scene.copy()
        material = scene.objects[0].material
        material.s = s
        material.md = material.ma = colorsys.hsv_to_rgb(h, 0.8, 0.7)
        scenes.append(scene.to_dict())
    return scenes


def render_task(scene_dict, base_dir, size, renderer="raster"):
    """One task, run on a worker: scene dict → 8-bit pixels. The worker's process-wide default Renderer is made
    by its first task and reused by the rest."""
    import shadelab

    scene = shadelab.Scene.from_dict(scene_dict, base_dir=base_dir)
    threads = 1 if renderer == "trace" else 0  # one tracer thread per Dask worker thread
    return shadelab.render(scene, size, renderer=renderer, threads=threads).to_uint8()


def render_on(client, scene_dicts, base_dir, size, renderer="raster"):
    """Renders every scene dict on the cluster behind `client`; returns the pixels in order."""
    futures = client.map(render_task, scene_dicts, base_dir=base_dir, size=size, renderer=renderer, pure=False)
    return client.gather(futures)


def render_serially(scene_dicts, base_dir, size, renderer="raster"):
    return [render_task(d, base_dir, size, renderer) for d in scene_dicts]


def local_cluster(workers):
    """A LocalCluster of `workers` processes with one thread each, no dashboard (it needs bokeh)."""
    from dask.distributed import LocalCluster

    return LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None,
                        host="127.0.0.1")


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--scheduler", help="a Dask scheduler's address (default: start a LocalCluster)")
    parser.add_argument("--workers", type=int, default=2, help="LocalCluster worker processes (default 2)")
    parser.add_argument("--materials", type=int, default=64, help="grid size (default 64)")
    parser.add_argument("--scene", default="default",
                        help="a scene file, or the name of a scene shadelab ships (shadelab.data.scenes(); "
                             "default: default)")
    parser.add_argument("--size", default="160x90", help="WxH (default 160x90)")
    parser.add_argument("--renderer", default="raster", choices=["raster", "trace"])
    parser.add_argument("--out", help="folder for the PNGs (default: render only)")
    args = parser.parse_args(argv)

    from dask.distributed import Client

    import shadelab

    w, h = (int(v) for v in args.size.lower().split("x"))
    # A shipped scene by name runs from any folder; anything else is a scene file's path.
    shipped = args.scene in shadelab.data.scenes()
    base = shadelab.data.scene(args.scene) if shipped else shadelab.Scene.load(args.scene)
    scenes = material_grid(args.materials, base)
    cluster = None if args.scheduler else local_cluster(args.workers)
    with Client(args.scheduler or cluster) as client:
        start = time.perf_counter()
        images = render_on(client, scenes, base.base_dir, (w, h), args.renderer)
        elapsed = time.perf_counter() - start
    if cluster is not None:
        cluster.close()
    print(f"{len(images)} renders of {w}x{h} in {elapsed:.2f} s ({len(images) / elapsed:.1f}/s)")
    if args.out:
        out = Path(args.out)
        out.mkdir(parents=True, exist_ok=True)
        for i, pixels in enumerate(images):
            shadelab.Image.from_array(pixels).save(out / f"material-{i:04d}.png")
        print(f"wrote {out}/material-*.png")
    return 0


if __name__ == "__main__":
    sys.exit(main())
