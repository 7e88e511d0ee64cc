"""Step 5 of the pipeline: turn the laid-out model into files, one target at a time.

A target is a folder under generator/targets/ with a `target.py` that lists its outputs and may
define FILTERS, GLOBALS and a `format(files)` hook, a `templates/` folder for what the spec decides
(tables, typed API, constants) and a `runtime/` folder of hand-written source files that are copied
into generated/ as they are, behind the notice line. Targets are discovered, so adding one touches
no shared file. Templates run under StrictUndefined; the model they read is immutable.
"""

from __future__ import annotations

import importlib
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Protocol

import jinja2

from .model import Spec
from .targets import naming

TARGETS_DIR = Path(__file__).resolve().parent / "targets"
ROOT = TARGETS_DIR.parent.parent

# The licence texts at the repository root, copied as they are into every folder a target names
# in LICENSED (a package or library that leaves the repository: the Python package, the crate, ...).
LICENCE_FILES = ("LICENSE-MIT", "LICENSE-APACHE")


@dataclass(frozen=True)
class Output:
    """One generated file: `path` relative to generated/, rendered from `template`."""

    path: str
    template: str
    context: dict[str, Any] = field(default_factory=dict)


@dataclass(frozen=True)
class Runtime:
    """One hand-written file: `source` relative to the target's runtime/ folder, copied to `path`.

    The copy starts with the notice lines in the file's comment syntax and is otherwise unchanged.
    """

    path: str
    source: str


# Line comment syntax per suffix, for the notice put in front of a copied runtime file.
COMMENT = {".py": "# ", ".rs": "// ", ".c": "// ", ".h": "// ", ".lua": "-- ", ".toml": "# ", ".cmake": "# "}


class TargetModule(Protocol):
    def outputs(self, spec: Spec) -> list[Output | Runtime]: ...


def target_names() -> list[str]:
    return sorted(p.name for p in TARGETS_DIR.iterdir() if (p / "target.py").is_file())


def derived_files(targets: list[str]) -> set[str]:
    """Files a target's make rules derive from its generated files (declared as DERIVED)."""
    found: set[str] = set()
    for target in targets:
        module = importlib.import_module(f"generator.targets.{target}.target")
        found.update(getattr(module, "DERIVED", ()))
    return found


def writers(spec: Spec) -> dict[str, set[str]]:
    """For each folder of generated/, the targets that write into it."""
    found: dict[str, set[str]] = {}
    for target in target_names():
        module = importlib.import_module(f"generator.targets.{target}.target")
        for out in module.outputs(spec):
            found.setdefault(out.path.split("/", 1)[0], set()).add(target)
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
        loader=jinja2.FileSystemLoader(str(TARGETS_DIR / target / "templates")),
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


def runtime_text(target: str, source: str) -> str:
    """The text of a hand-written runtime file of `target`."""
    return (TARGETS_DIR / target / "runtime" / source).read_text(encoding="utf-8")


def runtime_notice(spec: Spec, target: str, source: str) -> list[str]:
    """The notice lines of a copied runtime file."""
    return [
        f"Copied from generator/targets/{target}/runtime/{source} for {spec.file},",
        f"spec hash {spec.sha256}.",
        "Do not edit: change the runtime source and run `make generate`.",
    ]


def _copy_runtime(spec: Spec, target: str, out: Runtime) -> str:
    suffix = Path(out.path).suffix
    if suffix not in COMMENT:
        raise ValueError(f"no comment syntax for runtime file {out.path}")
    text = runtime_text(target, out.source)
    lines = [f"{COMMENT[suffix]}{line}" for line in runtime_notice(spec, target, out.source)]
    if text.startswith("#!"):
        first, _, rest = text.partition("\n")
        return "\n".join([first, *lines, rest])
    return "\n".join([*lines, text])


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
        env.globals["runtime_text"] = lambda source, _target=target: runtime_text(_target, source)
        mine: dict[str, str] = {}
        for out in module.outputs(spec):
            if isinstance(out, Runtime):
                text = _copy_runtime(spec, target, out)
            else:
                text = env.get_template(out.template).render(spec=spec, notice=notice(spec), **out.context)
            if out.path in files or out.path in mine:
                raise ValueError(f"two outputs write {out.path}")
            mine[out.path] = _tidy(text) if not out.path.endswith((".svg", ".png")) else text
        for folder in getattr(module, "LICENSED", ()):
            for name in LICENCE_FILES:
                mine[f"{folder}/{name}"] = (ROOT / name).read_text(encoding="utf-8")
        hook = getattr(module, "format", None)
        if hook is not None:
            mine = hook(mine)
        files.update(mine)
    return files
