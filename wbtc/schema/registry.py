"""The node schema as the rest of wbtc uses it: one `NodeSchema` per built-in node type.

Built once from the data table `wbtc.schema.nodes`: inherited fields are flattened (a node that
re-declares an inherited field replaces it), defaults and allowed values are parsed from their VRML
text on first use, and near-miss names get a "did you mean" suggestion.
"""

from __future__ import annotations

import difflib
from dataclasses import dataclass, field
from functools import cached_property, lru_cache
from typing import Any

from wbtc.schema.nodes import ALIASES, NODES
from wbtc.schema.spec import FieldDecl, NodeDecl

#: Roles that may stand in a `children` list (the "child" pseudo-role of the table). Geometry is
#: among them because a Pose/Transform/Group used as a boundingObject holds bare geometries.
CHILD_ROLES = frozenset({"group", "solid", "shape", "light", "joint", "other", "scene", "geometry"})


@dataclass(slots=True)
class FieldSchema:
    """One field of a built-in node, with its default parsed lazily."""

    decl: FieldDecl
    _default: Any = field(default=None, repr=False)
    _parsed: bool = field(default=False, repr=False)
    _allowed: list[Any] | None = field(default=None, repr=False)

    @property
    def name(self) -> str:
        """The field name."""
        return self.decl.name

    @property
    def type(self) -> str:
        """The VRML type ("SFVec3f")."""
        return self.decl.type

    @property
    def kind(self) -> str:
        """field, vrmlField, hiddenField or deprecatedField."""
        return self.decl.kind

    @property
    def accepts(self) -> frozenset[str] | None:
        """Roles accepted by a node-valued field ("child" expanded), or None for any."""
        if self.decl.accepts is None:
            return None
        roles = set(self.decl.accepts.split())
        if "child" in roles:
            roles = (roles - {"child"}) | CHILD_ROLES
        return frozenset(roles)

    @property
    def default(self) -> Any:
        """The typed default value."""
        if not self._parsed:
            self._default = _parse_typed(self.decl.default, self.decl.type)
            self._parsed = True
        return self._default

    @property
    def allowed(self) -> list[Any] | None:
        """The typed allowed values, or None when any value is allowed."""
        if self.decl.allowed is None:
            return None
        if self._allowed is None:
            self._allowed = list(_parse_typed("[" + self.decl.allowed + "]", "MF" + self.decl.type[2:]))
        return self._allowed


@dataclass(slots=True)
class NodeSchema:
    """A built-in node type with all its fields (inherited ones included), in declaration order."""

    name: str
    role: str
    fields: dict[str, FieldSchema]
    lineage: tuple[str, ...]
    deprecated: bool = False

    def field(self, name: str) -> FieldSchema | None:
        """The field called `name`, or None."""
        return self.fields.get(name)

    def suggest(self, name: str) -> str | None:
        """The field name closest to a misspelled `name`, if one is close enough."""
        return suggest(name, self.fields)

    def is_a(self, type_name: str) -> bool:
        """True if this node type is `type_name` or derives from it (Robot is a Solid)."""
        return type_name in self.lineage

    @cached_property
    def node_fields(self) -> tuple[str, ...]:
        """Names of the SFNode and MFNode fields."""
        return tuple(n for n, f in self.fields.items() if f.type.endswith("Node"))


def suggest(name: str, candidates: Any) -> str | None:
    """The candidate closest to `name` (case-insensitive first), or None."""
    candidates = list(candidates)
    lowered = {c.lower(): c for c in candidates}
    if name.lower() in lowered:
        return lowered[name.lower()]
    matches = difflib.get_close_matches(name, candidates, n=1, cutoff=0.7)
    return matches[0] if matches else None


def _parse_typed(text: str, field_type: str) -> Any:
    from wbtc.vrml.parser import parse_value
    from wbtc.vrml.values import coerce

    return coerce(parse_value(text, "<schema>"), field_type, "schema default", lambda _: False)


def _flatten(decl: NodeDecl, by_name: dict[str, NodeDecl]) -> tuple[list[FieldDecl], tuple[str, ...]]:
    chain = [decl]
    while chain[-1].extends is not None:
        chain.append(by_name[chain[-1].extends])
    fields: dict[str, FieldDecl] = {}
    for ancestor in reversed(chain):
        for field_decl in ancestor.fields:
            fields[field_decl.name] = field_decl  # a re-declaration replaces the inherited field
    return list(fields.values()), tuple(d.name for d in chain)


@lru_cache(maxsize=1)
def _registry() -> dict[str, NodeSchema]:
    by_name = {decl.name: decl for decl in NODES}
    registry = {}
    for decl in NODES:
        fields, lineage = _flatten(decl, by_name)
        registry[decl.name] = NodeSchema(decl.name, decl.role, {f.name: FieldSchema(f) for f in fields},
                                         lineage, decl.deprecated)
    return registry


def node_schema(type_name: str) -> NodeSchema | None:
    """The schema of a built-in node type (old names mapped to new ones), or None for a PROTO."""
    registry = _registry()
    schema = registry.get(type_name)
    if schema is None and type_name in ALIASES:
        schema = registry.get(ALIASES[type_name])
    return schema


def builtin_names() -> list[str]:
    """Every built-in node type name."""
    return list(_registry())
