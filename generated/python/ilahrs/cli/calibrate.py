# Copied from generator/targets/python/runtime/cli/calibrate.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""`ilahrs calibrate`: a guided hard/soft-iron calibration (ilahrs.cli.device)."""

from __future__ import annotations

import argparse
import sys

from ..payloads import PAYLOADS
from ..statemachine import TIMER_FIELDS
from .arguments import PORT_EPILOG, OneLineParser, port_arguments, variant_argument
from .common import variant_named
from .device import DEFAULT_ACCUMULATION_S

__all__ = ["add_parser", "run"]


def add_parser(commands: argparse._SubParsersAction[OneLineParser]) -> OneLineParser:
    cal = commands.add_parser("calibrate", help="guided hard/soft-iron calibration", epilog=PORT_EPILOG)
    port_arguments(cal)
    cal.add_argument("kind", metavar="2d|3d|2d2t", help="calibration type")
    table, field = TIMER_FIELDS["accumulation"]
    span = next(f for f in PAYLOADS[table].FIELDS if f.name == field)
    cal.add_argument(
        "--accumulation",
        type=int,
        default=DEFAULT_ACCUMULATION_S,
        metavar="S",
        help=f"accumulation time per run, seconds, {span.low:g}..{span.high:g}: long enough for a slow full "
        f"turn (default {DEFAULT_ACCUMULATION_S})",
    )
    place = "(default: what the device stores)"
    cal.add_argument("--latitude", type=float, metavar="DEG", help=f"latitude of the calibration {place}")
    cal.add_argument("--longitude", type=float, metavar="DEG", help=f"longitude of the calibration {place}")
    cal.add_argument("--altitude", type=float, metavar="M", help=f"altitude of the calibration {place}")
    cal.add_argument("--date", metavar="YYYY-MM-DD", help=f"date of the calibration {place}")
    cal.add_argument("--runs", type=int, default=2, metavar="N", help="runs of a 2D-2T calibration (default 2)")
    answer = cal.add_mutually_exclusive_group()
    answer.add_argument(
        "--yes", dest="answer", action="store_const", const=True, help="accept without asking (default: ask)"
    )
    answer.add_argument(
        "--no", dest="answer", action="store_const", const=False, help="discard without asking (default: ask)"
    )
    variant_argument(cal)
    return cal


def run(args: argparse.Namespace) -> int:
    from .device import calibrate, calibration_place

    variant = variant_named(args.variant)
    place = calibration_place(args.latitude, args.longitude, args.altitude, args.date)
    return calibrate(
        args.port,
        args.baud,
        args.kind,
        accumulation=args.accumulation,
        runs=args.runs,
        answer=args.answer,
        variant=variant,
        out=sys.stdout,
        place=place,
    )
