"""`python -m generator diff`: what changed between two specs (generator/diff/compare.py)."""

from .compare import (
    ADDITIVE,
    API,
    BUMPS,
    CLASSES,
    DOCS,
    RULES,
    WIRE,
    Change,
    actual_bump,
    bump_is_enough,
    compare,
    main,
    required_bump,
    wire_facts,
    wire_fingerprint,
    write_junit,
)

__all__ = [
    "ADDITIVE",
    "API",
    "BUMPS",
    "CLASSES",
    "DOCS",
    "RULES",
    "WIRE",
    "Change",
    "actual_bump",
    "bump_is_enough",
    "compare",
    "main",
    "required_bump",
    "wire_facts",
    "wire_fingerprint",
    "write_junit",
]
