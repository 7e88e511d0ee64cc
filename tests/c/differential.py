"""The C stream decoder against the Python reference binding on large damaged captures (make test-c).

Each round takes a capture written by the C library (bench/c/capture.c, a given seed), damages
it with random byte changes, cuts it into random chunks, and decodes it with the Python
`ilahrs.StreamDecoder` and with the C runner (`stream` request, conformance/README.md). Both
must hand out the same messages, byte for byte, and discard the same number of bytes. Seeded.

    python tests/c/differential.py CAPTURE-TOOL RUNNER [ROUNDS]
"""

from __future__ import annotations

import random
import subprocess
import sys
import tempfile
from pathlib import Path

import ilahrs


def python_events(chunks: list[bytes]) -> tuple[list[str], int]:
    decoder = ilahrs.StreamDecoder()
    events: list[ilahrs.StreamEvent] = []
    for chunk in chunks:
        events += decoder.feed(chunk)
    events += decoder.finish()
    return [("F:" if e.frame is not None else "N:") + e.raw.hex().upper() for e in events], decoder.discarded


def c_events(runner: str, chunks: list[bytes]) -> tuple[list[str], int]:
    line = "stream " + ",".join(chunk.hex() if chunk else "-" for chunk in chunks) + "\n"
    answer = subprocess.run([runner], input=line, capture_output=True, text=True, check=True).stdout.strip()
    status, discarded, events = answer.split(" ")
    if status != "ok":
        raise SystemExit(f"runner answered {answer[:200]}")
    tokens = events.removeprefix("events=")
    out = []
    for token in ([] if tokens == "-" else tokens.split(",")):
        kind, text = token.split(":", 1)
        raw = bytes.fromhex(text) if kind == "F" else _unpercent(text)
        out.append(f"{kind}:{raw.hex().upper()}")
    return out, int(discarded.removeprefix("discarded="))


def _unpercent(token: str) -> bytes:
    out = bytearray()
    i = 0
    while i < len(token):
        if token[i] == "%":
            out.append(int(token[i + 1 : i + 3], 16))
            i += 3
        else:
            out.append(ord(token[i]))
            i += 1
    return bytes(out)


def main(argv: list[str]) -> int:
    if len(argv) not in (3, 4):
        print(__doc__, file=sys.stderr)
        return 2
    tool, runner = argv[1], argv[2]
    rounds = int(argv[3]) if len(argv) == 4 else 12
    failures = 0
    with tempfile.TemporaryDirectory() as tmp:
        for seed in range(1, rounds + 1):
            rng = random.Random(seed)
            path = Path(tmp) / f"capture-{seed}.bin"
            size = rng.choice([2000, 30000, 120000])
            subprocess.run([tool, "--size", str(size), "--seed", str(seed), "--out", str(path)],
                           check=True, capture_output=True)
            data = bytearray(path.read_bytes())
            for _ in range(rng.choice([0, size // 500, size // 50])):
                data[rng.randrange(len(data))] = rng.randrange(256)
            chunks: list[bytes] = []
            at = 0
            while at < len(data):
                n = rng.choice([1, 2, 3, 9, 47, 60, 82, 500, 4096])
                chunks.append(bytes(data[at : at + n]))
                at += n
            want = python_events(chunks)
            got = c_events(runner, chunks)
            same = want == got
            failures += not same
            verdict = "same" if same else "DIFFERENT"
            print(f"seed {seed}: {size} bytes, {len(chunks)} chunks: python {len(want[0])} messages, "
                  f"{want[1]} discarded; c {len(got[0])} messages, {got[1]} discarded: {verdict}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
