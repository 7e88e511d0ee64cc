# Copied from generator/targets/python/runtime/conformance/__init__.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""The conformance suite: run the vectors against a runner and compare its answers.

    ilahrs conformance --command "./my_runner"                  # every vector shipped with the package
    ilahrs conformance --command "./my_runner" --kinds checksum,frame_decode --junit report.xml
    ilahrs conformance --bindings-dir conformance/bindings      # runners registered as NAME.json
    ilahrs conformance --bindings-dir conformance/bindings --bindings all --command "./mine" --name mine \
        --report report.html                                    # both, side by side in one page
    ilahrs conformance --device /dev/ttyUSB0                    # a device, live (ilahrs.conformance.live)

The suites (`vectors/*.json` in this package, the same files as the repository's
conformance/vectors) hold every request and expectation; a runner only turns request lines into
answer lines (the runner protocol of the package README). Each runner is started once and fed
every vector. Standard library only. Exit status: 0 when nothing failed, 1 when something failed,
2 when the suites or the registrations cannot be read.

The modules: `vectors` (the suites, a session's events as typed values), `protocol` (request and
answer lines), `compare` (an answer against its expectation), `runner` (registrations, runner
processes, a binding's run), `report` (table, JSON, JUnit XML), `html` (the results as one
self-contained HTML page, `--report`), `live` (the flows against a device) and `command` (the
options and the run of `ilahrs conformance`).
"""

from __future__ import annotations

from .command import add_arguments, main, run
from .compare import compare
from .protocol import Answer, parse_answer, request
from .report import junit_xml
from .runner import Binding, BindingError, Case, Result, load_bindings
from .vectors import (
    KINDS,
    OPTIONS,
    VECTORS_DIR,
    CommandEvent,
    DataEvent,
    SessionEvent,
    Suite,
    SuiteError,
    TimerEvent,
    Vector,
    load_suites,
)

__all__ = [
    "KINDS",
    "OPTIONS",
    "VECTORS_DIR",
    "Answer",
    "Binding",
    "BindingError",
    "Case",
    "CommandEvent",
    "DataEvent",
    "Result",
    "SessionEvent",
    "Suite",
    "SuiteError",
    "TimerEvent",
    "Vector",
    "add_arguments",
    "compare",
    "junit_xml",
    "load_bindings",
    "load_suites",
    "main",
    "parse_answer",
    "request",
    "run",
]
