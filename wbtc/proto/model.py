"""A PROTO file read once: its interface with typed defaults, and its body (nodes or template).

Models are cached by path for the life of the process: a world with 1,400 Walls reads Wall.proto
once. Node-valued defaults are kept as syntax and built afresh for each instance, so two instances
never share body nodes.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path
from typing import Any

from wbtc.errors import ProtoError, SchemaError
from wbtc.vrml import syntax as s
from wbtc.vrml.header import Version
from wbtc.vrml.values import coerce


@dataclass(slots=True)
class InterfaceField:
    """One field of a PROTO interface."""

    decl: s.FieldDeclSyntax
    default: Any  # typed value, or the syntax of a node-valued default (built per instance)
    allowed: list[Any] | None = None

    @property
    def name(self) -> str:
        """The field name."""
        return self.decl.name

    @property
    def type(self) -> str:
        """The VRML type."""
        return self.decl.type

    @property
    def has_nodes(self) -> bool:
        """True for SFNode/MFNode fields (their default is syntax, built per instance)."""
        return self.decl.type.endswith("Node")


@dataclass(slots=True)
class ProtoModel:
    """A parsed PROTO file."""

    name: str
    path: Path
    syntax: s.ProtoSyntax
    file: s.FileSyntax
    version: Version | None
    fields: dict[str, InterfaceField] = field(default_factory=dict)

    @property
    def is_template(self) -> bool:
        """True for a procedural PROTO (its body is JavaScript or Lua template text)."""
        return self.syntax.template is not None

    @property
    def tags(self) -> frozenset[str]:
        """The header's `# tags:` words (e.g. `nonDeterministic`, `hidden`, `deprecated`)."""
        return proto_tags(self.path)


def file_stamp(path: str | Path) -> tuple[int, int]:
    """A file's size and modification time, in the keys of the caches below.

    So a long-lived program (a notebook running a world while its PROTOs are edited) reads a PROTO
    file again once it changed.
    """
    try:
        info = os.stat(path)
    except OSError:
        return (-1, 0)
    return (info.st_size, info.st_mtime_ns)


def proto_tags(path: Path) -> frozenset[str]:
    """The `# tags: a, b` words of a PROTO file's leading comment lines (empty when it has none)."""
    return _proto_tags(path, file_stamp(path))


@lru_cache(maxsize=512)
def _proto_tags(path: Path, stamp: tuple[int, int]) -> frozenset[str]:
    tags: set[str] = set()
    try:
        with open(path, encoding="utf-8", errors="replace") as handle:
            for line in handle:
                text = line.strip()
                if text and not text.startswith("#"):
                    break  # the header comments end where the PROTO (or EXTERNPROTO) lines start
                if text.lower().startswith("# tags:"):
                    tags.update(t.strip() for t in text[len("# tags:"):].split(",") if t.strip())
    except OSError:
        pass
    return frozenset(tags)


def _not_node(_value: object) -> bool:
    return False


def _interface(proto: s.ProtoSyntax, path: Path) -> dict[str, InterfaceField]:
    fields: dict[str, InterfaceField] = {}
    for decl in proto.fields:
        if decl.type.endswith("Node"):
            default: Any = decl.default
        else:
            try:
                default = coerce(decl.default, decl.type, f"default of PROTO field '{decl.name}'", _not_node)
            except SchemaError as exc:
                raise ProtoError(f"in PROTO {proto.name}: {exc.message}", exc.span) from None
        allowed = None
        if decl.restriction is not None and not decl.type.endswith("Node"):
            # The allowed values are a list of SF values; numbers may be written as one run.
            listed = coerce(s.MFList(decl.restriction, decl.span), "MF" + decl.type[2:],
                            f"restriction of '{decl.name}'", _not_node)
            allowed = [tuple(v) if isinstance(v, list) else v for v in
                       (listed.tolist() if hasattr(listed, "tolist") else listed)]
            if decl.type in ("SFVec2f", "SFVec3f", "SFColor", "SFRotation"):
                allowed = [type(default)(*v) for v in allowed]
        fields[decl.name] = InterfaceField(decl, default, allowed)
    return fields


def written_version(path: str, world: str, world_version: Version | None) -> Version | None:
    """The header version of the file a node was written in: the world's, or a PROTO file's.

    A PROTO file without a header, or any other path (a node imported from a string), counts as written
    with the world.
    """
    if path != world and path.endswith(".proto") and Path(path).is_file():
        return load_proto(Path(path)).version or world_version
    return world_version


def load_proto(path: Path) -> ProtoModel:
    """Read and cache a PROTO file (read again once it changed).

    Raises:
        WbtcError: the file cannot be read or is malformed.
    """
    return _load_proto(path, file_stamp(path))


@lru_cache(maxsize=512)
def _load_proto(path: Path, stamp: tuple[int, int]) -> ProtoModel:
    from wbtc.vrml.parser import parse_file  # here: a run from the world cache never parses

    syntax = parse_file(path)
    if not syntax.protos:
        raise ProtoError(f"{path.name} declares no PROTO", None)
    proto = syntax.protos[0]
    version = Version.parse(syntax.version) if syntax.version else None
    model = ProtoModel(proto.name, path, proto, syntax, version)
    model.fields = _interface(proto, path)
    return model
