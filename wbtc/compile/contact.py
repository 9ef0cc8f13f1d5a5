"""ContactProperties' rolling friction and asymmetric friction: MuJoCo contact pairs and runtime frames.

How Webots builds an ODE contact (WbSimulationCluster::fillSurfaceParameters, ODE's joints/contact.cpp):

- `rollingFriction` (rho, rho2, rhoN) adds ODE rolling rows whose torque is at most rho·N (limits
  proportional to the normal force, dContactApprox1): about the first friction direction t1, the
  second t2 and the normal. With only rho set, ODE uses rho for all three (spinning included).
  With rho2 or rhoN set, Webots sets dContactAxisDep, which is the same bit as dContactMu2: the
  second friction direction then gets `mu2`, which Webots leaves unset when `coulombFriction` has
  one value (Webots' recorded rolling_friction poses show it as 0: balls slide freely along t2).
- Two to four `coulombFriction` values (asymmetric friction) set dContactFDir1 and dContactMu2. Each
  geometry gives a direction in its own frame (Plane: x; Box and Cylinder: x when the contact normal
  is closest to their z axis, else z; other geometries: none, and the contact falls back to the
  first value for both directions). `frictionRotation` turns the direction of the solid of
  `material1` (S1) and of `material2` (S2) about the contact normal by minus the given angles; t1 is
  S1's direction. With a angle between the two directions, two values (μ0, μ1) give
  μ(t1) = μ0 + μ0|cos a| + μ1|sin a| and μ(t2) = μ1 + μ0|sin a| + μ1|cos a|; three give μ0 + μ2 and
  μ1 + μ2; four give μ0 + μ2|cos a| + μ3|sin a| and μ1 + μ2|sin a| + μ3|cos a|.

MuJoCo mapping, and why:

- Rolling friction: an explicit MuJoCo contact `pair` for every two collision geoms whose Solids'
  materials match the ContactProperties, condim 6 (4 when only rhoN is set), friction (μ, μ2, spin,
  roll1, roll2) = (μ, μ or 0, rhoN, rho, rho2) with the same solref as the geoms. MuJoCo's torsional
  and rolling friction have ODE's units (torque ≤ coefficient × normal force), and an explicit pair
  replaces MuJoCo's own contact of the two geoms. MuJoCo's first tangent is world y made orthogonal
  to the normal, ODE's (dPlaneSpace) the normal's y-z plane: the same axis when the normal has no
  y component (floors and ramps tilted about y); elsewhere rho and rho2 may swap axes. A pair with
  the "default" material would need a pair per geom of the world, so it is set on the geoms of the
  other material instead (condim and friction (μ, spin, roll), higher priority), where MuJoCo has one
  rolling coefficient: rho2 is not honoured there.
- Sliding friction between two non-default materials (one μ, no rolling): explicit pairs the same
  way, condim 3, friction (μ, μ): MuJoCo's geoms carry one μ each, which would give that μ to every
  other contact of the two materials (a gripper's μ 10 with its stick also between the stick and
  the floor). The first ContactProperties of two materials wins, as in Webots; later ones are ignored.
- MuJoCo's friction cone couples sliding and rolling (elliptic: Σ(f_i/μ_i)² ≤ N²) where ODE bounds
  each row on its own, so a ball whose rolling friction is at its limit slips a little in MuJoCo;
  the elliptic cone (wbtc's) comes much closer to ODE than the pyramidal one on Webots' test.
- Asymmetric friction: MuJoCo picks a contact's tangents itself (from the normal alone for a plane
  or a box), so no model field can point them along Webots' t1, and μ(t1), μ(t2) change with the
  angle between the two geoms. The compiler records the asymmetric ContactProperties and the
  materials of the geoms they concern (`DeviceTable.asymmetric_friction`); at every substep the
  runtime (wbtc.runtime.contact_frames) turns each such contact's frame to Webots' t1, sets its two
  sliding coefficients and has MuJoCo build the constraints again from them. Which solid is S1 when
  both have the same material follows ODE's argument order, which Webots does not fix: a Plane (a
  "big box" of ODE's hash space, collided after the other geoms) comes second, else MuJoCo's order
  is taken. In Webots' api/asymmetric_friction test (box1 started on the plane's surface) this
  order ends box1 6 cm from Webots' pose after 40 steps, ODE's other order (the Plane as o1, so
  box1 is S1) 9 cm, and a wrong S1 without the matching normal 0.8 m or more.

softERP and softCFM: see wbtc.compile.soft_contact.

Not honoured yet: `forceDependentSlip`, `bounce`, `bounceVelocity`; rho2 in
pairs with the "default" material; asymmetric friction on geometries of worlds older than R2022a
(Webots' older axis rules); ODE's box-shaped friction bounds (MuJoCo's cone is elliptic).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import mujoco

from wbtc.compile.context import CompileContext
from wbtc.scene.model import Node

#: μ = -1 (or rho = -1) means infinite in Webots; MuJoCo needs a finite number.
INFINITE = 100.0
#: The geometries Webots gives a friction direction: Plane, Box, Cylinder.
_DIRECTED = (mujoco.mjtGeom.mjGEOM_PLANE, mujoco.mjtGeom.mjGEOM_BOX, mujoco.mjtGeom.mjGEOM_CYLINDER)
#: MuJoCo clamps friction coefficients below its mjMINMU (1e-5) up to it; 0 stands for "none".
NO_FRICTION = 0.0


#: MuJoCo's torsional and rolling coefficients of a contact without ODE rolling rows (MuJoCo's defaults;
#: unused at condim 3, which every contact without rolling friction has).
SPIN_FRICTION, ROLL_FRICTION = 0.005, 0.0001


@dataclass(frozen=True)
class ContactLaw:
    """One ContactProperties, as ODE sees it.

    Attributes:
        materials: (material1, material2).
        mu: the coulombFriction values (1 to 4), -1 made INFINITE.
        rho: rollingFriction (rho, rho2, rhoN), -1 made INFINITE.
        rotation: frictionRotation (S1's angle, S2's angle), radians.
        softness: (softERP, softCFM), see wbtc.compile.soft_contact.
        bounce: (bounce, bounceVelocity), see wbtc.compile.bounce.
    """

    materials: tuple[str, str]
    mu: tuple[float, ...]
    rho: tuple[float, float, float]
    rotation: tuple[float, float]
    softness: tuple[float, float] = (0.2, 0.001)
    bounce: tuple[float, float] = (0.5, 0.01)

    @property
    def asymmetric(self) -> bool:
        """Whether Webots gives the contact its own friction directions (two or more μ)."""
        return len(self.mu) > 1

    @property
    def rolling(self) -> bool:
        """Whether ODE adds rolling rows (some rho > 0)."""
        return any(r > 0 for r in self.rho)

    @property
    def axis_dependent(self) -> bool:
        """ODE's dContactAxisDep: rho2 or rhoN set (then rho, rho2, rhoN each act on their own axis)."""
        return self.rho[1] > 0 or self.rho[2] > 0


def read_law(props: Node) -> ContactLaw:
    """The ContactLaw of a ContactProperties node."""
    values = props.get("coulombFriction")
    mu = tuple(_finite(float(v)) for v in (values if values is not None and len(values) else [1.0]))[:4]
    rho = tuple(_finite(float(v)) for v in (props.get("rollingFriction") or (0.0, 0.0, 0.0)))
    rotation = tuple(float(v) for v in (props.get("frictionRotation") or (0.0, 0.0)))
    softness = (float(props.get("softERP")), float(props.get("softCFM")))
    bounce = (float(props.get("bounce")), float(props.get("bounceVelocity")))
    return ContactLaw((str(props.get("material1")), str(props.get("material2"))), mu,
                      (rho[0], rho[1], rho[2]), (rotation[0], rotation[1]), softness, bounce)


def _finite(value: float) -> float:
    return INFINITE if value < 0 else value


def surface_mu(law: ContactLaw, angle: float | None) -> tuple[float, float]:
    """Webots' (μ along t1, μ along t2); `angle` between S1's and S2's directions, None if unsupported."""
    mu = law.mu
    if not law.asymmetric or angle is None:
        # dContactAxisDep is dContactMu2: t2 then gets the mu2 Webots never set (0).
        return mu[0], (NO_FRICTION if law.axis_dependent else mu[0])
    c, s = abs(math.cos(angle)), abs(math.sin(angle))
    if len(mu) == 2:
        return mu[0] + mu[0] * c + mu[1] * s, mu[1] + mu[0] * s + mu[1] * c
    if len(mu) == 3:
        return mu[0] + mu[2], mu[1] + mu[2]
    return mu[0] + mu[2] * c + mu[3] * s, mu[1] + mu[2] * s + mu[3] * c


def pair_friction(law: ContactLaw) -> tuple[int, list[float]]:
    """MuJoCo condim and (slide1, slide2, spin, roll1, roll2) of a rolling-friction contact."""
    mu1, mu2 = surface_mu(law, None)
    rho, rho2, rho_n = law.rho if law.axis_dependent else (law.rho[0],) * 3
    condim = 6 if rho > 0 or rho2 > 0 else 4
    return condim, [mu1, mu2, rho_n, rho, rho2]


def apply_contact_laws(laws: list[ContactLaw], ctx: CompileContext, solref: list[float]) -> None:
    """Rolling friction as MuJoCo pairs or geom friction; asymmetric laws recorded for the runtime."""
    geoms_of: dict[str, list[tuple[int, mujoco.MjsGeom]]] = {}
    for index, (geom, solid) in enumerate(ctx.contact_geoms):
        geoms_of.setdefault(str(solid.get("contactMaterial")), []).append((index, geom))
    excluded = {frozenset((e.bodyname1, e.bodyname2)) for e in ctx.spec.excludes}
    seen: set[frozenset[str]] = set()
    for law in laws:
        if frozenset(law.materials) in seen:
            continue  # Webots takes the first ContactProperties that matches two materials
        seen.add(frozenset(law.materials))
        if law.rolling:
            _rolling(law, geoms_of, ctx, solref, excluded)
        elif "default" not in law.materials and not law.asymmetric:
            mu = surface_mu(law, None)[0]
            _pairs(law, geoms_of, ctx, solref, excluded, 3, [mu, mu, SPIN_FRICTION, ROLL_FRICTION, ROLL_FRICTION])
    # Webots falls back to the first μ (what the geoms carry) unless both geometries give directions.
    asymmetric = [law for law in laws if law.asymmetric
                  and all(any(g.type in _DIRECTED for _, g in geoms_of.get(m, [])) for m in law.materials)]
    if not asymmetric:
        return
    names: dict[str, str] = {}
    for material in {m for law in asymmetric for m in law.materials}:
        for index, geom in geoms_of.get(material, []):
            names[geom_name(geom, index)] = material
    ctx.table.asymmetric_friction = (asymmetric, names)


def _rolling(law: ContactLaw, geoms_of: dict[str, list[tuple[int, mujoco.MjsGeom]]], ctx: CompileContext,
             solref: list[float], excluded: set[frozenset[str]]) -> None:
    condim, friction = pair_friction(law)
    first, second = law.materials
    if "default" in law.materials:
        # One pair per geom of the world would be needed: the other material's geoms carry it.
        other = second if first == "default" else first
        for _, geom in geoms_of.get(other, []):
            geom.condim = condim
            geom.friction = [friction[0], friction[2], max(friction[3], friction[4])]
            geom.priority = 2
        return
    _pairs(law, geoms_of, ctx, solref, excluded, condim, friction)


def _pairs(law: ContactLaw, geoms_of: dict[str, list[tuple[int, mujoco.MjsGeom]]], ctx: CompileContext,
           solref: list[float], excluded: set[frozenset[str]], condim: int, friction: list[float]) -> None:
    """An explicit MuJoCo pair, with the law's condim and friction, for every two geoms of its two materials."""
    first, second = law.materials
    for index1, geom1 in geoms_of.get(first, []):
        for index2, geom2 in geoms_of.get(second, []):
            if first == second and index2 <= index1:
                continue  # each two geoms of one material once
            if geom1 is geom2 or not may_touch(geom1, geom2, excluded):
                continue
            pair = ctx.spec.add_pair()
            pair.geomname1, pair.geomname2 = geom_name(geom1, index1), geom_name(geom2, index2)
            pair.condim = condim
            pair.friction = friction
            pair.solref = solref


def may_touch(geom1: mujoco.MjsGeom, geom2: mujoco.MjsGeom, excluded: set[frozenset[str]]) -> bool:
    """Whether MuJoCo's own collision would consider the two geoms (an explicit pair skips its filters)."""
    if geom1.parent == geom2.parent or frozenset((geom1.parent.name, geom2.parent.name)) in excluded:
        return False
    if not (geom1.contype & geom2.conaffinity or geom2.contype & geom1.conaffinity):
        return False
    return moves(geom1.parent) or moves(geom2.parent)


def moves(body: mujoco.MjsBody) -> bool:
    """Whether a body can move: it or a body above it has a joint."""
    while body is not None and body.name != "world":
        if len(body.joints):
            return True
        body = body.parent
    return False


def geom_name(geom: mujoco.MjsGeom, index: int) -> str:
    """The geom's name, giving it one if it has none (pairs and the runtime refer to geoms by name)."""
    if not geom.name:
        geom.name = f"contact#{index}"
    return geom.name
