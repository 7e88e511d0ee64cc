# Copied from generator/targets/python/runtime/session/device.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""The reference model of the AHRS: what the device does with every message, as time passes.

Sans-I/O (h11 style): `Device.receive(data)` takes the bytes the host sends and returns the bytes
the AHRS answers at once; `Device.advance(seconds)` moves the device's clock and returns what it
sends meanwhile (the alignment block, output at the configured rate, calibration results, nothing
after a parameter block timeout). No sockets, threads or sleeping; equal inputs give equal bytes.
A message never spans an idle line (E41): when the clock passes IDLE_TIMEOUT after the last bytes
received while the decoder holds some (the start of a frame whose rest never came), `advance`
gives them up and answers the messages behind them then.

Every decision comes from the table in `ilahrs.statemachine`: the device finds the event (the
command, resolved by mode for 0xFE; a parameter block of the size its state expects; any other
message; a timer), looks the transition up, sends what it lists and enters the next state. A
(state, event) pair without a transition is ignored (E33).

The data are synthetic but physically consistent (`ilahrs.session.motion`): angles, quaternion, gyros,
accelerometers and magnetometers describe one seeded motion, scaled per device variant (KG, KA of
Table 6.6). Parameter blocks are read with the payload classes and kept, so the read command shows
what the load command wrote (READ_PARAMETERS and LOAD_PARAMETERS of `ilahrs.roles`) and the
alignment time, update rate and accumulation time take effect.

>>> from ilahrs import build_command
>>> device = Device(seed=1)
>>> device.receive(build_command("AHRScont3")).hex(" ")    # the acknowledgement (6.3.1)
'aa 55 01 00 08 00 8a 00 93 00'
>>> device.state
'aligning_continuous'
"""

from __future__ import annotations

import math
import random
from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Final

from ..codec import FieldInfo, Payload, field_kind, required_variant
from ..commands import COMMANDS, ack_for
from ..encodings import CALIBRATION_FAILED, CALIBRATION_NO_ESTIMATE, VARIANTS, Variant, encode_date
from ..errors import ErrorKind, IlahrsError, brief, require_seconds
from ..frame import Frame, MessageType
from ..machine import firmware_is_valid
from ..nmea import NMEA_MAX_RATE_HZ, PahrSentence
from ..payloads import PAYLOADS
from ..roles import CALIBRATION_RESULTS, FINISH, FIRMWARE, LOAD_PARAMETERS, STOP_RUN, ParameterBlock
from ..spec import ICD_DATE
from ..statemachine import (
    ACK,
    BLOCK_TIMEOUT,
    CALIBRATION_TYPES,
    COMMAND_EFFECTS,
    DEFAULT_ALIGNMENT_TIME_S,
    DEFAULT_FIRMWARE,
    DEFAULT_UPDATE_RATE_HZ,
    INITIAL,
    MIN_SUCCESSFUL_RUNS,
    OTHER_MESSAGE,
    OUTPUT,
    OUTPUT_FORMATS,
    OUTPUT_PREFIX,
    PARAMETER_BLOCK,
    PARAMETER_BLOCK_TIMEOUT_S,
    STATES,
    TIMER_EVENTS,
    TIMER_FIELDS,
    TIMER_IS_RATE,
    UNKNOWN,
    Transition,
    command_event,
    firmware_version,
    lookup,
    timer_transition,
)
from ..status import USW_MODES
from ..stream import IDLE_TIMEOUT_NS, StreamDecoder, StreamEvent
from .motion import Motion, Sensors
from .synthetic import quantity as synthetic_quantity

__all__ = ["DEFAULT_DEVICE_ID", "DEFAULT_VARIANT", "Device", "default_parameters"]

DEFAULT_VARIANT: Final = next(iter(VARIANTS))
"""The first variant the spec lists."""
DEFAULT_DEVICE_ID: Final = "VIRT0001"
_NS: Final = 1_000_000_000


def _text_field(table: type[Payload]) -> str:
    return next(f.name for f in table.FIELDS if field_kind(f) == "char")


# The tables the device treats specially, by the part their command plays (`ilahrs.roles`).
_LOAD_BLOCK: Final = COMMANDS[LOAD_PARAMETERS].parameter_block or ""
_FINAL_RESULT: Final = COMMANDS[FINISH].response_payloads[0]
_RUN_RESULT: Final = next(p for p in COMMANDS[STOP_RUN].response_payloads if p != _FINAL_RESULT)
_STATUS_BLOCK: Final = COMMANDS[CALIBRATION_RESULTS].response_payloads[0]
_FIRMWARE_BLOCK: Final = COMMANDS[FIRMWARE].response_payloads[0]
_FIRMWARE_FIELD: Final = _text_field(PAYLOADS[_FIRMWARE_BLOCK])
_DEVICE_ID_FIELD: Final = _text_field(ParameterBlock)
_DECLINATION_FIELD: Final = next(f.name for f in ParameterBlock.FIELDS if f.encoding == "declination")
_DATE_FIELDS: Final = tuple(f.name for f in ParameterBlock.FIELDS if f.encoding == "date")

# The values the device model fills fields with from its own context, by field name.
_LATITUDE_FIELD: Final = "latitude"
"""The parameter the sensor model reads (the Earth field depends on it)."""
_CAL_TYPE: Final = "calibration_type"
_CAL_RUN: Final = "run"
_CAL_RUNS_USED: Final = "runs_used"
_CAL_DATA_USED: Final = "data_used"
_CAL_SUCCESS: Final = "success"
_USW_MODES: Final[Mapping[str, int]] = MappingProxyType({mode.value: bits for bits, mode in USW_MODES.items()})
"""USW mode name -> its bits (Table 6.19)."""

_FillRow = tuple[str, tuple[str, ...], int, int | str, float | None, float | None, str]


def _fill_row(info: FieldInfo) -> _FillRow:
    """(field, synthetic quantities, multiplier, divisor, low, high, kind): a multiplexed field
    lists its quantities in turn (Table 6.4 notes 2 and 3)."""
    quantities = synthetic_quantity(info.name, info.unit, info.type, info.encoding, info.multiplexed)
    return (info.name, quantities, info.multiplier, info.divisor, info.low, info.high, field_kind(info))


_FILL: Final[Mapping[str, tuple[_FillRow, ...]]] = MappingProxyType(
    {
        name: tuple(_fill_row(info) for info in table.FIELDS)
        for name, table in PAYLOADS.items()
        if table.DIRECTION == "device_to_host"
    }
)
"""Per device-to-host table: how the device fills each field."""
_NMEA_FILL: Final = tuple(
    (name, synthetic_quantity(name, unit, "", None, 0)[0], 10**decimals, low, high)
    for name, _kind, _width, decimals, low, high, unit in PahrSentence._SPEC
)
"""Per $PAHR field: (field, synthetic quantity, 10**decimals, low, high)."""


def default_parameters(device_id: str = DEFAULT_DEVICE_ID) -> ParameterBlock:
    """The parameter block (Table 6.10 form) of a new device: the defaults of Table 6.9 and the given id."""
    load = PAYLOADS[_LOAD_BLOCK]()
    fields = {f.name for f in ParameterBlock.FIELDS if f.type != "reserved"}
    values: dict[str, object] = {k: v for k, v in load.raw().items() if k in fields}
    for name in _DATE_FIELDS:
        values[name] = encode_date(*ICD_DATE)
    values[_DEVICE_ID_FIELD] = device_id
    return ParameterBlock.from_raw(values)


def _check_firmware_text(text: object) -> None:
    """The FIRMWARE answer must be Latin-1 text; it is cut to the block's size when sent."""
    table = PAYLOADS[_FIRMWARE_BLOCK]
    field = next(f for f in table.FIELDS if f.name == _FIRMWARE_FIELD)
    if isinstance(text, str):
        text = text[: field.size]
    try:
        table.from_raw({_FIRMWARE_FIELD: text})
    except IlahrsError as exc:
        raise IlahrsError(exc.kind, None, "firmware_text", exc.detail) from None


def _round(value: float) -> int:
    """Round half away from zero."""
    return math.floor(value + 0.5) if value >= 0 else -math.floor(-value + 0.5)


def _raw(value: object, row: _FillRow, variant: Variant) -> object:
    """The raw field value of an engineering value: scaled, rounded, saturated to the bounds."""
    _name, _quantities, multiplier, divisor, low, high, kind = row
    if kind in ("char", "reserved") or isinstance(value, (str, bytes)):
        return value
    assert isinstance(value, (int, float))
    scale = getattr(variant, divisor) if isinstance(divisor, str) else divisor
    raw = value * scale / multiplier
    if low is not None and high is not None:
        raw = max(low, min(high, raw))
    if kind == "float":
        return float(raw)
    rounded = _round(raw)
    if low is not None and high is not None:
        rounded = max(int(low), min(int(high), rounded))
    return rounded


@dataclass(slots=True)
class _Calibration:
    """A calibration in progress: its type, the runs done, the last evaluation and result."""

    type: int
    runs: list[dict[str, object]] = field(default_factory=list)
    last: dict[str, object] | None = None
    """The evaluation of the accumulation that ended last."""
    result: dict[str, object] | None = None
    """The result sent last (Table 6.14 form), which ACCEPT saves."""


class Device:
    """The AHRS as the ICD describes it (sections 6.1, 6.3, 6.4), driven by bytes and a clock.

    Options: `seed` (motion, noise and calibration outcomes), `variant` (a name of
    ilahrs.VARIANTS or a Variant: KG, KA), `firmware` (version; before DEFAULT_FIRMWARE the legacy rows of
    the table apply, e.g. 0x20 between 2D-2T runs finishes the calibration), `firmware_text`
    (the FIRMWARE answer), `parameters` (the initial parameter block, Table 6.10 form) and
    `device_id` (overrides the id in `parameters`).
    """

    def __init__(
        self,
        *,
        seed: int = 0,
        variant: str | Variant = DEFAULT_VARIANT,
        firmware: str = DEFAULT_FIRMWARE,
        firmware_text: str | None = None,
        parameters: ParameterBlock | None = None,
        device_id: str | None = None,
    ) -> None:
        self.variant = required_variant(variant)
        if not firmware_is_valid(firmware):
            detail = f"{brief(firmware)} is not a firmware version such as {DEFAULT_FIRMWARE}"
            raise IlahrsError(ErrorKind.OUT_OF_RANGE, None, "firmware", detail)
        self.firmware = firmware
        self.firmware_text = firmware_text if firmware_text is not None else f"ilahrs virtual AHRS {firmware}"
        _check_firmware_text(self.firmware_text)
        params = parameters if parameters is not None else default_parameters()
        if not isinstance(params, ParameterBlock):
            detail = f"{brief(params)} is not a {ParameterBlock.NAME} block"
            raise IlahrsError(ErrorKind.MALFORMED, None, "parameters", detail)
        params.check()
        self._memory: dict[str, object] = {k: v for k, v in params.raw().items() if not isinstance(v, bytes)}
        if device_id is not None:
            self._memory[_DEVICE_ID_FIELD] = device_id
        if isinstance(seed, bool) or not isinstance(seed, int):
            raise IlahrsError(ErrorKind.OUT_OF_RANGE, None, "seed", f"{brief(seed)} is not an integer")
        ParameterBlock.from_raw(self._memory).check()
        self._calibration_memory: dict[str, object] = {}
        """The calibration saved by ACCEPT (what CALIBRATION_RESULTS reads, Table 6.17)."""
        self._received: dict[str, Payload] = {}
        """The last parameter block accepted, per table."""
        self._rng = random.Random(seed ^ 0xCA1)
        self._motion = Motion(seed)
        self._sensors = Sensors(seed)
        self._decoder = StreamDecoder()
        self._state = INITIAL
        self._now = 0
        self._idle_at: int | None = None
        self._deadline: int | None = None
        self._deadline_event: str | None = None
        self._output: str | None = None
        self._outputs_sent = 0
        self._calibration: _Calibration | None = None
        self.ignored = 0
        """Messages the device ignored (no transition in their state, E33)."""
        self.rejected_blocks = 0
        """Parameter blocks acknowledged but not stored because a value is out of range."""

    # --- What the host sees --------------------------------------------------------------------

    @property
    def state(self) -> str:
        """The current state of the table."""
        return self._state

    @property
    def mode(self) -> str:
        """The operating mode (6.1) of the current state."""
        return STATES[self._state].mode

    @property
    def output_format(self) -> str | None:
        """The output format the last start command chose (a payload name, or the $PAHR sentence)."""
        return self._output

    @property
    def now(self) -> float:
        """Seconds since power-up."""
        return self._now / _NS

    @property
    def discarded(self) -> int:
        """Received bytes that belong to no frame."""
        return self._decoder.discarded

    @property
    def parameters(self) -> ParameterBlock:
        """The parameter block as READ_PARAMETERS returns it."""
        return ParameterBlock.from_raw(self._memory)

    @property
    def next_event_in(self) -> float | None:
        """Seconds until the device next acts on its own (a timer, or the line going idle while it
        holds the start of a message), or None."""
        due = [t for t in (self._deadline, self._idle_at) if t is not None]
        return max(0, min(due) - self._now) / _NS if due else None

    def receive(self, data: bytes | bytearray | memoryview) -> bytes:
        """Take bytes from the host; return what the AHRS answers at once."""
        out = self._answer(self._decoder.feed(data))
        if len(data):
            waiting = self._decoder.pending and IDLE_TIMEOUT_NS is not None
            self._idle_at = self._now + IDLE_TIMEOUT_NS if waiting and IDLE_TIMEOUT_NS is not None else None
        return out

    def idle(self, quiet: float | None = None) -> bytes:
        """The line has been quiet for `quiet` seconds since the last byte (None: it is idle). From
        IDLE_TIMEOUT on, the bytes held are given up (E41; StreamDecoder.idle); return the answers
        to the messages behind them. A shorter quiet time changes nothing."""
        out = self._answer(self._decoder.idle(quiet))
        if not self._decoder.pending:
            self._idle_at = None
        return out

    def _answer(self, events: list[StreamEvent]) -> bytes:
        out = bytearray()
        for event in events:
            if event.frame is not None:
                out += self._message(event.raw, event.frame)
        return bytes(out)

    def advance(self, seconds: float) -> bytes:
        """Let `seconds` pass; return what the AHRS sends meanwhile, in order."""
        target = self._now + round(require_seconds(seconds) * _NS)
        out = bytearray()
        while True:
            idle_at = self._idle_at
            if idle_at is not None and idle_at <= target and (self._deadline is None or idle_at <= self._deadline):
                self._now = idle_at
                out += self.idle()
                continue
            if self._deadline is None or self._deadline > target:
                break
            self._now = self._deadline
            event = self._deadline_event
            self._deadline = self._deadline_event = None
            assert event is not None
            out += self._fire(event, None, None)
        self._now = target
        return bytes(out)

    # --- The table, interpreted ---------------------------------------------------------------

    def _message(self, raw: bytes, frame: Frame) -> bytes:
        expects = STATES[self._state].expects
        event: str | None
        if frame.message_type == MessageType.COMMAND and len(frame.payload) == 1:
            event = command_event(frame.payload[0], self._state) or UNKNOWN
        elif expects is not None and len(frame.payload) == PAYLOADS[expects].SIZE:
            event = PARAMETER_BLOCK  # message type 0 or 1 (E5)
        else:
            event = OTHER_MESSAGE
        return self._fire(event, raw, frame)

    def _fire(self, event: str, raw: bytes | None, frame: Frame | None) -> bytes:
        old = self._state
        transition = lookup(old, event, self.firmware)
        if transition is None:
            self.ignored += 1
            return b""
        if event == PARAMETER_BLOCK and frame is not None:
            self._accept_block(PAYLOADS[STATES[old].expects or ""], frame.payload)
        info = COMMANDS.get(event)
        if info is not None and info.starts_output is not None:
            self._output = info.starts_output
        if event in CALIBRATION_TYPES:
            self._calibration = _Calibration(CALIBRATION_TYPES[event])
        if STATES[old].timer == "accumulation" and transition.to != old:
            self._end_accumulation()
        effect = COMMAND_EFFECTS.get(event)
        if effect == "save_calibration" and self._calibration is not None and self._calibration.result is not None:
            self._calibration_memory = dict(self._calibration.result)
        elif effect == "clear_calibration":
            self._calibration_memory = {}
        out = b"".join(self._send(item, raw, event) for item in transition.send)
        self._enter(transition, event)
        return out

    def _enter(self, transition: Transition, event: str) -> None:
        old, new = self._state, transition.to
        self._state = new
        info = STATES[new]
        if new == INITIAL:
            self._calibration = None
        if new == old:
            timer = info.timer
            if timer is not None and event == TIMER_EVENTS[timer]:
                self._arm(event, self._duration(timer))  # periodic: one period after the last
            return
        self._deadline = self._deadline_event = None
        if info.expects is not None:
            self._arm(BLOCK_TIMEOUT, PARAMETER_BLOCK_TIMEOUT_S)
        elif info.timer is not None:
            self._arm(TIMER_EVENTS[info.timer], self._duration(info.timer))
        t = self.now
        if info.timer == "alignment":
            self._start_alignment(t)
        elif info.timer == "accumulation":
            self._start_accumulation(t)
        elif self._motion.kind != "moving":
            self._motion.start("moving", t)

    def _arm(self, event: str, seconds: float) -> None:
        self._deadline = self._now + max(1, round(seconds * _NS))
        self._deadline_event = event

    def _setting(self, timer: str) -> float:
        block, name = TIMER_FIELDS[timer]
        received = self._received.get(block)
        value: object
        if received is not None:
            value = received.raw()[name]
        elif name in self._memory:
            value = self._memory[name]
        else:
            value = DEFAULT_UPDATE_RATE_HZ if TIMER_IS_RATE[timer] else DEFAULT_ALIGNMENT_TIME_S
        assert isinstance(value, (int, float))
        return float(value)

    def _duration(self, timer: str) -> float:
        value = self._setting(timer)
        if not TIMER_IS_RATE[timer]:
            return value
        if self._output is not None and OUTPUT_FORMATS.get(self._output) is None:
            value = min(value, NMEA_MAX_RATE_HZ)  # E22
        return 1.0 / value

    def _accept_block(self, cls: type[Payload], payload: bytes) -> None:
        """Read a parameter block and keep it; the parameter memory takes what the load block carries."""
        block = cls.parse(payload)
        try:
            block.check()
        except IlahrsError:
            self.rejected_blocks += 1
            return
        self._received[cls.NAME] = block
        if cls.NAME == _LOAD_BLOCK:
            read = {f.name: f for f in ParameterBlock.FIELDS}
            for f in cls.FIELDS:
                same = read.get(f.name)
                if same is not None and same.type == f.type and same.size == f.size and f.type != "reserved":
                    self._memory[f.name] = getattr(block, f.name)

    # --- What the device sends ----------------------------------------------------------------

    def _send(self, item: str, raw: bytes | None, event: str) -> bytes:
        if item == ACK:
            return ack_for(raw) if raw is not None else b""
        if item == OUTPUT or item.startswith(OUTPUT_PREFIX):
            mode = item.removeprefix(OUTPUT_PREFIX) if item != OUTPUT else None
            return self._output_block(mode)
        averaged = event == TIMER_EVENTS.get("alignment")
        values = self._values(noise=not averaged, usw=0)
        values.update(self._context(item))
        return Frame(MessageType.DATA, self._build(item, values)).build()

    def _values(self, *, noise: bool, usw: int) -> dict[str, object]:
        latitude = self._memory.get(_LATITUDE_FIELD, 0.0)
        declination = self._memory.get(_DECLINATION_FIELD, 0.0)
        assert isinstance(latitude, (int, float)) and isinstance(declination, (int, float))
        if not -180 <= declination <= 180:
            declination = 0.0  # "compute it": the virtual device has no World Magnetic Model
        sample = self._sensors.sample(self._motion, self.now, latitude=latitude, declination=declination, noise=noise)
        values: dict[str, object] = dict(self._memory)
        values.update(sample)
        values["usw"] = usw
        return values

    def _context(self, item: str) -> dict[str, object]:
        if item == _FIRMWARE_BLOCK:
            return {_FIRMWARE_FIELD: self.firmware_text[: PAYLOADS[item].SIZE]}
        if item == _STATUS_BLOCK:
            return dict(self._calibration_memory)
        calibration = self._calibration
        if calibration is None:
            return {}
        if item == _RUN_RESULT and calibration.last is not None:
            run = dict(calibration.last)
            run[_CAL_RUN] = min(len(calibration.runs) + 1, 255)
            calibration.runs.append(run)
            return run
        if item == _FINAL_RESULT:
            result = self._final_result(calibration)
            calibration.result = result
            return result
        return {}

    def _build(self, name: str, values: Mapping[str, object], turn: int = 0) -> bytes:
        """A payload of table `name` from synthetic values; a multiplexed field carries its
        quantity number `turn` (modulo the count)."""
        cls = PAYLOADS[name]
        raw: dict[str, object] = {}
        for row in _FILL.get(name, ()):
            quantities = row[1]
            if not quantities:
                continue
            quantity = quantities[turn % len(quantities)]
            if quantity in values:
                raw[row[0]] = _raw(values[quantity], row, self.variant)
        return cls.from_raw(raw).build()

    def _output_block(self, mode: str | None) -> bytes:
        usw = _USW_MODES.get(mode, 0) if mode is not None else 0
        values = self._values(noise=True, usw=usw)
        fmt = OUTPUT_FORMATS.get(self._output or "")
        self._outputs_sent += 1
        if fmt is not None:
            payload = self._build(fmt, values, self._outputs_sent - 1)
            return Frame(MessageType.DATA, payload).build()
        sentence: dict[str, int] = {}
        for name, quantity, divisor, low, high in _NMEA_FILL:
            value = values.get(quantity, 0)
            assert isinstance(value, (int, float))
            sentence[name] = max(low, min(high, _round(value * divisor)))
        return PahrSentence(**sentence).build().encode("ascii")

    # --- Calibration (6.4) ----------------------------------------------------------------------

    def _run_pose(self) -> tuple[float, float]:
        """(pitch, roll) at which the operator holds the object for the coming calibration run:
        level for a single-run calibration, a new pitch for each run of a multi-run one (-5, 5,
        -10, 10 ... deg, 6.4.5: "a few full 360 deg rotations ... with different pitch angles")."""
        calibration = self._calibration
        run = len(calibration.runs) + 1 if calibration is not None else 1
        roll = self._rng.uniform(-1, 1)
        return ((-1) ** run * 5.0 * ((run + 1) // 2) if self._multi_run() else 0.0), roll

    def _multi_run(self) -> bool:
        """Whether the accumulation ahead (or under way) ends in a run result rather than the result."""
        state = self._state
        for _ in STATES:
            timed = timer_transition(state)
            if timed is None:
                return False
            if STATES[state].timer == "accumulation":
                return _RUN_RESULT in timed[1].send
            state = timed[1].to
        return False

    def _start_alignment(self, t: float) -> None:
        if self._calibration is None:
            self._motion.start("still", t)
            return
        pitch, roll = self._run_pose()
        self._motion.start("still", t, pitch=pitch, roll=roll)

    def _start_accumulation(self, t: float) -> None:
        # The operator turns the object once in 80 % of the accumulation time (6.4.5: "correct the
        # time ... to provide necessary rotation"), keeping the pitch and roll of the alignment.
        seconds = self._setting("accumulation")
        self._motion.start("turning", t, turn_rate=360.0 / (0.8 * seconds))

    def _end_accumulation(self) -> None:
        calibration = self._calibration
        if calibration is None:
            return
        turned = self._motion.turned(self.now)
        complete = turned >= 360.0
        _heading, pitch, roll = self._motion.angles(self.now)
        calibration.last = {
            _CAL_TYPE: calibration.type,
            _CAL_DATA_USED: min(100, _round(100 * turned / 360.0)) if not complete else self._rng.randint(92, 100),
            _CAL_SUCCESS: self._success() if complete else CALIBRATION_FAILED,
            "pitch": pitch,
            "roll": roll,
        }

    def _success(self) -> int:
        """The "Calibration success" byte of a good calibration: the predicted heading error in
        deg*10 (since the current firmware), or "successful, no estimate" before it (E26)."""
        if firmware_version(self.firmware) < firmware_version(DEFAULT_FIRMWARE):
            return CALIBRATION_NO_ESTIMATE
        return self._rng.randint(3, 9)

    def _final_result(self, calibration: _Calibration) -> dict[str, object]:
        if calibration.runs:
            good = [run for run in calibration.runs if run[_CAL_SUCCESS] != CALIBRATION_FAILED]
            result: dict[str, object] = {
                _CAL_TYPE: calibration.type,
                _CAL_RUNS_USED: len(good),
                _CAL_DATA_USED: 0,  # "for 2D and 3D calibrations only" (Table 6.14)
                _CAL_SUCCESS: self._success() if len(good) >= MIN_SUCCESSFUL_RUNS else CALIBRATION_FAILED,
            }
        else:
            last = calibration.last or {_CAL_DATA_USED: 0, _CAL_SUCCESS: CALIBRATION_FAILED}
            result = {
                _CAL_TYPE: calibration.type,
                _CAL_RUNS_USED: 1,
                _CAL_DATA_USED: last[_CAL_DATA_USED],
                _CAL_SUCCESS: last[_CAL_SUCCESS],
            }
        soft, hard = self._sensors.soft_iron, self._sensors.hard_iron
        for i in range(3):
            result[f"hard_iron_{'xyz'[i]}"] = -hard[i] + self._rng.gauss(0, 2.0)
            for j in range(3):
                result[f"soft_iron_{i + 1}{j + 1}"] = (2.0 if i == j else 0.0) - soft[i][j] + self._rng.gauss(0, 0.002)
        return result
