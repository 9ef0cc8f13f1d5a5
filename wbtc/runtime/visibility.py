"""A supervisor's `Node.setVisibility(fromNode, visible)`: shapes hidden from one camera only.

Webots stops drawing a node (and everything below it) in the images of one Camera, Lidar or
RangeFinder; other cameras still see it. Here the (node, viewer) pairs are kept by node, and the
geoms each model camera must skip (`Simulation.invisible`, read by the offscreen renderer) are
worked out from them again after every model rebuild, so hiding survives a node's removal or import
elsewhere; a hidden node that is removed simply has no geoms left.

Not honoured yet: hiding from the Viewpoint (the window and recordings draw every shape).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from wbtc.compile.context import VISUAL_GROUP, info
from wbtc.scene.model import Node

if TYPE_CHECKING:
    from wbtc.runtime.simulation import Simulation


def set_visibility(sim: Simulation, node: Node, viewer: Node, visible: bool) -> None:
    """Show or hide `node` in the images of the device node `viewer`."""
    key = (id(node), id(viewer))
    if visible:
        sim.hidden.pop(key, None)
    else:
        sim.hidden[key] = (node, viewer)
    refresh(sim)


def refresh(sim: Simulation) -> None:
    """Work out every camera's invisible geoms from the hidden (node, viewer) pairs, for the current model."""
    sim.invisible.clear()
    if not sim.hidden:
        return
    by_info: dict[str, list[int]] = {}
    model = sim.model
    for geom in sim.result.spec.geoms:
        gid = int(geom.id)
        if 0 <= gid < model.ngeom and int(model.geom_group[gid]) == VISUAL_GROUP:
            by_info.setdefault(geom.info, []).append(gid)
    for node, viewer in sim.hidden.values():
        cameras = _cameras(sim, viewer)
        geoms = {g for part in _subtree(node) for g in by_info.get(info(part), [])}
        for camera in cameras:
            sim.invisible.setdefault(camera, set()).update(geoms)


def _cameras(sim: Simulation, viewer: Node) -> list[int]:
    """The model cameras of a Camera, Lidar or RangeFinder device node (none for the Viewpoint)."""
    return [sim.model.camera(dev.camera).id for robot in sim.robots for dev in robot.entry.devices
            if dev.node is viewer and dev.camera]


def _subtree(node: Node) -> list[Node]:
    """`node` and every node below it (children, geometry, appearance ...)."""
    found, stack = [], [node]
    while stack:
        current = stack.pop()
        found.append(current)
        stack += list(current.child_nodes())
    return found
