"""rdisc's runtime: interprets a checked Model against real devices.

The semantics below are defined once and implemented twice, here (interpreting
the Model) and in the drivers `rdisc emit-python` generates (compiled Python);
tests drive both with the same inputs and device replies and compare bytes,
outputs and errors.

Values. State starts at its initial values. Arguments are bound to parameters,
fields and state with ints widened to floats where a float is declared.

Primitive. (1) Evaluate the format arguments over state and parameters. (2) Encode:
`pack` with struct (strings as latin-1 bytes), `format` with str.format, then
latin-1. A value the encoding refuses (out of range for its code, a character
above U+00FF) is an RdisValueError. (3) Under the connection's lock: if a reply is
expected, discard unread input; write; read the reply. `unpack`: exactly
calcsize bytes; none within the timeout is RdisTimeout, fewer is
RdisProtocolError; strings decoded latin-1. `regex`: one line up to b"\\n" (at
most MAX_LINE bytes), "\\r\\n" or "\\n" stripped, matched with re.match from its
start; no line is RdisTimeout, a line without terminator or not matching is
RdisProtocolError; the groups are the values (an unmatched group is "").
(4) Post-actions: every value is computed from the same snapshot of state, then
all are assigned together. An expression that cannot be evaluated (division by
zero, ...) is an RdisValueError.

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
"""
