"""What PROTO expansion leaves in a scene: each expanded node's instance record, the expansion report.

Apart from the expander (`wbtc.proto.expand`) so that unpickling a scene from `wbtc.world_cache`
(whose nodes keep their `ProtoInstance`) does not load the expander, the template renderer and the
scene builder at start-up.
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, field
from typing import Any

from wbtc.errors import Diagnostic, Span
from wbtc.proto.resolve import ProtoSource


@dataclass(slots=True)
class Typed:
    """A value already typed by an outer PROTO, passed by IS into a nested instance's field."""

    type: str
    value: Any
    span: Span | None = None


@dataclass(slots=True)
class ProtoInstance:
    """What an expanded root node remembers about the instance it came from."""

    name: str
    source: ProtoSource
    values: dict[str, Any]
    span: Span
    def_name: str | None = None
    inner: ProtoInstance | None = None
    #: This instance's fields written `IS param` in the PROTO body holding it (field -> param of `owner`).
    links: dict[str, str] | None = None
    #: The instance (one level of a PROTO chain) whose body holds this one; None in the world itself.
    owner: ProtoInstance | None = None
    #: The `context.id` this level's template was rendered with: the node id the instance gets.
    context_id: int | None = None

    def claimed_id(self) -> int | None:
        """The node id a template claimed by reading `context.id` (the first level that did)."""
        level: ProtoInstance | None = self
        while level is not None and level.context_id is None:
            level = level.inner
        return level.context_id if level is not None else None


@dataclass(slots=True)
class Expansion:
    """What expanding a scene found: PROTO sources, counts of instances written in the world."""

    sources: dict[str, ProtoSource | None] = field(default_factory=dict)
    counts: Counter[str] = field(default_factory=Counter)
    warnings: list[Diagnostic] = field(default_factory=list)
    errors: list[Diagnostic] = field(default_factory=list)
    console: list[str] = field(default_factory=list)
