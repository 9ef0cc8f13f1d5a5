"""WorldInfo, Viewpoint and Background to MuJoCo options, a viewpoint camera and colours; contact friction.

- Gravity: Webots gives a magnitude along the world's down axis; the model is always ENU (z up),
  so it is (0, 0, -g).
- Time: MuJoCo's timestep is the largest substep no longer than `max_substep_ms` that divides
  `basicTimeStep` exactly (controllers see Webots time; contacts want a few ms).
- Friction: ODE's Coulomb μ of each `contactMaterial` pair. MuJoCo combines two geoms' frictions
  by their priority, else by maximum: geoms whose material has a ("default", M) ContactProperties
  get μ and a higher priority, so they win against default geoms; a ("default", "default") entry
  sets everyone's μ. Two non-default materials get explicit MuJoCo pairs for their geoms with the
  pair's own μ (wbtc.compile.contact), so their geoms keep the default μ against anything else; an
  asymmetric pair of two non-default materials is still approximated by the first rule.
  Rolling friction and asymmetric friction (several μ, `frictionRotation`): see wbtc.compile.contact.
- Ambient light: Webots has no headlight. Its PBRAppearances are lit by the Background (image-based
  light; a plain sky colour without cube maps) and its Materials by the lights' ambientIntensity.
  MuJoCo has one global ambient (the headlight's, here without diffuse or specular); see
  `set_ambient` for how each material gets its own: the sky's mean level c (colour × luminosity;
  neutral, so greys stay grey) as radiance for PBR, the lights' ambient for Phong Materials.
  A world with neither lights nor a Background keeps MuJoCo's headlight so that it is not black.
- NUE worlds (x north, y up, z east) are turned into ENU once, at the root: every top-level node
  is placed in a frame rotated by NUE → ENU, so bodies, joints and sensors need nothing else.
- Contact softness: by default MuJoCo's contact, stiffer than ODE's (time constant 10 ms). With
  `CompileOptions.ode_contacts`, ContactProperties `softERP` and `softCFM` are recorded here and
  applied once the model is compiled (wbtc.compile.soft_contact), and `bounce` and
  `bounceVelocity` are tabled for the runtime (wbtc.compile.bounce).
- ERP and CFM: WorldInfo's `ERP` and `CFM` are the default stopERP and stopCFM of joint stops
  (wbtc.compile.joint_stops); MuJoCo's contacts and other joint rows do not use them.

Not honoured yet: WorldInfo `physics` (plugins), `optimalThreadCount` (MuJoCo runs
single-threaded), `physicsDisable*`, `lineScale`; ContactProperties `forceDependentSlip` (and
`softERP`, `softCFM`, `bounce`, `bounceVelocity` without `ode_contacts`); Fog;
Background textures (a plain sky colour is used).
"""

from __future__ import annotations

import math

import mujoco
import numpy as np

from wbtc.compile import contact
from wbtc.compile.context import CompileContext, info
from wbtc.compile.device import CAMERA_QUAT
from wbtc.compile.frames import IDENTITY_QUAT, NUE_TO_ENU, NUE_TO_ENU_QUAT, Frame, axis_angle_quat, quat_mul
from wbtc.compile.light import MATERIAL_AMBIENT
from wbtc.compile.table import plain_fields
from wbtc.scene.model import Node

_UNHONOURED_WORLD = frozenset({"physics"})
_UNHONOURED_CONTACT = frozenset({"forceDependentSlip"})
_UNHONOURED_STIFF = _UNHONOURED_CONTACT | {"softERP", "softCFM", "bounce", "bounceVelocity"}
#: μ = -1 means infinite friction in Webots; MuJoCo needs a finite number.
INFINITE_FRICTION = 100.0


def root_frame(coordinate_system: str) -> Frame:
    """The frame top-level nodes are placed in: NUE worlds are rotated into ENU here, once."""
    if coordinate_system == "NUE":
        return Frame(np.zeros(3), NUE_TO_ENU_QUAT.copy(), np.ones(3))
    return Frame(np.zeros(3), IDENTITY_QUAT.copy(), np.ones(3))


def setup_world(info_node: Node | None, ctx: CompileContext) -> None:
    """Options from WorldInfo: gravity, time step and substeps, seed, default damping."""
    spec, table = ctx.spec, ctx.table
    table.coordinate_system = ctx.scene.coordinate_system if ctx.scene.coordinate_system == "NUE" else "ENU"
    table.webots_version = str(ctx.scene.version) if ctx.scene.version is not None else ""
    if ctx.scene.coordinate_system == "EUN":
        ctx.warn("the EUN coordinate system is not supported by wbtc yet; the world is read as ENU", None)
    table.to_model = NUE_TO_ENU if table.coordinate_system == "NUE" else np.eye(3)
    gravity, step = 9.81, 32.0
    if info_node is not None:
        ctx.unhonoured(info_node, _UNHONOURED_WORLD)
        gravity, step = float(info_node.get("gravity")), float(info_node.get("basicTimeStep"))
        table.random_seed = int(info_node.get("randomSeed"))
        table.gps_reference = [float(v) for v in info_node.get("gpsReference")]
        table.gps_wgs84 = str(info_node.get("gpsCoordinateSystem")) == "WGS84"
        table.ink_evaporation = max(float(info_node.get("inkEvaporation") or 0.0), 0.0)  # pens' ink fades (runtime.pen)
        damping = info_node.get("defaultDamping")
        ctx.default_damping = damping if isinstance(damping, Node) else None
        ctx.world_erp, ctx.world_cfm = float(info_node.get("ERP")), float(info_node.get("CFM"))
    step = step if step > 0 else 32.0
    substeps = max(1, math.ceil(step / ctx.options.max_substep_ms - 1e-9))
    table.basic_time_step, table.substeps = step, substeps
    spec.option.timestep = step / substeps / 1000.0
    spec.option.gravity = [0.0, 0.0, -gravity]
    # Semi-implicit Euler: the motor servos' implicit damping is carried by their joints' armature
    # (see device.tune_servos), which the constraint solver sees, unlike implicitfast's, which it
    # does not (contacts then fought a servo they took for explicit: hops, spring-back, slip).
    spec.option.integrator = mujoco.mjtIntegrator.mjINT_EULER
    spec.option.cone = mujoco.mjtCone.mjCONE_ELLIPTIC
    spec.visual.global_.offwidth = max(spec.visual.global_.offwidth, 1280)
    spec.visual.global_.offheight = max(spec.visual.global_.offheight, 720)


def add_viewpoint(node: Node, ctx: CompileContext, root: Frame) -> None:
    """The Viewpoint as a fixed camera named "viewpoint" (what recordings show)."""
    ctx.table.viewpoint = plain_fields(node)
    ctx.table.viewpoint["follow"] = str(node.get("follow") or "")
    rotation = node.get("orientation")
    pose = root.compose(np.asarray(node.get("position"), dtype=float),
                        axis_angle_quat((rotation[0], rotation[1], rotation[2]), rotation[3]))
    camera = ctx.spec.worldbody.add_camera()
    camera.name = "viewpoint"
    camera.info = info(node)
    camera.pos = pose.pos
    # R2022a+ viewpoints look along +x with z up, like device cameras; older ones along -z, y up.
    camera.quat = pose.quat if ctx.legacy_axes(node) else quat_mul(pose.quat, CAMERA_QUAT)
    camera.fovy = math.degrees(float(node.get("fieldOfView")))


def add_background(node: Node, ctx: CompileContext) -> None:
    """Background's first sky colour as MuJoCo's haze and a plain skybox.

    Webots fills the sky with one colour when `skyColor` has one entry; the skybox is MuJoCo's
    gradient builtin with both ends that colour, so that turning the view does not change the sky.
    """
    sky = node.get("skyColor")
    if sky is None or len(sky) == 0:
        return
    colour = np.clip(np.asarray(sky[0], dtype=float), 0, 1)
    texture = ctx.spec.add_texture(name="sky", type=mujoco.mjtTexture.mjTEXTURE_SKYBOX)
    texture.builtin = mujoco.mjtBuiltin.mjBUILTIN_GRADIENT
    texture.rgb1, texture.rgb2 = colour, colour
    texture.width = texture.height = 64
    ctx.spec.visual.rgba.haze = [*colour, 1.0]


def set_ambient(background: Node | None, ctx: CompileContext) -> None:
    """Ambient light per material, standing for Webots' light ambients and Background lighting.

    MuJoCo lights every geom with one ambient: the headlight's plus each light's (a light's ambient is
    colour × ambientIntensity × 0.2, what a default Phong Material sees). Webots lights a Phong
    Material by Σ light ambientIntensity × its own ambientIntensity (no Background), a PBRAppearance
    (or a shape without Material) by the Background's image light. So the headlight's ambient is 0 and
    each material's emission (which MuJoCo multiplies by its colour, as an ambient term) makes up the
    difference from the lights' shared ambient (never below 0).
    """
    headlight, lights = ctx.spec.visual.headlight, list(ctx.spec.lights)
    if background is None and not lights:
        return  # nothing lights the world: MuJoCo's own headlight shows it
    headlight.ambient = [0.0, 0.0, 0.0]
    headlight.diffuse = [0.0, 0.0, 0.0]
    headlight.specular = [0.0, 0.0, 0.0]
    sky = background.get("skyColor") if background is not None else None
    if sky is not None and len(sky) > 0:
        level = max(float(background.get("luminosity")), 0.0) * float(np.mean(np.clip(sky[0], 0.0, None)))
        image_light = level  # radiance; cameras tone-map it as everything else (wbtc.runtime.tone)
    else:
        image_light = 0.0
    own = float(np.mean(np.sum([np.asarray(light.ambient, dtype=float) for light in lights], axis=0))) \
        if lights else 0.0
    for name, role in ctx.ambient_roles.items():
        target = image_light if role is None else own / MATERIAL_AMBIENT * role
        material = ctx.spec.material(name)
        emissive = float(material.emission)
        material.emission = float(np.clip(emissive + max(target - own, 0.0), 0.0, 1.0))
        # Cameras work in Webots' linear radiance (wbtc.runtime.tone): wren turns a Material's colours
        # from sRGB to linear, its ambient (ambientIntensity × diffuseColor) included, so the lights'
        # ambient gives Σ ambientIntensity × lin(ambientIntensity) of the linear colour (lin(a·d) ≈
        # lin(a)·lin(d)); the Background's light on PBR is already radiance; emission is linearised too.
        # Cameras draw the colour × k and the emission ÷ k (see appearance._camera_terms); an unlit
        # material's own share (glow) is drawn as emission.
        k, scale, glow = ctx.camera_terms.get(name, (1.0, 1.0, 0.0))
        lit = image_light if role is None else own / MATERIAL_AMBIENT * srgb_to_linear(role)
        ctx.table.camera_light[name] = ((lit * scale + srgb_to_linear(emissive) + glow) / k, k)


def srgb_to_linear(value: float) -> float:
    """One sRGB channel value (0-1) as linear light, the standard curve (wren's srgbToLinear)."""
    value = min(max(float(value), 0.0), 1.0)
    return value / 12.92 if value <= 0.04045 else ((value + 0.055) / 1.055) ** 2.4


def apply_friction(info_node: Node | None, ctx: CompileContext) -> None:
    """Friction of every collision geom from WorldInfo.contactProperties (see the module docstring)."""
    default_mu, by_material, laws = 1.0, {}, []
    for props in (info_node.get("contactProperties") if info_node is not None else None) or []:
        if not isinstance(props, Node):
            continue
        ctx.unhonoured(props, _UNHONOURED_CONTACT if ctx.options.ode_contacts else _UNHONOURED_STIFF)
        law = contact.read_law(props)
        laws.append(law)
        ctx.contact_softness.setdefault(frozenset(law.materials), law.softness)
        ctx.contact_bounce.setdefault(frozenset(law.materials), law.bounce)
        mu = _mu(props)
        pair = {str(props.get("material1")), str(props.get("material2"))}
        if pair == {"default"}:
            default_mu = mu
        elif "default" in pair:
            by_material[(pair - {"default"}).pop()] = mu
        elif law.asymmetric:
            for material in pair:
                by_material.setdefault(material, mu)
            ctx.warn("friction between two non-default contact materials is approximated per material",
                     props.span)
        # Else the two materials' geoms get explicit pairs with this law's friction (contact.apply_contact_laws).
    # Contacts stiffer than MuJoCo's default (time constant 0.02 s), so robots sink about as little
    # as in ODE; much stiffer (two substeps) and light robots such as the e-puck start to hop. With
    # ode_contacts, soft_contact.apply replaces them with ODE's, body by body, once the model is compiled.
    solref = [max(5 * ctx.spec.option.timestep, 0.01), 1.0]
    for geom, solid in ctx.contact_geoms:
        geom.solref = solref
        material = str(solid.get("contactMaterial"))
        mu = by_material.get(material, default_mu)
        geom.friction = [mu, contact.SPIN_FRICTION, contact.ROLL_FRICTION]
        geom.priority = 1 if material in by_material else 0
    contact.apply_contact_laws(laws, ctx, solref)


def _mu(props: Node) -> float:
    values = props.get("coulombFriction")
    mu = float(values[0]) if values is not None and len(values) > 0 else 1.0
    return INFINITE_FRICTION if mu < 0 else mu
