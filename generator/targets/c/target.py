"""The C target: a header and a source to vendor (generated/c/), plus build files and an example."""

from __future__ import annotations

import calendar
import math
import re
import struct
from dataclasses import dataclass
from pathlib import Path

from generator.formatting import run_formatter, tool
from generator.model import TIMER_EVENTS, Frame, Nmea, Spec
from generator.render import Output, Runtime, runtime_text

from . import filters, machine, tables

__all__ = ["FILTERS", "GLOBALS", "format", "fragment", "header_part", "outputs"]

# The #include lines that open a runtime .c file (after an optional comment), and the blank lines
# after them: what lets the file compile on its own, and what ilahrs.c leaves out.
INCLUDES = re.compile(r"(?:/\*(?:[^*]|\*(?!/))*\*/\n)?(?:#include [^\n]+\n)+\n*")


def fragment(source: str) -> str:
    """A runtime .c file as ilahrs.c holds it: without the includes that open it. ilahrs.c has
    what they include before it (ilahrs_internal.h's text, then the runtime files before it)."""
    text = runtime_text("c", source)
    found = INCLUDES.match(text)
    if found is None:
        raise ValueError(f"runtime/{source} does not open with its #include lines")
    return text[found.end() :]


# A banner of the header (filters.banner()): the runtime's api*.h files are cut at theirs.
BANNER = re.compile(r"^/\* =+ \*/\n/\* (.*?) *\*/\n/\* =+ \*/\n", re.MULTILINE)


def header_part(source: str, title: str | None = None) -> str:
    """The declarations under banner `title` of the runtime header `source`, without the banner,
    or those of its only banner: ilahrs.h.j2 puts each after the spec's types of its topic."""
    text = runtime_text("c", source)
    cuts = list(BANNER.finditer(text))
    if not cuts or text[: cuts[0].start()].strip():
        raise ValueError(f"runtime/{source} does not start with a banner")
    ends = [c.start() for c in cuts[1:]] + [len(text)]
    parts = {m.group(1): text[m.end() : end] for m, end in zip(cuts, ends, strict=True)}
    if title is None and len(parts) == 1:
        return next(iter(parts.values()))
    if title not in parts:
        raise ValueError(f"runtime/{source} has no banner {title!r} (it has {', '.join(parts)})")
    return parts[title]


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
    "banner": filters.banner,
    "fragment": fragment,
    "header_part": header_part,
}

# The committed clang-format configuration the generated C is formatted with (and the runtime
# checked against, by `make lint-c`).
CLANG_FORMAT_CONFIG = Path(__file__).resolve().parent / ".clang-format"


def format(files: dict[str, str]) -> dict[str, str]:
    """The generated C and headers through clang-format, with the committed configuration."""
    return run_formatter(
        files,
        (".c", ".h"),
        lambda paths: [tool("clang-format"), f"--style=file:{CLANG_FORMAT_CONFIG}", "-i", *map(str, paths)],
    )


# The $PAHR field reader saturates magnitudes here (ilahrs.c, SATURATED): every range must lie below.
PAHR_SATURATED = 0x01000000


@dataclass(frozen=True)
class DateTables:
    scale: int  # least common multiple of the term divisors
    min_key: int  # float_key of the smallest date float a decoder accepts
    max_key: int  # and of the largest
    exponent: int  # biased float32 exponent of the smallest


def nearest_float32(n: int, scale: int) -> float:
    """The float32 nearest n / scale, ties to even, as ilahrs.c (date_float()) computes it."""
    m, r = divmod(n, scale)
    exponent = 150
    while m < 0x800000:
        r, m, exponent = 2 * r, 2 * m, exponent - 1
        if r >= scale:
            r, m = r - scale, m | 1
    if 2 * r > scale or (2 * r == scale and m & 1):
        m += 1
    bits = (exponent << 23) + m - 0x800000
    value: float = struct.unpack("<f", struct.pack("<I", bits))[0]
    return value


def date_tables(spec: Spec) -> DateTables | None:
    """What the C date code needs, after checking the assumptions it rests on: the decode rule it
    implements, dates as integers below 2^24 once scaled, and float32(scaled / scale) equal to the
    double-precision formula rounded to float32 for every date in range."""
    d = spec.date
    if d is None:
        return None
    if d.decode != "nearest_calendar_date":
        raise ValueError(f"the C target does not implement date decode rule {d.decode!r}")
    scale = math.lcm(*(term.divisor for term in d.terms))
    parts = {"year": 0, "month": 1, "day": 2}
    spread = 0  # the largest |scaled - base * scale| the decoder meets (base: the year or the next)
    for year in range(d.year_min, d.year_max + 1):
        for month in range(1, 13):
            for day in range(1, calendar.monthrange(year, month)[1] + 1):
                ymd = (year, month, day)
                scaled = sum((ymd[parts[t.part]] + t.offset) * (scale // t.divisor) for t in d.terms)
                formula = 0.0
                for t in d.terms:
                    formula += (ymd[parts[t.part]] + t.offset) / t.divisor
                if not 0 < scaled < 2**24 or nearest_float32(scaled, scale) != filters.float32(formula):
                    raise ValueError(f"date {ymd}: the C encoder's exact float32 division does not apply")
                spread = max(spread, abs(scaled - year * scale), abs(scaled - (year + 1) * scale))
    # Accepted: the floats from year_min to below year_max + 2. Below year_min, and from year_max + 2,
    # no date of year_min..year_max is among the decoder's candidates (the years floor(value) - 1
    # and floor(value)); up to year_max + 2 the nearest is 30 or 31 December of year_max.
    low, high = float(d.year_min), float(d.year_max + 2)
    exponent = (struct.unpack("<I", struct.pack("<f", low))[0] >> 23) & 0xFF
    top = (struct.unpack("<I", struct.pack("<f", high))[0] >> 23) & 0xFF
    # ilahrs_date_decode() holds the value in units of 2^-(150 - exponent) in a uint32 and its
    # distances to dates, in units of 1 / (scale * 2^(150 - exponent)), in an int32.
    fraction_bits = 150 - exponent
    if (
        not 127 <= exponent <= 150
        or top > 150
        or 2**24 << (top - exponent) > 2**32
        or (spread + scale) << fraction_bits >= 2**31
        or (d.year_max + 2) * scale >= 2**31
    ):
        raise ValueError("date floats outside what the C decoder's 32-bit integers hold")
    return DateTables(scale, filters.float_key(low), filters.float_key(high) - 1, exponent)


@dataclass(frozen=True)
class FieldPacking:
    """How ilahrs_field_info_t packs a field in three columns of small numbers:
    - name_type: the name's pool offset above the type (kind, encoding, then log2 of a number's size);
    - place: the member's distance from the wire offset (struct padding so far) above the wire offset;
    - info: an array's size (char, reserved: the last kinds), else the scale index above the bounds index."""

    kind_bits: int
    encoding_bits: int
    type_bits: int
    name_type: str  # C type of name << type_bits | type
    offset_bits: int
    place: str  # C type of (member - offset) << offset_bits | offset
    bounds_bits: int
    info: str  # C type of an array's size, or scale << bounds_bits | bounds


def bits_for(count: int) -> int:
    """Bits that hold the values 0 .. count - 1 (at least one)."""
    return max(1, (count - 1).bit_length())


def packed_type(bits: int) -> str:
    if bits > 32:
        raise ValueError(f"a packed column of {bits} bits: no 32-bit C integer type holds it")
    return "uint8_t" if bits <= 8 else "uint16_t" if bits <= 16 else "uint32_t"


ARRAY_KINDS = ("char", "reserved")


def field_packing(t: tables.Tables) -> FieldPacking:
    if t.kinds[-len(ARRAY_KINDS) :] != ARRAY_KINDS:
        raise ValueError("the C field table needs the array kinds (char, reserved) last")
    kind_bits = bits_for(len(t.kinds))
    encoding_bits = bits_for(len(t.encodings))
    numbers = [r.field.size for r in t.fields if r.field.is_numeric]
    if any(size & (size - 1) for size in numbers):
        raise ValueError("the C field table holds sizes of numbers as powers of two")
    type_bits = kind_bits + encoding_bits + bits_for(max(numbers, default=1).bit_length())
    offset_bits = bits_for(max(r.field.offset for r in t.fields) + 1)
    padding_bits = bits_for(max(r.member - r.field.offset for r in t.fields) + 1)
    bounds_bits = bits_for(max(len(t.int_bounds), len(t.float_bounds)))
    arrays = [r.field.size for r in t.fields if not r.field.is_numeric]
    return FieldPacking(
        kind_bits=kind_bits,
        encoding_bits=encoding_bits,
        type_bits=type_bits,
        name_type=packed_type(bits_for(t.pools["field"].size) + type_bits),
        offset_bits=offset_bits,
        place=packed_type(offset_bits + padding_bits),
        bounds_bits=bounds_bits,
        info=packed_type(max(bounds_bits + bits_for(len(t.scales)), bits_for(max(arrays, default=0) + 1))),
    )


C_WIDTHS = {"int8_t": 1, "uint8_t": 1, "int16_t": 2, "uint16_t": 2, "int32_t": 4, "uint32_t": 4, "float": 4}


def row_members(columns: dict[str, list[int] | str]) -> list[tuple[str, str]]:
    """The members of a table row, (C type, name): a column of integers gets the smallest type that
    holds them (a string is a fixed type); widest first, so that the row has no padding inside."""
    members = [
        (kind if isinstance(kind, str) else filters.c_int_type(min(kind, default=0), max(kind, default=0)), name)
        for name, kind in columns.items()
    ]
    return sorted(members, key=lambda m: -C_WIDTHS[m[0]])


def scale_members(t: tables.Tables) -> list[tuple[str, str]]:
    return row_members(
        {
            "multiplier": [s.multiplier for s in t.scales],
            "divisor": [s.divisor for s in t.scales],
            "parameter": [s.parameter for s in t.scales],
        }
    )


def default_members(t: tables.Tables) -> list[tuple[str, str]]:
    """ilahrs_defaults: the field's row, the text pool offset of a char default (0 for a number), the
    bits of a numeric field's member."""
    return row_members(
        {
            "field": [r.field for r in t.defaults],
            "text": [max(r.text, 0) for r in t.defaults],
            "bits": "uint32_t",
        }
    )


def longest_sentence(nmea: Nmea) -> int:
    """Characters of the longest sentence ilahrs_pahr_build() writes for in-range values: a field
    is longest at one end of its range (the sign counts within the template width)."""
    total = len(nmea.identifier) + 2 + len(nmea.fields) - 1 + 5  # "$ID,", separators, "*hh" CR LF
    for f in nmea.fields:
        longest = 0
        for value in (f.min, f.max):
            sign = 1 if value < 0 else 0
            if f.format == "hex":
                chars = max(f.width, len(f"{abs(value):X}"))
            else:
                whole = len(str(abs(value) // f.divisor))
                chars = max(f.width - sign, 1, whole) + f.decimals + (1 if f.decimals else 0)
            longest = max(longest, sign + chars)
        total += longest
    return total


def frame_constants(spec: Spec) -> list[tuple[str, int, str]]:
    """The header's frame and message sizes: (macro name after ILAHRS_, value, doc)."""
    fr: Frame = spec.frame
    return [
        ("FRAME_PAYLOAD_OFFSET", fr.payload_offset, "Offset of the payload in a frame."),
        ("FRAME_CHECKSUM_SIZE", fr.checksum.size, "Size of the checksum that ends a frame."),
        ("FRAME_OVERHEAD", fr.overhead, "Bytes in a frame besides the payload."),
        ("FRAME_LENGTH_BIAS", fr.length_bias, "message_length = payload size + ILAHRS_FRAME_LENGTH_BIAS."),
        ("FRAME_MIN_LENGTH", fr.min_length, "Smallest message length a decoder accepts (E17)."),
        ("FRAME_MAX_LENGTH", fr.max_length, "Largest message length a decoder accepts (E17)."),
        ("FRAME_MIN_PAYLOAD", fr.min_payload, "Smallest payload a frame carries."),
        ("FRAME_MAX_PAYLOAD", fr.max_payload, "Largest payload a frame carries."),
        ("FRAME_MIN_SIZE", fr.min_frame_size, "Size of the shortest frame."),
        ("FRAME_MAX_SIZE", fr.max_frame_size, "Size of the longest frame: a buffer of this size holds any frame."),
        ("MAX_MESSAGE_SIZE", spec.max_message_size, "The longest message on the wire, frame or sentence."),
    ]


# Folders that carry the licence texts (render.LICENCE_FILES).
LICENSED = ("c",)


def outputs(spec: Spec) -> list[Output | Runtime]:
    if spec.byte_order != "little":
        raise ValueError(f"the C target implements little-endian wire values, not {spec.byte_order!r}")
    if spec.frame.checksum_algorithm != "sum16":
        raise ValueError(f"the C target implements the sum16 checksum, not {spec.frame.checksum_algorithm!r}")
    t = tables.build_tables(spec)
    pahr_types = ("int32_t", "int32_t")
    pahr_longest = 0
    if spec.nmea is not None:
        lows = [f.min for f in spec.nmea.fields]
        highs = [f.max for f in spec.nmea.fields]
        if max(abs(v) for v in lows + highs) >= PAHR_SATURATED:
            raise ValueError("a $PAHR range reaches the C reader's saturation value")
        pahr_types = (filters.c_int_type(min(lows), max(lows)), filters.c_int_type(min(highs), max(highs)))
        pahr_longest = longest_sentence(spec.nmea)
        filters.pahr_max_divisor(spec.nmea)  # refuses a divisor the exact rounding does not cover
        if pahr_longest > spec.nmea.max_length:
            raise ValueError(
                f"an in-range $PAHR sentence can be {pahr_longest} characters, above the maximum "
                f"{spec.nmea.max_length}: the C builder writes without length checks"
            )
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
        "max_response_payloads": max(1, *(len(c.response_payloads) for c in spec.commands)),
        "m": machine.build_machine(spec),
        "date": date_tables(spec),
        "pahr_min_type": pahr_types[0],
        "pahr_max_type": pahr_types[1],
        "pahr_saturated": PAHR_SATURATED,
        "fp": field_packing(t),
        "scale_members": scale_members(t),
        "default_members": default_members(t),
        "timer_names": dict(sorted(TIMER_EVENTS.items())),
        "frame_constants": frame_constants(spec),
    }
    return [
        Output("c/ilahrs.h", "ilahrs.h.j2", context),
        Output("c/ilahrs.c", "ilahrs.c.j2", context),
        Output("c/ilahrs_internal.h", "ilahrs_internal.h.j2", context),
        Output("c/CMakeLists.txt", "CMakeLists.txt.j2"),
        Output("c/ilahrs.pc.in", "ilahrs.pc.in.j2"),
        Output("c/README.md", "README.md.j2"),
        Runtime("c/examples/decode_capture.c", "examples/decode_capture.c"),
    ]
