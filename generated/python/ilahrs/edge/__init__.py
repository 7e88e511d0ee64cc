# Copied from generator/targets/python/runtime/edge/__init__.py for spec/ilahrs.yaml,
# spec hash 7c7bff7a4eb096f2155fc3604f09bf92d9cb73a52d0059845310eba9f5ff0c74.
# Do not edit: change the runtime source and run `make generate`.
"""The I/O edges over the sans-I/O session: the serial client (`serial`), the virtual device on a
pty or loopback socket (`simulate`) and its test-only misbehaviours (`misbehave`)."""
