"""Spec prose as the model holds it."""

from __future__ import annotations


def prose(value: object) -> str:
    """Spec prose on one line: the line breaks and indentation of a YAML block become single spaces
    (None becomes empty)."""
    return " ".join(str(value or "").split())
