"""The protocol's behaviour, sans-I/O: the reference device model (`device`, with its motion and
synthetic sensors), the host session (`host`) and requests that work from any state (`anystate`).
Above the codec and the tables (the state machine's table and its types among them); no I/O."""
