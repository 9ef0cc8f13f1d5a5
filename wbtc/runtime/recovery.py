"""Bodies placed inside each other pushed apart at ODE's speed, not MuJoCo's (see wbtc.compile.recovery).

MuJoCo's contact row has the reference acceleration a_ref = −B·v − K·imp·r of a stiff spring: a body
started 3 cm inside the floor leaves it at 1.2 m/s and hops. ODE's row takes softERP of the depth
out per basic step; as a speed over the substeps, `rate` × depth (see wbtc.compile.recovery).

This applies to overlaps that were placed, not to impacts: the pairs of geoms deeper than `DEEP`
into each other when the simulation starts, after a supervisor moved a body, or after the world was
recompiled (a regenerated bounding object, an imported node). While such a pair is that deep, the
basic step's substeps are split (wbtc.runtime.substeps) and each of its deep contacts' normal rows
gets a_ref = min(a_ref, (rate × depth − v) / h), h the substep, v its normal speed (positive apart):
the velocity change that takes it to ODE's speed within the substep, never more than MuJoCo's own.
A pair leaves the set once it is no deeper than `DEEP`. When both geoms belong to one kinematic
tree (a robot's links, which joints may keep inside each other for good), the normal row also gets
ODE's softness, R = softCFM / h (see `_soften`): a spring its motors can hold against.

Impacts keep MuJoCo's row: its spring sends a ball back off a post much as Webots' default bounce
does, where ODE's push-out speed would leave it stuck. So do resting contacts (0.03 mm deep for a
box, 0.5 mm under a 2000 kg car), which ODE's speed would let sink deeper.

wbtc's cone is elliptic (wbtc.compile.world), so a contact's normal row is its first row.
"""

from __future__ import annotations

import mujoco
import numpy as np

from wbtc.compile.recovery import RecoveryTable

#: Placed overlaps deeper than this (metres) get ODE's push-out. Below it MuJoCo's own throws a body
#: out less than 0.1 mm above where it rests.
DEEP = 1e-3


class Recovery:
    """The overlapping pairs of one model and the hook that caps their rows.

    Attributes:
        pairs: (geom, geom) pairs, lower id first, placed deeper than `DEEP` and not yet out.
    """

    def __init__(self, table: RecoveryTable, model: mujoco.MjModel) -> None:
        self.classes, self.rate, self.cfm = table.geom_class, table.rate, table.cfm
        # Each geom's kinematic tree (0: the static world): overlaps inside one tree may never resolve.
        self.tree = model.body_rootid[model.geom_bodyid]
        self.model = model
        self.pairs: set[tuple[int, int]] = set()

    def find(self, model: mujoco.MjModel, data: mujoco.MjData) -> None:
        """Add the pairs that overlap now (the poses as they are; contacts found again)."""
        mujoco.mj_collision(model, data)
        self.pairs |= {pair for pair, depth in _deepest(_pair_keys(data), data).items() if depth < -DEEP}

    def hook(self, model: mujoco.MjModel, data: mujoco.MjData) -> None:
        """After `mj_step1`: cap the rows of the overlapping pairs' deep contacts; drop the pairs that are out."""
        keys = _pair_keys(data)
        deepest = _deepest(keys, data)
        self.pairs = {pair for pair in self.pairs if deepest.get(pair, 0.0) < -DEEP}
        if not self.pairs:
            return
        contacts = data.contact
        rows = contacts.efc_address
        first, second = self.classes[contacts.geom[:, 0]], self.classes[contacts.geom[:, 1]]
        placed = np.array([key in self.pairs for key in keys], dtype=bool)
        chosen = placed & (contacts.dist < -DEEP) & (rows >= 0) & (first >= 0) & (second >= 0)
        if not chosen.any():
            return
        rows = rows[chosen]
        a, b = first[chosen], second[chosen]
        h = model.opt.timestep
        target = self.rate[a, b] * -contacts.dist[chosen]
        wanted = (target - data.efc_vel[rows]) / h
        data.efc_aref[rows] = np.minimum(data.efc_aref[rows], wanted)
        if self.cfm is not None:
            first_tree, second_tree = self.tree[contacts.geom[chosen, 0]], self.tree[contacts.geom[chosen, 1]]
            linked = (first_tree == second_tree) & (first_tree > 0)
            _soften(data, rows[linked], self.cfm[a, b][linked] / h)


def _soften(data: mujoco.MjData, rows: np.ndarray, soft: np.ndarray) -> None:
    """Give the normal rows at `rows` ODE's regularisation R = softCFM / h where MuJoCo's is stiffer.

    For the overlaps of two bodies of one kinematic tree (a robot's links), which may never resolve:
    ODE's row is the implicit spring of its ERP and CFM (kp = ERP / (h·CFM) per point), so a row its
    bodies cannot satisfy (a finger hinged 3 cm inside a palm, as Webots' own Robotiq 3F is) pushes
    with (rate × depth − v) / CFM at most: a 100 N·m motor then holds its finger 0.025 rad from its
    target, where MuJoCo's stiff row, asking the same speed with any force, opened it 0.28 rad. A free
    body leaves its overlap at the capped speed whatever the softness. The friction rows stay MuJoCo's:
    softened with it they let a box placed in a slope creep down it, and left stiff against a soft
    normal row they buy friction with normal force (MuJoCo's convex cone): a box placed 4.5 cm in a
    tilted plane stuck to it.
    """
    softer = soft > data.efc_R[rows]
    rows, soft = rows[softer], soft[softer]
    if not len(rows):
        return
    data.efc_R[rows] = soft
    data.efc_D[rows] = 1.0 / soft
    if data.nisland:  # the solver reads its islands' copies, made in mj_step1
        at = data.map_efc2iefc[rows]
        data.iefc_R[at] = soft
        data.iefc_D[at] = 1.0 / soft


def recovery_for(table: RecoveryTable | None, model: mujoco.MjModel) -> Recovery | None:
    """The Recovery of `model`, or None when it has no table (`--ode-contacts`: ODE's rows already)."""
    if table is None or len(table.geom_class) != model.ngeom or not len(table.rate):
        return None
    return Recovery(table, model)


def _pair_keys(data: mujoco.MjData) -> list[tuple[int, int]]:
    """Each contact's pair of geoms, lower id first."""
    if not data.ncon:
        return []
    return [(a, b) if a < b else (b, a) for a, b in data.contact.geom.tolist()]


def _deepest(keys: list[tuple[int, int]], data: mujoco.MjData) -> dict[tuple[int, int], float]:
    """The deepest contact distance of each touching pair of geoms (`keys`: each contact's pair)."""
    deepest: dict[tuple[int, int], float] = {}
    if keys:
        for pair, dist in zip(keys, data.contact.dist.tolist(), strict=True):
            deepest[pair] = min(dist, deepest.get(pair, 0.0))
    return deepest
