# Copied from generator/targets/python/runtime/cli/to_parquet.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""`ilahrs decode CAPTURE... --to parquet DIR`: captures, and folders of captures, as one Parquet
dataset (`ilahrs.cli.dataset`: a file per capture per message kind, DIR/kind=<kind>/...), decoded
in `--jobs` processes at once.

A FILE argument must be a capture (pcapng or raw dump: the run is refused otherwise); a folder is searched
recursively (in name order; names beginning with '.' are left out) and each file in it that is a
capture by its content (a pcapng Section Header Block, or a frame or a $PAHR sentence in its first
64 KiB, as `ilahrs decode` tells them) is decoded; each other file is skipped with one line on
stderr. A capture given twice (or reached twice) is decoded once.

With more than one job, the captures go to a pool of processes (concurrent.futures, processes
started by a fork server where there is one, so no thread of this process is copied), each
writing its own files; a line per capture done goes to stderr when it is a terminal, and a
summary at the end. Ctrl-C (or SIGTERM) stops the workers and leaves nothing at DIR. A capture
that cannot be read or is cut short is one line on stderr and exit status 2, its rows before the
damage kept in the dataset, which is written all the same."""

from __future__ import annotations

import argparse
import multiprocessing
import os
import signal
import sys
from collections import Counter
from collections.abc import Callable, Iterator
from concurrent.futures import Future, ProcessPoolExecutor, as_completed
from concurrent.futures.process import BrokenProcessPool
from typing import TextIO

from ..edge.signals import sigterm_as_interrupt
from .capture import open_source
from .common import CliError
from .dataset import ARROW_MODULES, EXTRA, CaptureParts, DatasetOptions, arrow, write_capture
from .exports import Export

__all__ = ["EXPORTS", "add_options", "captures", "default_jobs", "write"]

PROG = "ilahrs decode"
_PRELOAD = f"{__package__}.dataset"


def default_jobs() -> int:
    """The processors this process may run on."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except AttributeError:  # not on every system
        return max(1, os.cpu_count() or 1)


def add_options(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--jobs",
        type=_positive,
        metavar="N",
        default=default_jobs(),
        help="captures decoded at once, in processes, for --to parquet (default: the processors, %(default)s here)",
    )


def _positive(text: str) -> int:
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number of jobs") from None
    if value < 1:
        raise argparse.ArgumentTypeError(f"{value} jobs: at least 1")
    return value


def _walk(folder: str, report: Callable[[str], None], output: str | None) -> Iterator[str]:
    """The files under `folder` that are captures, in name order (not under the folder `output`)."""
    skip = os.path.realpath(output) if output else None
    for top, folders, files in os.walk(folder, onerror=lambda exc: report(f"{exc.filename}: {exc.strerror}")):
        folders[:] = sorted(
            name for name in folders if not name.startswith(".") and os.path.realpath(os.path.join(top, name)) != skip
        )
        for name in sorted(files):
            if name.startswith("."):
                continue
            path = os.path.join(top, name)
            if not os.path.isfile(path):  # a pipe or a device would be read forever
                report(f"skipped {path}: not a regular file")
                continue
            try:
                open_source(path).close()
            except CliError as exc:
                report(f"skipped {exc}")
                continue
            yield path


def captures(paths: list[str], report: Callable[[str], None], output: str | None = None) -> list[str]:
    """The captures that FILE arguments name: files as they are, the captures found in folders
    (the dataset's folder `output` left out); each once. CliError for standard input, a missing
    path, a file named that is no capture, or no capture at all; `report` gets a line for each
    file skipped."""
    found: list[str] = []
    seen: set[str] = set()
    for path in paths:
        if path == "-":
            raise CliError("--to parquet reads capture files, not standard input")
        if not os.path.exists(path):
            raise CliError(f"{path}: no such file or directory")
        if not os.path.isdir(path):
            open_source(path).close()  # a file named is a capture, or the run is refused
        for capture in _walk(path, report, output) if os.path.isdir(path) else [path]:
            key = os.path.realpath(capture)
            if key not in seen:
                seen.add(key)
                found.append(capture)
    if not found:
        raise CliError(f"no captures in {', '.join(paths)}")
    return found


def _quiet() -> None:
    """A worker leaves Ctrl-C to the parent, which stops it."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)


def _run(found: list[str], out: str, options: DatasetOptions, jobs: int, done: Callable[[CaptureParts], None]) -> None:
    if jobs == 1:
        for capture in found:
            done(write_capture(capture, out, options))
        return
    methods = multiprocessing.get_all_start_methods()
    context = multiprocessing.get_context("forkserver" if "forkserver" in methods else "spawn")
    if context.get_start_method() == "forkserver":
        context.set_forkserver_preload([_PRELOAD, *ARROW_MODULES])  # imported once, in the server
    pool = ProcessPoolExecutor(max_workers=jobs, mp_context=context, initializer=_quiet)
    try:
        futures: list[Future[CaptureParts]] = [pool.submit(write_capture, c, out, options) for c in found]
        for future in as_completed(futures):
            done(future.result())
    except BrokenProcessPool as exc:
        _stop(pool)
        raise CliError(f"a worker process ended abruptly (killed, or out of memory?): {exc}") from exc
    except BaseException:
        _stop(pool)
        raise
    pool.shutdown()


def _stop(pool: ProcessPoolExecutor) -> None:
    """End the workers now (Ctrl-C, or a worker that failed): the files they write are thrown away."""
    workers = list(getattr(pool, "_processes", {}).values())  # the executor names no public way before 3.14
    pool.shutdown(wait=False, cancel_futures=True)
    for worker in workers:
        worker.terminate()
    for worker in workers:
        worker.join()


def write(args: argparse.Namespace, path: str, stream: TextIO | None = None) -> int:
    """`--to parquet DIR`: every capture of `args.files` into the dataset at `path`; progress,
    the summary and errors to `stream` (standard error)."""
    stream = stream or sys.stderr
    arrow()  # a missing extra is one line before any capture is read
    found = captures(args.files, lambda line: print(f"{PROG}: {line}", file=stream), getattr(args, "out", None))
    jobs = min(args.jobs, len(found))
    options = DatasetOptions(
        kinds=tuple(args.selected),
        variant=args.variant,
        raw=args.raw,
        output_format=args.output_format,
        strict=args.strict,
        threads=jobs == 1,
    )
    os.makedirs(path)
    results: list[CaptureParts] = []
    live = stream.isatty()

    def done(result: CaptureParts) -> None:
        results.append(result)
        if live:
            state = f"error: {result.error}" if result.error else f"{result.messages} messages"
            print(f"{PROG}: [{len(results)}/{len(found)}] {result.capture}: {state}", file=stream, flush=True)

    with sigterm_as_interrupt():  # the workers stopped, nothing left at DIR, as with Ctrl-C
        _run(found, path, options, jobs, done)
    rows: Counter[str] = Counter()
    for result in results:
        rows.update(result.rows)
    messages = sum(r.messages for r in results)
    damaged = sum(r.damaged for r in results)
    per_kind = ", ".join(f"{kind} {count}" for kind, count in rows.most_common())
    captured = f"{len(found)} capture{'' if len(found) == 1 else 's'}"
    print(f"{PROG}: {captured}, {messages} messages, {damaged} damaged rows ({per_kind})", file=stream)
    failed = [r for r in results if r.error]
    for result in failed:
        print(f"{PROG}: {result.error}", file=stream)
    return 2 if failed else 0


EXPORTS = {
    "parquet": Export(
        "directory",
        EXTRA,
        "a Parquet dataset, a folder per message kind, of one or many captures and folders of captures",
        write,
        many=True,
    )
}
