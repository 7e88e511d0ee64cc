"""The generator: invalid specs are rejected with file, line and path; output is reproducible."""

from __future__ import annotations

import copy
import re
import subprocess
import sys
from pathlib import Path

import pytest

from generator import ROOT, build_spec, naming
from generator.load import SpecError
from generator.render import render, target_names
from generator.targets.python import filters as py_filters

INVALID = sorted((ROOT / "spec" / "invalid").glob("*.yaml"))


def test_the_spec_is_valid() -> None:
    spec = build_spec()
    assert len(spec.commands) == 26
    assert len(spec.payloads) == 14
    assert spec.frame.max_frame_size == 60
    assert spec.max_message_size == 82


def test_there_are_invalid_specs() -> None:
    assert len(INVALID) >= 15


@pytest.mark.parametrize("path", INVALID, ids=[p.stem for p in INVALID])
def test_invalid_spec_is_rejected_with_location(path: Path) -> None:
    # (read leniently: one of them is not UTF-8, which is its point)
    text = path.read_bytes().decode("utf-8", errors="replace")
    first = text.splitlines()[0]
    assert first.startswith("# expect: "), f"{path.name} must start with '# expect: <message>'"
    expected = first.removeprefix("# expect: ")
    with pytest.raises(SpecError) as info:
        build_spec(path)
    message = str(info.value)
    assert expected in message
    match = re.match(r"^spec/invalid/[a-z_]+\.yaml:(\d+): ", message)
    assert match, f"no file:line in {message!r}"
    line = int(match.group(1))
    lines = text.splitlines()
    assert 1 <= line <= len(lines)
    # The line named is where the offending value (or its enclosing item) is written.
    last = info.value.path[-1] if info.value.path else None
    if isinstance(last, str) and last not in ("name",):
        assert last in lines[line - 1] or last in " ".join(lines[line - 2 : line + 1]), (line, lines[line - 1])


def test_a_missing_spec_file_is_named_not_a_traceback(tmp_path: Path) -> None:
    missing = tmp_path / "nowhere.yaml"
    with pytest.raises(SpecError, match=r"nowhere\.yaml: \(top\): cannot read the spec file: No such file"):
        build_spec(missing)
    result = subprocess.run(
        [sys.executable, "-m", "generator", "--spec", str(missing), "--validate-only"],
        cwd=ROOT,
        capture_output=True,
        text=True,
        check=False,
    )
    assert result.returncode == 2
    assert result.stderr.count("\n") == 1 and "Traceback" not in result.stderr
    assert "nowhere.yaml: (top): cannot read the spec file" in result.stderr


def test_output_is_reproducible_and_names_the_spec() -> None:
    spec = build_spec()
    first = render(spec)
    second = render(build_spec())
    assert first == second
    for path, text in first.items():
        assert str(ROOT) not in text, f"{path} contains an absolute path"
        if path.endswith((".py", ".h", ".c", ".rs", ".ksy", ".toml", ".md", ".txt")):
            assert spec.sha256 in text, f"{path} does not carry the spec hash"


def test_every_target_renders() -> None:
    spec = build_spec()
    for target in target_names():
        assert render(spec, [target]), target


def test_naming() -> None:
    assert naming.pascal("orientation_sensors") == "OrientationSensors"
    assert naming.upper("bad_checksum") == "BAD_CHECKSUM"
    assert naming.hex_byte(0xFE) == "0xFE"
    assert naming.wrap("a b c", 3) == ["a b", "c"]


def test_python_filters() -> None:
    spec = build_spec()
    payload = spec.payload("orientation_sensors")
    assert py_filters.struct_format(payload.fields) == "<Hhhhhhhhhhhh4sHHh"
    assert py_filters.accessor(payload.field("gyro_x")) == "gyro_x_dps"
    assert py_filters.scale_expr(payload.field("gyro_x"), "r") == "r / variant.kg"
    assert py_filters.scale_expr(payload.field("mag_x"), "r") == "float(r * 10)"
    assert py_filters.all_sorted(["b", "A_B", "Cls", "a2", "a10"]) == ["A_B", "Cls", "a2", "a10", "b"]
    assert py_filters.tuple_literal(["x"]) == "('x',)"


def test_c_longest_sentence() -> None:
    """The C target's longest in-range $PAHR sentence; a field too wide for the maximum is refused."""
    from dataclasses import replace

    from generator.targets.c import target as c_target

    spec = build_spec()
    assert spec.nmea is not None
    assert c_target.longest_sentence(spec.nmea) == len("$PAHR,-180.00,-90.00,359.99,-99.9,9.99,FFFF*hh\r\n")
    wide = replace(spec.nmea, fields=(replace(spec.nmea.fields[0], width=80), *spec.nmea.fields[1:]))
    with pytest.raises(ValueError, match="above the maximum"):
        c_target.outputs(replace(spec, nmea=wide))


def test_c_string_pools_share_tails() -> None:
    """C string pools store a name ending another name as its tail; part numbers and char defaults
    stay in pools of their own."""
    from dataclasses import replace

    from generator.targets.c import tables

    spec = build_spec()
    t = tables.build_tables(spec)
    for pool in t.pools.values():
        if not pool.strings:
            assert pool.size == 0
            continue
        text = "\0".join(pool.strings) + "\0"
        assert len(text) == pool.size
        for name, offset in pool.offsets.items():
            assert text[offset:].split("\0", 1)[0] == name
    assert t.pools["field"].offsets["gyro_x"] == t.pools["field"].offsets["ugyro_x"] + 1
    # Strings that stay without names: part numbers and char defaults, in pools of their own.
    assert list(t.pools["part"].offsets) == [v.part_number for v in spec.variants]
    assert all(v.part_number not in t.pools["name"].offsets for v in spec.variants)
    assert not t.pools["text"].strings and all(r.text < 0 for r in t.defaults)
    payload = next(p for p in spec.payloads if any(f.kind == "char" for f in p.fields))
    char = next(f for f in payload.fields if f.kind == "char")
    texted = replace(payload, fields=tuple(replace(f, default="X1") if f is char else f for f in payload.fields))
    t2 = tables.build_tables(replace(spec, payloads=tuple(texted if p is payload else p for p in spec.payloads)))
    assert t2.pools["text"].strings == ["X1"] and "X1" not in t2.pools["field"].offsets
    assert [r.text for r in t2.defaults if r.text >= 0] == [0]


def test_c_name_sections() -> None:
    """One pool for the names of the accessors: each section lists its kind in enum order, the event
    section continues the command section, and a USW bit without a flag has the empty name."""
    import itertools

    from generator.targets.c import tables

    spec = build_spec()
    t = tables.build_tables(spec)
    sections = {s.kind: s for s in t.name_sections}
    assert [s.first for s in t.name_sections] == [0, *itertools.accumulate(len(s.names) for s in t.name_sections)][:-1]
    assert sections["command"].names == tuple(c.name for c in spec.commands)
    assert sections["event"].first == len(spec.commands)
    assert sections["answer"].names[1] == "ahrs_parameters_read"
    assert spec.status_word is not None
    flags = {f.bit: f.name for f in spec.status_word.flags}
    assert sections["flag"].names == tuple(flags.get(bit, "") for bit in range(len(sections["flag"].names)))
    distinct = {n for s in t.name_sections for n in s.names}
    assert "" in sections["flag"].names and t.pools["name"].size < sum(len(n) + 1 for n in distinct)


def test_c_tables_fit_their_packing() -> None:
    """The C field table packed into the widths chosen, and rows of small tables in the smallest
    types that hold them."""
    from generator.targets.c import tables
    from generator.targets.c import target as c_target

    t = tables.build_tables(build_spec())
    fp = c_target.field_packing(t)
    width = {"uint8_t": 8, "uint16_t": 16, "uint32_t": 32}
    assert t.pools["field"].size <= 1 << (width[fp.name_type] - fp.type_bits)
    assert max(r.bounds for r in t.fields) < 1 << fp.bounds_bits
    assert max(r.scale for r in t.fields) < 1 << (width[fp.info] - fp.bounds_bits)
    assert max(r.field.size for r in t.fields if not r.field.is_numeric) < 1 << width[fp.info]
    assert max(r.field.offset for r in t.fields) < 1 << fp.offset_bits
    assert max(r.member - r.field.offset for r in t.fields) < 1 << (width[fp.place] - fp.offset_bits)
    assert t.kinds[-2:] == ("char", "reserved")  # the array kinds, whose info is their size
    # This spec fits four bytes a row; a column wider than 32 bits is refused.
    assert (fp.name_type, fp.place, fp.info) == ("uint16_t", "uint8_t", "uint8_t")
    with pytest.raises(ValueError, match="no 32-bit C integer type"):
        c_target.packed_type(33)
    huge_pool = copy.copy(t.pools["field"])
    huge_pool.size = 1 << 30  # names at offsets that leave no room for the type in 32 bits
    huge = copy.copy(t)
    huge.pools = {**t.pools, "field": huge_pool}
    with pytest.raises(ValueError, match="no 32-bit C integer type"):
        c_target.field_packing(huge)

    # Rows of small tables: each column in the smallest type that holds it, widest first.
    assert c_target.row_members({"a": [1, 2], "b": [0, 70000], "c": "float", "d": [-1, 300]}) == [
        ("uint32_t", "b"), ("float", "c"), ("int16_t", "d"), ("uint8_t", "a")]
    with pytest.raises(ValueError, match="no 32-bit C integer type"):
        c_target.row_members({"a": [0, 1 << 40]})
    assert [name for _, name in c_target.default_members(t)] == ["bits", "field", "text"]


def test_c_state_table_is_sparse_and_fits_its_packing() -> None:
    """The C state table: each state's default cell plus the cells that differ from it give back
    every cell; entries and outcomes fit the widths chosen, and a machine too big is refused."""
    from generator.targets.c import machine

    m = machine.build_machine(build_spec())
    assert m is not None
    p = m.packing
    rebuilt = [[m.defaults[s]] * len(m.events) for s in range(len(m.states))]
    for s, e, cell in m.exceptions:
        assert cell != m.defaults[s]
        rebuilt[s][e] = cell
        assert ((s * len(m.events) + e) << p.cell_bits | cell) < 1 << int(p.exception_type[4:-2])
    assert rebuilt == m.cells
    assert len(m.exceptions) < sum(1 for row in m.cells for cell in row if cell)
    assert max(max(row) for row in m.cells) < 1 << p.cell_bits
    assert all((o.to << p.sequence_bits | o.sequence) < 1 << int(p.outcome_type[4:-2]) for o in m.outcomes)
    assert (p.exception_type, p.outcome_type) == ("uint16_t", "uint8_t")
    with pytest.raises(ValueError, match="more than the C table's 32"):
        machine.machine_packing(states=1 << 14, events=1 << 12, outcomes=1000, sequences=4)


def test_c_double_keys_order_like_doubles() -> None:
    """The keys ilahrs.c compares exact float bounds by: strictly increasing with the double, equal
    for -0.0 and 0.0, and each bound's key decoding back to the bound itself."""
    import itertools
    import math
    import struct

    from generator.targets.c import filters, tables

    def from_key(key: int) -> float:
        bits = key if key >= 0 else (-key) | (1 << 63)
        value: float = struct.unpack("<d", struct.pack("<Q", bits))[0]
        return value

    samples = [-math.inf, -1e300, -360.0, -1.0, -5e-324, -0.0, 0.0, 5e-324, 0.5, 1.0, 359.99, 360.0, 1e300]
    finite = [v for v in samples if math.isfinite(v)]
    keys = [filters.double_key(v) for v in finite]
    assert keys == sorted(keys) and filters.double_key(-0.0) == filters.double_key(0.0) == 0
    for a, b in itertools.pairwise(finite):
        assert (filters.double_key(a) < filters.double_key(b)) == (a < b)
        assert filters.double_key(math.nextafter(a, math.inf)) == filters.double_key(a) + 1
    for bound in tables.build_tables(build_spec()).float_bounds:
        for value in (bound.low, bound.high):
            assert from_key(filters.double_key(value)) == value


def test_c_date_decoder_integers_fit() -> None:
    """ilahrs_date_decode() measures distances in int32: the generator refuses a date encoding
    whose values and dates would not fit (here years near 1, where a float32 has 23 fraction bits)."""
    from dataclasses import replace

    from generator.targets.c import filters as c_filters
    from generator.targets.c import target as c_target

    spec = build_spec()
    assert spec.date is not None
    tables = c_target.date_tables(spec)
    assert tables is not None
    # The decoder accepts the floats from year_min to just below year_max + 2.
    assert tables.min_key == c_filters.float_key(float(spec.date.year_min))
    assert tables.max_key == c_filters.float_key(float(spec.date.year_max + 2)) - 1
    early = replace(spec, date=replace(spec.date, year_min=2, year_max=3))
    with pytest.raises(ValueError, match="32-bit integers"):
        c_target.date_tables(early)


def test_c_member_bits() -> None:
    """Builder defaults are stored as the bits of their struct member: a float's float32 bits, an
    integer's two's complement in the member's size; an integer the member cannot hold is refused."""
    from dataclasses import replace

    from generator.model import PRIMITIVES
    from generator.targets.c import filters

    gyro = build_spec().payload("orientation_sensors").field("gyro_x")
    signed16 = replace(gyro, type=PRIMITIVES["s16"], size=2)
    unsigned8 = replace(gyro, type=PRIMITIVES["u8"], size=1)
    float32 = replace(gyro, type=PRIMITIVES["f32"], size=4)
    assert filters.c_member_bits(100, unsigned8) == "0x00000064u"
    assert filters.c_member_bits(-2, signed16) == "0x0000FFFEu"
    assert filters.c_member_bits(1900.002685546875, float32) == "0x44ED8016u"
    assert filters.c_member_bits(0.1, float32) == "0x3DCCCCCDu"  # the float32 nearest, as C's (float)
    for value, f in ((256, unsigned8), (-1, unsigned8), (32768, signed16), (1.5, signed16)):
        with pytest.raises(ValueError):
            filters.c_member_bits(value, f)
