"""Differential: the `construct` definition compiled from generated/kaitai/ilahrs.ksy as an
independent builder and parser, against the ilahrs binding.

For every payload table, raw values a builder accepts are built by construct and by the binding's
`build()`, which must give the same bytes; construct parses them back to the same values. Frames
are parsed by construct too (it does not check what the .ksy validates: contents, `valid`).
"""

from __future__ import annotations

import random

import kaitai_support as ks
import pytest

import ilahrs
from generator.targets.kaitai.filters import constant_scaled, engineering_id

SEED = 20140311
SPEC = ks.spec()
PAYLOADS = {p.name: p for p in SPEC.payloads}


@pytest.mark.parametrize("name", list(PAYLOADS))
def test_construct_builds_what_the_binding_builds(name: str) -> None:
    p = PAYLOADS[name]
    cls = ilahrs.PAYLOADS[name]
    con = ks.construct_type(name)
    rng = random.Random(f"{SEED}-construct-{name}")
    defaults = cls.from_raw({}).raw()
    for raw in [defaults, *(ks.valid_raw(p, rng) for _ in range(200))]:
        ours = cls.from_raw(raw).build()
        theirs = con.build(ks.construct_input(p, raw))
        assert theirs == ours, raw
        assert ks.same_raw(ks.construct_raw(p, con.parse(ours)), raw)
        assert ks.same_raw(cls.parse(theirs).raw(), raw)


@pytest.mark.parametrize("name", list(PAYLOADS))
def test_construct_parses_what_the_binding_parses(name: str) -> None:
    p = PAYLOADS[name]
    cls = ilahrs.PAYLOADS[name]
    con = ks.construct_type(name)
    rng = random.Random(f"{SEED}-construct-parse-{name}")
    for data in [bytes(p.size), b"\xff" * p.size, *(rng.randbytes(p.size) for _ in range(100))]:
        assert ks.same_raw(ks.construct_raw(p, con.parse(data)), cls.parse(data).raw()), data.hex()
        values = {f.name: float(con.parse(data)[engineering_id(f)]) for f in constant_scaled(p)}
        ours = cls.parse(data).values()
        assert values == {k: v for k, v in ours.items() if k in values}


def test_construct_parses_frames() -> None:
    rng = random.Random(SEED)
    frame_type = ks.construct_type()
    for table, payload in ks.random_frame_payloads(rng, 300):
        data = ilahrs.Frame(1, payload, rng.randrange(256)).build()
        parsed = frame_type.parse(data)
        assert parsed.payload == payload
        assert parsed.checksum == parsed.checksum_computed == ilahrs.checksum(data[2:-2])
        assert ks.same_raw(ks.construct_raw(table, ks.construct_type(table.name).parse(parsed.payload)),
                           ilahrs.PAYLOADS[table.name].parse(payload).raw())
