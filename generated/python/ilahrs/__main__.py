# Copied from generator/targets/python/runtime/__main__.py for spec/ilahrs.yaml,
# spec hash 905562f909021aa2014695e63891380eb8bec4c960db652411cc7de9726e784b.
# Do not edit: change the runtime source and run `make generate`.
"""`python -m ilahrs`: the `ilahrs` command (ilahrs.cli, one module per subcommand)."""

from __future__ import annotations

import sys

from .cli import main

__all__ = ["main"]

if __name__ == "__main__":
    sys.exit(main())
