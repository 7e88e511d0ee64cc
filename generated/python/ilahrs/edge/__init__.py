# Copied from generator/targets/python/runtime/edge/__init__.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""The I/O edges over the sans-I/O session: the serial client (`serial`), the virtual device on a
pty or loopback socket (`simulate`) and its test-only misbehaviours (`misbehave`)."""
