"""Many captures into one Parquet dataset: `ilahrs decode DIR --to parquet OUT --jobs J` for 1, 2
and N jobs (N: the processors), captures per second and messages per second, end to end as a user
runs it (a subprocess: start-up, the fork server and its imports included).

The captures are two-direction pcapng files made by the device model (bench_decode's
two_way_capture: Stop, AHRScont1, output frames 10 ms apart, Stop, ReadAHRSPar, the output again),
each with another seed of frame count so that no two are the same file; one in four is written as a
raw dump of its device-to-host bytes instead. Beside them, `ilahrs decode CAPTURE --to csv` of
one capture: the decoding the dataset is made of, without Arrow or Parquet.

    .venv/bin/python bench/python/bench_dataset.py [--captures C] [--frames F] [--repeat R]
"""

from __future__ import annotations

import argparse
import io
import os
import platform
import re
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from bench_decode import two_way_capture

import ilahrs
from ilahrs.cli.to_parquet import default_jobs

ILAHRS = [sys.executable, "-m", "ilahrs"]


def make_captures(folder: Path, count: int, frames: int) -> None:
    for i in range(count):
        data = two_way_capture(frames + i)
        if i % 4 == 3:
            capture = ilahrs.pcapng.read(io.BytesIO(data))
            inbound = [p.data for p in capture.packets if p.direction == ilahrs.pcapng.Direction.INBOUND]
            (folder / f"unit{i:02d}.bin").write_bytes(b"".join(inbound))
        else:
            (folder / f"unit{i:02d}.pcapng").write_bytes(data)


def run(args: list[str]) -> tuple[float, str]:
    """Seconds (wall) and stderr of `ilahrs ARGS`."""
    start = time.perf_counter()
    done = subprocess.run([*ILAHRS, *args], capture_output=True, text=True, check=False)
    seconds = time.perf_counter() - start
    if done.returncode != 0:
        raise SystemExit(f"ilahrs {' '.join(args)}: {done.stderr.strip()}")
    return seconds, done.stderr


def messages(summary: str) -> int:
    found = re.search(r"(\d+) messages", summary)
    assert found is not None, summary
    return int(found.group(1))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--captures", type=int, default=12, help="captures in the folder (default 12)")
    parser.add_argument("--frames", type=int, default=20_000, help="output frames per capture (default 20000)")
    parser.add_argument("--repeat", type=int, default=1, help="runs of each; the best counts (default 1)")
    options = parser.parse_args()
    cores = default_jobs()
    print(
        f"python {platform.python_version()}, {platform.machine()}, {cores} processors, load {os.getloadavg()[0]:.1f}"
    )
    with tempfile.TemporaryDirectory(prefix="bench-dataset-") as scratch:
        folder = Path(scratch) / "captures"
        folder.mkdir()
        make_captures(folder, options.captures, options.frames)
        size = sum(p.stat().st_size for p in folder.iterdir())
        print(f"{options.captures} captures ({size / 1e6:.1f} MB), {options.frames} output frames each")
        one = next(folder.glob("*.pcapng"))
        best = min(
            run(["decode", str(one), "--to", "csv", str(Path(scratch) / "one.csv")])[0] for _ in range(options.repeat)
        )
        count = messages(run(["decode", str(one), "--to", "csv", str(Path(scratch) / "one.csv")])[1])
        print(f"  decode --to csv, one capture:   {count / best:>9,.0f} messages/s ({best:.2f} s)")
        for jobs in sorted({1, 2, cores}):
            times = []
            total = 0
            for _ in range(options.repeat):
                out = Path(scratch) / "dataset"
                shutil.rmtree(out, ignore_errors=True)
                seconds, summary = run(["decode", str(folder), "--to", "parquet", str(out), "--jobs", str(jobs)])
                times.append(seconds)
                total = messages(summary)
            best = min(times)
            rate = options.captures / best
            print(
                f"  --to parquet --jobs {jobs}: {rate:>6.2f} captures/s,"
                f" {total / best:>9,.0f} messages/s ({best:.2f} s)"
            )


if __name__ == "__main__":
    main()
