"""What every part of validation uses (part of generator.validate): the check that names are
unique, and the names a spec defines that other parts refer to."""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass
from typing import Any

from ..load import LoadedSpec, PathKey


def duplicates(items: Iterable[tuple[PathKey, Any]], what: str, spec: LoadedSpec) -> None:
    """Every key given is different; the second use of one is an error at its path."""
    seen: dict[Any, PathKey] = {}
    for path, key in items:
        if key in seen:
            raise spec.error(path, f"duplicate {what} {key!r} (first at line {spec.line_of(seen[key])})")
        seen[key] = path


def unique(spec: LoadedSpec, items: list[Any], prefix: PathKey, key: str, what: str) -> None:
    """Every item of the list at `prefix` has a different `key`."""
    duplicates((((*prefix, i, key), item[key]) for i, item in enumerate(items)), what, spec)


@dataclass(frozen=True)
class Names:
    """What the spec defines that fields, commands and the state machine refer to by name."""

    units: set[str]
    variant_parameters: set[str]
    enums: dict[str, Any]  # name -> the enum's data
    encodings: set[str]
    status_word: dict[str, Any] | None
    errata: set[str]
    modes: list[str]
    payloads: list[str]
