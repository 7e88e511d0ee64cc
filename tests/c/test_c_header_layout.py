"""generated/c/ilahrs.h reads a topic at a time: each library function is declared under the same
banner as the type it works on, not hundreds of lines after it in a section of functions."""

from __future__ import annotations

import re

from generator import ROOT

HEADER = ROOT / "generated" / "c" / "ilahrs.h"
BANNER = re.compile(r"^/\* =+ \*/\n/\* (.*?) *\*/\n/\* =+ \*/\n", re.MULTILINE)
TYPEDEF = re.compile(r"(?:^\}|^typedef [^;{]*?) (ilahrs_\w+_t);", re.MULTILINE)
# A declaration of a library function (not a static inline one): its return type, name, parameters.
PROTOTYPE = re.compile(r"^(?!static|typedef|#|\s|/|\*)([\w \*]+?)\b(ilahrs_\w+)\(([^()]*)\);", re.MULTILINE)
TYPE = re.compile(r"\bilahrs_\w+_t\b")


def sections(text: str) -> list[tuple[str, str]]:
    cuts = list(BANNER.finditer(text))
    ends = [c.start() for c in cuts[1:]] + [len(text)]
    return [(m.group(1), text[m.end() : end]) for m, end in zip(cuts, ends, strict=True)]


def test_each_function_lies_with_its_type() -> None:
    parts = sections(HEADER.read_text(encoding="utf-8"))
    home = {name: title for title, body in parts for name in TYPEDEF.findall(body)}
    assert {"ilahrs_frame_t", "ilahrs_payload_t", "ilahrs_command_t", "ilahrs_stream_t"} <= home.keys()
    checked = 0
    misplaced = []
    for title, body in parts:
        for returned, name, parameters in PROTOTYPE.findall(body):
            types = [t for t in TYPE.findall(parameters) + TYPE.findall(returned) if t != "ilahrs_error_t"]
            if not types:
                continue
            checked += 1
            if home[types[0]] != title:
                misplaced.append(f"{name} (under {title!r}) works on {types[0]} (under {home[types[0]]!r})")
    assert checked > 50
    assert not misplaced, "\n".join(misplaced)


def test_one_banner_per_topic() -> None:
    titles = [title.split(" (")[0] for title, _ in sections(HEADER.read_text(encoding="utf-8"))]
    assert len(titles) == len(set(titles)), titles
    assert titles[:5] == ["Errors", "Frame", "Device variants", "Payload tables", "Commands"]
