"""Running tshark with the generated dissector and reading what it shows.

tshark runs with HOME and the configuration folders in a temporary folder, so no personal
preference or plugin interferes; `-T json -x` output is read keeping repeated keys (a packet with
several messages has several `ilahrs` trees) and the raw bytes of every field.
"""

from __future__ import annotations

import json
import os
import subprocess
import tempfile
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

PROTO = "ilahrs"

Pairs = list[tuple[str, Any]]


def run(
    lua: Path, capture: Path, *options: str, two_pass: bool = True, fmt: tuple[str, ...] = ("-T", "json", "-x")
) -> str:
    """tshark's output for `capture` with the dissector `lua` loaded."""
    with tempfile.TemporaryDirectory(prefix="ilahrs-tshark-") as home:
        env = {**os.environ, "HOME": home, "XDG_CONFIG_HOME": str(Path(home) / ".config")}
        env.pop("WIRESHARK_CONFIG_DIR", None)
        command = ["tshark", *(["-2"] if two_pass else []), "-X", f"lua_script:{lua}", "-r", str(capture)]
        command += [*fmt, *(o for option in options for o in ("-o", option))]
        done = subprocess.run(command, env=env, capture_output=True, text=True, check=False)
    errors = [line for line in done.stderr.splitlines() if "dangerous" not in line and line.strip()]
    if done.returncode != 0 or errors:
        raise RuntimeError(f"{' '.join(command)} failed ({done.returncode}):\n" + "\n".join(errors))
    return done.stdout


def fields(lua: Path) -> list[list[str]]:
    """`tshark -G fields` rows of the dissector's protocol."""
    with tempfile.TemporaryDirectory(prefix="ilahrs-tshark-") as home:
        env = {**os.environ, "HOME": home, "XDG_CONFIG_HOME": str(Path(home) / ".config")}
        done = subprocess.run(
            ["tshark", "-G", "fields", "-X", f"lua_script:{lua}"], env=env, capture_output=True, text=True, check=True
        )
    rows = [line.split("\t") for line in done.stdout.splitlines()]
    return [row for row in rows if len(row) > 4 and row[0] == "F" and row[4] == PROTO]


def version() -> str:
    done = subprocess.run(["tshark", "--version"], capture_output=True, text=True, check=True)
    return done.stdout.splitlines()[0]


@dataclass
class Tree:
    """One `ilahrs` tree: every (key, value) in order, subtrees flattened."""

    items: Pairs = field(default_factory=list)
    raw: bytes = b""
    """The bytes the tree covers (of the packet, or reassembled)."""

    def get(self, key: str) -> Any:
        return next((v for k, v in self.items if k == key), None)

    def all(self, key: str) -> list[Any]:
        return [v for k, v in self.items if k == key]

    def has(self, key: str) -> bool:
        return any(k == key for k, _ in self.items)


@dataclass
class Shown:
    """One packet as tshark shows it."""

    layers: Pairs
    trees: list[Tree]

    def frame(self, key: str) -> Any:
        frame = next(v for k, v in self.layers if k == "frame")
        return _find(frame, key)

    def raw(self) -> bytes:
        value = next(v for k, v in self.layers if k == "frame_raw")
        return bytes.fromhex(value[0])


def _find(pairs: Pairs, key: str) -> Any:
    for k, v in pairs:
        if k == key:
            return v
        if isinstance(v, list) and v and isinstance(v[0], tuple):
            found = _find(v, key)
            if found is not None:
                return found
    return None


def _flatten(pairs: Pairs, out: Pairs) -> None:
    for k, v in pairs:
        if isinstance(v, list) and v and isinstance(v[0], tuple):
            _flatten(v, out)
        else:
            out.append((k, v))


def parse(text: str) -> list[Shown]:
    """Packets of `tshark -T json` output, in order."""
    packets: list[Pairs] = json.loads(text, object_pairs_hook=list)
    shown = []
    for packet in packets:
        source = next(v for k, v in packet if k == "_source")
        layers = next(v for k, v in source if k == "layers")
        trees = []
        raw = b""
        for key, value in layers:
            if key == PROTO + "_raw":
                raw = bytes.fromhex(value[0])
            elif key == PROTO:
                items: Pairs = []
                _flatten(value, items)
                trees.append(Tree(items, raw))
        shown.append(Shown(layers, trees))
    return shown
