"""Write the small MAVLink dialect the comparison uses, from the definitions pymavlink ships.

The messages are copied from pymavlink's own common.xml (and the files it includes), with every
enum they name, so mavgen sees the real message definitions (same fields, same CRC_EXTRA) and
nothing of MAVLink is kept in this repository. A small dialect keeps MAVLink's message table, and
so its decoder, as small as a firmware that knows only these messages would have it.

    .venv/bin/python bench/mavlink/dialect.py OUT.xml
"""

from __future__ import annotations

import importlib.util
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

# An autopilot's attitude and IMU outputs (sizes close to the AHRS output frames), its heartbeat,
# and the command / acknowledgement pair.
MESSAGES = ("HEARTBEAT", "RAW_IMU", "ATTITUDE", "ATTITUDE_QUATERNION", "COMMAND_LONG", "COMMAND_ACK")


def definitions() -> list[ET.Element]:
    """Root elements of common.xml and of every file it includes, from pymavlink's package."""
    spec = importlib.util.find_spec("pymavlink")
    if spec is None or spec.origin is None:
        raise SystemExit("dialect.py: pymavlink is not installed (pip install -r bench/mavlink/requirements.txt)")
    folder = Path(spec.origin).parent / "dialects" / "v20"
    roots: list[ET.Element] = []
    pending = ["common.xml"]
    while pending:
        root = ET.parse(folder / pending.pop()).getroot()
        roots.append(root)
        pending.extend(include.text or "" for include in root.iter("include"))
    return roots


def dialect() -> ET.Element:
    roots = definitions()
    messages = {m.get("name"): m for root in roots for m in root.iter("message")}
    enums = {e.get("name"): e for root in roots for e in root.iter("enum")}
    chosen = [messages[name] for name in MESSAGES]
    named = sorted({f.get("enum") for m in chosen for f in m.iter("field")} - {None}, key=str)
    out = ET.Element("mavlink")
    ET.SubElement(out, "version").text = "3"
    ET.SubElement(out, "dialect").text = "0"
    enums_out = ET.SubElement(out, "enums")
    enums_out.extend(enums[str(name)] for name in named)
    messages_out = ET.SubElement(out, "messages")
    messages_out.extend(sorted(chosen, key=lambda m: int(m.get("id", "0"))))
    return out


def main() -> int:
    if len(sys.argv) != 2:
        sys.stderr.write(__doc__ or "")
        return 2
    root = dialect()
    ET.indent(root)
    Path(sys.argv[1]).write_text(ET.tostring(root, encoding="unicode") + "\n", encoding="utf-8")
    return 0


if __name__ == "__main__":
    sys.exit(main())
