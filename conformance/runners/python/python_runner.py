"""Conformance runner for the Python binding (package `ilahrs`, generated/python).

The line protocol of conformance/README.md, nothing else: parse a request, call the binding,
format its answer or its IlahrsError. All test logic lives in conformance/harness.py.
Implements every kind; `session` walks the binding's generated state machine (ilahrs.statemachine).
"""

from __future__ import annotations

import math
import sys
import traceback
from collections.abc import Callable
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[3] / "generated" / "python"))

import ilahrs
from ilahrs import statemachine


def read_hex(token: str) -> bytes:
    return b"" if token == "-" else bytes.fromhex(token)


def write_hex(data: bytes) -> str:
    return data.hex().upper() if data else "-"


def read_text(token: str) -> bytes:
    out = bytearray()
    i = 0
    while i < len(token):
        if token[i] == "%":
            out.append(int(token[i + 1:i + 3], 16))
            i += 3
        else:
            out.append(ord(token[i]))
            i += 1
    return bytes(out)


def write_text(data: bytes) -> str:
    return "".join(chr(b) if 0x21 <= b <= 0x7E and b not in b"%,=" else f"%{b:02X}" for b in data)


def write_num(value: float) -> str:
    return "nan" if math.isnan(value) else repr(float(value))


def pairs(tokens: list[str]) -> dict[str, str]:
    return dict(token.split("=", 1) for token in tokens)


def write_raw(value: int | float | str | bytes) -> str:
    if isinstance(value, bytes):
        return write_hex(value)
    if isinstance(value, str):
        return write_text(value.encode("latin-1"))
    if isinstance(value, float):
        return write_num(value)
    return str(value)


def read_raw(field_type: str, token: str) -> object:
    """A FIELD=VALUE token as the Python type the payload class holds for that wire type."""
    if field_type == "f32":
        return float(token)
    if field_type == "char":
        return read_text(token).decode("latin-1")
    if field_type == "reserved":
        return read_hex(token)
    return int(token)


def variant(name: str | None) -> ilahrs.Variant | None:
    return None if name is None or name == "-" else ilahrs.VARIANTS[name]


def checksum(args: list[str]) -> str:
    return f"ok {ilahrs.checksum(read_hex(args[0]))}"


class UnknownOptionError(Exception):
    """A request token this runner does not know: the vector fails, it is never ignored."""


def options(tokens: list[str], known: tuple[str, ...]) -> dict[str, str]:
    """Option tokens after a request's operands: `NAME` (a flag) or `NAME=VALUE`."""
    found = {}
    for token in tokens:
        name, _, value = token.partition("=")
        if name not in known:
            raise UnknownOptionError(token)
        found[name] = value
    return found


def frame_decode(args: list[str]) -> str:
    strict = "strict" in options(args[1:], ("strict",))
    frame = ilahrs.Frame.parse(read_hex(args[0]), strict=strict)
    return f"ok message_type={int(frame.message_type)} reserved={frame.reserved} payload={write_hex(frame.payload)}"


def frame_encode(args: list[str]) -> str:
    reserved = int(args[2]) if len(args) > 2 else 0
    return f"ok {write_hex(ilahrs.Frame(int(args[0]), read_hex(args[1]), reserved).build())}"


def command_encode(args: list[str]) -> str:
    return f"ok {write_hex(ilahrs.build_command(args[0]))}"


def command_decode(args: list[str]) -> str:
    code, names = ilahrs.decode_command(read_hex(args[0]))
    return f"ok code={code} names={','.join(names) or '-'}"


def ack(args: list[str]) -> str:
    return f"ok {write_hex(ilahrs.ack_for(read_hex(args[0])))}"


def payload_decode(args: list[str]) -> str:
    obj = ilahrs.PAYLOADS[args[0]].parse(read_hex(args[1]))
    fields = [f"f.{name}={write_raw(value)}" for name, value in obj.raw().items()]
    values = [f"v.{name}={write_num(value)}" for name, value in
              obj.values(variant(args[2] if len(args) > 2 else None)).items()]
    return " ".join(["ok", *fields, *values])


def payload_encode(args: list[str]) -> str:
    cls = ilahrs.PAYLOADS[args[0]]
    types = {f.name: f.type for f in cls.FIELDS}
    given = pairs(args[2:])
    values = {name: read_raw(types[name], token) if name in types else token for name, token in given.items()}
    return f"ok {write_hex(cls.from_raw(values).build())}"


def nmea_decode(args: list[str]) -> str:
    values = ilahrs.PahrSentence.parse(read_text(args[0])).values()
    return "ok " + " ".join(f"{k}={int(v) if k == 'usw' else write_num(v)}" for k, v in values.items())


def nmea_encode(args: list[str]) -> str:
    given = pairs(args)
    sentence = ilahrs.PahrSentence.from_values(
        roll=float(given["roll"]), pitch=float(given["pitch"]), heading=float(given["heading"]),
        temperature=float(given["temperature"]), vdd=float(given["vdd"]), usw=int(given["usw"]))
    return f"ok {write_text(sentence.build().encode('latin-1'))}"


def stream(args: list[str]) -> str:
    given = options(args[1:], ("strict", "idle"))
    gaps: dict[int, list[int]] = {}
    for gap in given["idle"].split(",") if "idle" in given else []:
        after, quiet = gap.split(":")
        gaps.setdefault(int(after), []).append(int(quiet))
    decoder = ilahrs.StreamDecoder(strict="strict" in given)
    events: list[ilahrs.StreamEvent] = []
    for n, chunk in enumerate(args[0].split(",") if args else []):
        events += decoder.feed(read_hex(chunk))
        for us in gaps.get(n, []):
            events += decoder.idle(us / 1_000_000)
    events += decoder.finish()
    tokens = [f"F:{write_hex(e.raw)}" if e.frame is not None else f"N:{write_text(e.raw)}" for e in events]
    return f"ok discarded={decoder.discarded} events={','.join(tokens) or '-'}"


def session_event(token: str, state: str) -> str:
    """`C:HH`, `D:N` or `E:NAME` as the table's event in `state`: a code is the command it means
    there (`unknown` if none), a data message the parameter block when the state expects a block
    of that size."""
    kind, _, value = token.partition(":")
    if kind == "C":
        return statemachine.command_event(int(value, 16), state) or "unknown"
    if kind == "D":
        expects = statemachine.STATES[state].expects
        size_fits = expects is not None and int(value) == ilahrs.PAYLOADS[expects].SIZE
        return statemachine.PARAMETER_BLOCK if size_fits else statemachine.OTHER_MESSAGE
    return value


def session(args: list[str]) -> str:
    firmware = None if args[0] == "-" else args[0]
    state = statemachine.INITIAL
    steps = []
    for token in args[1].split(","):
        event = session_event(token, state)
        transition = statemachine.lookup(state, event, firmware)
        sends: tuple[str, ...] = ()
        if transition is not None:
            state, sends = transition.to, transition.send
        steps.append(f"{event}>{state}>{'+'.join(sends) or '-'}")
    return f"ok steps={','.join(steps)}"


HANDLERS: dict[str, Callable[[list[str]], str]] = {
    "checksum": checksum, "frame_decode": frame_decode, "frame_encode": frame_encode,
    "command_encode": command_encode, "command_decode": command_decode, "ack": ack,
    "payload_decode": payload_decode, "payload_encode": payload_encode,
    "nmea_decode": nmea_decode, "nmea_encode": nmea_encode, "stream": stream, "session": session,
}


def answer(line: str) -> str:
    kind, *args = line.split(" ")
    handler = HANDLERS.get(kind)
    if handler is None:
        return "unsupported"
    try:
        return handler(args)
    except UnknownOptionError as unknown:
        return f"crash unknown%20option%20{write_text(str(unknown).encode())}"
    except ilahrs.IlahrsError as err:
        offset = "-" if err.offset is None else str(err.offset)
        return f"error {err.kind.value} {offset} {err.field or '-'}"


def main() -> int:
    for raw in sys.stdin:
        line = raw.rstrip("\r\n")
        try:
            reply = answer(line)
        except Exception as exc:  # a crash in the binding: say so on this line, keep serving
            traceback.print_exc(file=sys.stderr)
            reply = f"crash {write_text(f'{type(exc).__name__}: {exc}'.encode('utf-8', 'replace'))}"
        sys.stdout.write(reply + "\n")
        sys.stdout.flush()
    return 0


if __name__ == "__main__":
    sys.exit(main())
