# Copied from generator/targets/python/runtime/edge/__init__.py for spec/ilahrs.yaml,
# spec hash e075094c86a09f5e6758923635c18e3bbdff7468c7c93495887a7d5071ed5862.
# Do not edit: change the runtime source and run `make generate`.
"""The I/O edges over the sans-I/O session: the serial client (`serial`), the virtual device on a
pty or loopback socket (`simulate`) and its test-only misbehaviours (`misbehave`)."""
