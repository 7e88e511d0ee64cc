"""The frames-only C stream decoder (ILAHRS_STREAM_SENTENCES=0) against the full one (make test-c).

Compiled without sentences, the stream decoder must hand out exactly the frames the full decoder
hands out, in the same order, and count every byte of each sentence the full decoder would hand
out as discarded (the reasoning is in ilahrs.c, at ILAHRS_STREAM_SENTENCES). This checks it twice:

- every `stream` vector of conformance/vectors, its expectation turned into that (sentences
  dropped, their lengths added to `discarded`), run by the conformance harness against RUNNER;
- damaged captures cut into random chunks (tests/c/differential.py), decoded by the Python binding
  with the same turn and by RUNNER.

    python tests/c/frames_only.py CAPTURE-TOOL RUNNER [ROUNDS]

RUNNER is conformance/runners/c/conformance_runner.c built with -DILAHRS_STREAM_SENTENCES=0, as a command line
(e.g. "RUNNER --bytewise").
"""

from __future__ import annotations

import json
import subprocess
import sys
import tempfile
from pathlib import Path
from typing import Any

import differential

ROOT = Path(__file__).resolve().parent.parent.parent


def frames_only_expectation(expect: dict[str, Any]) -> dict[str, Any]:
    """A stream vector's expectation for a decoder that hands out frames only."""
    events = expect.get("events", [])
    dropped = sum(len(e["nmea"].encode("latin-1")) for e in events if "nmea" in e)
    turned: dict[str, Any] = {"events": [e for e in events if "nmea" not in e]}
    if "discarded" in expect:
        turned["discarded"] = expect["discarded"] + dropped
    return turned


def frames_only_vectors(out: Path) -> int:
    """Write every stream vector, turned, as suites in `out`; how many."""
    count = 0
    for path in sorted((ROOT / "conformance" / "vectors").glob("*.json")):
        suite = json.loads(path.read_text(encoding="utf-8"))
        vectors = [{**v, "expect": frames_only_expectation(v["expect"])} for v in suite["vectors"]
                   if v["kind"] == "stream"]
        if vectors:
            doc = {"suite": suite["suite"], "source": f"{path.name}, stream vectors, sentences dropped",
                   "vectors": vectors}
            (out / path.name).write_text(json.dumps(doc), encoding="utf-8")
            count += len(vectors)
    return count


def python_frames(chunks: list[bytes]) -> tuple[list[str], int]:
    events, discarded = differential.python_events(chunks)
    frames = [e for e in events if e.startswith("F:")]
    dropped = sum(len(bytes.fromhex(e[2:])) for e in events if e.startswith("N:"))
    return frames, discarded + dropped


def captures(tool: str, runner: str, rounds: int) -> int:
    """Damaged captures in random chunks; the number of rounds where the runner differs."""
    failures = 0
    with tempfile.TemporaryDirectory() as tmp:
        for seed in range(1, rounds + 1):
            size, chunks = differential.damaged_capture(tool, seed, Path(tmp))
            want = python_frames(chunks)
            got = differential.c_events(runner, chunks)
            if any(e.startswith("N:") for e in got[0]):
                raise SystemExit(f"{runner} handed out a sentence: is it built with ILAHRS_STREAM_SENTENCES=0?")
            failures += want != got
            verdict = "same" if want == got else "DIFFERENT"
            print(f"seed {seed}: {size} bytes, {len(chunks)} chunks: {len(want[0])} frames, {want[1]} discarded "
                  f"expected; runner {len(got[0])} frames, {got[1]} discarded: {verdict}")
    return failures


def main(argv: list[str]) -> int:
    if len(argv) not in (3, 4):
        print(__doc__, file=sys.stderr)
        return 2
    tool, runner = argv[1], argv[2]
    rounds = int(argv[3]) if len(argv) == 4 else 8
    with tempfile.TemporaryDirectory() as tmp:
        count = frames_only_vectors(Path(tmp))
        print(f"{count} stream vectors, sentences dropped")
        status = subprocess.run([sys.executable, str(ROOT / "conformance" / "harness.py"), "--vectors", tmp,
                                 "--command", runner, "--name", "c-frames-only"], check=False).returncode
    return 1 if status != 0 or captures(tool, runner, rounds) else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
