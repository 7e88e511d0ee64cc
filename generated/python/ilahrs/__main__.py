# Copied from generator/targets/python/runtime/__main__.py for spec/ilahrs.yaml,
# spec hash e075094c86a09f5e6758923635c18e3bbdff7468c7c93495887a7d5071ed5862.
# Do not edit: change the runtime source and run `make generate`.
"""`python -m ilahrs`: the `ilahrs` command (ilahrs.cli, one module per subcommand)."""

from __future__ import annotations

import sys

from .cli import main

__all__ = ["main"]

if __name__ == "__main__":
    sys.exit(main())
