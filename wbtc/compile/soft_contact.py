"""ODE's soft contact (ContactProperties `softERP`, `softCFM`) as MuJoCo solver parameters; hard friction.

Opt-in (`CompileOptions.ode_contacts`, `wbtc run --ode-contacts`), with ODE's bounce
(wbtc.compile.bounce), ODE's solve of each contact's normal and friction rows together
(wbtc.runtime.ode_solve) and wheels that touch at both cylinder rims (wbtc.compile.joint keeps their
cylinders). It is Webots' contact, but not Webots' step: a Thymio II's 0.6 s spin in the shapes
lesson turns about 82 degrees at wbtc's 2 ms substeps, where Webots' one 20 ms step turns 90.4 to 90.9
in an ODE model (85 at steps of 10 ms and below); with one 20 ms step here too, about 78 (README,
Contacts: the cause is not found).

Webots solves each contact point as an ODE constraint row whose `softERP` and `softCFM` (0.2 and 0.001
by default) make it, per point, a spring kp = ERP / (h·CFM) and a damper kd = (1 − ERP) / CFM in
newtons (h: `basicTimeStep`; 6250 N/m and 800 N·s/m at 32 ms), solved implicitly with the rest of the
step. So a resting body sinks by its weight over kp per point (a 100 kg box on its four corners:
3.9 cm; a 0.15 kg e-puck: about 0.1 mm), and a body started inside another is pushed out over
several steps instead of at once.

MuJoCo solves (A + R)·f = a_ref − a0 per contact row, with a_ref = −B·v − K·imp·r and
R = (1 − imp) / imp × diagApprox, where diagApprox is the sum of the two bodies' `body_invweight0`
(their inverse weight at the reference pose: about 1 / mass). ODE's step solves the same equation
with R = CFM / h and a_ref = ERP·depth / h² − v / h. So, with ODE's spring and damper re-expressed for
MuJoCo's substep h_s (CFM_s = 1 / (h_s·kp + kd), ERP_s = h_s·kp·CFM_s: the same continuous spring):

- R = CFM_s / h_s for every contact, whatever its mass: imp = diag / (diag + R), from the geom's body;
- K·imp = ERP_s / h_s² and B = 1 / h_s: MuJoCo's direct solref (−ERP_s·imp / h_s², −imp / h_s), whose
  K and B are divided by dmax = imp.

At rest the depth is then force / kp, ODE's, for any mass and any number of points.

Friction. MuJoCo's convex solver bounds friction by μ × the normal force it is solving for, so a
sliding contact whose friction rows are stiff buys friction with extra normal force: with soft normal
rows a 100 kg box slid at 3 m/s hopped 7 cm (MuJoCo's default contact: 2 cm, for any mass). ODE's
friction rows take the normal force as it is (and are hard, at WorldInfo's CFM). So here the main
solve gets almost free friction rows (impratio FRICTION_IMPRATIO: their R is 1000 × the normal
row's), which then only carries the normal forces, and MuJoCo's noslip pass (NOSLIP_ITERATIONS)
solves the friction rows without regularisation within μ × those normal forces: Coulomb friction
that stops a slip within a substep, without hops (measured: no hop for 100 kg, 2.8 mm for 0.1 kg
at 3 m/s; slides of 1 and 3 m/s within 3 % of Coulomb's v² / 2μg; a 0.3 rad slope holds a 100 kg
box to 3 µm/s). The noslip pass leaves the normal forces as the main solve found them, so nothing meets
the friction forces' torque: wbtc.runtime.ode_solve then solves normal and friction rows together, from
these forces, as ODE's one solve does.

How the two geoms of a contact combine (MuJoCo's collision driver):

- A static geom (its body has no degree of freedom, diag 0) gets solmix 0 and a solref of almost 0:
  the moving geom's parameters are taken whole (two direct solrefs combine by their minimum).
- Two moving geoms: solimp is mixed by solmix = each geom's diag, so the lighter body's impedance
  dominates, as it does in the exact diag1 + diag2; equal bodies get their own exactly.
- A static geom of higher priority (its material has a ContactProperties; see world.apply_friction)
  would impose its own parameters, which cannot know the other body: every such geom gets an
  explicit pair with each moving geom it may touch, with its friction and condim (what its priority
  gave) and both bodies' diag (`pair_static_priority`). Explicit pairs (these and contact's rolling
  pairs) get the exact diag1 + diag2.

Not honoured yet: WorldInfo `CFM` (friction rows are hard); a supervisor's change of a mass at run
time keeps the impedance computed at compile time.
"""

from __future__ import annotations

from dataclasses import dataclass

import mujoco
import numpy as np

from wbtc.compile import contact
from wbtc.compile.context import CompileContext

#: WbContactProperties' defaults, which a contact without a matching ContactProperties gets.
SOFT_ERP, SOFT_CFM = 0.2, 0.001
#: The main solve's friction rows are this much easier than its normal rows (R / impratio): almost free.
FRICTION_IMPRATIO = 1e-3
#: Sweeps of MuJoCo's noslip pass, which solves the friction rows hard within the normal forces found.
NOSLIP_ITERATIONS = 10
#: MuJoCo's bounds of a constraint's impedance (mjMINIMP, mjMAXIMP).
MIN_IMP, MAX_IMP = 1e-4, 0.9999
#: The solref of a static geom: direct, and above every moving geom's, so that the minimum MuJoCo
#: takes of two direct solrefs is always the moving geom's.
STATIC_SOLREF = (-1e-12, -1e-12)
#: Beyond this many (static priority geom, moving geom) pairs, static priority geoms keep geom-level
#: parameters computed for the mean moving body instead (MuJoCo checks every explicit pair each step).
MAX_PRIORITY_PAIRS = 4000


@dataclass(frozen=True)
class Softness:
    """ODE's softERP and softCFM of one ContactProperties (or Webots' defaults)."""

    erp: float = SOFT_ERP
    cfm: float = SOFT_CFM


@dataclass(frozen=True)
class RowTerms:
    """One contact row's target in MuJoCo's terms: R (1/kg), K·imp (1/s²) and B (1/s)."""

    r: float
    stiffness: float
    damping: float

    def parameters(self, diag: float) -> tuple[list[float], list[float]]:
        """(solref, solimp) of a contact whose two bodies' inverse weights sum to `diag`."""
        imp = min(max(diag / (diag + self.r), MIN_IMP), MAX_IMP) if diag > 0 else MIN_IMP
        # MuJoCo's direct solref: K = −solref[0] / dmax², B = −solref[1] / dmax, dmax = imp (flat).
        solref = [-self.stiffness * imp, -self.damping * imp]
        return solref, [imp, imp, 0.001, 0.5, 2.0]


def row_terms(softness: Softness, basic_step: float, substep: float) -> RowTerms:
    """ODE's contact row at `basic_step` seconds as MuJoCo's R, K·imp and B at `substep` seconds."""
    cfm = max(softness.cfm, 1e-10)
    # The spring and damper ODE's ERP and CFM stand for at Webots' step (ODE manual, "soft constraint").
    kp = softness.erp / (basic_step * cfm)
    kd = (1.0 - softness.erp) / cfm
    cfm_s = 1.0 / (substep * kp + kd)  # ODE's CFM for the same spring and damper at the substep
    erp_s = substep * kp * cfm_s
    return RowTerms(cfm_s / substep, erp_s / substep**2, 1.0 / substep)


def material_classes(ctx: CompileContext, model: mujoco.MjModel) -> tuple[np.ndarray, list[str]]:
    """Each compiled collision geom's contact-material index (-1: none), and the materials in order of first use."""
    materials: list[str] = []
    geom_class = np.full(model.ngeom, -1, dtype=np.int32)
    for geom, solid in ctx.contact_geoms:
        material = str(solid.get("contactMaterial"))
        if material not in materials:
            materials.append(material)
        if 0 <= geom.id < model.ngeom:
            geom_class[geom.id] = materials.index(material)
    return geom_class, materials


def softness_of(ctx: CompileContext, material1: str, material2: str) -> Softness:
    """The softness of a contact between two contact materials: their ContactProperties', else Webots' defaults."""
    found = ctx.contact_softness.get(frozenset((material1, material2)))
    return Softness(*found) if found is not None else Softness()


def pair_static_priority(ctx: CompileContext) -> None:
    """Explicit pairs between static geoms of higher priority and the moving geoms they may touch."""
    moving = [(i, g) for i, (g, _) in enumerate(ctx.contact_geoms) if contact.moves(g.parent)]
    static = [(i, g) for i, (g, _) in enumerate(ctx.contact_geoms)
              if not contact.moves(g.parent) and g.priority > 0]
    candidates = [(s, m) for s in static for m in moving if s[1].priority > m[1].priority]
    if not candidates or len(candidates) > MAX_PRIORITY_PAIRS:
        return
    excluded = {frozenset((e.bodyname1, e.bodyname2)) for e in ctx.spec.excludes}
    paired = {frozenset((p.geomname1, p.geomname2)) for p in ctx.spec.pairs}
    for (index1, geom1), (index2, geom2) in candidates:
        if not contact.may_touch(geom1, geom2, excluded):
            continue
        names = (contact.geom_name(geom1, index1), contact.geom_name(geom2, index2))
        if frozenset(names) in paired:
            continue
        pair = ctx.spec.add_pair()
        pair.geomname1, pair.geomname2 = names
        pair.condim = geom1.condim
        slide, spin, roll = (float(v) for v in geom1.friction)
        pair.friction = [slide, slide, spin, roll, roll]


def apply(spec: mujoco.MjSpec, model: mujoco.MjModel, ctx: CompileContext) -> None:
    """Solver parameters of every colliding geom and pair from its bodies' inverse weights (see above)."""
    table = ctx.table
    basic, substep = table.basic_time_step / 1000.0, float(model.opt.timestep)
    materials = {geom.id: str(solid.get("contactMaterial")) for geom, solid in ctx.contact_geoms}
    diag = model.body_invweight0[:, 0]
    colliding = np.flatnonzero((model.geom_contype != 0) | (model.geom_conaffinity != 0))
    moving_diag = [float(diag[model.geom_bodyid[g]]) for g in colliding if diag[model.geom_bodyid[g]] > 0]
    mean_diag = float(np.mean(moving_diag)) if moving_diag else 0.0
    geoms = {element.id: element for element in spec.geoms}
    for g in colliding:
        geom_diag = float(diag[model.geom_bodyid[g]])
        terms = row_terms(softness_of(ctx, materials.get(int(g), "default"), "default"), basic, substep)
        if geom_diag > 0:
            solref, solimp, solmix = *terms.parameters(geom_diag), geom_diag
        elif model.geom_priority[g] > 0:  # left without pairs (too many): the mean moving body
            solref, solimp, solmix = *terms.parameters(mean_diag), 1.0
        else:
            solref, solimp, solmix = list(STATIC_SOLREF), list(terms.parameters(mean_diag)[1]), 0.0
        model.geom_solref[g], model.geom_solimp[g], model.geom_solmix[g] = solref, solimp, solmix
        element = geoms[int(g)]
        element.solref, element.solimp, element.solmix = solref, solimp, solmix
    pairs = {element.id: element for element in spec.pairs}
    for p in range(model.npair):
        g1, g2 = int(model.pair_geom1[p]), int(model.pair_geom2[p])
        pair_diag = float(diag[model.geom_bodyid[g1]] + diag[model.geom_bodyid[g2]])
        softness = softness_of(ctx, materials.get(g1, "default"), materials.get(g2, "default"))
        solref, solimp = row_terms(softness, basic, substep).parameters(pair_diag)
        model.pair_solref[p], model.pair_solimp[p] = solref, solimp
        element = pairs[p]
        element.solref, element.solimp = solref, solimp
    model.opt.impratio = spec.option.impratio = FRICTION_IMPRATIO
    model.opt.noslip_iterations = spec.option.noslip_iterations = NOSLIP_ITERATIONS

