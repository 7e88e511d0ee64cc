# Generated from spec/ilahrs.yaml, spec hash af3b7671e6a989940ee52f3a699e8d4497531bc68066f57c0c5f2b4e271b050f.
# Do not edit: change the spec or the generator and run `make generate`.
"""Errors: one list of kinds for every ilahrs binding (spec `errors`)."""

from __future__ import annotations

from enum import StrEnum

__all__ = ["ErrorKind", "IlahrsError"]


class ErrorKind(StrEnum):
    """What went wrong. The values are the spec's names, shared by every binding."""

    TRUNCATED = 'truncated'
    """The input ends before the frame, payload or sentence does."""
    BAD_HEADER = 'bad_header'
    """The frame does not start with AA 55, or a sentence does not start with the $PAHR identifier."""
    BAD_MESSAGE_TYPE = 'bad_message_type'
    """The message type byte is neither 0 (command) nor 1 (data) (Table 6.2)."""
    BAD_LENGTH = 'bad_length'
    """The message length is outside the bounds the spec accepts, or a payload is not the size its table
    defines."""
    BAD_CHECKSUM = 'bad_checksum'
    """The transmitted checksum does not match the one computed over the received bytes."""
    TRAILING_DATA = 'trailing_data'
    """Bytes follow the end of a complete frame, payload or sentence where none are allowed."""
    UNKNOWN_COMMAND = 'unknown_command'
    """A command code or command name that Table C.1 does not define."""
    OUT_OF_RANGE = 'out_of_range'
    """A value outside the range the spec allows for its field (refused by builders, never wrapped or
    truncated)."""
    MALFORMED = 'malformed'
    """Text that does not follow the sentence grammar (missing or extra fields, a bad number)."""
    BUFFER_TOO_SMALL = 'buffer_too_small'
    """The caller's output buffer cannot hold the message being built."""
    UNEXPECTED_MESSAGE = 'unexpected_message'
    """The peer sent a message that the protocol state does not allow (host session and device model)."""
    TIMEOUT = 'timeout'
    """An answer the protocol requires did not arrive in time (host session)."""


class IlahrsError(ValueError):
    """Bad input: what (`kind`), where (`offset`, a byte or character index into the input) and,
    where it applies, which `field`."""

    kind: ErrorKind
    offset: int | None
    field: str | None

    def __init__(self, kind: ErrorKind, offset: int | None = None, field: str | None = None, detail: str = "") -> None:
        self.kind = kind
        self.offset = offset
        self.field = field
        self.detail = detail
        super().__init__(str(self))

    def __str__(self) -> str:
        text = str(self.kind.value)
        if self.field is not None:
            text += f" in {self.field}"
        if self.offset is not None:
            text += f" at offset {self.offset}"
        if self.detail:
            text += f": {self.detail}"
        return text

    def __reduce__(self) -> tuple[type[IlahrsError], tuple[ErrorKind, int | None, str | None, str]]:
        return (IlahrsError, (self.kind, self.offset, self.field, self.detail))
