"""Formatting generated files with each language's own formatter (ruff format, clang-format, rustfmt).

The render step hands a target's files to the target's `format(files)` hook, if it defines one; the
hook calls `run_formatter` with the command that formats files in place. The files are written to a
temporary folder with their relative paths (so a formatter that follows modules, like rustfmt, finds
them), formatted there and read back: the result depends only on the text and the pinned tool, never
on where the repository lives.
"""

from __future__ import annotations

import shutil
import subprocess
import sys
import tempfile
from collections.abc import Callable, Sequence
from pathlib import Path

VENV_BIN = Path(sys.executable).parent


class FormatterError(RuntimeError):
    """A formatter is missing or refused a generated file."""


def tool(name: str) -> str:
    """The path of a formatter: the one beside the running interpreter (the pinned venv), else PATH."""
    beside = VENV_BIN / name
    if beside.is_file():
        return str(beside)
    found = shutil.which(name)
    if found is None:
        raise FormatterError(f"{name} is not installed (run `make setup`)")
    return found


def run_formatter(
    files: dict[str, str],
    suffixes: tuple[str, ...],
    command: Callable[[list[Path]], Sequence[str]],
) -> dict[str, str]:
    """Format the files whose path ends with one of `suffixes`; `command(paths)` gives the argv."""
    chosen = sorted(path for path in files if path.endswith(suffixes))
    if not chosen:
        return files
    with tempfile.TemporaryDirectory(prefix="ilahrs-format-") as tmp:
        root = Path(tmp)
        for path, text in files.items():
            dest = root / path
            dest.parent.mkdir(parents=True, exist_ok=True)
            dest.write_text(text, encoding="utf-8", newline="\n")
        argv = list(command([root / path for path in chosen]))
        done = subprocess.run(argv, cwd=root, capture_output=True, text=True, check=False)
        if done.returncode != 0:
            detail = (done.stderr or done.stdout).strip().replace(str(root) + "/", "")
            raise FormatterError(f"{Path(argv[0]).name} failed on generated files:\n{detail}")
        out = dict(files)
        for path in chosen:
            out[path] = (root / path).read_text(encoding="utf-8")
        return out
