# Generated from spec/ilahrs.yaml, spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the spec or the generator and run `make generate`.
"""`ilahrs.session.anystate` under the path of earlier releases."""

from .session.anystate import *  # noqa: F403
