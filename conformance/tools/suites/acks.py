"""acks: the acknowledgement (E12) of every Table C.1 command, of parameter blocks, and of
messages that do not decode (none)."""

from __future__ import annotations

import oracle as o

from .common import ICD, Vector, attempt, cases, expand, hx, phrases, vec
from .messages import Messages

SUITE = "acks"


def vectors() -> list[Vector]:
    names = phrases(SUITE)
    out: list[Vector] = []
    for row in o.table_c1():
        text = f"{ICD}, Table C.1 row {row.name} as printed; {names['rule']} (6.3.1)"
        out.append(vec(f"ack/{row.name}", "ack", row.icd_hex, hx(o.ack(bytes.fromhex(row.icd_hex))), text))
    messages = Messages()
    for case in cases(SUITE)["cases"]:
        message = messages.build(case["message"])
        expect = attempt(lambda m=message: hx(o.ack(m)))  # type: ignore[misc]
        note = expand(case["note"], names)
        out.append(vec(f"ack/{case['name']}", "ack", hx(message), expect, note, tests=case.get("tests")))
    return out
