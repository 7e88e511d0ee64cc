# Copied from generator/targets/python/runtime/session/__init__.py for spec/ilahrs.yaml,
# spec hash 905562f909021aa2014695e63891380eb8bec4c960db652411cc7de9726e784b.
# Do not edit: change the runtime source and run `make generate`.
"""The protocol's behaviour, sans-I/O: the reference device model (`device`, with its motion and
synthetic sensors), the host session (`host`) and requests that work from any state (`anystate`).
Above the codec and the tables (the state machine's table and its types among them); no I/O."""
