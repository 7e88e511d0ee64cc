"""Run the fuzz targets: the short coverage check of `make test`, and `make fuzz` to a plateau.

    python fuzz/run.py check TARGET... [--runs N] [--corpus DIR]
    python fuzz/run.py fuzz TARGET... [--plateau N] [--plateau-python N] [--cap S] [--jobs J]

`check` runs each C fuzzer for N runs (seed 1) from its seeds (fuzz/seeds.py, under build/fuzz/seeds/)
and any --corpus directories, with libFuzzer's -print_coverage=1, and fails naming every function its
source lists on a `fuzz-must-reach:` line that the run did not reach (the build and round-trip
functions); a crash fails too.

`fuzz` runs each target in rounds of N/4 executions, each starting from its committed corpus
(fuzz/corpus/TARGET/), its seeds and what earlier rounds found (build/fuzz/TARGET/corpus/), until
the rounds since the last one that covered a new edge add up to N executions: N executions in a row
without new coverage. That is the plateau (libFuzzer's `cov`, the edges of the code reached; its `ft`,
features, also counts how often each edge ran and keeps creeping up long after, so it is reported,
not waited for). A target that has not reached the plateau after --cap seconds is stopped and
reported as CAPPED. Then the corpus is minimised (libFuzzer -merge=1) back into fuzz/corpus/TARGET/,
and one line per target is printed: executions, edges and features covered, corpus size, crashes,
how the run ended. A crash stops that target (its input is kept under build/fuzz/TARGET/crashes/)
and the exit status is 1. J targets (default 2) are fuzzed at once, each in one process.
"""

from __future__ import annotations

import argparse
import os
import re
import shutil
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
BUILD = ROOT / "build" / "fuzz"
PYTHON = ROOT / ".venv" / "bin" / "python"
ROUNDS = 4  # a plateau is checked in rounds of a quarter of it
RUST_BIN = ROOT / "build" / "rust" / "target" / "fuzz" / "x86_64-unknown-linux-gnu" / "release"


@dataclass(frozen=True)
class Target:
    language: str
    shape: str  # the seeds and dictionary it takes (fuzz/seeds.py)
    program: str  # C: the fuzzer's name; Rust: the cargo-fuzz target; Python: the atheris target
    max_len: int

    def command(self, name: str) -> list[str]:
        if self.language == "c":
            return [str(ROOT / "build" / "c" / "fuzz" / self.program)]
        if self.language == "rust":
            return [str(RUST_BIN / self.program)]
        return [str(wrapper(name, self.program))]

    def must_reach(self) -> list[str]:
        if self.language != "c":
            return []
        source = (ROOT / "fuzz" / "c" / f"{self.program}.c").read_text()
        return [name for line in re.findall(r"fuzz-must-reach:(.*)", source) for name in line.split()]


TARGETS = {
    "c-fuzz_parsers": Target("c", "selector", "fuzz_parsers", 256),
    "c-fuzz_stream": Target("c", "stream", "fuzz_stream", 512),
    "rust-payloads": Target("rust", "selector", "payloads", 256),
    "rust-stream": Target("rust", "cut-stream", "stream", 512),
    "python-stream": Target("python", "cut-stream", "stream", 512),
    "python-payloads": Target("python", "selector", "payloads", 256),
    "python-sentences": Target("python", "sentence", "sentences", 256),
    "python-device": Target("python", "device", "device", 256),
    "python-host": Target("python", "host", "host", 512),
}


def wrapper(name: str, program: str) -> Path:
    """A program that runs one atheris target: libFuzzer starts its own command again to merge."""
    path = BUILD / "bin" / name
    path.parent.mkdir(parents=True, exist_ok=True)
    targets = ROOT / "fuzz" / "python" / "targets.py"
    script = f'#!/bin/sh\nFUZZ_SELF="{path}" PYTHONPATH="{BUILD / "python"}"\nexport FUZZ_SELF PYTHONPATH\n'
    script += f'exec "{PYTHON}" "{targets}" {program} "$@"\n'
    if not path.exists() or path.read_text() != script:
        path.write_text(script)
        path.chmod(0o755)
    return path


def symbolizer_env() -> dict[str, str]:
    """libFuzzer names functions through llvm-symbolizer; clang's own when none is on PATH."""
    env = dict(os.environ)
    if shutil.which("llvm-symbolizer") is None:
        found = sorted(Path("/usr/lib").glob("llvm-*/bin/llvm-symbolizer"))
        if found:
            env["ASAN_SYMBOLIZER_PATH"] = str(found[-1])
    return env


def options(target: Target) -> list[str]:
    return [
        f"-max_len={target.max_len}",
        f"-dict={BUILD / 'dict' / f'{target.shape}.dict'}",
        "-timeout=60",
        "-rss_limit_mb=2048",
        "-print_final_stats=1",
    ]


def check(names: list[str], runs: int, corpora: list[str]) -> int:
    failed = 0
    for name in names:
        target = TARGETS[name]
        work = BUILD / name / "check"
        shutil.rmtree(work, ignore_errors=True)
        work.mkdir(parents=True)
        seeds = BUILD / "seeds" / target.shape
        command = [
            *target.command(name),
            *options(target),
            "-seed=1",
            f"-runs={runs}",
            "-print_coverage=1",
            f"-artifact_prefix={work}/",
            str(work),
            str(seeds),
            *corpora,
        ]
        result = subprocess.run(command, capture_output=True, text=True, env=symbolizer_env(), check=False)
        log = work.parent / "check.log"
        log.write_text(result.stderr)
        covered = set(re.findall(r"^COVERED_FUNC: .* (\S+) \S+:\d+$", result.stderr, re.MULTILINE))
        missing = [f for f in target.must_reach() if f not in covered]
        if result.returncode != 0:
            print(result.stderr[-4000:])
            print(f"{name}: the fuzzer failed (exit {result.returncode}) in {runs} runs; log {log}")
            failed += 1
        elif not covered:
            print(f"{name}: libFuzzer printed no coverage by function (is llvm-symbolizer installed?); log {log}")
            failed += 1
        elif missing:
            print(
                f"{name}: {runs} runs from {seeds.relative_to(ROOT)} did not reach {', '.join(missing)}: "
                f"the seeds or the dictionary no longer make inputs that get there (log {log})"
            )
            failed += 1
        else:
            print(f"{name}: {runs} runs, seed 1: no crash; reached {', '.join(target.must_reach())}")
    return 1 if failed else 0


@dataclass
class Round:
    executions: int
    edges: int
    features: int
    corpus: int
    crashed: bool


def one_round(name: str, target: Target, number: int, runs: int, seconds: int) -> Round:
    work = BUILD / name
    committed = ROOT / "fuzz" / "corpus" / name
    committed.mkdir(parents=True, exist_ok=True)
    (work / "crashes").mkdir(parents=True, exist_ok=True)
    command = [
        *target.command(name),
        *options(target),
        f"-seed={number}",
        f"-runs={runs}",
        f"-max_total_time={seconds}",
        f"-artifact_prefix={work / 'crashes'}/",
        str(work / "corpus"),
        str(committed),
        str(BUILD / "seeds" / target.shape),
    ]
    log = work / f"round-{number}.log"
    with log.open("w") as out:
        result = subprocess.run(command, stdout=out, stderr=subprocess.STDOUT, env=symbolizer_env(), check=False)
    text = log.read_text(errors="replace")
    stats = dict(re.findall(r"^stat::(\w+): +(\d+)$", text, re.MULTILINE))
    last = re.findall(r"cov: (\d+) ft: (\d+) corp: (\d+)/", text)
    edges, features, corpus = map(int, last[-1]) if last else (0, 0, 0)
    executions = int(stats.get("number_of_executed_units", 0))
    return Round(executions, edges, features, corpus, result.returncode != 0)


def minimise(name: str, target: Target) -> int:
    """Merge what this run found into fuzz/corpus/NAME/, keeping only inputs that add coverage."""
    work = BUILD / name
    committed = ROOT / "fuzz" / "corpus" / name
    merged = work / "merged"
    shutil.rmtree(merged, ignore_errors=True)
    merged.mkdir()
    command = [
        *target.command(name),
        *options(target),
        "-merge=1",
        f"-artifact_prefix={work / 'crashes'}/",
        str(merged),
        str(committed),
        str(work / "corpus"),
        str(BUILD / "seeds" / target.shape),
    ]
    with (work / "merge.log").open("w") as out:
        subprocess.run(command, stdout=out, stderr=subprocess.STDOUT, env=symbolizer_env(), check=True)
    shutil.rmtree(committed)
    shutil.copytree(merged, committed)
    return len(list(committed.iterdir()))


def fuzz(name: str, plateau: int, cap: int) -> list[str]:
    """Fuzz one target to its plateau: its closing lines (the first is the summary)."""
    target = TARGETS[name]
    shutil.rmtree(BUILD / name, ignore_errors=True)
    (BUILD / name / "corpus").mkdir(parents=True)
    start, executions, number, ending = time.monotonic(), 0, 0, "CAPPED"
    result, best, quiet = Round(0, 0, 0, 0, crashed=False), 0, 0
    while (left := cap - int(time.monotonic() - start)) > 0:
        number += 1
        result = one_round(name, target, number, -(-plateau // ROUNDS), left)
        executions += result.executions
        if result.crashed:
            ending = "CRASH"
            break
        # executions since the round that last covered a new edge (at most a round's worth more)
        quiet = 0 if result.edges > best else quiet + result.executions
        best = max(best, result.edges)
        if quiet >= plateau:
            ending = "plateau"
            break
    crashes = sorted(str(p.relative_to(ROOT)) for p in (BUILD / name / "crashes").iterdir())
    size = minimise(name, target) if not crashes else len(list((ROOT / "fuzz" / "corpus" / name).iterdir()))
    elapsed = time.monotonic() - start
    lines = [
        f"{name}: {executions} executions, cov {best} edges, ft {result.features} features, "
        f"corpus {size} inputs, {len(crashes)} crashes; {ending} ({quiet} executions without a new edge) "
        f"after {elapsed:.0f} s"
    ]
    lines += [f"  crash input kept: {c} (log build/fuzz/{name}/round-{number}.log)" for c in crashes]
    print("\n".join(lines), flush=True)
    return lines


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("mode", choices=("check", "fuzz"))
    parser.add_argument("targets", nargs="*", default=list(TARGETS))
    parser.add_argument("--runs", type=int, default=150000)
    parser.add_argument("--corpus", action="append", default=[])
    parser.add_argument("--plateau", type=int, default=1_000_000)
    parser.add_argument("--plateau-python", type=int, default=50_000)
    parser.add_argument("--cap", type=int, default=480)
    parser.add_argument("--jobs", type=int, default=2, help="targets fuzzed at once")
    args = parser.parse_intermixed_args()
    unknown = [t for t in args.targets if t not in TARGETS]
    if unknown:
        parser.error(f"unknown targets {unknown}; known: {', '.join(TARGETS)}")
    if args.mode == "check":
        return check(args.targets, args.runs, args.corpus)
    with ThreadPoolExecutor(max_workers=args.jobs) as pool:
        runs = [
            pool.submit(
                fuzz, name, args.plateau_python if TARGETS[name].language == "python" else args.plateau, args.cap
            )
            for name in args.targets
        ]
        lines = [line for run in runs for line in run.result()]
    crashed = sum(1 for line in lines if line.startswith("  crash"))
    print(
        f"\nfuzz: {len(args.targets)} targets, {crashed} crashes; a plateau is {args.plateau} executions "
        f"({args.plateau_python} for Python) without a new edge, at most {args.cap} s a target:"
    )
    print("\n".join(lines))
    return 1 if crashed else 0


if __name__ == "__main__":
    sys.exit(main())
