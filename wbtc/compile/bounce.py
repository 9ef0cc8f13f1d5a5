"""ContactProperties `bounce` and `bounceVelocity` (ODE's restitution), tabled for the runtime.

Webots gives every contact the first ContactProperties whose `material1` and `material2` match the
two Solids' `contactMaterial` (in either order), and a ContactProperties' defaults when none does:
bounce 0.5 above 0.01 m/s. ODE (joints/contact.cpp) then sets the contact's normal row to reach the
larger of its ERP correction and `bounce` × the incoming normal speed, when that speed exceeds
`bounceVelocity`: a ball dropped on the floor leaves it at half its landing speed.

MuJoCo has no restitution, so the compiler only tables the values here: each collision geom's
material class (`BounceTable.geom_class`, by compiled geom id) and the (bounce, bounceVelocity) of
every two classes. wbtc.runtime.bounce sets the contacts' normal rows from it at every substep.

Tabled with `CompileOptions.ode_contacts` only, with ODE's soft rows (wbtc.compile.soft_contact):
on MuJoCo's default contact (the nstep fast path, no split substeps) nothing bounces, as before.
"""

from __future__ import annotations

from dataclasses import dataclass

import mujoco
import numpy as np

from wbtc.compile import soft_contact
from wbtc.compile.context import CompileContext

#: A ContactProperties' `bounce` and `bounceVelocity` defaults, which an unmatched contact gets.
DEFAULT_BOUNCE, DEFAULT_VELOCITY = 0.5, 0.01


@dataclass
class BounceTable:
    """Restitution of every pair of contact materials, for the runtime.

    Attributes:
        geom_class: per compiled geom, the index of its Solid's contactMaterial in `materials`
            (-1 for geoms that do not collide).
        materials: the contact materials, in order of first use.
        bounce: (n, n) ODE bounce of two classes (0 to 1).
        velocity: (n, n) ODE bounceVelocity of two classes (m/s): slower landings do not bounce.
        regularisation: (n, n) the R of the two classes' contact rows in Webots' ODE step,
            softCFM / basicTimeStep (1/kg): how much of its target a row reaches in one step.
    """

    geom_class: np.ndarray
    materials: list[str]
    bounce: np.ndarray
    velocity: np.ndarray
    regularisation: np.ndarray

    @property
    def threshold(self) -> float:
        """The slowest approach that can bounce anywhere (inf when nothing bounces)."""
        bouncing = self.bounce > 0.0
        return float(self.velocity[bouncing].min()) if bouncing.any() else float("inf")


def table(ctx: CompileContext, model: mujoco.MjModel) -> BounceTable:
    """The BounceTable of a compiled model (geom ids are the compiled ones, so after `compile`).

    The (bounce, bounceVelocity) of two materials are `ctx.contact_bounce`'s, which
    `world.apply_friction` fills with the first ContactProperties of each pair, as Webots matches them.
    """
    geom_class, materials = soft_contact.material_classes(ctx, model)
    n = len(materials)
    bounce, velocity = np.full((n, n), DEFAULT_BOUNCE), np.full((n, n), DEFAULT_VELOCITY)
    regularisation = np.zeros((n, n))
    basic = ctx.table.basic_time_step / 1000.0
    for i, first in enumerate(materials):
        for j, second in enumerate(materials):
            regularisation[i, j] = soft_contact.softness_of(ctx, first, second).cfm / basic
            found = ctx.contact_bounce.get(frozenset((first, second)))
            if found is not None:
                bounce[i, j], velocity[i, j] = min(max(found[0], 0.0), 1.0), max(found[1], 0.0)
    return BounceTable(geom_class, materials, bounce, velocity, regularisation)
