# Copied from generator/targets/python/runtime/edge/__init__.py for spec/ilahrs.yaml,
# spec hash 905562f909021aa2014695e63891380eb8bec4c960db652411cc7de9726e784b.
# Do not edit: change the runtime source and run `make generate`.
"""The I/O edges over the sans-I/O session: the serial client (`serial`), the virtual device on a
pty or loopback socket (`simulate`) and its test-only misbehaviours (`misbehave`)."""
