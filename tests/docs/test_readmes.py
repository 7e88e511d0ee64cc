"""The READMEs run: every shell and Python code block of the hand-written and generated READMEs
is executed, in order, against the virtual AHRS (`ilahrs simulate`), so a documented command
cannot drift from the code.

- A ```sh / ```shell / ```bash / ```console block runs with `bash -e` (console: the `$ ` lines);
  a ```python block runs with this checkout's .venv python. Both run in a scratch directory that
  mirrors the repository root (symlinks; `conformance/harness.py` is copied so that the commands
  it starts run there), or in a copy of the README's own folder where its blocks are written for
  it (generated/c). `.venv/bin` is first on PATH, so `ilahrs`, `python` and `python3` are the
  checkout's; `cmake --install` goes under DESTDIR in the scratch directory.
- A block that starts `ilahrs simulate ... &` uses that simulator: the line's output goes to a
  file, the port it prints is read back and put where the block names a port (`/dev/pts/3`,
  `/dev/ttyUSB0`, ...). A block that names a port without starting a simulator gets one started
  by the test. Whatever a block leaves running is stopped with it (its own process group).
- A block is not run only when the README says so on the line before its fence,
  `<!-- not run: why -->`; `<!-- file: NAME -->` writes the block to NAME in the scratch
  directory for the blocks after it (a runner a later block starts). Every skip is listed in
  SKIPPED below with the README and the first line of the block; a new one fails the test until
  it is added there.
"""

from __future__ import annotations

import contextlib
import os
import re
import select
import shutil
import signal
import subprocess
import sys
import time
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path

import pytest
from kaitai_support import kaitai_module

pytest.importorskip("serial")
pytestmark = pytest.mark.skipif(sys.platform == "win32", reason="ptys and bash are POSIX")

ROOT = Path(__file__).resolve().parents[2]
VENV_BIN = ROOT / ".venv" / "bin"
PYTHON = VENV_BIN / "python"

# README -> the folder its shell blocks run from ("." = the repository root).
READMES = {
    "README.md": ".",
    "generated/python/README.md": ".",
    "generated/c/README.md": "generated/c",
    "generated/rust/README.md": ".",
    "generated/kaitai/README.md": ".",
    "conformance/README.md": ".",
    "fuzz/README.md": ".",
}

# Every block a README marks `<!-- not run: ... -->`: (README, first command of the block).
SKIPPED = [
    ("README.md", "make"),
    ("README.md", ".venv/bin/ilahrs monitor /dev/pts/3"),
    ("generated/python/README.md", 'pip install "./generated/python[serial]"'),
    ("generated/python/README.md", "screen /dev/pts/3 115200"),
    ("generated/python/README.md", "import pandas, ilahrs"),
    ("generated/python/README.md", "ilahrs decode logs/ --to parquet flights --jobs 4"),
    ("generated/python/README.md", "from pathlib import Path"),
    ("generated/python/README.md", 'pip install "./generated/python[serial]"'),
    ("conformance/README.md", "make conformance"),
    ("fuzz/README.md", "make fuzz"),
]

# Fragments that take their input from the reader: what runs before them, (README, first line).
KAITAI_PRELUDE = """\
import sys

import ilahrs as binding  # the Python binding makes the input; the compiler's module has its name

device = binding.Device(seed=1)
received = device.receive(binding.build_command("AHRScont1")) + device.advance(30.02)
data = [e.frame for e in binding.StreamDecoder().feed(received) if e.frame][-1].build()  # Full Output
device.receive(binding.build_command("Stop"))
received = device.receive(binding.build_command("AHRScont3")) + device.advance(30.02)
payload = [e.frame for e in binding.StreamDecoder().feed(received) if e.frame][-1].payload
del sys.modules["ilahrs"]
sys.path.insert(0, "build/kaitai/python")  # `make build-kaitai`
"""
PRELUDES = {("generated/kaitai/README.md", "from io import BytesIO"): KAITAI_PRELUDE}

BLOCK_TIMEOUT = 150.0
STARTUP_TIMEOUT = 20.0

FENCE = re.compile(r"^(?P<indent> *)```(?P<lang>[A-Za-z]*)\s*$")
MARKER = re.compile(r"^\s*<!--\s*(?P<what>not run|file):\s*(?P<text>.*?)\s*-->\s*$")
PORT = re.compile(r"/dev/pts/\d+|/dev/tty(?:USB|ACM|S)\d+|socket://127\.0\.0\.1:\d+")
BACKGROUND_SIMULATOR = re.compile(r"^(?P<command>\S*ilahrs simulate\b[^&#]*?)\s*&(?P<rest>\s*(?:#.*)?)$")
SHELL = {"sh", "shell", "bash", "console"}
# Run from the mirror, these write through its symlinks into the checkout (or into .venv): a block
# with one must be marked not run.
REPOSITORY_WRITERS = re.compile(r"^\s*(?:\S*/)?(?:make|pip3?)\b")


@dataclass(frozen=True)
class Block:
    readme: str
    line: int  # of the opening fence, 1-based
    lang: str  # "shell" or "python"
    text: str
    skip: str | None  # the reason a README gives for not running it
    file: str | None  # write the block to this file instead of running it

    @property
    def first_line(self) -> str:
        return next((line for line in self.text.splitlines() if line.strip()), "")

    @property
    def first_command(self) -> str:
        """The first line without its comment."""
        return re.split(r"\s+#", self.first_line, maxsplit=1)[0].strip()

    def __str__(self) -> str:
        return f"{self.readme}:{self.line} ({self.lang})"


def blocks(readme: str) -> list[Block]:
    lines = (ROOT / readme).read_text().splitlines()
    found: list[Block] = []
    i = 0
    while i < len(lines):
        opening = FENCE.match(lines[i])
        if not opening or not opening["lang"]:
            i += 1
            continue
        indent, lang = opening["indent"], opening["lang"].lower()
        end = next(j for j in range(i + 1, len(lines)) if lines[j].strip() == "```")
        body = [line[len(indent) :] if line.startswith(indent) else line for line in lines[i + 1 : end]]
        previous = next((lines[j] for j in range(i - 1, -1, -1) if lines[j].strip()), "")
        marker = MARKER.match(previous)
        if lang in SHELL or lang == "python":
            if lang == "console":
                body = [line[2:] for line in body if line.startswith("$ ")]
            found.append(
                Block(
                    readme,
                    i + 1,
                    "python" if lang == "python" else "shell",
                    "\n".join(body) + "\n",
                    marker["text"] if marker and marker["what"] == "not run" else None,
                    marker["text"] if marker and marker["what"] == "file" else None,
                )
            )
        i = end + 1
    return found


def all_blocks() -> list[Block]:
    return [block for readme in READMES for block in blocks(readme)]


@contextmanager
def simulator(log: Path) -> Iterator[str]:
    """`ilahrs simulate` on a pty; yields its port."""
    command = [str(PYTHON), "-m", "ilahrs", "simulate", "--alignment-time", "2", "--log", str(log)]
    process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        assert process.stdout is not None
        ready, _, _ = select.select([process.stdout], [], [], STARTUP_TIMEOUT)
        assert ready, "the simulator printed nothing"
        port = process.stdout.readline().strip()
        assert port, process.stderr.read() if process.stderr else ""
        yield port
    finally:
        if process.poll() is None:
            process.send_signal(signal.SIGTERM)
            try:
                process.wait(10)
            except subprocess.TimeoutExpired:
                process.kill()
                process.wait(10)
        for stream in (process.stdout, process.stderr):
            if stream is not None:
                stream.close()


def mirror(scratch: Path) -> Path:
    """A directory that looks like the repository root: a symlink per top-level entry, except
    `conformance/`, whose harness.py is copied (it runs commands from the folder it sits in)."""
    where = scratch / "repo"
    where.mkdir()
    for entry in ROOT.iterdir():
        if entry.name in {".git", "conformance"}:
            continue
        (where / entry.name).symlink_to(entry)
    (where / "conformance").mkdir()
    for entry in (ROOT / "conformance").iterdir():
        if entry.name == "harness.py":
            shutil.copy(entry, where / "conformance" / entry.name)
        else:
            (where / "conformance" / entry.name).symlink_to(entry)
    return where


PRELUDE = """\
_ilahrs_port() {  # the first line the simulator started in the background printed
    for _ in $(seq 200); do
        if [ -s "$1" ] && [ "$(wc -l < "$1")" -ge 1 ]; then head -n 1 "$1"; return 0; fi
        sleep 0.1
    done
    echo "the simulator printed no port" >&2; return 1
}
"""


def shell_script(block: Block, port: str | None) -> str:
    """The block as it runs: each `ilahrs simulate ... &` writes its port to a file that is read
    back; a port the block names is the simulator's."""
    lines: list[str] = [PRELUDE]
    started = 0
    for line in block.text.splitlines():
        background = BACKGROUND_SIMULATOR.match(line)
        if background:
            started += 1
            out = f"simulator-{started}.out"
            lines.append(f"{background['command']} > {out} &{background['rest']}")
            lines.append(f"ILAHRS_PORT=$(_ilahrs_port {out})")
            continue
        if started:
            lines.append(PORT.sub("${ILAHRS_PORT}", line))
        else:
            lines.append(PORT.sub(port, line) if port is not None else line)
    return "\n".join(lines) + "\n"


def run(command: list[str], cwd: Path, env: dict[str, str]) -> subprocess.CompletedProcess[str]:
    process = subprocess.Popen(
        command, cwd=cwd, env=env, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
        text=True, start_new_session=True,
    )  # fmt: skip
    try:
        out, err = process.communicate(timeout=BLOCK_TIMEOUT)
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, signal.SIGKILL)
        out, err = process.communicate()
        err += f"\n(killed after {BLOCK_TIMEOUT} s)"
    finally:
        with contextlib.suppress(ProcessLookupError):  # whatever the block left running in the background
            os.killpg(process.pid, signal.SIGTERM)
    return subprocess.CompletedProcess(command, process.returncode, out, err)


def run_readme(readme: str, scratch: Path) -> list[Block]:
    """Runs the README's blocks in order; returns the ones it marks not run."""
    home = mirror(scratch)
    folder = READMES[readme]
    cwd = home
    if folder != ".":
        cwd = scratch / Path(folder).name
        shutil.copytree(ROOT / folder, cwd)
    env = os.environ | {
        "PATH": f"{VENV_BIN}{os.pathsep}{os.environ.get('PATH', '')}",
        "VIRTUAL_ENV": str(ROOT / ".venv"),
        "DESTDIR": str(scratch / "destdir"),
        "PYTHONDONTWRITEBYTECODE": "1",
    }
    env.pop("PYTHONPATH", None)
    if readme == "generated/kaitai/README.md":
        kaitai_module()  # the compiled parser is there and fresh
    skipped = []
    for number, block in enumerate(blocks(readme)):
        if block.skip is not None:
            skipped.append(block)
            continue
        if block.file is not None:
            (cwd / block.file).write_text(block.text)
            continue
        if block.lang == "shell":
            writes = [line for line in block.text.splitlines() if REPOSITORY_WRITERS.match(line)]
            assert not writes, f"{block} would change the checkout or .venv; mark it not run: {writes}"
        needs_port = PORT.search(block.text) is not None
        starts_own = block.lang == "shell" and any(BACKGROUND_SIMULATOR.match(line) for line in block.text.splitlines())
        started = time.monotonic()
        with contextmanager_or_none(needs_port and not starts_own, scratch / f"simulator-{number}.jsonl") as port:
            if block.lang == "python":
                text = PRELUDES.get((readme, block.first_line), "") + block.text
                text = PORT.sub(port, text) if port else text
                script = scratch / f"block-{number}.py"
                script.write_text(text)
                result = run([str(PYTHON), str(script)], cwd, env)
            else:
                script = scratch / f"block-{number}.sh"
                script.write_text(shell_script(block, port))
                result = run(["bash", "-e", str(script)], cwd, env)
        print(f"ran: {block} in {time.monotonic() - started:.1f} s")
        assert result.returncode == 0, (
            f"{block} exited with status {result.returncode}\n--- block as run ---\n{script.read_text()}"
            f"--- stdout ---\n{result.stdout[-3000:]}\n--- stderr ---\n{result.stderr[-3000:]}"
        )
    return skipped


@contextmanager
def contextmanager_or_none(wanted: bool, log: Path) -> Iterator[str | None]:
    if not wanted:
        yield None
        return
    with simulator(log) as port:
        yield port


@pytest.mark.parametrize("readme", list(READMES))
def test_readme_blocks_run(readme: str, tmp_path: Path) -> None:
    skipped = run_readme(readme, tmp_path)
    for block in skipped:
        print(f"not run: {block}: {block.skip}")


def test_the_blocks_not_run_are_the_listed_ones() -> None:
    found = all_blocks()
    skipped = [block for block in found if block.skip is not None]
    print(f"{len(found)} blocks, {len(skipped)} not run:")
    for block in skipped:
        print(f"  {block} {block.first_line!r}: {block.skip}")
    assert all(block.skip for block in skipped), "a `not run` marker without a reason"
    listed = sorted((block.readme, block.first_command) for block in skipped)
    assert listed == sorted(SKIPPED), "a block not run is missing from SKIPPED, or SKIPPED names one that runs"
    assert len(found) - len(skipped) > len(skipped), "most blocks run"


# --- installing: the package is on no index ----------------------------------------------------

INDEX_INSTALL = re.compile(r"""pip install +["']?ilahrs\b|["'`]ilahrs\[""")


def test_no_text_installs_ilahrs_from_an_index() -> None:
    """The package is on no index: READMEs and messages install it from the checkout or a wheel."""
    texts = [ROOT / readme for readme in READMES]
    texts += sorted(p for p in (ROOT / "generator" / "targets" / "python" / "runtime").rglob("*") if p.is_file())
    texts += [ROOT / "generator" / "targets" / "python" / "templates" / "README.md.j2"]
    found = [
        f"{path.relative_to(ROOT)}:{number}: {line.strip()}"
        for path in texts
        for number, line in enumerate(path.read_text().splitlines(), 1)
        if INDEX_INSTALL.search(line)
    ]
    assert not found, "\n".join(found)


def extra(name: str) -> str:
    """The one requirement of the package's optional dependency `name` (generated/python/pyproject.toml)."""
    import tomllib

    project = tomllib.loads((ROOT / "generated" / "python" / "pyproject.toml").read_text())["project"]
    (requirement,) = project["optional-dependencies"][name]
    return str(requirement)


@pytest.mark.parametrize(
    ("module", "args", "extra_name"),
    [
        ("serial", ["send", "/dev/ttyUSB0", "Stop"], "serial"),
        ("matplotlib", ["plot", "CAPTURE", "-o", "x.png"], "plot"),
        ("pyarrow", ["decode", "CAPTURE", "--to", "parquet", "out"], "parquet"),
        ("rosbags", ["decode", "CAPTURE", "--to", "rosbag2", "bag"], "ros"),
    ],
)
def test_a_missing_optional_dependency_names_a_command_that_installs_it(
    module: str, args: list[str], extra_name: str, tmp_path: Path
) -> None:
    """Without pyserial (matplotlib), the one line the command prints says `pip install REQUIREMENT`
    with the requirement of the package's extra, which pip finds on PyPI (ilahrs[...] it would not)."""
    missing = tmp_path / "missing"
    (missing / module).mkdir(parents=True)
    (missing / module / "__init__.py").write_text("raise ImportError('not installed')\n")
    capture = tmp_path / "s.bin"
    capture.write_bytes(b"")
    args = [str(capture) if arg == "CAPTURE" else arg for arg in args]
    env = os.environ | {"PYTHONPATH": str(missing)}
    result = subprocess.run(
        [str(PYTHON), "-m", "ilahrs", *args],
        cwd=tmp_path,
        env=env,
        capture_output=True,
        text=True,
        timeout=60,
        check=False,
    )
    assert result.returncode == 2, result.stderr
    assert len(result.stderr.splitlines()) == 1, result.stderr
    assert result.stderr.rstrip().endswith(f"pip install '{extra(extra_name)}'"), result.stderr


# --- the licence ----------------------------------------------------------------------------------

LICENCE = "MIT OR Apache-2.0"


def test_every_binding_carries_the_same_licence() -> None:
    """The repository, the Python package, the C library and the Rust crate say MIT OR Apache-2.0,
    with both texts next to them (the crate's `cargo package` and the wheel take them from there)."""
    import tomllib

    texts = {name: (ROOT / name).read_text() for name in ("LICENSE-MIT", "LICENSE-APACHE")}
    assert "Copyright (c) the ilahrs developers" in texts["LICENSE-MIT"]
    assert "Apache License\n                           Version 2.0, January 2004" in texts["LICENSE-APACHE"]
    assert "END OF TERMS AND CONDITIONS" in texts["LICENSE-APACHE"]
    for folder in ("python", "c", "rust"):
        for name, text in texts.items():
            assert (ROOT / "generated" / folder / name).read_text() == text, f"generated/{folder}/{name}"
    crate = tomllib.loads((ROOT / "generated" / "rust" / "Cargo.toml").read_text())["package"]
    assert crate["license"] == LICENCE
    package = tomllib.loads((ROOT / "generated" / "python" / "pyproject.toml").read_text())["project"]
    assert package["license"] == {"text": LICENCE}
    assert "install(FILES LICENSE-MIT LICENSE-APACHE" in (ROOT / "generated" / "c" / "CMakeLists.txt").read_text()
    for readme in ("README.md", "generated/python/README.md", "generated/c/README.md", "generated/rust/README.md"):
        text = (ROOT / readme).read_text()
        assert "LICENSE-MIT" in text and "LICENSE-APACHE" in text, readme
