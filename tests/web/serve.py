"""Serves one folder on 127.0.0.1 at a free port from a background thread, for the web page's tests.

Quiet (no request log), no caching, and the MIME types the page needs: WebAssembly must be served as
application/wasm for streaming compilation. The page is cross-origin isolated (COOP/COEP), so that a build
with threads gets SharedArrayBuffer; a single-threaded build does not mind."""

import functools
import http.server
import threading
from pathlib import Path

MIME_TYPES = {
    ".wasm": "application/wasm",
    ".js": "text/javascript",
    ".mjs": "text/javascript",
    ".json": "application/json",
    ".glb": "model/gltf-binary",
    ".gltf": "model/gltf+json",
    ".html": "text/html",
    ".png": "image/png",
    ".hdr": "application/octet-stream",
    ".bin": "application/octet-stream",
}


class _Handler(http.server.SimpleHTTPRequestHandler):
    extensions_map = {**http.server.SimpleHTTPRequestHandler.extensions_map, **MIME_TYPES}

    def send_error(self, code, message=None, explain=None):
        # Browsers ask for /favicon.ico on their own; a page without one is not an error of the page.
        if code == 404 and self.path == "/favicon.ico":
            self.send_response(204)
            self.end_headers()
            return
        super().send_error(code, message, explain)

    def end_headers(self):
        self.send_header("Cache-Control", "no-store")
        self.send_header("Cross-Origin-Opener-Policy", "same-origin")
        self.send_header("Cross-Origin-Embedder-Policy", "require-corp")
        super().end_headers()

    def log_message(self, format, *args):
        self.server.requests.append(format % args)


class Server:
    """`with Server(folder) as s: page.navigate(s.url("index.html"))`; s.requests lists what was asked for."""

    def __init__(self, folder):
        self.folder = Path(folder)
        if not self.folder.is_dir():
            raise FileNotFoundError(f"{self.folder}: no such folder to serve")
        self.httpd = None
        self.thread = None

    def __enter__(self):
        handler = functools.partial(_Handler, directory=str(self.folder))
        self.httpd = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
        self.httpd.daemon_threads = True
        self.httpd.requests = []
        self.thread = threading.Thread(target=self.httpd.serve_forever, name="serve", daemon=True)
        self.thread.start()
        return self

    def __exit__(self, *exc):
        self.httpd.shutdown()
        self.httpd.server_close()
        self.thread.join(timeout=5)
        return False

    @property
    def port(self):
        return self.httpd.server_address[1]

    @property
    def requests(self):
        return self.httpd.requests

    def url(self, path=""):
        return f"http://127.0.0.1:{self.port}/{path.lstrip('/')}"
