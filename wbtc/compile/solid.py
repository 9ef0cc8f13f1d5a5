"""Solids, Robots and grouping nodes to MuJoCo bodies, with Webots' physics rules.

Every Solid becomes a MuJoCo body (so the supervisor and the runtime can find it by name), except
a robot's massless, non-colliding Solid devices (sensors, LEDs, cameras...), which are frames of
their parent's body: Webots merges those into the parent's rigid body too. Webots' other
rules then fall out of MuJoCo's own: a top-level Solid with Physics gets a free joint; any other
Solid not reached through a Joint has no joint, so MuJoCo welds it to its parent: to the static
world when the parent is static (Webots' fixed joint), into the parent's rigid body when the
parent moves (Webots' implicit solid merging). Group, Pose and Transform are frames, not bodies;
a top-level Billboard is a body at the Viewpoint's pose (its children face the view).

Masses come from Physics nodes only: density × the volume of the Solid's own bounding objects, or
`mass`; `centerOfMass` and `inertiaMatrix` override the computed ones (an `inertiaMatrix` Webots finds
invalid is left out with its warning; one that is valid for ODE but whose principal moments no body
could have, A + B < C, which MuJoCo refuses, is replaced by their mean with a warning). Bodies get explicit
inertials and every geom is massless to MuJoCo.

Solids with `recognitionColors` are listed in the table for the runtime's camera recognition (and a
Camera's entry gets its Recognition node's fields under `recognition`).

A Solid with Physics starts with its `linearVelocity`/`angularVelocity` (the runtime sets them).

Not honoured yet: Solid `immersionProperties`, `locked`, the initial velocity
of a Solid without Physics; Physics `damping` acts on the free joint only (see `damping`);
Robot `battery`, `cpuConsumption`.
Robot `selfCollision FALSE` (the default) excludes every pair of the robot's colliding bodies.
"""

from __future__ import annotations

from typing import Any

import mujoco
import numpy as np

from wbtc.compile import (
    appearance,
    cad_shape,
    damping,
    device,
    geometry,
    joint,
    legacy_protos,
    light,
    paintable,
    propeller,
    textures,
    track,
)
from wbtc.compile.bodyless import make_kinematic
from wbtc.compile.context import CompileContext, info
from wbtc.compile.frames import Frame, axis_angle_quat
from wbtc.compile.kinematic_drive import find_drive
from wbtc.compile.table import DeviceEntry, Recognizable, RobotEntry, plain
from wbtc.compile.texture_clamp import Clamp
from wbtc.errors import INVALID_VALUE
from wbtc.scene.model import Node, Scene

_UNHONOURED = frozenset({"immersionProperties", "locked", "battery"})
JOINT_TYPES = frozenset({"HingeJoint", "Hinge2Joint", "BallJoint", "SliderJoint"})


def pose_quat(node: Node) -> np.ndarray:
    """A Pose/Solid's `rotation` field as a quaternion."""
    rot = node.get("rotation")
    return axis_angle_quat((rot[0], rot[1], rot[2]), rot[3])


class BodyBuilder:
    """Walks the expanded scene and adds bodies, geoms, joints and devices to the spec."""

    def __init__(self, ctx: CompileContext) -> None:
        self.ctx = ctx

    def walk(self, node: Node, body: mujoco.MjsBody, frame: Frame, robot: RobotEntry | None,
             dynamic: bool) -> None:
        """Add one node found in a `children` list.

        Args:
            node: the node.
            body: the MuJoCo body it belongs to.
            frame: its parent frame in `body`.
            robot: the robot whose devices it may hold.
            dynamic: True when `body` moves (it or an ancestor has Physics).
        """
        kind = node.base_type
        if node.is_proto:
            return  # an unresolved PROTO: the PROTO stage already warned
        if node.is_a("Solid"):
            self.add_solid(node, body, frame, robot, dynamic)
        elif kind == "Billboard":
            self._billboard(node, body, frame, robot, dynamic)
        elif kind == "Group":
            self.walk_children(node.get("children"), body, frame, robot, dynamic, node)
        elif kind in ("Pose", "Transform"):
            scale = np.asarray(node.get("scale"), dtype=float) if kind == "Transform" else None
            inner = frame.compose(np.asarray(node.get("translation"), dtype=float), pose_quat(node), scale)
            self.walk_children(node.get("children"), body, inner, robot, dynamic, node)
        elif kind == "Shape":
            self.add_shape(node, body, frame)
        elif kind in JOINT_TYPES:
            joint.add_joint(self, node, body, frame, robot, dynamic)
        elif kind in ("DirectionalLight", "PointLight", "SpotLight"):
            light.add_light(node, body, frame, self.ctx)
        elif kind == "Slot":
            end = joint.slot_end(node, self.ctx)
            if end is not None:
                self.walk(end, body, frame, robot, dynamic)
        elif kind == "Propeller":
            propeller.add_propeller(self, node, body, frame, robot)
        elif kind == "CadShape":
            self.ctx.cad_geoms.extend(cad_shape.add_cad_shape(node, body, frame, self.ctx))
        elif kind in ("Fluid", "Skin", "Muscle"):
            self.ctx.warn(f"{kind} is not supported by wbtc yet; it is left out", node.span)

    def _billboard(self, node: Node, body: mujoco.MjsBody, frame: Frame, robot: RobotEntry | None,
                   dynamic: bool) -> None:
        """A Billboard: its children in the Viewpoint's frame, so that they always face the view.

        Webots moves a Billboard's frame with the viewpoint (position and orientation), which makes
        its children an overlay fixed to the view. A supervisor's write to the Viewpoint recompiles
        the model, so placing the body at the Viewpoint's pose keeps up with it. A Billboard inside
        a moving body, or in a world without a Viewpoint, stays a Group.
        """
        viewpoint = world_viewpoint(self.ctx.scene)
        if viewpoint is None or body is not self.ctx.spec.worldbody:
            self.walk_children(node.get("children"), body, frame, robot, dynamic, node)
            return
        rotation = viewpoint.get("orientation")
        pose = frame.compose(np.asarray(viewpoint.get("position"), dtype=float),
                             axis_angle_quat((rotation[0], rotation[1], rotation[2]), rotation[3]))
        board = body.add_body()
        board.name = self.ctx.unique("body", "billboard")
        board.pos, board.quat = pose.pos, pose.quat
        board.info = info(node)
        self.walk_children(node.get("children"), board, Frame.identity(), robot, dynamic, node)

    def _walk_device_children(self, entry: DeviceEntry | None, node: Node, body: mujoco.MjsBody, frame: Frame,
                              robot: RobotEntry | None, dynamic: bool) -> None:
        """A Solid's (or Solid device's) children; an LED collects the lights among them."""
        led = entry is not None and entry.type == "LED"
        if led:
            self.ctx.led_lights = []
        self.walk_children(node.get("children"), body, frame, robot, dynamic, node)
        if led:
            entry.lights, self.ctx.led_lights = self.ctx.led_lights or [], None

    def walk_children(self, children: list | None, body: mujoco.MjsBody, frame: Frame,
                      robot: RobotEntry | None, dynamic: bool, owner: Node | None = None) -> None:
        """Add every node of a `children` list (of `owner`)."""
        for child in children or []:
            if isinstance(child, Node):
                # A pre-R2022a world's node in a library robot's slot: RUB axes, as it was written for.
                turned = legacy_protos.turns_content(self.ctx, owner, child, robot)
                inner = frame.compose(np.zeros(3), legacy_protos.back_turn(robot)) if turned else frame
                self.walk(child, body, inner, robot, dynamic)

    def add_shape(self, shape: Node, body: mujoco.MjsBody, frame: Frame, name: str | None = None) -> list[str]:
        """A Shape as a visual geom; returns the names of the geoms made (for LEDs)."""
        geom_node = shape.get("geometry")
        if not isinstance(geom_node, Node) or geom_node.base_type not in geometry.GEOMETRY_TYPES:
            return []
        rgba, material, path = appearance.shape_look(shape, self.ctx)
        look = shape.get("appearance")
        transform = look.get("textureTransform") if isinstance(look, Node) else None
        # In a world with a Pen, a shape gets a texture of its own and Webots' mapping (paintable).
        own = paintable.prepare(self.ctx, shape, material, path, rgba) \
            if material is not None and paintable.enabled(self.ctx) else None
        if own is not None and path is None:
            rgba = np.array([1.0, 1.0, 1.0, rgba[3]])  # its layer carries its colour
        made = geometry.add_geometry(body, geom_node, frame, self.ctx, collision=False, rgba=rgba,
                                     material=own.material if own else material, name=name,
                                     texture_transform=transform if isinstance(transform, Node) else None,
                                     texture_clamp=_texture_clamp(look, path),
                                     painted=own.painted if own else None)
        if made is None:
            return []
        if own is not None:
            paintable.register(self.ctx, made[0], own, shape)
        return [made[0].name] if made[0].name else []

    def add_solid(self, node: Node, parent: mujoco.MjsBody, frame: Frame, robot: RobotEntry | None,
                  dynamic: bool, joint_frame: Frame | None = None) -> mujoco.MjsBody:
        """One Solid (or Robot, or Solid device) as a MuJoCo body under `parent`.

        Args:
            node: the Solid.
            parent: the MuJoCo parent body.
            frame: the Solid's parent frame in `parent`.
            robot: the enclosing robot.
            dynamic: whether `parent` moves.
            joint_frame: set when a Joint made this body (its joints are added by the caller).

        Returns:
            The new body.
        """
        ctx = self.ctx
        ctx.unhonoured(node, _UNHONOURED)
        pose = frame.compose(np.asarray(node.get("translation"), dtype=float), pose_quat(node))
        turn = legacy_protos.root_turn(ctx, node, robot)
        after = turn if turn is not None else legacy_protos.identity()
        if turn is not None:  # a library robot or floor in a pre-R2022a world: see legacy_protos
            pose = pose.compose(np.zeros(3), after)
        if robot is not None and joint_frame is None and self._mergeable(node, parent):
            self._merge_device(node, parent, pose, robot, dynamic)
            return parent
        body = parent.add_body()
        body.name = ctx.unique("body", _body_name(node, robot))
        body.pos, body.quat = pose.pos, pose.quat
        body.info = info(node)
        if id(node) not in ctx.table.solids:
            ctx.table.solids[id(node)] = (body.name, frame.pos.copy(), frame.quat.copy(), after)
            ctx.table.solid_nodes[id(node)] = node
        if node.def_name and node.def_name not in ctx.table.bodies:
            ctx.table.bodies[node.def_name] = body.name
        cross_section = float(node.get("radarCrossSection") or 0.0)
        if cross_section > 0:
            ctx.table.radar_targets.append((body.name, cross_section))
        colors = plain(node.get("recognitionColors"))
        if colors:
            ctx.table.recognizable.append(Recognizable(node, body.name, [[float(c) for c in color] for color in colors],
                                                       str(node.get("model") or "")))
        physics = node.get("physics")
        has_physics = isinstance(physics, Node)
        _initial_velocity(ctx, node, body.name, has_physics)
        top_level = parent is ctx.spec.worldbody
        moves = dynamic or has_physics or joint_frame is not None
        if top_level and has_physics:
            free = body.add_freejoint()
            free.name = ctx.unique("joint", body.name)
            free.info = info(node)
        if node.is_a("Robot"):
            robot = device.add_robot(node, body, ctx)
            robot.rub = turn is not None
            robot.old_axes = turn
            if top_level:
                robot.drive = find_drive(node)
        # Old Solids had a `scale` field (graphics only); it scales what the Solid holds.
        scale = np.asarray(node.fields["scale"], dtype=float) if "scale" in node.fields else None
        inner = Frame(np.zeros(3), np.array([1.0, 0, 0, 0]), frame.scale if scale is None else frame.scale * scale)
        props = self._bounding(node.get("boundingObject"), body, inner, node)
        _inertial(body, physics if has_physics else None, props, moves and joint_frame is not None, ctx, node)
        if top_level and has_physics:
            linear, angular = damping.rates(physics, ctx)
            free_joint = body.first_joint()
            free_joint.damping = [linear * body.mass, 0.0, 0.0]  # the tree's six come once compiled
            if linear or angular:
                ctx.damped.append((free_joint.name, linear, angular))
        entry = device.add_device(node, body, robot, ctx, self) if robot is not None else None
        if node.base_type == "Track":  # its devices come before its children's (Webots' device order)
            track.add_track(self, node, body, robot)
        if robot is None and node.base_type == "Connector":
            device.add_loose_connector(node, body, ctx)
        self._walk_device_children(entry, node, body, inner, robot, moves)
        if entry is not None and entry.type == "LED":
            device.finish_led(entry, body, ctx)
        if node.is_a("Robot") and not node.get("selfCollision"):
            _exclude_self_collisions(body, ctx)
        return body

    def _mergeable(self, node: Node, parent: mujoco.MjsBody) -> bool:
        """Whether a Solid device can live in its parent's body instead of a body of its own.

        Webots itself merges a Solid without Physics into its parent's rigid body. A device that
        collides (boundingObject: contact points, TouchSensor forces) or that camera recognition
        reports keeps its body, and so does anything at the top of the world or on a joint.
        """
        return (node.base_type in device.SOLID_DEVICES and node.base_type != "TouchSensor"
                and parent is not self.ctx.spec.worldbody and not isinstance(node.get("physics"), Node)
                and not isinstance(node.get("boundingObject"), Node) and not plain(node.get("recognitionColors")))

    def _merge_device(self, node: Node, body: mujoco.MjsBody, pose: Frame, robot: RobotEntry,
                      dynamic: bool) -> None:
        """A massless, non-colliding Solid device as a frame of its parent's body.

        A body of its own would only cost: MuJoCo computes every body's pose at every substep, and
        a robot's sensors and LEDs outnumber its moving parts (an E-puck has 3 moving bodies and
        32 device Solids). The device's site, camera and shapes carry the composed pose instead,
        and the supervisor reads the Solid's pose through its parent (it has no table.solids entry).
        """
        ctx = self.ctx
        if node.def_name:
            ctx.table.bodies.setdefault(node.def_name, body.name)
        scale = np.asarray(node.fields["scale"], dtype=float) if "scale" in node.fields else None
        inner = Frame(pose.pos, pose.quat, pose.scale if scale is None else pose.scale * scale)
        entry = device.add_device(node, body, robot, ctx, self, inner)
        first = len(body.geoms)
        self._walk_device_children(entry, node, body, inner, robot, dynamic)
        if entry is not None and entry.type == "LED":
            device.finish_led(entry, body, ctx, first)

    def _bounding(self, bounding: object, body: mujoco.MjsBody, frame: Frame,
                  solid: Node) -> list[geometry.MassProps]:
        """Collision geoms of a boundingObject; returns their unit-density mass properties."""
        props: list[geometry.MassProps] = []
        if not isinstance(bounding, Node):
            return props
        kind = bounding.base_type
        if kind in geometry.GEOMETRY_TYPES:
            made = geometry.add_geometry(body, bounding, frame, self.ctx, collision=True)
            if made is not None:
                self.ctx.contact_geoms.append((made[0], solid))
                if made[1] is not None:
                    props.append(made[1])
        elif kind == "Shape":
            props += self._bounding(bounding.get("geometry"), body, frame, solid)
        elif kind in ("Pose", "Transform"):
            scale = np.asarray(bounding.get("scale"), dtype=float) if kind == "Transform" else None
            inner = frame.compose(np.asarray(bounding.get("translation"), dtype=float), pose_quat(bounding), scale)
            for child in bounding.get("children") or []:
                props += self._bounding(child, body, inner, solid)
        elif kind == "Group":
            for child in bounding.get("children") or []:
                props += self._bounding(child, body, frame, solid)
        return props


def _texture_clamp(look: object, path: str | None) -> Clamp | None:
    """The axes the appearance's ImageTexture clamps (`repeatS`/`repeatT` FALSE), or None."""
    if not isinstance(look, Node) or path is None:
        return None
    texture = look.get("baseColorMap" if look.base_type == "PBRAppearance" else "texture")
    if not isinstance(texture, Node) or texture.base_type != "ImageTexture":
        return None
    if texture.get("repeatS") and texture.get("repeatT"):
        return None
    image = textures.load_texture(path)
    return Clamp(not texture.get("repeatS"), not texture.get("repeatT"), image.width, image.height)


def _exclude_self_collisions(robot: mujoco.MjsBody, ctx: CompileContext) -> None:
    """Webots' `selfCollision FALSE` (the default): no two parts of a robot collide with each other."""
    bodies = [robot, *robot.find_all(mujoco.mjtObj.mjOBJ_BODY)]
    solid = [b for b in bodies if any(g.contype for g in b.geoms)]
    for i, first in enumerate(solid):
        for second in solid[i + 1:]:
            ctx.spec.add_exclude(bodyname1=first.name, bodyname2=second.name)


def _body_name(node: Node, robot: RobotEntry | None) -> str:
    base = node.def_name or str(node.get("name") or node.base_type.lower())
    if robot is not None and not node.is_a("Robot"):
        return f"{robot.name}/{base}"
    return base


def _inertial(body: mujoco.MjsBody, physics: Node | None, props: list[geometry.MassProps], on_joint: bool,
              ctx: CompileContext, solid: Node) -> None:
    """Set the body's explicit inertial from its Physics node (Webots' rules) or make it massless."""
    body.explicitinertial = True
    if physics is None:
        # A static or merged Solid adds no mass; one that moves on a joint without Physics is moved
        # kinematically by Webots, and MuJoCo needs some inertia for a jointed body.
        body.mass, body.inertia = 0.0, [0.0] * 3
        body.ipos = [0.0, 0.0, 0.0]  # MJCF writes an explicit inertial only with a position set
        if on_joint:
            make_kinematic(body)  # some mass, no gravity (Webots gives it no ODE body)
        return
    volume = sum(p.volume for p in props)
    density, given_mass = float(physics.get("density")), float(physics.get("mass"))
    matrix = _two_lines(physics.get("inertiaMatrix"), ctx, physics)
    custom = matrix is not None and len(matrix) == 2 and given_mass > 0
    if volume <= 0 and not custom:
        # Webots' default mass settings for a body without a bounding volume: the given mass (else
        # 1 kg) with the identity inertia matrix (1 kg m^2 about each axis), and a warning.
        mass = given_mass if given_mass > 0 else 1.0
        com, inertia = np.zeros(3), np.eye(3)
        ctx.warn("Undefined inertia matrix: using the identity matrix. Please specify 'boundingObject' or "
                 "'inertiaMatrix' values." if given_mass > 0 else
                 "Mass is invalid because 'boundingObject' is not defined. Using default mass properties: "
                 "mass = 1, inertia matrix = identity", physics.span)
    else:
        mass = density * volume if density > 0 else max(given_mass, 0.0)
        if given_mass > 0:
            mass = given_mass  # Webots: with both given, the density is ignored
        if mass <= 0:
            ctx.warn("Either the 'mass' or the 'density' must be specified; 1 kg is used", physics.span)
            mass = 1.0
        com, inertia = _combine(props, mass)
    com_field = physics.get("centerOfMass")
    if com_field is not None and len(com_field) > 0:
        com = np.asarray(com_field[0], dtype=float)
    written = _full(matrix) if matrix is not None and len(matrix) == 2 else None
    if written is not None and _valid_inertia(written, ctx, physics):
        # MuJoCo's fullinertia is xx yy zz xy xz yz.
        full = _balanced(written, ctx, physics)
        body.fullinertia = [full[0, 0], full[1, 1], full[2, 2], full[0, 1], full[0, 2], full[1, 2]]
    else:
        body.fullinertia = [inertia[0, 0], inertia[1, 1], inertia[2, 2], inertia[0, 1], inertia[0, 2], inertia[1, 2]]
    body.mass = mass
    body.ipos = com


def _two_lines(matrix: Any, ctx: CompileContext, physics: Node) -> Any:
    """`inertiaMatrix` as Webots reads it: a missing second line is 0 0 0, lines past two are dropped."""
    if matrix is None or len(matrix) in (0, 2):
        return matrix
    if len(matrix) == 1:
        ctx.warn("'inertiaMatrix' must have exactly 0 or 2 lines. Second line inserted.", physics.span,
                 topic=INVALID_VALUE)
        return [matrix[0], (0.0, 0.0, 0.0)]
    ctx.warn("'inertiaMatrix' must have exactly 0 or 2 lines. Extra lines skipped.", physics.span,
             topic=INVALID_VALUE)
    return list(matrix[:2])


def _full(matrix: Any) -> np.ndarray:
    """The 3 x 3 inertia tensor of a written `inertiaMatrix`: Webots writes [I11 I22 I33], [I12 I13 I23]."""
    (xx, yy, zz), (xy, xz, yz) = (map(float, matrix[0]), map(float, matrix[1]))
    return np.array([[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]])


def _valid_inertia(full: np.ndarray, ctx: CompileContext, physics: Node) -> bool:
    """Webots' check of a written `inertiaMatrix` (WbPhysics::checkInertiaMatrix), with its warnings.

    Webots leaves an invalid matrix out; wbtc then uses the bounding object's inertia.
    """
    valid = True
    if (np.diag(full) <= 0.0).any():
        ctx.warn("The first line of 'inertiaMatrix' (principal moments of inertia) must have only positive values.",
                 physics.span, topic=INVALID_VALUE)
        valid = False
    if np.linalg.eigvalsh(full).min() <= 0.0:
        ctx.warn("'inertiaMatrix' must be positive definite.", physics.span, topic=INVALID_VALUE)
        valid = False
    return valid


def _balanced(full: np.ndarray, ctx: CompileContext, physics: Node) -> np.ndarray:
    """A written inertia MuJoCo accepts: principal moments that no body could have are made equal.

    ODE takes any positive definite matrix; MuJoCo needs principal moments A + B >= C, as a real body's
    are, and refuses the model otherwise. Those are replaced by their mean (MuJoCo's `balanceinertia`),
    with a warning.
    """
    moments = np.sort(np.linalg.eigvalsh(full))
    if moments[0] + moments[1] >= moments[2] * (1.0 - 1e-9):
        return full
    mean = float(moments.mean())
    ctx.warn(f"'inertiaMatrix' has principal moments {moments[0]:g}, {moments[1]:g}, {moments[2]:g}, which "
             f"no body has ({moments[0]:g} + {moments[1]:g} < {moments[2]:g}): MuJoCo needs a body's, so their "
             f"mean {mean:g} is used", physics.span, topic=INVALID_VALUE)
    return np.eye(3) * mean


def _combine(props: list[geometry.MassProps], mass: float) -> tuple[np.ndarray, np.ndarray]:
    """Centre of mass and inertia about it of several geoms sharing one mass in proportion to volume."""
    volume = sum(p.volume for p in props)
    if volume <= 0:  # a given inertiaMatrix replaces this
        return np.zeros(3), np.eye(3)
    density = mass / volume
    com = sum(p.volume * p.com for p in props) / volume
    inertia = np.zeros((3, 3))
    for p in props:
        d = p.com - com
        # Parallel-axis theorem: shift each geom's inertia to the common centre of mass.
        inertia += density * p.inertia + density * p.volume * (np.dot(d, d) * np.eye(3) - np.outer(d, d))
    inertia = np.maximum(inertia, inertia.T)
    floor = 1e-9 * max(1.0, mass)
    for i in range(3):
        inertia[i, i] = max(inertia[i, i], floor)
    return com, inertia


def world_viewpoint(scene: Scene) -> Node | None:
    """The world's first Viewpoint node, or None."""
    return next((node for node in scene.nodes if node.base_type == "Viewpoint"), None)


def _initial_velocity(ctx: CompileContext, node: Node, body_name: str, has_physics: bool) -> None:
    """Record a Solid's initial `linearVelocity`/`angularVelocity` (world axes) for the runtime to set.

    MuJoCo has no per-body initial velocity, so the simulation sets the joint velocities that give
    this twist when it starts (`Simulation._start_velocities`). A Solid without Physics is moved
    kinematically at that velocity, as Webots moves it (and as a supervisor's setVelocity does).
    """
    linear = [float(v) for v in node.get("linearVelocity")]
    angular = [float(v) for v in node.get("angularVelocity")]
    if any(linear) or any(angular):
        target = ctx.table.initial_velocities if has_physics else ctx.table.kinematic_velocities
        target[body_name] = (linear, angular)
