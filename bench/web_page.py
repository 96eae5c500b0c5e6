#!/usr/bin/python3
"""Benchmark of the web page (docs/web.md) in Debian's headless Chromium on SwiftShader, against the native
binary on the same machine in the same run. Prints medians:

- the page's size (HTML, JS, wasm, shipped scenes) before compression; target at most 4 MB;
- the first picture of the default scene at 960x540, from navigation (performance.now() when shadelab.ready
  resolves), each run in a fresh browser with a fresh profile, so nothing is cached; target at most 3 s;
- a frame while the shininess slider is dragged at 960x540 (one slider step per animation frame, the time from
  step to step), against the native viewer's frame at 960x540 with the same drag
  (`shadelab view --script bench/viewer_drag.json --frames N --stats` under Xvfb); target at most 2x;
- the Whitted reference of the default scene at 320x180 in the page's workers (scene sent, tiles traced and
  assembled), against `shadelab render --renderer trace --threads 2 --size 320x180`'s trace stage
  (--timings); target at most 2x;
- the Global view's path tracer at 320x180 over the page's workers, in samples per pixel per second, against
  `shadelab render --renderer path --threads 2`.

The page is served by `python3 -m http.server`, as a user would serve it: no COOP/COEP headers.
Usage: bench/web_page.py [--runs N] [--page DIR] [--bin PATH]   (defaults: 5, build-web/page, build/shadelab)"""

import argparse
import json
import os
import re
import socket
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

SOURCE = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(SOURCE / "tests" / "web"))
import cdp  # noqa: E402


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def chromium_version():
    out = subprocess.run([cdp.CHROMIUM, "--version"], capture_output=True, text=True).stdout.strip()
    return out or "unknown"


def page_size(page):
    return sum(f.stat().st_size for f in page.iterdir() if f.is_file())


def open_page(browser, url):
    page = browser.new_page()
    page.navigate(url, timeout=60)
    page.wait_for("window.shadelab && window.shadelab.ready && true", timeout=60)
    page.evaluate("shadelab.ready.then(() => true)", timeout=120)
    return page


def first_picture(url, runs, evidence):
    times = []
    for i in range(runs):
        with cdp.Browser(evidence / f"first-{i}", width=1400, height=900) as browser:
            page = open_page(browser, url)
            times.append(page.evaluate("shadelab.timings().firstPictureMs") / 1000.0)
    return times


def slider_and_reference(url, runs, evidence):
    with cdp.Browser(evidence / "frames", width=1400, height=900) as browser:
        page = open_page(browser, url)
        page.evaluate("shadelab.setSize(960, 540)", timeout=60)
        # The object the page selects on load is the scene's first, "red plastic": the one the viewer's
        # benchmark drags (bench/viewer_drag.json).
        assert "red plastic" in page.evaluate("document.querySelector('#selected-label').textContent")
        # A drag: one slider step a frame. The page draws in the animation frame after the input; the browser
        # holds the next frame back until the GPU (SwiftShader) has finished, so the time from one step to the
        # next is the frame time.
        frames = page.evaluate("""(async () => {
            const s = document.querySelector('#shininess'), out = [];
            let last = performance.now();
            for (let i = 0; i < 60; ++i) {
                s.value = String(3 + 4 * (i % 20) / 20);
                s.dispatchEvent(new Event('input'));
                await new Promise((r) => requestAnimationFrame(() => r()));
                const now = performance.now();
                out.push(now - last);
                last = now;
            }
            return out; })()""", timeout=300)
        page.evaluate("shadelab.setSize(320, 180)", timeout=60)
        references = []
        for i in range(runs + 1):  # the first one builds the workers' BVHs cold: a warm-up
            page.evaluate(f"shadelab.setSize({320 + (i % 2)}, 180)", timeout=60)
            page.evaluate("shadelab.setSize(320, 180)", timeout=60)
            time.sleep(0.3)  # the raster redraw of the new size is done: the reference alone is timed
            page.evaluate("shadelab.imageDataUrl('reference').then(() => true)", timeout=120)
            references.append(page.evaluate("shadelab.timings().referenceMs") / 1000.0)
        # Global: samples per pixel the workers reach in 6 s at 320x180, counted from the first whole pass.
        page.evaluate("shadelab.setView('global')", timeout=60)
        count = "parseInt((document.querySelector('#progress').textContent.match(/(\\d+) samples/) || [0, 0])[1])"
        page.wait_for(f"{count} >= 1", timeout=120)
        start, t0 = page.evaluate(count), time.monotonic()
        time.sleep(6)
        rate = (page.evaluate(count) - start) / (time.monotonic() - t0)
        page.evaluate("shadelab.setView('raster')", timeout=60)
        return frames[5:], references[1:], rate


def native_trace(binary, runs):
    times = []
    scene = SOURCE / "assets" / "scenes" / "default.json"
    with tempfile.TemporaryDirectory() as tmp:
        for _ in range(runs + 1):
            p = subprocess.run([binary, "render", str(scene), "--renderer", "trace", "--threads", "2", "--size",
                                "320x180", "-o", f"{tmp}/t.png", "--timings"], capture_output=True, text=True)
            m = re.search(r"^\s*trace\s+([\d.]+) ms", p.stderr, re.M)
            if not m:
                sys.exit(f"web_page: no trace stage in --timings: {p.stderr}")
            times.append(float(m.group(1)) / 1000.0)
    return times[1:]


def native_path_rate(binary):
    """Samples per pixel per second of `shadelab render --renderer path --threads 2` at 320x180."""
    scene = SOURCE / "assets" / "scenes" / "default.json"
    with tempfile.TemporaryDirectory() as tmp:
        p = subprocess.run([binary, "render", str(scene), "--renderer", "path", "--threads", "2", "--size", "320x180",
                            "--spp", "256", "-o", f"{tmp}/p.png"], capture_output=True, text=True)
    m = re.search(r"path traced (\d+) samples per pixel.* in ([\d.]+) s", p.stderr)
    if not m:
        sys.exit(f"web_page: no path tracer summary: {p.stderr}")
    return int(m.group(1)) / float(m.group(2))


def native_frames(binary, runs):
    medians = []
    for _ in range(runs):
        p = subprocess.run(["xvfb-run", "-a", "-s", "-screen 0 1920x1080x24", binary, "view",
                            str(SOURCE / "assets" / "scenes" / "default.json"), "--script",
                            str(SOURCE / "bench" / "viewer_drag.json"), "--size", "960x540", "--frames", "120",
                            "--stats"], capture_output=True, text=True)
        m = re.search(r"frame, raster redrawn.*?median\s+([\d.]+) ms", p.stdout + p.stderr)
        if not m:
            sys.exit(f"web_page: no frame statistics from shadelab view: {p.stdout}{p.stderr}")
        medians.append(float(m.group(1)))
    return medians


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--runs", type=int, default=5)
    ap.add_argument("--page", type=Path, default=SOURCE / "build-web" / "page")
    ap.add_argument("--bin", default=str(SOURCE / "build" / "shadelab"))
    a = ap.parse_args()
    if not (a.page / "shadelab.wasm").is_file():
        sys.exit(f"web_page: {a.page} has no built page (scripts/web.sh --build-only)")
    evidence = Path(tempfile.mkdtemp(prefix="shadelab-web-bench-"))
    port = free_port()
    server = subprocess.Popen([sys.executable, "-m", "http.server", str(port), "--bind", "127.0.0.1", "--directory",
                               str(a.page)], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        time.sleep(0.5)
        url = f"http://127.0.0.1:{port}/index.html"
        cpu = next((l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name")), "?")
        print(f"machine: {os.cpu_count()} cores, {cpu}; {chromium_version()} (SwiftShader)")
        size = page_size(a.page)
        print(f"page size: {size / 1e6:.2f} MB (target <= 4 MB)")
        first = first_picture(url, a.runs, evidence)
        print(f"first picture, default scene 960x540: median {statistics.median(first):.2f} s "
              f"(runs {', '.join(f'{t:.2f}' for t in first)}; target <= 3 s)")
        frames, refs, global_rate = slider_and_reference(url, a.runs, evidence)
        native = native_frames(a.bin, a.runs)
        page_frame, native_frame = statistics.median(frames), statistics.median(native)
        print(f"shininess drag frame at 960x540: page median {page_frame:.1f} ms, native viewer median "
              f"{native_frame:.1f} ms (runs {', '.join(f'{t:.1f}' for t in native)}): "
              f"{page_frame / native_frame:.2f}x (target <= 2x)")
        trace = native_trace(a.bin, a.runs)
        page_ref, native_ref = statistics.median(refs), statistics.median(trace)
        print(f"Whitted reference 320x180: page workers median {page_ref * 1000:.0f} ms "
              f"(runs {', '.join(f'{t * 1000:.0f}' for t in refs)}), native --threads 2 median "
              f"{native_ref * 1000:.0f} ms: {page_ref / native_ref:.2f}x (target <= 2x)")
        native_rate = native_path_rate(a.bin)
        print(f"Global (path tracer) 320x180: page {global_rate:.1f} samples per pixel per second, native --threads 2 "
              f"{native_rate:.1f}: the page takes {native_rate / global_rate:.2f}x the time")
        print(f"evidence (browser logs): {evidence}")
    finally:
        server.terminate()


if __name__ == "__main__":
    main()
