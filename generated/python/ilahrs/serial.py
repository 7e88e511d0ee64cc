# Generated from spec/ilahrs.yaml, spec hash 905562f909021aa2014695e63891380eb8bec4c960db652411cc7de9726e784b.
# Do not edit: change the spec or the generator and run `make generate`.
"""`ilahrs.edge.serial` under the path of earlier releases."""

from .edge.serial import *  # noqa: F403
