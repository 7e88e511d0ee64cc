"""Three-way differential: the C, Rust and Python bindings on the same seeded random inputs.

Every request goes to the three conformance runners registered in conformance/bindings/ (c.json,
rust.json, python.json: the same line protocol, conformance/README.md), and every answer is compared
with the two others: C with Rust, C with Python, Rust with Python (numbers to within 1e-9 relative,
as the harness compares them). The requests are:

- `stream`: captures written by the C library (bench/c/capture.c), damaged by random byte changes
  and cut into random chunks (tests/c/differential.py), and streams of random messages, most of them
  mutated (tests/rust/differential.py), the latter with idle gaps around the idle timeout (E41)
  and the strict option (E42) on about half of them;
- `frame_decode` (strict on about half), `command_decode`, `ack`: mutated frames and command frames;
- `payload_decode` of every payload table (with and without a device variant): payloads of the
  table's size made of random bytes, of bytes of a random valid message, and a byte too many or too
  few; then `payload_encode` of the raw values the Python runner decoded, changed at random;
- `nmea_decode` of mutated $PAHR sentences, and `nmea_encode` of random values around each range;
- `frame_encode` and `command_encode` of random types, payloads and names.

Seeded and deterministic; run from the repository root after `make build`:

    .venv/bin/python fuzz/differential.py --capture build/c/capture [--cases N] [--seed S]
"""

from __future__ import annotations

import argparse
import importlib.util
import json
import math
import random
import struct
import subprocess
import sys
import tempfile
import threading
from pathlib import Path
from types import ModuleType

import ilahrs
from ilahrs.spec import IDLE_TIMEOUT

ROOT = Path(__file__).resolve().parents[1]
BINDINGS = ("c", "rust", "python")
PER_TABLE = 100
CAPTURES = 8


def load(path: str, name: str) -> ModuleType:
    spec = importlib.util.spec_from_file_location(name, ROOT / path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


# The generators and the answer comparison of the two binding-against-Python differentials.
RUST_DIFF = load("tests/rust/differential.py", "rust_differential")
C_DIFF = load("tests/c/differential.py", "c_differential")
SPEC = RUST_DIFF.build_spec()
mutate = RUST_DIFF.mutate


def hex_token(data: bytes) -> str:
    return str(RUST_DIFF.hex_token(data))


def text_token(data: bytes) -> str:
    return str(RUST_DIFF.text_token(data))


def runner(name: str) -> list[str]:
    """The command a binding registered for conformance runs."""
    binding = json.loads((ROOT / "conformance" / "bindings" / f"{name}.json").read_text())
    return [sys.executable if part == "{python}" else part for part in binding["command"]]


def ask(command: list[str], lines: list[str], answers: dict[str, list[str]], name: str) -> None:
    result = subprocess.run(
        command, input="".join(f"{line}\n" for line in lines), capture_output=True, text=True, check=False, cwd=ROOT
    )
    answers[name] = result.stdout.splitlines()
    if len(answers[name]) != len(lines):
        answers[name] += [f"no answer (runner exited {result.returncode}: {result.stderr[-300:]})"] * (
            len(lines) - len(answers[name])
        )


def ask_all(lines: list[str]) -> dict[str, list[str]]:
    """Every binding's answers to `lines`, the three runners at once."""
    answers: dict[str, list[str]] = {}
    threads = [threading.Thread(target=ask, args=(runner(n), lines, answers, n)) for n in BINDINGS]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    return answers


def payload_requests(rng: random.Random, messages: list[bytes]) -> list[str]:
    lines = []
    variants = ["-", *ilahrs.VARIANTS]
    for name, table in ilahrs.PAYLOADS.items():
        for _ in range(PER_TABLE):
            size = table.SIZE + rng.choice((0, 0, 0, 0, 0, -1, 1))
            data = rng.randbytes(max(size, 0)) if rng.random() < 0.5 else rng.choice(messages)[:size].ljust(size, b"\0")
            variant = rng.choice(variants)
            lines.append(f"payload_decode {name} {hex_token(data)}" + ("" if variant == "-" else f" {variant}"))
    return lines


def wild(rng: random.Random, field: ilahrs.FieldInfo, value: str) -> str:
    """Another value of the field's wire type (conformance/README.md token forms), often out of range."""
    if field.type == "f32":
        return rng.choice(("nan", "inf", "-inf", "-0.0", "1e300", "3.4028235e38", repr(rng.uniform(-1e6, 1e6))))
    if field.type == "char":
        return text_token(rng.randbytes(rng.choice((0, 1, field.size - 1, field.size, field.size + 1))))
    if field.type == "reserved":
        return hex_token(rng.randbytes(rng.choice((0, field.size - 1, field.size, field.size + 1))))
    low = field.low if field.low is not None else 0
    high = field.high if field.high is not None else 1 << (8 * field.size)
    return str(rng.choice((low - 1, low, high, high + 1, int(value) + 1, int(value) - 1, -(1 << 31), 1 << 32)))


def encode_requests(rng: random.Random, decoded: list[tuple[str, str]]) -> list[str]:
    """payload_encode of the raw values a decode answered, some changed, some left out."""
    lines = []
    for request, answer in decoded:
        if not answer.startswith("ok "):
            continue
        table = ilahrs.PAYLOADS[request.split(" ")[1]]
        fields = {f.name: f for f in table.FIELDS}
        out = []
        for token in answer.split(" ")[1:]:
            key, _, value = token.removeprefix("f.").partition("=")
            roll = rng.random()
            if not token.startswith("f.") or roll < 0.1:
                continue
            out.append(f"{key}={wild(rng, fields[key], value) if roll < 0.3 else value}")
        variant = rng.choice(["-", *ilahrs.VARIANTS])
        lines.append(" ".join(["payload_encode", table.NAME, variant, *out]))
    return lines


def nmea_encode(rng: random.Random) -> str:
    nmea = SPEC.nmea
    assert nmea is not None
    values = []
    for field in nmea.fields:
        low, high = field.min / field.divisor, field.max / field.divisor
        spread = (high - low) * 0.05 + 1
        value = rng.uniform(low - spread, high + spread)
        if field.format == "hex":
            values.append(f"{field.name}={round(value)}")
        else:
            values.append(f"{field.name}={rng.choice((value, round(value, field.decimals + 1), low, high))!r}")
    return "nmea_encode " + " ".join(values)


def frame_encode(rng: random.Random) -> str:
    """A frame_encode request: any message type and reserved byte, most of them valid."""
    message_type, reserved = rng.choice(range(256)), rng.choice((0, 0, 0, 1, 255, -1, 256))
    if rng.random() < 0.7:
        message_type = rng.choice([t.value for t in SPEC.frame.message_types])
    payload = rng.randbytes(rng.choice((0, 1, 2, 34, 52, 53, rng.randrange(70))))
    return f"frame_encode {message_type} {hex_token(payload)}" + (
        f" {reserved}" if reserved or rng.random() < 0.5 else ""
    )


def stream_options(rng: random.Random, chunks: int) -> str:
    """Idle gaps after random chunks, around the idle timeout (E41), and the strict option (E42),
    each on about half the requests."""
    text = ""
    if chunks and rng.random() < 0.5:
        timeout = round(IDLE_TIMEOUT * 1_000_000)
        quiet = (0, timeout - 1, timeout, timeout + 1, 0xFFFFFFFF)
        gaps = sorted(rng.sample(range(chunks), rng.randint(1, min(chunks, 4))))
        text += " idle=" + ",".join(f"{after}:{rng.choice(quiet)}" for after in gaps)
    return text + (" strict" if rng.random() < 0.5 else "")


def requests(rng: random.Random, cases: int, capture: str, tmp: Path) -> list[str]:
    lines = []
    for seed in range(1, CAPTURES + 1):
        _, chunks = C_DIFF.damaged_capture(capture, seed, tmp)
        lines.append("stream " + ",".join(hex_token(c) for c in chunks))
    frames = [RUST_DIFF.frame(SPEC, rng) for _ in range(cases)]
    names = list(ilahrs.COMMANDS)
    for i in range(cases):
        data = b"".join(RUST_DIFF.message(SPEC, rng) for _ in range(rng.randint(1, 12)))
        chunks = RUST_DIFF.chunks(data, rng)
        lines.append("stream " + ",".join(hex_token(c) for c in chunks) + stream_options(rng, len(chunks)))
        strict = " strict" if rng.random() < 0.5 else ""
        lines.append("frame_decode " + hex_token(mutate(frames[i], rng, SPEC.frame.header)) + strict)
        command = ilahrs.build_command(rng.choice(names))
        lines.append("command_decode " + hex_token(mutate(command, rng, bytes(range(256)))))
        lines.append("ack " + hex_token(mutate(rng.choice((command, frames[i])), rng, SPEC.frame.header)))
        lines.append("nmea_decode " + text_token(mutate(RUST_DIFF.sentence(SPEC, rng), rng, RUST_DIFF.SENTENCE_BYTES)))
        lines.append(nmea_encode(rng))
        lines.append(frame_encode(rng))
        lines.append("command_encode " + (rng.choice(names) if rng.random() < 0.9 else rng.choice(names).lower()))
    return lines


def f32(text: str) -> bytes | None:
    """The float32 a NUM token reads as, NaNs as one; None if it is not a number."""
    try:
        value = float(text)
    except ValueError:
        return None
    try:
        return b"nan" if math.isnan(value) else struct.pack("<f", value)
    except OverflowError:
        return None


def same(request: str, a: str, b: str) -> bool:
    """Equal answers as the conformance harness compares them: raw float32 fields as float32 values
    (the runner protocol lets each binding spell them its own way), engineering values and sentence
    numbers to within 1e-9 relative, everything else exactly."""
    if a == b:
        return True
    ta, tb = a.split(" "), b.split(" ")
    if ta[0] != "ok" or tb[0] != "ok" or len(ta) != len(tb):
        return False
    floats: set[str] = set()
    if request.startswith("payload_decode "):
        floats = {f"f.{f.name}" for f in ilahrs.PAYLOADS[request.split(" ")[1]].FIELDS if f.type == "f32"}
    for x, y in zip(ta[1:], tb[1:], strict=True):
        (kx, _, vx), (ky, _, vy) = x.partition("="), y.partition("=")
        if kx != ky:
            return False
        if kx in floats:
            if f32(vx) is None or f32(vx) != f32(vy):
                return False
        elif x != y and not RUST_DIFF.same(f"ok {x}", f"ok {y}"):
            return False
    return True


def compare(lines: list[str], answers: dict[str, list[str]]) -> int:
    """Print what the three bindings disagree on; the number of requests with a disagreement."""
    pairs = [(a, b) for i, a in enumerate(BINDINGS) for b in BINDINGS[i + 1 :]]
    differ = dict.fromkeys(pairs, 0)
    kinds: dict[str, int] = {}
    accepted: dict[str, int] = {}
    shown = failures = 0
    for i, line in enumerate(lines):
        kind = line.split(" ", 1)[0]
        kinds[kind] = kinds.get(kind, 0) + 1
        accepted[kind] = accepted.get(kind, 0) + answers["python"][i].startswith("ok ")
        bad = [pair for pair in pairs if not same(line, answers[pair[0]][i], answers[pair[1]][i])]
        for pair in bad:
            differ[pair] += 1
        if bad:
            failures += 1
            if shown < 8:
                shown += 1
                print(f"request: {line[:300]}")
                for name in BINDINGS:
                    print(f"  {name:>6}: {answers[name][i][:300]}")
    print(
        f"three-way differential: {len(lines)} requests ("
        + ", ".join(f"{k} {n} ({accepted.get(k, 0)} ok)" for k, n in sorted(kinds.items()))
        + "); disagreements: "
        + ", ".join(f"{a}/{b} {n}" for (a, b), n in differ.items())
    )
    return failures


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0] if __doc__ else None)
    parser.add_argument("--capture", required=True, help="the capture tool (make build/c/capture)")
    parser.add_argument("--cases", type=int, default=6000)
    parser.add_argument("--seed", type=int, default=18)
    args = parser.parse_args()
    for name in BINDINGS:
        program = runner(name)[0]
        if not (ROOT / program).exists():
            print(f"{program} not built (make build)", file=sys.stderr)
            return 1
    rng = random.Random(args.seed)
    with tempfile.TemporaryDirectory() as tmp:
        lines = requests(rng, args.cases, args.capture, Path(tmp))
    tokens = [line.split(" ")[1] for line in lines if line.startswith("frame_decode ")]
    messages = [bytes.fromhex(token) for token in tokens if token != "-"]
    decodes = payload_requests(rng, messages)
    answers = ask_all(lines + decodes)
    python = answers["python"][len(lines) :]
    encodes = encode_requests(rng, list(zip(decodes, python, strict=True)))
    more = ask_all(encodes)
    every = lines + decodes + encodes
    merged = {name: answers[name] + more[name] for name in BINDINGS}
    return 1 if compare(every, merged) else 0


if __name__ == "__main__":
    sys.exit(main())
