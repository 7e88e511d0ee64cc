"""The conformance suites, one module each, with their cases as data in cases/<suite>.json.

Each module's `vectors()` returns its suite's vectors in order; `build_all` renders every suite as
the committed conformance/vectors/<suite>.json. The oracles (oracle.py, device_oracle.py, beside
this package) compute every expected answer.
"""

from __future__ import annotations

import json
from collections.abc import Callable

from . import acks, appendix_c, checksum, frames, nmea, payloads, sessions, streams
from .common import Vector, source
from .levels import annotate, icd_revision

VERSION = "1.0.0"
"""The version of the suites (semver), written into every suite file: a changed expectation (input,
expect or options of a vector id, or a vector removed) is a major bump, a new vector or a changed
level a minor one, anything else (notes) a patch or nothing. `make_vectors.py --check` compares
with the suites of the last release tag (git) and refuses a change without its bump; before the
first tag nothing is compared, and 1.0.0 is the first release's version."""

SUITES: dict[str, Callable[[], list[Vector]]] = {
    "appendix-c": appendix_c.vectors,
    "checksum": checksum.vectors,
    "acks": acks.vectors,
    "payloads": payloads.vectors,
    "frames": frames.vectors,
    "streams": streams.vectors,
    "nmea": nmea.vectors,
    "sessions": sessions.vectors,
}


def render(suite: str, source: str, vectors: list[Vector]) -> str:
    """One vector per line, so that a diff shows which vectors changed."""
    ids = [v["id"] for v in vectors]
    assert len(ids) == len(set(ids)), [i for i in ids if ids.count(i) > 1]
    lines = [json.dumps(annotate(v), ensure_ascii=True, allow_nan=False) for v in vectors]
    head = (
        f'{{"suite": {json.dumps(suite)}, "version": {json.dumps(VERSION)}, '
        f'"icd_revision": {json.dumps(icd_revision())}, "source": {json.dumps(source)}, "vectors": [\n'
    )
    return head + ",\n".join(lines) + "\n]}\n"


def build_all() -> dict[str, str]:
    """File name -> text, for every suite."""
    return {f"{name}.json": render(name, source(name), build()) for name, build in SUITES.items()}
