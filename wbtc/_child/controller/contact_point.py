"""``ContactPoint``: one contact of a solid, as ``Node.getContactPoints()`` returns them."""

from __future__ import annotations

from collections.abc import Sequence


class ContactPoint:
    """A contact point: its world position and the id of the node in contact.

    As in Webots, ``point`` is a tuple ``(x, y, z)`` and ``node_id`` the unique id of the solid touching there
    (``Supervisor.getFromId(node_id)`` gives its node).
    """

    def __init__(self, point: Sequence) -> None:
        """Build from ``(x, y, z, node_id)``, the layout Webots unpacks from its C structure."""
        self.point = tuple(float(v) for v in point[0:3])
        self.node_id = int(point[3])

    def getPoint(self) -> tuple[float, float, float]:
        """The contact position in world coordinates."""
        return self.point

    def getNodeId(self) -> int:
        """The unique id of the node in contact."""
        return self.node_id

    def __repr__(self) -> str:
        return f"ContactPoint(point={self.point!r}, node_id={self.node_id})"
