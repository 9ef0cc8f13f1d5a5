"""Declarations used by the node-schema table (`wbtc.schema.nodes`).

The table is data: each built-in node is declared with `node(...)` and its fields with `f(...)`.
Defaults and allowed values are written as VRML text, exactly as in Webots' node reference, and
are parsed into typed values when the schema is loaded (`wbtc.schema.registry`).
"""

from __future__ import annotations

from dataclasses import dataclass, field

#: The eighteen VRML field types Webots uses.
FIELD_TYPES = (
    "SFBool", "SFInt32", "SFFloat", "SFVec2f", "SFVec3f", "SFRotation", "SFColor", "SFString", "SFNode",
    "MFBool", "MFInt32", "MFFloat", "MFVec2f", "MFVec3f", "MFRotation", "MFColor", "MFString", "MFNode",
)

#: Field keywords: `field` (normal), `vrmlField` (VRML97 field), `hiddenField` (saved state such as
#: a joint's `position`), `deprecatedField` (accepted for old files, converted or ignored).
FIELD_KINDS = ("field", "vrmlField", "hiddenField", "deprecatedField")


@dataclass(frozen=True, slots=True)
class FieldDecl:
    """One field of a built-in node, as written in the table."""

    name: str
    type: str
    default: str
    kind: str = "field"
    allowed: str | None = None
    accepts: str | None = None
    doc: str = ""

    def __post_init__(self) -> None:
        if self.type not in FIELD_TYPES:
            raise ValueError(f"unknown field type {self.type!r} for field {self.name!r}")
        if self.kind not in FIELD_KINDS:
            raise ValueError(f"unknown field kind {self.kind!r} for field {self.name!r}")


@dataclass(frozen=True, slots=True)
class NodeDecl:
    """One built-in node type: its role, the type it extends and its own fields."""

    name: str
    role: str
    fields: tuple[FieldDecl, ...] = field(default_factory=tuple)
    extends: str | None = None
    deprecated: bool = False
    doc: str = ""


def f(name: str, type_: str, default: str, kind: str = "field", *, allowed: str | None = None,
      accepts: str | None = None, doc: str = "") -> FieldDecl:
    """Declare a field.

    Args:
        name: the field name.
        type_: one of `FIELD_TYPES`.
        default: the default value as VRML text ("2 2 2", '"solid"', "TRUE", "NULL", "[]").
        kind: one of `FIELD_KINDS`.
        allowed: the allowed values as VRML text ('"generic" "infra-red"'), or None for any.
        accepts: for SFNode/MFNode fields, the node roles accepted, space separated ("geometry").
        doc: a one-line description.

    Returns:
        The field declaration.
    """
    return FieldDecl(name, type_, default, kind, allowed, accepts, doc)


def node(name: str, role: str, fields: list[FieldDecl] | tuple[FieldDecl, ...] = (), *,
         extends: str | None = None, deprecated: bool = False, doc: str = "") -> NodeDecl:
    """Declare a built-in node type.

    Args:
        name: the node type name ("Solid").
        role: what the node is, used to check node-valued fields ("geometry", "solid", ...).
        fields: the fields this node adds to those of `extends`.
        extends: the node type whose fields this one inherits ("Pose" for Solid).
        deprecated: True for node types Webots only accepts in old files.
        doc: a one-line description.

    Returns:
        The node declaration.
    """
    return NodeDecl(name, role, tuple(fields), extends, deprecated, doc)
