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

# `typing.TYPE_CHECKING` without importing `typing` (a twentieth of a cold `rdisc check`, which imports
# this package, `operations` and `signals`, each of which says the same): type checkers read
# `if TYPE_CHECKING:` by its name as true.
TYPE_CHECKING = False

if TYPE_CHECKING:  # at run time each name is imported when it is first asked for (__getattr__, below)
    from rdisc.engine.actuation import Actuated, ActuatorLimit
    from rdisc.engine.arguments import Unbound, bind_named, bind_settings, call_values, read_value
    from rdisc.engine.checksums import Checksum
    from rdisc.engine.codec import Format, Group, Match, Pack, Split, Unpack, Varying
    from rdisc.engine.command import (
        add_arguments,
        made_from,
        make_call,
        named_pairs,
        parse_call,
        parse_ports,
        parse_settings,
        ports_held,
        run_command,
        start_recording,
    )
    from rdisc.engine.errors import (
        RdisCallbackError,
        RdisConnectionError,
        RdisDeviceError,
        RdisError,
        RdisLimitError,
        RdisProtocolError,
        RdisTimeout,
        RdisValueError,
        nearest,
    )
    from rdisc.engine.exchange import Exchange
    from rdisc.engine.frames import Frame, Wrap
    from rdisc.engine.kalman import FilterPlan, KalmanFilter
    from rdisc.engine.matrices import (
        Matrix,
        as_column,
        as_matrix,
        matrix_identity,
        matrix_inverse,
        matrix_product,
        matrix_shape,
        matrix_sum,
        matrix_transpose,
    )
    from rdisc.engine.operations import (
        BINARY,
        EVAL_ERRORS,
        FLOAT_MAX,
        FUNCTIONS,
        MAX_ARRAY,
        MAX_INT,
        MAX_INT_BYTES,
        MAX_LINE,
        MAX_NIBBLES,
        MAX_RESULT_BITS,
        MAX_SHIFT,
        MAX_TEXT,
        UNARY,
        EvalError,
        LookupMiss,
        element,
        fits,
        lookup,
        lookup_or,
        replaced,
        shown,
    )
    from rdisc.engine.plans import (
        NO_REPLY,
        Call,
        Connection,
        Device,
        ErrorReply,
        FixedReply,
        FramedReply,
        FrameUse,
        Hook,
        Input,
        Interface,
        KeyedReply,
        LineReply,
        ListedReplies,
        Message,
        NoReply,
        Output,
        Primitive,
        Records,
        Reply,
        Request,
        Sensor,
        SeveralReplies,
        SubPayloads,
        TaggedReply,
        TaggedStream,
        asked_at_once,
        plainly_given,
        sent_at_once,
        written_at_once,
    )
    from rdisc.engine.ports import Port, PortSpec, Simulator
    from rdisc.engine.recording import (
        BYTES_TYPE,
        LOG_TYPE,
        RUNS_TOPIC,
        STATE_TOPIC,
        TEXT_TYPE,
        Recorder,
        Session,
        Sink,
        Topic,
        ros_message,
        session_topics,
    )
    from rdisc.engine.replies import Replies, device_error
    from rdisc.engine.robot import Calls, Robot, State
    from rdisc.engine.running import Running
    from rdisc.engine.sensing import SensorCache, Sensors
    from rdisc.engine.signals import (
        EXIT_ERROR,
        EXIT_OK,
        EXIT_SIGINT,
        EXIT_SIGTERM,
        EXIT_USAGE,
        command_line,
        without_signals,
    )
    from rdisc.engine.telling import Telling
    from rdisc.engine.values import (
        Args,
        ErrorCallback,
        IoCallback,
        OutputCallback,
        OutputMessage,
        Param,
        StateValues,
        TraceCallback,
        Value,
        held_to,
        not_finite,
        one_step_bounds,
    )
    from rdisc.engine.wire import (
        MAX_FRAME,
        MAX_SKIP,
        Bits,
        Bytes,
        Check,
        ChecksumError,
        Escaping,
        Field,
        FrameError,
        Incoming,
        Length,
        MissingSeed,
        OptionalParts,
        Part,
        Payload,
        Reader,
        Side,
        Stuffing,
    )

__all__ = [
    "BINARY",
    "BYTES_TYPE",
    "EVAL_ERRORS",
    "EXIT_ERROR",
    "EXIT_OK",
    "EXIT_SIGINT",
    "EXIT_SIGTERM",
    "EXIT_USAGE",
    "FLOAT_MAX",
    "FUNCTIONS",
    "LOG_TYPE",
    "MAX_ARRAY",
    "MAX_FRAME",
    "MAX_INT",
    "MAX_INT_BYTES",
    "MAX_LINE",
    "MAX_NIBBLES",
    "MAX_RESULT_BITS",
    "MAX_SHIFT",
    "MAX_SKIP",
    "MAX_TEXT",
    "NO_REPLY",
    "RUNS_TOPIC",
    "STATE_TOPIC",
    "TEXT_TYPE",
    "UNARY",
    "Actuated",
    "ActuatorLimit",
    "Args",
    "Bits",
    "Bytes",
    "Call",
    "Calls",
    "Check",
    "Checksum",
    "ChecksumError",
    "Connection",
    "Device",
    "ErrorCallback",
    "ErrorReply",
    "Escaping",
    "EvalError",
    "Exchange",
    "Field",
    "FilterPlan",
    "FixedReply",
    "Format",
    "Frame",
    "FrameError",
    "FrameUse",
    "FramedReply",
    "Group",
    "Hook",
    "Incoming",
    "Input",
    "Interface",
    "IoCallback",
    "KalmanFilter",
    "KeyedReply",
    "Length",
    "LineReply",
    "ListedReplies",
    "LookupMiss",
    "Match",
    "Matrix",
    "Message",
    "MissingSeed",
    "NoReply",
    "OptionalParts",
    "Output",
    "OutputCallback",
    "OutputMessage",
    "Pack",
    "Param",
    "Part",
    "Payload",
    "Port",
    "PortSpec",
    "Primitive",
    "RdisCallbackError",
    "RdisConnectionError",
    "RdisDeviceError",
    "RdisError",
    "RdisLimitError",
    "RdisProtocolError",
    "RdisTimeout",
    "RdisValueError",
    "Reader",
    "Recorder",
    "Records",
    "Replies",
    "Reply",
    "Request",
    "Robot",
    "Running",
    "Sensor",
    "SensorCache",
    "Sensors",
    "Session",
    "SeveralReplies",
    "Side",
    "Simulator",
    "Sink",
    "Split",
    "State",
    "StateValues",
    "Stuffing",
    "SubPayloads",
    "TaggedReply",
    "TaggedStream",
    "Telling",
    "Topic",
    "TraceCallback",
    "Unbound",
    "Unpack",
    "Value",
    "Varying",
    "Wrap",
    "add_arguments",
    "as_column",
    "as_matrix",
    "asked_at_once",
    "bind_named",
    "bind_settings",
    "call_values",
    "command_line",
    "device_error",
    "element",
    "fits",
    "held_to",
    "lookup",
    "lookup_or",
    "made_from",
    "make_call",
    "matrix_identity",
    "matrix_inverse",
    "matrix_product",
    "matrix_shape",
    "matrix_sum",
    "matrix_transpose",
    "named_pairs",
    "nearest",
    "not_finite",
    "one_step_bounds",
    "parse_call",
    "parse_ports",
    "parse_settings",
    "plainly_given",
    "ports_held",
    "read_value",
    "replaced",
    "ros_message",
    "run_command",
    "sent_at_once",
    "session_topics",
    "shown",
    "start_recording",
    "without_signals",
    "written_at_once",
]


def __getattr__(name: str) -> object:
    """A public name, from the first of the engine's modules (in the order a driver carries them,
    so the one that defines it) that has it, imported now: the checker imports
    `rdisc.engine.operations`, and with it no more of the engine (start-up time)."""
    if name not in __all__:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    from importlib import import_module

    from rdisc.engine.carry import MODULES

    for module, _ in MODULES:
        found = import_module(f"{__name__}.{module}").__dict__.get(name, _MISSING)
        if found is not _MISSING:
            globals()[name] = found
            return found
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


_MISSING = object()
