"""The Python target: the `ilahrs` package in generated/python/.

Templates write what the spec decides (the tables, the payload and sentence classes, the enums and
constants); the modules of runtime/ are the code that reads them, copied as they are. Everything
is formatted by `ruff format`, with the package's settings given on the command line.
"""

from __future__ import annotations

from pathlib import Path

from generator.model import Spec
from generator.render import Output, Runtime
from generator.targets.formatting import run_formatter, tool

from .filters import ENCODING_PROPERTIES
from .filters import FILTERS as CODEC_FILTERS
from .roles import roles
from .tables import FILTERS as TABLE_FILTERS
from .tables import GLOBALS as TABLE_GLOBALS

__all__ = ["FILTERS", "GLOBALS", "format", "outputs"]

FILTERS = {**CODEC_FILTERS, **TABLE_FILTERS}
GLOBALS = {**TABLE_GLOBALS, "roles": roles, "encoding_properties": ENCODING_PROPERTIES}

PACKAGE = "python/ilahrs"
# Generated modules: the spec's facts, from the bottom of the import graph up.
TABLES = ("spec", "encodings", "status", "payloads", "commands", "nmea")
# Runtime modules: what Python 3.10 lacks (compat), the codec (errors, frame, value encodings,
# payloads, sentences, commands) and the stream decoder.
CODEC = ("compat", "errors", "frame", "valuecodec", "codec", "sentence", "commandset", "stream", "bulk", "columnar")
# The protocol's behaviour: the state-machine table and the roles of the commands (generated), the
# device model and the host session (sans-I/O), then the edge: the virtual device on a pty or loopback
# socket, the serial client, the command line.
BEHAVIOUR_TABLES = ("statemachine", "roles")
BEHAVIOUR = (
    "diagram",
    "machine",
    "synthetic",
    "motion",
    "device",
    "host",
    "anystate",
    "simulate",
    "serial",
    "__main__",
)
# The subcommands of the `ilahrs` command besides simulate and diagram (record, decode, send, params,
# monitor, calibrate, plot).
CLI = ("cli_common", "cli_capture", "cli_decode", "cli_device", "cli_monitor", "cli_plot", "cli")
# What a spec must have for the package to be generated.
# The conformance suite: the harness and its suites (package data, copied byte for byte from the
# repository's conformance/vectors); with the state machine, the live run against a device and the
# virtual device's test-only misbehaviours.
CONFORMANCE = ("conformance",)
LIVE = ("live", "misbehave")
VECTORS = Path(__file__).resolve().parents[3] / "conformance" / "vectors"
REQUIRED = ("serial_line", "status_word", "nmea", "date", "declination", "calibration_success", "ack_payload")

LINE_LENGTH = 120
"""The package's line length (the repository's ruff setting)."""


# Folders that carry the licence texts (render.LICENCE_FILES).
LICENSED = ("python",)


def outputs(spec: Spec) -> list[Output | Runtime]:
    missing = [name for name in REQUIRED if getattr(spec, name) is None]
    if missing:
        raise ValueError(f"the Python target needs the spec's {', '.join(missing)}")
    files: list[Output | Runtime] = [Output(f"{PACKAGE}/{name}.py", f"{name}.py.j2") for name in TABLES]
    files += [Runtime(f"{PACKAGE}/{name}.py", f"{name}.py") for name in CODEC]
    if spec.state_machine is not None:
        files += [Output(f"{PACKAGE}/{name}.py", f"{name}.py.j2") for name in BEHAVIOUR_TABLES]
        files += [Runtime(f"{PACKAGE}/{name}.py", f"{name}.py") for name in BEHAVIOUR]
        files += [Runtime(f"{PACKAGE}/{name}.py", f"{name}.py") for name in CLI]
        files += [Runtime(f"{PACKAGE}/{name}.py", f"{name}.py") for name in LIVE]
    files += [Runtime(f"{PACKAGE}/{name}.py", f"{name}.py") for name in CONFORMANCE]
    files += [vectors_output(path) for path in sorted(VECTORS.glob("*.json"))]
    files += [
        Output(f"{PACKAGE}/__init__.py", "__init__.py.j2"),
        Output(f"{PACKAGE}/py.typed", "py.typed.j2"),
        Runtime(f"{PACKAGE}/pcapng.py", "pcapng.py"),
        Output("python/pyproject.toml", "pyproject.toml.j2"),
        Output("python/README.md", "README.md.j2"),
    ]
    return files


def vectors_output(path: Path) -> Output:
    """A suite of conformance/vectors as package data, unchanged (`make check` finds any drift)."""
    return Output(f"{PACKAGE}/vectors/{path.name}", "vector.json.j2", {"text": path.read_text(encoding="utf-8")})


def format(files: dict[str, str]) -> dict[str, str]:
    """Format the package's Python files and the Python examples of its README with the pinned ruff,
    with settings that do not depend on the machine."""

    def command(paths: list[Path]) -> list[str]:
        settings = ["--isolated", "--no-cache", f"--line-length={LINE_LENGTH}", "--target-version=py310"]
        return [tool("ruff"), "format", *settings, *map(str, paths)]

    return run_formatter(files, (".py", ".md"), command)
