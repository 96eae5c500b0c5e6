// The page's script: it moves the DOM, the canvas and the workers, and nothing else. Every scene rule,
// lighting formula and name lives in the C++ (web/src/page_lab.h): an edit here is a viewer-script action
// handed to lab.act(), a picture is lab.renderRaster() or the workers' tiles.
'use strict';
(() => {
  const $ = (id) => document.getElementById(id);
  const view = $('view');
  const ctx2d = view.getContext('2d');
  const WORKERS = Math.max(1, Math.min(8, (navigator.hardwareConcurrency || 2)));
  const VIEWS = ['raster', 'reference', 'split', 'difference', 'global'];

  let M = null, lab = null;
  let width = 960, height = 540, mode = 'raster', message = '', split = 0.5;
  let rasterImage = null;       // ImageData of the last raster picture
  let rasterRevision = -1;      // lab.revision() it was drawn at
  let reference = null;         // {revision, width, height, image, done: Promise}
  let globalJob = null;         // {image, samples}
  let pool = null;              // the tracers' workers (tracer_pool.js)
  const uploads = new Map();    // path -> bytes of the files opened from disk, which the workers need too

  function setMessage(line) { message = line || ''; $('message').textContent = message; }
  function state() { return JSON.parse(lab.stateJson()); }
  function imageOf(bytes) {
    const img = new ImageData(width, height);
    img.data.set(bytes);
    return img;
  }

  // --- pictures -------------------------------------------------------------------------------------------
  // What the benchmarks read (bench/web_page.py): milliseconds since navigation to the first picture, of the
  // last raster frame (draw, readback, ImageData) and of the last complete reference (scene sent to the workers,
  // tiles traced and assembled, encoded).
  const timings = { firstPictureMs: null, rasterMs: null, referenceMs: null };

  function renderRaster() {
    const t0 = performance.now();
    const bytes = lab.renderRaster(width, height);
    if (typeof bytes === 'string') { setMessage(bytes); return; }
    rasterImage = imageOf(bytes);
    timings.rasterMs = performance.now() - t0;
  }

  // What a worker needs to rebuild the scene: its JSON, its folder, and the files opened from disk.
  function sceneMessage() {
    return { sceneJson: lab.sceneJson(), sceneDir: lab.sceneDir(), files: [...uploads].map(([path, bytes]) => ({ path, bytes })) };
  }

  // The Whitted reference of the scene as it is now, traced by the pool's workers over tiles.
  function startReference() {
    const w = width, h = height, t0 = performance.now();
    const r = { revision: lab.referenceRevision(), width: w, height: h, image: null };
    r.done = pool.reference(sceneMessage(), w, h, (f) => { $('progress').textContent = `reference ${Math.round(100 * f)} %`; })
      .then(({ rgba, coverage }) => {
        $('progress').textContent = '';
        const bytes = lab.setReference(rgba, coverage, w, h);
        if (typeof bytes === 'string') throw new Error(bytes);
        r.image = imageOf(bytes);
        timings.referenceMs = performance.now() - t0;
        if (reference === r) show();
        return r.image;
      });
    r.done.catch((e) => {
      if (reference === r) reference = null;  // traced again when next shown
      if (e.message !== 'cancelled') setMessage(e.message);
    });
    reference = r;
  }

  function startGlobal() {
    const w = width, h = height;
    const job = { image: null, samples: 0 };
    globalJob = job;
    pool.global(sceneMessage(), w, h, (m) => {
      const bytes = lab.encodeGlobal(m.rgba, w, h);
      if (typeof bytes === 'string') { setMessage(bytes); return; }
      job.image = imageOf(bytes);
      job.samples = m.samples;
      $('progress').textContent = `path traced: ${m.samples} samples per pixel`;
      if (globalJob === job) show();
    }, (e) => setMessage(e.message));
  }

  function referenceCurrent() {
    return reference && reference.revision === lab.referenceRevision() && reference.width === width && reference.height === height;
  }

  // Draws what the view mode shows; starts the tracers the mode needs and are not current.
  function show() {
    if (!rasterImage) return;
    $('difference-text').textContent = '';
    if (mode !== 'global' && pool.running() === 'global') { pool.stop(); globalJob = null; }  // nobody watches it
    if (mode === 'raster') { ctx2d.putImageData(rasterImage, 0, 0); return; }
    if (mode === 'global') {
      if (!globalJob) startGlobal();
      ctx2d.putImageData(globalJob.image || rasterImage, 0, 0);
      return;
    }
    if (!referenceCurrent()) startReference();
    const ref = reference.image;
    if (mode === 'reference') { ctx2d.putImageData(ref || rasterImage, 0, 0); return; }
    if (mode === 'split') {
      ctx2d.putImageData(rasterImage, 0, 0);
      if (ref) ctx2d.putImageData(ref, 0, 0, Math.round(split * width), 0, width, height);
      ctx2d.fillStyle = '#fff';
      ctx2d.fillRect(Math.round(split * width), 0, 1, height);
      return;
    }
    if (mode === 'difference') {
      if (!ref) { ctx2d.putImageData(rasterImage, 0, 0); return; }
      const heat = lab.differenceImage();
      if (heat.length) ctx2d.putImageData(imageOf(heat), 0, 0);
      $('difference-text').textContent = lab.differenceText();
    }
  }

  // Redraws the raster picture for the state as it is, once per animation frame however many edits came.
  let pending = null;
  function redraw() {
    if (pending) return pending;
    pending = new Promise((resolve) => requestAnimationFrame(() => {
      pending = null;
      // Only a change a renderer sees (lab.revision(), which every edit, camera move and load bumps) or a new
      // size draws again and restarts the path tracer; asking for the picture again draws nothing.
      const revision = lab.revision();
      if (!rasterImage || revision !== rasterRevision || rasterImage.width !== width || rasterImage.height !== height) {
        globalJob = null;
        renderRaster();
        rasterRevision = revision;
      }
      show();
      updateControls();
      resolve();
    }));
    return pending;
  }

  function act(action) {
    const error = lab.act(JSON.stringify(action));
    if (error) setMessage(error);
    return redraw();
  }

  // --- controls -------------------------------------------------------------------------------------------
  function updateControls() {
    const s = state();
    document.querySelectorAll('[data-step]').forEach((b) => b.classList.toggle('on', Number(b.dataset.step) === s.step));
    $('model').value = s.model;
    const selected = s.objects.find((o) => o.id === s.selected);
    $('selected-label').textContent = selected ? selected.label : 'nothing';
    if (s.material) {
      if (document.activeElement !== $('shininess')) $('shininess').value = Math.log2(Math.max(1, s.material.s));
      $('shininess-value').textContent = s.material.s.toPrecision(4);
    }
    $('caption').textContent = `${s.title || s.file} · ${s.model} · step ${s.step}`;
  }

  // What the last load warned about (a texture over the limit, an ignored feature), as one line.
  function warningLine() {
    const w = state().warnings;
    return w.length ? w[0] + (w.length > 1 ? ` (and ${w.length - 1} more warnings)` : '') : '';
  }

  function sceneNames() {
    return M.FS.readdir('/assets/scenes').filter((n) => n.endsWith('.json')).sort();
  }

  async function loadScene(name) {
    const error = lab.open('/assets/scenes/' + name);
    if (error) { setMessage(error); throw new Error(error); }
    setMessage(warningLine());
    $('scene').value = name;
    reference = null;
    await redraw();
  }

  async function openFile(file) {
    const bytes = new Uint8Array(await file.arrayBuffer());
    const dir = '/upload';
    try { M.FS.mkdir(dir); } catch (e) { /* exists */ }
    const path = dir + '/' + file.name.replace(/[\/\0]/g, '_');
    M.FS.writeFile(path, bytes);
    uploads.set(path, bytes);
    $('scene').value = '';  // no shipped scene is shown now
    const error = lab.open(path);
    setMessage(error || warningLine());
    reference = null;
    await redraw();
  }

  function wire() {
    for (const name of sceneNames()) $('scene').add(new Option(name, name));
    $('scene').addEventListener('change', () => loadScene($('scene').value).catch(() => {}));
    document.querySelectorAll('[data-step]').forEach((b) =>
      b.addEventListener('click', () => act({ action: 'progression', step: Number(b.dataset.step) })));
    addEventListener('keydown', (e) => {
      if (e.target instanceof HTMLInputElement || e.target instanceof HTMLSelectElement) return;
      if (e.key >= '0' && e.key <= '5') act({ action: 'progression', step: Number(e.key) });
    });
    $('model').addEventListener('change', () => act({ action: 'setModel', model: $('model').value }));
    $('view-mode').addEventListener('change', () => api.setView($('view-mode').value));
    $('shininess').addEventListener('input', () => {
      const s = state();
      if (s.selected) act({ action: 'setShininess', object: '#' + s.selected, s: Math.pow(2, Number($('shininess').value)) });
    });
    $('open-file').addEventListener('change', () => { const f = $('open-file').files[0]; if (f) openFile(f); });
    $('save').addEventListener('click', () => {
      const url = URL.createObjectURL(new Blob([lab.sceneJson()], { type: 'application/json' }));
      const a = document.createElement('a');
      a.href = url; a.download = 'scene.json'; a.click();
      setTimeout(() => URL.revokeObjectURL(url), 1000);
    });

    // Mouse and touch: drag orbits (right button or shift: pans), the wheel zooms, a click selects and probes.
    let drag = null;
    view.addEventListener('contextmenu', (e) => e.preventDefault());
    view.addEventListener('pointerdown', (e) => {
      view.setPointerCapture(e.pointerId);
      drag = { x: e.clientX, y: e.clientY, moved: false, pan: e.button === 2 || e.shiftKey, wipe: mode === 'split' };
    });
    view.addEventListener('pointermove', (e) => {
      if (!drag) return;
      const scale = width / view.clientWidth, dx = (e.clientX - drag.x) * scale, dy = (e.clientY - drag.y) * scale;
      if (!drag.moved && Math.hypot(dx, dy) < 3) return;
      drag.moved = true;
      drag.x = e.clientX; drag.y = e.clientY;
      if (drag.wipe) {
        const r = view.getBoundingClientRect();
        split = Math.min(1, Math.max(0, (e.clientX - r.left) / r.width));
        show();
        return;
      }
      if (drag.pan) lab.pan(dx, dy, height); else lab.orbit(dx, dy);
      redraw();
    });
    view.addEventListener('pointerup', (e) => {
      const d = drag;
      drag = null;
      if (!d || d.moved) return;
      const r = view.getBoundingClientRect();
      const x = Math.floor((e.clientX - r.left) * width / r.width), y = Math.floor((e.clientY - r.top) * height / r.height);
      const id = lab.objectAt(x, y);
      if (id) act({ action: 'select', object: '#' + id });
      $('probe').textContent = lab.probe(x, y, width, height);
    });
    view.addEventListener('wheel', (e) => { e.preventDefault(); lab.zoom(-Math.sign(e.deltaY)); redraw(); }, { passive: false });
  }

  function pngOf(image) {
    const c = document.createElement('canvas');
    c.width = image.width; c.height = image.height;
    c.getContext('2d').putImageData(image, 0, 0);
    return c.toDataURL('image/png');
  }

  // The page's interface for its tests (tests/web/README.md) and for anyone at the console.
  const api = {
    ready: null,
    loadScene,
    async setSize(w, h) {
      if (!(Number.isInteger(w) && Number.isInteger(h) && w >= 1 && h >= 1 && w <= 4096 && h <= 4096))
        throw new Error(`setSize: ${w}x${h} is not a size from 1x1 to 4096x4096`);
      width = w; height = h; view.width = w; view.height = h;
      reference = null;
      await redraw();
    },
    setView(m) {
      if (!VIEWS.includes(m)) throw new Error(`setView: no view "${m}"; one of ${VIEWS.join(', ')}`);
      mode = m;
      $('view-mode').value = m;
      show();
    },
    async imageDataUrl(which) {
      await redraw();
      if (which === 'raster') return pngOf(rasterImage);
      if (which !== 'reference') throw new Error(`imageDataUrl: "${which}" is not raster or reference`);
      if (!referenceCurrent()) startReference();
      return pngOf(await reference.done);
    },
    async coverageDataUrl(which) {
      if (which !== 'raster') throw new Error(`coverageDataUrl: "${which}" is not raster`);
      await redraw();
      return pngOf(imageOf(lab.rasterCoverageImage()));
    },
    exportScene() { return lab.sceneJson(); },
    timings() { return { ...timings }; },
    message() { return message; },
  };
  window.shadelab = api;

  api.ready = (async () => {
    // The wasm is compiled once here and handed to the workers, which would otherwise compile it again each.
    const wasm = await WebAssembly.compileStreaming(fetch('shadelab.wasm'));
    M = await createShadelab({
      instantiateWasm(imports, success) {
        WebAssembly.instantiate(wasm, imports).then((instance) => success(instance, wasm));
        return {};
      },
    });
    pool = new TracerPool(WORKERS, wasm);
    lab = M.createLab('#gl');
    if (!lab) { const e = M.createError(); setMessage(e); throw new Error(e); }
    wire();
    await loadScene('default.json');
    timings.firstPictureMs = performance.now();  // performance.now() counts from navigation
  })();
  api.ready.catch((e) => setMessage(String(e.message || e)));
})();
