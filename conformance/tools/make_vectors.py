"""Write the conformance suites, conformance/vectors/*.json, from the oracle in oracle.py.

    python3 conformance/tools/make_vectors.py            # rewrite conformance/vectors/
    python3 conformance/tools/make_vectors.py --check    # exit 1 if the committed files differ

Each suite is a module of suites/ (suites/payloads.py writes payloads.json) with its cases as data
in suites/cases/<suite>.json: every vector has a note saying where its bytes come from (an ICD
table, an erratum of spec/ilahrs.yaml, a rule of spec/README.md, or how it was computed). Expected
answers are computed by the oracles (oracle.py, device_oracle.py), never by the generator or a
binding. The output is deterministic (fixed seeds, sorted nothing that depends on hashing), so the
committed JSON is exactly what this script writes: edit the cases, never the JSON.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from suites import build_all

VECTORS_DIR = Path(__file__).resolve().parent.parent / "vectors"

__all__ = ["build_all", "main"]


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=VECTORS_DIR, help="where to write (default: conformance/vectors)")
    parser.add_argument("--check", action="store_true", help="compare with the files in --out instead of writing")
    args = parser.parse_args(argv)
    files = build_all()
    if args.check:
        stale = [
            name
            for name, text in files.items()
            if not (args.out / name).is_file() or (args.out / name).read_text(encoding="utf-8") != text
        ]
        extra = sorted(p.name for p in args.out.glob("*.json") if p.name not in files)
        for name in stale:
            print(f"{args.out / name}: differs from what {Path(__file__).name} writes", file=sys.stderr)
        for name in extra:
            print(f"{args.out / name}: not written by {Path(__file__).name}", file=sys.stderr)
        return 1 if stale or extra else 0
    args.out.mkdir(parents=True, exist_ok=True)
    for name, text in files.items():
        (args.out / name).write_text(text, encoding="utf-8")
    return 0


if __name__ == "__main__":
    sys.exit(main())
