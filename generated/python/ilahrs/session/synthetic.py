# Copied from generator/targets/python/runtime/session/synthetic.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""Which synthetic quantity the virtual AHRS puts in which field, stated once, by the field's unit
and name (the spec's units and field names).

The device model (`ilahrs.session.device`) computes quantities in engineering units (the field's unit)
from its motion and sensor model and its own context, then fills each device-to-host field with
the quantity named here. This module uses the standard library only and no other module of the
package, so the generator reads the same rule when it checks the spec against it.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from typing import Final

__all__ = ["quantity"]

_ANGLES: Final = ("heading", "pitch", "roll")
_AXIS_QUANTITIES: Final = {"deg_per_s": "rate_", "g": "acc_", "nT": "mag_"}
"""Unit of a per-axis field -> the quantity it carries, completed by the axis (x, y, z)."""
_ADC_PREFIXES: Final = {
    "ugyro_": "adc_gyro_",
    "uacc_": "adc_acc_",
    "umag_": "adc_mag_",
    "gyro_bias_": "adc_gyro_",
    "average_acc_": "adc_acc_",
    "average_mag_": "adc_mag_",
    "hm_0_": "hard_iron_",
}
"""Name prefix of an ADC-code field -> the quantity, completed by the rest of the name."""
_VOLTAGES: Final = ("vdd_input", "vdd_sensors")
"""The voltages in turn: the AHRS input, then the stabilised sensor supply."""

_Rule = Callable[[str, int], tuple[str, ...] | None]


def _angle(name: str, multiplexed: int) -> tuple[str, ...] | None:
    del multiplexed
    for angle in _ANGLES:
        if name == angle or name.endswith("_" + angle):
            return (angle,)
    return None


def _dimensionless(name: str, multiplexed: int) -> tuple[str, ...] | None:
    del multiplexed
    match = re.fullmatch(r"lk(\d)", name)
    if match:
        return ("q" + match.group(1),)
    if name.startswith("tm_c_"):
        return ("soft_iron_" + name.removeprefix("tm_c_"),)
    return None


def _voltage(name: str, multiplexed: int) -> tuple[str, ...]:
    del name
    return _VOLTAGES[:multiplexed] if multiplexed else _VOLTAGES[:1]


def _adc(name: str, multiplexed: int) -> tuple[str, ...] | None:
    if multiplexed:
        return tuple(f"adc_temp_{i + 1}" for i in range(multiplexed))
    for prefix, source in _ADC_PREFIXES.items():
        if name.startswith(prefix):
            return (source + name.removeprefix(prefix),)
    return None


_BY_UNIT: Final[dict[str, _Rule]] = {
    "deg": _angle,
    "one": _dimensionless,
    "degC": lambda name, multiplexed: ("temperature",),
    "V": _voltage,
    "adc": _adc,
    "percent": lambda name, multiplexed: ("data_used",),
}


def quantity(name: str, unit: str | None, wire_type: str, encoding: str | None, multiplexed: int) -> tuple[str, ...]:
    """The synthetic quantities that fill a field, in engineering units (the field's unit): one
    name, or one per multiplexed quantity in turn (Table 6.4 notes 2 and 3), or () for a field left
    at its default (reserved bytes).

    By unit and name: angles (deg) by their last word; rates, accelerations and magnetic fields by
    unit and axis; quaternion components `lk0..lk3` -> `q0..q3`; temperatures (degC) ->
    `temperature`; voltages (V) -> the input voltage, then the stabilised sensor supply; ADC codes
    by sensor; soft-iron matrix `tm_c_RC` -> `soft_iron_RC`; percent -> `data_used`; the USW
    encoding -> `usw`. Any other field is filled from the device's context value of the same name
    (calibration type, runs, success, firmware version ...), or keeps its default.
    """
    if wire_type == "reserved":
        return ()
    if encoding == "usw":
        return ("usw",)
    if unit in _AXIS_QUANTITIES and re.search(r"_[xyz]$", name):
        return (_AXIS_QUANTITIES[unit] + name[-1],)
    rule = _BY_UNIT.get(unit or "")
    found = rule(name, multiplexed) if rule is not None else None
    return found if found is not None else (name,)
