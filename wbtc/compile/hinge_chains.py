"""Bodies linked by a chain of hinges sharing one anchor never touch each other, as in Webots.

Besides bodies connected by a joint (MuJoCo's `filterparent` and wbtc.compile.static_links), Webots'
collision callback (WbSimulationCluster::odeNearCallback) skips two bodies when one hangs below the
other through HingeJoints (Hinge2Joint and BallJoint are HingeJoints there too) whose `anchor` fields
are all equal, with at least one body between them: a shoulder or a hip built of two or three hinges
about one point, whose outer link may overlap the inner one. It climbs from the lower Solid; the first
hinge met sets the anchor, a hinge with another anchor ends the climb (the pair collides), other joints
(SliderJoint) are passed by, and reaching a Solid of the upper body after at least one hinge skips the
pair. It applies to bodies with Physics only (ODE bodies): a static base is not such a body.

Here each endPoint body remembers its joint's anchor as written (CompileContext.hinge_anchors); Solids
fixed to a body (no joint) are that body, as Webots merges them into one ODE body. Pairs found get
explicit excludes between their bodies that have collision geoms, which matters only where the two
could collide: within a robot whose `selfCollision` is TRUE, or between Solids outside robots.

Not honoured: Webots compares the anchors as written in each joint's own parent frame; so does this.
"""

from __future__ import annotations

from collections.abc import Callable

import mujoco
import numpy as np

from wbtc.compile.static_links import collides, welded_group

#: Webots' WbVector3::almostEquals tolerance on each coordinate.
TOLERANCE = 1e-10


def exclude_hinge_chains(spec: mujoco.MjSpec, anchors: dict[str, tuple[float, float, float]],
                         moves: Callable[[mujoco.MjsBody], bool]) -> int:
    """Add excludes for the pairs of bodies Webots' hinge-chain rule spares; returns how many."""
    if len(anchors) < 2:
        return 0
    bodies = spec.worldbody.find_all(mujoco.mjtObj.mjOBJ_BODY)
    existing = {frozenset((e.bodyname1, e.bodyname2)) for e in spec.excludes}
    added = 0
    for lower in bodies:
        if not len(lower.joints) or not moves(lower):
            continue  # climb from each ODE body's own (jointed) body
        for upper in _skipped_ancestors(lower, anchors, moves):
            for a in welded_group(lower):
                for b in welded_group(upper):
                    key = frozenset((a.name, b.name))
                    if key in existing or not (collides(a) and collides(b)):
                        continue
                    existing.add(key)
                    spec.add_exclude(bodyname1=a.name, bodyname2=b.name)
                    added += 1
    return added


def _skipped_ancestors(lower: mujoco.MjsBody, anchors: dict[str, tuple[float, float, float]],
                       moves: Callable[[mujoco.MjsBody], bool]) -> list[mujoco.MjsBody]:
    """The jointed bodies above `lower` that Webots' climb reaches while the hinges' anchors agree.

    The first one is left out: it is jointed to `lower` directly, a pair every collider skips already.
    """
    found: list[mujoco.MjsBody] = []
    first: tuple[float, float, float] | None = None
    passed = 0  # ODE bodies met above `lower`
    node: mujoco.MjsBody | None = lower
    while node is not None and node.name != "world":
        if node is not lower and len(node.joints):  # a Solid of another ODE body
            if not moves(node):
                break  # welded to the world: no ODE body, Webots' rule stops
            passed += 1
            if first is not None and passed > 1:
                found.append(node)
        anchor = anchors.get(node.name)  # the hinge above this body, if it is one
        if anchor is not None:
            if first is None:
                first = anchor
            elif not np.allclose(anchor, first, rtol=0.0, atol=TOLERANCE):
                break
        node = node.parent
    return found
