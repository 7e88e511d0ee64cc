# Copied from generator/targets/python/runtime/__main__.py for spec/ilahrs.yaml,
# spec hash 7c7bff7a4eb096f2155fc3604f09bf92d9cb73a52d0059845310eba9f5ff0c74.
# Do not edit: change the runtime source and run `make generate`.
"""`python -m ilahrs`: the `ilahrs` command (ilahrs.cli, one module per subcommand)."""

from __future__ import annotations

import sys

from .cli import main

__all__ = ["main"]

if __name__ == "__main__":
    sys.exit(main())
