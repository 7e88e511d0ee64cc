"""One frame rule: `ilahrs.frame.frame_at` decides every frame the package accepts; the numpy
scan of ilahrs.columnar checks the same rule on every candidate at once, so it is property tested
against the standard-library scan (which calls frame_at), lenient and strict."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import ilahrs
from ilahrs.columnar import Scanner
from ilahrs.errors import IlahrsError
from ilahrs.frame import NEED_MORE, REFUSALS, STRICT_RESERVED, Frame, frame_at

numpy = pytest.importorskip("numpy")

TYPES = sorted(int(t) for t in ilahrs.MessageType)


@st.composite
def captures(draw: st.DrawFn) -> bytes:
    """Frames (some with a reserved byte the AHRS does not send, some damaged) among noise and
    pieces of headers."""
    parts: list[bytes] = []
    for _ in range(draw(st.integers(0, 12))):
        choice = draw(st.integers(0, 4))
        if choice == 0:
            parts.append(draw(st.binary(max_size=12)))
        elif choice == 1:
            parts.append(bytes.fromhex("AA 55") + draw(st.binary(max_size=6)))
        else:
            kind = draw(st.sampled_from(TYPES))
            reserved = draw(st.sampled_from([STRICT_RESERVED.get(kind, 0), 0x3C]))
            frame = Frame(kind, draw(st.binary(min_size=1, max_size=60)), reserved).build()
            if choice == 4 and draw(st.booleans()):
                at = draw(st.integers(0, len(frame) - 1))
                frame = frame[:at] + bytes([frame[at] ^ 0x01]) + frame[at + 1 :]
            parts.append(frame)
    return b"".join(parts)


def messages(backend: object, data: bytes, strict: bool) -> list[tuple[int, int, int]]:
    scanner = Scanner(backend, sentences=True, strict=strict)  # type: ignore[arg-type]
    found: list[tuple[int, int, int]] = []
    for window in scanner.scan(data, final=True):
        found += zip(list(window.starts), list(window.lengths), list(window.types), strict=True)
    return [(int(a), int(b), int(c)) for a, b, c in found]


@settings(max_examples=300, deadline=None)
@given(captures(), st.booleans())
def test_the_numpy_scan_finds_the_frames_frame_at_accepts(data: bytes, strict: bool) -> None:
    expected = messages(None, data, strict)
    assert messages(numpy, data, strict) == expected
    decoder = ilahrs.StreamDecoder(strict=strict)
    events = decoder.feed(data) + decoder.finish()
    assert [len(e.raw) for e in events] == [length for _, length, _ in expected]


@settings(max_examples=300, deadline=None)
@given(captures(), st.booleans())
def test_frame_parse_accepts_what_frame_at_accepts(data: bytes, strict: bool) -> None:
    found = frame_at(data, strict=strict)
    try:
        Frame.parse(data, strict=strict)
    except IlahrsError as error:
        assert found != len(data)
        if found < 0:
            assert error.kind in (REFUSALS[found], ilahrs.ErrorKind.TRAILING_DATA)
    else:
        assert found == len(data)
    assert found > 0 or found == NEED_MORE or found in REFUSALS
