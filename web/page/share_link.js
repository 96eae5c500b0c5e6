// ShareLink: the edited scene and view in the page's address, so that a teacher can send "this slider setting"
// to a class. The link's hash is `#v1,<view>,<folder>,<scene>`: the view mode, the folder the scene's relative
// model paths start from (a shipped folder under /assets/), and the scene as the page saves it (scene JSON),
// deflated and in base64url. Decoding checks each part and says in one line what is wrong; the page then shows
// the default scene. The scene text is read by the same scene reader as any file, so a link can hold nothing a
// scene file could not.
'use strict';
const ShareLink = (() => {
  const PREFIX = 'v1';
  const MAX_SCENE_BYTES = 16 << 20;  // a link's scene, inflated; a deflate bomb stops here

  function toBase64Url(bytes) {
    let binary = '';
    for (let i = 0; i < bytes.length; i += 0x8000) binary += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
    return btoa(binary).replace(/\+/g, '-').replace(/\//g, '_').replace(/=+$/, '');
  }

  function fromBase64Url(text) {
    if (!/^[A-Za-z0-9_-]*$/.test(text)) throw new Error('the scene part holds characters base64url has not');
    const b64 = text.replace(/-/g, '+').replace(/_/g, '/') + '==='.slice((text.length + 3) % 4);
    let binary;
    try { binary = atob(b64); } catch (e) { throw new Error('the scene part is not base64url'); }
    return Uint8Array.from(binary, (c) => c.charCodeAt(0));
  }

  async function deflate(text) {
    const stream = new Blob([text]).stream().pipeThrough(new CompressionStream('deflate-raw'));
    return new Uint8Array(await new Response(stream).arrayBuffer());
  }

  async function inflate(bytes) {
    const reader = new Blob([bytes]).stream().pipeThrough(new DecompressionStream('deflate-raw')).getReader();
    const chunks = [];
    let total = 0;
    try {
      for (;;) {
        const { done, value } = await reader.read();
        if (done) break;
        total += value.length;
        if (total > MAX_SCENE_BYTES) {
          reader.cancel().catch(() => {});
          throw new Error(`the scene is larger than ${MAX_SCENE_BYTES >> 20} MiB`);
        }
        chunks.push(value);
      }
    } catch (e) {
      if (/larger than/.test(e.message)) throw e;
      throw new Error('the scene part is damaged (truncated or altered)');
    }
    const all = new Uint8Array(total);
    let at = 0;
    for (const c of chunks) { all.set(c, at); at += c.length; }
    try {
      return new TextDecoder('utf-8', { fatal: true }).decode(all);
    } catch (e) {
      throw new Error('the scene is not UTF-8 text');
    }
  }

  async function encode(sceneJson, folder, view) {
    return `#${PREFIX},${view},${encodeURIComponent(folder)},${toBase64Url(await deflate(sceneJson))}`;
  }

  // {view, folder, sceneJson}; `views` are the page's view modes, of which the link's must be one. Throws
  // Error('link: ...') naming what is wrong.
  async function decode(hash, views) {
    try {
      const parts = hash.replace(/^#/, '').split(',');
      if (parts.length !== 4 || parts[0] !== PREFIX)
        throw new Error(`expected #${PREFIX},view,folder,scene, got ${parts.length} part(s) starting "${parts[0].slice(0, 12)}"`);
      const [, view, rawFolder, scene] = parts;
      if (!views.includes(view)) throw new Error(`no view "${view.slice(0, 20)}"; one of ${views.join(', ')}`);
      let folder;
      try { folder = decodeURIComponent(rawFolder); } catch (e) { throw new Error('the folder part is not URI-encoded'); }
      if (!/^\/assets(\/[A-Za-z0-9_.-]+)*$/.test(folder) || folder.split('/').includes('..'))
        throw new Error(`folder "${folder.slice(0, 40)}" is not one of the page's own (under /assets/)`);
      return { view, folder, sceneJson: await inflate(fromBase64Url(scene)) };
    } catch (e) {
      throw new Error(`link: ${e.message}; showing the default scene`);
    }
  }

  return { encode, decode };
})();
