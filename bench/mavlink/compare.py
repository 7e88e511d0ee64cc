"""Our C stream decoder beside MAVLink's mavlink_parse_char(): make bench-mavlink.

Runs the host benchmark (bench_mavlink.c, gcc -O2) for throughput, the same program under
valgrind's callgrind on a 1 MiB capture of each protocol for instructions per byte (-Os and -O2
builds), and builds the smallest Cortex-M4 firmware around each decoder (m4_ours.c, m4_theirs.c)
for flash and RAM. Prints one line per figure: ours / theirs, which way is better, and whether
ours is no worse. Targets are reported, not enforced. bench/mavlink/README.md says what each
figure measures and how.

    compare.py --bench-o2 BIN --bench-os BIN --ilahrs DIR --mavlink DIR --cc arm-none-eabi-gcc
               --flags "..." --out DIR [--size BYTES] [--callgrind-size BYTES]
"""

from __future__ import annotations

import argparse
import re
import shlex
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

HERE = Path(__file__).resolve().parent
DECODERS = ("ours-whole", "ours-bytes", "theirs-whole", "theirs-bytes")
# MAVLink configured as its smallest single-channel decoder without signing.
MAVLINK_DEFINES = ["-DMAVLINK_COMM_NUM_BUFFERS=1", "-DMAVLINK_NO_SIGNATURE_CHECK", "-DMAVLINK_NO_SIGN_PACKET"]


@dataclass(frozen=True)
class Figure:
    label: str
    unit: str
    ours: float
    theirs: float
    higher_is_better: bool
    digits: int = 0

    def no_worse(self) -> bool:
        return self.ours >= self.theirs if self.higher_is_better else self.ours <= self.theirs

    def line(self) -> str:
        better = "higher" if self.higher_is_better else "lower"
        ratio = self.ours / self.theirs if self.theirs else float("inf")
        return (
            f"{self.label}: ours {self.ours:,.{self.digits}f} / theirs {self.theirs:,.{self.digits}f}{self.unit} "
            f"= {ratio:.2f} ({better} is better); ours no worse: {'yes' if self.no_worse() else 'no'}"
        )


def run(cmd: list[str]) -> str:
    result = subprocess.run(cmd, capture_output=True, text=True, check=False)
    if result.returncode != 0:
        sys.stderr.write(f"$ {shlex.join(cmd)}\n{result.stdout}{result.stderr}")
        raise SystemExit(1)
    return result.stdout


def keyed(text: str) -> dict[str, str]:
    """The `key: value` lines of bench_mavlink's output."""
    return dict(line.split(": ", 1) for line in text.splitlines() if ": " in line)


def first_number(text: str) -> float:
    match = re.search(r"[0-9][0-9.]*", text)
    if match is None:
        raise SystemExit(f"compare.py: no number in {text!r}")
    return float(match.group())


def instructions(binary: Path, decoder: str, size: int, out: Path) -> float:
    """Instructions per input byte that callgrind counts inside measured() for one decoder."""
    log = out / f"callgrind.{binary.name}.{decoder}.out"
    run(
        [
            "valgrind",
            "--tool=callgrind",
            "--toggle-collect=measured",
            f"--callgrind-out-file={log}",
            str(binary),
            "--measure",
            decoder,
            "--size",
            str(size),
        ]
    )
    totals = re.search(r"^totals: (\d+)", log.read_text(encoding="utf-8"), re.MULTILINE)
    if totals is None:
        raise SystemExit(f"compare.py: no totals in {log}")
    return int(totals.group(1)) / size


@dataclass(frozen=True)
class Image:
    text: int
    ram: int
    detail: str


def tool(cc: str, name: str) -> str:
    return re.sub(r"gcc$", name, cc)


def sizes_of(cc: str, flags: list[str], include: list[str], types: dict[str, str], out: Path) -> dict[str, int]:
    """sizeof of each type on the target, read from the symbol sizes of a probe object."""
    probe = out / f"sizes_{'_'.join(types)}.c"
    lines = [f"#include <{header}>" for header in dict.fromkeys(types.values())]
    lines += [f"const char sizeof_{name}[sizeof({name})] = {{0}};" for name in types]
    probe.write_text("\n".join(lines) + "\n", encoding="utf-8")
    obj = probe.with_suffix(".o")
    run([cc, *flags, *include, "-c", str(probe), "-o", str(obj)])
    found = {}
    for line in run([tool(cc, "nm"), "-S", str(obj)]).splitlines():
        parts = line.split()
        if len(parts) == 4 and parts[3].startswith("sizeof_"):
            found[parts[3].removeprefix("sizeof_")] = int(parts[1], 16)
    return found


def image(cc: str, flags: list[str], sources: list[Path], include: list[str], elf: Path) -> Image:
    """Text (code and const data) and static RAM (data + bss) of a firmware image."""
    run(
        [
            cc,
            *flags,
            *include,
            "-nostartfiles",
            "--specs=nano.specs",
            "-Wl,--gc-sections",
            "-Wl,-e,main",
            *map(str, sources),
            "-o",
            str(elf),
            "-lc",
            "-lgcc",
        ]
    )
    text, data, bss = (int(v) for v in run([tool(cc, "size"), str(elf)]).splitlines()[1].split()[:3])
    largest = []
    for line in run([tool(cc, "nm"), "--size-sort", "-r", "-S", str(elf)]).splitlines()[:6]:
        parts = line.split()
        if len(parts) == 4:
            largest.append(f"{parts[3]} {int(parts[1], 16)}")
    return Image(text, data + bss, ", ".join(largest))


def footprint(args: argparse.Namespace) -> tuple[list[Figure], list[str]]:
    flags = shlex.split(args.flags)
    out: Path = args.out / "m4"
    out.mkdir(parents=True, exist_ok=True)
    ours_inc = [f"-I{args.ilahrs}"]
    theirs_inc = [f"-isystem{args.mavlink}", *MAVLINK_DEFINES]
    ours = image(args.cc, flags, [HERE / "m4_ours.c", args.ilahrs / "ilahrs.c"], ours_inc, out / "ours.elf")
    frames = image(
        args.cc,
        [*flags, "-DILAHRS_STREAM_SENTENCES=0"],
        [HERE / "m4_ours.c", args.ilahrs / "ilahrs.c"],
        ours_inc,
        out / "ours_frames_only.elf",
    )
    theirs = image(args.cc, flags, [HERE / "m4_theirs.c"], theirs_inc, out / "theirs.elf")
    ours_types = sizes_of(
        args.cc, flags, ours_inc, {"ilahrs_stream_t": "ilahrs.h", "ilahrs_message_t": "ilahrs.h"}, out
    )
    theirs_types = sizes_of(
        args.cc, flags, theirs_inc, {"mavlink_message_t": "mavlink.h", "mavlink_status_t": "mavlink.h"}, out
    )
    caller_theirs = theirs_types["mavlink_message_t"] + theirs_types["mavlink_status_t"]
    figures = [
        Figure(
            "Cortex-M4 text of the decoder closure (tiny main, --gc-sections)",
            " bytes",
            ours.text,
            theirs.text,
            higher_is_better=False,
        ),
        Figure(
            "Cortex-M4 RAM per channel (static RAM: decoder state and buffers)",
            " bytes",
            ours.ram,
            theirs.ram,
            higher_is_better=False,
        ),
        Figure(
            "Cortex-M4 stack for the message handed to the caller",
            " bytes",
            ours_types["ilahrs_message_t"],
            caller_theirs,
            higher_is_better=False,
        ),
    ]
    notes = [
        f"    ours largest: {ours.detail}",
        f"    theirs largest: {theirs.detail}",
        f"    ours RAM: ilahrs_stream_t {ours_types['ilahrs_stream_t']} + the main's 4-byte sink; "
        f"theirs RAM: one channel's mavlink_message_t {theirs_types['mavlink_message_t']} + mavlink_status_t "
        f"{theirs_types['mavlink_status_t']} (static in mavlink_helpers.h) + the same sink",
        f"    ours stack: ilahrs_message_t; theirs stack: the mavlink_message_t copy and the mavlink_status_t "
        f"mavlink_parse_char() fills ({theirs_types['mavlink_message_t']} + {theirs_types['mavlink_status_t']})",
        f"    ours frames-only build (-DILAHRS_STREAM_SENTENCES=0, no $PAHR): text {frames.text} bytes, "
        f"RAM {frames.ram} bytes",
    ]
    return figures, notes


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--bench-o2", type=Path, required=True)
    parser.add_argument("--bench-os", type=Path, required=True)
    parser.add_argument("--ilahrs", type=Path, required=True, help="folder of ilahrs.h and ilahrs.c")
    parser.add_argument("--mavlink", type=Path, required=True, help="folder of the dialect's mavlink.h")
    parser.add_argument("--cc", default="arm-none-eabi-gcc")
    parser.add_argument("--flags", required=True, help="Cortex-M4 compiler flags")
    parser.add_argument("--out", type=Path, required=True)
    parser.add_argument("--size", type=int, default=16 << 20, help="bytes per capture for throughput")
    parser.add_argument("--callgrind-size", type=int, default=1 << 20, help="bytes per capture under callgrind")
    args = parser.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)

    report = run([str(args.bench_o2), "--size", str(args.size)])
    (args.out / "bench_o2.txt").write_text(report, encoding="utf-8")
    values = keyed(report)
    print(
        "MAVLink beside us: ours = the ilahrs C stream decoder (generated/c), theirs = mavlink_parse_char() "
        "(pymavlink mavgen, C, MAVLink 2, bench/mavlink/dialect.py, no signing)"
    )
    for key in ("ours_capture", "theirs_capture", "ours_decoded", "theirs_decoded"):
        print(f"{key}: {values[key]}")

    speed = {name: first_number(values[name]) for name in DECODERS}
    figures = [
        Figure(
            f"throughput fed whole ({values['build']})",
            " MiB/s",
            speed["ours-whole"],
            speed["theirs-whole"],
            higher_is_better=True,
        ),
        Figure(
            f"throughput fed one byte at a time ({values['build']})",
            " MiB/s",
            speed["ours-bytes"],
            speed["theirs-bytes"],
            higher_is_better=True,
        ),
    ]
    for label, binary in (
        ("-Os, as on a Cortex-M", args.bench_os),
        ("-O2, host build", args.bench_o2),
    ):
        per_byte = {name: instructions(binary, name, args.callgrind_size, args.out) for name in DECODERS}
        for mode, text in (("whole", "fed whole"), ("bytes", "fed one byte at a time")):
            figures.append(
                Figure(
                    f"instructions per byte {text} (callgrind, {label})",
                    "",
                    per_byte[f"ours-{mode}"],
                    per_byte[f"theirs-{mode}"],
                    higher_is_better=False,
                    digits=1,
                )
            )
    m4_figures, notes = footprint(args)
    figures += m4_figures
    for figure in figures:
        print(figure.line())
    print("\n".join(notes))
    behind = [figure.label for figure in figures if not figure.no_worse()]
    print(
        f"ours no worse on every figure: {'yes' if not behind else 'no'}"
        + (f" (behind: {'; '.join(behind)})" if behind else "")
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
