"""DirectionalLight, PointLight and SpotLight to MuJoCo lights.

Webots' light colour × intensity becomes MuJoCo's diffuse colour; `ambientIntensity` becomes its
ambient as a default Material sees it (× the Material's ambientIntensity, 0.2; PBRAppearances
ignore light ambient in Webots and take the Background's instead, see `world.set_ambient`);
`attenuation` carries over as is (both use 1 / (a0 + a1 d + a2 d²)), a spot's `cutOffAngle`
(radians, half angle) becomes MuJoCo's cutoff (degrees) and `beamWidth` a rough exponent. A
PointLight is a MuJoCo spot with a 180° cut-off (MuJoCo's OpenGL renderer draws no point lights).

Not honoured yet: `radius` (MuJoCo lights reach everywhere), `castLensFlares`. MuJoCo's OpenGL
renderer uses at most eight lights.
"""

from __future__ import annotations

import math

import mujoco
import numpy as np

from wbtc.compile.context import CompileContext, info
from wbtc.compile.frames import Frame
from wbtc.scene.model import Node

_UNHONOURED = frozenset({"radius", "castLensFlares"})
#: Material.ambientIntensity's default: Webots' Phong ambient is light ambient × this × diffuseColor.
MATERIAL_AMBIENT = 0.2


def add_light(node: Node, body: mujoco.MjsBody, frame: Frame, ctx: CompileContext) -> mujoco.MjsLight | None:
    """Add one light node to `body` at `frame`; None when the light is off.

    A light inside an LED is added even when off (inactive): the LED switches it on in its colour.
    """
    ctx.unhonoured(node, _UNHONOURED)
    if not node.get("on") and ctx.led_lights is None:
        return None
    kind = node.base_type
    light = body.add_light()
    light.name = ctx.unique("light", node.def_name or kind)
    light.active = bool(node.get("on"))
    if ctx.led_lights is not None:
        ctx.led_lights.append((light.name, float(node.get("intensity")), float(node.get("ambientIntensity"))))
    light.info = info(node)
    colour = np.asarray(node.get("color"), dtype=float)
    intensity = float(node.get("intensity"))
    # MuJoCo's renderer has no tone mapping: a directional light above 1 (a TexturedBackgroundLight's
    # sun is 2.7, meant for Webots' exposure curve) would saturate everything, so it is capped at 1.
    # Point and spot lights are not: their attenuation divides the intensity (worlds write 10 or 16
    # with 1/d² fall-off), and MuJoCo scales by a diffuse above 1 as Webots does.
    # Cameras tone-map as Webots does (wbtc.runtime.tone) and draw with the full intensity.
    cap = 1.0 if kind == "DirectionalLight" else math.inf
    light.diffuse = np.clip(colour * intensity, 0.0, cap)
    light.specular = np.clip(colour * intensity * 0.3, 0.0, cap)
    if intensity > cap:
        ctx.table.light_boost[light.name] = intensity / cap
    light.ambient = np.clip(colour * float(node.get("ambientIntensity")) * MATERIAL_AMBIENT, 0.0, 1.0)
    light.castshadow = bool(node.get("castShadows"))
    if kind in ("DirectionalLight", "SpotLight"):
        # Webots' LightSensor takes this field as written, in world axes, whatever turns the light.
        ctx.table.light_directions[light.name] = tuple(float(v) for v in node.get("direction"))
    if kind == "DirectionalLight":
        light.type = mujoco.mjtLightType.mjLIGHT_DIRECTIONAL
        light.dir = _unit(frame.rotate(np.asarray(node.get("direction"), dtype=float)))
        # A directional light has no position in Webots; MuJoCo draws it from above the scene.
        light.pos = frame.pos + np.array([0.0, 0.0, 10.0])
        return light
    light.pos = frame.apply(np.asarray(node.get("location"), dtype=float))
    light.attenuation = np.asarray(node.get("attenuation"), dtype=float)
    if kind == "PointLight":
        # MuJoCo's OpenGL renderer draws nothing for its point lights: a spot lighting every way
        # (180° cut-off, no fall-off) is the same light.
        light.type = mujoco.mjtLightType.mjLIGHT_SPOT
        light.cutoff, light.exponent = 180.0, 0.0
        return light
    light.type = mujoco.mjtLightType.mjLIGHT_SPOT
    light.dir = _unit(frame.rotate(np.asarray(node.get("direction"), dtype=float)))
    cutoff = float(node.get("cutOffAngle"))
    light.cutoff = math.degrees(cutoff)
    beam = float(node.get("beamWidth"))
    # Webots keeps full intensity inside beamWidth then fades to the cut-off; a MuJoCo exponent
    # approximates that fall-off (0 = uniform when the beam fills the cone).
    light.exponent = 0.0 if beam >= cutoff else 10.0 * (1 - beam / max(cutoff, 1e-6))
    return light


def _unit(v: np.ndarray) -> np.ndarray:
    norm = float(np.linalg.norm(v))
    return v / norm if norm > 0 else np.array([0.0, 0.0, -1.0])
