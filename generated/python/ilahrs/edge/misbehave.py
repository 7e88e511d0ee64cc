# Copied from generator/targets/python/runtime/edge/misbehave.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""Test-only faults of the virtual device: a device model that breaks one rule of the protocol, so
that a conformance check can be shown to fail (`ilahrs simulate --misbehave NAME`).

Unlike the line faults of `ilahrs.edge.simulate` (damaged bytes, which a host discards), each of these
sends well-formed messages that say the wrong thing:

- `wrong-ack-checksum`: every acknowledgement carries the checksum of the message plus one (E12).
- `skip-alignment-block`: the initial alignment ends without its data block (6.3.3).
- `wrong-rate`: continuous output comes at half the configured update rate (6.3.1).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from types import MappingProxyType
from typing import Any, Final

from ..commands import COMMAND_SET
from ..frame import Frame, MessageType
from ..session.device import Device
from ..statemachine import ACK, TIMER_EVENTS, TIMER_IS_RATE

__all__ = ["MISBEHAVIOURS", "MisbehavingDevice", "device_class"]

MISBEHAVIOURS: Final[Mapping[str, str]] = MappingProxyType(
    {
        "wrong-ack-checksum": "acknowledgements carry the wrong checksum",
        "skip-alignment-block": "the initial alignment ends without its data block",
        "wrong-rate": "continuous output at half the configured update rate",
    }
)
"""Name -> what the device does wrong."""


class MisbehavingDevice(Device):
    """The device model with one misbehaviour of MISBEHAVIOURS (`misbehave`)."""

    def __init__(self, *, misbehave: str, **options: Any) -> None:
        if misbehave not in MISBEHAVIOURS:
            raise ValueError(f"no misbehaviour {misbehave!r} (known: {', '.join(MISBEHAVIOURS)})")
        super().__init__(**options)
        self.misbehave = misbehave

    def _send(self, item: str, raw: bytes | None, event: str) -> bytes:
        out = super()._send(item, raw, event)
        if self.misbehave == "skip-alignment-block" and event == TIMER_EVENTS["alignment"]:
            return b""
        if self.misbehave == "wrong-ack-checksum" and item == ACK and out:
            ack = COMMAND_SET.acknowledgement
            name = ack.FIELDS[0].name
            value = getattr(ack.parse(Frame.parse(out).payload), name)
            return Frame(MessageType.DATA, ack.from_raw({name: (value + 1) & 0xFFFF}).build()).build()
        return out

    def _duration(self, timer: str) -> float:
        seconds = super()._duration(timer)
        if self.misbehave == "wrong-rate" and TIMER_IS_RATE[timer]:
            return 2 * seconds
        return seconds


def device_class(misbehave: str | None) -> Callable[..., Device]:
    """The device model to build: Device itself, or one that misbehaves as named."""
    if misbehave is None:
        return Device

    def build(**options: Any) -> Device:
        return MisbehavingDevice(misbehave=misbehave, **options)

    return build
