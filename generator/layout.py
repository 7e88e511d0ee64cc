"""Step 4 of the pipeline: where every field sits.

Offsets follow from declaration order and are computed here and nowhere else. The
result is the same model with `offset` filled in on every field and the frame's payload
offset set. A declared `size` that is not the sum of the fields, an explicit `offset`
that does not match (a gap or an overlap in the ICD table), or a payload the frame
cannot carry is an error naming file, line and path.
"""

from __future__ import annotations

import dataclasses

from .diff import wire_fingerprint
from .load import LoadedSpec
from .model import Field, Payload, Spec


def _place(fields: tuple[Field, ...], start: int, spec: LoadedSpec) -> tuple[tuple[Field, ...], int]:
    placed: list[Field] = []
    offset = start
    for f in fields:
        if f.declared_offset is not None and f.declared_offset != offset:
            what = (
                "overlaps the field before it"
                if f.declared_offset < offset
                else "leaves a gap after the field before it"
            )
            raise spec.error(
                (*f.path, "offset"),
                f"field {f.name!r} declares offset {f.declared_offset} but follows at {offset}: it {what}",
            )
        placed.append(dataclasses.replace(f, offset=offset))
        offset += f.size
    return tuple(placed), offset


def _payload(p: Payload, spec: LoadedSpec) -> Payload:
    fields, end = _place(p.fields, 0, spec)
    if end != p.size:
        raise spec.error(
            (*p.path, "size"),
            f"payload {p.name!r} declares size {p.size} but its fields add up to {end}",
        )
    return dataclasses.replace(p, fields=fields)


def layout(model: Spec, loaded: LoadedSpec) -> Spec:
    """Return `model` with every offset computed and checked."""
    frame = model.frame
    frame_fields, payload_offset = _place(frame.fields, frame.header_size, loaded)
    frame = dataclasses.replace(frame, fields=frame_fields, payload_offset=payload_offset)
    if frame.min_payload < 0:
        raise loaded.error(
            ("frame", "message_length", "min"),
            f"a message length of {frame.min_length} cannot hold the {frame.length_bias} bytes every frame carries",
        )
    payloads = tuple(_payload(p, loaded) for p in model.payloads)
    for p in payloads:
        if not frame.min_payload <= p.size <= frame.max_payload:
            raise loaded.error(
                (*p.path, "size"),
                f"payload {p.name!r} of {p.size} bytes is outside what a frame carries "
                f"({frame.min_payload} to {frame.max_payload} bytes by frame.message_length)",
            )
    if frame.min_payload > 1:
        raise loaded.error(("frame", "message_length", "min"), "a one-byte command must fit the minimum message length")
    laid_out = dataclasses.replace(model, frame=frame, payloads=payloads)
    return dataclasses.replace(laid_out, wire_fingerprint=wire_fingerprint(laid_out))
