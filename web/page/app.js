// The page's script: it moves the DOM, the canvas and the workers, and nothing else. Every scene rule,
// lighting formula and name lives in the C++ (web/src/page_lab.h): an edit here is a viewer-script action
// handed to lab.act(), a picture is lab.renderRaster() or the workers' tiles.
'use strict';
(() => {
  const $ = (id) => document.getElementById(id);
  // A text or a control's value written only when it changes: the same text written again still has the browser
  // lay the page out, repaint it and composite the window (on SwiftShader, CPU work that the tracing workers feel
  // on a 2-core machine, since every redraw writes every label).
  const setText = (el, text) => { if (el.textContent !== text) el.textContent = text; };
  const setValue = (el, value) => { if (el.value !== String(value)) el.value = value; };
  const view = $('view');        // the 2D canvas over the GL one: every view but Raster
  const glCanvas = $('gl');      // the rasterizer's WebGL2 canvas: Raster is drawn here, nothing read back
  const stage = $('stage');      // both canvases; the pointer's events land here
  const ctx2d = view.getContext('2d');
  const WORKERS = Math.max(1, Math.min(8, (navigator.hardwareConcurrency || 2)));
  const VIEWS = ['raster', 'reference', 'split', 'difference', 'global'];

  let M = null, lab = null;
  let width = 960, height = 540, mode = 'raster', message = '', split = 0.5;
  let rasterImage = null;       // ImageData of the raster picture read back (other views, images), or null
  let rasterRevision = -1;      // lab.revision() the pictures are of
  let glDrawn = false;          // the GL canvas shows the raster picture of that revision and size
  let reference = null;         // {revision, width, height, image, done: Promise}
  let globalJob = null;         // {image, samples}
  let pool = null;              // the tracers' workers (tracer_pool.js)
  const uploads = new Map();    // path -> bytes of the files opened from disk, which the workers need too

  function setMessage(line) { message = line || ''; setText($('message'), message); }
  function state() { return JSON.parse(lab.stateJson()); }
  function imageOf(bytes) {
    const img = new ImageData(width, height);
    img.data.set(bytes);
    return img;
  }

  // --- pictures -------------------------------------------------------------------------------------------
  // What the benchmarks read (bench/web_page.py): milliseconds since navigation to the first picture, of the
  // page's script in the last redraw and of its GL draw (drawRaster; WebGL makes it wait for SwiftShader), of the
  // last raster picture read back (draw, readback, ImageData) and of the last complete reference (scene sent to
  // the workers, tiles traced and assembled, encoded).
  const timings = { firstPictureMs: null, frameMs: null, drawMs: null, rasterMs: null, referenceMs: null };

  // The raster picture read back, as `shadelab render` writes it: for the views that combine it, and the images.
  function rasterPicture() {
    if (rasterImage) return rasterImage;
    const t0 = performance.now();
    const bytes = lab.renderRaster(width, height);
    if (typeof bytes === 'string') { setMessage(bytes); return null; }
    rasterImage = imageOf(bytes);
    timings.rasterMs = performance.now() - t0;
    return rasterImage;
  }

  // The raster picture on the GL canvas (the viewer's display pass and partial redraw; nothing read back).
  function drawGl() {
    if (glCanvas.width !== width || glCanvas.height !== height) { glCanvas.width = width; glCanvas.height = height; }
    const t0 = performance.now();
    const error = lab.drawRaster(width, height);
    timings.drawMs = performance.now() - t0;
    if (error) setMessage(error);
    glDrawn = true;
  }

  // What a worker needs to rebuild the scene: its JSON, its folder, and the files opened from disk.
  function sceneMessage() {
    return { sceneJson: lab.sceneJson(), sceneDir: lab.sceneDir(), files: [...uploads].map(([path, bytes]) => ({ path, bytes })) };
  }

  // The Whitted reference of the scene as it is now, traced by the pool's workers over tiles.
  function startReference() {
    if (pool.running() === 'global') globalJob = null;  // the pool stops it; Global starts again when shown
    const w = width, h = height, t0 = performance.now();
    const r = { revision: lab.referenceRevision(), width: w, height: h, image: null };
    // The progress line appears after a quarter of a second and changes at most four times a second: each change
    // repaints and composites the window, which on SwiftShader costs the workers more than a small reference takes.
    let shown = t0;
    const progress = (f) => {
      const now = performance.now();
      if (now - shown < 250) return;
      shown = now;
      setText($('progress'), `reference ${Math.round(100 * f)} %`);
    };
    r.done = pool.reference(sceneMessage(), w, h, progress)
      .then(({ rgb, coverage }) => {
        setText($('progress'), '');
        const bytes = lab.setReference(rgb, coverage, w, h);
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

  // The path tracer's progressive picture, up to `limit` samples per pixel; job.done resolves with it there.
  function startGlobal(limit = 4096) {
    const w = width, h = height;
    const job = { image: null, samples: 0 };
    job.done = new Promise((resolve, reject) => { job.resolve = resolve; job.reject = reject; });
    job.done.catch(() => {});
    globalJob = job;
    pool.global(sceneMessage(), w, h, (m) => {
      const bytes = lab.encodeGlobal(m.rgba, w, h);
      if (typeof bytes === 'string') { setMessage(bytes); job.reject(new Error(bytes)); return; }
      job.image = imageOf(bytes);
      job.samples = m.samples;
      setText($('progress'), `path traced: ${m.samples} samples per pixel`);
      if (m.samples >= limit) job.resolve(job.image);
      if (globalJob === job) show();
    }, (e) => { setMessage(e.message); job.reject(e); }, limit);
  }

  function referenceCurrent() {
    return reference && reference.revision === lab.referenceRevision() && reference.width === width && reference.height === height;
  }

  // Draws what the view mode shows; starts the tracers the mode needs and are not current.
  function show() {
    setText($('difference-text'), '');
    if (mode !== 'global' && pool.running() === 'global') {  // nobody watches it
      pool.stop();
      globalJob = null;
      setText($('progress'), '');
    }
    view.classList.toggle('off', mode === 'raster');
    if (mode === 'raster') { if (!glDrawn) drawGl(); return; }
    const raster = rasterPicture();
    if (!raster) return;
    if (mode === 'global') {
      if (!globalJob) startGlobal();
      ctx2d.putImageData(globalJob.image || raster, 0, 0);
      return;
    }
    if (!referenceCurrent()) startReference();
    const ref = reference.image;
    if (mode === 'reference') { ctx2d.putImageData(ref || raster, 0, 0); return; }
    if (mode === 'split') {
      ctx2d.putImageData(raster, 0, 0);
      if (ref) ctx2d.putImageData(ref, 0, 0, Math.round(split * width), 0, width, height);
      ctx2d.fillStyle = '#fff';
      ctx2d.fillRect(Math.round(split * width), 0, 1, height);
      return;
    }
    if (mode === 'difference') {
      if (!ref) { ctx2d.putImageData(raster, 0, 0); return; }
      const heat = lab.differenceImage();
      if (heat.length) ctx2d.putImageData(imageOf(heat), 0, 0);
      setText($('difference-text'), lab.differenceText());
    }
  }

  // Redraws the raster picture for the state as it is, once per animation frame however many edits came.
  let pending = null;
  function redraw() {
    if (pending) return pending;
    pending = new Promise((resolve) => requestAnimationFrame(() => {
      const t0 = performance.now();
      pending = null;
      // Only a change a renderer sees (lab.revision(), which every edit, camera move and load bumps) or a new
      // size draws again and restarts the path tracer; asking for the picture again draws nothing.
      const revision = lab.revision();
      if (revision !== rasterRevision || view.width !== width || view.height !== height) {
        globalJob = null;
        rasterImage = null;
        glDrawn = false;
        rasterRevision = revision;
        if (view.width !== width || view.height !== height) { view.width = width; view.height = height; }
      }
      show();
      updateControls();
      timings.frameMs = performance.now() - t0;
      resolve();
    }));
    return pending;
  }

  // Applies a viewer-script action (or takes the error line of an edit already made) and redraws.
  function act(action, done) {
    const error = done !== undefined ? done : lab.act(JSON.stringify(action));
    if (error) setMessage(error);
    return redraw();
  }

  // --- controls -------------------------------------------------------------------------------------------
  function updateControls() {
    const s = state();
    document.querySelectorAll('[data-step]').forEach((b) => b.classList.toggle('on', Number(b.dataset.step) === s.step));
    setValue($('model'), s.model);
    const selected = s.objects.find((o) => o.id === s.selected);
    setText($('selected-label'), selected ? selected.label : 'nothing');
    if (s.material) {
      if (document.activeElement !== $('shininess')) setValue($('shininess'), Math.log2(Math.max(1, s.material.s)));
      setText($('shininess-value'), s.material.s.toPrecision(4));
    }
    for (const field of ['ma', 'md', 'ms']) {
      const c = s.material && s.material.colors[field];
      $(field).disabled = $(field + '-color').disabled = !c;
      if (!c) continue;
      if (document.activeElement !== $(field)) setValue($(field), Math.min(1, c.intensity));
      if (document.activeElement !== $(field + '-color')) setValue($(field + '-color'), hexOf(c.color));
      setText($(field + '-value'), c.intensity.toFixed(2));
    }
    updateLights(s.lights);
    schedulePlots(JSON.stringify([s.selected, s.model, s.material]));
    setText($('caption'), `${s.title || s.file} · ${s.model} · step ${s.step}`);
  }

  // '#rrggbb' for a colour whose largest channel is 1 (the split of app::splitIntensity), and back.
  function hexOf(rgb) {
    return '#' + rgb.map((v) => Math.round(Math.min(1, Math.max(0, v)) * 255).toString(16).padStart(2, '0')).join('');
  }
  function rgbOf(hex) { return [1, 3, 5].map((i) => parseInt(hex.slice(i, i + 2), 16) / 255); }

  // One row per light: its name, colour, intensity (a log2 slider, 1/64 .. 64) and a remove button.
  function updateLights(lights) {
    const box = $('lights');
    if (box.children.length !== lights.length) {
      box.replaceChildren(...lights.map((l, i) => {
        const row = document.createElement('div');
        row.className = 'light';
        row.innerHTML = `<span class="name"></span> <input type="color" aria-label="colour">
          <input type="range" min="-6" max="6" step="0.01" aria-label="intensity"> <output></output>
          <button aria-label="remove">✕</button>`;
        const [color, intensity] = row.querySelectorAll('input');
        const send = () => act({}, lab.setLightColor(i, ...rgbOf(color.value), Math.pow(2, Number(intensity.value))));
        color.addEventListener('input', send);
        intensity.addEventListener('input', send);
        row.querySelector('button').addEventListener('click', () => act({ action: 'removeLight', index: i }));
        return row;
      }));
    }
    lights.forEach((l, i) => {
      const row = box.children[i], [color, intensity] = row.querySelectorAll('input');
      setText(row.querySelector('.name'), `${l.name || 'light ' + (i + 1)} (${l.type})`);
      if (document.activeElement !== color) setValue(color, hexOf(l.color));
      if (document.activeElement !== intensity) setValue(intensity, Math.log2(Math.max(1 / 64, l.intensity)));
      setText(row.querySelector('output'), l.intensity.toPrecision(3));
    });
    $('add-light').disabled = lights.length >= 8;
  }

  // The lobe plot (polar: each curve's value over its peak against the outgoing angle, the normal up, L drawn
  // in white on the left) and the albedo plot (albedo over the
  // view angle), from the viewer's plot data (app/lobe_plot.h, app/albedo_plot.h).
  const PLOT_COLOURS = ['#ffb86c', '#8be9fd', '#50fa7b', '#ff79c6', '#bd93f9'];
  // The plots are redrawn after the frame, not in it, and only when what they show changed, so that a slider
  // drag's frames are the picture's alone. The lobe plot (cheap) follows within a tenth of a second; the albedo
  // plot integrates each curve over the sphere (about 50 ms of the page's thread on a 2-core machine), so it
  // waits until the material has rested for a fifth of a second: during a drag it would hold back every
  // other frame.
  const plots = {
    lobe: { key: null, pending: null, timer: null, delay: 100, rest: false, canvas: 'lobe-plot', data: () => lab.lobePlotJson(45), draw: drawLobe },
    albedo: { key: null, pending: null, timer: null, delay: 200, rest: true, canvas: 'albedo-plot', data: () => lab.albedoPlotJson(), draw: drawAlbedo },
  };
  function schedulePlots(key) {
    for (const p of Object.values(plots)) {
      if (key === p.key || (p.timer && (!p.rest || key === p.pending))) continue;  // shown, or already due
      clearTimeout(p.timer);  // debounced: due again once the changes stop
      p.pending = key;
      p.timer = setTimeout(() => {
        p.timer = null;
        const s = state(), now = JSON.stringify([s.selected, s.model, s.material]);
        if (now === p.key) return;
        p.key = now;
        drawPlot(p);
      }, p.delay);
    }
  }
  function drawPlot(p) {
    const plot = JSON.parse(p.data()), canvas = $(p.canvas), g = canvas.getContext('2d');
    g.clearRect(0, 0, canvas.width, canvas.height);
    if (plot.curves) p.draw(g, canvas, plot);
  }
  function legend(g, curves, x, y) {
    curves.forEach((c, k) => { g.fillStyle = PLOT_COLOURS[k % PLOT_COLOURS.length]; g.fillText(c.label, x, y + 12 * k); });
  }
  function drawLobe(g, canvas, plot) {
    const cx = canvas.width / 2, cy = canvas.height - 8, r = Math.min(cx, cy) - 6;
    g.strokeStyle = '#555';
    g.beginPath(); g.arc(cx, cy, r, Math.PI, 2 * Math.PI); g.moveTo(cx, cy); g.lineTo(cx, cy - r); g.stroke();
    // The incoming light's direction, θi from the normal on the left.
    const ti = plot.incidence * Math.PI / 180;
    g.strokeStyle = '#ddd';
    g.beginPath(); g.moveTo(cx, cy); g.lineTo(cx - r * Math.sin(ti), cy - r * Math.cos(ti)); g.stroke();
    plot.curves.forEach((c, k) => {
      g.strokeStyle = PLOT_COLOURS[k % PLOT_COLOURS.length];
      g.beginPath();
      c.polar.forEach((v, i) => {
        const t = plot.polarAngles[i] * Math.PI / 180;
        const x = cx + r * v * Math.sin(t), y = cy - r * v * Math.cos(t);
        if (i) g.lineTo(x, y); else g.moveTo(x, y);
      });
      g.stroke();
    });
    legend(g, plot.curves, 4, 12);
  }
  // Lambert, Phong and its normalised lobe, Blinn-Phong and its, GGX and compensated, then disney's diffuse, metal
  // and coat, and glTF's sheen: a lobe and its dashed normalised curve share a colour, as in the viewer's panel.
  const ALBEDO_COLOURS = ['#aaaaaa', '#ffb86c', '#ffb86c', '#50fa7b', '#50fa7b', '#ff79c6', '#ff79c6', '#96c8e6',
    '#bd93f9', '#c8f0fa', '#f1fa8c'];
  function drawAlbedo(g, canvas, plot) {
    // The plot on top, the legend under it in two columns (it would hide the curves drawn over them).
    const rows = Math.ceil(plot.curves.length / 2), legendH = 12 * rows + 4;
    const x0 = 28, y0 = canvas.height - legendH - 16, w = canvas.width - x0 - 6, h = y0 - 6;
    const last = plot.viewAngles[plot.viewAngles.length - 1] || 90;
    // Up to at least 1.25 (a rough disney diffuse reflects more than Lambert toward grazing), 3 at most.
    let top = 1.25;
    for (const c of plot.curves) for (const a of c.albedo) top = Math.max(top, Math.min(1.05 * a, 3));
    const yOf = (a) => y0 - h * Math.min(a, top) / top;
    g.strokeStyle = '#555';
    g.strokeRect(x0, y0 - h, w, h);
    g.beginPath(); g.moveTo(x0, yOf(1)); g.lineTo(x0 + w, yOf(1)); g.stroke();
    g.fillStyle = '#aaa';
    g.fillText('1', 16, yOf(1) + 4); g.fillText('0', 16, y0); g.fillText(`θ 0..${last}°`, x0 + w - 60, y0 + 12);
    plot.curves.forEach((c, k) => {
      g.strokeStyle = ALBEDO_COLOURS[k % ALBEDO_COLOURS.length];
      g.setLineDash(c.dashed ? [4, 3] : []);
      g.beginPath();
      c.albedo.forEach((a, i) => {
        const x = x0 + w * plot.viewAngles[i] / last, y = yOf(a);
        if (i) g.lineTo(x, y); else g.moveTo(x, y);
      });
      g.stroke();
    });
    g.setLineDash([]);
    plot.curves.forEach((c, k) => {
      g.fillStyle = ALBEDO_COLOURS[k % ALBEDO_COLOURS.length];
      g.fillText(c.label, 4 + (canvas.width / 2) * Math.floor(k / rows), y0 + 28 + 12 * (k % rows));
    });
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
    uploads.clear();  // a shipped scene needs none of the files opened before
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

  // A shared link (share_link.js): the scene it holds, read as a scene file in the folder it names, and its view.
  // A bad link is one line, and the default scene.
  async function openLink(hash) {
    let error = '';
    try {
      const link = await ShareLink.decode(hash, VIEWS);
      const path = link.folder + '/.link-scene.json';
      try {
        M.FS.writeFile(path, link.sceneJson);
      } catch (e) {
        throw new Error(`link: the page has no folder "${link.folder}"; showing the default scene`);
      }
      error = lab.open(path);
      if (!error) {
        $('scene').value = '';
        uploads.clear();
        reference = null;
        setMessage(warningLine());
        api.setView(link.view);
        await redraw();
        return true;
      }
      error = `link: ${error}; showing the default scene`;
    } catch (e) {
      error = e.message;
    }
    await loadScene('default.json');
    setMessage(error);
    return false;
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
    for (const field of ['ma', 'md', 'ms']) {
      const send = () => act({}, lab.setMaterialColor(field, ...rgbOf($(field + '-color').value), Number($(field).value)));
      $(field).addEventListener('input', send);
      $(field + '-color').addEventListener('input', send);
    }
    $('add-light').addEventListener('click', () => act({ action: 'addLight', type: 'point' }));
    $('share').addEventListener('click', async () => {
      try {
        const url = await api.link();
        history.replaceState(null, '', url);
        await navigator.clipboard.writeText(url).catch(() => {});
        setMessage('the link to this scene and view is in the address bar (and copied)');
      } catch (e) { setMessage(e.message); }
    });
    addEventListener('hashchange', () => { if (location.hash) openLink(location.hash); });
    $('open-file').addEventListener('change', () => { const f = $('open-file').files[0]; if (f) openFile(f); });
    // Drag and drop a file anywhere on the page opens it, as the file input does.
    addEventListener('dragover', (e) => { e.preventDefault(); e.dataTransfer.dropEffect = 'copy'; });
    addEventListener('drop', (e) => {
      e.preventDefault();
      const f = e.dataTransfer.files[0];
      if (f) openFile(f);
    });
    $('save').addEventListener('click', () => {
      const url = URL.createObjectURL(new Blob([lab.sceneJson()], { type: 'application/json' }));
      const a = document.createElement('a');
      a.href = url; a.download = 'scene.json'; a.click();
      setTimeout(() => URL.revokeObjectURL(url), 1000);
    });

    // Mouse and touch: drag orbits (right button or shift: pans), the wheel zooms, a click selects and probes.
    // Two fingers: pinching zooms and moving both pans.
    let drag = null;
    const touches = new Map();  // pointerId -> {x, y}, the fingers down
    let pinch = null;           // {distance, x, y} of the two fingers at the last move
    const fingers = () => { const [a, b] = [...touches.values()]; return { distance: Math.hypot(a.x - b.x, a.y - b.y), x: (a.x + b.x) / 2, y: (a.y + b.y) / 2 }; };
    stage.addEventListener('contextmenu', (e) => e.preventDefault());
    stage.addEventListener('pointerdown', (e) => {
      stage.setPointerCapture(e.pointerId);
      if (e.pointerType === 'touch') touches.set(e.pointerId, { x: e.clientX, y: e.clientY });
      if (touches.size === 2) { pinch = fingers(); drag = null; return; }
      drag = { x: e.clientX, y: e.clientY, moved: false, pan: e.button === 2 || e.shiftKey, wipe: mode === 'split' };
    });
    const lift = (e) => { touches.delete(e.pointerId); if (touches.size < 2) pinch = null; };
    stage.addEventListener('pointercancel', (e) => { lift(e); drag = null; });
    stage.addEventListener('pointermove', (e) => {
      if (pinch && touches.has(e.pointerId)) {
        touches.set(e.pointerId, { x: e.clientX, y: e.clientY });
        const now = fingers(), scale = width / stage.clientWidth;
        // A wheel step per doubling of the fingers' distance, the viewer's zoom unit.
        if (pinch.distance > 0 && now.distance > 0) lab.zoom(Math.log2(now.distance / pinch.distance) * 4);
        lab.pan((now.x - pinch.x) * scale, (now.y - pinch.y) * scale, height);
        pinch = now;
        redraw();
        return;
      }
      if (!drag) return;
      const scale = width / stage.clientWidth, dx = (e.clientX - drag.x) * scale, dy = (e.clientY - drag.y) * scale;
      if (!drag.moved && Math.hypot(dx, dy) < 3) return;
      drag.moved = true;
      drag.x = e.clientX; drag.y = e.clientY;
      if (drag.wipe) {
        const r = stage.getBoundingClientRect();
        split = Math.min(1, Math.max(0, (e.clientX - r.left) / r.width));
        show();
        return;
      }
      if (drag.pan) lab.pan(dx, dy, height); else lab.orbit(dx, dy);
      redraw();
    });
    stage.addEventListener('pointerup', (e) => {
      lift(e);
      const d = drag;
      drag = null;
      if (!d || d.moved) return;
      const r = stage.getBoundingClientRect();
      const x = Math.floor((e.clientX - r.left) * width / r.width), y = Math.floor((e.clientY - r.top) * height / r.height);
      const id = lab.objectAt(x, y);
      // A selection changes no render (no revision), but the outline: the display pass runs again.
      if (id) { glDrawn = false; act({ action: 'select', object: '#' + id }); }
      setText($('probe'), lab.probe(x, y, width, height));
    });
    stage.addEventListener('wheel', (e) => { e.preventDefault(); lab.zoom(-Math.sign(e.deltaY)); redraw(); }, { passive: false });
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
      width = w; height = h;
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
      if (which === 'raster') return pngOf(rasterPicture());
      if (which !== 'reference') throw new Error(`imageDataUrl: "${which}" is not raster or reference`);
      if (!referenceCurrent()) startReference();
      return pngOf(await reference.done);
    },
    async coverageDataUrl(which) {
      if (which !== 'raster') throw new Error(`coverageDataUrl: "${which}" is not raster`);
      await redraw();
      rasterPicture();  // the coverage of the picture read back, as `render --coverage` writes it
      return pngOf(imageOf(lab.rasterCoverageImage()));
    },
    // Promise of the probe report (JSON text, docs/viewer.md) of pixel (x, y) of the picture, as a click gives.
    async probe(x, y) {
      await redraw();
      return lab.probe(x, y, width, height);
    },
    // Promise of the Global view's picture at exactly `samples` samples per pixel (PNG data URL), as
    // `shadelab render --renderer path --spp N` writes it; switches the view to Global.
    async globalDataUrl(samples) {
      if (!(Number.isInteger(samples) && samples >= 1 && samples <= 4096))
        throw new Error(`globalDataUrl: ${samples} is not a sample count from 1 to 4096`);
      api.setView('global');
      await redraw();
      startGlobal(samples);
      return pngOf(await globalJob.done);
    },
    exportScene() { return lab.sceneJson(); },
    // Promise of this page's address with the edited scene and the view in its hash (share_link.js).
    async link() {
      if (!lab.sceneDir().startsWith('/assets'))
        throw new Error('link: a link cannot carry files opened from disk; use Save scene instead');
      return location.href.replace(/#.*$/, '') + await ShareLink.encode(lab.sceneJson(), lab.sceneDir(), mode);
    },
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
    if (location.hash) await openLink(location.hash); else await loadScene('default.json');
    timings.firstPictureMs = performance.now();  // performance.now() counts from navigation
  })();
  api.ready.catch((e) => setMessage(String(e.message || e)));
})();
