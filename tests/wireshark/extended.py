"""A spec with one more command and one more payload table (tests/c/extend_spec.py) gives a
dissector that decodes them, with no template change (`make test-wireshark`).

The Python package and the dissector are generated from the extended spec into OUT_DIR; the new
table and its fields must be in the Lua tables and registered by tshark, and a session that sends
the new command must show its answer in tshark exactly as the extended Python binding decodes it
(the same comparison as differential.py, run in a process that imports the extended package).

    python tests/wireshark/extended.py OUT_DIR
"""

from __future__ import annotations

import importlib.util
import os
import subprocess
import sys
from pathlib import Path
from types import ModuleType

import tshark

ROOT = Path(__file__).resolve().parent.parent.parent
HERE = Path(__file__).resolve().parent


def extension() -> ModuleType:
    spec = importlib.util.spec_from_file_location("extend_spec", ROOT / "tests" / "c" / "extend_spec.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def generate(out: Path) -> Path:
    spec = out / "ilahrs.yaml"
    subprocess.run([sys.executable, str(ROOT / "tests" / "c" / "extend_spec.py"), str(spec)], check=True)
    subprocess.run(
        [
            sys.executable,
            "-m",
            "generator",
            "--spec",
            str(spec),
            "--out",
            str(out / "generated"),
            "--target",
            "python",
            "--target",
            "wireshark",
        ],
        check=True,
        cwd=ROOT,
        stdout=subprocess.DEVNULL,
    )
    return out / "generated" / "wireshark" / "ilahrs.lua"


def inner(out: Path, lua: Path) -> int:
    """In a process that imports the extended package: send the new command, compare."""
    import differential
    import reference
    import session

    import ilahrs
    from ilahrs.pcapng import read

    assert Path(ilahrs.__file__).resolve().is_relative_to(out.resolve()), ilahrs.__file__
    command, table = extension().COMMAND["name"], extension().PAYLOAD["name"]
    run = session.Session("g300_a2_tmga", seed=7)
    for name in ("GetBIT", command, command, "ReadAHRSPar", command):
        run.send(name)
    run.idle(0.1)
    assert table in run.recording.tables, f"the device never sent {table}"
    path = out / "extended.pcapng"
    session.save(path, run.recording)
    shown = tshark.parse(tshark.run(lua, path))
    with path.open("rb") as f:
        expected = reference.Reference(ilahrs.VARIANTS["g300_a2_tmga"]).decode(read(f))
    differential.mark_answered(expected)
    messages, values = differential.compare(path, shown, expected)
    new = [m for packet in expected for m in packet.messages if m.table == table]
    print(
        f"extended spec: {table} ({len(ilahrs.PAYLOADS[table].FIELDS)} fields) in the dissector with no template "
        f"change; {len(new)} of its blocks among {messages} messages and {values} field values identical in tshark"
    )
    return 0


def main(argv: list[str]) -> int:
    out = Path(argv[1])
    out.mkdir(parents=True, exist_ok=True)
    lua = generate(out)
    ext = extension()
    table = ext.PAYLOAD["name"]
    text = lua.read_text(encoding="utf-8")
    assert f'name = "{table}"' in text, f"{table} is not in {lua}"
    assert f'"{ext.COMMAND["name"]}"' in text, f"{ext.COMMAND['name']} is not in {lua}"
    registered = {row[2] for row in tshark.fields(lua)}
    wanted = {f"{tshark.PROTO}.{table}.{f['name']}" for f in ext.PAYLOAD["fields"]}
    assert wanted <= registered, f"tshark does not register {sorted(wanted - registered)}"
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(out / "generated" / "python"), str(HERE)])}
    done = subprocess.run([sys.executable, __file__, "--inner", str(out), str(lua)], env=env, check=False)
    return done.returncode


if __name__ == "__main__":
    if sys.argv[1] == "--inner":
        sys.exit(inner(Path(sys.argv[2]), Path(sys.argv[3])))
    sys.exit(main(sys.argv))
