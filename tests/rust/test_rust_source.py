"""The generated Rust crate reads as code: every accessor is written out where grep finds it (no
macro writes an API), and the templates' own intra-doc links stay links (only spec prose is
escaped). `make check` keeps generated/ equal to what the generator writes, so the committed
files are what is read here."""

from __future__ import annotations

import re
from pathlib import Path

from generator import DEFAULT_SPEC, ROOT, build_spec
from generator.targets.rust import filters

CRATE = ROOT / "generated" / "rust" / "src"
SPEC = build_spec(DEFAULT_SPEC)


def _sources() -> dict[Path, str]:
    return {path: path.read_text(encoding="utf-8") for path in sorted(CRATE.rglob("*.rs"))}


def test_no_macro_writes_code() -> None:
    found = [path.relative_to(ROOT).as_posix() for path, text in _sources().items() if "macro_rules!" in text]
    assert found == []


def test_every_accessor_is_written_out() -> None:
    """`grep 'fn heading_deg'` finds the view's and the value's getter, and likewise every field's
    getter, setter and engineering accessors of every table."""
    for payload in SPEC.payloads:
        text = (CRATE / "payload" / f"{payload.name}.rs").read_text(encoding="utf-8")
        view = filters.type_name(payload.name)
        assert f"pub struct {view}<T: AsRef<[u8]>>" in text
        assert f"pub struct {view}Repr {{" in text
        for field in payload.fields:
            name = filters.ident(field.name)
            assert re.search(rf"pub fn {name}\(&self\)", text), (payload.name, name)
            assert f"pub fn set_{name}(&mut self, value: " in text, (payload.name, name)
            if field.scale is not None:
                unit = filters.accessor(field)
                assert len(re.findall(rf"pub fn {unit}\(&self", text)) == 2, (payload.name, unit)
                assert f"pub fn set_{unit}(&mut self, " in text, (payload.name, unit)


def test_intra_doc_links_are_not_escaped() -> None:
    """A link the template writes (`[`Type::method`]`) is never escaped into literal text."""
    escaped = [
        f"{path.relative_to(ROOT).as_posix()}:{number}"
        for path, text in _sources().items()
        for number, line in enumerate(text.splitlines(), 1)
        if "\\[`" in line
    ]
    assert escaped == []
    first = SPEC.payloads[0]
    text = (CRATE / "payload" / f"{first.name}.rs").read_text(encoding="utf-8")
    assert f"[`{filters.type_name(first.name)}::new_checked`]" in text


def test_only_spec_prose_is_escaped() -> None:
    assert filters.escape_doc("a [b] <c>") == "a \\[b\\] &lt;c&gt;"
    assert filters.doc("See [`Frame::parse`].", 4) == "    /// See [`Frame::parse`]."
