"""`python -m ilahrs`: the `ilahrs` command (ilahrs.cli, one module per subcommand)."""

from __future__ import annotations

import sys

from .cli import main

__all__ = ["main"]

if __name__ == "__main__":
    sys.exit(main())
