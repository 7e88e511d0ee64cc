"""The C target: a header and a source to vendor (generated/c/), plus build files and an example."""

from __future__ import annotations

from generator.model import TIMER_EVENTS, Spec
from generator.render import Output

from . import filters, machine, tables

__all__ = ["FILTERS", "GLOBALS", "outputs"]

FILTERS = filters.FILTERS
GLOBALS = {
    "kinds": tables.KINDS,
    "no_parameter": tables.NO_PARAMETER,
    "frame_header_name": tables.FRAME_HEADER_NAME,
    "frame_payload_name": tables.FRAME_PAYLOAD_NAME,
    "nmea_suffix": filters.nmea_suffix,
    "macro": filters.macro,
    "field_doc": filters.field_doc,
    "response_doc": filters.response_doc,
}


# The $PAHR field reader saturates magnitudes here (ilahrs.c, SATURATED): every range must lie below.
PAHR_SATURATED = 0x0FFFFFFF


def outputs(spec: Spec) -> list[Output]:
    t = tables.build_tables(spec)
    pahr_types = ("int32_t", "int32_t")
    if spec.nmea is not None:
        lows = [f.min for f in spec.nmea.fields]
        highs = [f.max for f in spec.nmea.fields]
        if max(abs(v) for v in lows + highs) >= PAHR_SATURATED:
            raise ValueError("a $PAHR range reaches the C reader's saturation value")
        pahr_types = (filters.c_int_type(min(lows), max(lows)), filters.c_int_type(min(highs), max(highs)))
    usw_flags = 0
    if spec.status_word is not None:
        for flag in spec.status_word.flags:
            usw_flags |= flag.mask
    context = {
        "t": t,
        "max_per_code": max(len(spec.commands_with_code(code)) for code in spec.codes),
        "member_type": tables.member_type(spec),
        "usw_flags_mask": usw_flags,
        "response_kinds": tables.response_kinds(spec),
        "canon": tables.canonical_layout(spec),
        "max_response_payloads": max(1, *(len(c.response_payloads) for c in spec.commands)),
        "m": machine.build_machine(spec),
        "pahr_min_type": pahr_types[0],
        "pahr_max_type": pahr_types[1],
        "timer_names": dict(sorted(TIMER_EVENTS.items())),
    }
    return [
        Output("c/ilahrs.h", "ilahrs.h.j2", context),
        Output("c/ilahrs.c", "ilahrs.c.j2", context),
        Output("c/CMakeLists.txt", "CMakeLists.txt.j2"),
        Output("c/ilahrs.pc.in", "ilahrs.pc.in.j2"),
        Output("c/README.md", "README.md.j2"),
        Output("c/examples/decode_capture.c", "decode_capture.c.j2"),
    ]
