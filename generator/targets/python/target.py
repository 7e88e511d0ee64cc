"""The Python target: the `ilahrs` package in generated/python/."""

from __future__ import annotations

from generator.model import Spec
from generator.render import Output

from .filters import FILTERS

__all__ = ["FILTERS", "outputs"]

MODULES = ("errors", "frame", "encodings", "status", "payloads", "commands", "nmea", "stream")


def outputs(spec: Spec) -> list[Output]:
    base = "python/ilahrs"
    files = [Output(f"{base}/{name}.py", f"{name}.py.j2") for name in MODULES]
    files += [
        Output(f"{base}/__init__.py", "__init__.py.j2"),
        Output(f"{base}/py.typed", "py.typed.j2"),
        Output("python/pyproject.toml", "pyproject.toml.j2"),
        Output("python/README.md", "README.md.j2"),
    ]
    return files
