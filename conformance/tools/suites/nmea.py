"""nmea: $PAHR sentences (Table 6.7) decoded, each check of spec/README.md, and built (E16).

cases/nmea.json: "messages" names sentences (suites/messages.py); a decode case gives its input as
a message, or as "edit": {field: text}, the typical sentence with those fields' text replaced and
its checksum computed again. An encode case gives engineering values.
"""

from __future__ import annotations

import math
from typing import Any

import oracle as o

from .common import Vector, attempt, cases, expand, jsonable, phrases, vec
from .messages import Messages, sentence_values

SUITE = "nmea"


def _letter_checksum(start: dict[str, Any]) -> bytes:
    """The first sentence from `start`, stepping the roll up, whose checksum has a letter digit."""
    for roll in range(start["roll"], 18000):
        text = o.build_sentence({**start, "roll": roll})
        if text[-3] in "ABCDEF":  # XOR of ASCII is below 0x80: only the low digit can be a letter
            return text.encode()
    raise AssertionError("no sentence with a letter checksum")


def _messages(data: dict[str, Any]) -> Messages:
    """The named sentences, and three computed ones: a checksum with a letter digit (upper case as
    built, and in lower case), and the typical sentence with checksum digits that do not match."""
    messages = Messages(data["messages"])
    named = messages.named
    letter = _letter_checksum(sentence_values(data["letter_checksum"]))
    named["letter-checksum"] = letter
    named["letter-checksum-lower"] = letter[:-4] + letter[-4:-2].lower() + b"\r\n"
    typical = named["typical"]
    named["wrong-checksum"] = typical[:-4] + (b"00" if typical[-4:-2] != b"00" else b"01") + b"\r\n"
    return messages


def _edited(typical: str, edit: dict[str, str]) -> str:
    """The typical sentence with some fields' text replaced, checksum computed again."""
    parts = typical[1 : typical.index("*")].split(",")
    for name, text in edit.items():
        parts[1 + [f.name for f in o.NMEA_FIELDS].index(name)] = text
    return o.sentence(",".join(parts))


def _decoded(text: str) -> Any:
    expect = attempt(lambda: o.sentence_values(o.decode_sentence(text.encode("latin-1"))))
    # Offsets for truncated, trailing_data and malformed are not stated by spec/README.md: not checked.
    if isinstance(expect, dict) and expect.get("error") in ("truncated", "trailing_data", "malformed"):
        expect.pop("offset", None)
    return expect


def _raw(values: dict[str, float | int]) -> dict[str, int]:
    """Engineering values to scaled integers, rounding half away from zero."""
    out: dict[str, int] = {}
    for f in o.NMEA_FIELDS:
        value = values[f.name]
        if f.decimals == 0:
            out[f.name] = int(value)
            continue
        if math.isnan(value):
            raise o.OracleError("out_of_range", None, f.name)
        scaled = value * 10**f.decimals
        out[f.name] = int(math.copysign(math.floor(abs(scaled) + 0.5), scaled))
    return out


def _padded(sentence: str) -> bool:
    """Whether a built sentence has a field with leading zeros: what E16's choice writes and its
    alternative (no zero padding) would not."""
    fields = sentence[sentence.index(",") + 1 : sentence.index("*")].split(",")
    return any(len(text.lstrip("-").split(".")[0]) > 1 and text.lstrip("-").startswith("0") for text in fields)


def vectors() -> list[Vector]:
    data = cases(SUITE)
    names = phrases(SUITE)
    messages = _messages(data)
    typical = messages.text("@typical")
    out: list[Vector] = []
    for case in data["decode"]:
        text = _edited(typical, case["edit"]) if "edit" in case else messages.text(case["input"])
        note = expand(case["note"], names)
        tests = case.get("tests")
        out.append(vec(f"nmea_decode/{case['name']}", "nmea_decode", text, _decoded(text), note, tests=tests))
    for case in data["encode"]:
        values = sentence_values(case["values"])
        input_ = {k: jsonable(v) for k, v in values.items()}
        expect = attempt(lambda v=values: o.build_sentence(_raw(v)))  # type: ignore[misc]
        note, tests = expand(case["note"], names), case.get("tests")
        if tests is None and isinstance(expect, str) and _padded(expect):
            tests = "E16"  # the sentence as built depends on zero padding
            note += "" if "E16" in note else "; fields zero-padded to the template width (E16)"
        out.append(vec(f"nmea_encode/{case['name']}", "nmea_encode", input_, expect, note, tests=tests))
    return out
