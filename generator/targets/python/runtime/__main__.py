"""Command line: `ilahrs simulate` (a virtual AHRS on a pty or loopback socket) and `ilahrs
diagram` (the state machine as a Mermaid diagram). Run `ilahrs simulate --help` for the options."""

from __future__ import annotations

import argparse
import os
import sys
from collections.abc import Sequence
from contextlib import ExitStack

from .cli import COMMANDS_RUN, OneLineParser, add_subcommands, run
from .cli.common import CliError, variant_named
from .conformance import add_arguments as conformance_arguments
from .conformance import run as run_conformance
from .edge.misbehave import MISBEHAVIOURS, device_class
from .edge.simulate import BAUDRATE, Faults, Line, recorder, run_pty, run_tcp
from .encodings import VARIANTS
from .errors import IlahrsError
from .roles import FIRMWARE, READ_PARAMETERS, ParameterBlock
from .session.device import DEFAULT_DEVICE_ID, DEFAULT_VARIANT, Device, default_parameters
from .spec import SPEC_VERSION
from .statemachine import DEFAULT_FIRMWARE, TIMER_FIELDS, mermaid

__all__ = ["main"]


def _rate(text: str) -> float:
    value = float(text)
    if not 0.0 <= value <= 1.0:
        raise argparse.ArgumentTypeError(f"{text} is not a probability between 0 and 1")
    return value


def _parser() -> argparse.ArgumentParser:
    parser = OneLineParser(prog="ilahrs", description=f"ilahrs {SPEC_VERSION}: Inertial Labs AHRS tools")
    parser.add_argument("--version", action="version", version=f"ilahrs {SPEC_VERSION}")
    commands = parser.add_subparsers(dest="command", required=True)
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
    commands.add_parser(
        "diagram",
        help="print the device state machine as a Mermaid diagram",
        description="Print the device's state machine (ilahrs.statemachine, from the spec) as a Mermaid "
        "stateDiagram on standard output: every state, and every transition with the event and what "
        "the AHRS sends.",
    )
    add_subcommands(commands)
    conformance = commands.add_parser(
        "conformance",
        help="run the conformance suite against a runner (--command) or a device (--device)",
        description="Run the conformance vectors shipped with the package against a runner that speaks the "
        "runner protocol (--command), or the session flows live against a device (--device).",
    )
    conformance_arguments(conformance)
    return parser


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


def main(argv: Sequence[str] | None = None) -> int:
    """Run `ilahrs`: its exit status. A closed standard output (`ilahrs params PORT | head -1`)
    ends the command with one line on stderr and status 2, never a traceback."""
    try:
        status = _main(argv)
        sys.stdout.flush()  # a closed pipe shows here, not in the interpreter's exit
    except BrokenPipeError:
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())  # nothing more to write at exit
        print(f"ilahrs: {_command(argv)}standard output closed", file=sys.stderr)
        return 2
    return status


def _command(argv: Sequence[str] | None) -> str:
    words = list(sys.argv[1:] if argv is None else argv)
    return next((f"{word}: " for word in words if not word.startswith("-")), "")


def _main(argv: Sequence[str] | None) -> int:
    args = _parser().parse_args(argv)
    if args.command in COMMANDS_RUN:
        return run(args)
    if args.command == "conformance":
        return run_conformance(args)
    if args.command == "diagram":
        sys.stdout.write(mermaid())
        return 0
    try:
        args.variant = variant_named(args.variant).name
        device = _device(args)
    except (CliError, IlahrsError) as exc:
        print(f"ilahrs simulate: {exc}", file=sys.stderr)
        return 2
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


if __name__ == "__main__":
    sys.exit(main())
