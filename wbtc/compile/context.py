"""What every emitter shares while one scene is compiled: the spec, names, warnings, options.

Also the per-file facts emitters need: which version wrote a node (pre-R2022a files have their
primitive axes along y), and where its relative URLs start.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import mujoco
import numpy as np

from wbtc.compile.table import DeviceTable
from wbtc.errors import Diagnostic, Span
from wbtc.proto.model import written_version
from wbtc.resources import protos_dir
from wbtc.scene.model import Node, Scene
from wbtc.vrml.header import Version, before_r2022a

_LIBRARY = str(protos_dir())
#: MuJoCo geom groups: the viewer shows 0-2 by default, so visuals go in 1 and collisions in 3.
VISUAL_GROUP = 1
COLLISION_GROUP = 3
#: Mass of a body that moves on a joint but has no Physics node (Webots moves it kinematically).
KINEMATIC_MASS = 1e-3


@dataclass
class CompileOptions:
    """Knobs of the compiler.

    Attributes:
        max_substep_ms: the longest MuJoCo timestep allowed; the substep divides basicTimeStep.
        strict: unhonoured fields are errors instead of warnings.
        ode_contacts: contacts as ODE's soft rows (softERP, softCFM) with hard Coulomb friction
            (wbtc.compile.soft_contact), instead of MuJoCo's stiff default contact.
        paint: in a world with a Pen, give every shape a paint layer of its own for the pen's ink
            (wbtc.compile.paintable). `wbtc compile` leaves it off: plain MuJoCo has no pen, and the
            layers show what the shared textures show.
    """

    max_substep_ms: float = 2.0
    strict: bool = False
    ode_contacts: bool = False
    paint: bool = True


@dataclass
class CompileContext:
    """State shared by the emitters while compiling one scene."""

    scene: Scene
    spec: mujoco.MjSpec
    options: CompileOptions
    table: DeviceTable = field(default_factory=DeviceTable)
    warnings: list[Diagnostic] = field(default_factory=list)
    _warned: set[Diagnostic] = field(default_factory=set)
    contact_geoms: list[tuple[mujoco.MjsGeom, Node]] = field(default_factory=list)
    # CadShapes' visual geoms: Webots' infra-red rays pass through them (see wbtc.compile.cad_shape).
    cad_geoms: list[mujoco.MjsGeom] = field(default_factory=list)
    default_damping: Node | None = None
    damped: list[tuple[str, float, float]] = field(default_factory=list)  # free joint, linear and angular rates
    # The `anchor` field of the HingeJoint, Hinge2Joint or BallJoint above each endPoint body, as written
    # (in its parent's frame), by body name: Webots' hinge-chain collision skip (wbtc.compile.hinge_chains).
    hinge_anchors: dict[str, tuple[float, float, float]] = field(default_factory=dict)
    texture_paths: dict[str, str] = field(default_factory=dict)
    display_textures: dict[int, object] = field(default_factory=dict)  # id(ImageTexture) -> its Display's entry
    led_lights: list[tuple[str, float, float]] | None = None  # collects an LED's lights while its children are walked
    #: For each MuJoCo material: its Phong Material's ambientIntensity, or None for a PBRAppearance or a
    #: shape without Material (lit by the Background); `world.set_ambient` turns it into emission.
    ambient_roles: dict[str, float | None] = field(default_factory=dict)
    camera_terms: dict[str, tuple[float, float, float]] = field(default_factory=dict)  # appearance._camera_terms
    #: ContactProperties' (softERP, softCFM) by their two materials (see soft_contact).
    contact_softness: dict[frozenset[str], tuple[float, float]] = field(default_factory=dict)
    #: ContactProperties' (bounce, bounceVelocity) by their two materials (see bounce).
    contact_bounce: dict[frozenset[str], tuple[float, float]] = field(default_factory=dict)
    #: WorldInfo's ERP and CFM: the default stopERP and stopCFM of joint stops (see joint_stops).
    world_erp: float = 0.2
    world_cfm: float = 1e-5
    #: Each limited joint's stop softness (ERP, CFM), by MuJoCo joint name (see joint_stops).
    joint_stops: dict[str, tuple[float, float]] = field(default_factory=dict)
    paint: bool | None = None  # the world has a Pen: textured shapes are compiled paintable (see `paintable`)
    _names: dict[str, set[str]] = field(default_factory=dict)
    _warned: set[tuple[str, str]] = field(default_factory=set)
    _versions: dict[str, Version | None] = field(default_factory=dict)

    def unique(self, kind: str, base: str) -> str:
        """A name not used yet for this kind of element: `base`, else `base(1)`, `base(2)`...

        Webots renames clashing sibling Solids the same way ("solid(1)"), so names stay familiar.
        """
        used = self._names.setdefault(kind, set())
        base = base or kind
        name, n = base, 0
        while name in used:
            n += 1
            name = f"{base}({n})"
        used.add(name)
        return name

    def warn(self, message: str, span: Span | None, topic: str | None = None) -> None:
        """Record one warning (`topic`: see `Diagnostic.topic`)."""
        diagnostic = Diagnostic(message, span, severity="warning", topic=topic)
        if diagnostic not in self._warned:  # said once: a node a PROTO repeats (four arena walls) warns alike
            self._warned.add(diagnostic)
            self.warnings.append(diagnostic)

    def unhonoured(self, node: Node, names: frozenset[str]) -> None:
        """Warn once per (node type, field) for a written field the compiler does not honour yet."""
        if node.span.file.startswith(_LIBRARY):
            return  # wbtc's own PROTOs: the user cannot act on them (their limits are in protos/README.md)
        for name in node.fields:
            if name not in names or _is_default(node, name):
                continue
            key = (node.base_type, name)
            if key in self._warned:
                continue
            self._warned.add(key)
            span = node.field_spans.get(name, node.span)
            self.warn(f"{node.base_type}.{name} is not honoured by wbtc yet; it is ignored", span)

    def legacy_axes(self, node: Node) -> bool:
        """True when the file that wrote this node predates R2022a (primitives along y, cameras along -z)."""
        return before_r2022a(self.file_version(node.span.file))

    def file_version(self, path: str) -> Version | None:
        """The header version of the world or PROTO file at `path`."""
        if path not in self._versions:
            self._versions[path] = written_version(path, str(self.scene.path), self.scene.version)
        return self._versions[path]


def _is_default(node: Node, name: str) -> bool:
    """True when a written field holds its schema default (a PROTO body writing `top TRUE`)."""
    if node.schema is None:
        return False
    spec = node.schema.field(name)
    if spec is None:
        return False
    try:
        return bool(np.array_equal(np.asarray(node.fields[name], dtype=object), np.asarray(spec.default, dtype=object)))
    except (TypeError, ValueError):
        return False


def info(node: Node) -> str:
    """The `info` string of a MuJoCo element made from `node`: the world's line first.

    A node made by a PROTO names the instance's line in the world and the line in the PROTO file.
    """
    span = node.span
    if node.origin is not None and node.origin != span:
        return f"{node.origin} > {span} {node.type_name}"
    return f"{span} {node.type_name}"
