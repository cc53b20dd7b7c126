"""The console's server: the page, and one WebSocket a page on which everything that
happens is pushed and through which the page makes calls.

One asyncio loop serves HTTP and the WebSockets (the `websockets` library); the robot
runs on its own threads, and its callbacks hand what happened to the loop. Calls from
the pages run on the console's own calls thread, one at a time and in the order they came,
as `rdisc run --call` makes them; the robot is closed on a thread of its own, so the
stop never waits behind page calls, and once the console is stopping no call is made.
When the last page closes (or stops answering pings) the terminate hooks run, so a robot
is not left moving with nobody watching; it stays open for the next page.

Safety: a credential, as Jupyter's: a random `token` in the address the console prints
(`http://127.0.0.1:P/?token=...`) is required for the page and for the WebSocket (the page
passes it on), compared in constant time; a request without it, or with another, is
answered 403 and nothing is called. A WebSocket is also accepted only from a page of this
console: its Origin must be one of `origins` (this console's own addresses), and every
request's Host must be one of them too, so a page of another site that had its name
point here (DNS rebinding) is refused as well.
"""

from __future__ import annotations

import asyncio
import hmac
import json
import math
import secrets
import threading
import time
from collections import deque
from collections.abc import Callable, Iterable
from concurrent.futures import ThreadPoolExecutor
from importlib import resources
from typing import TYPE_CHECKING, Any
from urllib.parse import parse_qs, urlsplit

from websockets.asyncio.server import ServerConnection, broadcast, serve
from websockets.datastructures import Headers
from websockets.exceptions import ConnectionClosed
from websockets.http11 import Request, Response

from rdisc import engine
from rdisc.capture import Message
from rdisc.console import PING_S

if TYPE_CHECKING:
    from rdisc.emit.decode import Teller
    from rdisc.sim import Simulation

ASSETS = {"/console.js": "text/javascript; charset=utf-8", "/console.css": "text/css; charset=utf-8"}
TRACE_KEPT, ERRORS_KEPT = 500, 100  # what a page opened later is shown of the past
LOOPBACK = ("127.0.0.1", "localhost", "[::1]")
BODY_HZ = 10  # how often a simulated body is pushed to the open pages
MAX_DEPTH = 32  # how deep a page's call may nest its JSON (a call is an object of texts)
STOPPING = "the console is stopping: no more calls are made"
MAX_RAW = 4096  # bytes one raw send may write


def origins_for(host: str, port: int, extra: Iterable[str] = ()) -> set[str]:
    """The origins (scheme://host:port) of pages this console serves: its loopback names, the host
    it was bound to (unless a wildcard) and those given."""
    hosts = set(LOOPBACK)
    if host not in ("", "0.0.0.0", "::"):
        hosts.add(f"[{host}]" if ":" in host else host)
    return {f"http://{h}:{port}" for h in hosts} | {o.rstrip("/") for o in extra}


def jsonable(value: Any) -> Any:
    """A value of the description as JSON shows it: bytes as hex, arrays as lists, a float
    that JSON cannot write (inf, nan) as its text."""
    if isinstance(value, bytes):
        return value.hex(" ")
    if isinstance(value, (tuple, list)):
        return [jsonable(v) for v in value]
    if isinstance(value, float) and not math.isfinite(value):
        return str(value)
    if isinstance(value, dict):
        return {k: jsonable(v) for k, v in value.items()}
    return value


class Console:
    """A connected robot, shown and driven by the pages of one server; with the robot's `session`
    (what `--record` records and `--foxglove` serves), each call a page makes is told to it as
    the host's call, as `rdisc run` tells its --call calls (the robot's bytes, outputs and errors
    the session takes from the robot);
    with the `body` it drives (`--sim`), the body as it is now is pushed BODY_HZ times a second;
    with a `teller` (`rdisc decode`'s), each line of the byte trace names the primitive whose
    request or reply it is, for the page to filter by."""

    def __init__(self, robot: engine.Robot, page: str, session: engine.Session | None = None,
                 body: Simulation | None = None, tell: Callable[[str], None] | None = None,
                 ping: float = PING_S, teller: Teller | None = None) -> None:
        self.robot = robot
        self.teller = teller
        self.ping = ping  # seconds: how often a page is pinged, and how long it has to answer, or to close
        self.session = session
        self.body = body
        self.page = page.encode("utf-8")
        self.origins: set[str] = set()
        self.token = secrets.token_urlsafe(32)  # the credential: in the printed address, asked of every page
        self.tell = tell or (lambda text: None)  # a line for the person who started the console
        self.stopping = False  # set when the console stops: no page call is made from then on
        self._calls = ThreadPoolExecutor(max_workers=1, thread_name_prefix="rdisc-console-calls")
        self._start = time.monotonic()
        self._lock = threading.Lock()
        self._trace: deque[dict[str, Any]] = deque(maxlen=TRACE_KEPT)
        self._errors: deque[dict[str, Any]] = deque(maxlen=ERRORS_KEPT)
        self._outputs: dict[str, dict[str, Any]] = {}
        self._state: dict[str, Any] = {}
        self._ages: dict[str, float | None] = {}  # each sensor's age when the state was last pushed
        self._loop: asyncio.AbstractEventLoop | None = None
        self._pages: set[ServerConnection] = set()
        robot.on_output(self._output)
        robot.on_error(self._error)
        robot.on_io(self._io)

    # ---- what happens on the robot's threads ---------------------------------------------------------

    def _now(self) -> float:
        return round(time.monotonic() - self._start, 3)

    def _output(self, message: dict[str, Any]) -> None:
        event = {"type": "output", "t": self._now(), "name": message["name"], "contents": jsonable(message["contents"])}
        with self._lock:
            self._outputs[message["name"]] = event
        self._push(event)
        self._push_state()

    def _error(self, error: BaseException) -> None:
        self.report(type(error).__name__, str(error))

    def report(self, kind: str, message: str) -> None:
        """An error on the page's error list (and on every page open)."""
        event = {"type": "error", "t": self._now(), "error": kind, "message": message}
        with self._lock:
            self._errors.append(event)
        self._push(event)

    def _io(self, direction: str, connection: str, data: bytes) -> None:
        shown = data.decode("ascii") if direction == "lines" else data.hex(" ")
        primitive = None
        if self.teller is not None and direction != "lines":  # told in the order of the wire (`_show`)
            primitive = self.teller.primitive(Message(direction == "write", data, connection))
        event = {"type": "io", "t": self._now(), "direction": direction, "connection": connection, "data": shown,
                 "primitive": primitive}
        with self._lock:
            self._trace.append(event)
        self._push(event)
        self._push_state()

    def _push_state(self) -> None:
        """The state, when it changed or a sensor was read anew, with each sensor's age then."""
        state = jsonable(dict(self.robot.state))
        ages = self._sensor_ages()
        with self._lock:
            fresh = any(a is not None and ((was := self._ages.get(n)) is None or a < was) for n, a in ages.items())
            if state == self._state and not fresh:
                return
            self._state, self._ages = state, ages
        event: dict[str, Any] = {"type": "state", "state": state}
        if ages:
            event["sensor_ages"] = ages
        self._push(event)

    def _sensor_ages(self) -> dict[str, float | None]:
        """Seconds since each sensor's value was read (None: never), by the robot's clock."""
        return {n: None if (a := self.robot.sensor_age(n)) is None else round(a, 3) for n in self.robot.device.sensors}

    def _push(self, event: dict[str, Any]) -> None:
        loop = self._loop
        if loop is None:
            return  # no page yet: a page opened later is sent what was kept
        try:
            loop.call_soon_threadsafe(self._send, json.dumps(event))
        except RuntimeError:  # the loop is closed: the console is stopping and no page is left
            pass

    def _send(self, text: str) -> None:
        broadcast(self._pages, text)

    def _body_event(self, body: Simulation) -> dict[str, Any]:
        """The simulated body now: each link's world frame, each moving joint's position."""
        links = {name: [round(v, 6) for v in pose] for name, pose in body.link_poses().items()}
        joints = {name: round(value, 6) for name, value in body.joint_positions().items()}
        return {"type": "body", "t": self._now(), "links": links, "joints": joints}

    async def _push_body(self, body: Simulation) -> None:
        """While a page is open, the body as the simulation has it, BODY_HZ times a second
        (read on a worker thread: the simulation's lock may be held by a step)."""
        while True:
            await asyncio.sleep(1 / BODY_HZ)
            if self._pages:
                self._send(json.dumps(await asyncio.to_thread(self._body_event, body)))

    # ---- the server ----------------------------------------------------------------------------------

    async def serve(self, host: str, port: int, stop: asyncio.Event, listening: Callable[[int], None],
                    extra_origins: Iterable[str] = ()) -> None:
        """Serve pages until `stop` is set, then close the robot (its terminate hooks run, and the
        pages still see their bytes); `listening(port)` once the socket listens (port 0: a free one)."""
        self._loop = asyncio.get_running_loop()
        try:
            async with serve(self._page, host, port, process_request=self._http, compression=None,
                             max_size=2**16, ping_interval=self.ping, ping_timeout=self.ping,
                             close_timeout=self.ping) as server:
                bound = next(iter(server.sockets)).getsockname()[1]
                self.origins = origins_for(host, bound, extra_origins)
                listening(bound)
                pushing = asyncio.create_task(self._push_body(self.body)) if self.body is not None else None
                try:
                    await stop.wait()
                finally:
                    self.stopping = True
                    if pushing is not None:
                        pushing.cancel()
                await self.close()
        finally:
            self.stopping = True
            self._calls.shutdown(wait=False, cancel_futures=True)

    async def close(self) -> None:
        """Close the robot on a thread of its own (never queued behind page calls): from now on no
        page call is made, and the engine ends the one in progress (`Robot.close`)."""
        self.stopping = True
        loop = asyncio.get_running_loop()
        closed: asyncio.Future[None] = loop.create_future()

        def done() -> None:
            if not closed.done():
                closed.set_result(None)

        def close() -> None:
            try:
                self.robot.close()
            finally:
                loop.call_soon_threadsafe(done)

        threading.Thread(target=close, name="rdisc-console-close", daemon=True).start()
        await closed

    def _http(self, connection: ServerConnection, request: Request) -> Response | None:
        """Plain requests get the page and its assets; the WebSocket's handshake is checked."""
        host = _one(request.headers, "Host")
        if f"http://{host}" not in self.origins:
            return _response(403, f"Forbidden: this console is not served as {host!r}\n")
        address = urlsplit(request.path)
        path = address.path
        if path == "/ws":
            origin = _one(request.headers, "Origin")
            if origin not in self.origins:
                return _response(403, f"Forbidden: a page from {origin!r} may not drive this robot\n")
            if not self._holds_token(address.query):
                return _response(403, _NO_TOKEN)
            return None
        if "websocket" in (value.lower() for value in request.headers.get_all("Upgrade")):
            return _response(404, "Not found\n")
        if path == "/":
            if not self._holds_token(address.query):
                return _response(403, _NO_TOKEN)
            return _response(200, self.page, "text/html; charset=utf-8")
        kind = ASSETS.get(path)
        if kind is not None:
            data = resources.files("rdisc.console").joinpath("assets", path[1:]).read_bytes()
            return _response(200, data, kind)
        return _response(404, "Not found\n")

    def _holds_token(self, query: str) -> bool:
        """Whether a request's query gives this console's token (once), compared in constant time."""
        given = parse_qs(query).get("token", [])
        return len(given) == 1 and hmac.compare_digest(given[0].encode("utf-8"), self.token.encode("utf-8"))

    async def _page(self, page: ServerConnection) -> None:
        """One open page: first what happened so far, then every event as it comes; its calls, each
        made on the calls thread. When the last page closes, the terminate hooks run."""
        with self._lock:
            self._state = jsonable(dict(self.robot.state))
            hello = {"type": "hello", "t": self._now(), "state": self._state, "trace": list(self._trace),
                     "errors": list(self._errors), "outputs": list(self._outputs.values())}
        if self.robot.device.sensors:
            hello["sensor_ages"] = self._sensor_ages()
        self._pages.add(page)
        loop = asyncio.get_running_loop()
        try:
            await page.send(json.dumps(hello))
            async for text in page:
                reply = _refused(text) if self.stopping else await loop.run_in_executor(self._calls, self.call, text)
                await page.send(json.dumps(reply))
        except ConnectionClosed:
            pass
        finally:
            self._pages.discard(page)
            if not self._pages and not self.stopping:
                self._calls.submit(self._last_page_closed)

    def _last_page_closed(self) -> None:
        """No page is open: run the terminate hooks (the robot stops), and say so; the robot stays
        open for the next page. On the calls thread, after any call a page made before it closed."""
        if self.stopping or self._pages or self.robot.closed:
            return
        hooks = [c.terminate for c in self.robot.device.connections.values() if c.terminate is not None]
        if not hooks:
            return
        with engine.ports_held(self.robot):  # recorded in the wire's order: no tick between telling and writing
            if self.session is not None:  # told as the host's calls, so a replay writes the same stop
                state = dict(self.robot.state)
                for hook in hooks:
                    try:
                        values = dict(zip((p.name for p in hook.interface.params), hook.args(state), strict=True))
                    except Exception:  # noqa: BLE001, S112 - the hook's own run reports it
                        continue
                    self.session.call("interface", hook.interface.name, values)
            self.robot.terminate()  # its errors are reported, as the robot's are
        names = ", ".join(f"{hook.interface.name}()" for hook in hooks)
        self.tell(f"rdisc console: the last page closed: {names} ran (the terminate hook); "
                  "the robot stays open for the next page")

    # ---- calls from a page ---------------------------------------------------------------------------

    def call(self, text: str | bytes) -> dict[str, Any]:
        """One call a page asked for, `{"id", "kind", "name", "values": {NAME: text}}`, or raw bytes
        to send, `{"id", "kind": "raw", "connection": C, "hex": TEXT}`; its result (a raw send's
        with the bytes written, `"sent"` in hex and `"sent_text"` in ASCII, and the device's answer,
        `"answer"` and `"text"`; `.` for a byte that is no printable character)."""
        if self.stopping:
            return _refused(text)
        ident: Any = None
        made = False  # a call refused before it is made is not the robot's error, nor recorded
        try:
            request = _parse(text)
            if not isinstance(request, dict):
                raise TypeError("a call is a JSON object")
            ident = request.get("id")
            kind, name, values = request.get("kind"), request.get("name"), request.get("values", {})
            if kind == "raw":
                connection, data = self._raw_request(request)  # not a call: the session records only its bytes
                answer = self.robot.send_raw(connection, data)
                self._push_state()
                return {"type": "result", "id": ident, "ok": True, "sent": data.hex(" "), "sent_text": printable(data),
                        "answer": answer.hex(" "), "text": printable(answer)}
            if not isinstance(name, str) or not isinstance(values, dict):
                raise TypeError("a call names what it calls and gives its values by name")
            given = _read(self.robot.device, kind, name, values)
            with engine.ports_held(self.robot):  # recorded in the wire's order, as `rdisc run` does
                if self.session is not None:  # told before it is made
                    self.session.call(str(kind), name, given)
                made = True
                engine.make_call(self.robot, str(kind), name, given)
        except (engine.RdisError, TypeError, ValueError, KeyError) as err:
            if self.session is not None and made and isinstance(err, engine.RdisError):
                self.session.error(err)
            message = err.args[0] if isinstance(err, KeyError) and err.args else str(err)
            self.report(type(err).__name__, str(message))
            self._push_state()
            return {"type": "result", "id": ident, "ok": False, "error": type(err).__name__, "message": str(message)}
        self._push_state()
        return {"type": "result", "id": ident, "ok": True}

    def _raw_request(self, request: dict[str, Any]) -> tuple[str, bytes]:
        """A raw send's connection (the only one when not named) and its bytes."""
        connections = self.robot.device.connections
        connection = request.get("connection") or (next(iter(connections)) if len(connections) == 1 else None)
        if not isinstance(connection, str):
            raise TypeError(f"raw: name the connection to send on ({', '.join(connections)})")
        if connection not in connections:
            raise KeyError(f"{self.robot.name} has no connection named {connection!r}")
        return connection, raw_bytes(request.get("hex"))


def raw_bytes(text: object) -> bytes:
    """The bytes of a raw send, typed as hex: pairs of digits, spaces (or commas) between bytes
    allowed, each byte may be written `0x..`; anything else a ValueError that says what."""
    if not isinstance(text, str):
        raise TypeError("raw: the bytes are given as hex text")
    words = text.replace(",", " ").split()
    digits = "".join(word[2:] if word[:2].lower() == "0x" else word for word in words)
    if not digits:
        raise ValueError("raw: no bytes given (type them as hex: 8e 16)")
    bad = next((c for c in digits if c not in "0123456789abcdefABCDEF"), None)
    if bad is not None:
        raise ValueError(f"raw: {bad!r} is not a hex digit (type the bytes as hex: 8e 16)")
    if len(digits) % 2:
        raise ValueError(f"raw: {len(digits)} hex digits are not whole bytes (two digits a byte: 0e, not e)")
    if len(digits) // 2 > MAX_RAW:
        raise ValueError(f"raw: {len(digits) // 2} bytes; a raw send writes at most {MAX_RAW}")
    return bytes.fromhex(digits)


def printable(data: bytes) -> str:
    """Bytes as ASCII, as miniterm's hex view shows them beside the hex: `.` for a byte that is no
    printable character."""
    return "".join(chr(b) if 0x20 <= b < 0x7F else "." for b in data)


def _parse(text: str | bytes) -> Any:
    """A page's message as JSON, refused (ValueError) when it nests deeper than MAX_DEPTH (the
    depth is counted before parsing, so no message can exhaust the parser's recursion) or holds a
    number that is not finite."""
    chars = text.decode("utf-8", "replace") if isinstance(text, bytes) else text
    depth, quoted, escaped = 0, False, False
    for char in chars:
        if quoted:
            if escaped:
                escaped = False
            elif char == "\\":
                escaped = True
            elif char == '"':
                quoted = False
        elif char == '"':
            quoted = True
        elif char in "[{":
            depth += 1
            if depth > MAX_DEPTH:
                raise ValueError(f"a call nests its values at most {MAX_DEPTH} deep")
        elif char in "]}":
            depth -= 1
    return json.loads(text, parse_constant=_not_finite, parse_float=_finite)


def _not_finite(word: str) -> float:
    """Python's JSON reader takes NaN and Infinity, which are not JSON: echoed as a call's id they
    made an answer no page can read."""
    raise ValueError(f"a call's numbers are finite: {word} is not")


def _finite(word: str) -> float:
    number = float(word)
    return number if math.isfinite(number) else _not_finite(word)


def _refused(text: str | bytes) -> dict[str, Any]:
    """The answer to a call made while the console is stopping: nothing is called."""
    try:
        request = _parse(text)
        ident = request.get("id") if isinstance(request, dict) else None
    except ValueError:
        ident = None
    return {"type": "result", "id": ident, "ok": False, "error": "Refused", "message": STOPPING}


_FORM_WORDS = {int: "an int", float: "a number", bool: "true or false"}
"""What a form's field of a scalar type must hold, in the words of the console's errors."""


def _read(device: engine.Device, kind: object, name: str, values: dict[str, Any]) -> dict[str, Any]:
    """The form's values, each a text (a checkbox's a bool), typed as `--call` types them
    (`engine.call_values`), in the parameters' order; the console's words for what is refused."""

    def read(given: Any, p: engine.Param, what: str) -> Any:
        if not isinstance(given, str) and not (isinstance(given, bool) and p.kind is bool and p.size is None):
            raise TypeError(f"{name}: {p.name} is given as text, not {type(given).__name__}")
        try:
            return engine.read_value(given, p, what)
        except TypeError:
            if p.size is not None or p.kind not in _FORM_WORDS:
                raise
            raise ValueError(f"{name}: {p.name} must be {_FORM_WORDS[p.kind]}, not {given!r}") from None

    try:
        return engine.call_values(device, kind, name, values, read)
    except engine.Unbound as err:
        if err.unknown is not None:
            raise TypeError(f"{name} has no parameter or field named {err.unknown!r}") from None
        raise TypeError(f"{name}: {err.missing} is missing") from None


_NO_TOKEN = ("Forbidden: open the address this console printed, with its token "
             "(http://HOST:PORT/?token=...)\n")

# the page's own files only, its WebSocket only, and no framing by another site
_POLICY = ("default-src 'self'; connect-src 'self'; img-src 'self' data:; style-src 'self' 'unsafe-inline'; "
           "frame-ancestors 'none'")


def _one(headers: Headers, name: str) -> str | None:
    """The header's value, when it is given exactly once."""
    values = headers.get_all(name)
    return values[0] if len(values) == 1 else None


def _response(status: int, body: str | bytes, kind: str = "text/plain; charset=utf-8") -> Response:
    data = body.encode("utf-8") if isinstance(body, str) else body
    reasons = {200: "OK", 403: "Forbidden", 404: "Not Found"}
    headers = Headers([("Content-Type", kind), ("Content-Length", str(len(data))), ("Cache-Control", "no-store"),
                       ("X-Content-Type-Options", "nosniff"), ("Connection", "close"),
                       ("Referrer-Policy", "no-referrer"),
                       ("Content-Security-Policy", _POLICY)])
    return Response(status, reasons[status], headers, data)
