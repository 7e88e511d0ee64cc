"""`ilahrs simulate` as a subprocess, as a user starts it (`python -m ilahrs simulate ...`), and the
`ilahrs` command run the same way. Shared by the tests of the serial client, the command line and the
conformance suite's live mode; the simulator is always stopped."""

from __future__ import annotations

import json
import select
import signal
import subprocess
import sys
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

ILAHRS = [sys.executable, "-m", "ilahrs"]
STARTUP_TIMEOUT = 20.0


def ilahrs(*args: str, timeout: float = 60.0) -> subprocess.CompletedProcess[str]:
    """`ilahrs ARGS...`, its output captured as text."""
    return subprocess.run([*ILAHRS, *args], capture_output=True, text=True, timeout=timeout, check=False)


class Simulator:
    def __init__(self, process: subprocess.Popen[str], first_line: str, log: Path) -> None:
        self.process = process
        self.first_line = first_line
        """What the simulator printed first: its pty's path, or `socket://HOST:PORT` with --tcp."""
        self.log = log

    @property
    def port(self) -> str:
        """The port a client opens (the first line)."""
        return self.first_line

    def entries(self) -> list[dict[str, object]]:
        """The simulator's log (--log): one JSON object per message it wrote."""
        return [json.loads(line) for line in self.log.read_text().splitlines()]

    def stop(self, sig: int = signal.SIGTERM) -> int:
        """Send `sig` (if still running) and return the exit status; killed after 10 s."""
        if self.process.poll() is None:
            self.process.send_signal(sig)
        try:
            return self.process.wait(10)
        except subprocess.TimeoutExpired:
            self.process.kill()
            return self.process.wait(10)


@contextmanager
def simulator(tmp_path: Path, *args: str) -> Iterator[Simulator]:
    """`ilahrs simulate --log tmp_path/simulator.jsonl ARGS...`, stopped on leaving."""
    log = tmp_path / "simulator.jsonl"
    command = [*ILAHRS, "simulate", "--log", str(log), *args]
    process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        assert process.stdout is not None
        ready, _, _ = select.select([process.stdout], [], [], STARTUP_TIMEOUT)
        assert ready, "the simulator printed nothing"
        first = process.stdout.readline().strip()
        assert first, process.stderr.read() if process.stderr else ""
        yield Simulator(process, first, log)
    finally:
        Simulator(process, "", log).stop()
        for stream in (process.stdout, process.stderr):
            if stream is not None:
                stream.close()
