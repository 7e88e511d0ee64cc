# Copied from generator/targets/python/runtime/session/__init__.py for spec/ilahrs.yaml,
# spec hash 509a20d572b51070813f406350f044557d3a84d394e7f0ead989af38b8770d0d.
# Do not edit: change the runtime source and run `make generate`.
"""The protocol's behaviour, sans-I/O: the reference device model (`device`, with its motion and
synthetic sensors), the host session (`host`) and requests that work from any state (`anystate`).
Above the codec and the tables (the state machine's table and its types among them); no I/O."""
