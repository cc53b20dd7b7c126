"""rdisc's runtime: interprets a checked Model against real devices.

The semantics below are implemented once, in `rdisc.runtime.engine`, which the
runtime imports and every driver `rdisc emit-python` generates carries verbatim.
What differs is only how a description becomes the engine's plans: here the
expressions are interpreted (`rdisc.runtime.evaluate`), in a driver they are
compiled to Python; tests drive both over generated descriptions with the same
inputs and device replies and compare bytes, state, outputs, errors and I/O.

Settings. A description's `setting`s are given when connecting (`connect(...,
settings={NAME: value})` here, a keyword each on a driver's `connect`, `--set NAME=VALUE`
on the command line); the others keep their defaults. Each value is made its type as
a parameter's is, then checked against its range and the width of integers; a name
the description lacks or a value that does not fit is RdisValueError "ROBOT: setting
S is V, outside LOW..HIGH" ("ROBOT: setting S must be TYPE, not ...", "ROBOT: no
setting named 'S' (its settings: ...)"), raised before any port is opened. Settings
are read as state is (they are in the state mapping, and `robot.state` shows them),
and nothing writes them. A connection whose `baud` is a setting opens its port at
the setting's value.

Values. State starts at its initial values. Arguments are bound to parameters,
fields and state with ints widened to floats where a float is declared.

Primitive. (1) Evaluate the format arguments over state and parameters. (2) Encode:
`pack` with struct (strings as latin-1 bytes), `format` with str.format, then
latin-1. A value the encoding refuses (out of range for its code, a character
above U+00FF) is an RdisValueError. (3) Under the connection's lock: if a reply is
expected, discard unread input; write; read the reply. `unpack`: exactly
calcsize bytes; none within the timeout is RdisTimeout, fewer is
RdisProtocolError; strings decoded latin-1. `regex`: one line up to the
connection's `terminator` (default b"\\n"; at most MAX_LINE bytes), the terminator
stripped (the default also strips a "\\r" before it), matched with re.match from its
start; no line is RdisTimeout, a line without terminator or not matching is
RdisProtocolError; the groups are the values (an unmatched group is "").
(4) Post-actions: every value is computed from the same snapshot of state, then
all are assigned together. An expression that cannot be evaluated (division by
zero, ...) is an RdisValueError.

Modem lines. A primitive's `lines` are evaluated (bools, over state and its
parameters) after its request is encoded and set, under the lock and in the order
written, before its request is written (pyserial's `port.dtr`, `port.rts`; True
asserts). A primitive without `pack` or `format` only sets them. A port that
refuses is RdisConnectionError "C: P: cannot set dtr = False: ..."; nothing is
written then.

Ranges. A parameter declared `in LOW..HIGH` refuses a value outside it (for
bytes, a length outside it) with RdisValueError "OWNER: parameter P is V, outside
LOW..HIGH" ("has N bytes" for bytes), checked after binding and before the
arguments of its calls or its format arguments are evaluated.

Bytes. A pack format ending in `*` appends its last value, bytes, as it is; an
unpack format ending in `*` gives the rest of the reply as bytes (after its fixed
part: fewer bytes than that is RdisProtocolError "P: expected N bytes or more,
got K"). `len(b)` and `byte(b, i)` read them.

Frames. The
request is the payload framed: constants, fields (the frame's field expressions
over its arguments, which are the primitive's frame arguments), the length
(payload size + adjust), checksums over the parts they cover. A field of the reply
is checked against its own expression (a reply field may share a request
field's name and differ in value). A reply is read
through the frame's reply side: bytes before its header are skipped (up to 4096);
the payload's size comes from the length field, else the decoding's fixed size,
else the constant after it; every constant, field and checksum is checked
(binary checksums exactly, hex digits in either case). Nothing at all is
RdisTimeout; anything else wrong is RdisProtocolError "P: FRAME: what is wrong".
A frame that escapes (SLIP, HDLC) has the bytes between its header and terminator
escaped after framing; its reply is read up to the first terminator (empty packets
dropped), unescaped (an escape before no code is a protocol error), its length
field checked against the payload's size, then checked as any other.
A frame whose reply has no payload is an acknowledgement, read after every
request. A request of no bytes (a listener) is not written and does not discard
unread input: its reply is the next frame. With `skip unmatched`, a reply frame
that does not decode is read past, until one does within the timeout, else
RdisTimeout "P: no matching reply within T s". A primitive's `timeout D` is its
reply's, instead of the robot's (T in the messages is then D). The timeout is a
deadline for the whole reply, resynchronisation and skipped frames included.

Reply tables. `reply KEY { VALUE: unpack ... }`: the entry for the key
parameter's value decodes the reply and runs its post-actions (the range check
guarantees there is one). `reply tag "fmt" { VALUE: ... }`: the framed payload
starts with a tag (the payload's end found as the frame says: its length field or
the constant after it); its entry decodes the rest; an unknown tag is
RdisProtocolError "P: no reply entry for tag V".

Interface. Its calls in priority order (then as written); after each, sleep its
delay. Then, if it triggers an output, evaluate the output's fields over state
(in the adapter's field order) and deliver {"name": output, "contents": {...}}
to every output callback in registration order. An exception raised by a
callback is reported to the error callbacks as RdisCallbackError; delivery goes on.

Input. `call_input(name, **fields)`: exactly the adapter's fields (else
TypeError), evaluate the arguments, call the interface on the caller's thread.
Errors are raised to the caller.

Connection. Opened with pyserial's serial_for_url (any port or URL) at the
connection's baud, 8N1, reply timeout 1 s unless given; failure is
RdisConnectionError, as is any I/O error later. `connect` opens every connection,
runs the startup hooks in declaration order, then starts one thread per
connection. Each thread ticks at the connection's frequency: it runs the periodic
interfaces it owns (declaration order), then the keepalive when its interval has
passed (first one interval after start). Errors in that work go to the error
callbacks and the schedule goes on; waiting never spins. `close` (also on leaving
the context, on exceptions, SIGINT and SIGTERM in `rdisc run`) stops the threads,
runs the terminate hooks (errors reported, not raised) and closes the ports.

Details both implementations follow (where the above is silent):

- MAX_LINE is 4096 bytes. The pyserial write timeout equals the reply timeout; a
  write that cannot complete in it is RdisTimeout.
- Values given to an input or an interface: an `int` parameter or field takes an
  Integral that is not a bool, a `float` one any Real that is not a bool (made a
  float), `bool` a bool, `string` a str; anything else is a TypeError, raised
  before anything is written. A value assigned to state, a parameter or an output
  field is converted to its declared type the same way (int -> float only).
- Names: input arguments see state and the adapter's fields; a call's arguments
  see state and the interface's parameters; format arguments and post-actions see
  state and the primitive's parameters (plus `out`); hooks and output fields see
  state only. A parameter or field shadows a state variable of the same name.
  Every expression reads state as it is when evaluated: a call's arguments just
  before that call, an output's fields after the interface's last call.
- An error stops the interface where it happened: later calls are not made,
  nothing is delayed further, the output is not triggered; state already
  assigned stays.
- Error messages begin with the name of the element at fault and a colon: the
  primitive for I/O and encoding, the connection for RdisConnectionError, the
  input, interface or output whose expression failed for RdisValueError. The
  texts: "P: no reply within T s" (T formatted with :g), "P: expected N bytes,
  got K", "P: reply line not terminated: LINE", "P: reply LINE does not match
  PATTERN" (LINE, PATTERN with repr), "P: write not completed within T s",
  "C: cannot open PORT: ...", "C: ..." with the I/O error's text, "C: P: cannot
  set LINE = LEVEL: ..." for a modem line the port refuses, "O: output
  callback raised TYPE: ..." and "C: I/O callback raised TYPE: ..." for
  RdisCallbackError, "ROBOT: closed" for a call after `close`.
  Comparisons across implementations use the type and that first name.
- An unknown input, interface or primitive name is a KeyError; the wrong number
  of arguments to an interface or a primitive, or not exactly an input's fields,
  a TypeError. `call_primitive(name, *args)` sends one device command directly.
- Bytes given for a parameter: bytes, a bytearray, a list of ints 0..255, or hex
  text ("3c20"); anything else is a TypeError.
- Callbacks: on_output(cb) gets cb(output_dict), on_error(cb) gets cb(exception),
  on_io(cb) gets cb("write" | "read", connection, data) after each write and after
  each exchange that read bytes: every byte the port gave, whatever became of it
  (a short read, a frame refused, garbage skipped); and cb("lines", connection,
  b"dtr=False rts=True") after a primitive's `lines` are set, before its write.
  Callbacks run on the thread that did the work (the caller's for inputs, a
  connection's for periodic work and keepalives) and never concurrently with each
  other (one reentrant lock).
  An exception from an output or I/O callback becomes RdisCallbackError (cause
  set) reported to the error callbacks; one from an error callback is ignored.
  An error with no error callback registered is logged (logger "rdisc").
- Schedule: tick k of a connection is due at start + k / frequency; a tick that
  is already past when the previous one ends is skipped, never run in a burst.
  The keepalive is due at start + interval, then every interval after the due
  time it ran for (if that is past too, one interval after now). A connection
  with neither periodic interfaces nor a keepalive has a thread that only waits.
  A periodic interface belongs to the connection of its first call's primitive.
- `tick()` runs, on the caller's thread, one iteration of every connection's
  work in declaration order (periodic interfaces, then the keepalive if due),
  errors reported like the threads'. `connect(..., threads=False)` starts no
  threads, for a framework that calls `tick()` itself.
- Ports: one string is used for every connection (opened once and shared, with
  one lock per open port); a dict maps each connection name to its port; a
  value may also be an already-open pyserial-like object (write, read,
  read_until, reset_input_buffer), which is used as it is and not closed.
  A connection given no port (no port at all, or missing from the dict) opens
  its `address`; one without an address is a ValueError, as is an unknown name.
- `connect(port=None, timeout=1.0, threads=True, *, on_output=None, on_error=None,
  on_io=None, settings=None)` (a driver: a keyword per setting in place of `settings`): callbacks given there are registered before anything is opened,
  so they see the startup hooks' I/O and errors too.
- `connect` that fails (opening, or a startup hook) closes what it opened (as
  `close` does, terminate hooks included) and raises the error. `close` is
  idempotent; a call after it is RdisConnectionError. Stopping lets a thread
  finish the interface it is running, delays included.
- The command line (`rdisc run` and a generated driver's `__main__`): `--call
  NAME K=V ...` calls an input with its fields, else an interface, else a
  primitive, with its parameters by name, each value read as its parameter's
  type says: a string as written (`line=1234` is text), bytes as hex
  (`data=00080000`), an array as `[1,2,3]`, a number or True/False otherwise. An
  unknown name is answered with the nearest known one ("did you mean ...?").
  `--set NAME=VALUE` gives a setting, read the same way; one that does not fit is
  a usage error. Without `--port`, every connection opens its address.
  `--duration S` runs S seconds from the end of the startup hooks. `--watch`
  prints each output as `json.dumps(output_dict)` on stdout, one a line; `--trace`
  prints, after the monotonic seconds since the run started (four decimals),
  "0.1234 CONN > 89 00 c8 7f ff" (written), "0.1250 CONN < 00" (read) and
  "0.1201 CONN lines dtr=False" (modem lines set) on stderr; errors reported
  while running are printed on stderr as "rdisc run: TYPE: MESSAGE". Exit status: 0 done, 1 a description or device
  error, 2 a usage error, 130 after SIGINT, 143 after SIGTERM; the terminate
  hooks run in every case.
"""

from rdisc.engine import MAX_LINE, Robot
from rdisc.runtime.device import Description, load
from rdisc.runtime.errors import (
    RdisCallbackError,
    RdisConnectionError,
    RdisError,
    RdisLoadError,
    RdisProtocolError,
    RdisTimeout,
    RdisValueError,
)

__all__ = [
    "MAX_LINE",
    "Description",
    "RdisCallbackError",
    "RdisConnectionError",
    "RdisError",
    "RdisLoadError",
    "RdisProtocolError",
    "RdisTimeout",
    "RdisValueError",
    "Robot",
    "load",
]
