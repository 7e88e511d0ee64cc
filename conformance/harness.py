#!/usr/bin/env python3
"""Run conformance vectors against one or more bindings' runners and compare the answers.

    python3 conformance/harness.py                               # every registered binding, every suite
    python3 conformance/harness.py --bindings python,c           # some bindings
    python3 conformance/harness.py --vectors DIR                 # any directory of suites
    python3 conformance/harness.py --command ./my_runner         # an unregistered runner, no JSON needed
    python3 conformance/harness.py --suite nmea -k bad-checksum  # a subset, for debugging
    python3 conformance/harness.py --junit report.xml            # JUnit XML for a CI dashboard

The harness is the Python package's (`ilahrs.conformance`, generated/python/ilahrs/conformance/;
`ilahrs conformance` once the package is installed); this wrapper runs it with the repository's
defaults: the suites of conformance/vectors, the registrations of conformance/bindings, runner
commands run from the repository root. Standard library only, Python 3.10 or later.
Exit status: 0 when nothing failed, 1 when something failed, 2 when the suites or the
bindings cannot be read.
"""

from __future__ import annotations

import sys
from collections.abc import Sequence
from pathlib import Path
from typing import IO

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "generated" / "python"))

from ilahrs import conformance  # noqa: E402
from ilahrs.conformance import (  # noqa: E402
    KINDS,
    Answer,
    Binding,
    BindingError,
    Result,
    Suite,
    SuiteError,
    Vector,
    compare,
    load_bindings,
    load_suites,
    parse_answer,
    request,
)

__all__ = [
    "KINDS",
    "ROOT",
    "Answer",
    "Binding",
    "BindingError",
    "Result",
    "Suite",
    "SuiteError",
    "Vector",
    "compare",
    "load_bindings",
    "load_suites",
    "main",
    "parse_answer",
    "request",
]


def main(argv: Sequence[str] | None = None, out: IO[str] = sys.stdout) -> int:
    return conformance.main(
        argv,
        out,
        vectors=ROOT / "conformance" / "vectors",
        root=ROOT,
        bindings_dir=ROOT / "conformance" / "bindings",
    )


if __name__ == "__main__":
    sys.exit(main())
