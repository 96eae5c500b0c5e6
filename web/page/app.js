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
  let globalJob = null;         // {workers, image, samples}
  let workers = [];
  let job = 0;
  const uploads = new Map();    // path -> bytes of the files opened from disk, which the workers need too

  function setMessage(line) { message = line || ''; $('message').textContent = message; }
  function state() { return JSON.parse(lab.stateJson()); }
  function imageOf(bytes) {
    const img = new ImageData(width, height);
    img.data.set(bytes);
    return img;
  }

  // --- pictures -------------------------------------------------------------------------------------------
  function renderRaster() {
    const bytes = lab.renderRaster(width, height);
    if (typeof bytes === 'string') { setMessage(bytes); return; }
    rasterImage = imageOf(bytes);
  }

  // What a worker needs to rebuild the scene: its JSON, its folder, and the files opened from disk.
  function sceneMessage() {
    return { sceneJson: lab.sceneJson(), sceneDir: lab.sceneDir(), files: [...uploads].map(([path, bytes]) => ({ path, bytes })) };
  }

  function stopWorkers() { workers.forEach((w) => w.terminate()); workers = []; }

  // The Whitted reference of the scene as it is now, traced by the workers over tiles.
  function startReference() {
    stopWorkers();
    const id = ++job, w = width, h = height;
    const rgba = new Float32Array(w * h * 4), coverage = new Uint32Array(w * h);
    const msg = { kind: 'reference', job: id, ...sceneMessage(), width: w, height: h };
    let count = -1, arrived = 0;
    const r = { revision: lab.referenceRevision(), width: w, height: h, image: null };
    r.done = new Promise((resolve, reject) => {
      for (let k = 0; k < WORKERS; ++k) {
        const worker = new Worker('worker.js');
        worker.onmessage = (e) => {
          const m = e.data;
          if (m.job !== id) return;
          if (m.kind === 'error') { setMessage(m.error); reject(new Error(m.error)); return; }
          if (m.kind === 'count') { count = m.count; return; }
          const t = m.tile;
          for (let y = 0; y < t.height; ++y) {
            rgba.set(t.rgba.subarray(y * t.width * 4, (y + 1) * t.width * 4), ((t.y0 + y) * w + t.x0) * 4);
            coverage.set(t.coverage.subarray(y * t.width, (y + 1) * t.width), (t.y0 + y) * w + t.x0);
          }
          ++arrived;
          $('progress').textContent = `reference ${Math.round(100 * arrived / count)} %`;
          if (arrived === count) {
            const bytes = lab.setReference(rgba, coverage, w, h);
            if (typeof bytes === 'string') { setMessage(bytes); reject(new Error(bytes)); return; }
            r.image = imageOf(bytes);
            $('progress').textContent = '';
            stopWorkers();
            resolve(r.image);
            show();
          }
        };
        worker.postMessage({ ...msg, first: k, step: WORKERS });
        workers.push(worker);
      }
    });
    r.done.catch(() => {});
    reference = r;
  }

  function startGlobal() {
    stopWorkers();
    const id = ++job, w = width, h = height;
    const worker = new Worker('worker.js');
    globalJob = { image: null, samples: 0 };
    worker.onmessage = (e) => {
      const m = e.data;
      if (m.job !== id) return;
      if (m.kind === 'error') { setMessage(m.error); return; }
      const bytes = lab.encodeGlobal(m.rgba, w, h);
      if (typeof bytes === 'string') { setMessage(bytes); return; }
      globalJob.image = imageOf(bytes);
      globalJob.samples = m.samples;
      $('progress').textContent = `path traced: ${m.samples} samples per pixel`;
      show();
    };
    worker.postMessage({ kind: 'global', job: id, ...sceneMessage(), width: w, height: h, samples: 4096 });
    workers.push(worker);
  }

  function referenceCurrent() {
    return reference && reference.revision === lab.referenceRevision() && reference.width === width && reference.height === height;
  }

  // Draws what the view mode shows; starts the tracers the mode needs and are not current.
  function show() {
    if (!rasterImage) return;
    $('difference-text').textContent = '';
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
    exportScene() { return lab.sceneJson(); },
    message() { return message; },
  };
  window.shadelab = api;

  api.ready = (async () => {
    M = await createShadelab();
    lab = M.createLab('#gl');
    if (!lab) { const e = M.createError(); setMessage(e); throw new Error(e); }
    wire();
    await loadScene('default.json');
  })();
  api.ready.catch((e) => setMessage(String(e.message || e)));
})();
