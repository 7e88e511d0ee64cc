"""Code and RAM footprint of the C binding on a Cortex-M4 (make footprint-c).

Compiles generated/c/ilahrs.c with arm-none-eabi-gcc, then links three closures with
--gc-sections, keeping only what the named entry points reach (newlib-nano's memcpy/memchr and
libgcc's soft-float helpers included, since a firmware image needs them too):

- the stream decoder (ilahrs_stream_init/next/push/poll/finish/idle), and how much of it is the
  $PAHR validation it shares with ilahrs_pahr_parse (the sentence parser, also linked alone),
- the frames-only stream decoder (the library compiled with ILAHRS_STREAM_SENTENCES=0, for a
  firmware that never turns on NMEA output),
- the frame and command builders (ilahrs_frame_build, ilahrs_command_build, ilahrs_checksum,
  ilahrs_ack_build),
- the parameter-block (payload) builder, ilahrs_payload_build_frame, with the field table,
- the device state machine (ilahrs_transition_on, ilahrs_event_for_frame, ilahrs_state_timer),
- what a firmware links: the stream decoder, the frame and command builders and payload parse and
  build,
- a firmware core: that plus frame, command and sentence decoding and sentence encoding,
- the whole library without the host conveniences that take doubles (ilahrs_field_check,
  ilahrs_pahr_from_array/from_values), and the whole library (every public function),
- the firmware closure and the whole library again with the library compiled with ILAHRS_NAMES=0
  (no name strings, no name accessors or by-name lookups, errors without field names).

Prints the flash size (text: code and const tables) of each next to the targets, split into the
library's own code, its const tables and what newlib-nano/libgcc add, the decoder state size, and whether anything
uses the heap or static RAM. Sizes are measured, never assumed; targets are reported, not enforced.
"""

from __future__ import annotations

import argparse
import re
import shlex
import subprocess
import sys
from pathlib import Path

STREAM = ["ilahrs_stream_init", "ilahrs_stream_next", "ilahrs_stream_push", "ilahrs_stream_poll",
          "ilahrs_stream_finish", "ilahrs_stream_idle"]
BUILDERS = ["ilahrs_frame_build", "ilahrs_command_build", "ilahrs_checksum", "ilahrs_ack_build"]
BLOCKS = ["ilahrs_payload_build_frame"]
FIRMWARE = [*STREAM, *BUILDERS, *BLOCKS, "ilahrs_payload_parse", "ilahrs_payload_build"]
CORE = [*FIRMWARE, "ilahrs_frame_parse", "ilahrs_command_decode", "ilahrs_pahr_parse", "ilahrs_pahr_build",
        "ilahrs_error_kind_name"]
MACHINE = ["ilahrs_transition_on", "ilahrs_event_for_frame", "ilahrs_state_timer"]
# Host conveniences that take engineering values as doubles (done in integers: no soft-float).
DOUBLE_HELPERS = {"ilahrs_field_check", "ilahrs_pahr_from_array", "ilahrs_pahr_from_values"}
TARGETS = {"stream decoder": 512, "stream decoder, frames only": 512, "sentence parser": None,
           "frame and command builders": None, "payload builder": None, "state machine": None, "firmware": 4096,
           "firmware core": None,
           "whole library without the double helpers": 8 * 1024, "whole library": 8 * 1024,
           "firmware, names off": None, "whole library, names off": 8 * 1024}
STATE_TARGET = 128
HEAP_SYMBOLS = {"malloc", "free", "calloc", "realloc", "_sbrk", "_malloc_r", "_free_r"}


def run(cmd: list[str]) -> str:
    result = subprocess.run(cmd, capture_output=True, text=True, check=False)
    if result.returncode != 0:
        sys.stderr.write(f"$ {shlex.join(cmd)}\n{result.stdout}{result.stderr}")
        raise SystemExit(1)
    return result.stdout


def tool(cc: str, name: str) -> str:
    return re.sub(r"gcc$", name, cc)


def size_of(cc: str, elf: Path) -> tuple[int, int, int]:
    out = run([tool(cc, "size"), str(elf)]).splitlines()[1].split()
    return int(out[0]), int(out[1]), int(out[2])


def symbols(cc: str, elf: Path) -> list[tuple[int, int, str, bool]]:
    """(address, size, name, is code) of every sized code or data symbol, one name per address."""
    rows: dict[int, tuple[int, int, str, bool]] = {}
    for line in run([tool(cc, "nm"), "--size-sort", "-S", str(elf)]).splitlines():
        parts = line.split()
        if len(parts) == 4 and parts[2].lower() in ("t", "r", "d", "b"):
            address = int(parts[0], 16)
            row = (address, int(parts[1], 16), parts[3], parts[2].lower() == "t")
            if address not in rows or parts[3].startswith("__aeabi"):  # libgcc aliases: one name
                rows[address] = row
    return sorted(rows.values(), key=lambda r: (-r[1], r[2]))


def link(cc: str, flags: list[str], obj: Path, entries: list[str], elf: Path) -> None:
    keep = [f"-Wl,-u,{name}" for name in entries]
    run([cc, *flags, "-nostartfiles", "--specs=nano.specs", "-Wl,--gc-sections", f"-Wl,-e,{entries[0]}",
         *keep, str(obj), "-o", str(elf), "-lc", "-lgcc"])


def type_sizes(cc: str, flags: list[str], include: Path, out: Path) -> dict[str, int]:
    """Decoder state and message sizes, from the compiler: ilahrs_sizeof_stream and _message."""
    probe = out / "sizes.c"
    probe.write_text(
        '#include "ilahrs.h"\n'
        "const char ilahrs_sizeof_stream[sizeof(ilahrs_stream_t)] = {0};\n"
        "const char ilahrs_sizeof_message[sizeof(ilahrs_message_t)] = {0};\n",
        encoding="utf-8",
    )
    probe_obj = out / "sizes.o"
    run([cc, *flags, f"-I{include}", "-c", str(probe), "-o", str(probe_obj)])
    return {
        parts[3]: int(parts[1], 16)
        for parts in (line.split() for line in run([tool(cc, "nm"), "-S", str(probe_obj)]).splitlines())
        if len(parts) == 4
    }


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--cc", default="arm-none-eabi-gcc")
    parser.add_argument("--flags", required=True)
    parser.add_argument("--source", type=Path, required=True)
    parser.add_argument("--include", type=Path, required=True)
    parser.add_argument("--out", type=Path, required=True)
    args = parser.parse_args()
    flags = shlex.split(args.flags)
    out: Path = args.out
    out.mkdir(parents=True, exist_ok=True)
    obj = out / "ilahrs.o"
    run([args.cc, *flags, f"-I{args.include}", "-c", str(args.source), "-o", str(obj)])
    variants = {"": obj, "frames only": out / "ilahrs_frames_only.o", "names off": out / "ilahrs_names_off.o"}
    for variant, define in (("frames only", "-DILAHRS_STREAM_SENTENCES=0"), ("names off", "-DILAHRS_NAMES=0")):
        run([args.cc, *flags, define, f"-I{args.include}", "-c", str(args.source), "-o", str(variants[variant])])

    # Static RAM and heap use of the library itself, in every variant.
    obj_text, _, _ = size_of(args.cc, obj)
    static_ram = max(sum(size_of(args.cc, o)[1:]) for o in variants.values())
    undefined = set().union(*(set(run([tool(args.cc, "nm"), "-u", str(o)]).split()) for o in variants.values())) - {"U"}

    def public_of(o: Path) -> list[str]:
        defined = run([tool(args.cc, "nm"), "-g", "--defined-only", str(o)]).splitlines()
        return sorted(parts[2] for parts in (line.split() for line in defined) if len(parts) == 3 and parts[1] == "T")

    public = public_of(obj)

    sizes = type_sizes(args.cc, flags, args.include, out)

    print(f"compiler: {run([args.cc, '--version']).splitlines()[0]}")
    print(f"flags: {args.flags}")
    print(f"library object: text {obj_text} (code and const tables)")
    linked: dict[str, set[tuple[str, int]]] = {}
    own = {line.split()[-1] for o in variants.values()
           for line in run([tool(args.cc, "nm"), "--defined-only", str(o)]).splitlines()}
    groups = {"stream decoder": STREAM, "stream decoder, frames only": STREAM,
              "sentence parser": ["ilahrs_pahr_parse"],
              "frame and command builders": BUILDERS, "payload builder": BLOCKS, "state machine": MACHINE,
              "firmware": FIRMWARE, "firmware core": CORE,
              "whole library without the double helpers": [p for p in public if p not in DOUBLE_HELPERS],
              "whole library": public,
              "firmware, names off": FIRMWARE, "whole library, names off": public_of(variants["names off"])}
    for name, entries in groups.items():
        elf = out / (name.replace(",", "").replace(" ", "_") + ".elf")
        variant = name.split(", ")[-1] if ", " in name else ""
        link(args.cc, flags, variants[variant], entries, elf)
        text, _data, _bss = size_of(args.cc, elf)
        rows = symbols(args.cc, elf)
        code = sum(size for _, size, sym, is_code in rows if sym in own and is_code)
        tables = sum(size for _, size, sym, is_code in rows if sym in own and not is_code)
        target = TARGETS[name]
        verdict = "" if target is None else f"  (target <= {target}: {'met' if text <= target else 'NOT met'})"
        print(f"{name}: text {text} = {code} library code + {tables} library const tables + "
              f"{text - code - tables} newlib-nano/libgcc and alignment{verdict}")
        print("    largest: " + ", ".join(f"{sym} {size}" for _, size, sym, _ in rows[:8]))
        linked[name] = {(sym, size) for _, size, sym, _ in rows}
    shared = sum(size for _, size in linked["stream decoder"] & linked["sentence parser"])
    print(f"stream decoder without the $PAHR validation it shares with ilahrs_pahr_parse: "
          f"{sum(size for _, size in linked['stream decoder']) - shared} (shared: {shared})")
    state = sizes["ilahrs_sizeof_stream"]
    print(f"decoder state (ilahrs_stream_t): {state} bytes of RAM, caller-owned "
          f"(target <= {STATE_TARGET}: {'met' if state <= STATE_TARGET else 'NOT met'})")
    print(f"message (ilahrs_message_t, on the caller's stack): {sizes['ilahrs_sizeof_message']} bytes")
    heap = sorted(undefined & HEAP_SYMBOLS)
    print(f"heap: {'none' if not heap else 'uses ' + ', '.join(heap)} (target: none)")
    print(f"static RAM (data + bss of the library, any variant): {static_ram} bytes (target: 0)")
    print(f"library calls: {', '.join(sorted(undefined)) or 'none'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
