"""The levels come from the spec: each erratum of spec/ilahrs.yaml says whether an implementation may
take another side (`alternative`) or not (`correction`), and a vector is at the erratum level only
when its expected answer rests on an erratum with an alternative (conformance/README.md, Levels).

In-process: conformance/tools/suites/levels.py pointed at an edited copy of the spec, the generator's
validator on edited copies, the shipped suites and the live mode's flow plan.
"""

from __future__ import annotations

import argparse
import importlib
import json
import re
import sys
from collections.abc import Iterator
from pathlib import Path
from types import ModuleType
from typing import Any

import pytest
import yaml

from generator import build_spec
from generator.load import SpecError
from ilahrs.conformance import load_suites
from ilahrs.conformance.declaration import DeclarationError, check, everything
from ilahrs.conformance.live import _flows
from ilahrs.spec import ERRATA_ALTERNATIVES

ROOT = Path(__file__).resolve().parents[2]
SPEC = ROOT / "spec" / "ilahrs.yaml"
CONFORMANCE = ROOT / "conformance"
TOOLS = CONFORMANCE / "tools"
SUITES = load_suites(CONFORMANCE / "vectors")
VECTORS = {v.key: v for s in SUITES for v in s.vectors}
SPEC_DOC: dict[str, Any] = yaml.safe_load(SPEC.read_text(encoding="utf-8"))


def _tools() -> tuple[ModuleType, ModuleType]:
    if str(TOOLS) not in sys.path:
        sys.path.insert(0, str(TOOLS))
    return importlib.import_module("suites.levels"), importlib.import_module("make_vectors")


@pytest.fixture
def levels(tmp_path: Path) -> Iterator[tuple[ModuleType, Path]]:
    """levels.py reading a copy of the spec (edit it, then call `reread`), put back afterwards."""
    module, _ = _tools()
    copy = tmp_path / "ilahrs.yaml"
    copy.write_text(SPEC.read_text(encoding="utf-8"), encoding="utf-8")
    original = getattr(module, "SPEC_FILE")  # noqa: B009 (a module loaded by name: mypy knows no attributes)
    setattr(module, "SPEC_FILE", copy)  # noqa: B010
    reread(module)
    yield module, copy
    setattr(module, "SPEC_FILE", original)  # noqa: B010
    reread(module)


def reread(module: ModuleType) -> None:
    for cached in (module.spec, module.alternatives, module._errata):
        cached.cache_clear()


def _raw(key: str) -> dict[str, Any]:
    """A shipped vector as make_vectors wrote it, without its level."""
    suite, _, vid = key.partition("/")
    doc = json.loads((CONFORMANCE / "vectors" / f"{suite}.json").read_text(encoding="utf-8"))
    (found,) = [v for v in doc["vectors"] if v["id"] == vid]
    return {k: v for k, v in found.items() if k not in ("level", "erratum", "requires")}


def test_every_erratum_of_the_spec_says_whether_another_side_may_be_taken() -> None:
    for e in SPEC_DOC["errata"]:
        assert ("alternative" in e) != (e.get("correction") is True), (
            f"{e['id']}: give it `alternative: <the other reading>` or `correction: true` (conformance/README.md)"
        )
    alternatives = {e["id"]: e["alternative"] for e in SPEC_DOC["errata"] if "alternative" in e}
    assert dict(ERRATA_ALTERNATIVES) == alternatives  # the generated table is the spec's
    errata_md = (ROOT / "generated" / "docs" / "errata.md").read_text(encoding="utf-8")
    for eid, text in alternatives.items():
        section = errata_md.split(f"\n## {eid}: ")[1].split("\n## ")[0]
        assert f"- **Another reading:** {text}" in section
    assert "- **Correction:**" in errata_md.split("\n## E1: ")[1].split("\n## ")[0]


def test_an_alternative_given_to_a_correction_changes_the_levels(levels: tuple[ModuleType, Path]) -> None:
    module, copy = levels
    stop = _raw("sessions/flow/0xFE/idle")  # Stop in idle: no answer (E14, a correction today)
    ack = _raw("acks/ack/AHRScont1")  # E12's rule for a command: one reading either way
    assert module.level(stop) == ("required", None)
    assert VECTORS["sessions/flow/0xFE/idle"].level == "required"
    text = copy.read_text(encoding="utf-8")
    at = text.index("  - id: E14\n")
    end = text.index("    correction: true\n", at)
    alternative = "    alternative: Stop is acknowledged like ExitClb.\n"
    copy.write_text(text[:end] + alternative + text[end + len("    correction: true\n") :], encoding="utf-8")
    reread(module)
    assert module.level(stop) == ("erratum", "E14")
    assert module.level(ack) == ("required", None)
    # and the other way: E12 made a correction, its parameter-block acks become required
    (block,) = [v for v in importlib.import_module("suites.acks").vectors() if v["id"] == "ack/LoadAHRSPar-block"]
    assert block["tests"] == "E12"  # set by the code that writes it, from cases/acks.json
    assert module.level(block) == ("erratum", "E12")
    text = copy.read_text(encoding="utf-8")
    copy.write_text(re.sub(r"(  - id: E12\n(?:    .*\n)*?)    alternative: .*\n", r"\1    correction: true\n", text))
    reread(module)
    assert module.level(block) == ("required", None)


def test_a_vector_that_cites_an_erratum_in_passing_is_required(levels: tuple[ModuleType, Path]) -> None:
    module, _ = levels
    for key in ("frames/frame_decode/data-ack", "streams/stream/sweep-ack-sentence-3", "acks/ack/AHRScont1",
                "frames/frame_decode/longest", "streams/stream/false-header-ffff"):
        assert re.search(r"\bE1[27]\b", VECTORS[key].note or ""), key  # E12 or E17 named in its note
        assert VECTORS[key].level in ("required", "recommended") and VECTORS[key].erratum is None, key
    passing = {"id": "c/x", "kind": "checksum", "input": "", "expect": 0, "note": "as E33 and E12 say"}
    assert module.level(passing) == ("required", None)
    assert module.level({**passing, "tests": "E12"}) == ("erratum", "E12")
    assert module.level({**passing, "note": "E28", "tests": "E28"}) == ("required", None)  # a correction
    with pytest.raises(AssertionError, match="its note must say so"):
        module.level({**passing, "tests": "E6"})


def test_the_live_flows_include_required_ones() -> None:
    flows = [v for v in VECTORS.values() if v.id.startswith("flow/")]
    assert {v.level for v in flows} == {"required", "erratum"}
    args = argparse.Namespace(vectors=CONFORMANCE / "vectors", pattern=None, declaration=None, level="required")
    run, excluded = _flows(args)
    assert run and all(v.level == "required" for v in run)
    assert {v.id for v in run} >= {"flow/load-parameters/block", "flow/0xFE/idle", "flow/0xFE/run_accumulating"}
    assert len(run) + len(excluded) == len(flows)


def test_only_errata_with_an_alternative_are_erratum_levels_and_choices(tmp_path: Path) -> None:
    assert {v.erratum for v in VECTORS.values() if v.erratum} <= set(ERRATA_ALTERNATIVES)
    doc = everything(SUITES)
    assert doc["errata"] and set(doc["errata"]) <= set(ERRATA_ALTERNATIVES)
    check({**doc, "errata": {"E33": "other"}}, "ok")
    with pytest.raises(DeclarationError, match="E13: no other side to take"):
        check({**doc, "errata": {"E13": "other"}}, "bad")
    schema = json.loads((CONFORMANCE / "declaration.schema.json").read_text(encoding="utf-8"))
    assert schema["properties"]["errata"]["propertyNames"]["enum"] == list(ERRATA_ALTERNATIVES)


@pytest.mark.parametrize(
    ("edit", "needle"),
    [
        ("    alternative: Another.\n    correction: true\n", "an erratum with an alternative is no correction"),
        ("    alternative: ' '\n", "an empty alternative"),
    ],
)
def test_the_validator_checks_the_field(tmp_path: Path, edit: str, needle: str) -> None:
    text = SPEC.read_text(encoding="utf-8")
    at = text.index("  - id: E1\n")
    end = text.index("    correction: true\n", at)
    path = tmp_path / "careless.yaml"
    path.write_text(text[:end] + edit + text[end + len("    correction: true\n") :], encoding="utf-8")
    with pytest.raises(SpecError, match=needle):
        build_spec(path)
