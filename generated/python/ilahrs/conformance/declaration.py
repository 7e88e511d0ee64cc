# Copied from generator/targets/python/runtime/conformance/declaration.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""Declarations and expected failures: what an implementation says it supports
(conformance/declaration.schema.json), which vectors apply to it, and the vectors it is known to
fail ({"<suite>/<id>": "reason"}).

A vector applies when the declaration lists everything in the vector's "requires" and does not take
the other side of the vector's erratum. A declaration chooses a side only of the errata the spec gives
an `alternative` (ilahrs.spec.ERRATA_ALTERNATIVES); the others are corrections with one reading. The
checks here are written by hand (standard library only) and agree with the schema; tests/conformance
holds them to it.
"""

from __future__ import annotations

import json
import os
import re
import tempfile
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from ..commands import COMMANDS
from ..encodings import VARIANTS
from ..payloads import PAYLOADS
from ..spec import ERRATA_ALTERNATIVES
from ..statemachine import OUTPUT_FORMATS
from .vectors import Suite, Vector

__all__ = [
    "CHOICES",
    "FIRMWARE_BEHAVIOURS",
    "NAME_LISTS",
    "Declaration",
    "DeclarationError",
    "everything",
    "load_declaration",
    "load_expected_failures",
    "vocabulary",
    "write_expected_failures",
    "write_new",
]

FIRMWARE_BEHAVIOURS = ("legacy_stop_clb",)
"""Firmware behaviours a vector may need: legacy_stop_clb, firmware before the current one whose
StopClb (0x20) also finishes a 2D-2T calibration (E29)."""
CHOICES = ("spec", "other")
"""An erratum choice: the spec's side, or the other one (its vectors do not apply)."""
NAME_LISTS = ("commands", "outputs", "payloads", "variants", "firmware")
_KEYS = ("$schema", "implementation", *NAME_LISTS, "nmea", "errata")
_REQUIRED = (*NAME_LISTS, "nmea")
_ERRATUM_RE = re.compile(r"E[0-9]+")
_KEY_RE = re.compile(r"[^/]+/.+")


class DeclarationError(Exception):
    """A declaration or an expected-failure file that cannot be used."""


def vocabulary() -> dict[str, tuple[str, ...]]:
    """The names each list of a declaration takes, from the spec's tables."""
    return {
        "commands": tuple(COMMANDS),
        "outputs": tuple(OUTPUT_FORMATS),
        "payloads": tuple(PAYLOADS),
        "variants": tuple(VARIANTS),
        "firmware": FIRMWARE_BEHAVIOURS,
    }


@dataclass
class Declaration:
    doc: dict[str, Any]
    path: Path | None = None

    def why_not(self, v: Vector) -> str | None:
        """Why the vector does not apply to this implementation, or None when it does."""
        for key in NAME_LISTS:
            missing = [n for n in v.requires.get(key, ()) if n not in self.doc[key]]
            if missing:
                return f"not declared: {key} {', '.join(missing)}"
        if v.requires.get("nmea") and not self.doc["nmea"]:
            return "not declared: nmea ($PAHR)"
        if v.erratum is not None and self.doc.get("errata", {}).get(v.erratum) == "other":
            return f"declares the other side of {v.erratum}"
        return None


def check(doc: object, where: str) -> dict[str, Any]:
    """A declaration, checked as declaration.schema.json says."""
    if not isinstance(doc, dict):
        raise DeclarationError(f"{where}: a declaration is a JSON object (conformance/declaration.schema.json)")
    unknown = sorted(set(doc) - set(_KEYS))
    if unknown:
        raise DeclarationError(f"{where}: unknown keys {', '.join(unknown)} (keys: {', '.join(_KEYS)})")
    missing = [k for k in _REQUIRED if k not in doc]
    if missing:
        raise DeclarationError(f"{where}: missing {', '.join(missing)}")
    for key in ("$schema", "implementation"):
        if key in doc and not isinstance(doc[key], str):
            raise DeclarationError(f"{where}: {key} must be a string")
    names = vocabulary()
    for key in NAME_LISTS:
        value = doc[key]
        if not isinstance(value, list) or not all(isinstance(n, str) for n in value):
            raise DeclarationError(f"{where}: {key} must be a list of names")
        wrong = [n for n in value if n not in names[key]]
        if wrong:
            raise DeclarationError(f"{where}: unknown {key} {', '.join(wrong)} (known: {', '.join(names[key])})")
        if len(set(value)) != len(value):
            raise DeclarationError(f"{where}: {key} names one more than once")
    if not isinstance(doc["nmea"], bool):
        raise DeclarationError(f"{where}: nmea must be true or false")
    errata = doc.get("errata", {})
    if not isinstance(errata, dict) or not all(
        isinstance(k, str) and _ERRATUM_RE.fullmatch(k) and v in CHOICES for k, v in errata.items()
    ):
        raise DeclarationError(f'{where}: errata maps ids like E12 to "spec" or "other"')
    single = sorted((k for k in errata if k not in ERRATA_ALTERNATIVES), key=lambda e: int(e[1:]))
    if single:
        raise DeclarationError(
            f"{where}: errata {', '.join(single)}: no other side to take (only one reading; the errata with "
            f"an alternative: {', '.join(ERRATA_ALTERNATIVES)})"
        )
    return doc


def load_declaration(path: Path) -> Declaration:
    try:
        doc = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError) as err:
        raise DeclarationError(f"declaration {path}: {err}") from None
    return Declaration(check(doc, f"declaration {path}"), path)


def everything(suites: Iterable[Suite]) -> dict[str, Any]:
    """A declaration with everything enabled and the spec's side of every erratum the suites test that
    has an alternative (an implementation may take its other side)."""
    tested = {v.erratum for s in suites for v in s.vectors if v.erratum is not None}
    errata = tested & set(ERRATA_ALTERNATIVES)
    doc: dict[str, Any] = {"implementation": "my implementation"}
    doc |= {key: list(names) for key, names in vocabulary().items()}
    doc["nmea"] = True
    doc["errata"] = dict.fromkeys(sorted(errata, key=lambda e: int(e[1:])), "spec")
    return doc


def _replace(path: Path, text: str) -> None:
    """Write `text` to `path` through a temporary file in the same folder, renamed over it."""
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", dir=path.parent or Path("."))
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as file:
            file.write(text)
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


def write_new(path: Path, doc: Mapping[str, Any], force: bool) -> None:
    """Write a declaration; an existing file only with `force`."""
    if path.exists() and not force:
        raise DeclarationError(f"{path} exists (--force replaces it)")
    if not path.parent.is_dir():
        raise DeclarationError(f"{path.parent} is not a directory")
    try:
        _replace(path, json.dumps(doc, indent=1) + "\n")
    except OSError as err:
        raise DeclarationError(f"cannot write {path}: {err.strerror or err}") from None


def load_expected_failures(path: Path, suites: Iterable[Suite], *, missing_ok: bool = False) -> dict[str, str]:
    """An expected-failure file, {"<suite>/<id>": "reason"}; every id must name a vector of `suites`."""
    if missing_ok and not path.exists():
        return {}
    try:
        doc = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError) as err:
        raise DeclarationError(f"expected failures {path}: {err}") from None
    if not isinstance(doc, dict) or not all(
        isinstance(k, str) and _KEY_RE.fullmatch(k) and isinstance(v, str) for k, v in doc.items()
    ):
        raise DeclarationError(f'expected failures {path}: an object {{"<suite>/<vector id>": "reason", ...}}')
    known = {v.key for s in suites for v in s.vectors}
    unknown = sorted(k for k in doc if k not in known)
    if unknown:
        more = f" and {len(unknown) - 1} more" if len(unknown) > 1 else ""
        raise DeclarationError(f"expected failures {path}: no vector {unknown[0]}{more} in the suites")
    return dict(doc)


def write_expected_failures(path: Path, entries: Mapping[str, str]) -> None:
    """Rewrite an expected-failure file, sorted, atomically."""
    try:
        _replace(path, json.dumps(dict(sorted(entries.items())), indent=1) + "\n")
    except OSError as err:
        raise DeclarationError(f"cannot write {path}: {err.strerror or err}") from None
