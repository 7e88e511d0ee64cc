"""Differential test of the Rust binding against the Python reference, through both conformance runners.

Seeded inputs built from the spec model (frames, $PAHR sentences, byte streams), most of them
mutated (bytes replaced, inserted, deleted, cut), go as `frame_decode`, `nmea_decode` and `stream`
requests to the Rust runner and to the Python runner; every answer must agree: the same error kind,
offset and field, the same stream events and discarded count, the same values (numbers to within
1e-9). Random `session` requests go to the Rust runner and are checked against the spec model's
own table (`StateMachine`, `Spec.command_in_mode`). Run from the repository root after
`make build-rust`:

    .venv/bin/python tests/rust/differential.py [--cases N] [--seed S]
"""

from __future__ import annotations

import argparse
import math
import random
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from generator import build_spec  # noqa: E402
from generator.model import NmeaField, Spec  # noqa: E402

RUST_RUNNER = ROOT / "build" / "rust" / "target" / "release" / "ilahrs-conformance"
PYTHON_RUNNER = ROOT / "conformance" / "runners" / "python" / "python_runner.py"

# Bytes a mutation writes: the $PAHR grammar's characters, both frame start bytes, and any byte.
SENTENCE_BYTES = b"0123456789.,-*$\r\nabcdefABCDEFgG "
FIELD_BYTES = b"0123456789.,-aF"


def hex_token(data: bytes) -> str:
    return data.hex().upper() if data else "-"


def text_token(data: bytes) -> str:
    return "".join(chr(b) if 0x21 <= b <= 0x7E and b not in b"%,=" else f"%{b:02X}" for b in data)


def frame(spec: Spec, rng: random.Random) -> bytes:
    """A frame of a random type and payload: valid, or with a wrong length, type or checksum."""
    fr = spec.frame
    types = [t.value for t in fr.message_types]
    payload = rng.randbytes(rng.randint(fr.min_payload, fr.max_payload))
    message_type = rng.choice(types) if rng.random() < 0.9 else rng.randrange(256)
    length = len(payload) + fr.length_bias
    if rng.random() < 0.05:
        length = rng.randrange(1 << (8 * fr.field("message_length").size))
    body = bytearray(fr.header)
    body += bytes([message_type, rng.randrange(256) if rng.random() < 0.2 else 0])
    body += length.to_bytes(fr.field("message_length").size, spec.byte_order)  # type: ignore[arg-type]
    body += payload
    checksum = sum(body[fr.header_size :]) & 0xFFFF
    if rng.random() < 0.05:
        checksum ^= 1 << rng.randrange(16)
    body += checksum.to_bytes(fr.checksum.size, spec.byte_order)  # type: ignore[arg-type]
    return bytes(body)


def nmea_field(field: NmeaField, rng: random.Random, canonical: bool) -> str:
    """A field as builders write it (`canonical`: every field at its template width, E16) or as a
    device may write it (any padding, fewer decimals, either hex case); sometimes out of range."""
    if field.format == "hex":
        value = rng.randint(field.min, field.max)
        text = f"{value:0{field.width if canonical else rng.randint(1, field.width)}X}"
        return text.lower() if rng.random() < 0.3 else text
    low, high = field.min, field.max
    if rng.random() < 0.05:
        low, high = field.min - 10 * field.divisor, field.max + 10 * field.divisor
    scaled = rng.randint(low, high)
    sign = "-" if scaled < 0 else ""
    whole, fraction = divmod(abs(scaled), field.divisor)
    digits = f"{fraction:0{field.decimals}d}" if field.decimals else ""
    if canonical:
        return f"{sign}{whole:0{max(field.width - len(sign), 1)}d}" + (f".{digits}" if digits else "")
    decimals = rng.randint(0, field.decimals + (1 if rng.random() < 0.05 else 0))
    digits = (digits + "0")[:decimals] if decimals else ""
    return f"{sign}{whole:0{rng.randint(1, field.width)}d}" + (f".{digits}" if digits else "")


def sentence(spec: Spec, rng: random.Random) -> bytes:
    """A $PAHR sentence with a right (usually) or wrong checksum."""
    nmea = spec.nmea
    assert nmea is not None
    canonical = rng.random() < 0.5
    fields = ",".join(nmea_field(f, rng, canonical) for f in nmea.fields)
    if rng.random() < 0.5:
        # Broken fields under a right checksum reach the field checks.
        fields = mutate(fields.encode("latin-1"), rng, FIELD_BYTES).decode("latin-1")
    body = f"{nmea.identifier},{fields}"
    check = 0
    for byte in body.encode("latin-1"):
        check ^= byte
    if rng.random() < 0.05:
        check ^= 1 << rng.randrange(8)
    text = f"${body}*{check:02X}" if rng.random() < 0.8 else f"${body}*{check:02x}"
    return text.encode("latin-1") + b"\r\n"


def mutate(data: bytes, rng: random.Random, alphabet: bytes) -> bytes:
    """`data` with 0 to 3 bytes replaced, inserted or deleted, or cut short."""
    out = bytearray(data)
    for _ in range(rng.choice((0, 0, 1, 1, 2, 3))):
        at = rng.randrange(len(out) + 1)
        byte = rng.choice(alphabet) if rng.random() < 0.8 else rng.randrange(256)
        action = rng.randrange(4)
        if action == 0 and at < len(out):
            out[at] = byte
        elif action == 1:
            out.insert(at, byte)
        elif action == 2 and at < len(out):
            del out[at]
        elif out:
            del out[rng.randrange(len(out)) :]
    return bytes(out)


def message(spec: Spec, rng: random.Random) -> bytes:
    choice = rng.randrange(5)
    if choice == 0:
        return rng.randbytes(rng.randint(1, 8))
    if choice in (1, 2):
        return mutate(frame(spec, rng), rng, bytes(spec.frame.header) + SENTENCE_BYTES)
    return mutate(sentence(spec, rng), rng, SENTENCE_BYTES + bytes(spec.frame.header))


def chunks(data: bytes, rng: random.Random) -> list[bytes]:
    out, at = [], 0
    while at < len(data):
        size = rng.choice((1, 2, 7, 64, 300, len(data)))
        out.append(data[at : at + size])
        at += size
    return out or [b""]


def session_request(spec: Spec, rng: random.Random) -> str:
    machine = spec.state_machine
    assert machine is not None
    timers = [e.name for e in machine.events if e.name not in ("parameter_block", "other_message")]
    sizes = sorted({p.size for p in spec.payloads})
    codes = list(spec.codes)
    tokens = []
    for _ in range(rng.randint(1, 40)):
        kind = rng.randrange(10)
        if kind < 5:
            tokens.append(f"C:{rng.choice(codes) if rng.random() < 0.95 else rng.randrange(256):02X}")
        elif kind < 7:
            tokens.append(f"D:{rng.choice(sizes) if rng.random() < 0.8 else rng.randrange(64)}")
        else:
            tokens.append(f"E:{rng.choice(timers)}")
    versions = ["-", "-", *(t.firmware_before for t in machine.transitions if t.firmware_before)]
    version = rng.choice(versions) or "-"
    if version != "-" and rng.random() < 0.5:
        parts = [int(p) for p in version.split(".")]
        parts[rng.randrange(len(parts))] += rng.choice((-1, 1))
        version = ".".join(str(max(p, 0)) for p in parts)
    return f"session {version} " + ",".join(tokens)


def version(text: str) -> tuple[int, ...]:
    return tuple(int(part) for part in text.split("."))


def session_answer(spec: Spec, request: str) -> str:
    """The answer the spec model gives to a `session` request."""
    machine = spec.state_machine
    assert machine is not None
    _, firmware, tokens = request.split(" ")
    state = machine.initial
    steps = []
    for token in tokens.split(","):
        kind, _, value = token.partition(":")
        if kind == "C":
            command = spec.command_in_mode(int(value, 16), machine.state(state).mode)
            event = "unknown" if command is None else command.name
        elif kind == "D":
            expects = machine.state(state).expects
            fits = expects is not None and spec.payload(expects).size == int(value)
            event = "parameter_block" if fits else "other_message"
        else:
            event = value
        rows = [t for t in machine.transitions if t.state == state and t.event == event]
        older = [t for t in rows if t.firmware_before and firmware != "-"]
        older = [t for t in older if version(firmware) < version(t.firmware_before or "")]
        current = [t for t in rows if t.firmware_before is None]
        sends: tuple[str, ...] = ()
        if older or current:
            row = (older or current)[0]
            state, sends = (state if row.to == "same" else row.to), row.send
        steps.append(f"{event}>{state}>{'+'.join(sends) or '-'}")
    return "ok steps=" + ",".join(steps)


def requests(spec: Spec, rng: random.Random, cases: int) -> tuple[list[str], list[str]]:
    """Requests for both runners, and `session` requests for the Rust runner alone."""
    lines, sessions = [], []
    for _ in range(cases):
        lines.append("frame_decode " + hex_token(mutate(frame(spec, rng), rng, bytes(spec.frame.header))))
        lines.append("nmea_decode " + text_token(mutate(sentence(spec, rng), rng, SENTENCE_BYTES)))
        data = b"".join(message(spec, rng) for _ in range(rng.randint(1, 12)))
        lines.append("stream " + ",".join(hex_token(c) for c in chunks(data, rng)))
        if spec.state_machine is not None:
            sessions.append(session_request(spec, rng))
    return lines, sessions


def run(command: list[str], lines: list[str]) -> list[str]:
    result = subprocess.run(
        command, input="".join(f"{line}\n" for line in lines), capture_output=True, text=True, check=False, cwd=ROOT
    )
    answers = result.stdout.splitlines()
    if len(answers) != len(lines):
        raise SystemExit(f"{command[-1]}: {len(answers)} answers to {len(lines)} requests\n{result.stderr}")
    return answers


def same(rust: str, python: str) -> bool:
    """Equal answers; `ok` answers may spell numbers differently (1e-9 relative)."""
    if rust == python:
        return True
    a, b = rust.split(" "), python.split(" ")
    if a[0] != "ok" or b[0] != "ok" or len(a) != len(b):
        return False
    for x, y in zip(a[1:], b[1:], strict=True):
        (kx, _, vx), (ky, _, vy) = x.partition("="), y.partition("=")
        if kx != ky:
            return False
        try:
            fx, fy = float(vx), float(vy)
        except ValueError:
            return False
        if not math.isclose(fx, fy, rel_tol=1e-9, abs_tol=1e-12):
            return False
    return True


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0] if __doc__ else None)
    parser.add_argument("--cases", type=int, default=3000)
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()
    if not RUST_RUNNER.exists():
        print(f"{RUST_RUNNER.relative_to(ROOT)} not built: run make build-rust", file=sys.stderr)
        return 1
    spec = build_spec()
    shared, sessions = requests(spec, random.Random(args.seed), args.cases)
    lines = shared + sessions
    rust = run([str(RUST_RUNNER)], lines)
    python = run([sys.executable, str(PYTHON_RUNNER)], shared) + [session_answer(spec, line) for line in sessions]
    failures = [(line, r, p) for line, r, p in zip(lines, rust, python, strict=True) if not same(r, p)]
    kinds: dict[str, int] = {}
    for line, r, _ in zip(lines, rust, python, strict=True):
        key = line.split(" ", 1)[0] + (" ok" if r.startswith("ok") else " " + " ".join(r.split(" ")[:2]))
        kinds[key] = kinds.get(key, 0) + 1
    for line, r, p in failures[:10]:
        print(f"request: {line[:300]}\n   rust: {r[:300]}\n expect: {p[:300]}")
    print(
        f"differential: {len(lines)} requests, {len(failures)} disagreements; "
        + ", ".join(f"{k}: {n}" for k, n in sorted(kinds.items()))
    )
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
