# Generated from spec/ilahrs.yaml, spec hash e075094c86a09f5e6758923635c18e3bbdff7468c7c93495887a7d5071ed5862.
# Do not edit: change the spec or the generator and run `make generate`.
"""`ilahrs.cli.plot` under the path of earlier releases."""

from .cli.plot import *  # noqa: F403
