"""What every suite module shares: the vector record, hex as the ICD prints it, the case files."""

from __future__ import annotations

import json
import math
from collections.abc import Callable, Mapping
from functools import cache
from pathlib import Path
from typing import Any

import oracle as o

ICD = "Inertial Labs AHRS ICD rev 1.7"
CASES_DIR = Path(__file__).resolve().parent / "cases"

Vector = dict[str, Any]


def hx(data: bytes) -> str:
    """Bytes as the ICD prints them: upper-case hex, one space between bytes."""
    return " ".join(f"{b:02X}" for b in data)


def vec(id_: str, kind: str, input_: Any, expect: Any, note: str, *, tests: str | None = None) -> Vector:
    """A vector; `tests` names the erratum of spec/ilahrs.yaml it was written to test (its expected
    answer rests on that erratum's side), which levels.py turns into its level."""
    out = {"id": id_, "kind": kind, "input": input_, "expect": expect, "note": note}
    if tests is not None:
        out["tests"] = tests
    return out


def jsonable(value: object) -> object:
    """NaN and infinities are not JSON numbers: the suites write them as "nan", "inf", "-inf"."""
    if isinstance(value, float) and not math.isfinite(value):
        return "nan" if math.isnan(value) else ("inf" if value > 0 else "-inf")
    return value


def attempt(fn: Callable[[], Any]) -> Any:
    """The oracle's answer, or its refusal as an expected error."""
    try:
        return fn()
    except o.OracleError as err:
        return err.expect()


@cache
def cases(suite: str) -> Any:
    """The case file of a suite, cases/<suite>.json: its values and notes, read as they are."""
    with (CASES_DIR / f"{suite}.json").open(encoding="utf-8") as file:
        return json.load(file)


def phrases(suite: str) -> dict[str, str]:
    """The phrases a suite's notes name as {name}; {ICD} is the ICD's title."""
    return {"ICD": ICD, **cases(suite).get("phrases", {})}


def expand(text: str, names: Mapping[str, object]) -> str:
    """A note of a case file with its {name} phrases filled in."""
    return text.format_map(names)


def source(suite: str) -> str:
    """The suite's "source" line: the ICD sections and spec rules its vectors come from."""
    return expand(cases(suite)["source"], phrases(suite))
