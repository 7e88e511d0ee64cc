# Copied from generator/targets/python/runtime/compat.py for spec/ilahrs.yaml,
# spec hash be1a7f680a52339a957fa7513d00f92b22f2d5205e71718d9f5ea37a0f7ce887.
# Do not edit: change the runtime source and run `make generate`.
"""What the package uses from Python 3.11 and later, on 3.10 too: `StrEnum`."""

from __future__ import annotations

import sys
from enum import Enum

__all__ = ["StrEnum"]

if sys.version_info >= (3, 11):
    from enum import StrEnum
else:

    class StrEnum(str, Enum):
        """Members that are strings, whose str() and format() are the value (enum.StrEnum of 3.11)."""

        def __str__(self) -> str:
            return str.__str__(self)

        def __format__(self, spec: str) -> str:
            return str.__format__(str(self), spec)
