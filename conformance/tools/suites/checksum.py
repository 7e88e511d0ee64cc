"""checksum: the Table 6.2 sum over chosen byte strings, the ICD's own and the wrap-arounds."""

from __future__ import annotations

import oracle as o

from .common import Vector, cases, expand, hx, phrases, vec
from .messages import Messages

SUITE = "checksum"


def vectors() -> list[Vector]:
    names = phrases(SUITE)
    messages = Messages()
    out: list[Vector] = []
    for case in cases(SUITE)["cases"]:
        data = messages.build(case["bytes"])
        out.append(vec(f"checksum/{case['name']}", "checksum", hx(data), o.checksum(data), expand(case["note"], names)))
    return out
