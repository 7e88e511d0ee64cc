"""Step 1 of the pipeline: read a spec file into plain data, remembering where each value was.

The result is the parsed YAML (dicts, lists, scalars) plus a map from every path in it
(a tuple of keys and list indices) to the line it starts on, so that validation errors
can name file, line and path.
"""

from __future__ import annotations

import hashlib
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import yaml
from yaml.nodes import MappingNode, Node, ScalarNode, SequenceNode

PathKey = tuple[str | int, ...]

# Bounds on what a spec file may be. The ICD's spec is some 60 kB, 9 levels deep, and its longest
# prose is about 1 kB; a spec past these is a mistake, not a protocol, and it would otherwise cost
# the generator gigabytes (a doc string is copied into every binding) or end in a RecursionError.
MAX_FILE_BYTES = 4 * 1024 * 1024
MAX_DEPTH = 64
MAX_DOC_CHARS = 16 * 1024


class SpecError(Exception):
    """A spec that cannot be used: names the file, line and path of the problem."""

    def __init__(self, file: str, line: int | None, path: PathKey, message: str) -> None:
        self.file = file
        self.line = line
        self.path = path
        self.message = message
        super().__init__(str(self))

    def __str__(self) -> str:
        where = self.file if self.line is None else f"{self.file}:{self.line}"
        return f"{where}: {format_path(self.path)}: {self.message}"


def format_path(path: PathKey) -> str:
    """Render a path as `payloads[3].fields[0].type`."""
    text = ""
    for part in path:
        if isinstance(part, int):
            text += f"[{part}]"
        else:
            text += f".{part}" if text else part
    return text or "(top)"


@dataclass(frozen=True)
class LoadedSpec:
    """A spec file as data, with its source name, hash and line map."""

    data: dict[str, Any]
    file: str
    sha256: str
    lines: dict[PathKey, int]
    key_lines: dict[PathKey, int] = field(default_factory=dict)

    def line_of(self, path: PathKey) -> int | None:
        """The line where `path`, or the nearest enclosing value, starts."""
        while True:
            if path in self.lines:
                return self.lines[path]
            if not path:
                return None
            path = path[:-1]

    def error(self, path: PathKey, message: str) -> SpecError:
        return SpecError(self.file, self.line_of(path), path, message)

    def key_error(self, path: PathKey, message: str) -> SpecError:
        """An error about the mapping key that ends `path`, at the key's own line."""
        line = self.key_lines.get(path)
        return SpecError(self.file, line if line is not None else self.line_of(path), path, message)


class _Loader(yaml.SafeLoader):
    """SafeLoader whose scalars are plain YAML 1.1 values (no dates), refusing aliases and nesting
    deeper than MAX_DEPTH.

    An alias (`*name`) repeats a node; a few nested ones multiply into billions of values (the
    "billion laughs"), so a spec writes every value out and an alias is an error where it stands.
    The composer recurses once per level, so the depth is bounded before Python's stack is.
    """

    depth = 0
    file = ""

    def compose_node(self, parent: Node | None, index: int) -> Node | None:
        if self.check_event(yaml.AliasEvent):
            event = self.peek_event()  # type: ignore[no-untyped-call]
            problem = f"an alias (*{event.anchor}): a spec writes every value out, aliases are refused"
            raise yaml.composer.ComposerError(None, None, problem, event.start_mark)
        if self.depth >= MAX_DEPTH:
            event = self.peek_event()  # type: ignore[no-untyped-call]
            problem = f"nested more than {MAX_DEPTH} levels deep: a spec is never that deep"
            raise SpecError(self.file, event.start_mark.line + 1, (), problem)
        self.depth += 1
        try:
            return super().compose_node(parent, index)
        finally:
            self.depth -= 1


# Keep "2014-03-11" a string: dates have no meaning in the spec.
_Loader.yaml_implicit_resolvers = {
    key: [(tag, regexp) for tag, regexp in resolvers if tag != "tag:yaml.org,2002:timestamp"]
    for key, resolvers in yaml.SafeLoader.yaml_implicit_resolvers.items()
}


@dataclass(frozen=True)
class _Lines:
    values: dict[PathKey, int]
    keys: dict[PathKey, int]


def _convert(node: Node, path: PathKey, lines: _Lines, loader: _Loader, file: str) -> Any:
    lines.values[path] = node.start_mark.line + 1
    if isinstance(node, MappingNode):
        result: dict[str, Any] = {}
        for key_node, value_node in node.value:
            key = loader.construct_object(key_node, deep=True)
            if not isinstance(key, str):
                raise SpecError(file, key_node.start_mark.line + 1, path, f"mapping key {key!r} is not a string")
            if key in result:
                raise SpecError(file, key_node.start_mark.line + 1, path, f"duplicate key {key!r}")
            lines.keys[(*path, key)] = key_node.start_mark.line + 1
            result[key] = _convert(value_node, (*path, key), lines, loader, file)
        return result
    if isinstance(node, SequenceNode):
        return [_convert(item, (*path, index), lines, loader, file) for index, item in enumerate(node.value)]
    assert isinstance(node, ScalarNode)
    value = loader.construct_object(node, deep=True)
    if isinstance(value, str) and len(value) > MAX_DOC_CHARS:
        problem = f"a text of {len(value)} characters; a spec's text is at most {MAX_DOC_CHARS}"
        raise SpecError(file, node.start_mark.line + 1, path, problem)
    return value


def load(path: Path, display_name: str | None = None) -> LoadedSpec:
    """Read and parse `path`. `display_name` is what messages call the file."""
    name = display_name if display_name is not None else path.as_posix()
    try:
        with path.open("rb") as stream:
            raw = stream.read(MAX_FILE_BYTES + 1)
    except OSError as exc:
        raise SpecError(name, None, (), f"cannot read the spec file: {exc.strerror or exc}") from exc
    if len(raw) > MAX_FILE_BYTES:
        raise SpecError(name, None, (), f"larger than {MAX_FILE_BYTES // (1024 * 1024)} MB: a spec is never that large")
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        bad_line = raw.count(b"\n", 0, exc.start) + 1
        raise SpecError(name, bad_line, (), f"not UTF-8: byte 0x{raw[exc.start]:02X} at offset {exc.start}") from exc
    loader = _Loader(text)
    loader.file = name
    try:
        try:
            root = loader.get_single_node()
        except yaml.MarkedYAMLError as exc:
            mark = exc.problem_mark
            line = mark.line + 1 if mark is not None else None
            raise SpecError(name, line, (), f"not valid YAML: {exc.problem}") from exc
        if root is None:
            raise SpecError(name, 1, (), "the file is empty")
        lines = _Lines({}, {})
        data = _convert(root, (), lines, loader, name)
    finally:
        loader.dispose()
    if not isinstance(data, dict):
        raise SpecError(name, 1, (), "the top level must be a mapping")
    digest = hashlib.sha256(raw).hexdigest()
    return LoadedSpec(data=data, file=name, sha256=digest, lines=lines.values, key_lines=lines.keys)
