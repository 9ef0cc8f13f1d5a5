"""The typed scene: nodes with checked values, DEF/USE bound, version and axes recorded."""

from wbtc.scene.build import NodeBuilder, build_scene
from wbtc.scene.model import Node, Scene, walk

__all__ = ["Node", "NodeBuilder", "Scene", "build_scene", "walk"]
