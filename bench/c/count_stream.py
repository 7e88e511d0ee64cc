"""Instructions per byte of the C stream decoder, counted by valgrind's callgrind (make bench-c).

Runs count_stream (bench/c/count_stream.c, built with the flags a Cortex-M build uses) under
`valgrind --tool=callgrind`, collecting only decode_whole() or decode_bytes(): the decoder fed the
capture as one buffer, and fed one byte at a time. Prints one line per mode with the instructions
counted divided by the capture's size, next to the target for byte-at-a-time feeding.

    python bench/c/count_stream.py BINARY [--size BYTES] [--out DIR] [--build TEXT]
"""

from __future__ import annotations

import argparse
import re
import subprocess
import sys
from pathlib import Path

TARGET_BYTES = 60  # instructions per byte, fed one byte at a time
MODES = {"whole": ("decode_whole", "fed whole (ilahrs_stream_next)"),
         "bytes": ("decode_bytes", "fed one byte at a time (ilahrs_stream_push)")}


def counted(binary: str, mode: str, size: int, out: Path) -> int:
    """Instructions callgrind counts inside the mode's decode function."""
    function, _ = MODES[mode]
    report = out / f"callgrind.{mode}.out"
    cmd = ["valgrind", "--tool=callgrind", f"--toggle-collect={function}", f"--callgrind-out-file={report}",
           binary, mode, "--size", str(size)]
    done = subprocess.run(cmd, capture_output=True, text=True, check=False)
    if done.returncode != 0:
        sys.stderr.write(done.stdout + done.stderr)
        raise SystemExit(1)
    found = re.search(r"^(?:summary|totals):\s+(\d+)", report.read_text(encoding="utf-8"), re.MULTILINE)
    if found is None:
        raise SystemExit(f"no instruction total in {report}")
    return int(found.group(1))


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("binary")
    parser.add_argument("--size", type=int, default=1 << 20)
    parser.add_argument("--out", type=Path, default=Path("."))
    parser.add_argument("--build", default="")
    args = parser.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)
    for mode, (_, what) in MODES.items():
        per_byte = counted(args.binary, mode, args.size, args.out) / args.size
        verdict = "met" if per_byte <= TARGET_BYTES else "NOT met"
        target = f" (target <= {TARGET_BYTES}: {verdict})" if mode == "bytes" else ""
        print(f"c_stream instructions/byte, {what}, {args.build}, callgrind on {args.size >> 20} MiB: "
              f"{per_byte:.1f}{target}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
