# Copied from generator/targets/python/runtime/errors.py for spec/ilahrs.yaml,
# spec hash 38d8054fc9091a0f2db18707b13da0eb865efacbd31314c577a8365c9c4e97c8.
# Do not edit: change the runtime source and run `make generate`.
"""Errors: one list of kinds for every ilahrs binding (the spec's `errors`, in `ilahrs.spec`)."""

from __future__ import annotations

from .spec import ErrorKind

__all__ = ["ErrorKind", "IlahrsError"]


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
