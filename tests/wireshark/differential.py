"""The generated Wireshark dissector against the Python binding, message by message (`make test-wireshark`).

1. Records a session with the virtual AHRS (session.py): every command, every payload table, 2D,
   3D and 2D-2T calibrations, $PAHR output, garbage, split and merged packets, a damaged frame and
   a damaged sentence, output arriving after Stop.
2. Checks the pcapng writer against tshark: same packets, bytes, microsecond timestamps,
   directions, interface name and description; and against the package's own reader.
3. Runs `tshark -2 -X lua_script:ilahrs.lua -T json -x` and compares every packet with the Python
   binding's decode of the same capture (reference.py): the messages in order with their kind,
   table, command or source, late flag, checksum status and every field's raw and engineering
   value; the bytes discarded. Each damaged message must carry the bad-checksum expert warning.
   Again for another device variant, chosen in the dissector's preferences.
4. The same session over TCP (Ethernet, IPv4, TCP in pcapng) on the port of the preferences must
   give the same messages.
5. generated/docs/wireshark.md names exactly the fields tshark registers.
6. A capture of random traffic (valid and broken frames and sentences, unknown commands, noise,
   both directions, any chunking) decodes without a Lua error, into the messages and discarded
   bytes the binding's StreamDecoder finds, packet by packet.

    python tests/wireshark/differential.py generated/wireshark/ilahrs.lua OUT_DIR
"""

from __future__ import annotations

import random
import re
import struct
import sys
from pathlib import Path
from typing import Any

import reference
import session
import tshark
from reference import Expected, PacketExpected, Value

import ilahrs
from ilahrs.pcapng import Direction, PcapngWriter, line_description, read

P = tshark.PROTO
OTHER_VARIANT = "sn_11ac0001_0009"
TCP_PORT = 4001


class MismatchError(AssertionError):
    pass


def check(condition: bool, where: str, detail: str) -> None:
    if not condition:
        raise MismatchError(f"{where}: {detail}")


def same_value(expected: Value, shown: Any, raw: Any) -> bool:
    if shown is None:
        return False
    if expected.kind == "int":
        return bool(int(shown, 0) == expected.value)
    if expected.kind == "double":
        return float(shown) == float(f"{expected.value:.15g}")
    if expected.kind == "float":
        wire = expected.wire if expected.wire is not None else struct.pack("<f", expected.value)
        return float(shown) == float(f"{expected.value:.6g}") and bytes.fromhex(raw[0]) == wire
    if expected.kind == "text":
        return bool(shown == expected.value)
    return bool(bytes.fromhex(str(shown).replace(":", "")) == expected.value)


def compare_message(where: str, expected: Expected, tree: tshark.Tree) -> int:
    """Compare one message; return the number of field values compared."""
    check(tree.get(f"{P}.kind") == expected.kind, where, f"kind {tree.get(f'{P}.kind')!r}, expected {expected.kind!r}")
    check(
        tree.get(f"{P}.table") == expected.table,
        where,
        f"table {tree.get(f'{P}.table')!r}, expected {expected.table!r}",
    )
    check(tree.get(f"{P}.command") == expected.command, where, f"command {tree.get(f'{P}.command')!r}")
    if expected.direction == "device":
        check(
            tree.get(f"{P}.source") == expected.source,
            where,
            f"source {tree.get(f'{P}.source')!r}, expected {expected.source!r}",
        )
    check((tree.get(f"{P}.late") == "1") == expected.late, where, "late flag")
    check(tree.has(f"{P}.expert.wrong_ack") == expected.wrong, where, "wrong acknowledgement")
    check(tree.has(f"{P}.expert.missing") == (expected.missing is not None), where, f"missing {expected.missing}")
    check(tree.has(f"{P}.expert.unexpected") == (expected.kind == "unexpected"), where, "unexpected")
    check(tree.get(f"{P}.checksum.status") == "1", where, "checksum status not good")
    if expected.direction == "device":
        link = tree.get(f"{P}.ack_frame" if expected.kind == "ack" else f"{P}.request_in")
        check(
            link == (str(expected.request) if expected.request else None),
            where,
            f"linked to frame {link}, expected {expected.request}",
        )
    if expected.direction == "host" and expected.kind == "command":
        check(tree.has(f"{P}.response_in") == expected.answered, where, "answered-in link")
    shown = {k for k, _ in tree.items if k.startswith((f"{P}.{expected.table}.", reference.SENTENCE))}
    names = {k for k in shown if not k.endswith("_raw")}
    names -= {f"{reference.SENTENCE}.{name}" for name in ("sentence", "checksum", "checksum.computed")}
    check(names == set(expected.values), where, f"fields {sorted(names ^ set(expected.values))}")
    for name, value in expected.values.items():
        got = tree.get(name)
        check(same_value(value, got, tree.get(name + "_raw")), where, f"{name} = {got!r}, expected {value}")
    return len(expected.values)


def compare(capture_path: Path, shown: list[tshark.Shown], expected: list[PacketExpected]) -> tuple[int, int]:
    check(len(shown) == len(expected), str(capture_path), f"{len(shown)} packets shown, {len(expected)} read")
    messages = values = 0
    for number, (packet, wanted) in enumerate(zip(shown, expected, strict=True), start=1):
        trees = [t for t in packet.trees if t.has(f"{P}.kind")]
        discarded = sum(len(str(t.get(f"{P}.discarded")).split(":")) for t in packet.trees if t.has(f"{P}.discarded"))
        where = f"{capture_path.name} frame {number}"
        kinds = [(t.get(f"{P}.kind"), t.get(f"{P}.table")) for t in trees]
        check(
            len(trees) == len(wanted.messages),
            where,
            f"{kinds}, expected {[(m.kind, m.table) for m in wanted.messages]}",
        )
        check(discarded == wanted.discarded, where, f"{discarded} bytes discarded, expected {wanted.discarded}")
        for index, (tree, message) in enumerate(zip(trees, wanted.messages, strict=True)):
            values += compare_message(f"{where} message {index + 1}", message, tree)
            messages += 1
    return messages, values


def mark_answered(expected: list[PacketExpected]) -> None:
    """A command the device answers links to its answer on the second pass."""
    last: Expected | None = None
    for packet in expected:
        for message in packet.messages:
            if message.direction == "host":
                last = message if message.kind in ("command", "parameter_block") else None
            elif last is not None and message.source in (last.command, last.table) and message.kind != "unexpected":
                last.answered = True


def check_capture_file(path: Path, recording: session.Recording, shown: list[tshark.Shown]) -> None:
    """The pcapng writer: what tshark and the package's reader read is what was written."""
    with path.open("rb") as f:
        capture = read(f)
    description = line_description(session.PORT, 115200)
    check([i.name for i in capture.interfaces] == [session.PORT], str(path), "interface name (reader)")
    check(len(shown) == len(recording.packets) == len(capture.packets), str(path), "packet count")
    directions = {Direction.INBOUND: 1, Direction.OUTBOUND: 2}
    for number, (written, got, packet) in enumerate(zip(recording.packets, capture.packets, shown, strict=True), 1):
        where = f"{path.name} frame {number}"
        check(
            (got.timestamp_us, got.direction, got.data) == (written.timestamp_us, written.direction, written.data),
            where,
            "the package's reader",
        )
        seconds, micro = divmod(written.timestamp_us, 1_000_000)
        check(
            packet.frame("frame.time_epoch") == f"{seconds}.{micro:06d}000",
            where,
            f"timestamp {packet.frame('frame.time_epoch')}",
        )
        check(int(packet.frame("frame.packet_flags_direction"), 0) == directions[written.direction], where, "direction")
        check(packet.raw() == written.data, where, "bytes")
        check(packet.frame("frame.interface_name") == session.PORT, where, "interface name")
        check(packet.frame("frame.interface_description") == description, where, "interface description")
        check(packet.frame("frame.encap_type") == "45", where, "encapsulation (USER0)")


def tcp_capture(path: Path, recording: session.Recording) -> None:
    """The session's chunks as TCP segments between 127.0.0.1:50000 (host) and :TCP_PORT (device)."""
    seq = {Direction.OUTBOUND: 1000, Direction.INBOUND: 9000}
    with path.open("wb") as f:
        writer = PcapngWriter(f, port="lo", baud=115200, linktype=1)
        for packet in recording.packets:
            out = packet.direction == Direction.OUTBOUND
            ports = (50000, TCP_PORT) if out else (TCP_PORT, 50000)
            ack = seq[Direction.INBOUND if out else Direction.OUTBOUND]
            tcp = struct.pack("!HHIIBBHHH", *ports, seq[packet.direction], ack, 5 << 4, 0x18, 65535, 0, 0)
            ip = struct.pack(
                "!BBHHHBBH4s4s",
                0x45,
                0,
                20 + len(tcp) + len(packet.data),
                0,
                0x4000,
                64,
                6,
                0,
                bytes([127, 0, 0, 1]),
                bytes([127, 0, 0, 1]),
            )
            ethernet = bytes(12) + b"\x08\x00"
            writer.write(ethernet + ip + tcp + packet.data, packet.timestamp_us, packet.direction)
            seq[packet.direction] += len(packet.data)


def summary(shown: list[tshark.Shown]) -> list[tuple[Any, ...]]:
    return [
        (t.get(f"{P}.kind"), t.get(f"{P}.table"), t.get(f"{P}.command"), t.get(f"{P}.source"))
        for packet in shown
        for t in packet.trees
        if t.has(f"{P}.kind")
    ]


def check_fields_doc(lua: Path) -> int:
    registered = {row[2] for row in tshark.fields(lua)}
    text = (lua.parent.parent / "docs" / "wireshark.md").read_text(encoding="utf-8")
    documented: set[str] = set()
    for row in re.findall(r"^\| `[a-z0-9_.]+` \|.*$", text, re.MULTILINE):
        cells = [cell.strip() for cell in row.strip("|").split(" | ")]
        name = cells[0].strip("`")
        documented.add(name)
        # A scaled value (its value cell: raw x multiplier / divisor) or a $PAHR decimal has `.raw`.
        scaled = "double" in cells and any(cell == "raw" or cell.startswith("raw ") for cell in cells)
        if scaled or any(cell.startswith("double (`.raw`") for cell in cells):
            documented.add(name + ".raw")
    difference = sorted(documented ^ registered)
    check(documented == registered, "docs/wireshark.md", f"differs from tshark -G fields: {difference}")
    return len(registered)


def random_traffic(path: Path, seed: int, count: int) -> None:
    """Frames of every table size and of random sizes, commands with any code, sentences (some
    damaged), noise; random directions and chunks."""
    rng = random.Random(seed)
    sizes = sorted({p.SIZE for p in ilahrs.PAYLOADS.values()})
    stream = {Direction.INBOUND: bytearray(), Direction.OUTBOUND: bytearray()}
    for _ in range(count):
        choice = rng.random()
        if choice < 0.45:
            size = rng.choice(sizes) if rng.random() < 0.8 else rng.randint(1, ilahrs.frame.MAX_PAYLOAD_SIZE)
            message = ilahrs.Frame(rng.choice((0, 1)), rng.randbytes(size), rng.choice((0, 0, 7))).build()
        elif choice < 0.7:
            message = ilahrs.Frame(ilahrs.MessageType.COMMAND, bytes([rng.randrange(256)])).build()
        elif choice < 0.85:
            sentence = ilahrs.PahrSentence(
                rng.randint(-18000, 18000), 0, rng.randint(0, 35999), 0, 500, rng.randrange(65536)
            )
            message = sentence.build().encode()
        else:
            message = rng.randbytes(rng.randint(1, 30))
        if rng.random() < 0.1:
            flip = rng.randrange(len(message))
            message = message[:flip] + bytes([message[flip] ^ (1 << rng.randrange(8))]) + message[flip + 1 :]
        stream[rng.choice(list(stream))] += message
    with path.open("wb") as f:
        writer = PcapngWriter(f, port="fuzz", baud=115200)
        now = session.EPOCH_US
        while any(stream.values()):
            direction = rng.choice([d for d, data in stream.items() if data])
            size = rng.randint(1, 90)
            writer.write(bytes(stream[direction][:size]), now, direction)
            del stream[direction][:size]
            now += rng.randint(1, 400_000)


def compare_streams(path: Path, shown: list[tshark.Shown]) -> tuple[int, int]:
    """Per packet, the messages and discarded bytes of the binding's StreamDecoder (one per direction)."""
    with path.open("rb") as f:
        capture = read(f)
    decoders = {Direction.INBOUND: ilahrs.StreamDecoder(), Direction.OUTBOUND: ilahrs.StreamDecoder()}
    found = discarded = 0
    for number, (packet, got) in enumerate(zip(capture.packets, shown, strict=True), start=1):
        decoder = decoders[packet.direction]
        before = decoder.discarded
        messages = [event.raw for event in decoder.feed(packet.data)]
        dropped = decoder.discarded - before
        trees = [t for t in got.trees if t.has(f"{P}.kind")]
        shown_dropped = sum(len(t.raw) for t in got.trees if t.has(f"{P}.discarded"))
        where = f"{path.name} frame {number}"
        check(
            [t.raw for t in trees] == messages,
            where,
            f"messages {[t.raw.hex() for t in trees]}, expected {[m.hex() for m in messages]}",
        )
        check(shown_dropped == dropped, where, f"{shown_dropped} bytes discarded, expected {dropped}")
        found += len(messages)
        discarded += dropped
    return found, discarded


def run_variant(
    lua: Path, out: Path, variant: str, options: tuple[str, ...]
) -> tuple[int, int, session.Recording, list[tshark.Shown]]:
    path = out / f"session-{variant}.pcapng"
    recording = session.record(path, variant=variant)
    missing_commands, missing_tables = recording.covered()
    check(
        not missing_commands and not missing_tables,
        str(path),
        f"never used: {sorted(missing_commands | missing_tables)}",
    )
    check(recording.late > 0, str(path), "no late output")
    shown = tshark.parse(tshark.run(lua, path, *options))
    with path.open("rb") as f:
        capture = read(f)
    expected = reference.Reference(ilahrs.VARIANTS[variant]).decode(capture)
    mark_answered(expected)
    messages, values = compare(path, shown, expected)
    wanted = [m for packet in expected for m in packet.messages]
    missing = [(m.kind, m.command or m.table, m.missing) for m in wanted if m.missing is not None]
    check(
        ("command", "ClearClb", "ack") in missing and ("output", "quaternion", "initial_alignment") in missing,
        str(path),
        f"missing answers: {missing}",
    )
    damaged = [t for packet in shown for t in packet.trees if t.has(f"{P}.damaged")]
    check(len(damaged) == len(recording.damaged), str(path), f"{len(damaged)} damaged messages shown")
    for tree, spoiled in zip(damaged, recording.damaged, strict=True):
        check(tree.has(f"{P}.expert.bad_checksum"), str(path), "a damaged message without the expert warning")
        if spoiled.startswith(b"$"):
            check(tree.get(f"{reference.SENTENCE}.sentence") == spoiled.decode().rstrip("\r\n"), str(path), "sentence")
        else:
            frame_payload = spoiled[ilahrs.frame.PAYLOAD_OFFSET : -ilahrs.frame.CHECKSUM_SIZE]
            check(bytes.fromhex(tree.get(f"{P}.payload").replace(":", "")) == frame_payload, str(path), "payload")
            sent = int.from_bytes(spoiled[-2:], "little")
            check(int(tree.get(f"{P}.checksum"), 0) == sent, str(path), "damaged checksum")
            check(int(tree.get(f"{P}.checksum.computed"), 0) == ilahrs.checksum(spoiled[2:-2]), str(path), "computed")
    return messages, values, recording, shown


def main(argv: list[str]) -> int:
    lua, out = Path(argv[1]), Path(argv[2])
    out.mkdir(parents=True, exist_ok=True)
    print(tshark.version())
    messages, values, recording, shown = run_variant(lua, out, "g300_a2_tmga", ())
    check_capture_file(
        out / "session-g300_a2_tmga.pcapng",
        recording,
        tshark.parse(tshark.run(lua, out / "session-g300_a2_tmga.pcapng", two_pass=False)),
    )
    print(
        f"pcapng writer: {len(recording.packets)} packets read back by tshark and ilahrs.pcapng, "
        "bytes, timestamps, directions and interface alike"
    )
    other = run_variant(lua, out, OTHER_VARIANT, (f"{P}.variant:{OTHER_VARIANT}",))
    print(
        f"tshark vs Python: {messages + other[0]} messages and {values + other[1]} field values identical "
        f"({len(recording.damaged) + len(other[2].damaged)} damaged messages flagged with the bad-checksum warning; "
        f"variants g300_a2_tmga and {OTHER_VARIANT})"
    )
    tcp = out / "session-tcp.pcapng"
    tcp_capture(tcp, recording)
    over_tcp = summary(tshark.parse(tshark.run(lua, tcp, f"{P}.tcp_port:{TCP_PORT}")))
    check(over_tcp == summary(shown), str(tcp), "TCP shows other messages than the serial capture")
    print(f"TCP port {TCP_PORT}: the same {len(over_tcp)} messages")
    print(f"docs/wireshark.md: {check_fields_doc(lua)} fields, as tshark registers them")
    noise = out / "random.pcapng"
    random_traffic(noise, seed=5, count=3000)
    text = tshark.run(lua, noise, fmt=("-V",))
    check("Lua Error" not in text and "[Malformed Packet" not in text, str(noise), "a Lua error")
    found, discarded = compare_streams(noise, tshark.parse(tshark.run(lua, noise)))
    print(
        f"random traffic: {found} messages and {discarded} discarded bytes as the StreamDecoder finds them, "
        "no Lua error"
    )
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv))
    except MismatchError as exc:
        print(f"FAILED: {exc}", file=sys.stderr)
        sys.exit(1)
