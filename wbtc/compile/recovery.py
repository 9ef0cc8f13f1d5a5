"""How fast Webots pushes apart two bodies started (or driven) deep inside each other, tabled for the runtime.

ODE's contact row asks for a separating speed of softERP × depth / basicTimeStep (ContactProperties
`softERP`, 0.2 by default), so each step takes a fifth of the depth out: a box started 3 cm inside the
floor rises at 0.19 m/s, and most of the way out in about 0.5 s, where MuJoCo's contact spring (time
constant 10 ms) throws it out at 1.2 m/s, 4.6 cm above its resting height. wbtc.runtime.recovery
caps MuJoCo's deep contact rows at ODE's speed; this module tables each collision geom's contact
material and the softERP of every two materials.

Tabled for MuJoCo's default contact only: `--ode-contacts` (wbtc.compile.soft_contact) already gives
every row ODE's spring and damper.
"""

from __future__ import annotations

from dataclasses import dataclass

import mujoco
import numpy as np

from wbtc.compile import soft_contact
from wbtc.compile.context import CompileContext

#: A softERP of 1 takes the whole depth out in one step: capped so that the rate stays finite.
MAX_ERP = 0.99


@dataclass
class RecoveryTable:
    """ODE's push-out rate of every pair of contact materials.

    Attributes:
        geom_class: per compiled geom, the index of its Solid's contactMaterial (-1: no collision).
        rate: (n, n) of two classes, −ln(1 − softERP) / basicTimeStep (1/s): the separating speed per
            metre of depth that takes out ODE's share of the depth per step.
        cfm: (n, n) of two classes, their softCFM: how soft ODE's row is, which bounds the force it
            pushes with (None: MuJoCo's own softness).
    """

    geom_class: np.ndarray
    rate: np.ndarray
    cfm: np.ndarray | None = None


def table(ctx: CompileContext, model: mujoco.MjModel) -> RecoveryTable:
    """The RecoveryTable of a compiled model (geom ids are the compiled ones, so after `compile`)."""
    geom_class, materials = soft_contact.material_classes(ctx, model)
    basic = ctx.table.basic_time_step / 1000.0
    # ODE takes softERP of the depth out per step: depth × (1 − ERP)^n after n steps. The same decay,
    # continuous over the substeps, is exp(−rate·t) with rate = −ln(1 − ERP) / basicTimeStep.
    softness = [[soft_contact.softness_of(ctx, a, b) for b in materials] for a in materials]
    erp = np.array([[min(s.erp, MAX_ERP) for s in row] for row in softness])
    rate = -np.log1p(-np.maximum(erp, 0.0)) / basic
    cfm = np.array([[max(s.cfm, 1e-10) for s in row] for row in softness])
    shape = (len(materials), len(materials))
    return RecoveryTable(geom_class, rate.reshape(shape), cfm.reshape(shape))
