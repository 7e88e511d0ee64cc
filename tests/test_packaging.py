"""The Python package as it is installed: the Python versions it supports, what `pip install` leaves."""

from __future__ import annotations

import ast
import re
import subprocess
from pathlib import Path

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
