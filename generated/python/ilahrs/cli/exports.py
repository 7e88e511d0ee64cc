# Copied from generator/targets/python/runtime/cli/exports.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""Where `ilahrs decode` writes: standard output, a file, or a dataset that a format's own library
writes (`--to FORMAT [PATH]`).

The formats that write files of their own (a ROS 2 bag, a Parquet dataset) are modules of this
package named `to_<something>.py`, each with `EXPORTS`, a dict of format name -> `Export`, and
optionally `add_options(parser)` for options of their own; they are found in the folder, so a new
format is a new module. An export's library comes with an optional extra of the package (the
`ros` extra: `pip install "./generated/python[ros]"` from a checkout, or the wheel's), imported
only when the format is used.

Output is never left half-written: a file is written beside its path and renamed onto it at the
end (an existing file is replaced whole, or left as it was when the decoding fails); a directory
is written beside its path and renamed into place, and an existing directory is replaced only with
`--force` (never a directory that is not empty otherwise)."""

from __future__ import annotations

import argparse
import importlib
import os
import pkgutil
import shutil
import sys
import tempfile
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from types import ModuleType
from typing import Literal, TextIO

from .common import CliError

__all__ = ["Export", "export_modules", "exports", "replacing", "text_output"]


@dataclass(frozen=True)
class Export:
    """A `--to` format whose output is a file or a directory of its own."""

    target: Literal["file", "directory"]
    """What PATH names."""
    extra: str
    """The optional extra of the package that brings the library it needs."""
    help: str
    """One line for `--help`."""
    write: Callable[[argparse.Namespace, str], int]
    """Decode `args.files` into the (temporary) path given; the exit status."""
    many: bool = False
    """Several captures (or directories of captures) in one output."""


def export_modules() -> list[ModuleType]:
    """The `to_*` modules of this package, in name order."""
    package = importlib.import_module(__package__ or "ilahrs.cli")
    names = sorted(info.name for info in pkgutil.iter_modules(package.__path__) if info.name.startswith("to_"))
    return [importlib.import_module(f"{package.__name__}.{name}") for name in names]


def exports() -> dict[str, Export]:
    """Format name -> Export, from every `to_*` module."""
    found: dict[str, Export] = {}
    for module in export_modules():
        found.update(getattr(module, "EXPORTS", {}))
    return found


@contextmanager
def replacing(path: str, *, directory: bool, force: bool = False) -> Iterator[str]:
    """A temporary path beside `path` to write to, renamed onto `path` when the block ends without
    an exception (removed otherwise). CliError, before anything is written, for a directory `path`
    that exists (unless `force`; then it is replaced once the new one is complete), a file `path`
    that is a directory, or a folder that cannot be written."""
    target = os.path.abspath(path)
    folder = os.path.dirname(target) or "."
    name = os.path.basename(target)
    if directory:
        if os.path.exists(target) and not os.path.isdir(target):
            raise CliError(f"{path}: exists and is not a directory")
        if os.path.isdir(target) and os.listdir(target) and not force:
            raise CliError(f"{path}: exists and is not empty (--force replaces it)")
    elif os.path.isdir(target):
        raise CliError(f"{path}: is a directory")
    if not os.path.isdir(folder):
        raise CliError(f"{path}: no such directory {folder}")
    try:
        temporary = tempfile.mkdtemp(prefix=f".{name}.", suffix=".part", dir=folder)
    except OSError as exc:
        raise CliError(f"{path}: cannot write there: {exc.strerror or exc}") from exc
    inner = os.path.join(temporary, name)
    try:
        yield inner
        if not os.path.exists(inner):
            raise CliError(f"{path}: nothing was written")
        old = None
        if directory and os.path.isdir(target):
            old = os.path.join(temporary, ".replaced")
            os.replace(target, old)
        if not directory:
            mask = os.umask(0)
            os.umask(mask)
            os.chmod(inner, 0o666 & ~mask)
        os.replace(inner, target)
    except OSError as exc:
        raise CliError(f"{path}: {exc.strerror or exc}") from exc
    finally:
        shutil.rmtree(temporary, ignore_errors=True)


@contextmanager
def text_output(path: str | None) -> Iterator[TextIO]:
    """Standard output (`path` None or "-"), or a file written beside `path` and renamed onto it."""
    if path is None or path == "-":
        yield sys.stdout
        return
    with replacing(path, directory=False) as temporary:
        try:
            stream = open(temporary, "w", encoding="utf-8", newline="")  # noqa: SIM115 - closed below
        except OSError as exc:
            raise CliError(f"{path}: {exc.strerror or exc}") from exc
        with stream:
            yield stream
