"""A spec with one more command and one more payload table (tests/c/extend_spec.py) gives a Python
package that has both, with no template or runtime change: the command in COMMANDS and CODES, the
table in PAYLOADS with its class, the device model answering the command with a block of the
table and the host session reading it by context."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

from generator import ROOT

CHECK = """
import ilahrs
from ilahrs.session.device import Device
from ilahrs.session.host import DataBlock, Host

assert ilahrs.__file__.startswith(OUT), ilahrs.__file__
info = ilahrs.COMMANDS["GetTemp"]
assert ilahrs.CODES[info.code] == ("GetTemp",)
table = ilahrs.PAYLOADS["temperature_block"]
assert table is ilahrs.TemperatureBlock and table.SIZE == 11
block = table.from_raw({"temp_a": 215, "gain": 1.5})
assert table.parse(block.build()) == block and block.temp_a_degc == 21.5 and block.label == "T1"
device, host = Device(seed=1), Host()
[event] = host.receive(device.receive(host.send("GetTemp")))
assert isinstance(event, DataBlock) and event.payload.NAME == "temperature_block", event
print("ok")
"""


def test_extended_spec_gives_a_package_with_the_new_command_and_table(tmp_path: Path) -> None:
    spec = tmp_path / "ilahrs.yaml"
    out = tmp_path / "generated"
    subprocess.run([sys.executable, str(ROOT / "tests" / "c" / "extend_spec.py"), str(spec)], check=True)
    generate = [sys.executable, "-m", "generator", "--spec", str(spec), "--out", str(out), "--target", "python"]
    subprocess.run(generate, check=True, cwd=ROOT, capture_output=True)
    package = str(out / "python")
    env = {**os.environ, "PYTHONPATH": package}
    code = f"OUT = {package!r}\n" + CHECK
    run = [sys.executable, "-c", code]
    result = subprocess.run(run, check=False, env=env, cwd=tmp_path, capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    assert result.stdout == "ok\n"
