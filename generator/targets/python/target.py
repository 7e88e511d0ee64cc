"""The Python target: the `ilahrs` package in generated/python/."""

from __future__ import annotations

from generator.model import Spec
from generator.render import Output, Runtime

from .behaviour import FILTERS as BEHAVIOUR_FILTERS
from .behaviour import GLOBALS
from .filters import FILTERS as CODEC_FILTERS

__all__ = ["FILTERS", "GLOBALS", "outputs"]

FILTERS = {**CODEC_FILTERS, **BEHAVIOUR_FILTERS}

MODULES = ("errors", "frame", "encodings", "status", "payloads", "commands", "nmea", "stream")
# The protocol's behaviour: the state-machine table, the device model and the host session (sans-I/O),
# then the edge: the virtual device on a pty or loopback socket, the serial client, the command line.
BEHAVIOUR_MODULES = ("statemachine", "motion", "device", "host", "simulate", "serial", "__main__")


def outputs(spec: Spec) -> list[Output | Runtime]:
    base = "python/ilahrs"
    files: list[Output | Runtime] = [Output(f"{base}/{name}.py", f"{name}.py.j2") for name in MODULES]
    if spec.state_machine is not None:
        files += [Output(f"{base}/{name}.py", f"{name}.py.j2") for name in BEHAVIOUR_MODULES]
    files += [
        Output(f"{base}/__init__.py", "__init__.py.j2"),
        Output(f"{base}/py.typed", "py.typed.j2"),
        Runtime(f"{base}/pcapng.py", "pcapng.py"),
        Output("python/pyproject.toml", "pyproject.toml.j2"),
        Output("python/README.md", "README.md.j2"),
    ]
    return files
