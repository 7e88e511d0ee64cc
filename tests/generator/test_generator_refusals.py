"""Specs that would generate broken code are refused with the spec's file:line, and every spec the
validator accepts generates code that builds in every target.

Each careless spec is a copy of spec/ilahrs.yaml with one edit, run through
`python -m generator --spec ... --out ...` as a spec author runs it: exit status 2, one line on
stderr naming the file and the line of the edit. The property test renames fields, enum values
and a payload table to identifiers the validator accepts (keywords of one language that another
target escapes, soft keywords, builtins, odd underscores, random ones) and builds every target:
Python (import, a round trip through every payload class, ruff's error rules), C (gcc -Werror and
the header under g++), Rust (cargo check), Lua (the dissector loaded by tshark, or luac -p) and
Kaitai (ksc, when tools/kaitai has it installed).
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

from generator import ROOT
from generator.load import MAX_DEPTH, MAX_DOC_CHARS, MAX_FILE_BYTES
from generator.validate.names import reserved_lists

SPEC = ROOT / "spec" / "ilahrs.yaml"
PY = sys.executable
FIRST_FIELD = "- {name: heading, icd_name: Heading, type: u16"  # payloads[0].fields[0], full_output


def generate(spec: Path, out: Path) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [PY, "-m", "generator", "--spec", str(spec), "--out", str(out)],
        check=False,
        cwd=ROOT,
        capture_output=True,
        text=True,
        timeout=600,
    )


def edited(tmp_path: Path, old: str, new: str) -> tuple[Path, int]:
    """A copy of the spec with the first `old` replaced by `new`, and the line of the edit."""
    text = SPEC.read_text(encoding="utf-8")
    at = text.index(old)
    path = tmp_path / "careless.yaml"
    path.write_text(text[:at] + new + text[at + len(old) :], encoding="utf-8")
    return path, text.count("\n", 0, at) + 1


def assert_refused(tmp_path: Path, spec: Path, line: int | None, *needles: str) -> str:
    result = generate(spec, tmp_path / "out")
    assert result.returncode == 2, result.stderr[-2000:]
    assert result.stdout == ""
    lines = result.stderr.splitlines()
    assert len(lines) == 1, result.stderr[-2000:]
    message = lines[0]
    where = f"error: {spec.name}:{line}: " if line is not None else f"error: {spec.name}: "
    assert message.startswith(where), message
    for needle in needles:
        assert needle in message, message
    assert not (tmp_path / "out").exists()
    return message


# --- careless names --------------------------------------------------------------------------

# (a field name, the language that refuses it, the list that says so)
CARELESS_FIELDS = [
    *[(word, "C and C++", "c") for word in ("int", "char", "float", "static", "default", "switch", "sizeof")],
    *[(word, "C and C++", "c") for word in ("new", "delete", "this", "template", "bool")],
    *[(word, "Python", "python") for word in ("def", "lambda", "for", "yield")],
    *[(word, "Python", "python") for word in ("raw", "parse", "build", "check", "values", "json", "from_raw")],
    ("replace", "Python", "python"),
    ("property", "Python", "python"),
    ("size", "Kaitai Struct", "kaitai"),
]


@pytest.mark.parametrize(("name", "language", "target"), CARELESS_FIELDS, ids=[n for n, _, _ in CARELESS_FIELDS])
def test_a_field_named_like_a_keyword_or_an_api_member_is_refused_at_its_line(
    tmp_path: Path, name: str, language: str, target: str
) -> None:
    spec, line = edited(tmp_path, FIRST_FIELD, FIRST_FIELD.replace("heading", name))
    assert_refused(
        tmp_path,
        spec,
        line,
        f"payloads[0].fields[0].name: {name!r} cannot be a field name",
        language,
        f"generator/targets/{target}/reserved.txt",
    )


def test_python_keywords_are_refused_with_the_spec_line_not_a_generated_one(tmp_path: Path) -> None:
    spec, line = edited(tmp_path, FIRST_FIELD, FIRST_FIELD.replace("heading", "class"))
    message = assert_refused(tmp_path, spec, line, "`class` is reserved in C and C++", "`class` is reserved in Python")
    assert "payloads.py" not in message and "ruff" not in message


def test_a_pahr_field_named_like_a_parameter_of_its_c_function_is_refused(tmp_path: Path) -> None:
    # ilahrs_pahr_from_values(double roll, ..., ilahrs_pahr_t *out, ilahrs_error_t *err)
    text = SPEC.read_text(encoding="utf-8")
    line = next(n for n, s in enumerate(text.splitlines(), 1) if s.startswith("    - {name: temperature,"))
    spec = tmp_path / "careless.yaml"
    spec.write_text(re.sub(r"\btemperature\b", "out", text), encoding="utf-8")
    assert_refused(tmp_path, spec, line, "nmea.fields[3].name: 'out' cannot be a field name", "generated C and C++ API")


def test_a_name_whose_pascal_case_form_is_reserved_is_refused(tmp_path: Path) -> None:
    # An enum value becomes a Rust variant (`Self` is not one); refused where it is defined, not
    # where a command refers to it earlier in the file.
    text = SPEC.read_text(encoding="utf-8")
    line = text.splitlines().index("      - {name: two_d, value: 1, doc: 2D calibration}") + 1
    spec = tmp_path / "careless.yaml"
    for name, needles in (
        ("self", ("'self' cannot be a name", "PascalCase form `Self` is reserved in Rust")),
        ("none", ("its PascalCase form `None` is reserved in Python",)),
    ):
        spec.write_text(re.sub(r"\btwo_d\b", name, text), encoding="utf-8")
        assert_refused(tmp_path, spec, line, f"enums.calibration_type.values[0].name: {name!r}", *needles)


def test_a_field_may_take_a_lua_keyword_an_enum_may_not(tmp_path: Path) -> None:
    spec, _ = edited(tmp_path, FIRST_FIELD, FIRST_FIELD.replace("heading", "until"))
    result = subprocess.run(
        [PY, "-m", "generator", "--spec", str(spec), "--validate-only"],
        check=False,
        cwd=ROOT,
        capture_output=True,
        text=True,
    )
    assert result.returncode == 0, result.stderr


def test_an_enum_named_like_a_keyword_is_refused_at_its_key(tmp_path: Path) -> None:
    text = SPEC.read_text(encoding="utf-8")
    spec = tmp_path / "careless.yaml"
    spec.write_text(re.sub(r"\bcalibration_status_type\b", "repeat", text), encoding="utf-8")
    line = spec.read_text(encoding="utf-8").splitlines().index("  repeat:") + 1
    assert_refused(tmp_path, spec, line, "enums.repeat: 'repeat' cannot be a name", "Lua")


def test_a_payload_named_like_the_c_api_is_refused(tmp_path: Path) -> None:
    text = SPEC.read_text(encoding="utf-8")
    spec = tmp_path / "careless.yaml"
    spec.write_text(re.sub(r"\bquaternion\b", "stream", text), encoding="utf-8")
    line = spec.read_text(encoding="utf-8").splitlines().index("  - name: stream") + 1
    assert_refused(tmp_path, spec, line, "'stream' cannot be a payload name", "already a name in the generated C")


# --- limits ----------------------------------------------------------------------------------


def test_a_message_length_the_c_runtime_cannot_hold_is_refused(tmp_path: Path) -> None:
    spec, line = edited(tmp_path, "    max: 58\n", "    max: 254\n")
    assert_refused(tmp_path, spec, line, "frame.message_length.max: 254 is above 253", "C runtime", "uint8_t")
    # 253 (a 255-byte frame) is the longest the C stream decoder holds: valid.
    spec, _ = edited(tmp_path, "    max: 58\n", "    max: 253\n")
    result = subprocess.run(
        [PY, "-m", "generator", "--spec", str(spec), "--validate-only"],
        check=False,
        cwd=ROOT,
        capture_output=True,
        text=True,
    )
    assert result.returncode == 0, result.stderr


def test_nesting_deeper_than_the_bound_is_refused_not_a_recursion_error(tmp_path: Path) -> None:
    text = SPEC.read_text(encoding="utf-8")
    spec = tmp_path / "deep.yaml"
    spec.write_text(text + "deep: " + "[" * 400 + "]" * 400 + "\n", encoding="utf-8")
    line = text.count("\n") + 1
    assert_refused(tmp_path, spec, line, f"nested more than {MAX_DEPTH} levels deep")
    # The bound itself is not in the way of a spec: the real one is far shallower.
    spec.write_text(text.replace("erratum: E41}", "erratum: E41, x: " + "[" * 50 + "]" * 50 + "}"), encoding="utf-8")
    assert "nested" not in generate(spec, tmp_path / "out").stderr


def test_a_doc_longer_than_the_bound_is_refused(tmp_path: Path) -> None:
    spec, line = edited(tmp_path, "doc: degrees}", "doc: " + "x" * (MAX_DOC_CHARS + 1) + "}")
    assert_refused(tmp_path, spec, line, f"units.deg.doc: a text of {MAX_DOC_CHARS + 1} characters")


def test_a_file_larger_than_the_bound_is_refused_before_it_is_parsed(tmp_path: Path) -> None:
    spec = tmp_path / "large.yaml"
    with spec.open("w", encoding="utf-8") as stream:
        stream.write(SPEC.read_text(encoding="utf-8"))
        stream.write(("#" * 1023 + "\n") * (MAX_FILE_BYTES // 1024 + 1))
    assert_refused(tmp_path, spec, None, "larger than 4 MB")


def test_an_unknown_top_level_key_is_reported_at_its_own_line(tmp_path: Path) -> None:
    spec, line = edited(tmp_path, "byte_order: little", "wibble: 3\nbyte_order: little")
    assert_refused(tmp_path, spec, line, "wibble: unknown key 'wibble'")


# --- the lists stay in step with what they describe ------------------------------------------


def test_every_target_with_generated_identifiers_has_a_list() -> None:
    assert {r.target for r in reserved_lists()} == {"c", "kaitai", "python", "rust", "wireshark"}


def _words(target: str, kind: str) -> frozenset[str]:
    (found,) = [r for r in reserved_lists() if r.target == target]
    return found.words[kind] | found.words["any"]


def test_the_python_list_holds_every_member_of_a_generated_payload_class() -> None:
    from ilahrs.payloads import PAYLOADS

    members = set()
    for cls in PAYLOADS.values():
        fields = {info.name for info in cls.FIELDS}
        accessors = {n for n in dir(cls) for f in fields if n.startswith(f + "_")}
        members |= {n for n in dir(cls) if n[:1].islower() and n not in fields and n not in accessors}
    assert members, "no members found"
    assert members <= _words("python", "field"), members - _words("python", "field")


def test_the_c_list_holds_every_ilahrs_stem_of_the_runtime() -> None:
    from generator import build_spec

    spec = build_spec()
    own = {p.name for p in spec.payloads} | {e.name for e in spec.enums}
    sources = [*(ROOT / "generator/targets/c/runtime").glob("*.[ch]"), *(ROOT / "generated/c").glob("*.[ch]")]
    text = "\n".join(p.read_text(encoding="utf-8") for p in sources)
    ids = set(re.findall(r"\b(?:ilahrs|ILAHRS)_\w+", text))
    stems = set()
    for name in (i.lower()[len("ilahrs_") :] for i in ids):
        parts = name.split("_")
        for end in range(1, len(parts) + 1):
            stem = "_".join(parts[:end])
            if any(stem.startswith(p + "_") for p in own) or stem.startswith(("build_", "check_")):
                continue
            generated = {f"ilahrs_{stem}_t", f"ilahrs_{stem}_parse", f"ilahrs_{stem}_build"}
            generated |= {f"ilahrs_{stem}_build_frame", f"ILAHRS_{stem.upper()}_SIZE", f"ILAHRS_PAYLOAD_{stem.upper()}"}
            if generated & ids or f"struct ilahrs_{stem} " in text:
                stems.add(stem)
    stems -= own
    assert stems <= _words("c", "payload"), sorted(stems - _words("c", "payload"))


def test_the_rust_list_holds_the_keywords_the_rust_target_escapes() -> None:
    from generator.targets.rust import filters

    assert _words("rust", "payload") >= filters._KEYWORDS


# --- the property: what the validator accepts builds everywhere --------------------------------

# Fields of full_output renamed (each name is renamed everywhere it appears, so the $PAHR sentence
# and the other tables holding a field of that name follow), two enum values and a payload table.
FIELD_SLOTS: tuple[str, ...] = (
    "heading",
    "pitch",
    "roll",
    "ugyro_x",
    "ugyro_y",
    "ugyro_z",
    "uacc_x",
    "uacc_y",
    "uacc_z",
)
FIELD_SLOTS += ("umag_x", "umag_y", "umag_z", "vdd")
ENUM_SLOTS = ("two_d", "three_d")
PAYLOAD_SLOT = "quaternion"
SLOTS = FIELD_SLOTS + ENUM_SLOTS + (PAYLOAD_SLOT,)

# Names at the edges of what the validator accepts: escaped in Rust, soft keywords in Python,
# builtins and C library names, the generated code's own locals, odd underscores.
EDGES = [
    "self", "type", "match", "fn", "mut", "impl", "loop", "crate", "super", "move", "ref", "use",
    "none", "cls", "print", "len", "list", "str", "bytes", "object", "struct_", "int_", "errno_", "m",
    "k", "cap", "data", "result", "variant", "info", "field", "local", "function", "until", "x__y",
    "a_", "z9", "std", "core", "uint8_t", "size_t", "ilahrs", "nan", "inf", "self_", "error_",
]  # fmt: skip


def accepted(name: str, *, field: bool) -> bool:
    """Whether no list refuses `name` as a field name (`field`) or as an enum value or
    payload name (PascalCase too)."""
    from generator.targets.naming import pascal

    kinds = ("field",) if field else ("payload", "other")
    forms = (name,) if field else (name, pascal(name))
    return not any(
        form in _words(target, kind)
        for target in ("c", "kaitai", "python", "rust", "wireshark")
        for kind in kinds
        for form in forms
    )


IDENT = st.from_regex(r"[a-z][a-z0-9_]{0,14}", fullmatch=True)
FIELD_IDENTS = st.one_of(st.sampled_from(EDGES), IDENT).filter(lambda n: accepted(n, field=True))
OTHER_IDENTS = st.one_of(st.sampled_from(EDGES), IDENT).filter(lambda n: accepted(n, field=False))


@st.composite
def slot_names(draw: st.DrawFn) -> list[str]:
    fields = draw(st.lists(FIELD_IDENTS, min_size=len(FIELD_SLOTS), max_size=len(FIELD_SLOTS), unique=True))
    others = st.lists(OTHER_IDENTS.filter(lambda n: n not in fields), min_size=3, max_size=3, unique=True)
    return [*fields, *draw(others)]


def test_the_edge_names_are_ones_the_validator_accepts_as_fields() -> None:
    assert [name for name in EDGES if not accepted(name, field=True)] == []


def renamed_spec(path: Path, names: list[str]) -> Path:
    text = SPEC.read_text(encoding="utf-8")
    # Through placeholders, so that a new name equal to a later slot is not renamed again.
    for index, old in enumerate(SLOTS):
        text = re.sub(rf"\b{old}\b", f"@{index}@", text)
    for index, new in enumerate(names):
        text = text.replace(f"@{index}@", new)
    path.write_text(text, encoding="utf-8")
    return path


PYTHON_CHECK = """
import importlib, pkgutil, sys
sys.path.insert(0, sys.argv[1])
import ilahrs
for module in pkgutil.iter_modules(ilahrs.__path__):
    if module.name != "__main__":
        importlib.import_module("ilahrs." + module.name)
from ilahrs.payloads import PAYLOADS
for name, cls in PAYLOADS.items():
    block = cls()
    assert cls.parse(block.build()) == block, name
    assert cls.from_raw(block.raw()) == block, name
    block.values(); block.json(); block.check()
    for info in cls.FIELDS:
        getattr(block, info.name)
"""


def run(args: list[str], cwd: Path, env: dict[str, str] | None = None) -> str:
    result = subprocess.run(args, check=False, cwd=cwd, capture_output=True, text=True, timeout=900, env=env)
    assert result.returncode == 0, f"{' '.join(args)} failed:\n{result.stdout[-3000:]}\n{result.stderr[-3000:]}"
    return result.stdout + result.stderr


def build_everything(out: Path, work: Path) -> None:
    # Python: imports, round trips through every payload class, no error-level ruff finding.
    run([PY, "-I", "-c", PYTHON_CHECK, str(out / "python")], cwd=work)
    ruff = Path(PY).parent / "ruff"
    run([str(ruff), "check", "--isolated", "--no-cache", "--select", "E9,F63,F7,F82,F811", "ilahrs"], out / "python")
    # C: the library with gcc -Werror, the header as C++ with g++.
    c_dir = out / "c"
    run(
        ["gcc", "-std=c99", "-Wall", "-Wextra", "-Wpedantic", "-Werror", "-c", "ilahrs.c", "-o", str(work / "c.o")],
        c_dir,
    )
    cpp = work / "header.cpp"
    cpp.write_text('#include "ilahrs.h"\nint main() { return 0; }\n', encoding="utf-8")
    run(["g++", "-std=c++11", "-Wall", "-Wextra", "-Werror", "-fsyntax-only", f"-I{c_dir}", str(cpp)], work)
    # Rust: the crate type-checks (a target folder shared by the examples keeps this quick).
    if shutil.which("cargo"):
        env = {**os.environ, "CARGO_TARGET_DIR": str(ROOT / "build" / "refusals-cargo")}
        run(["cargo", "check", "--offline", "--quiet"], out / "rust", env)
    # Lua: the dissector loads in tshark (which reports a Lua error on stderr, status 0), or luac -p.
    lua = out / "wireshark" / "ilahrs.lua"
    luac = shutil.which("luac") or shutil.which("luac5.4") or shutil.which("luac5.3")
    if luac:
        run([luac, "-p", str(lua)], work)
    if shutil.which("tshark"):
        output = run(["tshark", "-G", "protocols", "-X", f"lua_script:{lua}"], work)
        assert "Lua:" not in output and "ilahrs" in output.lower(), output[-3000:]
    # Kaitai: the .ksy compiles with the official compiler into Python that compiles.
    compiler = ROOT / "tools" / "kaitai" / "compile.js"
    if shutil.which("node") and (ROOT / "tools" / "kaitai" / "node_modules" / "kaitai-struct-compiler").is_dir():
        run(["node", str(compiler), "python", str(out / "kaitai" / "ilahrs.ksy"), str(work / "ksc")], work)
        run([PY, "-m", "py_compile", *map(str, (work / "ksc").glob("*.py"))], work)


EDGE_EXAMPLE = [*EDGES[: len(FIELD_SLOTS)], "cls", "a_", "print"]


@settings(
    max_examples=4,
    derandomize=True,
    deadline=None,
    database=None,
    suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow],
)
@example(names=EDGE_EXAMPLE)
@given(names=slot_names())
def test_every_spec_the_validator_accepts_builds_in_every_target(
    tmp_path_factory: pytest.TempPathFactory, names: list[str]
) -> None:
    work = tmp_path_factory.mktemp("build")
    spec = renamed_spec(work / "renamed.yaml", names)
    out = work / "out"
    result = generate(spec, out)
    if names == EDGE_EXAMPLE:
        assert result.returncode == 0, result.stderr[-3000:]
    if result.returncode != 0:
        # Refused: then by the validator, in one line naming the spec's line, never later.
        lines = result.stderr.splitlines()
        assert result.returncode == 2 and len(lines) == 1, result.stderr[-3000:]
        assert re.match(r"^error: renamed\.yaml:\d+: ", lines[0]), lines[0]
        return
    build_everything(out, work)
