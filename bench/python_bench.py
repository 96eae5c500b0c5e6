#!/usr/bin/env python3
"""The Python package's benchmarks, printing medians; run by hand, never as a test:

    PYTHONPATH=build/python /usr/bin/python3 bench/python_bench.py build/shadelab [--runs 5]

1. 64x64 renders of the default scene with one reused Renderer: renders per second (median per render).
2. 1280x720: a reused Renderer's render() against the binary's "draw" + "readback + conversion" stages
   (`shadelab render --timings`), both medians.
3. The first render in a fresh process (python3 -c 'import shadelab; render; save') against the binary's whole
   process (`shadelab render -o`), both wall time, medians; also the fresh process rendering to memory only.
"""

import argparse
import re
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import shadelab

REPO = Path(__file__).resolve().parents[1]
SCENE = REPO / "assets" / "scenes" / "default.json"


def median_ms(samples):
    return statistics.median(samples) * 1000.0


def wall(cmd):
    """(wall, CPU) seconds of a whole child process; CPU (user + sys, every thread) is the steadier figure when
    other jobs share the machine."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t = time.perf_counter()
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    elapsed = time.perf_counter() - t
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return elapsed, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def binary_stages(binary, out, runs):
    """Median draw + readback (ms) of `shadelab render --timings` at 1280x720."""
    totals, draws = [], []
    for _ in range(runs):
        p = subprocess.run([binary, "render", SCENE, "-o", out, "--timings"], check=True, capture_output=True,
                           text=True)
        draw = float(re.search(r"draw.*?([\d.]+) ms", p.stderr).group(1))
        read = float(re.search(r"readback \+ conversion\s+([\d.]+) ms", p.stderr).group(1))
        draws.append(draw)
        totals.append(draw + read)
    return statistics.median(totals), statistics.median(draws)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("binary")
    parser.add_argument("--runs", type=int, default=5)
    args = parser.parse_args()
    scene = shadelab.Scene.load(SCENE)
    print(f"GL: {shadelab.default_renderer().info['gl_renderer']}; python {sys.version.split()[0]}")

    # 1. Small renders through one Renderer.
    r = shadelab.Renderer()
    for _ in range(5):
        r.render(scene, (64, 64))
    per = []
    for _ in range(200):
        t = time.perf_counter()
        r.render(scene, (64, 64))
        per.append(time.perf_counter() - t)
    print(f"1. 64x64 default scene, reused Renderer: median {median_ms(per):.2f} ms per render = "
          f"{1.0 / statistics.median(per):.0f} renders/s (target >= 50/s)")
    per_trace = []
    for _ in range(50):
        t = time.perf_counter()
        r.render(scene, (64, 64), renderer="trace")
        per_trace.append(time.perf_counter() - t)
    print(f"   (trace: median {median_ms(per_trace):.2f} ms = {1.0 / statistics.median(per_trace):.0f} renders/s)")

    # 2. 1280x720 against the binary's draw and readback stages, interleaved run by run (the machine is shared:
    #    back-to-back pairs see the same load).
    with tempfile.TemporaryDirectory() as tmp:
        out = str(Path(tmp) / "b.png")
        r.render(scene, (1280, 720))  # warm: the variant's lazy compile happens in the first draw
        stages, draws, calls, inner = [], [], [], []
        for _ in range(args.runs):
            total, draw = binary_stages(args.binary, out, 1)
            stages.append(total)
            draws.append(draw)
            image = None  # the previous image is freed outside the timing, as the binary frees nothing
            t = time.perf_counter()
            image = r.render(scene, (1280, 720))
            calls.append(time.perf_counter() - t)
            inner.append(image.timings["draw_ms"] + image.timings["read_ms"])
        binary = statistics.median(stages)
        print(f"2. 1280x720: binary draw + readback median {binary:.1f} ms (draw {statistics.median(draws):.1f} ms, "
              f"incl. its lazy compile); Python render() median {median_ms(calls):.1f} ms (draw + read inside "
              f"{statistics.median(inner):.1f} ms) = {median_ms(calls) / binary:.2f} of the binary's "
              f"(target <= 1.10)")

        # 3. Fresh processes, interleaved.
        py = sys.executable
        code = "import shadelab; shadelab.render({scene!r}, (1280, 720)){save}"
        to_file = [py, "-c", code.format(scene=str(SCENE), save=f".save({out!r})")]
        to_memory = [py, "-c", code.format(scene=str(SCENE), save="")]
        # The first render() call alone, timed inside a fresh process (context, programs, draw, readback).
        first_call = [py, "-c", "import time, shadelab; t = time.perf_counter(); shadelab.render({!r}, (1280, 720)); "
                      "print(time.perf_counter() - t)".format(str(SCENE))]
        cli = [args.binary, "render", str(SCENE), "-o", out]
        wall(cli)  # Mesa's shader cache warm for both
        runs = {"binary": [], "save": [], "memory": []}
        calls = []
        for _ in range(args.runs):
            runs["binary"].append(wall(cli))
            runs["save"].append(wall(to_file))
            runs["memory"].append(wall(to_memory))
            out_call = subprocess.run(first_call, check=True, capture_output=True, text=True).stdout
            calls.append(float(out_call))
        med = {k: (median_ms([w for w, _ in v]), median_ms([c for _, c in v])) for k, v in runs.items()}
        b = med["binary"]
        print(f"3. fresh process, 1280x720 default scene, medians, wall / CPU: binary whole process "
              f"{b[0]:.0f} / {b[1]:.0f} ms; python3 import + render + save {med['save'][0]:.0f} / {med['save'][1]:.0f} ms "
              f"({med['save'][0] / b[0]:.2f} / {med['save'][1] / b[1]:.2f}); import + render to memory "
              f"{med['memory'][0]:.0f} / {med['memory'][1]:.0f} ms ({med['memory'][0] / b[0]:.2f} / "
              f"{med['memory'][1] / b[1]:.2f}) (target <= 1.00)")
        print(f"   the first shadelab.render() call in a fresh process (timed inside it): median {median_ms(calls):.0f} ms "
              f"= {median_ms(calls) / b[0]:.2f} of the binary's whole process")


if __name__ == "__main__":
    main()
