"""The registry of diagnostic codes: a stable id, a kebab-case name, an explanation.

Codes never change meaning once published; `rdisc explain CODE` prints the text.
E-codes are errors, W-codes warnings.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from dataclasses import dataclass
else:  # the same classes, their methods written out ahead of time: rdisc/frozen.py
    from rdisc.diagnostics.codes_methods import dataclass

from rdisc.frozen import Frozen


@dataclass(frozen=True, slots=True)
class Code(metaclass=Frozen):
    id: str
    name: str
    explanation: str


_TABLE = (
    # -- reading and parsing ------------------------------------------------
    ("E001", "syntax-error", """
The text does not follow the RDIS grammar at this point. The message says what
the parser expected instead. Clauses and declarations are recognised by their
keywords (`primitive`, `interface`, `on`, `pack`, `delay`, ...); a missing `}` or
`)` is reported where the parser first notices it, often at the next declaration.
Parsing resumes at the next top-level declaration, so later errors are reported too."""),
    ("E002", "invalid-token", """
A character that begins no token of the language, or a string literal that is
not closed on the same line. Strings are written in double quotes; a string
cannot span lines (write `\\n` for a newline)."""),
    ("E003", "invalid-escape", """
A backslash escape that RDIS strings do not know. Known escapes are `\\n`, `\\r`,
`\\t`, `\\0`, `\\\\`, `\\"`, `\\xHH` and `\\uHHHH`; `\\uD800` to `\\uDFFF` are halves of
surrogate pairs, not characters, and are refused. Regular expressions are easier to
write as raw strings, where backslashes are kept as written: r"(\\d+),(\\d+)".
A bytes literal has the same escapes but `\\uHHHH`, which is a character, not a byte.
Wrong: `b"caf\\u00e9"`. Right: `b"caf\\xc3\\xa9"`."""),
    ("E004", "invalid-literal", """
A number that cannot be read (a decimal integer with leading zeros, a misplaced
`_`), or one too large: integers are limited to 64 bits and a sign (at most
18446744073709551615, `0xFFFF_FFFF_FFFF_FFFF`, either way), in .rdis and JSON
alike, and floats must be finite. A bytes literal holds ASCII characters and
escapes: a character past ASCII has no single byte. Wrong: `b"°"`. Right:
`b"\\xc2\\xb0"` (its UTF-8), or `encode(...)` of an ASCII string."""),
    ("E005", "too-complex", """
Too much to read: an expression nested deeper than 100 levels, a line longer
than 65,536 characters, a declaration of more than 20,000 tokens, a description
of more than 200,000 tokens with its imports (`--max-tokens N` raises this
one), a file larger than 8 MiB, more than 256 imported files, or
transmissions whose conversions have more than 50,000 operations in all (each is sampled at 33 points of its joint's range).
Descriptions may come from devices and networks, so rdisc bounds the work any
input can cause before it reads it."""),
    ("E006", "unreadable-file", """
The file could not be read: it does not exist, is not readable, or is not UTF-8
text."""),
    ("E007", "import-not-found", """
An `import` names a file that does not exist, or one it may not read. Imports
are relative paths to `.rdis` files in the main description's folder or below
(a description may come from a device or a network, so it reads no other
files). `stdlib/adapters.rdis` is always available without import."""),
    ("E008", "invalid-json", """
A JSON description (`rdisc import`, or `rdisc build` of a .json file) is not
valid JSON, or does not have the shape of an RDIS description: the message says
which member is missing or has the wrong kind of value. A string escape `\\udXXX`
that is half of a surrogate pair without its other half is not a character, and
is refused too."""),
    # -- names ---------------------------------------------------------------
    ("E101", "duplicate-name", """
Two elements of the same kind have the same name. Names are unique per kind: a
primitive and an interface may share a name (the place of a reference decides
its kind), two primitives may not. A loop variable has a name of its own: not
that of a parameter, state variable, constant or outer loop's variable, which it
would hide. Both places are shown."""),
    ("E102", "unknown-element", """
A reference to an element that is not declared: a primitive or interface called
by an interface (a call names a primitive of that name, or else an interface), an
interface called by a hook or an input, an output triggered by an interface, a
connection, a frame, an adapter, a link joined by a joint or named by an output's
`frame` (`output detect_bump: Range frame bumper`: the body's link its data belongs
to, whose name its messages carry as their frame), a joint a transmission moves
and the state variable it measures, or an enum naming an error reply's `code`.
When a declared name is close, the help line suggests it."""),
    ("E103", "unknown-variable", """
A name used in an expression is not in scope there. Scopes follow the thesis:
state variables are readable everywhere except in initial values; primitives also
see their parameters, post-actions also see the reply `out` (and those of a
tagged reply's entries its tag, `tag`); interfaces see their parameters; inputs
see their adapter's fields; hook arguments and outputs see state variables only."""),
    ("E104", "reserved-name", """
The name is a keyword of the language or the name of a built-in function, and
cannot name an element, parameter, field or state variable (a link, joint or
transmission, which no expression reads, may take a function's name: `link upper`). A primitive whose
reply is chosen by its tag has no parameter named `tag`: its entries read the
tag by that name."""),
    ("E105", "unknown-type", """
Types are `int`, `float`, `bool`, `string` and `bytes`. An adapter field crosses
to a framework, which takes text and numbers, so it cannot be bytes. Wrong:
`adapter Firmware { name: bytes }`. Right: `adapter Firmware { name: string }`,
with the output giving it `ascii(firmware)` or `hex(firmware)`."""),
    ("E106", "unknown-function", """
Only the built-in functions can be called in expressions: abs, min, max, round,
int, float, bool, str, clamp, sqrt, sin, cos, atan2, hypot, len (of a string or
bytes), byte (`byte(data, i)`, the i-th byte of bytes as an int), hex (bytes as
lowercase hex digits), ascii (ASCII bytes as a string), encode (an ASCII string as
bytes), pack7 and unpack7 (Firmata's two 7-bit bytes per byte), bitset (an int with
bit a[i] set for each element of an int array), unhex (hex digits as bytes), upper
(a string or bytes in upper case), int_le and int_be (an int from up to 8 bytes),
f32le, f32be, f64le and f64be (a number as the bytes of a float) with from_f32le,
from_f32be, from_f64le and from_f64be (those bytes as a float), nibbles
(`nibbles(v, 4)`: an int spread 4 bits a byte) and from_nibbles (back). A lookup
table has one method, `TABLE.get(key, default)`. There is no way to reach Python's
own functions, attributes or modules."""),
    ("E107", "robot-declaration", """
A description has exactly one `robot` declaration, in its main file. Imported
files hold reusable declarations (adapters, primitives, ...) but no robot."""),
    ("E108", "invalid-ros-name", """
An adapter's `ros` annotations name a ROS message type and where each field lives
in it, and the generated ROS node writes them as Python code (an import and
attribute access), so only what ROS itself allows is accepted. The message type
is `package/Message`: the package in lower case (letters, digits, `_`), the
message starting with a capital. A field path is field names joined by `.`
(letters, digits and `_`, starting with a letter, not a Python keyword), each
optionally with a list item `[i]` up to [1023], and optionally a final `:yaw`
(a quaternion read or written as its yaw angle). Wrong: `ros "this/Bool"` with
`hit: bool ros "__class__.__init__"`. Right: `ros "std_msgs/Bool"` with
`hit: bool ros "data"`."""),
    ("E109", "unknown-unit", """
A parameter's `unit` is one of the units rdisc knows, each with what it
measures: m, cm, mm (a length); rad, deg (an angle); s, ms (a time); m/s, mm/s
(a linear velocity); rad/s, deg/s, rpm (an angular velocity); N (a force); N m,
mN m (a torque); A, mA (a current); V, mV (a voltage); % and count (no
dimension). Only a number, or an array of numbers, has a unit. The unit is not
converted: it documents the parameter and lets a transmission check that the
joint quantity it commands fits (E605). Wrong: `drive(speed: int unit "mm/sec")`.
Right: `drive(speed: int unit "mm/s")`."""),
    # -- structure -----------------------------------------------------------
    ("E201", "arity-mismatch", """
A call passes a different number of arguments than its target takes: an
interface calling a primitive or an interface, a hook calling an interface, an
input calling an interface, a primitive using a frame, or a built-in function.
Parameters with a default (`speed: int = 5`) may be left out."""),
    ("E202", "missing-clause", """
A required clause is missing: a primitive needs `on CONNECTION` and exactly one
of `pack` or `format`, unless it only sets modem lines (`lines dtr = on`): then it
writes no request, and so has no reply and no frame. A primitive that reads
several replies (`replies 6`) says how each is read: `unpack` or `regex`. Wrong:
`primitive read() on bus pack "B" (1) replies 6`. Right: `primitive read() on bus
pack "B" (1) replies 6 unpack "<BBh"`."""),
    ("E203", "conflicting-clause", """
Clauses that exclude each other, or a clause given twice: a primitive has exactly
one of `pack`/`format` and at most one of `unpack`/`regex`, and sets each modem
line once (`lines dtr = True, dtr = False` is refused); an interface is either
`periodic` or `adhoc`, and lists the outputs it triggers in one `triggers`
clause, each once; each attribute of a robot or connection is given once. A
primitive whose replies differ in shape (`replies { ... }`) gives each reply its
own decoding, `expect` and post-actions there, and none of the primitive's own.
Wrong: `primitive bulk() on bus pack "B" (0x92) unpack "<BB" replies { unpack "<BBi"
unpack "<BBB" }`. Right: `primitive bulk() on bus pack "B" (0x92) replies { unpack
"<BBi" { position = out[2] }  unpack "<BBB" { temperature = out[2] } }`."""),
    ("E204", "invalid-value", """
A setting outside its range: baud and frequency must be positive, a keepalive
interval positive, a delay zero or more, a reply-line `terminator` 1 to 8 bytes.
Settings must be constants. A parameter's range has constant bounds, low <= high,
of its type; a default is a constant, and the parameters after one with a default
have defaults too. A loop's range counts up: `for i in 5..0` is empty. A reply
count (`replies N`) is a constant int from 2 to 1024, and `replies { ... }` lists 2
to 1024 replies. Wrong: `replies { unpack "<BBi" }` (one reply: say it with `unpack`
alone). Right: `replies { unpack "<BBi"  unpack "<BBB" }`. A retry count (`retry N`)
is a constant int from 1 to 10, of a primitive that writes a request and reads a
reply: a resend needs both. Wrong: `primitive go() on link pack "B" (1) retry 2`.
Right: `primitive ping() on link pack "B" (1) unpack "B" retry 2`. A poll (`until
COND every P within T` on a call) has an interval P above zero and at most its
limit T, and makes at most 100000 calls (T / P + 1). Wrong: `status() until done
every 2 s within 1 s`. Right: `status() until done every 10 ms within 2 s`."""),
    ("E205", "periodic-with-parameters", """
A periodic interface runs on every tick of its connection's thread, where nobody
supplies arguments, so it cannot take parameters."""),
    ("E206", "output-fields", """
An output defines each field of its adapter exactly once: a missing field, a
field defined twice, or a field the adapter does not have is an error."""),
    ("E207", "state-write", """
Only post-actions write state, and they write state variables only: the target
of an assignment in a primitive's `{ ... }` block must be a state variable, not a
parameter, and not a `setting`, which is given when connecting and read-only.
Wrong: `setting ID: int = 1` with `{ ID = out[0] }`. Right: `state id: int` with
`{ id = out[0] }`."""),
    ("E208", "periodic-connection", """
A periodic interface runs on the thread of a connection: the one its primitives
use. It must call primitives of exactly one connection (or the description must
have a single connection)."""),
    ("E209", "unsupported-kind", """
The connection kind or threading model is not supported. Connections are
`serial` (a serial port, or any pyserial URL) or `tcp` (a `socket://host:port`
address); threading is `single` (a tick holds the port: a command waits for the
whole tick), `dual` (the periodic thread holds the port for one exchange at a time:
a command waits for at most the exchange in flight) or `multiple` (a thread for each
periodic interface, each at its own rate)."""),
    ("E210", "interface-cycle", """
An interface may call other interfaces (a call names a primitive of that name, or
else an interface), but the calls must not lead back to the interface that makes
them: a cycle would never end, and neither the link budget nor the worst-case time
of a call could be known. Break the cycle: move the shared calls into an interface
that both call."""),
    ("E211", "modem-lines", """
A primitive's `lines` clause sets the modem lines of a serial port, `dtr` and `rts`,
to bools before its request is written (True asserts the line, as in pyserial: an
RPLIDAR A1's motor runs while DTR is cleared, an Arduino resets on a DTR pulse).
Those two are the only lines a primitive sets; it may also send a break, `break 10 ms`
among them (TX held low that long, as pyserial's `send_break`: a LIN or DMX frame's
start, a device woken or reset), held more than 0 and at most 10000 ms. Only a
`serial` connection has them: a `tcp` connection carries bytes alone. Wrong:
`connection net: tcp { address "socket://10.0.0.2:4000" }` with
`primitive motor(on: bool) on net lines dtr = not on`, `lines cts = True`, or
`lines break 0 ms`. Right: `connection link: serial { baud 115200 }` with
`primitive motor(on: bool) on link lines dtr = not on`, or
`primitive wake() on link lines break 10 ms pack "B" (0x55)`."""),
    ("E212", "loop", """
A loop in an interface's body, `for NAME in LOW..HIGH { ... }` (both ends included)
or `for NAME in ARRAY { ... }`, runs a number of rounds known when the description
is checked, so the link budget and the time of a call stay known: the checker
writes the loop out as its calls. Its bounds are constant ints and its array a
constant array (a `const` or a literal); an array parameter or state array is
read by its indexes, whose count its type fixes. A loop makes calls, and an
interface's loops write out at most 4096 of them (65536 for all interfaces).
Wrong: `interface all(n: int) { for i in 0..n { torque(i, True) } }`. Right:
`const IDS = [1, 2, 3]` with `interface all() { for id in IDS { torque(id, True) } }`,
or `interface move(p: int[3]) { for i in 0..2 { goal(IDS[i], p[i]) } }`. A
primitive's `replies id in IDS frame status(id)` goes over the same, a reply a
value, or over an array parameter of the primitive, a reply an element, as many as
the caller gives (`primitive read(ids: int[]) ... replies id in ids frame
status(id)`); not over a state array, known only when it runs: pass it as a
parameter."""),
    ("E213", "connect-setting", """
A `setting` is a value given when connecting (`rdisc run --set BAUD=1000000`, a
driver's `connect(port, BAUD=1000000)`, a ROS node's `_BAUD:=1000000`), such as a
bus's baud rate, a servo's ID or a wheel base. It has a default, which holds when
none is given and which the checks and the link budget use. It is read where state
is read (arguments, format values, conditions, post-actions, outputs, inputs), but
not where a constant is needed (an array's size, a range, a delay, a timeout, a
frequency, a constant), since its value is not known then; a connection's `baud`
may be an int setting, and the body's sizes, places and limits number settings (the
body is built with the value given: `rdisc emit-urdf --set TRACK=0.3`), never a bool or
string one. A frame's own expressions read only its parameters, as it is
checked once for every primitive that names it: give the frame a parameter and pass
the setting where a primitive names it (`frame dxl(id: int)` with `field id "B" = id`,
then `frame dxl(SERVO_ID)`). Wrong: `setting BAUD: int` (no default), `delay WAIT ms`,
`setting RATE: float = 57600.0` with `baud RATE`. Right:
`setting BAUD: int in 9600..1000000 = 57600` with `baud BAUD`, and
`setting WAIT: int = 20` read as `pack "BH" (0x05, WAIT)`."""),
    ("E214", "dependent-range", """
A range may depend on the parameters before it: `channel: int in 0..count - 1`,
`length: int in 0..MAX - offset`. Each bound is then a sum of constants and earlier
int parameters that have ranges, each added or taken away; the value is checked at
each call against the bounds those parameters give (`RdisValueError`, nothing
written), and the widest range they can give is what the checks and the link budget
use. Only an int parameter (or an int array, each element) has such a range. Wrong:
`count: int, channel: int in 0..count - 1` (`count` has no range), `channel: int in
0..count * 2` (another operator), `data: bytes in 0..count`. Right: `count: int in
1..8, channel: int in 0..count - 1`."""),
    ("E215", "serial-line", """
A serial connection's character is 8 data bits, no parity and 1 stop bit (8N1) unless
its declaration says otherwise: `databits 5` to `8`, `parity none`, `even`, `odd`,
`mark` or `space`, `stopbits 1`, `1.5` or `2`, each a constant and each given once (E203 for a repeat).
The port opens with them (pyserial's `bytesize`, `parity` and `stopbits`), and the link
budget counts each byte's bits with them (a start bit, the data bits, a parity bit,
the stop bits). A UART sends 1.5 stop bits only after 5 data bits. A `tcp` connection
carries bytes alone, with no serial line to set. Wrong: `connection bus: serial {
parity evn }`, `stopbits 3`, `databits 9`, `databits 8 stopbits 1.5`, or
`connection net: tcp { address "socket://10.0.0.2:502" parity even }`. Right: S.BUS's
`connection sbus: serial { baud 100000 parity even stopbits 2 }`, or Modbus RTU's
`connection bus: serial { baud 19200 parity even }`."""),
    ("E230", "sensor", """
A `sensor NAME: TYPE from PRIMITIVE() cache N ms` holds the one value its primitive's
reply decodes, and keeps it for the cache time: a reader within that time gets the kept
value and sends nothing; a reader after it makes the primitive's exchange again. So the
primitive takes no parameters, and its reply is one value read as it is (`unpack "B"`,
not a reply table, listed or repeated replies, records, or a repeated group); that
value's type flows into the sensor's (E401, E402 otherwise). The cache time is a
positive constant: a time of 0 would read on every use, which a primitive call already
does. An unknown primitive is E102. Wrong: `sensor bumps: int from bumpers() cache 0 ms`,
or a `bumpers(packet: int)` with a parameter. Right: `primitive bumpers() on oi pack "BB"
(142, 7) unpack "B"` and `sensor bumps: int from bumpers() cache 100 ms`."""),
    # -- message formats -------------------------------------------------------
    ("E301", "invalid-pack-format", """
`pack` and `unpack` take Python struct format strings: an optional byte order
(`<`, `>`, `!`, `=`, `@`) then codes such as `B` (unsigned byte), `h` (signed
16-bit), `f` (float), with optional repeat counts, and a final `*` for the rest of
the message as bytes. Pointer codes (`P`) are not allowed. A group of int, float
and bool codes repeats `N(BH)` N times (1 to 4096), or as many times as the message
says: `#(BH)`, counted by one unsigned count field `#B` (or `#H`, ...) before it,
or `*(BH)`, until the message ends, last. One such group a message, with a byte
order (`<`, `>` or `!`). An unsigned integer code (`B`, `H`, `I`, `L`, `Q`, without
a count, outside groups) may be split into two bit fields or more, from its lowest bit
up, whose widths add up to its bits: `B{1,1,6}`, one value each; `Ns{...}` splits
the integer N bytes hold in the format's byte order (`<` or `>`), into one field or
more of 1 to 64 bits (`<22s{11*16}`: sixteen fields of 11 bits; `>3s{24}`: a 3-byte
integer). In a request's groups, `%` is an unsigned integer of as many bytes (1 to 8)
as one width field `%B` (or `%H`, ...) before the groups states, in the format's
byte order (`<` or `>`): Dynamixel's sync write of N bytes a servo is `pack
"<BH%H*(B%)"`; a reply reads such bytes as a `*` rest. Wrong: `unpack "<B#(BH)"` (no
count field), `unpack "<*(BH)B"` (not last), `unpack "<B{1,6}"` (7 of 8 bits), `pack
"<h{8,8}"` (signed), `pack "22s{11*16}"` (no byte order), `pack "<B*(B%)"` (no width
field). Right: `unpack "<#B#(BH)B"`, `unpack "<B*(BH)"`, `unpack "<B{1,1,6}H{1,15}H"`,
`pack "<B22s{11*16}BB"`, `pack "<BH%H*(B%)"`."""),
    ("E302", "format-argument-count", """
The number of format arguments differs from the number of values the `pack` or
`format` string takes. `pack ">Bhh"` takes three values; `format "D,{},{}"` two."""),
    ("E303", "invalid-format-string", """
`format` takes a PEP 3101 format string whose fields are positional: `{}` or
`{0}`, with an optional format spec (`{:04d}`). Named fields, attribute or index
access (`{0.x}`, `{0[1]}`), conversions (`!r`) and nested fields are refused:
they would reach into Python objects."""),
    ("E304", "invalid-regex", """
The `regex` does not compile as a Python regular expression, or it has a shape
that can make Python's backtracking matcher take far more than linear time on a
bad reply line (a device can send one): two parts of variable length in a row
that can match the same characters (`\\s*\\s*`, `\\d+\\.?\\d*`), or a repeated
part whose rounds can share characters (`(a+)+`, `(?:a{0,64}){0,64}`, `(a|aa)*`).
Put a character that neither part matches between them (`(\\d+),(\\d+)` is fine),
or make the first part possessive (`\\d++`) or atomic (`(?>...)`), so that it
never gives characters back."""),
    ("E305", "reply-index", """
`out[i]` reads value i of the reply: it must be a constant within the number of
values the `unpack` format produces or the number of groups the `regex` has, and
the primitive must read a reply at all."""),
    # -- types ---------------------------------------------------------------
    ("E401", "type-mismatch", """
A value of one type is used where another is required, for example a string
passed to an integer parameter or assigned to a float state variable. An `int`
is accepted where a `float` is expected."""),
    ("E402", "float-to-int", """
A float flows into an integer: an `int` parameter, an integer pack code or an
`int` state variable. Say how to convert it, usually with `round(...)` (nearest)
or `int(...)` (towards zero)."""),
    ("E403", "value-out-of-range", """
A constant cannot be represented where it goes: 300 does not fit pack code `B`
(0..255), -1 does not fit `H` (0..65535), "ABCDE" does not fit `4s`, 1e39 does
not fit `f`; a constant argument is outside its parameter's range (a primitive's
or a frame's: `frame dxl(id: int in 0..254)` refuses `dxl(300)`; bytes by their
length: `data: bytes in 1..16` refuses `b""`); a frame field
computed from constant arguments does not fit its code; the arrays of a group
repeated as the message says have sizes that differ, or more values than its
count field holds (`#B` counts to 255: an `int[300]` needs `#H`). At run time the
same is an `RdisValueError`, raised before anything is written."""),
    ("E404", "invalid-operation", """
The operator or function does not apply to these types: arithmetic needs
numbers (`+` also joins two strings or two bytes), bitwise operators and shifts
need integers, `and`/`or`/`not` and the condition of `x if c else y` need
booleans, `hex`, `ascii`, `pack7`, `unpack7`, `from_nibbles` and `from_f32le` (and
the other floats from bytes) take bytes, `encode` and `unhex` a string, `upper` a
string or bytes, `f32le` (and the others) a number, `int_le` and `int_be` bytes and
an optional `True` for signed, `nibbles` an int and a count of nibbles; `key in
TABLE` and `TABLE.get(key, default)` need a lookup table (`const HEALTH = { 0: "ok" }`),
not an array or a name of anything else.
Wrong: `b"\\x01" + "a"`. Right: `b"\\x01" + encode("a")`."""),
    ("E405", "evaluation-error", """
A constant expression cannot be evaluated: a division by zero, a power, shift or
product whose result would pass 4096 bits, a float result too large for a float,
a string or bytes longer than 1 MiB, `ascii` of bytes or `encode` of a string that
is not ASCII, `unpack7` of bytes that are not pairs of 7-bit bytes, `unhex` of
anything but an even number of hex digits, `int_le` or `int_be` of more than 8
bytes, `from_f32le` of bytes not 4 long (8 for `from_f64le`), a number too large
for `f32le`, `nibbles(v, n)` of a v that does not fit in n nibbles (n from 1 to 16)
or `from_nibbles` of a byte past 0x0f; or the value of a constant or a state variable does not fit the integers rdisc
keeps: 64 bits and a sign. (Inside an expression a result may pass 64 bits, as
`2 ** 64 - 1` does on its way; what is kept may not.) Wrong: `const MASK = 1 << 64`.
Right: `const MASK = (1 << 64) - 1`."""),
    # -- frames ----------------------------------------------------------------
    ("E501", "frame-structure", """
A frame is a sequence of parts: `header`, `literal` and `terminator` bytes,
`field`s, one `length` (or two: a packet's length and its sub-payload's, each
stating the payload with its own adjustment, neither in a `bits`), one `payload`
and `checksum`s, either one sequence for both directions or a `request { }` and a
`reply { }`. A request frame has exactly one payload, a header comes first and a
terminator last, and constant bytes are 1 to 64 bytes (characters up to \\xff)."""),
    ("E502", "checksum", """
A checksum names its algorithm: "sum", "xor", "lrc" (the two's complement of the
sum, Modbus ASCII's), "fletcher8" (UBX's CK_A, CK_B: 16 bits, CK_A the low byte),
"crc" with its `poly` (and `init`, `xorout`, `width`, and `reflect`, or `reflect
in` or `reflect out` for one way only), or a catalogue CRC such as "crc8",
"crc7-mmc", "crc16-xmodem", "crc16-modbus", "crc24-lte-a" (RTCM 3's CRC-24Q),
"crc32", "crc64-xz". A sum, an XOR or an LRC is 1 to 32 bits
wide, a CRC 1 to 64, and a CRC's `poly`, `init` and `xorout` fit its width (the
polynomial without its top bit, as the CRC catalogue writes it: 0x864CFB, not
0x1864CFB). A `mask` (the bits of the checksum that are kept) is at most 64 bits.
The width must fit the struct format, which holds one unsigned integer, or be
written as `hex` digits. `over A .. B` names the parts it covers
(`request` first covers the request as sent, in a reply); they come before the checksum."""),
    ("E503", "length-field", """
A length field holds the payload's size plus a constant, in a struct format of
one unsigned integer. It must be able to hold the largest payload of every
primitive that uses the frame (for a `*` rest of a `bytes` parameter, every
length its range allows; for a group repeated as the message says, its arrays'
size, its count field's largest value or 1024 rounds), and the frame's reply must
let the reader find the end of the payload: a length field, a size fixed by the
decoding, or constant bytes right after the payload. A reply that ends in `*` or
repeats a group as the message says (`#(BH)`, `*(BH)`) is read through such a
frame. Wrong: `unpack "<B*(BH)"` without a frame. Right: the same with
`frame f()` whose reply has a `length` field. A side whose `payload trimmed` drops
its trailing zero bytes (MAVLink 2) has a length field, the only way a reader knows
how many bytes were kept: `header "\\xFD"  length "B" = payload  ...  payload
trimmed`."""),
    ("E504", "frame-use", """
A primitive's `frame NAME(args)` passes one argument per frame parameter. A
primitive that decodes a reply needs a frame whose reply has a payload; a frame
field's value must fit its format. `skip unmatched` (read past frames that do not
decode: other traffic on a shared line) needs a framed reply to decode, or a
tagged reply read without a frame (it reads past tags without an entry). A reply
of `replies { ... }` read through a frame of its own needs one whose reply side
has a payload. Wrong: `replies { frame quiet() unpack "<h" ... }` where `frame
quiet { request { payload } }` answers nothing. Right: `replies { frame status(1)
unpack "<h" ... }` where `status` has `reply { header "\\xFE" field id "B" = id
payload }`."""),
    ("E506", "optional-part", """
`optional { ... }` holds parts a reply may lack, all together: NMEA's `*hh`
checksum, which some talkers leave out. It comes right after the payload, starts
with constant bytes (a `literal`) and is followed by constant bytes (a `literal`
or the `terminator`) that start with another byte, so that a reader sees by one
byte whether the optional parts came; when they did, each is checked. Inside it:
literals, fields and checksums, not a `payload`, `length`, `header`,
`terminator`, `optional` or `either`. A request writes the optional parts always,
so `optional` belongs in a frame written once for both directions or in its
`reply { }`, not in `request { }`. One `optional` per layout. Wrong:
`header "$" payload optional { checksum "xor" hex } terminator "\\r\\n"`.
Right: `header "$" payload optional { literal "*" checksum "xor" hex over payload }
terminator "\\r\\n"`."""),
    ("E507", "frame-alternatives", """
`either { ... } or { ... }` gives a side of a frame several layouts, each the
parts around it with one alternative in their place: VESC's `02 LEN` for a payload
up to 255 bytes and `03 LEN LEN` for a longer one. A request is written with the
first alternative whose length field can state the payload, so every alternative
but the last needs a length field (one without takes every payload, and those
after it would never be written). A reply is read by its header: each
alternative read as a reply starts with a `header` of its own, none the end of
another's, and they all have a payload or none do. One `either` per side, not
inside another `either` or an `optional`. Wrong: `either { payload } or
{ header "\\x03" length ">H" = payload payload }`. Right: `either { header
"\\x02" length "B" = payload } or { header "\\x03" length ">H" = payload }
payload checksum "crc16-xmodem" ">H" over payload terminator "\\x03"`."""),
    ("E508", "bit-fields", """
`bits FORMAT { ... }` splits one unsigned integer of a struct format (`"B"`,
`"<H"`, `"<I"`, `"<Q"`) into fields, from its lowest bit up: `field NAME: WIDTH =
expr` (a value over the frame's parameters, checked in a reply like a `field`) and
at most one `length: WIDTH = payload + N` (the frame's one length, which must state
every payload as a `length` part must, E503). The widths, each 1 bit or more, add
up to the integer's bits exactly: a reserved bit is a field too (`field reserved:
1 = 0`). A constant that does not fit its width is E403. RPLIDAR's response
descriptor keeps a 30-bit length under a 2-bit send mode in one little-endian u32.
Wrong: `bits "<I" { length: 30 = payload }` (2 bits unsaid). Right: `bits "<I" {
length: 30 = payload  field mode: 2 = mode }`."""),
    ("E510", "escaping", """
`escape ESC xor MASK for "BYTES"` (HDLC, PPP: `escape "\\x7D" xor 0x20 for
"\\x7E\\x7D"`) or `escape ESC { "BYTE": "CODE", ... }` (SLIP: `escape "\\xDB" {
"\\xC0": "\\xDC", "\\xDB": "\\xDD" }`) sends each listed byte between a frame's
flags as the escape and its code. The escape, each byte and each code are one
byte; a byte is listed once and no two share a code; the escape is escaped itself
(else the same byte in the data would read as an escape) and no code is an
escaped byte (a code follows the escape as it is). A reader finds a packet's end
at its terminator, so each side of the frame ends with a `terminator` whose first
byte is escaped and is not the escape; the packet is then unescaped and taken
apart by the sizes of its parts, so the frame has no `optional` and no `either`,
and it is not also stuffed (`stuff`). Wrong: `frame slip { payload terminator
"\\xC0"  escape "\\xDB" { "\\xC0": "\\xDC" } }` (a DB in the data reads as an
escape). Right: `frame slip { payload terminator "\\xC0"  escape "\\xDB" {
"\\xC0": "\\xDC", "\\xDB": "\\xDD" } }`."""),
    ("E513", "layout-condition", """
`either when COND { ... } or when COND { ... } or { ... }` in a frame's `request
{ }` or `reply { }` chooses that side's layout by conditions over the frame's
parameters (a setting passed as the frame's argument picks the framing): the
first alternative whose condition holds is the one written or read, a plain last
alternative when none does (with none, a call where no condition holds is a value
error, before anything is sent). Each COND is a bool. Only the last alternative
may go without `when`: alternatives chosen by a payload's size (a request) or by
their header (a reply) and by a condition are not mixed. A reply's layout is the
device's configuration, known when connecting: the argument of each parameter a
reply's `when` reads is a setting or a constant, not a primitive's parameter or
state. One condition cannot choose for both directions, so `when` is refused in a
frame's parts written for both. Wrong: `request { either { payload } or when
mode == 1 { header "\\xAA" payload } }`. Right: `request { either when mode == 1 {
header "\\xAA" payload } or { payload } }`, and `reply { either when crc { payload
checksum "crc" "B" width 7 poly 0x09 reflect over payload } or { payload } }`."""),
    ("E512", "checksum-seed", """
`seed TABLE[FIELD]` on a checksum sums one more byte after the bytes it covers and
never sends it: the value a lookup table holds for the value of a `field` of the
same side (MAVLink 2's CRC_EXTRA, a byte per message id, makes a reader that knows
another version of a message refuse it). TABLE is a lookup table declared with
`const`, keyed by integers, each of its values a byte (0 to 255); FIELD names a
`field` of the side the checksum is on (a reply is checked with the seed of its
own field's value). A field's value the table lacks is an `RdisValueError` when
a request is framed. Wrong: `checksum "crc16-mcrf4xx" "<H" seed EXTRAS[id]` with
`const EXTRAS = { 0: 300 }`. Right: `const EXTRAS = { 0: 50, 23: 168 }` and a
`field id "<H" = id` in the frame."""),
    ("E505", "reply-table", """
A reply table (`reply KEY { VALUE: unpack ... }`) chooses a primitive's reply by
the value of one of its int parameters, so that parameter needs a range
(`KEY: int in LOW..HIGH`) and every value in it needs its entry: a value without
one would send a request whose reply rdisc cannot read. An entry is for one value
or a range of them (`0..3: unpack "B"`); a table holds at most 4096 values.

A tagged reply (`reply tag "B" { ... }`) is chosen by the integer at its start,
whose struct format is one integer code. Read through a frame, the frame must say
where the reply ends. Read without one (Firmata's stream, where the first byte
says what follows), the entry the tag chooses says how many bytes follow it, so
each entry has a fixed size: an `unpack` without `*`, not a `regex`, unless it is
read to an end marker: `until "\\xF7"` (1 to 8 bytes, only in such a table) reads to
those bytes, drops them and decodes the rest with an `unpack` ending in `*`.
Wrong: `0xF0: unpack "B*"`. Right: `0xE0..0xEF: unpack "BB" { pin = tag & 0x0F }`,
two bytes after any tag from 0xE0 to 0xEF, whose value the entry reads as `tag`;
`0xF0: unpack "B*" until "\\xF7"`, a Firmata sysex message.

An entry of such a table may be a table of its own, chosen by the tag after its
own (`0xF0: tag "B" { 0x79: unpack "BB*" until "\\xF7" }`, Firmata's sysex
sub-commands): it is for one value, one level deep, and only in a tagged reply
read without a frame. Wrong: `0xF0..0xF1: tag "B" { ... }`.

A reply of sub-payloads (`reply each tag "B" length "B" { ... }`, Kobuki's feedback)
is read through a frame that says where its payload ends, as the sub-payloads run
to that end. Each entry decodes bytes with an `unpack`, not a `regex`. Without
`length`, the entry's size says where the next tag starts, so it is fixed (no `*`);
with it, the length is one unsigned integer that can state the entry's size.
Wrong: `reply each tag "B" { 1: unpack "B*" }`. Right: `reply each tag "B" length
"B" { 0x04: unpack "<hh3x" { angle = out[0] } }`, through `frame packet`."""),
    ("E509", "reply-records", """
`reply each until "\\x7F"` reads a reply's payload as records, each ended by its
marker (Firmata's capability report: for each pin its mode and resolution pairs,
then 7F). The marker is 1 to 8 constant bytes, and a record ends where the marker
first comes. Each record is decoded by the primitive's one `unpack` (not a `regex`:
records are bytes), typically ending in a group `<*(...)`, and the post-actions run
once per record, in order, reading its position from 0 as `index`. The records run
to the payload's end, so the reply is read through a frame that says where that
is; and the primitive reads one reply, so not with `replies` or a reply table.
Wrong: `primitive caps() on link pack "B" (0x6B) reply each until "\\x7F" unpack
"<*(BB)"`, no frame. Right: the same with `frame capability`, a frame whose reply is
`header "\\xF0\\x6C" payload terminator "\\xF7"`."""),
    ("E511", "error-reply", """
`error ...` is the reply a device may send instead of the one asked for (a Modbus
exception: the function code with 0x80 set, then an exception code; a NACK byte),
raised as an `RdisDeviceError` carrying the device's code and its name. The reader
must tell it from the reply before reading either, so it is known by its own frame
(`error frame rtu(unit, 0x83) unpack "B" code Exception`: a field the reply's frame
has otherwise) or by the bytes it starts with (`error "\\x15" unpack "B"`); known by
its first bytes inside the primitive's frame, that frame says where a payload ends
without its decoding (a `length` field or constant bytes after it), and read without a
frame its size is fixed (no `*`). It is decoded with `unpack`; with `code ENUM`, its
first value is the device's code, an int, named by the enum's member of that value.
It stands in for one reply: a primitive decoding one reply with `unpack`, or through a
frame, not a `regex` line, `replies` or a reply table. Wrong: `primitive ack() on link
pack "B" (1) unpack "B" error unpack "B"` (which is it?). Right: `primitive ack() on
link pack "B" (1) unpack "B" error "\\x15" unpack "B" code Nack`. A device whose every
reply carries a status (a TMCL module's: below 100, a refusal) says no in the reply
itself: `error when COND [code ENUM]` takes the reply decoded by the primitive's own
`unpack` as the device's error when COND, a bool over `out`, holds, its first value the
code (an int when `code` names it): `unpack ">BBi" error when out[0] < 100 code Status`."""),
    # -- the body -------------------------------------------------------------
    ("E601", "body-tree", """
A robot's body is one tree of links: one root (the base, the child of no joint),
every other link the child of exactly one joint, every link reachable from the
root, no cycle, no joint joining a link to itself. Tools reading URDF silently drop
links they cannot reach, so rdisc refuses them before any tool sees them. Only the
root meets the world, so only it may say `spawn floating` or `spawn fixed` (no
other word). Wrong: `joint a: fixed base -> arm {}` with `joint b: revolute hand ->
arm {...}` (two parents). Right: `joint b: revolute arm -> hand {...}`."""),
    ("E602", "body-shape", """
A link's `visual` and `collision` shapes are `box(x, y, z)` (full lengths),
`cylinder(radius, length)` (along its z axis), `sphere(radius)` or
`mesh("file.stl")` / `mesh("file.stl", scale)`, in metres, every size a constant
number more than 0 and at most 10,000 m (a mesh's path printable characters, as URDF and SDF carry it); a shape is placed by `at [x, y, z]` and `rpy [roll, pitch,
yaw]` in its link's frame. Vectors are three constant numbers in brackets. Wrong:
`visual cylinder(0.1) at (0, 0, 1)`. Right: `visual cylinder(0.1, 0.05) at [0, 0, 1]`."""),
    ("E603", "joint", """
A joint is `joint NAME: KIND PARENT -> CHILD { ... }` with KIND `fixed`,
`revolute`, `continuous` or `prismatic`. `at` and `rpy` place the child's frame in
the parent's; `axis` (not zero) is what it turns about or slides along;
`limit LOW..HIGH` (LOW < HIGH) bounds a revolute or prismatic joint's position,
and those two also need `velocity` and `effort` (more than 0; URDF requires
them); a continuous joint has no `limit`; a fixed joint has only `at` and `rpy`;
`damping` and `friction` are 0 or more. `mimic JOINT multiplier M offset O` makes
a moving joint follow another (M times its position, plus O; M not 0): the one it
follows is another moving joint of the body that mimics none itself. Wrong: `joint
j: revolute a -> b { axis [0, 0, 0] }`. Right: `joint j: revolute a -> b { axis [0,
0, 1]  limit -1.5..1.5  velocity 2  effort 1 }`."""),
    ("E604", "inertial", """
A link's inertial is its `mass` (kg, more than 0), its `centre` of mass (m, in the
link's frame; the link's origin when not given) and its `inertia` about that
centre (kg m²): `[ixx, iyy, izz]`, or `[ixx, iyy, izz, ixy, ixz, iyz]`. Mass and
inertia come together. The tensor must be physical: positive definite, and its
principal moments meet the triangle inequality (none larger than the other two
together). Wrong: `mass 1  inertia [0.1, 0.1, 0.3]`. Right: `mass 1  inertia [0.1,
0.1, 0.15]`. A simulator integrates a mass of at most 1,000,000 kg and an inertia
whose elements are at most 1,000,000 kg m²; larger (a mass of 1e308) is refused here
rather than met as a simulation that never ends."""),
    ("E605", "transmission", """
A transmission binds a moving joint to the device: `command QUANTITY to
TARGET.PARAM { ... }` names a numeric parameter of a primitive or interface that
sets the joint's `position`, `velocity` or `effort`; `measure QUANTITY from STATE
{ ... }` names a numeric state variable that the device's replies set (an array's
element as `[i]`, a constant index). Each says both conversions: `raw = ...`, the
device's value from the quantity, and `QUANTITY = ...`, the quantity from `raw`;
they read only their variable and constants, and `raw` has the device's type (an
int is written with `round(...)`). A commanded parameter's unit must carry the
quantity: a position an angle or a length, a velocity an angular or a linear
velocity, an effort a torque, a force or a current, and `count` or `%` any of them
(the conversion may turn a wheel's rad/s into mm/s). Wrong: `command velocity to
drive.speed { raw = velocity * 1000 }`, or a position to `speed: int unit "mm/s"`.
Right: `command velocity to drive.speed { raw = round(velocity * 1000)  velocity =
raw / 1000 }`."""),
    ("E606", "body-device-agreement", """
The body and the device must agree. Every value of a joint's range (its `limit`
for a position, -velocity..velocity, -effort..effort), converted by `raw = ...`,
must be a finite number in the range the commanded parameter accepts (`goal: int
in 0..4095`), and converting it must not fail (no division by zero);
and the two conversions must undo each other: a device value converted to the
joint and back is itself, to one step of an int. Both are checked at 33 points of
the joint's range with the interpreter the runtime uses; the range is then checked
whole by interval arithmetic over `raw = ...` (bounds of `+ - * /`, `round`, `min`,
`max`, `clamp`, `abs` and `if`/`else` over comparisons), and where its bounds leave the
device's range, the joint's values there are halved down until one that truly
converts outside is found (reported "between the 33 values sampled"); a conversion
with another operator is checked at its samples only. Wrong: a servo's `goal:
int in 0..1023` with `limit -3.2..3.2` through `raw = round(position * 195.3) +
512`. Right: `limit -2.6..2.6`."""),
    ("E607", "portable-names", """
Every name of the body is one that every model format carries as written, so that
URDF, SDF, MJCF, ros2_control and the ROS JointState name each joint alike. SDF
(and so Gazebo, `ign sdf -k`) gives links and joints one namespace: a joint never
takes a link's name. SDF also keeps `world` for itself (and `__...__`, which no
RDIS name can be), so neither a link nor a joint is named `world`. Wrong: `link shoulder { ... }`
beside `joint shoulder: revolute shoulder -> upper_arm { ... }`. Right: `link
turret { ... }` and `joint shoulder: revolute turret -> upper_arm { ... }`."""),
    ("E611", "massless-moving-link", """
Every link a moving joint (revolute, continuous, prismatic) carries has its own
`mass` and `inertia`: a simulator cannot move a body with none, and the tools
reading the URDF do not say so (libsdformat silently gives such a link 1 kg, and
`ign sdf -p` drops it from the SDF). A link fixed to the base, or fixed below a
moving link that has a mass, may go without. Wrong: `link arm { visual box(0.1,
0.1, 0.3) }` moved by `joint lift: revolute base -> arm { ... }`. Right: `link arm
{ visual box(0.1, 0.1, 0.3)  mass 0.2  inertia [0.0016, 0.0016, 0.0003] }`."""),
    ("E612", "drive-direction", """
A differential drive's body must move the way the input that drives it commands
(both halves together; no URDF tool can see this). For an input of a Twist
(`DifferentialSpeed`) and a body whose velocity transmissions turn two wheels
(continuous or revolute joints, fixed to the base, each child with a cylinder or
sphere), the checker evaluates the input's arguments, the interface's calls and the
transmissions' `velocity = ...` conversions for a forward command (linear 0.1 m/s)
and a counter-clockwise one (angular 0.5 rad/s), and rolls each wheel on the floor
below it about its joint's axis (in the base's frame, through the joints' `rpy`). A
forward command must roll both wheels forward (+x), and a positive angular command
must turn the base counter-clockwise seen from above (+z). Nothing is simulated.
Wrong: a right wheel with `axis [0, -1, 0]` beside a left one with `axis [0, 1, 0]`,
both commanded by the same conversion (the base spins in place). Right: `axis [0, 1,
0]` on both, or the right one's conversion negated."""),
    ("E613", "drive-scale", """
A differential drive's body must move at the speed its input commands: a forward
command of 0.1 m/s, evaluated through the input, the interface and the
transmissions' conversions as for E612, must move the base at 0.1 m/s (within 5%, the
device's steps) when its wheels roll at their shapes' radius, without turning it; and
a counter-clockwise command of 0.5 rad/s must turn it at 0.5 rad/s about the wheels'
places (their joints' `at`). So the wheel radius and the wheel base the conversions
and the input use are the body's: where they differ, a ROS odometry computed with the
same constants says one distance while the base travels another. The odometry is
held to the body too: an `Odometry` output whose pose a primitive's post-actions
integrate from the two wheels' encoders (each measured by a `measure position`
transmission, stored as `ENCODER = out[i]`) is stepped twice, as two replies would
step it, and must move as the body's wheels roll for those counts: 100 counts of each
wheel forward, then of the right forward and the left back, within 5% of the roll.
Wrong: `const R = 0.036` in the conversions or the odometry's metres per count with
`collision cylinder(0.044, 0.02)` on the wheels (the odometry says 0.396 m where the
base went 0.485 m). Right: `collision cylinder(R, 0.02)`. An odometry whose step reads
state the device sets elsewhere is not judged: `rdisc sim` holds it to the physics."""),
    ("E614", "mesh-file", """
A mesh's file must exist, found as the checker, the emitters and the simulation all
find it: a relative path (`mesh("meshes/base.stl")`) starts at the folder of the
description file that declares the link, never at the current folder;
`package://NAME/PATH` is PATH in the package NAME, whose root is the nearest folder
named NAME holding the description, else NAME in a folder of `ROS_PACKAGE_PATH` (or
that folder itself); `file:///PATH` and an absolute path are that file. Without it
MuJoCo refuses the model and a URDF tool shows nothing. A URDF, SDF or MJCF written
with `-o` carries a relative path rewritten to start at its own folder (MJCF a
package's file, as MuJoCo knows no packages). Wrong: `mesh("base.stl")` with
base.stl in the current folder only. Right: base.stl beside the description."""),
    ("E620", "actuator", """
An actuator is what drives a joint between the device's command and the joint
(thesis section 7.2.6): `actuator NAME: servo { ... }` a position servo, `actuator
NAME: wheel { ... }` a velocity-controlled motor. Its items, each at most once and
each a constant number more than 0: `velocity` (rad/s or m/s) and `acceleration`
(rad/s² or m/s²), the limits its commands are shaped to, `effort` (N m or N), and
for a servo its simulated `gain` (N m/rad) and `damping` (N m s/rad); and `limit
shape` (the default: a command beyond a limit is slowed to it) or `limit refuse`
(it is refused, nothing written), a word. A transmission names it, `transmission T: JOINT actuator NAME { ... }`; one actuator
drives one joint, and a servo is commanded a `position`, a wheel a `velocity`.
Wrong: `actuator m: wheel { gain 5 }`, or one actuator named by two transmissions.
Right: `actuator m: servo { velocity 4.8  effort 4.1 }`."""),
    ("E731", "noise", """
An output's `noise FIELD ...` states a field's error model (thesis section 7.2.3):
a standard deviation and its unit (`noise distance 0.01 "m"`, the variance its
square), or a covariance over an array's values (`noise position [0.0001, 0; 0,
0.0001]`, rows apart by `;`). The field is one of the adapter's number fields,
given noise once; a deviation is not negative and its unit is the field's; a
covariance is square, as large as the field's values, symmetric, and no variance
on its diagonal is negative. One covariance may span several number fields,
`noise (x, y) [0.04, 0.01; 0.01, 0.09]`, n by n for n fields, each field given
noise once in all. A state variable or a sensor of numbers states its
own the same way after its declaration (`state level: float = 0.0 noise 0.5 "mm"`,
`sensor gyro: float from read_gyro() cache 20 ms noise 0.01`). Wrong: `noise
distance 0.01 "mm"` for a field in "m". Right: `noise distance 0.00001 "m"`."""),
    ("E732", "kalman-filter", """
`filter FIELD kalman { ... }` publishes a field as a linear Kalman filter's
estimate: each delivery predicts (x = F x, P = F P F' + Q) and updates with the
field's value. With n states (`state`, one row of n numbers) and k values measured
(the field's: one for a number), `transition` (F) and `process` (Q) are n by n,
`covariance` (P, the identity when not given) n by n, `measurement` (H) k by n and
`noise` (R) k by k; covariances (P, Q, R) are symmetric and not negative on their
diagonals. Each word is given once. Wrong: `measurement [1, 0; 0, 1]` for a
number field. Right: `measurement [1, 0]`."""),
    ("E733", "covariance-not-semidefinite", """
A covariance (an output's `noise FIELD [ ... ]`, a Kalman filter's `covariance`,
`process` or `noise`) must be positive semi-definite: no combination of the
values it describes may have a negative variance. A square, symmetric matrix with
no negative variance on its diagonal can still fail: an off-diagonal value larger
than the square root of the product of its row's and column's variances. Wrong:
`noise position [1, 2; 2, 1]` (x - y would have variance -2). Right: `noise
position [1, 0.5; 0.5, 1]`."""),
    # -- warnings --------------------------------------------------------------
    ("W102", "untriggered-output", """
No interface triggers this output, so it is never delivered. An interface
triggers any number of outputs, delivered in order after its calls:
`triggers detect_bump, odometry`."""),
    ("W103", "unread-state", """
The state variable is never read by any expression and never written by a
post-action: nothing uses it. (State that post-actions write is the host's to
read, through `robot.state`, even when no expression reads it.)"""),
    ("W104", "hidden-state", """
An input's expressions read the fields of its adapter and the state variables
and settings; a field with the name of a state variable or a setting hides it, so
the name there is always the field's value, the framework's, and the state is
not read. Rename the state variable (or setting), or the field: `adapter Goal {
target: float }` beside `state position: float`. An adapter of the standard
library (`JointState`, `Twist`, ...) is not warned of: its fields are a message's,
and state named after them (a servo's `position`) is read there by design."""),
    ("W501", "unseeded-message", """
A frame whose checksum takes a `seed TABLE[FIELD]` (MAVLink 2's CRC_EXTRA) sums the
table's byte for the field's value; a primitive that frames a message whose value
the table lacks cannot be written (its request is an `RdisValueError` when framed),
and a reply carrying it can never be checked. The check runs where the frame's
arguments are constants (`frame mav2(23, 22)`), so the field's value is known; a
value given at run time is checked then. Wrong: `const EXTRAS = { 20: 214 }` with
`frame mav2(23, 22)`. Right: `const EXTRAS = { 20: 214, 22: 220, 23: 168 }`."""),
    ("W201", "nonstandard-baud", """
The baud rate is not one of the standard rates (50 ... 4000000, and the rates of
radio-control buses: S.BUS's 100000, CRSF's 420000). Some serial adapters round a
non-standard rate or refuse it."""),
    ("W230", "unused-rate", """
A periodic interface states its own rate (`periodic 10 Hz`), but its connection is
not `threading multiple`: under `single` and `dual` one thread runs every periodic
interface of the connection at the connection's frequency, so the rate is not used.
Wrong: `threading single at 40 Hz` with `interface bumpers() periodic 10 Hz`. Right:
`threading multiple at 40 Hz` (each interface without a rate runs at 40 Hz)."""),
    ("W301", "native-byte-order", """
The struct format has no byte-order prefix, so it uses the host's native byte
order and alignment (padding between fields). Devices have a fixed order: write
`<` (little-endian) or `>` (big-endian)."""),
    ("W403", "thesis-float-truncated", """
Thesis-style JSON (no `parameterTypes`) ran on the thesis's Python 2 interpreter,
whose `struct` packed a float given to an integer code by truncating it towards
zero. `rdisc import` keeps that behaviour where a float may go into an int
parameter: `"<velocity * 1000>"` into `drive(velocity: int, ...)` is imported as
`int(velocity * 1000)`, and this warning shows each such conversion. Write
`round(...)` instead where the device wants the nearest integer."""),
    ("W401", "link-budget", """
The traffic this connection schedules (periodic interfaces every tick, keepalive
every interval; 10 bits a byte at 8N1, 12 at 8E2: a start bit and the connection's
serial line) needs more bytes per second than the baud
rate carries. `rdisc check --verbose` prints each connection's budget."""),
    ("W621", "unstable-gain", """
A servo's stated `gain` is more than the simulation can integrate for the inertia
its joint carries. A position servo of gain kp on an inertia I rings at
sqrt(kp / I) rad/s; stepped every 2 ms with its damping taken implicitly, as the
MuJoCo twin steps it, it diverges once that is more than 2 + 2 sqrt(2) rad a step:
the link chatters and reads nonsense. A 5 g servo horn (2e-6 kg m²) follows a gain
of at most 12 N m/rad. Wrong: `gain 82` on that horn. Right: leave `gain` out, and
the simulation derives one from the actuator's effort and the link's inertia."""),
    ("W622", "unlimited-command", """
An actuator's `velocity` and `acceleration` hold the commands its transmission
gives (`limit shape` slows them, `limit refuse` refuses them) where the engine can
put them in the device's units: a primitive's parameter, through a conversion that
is a ratio (`raw = round(position * K) + C`). A command through an interface's
parameter, or through any other conversion (a wrap with `%`, a condition, a table),
is written as it is given, however fast. Wrong: `command position to move.angle`
(an interface) with `actuator m: servo { velocity 2 }`. Right: `command position to
servo.goal { raw = round(position * 651.9) + 2048 ... }`."""),
    ("W402", "period-too-short", """
A schedule's period is shorter than the exchange it runs: the bytes on the wire
plus the declared delays of the periodic interfaces (per tick) or of the
keepalive interface (per interval). The schedule will slip."""),
)

CODES: dict[str, Code] = {row[0]: Code(row[0], row[1], row[2].strip()) for row in _TABLE}


def lookup(text: str) -> Code | None:
    """A code by id (`E102`, `e102`) or by name (`unknown-element`)."""
    key = text.strip()
    if key.upper() in CODES:
        return CODES[key.upper()]
    return next((c for c in CODES.values() if c.name == key.lower()), None)
