"""The README's tour of the repository is what `ls` shows: every top-level folder in git is in the
tree, every entry of the tree exists, and the folders it names under tests/ are the folders there."""

from __future__ import annotations

import re
import subprocess
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def _tree() -> dict[str, str]:
    """The README's tree: entry (as written, `spec/`) -> its description (continuation lines too)."""
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    block = text.split("## A tour", 1)[1].split("```", 2)[1]
    entries: dict[str, str] = {}
    current = ""
    for line in block.splitlines():
        match = re.match(r"(\S+)\s+(.*)", line)
        if match:
            current = match.group(1)
            entries[current] = match.group(2)
        elif current and line.strip():
            entries[current] += " " + line.strip()
    return entries


def _tracked_folders(under: str = "") -> set[str]:
    names = subprocess.run(
        ["git", "ls-files", *([under] if under else [])], cwd=ROOT, capture_output=True, text=True, check=True
    )
    prefix = len(under)
    folders = {name[prefix:].split("/", 1)[0] for name in names.stdout.splitlines() if "/" in name[prefix:]}
    return {folder for folder in folders if not folder.startswith(".")}


def test_every_top_level_folder_is_in_the_tree_and_every_entry_exists() -> None:
    tree = _tree()
    folders = {name.rstrip("/") for name in tree if name.endswith("/")}
    assert folders == _tracked_folders(), "README.md's tree and the repository's folders differ"
    for name in tree:
        assert (ROOT / name).exists(), f"README.md's tree names {name}, which does not exist"


def test_the_tests_folders_are_the_ones_the_tree_names() -> None:
    named = set(re.findall(r"\b([a-z]+)/", _tree()["tests/"]))
    assert named == _tracked_folders("tests/"), "README.md's tests/ entry and tests/ differ"
