"""The I/O edges over the sans-I/O session: the serial client (`serial`), the virtual device on a
pty or loopback socket (`simulate`) and its test-only misbehaviours (`misbehave`)."""
