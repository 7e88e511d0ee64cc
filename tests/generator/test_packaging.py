"""The Python package as it is installed: the Python versions it supports, what `pip install` leaves."""

from __future__ import annotations

import ast
import re
import subprocess
from pathlib import Path

import pytest

from generator import ROOT
from generator.__main__ import _on_disk

PACKAGE = ROOT / "generated" / "python"

# What the standard library gained in 3.11 and later, by module.
NEWER = {
    "typing": {
        "Self",
        "LiteralString",
        "Never",
        "assert_never",
        "reveal_type",
        "dataclass_transform",
        "NotRequired",
        "Required",
        "TypeVarTuple",
        "Unpack",
        "override",
        "TypeAliasType",
        "ReadOnly",
        "TypeIs",
    },
    "enum": {
        "StrEnum",
        "ReprEnum",
        "EnumCheck",
        "FlagBoundary",
        "verify",
        "member",
        "nonmember",
        "property",
        "global_enum",
        "show_flag_values",
    },
    "datetime": {"UTC"},
    "asyncio": {"TaskGroup", "timeout", "Runner"},
}
NEW_MODULES = {"tomllib", "wsgiref.types"}


def test_requires_python_3_10() -> None:
    text = (PACKAGE / "pyproject.toml").read_text(encoding="utf-8")
    assert re.search(r'^requires-python = ">=3\.10"$', text, re.MULTILINE)


def test_the_package_uses_nothing_newer_than_python_3_10() -> None:
    found = []
    # compat.py imports them where the interpreter has them, and defines them where it does not.
    for path in sorted(p for p in (PACKAGE / "ilahrs").glob("*.py") if p.name != "compat.py"):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            where = f"{path.name}:{getattr(node, 'lineno', 0)}"
            if isinstance(node, ast.ImportFrom) and node.module is not None and node.level == 0:
                if node.module in NEW_MODULES:
                    found.append(f"{where}: {node.module}")
                found += [
                    f"{where}: {node.module}.{a.name}" for a in node.names if a.name in NEWER.get(node.module, ())
                ]
            elif isinstance(node, ast.Import):
                found += [f"{where}: {a.name}" for a in node.names if a.name in NEW_MODULES]
            elif isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name):
                if node.attr in NEWER.get(node.value.id, ()):
                    found.append(f"{where}: {node.value.id}.{node.attr}")
            elif type(node).__name__ == "TryStar" or (isinstance(node, ast.Name) and node.id == "ExceptionGroup"):
                found.append(f"{where}: except* / ExceptionGroup")
    assert not found, found


def test_pip_build_folder_is_neither_tracked_nor_generated(tmp_path: Path) -> None:
    # `pip install ./generated/python` builds in place, into generated/python/build/.
    for leftover in ("generated/python/build/lib/ilahrs/frame.py", "generated/python/ilahrs.egg-info/PKG-INFO"):
        ignored = subprocess.run(["git", "check-ignore", "-q", leftover], cwd=ROOT, check=False)
        assert ignored.returncode == 0, f"{leftover} is not ignored by git"
    (tmp_path / "python" / "build" / "lib" / "ilahrs").mkdir(parents=True)
    (tmp_path / "python" / "build" / "lib" / "ilahrs" / "frame.py").write_text("", encoding="utf-8")
    (tmp_path / "python" / "ilahrs").mkdir()
    (tmp_path / "python" / "ilahrs" / "frame.py").write_text("", encoding="utf-8")
    assert _on_disk(tmp_path, ["python"]) == {"python/ilahrs/frame.py"}


NEED = ROOT / "tools" / "need"


def _fake_bin(folder: Path, programs: dict[str, str]) -> dict[str, str]:
    """A PATH of `programs` (name -> shell body) only: what tools/need finds on a given machine."""
    folder.mkdir()
    for name, body in programs.items():
        (folder / name).write_text(f"#!/bin/sh\n{body}\n", encoding="utf-8")
        (folder / name).chmod(0o755)
    return {"PATH": str(folder), "HOME": str(folder)}


def _need(env: dict[str, str], *args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(["/bin/bash", str(NEED), *args], env=env, capture_output=True, text=True, check=False)


def test_need_without_apt_get_names_the_tool_and_the_command(tmp_path: Path) -> None:
    result = _need(_fake_bin(tmp_path / "bin", {"id": "echo 0"}), "--tool", "dot", "graphviz")
    assert result.returncode == 1
    assert "dot is needed and not installed; apt-get is not available here" in result.stderr
    assert "sudo apt-get install -y graphviz" in result.stderr


def test_need_as_a_user_does_not_run_apt_get(tmp_path: Path) -> None:
    log = tmp_path / "apt.log"
    env = _fake_bin(tmp_path / "bin", {"id": "echo 1000", "apt-get": f'echo "$@" >> {log}'})
    result = _need(env, "gcc-arm-none-eabi", "libnewlib-arm-none-eabi")
    assert result.returncode == 1
    assert "gcc-arm-none-eabi is needed and not installed; installing it needs root" in result.stderr
    assert "sudo apt-get install -y gcc-arm-none-eabi libnewlib-arm-none-eabi" in result.stderr
    assert not log.exists()


@pytest.mark.parametrize("works", [True, False])
def test_need_as_root_installs_or_says_why_not(tmp_path: Path, works: bool) -> None:
    log = tmp_path / "apt.log"
    body = f'echo "$@" >> {log}' + ("" if works else '\n[ "$1" = update ] || exit 100')
    result = _need(_fake_bin(tmp_path / "bin", {"id": "echo 0", "apt-get": body}), "tshark")
    assert log.read_text(encoding="utf-8").splitlines() == ["update -qq", "install -y -qq tshark"]
    assert "installing tshark with apt-get" in result.stderr
    assert result.returncode == (0 if works else 1)
    assert ("apt-get could not install it" in result.stderr) != works


def test_every_apt_install_of_the_makefiles_goes_through_tools_need() -> None:
    for mk in sorted((ROOT / "mk").glob("*.mk")):
        for number, line in enumerate(mk.read_text(encoding="utf-8").splitlines(), 1):
            code = line.split("#", 1)[0]
            assert "apt-get" not in code and "apt " not in code, f"{mk.name}:{number}: {line.strip()}"
