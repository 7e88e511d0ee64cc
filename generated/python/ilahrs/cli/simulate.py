# Copied from generator/targets/python/runtime/cli/simulate.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""`ilahrs simulate`: a virtual AHRS on a pty or loopback socket (ilahrs.edge.simulate)."""

from __future__ import annotations

import argparse
import sys
from contextlib import ExitStack

from ..edge.misbehave import MISBEHAVIOURS, device_class
from ..edge.simulate import BAUDRATE, Faults, Line, recorder, run_pty, run_tcp
from ..encodings import VARIANTS
from ..roles import FIRMWARE, READ_PARAMETERS, ParameterBlock
from ..session.device import DEFAULT_DEVICE_ID, DEFAULT_VARIANT, Device, default_parameters
from ..statemachine import DEFAULT_FIRMWARE, TIMER_FIELDS
from .arguments import OneLineParser
from .common import variant_named

__all__ = ["add_parser", "run"]


def _rate(text: str) -> float:
    value = float(text)
    if not 0.0 <= value <= 1.0:
        raise argparse.ArgumentTypeError(f"{text} is not a probability between 0 and 1")
    return value


def add_parser(commands: argparse._SubParsersAction[OneLineParser]) -> OneLineParser:
    sim = commands.add_parser(
        "simulate",
        help="run a virtual AHRS on a pseudo-terminal (default) or a loopback TCP port",
        description="Run a virtual AHRS. The first line of output is the port a client opens: the device path, "
        f"or socket://HOST:PORT with --tcp; connect at {BAUDRATE} baud 8N1. Stop with Ctrl-C or SIGTERM.",
        epilog="With --tcp, clients are served one at a time, one after another, until the simulator is "
        "stopped; the device carries on between them (state, parameters and clock; its output is lost "
        "while nobody is connected).",
    )
    sim.add_argument(
        "--tcp",
        metavar="HOST:PORT",
        help="serve a loopback address instead of a pty (port 0: any free port), one client at a time",
    )
    sim.add_argument("--seed", type=int, default=0, help="seed of the motion, noise, calibration and faults")
    sim.add_argument(
        "--variant",
        metavar="NAME",
        default=DEFAULT_VARIANT,
        help=f"device variant, its scale factors KG and KA ({', '.join(VARIANTS)}; default {DEFAULT_VARIANT})",
    )
    sim.add_argument("--firmware", default=DEFAULT_FIRMWARE, help=f"firmware version (default {DEFAULT_FIRMWARE})")
    sim.add_argument("--firmware-text", help=f"the {FIRMWARE} answer")
    sim.add_argument("--device-id", default=DEFAULT_DEVICE_ID, help=f"the device id of {READ_PARAMETERS}")
    sim.add_argument("--alignment-time", type=int, metavar="S", help="initial alignment time in seconds")
    sim.add_argument("--update-rate", type=int, metavar="HZ", help="output rate in Hz")
    sim.add_argument("--corrupt-rate", type=_rate, default=0.0, metavar="P", help="probability of corrupting a byte")
    sim.add_argument("--drop-rate", type=_rate, default=0.0, metavar="P", help="probability of dropping a byte")
    sim.add_argument(
        "--garbage-rate", type=_rate, default=0.0, metavar="P", help="probability of noise before a message"
    )
    sim.add_argument(
        "--misbehave",
        choices=sorted(MISBEHAVIOURS),
        help="test only: break one protocol rule (" + "; ".join(f"{k}: {v}" for k, v in MISBEHAVIOURS.items()) + ")",
    )
    sim.add_argument("--log", metavar="FILE", help="write every message sent (meant and written) as JSON lines")
    sim.add_argument("--record", metavar="FILE.pcapng", help="record both directions with timestamps as pcapng")
    return sim


def _device(args: argparse.Namespace) -> Device:
    raw = default_parameters(args.device_id).raw()
    settings = {"alignment": args.alignment_time, "output": args.update_rate}
    for timer, value in settings.items():
        if value is not None:
            raw[TIMER_FIELDS[timer][1]] = value
    parameters = ParameterBlock.from_raw(raw)
    return device_class(args.misbehave)(
        seed=args.seed,
        variant=args.variant,
        firmware=args.firmware,
        firmware_text=args.firmware_text,
        parameters=parameters,
    )


def run(args: argparse.Namespace) -> int:
    args.variant = variant_named(args.variant).name
    device = _device(args)
    faults = Faults(args.corrupt_rate, args.drop_rate, args.garbage_rate, args.seed)
    with ExitStack() as stack:
        try:
            log = stack.enter_context(open(args.log, "w", encoding="utf-8")) if args.log else None
        except OSError as exc:
            print(f"ilahrs simulate: cannot write the log {args.log}: {exc.strerror or exc}", file=sys.stderr)
            return 2
        line = Line(device, faults, log)
        if args.record:
            line.recorder = recorder(stack.enter_context(open(args.record, "wb")), args.tcp or "pty")
        try:
            status = run_tcp(line, args.tcp) if args.tcp else run_pty(line)
        except (ValueError, OSError) as exc:
            print(f"ilahrs simulate: {exc}", file=sys.stderr)
            return 2
    print(f"ilahrs simulate: sent {line.sent} messages, {line.intact} intact, {line.lost} lost", file=sys.stderr)
    return status
