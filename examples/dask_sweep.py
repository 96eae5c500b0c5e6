#!/usr/bin/env python3
"""Render a grid of materials on a Dask cluster, one task per material: (scene, size) → 8-bit pixels. Each worker
process keeps its own shadelab Renderer (its GL context and compiled programs) for all the tasks it runs.

    python3 examples/dask_sweep.py                          # a LocalCluster: 2 worker processes on this machine
    python3 examples/dask_sweep.py --workers 8 --materials 1000 --out out/sweep
    python3 examples/dask_sweep.py --renderer path --spp 64 --seed 1 --out out/gi
    python3 examples/dask_sweep.py --scene my/scene.json --scheduler tcp://head:8786 --out out/sweep

Rendering is a pure function (design.md §10), so Dask only has to hand out tasks: shadelab has no scheduler of
its own. Workers render through their process's default Renderer: EGL on a GPU node, llvmpipe elsewhere, as the
binary would; the tracers (trace, path) use one thread per task.

Pre-flight: before the sweep every worker is asked for its shadelab (client.run). A worker that cannot import it,
or has another version than this client, is named on one line on stderr and left out; the sweep runs on the
others (exit status 1 when none is left).

Scenes travel by content, never by a path on this machine: a shipped scene (--scene torus) by its name, which
each worker resolves in its own package; a scene file with the files it reads (glTF models, their external
buffers and images, the environment map) as bytes, sent once to each worker and written there into a temporary
folder (removed after the sweep). Workers need no shared filesystem.

Failures: a task that raises is retried (--retries), then reported on stderr with its worker and error, while the
other tasks' images are kept and written (material-NNNN.png, atomically, as Image.save writes them). The exit
status is 1 when any task failed.

Against a real scheduler:

    dask-scheduler                                  # on the head node; it prints its address, tcp://head:8786
    dask-worker tcp://head:8786 --nthreads 1        # on each render node, as many as you like
    python3 examples/dask_sweep.py --scheduler tcp://head:8786 --out out/sweep

(or dask-ssh, dask-jobqueue for Slurm, dask-kubernetes: anything that gives a scheduler address). Every worker
needs the same shadelab version as this client, installed in the Python that runs dask-worker (`pip install .`
from this repository, at the same commit), and the Python and Dask versions Dask itself asks for; nothing else:
neither this file (its functions are sent by value) nor the scene's files. A worker process renders its raster
tasks one at a time on its one GL context, so for raster prefer more worker processes (--nworkers) of one thread;
for the tracers --nthreads up to the node's cores runs that many tasks at once. Workers that join after the
pre-flight get no tasks.
"""

import argparse
import hashlib
import itertools
import json
import os
import shutil
import struct
import sys
import tempfile
import time
from pathlib import Path
from urllib.parse import unquote

if __name__ != "__main__":
    # Imported as a module (by a test, or your own code), this file's functions would be pickled by reference and
    # every worker would need it on its path; by value, workers need shadelab alone (as when run as a script).
    try:
        import cloudpickle

        cloudpickle.register_pickle_by_value(sys.modules[__name__])
    except (ImportError, AttributeError):  # no Dask here, or a cloudpickle before 2.0
        pass


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


# Scenes by content ---------------------------------------------------------------------------------------------

def _gltf_references(path):
    """The files a glTF model reads beside itself (external buffers and images), as absolute paths; data: URIs
    are inside the file. A .glb's JSON chunk is read the same way."""
    data = Path(path).read_bytes()
    if data[:4] == b"glTF":  # binary glTF: 12-byte header, then the JSON chunk (length, type, bytes)
        length, kind = struct.unpack_from("<II", data, 12)
        document = json.loads(data[20:20 + length]) if kind == 0x4E4F534A else {}
    else:
        document = json.loads(data)
    folder = os.path.dirname(path)
    uris = [entry.get("uri") for key in ("buffers", "images") for entry in document.get(key, [])]
    return [os.path.normpath(os.path.join(folder, unquote(uri)))
            for uri in uris if isinstance(uri, str) and uri and not uri.startswith("data:")]


def _file_fields(scene_dict):
    """(holder, key) of every field of a scene dict that names a file: mesh sources and the environment map."""
    fields = [(o, "source") for o in scene_dict.get("objects", []) if isinstance(o, dict)
              and isinstance(o.get("source"), str)]
    environment = scene_dict.get("environment")
    if isinstance(environment, dict) and isinstance(environment.get("hdr"), str):
        fields.append((environment, "hdr"))
    return fields


def pack(scene_dicts, base_dir):
    """Scene dicts that name files relative to `base_dir`, made independent of this machine: returns the dicts with
    every file reference relative to the base folder, and a bundle {"key", "base", "files"} holding the bytes of
    every file they read (files: relative path → bytes, in the folders' layout from their common folder, so that
    `../models/x.gltf` and a model's own `x.bin` still resolve; base: the base folder in that layout)."""
    base_dir = os.path.abspath(base_dir)
    portable, files = [], set()
    for scene_dict in scene_dicts:
        scene_dict = json.loads(json.dumps(scene_dict))  # a deep copy of plain data
        for holder, key in _file_fields(scene_dict):
            path = os.path.normpath(os.path.join(base_dir, holder[key]))
            holder[key] = os.path.relpath(path, base_dir)  # absolute sources (a loaded .gltf's) too
            if path not in files and path.lower().endswith((".gltf", ".glb")) and os.path.isfile(path):
                files.update(_gltf_references(path))  # once per model, however many dicts name it
            files.add(path)
        portable.append(scene_dict)
    files = sorted(f for f in files if os.path.isfile(f))  # a missing file fails on the worker as it would here
    root = os.path.commonpath([base_dir, *files])
    contents = {os.path.relpath(f, root): Path(f).read_bytes() for f in files}
    digest = hashlib.sha256(os.path.relpath(base_dir, root).encode())
    for name, data in sorted(contents.items()):
        digest.update(b"\0" + name.encode() + b"\0" + hashlib.sha256(data).digest())
    return portable, {"key": digest.hexdigest()[:16], "base": os.path.relpath(base_dir, root), "files": contents}


def _bundle_folder(key):
    return os.path.join(tempfile.gettempdir(), f"shadelab-sweep-{os.getpid()}-{key}")


def _unpack(bundle):
    """The bundle's files written into this process's folder for it (once: later tasks reuse it); returns the base
    folder the scene dicts' paths are relative to."""
    folder = _bundle_folder(bundle["key"])
    if not os.path.isdir(folder):
        # Written aside and renamed into place, so that a task in another thread never sees half the files.
        staging = tempfile.mkdtemp(prefix=os.path.basename(folder) + ".", dir=os.path.dirname(folder))
        for name, data in bundle["files"].items():
            target = os.path.join(staging, name)
            os.makedirs(os.path.dirname(target), exist_ok=True)
            Path(target).write_bytes(data)
        try:
            os.rename(staging, folder)
        except OSError:  # another thread got there first
            shutil.rmtree(staging, ignore_errors=True)
    base = os.path.join(folder, bundle["base"])
    os.makedirs(base, exist_ok=True)  # a scene that reads no file still needs its base folder
    return base


def _forget_bundle(key):
    """Run on each worker after the sweep: removes its folder for the bundle."""
    shutil.rmtree(_bundle_folder(key), ignore_errors=True)


def _base_dir(source):
    """Where a task's scene dict's paths are relative to: `source` is a local folder (str or Path; for serial
    renders, or a cluster on a shared filesystem), {"shipped": name} (a scene shipped with the package, resolved
    in the worker's own package) or a bundle from pack()."""
    if isinstance(source, dict) and "shipped" in source:
        import shadelab

        return str(shadelab.data.path(source["shipped"]).parent)
    if isinstance(source, dict):
        return _unpack(source)
    return os.fspath(source)


# Tasks ------------------------------------------------------------------------------------------------------------

def render_task(scene_dict, source, size, renderer="raster", spp=None, seed=None):
    """One task: scene dict → 8-bit pixels (H, W, 3). The process-wide default Renderer is made by the first task a
    worker runs and reused by the rest. `source` as for _base_dir()."""
    import shadelab

    scene = shadelab.Scene.from_dict(scene_dict, base_dir=_base_dir(source))
    threads = 0 if renderer == "raster" else 1  # one tracer thread per Dask worker thread
    return shadelab.render(scene, size, renderer=renderer, spp=spp, seed=seed, threads=threads).to_uint8()


def _cluster_task(scene_dict, source, size, renderer, spp, seed):
    """render_task on a worker; its error is RuntimeError(this worker's address, "Type: message"), so that the report
    can name the node (one without GL drivers, or with a full disk)."""
    try:
        return render_task(scene_dict, source, size, renderer, spp, seed)
    except Exception as error:
        try:
            from distributed import get_worker

            where = get_worker().address
        except Exception:
            where = "an unknown worker"
        raise RuntimeError(where, f"{type(error).__name__}: {error}") from error


def render_serially(scene_dicts, source, size, renderer="raster", spp=None, seed=None):
    """The same renders in this process, for comparison."""
    return [render_task(d, source, size, renderer, spp, seed) for d in scene_dicts]


def _worker_shadelab():
    """Run on every worker by the pre-flight: (its shadelab's version, "") or (None, why it cannot import it)."""
    try:
        import shadelab

        return shadelab.__version__, ""
    except Exception as error:  # not installed, or an extension module that does not load
        return None, f"{type(error).__name__}: {error}"


def preflight(client, version=None):
    """Asks every worker for its shadelab. Returns (the addresses of the workers that have `version`, default this
    client's, sorted; {address: one line saying what is wrong} for the others)."""
    if version is None:
        import shadelab

        version = shadelab.__version__
    names = {a: w.get("name") for a, w in client.scheduler_info()["workers"].items()}
    good, problems = [], {}
    for address, answer in sorted(client.run(_worker_shadelab, on_error="return").items()):
        who = f"worker {address}" + (f" ({names[address]})" if str(names.get(address, address)) != address else "")
        if isinstance(answer, BaseException):
            problems[address] = f"{who}: the check itself failed: {type(answer).__name__}: {answer}"
        elif answer[1]:
            problems[address] = f"{who} cannot import shadelab ({answer[1]}); install shadelab {version} there"
        elif answer[0] != version:
            problems[address] = f"{who} has shadelab {answer[0]}, this client {version}; install {version} there"
        else:
            good.append(address)
    return good, problems


def submit(client, scene_dicts, source, size, renderer="raster", spp=None, seed=None, workers=None, retries=1):
    """One future per scene dict, in order, on `workers` only (None: any worker), each retried `retries` times. A
    bundle is sent to the workers once, not with every task."""
    if isinstance(source, dict) and "files" in source:
        source = client.scatter([source], workers=workers, broadcast=True)[0]
    elif isinstance(source, os.PathLike):
        source = os.fspath(source)
    return client.map(_cluster_task, scene_dicts, source=source, size=tuple(size), renderer=renderer, spp=spp,
                      seed=seed, workers=workers, allow_other_workers=False, retries=retries, pure=False)


def collect(futures, on_image=None):
    """Waits for the futures in the order they finish. Each image goes to on_image(index, pixels) as it arrives (and
    is then dropped from the cluster); returns {index: (where, why)} for the tasks that failed, or whose image
    on_image could not take."""
    from distributed import as_completed

    index = {future.key: i for i, future in enumerate(futures)}
    failures = {}
    for future in as_completed(futures):
        i = index[future.key]
        if future.status == "finished":
            try:
                if on_image is not None:
                    on_image(i, future.result())
            except Exception as error:  # a file that cannot be written (a full disk) costs that image only
                failures[i] = ("this client", f"{type(error).__name__}: {error}")
        elif future.status == "error":
            error = future.exception()
            if isinstance(error, RuntimeError) and len(error.args) == 2:  # from _cluster_task
                failures[i] = error.args
            else:  # raised by Dask itself, e.g. KilledWorker when the task took its workers down
                failures[i] = ("the cluster", f"{type(error).__name__}: {error}")
        else:  # cancelled: the scheduler or the connection to it went away
            failures[i] = ("the cluster", f"the task was {future.status}")
        future.release()
    return failures


def render_on(client, scene_dicts, source, size, renderer="raster", spp=None, seed=None, workers=None, retries=1):
    """Renders every scene dict on the cluster behind `client`: (the pixels in order, None where a task failed;
    {index: (where, why)} for those)."""
    images = [None] * len(scene_dicts)
    futures = submit(client, scene_dicts, source, size, renderer, spp, seed, workers, retries)
    failures = collect(futures, lambda i, pixels: images.__setitem__(i, pixels))
    return images, failures


def run_sweep(client, scene_dicts, source, size, renderer="raster", spp=None, seed=None, retries=1, out=None,
              stream=None):
    """The whole sweep on the cluster behind `client`: the pre-flight (a line on `stream` for each worker left out),
    the renders on the usable workers, each image written to `out` (a folder; None: none) as material-NNNN.png as
    it arrives, the failures reported on `stream`. Returns (usable workers, {index: (where, why)} of the failed
    tasks), or (None, {}) when no worker is usable. `stream` defaults to sys.stderr."""
    stream = sys.stderr if stream is None else stream
    good, problems = preflight(client)
    for line in problems.values():
        print(f"dask_sweep: skipping {line}", file=stream)
    if not good:
        import shadelab

        print(f"dask_sweep: no worker can render ({len(problems)} connected, none with shadelab "
              f"{shadelab.__version__}); nothing rendered", file=stream)
        return None, {}
    names = [f"material-{i:04d}" for i in range(len(scene_dicts))]

    def write(i, pixels):
        if out is not None:
            import shadelab

            shadelab.Image.from_array(pixels).save(Path(out) / f"{names[i]}.png")  # atomic, as the binary writes

    try:
        futures = submit(client, scene_dicts, source, size, renderer, spp, seed, good, retries)
        failures = collect(futures, write)
    finally:
        if isinstance(source, dict) and "files" in source:
            client.run(_forget_bundle, source["key"], workers=good, on_error="ignore")
    report_failures(failures, names, stream)
    return good, failures


def report_failures(failures, names, stream=None):
    """One line per distinct error on `stream` (default sys.stderr), naming its tasks (the first five, then a count)
    and the workers they failed on."""
    stream = sys.stderr if stream is None else stream
    by_reason = {}
    for i in sorted(failures):
        where, why = failures[i]
        tasks, workers = by_reason.setdefault(why, ([], []))
        tasks.append(names[i])
        if where not in workers:
            workers.append(where)
    for why, (tasks, workers) in by_reason.items():
        more = f" and {len(tasks) - 5} more" if len(tasks) > 5 else ""
        print(f"dask_sweep: {', '.join(tasks[:5])}{more} failed (on {', '.join(workers)}): {why}", file=stream)


def local_cluster(workers):
    """A LocalCluster of `workers` processes with one thread each. No dashboard (it needs bokeh), and the
    scheduler's HTTP endpoints on a free port rather than 8787, so that clusters started side by side do not
    collide. Its workers log errors only: a failed task is reported by the sweep, not also by each worker's
    "Compute Failed" warning."""
    import logging

    from dask.distributed import LocalCluster

    return LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=":0",
                        scheduler_kwargs={"dashboard": False}, host="127.0.0.1", silence_logs=logging.ERROR)


def _size(text):
    w, sep, h = text.lower().partition("x")
    if not sep or not w.isdigit() or not h.isdigit() or int(w) < 1 or int(h) < 1:
        raise argparse.ArgumentTypeError(f"expected WxH, e.g. 640x360, got {text!r}")
    return int(w), int(h)


def _positive(text):
    value = int(text)
    if value < 1:
        raise argparse.ArgumentTypeError(f"must be at least 1, got {value}")
    return value


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--scheduler", help="a Dask scheduler's address, tcp://host:8786 (default: start a "
                                            "LocalCluster on this machine)")
    parser.add_argument("--workers", type=_positive, default=2,
                        help="LocalCluster worker processes, one thread each (default 2; not with --scheduler)")
    parser.add_argument("--materials", type=_positive, default=64, help="renders in the grid (default 64)")
    parser.add_argument("--scene", default="default",
                        help="the name of a scene shadelab ships (shadelab.data.scenes()), or a scene file (.json, "
                             ".gltf, .glb) whose first object's material is swept (default: default)")
    parser.add_argument("--size", type=_size, default="160x90", help="WxH of each render (default 160x90)")
    parser.add_argument("--renderer", default="raster", choices=["raster", "trace", "path"],
                        help="raster (OpenGL), trace (the Whitted reference) or path (the path tracer; global "
                             "illumination); default raster")
    parser.add_argument("--spp", type=_positive,
                        help="samples per pixel (default 1, and 16 for path; raster and trace take a perfect "
                             "square up to 64)")
    parser.add_argument("--seed", type=int,
                        help="path only: the random numbers' seed, 0..4294967295; the same seed gives the same "
                             "images byte for byte (default 0)")
    parser.add_argument("--retries", type=int, default=1,
                        help="times a failed task is tried again, on any usable worker (default 1)")
    parser.add_argument("--out", help="folder for the PNGs, material-NNNN.png (default: render only)")
    args = parser.parse_args(argv)
    if args.seed is not None and args.renderer != "path":
        parser.error("--seed goes with --renderer path")
    if args.scheduler and args.workers != parser.get_default("workers"):
        parser.error("--workers starts a LocalCluster; with --scheduler the cluster has the workers it has")
    if args.retries < 0:
        parser.error(f"--retries must be 0 or more, got {args.retries}")

    from dask.distributed import Client

    import shadelab
    # A shipped scene goes by its name; anything else is a file read here, sent with the files it reads.
    if args.scene in shadelab.data.scenes():
        base = shadelab.data.scene(args.scene)
        scenes, source = material_grid(args.materials, base), {"shipped": args.scene}
    else:
        try:
            base = shadelab.Scene.load(args.scene)
        except (OSError, ValueError) as error:  # shadelab.InputError is a ValueError
            print(f"dask_sweep: {error}", file=sys.stderr)
            return 1
        scenes, source = pack(material_grid(args.materials, base), base.base_dir)
    out = Path(args.out) if args.out else None
    if out is not None:
        out.mkdir(parents=True, exist_ok=True)
    cluster = None if args.scheduler else local_cluster(args.workers)
    try:
        with Client(args.scheduler or cluster) as client:
            start = time.perf_counter()
            good, failures = run_sweep(client, scenes, source, args.size, args.renderer, args.spp, args.seed,
                                       args.retries, out)
            elapsed = time.perf_counter() - start
    finally:
        if cluster is not None:
            cluster.close()
    if good is None:
        return 1
    done = len(scenes) - len(failures)
    print(f"{done} of {len(scenes)} renders of {args.size[0]}x{args.size[1]} ({args.renderer}) on {len(good)} "
          f"worker{'s' if len(good) != 1 else ''} in {elapsed:.2f} s ({done / elapsed:.1f}/s)")
    if out is not None and done:
        print(f"wrote {done} images to {out}/material-*.png")
    return 1 if failures else 0

if __name__ == "__main__":
    sys.exit(main())
