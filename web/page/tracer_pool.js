// TracerPool: the page's Web Workers, started once and kept (each costs a module instantiation, so a job must not
// start workers). The wasm is compiled once, by the page, and handed to every worker. A reference job sends the
// scene to every worker; worker k traces tiles k, k + n, k + 2n, ... of the first half of the job without waiting
// for the page, sending what it has done every 2 ms in one message, and the page hands out the second half as the
// tiles come in, as many to a worker as it has just sent, so a worker that runs slower (it shares its core with the
// page, or the machine is busy) gets fewer and all finish together. A worker always has tiles in hand, so none
// waits for the page. A new job, or a stop, ends the old one between tiles, and tiles of an old job that arrive
// late are dropped. The Global view's path tracer shares the rows by turns (worker k: rows k, k + n, ...), a pass
// at a time, until another job replaces it.
'use strict';
class TracerPool {
  constructor(count, wasmModule) {
    this.workers = [];
    this.job = 0;
    for (let k = 0; k < count; ++k) {
      const worker = new Worker('worker.js');
      worker.postMessage({ kind: 'init', module: wasmModule });
      worker.onmessage = (e) => this._receive(k, e.data);
      this.workers.push({ worker });
    }
    this.current = null;
  }

  // 'reference', 'global' or null: what the workers are doing.
  running() { return this.current ? this.current.kind : null; }

  // Ends the running job; what its workers still send is ignored.
  stop() {
    ++this.job;
    for (const w of this.workers) w.worker.postMessage({ kind: 'stop', job: this.job });
    if (this.current && this.current.reject) this.current.reject(new Error('cancelled'));
    this.current = null;
  }

  // The Whitted reference of `scene` ({sceneJson, sceneDir, files}) at w x h. Resolves with {rgb, coverage}: the
  // 8-bit pixels as the native render encodes them, and the ids. onProgress(fraction) after each batch of tiles.
  reference(scene, w, h, onProgress) {
    this.stop();
    const id = this.job;
    // next: the next tile to hand out, once the first worker has said how many there are and where its share ends.
    const job = { id, kind: 'reference', w, h, count: -1, next: -1, arrived: 0, onProgress,
      rgb: new Uint8Array(w * h * 3), coverage: new Uint32Array(w * h) };
    const done = new Promise((resolve, reject) => { job.resolve = resolve; job.reject = reject; });
    done.catch(() => {});
    this.current = job;
    this.workers.forEach((w, k) => w.worker.postMessage(
      { kind: 'reference', job: id, ...scene, width: job.w, height: job.h, first: k, step: this.workers.length }));
    return done;
  }

  // The path tracer's progressive image of `scene` at w x h up to `samples` per pixel, the rows shared by turns
  // between the workers; onImage({rgba, samples}) whenever a worker has finished a pass, `samples` the fewest any
  // row has.
  global(scene, w, h, onImage, onError, samples = 4096) {
    this.stop();
    const n = this.workers.length;
    this.current = { id: this.job, kind: 'global', w, h, onImage, onError, rgba: new Float32Array(w * h * 4),
      passes: new Array(n).fill(0) };
    this.workers.forEach((worker, k) => worker.worker.postMessage(
      { kind: 'global', job: this.job, ...scene, width: w, height: h, samples, first: k, step: n }));
  }

  // A worker's rows of the Global image (first = k, step = the pool's size) into the whole.
  _globalRows(job, k, m) {
    const n = this.workers.length, row = job.w * 4;
    for (let y = k, i = 0; y < job.h; y += n, ++i) job.rgba.set(m.rows.subarray(i * row, (i + 1) * row), y * row);
    job.passes[k] = m.samples;
    const samples = Math.min(...job.passes);
    if (samples > 0) job.onImage({ rgba: job.rgba, samples });  // shown once every row has a sample
  }

  _receive(k, m) {
    const job = this.current;
    if (!job || m.job !== job.id) return;
    if (m.kind === 'error') {
      const error = new Error(m.error);
      this.current = null;  // so that stop() does not call it a cancellation
      this.stop();
      if (job.reject) job.reject(error);
      if (job.onError) job.onError(error);
      return;
    }
    if (m.kind === 'count') {
      if (job.count < 0) { job.count = m.count; job.next = m.until; }
      return;
    }
    if (m.kind === 'global') { this._globalRows(job, k, m); return; }
    // A worker's batch of tiles: (index, x0, y0, width, height) each in m.tiles, their pixels one after another in
    // m.rgb and m.coverage.
    const sent = m.tiles.length / 5;
    for (let i = 0, at = 0; i < sent; ++i) {
      const x0 = m.tiles[5 * i + 1], y0 = m.tiles[5 * i + 2], w = m.tiles[5 * i + 3], h = m.tiles[5 * i + 4];
      for (let y = 0; y < h; ++y, at += w) {
        const row = (y0 + y) * job.w + x0;
        job.rgb.set(m.rgb.subarray(3 * at, 3 * (at + w)), row * 3);
        job.coverage.set(m.coverage.subarray(at, at + w), row);
      }
      ++job.arrived;
    }
    // As many tiles of the second half to this worker as it has just sent, and its arrays back for the next batch.
    const more = [];
    while (more.length < sent && job.next < job.count) more.push(job.next++);
    this.workers[k].worker.postMessage({ kind: 'tiles', job: job.id, indices: more, rgb: m.rgb, coverage: m.coverage },
      [m.rgb.buffer, m.coverage.buffer]);
    if (job.onProgress) job.onProgress(job.arrived / job.count);
    if (job.arrived === job.count) {
      this.current = null;
      job.resolve({ rgb: job.rgb, coverage: job.coverage });
    }
  }
}
