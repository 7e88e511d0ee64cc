"""tools/generator_stats.py: the table and the JSON it prints, on this repository and on a small tree
whose numbers are known."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path
from typing import Any

from generator import ROOT

TOOL = ROOT / "tools" / "generator_stats.py"


def run(*args: str) -> str:
    result = subprocess.run([sys.executable, str(TOOL), *args], capture_output=True, text=True, check=True)
    assert not result.stderr
    return result.stdout


def test_json_shape_on_this_repository() -> None:
    data = json.loads(run("--json"))
    assert set(data) == {"limits", "templates", "generator_modules", "runtime_files", "generated"}
    assert set(data["limits"]) == {"template_total_lines", "template_lines", "module_lines"}
    templates = data["templates"]
    assert templates["count"] == len(templates["files"]) > 0
    assert templates["total_lines"] == sum(t["lines"] for t in templates["files"])
    assert templates["largest"] == {"path": templates["files"][0]["path"], "lines": templates["files"][0]["lines"]}
    for t in templates["files"]:
        assert set(t) == {"path", "lines", "jinja_lines", "jinja_share"}
        assert t["path"].startswith("generator/targets/") and "/templates/" in t["path"]
        assert 0 <= t["jinja_lines"] <= t["lines"] and 0 <= t["jinja_share"] <= 1
    assert [t["lines"] for t in templates["files"]] == sorted((t["lines"] for t in templates["files"]), reverse=True)
    modules = data["generator_modules"]
    assert modules["count"] > 0 and modules["largest"]["path"].startswith("generator/")
    assert modules["largest"]["path"].endswith(".py")
    runtime = data["runtime_files"]
    assert set(runtime) == {"count", "total_lines", "largest"}
    assert (runtime["largest"] is None) == (runtime["count"] == 0)
    bindings = data["generated"]["bindings"]
    assert list(bindings)[:2] == ["python", "c"] and {"rust", "kaitai", "docs"} <= set(bindings)
    assert data["generated"]["total_lines"] == sum(b["lines"] for b in bindings.values())


def test_table_on_this_repository_names_every_part() -> None:
    text = run()
    lines = text.splitlines()
    assert lines[0].split() == ["lines", "jinja", "share"]
    for heading in ("templates: ", "generator modules: ", "runtime files: ", "generated: "):
        assert sum(line.startswith(heading) for line in lines) == 1, heading
    for binding in ("python", "c", "rust", "kaitai", "docs"):
        assert any(line.startswith(f"  {binding}: ") for line in lines), binding
    assert "  c/ilahrs.h.j2" in text


def write(path: Path, text: str) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text, encoding="utf-8")


def test_counts_on_a_known_tree(tmp_path: Path) -> None:
    write(tmp_path / "generator/targets/py/templates/a.py.j2", "{{ x }}\nplain\n{% if y %}\n{# note #}")
    write(tmp_path / "generator/targets/py/templates/b.j2", "one\n")
    write(tmp_path / "generator/targets/py/runtime/device.py", "a\nb\nc\n")
    write(tmp_path / "generator/targets/py/filters.py", "a\n" * 5)
    write(tmp_path / "generator/model.py", "a\n" * 7)
    write(tmp_path / "generator/__pycache__/model.py", "a\n" * 99)
    write(tmp_path / "generated/python/x.py", "a\nb\n")
    write(tmp_path / "generated/python/ilahrs.egg-info/PKG-INFO", "skipped\n")
    write(tmp_path / "generated/zzz/y.txt", "a\n")
    write(tmp_path / "generated/c/ilahrs.c", "a\n" * 4)
    data: dict[str, Any] = json.loads(run("--json", "--root", str(tmp_path)))
    templates = data["templates"]
    assert templates["count"] == 2 and templates["total_lines"] == 5
    assert templates["files"][0] == {
        "path": "generator/targets/py/templates/a.py.j2",
        "lines": 4,
        "jinja_lines": 3,
        "jinja_share": 0.75,
    }
    assert data["generator_modules"] == {
        "count": 2,
        "total_lines": 12,
        "largest": {"path": "generator/model.py", "lines": 7},
    }
    assert data["runtime_files"]["largest"] == {"path": "generator/targets/py/runtime/device.py", "lines": 3}
    assert data["generated"]["bindings"] == {
        "python": {"files": 1, "lines": 2},
        "c": {"files": 1, "lines": 4},
        "zzz": {"files": 1, "lines": 1},
    }
    table = run("--root", str(tmp_path))
    assert "  py/a.py.j2" in table and "largest: generator/targets/py/runtime/device.py" in table


def test_an_empty_tree_prints_zeros(tmp_path: Path) -> None:
    data = json.loads(run("--json", "--root", str(tmp_path)))
    assert data["templates"] == {"count": 0, "total_lines": 0, "largest": None, "files": []}
    assert data["runtime_files"] == {"count": 0, "total_lines": 0, "largest": None}
    assert data["generated"] == {"total_lines": 0, "bindings": {}}
    assert "largest: none" in run("--root", str(tmp_path))


def test_this_repository_keeps_its_limits() -> None:
    """Templates hold only what the spec decides (at most 5,000 lines in all, none over 300), and no
    generator module grows past 400 lines: fixed code belongs in a target's runtime/ folder."""
    data = json.loads(run("--json"))
    limits = data["limits"]
    templates = data["templates"]
    assert templates["total_lines"] <= limits["template_total_lines"]
    over = [(t["path"], t["lines"]) for t in templates["files"] if t["lines"] > limits["template_lines"]]
    assert not over, f"templates over {limits['template_lines']} lines: {over}"
    largest = data["generator_modules"]["largest"]
    assert largest["lines"] <= limits["module_lines"], f"generator module over the limit: {largest}"
