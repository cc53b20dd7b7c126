"""The rdisc engine: the run-time semantics of RDIS, written once.

Everything that happens between a host and its devices lives in this package: ports
and their locks, frames, writing requests and reading every kind of reply, deadlines,
I/O callbacks, the connections' threads and schedules, hooks, the lifecycle, signals,
the error types and the command line. What a description specialises is data and small
functions, the *plans* (`rdisc.engine.plans`: per primitive its values, encoder,
decoder, frame, post-actions; per interface its calls, delays and output; per input its
arguments). The runtime (`rdisc.runtime.device`) builds plans from a checked Model with
its expression interpreter; `rdisc emit-python` writes them as Python source into a
driver that carries this package's modules as marked sections (`rdisc.engine.carry`).
So the runtime and every driver run the same code. It needs only the standard library,
and pyserial to open a port by name; nothing of rdisc outside it. The semantics are the
contract in docs/runtime.md.
"""

from rdisc.engine.arguments import Unbound, bind_named, bind_settings, call_values, read_value
from rdisc.engine.checksums import Checksum
from rdisc.engine.codec import Format, Group, Match, Pack, Split, Unpack, Varying
from rdisc.engine.command import (
    EXIT_ERROR,
    EXIT_OK,
    EXIT_SIGINT,
    EXIT_SIGTERM,
    EXIT_USAGE,
    add_arguments,
    make_call,
    parse_call,
    parse_ports,
    parse_settings,
    run_command,
    start_recording,
)
from rdisc.engine.errors import (
    RdisCallbackError,
    RdisConnectionError,
    RdisError,
    RdisProtocolError,
    RdisTimeout,
    RdisValueError,
)
from rdisc.engine.exchange import Exchange
from rdisc.engine.frames import Frame, Wrap
from rdisc.engine.operations import EVAL_ERRORS, MAX_ARRAY, MAX_INT, MAX_LINE, element, lookup, replaced
from rdisc.engine.plans import (
    Call,
    Connection,
    Device,
    FrameUse,
    Hook,
    Input,
    Interface,
    Message,
    Output,
    Param,
    Primitive,
    Request,
)
from rdisc.engine.ports import Port, PortSpec, Simulator
from rdisc.engine.recording import RUNS_TOPIC, Recorder, ros_message
from rdisc.engine.robot import Calls, Robot, State
from rdisc.engine.values import Args, ErrorCallback, IoCallback, OutputCallback, StateValues, Value
from rdisc.engine.wire import (
    MAX_FRAME,
    MAX_SKIP,
    Bits,
    Bytes,
    Check,
    Escaping,
    Field,
    FrameError,
    Incoming,
    Length,
    OptionalParts,
    Part,
    Payload,
    Reader,
    Side,
    Stuffing,
)

__all__ = [
    "EVAL_ERRORS",
    "EXIT_ERROR",
    "EXIT_OK",
    "EXIT_SIGINT",
    "EXIT_SIGTERM",
    "EXIT_USAGE",
    "MAX_ARRAY",
    "MAX_FRAME",
    "MAX_INT",
    "MAX_LINE",
    "MAX_SKIP",
    "RUNS_TOPIC",
    "Args",
    "Bits",
    "Bytes",
    "Call",
    "Calls",
    "Check",
    "Checksum",
    "Connection",
    "Device",
    "ErrorCallback",
    "Escaping",
    "Exchange",
    "Field",
    "Format",
    "Frame",
    "FrameError",
    "FrameUse",
    "Group",
    "Hook",
    "Incoming",
    "Input",
    "Interface",
    "IoCallback",
    "Length",
    "Match",
    "Message",
    "OptionalParts",
    "Output",
    "OutputCallback",
    "Pack",
    "Param",
    "Part",
    "Payload",
    "Port",
    "PortSpec",
    "Primitive",
    "RdisCallbackError",
    "RdisConnectionError",
    "RdisError",
    "RdisProtocolError",
    "RdisTimeout",
    "RdisValueError",
    "Reader",
    "Recorder",
    "Request",
    "Robot",
    "Side",
    "Simulator",
    "Split",
    "State",
    "StateValues",
    "Stuffing",
    "Unbound",
    "Unpack",
    "Value",
    "Varying",
    "Wrap",
    "add_arguments",
    "bind_named",
    "bind_settings",
    "call_values",
    "element",
    "lookup",
    "make_call",
    "parse_call",
    "parse_ports",
    "parse_settings",
    "read_value",
    "replaced",
    "ros_message",
    "run_command",
    "start_recording",
]
