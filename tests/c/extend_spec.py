"""Write spec/ilahrs.yaml plus one made-up command and one made-up payload table (used by `make test-c`).

The C target must pick both up with no template change: the test generates the C binding from
the extended spec, compiles it warning-free and runs the unit tests (which walk every command and
every payload table through the library's own tables) against it.

    python tests/c/extend_spec.py OUT.yaml
"""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Any

import yaml

ROOT = Path(__file__).resolve().parent.parent.parent

COMMAND = {
    "name": "GetTemp",
    "id": "get_temp",
    "code": 0x99,
    "icd": "test",
    "group": "control",
    "purpose": "A command that exists only in this test.",
    "valid_in": ["idle"],
    "response": {"kind": "data", "payloads": ["temperature_block"]},
}

PAYLOAD = {
    "name": "temperature_block",
    "icd": "test",
    "title": "Temperature block",
    "direction": "device_to_host",
    "size": 11,
    "doc": "A payload table that exists only in this test.",
    "fields": [
        {"name": "temp_a", "icd_name": "A", "type": "s16", "unit": "degC", "scale": {"divisor": 10},
         "range": [-400, 850]},
        {"name": "flags", "icd_name": "F", "type": "u8", "default": 7},
        {"name": "gain", "icd_name": "G", "type": "f32", "range": [0.5, 2]},
        {"name": "label", "icd_name": "L", "type": "char", "length": 4, "default": "T1"},
    ],
}


def main(argv: list[str]) -> int:
    if len(argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    spec: dict[str, Any] = yaml.safe_load((ROOT / "spec" / "ilahrs.yaml").read_text(encoding="utf-8"))
    spec["commands"].append(COMMAND)
    spec["payloads"].append(PAYLOAD)
    machine = spec.get("state_machine")
    if machine and machine.get("transitions") is not None:
        transition = {"from": ["idle"], "when": ["GetTemp"], "to": "idle", "send": ["temperature_block"]}
        machine["transitions"].append(transition)
    out = Path(argv[1])
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(yaml.safe_dump(spec, sort_keys=False, allow_unicode=True), encoding="utf-8")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
