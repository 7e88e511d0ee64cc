"""Name conversions shared by every target: spec names are lower_snake_case."""

from __future__ import annotations


def words(name: str) -> list[str]:
    return [w for w in name.split("_") if w]


def pascal(name: str) -> str:
    """`orientation_sensors` -> `OrientationSensors`, `start_2d2t_clb` -> `Start2d2tClb`."""
    return "".join(w[:1].upper() + w[1:] for w in words(name))


def upper(name: str) -> str:
    """`bad_checksum` -> `BAD_CHECKSUM`."""
    return "_".join(words(name)).upper()


def snake(name: str) -> str:
    return "_".join(words(name)).lower()


def hex_byte(value: int) -> str:
    return f"0x{value:02X}"


def hex_word(value: int) -> str:
    return f"0x{value:04X}"


def wrap(text: str, width: int = 88) -> list[str]:
    """Split prose into lines of at most `width` characters (never breaking words)."""
    lines: list[str] = []
    current = ""
    for word in text.split():
        if current and len(current) + 1 + len(word) > width:
            lines.append(current)
            current = word
        else:
            current = f"{current} {word}" if current else word
    if current:
        lines.append(current)
    return lines
