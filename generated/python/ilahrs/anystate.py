# Generated from spec/ilahrs.yaml, spec hash 7c7bff7a4eb096f2155fc3604f09bf92d9cb73a52d0059845310eba9f5ff0c74.
# Do not edit: change the spec or the generator and run `make generate`.
"""`ilahrs.session.anystate` under the path of earlier releases."""

from .session.anystate import *  # noqa: F403
