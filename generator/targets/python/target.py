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
RUNTIME = Path(__file__).resolve().parent / "runtime"
"""The hand-written modules, copied as a tree: the folders are the package's layers, from the bottom
of the import graph up (the contract of the repository's .importlinter holds them to it):

- the top level: the generated tables (TABLES, BEHAVIOUR_TABLES) and the codec: what Python 3.10
  lacks (compat), errors, frames, value encodings, payloads, sentences, commands, the stream
  decoder, bulk and columnar decoding, the pcapng format;
- session/: the protocol's behaviour, sans-I/O: the device model and the host session;
- edge/: the I/O edges: the virtual device on a pty or loopback socket (and its test-only
  misbehaviours), the serial client;
- cli/: the `ilahrs` command, one module per subcommand; conformance/: the conformance suite, its
  runners and the live run against a device."""
TABLES = ("spec", "encodings", "status", "payloads", "commands", "nmea")
"""Generated modules: the spec's facts, from the bottom of the import graph up."""
BEHAVIOUR_TABLES = ("statemachine", "roles")
"""Generated with a state machine: its table and the roles of the commands."""
BEHAVIOUR = ("session", "edge", "cli", "conformance/live.py", "__main__.py")
"""Runtime folders and files that need the state machine (left out of a spec without one)."""
ALIASES = {"serial": "edge.serial", "simulate": "edge.simulate", "anystate": "session.anystate", "cli_plot": "cli.plot"}
"""Module paths the documentation named before the layers, kept as aliases of the modules' new places."""
VECTORS = Path(__file__).resolve().parents[3] / "conformance" / "vectors"
# What a spec must have for the package to be generated.
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
    if spec.state_machine is not None:
        files += [Output(f"{PACKAGE}/{name}.py", f"{name}.py.j2") for name in BEHAVIOUR_TABLES]
        files += [Output(f"{PACKAGE}/{name}.py", "alias.py.j2", {"module": to}) for name, to in ALIASES.items()]
    files += [Runtime(f"{PACKAGE}/{source}", source) for source in runtime_sources(spec)]
    files += [vectors_output(path) for path in sorted(VECTORS.glob("*.json"))]
    files += [
        Output(f"{PACKAGE}/__init__.py", "__init__.py.j2"),
        Output(f"{PACKAGE}/py.typed", "py.typed.j2"),
        Output("python/pyproject.toml", "pyproject.toml.j2", {"packages": packages(spec)}),
        Output("python/README.md", "README.md.j2"),
    ]
    return files


def runtime_sources(spec: Spec) -> list[str]:
    """The Python files of runtime/ as paths relative to it, sorted; without a state machine, those
    of BEHAVIOUR left out."""
    sources = sorted(path.relative_to(RUNTIME).as_posix() for path in RUNTIME.rglob("*.py"))
    if spec.state_machine is None:
        sources = [s for s in sources if not any(s == b or s.startswith(f"{b}/") for b in BEHAVIOUR)]
    return sources


def packages(spec: Spec) -> list[str]:
    """The package and its subpackages (pyproject.toml's `packages`)."""
    folders = {source.rpartition("/")[0] for source in runtime_sources(spec)}
    return ["ilahrs", *(f"ilahrs.{folder.replace('/', '.')}" for folder in sorted(folders - {""}))]


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
