"""Smoke test of the MAVLink comparison (make test-mavlink): the report of bench/mavlink/compare.py
on small captures has every figure, and the captures and decoders behave as the harness says.

Checks structure and counts only, never a timing or a ratio (those belong to make bench):
both captures have the same length and about the same share of garbage, our decoder finds every
message written, MAVLink's finds most of them (it loses some to garbage by design), each figure
line has both numbers and a verdict.

    compare.py ... | python tests/mavlink/check_report.py
"""

from __future__ import annotations

import re
import sys

FIGURES = (
    "throughput fed whole",
    "throughput fed one byte at a time",
    "instructions per byte fed whole (callgrind, -Os",
    "instructions per byte fed one byte at a time (callgrind, -Os",
    "instructions per byte fed whole (callgrind, -O2",
    "instructions per byte fed one byte at a time (callgrind, -O2",
    "Cortex-M4 text of the decoder closure",
    "Cortex-M4 RAM per channel",
    "Cortex-M4 stack for the message handed to the caller",
)
CAPTURE = re.compile(r"(\d+) bytes, (\d+) messages, [0-9.]+ bytes per message, (\d+) garbage bytes")
DECODED = re.compile(r"(\d+) of (\d+) messages \((\d+) lost\)")
FIGURE = re.compile(r"ours ([0-9,.]+) / theirs ([0-9,.]+).*; ours no worse: (yes|no)$")


def check(report: str) -> list[str]:
    lines = dict(line.split(": ", 1) for line in report.splitlines() if ": " in line)
    failures: list[str] = []
    captures = {}
    for side in ("ours", "theirs"):
        match = CAPTURE.search(lines.get(f"{side}_capture", ""))
        if match is None:
            failures.append(f"no {side}_capture line")
            continue
        size, messages, garbage = (int(v) for v in match.groups())
        captures[side] = (size, messages, garbage / size)
    if len(captures) == 2:
        (size_a, _, share_a), (size_b, _, share_b) = captures["ours"], captures["theirs"]
        if size_a != size_b:
            failures.append(f"captures of different lengths: {size_a} and {size_b}")
        if abs(share_a - share_b) > 0.002 or min(share_a, share_b) < 0.01:
            failures.append(f"garbage shares differ or are under 1%: {share_a:.4f} and {share_b:.4f}")
    for side, least in (("ours", 1.0), ("theirs", 0.9)):
        match = DECODED.search(lines.get(f"{side}_decoded", ""))
        if match is None:
            failures.append(f"no {side}_decoded line")
            continue
        found, written, _lost = (int(v) for v in match.groups())
        if written == 0 or found > written or found < least * written:
            failures.append(f"{side} decoded {found} of {written} messages (expected at least {least:.0%})")
    figures = [line for line in report.splitlines() if FIGURE.search(line)]
    for label in FIGURES:
        matching = [line for line in figures if line.startswith(label)]
        if len(matching) != 1:
            failures.append(f"{len(matching)} lines for the figure {label!r}")
            continue
        match = FIGURE.search(matching[0])
        assert match is not None
        if min(float(v.replace(",", "")) for v in match.groups()[:2]) <= 0:
            failures.append(f"a figure is not positive: {matching[0]}")
    if not re.search(r"^ours no worse on every figure: (yes|no)", report, re.MULTILINE):
        failures.append("no closing verdict")
    return failures


def main() -> int:
    report = sys.stdin.read()
    failures = check(report)
    for failure in failures:
        print(f"FAIL: {failure}")
    checks = 2 + 2 + len(FIGURES) + 1
    print(f"mavlink smoke: {checks - len(failures)} passed, {len(failures)} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
