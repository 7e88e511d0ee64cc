"""frames: whole frames decoded (each check of spec/README.md in order, and strictly: E42) and built."""

from __future__ import annotations

from typing import Any

import oracle as o

from .common import Vector, attempt, cases, expand, hx, phrases, vec
from .messages import Messages

SUITE = "frames"


def _decoded(data: bytes, strict: bool) -> Any:
    def run() -> dict[str, Any]:
        mtype, reserved, payload = o.decode_frame(data, strict)
        return {"message_type": mtype, "reserved": reserved, "payload": hx(payload)}

    return attempt(run)


def _built(input_: dict[str, Any]) -> Any:
    def run() -> str:
        payload = bytes.fromhex(input_["payload"])
        return hx(o.frame(input_["message_type"], payload, input_.get("reserved", 0)))

    return attempt(run)


def vectors() -> list[Vector]:
    """Decode inputs are messages (suites/messages.py); an encode input is the request as sent,
    its payload written as a message."""
    data = cases(SUITE)
    names = phrases(SUITE)
    messages = Messages(data["messages"])
    out: list[Vector] = []
    for case in data["decode"]:
        frame = messages.build(case["bytes"])
        strict = case.get("strict", False)
        note = expand(case["note"], names)
        expect = _decoded(frame, strict)
        vector = vec(f"frame_decode/{case['name']}", "frame_decode", hx(frame), expect, note, tests=case.get("tests"))
        if strict:
            vector["options"] = {"strict": True}
        out.append(vector)
    for case in data["encode"]:
        input_ = {**case["input"], "payload": hx(messages.build(case["input"]["payload"]))}
        text = f"{expand(case['note'], names)}; spec/README.md, frame encode"
        tests = case.get("tests")
        out.append(vec(f"frame_encode/{case['name']}", "frame_encode", input_, _built(input_), text, tests=tests))
    return out
