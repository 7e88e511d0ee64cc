"""An independent model of what the AHRS does with each message it receives, for session vectors.

Written again from the ICD text (rev 1.7: 6 "the program works in the waiting mode of the
commands", 6.1 the five operating modes, 6.3 and 6.4 each command, Table 6.19 the sleep bits),
not from the `state_machine` table of spec/ilahrs.yaml, which it is meant to check. Where the ICD
is silent the decisions recorded as errata are the contract, and this model follows them; each is
quoted where it is used. It knows the command codes and the sizes of the parameter blocks from
oracle.py (Table C.1 and the payload tables as printed), and nothing from the generator, the
bindings or the spec. Standard library only.

The states are named as the conformance suite names them (conformance/README.md, `session`), so
that the vectors can say where the device is; how each state behaves is written here, state by
state, as the ICD describes it.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass

import oracle as o

# --- The states, with the operating mode of 6.1 each belongs to ---------------------------------

IDLE = "idle"  # 6.1 (1), 6.3: "After power connection the AHRS is in the idle mode."
AWAITING_PARAMETERS = "awaiting_parameters"  # 6.3.6: LoadAHRSPar received, Table 6.9 block to follow
ALIGNING_CONTINUOUS = "aligning_continuous"  # 6.3.1, 6.3.3: initial alignment after AHRScont*/NMEAcont
CONTINUOUS = "continuous"  # 6.1 (2)
ALIGNING_ON_REQUEST = "aligning_on_request"  # 6.3.2, 6.3.3: initial alignment after AHRSreq*/NMEAreq
ON_REQUEST = "on_request"  # 6.1 (3)
SLEEP = "sleep"  # 6.1 (5), 6.3.8
CALIBRATION_AWAITING_PARAMETERS = "calibration_awaiting_parameters"  # 6.4.1, 6.4.8: Table 6.13 block to follow
CALIBRATION_ALIGNING = "calibration_aligning"  # 6.4.1, 6.4.8: initial alignment
CALIBRATION_ACCUMULATING = "calibration_accumulating"  # 6.4.1, 6.4.8: data accumulation
CALIBRATION_DECIDING = "calibration_deciding"  # 6.4.1, 6.4.7: result sent, AcceptClb or ExitClb awaited
RUNS_AWAITING_PARAMETERS = "runs_awaiting_parameters"  # 6.4.5: Table 6.13 block to follow Start2D2TClb
RUNS_READY = "runs_ready"  # 6.4.5: between 2D-2T runs (E36)
RUN_AWAITING_PARAMETERS = "run_awaiting_parameters"  # 6.4.6: Table 6.16 block to follow StartClbRun
RUN_ALIGNING = "run_aligning"  # 6.4.5: initial alignment of a run
RUN_ACCUMULATING = "run_accumulating"  # 6.4.5: data accumulation of a run

MODES: dict[str, str] = {
    IDLE: "idle",
    AWAITING_PARAMETERS: "idle",  # LoadAHRSPar is an idle-mode command (6.3.5: Stop before any other)
    ALIGNING_CONTINUOUS: "continuous",  # 6.3: the indicator turns green when the command is received
    CONTINUOUS: "continuous",
    ALIGNING_ON_REQUEST: "on_request",
    ON_REQUEST: "on_request",
    SLEEP: "sleep",
    CALIBRATION_AWAITING_PARAMETERS: "calibration",
    CALIBRATION_ALIGNING: "calibration",
    CALIBRATION_ACCUMULATING: "calibration",
    CALIBRATION_DECIDING: "calibration",
    RUNS_AWAITING_PARAMETERS: "calibration",
    RUNS_READY: "calibration",
    RUN_AWAITING_PARAMETERS: "calibration",
    RUN_ALIGNING: "calibration",
    RUN_ACCUMULATING: "calibration",
}
STATES: tuple[str, ...] = tuple(MODES)

# Where each state's behaviour is written in the ICD, and the errata that decide what it is silent on.
SOURCES: dict[str, str] = {
    IDLE: "6.1 (1), 6.3, 6.3.1-6.3.11, 6.4.1-6.4.10; E13, E14, E25, E33, E35",
    AWAITING_PARAMETERS: "6.3.6, Table 6.9; E12, E13, E34",
    ALIGNING_CONTINUOUS: "6.3.1, 6.3.3, 6.3.5, Table 6.8; E14, E33, E35",
    CONTINUOUS: "6.1 (2), 6.3.1, 6.3.3, 6.3.5, 6.3.8, Table 6.19; E14, E33, E35",
    ALIGNING_ON_REQUEST: "6.3.2, 6.3.3, 6.3.5, Table 6.8; E14, E33, E39",
    ON_REQUEST: "6.1 (3), 6.3.2, 6.3.4, 6.3.5, 6.3.8, 6.3.11; E14, E25, E33, E35",
    SLEEP: "6.1 (5), 6.3.8, 6.3.9; E14, E33",
    CALIBRATION_AWAITING_PARAMETERS: "6.4.1, 6.4.8, Table 6.13, 6.4.4; E13, E14, E34",
    CALIBRATION_ALIGNING: "6.4.1, 6.4.8, Table 6.8, 6.4.4; E14, E33",
    CALIBRATION_ACCUMULATING: "6.4.1, 6.4.2, 6.4.8, Table 6.14, 6.4.4; E14, E33, E38",
    CALIBRATION_DECIDING: "6.4.1, 6.4.3, 6.4.4, 6.4.7, 6.4.8; E14, E33",
    RUNS_AWAITING_PARAMETERS: "6.4.5, Table 6.13, 6.4.4; E13, E14, E34, E36",
    RUNS_READY: "6.4.5, 6.4.6, 6.4.7, 6.4.4; E9, E13, E14, E29, E33, E37",
    RUN_AWAITING_PARAMETERS: "6.4.6, Table 6.16, 6.4.4; E13, E14, E34",
    RUN_ALIGNING: "6.4.5, Table 6.8, 6.4.4; E14, E33",
    RUN_ACCUMULATING: "6.4.2, 6.4.5, Table 6.15, 6.4.4; E14, E33",
}

# --- What the device sends -----------------------------------------------------------------------

ACK = "ack"  # 6.3.1 ...: "calculates the check sum of the message ... and returns it" (E12)
OUTPUT = "output"  # one block of the chosen format: Table 6.4, 6.5, 6.6 or a $PAHR sentence (6.3.1-6.3.4)
OUTPUT_SLEEP = "output_sleep"  # the same block with USW bits 7 and 15 set (Table 6.19, E35)
INITIAL_ALIGNMENT = "initial_alignment"  # Table 6.8, "block of the initial data" after every alignment
PARAMETERS_READ = "ahrs_parameters_read"  # Table 6.10 (6.3.7)
FIRMWARE_VERSION = "firmware_version"  # Table 6.11 (6.3.10)
BIT_RESULT = "bit_result"  # Table 6.12 (6.3.11)
CALIBRATION_RESULT = "calibration_result"  # Table 6.14 (6.4.1, 6.4.7, 6.4.8)
CALIBRATION_RUN_RESULT = "calibration_run_result"  # Table 6.15 (6.4.5)
CALIBRATION_STATUS = "calibration_status"  # Table 6.17 (6.4.10)

# --- What the device receives besides commands ---------------------------------------------------

PARAMETER_BLOCK = "parameter_block"  # a data message of the size the state waits for
OTHER_MESSAGE = "other_message"  # any other data message
BLOCK_TIMEOUT = "block_timeout"  # E34: "The AHRS waits 1 s" for the block
ALIGNMENT_DONE = "alignment_done"  # the initial alignment time has elapsed (6.3.1, Table 6.9)
ACCUMULATION_DONE = "accumulation_done"  # the accumulation time has elapsed (Table 6.13)
OUTPUT_DUE = "output_due"  # one output period has elapsed (6.3.1: 1-100 Hz; 6.3.3: 1-50 Hz)
UNKNOWN = "unknown"  # a command frame whose code is not in Table C.1
EVENTS: tuple[str, ...] = (BLOCK_TIMEOUT, ALIGNMENT_DONE, ACCUMULATION_DONE, OUTPUT_DUE)

# The parameter block each waiting state expects, by table (sizes from oracle.py, as printed).
EXPECTS: dict[str, str] = {
    AWAITING_PARAMETERS: "ahrs_parameters_load",  # 6.3.6: Table 6.9
    CALIBRATION_AWAITING_PARAMETERS: "calibration_parameters",  # 6.4.1, 6.4.8: Table 6.13
    RUNS_AWAITING_PARAMETERS: "calibration_parameters",  # 6.4.5: Table 6.13
    RUN_AWAITING_PARAMETERS: "calibration_run_parameters",  # 6.4.6: Table 6.16
}

# 6.4.5 note and 6.4.7 important note: "In AHRS firmware before v.4.9.9.0 to finish the 2D-2T
# calibration the StopClb command (code 0x20) was used instead of FinishClb (code 0x2C)."
STOPCLB_FINISHES_BEFORE = (4, 9, 9, 0)

Reaction = tuple[str, tuple[str, ...]]  # (next state, what is sent)


def version(text: str) -> tuple[int, ...]:
    """A firmware version such as "4.9.8.0", compared part by part as numbers (4.10 is after 4.9)."""
    return tuple(int(part) for part in text.split("."))


def is_legacy(firmware: str | None) -> bool:
    """Firmware older than 4.9.9.0 (None: current firmware)."""
    return firmware is not None and version(firmware) < STOPCLB_FINISHES_BEFORE


def block_size(state: str) -> int | None:
    table = EXPECTS.get(state)
    return None if table is None else o.TABLES[table][1]


def command_event(code: int, state: str) -> str:
    """The command a received code is. 0xFE is two rows of Table C.1; E14: "0xFE decodes to both
    names. In calibration mode it is ExitClb and is acknowledged; in any other mode it is Stop and
    gets no answer." A code not in Table C.1 is `unknown`."""
    names = o.command_names(code)
    if not names:
        return UNKNOWN
    if len(names) == 1:
        return names[0]
    assert names == ["ExitClb", "Stop"], names
    return "ExitClb" if MODES[state] == "calibration" else "Stop"


def data_event(size: int, state: str) -> str:
    """A data message is the parameter block when the state waits for a block of that size."""
    return PARAMETER_BLOCK if size == block_size(state) else OTHER_MESSAGE


def react(state: str, event: str, firmware: str | None = None) -> Reaction | None:
    """What the device does on `event` in `state`, or None: it ignores the event.

    E33: "A command with no transition in the current state is ignored; no answer, no change of
    state." (The ICD says in which mode a command is valid, never what an invalid one does.)
    """
    if state in EXPECTS:
        return _awaiting_block(state, event)
    handler = {
        IDLE: _idle,
        ALIGNING_CONTINUOUS: _aligning,
        ALIGNING_ON_REQUEST: _aligning,
        CALIBRATION_ALIGNING: _aligning,
        RUN_ALIGNING: _aligning,
        CONTINUOUS: _continuous,
        ON_REQUEST: _on_request,
        SLEEP: _sleep,
        CALIBRATION_ACCUMULATING: _accumulating,
        RUN_ACCUMULATING: _accumulating,
        CALIBRATION_DECIDING: _deciding,
        RUNS_READY: _between_runs,
    }[state]
    return handler(state, event, is_legacy(firmware))


def _idle(state: str, event: str, legacy: bool) -> Reaction | None:
    # 6.3: "The program works in the waiting mode of the commands."
    if event in ("AHRScont1", "AHRScont2", "AHRScont3", "NMEAcont"):
        # 6.3.1, 6.3.3: "the AHRS answers back immediately on this command prior to completion of
        # the initial alignment process", then "starts process of initial alignment".
        return ALIGNING_CONTINUOUS, (ACK,)
    if event in ("AHRSreq1", "AHRSreq2", "AHRSreq3", "NMEAreq"):
        return ALIGNING_ON_REQUEST, (ACK,)  # 6.3.2, 6.3.3: the same answer and alignment
    if event == "Stop":
        # 6.3.5: "stops work in an operating mode and goes to the idle mode"; it is there already.
        # E14: Stop "gets no answer".
        return IDLE, ()
    if event == "LoadAHRSPar":
        # 6.3.6: the Table 6.9 block "should be sent without pause after sending the LoadAHRSPar
        # command". E13: "The command gets no answer; the parameter block gets the acknowledgement."
        return AWAITING_PARAMETERS, ()
    if event == "ReadAHRSPar":
        return IDLE, (PARAMETERS_READ,)  # 6.3.7: "sends out the message with ... Table 6.10"
    if event == "GetVerFirmware":
        return IDLE, (FIRMWARE_VERSION,)  # 6.3.10: Table 6.11
    if event == "GetBIT":
        return IDLE, (BIT_RESULT,)  # 6.3.11: "in Idle or On Request operation mode"; Table 6.12
    if event == "LowPowerOn":
        # 6.3.8: "switches the AHRS to low power Sleep mode ... No outputs are from the AHRS".
        # E35: "from idle and on-request mode it sleeps without a block".
        return SLEEP, ()
    if event in ("Start2DClb", "Start3DClb"):
        # 6.4.1, 6.4.8: the command is "followed by message with block of parameters listed in the
        # Table 6.13"; E13: the command itself gets no answer.
        return CALIBRATION_AWAITING_PARAMETERS, ()
    if event == "Start2D2TClb":
        return RUNS_AWAITING_PARAMETERS, ()  # 6.4.5, E13
    if event == "ClearClb":
        return IDLE, (ACK,)  # 6.4.9: "The AHRS answers on this command" with the check sum
    if event == "GetClbRes":
        return IDLE, (CALIBRATION_STATUS,)  # 6.4.10: Table 6.17
    # GetDataReq (6.3.4: valid only after a request command), LowPowerOff (6.3.9: wakes from
    # Sleep), the calibration commands that need a calibration in progress (6.4.2-6.4.7), data
    # messages and timers: ignored (E33).
    return None


def _awaiting_block(state: str, event: str) -> Reaction | None:
    # E34: "The AHRS waits 1 s. A block of the expected size is acknowledged; anything else (no
    # block, a command, a data message of another size) abandons the command without an answer
    # and returns to idle (to between-runs for StartClbRun). ExitClb is still acknowledged in
    # calibration."
    abandon = RUNS_READY if state == RUN_AWAITING_PARAMETERS else IDLE
    if event == PARAMETER_BLOCK:
        # 6.3.6, 6.4.1, 6.4.5, 6.4.6, 6.4.8: "The AHRS calculates the check sum of received
        # parameters and returns it for a checking."
        after = {
            AWAITING_PARAMETERS: IDLE,  # 6.3.6: the parameters are stored; nothing else starts
            CALIBRATION_AWAITING_PARAMETERS: CALIBRATION_ALIGNING,  # 6.4.1, 6.4.8: "Then ... alignment"
            # E36: "After the Start2D2TClb block the AHRS waits for the first StartClbRun (no
            # alignment yet); alignment runs at the start of each run."
            RUNS_AWAITING_PARAMETERS: RUNS_READY,
            RUN_AWAITING_PARAMETERS: RUN_ALIGNING,  # 6.4.5: after StartClbRun and its message
        }[state]
        return after, (ACK,)
    if event == "ExitClb" and MODES[state] == "calibration":
        return IDLE, (ACK,)  # 6.4.4 and E34's last sentence
    if event in (ALIGNMENT_DONE, ACCUMULATION_DONE, OUTPUT_DUE):
        return None  # no timer runs while a block is awaited: nothing was received
    # Every received message other than the block, whatever its code (an unknown code too: it
    # is "anything else"), and the 1 s timeout.
    return abandon, ()


def _aligning(state: str, event: str, legacy: bool) -> Reaction | None:
    if event == ALIGNMENT_DONE:
        # 6.3.1-6.3.3: "After completing of the initial alignment the AHRS gives out message with
        # block of the initial data (payload is 50 bytes of the data - see the Table 6.8) and goes
        # to the 'Continuous' [or 'On Request'] operating mode". 6.4.1, 6.4.5, 6.4.8: the same
        # block, then "starts data accumulation".
        after = {
            ALIGNING_CONTINUOUS: CONTINUOUS,
            ALIGNING_ON_REQUEST: ON_REQUEST,
            CALIBRATION_ALIGNING: CALIBRATION_ACCUMULATING,
            RUN_ALIGNING: RUN_ACCUMULATING,
        }[state]
        return after, (INITIAL_ALIGNMENT,)
    if MODES[state] == "calibration":
        return _exit_calibration(event)
    if event == "Stop":
        return IDLE, ()  # 6.3.5; E14: no answer
    # The alignment is not yet the Continuous or On Request operating mode (6.3.1, 6.3.2: the
    # AHRS "goes to" that mode after it): GetDataReq (E39: "during alignment it is ignored"),
    # GetBIT and LowPowerOn, valid in those modes, are not heard yet.
    return None


def _continuous(state: str, event: str, legacy: bool) -> Reaction | None:
    if event == OUTPUT_DUE:
        # 6.3.1: "Data blocks are transmitted according to chosen variant of output data" at the
        # update rate; 6.3.3: NMEA sentences at up to 50 Hz.
        return CONTINUOUS, (OUTPUT,)
    if event == "Stop":
        return IDLE, ()  # 6.3.5, E14
    if event == "LowPowerOn":
        # Table 6.19: bits 7 and 15 are 1 "in the last data block sent by the AHRS before it went
        # to Sleep mode". E35: "In continuous mode the AHRS sends one last output block with the
        # sleep mode bits set, then sleeps".
        return SLEEP, (OUTPUT_SLEEP,)
    # GetBIT: 6.3.11 names Idle and On Request only. GetDataReq: 6.3.4, On Request only.
    return None


def _on_request(state: str, event: str, legacy: bool) -> Reaction | None:
    if event == "GetDataReq":
        # 6.3.2: "the AHRS sends only one data block after each request command GetDataReq";
        # 6.3.4: Table 6.4, 6.5 or 6.6, or Table 6.7 after NMEAreq.
        return ON_REQUEST, (OUTPUT,)
    if event == "GetBIT":
        # 6.3.11: "The USW can be got in any time if the AHRS is in Idle or 'On Request' operation
        # mode"; E25: "GetBIT is valid in idle and on_request."
        return ON_REQUEST, (BIT_RESULT,)
    if event == "Stop":
        return IDLE, ()  # 6.3.5, E14
    if event == "LowPowerOn":
        # E35: "from idle and on-request mode it sleeps without a block" ("in the other modes no
        # block is due").
        return SLEEP, ()
    return None


def _sleep(state: str, event: str, legacy: bool) -> Reaction | None:
    # 6.1 (5), 6.3.8: "No outputs are from the AHRS, Its microprocessor only waits command from
    # the host computer to exit from the Sleep mode."
    if event == "LowPowerOff":
        # 6.3.9: "awakes the AHRS from the Sleep mode and switches it to the idle mode"; no answer
        # is described.
        return IDLE, ()
    return None


def _exit_calibration(event: str) -> Reaction | None:
    # 6.4.4: ExitClb "is used to exit from the calibration without any calculations ... and goes
    # into the idle mode. The AHRS answers on this command" with the check sum. E14.
    if event == "ExitClb":
        return IDLE, (ACK,)
    return None


def _accumulating(state: str, event: str, legacy: bool) -> Reaction | None:
    # 6.4.2: StopClbRun "early stops data accumulation in the calibration run before set
    # accumulation time is reached. Then the calibration procedure continues in the same way as
    # after set accumulation time was reached." (Firmware before 4.9.9.0 called 0x20 StopClb and
    # it stopped a run the same way: revision 1.5.)
    if event in (ACCUMULATION_DONE, "StopClbRun"):
        if state == CALIBRATION_ACCUMULATING:
            # 6.4.1, 6.4.8: the parameters are computed (<0.5 s; E38: sent at once) and "the AHRS
            # gives out message with the calibration results (see the Table 6.14) and it waits"
            # for AcceptClb or ExitClb.
            return CALIBRATION_DECIDING, (CALIBRATION_RESULT,)
        # 6.4.5: "the AHRS gives out message with result of the calibration run (see the Table
        # 6.15)" and "waits one of the next three commands": StartClbRun, FinishClb, ExitClb.
        return RUNS_READY, (CALIBRATION_RUN_RESULT,)
    return _exit_calibration(event)


def _deciding(state: str, event: str, legacy: bool) -> Reaction | None:
    if event == "AcceptClb":
        # 6.4.3: "to accept the calibration parameters and to save them"; 6.4.1: "The AHRS answers
        # on these commands with checksum and goes to idle mode."
        return IDLE, (ACK,)
    return _exit_calibration(event)


def _between_runs(state: str, event: str, legacy: bool) -> Reaction | None:
    # 6.4.5: after each run "it waits one of the next three commands".
    if event == "StartClbRun":
        # 1. "StartClbRun command followed by its message (see section 6.4.6) to start new
        # calibration run"; E13: the command gets no answer, its block does.
        return RUN_AWAITING_PARAMETERS, ()
    if event == "FinishClb":
        # 2. "FinishClb command ... to finish the calibration procedure and to calculate
        # calibration parameters. After that the AHRS gives out message with the calibration
        # results (see the Table 6.14) and waits" for AcceptClb or ExitClb (6.4.7). E37: "FinishClb
        # is accepted between runs at any time". E9: "the spec does not gate commands by firmware
        # version except StopClb (E29)", so older firmware is not refused FinishClb either.
        return CALIBRATION_DECIDING, (CALIBRATION_RESULT,)
    if event == "StopClbRun" and legacy:
        # 6.4.5 note, 6.4.7: before 4.9.9.0 StopClb (0x20) finished the 2D-2T calibration "instead
        # of FinishClb". E29: "the former name is documentation and a device-model option".
        return CALIBRATION_DECIDING, (CALIBRATION_RESULT,)
    # 3. ExitClb. A current StopClbRun has no run to stop here (6.4.2): ignored.
    return _exit_calibration(event)


@dataclass(frozen=True)
class Step:
    event: str
    state: str
    send: tuple[str, ...]

    def expect(self) -> dict[str, object]:
        return {"event": self.event, "state": self.state, "send": list(self.send)}


Input = tuple[str, int | str]  # ("command", code), ("data", payload size) or ("event", name)


class Device:
    """The device from power-up (6.3: idle), fed one received message or elapsed timer at a time."""

    def __init__(self, firmware: str | None = None) -> None:
        self.firmware = firmware
        self.state = IDLE

    def feed(self, item: Input) -> Step:
        kind, value = item
        if kind == "command":
            assert isinstance(value, int)
            event = command_event(value, self.state)
        elif kind == "data":
            assert isinstance(value, int)
            event = data_event(value, self.state)
        else:
            assert kind == "event" and isinstance(value, str) and value in EVENTS, item
            event = value
        reaction = react(self.state, event, self.firmware)
        send: tuple[str, ...] = ()
        if reaction is not None:
            self.state, send = reaction
        return Step(event, self.state, send)

    def run(self, items: Iterable[Input]) -> list[Step]:
        return [self.feed(item) for item in items]


def inputs() -> list[Input]:
    """Every distinct thing a device can receive or have happen, in a fixed order: each code of
    Table C.1 in table order (0xFE once), an unknown code, a data message of each parameter block
    size and of a size no block has, then the timers."""
    codes: list[int] = []
    for row in o.table_c1():
        if row.code not in codes:
            codes.append(row.code)
    sizes = sorted({o.TABLES[t][1] for t in EXPECTS.values()})
    odd = next(n for n in range(1, 60) if n not in sizes and all(o.TABLES[t][1] != n for t in o.TABLES))
    return [
        *(("command", c) for c in codes),
        ("command", next(c for c in range(256) if not o.command_names(c))),
        *(("data", n) for n in sizes),
        ("data", odd),
        *(("event", e) for e in EVENTS),
    ]


def reach() -> dict[str, list[Input]]:
    """For every state, the shortest sequence of inputs from power-up that ends there (breadth
    first, inputs in the order of `inputs`, so the result is fixed)."""
    paths: dict[str, list[Input]] = {IDLE: []}
    frontier = [IDLE]
    while frontier:
        following: list[str] = []
        for state in frontier:
            for item in inputs():
                device = Device()
                device.run(paths[state])
                device.feed(item)
                if device.state not in paths:
                    paths[device.state] = [*paths[state], item]
                    following.append(device.state)
        frontier = following
    assert set(paths) == set(STATES), set(STATES) - set(paths)
    return {s: paths[s] for s in STATES}
