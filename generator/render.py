"""Step 5 of the pipeline: turn the laid-out model into files, one target at a time.

A target is a folder under generator/targets/ with a `target.py` that lists its outputs
(path, template, extra context) and may define FILTERS, and a `templates/` folder.
Targets are discovered, so adding one touches no shared file. Templates run under
StrictUndefined; the model they read is immutable.
"""

from __future__ import annotations

import importlib
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Protocol

import jinja2

from . import naming
from .model import Spec

TARGETS_DIR = Path(__file__).resolve().parent / "targets"
COMMON_TEMPLATES = Path(__file__).resolve().parent / "templates"


@dataclass(frozen=True)
class Output:
    """One generated file: `path` relative to generated/, rendered from `template`."""

    path: str
    template: str
    context: dict[str, Any] = field(default_factory=dict)


class TargetModule(Protocol):
    def outputs(self, spec: Spec) -> list[Output]: ...


def target_names() -> list[str]:
    return sorted(p.name for p in TARGETS_DIR.iterdir() if (p / "target.py").is_file())


def derived_files(targets: list[str]) -> set[str]:
    """Files a target's make rules derive from its generated files (declared as DERIVED)."""
    found: set[str] = set()
    for target in targets:
        module = importlib.import_module(f"generator.targets.{target}.target")
        found.update(getattr(module, "DERIVED", ()))
    return found


def notice(spec: Spec) -> list[str]:
    """The lines every generated file starts with, in the target's comment syntax."""
    return [
        f"Generated from {spec.file}, spec hash {spec.sha256}.",
        "Do not edit: change the spec or the generator and run `make generate`.",
    ]


COMMON_FILTERS: dict[str, Callable[..., Any]] = {
    "pascal": naming.pascal,
    "upper": naming.upper,
    "snake": naming.snake,
    "hex_byte": naming.hex_byte,
    "hex_word": naming.hex_word,
    "wrap": naming.wrap,
}


def _environment(target: str, module: Any) -> jinja2.Environment:
    env = jinja2.Environment(
        loader=jinja2.FileSystemLoader([str(TARGETS_DIR / target / "templates"), str(COMMON_TEMPLATES)]),
        undefined=jinja2.StrictUndefined,
        keep_trailing_newline=True,
        trim_blocks=True,
        lstrip_blocks=True,
        autoescape=False,
    )
    env.filters.update(COMMON_FILTERS)
    env.filters.update(getattr(module, "FILTERS", {}))
    env.globals.update(getattr(module, "GLOBALS", {}))
    return env


def _tidy(text: str) -> str:
    """Strip trailing white space on each line and end with exactly one newline."""
    lines = [line.rstrip() for line in text.splitlines()]
    while lines and not lines[-1]:
        lines.pop()
    return "\n".join(lines) + "\n"


def render(spec: Spec, targets: list[str] | None = None) -> dict[str, str]:
    """Every generated file, as {path relative to generated/: content}."""
    files: dict[str, str] = {}
    for target in targets if targets is not None else target_names():
        module = importlib.import_module(f"generator.targets.{target}.target")
        env = _environment(target, module)
        for out in module.outputs(spec):
            template = env.get_template(out.template)
            text = template.render(spec=spec, notice=notice(spec), **out.context)
            if out.path in files:
                raise ValueError(f"two outputs write {out.path}")
            files[out.path] = _tidy(text) if not out.path.endswith((".svg", ".png")) else text
    return files
