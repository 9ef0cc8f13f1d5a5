"""The typed scene: nodes with checked values, DEF/USE bound, version and axes recorded.

The names below load their module at first use (PEP 562): unpickling a scene from
`wbtc.world_cache` needs `wbtc.scene.model` only, not the builder and the value checks.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from wbtc.scene.build import NodeBuilder, build_scene
    from wbtc.scene.model import Node, Scene, walk

_HOMES = {"Node": "wbtc.scene.model", "Scene": "wbtc.scene.model", "walk": "wbtc.scene.model",
          "NodeBuilder": "wbtc.scene.build", "build_scene": "wbtc.scene.build"}

__all__ = ["Node", "NodeBuilder", "Scene", "build_scene", "walk"]


def __getattr__(name: str) -> Any:
    if name not in _HOMES:
        raise AttributeError(f"module 'wbtc.scene' has no attribute {name!r}")
    return getattr(importlib.import_module(_HOMES[name]), name)
