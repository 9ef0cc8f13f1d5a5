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
rows (equalities, joint limits, friction losses: ODE's motor rows, wbtc.runtime.motor_rows) within their
own bounds. Islands with motor rows are solved even without a contact. The constraint forces and
accelerations MuJoCo integrates are then the ones found here. Measured against ODE 0.16
(tests/runtime/test_ode_solve.py): the pushed box tilts 0.00126 rad where ODE's tilts 0.00134, at one
32 ms step and at 2 ms substeps alike.

Not honoured: WorldInfo `CFM` as written (the friction rows take its default); MuJoCo's torsional
and rolling rows (condim 4 and 6) keep their noslip forces; an island of more contacts than
`island_limit` allows keeps MuJoCo's forces (the solve runs in Python), its motor rows too.
"""

from __future__ import annotations

import mujoco
import numpy as np

from wbtc.runtime import lcp

#: Islands with more contacts keep MuJoCo's forces (noslip friction): the solve runs in Python and costs
#: the square of an island's rows (a pile of boxes on a fine elevation grid has a hundred contacts).
#: At wbtc's 2 ms substeps: 8; longer substeps allow more (`island_limit`).
MAX_ISLAND_CONTACTS = 8
#: The contacts an island may have per second of simulated time at one solve per substep: the Python
#: solve's cost goes with the contacts solved per simulated second, so a substep 16 times longer
#: (Webots' one step per 32 ms, `--physics-step 1000`) may solve islands 16 times larger (128).
CONTACTS_PER_SECOND = 4000.0
#: ODE's constraint force mixing of a friction row (WorldInfo `CFM`'s default): R = CFM / h, hard.
FRICTION_CFM = 1e-5


def applies(model: mujoco.MjModel) -> bool:
    """Whether `model` has ODE's contacts (wbtc.compile.soft_contact turns MuJoCo's noslip pass on)."""
    return model.opt.noslip_iterations > 0


def island_limit(substep: float) -> int:
    """The most contacts an island solved here may have at substeps of `substep` seconds.

    8 at 2 ms, 128 at Webots' 32 ms step: a robot on four cylinder legs touching at Webots' 20 points,
    with an e-puck against it, is one island of 26 contacts.
    """
    return max(MAX_ISLAND_CONTACTS, int(CONTACTS_PER_SECOND * substep + 1e-9))


def step2(model: mujoco.MjModel, data: mujoco.MjData) -> None:
    """MuJoCo's `mj_step2`, stage by stage, with the contact rows solved again before integrating."""
    live, chosen = _islands(model, data)
    # The damped joints of the islands solved here get ODE's implicit damper row in the solve instead of
    # MuJoCo's damping (its explicit force in this substep's passive forces, its implicit part in the
    # integration), restored after the step.
    dampers = _dampers(model, data, chosen)
    damping = model.dof_damping[dampers]
    if len(dampers):
        data.qfrc_passive[dampers] += damping * data.qvel[dampers]
        model.dof_damping[dampers] = 0.0
    mujoco.mj_fwdActuation(model, data)
    mujoco.mj_fwdAcceleration(model, data)
    mujoco.mj_fwdConstraint(model, data)
    if len(chosen):
        _solve(model, data, live, chosen, (dampers, damping))
    mujoco.mj_sensorAcc(model, data)
    mujoco.mj_checkAcc(model, data)
    mujoco.mj_Euler(model, data)  # wbtc's integrator (wbtc.compile.world)
    if len(dampers):
        model.dof_damping[dampers] = damping


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


def _islands(model: mujoco.MjModel, data: mujoco.MjData) -> tuple[np.ndarray, np.ndarray]:
    """The contacts re-solved here (indices into data.contact) and the islands they and other rows are in.

    MuJoCo's islands (bodies that touch, directly or through others) are independent problems; those
    of more contacts than `island_limit` allows keep MuJoCo's forces. The others are solved as one
    (their rows do not act on each other, so the sweeps treat them apart all the same).
    """
    ncon = data.ncon
    contacts = data.contact
    addresses = contacts.efc_address[:ncon]
    live = np.nonzero((addresses >= 0) & (contacts.dim[:ncon] >= 3))[0]
    if not data.nisland:
        return live[:0], live[:0]
    islands = data.efc_island[addresses[live]]
    live, islands = live[islands >= 0], islands[islands >= 0]  # (a row in no island: left as MuJoCo has it)
    crowded = np.bincount(islands, minlength=data.nisland) > island_limit(model.opt.timestep)
    live = live[~crowded[islands]]
    # Islands with joint friction rows are solved here too, contacts or not: under --ode-contacts these
    # are ODE's motor rows (wbtc.runtime.motor_rows), hard, which MuJoCo's Newton solver leaves far
    # from settled (a chain of 10 g links asked for 0.1 rad/s reached 530 rad/s in one 16 ms step).
    chosen = np.union1d(data.efc_island[addresses[live]], _friction_islands(data))
    return live, chosen[~crowded[chosen]]


def _dampers(model: mujoco.MjModel, data: mujoco.MjData, chosen: np.ndarray) -> np.ndarray:
    """The damped joint degrees of freedom (hinges, sliders, balls) of the islands `chosen`."""
    damped = np.nonzero((model.dof_damping > 0.0) & _JOINT_DOF[model.jnt_type[model.dof_jntid]])[0]
    if not len(damped) or not len(chosen):
        return damped[:0]
    island = data.dof_island[damped]
    inside = np.zeros(data.nisland + 1, bool)  # (the last entry: a dof in no island, index -1)
    inside[chosen] = True
    return damped[inside[island]]


def _solve(model: mujoco.MjModel, data: mujoco.MjData, live: np.ndarray, chosen: np.ndarray,
           dampers: tuple[np.ndarray, np.ndarray]) -> None:
    """Re-solve the rows of the islands `chosen` as ODE does (after `mj_fwdConstraint`).

    `live`: their contacts; `dampers`: their damped joints' degrees of freedom and dampings, each an
    implicit row of ODE's (Webots' spring-and-damper motor): its force −d v' at the velocity v' the
    step ends with, unbounded.
    """
    contacts = data.contact
    addresses = contacts.efc_address[:data.ncon]
    normal = addresses[live]
    friction = contacts.friction[live]
    # Rows: each contact's normal, then its two sliding friction rows (MuJoCo's elliptic layout).
    n = len(normal)
    others, bounds = _other_rows(data, chosen)
    rows = np.concatenate([normal, normal + 1, normal + 2, others])
    dofs, damping = dampers
    jac = np.concatenate([_rows_dense(model, data, rows), np.eye(model.nv)[dofs]])
    # Friction along ODE's axes: a box is not round, so where its sides lie matters.
    turn = _ode_turn(contacts.frame[live], friction)
    if turn is not None:
        jac[n:3 * n] = _turn(turn, jac[n:3 * n], n)
    solved = np.empty_like(jac)
    mujoco.mj_solveM(model, data, solved, jac)  # rows of J M^-1
    a_mat = jac @ solved.T
    h = model.opt.timestep
    # A damper row's force is not in MuJoCo's solution (0); its reference stops the joint within the
    # substep and its regularisation 1 / (h d) leaves it −d v' (ODE's CFM 1 / (h kp + kd), kp = 0).
    forces = np.concatenate([data.efc_force[rows], np.zeros(len(dofs))])
    ref = np.concatenate([data.efc_aref[rows], -data.qvel[dofs] / h])
    if turn is not None:
        forces[n:3 * n] = _turn(turn, forces[n:3 * n], n)
        ref[n:3 * n] = _turn(turn, ref[n:3 * n], n)
    # The acceleration the rows see without their own forces: MuJoCo's, less what they contribute.
    accel = jac @ data.qacc - a_mat @ forces
    # The normal rows as MuJoCo made them (ODE's spring, damper and bounce); the friction rows' reference
    # is MuJoCo's too, the sliding velocity gone within the substep (or a Track belt's speed reached).
    # Friction rows are ODE's: hard, at WorldInfo's default CFM over the step.
    friction_reg = np.full(2 * n, FRICTION_CFM / h)
    reg = np.concatenate([data.efc_R[normal], friction_reg, data.efc_R[others], 1.0 / (h * damping)])
    free = np.full(len(dofs), np.inf)
    bounds = (np.concatenate([bounds[0], -free]), np.concatenate([bounds[1], free]))
    mu = np.concatenate([friction[:, 0], friction[:, 1]])
    new = lcp.solve(a_mat, accel, ref, reg, mu, bounds, forces, n)
    delta = new - forces
    back = new.copy()
    if turn is not None:
        back[n:3 * n] = _turn((turn[0], -turn[1]), new[n:3 * n], n)  # MuJoCo's axes again
    data.efc_force[rows] = back[:len(rows)]
    data.qfrc_constraint[:] += jac.T @ delta
    data.qacc[:] += solved.T @ delta  # M^-1 J^T delta


_C = mujoco.mjtConstraint
#: The kind of each MuJoCo constraint type: 0 a contact's (or not solved here), 1 an equality, 2 a friction
#: loss (boxed), 3 one-sided (a limit, a frictionless contact).
_FRICTION_DOF = int(_C.mjCNSTR_FRICTION_DOF)
#: Whether a joint type's degrees of freedom are a joint's (free joints' damping is a Damping node's).
_JOINT_DOF = np.array([False, True, True, True])  # mjJNT_FREE, mjJNT_BALL, mjJNT_SLIDE, mjJNT_HINGE
_KIND = np.zeros(max(int(t) for t in _C.__members__.values()) + 1, int)
_KIND[int(_C.mjCNSTR_EQUALITY)] = 1
_KIND[[int(_C.mjCNSTR_FRICTION_DOF), int(_C.mjCNSTR_FRICTION_TENDON)]] = 2
_KIND[[int(_C.mjCNSTR_LIMIT_JOINT), int(_C.mjCNSTR_LIMIT_TENDON), int(_C.mjCNSTR_CONTACT_FRICTIONLESS)]] = 3


def _friction_islands(data: mujoco.MjData) -> np.ndarray:
    """The islands that hold a joint friction row (a motor row, a joint's `staticFriction`)."""
    nefc = data.nefc
    island = data.efc_island[:nefc]
    return np.unique(island[(data.efc_type[:nefc] == _FRICTION_DOF) & (island >= 0)])


def _other_rows(data: mujoco.MjData, islands: np.ndarray) -> tuple[np.ndarray, tuple[np.ndarray, np.ndarray]]:
    """The islands' rows other than their contacts' sliding rows, and their (lower, upper) force bounds.

    Equalities (a locked Connector's weld, a coupled joint) are unbounded; friction losses (a joint's
    `staticFriction`) lie within ±their loss; joint limits and
    frictionless contacts are one-sided. Torsional and rolling rows keep MuJoCo's forces.
    """
    nefc = data.nefc
    kind = _KIND[data.efc_type[:nefc]]
    if not kind.any():
        return np.zeros(0, int), (np.zeros(0), np.zeros(0))
    chosen = np.zeros(data.nisland, bool)
    chosen[islands] = True
    island = data.efc_island[:nefc]
    rows = np.nonzero((kind > 0) & (island >= 0) & chosen[island])[0]
    kind, loss = kind[rows], data.efc_frictionloss[rows]
    lower = np.where(kind == 2, -loss, np.where(kind == 3, 0.0, -np.inf))
    upper = np.where(kind == 2, loss, np.inf)
    return rows, (lower, upper)


def _ode_turn(frames: np.ndarray, friction: np.ndarray) -> tuple[np.ndarray, np.ndarray] | None:
    """Per contact, the turn (cos, sin) from MuJoCo's friction axes to ODE's; None when no box turns.

    ODE's contact joint takes its friction directions from the normal alone (dPlaneSpace: p in the y-z
    plane for a normal near ±z, else in the x-y plane; q = n × p). MuJoCo's frame (n, t1, t2) is
    right-handed too, so ODE's axes are MuJoCo's turned about n: p = cos·t1 + sin·t2. A box turned by
    a multiple of 90 degrees is the same box (a floor's contacts, whose t1 and t2 MuJoCo aligns with
    the world's axes): then nothing is turned. Contacts whose two μ differ (asymmetric friction,
    oriented by wbtc.runtime.contact_frames) keep their axes. The axes are the model's (ENU); in a NUE
    world a floor's or a wall's are the same lines as Webots'.
    """
    nx, ny, nz = frames[:, 0], frames[:, 1], frames[:, 2]
    t1, t2 = frames[:, 3:6], frames[:, 6:9]
    # p · t for p = (0, -nz, ny) / r (a normal near ±z) or (-ny, nx, 0) / r (any other).
    upright = np.abs(nz) > np.sqrt(0.5)
    if upright.all():  # floors, the usual case
        r = np.sqrt(ny * ny + nz * nz)
        cos = (ny * t1[:, 2] - nz * t1[:, 1]) / r
        sin = (ny * t2[:, 2] - nz * t2[:, 1]) / r
    else:
        a, b, c = np.where(upright, 0.0, -ny), np.where(upright, -nz, nx), np.where(upright, ny, 0.0)
        r = np.sqrt(a * a + b * b + c * c)
        cos = (a * t1[:, 0] + b * t1[:, 1] + c * t1[:, 2]) / r
        sin = (a * t2[:, 0] + b * t2[:, 1] + c * t2[:, 2]) / r
    asymmetric = friction[:, 0] != friction[:, 1]
    cos[asymmetric], sin[asymmetric] = 1.0, 0.0
    if np.all(np.abs(cos * sin) < 1e-12):
        return None
    return cos, sin


def _turn(turn: tuple[np.ndarray, np.ndarray], values: np.ndarray, n: int) -> np.ndarray:
    """The first and second friction rows' `values` (rows, or one number each) turned by (cos, sin)."""
    shape = (n,) + (1,) * (values.ndim - 1)
    cos, sin = turn[0].reshape(shape), turn[1].reshape(shape)
    first, second = values[:n], values[n:]
    return np.concatenate([cos * first + sin * second, cos * second - sin * first])
