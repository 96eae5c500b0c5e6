"""A small Chrome DevTools Protocol client for the web page's tests: it launches Debian's headless Chromium on
SwiftShader, opens one page and drives it (navigate, evaluate, mouse, keys, inputs, screenshots, files).

It is not a general CDP library: one browser, pages in flattened sessions over one websocket, every wait
bounded by a timeout. Chromium always dies with the context manager, also on failure; its stderr is kept in
<evidence>/chromium.log and what the page printed to its console in <evidence>/console.log."""

import base64
import ctypes
import json
import os
import shutil
import signal
import subprocess
import tempfile
import time
from pathlib import Path

import websocket

CHROMIUM = os.environ.get("SHADELAB_CHROMIUM", "/usr/bin/chromium")

# Headless Chromium with WebGL2 on the CPU: ANGLE over SwiftShader (--use-gl=swiftshader gives no WebGL).
# The background services are off because the test machines have no network and the refused connections
# slow Chromium down; the colour profile is forced so that screenshots carry the page's sRGB values as they are.
CHROMIUM_FLAGS = [
    "--headless=new",
    "--no-sandbox",
    "--use-angle=swiftshader",
    "--enable-unsafe-swiftshader",
    "--force-color-profile=srgb",
    "--disable-quic",
    "--no-first-run",
    "--no-default-browser-check",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--disable-extensions",
    "--disable-default-apps",
    "--mute-audio",
    "--hide-scrollbars",
]


class CdpError(Exception):
    """The browser refused a command, went away, or a wait ran out."""


class CdpTimeout(CdpError, TimeoutError):
    """A wait ran past its timeout."""


class JsError(CdpError):
    """JavaScript threw, or a promise the test awaited rejected; the message is the JS message."""


class Browser:
    """One headless Chromium, as a context manager: `with Browser(evidence) as b: page = b.new_page()`."""

    def __init__(self, evidence_dir, width=1024, height=768, timeout=30.0, extra_flags=()):
        self.evidence_dir = Path(evidence_dir)
        self.width, self.height = width, height
        self.timeout = timeout
        self.extra_flags = list(extra_flags)
        self.proc = None
        self.ws = None
        self.pages = []
        self._next_id = 0
        self._events = []  # recent events, (number, sessionId, method, params), for waits to look back on
        self.event_count = 0  # events received so far: a wait's `since`
        self._profile = None
        self._log = None

    # ---- lifetime ----

    def __enter__(self):
        try:
            self._launch()
        except BaseException:
            self.close()
            raise
        return self

    def __exit__(self, *exc):
        self.close()
        return False

    def _launch(self):
        self.evidence_dir.mkdir(parents=True, exist_ok=True)
        self._profile = tempfile.mkdtemp(prefix="shadelab-chromium-")
        self._log = open(self.evidence_dir / "chromium.log", "wb")
        args = [
            CHROMIUM,
            *CHROMIUM_FLAGS,
            f"--window-size={self.width},{self.height}",
            f"--user-data-dir={self._profile}",
            "--remote-debugging-port=0",
            *self.extra_flags,
            "about:blank",
        ]
        # A session of its own, so that close() can end Chromium's helper processes with it; and killed by
        # the kernel if this process dies first (a test runner's timeout), which the helpers then follow.
        self.proc = subprocess.Popen(args, stdin=subprocess.DEVNULL, stdout=self._log, stderr=subprocess.STDOUT,
                                     start_new_session=True, preexec_fn=_die_with_parent)
        port_file = Path(self._profile) / "DevToolsActivePort"
        deadline = time.monotonic() + self.timeout
        while True:
            if self.proc.poll() is not None:
                raise CdpError(f"chromium exited with status {self.proc.returncode} before it listened "
                               f"(see {self.evidence_dir / 'chromium.log'})")
            lines = port_file.read_text().splitlines() if port_file.exists() else []
            if len(lines) >= 2:
                break
            if time.monotonic() > deadline:
                raise CdpTimeout(f"chromium wrote no {port_file.name} within {self.timeout} s")
            time.sleep(0.05)
        self.ws = websocket.create_connection(f"ws://127.0.0.1:{lines[0]}{lines[1]}", timeout=self.timeout,
                                              suppress_origin=True)

    def close(self):
        for page in self.pages:
            page.write_console_log()
        if self.ws is not None:
            try:
                self.ws.settimeout(2)
                self._send("Browser.close", {})
            except Exception:
                pass
            try:
                self.ws.close()
            except Exception:
                pass
            self.ws = None
        if self.proc is not None:
            try:
                self.proc.wait(timeout=3)
            except subprocess.TimeoutExpired:
                pass
            group = self.proc.pid
            try:
                os.killpg(group, signal.SIGKILL)  # the group we started: helpers included
            except ProcessLookupError:
                pass
            self.proc.wait()
            self.proc = None
            _wait_for_group_to_die(group)
        if self._log is not None:
            self._log.close()
            self._log = None
        if self._profile is not None:
            shutil.rmtree(self._profile, ignore_errors=True)
            self._profile = None

    # ---- protocol ----

    def _send(self, method, params, session=None):
        self._next_id += 1
        message = {"id": self._next_id, "method": method, "params": params}
        if session:
            message["sessionId"] = session
        self.ws.send(json.dumps(message))
        return self._next_id

    def _receive(self, deadline, what):
        remaining = deadline - time.monotonic()
        if remaining <= 0:
            raise CdpTimeout(f"timed out waiting for {what}")
        self.ws.settimeout(remaining)
        try:
            raw = self.ws.recv()
        except websocket.WebSocketTimeoutException:
            raise CdpTimeout(f"timed out waiting for {what}") from None
        except (websocket.WebSocketException, OSError) as e:
            raise CdpError(f"lost the browser while waiting for {what}: {e}") from None
        message = json.loads(raw)
        if "method" in message:
            self._dispatch(message.get("sessionId"), message["method"], message.get("params", {}))
        return message

    def _dispatch(self, session, method, params):
        for page in self.pages:
            if page.session == session:
                page._on_event(method, params)
        self._events.append((self.event_count, session, method, params))
        self.event_count += 1
        del self._events[:-1000]  # only recent events can still be waited for

    def _check_alive(self, session):
        for page in self.pages:
            if page.session == session and page.crashed:
                raise CdpError(f"the page {page.crashed}")

    def call(self, method, params=None, session=None, timeout=None):
        """Sends one command and returns its result; an error reply, or the page crashing, raises CdpError."""
        deadline = time.monotonic() + (timeout or self.timeout)
        self._check_alive(session)
        wanted = self._send(method, params or {}, session)
        while True:
            message = self._receive(deadline, method)
            self._check_alive(session)
            if message.get("id") == wanted:
                if "error" in message:
                    raise CdpError(f"{method}: {message['error'].get('message')} {message['error'].get('data', '')}")
                return message.get("result", {})

    def wait_event(self, method, session=None, predicate=lambda p: True, timeout=None, since=0):
        """Waits for an event (received as number `since` or later, or arriving) and returns its params."""
        deadline = time.monotonic() + (timeout or self.timeout)
        self._check_alive(session)
        for n, s, m, p in self._events:
            if n >= since and s == session and m == method and predicate(p):
                return p
        while True:
            message = self._receive(deadline, method)
            self._check_alive(session)
            if message.get("method") == method and message.get("sessionId") == session and predicate(
                    message.get("params", {})):
                return message["params"]

    def new_page(self):
        target = self.call("Target.createTarget", {"url": "about:blank"})["targetId"]
        session = self.call("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]
        page = Page(self, target, session)
        self.pages.append(page)
        page._enable()
        return page


# Keys the tests press: the character, its DOM code and its Windows virtual key code.
def _key_info(key):
    if len(key) == 1 and key.isdigit():
        return key, f"Digit{key}", ord(key)
    if len(key) == 1 and key.isalpha():
        return key, f"Key{key.upper()}", ord(key.upper())
    named = {"Escape": ("Escape", 27), "Enter": ("Enter", 13), "Space": ("Space", 32), "Tab": ("Tab", 9)}
    if key in named:
        return key, named[key][0], named[key][1]
    raise ValueError(f"press_key: no key table entry for {key!r}")


class Page:
    """One tab in its own CDP session; collects console errors and uncaught exceptions as they come."""

    def __init__(self, browser, target, session):
        self.browser = browser
        self.target = target
        self.session = session
        self.console = []  # every console message: (type, text)
        self.errors = []  # console errors and uncaught exceptions, as one line each
        self.crashed = None  # what ended the page's renderer, once it has

    def call(self, method, params=None, timeout=None):
        return self.browser.call(method, params, session=self.session, timeout=timeout)

    def _enable(self):
        for domain in ("Inspector", "Page", "Runtime", "Log", "DOM"):
            self.call(f"{domain}.enable")
        self.call("Emulation.setDeviceMetricsOverride", {
            "width": self.browser.width, "height": self.browser.height, "deviceScaleFactor": 1, "mobile": False})

    def _on_event(self, method, params):
        if method == "Inspector.targetCrashed":
            self.crashed = "crashed (its renderer process died: out of memory, or killed)"
            self.errors.append("the page crashed")
        elif method == "Inspector.detached":
            self.crashed = f"was detached ({params.get('reason')})"
        elif method == "Runtime.consoleAPICalled":
            text = " ".join(_remote_text(a) for a in params.get("args", []))
            self.console.append((params.get("type"), text))
            if params.get("type") in ("error", "assert"):
                self.errors.append(f"console.{params['type']}: {text}")
        elif method == "Runtime.exceptionThrown":
            details = params.get("exceptionDetails", {})
            self.console.append(("exception", _exception_text(details)))
            self.errors.append(f"uncaught exception: {_exception_text(details)}")
        elif method == "Log.entryAdded":
            entry = params.get("entry", {})
            self.console.append((f"log.{entry.get('level')}", f"{entry.get('text')} {entry.get('url', '')}"))
            if entry.get("level") == "error":
                self.errors.append(f"{entry.get('source')} error: {entry.get('text')} {entry.get('url', '')}".strip())

    def close(self):
        """Closes the tab (its console log is kept)."""
        self.write_console_log()
        self.browser.call("Target.closeTarget", {"targetId": self.target})
        if self in self.browser.pages:
            self.browser.pages.remove(self)

    def write_console_log(self):
        path = self.browser.evidence_dir / "console.log"
        with open(path, "a") as f:
            f.write(f"--- page {self.target}\n")
            for kind, text in self.console:
                f.write(f"{kind}: {text}\n")

    def take_errors(self):
        """The errors collected since the last call, after the page has delivered what it had queued."""
        self.evaluate("0", await_promise=False)
        errors, self.errors = self.errors, []
        return errors

    # ---- navigation and script ----

    def navigate(self, url, timeout=None):
        since = self.browser.event_count
        result = self.call("Page.navigate", {"url": url})
        if result.get("errorText"):
            raise CdpError(f"cannot load {url}: {result['errorText']}")
        self.browser.wait_event("Page.loadEventFired", session=self.session, timeout=timeout, since=since)

    def evaluate(self, expression, await_promise=True, timeout=None):
        """Evaluates a JS expression and returns its value as JSON; a throw or rejection raises JsError."""
        result = self.call("Runtime.evaluate", {
            "expression": expression, "awaitPromise": await_promise, "returnByValue": True, "userGesture": True},
            timeout=timeout)
        if "exceptionDetails" in result:
            raise JsError(_exception_text(result["exceptionDetails"]))
        value = result.get("result", {})
        return value.get("value")

    def call_function(self, function, *args, timeout=None):
        """Evaluates `(function)(...args)` with the arguments passed as JSON, and awaits the result."""
        return self.evaluate(f"({function})(...{json.dumps(list(args))})", timeout=timeout)

    def wait_for(self, expression, timeout=None, interval=0.05):
        """Polls a JS expression until it is truthy; returns its value."""
        deadline = time.monotonic() + (timeout or self.browser.timeout)
        while True:
            value = self.evaluate(expression, timeout=max(1.0, deadline - time.monotonic()))
            if value:
                return value
            if time.monotonic() > deadline:
                raise CdpTimeout(f"timed out waiting for {expression}")
            time.sleep(interval)

    # ---- input ----

    def center_of(self, selector):
        """The centre of an element in viewport pixels (it is scrolled into view first)."""
        return tuple(self.call_function("""(sel) => {
            const e = document.querySelector(sel);
            if (!e) throw new Error(`no element matches ${sel}`);
            e.scrollIntoView({block: 'center', inline: 'center'});
            const r = e.getBoundingClientRect();
            return [r.left + r.width / 2, r.top + r.height / 2];
        }""", selector))

    def mouse(self, kind, x, y, buttons=0, button="none", click_count=0):
        self.call("Input.dispatchMouseEvent", {"type": kind, "x": x, "y": y, "button": button,
                                               "buttons": buttons, "clickCount": click_count})

    def click(self, x, y):
        self.mouse("mouseMoved", x, y)
        self.mouse("mousePressed", x, y, buttons=1, button="left", click_count=1)
        self.mouse("mouseReleased", x, y, buttons=0, button="left", click_count=1)

    def click_selector(self, selector):
        self.click(*self.center_of(selector))

    def drag(self, x0, y0, x1, y1, steps=8):
        """A left-button drag: press, `steps` moves along the line, release."""
        self.mouse("mouseMoved", x0, y0)
        self.mouse("mousePressed", x0, y0, buttons=1, button="left", click_count=1)
        for i in range(1, steps + 1):
            t = i / steps
            self.mouse("mouseMoved", x0 + (x1 - x0) * t, y0 + (y1 - y0) * t, buttons=1, button="left")
        self.mouse("mouseReleased", x1, y1, buttons=0, button="left", click_count=1)

    def press_key(self, key):
        """Presses and releases one key ('0'..'9', a letter, or Escape/Enter/Space/Tab) on the focused page."""
        text, code, vk = _key_info(key)
        down = {"type": "keyDown", "key": text, "code": code, "windowsVirtualKeyCode": vk,
                "nativeVirtualKeyCode": vk}
        if len(text) == 1:
            down["text"] = text
            down["unmodifiedText"] = text
        self.call("Input.dispatchKeyEvent", down)
        self.call("Input.dispatchKeyEvent", {"type": "keyUp", "key": text, "code": code,
                                             "windowsVirtualKeyCode": vk, "nativeVirtualKeyCode": vk})

    def set_range(self, selector, value):
        """Sets an <input type=range> (or any input) value and fires 'input' then 'change', as a user's drag
        ends; returns the value the input holds afterwards (clamped and stepped by the browser)."""
        return self.call_function("""(sel, v) => {
            const e = document.querySelector(sel);
            if (!e) throw new Error(`no element matches ${sel}`);
            e.value = String(v);
            e.dispatchEvent(new Event('input', {bubbles: true}));
            e.dispatchEvent(new Event('change', {bubbles: true}));
            return e.value;
        }""", selector, value)

    def select_option(self, selector, value):
        """Chooses an option of a <select> by value and fires 'input' and 'change'."""
        return self.call_function("""(sel, v) => {
            const e = document.querySelector(sel);
            if (!e) throw new Error(`no element matches ${sel}`);
            if (![...e.options].some(o => o.value === v)) throw new Error(`${sel} has no option ${v}`);
            e.value = v;
            e.dispatchEvent(new Event('input', {bubbles: true}));
            e.dispatchEvent(new Event('change', {bubbles: true}));
            return e.value;
        }""", selector, value)

    def set_file_input(self, selector, paths):
        """Puts files into an <input type=file>, as a user's choice would (Chromium fires 'input' and 'change')."""
        root = self.call("DOM.getDocument", {"depth": 0})["root"]["nodeId"]
        node = self.call("DOM.querySelector", {"nodeId": root, "selector": selector})["nodeId"]
        if not node:
            raise CdpError(f"no element matches {selector}")
        self.call("DOM.setFileInputFiles", {"nodeId": node, "files": [str(Path(p).resolve()) for p in paths]})

    # ---- pictures ----

    def screenshot(self, path, clip=None):
        """Writes the viewport (or clip = (x, y, w, h) in CSS pixels) as a PNG file; returns its bytes."""
        params = {"format": "png", "fromSurface": True}
        if clip:
            params["clip"] = {"x": clip[0], "y": clip[1], "width": clip[2], "height": clip[3], "scale": 1}
        data = base64.b64decode(self.call("Page.captureScreenshot", params)["data"])
        Path(path).write_bytes(data)
        return data


def living_in_group(group):
    """Processes of a process group that still run (zombies, which a container's init may never reap, hold
    nothing and do not count)."""
    living = []
    for stat in Path("/proc").glob("[0-9]*/stat"):
        try:
            fields = stat.read_text().rsplit(")", 1)[1].split()
        except OSError:
            continue
        if int(fields[2]) == group and fields[0] not in ("Z", "X"):
            living.append(stat.parent.name)
    return living


def _wait_for_group_to_die(group, timeout=10.0):
    """SIGKILL is delivered asynchronously: the helpers of a killed group can still show as running for a few
    milliseconds on a loaded machine. Returns once none does (or after `timeout`, leaving the rest to init)."""
    deadline = time.monotonic() + timeout
    while living_in_group(group) and time.monotonic() < deadline:
        time.sleep(0.01)


def _die_with_parent():
    """In the child before exec: SIGKILL when the parent dies (Linux prctl PR_SET_PDEATHSIG)."""
    try:
        ctypes.CDLL("libc.so.6", use_errno=True).prctl(1, signal.SIGKILL, 0, 0, 0)
    except OSError:
        pass


def _remote_text(obj):
    if "value" in obj:
        return str(obj["value"])
    return obj.get("description") or obj.get("unserializableValue") or obj.get("type", "")


def _exception_text(details):
    """The JS message of an exception: its description's first line, or the thrown value itself."""
    exception = details.get("exception")
    if exception:
        if "value" in exception:
            return str(exception["value"])
        if exception.get("description"):
            return exception["description"].splitlines()[0]
    return details.get("text", "exception")
