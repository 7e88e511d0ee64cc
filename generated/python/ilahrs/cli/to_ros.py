# Copied from generator/targets/python/runtime/cli/to_ros.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""`ilahrs decode CAPTURE --to rosbag2 DIR` and `--to mcap FILE`: a capture as ROS 2 messages
(REP 103, REP 145; `ilahrs.edge.ros`), in a rosbag2 directory with MCAP storage that
`ros2 bag play DIR` plays, or in that directory's one MCAP file alone.

The capture is decoded as `decode` decodes it (`CaptureDecoder`, following the commands of both
directions); every message from the device of the kinds `--types` selects becomes the ROS 2
messages its fields fill, stamped with the time its last byte was recorded (the pcapng packet's
timestamp, nanoseconds since the epoch), `--frame-id` in every header. A raw dump has no
timestamps and is refused; `--raw` is refused (a bag holds SI units). A capture cut short leaves
the bag of the messages before the damage, and the error (status 2), as a file of rows does.
"""

from __future__ import annotations

import argparse
import os
import shutil
import sys
from typing import Final

from ..edge.ros import EXTRA, TOPICS, BagWriter, require, samples
from ..pcapng import Direction
from .capture import open_source
from .capture_decoder import CaptureDecoder
from .common import CliError, variant_named
from .decode import Progress, output_table, summary
from .exports import Export
from .rows import Message

__all__ = ["DEFAULT_FRAME_ID", "EXPORTS", "add_options"]

DEFAULT_FRAME_ID: Final = "imu_link"
"""REP 145's name for the IMU's frame."""
_PROG: Final = "ilahrs decode"


def add_options(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--frame-id",
        default=DEFAULT_FRAME_ID,
        metavar="NAME",
        help="with --to rosbag2 or mcap: the frame_id of every message's header (default %(default)s)",
    )


def _convert(args: argparse.Namespace, bag_path: str, shown: str) -> int:
    """Decode `args.files[0]` into a rosbag2 directory at `bag_path`; the exit status."""
    if args.raw:
        raise CliError(f"--raw gives values as sent; --to {args.to} writes SI units")
    variant = variant_named(args.variant)
    table = output_table(args.output_format) if args.output_format else None
    try:
        require()  # before the capture is read
    except ImportError as exc:
        raise CliError(str(exc)) from exc
    source = open_source(args.files[0])
    try:
        if source.kind != "pcapng":
            raise CliError(
                f"{source.name}: a raw dump has no timestamps; --to {args.to} needs a pcapng capture (ilahrs record)"
            )
        bag = BagWriter(bag_path, args.frame_id)
        known = args.output_format is not None
        decoder = CaptureDecoder(
            context=True, output=table, output_known=known, strict=args.strict, start=args.output_format
        )
        wanted = set(args.selected)

        def take(messages: list[Message]) -> None:
            start = decoder.start
            for message in messages:
                if message.kind not in wanted or message.direction != Direction.INBOUND:
                    continue
                if message.data is None or message.time is None or start is None:
                    continue
                stamp_ns = round((start + message.time) * 1e6) * 1000  # pcapng times are microseconds
                bag.write_all(samples(message.data, variant, stamp_ns))

        progress = Progress(source)
        failure: CliError | None = None
        try:
            for chunk in source.chunks():
                take(decoder.feed(chunk))
                progress.update()
        except CliError as exc:
            failure = exc
        finally:
            progress.done()
        take(decoder.finish())
        bag.close()
    finally:
        source.close()
    if failure is not None:
        print(f"{_PROG}: {failure}", file=sys.stderr)  # after the bag of what came before it
        return 2
    for line in summary(decoder, _PROG):
        print(line, file=sys.stderr)
    topics = ", ".join(f"{topic} {count}" for topic, count in sorted(bag.counts.items()))
    print(f"{_PROG}: {shown}: {sum(bag.counts.values())} ROS 2 messages ({topics or 'none'})", file=sys.stderr)
    return 0


def _rosbag2(args: argparse.Namespace, path: str) -> int:
    return _convert(args, path, args.out)


def _mcap(args: argparse.Namespace, path: str) -> int:
    """The bag's MCAP file alone: the bag is written beside `path` (in the temporary folder
    `replacing` made) and its one storage file moved onto `path`."""
    folder = os.path.join(os.path.dirname(path), ".bag")
    try:
        status = _convert(args, folder, args.out)
        os.replace(os.path.join(folder, ".bag.mcap"), path)
    finally:
        shutil.rmtree(folder, ignore_errors=True)
    return status


_TOPICS: Final = ", ".join(sorted(TOPICS))

EXPORTS: Final = {
    "rosbag2": Export("directory", EXTRA, f"a ROS 2 bag, MCAP storage: {_TOPICS}", _rosbag2),
    "mcap": Export("file", EXTRA, "the same as one MCAP file", _mcap),
}
