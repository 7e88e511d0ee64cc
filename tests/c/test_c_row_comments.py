"""The C field table's rows say in their comments what their bare numbers stand for, and say it right:
the name's pool offset, the bounds row and its range, the scale row and its ratio (generated/c/ilahrs.c)."""

from __future__ import annotations

import re

from generator import ROOT, build_spec
from generator.targets.c import filters, tables

ROW = re.compile(r"^\s*(NUMBER|ARRAY)\(([^)]*)\),\s*/\* (\w+): name@(\d+)(.*) \*/$")


def test_every_row_comment_spells_its_numbers() -> None:
    spec = build_spec()
    t = tables.build_tables(spec)
    source = (ROOT / "generated" / "c" / "ilahrs.c").read_text(encoding="utf-8")
    body = source[source.index("ilahrs_fields[") : source.index("};", source.index("ilahrs_fields["))]
    rows = [ROW.match(line) for line in body.splitlines() if line.lstrip().startswith(("NUMBER(", "ARRAY("))]
    assert len(rows) == len(t.fields)
    for match, r in zip(rows, t.fields, strict=True):
        assert match is not None, r.field.name
        macro, args, name, offset, rest = match.groups()
        numbers = [a.strip() for a in args.split(",")]
        assert (name, int(offset), int(numbers[0])) == (r.field.name, r.name, r.name)
        assert t.pools["field"][name] == int(offset)
        if macro == "ARRAY":
            assert rest == ""
            continue
        bounds, scale = int(numbers[6]), int(numbers[7])
        assert (f"bounds[{bounds}]=" in rest) == (bounds != 0)
        assert (f"scale[{scale}]=" in rest) == (scale != 0)
        if r.field.range is not None and not r.field.is_float:
            low, high = r.field.range
            assert f"bounds[{bounds}]={int(low)}..{int(high)}" in rest
        if r.field.scale is not None and not r.field.scale.variant_dependent:
            assert f"scale[{scale}]={r.field.scale.multiplier}/{r.field.scale.divisor or 1}" in rest


def test_row_comment_of_heading_and_of_a_variant_scale() -> None:
    spec = build_spec()
    t = tables.build_tables(spec)
    row = {(r.payload.name, r.field.name): r for r in t.fields}
    heading = filters.field_row_comment(row["full_output", "heading"], t, spec)
    assert heading == f"heading: name@{row['full_output', 'heading'].name}, bounds[1]=0..35999, scale[1]=1/100 deg"
    gyro = filters.field_row_comment(row["orientation_sensors", "gyro_x"], t, spec)
    assert gyro.endswith("=1/KG deg/s")
    bias = filters.field_row_comment(row["initial_alignment", "gyro_bias_x"], t, spec)
    assert "bounds[1]=finite" in bias
