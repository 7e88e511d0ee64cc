"""Conformance runner for the Kaitai parser compiled from generated/kaitai/ilahrs.ksy.

Line protocol of conformance/README.md. Supports the decode kinds a Kaitai description can answer:

- `frame_decode`: the top-level type; a failed `contents`/`valid` check is mapped to the spec's
  error kind named by the attribute's `-ilahrs-error` key in the .ksy, running out of input to
  `truncated` at the input length, and bytes left after the checksum to `trailing_data`.
- `payload_decode`: the payload table's type. `f.` fields are the parsed attributes; `v.` values
  come from the .ksy's value instances: `<field>_<unit>` on the payload type, and for scales that
  divide by a variant parameter (KG, KA) the parametric type `<payload>_scaled`, given the named
  variant's parameters from the spec.

Every other kind is answered `unsupported` (building, commands, $PAHR and streams are not what a
Kaitai description expresses). Needs `make build-kaitai`.
"""

from __future__ import annotations

import math
import sys
import traceback
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]
sys.path[:0] = [str(ROOT), str(ROOT / "tests" / "support")]

import kaitai_support as ks  # noqa: E402

SUPPORTED = ("frame_decode", "payload_decode")


def hex_bytes(token: str) -> bytes:
    return b"" if token == "-" else bytes.fromhex(token)


def fmt_hex(data: bytes) -> str:
    return data.hex().upper() if data else "-"


def fmt_text(text: str) -> str:
    return "".join(
        chr(b) if 0x21 <= b <= 0x7E and chr(b) not in "%,=" else f"%{b:02X}" for b in text.encode("latin-1")
    )


def fmt_num(value: float) -> str:
    """Python's shortest round-trip form; `nan`, `inf`, `-inf` as the protocol spells them."""
    return "nan" if math.isnan(value) else repr(float(value))


def fmt_value(value: int | float | str | bytes) -> str:
    if isinstance(value, bytes):
        return fmt_hex(value)
    if isinstance(value, str):
        return fmt_text(value)
    if isinstance(value, float):
        return fmt_num(value)
    return str(value)


def fmt_refusal(refusal: ks.Refusal) -> str:
    offset = "-" if refusal.offset is None else str(refusal.offset)
    return f"error {refusal.kind} {offset} {refusal.field or '-'}"


def frame_decode(args: list[str]) -> str:
    frame = ks.decode_frame(hex_bytes(args[0]))
    return f"ok message_type={int(frame.message_type)} reserved={frame.reserved} payload={fmt_hex(frame.payload)}"


def payload_decode(args: list[str]) -> str:
    model = ks.spec()
    name, data = args[0], hex_bytes(args[1])
    payloads = {p.name: p for p in model.payloads}
    variants = {v.name: v for v in model.variants}
    if name not in payloads:
        return "error malformed - type"
    if len(args) > 2 and args[2] not in variants:
        return "error malformed - variant"
    payload = payloads[name]
    obj = ks.decode_payload(name, data)
    variant = variants[args[2]] if len(args) > 2 else None
    fields = [f"f.{k}={fmt_value(v)}" for k, v in ks.kaitai_raw(payload, obj).items()]
    values = [f"v.{k}={fmt_num(v)}" for k, v in ks.kaitai_values(payload, obj, variant).items()]
    return " ".join(["ok", *fields, *values])


def answer(line: str) -> str:
    kind, *args = line.split(" ")
    try:
        if kind == "frame_decode":
            return frame_decode(args)
        if kind == "payload_decode":
            return payload_decode(args)
    except ks.KaitaiRefusedError as exc:
        return fmt_refusal(exc.refusal)
    return "unsupported"


def main() -> int:
    ks.kaitai_module()  # fail at start, with the reason, if the build is missing or stale
    for raw in sys.stdin:
        request = raw.strip()
        if not request:
            continue
        try:
            reply = answer(request)
        except Exception:  # a bug here must not end the run: report it and answer
            traceback.print_exc(file=sys.stderr)
            reply = "error internal - -"
        sys.stdout.write(reply + "\n")
        sys.stdout.flush()
    return 0


if __name__ == "__main__":
    sys.exit(main())
