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

This module takes MuJoCo's solution (main solve and noslip) as the start of ODE's own LCP
(wbtc.runtime.lcp: Gauss-Seidel sweeps, then exact pivoting where they have not settled), island by
island (MuJoCo's islands: bodies touching each other, directly or through joints' rows): the normal
row as MuJoCo made it (its regularisation R and reference acceleration are ODE's spring, damper and
bounce), each friction row hard (WorldInfo's default `CFM`; reference: the sliding velocity gone
within the substep, or a Track's belt speed reached) and boxed by its μ times the normal force found
(ODE's `dContactApprox1`, along ODE's friction axes, dPlaneSpace of the normal), and the island's other
rows (equalities, joint limits, friction losses) within their own bounds. The constraint forces and
accelerations MuJoCo integrates are then the ones found here. Measured against ODE 0.16
(tests/runtime/test_ode_solve.py): the pushed box tilts 0.00126 rad where ODE's tilts 0.00134, at one
32 ms step and at 2 ms substeps alike.

Not honoured: WorldInfo `CFM` as written (the friction rows take its default); MuJoCo's torsional
and rolling rows (condim 4 and 6) keep their noslip forces; an island of more than MAX_ISLAND_CONTACTS
contacts keeps MuJoCo's forces (the solve runs in Python). Motors stay wbtc's velocity servos (MuJoCo
actuators, outside the rows), where ODE's are rows of this LCP.
"""

from __future__ import annotations

import mujoco
import numpy as np

from wbtc.runtime import lcp

#: Islands with more contacts keep MuJoCo's forces (noslip friction): the solve runs in Python and costs
#: the square of an island's rows (a pile of boxes on a fine elevation grid has a hundred contacts).
MAX_ISLAND_CONTACTS = 8
#: ODE's constraint force mixing of a friction row (WorldInfo `CFM`'s default): R = CFM / h, hard.
FRICTION_CFM = 1e-5


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
    others, bounds = _other_rows(data, np.unique(data.efc_island[normal]))
    rows = np.concatenate([normal, normal + 1, normal + 2, others])
    jac = _rows_dense(model, data, rows)
    # Friction along ODE's axes: a box is not round, so where its sides lie matters.
    axes = _ode_axes(contacts.frame[live], friction)
    jac[n:3 * n] = _turn(axes, jac[n:3 * n], n)
    solved = np.empty_like(jac)
    mujoco.mj_solveM(model, data, solved, jac)  # rows of J M^-1
    a_mat = jac @ solved.T
    forces = data.efc_force[rows]
    forces[n:3 * n] = _turn(axes, forces[n:3 * n], n)
    ref = data.efc_aref[rows]
    ref[n:3 * n] = _turn(axes, ref[n:3 * n], n)
    # The acceleration the rows see without their own forces: MuJoCo's, less what they contribute.
    accel = jac @ data.qacc - a_mat @ forces
    # The normal rows as MuJoCo made them (ODE's spring, damper and bounce); the friction rows' reference
    # is MuJoCo's too, the sliding velocity gone within the substep (or a Track belt's speed reached).
    # Friction rows are ODE's: hard, at WorldInfo's default CFM over the step.
    friction_reg = np.full(2 * n, FRICTION_CFM / model.opt.timestep)
    reg = np.concatenate([data.efc_R[normal], friction_reg, data.efc_R[others]])
    mu = np.concatenate([friction[:, 0], friction[:, 1]])
    new = lcp.solve(a_mat, accel, ref, reg, mu, bounds, forces, n)
    delta = new - forces
    back = new.copy()
    back[n:3 * n] = _turn(np.transpose(axes, (0, 2, 1)), new[n:3 * n], n)  # MuJoCo's axes again
    data.efc_force[rows] = back
    data.qfrc_constraint[:] += jac.T @ delta
    data.qacc[:] += solved.T @ delta  # M^-1 J^T delta


_EQUALITY = int(mujoco.mjtConstraint.mjCNSTR_EQUALITY)
_BOXED = (int(mujoco.mjtConstraint.mjCNSTR_FRICTION_DOF), int(mujoco.mjtConstraint.mjCNSTR_FRICTION_TENDON))
_ONE_SIDED = (int(mujoco.mjtConstraint.mjCNSTR_LIMIT_JOINT), int(mujoco.mjtConstraint.mjCNSTR_LIMIT_TENDON),
              int(mujoco.mjtConstraint.mjCNSTR_CONTACT_FRICTIONLESS))


def _other_rows(data: mujoco.MjData, islands: np.ndarray) -> tuple[np.ndarray, tuple[np.ndarray, np.ndarray]]:
    """The islands' rows other than their contacts' sliding rows, and their (lower, upper) force bounds.

    Equalities (a locked Connector's weld, a coupled joint) are unbounded; friction losses (ODE's motor
    rows, wbtc.runtime.motor_rows; a joint's `staticFriction`) lie within ±their loss; joint limits and
    frictionless contacts are one-sided. Torsional and rolling rows keep MuJoCo's forces.
    """
    nefc = data.nefc
    types = data.efc_type[:nefc]
    equality, boxed, one_sided = types == _EQUALITY, np.isin(types, _BOXED), np.isin(types, _ONE_SIDED)
    rows = np.nonzero((equality | boxed | one_sided) & np.isin(data.efc_island[:nefc], islands))[0]
    loss = data.efc_frictionloss[rows]
    lower = np.where(boxed[rows], -loss, np.where(one_sided[rows], 0.0, -np.inf))
    upper = np.where(boxed[rows], loss, np.inf)
    return rows, (lower, upper)


def _ode_axes(frames: np.ndarray, friction: np.ndarray) -> np.ndarray:
    """Per contact, the 2 x 2 turn from MuJoCo's friction axes (t1, t2) to ODE's (p, q).

    ODE's contact joint takes its friction directions from the normal alone (dPlaneSpace): on a floor
    facing +z, the world's y and x axes. Contacts whose two μ differ (asymmetric friction, oriented
    by wbtc.runtime.contact_frames) keep their axes. The axes are the model's (ENU); in a NUE world
    a floor's or a wall's are the same lines as Webots'.
    """
    frame = frames.reshape(-1, 3, 3)
    normal, t1, t2 = frame[:, 0], frame[:, 1], frame[:, 2]
    p = np.zeros_like(normal)
    q = np.zeros_like(normal)
    upright = np.abs(normal[:, 2]) > np.sqrt(0.5)
    nx, ny, nz = normal[:, 0], normal[:, 1], normal[:, 2]
    k = 1.0 / np.sqrt(np.where(upright, ny * ny + nz * nz, nx * nx + ny * ny))
    p[:, 0] = np.where(upright, 0.0, -ny * k)
    p[:, 1] = np.where(upright, -nz * k, nx * k)
    p[:, 2] = np.where(upright, ny * k, 0.0)
    q[:, 0] = np.where(upright, (ny * ny + nz * nz) * k, -nz * p[:, 1])
    q[:, 1] = np.where(upright, -nx * p[:, 2], nz * p[:, 0])
    q[:, 2] = np.where(upright, nx * p[:, 1], (nx * nx + ny * ny) * k)
    axes = np.stack([np.stack([np.sum(p * t1, 1), np.sum(p * t2, 1)], 1),
                     np.stack([np.sum(q * t1, 1), np.sum(q * t2, 1)], 1)], 1)
    keep = friction[:, 0] != friction[:, 1]
    axes[keep] = np.eye(2)
    return axes


def _turn(axes: np.ndarray, values: np.ndarray, n: int) -> np.ndarray:
    """The first and second friction rows' `values` (rows, or one number each) turned by `axes`."""
    first, second = values[:n], values[n:]
    shape = (n,) + (1,) * (values.ndim - 1)
    turned_first = axes[:, 0, 0].reshape(shape) * first + axes[:, 0, 1].reshape(shape) * second
    turned_second = axes[:, 1, 0].reshape(shape) * first + axes[:, 1, 1].reshape(shape) * second
    return np.concatenate([turned_first, turned_second])
