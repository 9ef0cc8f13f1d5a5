"""ODE's contact solve (`--ode-contacts`): each contact's normal and friction rows found together.

ODE, Webots' engine, solves a contact's rows in one LCP with the rest of the step: a soft normal row
(`softERP`, `softCFM`), two hard friction rows bounded by μ × the normal force being found
(`dContactApprox1`, a box per friction direction). A friction force's torque is then met within the
step by the normal forces shifting between a body's contact points (a pushed box presses harder on
its front edge). MuJoCo's main solve couples friction and normal forces through its soft cone, so
wbtc's `--ode-contacts` leaves its friction rows almost free there (wbtc.compile.soft_contact) and
solves friction afterwards in MuJoCo's noslip pass, within the normal forces already found: nothing
meets the friction's torque until the next step, and a body pushed or braked tilts and creeps (a
1 kg box pushed by 2 N in one 32 ms step: 0.086 rad where the contacts' springs allow 0.0016).

This module takes MuJoCo's solution (main solve and noslip) as the start of ODE's own iteration, a
projected Gauss-Seidel over the contact rows of the substep, island by island (MuJoCo's islands:
bodies touching each other): the normal row as MuJoCo made it (its regularisation R and reference
acceleration are ODE's spring, damper and bounce), each friction row hard (reference: the sliding
velocity gone within the substep, or a Track's belt speed reached) and boxed by its μ times the normal
force of the sweep (ODE's `dContactApprox1`). The other rows (joint limits, equalities, friction
loss) keep MuJoCo's forces. The constraint forces and accelerations MuJoCo integrates are then the
ones found here. Measured against ODE 0.16 (tests/runtime/test_ode_solve.py): the pushed box tilts
0.00126 rad where ODE's tilts 0.00134, at one 32 ms step and at 2 ms substeps alike.

Not honoured: WorldInfo `CFM` on the friction rows (they are hard); MuJoCo's torsional and rolling
rows (condim 4 and 6) keep their noslip forces; an island of more than MAX_ISLAND_CONTACTS contacts
keeps MuJoCo's forces (the sweeps run in Python: 13 contacts cost about 2 ms a substep).
"""

from __future__ import annotations

import mujoco
import numpy as np

#: Gauss-Seidel sweeps over a substep's contact rows (ODE's quickstep default is 20).
SWEEPS = 20
#: Islands with more contacts keep MuJoCo's forces (noslip friction): the sweeps run in Python and cost
#: the square of an island's rows (a pile of boxes on a fine elevation grid has a hundred contacts).
MAX_ISLAND_CONTACTS = 8
#: Sweeps end once no force changed by more than this share of the largest.
TOLERANCE = 1e-10
#: A friction row's regularisation relative to its diagonal: hard, as ODE's (CFM 1e-5).
FRICTION_SOFTNESS = 1e-9


def applies(model: mujoco.MjModel) -> bool:
    """Whether `model` has ODE's contacts (wbtc.compile.soft_contact turns MuJoCo's noslip pass on)."""
    return model.opt.noslip_iterations > 0


def step2(model: mujoco.MjModel, data: mujoco.MjData) -> None:
    """MuJoCo's `mj_step2`, stage by stage, with the contact rows solved again before integrating."""
    mujoco.mj_fwdActuation(model, data)
    mujoco.mj_fwdAcceleration(model, data)
    mujoco.mj_fwdConstraint(model, data)
    solve_contacts(model, data)
    mujoco.mj_sensorAcc(model, data)
    mujoco.mj_checkAcc(model, data)
    mujoco.mj_Euler(model, data)  # wbtc's integrator (wbtc.compile.world)


def _rows_dense(model: mujoco.MjModel, data: mujoco.MjData, rows: np.ndarray) -> np.ndarray:
    """The Jacobian rows `rows` of the constraints, dense (nrows x nv)."""
    nv = model.nv
    if not mujoco.mj_isSparse(model):
        return data.efc_J.reshape(-1, nv)[rows]
    dense = np.zeros((len(rows), nv))
    for k, row in enumerate(rows.tolist()):
        adr, nnz = int(data.efc_J_rowadr[row]), int(data.efc_J_rownnz[row])
        dense[k, data.efc_J_colind[adr:adr + nnz]] = data.efc_J[adr:adr + nnz]
    return dense


def solve_contacts(model: mujoco.MjModel, data: mujoco.MjData) -> None:
    """Re-solve the contact rows of this substep as ODE does (after `mj_fwdConstraint`)."""
    ncon = data.ncon
    if not ncon:
        return
    contacts = data.contact
    addresses = contacts.efc_address[:ncon]
    live = np.nonzero((addresses >= 0) & (contacts.dim[:ncon] >= 3))[0]
    if not len(live) or not data.nisland:
        return
    # MuJoCo's islands (bodies that touch, directly or through others) are independent problems; those
    # of more than MAX_ISLAND_CONTACTS contacts keep MuJoCo's forces. The others are solved as one
    # (their rows do not act on each other, so the sweeps treat them apart all the same).
    islands = data.efc_island[addresses[live]]
    live = live[np.bincount(islands)[islands] <= MAX_ISLAND_CONTACTS]
    if not len(live):
        return
    normal = addresses[live]
    friction = contacts.friction[live]
    # Rows: each contact's normal, then its two sliding friction rows (MuJoCo's elliptic layout).
    n = len(normal)
    rows = np.concatenate([normal, normal + 1, normal + 2])
    jac = _rows_dense(model, data, rows)
    solved = np.empty_like(jac)
    mujoco.mj_solveM(model, data, solved, jac)  # rows of J M^-1
    a_mat = jac @ solved.T
    forces = data.efc_force[rows]
    # The acceleration the rows see without their own forces: MuJoCo's, less what they contribute.
    accel = jac @ data.qacc - a_mat @ forces
    # The normal rows as MuJoCo made them (ODE's spring, damper and bounce); the friction rows' reference
    # is MuJoCo's too, the sliding velocity gone within the substep (or a Track belt's speed reached).
    reg = np.concatenate([data.efc_R[normal], FRICTION_SOFTNESS * np.diag(a_mat)[n:]])
    mu = np.concatenate([friction[:, 0], friction[:, 1]])
    new = _sweeps(a_mat, accel, data.efc_aref[rows], reg, mu, forces, n)
    delta = new - forces
    data.efc_force[rows] = new
    data.qfrc_constraint[:] += jac.T @ delta
    data.qacc[:] += solved.T @ delta  # M^-1 J^T delta


def _sweeps(a_mat: np.ndarray, accel: np.ndarray, ref: np.ndarray, reg: np.ndarray, mu: np.ndarray,
            start: np.ndarray, n: int) -> np.ndarray:
    """ODE's projected Gauss-Seidel over n contacts' rows (normals, first frictions, second frictions).

    Row k's force makes its acceleration a_k = accel_k + (A f)_k reach ref_k − R_k f_k, a normal force
    kept at 0 or above, a friction force within ±μ × its contact's normal force as this sweep has it.
    Starts from the forces `start`.
    """
    acc = accel + a_mat @ start
    total = np.diag(a_mat) + reg
    # A row the bodies' degrees of freedom cannot move (a friction direction along a hinge's axis) has
    # a zero diagonal: it gets no force.
    inverse = np.divide(1.0, total, out=np.zeros_like(total), where=total > 1e-12 * (1.0 + total.max()))
    # Python floats: scalar arithmetic on NumPy's values costs several times more.
    f, targets, soft, inv, mus = start.tolist(), ref.tolist(), reg.tolist(), inverse.tolist(), mu.tolist()
    columns = list(a_mat)  # A is symmetric: row k is column k
    order = [k for i in range(n) for k in (i, i + n, i + 2 * n)]
    for _ in range(SWEEPS):
        largest = 0.0
        for k in order:
            old = f[k]
            value = old - (acc.item(k) + soft[k] * old - targets[k]) * inv[k]
            if k < n:
                value = max(value, 0.0)
            else:
                bound = mus[k - n] * f[k % n]
                value = min(max(value, -bound), bound)
            change = value - old
            if change:
                f[k] = value
                acc += columns[k] * change
                largest = max(largest, abs(change))
        if largest <= TOLERANCE * (1.0 + max(map(abs, f))):
            break
    return np.array(f)
