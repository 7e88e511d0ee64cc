"""The C stream decoder and state machine against the Python reference binding (make test-c).

Each round takes a capture written by the C library (bench/c/capture.c, a given seed), damages
it with random byte changes, cuts it into random chunks, and decodes it with the Python
`ilahrs.StreamDecoder` and with the C runner (`stream` request, conformance/README.md). Both
must hand out the same messages, byte for byte, and discard the same number of bytes. Then random
sessions (`session` request: command codes, data messages of every block size and its neighbours,
timer events, on every firmware version the table names and around it) are stepped by the C runner
and by `ilahrs.statemachine`; every step must agree. Seeded.

    python tests/c/differential.py CAPTURE-TOOL RUNNER [ROUNDS]
"""

from __future__ import annotations

import random
import shlex
import subprocess
import sys
import tempfile
from pathlib import Path

import ilahrs
from ilahrs import statemachine


def python_events(chunks: list[bytes]) -> tuple[list[str], int]:
    decoder = ilahrs.StreamDecoder()
    events: list[ilahrs.StreamEvent] = []
    for chunk in chunks:
        events += decoder.feed(chunk)
    events += decoder.finish()
    return [("F:" if e.frame is not None else "N:") + e.raw.hex().upper() for e in events], decoder.discarded


def c_events(runner: str, chunks: list[bytes]) -> tuple[list[str], int]:
    line = "stream " + ",".join(chunk.hex() if chunk else "-" for chunk in chunks) + "\n"
    answer = subprocess.run(shlex.split(runner), input=line, capture_output=True, text=True, check=True).stdout.strip()
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


def python_session(firmware: str | None, tokens: list[str]) -> str:
    state = statemachine.INITIAL
    steps = []
    for token in tokens:
        kind, _, value = token.partition(":")
        if kind == "C":
            event = statemachine.command_event(int(value, 16), state) or statemachine.UNKNOWN
        elif kind == "D":
            expects = statemachine.STATES[state].expects
            fits = expects is not None and int(value) == ilahrs.PAYLOADS[expects].SIZE
            event = statemachine.PARAMETER_BLOCK if fits else statemachine.OTHER_MESSAGE
        else:
            event = value
        transition = statemachine.lookup(state, event, firmware)
        sends: tuple[str, ...] = ()
        if transition is not None:
            state, sends = transition.to, transition.send
        steps.append(f"{event}>{state}>{'+'.join(sends) or '-'}")
    return "ok steps=" + ",".join(steps)


def sessions(runner: str, count: int) -> int:
    """Random sessions through the C runner and the Python table; the number that differ."""
    rng = random.Random(0x5E55)
    codes = sorted({c.code for c in ilahrs.COMMANDS.values()})
    sizes = sorted({cls.SIZE + d for cls in ilahrs.PAYLOADS.values() for d in (-1, 0, 1)} - {0})
    timers = [statemachine.BLOCK_TIMEOUT, *sorted(set(statemachine.TIMER_EVENTS.values()))]
    versions: list[str | None] = [None]
    for before, _ in statemachine.LEGACY_TRANSITIONS.values():
        parts = [int(p) for p in before.split(".")]
        versions += [before, ".".join(map(str, [*parts[:-1], parts[-1] + 1])), ".".join(map(str, parts[:-1])),
                     ".".join(map(str, [parts[0] - 1, *parts[1:]]))]
    lines = []
    expected = []
    for _ in range(count):
        firmware = rng.choice(versions)
        tokens = []
        for _ in range(rng.randrange(1, 120)):
            roll = rng.random()
            if roll < 0.6:
                tokens.append(f"C:{rng.choice(codes) if rng.random() < 0.9 else rng.randrange(256):02X}")
            elif roll < 0.8:
                tokens.append(f"D:{rng.choice(sizes)}")
            else:
                tokens.append(f"E:{rng.choice(timers)}")
        lines.append(f"session {firmware or '-'} {','.join(tokens)}\n")
        expected.append(python_session(firmware, tokens))
    answers = subprocess.run(shlex.split(runner), input="".join(lines), capture_output=True, text=True,
                             check=True).stdout
    got = answers.splitlines()
    differ = sum(1 for a, b in zip(expected, got, strict=False) if a != b) + abs(len(expected) - len(got))
    print(f"sessions: {count} random sessions, {sum(len(x.split(',')) for x in lines)} events: "
          f"{'same' if differ == 0 else f'{differ} DIFFERENT'}")
    return differ


def damaged_capture(tool: str, seed: int, directory: Path) -> tuple[int, list[bytes]]:
    """A capture written by `tool` with this seed, damaged by random byte changes and cut into
    random chunks: its size and the chunks."""
    rng = random.Random(seed)
    path = directory / f"capture-{seed}.bin"
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
    return size, chunks


def main(argv: list[str]) -> int:
    if len(argv) not in (3, 4):
        print(__doc__, file=sys.stderr)
        return 2
    tool, runner = argv[1], argv[2]
    rounds = int(argv[3]) if len(argv) == 4 else 12
    failures = 0
    with tempfile.TemporaryDirectory() as tmp:
        for seed in range(1, rounds + 1):
            size, chunks = damaged_capture(tool, seed, Path(tmp))
            want = python_events(chunks)
            got = c_events(runner, chunks)
            same = want == got
            failures += not same
            verdict = "same" if same else "DIFFERENT"
            print(f"seed {seed}: {size} bytes, {len(chunks)} chunks: python {len(want[0])} messages, "
                  f"{want[1]} discarded; c {len(got[0])} messages, {got[1]} discarded: {verdict}")
    failures += sessions(runner, 400) != 0
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
