"""Reading Webots VRML text: header, grammar, syntax tree.

The names below load their module at first use (PEP 562): the scene's own classes need only
`wbtc.vrml.syntax`, so a run whose world comes from `wbtc.world_cache` never loads the parser.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from wbtc.vrml.header import Version, read_header
    from wbtc.vrml.parser import parse_file, parse_text, parse_value

_HOMES = {"Version": "wbtc.vrml.header", "read_header": "wbtc.vrml.header", "parse_file": "wbtc.vrml.parser",
          "parse_text": "wbtc.vrml.parser", "parse_value": "wbtc.vrml.parser"}

__all__ = ["Version", "parse_file", "parse_text", "parse_value", "read_header"]


def __getattr__(name: str) -> Any:
    if name not in _HOMES:
        raise AttributeError(f"module 'wbtc.vrml' has no attribute {name!r}")
    return getattr(importlib.import_module(_HOMES[name]), name)
