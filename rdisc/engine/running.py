"""The plans run: inputs, interfaces with their calls and polls, primitives, hooks."""

from __future__ import annotations

from collections.abc import Callable

from rdisc.engine.actuation import Actuated
from rdisc.engine.arguments import _accept_param, _accepted, _widen
from rdisc.engine.errors import RdisConnectionError, RdisTimeout, RdisValueError
from rdisc.engine.exchange import Exchange
from rdisc.engine.operations import EVAL_ERRORS
from rdisc.engine.plans import Call, Hook, Input, Interface, KeyedReply, Primitive
from rdisc.engine.values import (
    Args,
    _check_ranges,
)


class Running(Exchange):
    """The part of a Robot that runs its plans; `Robot` sets what is declared here."""

    _running: bool
    _sleep: Callable[[float], None]
    _actuated: Actuated

    def _not_running(self) -> RdisConnectionError:
        return RdisConnectionError(f"{self.name}: {'closed' if self._closed else 'not open'}")

    # ---- running the plans --------------------------------------------------------------------------

    def _input(self, plan: Input, values: Args) -> None:
        """Run an input with its fields' values by position (each made its type here)."""
        if not self._running:
            raise self._not_running()
        request = plan.request
        if request is not None:  # one plain write: every command's path
            data = request(self._state, values)
            if data is not None:
                assert plan.primitive is not None
                self._write(plan.primitive, data)
                return
        self._input_in_full(plan, values)

    def _input_in_full(self, plan: Input, values: Args) -> None:
        """An input the general way: its fields made their types, its interface's arguments."""
        if not self._running:
            raise self._not_running()
        for i, param in enumerate(plan.fields):
            if type(values[i]) is not param.kind or param.size is not None or param.kind is float:
                values[i] = _accept_param(values[i], param, f"input {plan.name}: field {param.name}")
        if plan.sensors:
            self._sense(plan.sensors)
        try:
            args = plan.args(self._state, values)
        except EVAL_ERRORS as err:
            raise RdisValueError(f"{plan.name}: {err}") from None
        for param, value in zip(plan.interface.params, args):
            if param.size and len(value) != param.size:  # an adapter's array, of any size, into one of a fixed size
                raise RdisValueError(f"{plan.name}: {plan.interface.name} takes {param.size} values for "
                                     f"{param.name}, not {len(value)}")
        self._interface(plan.interface, args)

    def _call_interface(self, plan: Interface, values: Args) -> None:
        """Run an interface the host called, with its parameters' values by position."""
        if not self._running:
            raise self._not_running()
        self._interface(plan, _accepted(f"interface {plan.name}", plan.params, values))

    def _call_primitive(self, plan: Primitive, values: Args) -> None:
        """Run a primitive the host called, with its parameters' values by position: a plain
        write in one step (`plan.request`) when it can be, else the general way."""
        request = plan.request
        if request is not None and self._direct:  # one plain write: every command's path
            data = request(self._state, values)
            if data is not None:
                self._write(plan, data)
                return
        asked = plan.asked
        if asked is not None and self._direct:  # a plain exchange: a sensor's path
            data = asked(self._state, values)
            if data is not None:
                self._ask(plan, data, values)
                return
        if not self._running:
            raise self._not_running()
        self._primitive(plan, _accepted(f"primitive {plan.name}", plan.params, values))

    def _send(self, plan: Primitive, request: bytes | None, values: Args) -> None:
        """A typed method's primitive, its request made by the driver's one-step function
        (`plan.request`; None: values it does not take): written at once on ports, else the
        general way, which says what is wrong (every command's path: one call to the write)."""
        if request is not None and self._direct:
            self._write(plan, request)
        else:
            self._call_primitive(plan, values)

    def _send_input(self, plan: Input, request: bytes | None, values: Args) -> None:
        """`_send` of a typed method's input: its request in one step (`plan.request`), else the general way."""
        if request is not None and self._direct and plan.primitive is not None:
            self._write(plan.primitive, request)
        else:
            self._input_in_full(plan, values)

    def _hook(self, hook: Hook) -> None:
        try:
            args = hook.args(self._state)
        except EVAL_ERRORS as err:
            raise RdisValueError(f"{hook.interface.name}: {err}") from None
        self._interface(hook.interface, args)

    def _interface(self, plan: Interface, args: Args) -> None:
        """Run an interface with its parameters' values: its calls in order, each followed by
        its delay, then its output. An error stops it where it happened."""
        for i in plan.floats:  # (inline: this is every command's path)
            if type(args[i]) is int:
                _widen(plan.name, plan.floats, args)
                break
        if plan.ranged:
            _check_ranges(plan.name, plan.params, plan.ranged, args)
        if plan.sensors:
            self._sense(plan.sensors)
        for call in plan.calls:
            try:
                if call.when is not None and not call.when(self._state, args):
                    continue  # not made, and so no delay after it
                values = call.args(self._state, args)
            except EVAL_ERRORS as err:
                raise RdisValueError(f"{plan.name}: {err}") from None
            self._make(call, values)
            if call.until is not None:
                self._poll(plan, call, args)
            if call.delay:
                self._sleep(call.delay)
        for output in plan.outputs:
            self._deliver(output)

    def _make(self, call: Call, values: Args) -> None:
        """One call of an interface, with its arguments' values."""
        target = call.target
        if isinstance(target, Interface):
            self._interface(target, values)
        elif call.direct:  # the call's values are the primitive's format values
            self._exchange(target, values, values)
        else:
            self._primitive(target, values)

    def _poll(self, plan: Interface, call: Call, args: Args) -> None:
        """`until COND every P within T`, after the call's first making: while COND does not
        hold, wait P and make the call again (its arguments evaluated again), at most T / P
        more times; then an RdisTimeout saying how many calls were made."""
        assert call.until is not None
        most = int(call.within / call.every + 1e-9) + 1
        made = 1
        while True:
            try:
                if call.until(self._state, args):
                    return
                if made == most:
                    break
                self._sleep(call.every)
                values = call.args(self._state, args)
            except EVAL_ERRORS as err:
                raise RdisValueError(f"{plan.name}: {err}") from None
            self._make(call, values)
            made += 1
        raise RdisTimeout(f"{plan.name}: {call.target.name}() did not meet its `until` within {call.within:g} s "
                          f"({made} calls, every {call.every:g} s)")

    def _primitive(self, plan: Primitive, args: Args) -> None:
        """Run a primitive with its parameters' values: its reply table's entry, if it has
        one, then the exchange."""
        request = plan.request
        if request is not None:  # one plain write
            data = request(self._state, args)
            if data is not None:
                self._write(plan, data)
                return
        asked = plan.asked
        if asked is not None:  # a plain exchange
            data = asked(self._state, args)
            if data is not None:
                self._ask(plan, data, args)
                return
        self._primitive_in_full(plan, args)

    def _primitive_in_full(self, plan: Primitive, args: Args) -> None:
        """A primitive the general way: its parameters checked, its reply table's entry chosen."""
        self._exchange(*self._planned(plan, args))

    def _planned(self, plan: Primitive, args: Args, actuated: Actuated | None = None) -> tuple[Primitive, Args, Args]:
        """A primitive's parameters checked (ints made floats, ranges) and held to its actuators'
        limits (`actuated`: what they were last given, else the robot's), its reply table's entry
        chosen: that plan, its format values and the parameters' values."""
        for i in plan.floats:
            if type(args[i]) is int:
                _widen(plan.name, plan.floats, args)
                break
        if plan.ranged:
            _check_ranges(plan.name, plan.params, plan.ranged, args)
        if plan.actuators:  # shaped to the actuators' limits, or refused (`actuation`)
            args = (actuated or self._actuated).limited(plan.actuators, args, self._clock())
        if isinstance(plan.reply, KeyedReply):
            plan = plan.reply.entry(args)
        try:
            values = plan.values(self._state, args)
        except EVAL_ERRORS as err:
            raise RdisValueError(f"{plan.name}: {err}") from None
        return plan, values, args
