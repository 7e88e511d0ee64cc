# Copied from generator/targets/python/runtime/session/__init__.py for spec/ilahrs.yaml,
# spec hash e075094c86a09f5e6758923635c18e3bbdff7468c7c93495887a7d5071ed5862.
# Do not edit: change the runtime source and run `make generate`.
"""The protocol's behaviour, sans-I/O: the reference device model (`device`, with its motion and
synthetic sensors), the host session (`host`) and requests that work from any state (`anystate`).
Above the codec and the tables (the state machine's table and its types among them); no I/O."""
