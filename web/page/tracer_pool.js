// TracerPool: the page's Web Workers, started once and kept (each costs a module instantiation and the scene's
// BVH, so a job must not start workers). The wasm is compiled once, by the page, and handed to every worker.
// A reference job is handed out a tile at a time to whichever worker is free, so a slow tile does not hold the
// rest back, and a new job cancels the old one between tiles: tiles of an old job that arrive late are dropped.
// The Global view's path tracer runs in worker 0, a pass at a time, until another job replaces it.
'use strict';
class TracerPool {
  constructor(count, wasmModule) {
    this.workers = [];
    this.job = 0;
    for (let k = 0; k < count; ++k) {
      const worker = new Worker('worker.js');
      worker.postMessage({ kind: 'init', module: wasmModule });
      worker.onmessage = (e) => this._receive(k, e.data);
      this.workers.push({ worker, busy: 0 });
    }
    this.current = null;
  }

  // 'reference', 'global' or null: what the workers are doing.
  running() { return this.current ? this.current.kind : null; }

  // Ends the running job; what its workers still send is ignored.
  stop() {
    ++this.job;
    for (const w of this.workers) { w.worker.postMessage({ kind: 'stop', job: this.job }); w.busy = 0; }
    if (this.current && this.current.reject) this.current.reject(new Error('cancelled'));
    this.current = null;
  }

  // The Whitted reference of `scene` ({sceneJson, sceneDir, files}) at w x h. Resolves with {rgba, coverage};
  // onProgress(fraction) after each tile.
  reference(scene, w, h, onProgress) {
    this.stop();
    const id = this.job;
    const job = { id, kind: 'reference', w, h, next: 0, count: -1, arrived: 0, onProgress,
      rgba: new Float32Array(w * h * 4), coverage: new Uint32Array(w * h) };
    const done = new Promise((resolve, reject) => { job.resolve = resolve; job.reject = reject; });
    done.catch(() => {});
    this.current = job;
    for (const w of this.workers) w.worker.postMessage({ kind: 'reference', job: id, ...scene, width: job.w, height: job.h });
    return done;
  }

  // The path tracer's progressive image of `scene` at w x h; onImage({rgba, samples}) after each pass.
  global(scene, w, h, onImage, onError) {
    this.stop();
    this.current = { id: this.job, kind: 'global', onImage, onError };
    this.workers[0].worker.postMessage({ kind: 'global', job: this.job, ...scene, width: w, height: h, samples: 4096 });
  }

  // Keeps two tiles queued at each worker, so none waits for the page between tiles.
  _dispatch() {
    const job = this.current;
    if (!job || job.kind !== 'reference' || job.count < 0) return;
    for (const w of this.workers) {
      while (w.busy < 2 && job.next < job.count) {
        w.worker.postMessage({ kind: 'tile', job: job.id, index: job.next++ });
        ++w.busy;
      }
    }
  }

  _receive(k, m) {
    const job = this.current;
    if (!job || m.job !== job.id) return;
    if (m.kind === 'error') {
      const error = new Error(m.error);
      this.stop();
      if (job.reject) job.reject(error);
      if (job.onError) job.onError(error);
      return;
    }
    if (m.kind === 'count') {
      if (job.count < 0) { job.count = m.count; this._dispatch(); }
      return;
    }
    if (m.kind === 'global') { job.onImage(m); return; }
    const t = m.tile;
    for (let y = 0; y < t.height; ++y) {
      job.rgba.set(t.rgba.subarray(y * t.width * 4, (y + 1) * t.width * 4), ((t.y0 + y) * job.w + t.x0) * 4);
      job.coverage.set(t.coverage.subarray(y * t.width, (y + 1) * t.width), (t.y0 + y) * job.w + t.x0);
    }
    --this.workers[k].busy;
    ++job.arrived;
    if (job.onProgress) job.onProgress(job.arrived / job.count);
    if (job.arrived === job.count) {
      this.current = null;
      job.resolve({ rgba: job.rgba, coverage: job.coverage });
      return;
    }
    this._dispatch();
  }
}
