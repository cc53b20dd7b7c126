"""The fixed parts of every generated driver: the same in every module `rdisc
emit-python` writes, whatever the description says.

`rdisc.emit.python` writes these texts as they are, between the parts it
compiles from the Model. They follow the rdisc runtime contract
(`rdisc.runtime`), like the runtime itself. They are not a library the driver
imports: a generated driver is a single module that needs nothing of rdisc.
Each text is code at module level; `ROBOT_*` texts go inside the robot class.
"""

from __future__ import annotations

ERRORS = '''\
class RdisError(Exception):
    """Any failure while the robot runs."""


class RdisTimeout(RdisError, TimeoutError):
    """The device sent no reply within the timeout."""


class RdisProtocolError(RdisError):
    """The device replied, but not as described: short, unterminated or unmatched."""


class RdisConnectionError(RdisError, ConnectionError):
    """A port could not be opened, failed, or disappeared."""


class RdisValueError(RdisError, ValueError):
    """A value could not be computed or encoded (division by zero, out of range for its code)."""


class RdisCallbackError(RdisError):
    """A user callback raised; the exception is the cause."""'''

TYPES = '''\
Value = int | float | bool | str
"""The value of a state variable, a parameter or an output field."""

OutputCallback = Callable[[dict[str, Any]], object]
ErrorCallback = Callable[[BaseException], object]
IoCallback = Callable[[str, str, bytes], object]

_EVAL_ERRORS = (ArithmeticError, ValueError, TypeError, IndexError)
"""What evaluating an expression can raise; each becomes an RdisValueError."""

_log = logging.getLogger("rdisc")'''

# Expression helpers: each one the same operation as rdisc.semantics.operators
# defines, written out so that the driver needs nothing of rdisc. Only the
# helpers a description uses are written into its driver.
HELPERS = {
    "_add": '''\
def _add(a: float, b: float) -> float:
    """a + b; a float result too large to represent is an error, not inf."""
    result = a + b
    if result - result != 0.0 and math.isinf(result) and not (math.isinf(a) or math.isinf(b)):
        raise ArithmeticError("the result is too large for a float")
    return result''',
    "_sub": '''\
def _sub(a: float, b: float) -> float:
    """a - b; a float result too large to represent is an error, not inf."""
    result = a - b
    if result - result != 0.0 and math.isinf(result) and not (math.isinf(a) or math.isinf(b)):
        raise ArithmeticError("the result is too large for a float")
    return result''',
    "_mul": '''\
def _mul(a: float, b: float) -> float:
    """a * b; a float result too large to represent is an error, not inf."""
    result = a * b
    if result - result != 0.0 and math.isinf(result) and not (math.isinf(a) or math.isinf(b)):
        raise ArithmeticError("the result is too large for a float")
    return result''',
    "_div": '''\
def _div(a: float, b: float) -> float:
    """a / b; division by zero, or a result too large to represent, is an error."""
    result = a / b
    if result - result != 0.0 and math.isinf(result) and not (math.isinf(a) or math.isinf(b)):
        raise ArithmeticError("the result is too large for a float")
    return result''',
    "_concat": '''\
def _concat(a: str, b: str) -> str:
    """a + b for strings, at most a mebibyte of text."""
    if len(a) + len(b) > 1 << 20:
        raise ValueError(f"string longer than {1 << 20} characters")
    return a + b''',
    "_pow": '''\
def _pow(a: Any, b: Any) -> Any:
    """a ** b, bounded: an int result stays within 4096 bits, a float one must be real and finite."""
    if isinstance(a, int) and isinstance(b, int):
        if b < 0:
            raise ArithmeticError(f"negative integer exponent {b}: write a float base")
        if abs(a) > 1 and b * max(1, abs(a).bit_length()) > 4096:
            raise ArithmeticError(f"{a} ** {b} is too large (results are limited to 4096 bits)")
        return a**b
    try:
        result = float(a) ** float(b)
    except OverflowError:
        raise ArithmeticError(f"{a} ** {b} is too large for a float") from None
    except ZeroDivisionError:
        raise ArithmeticError(f"{a} ** {b}: zero to a negative power") from None
    if isinstance(result, float):
        return result
    raise ArithmeticError(f"{a} ** {b} has no real value")  # a complex result''',
    "_lshift": '''\
def _lshift(a: int, b: int) -> int:
    """a << b, bounded: results stay below 4096 bits."""
    if b < 0:
        raise ArithmeticError(f"negative shift count {b}")
    if b > 1024 or a.bit_length() + b > 4096:
        raise ArithmeticError(f"{a} << {b} is too large (results are limited to 4096 bits)")
    return a << b''',
    "_clamp": '''\
def _clamp(x: _Number, low: _Number, high: _Number) -> _Number:
    """x, limited to [low, high]."""
    if x < low:
        return low
    if x > high:
        return high
    return x''',
    "_int": '''\
def _int(text: str) -> int:
    """The int a string spells, in decimal or with a 0x, 0o or 0b prefix."""
    stripped = text.strip()
    return int(stripped, 0) if stripped[:2].lower() in ("0x", "0b", "0o") else int(text)''',
    "_decoded": '''\
def _decoded(values: tuple[Any, ...], strings: tuple[int, ...]) -> tuple[Any, ...]:
    """Unpacked values with the bytes at `strings` decoded as latin-1 text."""
    decoded = list(values)
    for i in strings:
        decoded[i] = decoded[i].decode("latin-1")
    return tuple(decoded)''',
    "_unpacked_rest": '''\
def _unpacked_rest(primitive: str, fixed: struct.Struct, data: bytes, strings: tuple[int, ...]) -> tuple[Any, ...]:
    """The values of a reply ending in `*`: the fixed part, then the rest as bytes."""
    if len(data) < fixed.size:
        raise RdisProtocolError(f"{primitive}: expected {fixed.size} bytes or more, got {len(data)}")
    values = list(fixed.unpack_from(data))
    for i in strings:
        values[i] = values[i].decode("latin-1")
    return (*values, data[fixed.size :])''',
    "_unpacked": '''\
def _unpacked(primitive: str, layout: struct.Struct, data: bytes, strings: tuple[int, ...]) -> tuple[Any, ...]:
    """The values of a reply of exactly `layout.size` bytes, the bytes at `strings` as latin-1 text."""
    if len(data) != layout.size:
        raise RdisProtocolError(f"{primitive}: expected {layout.size} bytes, got {len(data)}")
    values = list(layout.unpack(data))
    for i in strings:
        values[i] = values[i].decode("latin-1")
    return tuple(values)''',
    "_tag_split": '''\
def _tag_split(primitive: str, tag: struct.Struct, payload: bytes) -> tuple[int, bytes]:
    """A reply's tag, and the rest of its payload."""
    if len(payload) < tag.size:
        raise RdisProtocolError(f"{primitive}: expected {tag.size} bytes or more, got {len(payload)}")
    value: int = tag.unpack_from(payload)[0]
    return value, payload[tag.size :]''',
    "_byte": '''\
def _byte(data: bytes, index: int) -> int:
    """`byte(b, i)`: byte i of bytes b, 0 first."""
    if not 0 <= index < len(data):
        raise IndexError(f"byte {index} of {len(data)} bytes: no such byte")
    return data[index]''',
    "_match": '''\
def _match(primitive: str, regex: re.Pattern[str], line: str) -> tuple[str, ...]:
    """The groups of a reply line (an unmatched group is ""); a line that does not match is an error."""
    found = regex.match(line)
    if found is None:
        raise RdisProtocolError(f"{primitive}: reply {line!r} does not match {regex.pattern!r}")
    return found.groups("")''',
}

NUMBER_TYPE = '_Number = TypeVar("_Number", int, float)'

PORTS = '''\
class Port(Protocol):
    """What the driver needs of an open port; pyserial's `Serial` has all of it."""

    def write(self, data: bytes, /) -> int | None: ...

    def read(self, size: int = 1, /) -> bytes: ...

    def read_until(self, expected: bytes = b"\\n", size: int | None = None, /) -> bytes: ...

    def reset_input_buffer(self) -> None: ...

    def close(self) -> None: ...

    timeout: float | None


PortSpec = str | os.PathLike[str] | Port | Mapping[str, str | os.PathLike[str] | Port]
"""A port for every connection (a pyserial port name or URL, or an open port), or a
dict from connection name to port."""


class _Link:
    """A connection's port. Connections given the same port share it and its lock, so
    one exchange at a time goes over it."""

    __slots__ = ("lock", "name", "owned", "port")

    def __init__(self, name: str, port: Port, lock: threading.Lock, owned: bool) -> None:
        self.name = name  # the connection's
        self.port = port
        self.lock = lock
        self.owned = owned  # opened by the driver, so closed by it too


def _open_links(port: PortSpec | None, bauds: Mapping[str, int], addresses: Mapping[str, str], timeout: float,
                links: dict[str, _Link]) -> None:
    """Open a port for each connection into `links`: one name or URL is opened once and
    shared; an open port object is used as it is (and never closed by the driver). A
    connection given no port opens its address."""
    given: dict[str, str | os.PathLike[str] | Port]
    if isinstance(port, Mapping):
        unknown = [name for name in port if name not in bauds]
        if unknown:
            raise ValueError(
                f"{ROBOT} has no connection named {unknown[0]!r} (its connections: {', '.join(bauds)})"
            )
        given = dict(port)
    else:
        given = dict.fromkeys(bauds, port) if port is not None else {}
    for name in bauds:
        if name not in given:
            if name not in addresses:
                raise ValueError(f"no port given for connection {name!r}, which has no `address`")
            given[name] = addresses[name]
    opened: dict[object, _Link] = {}
    for name, where in given.items():
        if isinstance(where, (str, os.PathLike)):
            key: object = os.fspath(where)
            if key not in opened:
                opened[key] = _Link(name, _open_port(name, os.fspath(where), bauds[name], timeout),
                                    threading.Lock(), owned=True)
        else:
            key = id(where)
            if key not in opened:
                opened[key] = _Link(name, where, threading.Lock(), owned=False)
        first = opened[key]
        links[name] = _Link(name, first.port, first.lock, first.owned)


def _open_port(connection: str, url: str, baud: int, timeout: float) -> Port:
    """A port opened with pyserial (any port name or URL it knows) at `baud`, 8N1."""
    try:
        serial: Any = importlib.import_module("serial")
    except ImportError as err:
        raise RdisConnectionError(f"{connection}: opening {url} needs pyserial (pip install pyserial)") from err
    try:
        port = serial.serial_for_url(
            url, baudrate=baud, bytesize=8, parity="N", stopbits=1, timeout=timeout, write_timeout=timeout
        )
    except (serial.SerialException, OSError, ValueError) as err:
        raise RdisConnectionError(f"{connection}: cannot open {url}: {err}") from err
    return cast(Port, port)


def _port_error(link: _Link, primitive: str, err: Exception, timeout: float) -> RdisError:
    """The typed error for what a port raised: a write that timed out, or a failed port."""
    try:
        serial: Any = importlib.import_module("serial")
        write_timeout = isinstance(err, serial.SerialTimeoutException)
    except ImportError:
        write_timeout = False
    if write_timeout:
        return RdisTimeout(f"{primitive}: write not completed within {timeout:g} s")
    return RdisConnectionError(f"{link.name}: {err}")


def _accept(value: Any, kind: type, what: str) -> Any:
    """A value given for a parameter or field of type `kind`, made that type; else TypeError."""
    if type(value) is kind:
        return value
    if kind is float and isinstance(value, numbers.Real) and not isinstance(value, bool):
        return float(value)
    if kind is int and isinstance(value, numbers.Integral) and not isinstance(value, bool):
        return int(value)
    if kind is str and isinstance(value, str):
        return value
    if kind is bytes:  # bytes, a bytearray, a list of ints 0..255, or hex text ("3c20")
        try:
            if isinstance(value, str):
                return bytes.fromhex(value)
            if isinstance(value, (bytes, bytearray, memoryview, list, tuple)):
                return bytes(value)
        except (ValueError, TypeError) as err:
            raise TypeError(f"{what} must be bytes: {err}") from None
    names = {float: "float", int: "int", bool: "bool", str: "string", bytes: "bytes"}
    raise TypeError(f"{what} must be {names[kind]}, not {type(value).__name__} {value!r}")


class _Schedule:
    """When one connection's work is due, and the loop of its thread.

    Tick k is due at start + k / frequency; a tick already past when the previous
    one ends is skipped, not run in a burst. The keepalive is due one interval after
    start, then every interval after the time it was due (or one interval after
    now, if that is past too).
    """

    def __init__(self, frequency_hz: float, periodic: bool, keepalive_s: float) -> None:
        self.period = 1.0 / frequency_hz if frequency_hz > 0 else math.inf
        self.periodic = periodic
        self.keepalive_s = keepalive_s  # 0: no keepalive
        self._lock = threading.Lock()
        self.restart()

    def restart(self) -> None:
        """Make now the start of the schedule."""
        with self._lock:
            self.start = time.monotonic()
            self.keepalive_at = self.start + self.keepalive_s

    def keepalive_due(self) -> bool:
        """Whether the keepalive is due now; if it is, the next one is scheduled."""
        if not self.keepalive_s:
            return False
        with self._lock:
            now = time.monotonic()
            if now < self.keepalive_at:
                return False
            due = self.keepalive_at + self.keepalive_s
            self.keepalive_at = due if due > now else now + self.keepalive_s
            return True

    def run(self, tick: Callable[[], None] | None, stop: threading.Event) -> None:
        """Call `tick` whenever it is due until `stop` is set, waiting on `stop` (never spinning).
        With nothing periodic to do (`tick` None), only wait."""
        if tick is None or not self.periodic and not self.keepalive_s:
            stop.wait()
            return
        k = 0
        while not stop.is_set():
            tick()
            if self.periodic:
                k = max(k + 1, math.ceil((time.monotonic() - self.start) / self.period))
                wake = self.start + k * self.period
            else:  # only a keepalive: wake when it is due
                wake = self.keepalive_at
            delay = wake - time.monotonic()
            if delay > 0 and stop.wait(delay):
                return'''

ROBOT_CALLBACKS = '''\
def on_output(self, callback: OutputCallback) -> OutputCallback:
    """Call `callback({"name": ..., "contents": {...}})` for every output triggered."""
    with self._callback_lock:
        self._output_callbacks.append(callback)
    return callback

def on_error(self, callback: ErrorCallback) -> ErrorCallback:
    """Call `callback(error)` for every error of periodic work, keepalives, terminate hooks
    and callbacks (with none registered, errors are logged to the "rdisc" logger)."""
    with self._callback_lock:
        self._error_callbacks.append(callback)
    return callback

def on_io(self, callback: IoCallback) -> IoCallback:
    """Call `callback("write" | "read", connection, data)` for every write and every read with data."""
    with self._callback_lock:
        self._io_callbacks.append(callback)
    return callback

@property
def state(self) -> State:
    """The state variables now: an immutable snapshot, `robot.state["name"]` or `.name`."""
    return self._state

@property
def closed(self) -> bool:
    return self._closed'''

ROBOT_LIFECYCLE = '''\
def close(self) -> None:
    """Stop the threads (each finishes the interface it is running, delays included), run
    the terminate hooks (errors reported, not raised) and close the ports open() opened.
    Idempotent; the robot does nothing more afterwards."""
    with self._close_lock:
        if self._closed:
            return
        self._closed = True
        self._running = False
    self._stop.set()
    for thread in self._threads:
        if thread is not threading.current_thread():
            thread.join()
    self.terminate()
    for link in {id(link.port): link for link in self._links.values()}.values():  # each port once
        if link.owned:
            try:
                link.port.close()
            except Exception:  # noqa: BLE001, S110 - a port that fails to close is closed enough
                pass

def _not_running(self) -> RdisConnectionError:
    return RdisConnectionError(f"{ROBOT}: {'closed' if self._closed else 'not open'}")'''

ROBOT_IO = '''\
def _send(self, link: _Link, primitive: str, request: bytes) -> None:
    """Write a request that expects no reply."""
    if not request:  # nothing to send
        return
    lock = link.lock
    lock.acquire()  # not `with`: this is every command's path, and acquire/release is faster
    try:
        link.port.write(request)
    except Exception as err:  # whatever the port raises, it failed
        raise _port_error(link, primitive, err, self.timeout) from err
    finally:
        lock.release()
    if self._io_callbacks:
        self._notify_io("write", link.name, request)

def _exchange(self, link: _Link, primitive: str, request: bytes, size: int, timeout: float | None = None) -> bytes:
    """Write a request and read a reply of exactly `size` bytes (within `timeout`, the
    primitive's own, else the robot's)."""
    reply = self._transfer(link, primitive, request, size, timeout=timeout)
    if not reply:
        raise RdisTimeout(f"{primitive}: no reply within {timeout or self.timeout:g} s")
    if len(reply) != size:
        raise RdisProtocolError(f"{primitive}: expected {size} bytes, got {len(reply)}")
    return reply

def _exchange_line(self, link: _Link, primitive: str, request: bytes, end: bytes = b"\\n",
                   timeout: float | None = None) -> str:
    """Write a request and read one reply line: the line without its terminator `end`
    (the default LF also takes a CR before it), as latin-1 text."""
    line = self._transfer(link, primitive, request, 0, end, timeout)
    if not line:
        raise RdisTimeout(f"{primitive}: no reply within {timeout or self.timeout:g} s")
    if not line.endswith(end):
        raise RdisProtocolError(f"{primitive}: reply line not terminated: {line.decode('latin-1')!r}")
    text = line[: -len(end)]
    if end == b"\\n" and text.endswith(b"\\r"):
        text = text[:-1]
    return text.decode("latin-1")

def _transfer(self, link: _Link, primitive: str, request: bytes, size: int, end: bytes = b"\\n",
              timeout: float | None = None) -> bytes:
    """Under the port's lock: discard unread input, write the request, read `size` bytes
    (0: one line, up to `end`) within `timeout` if given. The I/O callbacks see the write and
    what was read once the lock is released, so that a callback may call the robot."""
    written, data = False, b""
    try:
        with link.lock:
            try:
                if request:  # a listener (no request) keeps what has arrived
                    link.port.reset_input_buffer()
                    link.port.write(request)
                    written = True
                if timeout is not None:
                    link.port.timeout = timeout
                try:
                    data = link.port.read(size) if size else link.port.read_until(end, MAX_LINE)
                finally:
                    if timeout is not None:
                        link.port.timeout = self.timeout
            except Exception as err:
                raise _port_error(link, primitive, err, self.timeout) from err
    finally:
        if self._io_callbacks:
            if written:
                self._notify_io("write", link.name, request)
            if data:
                self._notify_io("read", link.name, bytes(data))
    return bytes(data)'''

ROBOT_FRAMED = '''\
def _exchange_frame(self, link: _Link, primitive: str, request: bytes, frame: Frame, fields: list[int],
                    size: int, accept: Callable[[bytes], object] | None = None,
                    timeout: float | None = None) -> bytes:
    """Write a framed request and read its framed reply, as rdisc.runtime.framing does:
    the payload (b"" for an acknowledgement). `size`: the payload's, or -1 if the frame says.
    An empty request (a listener) is not written and keeps unread input. With `accept`
    (`skip unmatched`), frames it refuses are read past until the timeout (`timeout`, the
    primitive's own, else the robot's)."""
    wait = timeout or self.timeout
    written, data, payload = False, b"", b""
    failed: FrameError | RdisProtocolError | None = None
    try:
        with link.lock:
            try:
                received = self._inputs.get(id(link.port))
                if received is None:
                    received = self._inputs[id(link.port)] = Input(link.port)
                if request:
                    link.port.reset_input_buffer()
                    received.clear()
                    link.port.write(request)
                    written = True
                if timeout is not None:
                    link.port.timeout = timeout
                deadline = time.monotonic() + wait
                while True:
                    try:
                        chunk, payload = frame.read(received, fields, request, size)
                        data += chunk
                        if size >= 0 and len(payload) != size and frame.reply.payload >= 0:
                            raise RdisProtocolError(f"{primitive}: expected {size} bytes, got {len(payload)}")
                        if accept is not None:
                            accept(payload)
                        break
                    except (FrameError, RdisProtocolError) as err:
                        if accept is None or getattr(err, "timeout", False) or time.monotonic() >= deadline:
                            failed = err
                            break
                if timeout is not None:
                    link.port.timeout = self.timeout
            except Exception as err:  # whatever the port raises, it failed
                raise _port_error(link, primitive, err, self.timeout) from err
    finally:
        if self._io_callbacks:
            if written:
                self._notify_io("write", link.name, request)
            if data:
                self._notify_io("read", link.name, data)
    if failed is not None:
        if getattr(failed, "timeout", False) or accept is not None:
            what = "matching reply" if accept is not None else "reply"
            raise RdisTimeout(f"{primitive}: no {what} within {wait:g} s")
        if isinstance(failed, RdisProtocolError):
            raise failed
        raise RdisProtocolError(f"{primitive}: {failed}")
    return payload'''

ROBOT_DELIVERY = '''\
def _deliver(self, output: str, contents: dict[str, Value]) -> None:
    message: dict[str, Any] = {"name": output, "contents": contents}
    with self._callback_lock:
        for callback in list(self._output_callbacks):
            try:
                callback(message)
            except Exception as err:  # noqa: BLE001 - a user's callback must not stop delivery
                error = RdisCallbackError(f"{output}: output callback raised {type(err).__name__}: {err}")
                error.__cause__ = err
                self._report(error)

def _notify_io(self, direction: str, connection: str, data: bytes) -> None:
    with self._callback_lock:
        for callback in list(self._io_callbacks):
            try:
                callback(direction, connection, data)
            except Exception as err:  # noqa: BLE001 - a user's callback must not stop the I/O
                error = RdisCallbackError(f"{connection}: I/O callback raised {type(err).__name__}: {err}")
                error.__cause__ = err
                self._report(error)

def _report(self, error: BaseException) -> None:
    with self._callback_lock:
        callbacks = list(self._error_callbacks)
        if not callbacks:
            _log.warning("%s: %s: %s", ROBOT, type(error).__name__, error)
        for callback in callbacks:
            try:
                callback(error)
            except Exception:  # noqa: BLE001, S110 - the contract: an error callback's failure is ignored
                pass'''

COMMAND_LINE = '''\
class _Terminated(BaseException):
    """SIGTERM, turned into an exception so that the terminate hooks run on the way out."""


def _port_argument(given: list[str]) -> str | dict[str, str] | None:
    """--port PORT for every connection, --port CONNECTION=PORT for one (a plain port is the
    default for the others; without one, a connection opens its address), as `rdisc run` reads them."""
    if not given:
        if all(name in _ADDRESSES for name in _CONNECTIONS):
            return None
        raise ValueError("give the device's port: --port /dev/ttyUSB0 (or CONNECTION=PORT for each connection)")
    default: str | None = None
    named: dict[str, str] = {}
    for value in given:
        name, sep, port = value.partition("=")
        if sep and name in _CONNECTIONS:
            if name in named:
                raise ValueError(f"two ports for connection `{name}`")
            named[name] = port
        elif sep and name.isidentifier():
            raise ValueError(f"`{name}` is not a connection of {ROBOT} (its connections: {', '.join(_CONNECTIONS)})")
        elif default is not None:
            raise ValueError(f"two ports without a connection name: `{default}` and `{value}`")
        else:
            default = value
    if not named:
        assert default is not None
        return default
    for name in _CONNECTIONS:
        if name not in named:
            if default is None and name not in _ADDRESSES:
                raise ValueError(f"no port for connection `{name}`: add --port {name}=PORT")
            named[name] = default if default is not None else _ADDRESSES[name]
    return named


def _value_argument(text: str) -> Value:
    """A command-line value: an int, a float, True or False, else the text itself."""
    for convert in (int, float):
        try:
            number: Value = convert(text)
        except ValueError:
            continue
        return number
    if text in ("True", "False"):
        return text == "True"
    return text


def _call_argument(words: list[str]) -> tuple[str, str, dict[str, Value]]:
    """--call NAME K=V ...: (name, "input" | "interface" | "primitive", values by name); an
    input is preferred to an interface of the same name, an interface to a primitive."""
    name, *pairs = words
    values: dict[str, Value] = {}
    for pair in pairs:
        key, sep, text = pair.partition("=")
        if not sep or not key:
            raise ValueError(f"--call {name}: `{pair}` is not KEY=VALUE")
        if key in values:
            raise ValueError(f"--call {name}: `{key}` given twice")
        values[key] = _value_argument(text)
    if name in _INPUTS:
        expected = [field for field, _ in _INPUTS[name][2]]
    elif name in _INTERFACES:
        expected = [param for param, _ in _INTERFACES[name][1]]
    elif name in _PRIMITIVES:
        expected = [param for param, _ in _PRIMITIVES[name][1]]
    else:
        known = ", ".join(dict.fromkeys([*_INPUTS, *_INTERFACES, *_PRIMITIVES])) or "none"
        raise ValueError(f"{ROBOT} has no input, interface or primitive `{name}` (there are: {known})")
    if sorted(values) != sorted(expected):
        wanted = " ".join(f"{e}=..." for e in expected) or "no values"
        raise ValueError(f"--call {name} takes {wanted}")
    kind = "input" if name in _INPUTS else "interface" if name in _INTERFACES else "primitive"
    return name, kind, values


def _print_output(message: dict[str, Any]) -> None:
    sys.stdout.write(json.dumps(message) + "\\n")
    sys.stdout.flush()


def _print_error(error: BaseException) -> None:
    print(f"rdisc run: {type(error).__name__}: {error}", file=sys.stderr, flush=True)  # as `rdisc run` prints it


def _print_io(direction: str, connection: str, data: bytes) -> None:
    arrow = ">" if direction == "write" else "<"
    print(f"{connection} {arrow} {data.hex(' ')}", file=sys.stderr, flush=True)


_shutting_down = [False]


def _on_signal(signum: int, frame: object) -> None:
    if _shutting_down[0]:
        return  # the first signal already started the shutdown: the terminate hooks run in peace
    _shutting_down[0] = True
    raise KeyboardInterrupt if signum == signal.SIGINT else _Terminated()


def _sleep(seconds: float | None) -> None:
    """Sleep (forever if None); a signal ends it through its handler."""
    if seconds is None:
        while True:
            time.sleep(3600)
    elif seconds > 0:
        time.sleep(seconds)'''


def framing() -> str:
    """The text of rdisc.runtime.framing from its first definition on: the driver's copy."""
    from pathlib import Path

    from rdisc.runtime import framing as module

    text = Path(module.__file__).read_text(encoding="utf-8")
    return text[text.index("\nMAX_FRAME") + 1 :].rstrip("\n")
