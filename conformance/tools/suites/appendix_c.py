"""appendix-c: every row of Table C.1 encoded and decoded as printed, then the refusals."""

from __future__ import annotations

import oracle as o

from .common import ICD, Vector, cases, expand, hx, phrases, vec
from .messages import Messages

SUITE = "appendix-c"


def _rows() -> list[Vector]:
    out: list[Vector] = []
    for row in o.table_c1():
        text = f"{ICD}, Table C.1 row {row.name} (code 0x{row.code:02X}), exact structure as printed"
        out.append(vec(f"command_encode/{row.name}", "command_encode", {"command": row.name}, row.icd_hex, text))
    for row in o.table_c1():
        names = o.command_names(row.code)
        text = f"{ICD}, Table C.1 row {row.name}, exact structure as printed"
        if len(names) > 1:
            text += "; code 0x{:02X} is shared by {} (E14), names sorted".format(row.code, " and ".join(names))
        expect = {"code": row.code, "names": names}
        out.append(vec(f"command_decode/{row.name}", "command_decode", row.icd_hex, expect, text))
    return out


def vectors() -> list[Vector]:
    """The rows, then the hand-written cases: a decode input is a message (suites/messages.py), its
    expected answer written out (the oracle has no command table of its own beyond Table C.1)."""
    names = phrases(SUITE)
    messages = Messages()
    out = _rows()
    for case in cases(SUITE)["cases"]:
        kind = case["kind"]
        input_ = hx(messages.build(case["input"])) if kind == "command_decode" else case["input"]
        note = expand(case["note"], names)
        out.append(vec(f"{kind}/{case['name']}", kind, input_, case["expect"], note, tests=case.get("tests")))
    return out
