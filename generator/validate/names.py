"""Names no target can take: keywords, reserved identifiers and the generated APIs' own members.

Each target keeps its list beside its templates, generator/targets/<target>/reserved.txt:

    language: C and C++           what the messages call the target
    [any]                         words refused for every name the spec feeds into generated code
    [other]                       ... for every name but field names (types, variants, table keys)
    [payload]                     ... for payload table names
    [field]                       ... for field names (of the frame, the payloads, the $PAHR sentence)

Words are separated by white space; `#` starts a comment. A name is compared as the templates use
it: as written (spec names are already lower_snake_case, the form fields, functions and modules
take) and, unless it is a field name, in PascalCase (`pascal`, the form of classes, types and
variants: `self` -> `Self`).
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass
from functools import cache
from pathlib import Path
from typing import Any

import jsonschema

from ..load import LoadedSpec, PathKey
from ..targets import naming

TARGETS_DIR = Path(__file__).resolve().parent.parent / "targets"
ROOT = TARGETS_DIR.parent.parent
KINDS = ("any", "other", "payload", "field")


@dataclass(frozen=True)
class Reserved:
    """One target's list."""

    target: str
    language: str
    source: str
    words: dict[str, frozenset[str]]


def parse_reserved(target: str, source: str, text: str) -> Reserved:
    """Read a reserved.txt; raise ValueError naming the line of anything it does not understand."""
    language = ""
    words: dict[str, set[str]] = {kind: set() for kind in KINDS}
    section: str | None = None
    for number, raw in enumerate(text.splitlines(), start=1):
        line = raw.split("#", 1)[0].strip()
        if not line:
            continue
        if line.startswith("language:"):
            language = line.removeprefix("language:").strip()
        elif line.startswith("[") and line.endswith("]"):
            section = line[1:-1]
            if section not in words:
                raise ValueError(f"{source}:{number}: unknown section [{section}] (one of {', '.join(KINDS)})")
        elif section is None:
            raise ValueError(f"{source}:{number}: a word before the first [section]")
        else:
            words[section].update(line.split())
    if not language:
        raise ValueError(f"{source}: no `language:` line")
    return Reserved(target, language, source, {kind: frozenset(found) for kind, found in words.items()})


@cache
def reserved_lists() -> tuple[Reserved, ...]:
    """Every target's list, in target order."""
    found = []
    for path in sorted(TARGETS_DIR.glob("*/reserved.txt")):
        source = path.relative_to(ROOT).as_posix()
        found.append(parse_reserved(path.parent.name, source, path.read_text(encoding="utf-8")))
    return tuple(found)


def _ident_pattern(schema: dict[str, Any]) -> str:
    pattern: str = schema["$defs"]["ident"]["pattern"]
    return pattern


def spec_names(spec: LoadedSpec, schema: dict[str, Any]) -> Iterator[tuple[PathKey, str]]:
    """Every name in the spec that generated code uses: each value the schema types as an
    identifier (`$defs/ident`), and the enum names (the keys of `enums`)."""
    ident = _ident_pattern(schema)

    def pattern(validator: Any, expected: str, instance: Any, sub: dict[str, Any]) -> Iterator[Any]:
        # Report every identifier as an "error" so that jsonschema supplies its path.
        if expected == ident and isinstance(instance, str):
            yield jsonschema.ValidationError(instance, validator="ident")

    marker = jsonschema.validators.extend(  # type: ignore[no-untyped-call]
        jsonschema.Draft202012Validator, {"pattern": pattern}
    )
    for error in marker(schema).iter_errors(spec.data):
        if error.validator == "ident":
            yield tuple(error.absolute_path), str(error.instance)
    for key in spec.data.get("enums", {}) or {}:
        yield ("enums", key), key


def _kind(path: PathKey) -> str:
    if len(path) == 3 and path[0] == "payloads" and path[2] == "name":
        return "payload"
    if len(path) >= 3 and path[-3] == "fields" and path[-1] == "name":
        return "field"
    return "any"


def _defines(path: PathKey) -> bool:
    """Whether the name at `path` is where a thing is named (the others refer to one)."""
    return bool(path) and (path[-1] in ("name", "id") or (path[0] == "enums" and len(path) == 2))


def _line(spec: LoadedSpec, path: PathKey) -> int:
    line = spec.key_lines.get(path) if path and path[0] == "enums" and len(path) == 2 else None
    return line if line is not None else spec.line_of(path) or 0


def check_reserved(spec: LoadedSpec, schema: dict[str, Any]) -> None:
    """Raise SpecError for the first name that a target's list refuses: where a thing is named
    rather than where it is referred to, then in file order."""
    lists = reserved_lists()
    names = sorted(
        spec_names(spec, schema), key=lambda item: (not _defines(item[0]), _line(spec, item[0]), str(item[0]))
    )
    for path, name in names:
        kind = _kind(path)
        forms = [(name, "")]
        pascal = naming.pascal(name)
        # Field names (of the frame, payloads and the $PAHR sentence) are members and functions,
        # never types: only the other names take the PascalCase form.
        if pascal != name and "fields" not in path:
            forms.append((pascal, "its PascalCase form "))
        problems: list[str] = []
        sources: list[str] = []
        for reserved in lists:
            general = reserved.words["any"] if "fields" in path else reserved.words["any"] | reserved.words["other"]
            for form, how in forms:
                if form in general:
                    problems.append(f"{how}`{form}` is reserved in {reserved.language}")
                elif kind != "any" and form in reserved.words[kind]:
                    problems.append(f"{how}`{form}` is already a name in the generated {reserved.language} API")
                else:
                    continue
                sources.append(reserved.source)
                break
        if problems:
            what = {"any": "name", "payload": "payload name", "field": "field name"}[kind]
            message = f"{name!r} cannot be a {what}: {'; '.join(problems)} (see {', '.join(sources)})"
            if path and path[0] == "enums" and len(path) == 2:
                raise spec.key_error(path, message)
            raise spec.error(path, message)
