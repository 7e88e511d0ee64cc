"""Validation of the commands (part of generator.validate): names, ids and codes used once unless
a code is declared shared, and every mode, payload and output a command names exists."""

from __future__ import annotations

from typing import Any

from ..load import LoadedSpec, PathKey
from .common import Names, duplicates, unique


def check_commands(spec: LoadedSpec, names: Names) -> None:
    """Raise SpecError for the first problem with a command, in the order of the spec."""
    commands = spec.data["commands"]
    duplicates(((("commands", i, "name"), c["name"]) for i, c in enumerate(commands)), "command name", spec)
    unique(spec, commands, ("commands",), "id", "command id")
    by_name = {c["name"]: c for c in commands}
    by_code: dict[int, list[int]] = {}
    for i, c in enumerate(commands):
        by_code.setdefault(c["code"], []).append(i)
    for i, c in enumerate(commands):
        path: PathKey = ("commands", i)
        _check_references(spec, c, path, names)
        _check_shared_code(spec, i, by_name, [k for k in by_code[c["code"]] if k != i])
        if "begins_calibration" in c:
            values = [v["name"] for v in names.enums.get("calibration_type", {}).get("values", [])]
            if c["begins_calibration"] not in values:
                raise spec.error(
                    (*path, "begins_calibration"), f"{c['begins_calibration']!r} is not a calibration_type value"
                )
        for j, former in enumerate(c.get("former_names", [])):
            if former["name"] in by_name:
                raise spec.error(
                    (*path, "former_names", j, "name"), f"former name {former['name']!r} is a current command name"
                )


def _check_references(spec: LoadedSpec, c: dict[str, Any], path: PathKey, names: Names) -> None:
    """The modes, payloads and output the command names exist; a `data` response, and only it,
    names payloads."""
    for j, mode in enumerate(c["valid_in"]):
        if mode not in names.modes:
            raise spec.error((*path, "valid_in", j), f"unknown mode {mode!r}")
    for j, name in enumerate(c["response"].get("payloads", [])):
        if name not in names.payloads:
            raise spec.error((*path, "response", "payloads", j), f"unknown payload {name!r}")
    kind = c["response"]["kind"]
    if (kind == "data") != ("payloads" in c["response"]):
        raise spec.error((*path, "response"), "a `data` response, and only it, names its payloads")
    if "parameter_block" in c and c["parameter_block"] not in names.payloads:
        raise spec.error((*path, "parameter_block"), f"unknown payload {c['parameter_block']!r}")
    if "starts" in c:
        if c["starts"]["mode"] not in names.modes:
            raise spec.error((*path, "starts", "mode"), f"unknown mode {c['starts']['mode']!r}")
        output = c["starts"]["output"]
        if output != "nmea" and output not in names.payloads:
            raise spec.error((*path, "starts", "output"), f"unknown output {output!r}")
        if output == "nmea" and "nmea" not in spec.data:
            raise spec.error((*path, "starts", "output"), "output 'nmea' needs an `nmea` section")


def _check_shared_code(spec: LoadedSpec, i: int, by_name: dict[str, Any], others: list[int]) -> None:
    """Command `i` shares its code (with the commands at `others`) only with the partner it declares,
    which declares it back; of a shared code's names exactly one is the default."""
    commands = spec.data["commands"]
    c = commands[i]
    path: PathKey = ("commands", i)
    partner = c.get("shares_code_with")
    if partner is not None:
        _check_partner(spec, c, path, by_name)
    for k in others:
        other = commands[k]
        if k < i and partner != other["name"]:
            raise spec.error(
                (*path, "code"),
                f"duplicate command code {c['code']:#04x} ({c['name']} and {other['name']})"
                " not declared with shares_code_with",
            )
    if others and partner is not None:
        group = [c, *(commands[k] for k in others)]
        defaults = [x["name"] for x in group if x.get("default_for_code")]
        if len(defaults) != 1:
            raise spec.error(
                (*path, "shares_code_with"),
                f"exactly one of {sorted(x['name'] for x in group)} must be default_for_code (found {defaults})",
            )
    elif c.get("default_for_code"):
        raise spec.error((*path, "default_for_code"), "default_for_code only applies to a shared code")


def _check_partner(spec: LoadedSpec, c: dict[str, Any], path: PathKey, by_name: dict[str, Any]) -> None:
    """The command named by `shares_code_with` exists, has the same code and names `c` back."""
    partner = c["shares_code_with"]
    if partner not in by_name:
        raise spec.error((*path, "shares_code_with"), f"unknown command {partner!r}")
    if by_name[partner]["code"] != c["code"]:
        raise spec.error(
            (*path, "shares_code_with"),
            f"{partner!r} has code {by_name[partner]['code']:#04x}, not {c['code']:#04x}",
        )
    if by_name[partner].get("shares_code_with") != c["name"]:
        raise spec.error((*path, "shares_code_with"), f"{partner!r} must declare shares_code_with: {c['name']}")
