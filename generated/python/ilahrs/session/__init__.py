# Copied from generator/targets/python/runtime/session/__init__.py for spec/ilahrs.yaml,
# spec hash 7c7bff7a4eb096f2155fc3604f09bf92d9cb73a52d0059845310eba9f5ff0c74.
# Do not edit: change the runtime source and run `make generate`.
"""The protocol's behaviour, sans-I/O: the reference device model (`device`, with its motion and
synthetic sensors), the host session (`host`) and requests that work from any state (`anystate`).
Above the codec and the tables (the state machine's table and its types among them); no I/O."""
