# Copied from generator/targets/python/runtime/commandset.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""The command table, used: a command's row (CommandInfo) and the functions over the table that
build and decode command frames, parameter blocks and the acknowledgement. `ilahrs.commands`
holds the spec's table in a CommandSet and binds these methods to its functions (`build_command`, ...).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType

from .codec import Payload, PayloadBase
from .errors import ErrorKind, IlahrsError, brief, suggest
from .frame import MESSAGE_LENGTH_OFFSET, MESSAGE_TYPE_OFFSET, PAYLOAD_OFFSET, Frame, MessageType

__all__ = ["CommandInfo", "CommandSet"]


@dataclass(frozen=True, slots=True)
class CommandInfo:
    """One row of Table C.1 with what sections 6.3 and 6.4 say about it."""

    name: str
    """ICD spelling, e.g. "AHRScont1"."""
    id: str
    """lower_snake identifier."""
    code: int
    icd: str
    """ICD section."""
    group: str
    purpose: str
    valid_in: tuple[str, ...]
    """Operating modes in which the command is valid."""
    response: str
    """What the AHRS answers: "ack", "data", "output" (one block of the current format) or "none"."""
    response_payloads: tuple[str, ...]
    """For a "data" response, the payload table(s) it can be."""
    parameter_block: str | None
    """The payload table the host must send right after the command, if any."""
    starts_mode: str | None
    starts_output: str | None
    shares_code_with: str | None
    former_names: tuple[str, ...]


@dataclass(frozen=True, slots=True, eq=False)
class CommandSet:
    """The commands by ICD name, the codes with their name(s), and the acknowledgement's table."""

    commands: Mapping[str, CommandInfo]
    codes: Mapping[int, tuple[str, ...]]
    acknowledgement: type[Payload]
    payloads: Mapping[str, type[Payload]] = field(default_factory=lambda: MappingProxyType({}))
    """Every payload class by table name (for parameter blocks given as raw values)."""

    def _info(self, name: str) -> CommandInfo:
        info = self.commands.get(name) if isinstance(name, str) else None
        if info is None:
            raise self.unknown(name)
        return info

    def unknown(self, name: object) -> IlahrsError:
        """The error for a command name that is not in the table, with the closest name."""
        detail = f"no command is called {brief(name)}{suggest(name, self.commands)}"
        return IlahrsError(ErrorKind.UNKNOWN_COMMAND, None, None, detail)

    def parameter_block(self, command: str, block: Payload | Mapping[str, object]) -> Payload:
        """The parameter block `command` takes, from a payload object or raw field values of its
        table (every name must be one of the table's fields: MALFORMED otherwise, nothing is built)."""
        info = self._info(command)
        if isinstance(block, PayloadBase):
            return block  # type: ignore[return-value]
        if not isinstance(block, Mapping):
            detail = f"{brief(block)} is neither a payload object nor a mapping of field values"
            raise IlahrsError(ErrorKind.MALFORMED, None, None, detail)
        table = self.payloads.get(info.parameter_block or "")
        if table is None:
            raise IlahrsError(ErrorKind.UNEXPECTED_MESSAGE, None, None, f"{command} takes no parameter block")
        return table.from_raw(block)

    def command_names(self, code: int) -> tuple[str, ...]:
        """The ICD name(s) of a command code (two for 0xFE); IlahrsError(UNKNOWN_COMMAND) for others."""
        names = self.codes.get(code) if isinstance(code, int) and not isinstance(code, bool) else None
        if names is None:
            shown = f"{code:#04x}" if isinstance(code, int) and not isinstance(code, bool) else brief(code)
            raise IlahrsError(ErrorKind.UNKNOWN_COMMAND, None, None, f"no command has code {shown}")
        return names

    def build_command(self, name: str, reserved: int = 0) -> bytes:
        """The frame of command `name` (ICD spelling, e.g. "AHRScont3")."""
        return Frame(MessageType.COMMAND, bytes((self._info(name).code,)), reserved).build()

    def build_parameter_block(self, command: str, block: Payload | Mapping[str, object], reserved: int = 0) -> bytes:
        """The data frame carrying the parameter block that must follow `command`: a payload object
        or raw field values of its table (a name the table does not have is refused, MALFORMED)."""
        info = self._info(command)
        block = self.parameter_block(command, block)
        if info.parameter_block is None or info.parameter_block != block.NAME:
            expected = info.parameter_block or "no parameter block"
            raise IlahrsError(ErrorKind.UNEXPECTED_MESSAGE, None, None, f"{command} takes {expected}, not {block.NAME}")
        return Frame(MessageType.DATA, block.build(), reserved).build()

    def decode_command(self, data: bytes | bytearray | memoryview) -> tuple[int, tuple[str, ...]]:
        """The code and sorted ICD name(s) of a command frame."""
        frame = Frame.parse(data)
        if frame.message_type != MessageType.COMMAND:
            raise IlahrsError(ErrorKind.BAD_MESSAGE_TYPE, MESSAGE_TYPE_OFFSET, "message_type", "not a command frame")
        if len(frame.payload) != 1:
            detail = "a command has a one-byte payload"
            raise IlahrsError(ErrorKind.BAD_LENGTH, MESSAGE_LENGTH_OFFSET, "message_length", detail)
        code = frame.payload[0]
        names = self.codes.get(code)
        if names is None:
            raise IlahrsError(ErrorKind.UNKNOWN_COMMAND, PAYLOAD_OFFSET, None, f"no command has code {code:#04x}")
        return code, names

    def ack_for(self, message: bytes | bytearray | memoryview) -> bytes:
        """The acknowledgement frame for a host message: a data frame carrying its checksum (E12)."""
        frame = Frame.parse(message)
        table = self.acknowledgement
        payload = table.from_raw({table.FIELDS[0].name: frame.checksum})
        return Frame(MessageType.DATA, payload.build()).build()
