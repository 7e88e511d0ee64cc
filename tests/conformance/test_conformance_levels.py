"""Levels, declarations, expected failures and the suites' version (conformance/README.md).

In-process runs of `ilahrs conformance` against a scripted runner on a small suite, and counts on
the shipped suites done twice: by the harness (a declaration's plan), and independently from the
vectors' own bytes.
"""

from __future__ import annotations

import argparse
import io
import json
import shlex
import subprocess
import sys
from pathlib import Path
from typing import Any
from xml.etree import ElementTree

import jsonschema
import pytest
from script_support import load_script

from ilahrs.commands import COMMANDS
from ilahrs.conformance import VECTORS_DIR, load_suites, main
from ilahrs.conformance.declaration import Declaration, DeclarationError, check, everything, vocabulary
from ilahrs.conformance.live import _flows
from ilahrs.conformance.runner import Plan

ROOT = Path(__file__).resolve().parents[2]
CONFORMANCE = ROOT / "conformance"
SCHEMA = json.loads((CONFORMANCE / "declaration.schema.json").read_text(encoding="utf-8"))
SUITES = load_suites(CONFORMANCE / "vectors")
EXAMPLE = CONFORMANCE / "examples" / "javascript"

SCRIPTED_RUNNER = """\
import json, sys
table = json.load(open(sys.argv[1]))
for line in sys.stdin:
    sys.stdout.write(table.get(line.rstrip("\\n"), "unsupported") + "\\n")
    sys.stdout.flush()
"""

VECTORS: list[dict[str, Any]] = [
    {"id": "c/empty", "kind": "checksum", "input": "", "expect": 0, "level": "required"},
    {"id": "c/one", "kind": "checksum", "input": "01", "expect": 1, "level": "recommended"},
    {"id": "c/two", "kind": "checksum", "input": "02", "expect": 2, "level": "erratum", "erratum": "E12"},
    {"id": "e/bit", "kind": "command_encode", "input": {"command": "GetBIT"}, "expect": "AA 55 00 00 07 00 1A 21 00",
     "level": "required", "requires": {"commands": ["GetBIT"]}},
]
TABLE = {"checksum -": "ok 0", "checksum 01": "ok 7", "checksum 02": "ok 2", "command_encode GetBIT": "ok AA55"}


@pytest.fixture
def setup(tmp_path: Path) -> tuple[Path, str]:
    (tmp_path / "v").mkdir()
    suite = {"suite": "t", "version": "2.1.0", "icd_revision": "1.7", "source": "test", "vectors": VECTORS}
    (tmp_path / "v" / "t.json").write_text(json.dumps(suite))
    (tmp_path / "runner.py").write_text(SCRIPTED_RUNNER)
    (tmp_path / "table.json").write_text(json.dumps(TABLE))
    command = shlex.join([sys.executable, str(tmp_path / "runner.py"), str(tmp_path / "table.json")])
    return tmp_path / "v", command


def run(*args: str | Path) -> tuple[int, str]:
    out = io.StringIO()
    code = main([str(a) for a in args], out=out)
    return code, out.getvalue()


def _declaration(**changes: Any) -> dict[str, Any]:
    return {**everything(SUITES), **changes}


# --- levels ---------------------------------------------------------------------------------------


def test_levels_follow_the_rule_of_the_readme() -> None:
    vectors = {v.key: v for s in SUITES for v in s.vectors}
    assert {v.level for v in vectors.values()} == {"required", "recommended", "erratum"}
    assert all((v.level == "erratum") == (v.erratum is not None) for v in vectors.values())
    ignored = vectors[f"sessions/step/idle/0x{COMMANDS['GetDataReq'].code:02X}"]
    assert (ignored.level, ignored.erratum) == ("erratum", "E33")  # no transition: ignored (E33)
    assert vectors[f"sessions/step/idle/0x{COMMANDS['AHRScont1'].code:02X}"].level == "required"
    assert all(v.level == "recommended" for v in vectors.values()
               if v.kind == "stream" and v.expect["discarded"] and v.erratum is None)
    assert all(v.level == "required" for v in vectors.values() if v.suite == "checksum")  # E28: the only reading


def test_level_option_skips_the_vectors_above_it(setup: tuple[Path, str], tmp_path: Path) -> None:
    vectors, command = setup
    code, text = run("--vectors", vectors, "--command", command, "--level", "required", "--json", tmp_path / "r.json")
    assert code == 1 and "1 passed, 1 FAILED, 2 skipped" in text  # e/bit is answered wrong
    cases = {c["id"]: c for c in json.loads((tmp_path / "r.json").read_text())["cases"]}
    assert cases["c/one"]["outcome"] == cases["c/two"]["outcome"] == "skipped"
    assert (cases["c/two"]["level"], cases["c/two"]["erratum"]) == ("erratum", "E12")
    code, text = run("--vectors", vectors, "--command", command, "--level", "recommended")
    assert code == 1 and "1 passed, 2 FAILED, 1 skipped" in text and "level:    recommended" in text


# --- declarations ---------------------------------------------------------------------------------


def _independent_count(name: str) -> int:
    """The vectors that send, encode or decode the command: read from their bytes, not "requires"."""
    code = COMMANDS[name].code
    count = 0
    for v in (v for s in SUITES for v in s.vectors):
        refused = isinstance(v.expect, dict) and "error" in v.expect
        data = bytes.fromhex(v.input.replace(" ", "")) if v.kind in ("command_decode", "ack") else b""
        frame = len(data) == 9 and data[:3] == b"\xaa\x55\x00" and data[6] == code
        count += (
            (v.kind == "command_encode" and v.input["command"] == name)
            or (v.kind in ("command_decode", "ack") and frame and not refused)
            or (v.kind == "session" and {"command": f"0x{code:02X}"} in v.input["events"])
        )
    return count


def test_a_declaration_without_a_command_excludes_exactly_its_vectors_and_flows(tmp_path: Path) -> None:
    declaration = _declaration(commands=[c for c in COMMANDS if c != "GetBIT"])
    plan = Plan(declaration=Declaration(declaration))
    excluded = [v for s in SUITES for v in s.vectors if plan.excluded(v) is not None]
    assert len(excluded) == _independent_count("GetBIT") > 0
    assert {plan.excluded(v) for v in excluded} == {("not_applicable", "not declared: commands GetBIT")}
    # the live flows: the same exclusion, shown as not applicable
    path = tmp_path / "d.json"
    path.write_text(json.dumps(declaration))
    args = argparse.Namespace(vectors=CONFORMANCE / "vectors", pattern=None, declaration=path, level="all")
    run_flows, out = _flows(args)
    code = f"0x{COMMANDS['GetBIT'].code:02X}"
    assert sorted(v.id for v, *_ in out) == sorted(
        v.id for s in SUITES for v in s.vectors if v.id.startswith("flow/") and {"command": code} in v.input["events"])
    assert out and {o for _, o, _ in out} == {"not_applicable"} and run_flows


def test_declared_out_vectors_are_not_applicable_never_failures(setup: tuple[Path, str], tmp_path: Path) -> None:
    vectors, command = setup  # the runner gets e/bit wrong: not declared, it does not count
    path = tmp_path / "d.json"
    path.write_text(json.dumps(_declaration(commands=["Stop"], errata={"E12": "other"})))
    code, text = run("--vectors", vectors, "--command", command, "--declaration", path, "--json", tmp_path / "r.json")
    assert code == 1 and "1 passed, 1 FAILED, 2 n/a" in text  # c/one fails; c/two (E12) and e/bit n/a
    report = json.loads((tmp_path / "r.json").read_text())
    assert report["implementations"][0]["declaration_file"] == str(path)
    assert report["implementations"][0]["declaration"]["commands"] == ["Stop"]
    assert report["results"][0]["not_applicable"] == 2


def test_declaration_checks_agree_with_the_schema(tmp_path: Path) -> None:
    jsonschema.Draft202012Validator.check_schema(SCHEMA)
    props = SCHEMA["properties"]
    assert {k: tuple(props[k]["items"]["enum"]) for k in vocabulary()} == vocabulary()
    good = [everything(SUITES), json.loads((EXAMPLE / "declaration.json").read_text())]
    bad = [[], _declaration(commands=["Nope"]), _declaration(nmea="yes"), _declaration(errata={"E12": "maybe"}),
           _declaration(extra=1), {k: v for k, v in everything(SUITES).items() if k != "payloads"},
           _declaration(variants=["g300_a2_tmga", "g300_a2_tmga"])]
    for doc in good:
        jsonschema.validate(doc, SCHEMA)
        check(doc, "good")
    for doc in bad:
        with pytest.raises(jsonschema.ValidationError):
            jsonschema.validate(doc, SCHEMA)
        with pytest.raises(DeclarationError):
            check(doc, "bad")


def test_init_declaration_writes_everything_and_keeps_a_file(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    path = tmp_path / "d.json"
    assert run("--init-declaration", path)[0] == 0
    assert json.loads(path.read_text()) == everything(load_suites(VECTORS_DIR))
    path.write_text("mine")
    capsys.readouterr()
    assert run("--init-declaration", path)[0] == 2
    err = capsys.readouterr().err
    assert path.read_text() == "mine" and err.count("\n") == 1 and "--force" in err
    assert run("--init-declaration", path, "--force")[0] == 0 and path.read_text() != "mine"


# --- expected failures ----------------------------------------------------------------------------


def test_expected_failures_unexpected_passes_and_update(
    setup: tuple[Path, str], tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    vectors, command = setup  # c/one and e/bit fail
    xfail = tmp_path / "x.json"
    xfail.write_text(json.dumps({"t/c/one": "wrong sum", "t/e/bit": "no encoder"}))
    code, text = run("--vectors", vectors, "--command", command, "--expected-failures", xfail)
    assert code == 0 and "2 passed, 2 xfail" in text
    assert "2 passed, 0 failed, 2 expected failures, 0 unexpected passes, 0 not applicable, 0 skipped" in text
    xfail.write_text(json.dumps({"t/c/two": "said to fail", "t/c/one": "wrong sum"}))
    code, text = run("--vectors", vectors, "--command", command, "--expected-failures", xfail, "--json",
                     tmp_path / "r.json", "--update-expected-failures")
    assert code == 1 and "1 XPASS" in text
    failures = json.loads((tmp_path / "r.json").read_text())["failures"]
    assert {f["id"]: f["reason"] for f in failures} == {
        "c/two": "unexpected pass: listed as an expected failure (said to fail)",
        "e/bit": "bytes differ"}
    # rewritten: the passing one gone, the reason kept, the new failure with its reason, sorted
    assert xfail.read_text() == json.dumps({"t/c/one": "wrong sum", "t/e/bit": "bytes differ"}, indent=1) + "\n"
    assert sorted(p.name for p in tmp_path.iterdir() if p.name.startswith(".x.json")) == []
    xfail.write_text(json.dumps({"t/c/gone": "old"}))
    capsys.readouterr()
    assert run("--vectors", vectors, "--command", command, "--expected-failures", xfail)[0] == 2
    err = capsys.readouterr().err
    assert err == f"ilahrs conformance: expected failures {xfail}: no vector t/c/gone in the suites\n"


# --- version --------------------------------------------------------------------------------------


def test_the_version_is_in_every_report(setup: tuple[Path, str], tmp_path: Path) -> None:
    vectors, command = setup
    code, text = run("--vectors", vectors, "--command", command, "--json", tmp_path / "r.json",
                     "--junit", tmp_path / "r.xml", "-k", "c/")
    assert code == 1  # c/one is answered wrong
    assert text.count("suites 2.1.0 (ICD rev 1.7)") == 2 and "1 skipped" in text
    assert json.loads((tmp_path / "r.json").read_text())["suite"] == {"version": "2.1.0", "icd_revision": "1.7"}
    props = ElementTree.parse(tmp_path / "r.xml").getroot().find("testsuite/properties")
    assert props is not None
    assert {p.get("name"): p.get("value") for p in props} == {"suite_version": "2.1.0", "suite_icd_revision": "1.7"}
    assert {s.version for s in SUITES} == {sys.modules["suites"].VERSION}


MAKE_VECTORS = load_script("make_vectors_for_levels", CONFORMANCE / "tools" / "make_vectors.py")


def test_a_changed_expectation_needs_a_major_bump() -> None:
    old = {"suite": "s", "version": "1.2.0", "vectors": [{"id": "a", "kind": "checksum", "input": "", "expect": 0}]}
    changed = {**old, "vectors": [{"id": "a", "kind": "checksum", "input": "", "expect": 1}]}
    added = {**old, "vectors": [*old["vectors"], {"id": "b", "kind": "checksum", "input": "01", "expect": 1}]}
    problems = MAKE_VECTORS.version_problems
    assert problems(old, changed) and "major" in problems(old, changed)[0]
    assert problems(old, {**changed, "version": "1.3.0"}) and not problems(old, {**changed, "version": "2.0.0"})
    assert problems(old, {**old, "vectors": []})  # a vector removed
    assert "minor" in problems(old, added)[0] and not problems(old, {**added, "version": "1.3.0"})
    assert not problems(old, old)


def test_suite_versions_are_compared_with_the_last_release_tag(tmp_path: Path) -> None:
    git = ["git", "-c", "user.name=t", "-c", "user.email=t@t", "-C", str(tmp_path)]
    subprocess.run([*git, "init", "-q"], check=True)
    assert MAKE_VECTORS.last_release(tmp_path) is None  # no commit, no tag
    (tmp_path / "f").write_text("x")
    subprocess.run([*git, "add", "f"], check=True)
    subprocess.run([*git, "commit", "-q", "-m", "x"], check=True)
    assert MAKE_VECTORS.last_release(tmp_path) is None  # not released yet: versions not compared
    subprocess.run([*git, "tag", "v1.0.0"], check=True)
    assert MAKE_VECTORS.last_release(tmp_path) == "v1.0.0"


def test_a_registration_names_its_declaration_and_expected_failures(setup: tuple[Path, str], tmp_path: Path) -> None:
    vectors, command = setup
    bindings = tmp_path / "b"
    bindings.mkdir()
    (bindings / "fake.json").write_text(json.dumps({
        "name": "fake", "command": shlex.split(command), "kinds": ["checksum", "command_encode"], "build": "-",
        "declaration": "../fake.declaration.json", "expected_failures": "../fake.xfail.json"}))
    (tmp_path / "fake.declaration.json").write_text(json.dumps(_declaration(commands=[])))
    (tmp_path / "fake.xfail.json").write_text(json.dumps({"t/c/one": "wrong sum"}))
    code, text = run("--vectors", vectors, "--bindings-dir", bindings, "--json", tmp_path / "r.json")
    assert code == 0 and "2 passed, 1 xfail, 1 n/a" in text
    (implementation,) = json.loads((tmp_path / "r.json").read_text())["implementations"]
    assert implementation["expected_failures"] == {"t/c/one": "wrong sum"}
    assert implementation["expected_failures_file"] == str((tmp_path / "fake.xfail.json").resolve())
    assert implementation["declaration"]["commands"] == []
