"""Filters and globals for the behaviour modules of the Python target: the state-machine table,
the device model, the host session and the virtual device.

Everything about the protocol is read from the model (calibration types of the start commands,
transition effects, timer fields, the serial line, the minimum number of 2D-2T runs). What is
written here is the library's own design: which command each convenience method of the serial
client sends, and which synthetic quantity fills each device-to-host field.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from typing import Any

from generator.model import TIMER_EVENTS, Field, Payload, Spec, Transition

# --- The serial client's convenience methods (library design), checked against the model ----------

# The commands the serial client's convenience methods send, by role.
ROLES = {
    "stop": "Stop",
    "exit": "ExitClb",
    "read_parameters": "ReadAHRSPar",
    "load_parameters": "LoadAHRSPar",
    "get_data": "GetDataReq",
    "firmware": "GetVerFirmware",
    "bit": "GetBIT",
    "low_power_on": "LowPowerOn",
    "low_power_off": "LowPowerOff",
    "start_multi_run": "Start2D2TClb",
    "start_run": "StartClbRun",
    "stop_run": "StopClbRun",
    "finish": "FinishClb",
    "accept": "AcceptClb",
    "clear_calibration": "ClearClb",
    "calibration_results": "GetClbRes",
}

# --- Which synthetic quantity fills a device-to-host field ----------------------------------------

_ANGLES = ("heading", "pitch", "roll")
_ADC_PREFIXES = {
    "ugyro_": "adc_gyro_",
    "uacc_": "adc_acc_",
    "umag_": "adc_mag_",
    "gyro_bias_": "adc_gyro_",
    "average_acc_": "adc_acc_",
    "average_mag_": "adc_mag_",
    "hm_0_": "hard_iron_",
}
_AXIS_UNITS = {"deg_per_s": "rate_", "g": "acc_", "nT": "mag_"}


def quantity(field: Field) -> tuple[str, ...]:
    """The synthetic quantities that fill `field` in the virtual device, in engineering units (the
    field's unit): one name, or one per multiplexed quantity in turn (Table 6.4 notes 2 and 3), or
    () for a field left at its default (reserved bytes).

    By unit and name: angles (deg) by their last word; rates, accelerations and magnetic fields by
    unit and axis; quaternion components `lk0..lk3` -> `q0..q3`; temperatures (degC) ->
    `temperature`; voltages (V) -> the input voltage, then the stabilised sensor supply; ADC codes
    by sensor; soft-iron matrix `tm_c_RC` -> `soft_iron_RC`; percent -> `data_used`; the USW
    encoding -> `usw`. Any other field is filled from the device's context value of the same name
    (calibration type, runs, success, firmware version ...), or keeps its default.
    """
    name = field.name
    unit = field.unit.key if field.unit is not None else None
    if field.kind == "reserved":
        return ()
    if field.encoding == "usw":
        return ("usw",)
    axis = name[-1] if re.search(r"_[xyz]$", name) else None
    if unit == "deg":
        for angle in _ANGLES:
            if name == angle or name.endswith("_" + angle):
                return (angle,)
    if unit in _AXIS_UNITS and axis is not None:
        return (_AXIS_UNITS[unit] + axis,)
    if unit == "one":
        match = re.fullmatch(r"lk(\d)", name)
        if match:
            return ("q" + match.group(1),)
        if name.startswith("tm_c_"):
            return ("soft_iron_" + name.removeprefix("tm_c_"),)
    if unit == "degC":
        return ("temperature",)
    if unit == "V":
        both = ("vdd_input", "vdd_sensors")
        return both[: field.multiplexed_count] if field.multiplexed_count else both[:1]
    if unit == "adc":
        if field.multiplexed_count:
            return tuple(f"adc_temp_{i + 1}" for i in range(field.multiplexed_count))
        for prefix, source in _ADC_PREFIXES.items():
            if name.startswith(prefix):
                return (source + name.removeprefix(prefix),)
    if unit == "percent":
        return ("data_used",)
    return (name,)


def fill_rows(payload: Payload) -> list[tuple[Any, ...]]:
    """One row per field: (name, quantities, multiplier, divisor or variant parameter, low, high, kind).
    The device converts engineering values to raw with them (round half away from zero, then
    saturate to the bounds like a real sensor; angles wrap)."""
    rows: list[tuple[Any, ...]] = []
    for f in payload.fields:
        bounds = f.bounds
        scale = f.scale
        multiplier = scale.multiplier if scale is not None else 1
        divisor: int | str = 1
        if scale is not None:
            divisor = scale.divisor_parameter.lower() if scale.divisor_parameter else (scale.divisor or 1)
        low = bounds[0] if bounds is not None else None
        high = bounds[1] if bounds is not None else None
        rows.append((f.name, quantity(f), multiplier, divisor, low, high, f.kind))
    return rows


# --- The state machine, as the generated table holds it ------------------------------------------


def transitions(spec: Spec, legacy: bool = False) -> list[Transition]:
    """The expanded transitions: the current ones (one per (state, event)), or only the rows that
    apply before a firmware version."""
    sm = spec.state_machine
    assert sm is not None
    return [t for t in sm.transitions if (t.firmware_before is not None) == legacy]


def timer_field(spec: Spec, timer: str) -> tuple[str, str]:
    """(payload, field) of the host-to-device parameter that sets a timer (`state_machine.timers`)."""
    assert spec.state_machine is not None
    entry = spec.state_machine.timer(timer)
    return entry.payload, entry.field


_PARITY = {"none": "N", "even": "E", "odd": "O"}


def serial_line(spec: Spec) -> dict[str, Any]:
    """The serial line of the spec in pyserial's terms."""
    line = spec.serial_line
    if line is None:
        raise KeyError("the spec has no serial_line")
    return {
        "baudrate": line.baud_rate,
        "bytesize": line.data_bits,
        "parity": _PARITY[line.parity],
        "stopbits": line.stop_bits,
    }


def output_formats(spec: Spec) -> dict[str, str | None]:
    """Output format (a start command's `starts.output`) -> payload name, or None for $PAHR
    sentences (the format named after the spec's `nmea` section)."""
    names = {p.name for p in spec.payloads}
    result: dict[str, str | None] = {}
    for c in spec.commands:
        if c.starts_output is None or c.starts_output in result:
            continue
        if c.starts_output in names:
            result[c.starts_output] = c.starts_output
        elif c.starts_output == "nmea" and spec.nmea is not None:
            result[c.starts_output] = None
        else:
            raise KeyError(f"{c.name} starts output {c.starts_output!r}: neither a payload nor the nmea sentence")
    return result


def default_firmware(spec: Spec) -> str:
    """The newest firmware version the spec mentions: a device that has every current behaviour."""
    sm = spec.state_machine
    versions = [t.firmware_before for t in sm.transitions if t.firmware_before] if sm is not None else []
    for c in spec.commands:
        versions += [f.until_firmware for f in c.former_names if f.until_firmware]
    if not versions:
        return "0"
    return max(versions, key=lambda v: tuple(int(p) for p in v.split(".")))


def behaviour(spec: Spec) -> dict[str, Any]:
    """Check the mappings above against the model and return them for the templates."""
    sm = spec.state_machine
    if sm is None:
        raise KeyError("the spec has no state_machine")
    for name in ROLES.values():
        spec.command(name)
    calibration_enum = spec.enum("calibration_type")
    by_name = {v.name: v.value for v in calibration_enum.values}
    calibration_types = {c.name: by_name[c.begins_calibration] for c in spec.commands if c.begins_calibration}
    commands = {c.name for c in spec.commands}
    effects = {t.event: t.effect for t in sm.transitions if t.effect is not None and t.event in commands}
    if sm.min_successful_runs is None:
        raise KeyError("the spec's state_machine has no calibration.min_successful_runs")
    timers = sorted({s.timer for s in sm.states if s.timer is not None})
    return {
        **_payload_roles(spec),
        "calibration_types": calibration_types,
        "effects": effects,
        "min_successful_runs": sm.min_successful_runs,
        "serial_line": serial_line(spec),
        "roles": ROLES,
        "timer_fields": {timer: timer_field(spec, timer) for timer in timers if timer in TIMER_EVENTS},
        "timer_events": {timer: TIMER_EVENTS[timer] for timer in timers},
        "output_formats": output_formats(spec),
        "default_firmware": default_firmware(spec),
    }


# The context values the device model fills calibration results with, by meaning -> field quantity.
CALIBRATION_FIELDS = {
    "type": "calibration_type",
    "run": "run",
    "runs_used": "runs_used",
    "data_used": "data_used",
    "success": "success",
}
# Parameters (Table 6.10 form) the motion and sensor model reads, by meaning -> field.
PHYSICS_FIELDS = {"latitude": "latitude"}


def _char_field(payload: Payload) -> str:
    return next(f.name for f in payload.fields if f.kind == "char")


def _payload_roles(spec: Spec) -> dict[str, Any]:
    """The payload tables the device model treats specially, found through the commands that send
    or take them, and the fields it fills from its own context."""
    read = spec.payload(spec.command(ROLES["read_parameters"]).response_payloads[0])
    load_name = spec.command(ROLES["load_parameters"]).parameter_block
    assert load_name is not None
    final = spec.command(ROLES["finish"]).response_payloads[0]
    runs = [p for p in spec.command(ROLES["stop_run"]).response_payloads if p != final]
    status = spec.command(ROLES["calibration_results"]).response_payloads[0]
    firmware = spec.payload(spec.command(ROLES["firmware"]).response_payloads[0])
    quantities = {q for name in (final, *runs) for f in spec.payload(name).fields for q in quantity(f)}
    for meaning, name in CALIBRATION_FIELDS.items():
        if name not in quantities:
            raise KeyError(f"no calibration result field carries {meaning} ({name!r})")
    for name in PHYSICS_FIELDS.values():
        read.field(name)
    declination = next(f.name for f in read.fields if f.encoding == "declination")
    status_word = spec.status_word
    assert status_word is not None
    return {
        "read_block": read.name,
        "load_block": load_name,
        "final_result": final,
        "run_result": runs[0],
        "status_block": status,
        "firmware_block": firmware.name,
        "firmware_field": _char_field(firmware),
        "device_id_field": _char_field(read),
        "declination_field": declination,
        "physics_fields": PHYSICS_FIELDS,
        "calibration_fields": CALIBRATION_FIELDS,
        "usw_modes": {m.name: status_word.mode_pattern(m) for m in status_word.modes},
    }


def nmea_quantity(name: str, unit: str) -> str:
    """The synthetic quantity of a $PAHR field: angles by name, degC -> temperature, V -> the input
    voltage, anything else (the USW) by name."""
    if unit == "degC":
        return "temperature"
    if unit == "V":
        return "vdd_input"
    return name


def mermaid(spec: Spec) -> str:
    """The state machine as a Mermaid state diagram: one edge per (state, next state), labelled
    with the events and what is sent (`*` rows folded into one `*` label)."""
    sm = spec.state_machine
    assert sm is not None
    lines = ["stateDiagram-v2", f"    [*] --> {sm.initial}"]
    edges: dict[tuple[str, str], list[str]] = {}
    for t in transitions(spec):
        label = "*" if t.wildcard else t.event
        if t.send:
            label += " / " + " ".join(t.send)
        labels = edges.setdefault((t.state, t.to), [])
        if label not in labels:
            labels.append(label)
    for t in transitions(spec, True):
        label = f"{t.event} (firmware before {t.firmware_before}) / " + " ".join(t.send)
        edges.setdefault((t.state, t.to), []).append(label)
    for (state, to), labels in edges.items():
        lines.append(f"    {state} --> {to}: {', '.join(labels)}")
    return "\n".join(lines) + "\n"


def py_text(text: str, indent: int, width: int = 116) -> str:
    """A string literal that fits the line length: one literal, or implicitly concatenated pieces
    in parentheses, each on its own line at `indent` (+4) spaces."""
    if indent + len(repr(text)) <= width - 8:
        return repr(text)
    pieces: list[str] = []
    current = ""
    for word in re.split(r"(?<= )(?=[^ ])", text):
        if current and indent + 4 + len(repr(current + word)) > width:
            pieces.append(current)
            current = word
        else:
            current += word
    pieces.append(current)
    pad = " " * (indent + 4)
    return "(\n" + "".join(f"{pad}{piece!r}\n" for piece in pieces) + " " * indent + ")"


def py_dict(value: dict[Any, Any], indent: int = 0, width: int = 100) -> str:
    """A dict literal: on one line if it fits, else one entry per line."""
    text = repr(value)
    if indent + len(text) <= width:
        return text
    pad = " " * (indent + 4)
    return "{\n" + "".join(f"{pad}{k!r}: {v!r},\n" for k, v in value.items()) + " " * indent + "}"


def py_row(row: tuple[Any, ...], indent: int, width: int = 118) -> str:
    """A tuple literal with double-quoted strings: on one line if it fits, else one item per line."""
    items = [repr(item).replace("'", '"') for item in row]
    text = "(" + ", ".join(items) + ("," if len(items) == 1 else "") + ")"
    if indent + len(text) + 1 <= width:
        return text
    pad = " " * (indent + 4)
    return "(\n" + "".join(f"{pad}{item},\n" for item in items) + " " * indent + ")"


FILTERS: dict[str, Callable[..., Any]] = {
    "quantity": quantity,
    "fill_rows": fill_rows,
    "nmea_quantity": nmea_quantity,
    "py_text": py_text,
    "py_dict": py_dict,
    "py_row": py_row,
}

GLOBALS: dict[str, Callable[..., Any]] = {
    "behaviour": behaviour,
    "mermaid": mermaid,
    "transitions": transitions,
}
