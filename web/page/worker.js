// One of the page's tracers: a copy of the lab's module in a Web Worker, tracing the tiles it is given of the
// scene the page sends (its saved JSON). No lighting here: the C++ (web/src/worker_tracer.h) does all of it.
'use strict';
importScripts('shadelab.js');
const modulePromise = createShadelab();

function withTracer(M, msg) {
  // The files the user opened in the page, at the same paths in this worker's file system.
  for (const f of msg.files || []) {
    try { M.FS.mkdir(f.path.slice(0, f.path.lastIndexOf('/'))); } catch (e) { /* exists */ }
    M.FS.writeFile(f.path, f.bytes);
  }
  const tracer = M.createTracer(msg.sceneJson, msg.sceneDir);
  if (!tracer) throw new Error(M.createError());
  return tracer;
}

onmessage = async (event) => {
  const msg = event.data;
  const M = await modulePromise;
  try {
    if (msg.kind === 'reference') {
      // Tiles first, first + step, ... of the job: the page's workers share the tiles between them.
      const tracer = withTracer(M, msg);
      const count = tracer.startReference(msg.width, msg.height);
      postMessage({ kind: 'count', job: msg.job, count });
      for (let i = msg.first; i < count; i += msg.step) {
        const t = tracer.traceTile(i);
        postMessage({ kind: 'tile', job: msg.job, index: i, tile: t }, [t.rgba.buffer, t.coverage.buffer]);
      }
      tracer.delete();
    } else if (msg.kind === 'global') {
      // The path tracer, one sample per pixel a pass, the running mean after each; the page ends it.
      const tracer = withTracer(M, msg);
      tracer.startGlobal(msg.width, msg.height);
      for (let pass = 0; pass < msg.samples; ++pass) {
        tracer.addGlobalSamples(1);
        const rgba = tracer.globalImage();
        postMessage({ kind: 'global', job: msg.job, samples: tracer.globalSamples(), rgba }, [rgba.buffer]);
        await new Promise((r) => setTimeout(r, 0));  // lets a terminate() in
      }
      tracer.delete();
    }
  } catch (e) {
    postMessage({ kind: 'error', job: msg.job, error: String(e.message || e) });
  }
};
