// One of the page's tracers (tracer_pool.js): a copy of the lab's module in a Web Worker, instantiated once
// from the wasm the page compiled, tracing its share of the tiles of the scene the page sends (its saved JSON).
// No lighting here: the C++ (web/src/worker_tracer.h) does all of it.
'use strict';
importScripts('shadelab.js');
let modulePromise = null;
let current = null;  // {job, tracer}: the job this worker has set up, the only one it works for

// The module, from the page's compiled wasm when it sent one (else this worker compiles its own).
function start(wasmModule) {
  const options = {};
  if (wasmModule) {
    options.instantiateWasm = (imports, success) => {
      WebAssembly.instantiate(wasmModule, imports).then((instance) => success(instance, wasmModule));
      return {};
    };
  }
  modulePromise = createShadelab(options);
}

// The tracer of the scene the page sent. The last one is kept: a job of the same scene text (another size,
// another view, the reference after Global) reuses its BVH. Files opened from disk may change under the same
// name, so a scene that has them is always built afresh.
let kept = null;  // {key, tracer}
function withTracer(M, msg) {
  const files = msg.files || [];
  const key = files.length ? null : msg.sceneDir + '\n' + msg.sceneJson;
  if (kept && key !== null && kept.key === key) return kept.tracer;
  if (kept) kept.tracer.delete();
  kept = null;
  // The files the user opened in the page, at the same paths in this worker's file system.
  for (const f of files) {
    try { M.FS.mkdir(f.path.slice(0, f.path.lastIndexOf('/'))); } catch (e) { /* exists */ }
    M.FS.writeFile(f.path, f.bytes);
  }
  const tracer = M.createTracer(msg.sceneJson, msg.sceneDir);
  if (!tracer) throw new Error(M.createError());
  kept = { key, tracer };
  return tracer;
}

// Resolves in a task of its own, after the messages already queued: a loop that awaits it between pieces of
// work lets a stop in (a MessageChannel, because a worker's setTimeout(0) is held back to 4 ms once nested).
const channel = new MessageChannel();
const waiting = [];
channel.port1.onmessage = () => waiting.shift()();
function nextTask() {
  return new Promise((resolve) => { waiting.push(resolve); channel.port2.postMessage(0); });
}

// The tiles traced since the last message: the tracer packs them (WorkerTracer::TileBatch), and the worker copies the
// batch into arrays that go to the page with the message (transferred, not copied) and come back with its reply for
// the next batch. So tracing allocates nothing in the steady state: a new array per tile took a fifth of a worker's
// time, and a new array per message, fresh pages the kernel had to fault in, a tenth.
const batch = {
  spare: [],  // {rgb, coverage} pairs the page has sent back
  // Sends the tracer's batch: `tiles` holds (index, x0, y0, width, height) per tile, their 8-bit pixels one after
  // another in `rgb` and their ids in `coverage` (both may be longer than they need).
  send(job, tracer) {
    const v = tracer.batch();  // views of the module's memory: copied before the next call into it
    if (!v.tiles.length) return;
    const s = this.spare.pop() || { rgb: new Uint8Array(0), coverage: new Uint32Array(0) };
    const rgb = fit(s.rgb, v.rgb.length), coverage = fit(s.coverage, v.coverage.length), tiles = v.tiles.slice();
    rgb.set(v.rgb);
    coverage.set(v.coverage);
    tracer.clearBatch();
    postMessage({ kind: 'tiles', job, tiles, rgb, coverage }, [tiles.buffer, rgb.buffer, coverage.buffer]);
  },
};
function fit(array, length) {
  return array.length >= length ? array : new array.constructor(Math.max(length, 2 * array.length));
}

// Traces the tiles queued for the reference job `mine` until the queue is empty or another job (or a stop)
// replaces it. Every 2 ms, between tiles, it sends the tiles done so far in one message and lets the next
// message in (nextTask): a stop, a new job, or more tiles for the queue, which this loop then traces too.
async function traceQueue(mine) {
  mine.running = true;
  try {
    let resumed = performance.now();
    while (current === mine && mine.queue.length) {
      mine.tracer.traceTile(mine.queue.shift());
      if (performance.now() - resumed > 2 || !mine.queue.length) {
        batch.send(mine.job, mine.tracer);
        await nextTask();
        resumed = performance.now();
      }
    }
  } finally {
    mine.tracer.clearBatch();  // sent before every wait; left over only when a tile threw
    mine.running = false;
  }
}

// Ends the job in hand (its loop sees current change and stops); the tracer stays kept for the next job.
function drop() {
  current = null;
}

onmessage = async (event) => {
  const msg = event.data;
  if (msg.kind === 'init') { start(msg.module); return; }
  if (!modulePromise) start(null);
  const M = await modulePromise;
  try {
    if (msg.kind === 'stop') {
      drop();
    } else if (msg.kind === 'reference') {
      // Tiles first, first + step, ... of the first half of the job (the pool's workers share it by turns), then
      // the tiles of the second half the page hands out as this worker's batches arrive there (tracer_pool.js).
      drop();
      const mine = { job: msg.job, tracer: withTracer(M, msg), queue: [], running: false };
      current = mine;
      const count = mine.tracer.startReference(msg.width, msg.height);
      const until = Math.ceil(count / 2);
      postMessage({ kind: 'count', job: msg.job, count, until });
      for (let i = msg.first; i < until; i += msg.step) mine.queue.push(i);
      await traceQueue(mine);
    } else if (msg.kind === 'tiles') {
      if (msg.rgb) batch.spare.push({ rgb: msg.rgb, coverage: msg.coverage });  // any job's: reused
      if (current && current.job === msg.job && current.queue) {
        current.queue.push(...msg.indices);
        if (!current.running) await traceQueue(current);
      }
    } else if (msg.kind === 'global') {
      // The path tracer over this worker's share of the rows (first, first + step, ...), one sample per pixel a
      // pass, the running mean of those rows after each, until another job comes.
      drop();
      const mine = { job: msg.job, tracer: withTracer(M, msg) };
      current = mine;
      mine.tracer.startGlobal(msg.width, msg.height);
      for (let pass = 1; pass <= msg.samples && current === mine; ++pass) {
        mine.tracer.addGlobalRowSamples(1, msg.first, msg.step);
        const rows = mine.tracer.globalRows(msg.first, msg.step);
        postMessage({ kind: 'global', job: msg.job, samples: pass, rows }, [rows.buffer]);
        await nextTask();  // lets the next message (a stop, a new job) in
      }
      if (current === mine) drop();
    }
  } catch (e) {
    postMessage({ kind: 'error', job: msg.job, error: String(e.message || e) });
  }
};
