"""Joint stops (`minStop`, `maxStop` with HingeJointParameters `stopERP`, `stopCFM`) as ODE's stop rows.

Webots gives a joint at one of its stops an ODE limit row: one-sided (it only pushes the joint back
into its range), with regularisation R = stopCFM / h and target relative velocity stopERP·depth / h
(h: `basicTimeStep`). stopERP and stopCFM default to -1, which means WorldInfo's `ERP` and `CFM`
(0.2 and 1e-5); joints whose parameters have no such fields (a SliderJoint's, a Hinge2Joint's second
axis) get WorldInfo's values too, as ODE starts every joint's stops with its world's ERP and CFM.
With CFM 1e-5 the stop is hard for any link, however light: a 4e-8 kg m² gear (Webots'
HingeJointWithBacklash) stops against a pendulum 200 000 times heavier as it would against a wall.

MuJoCo's limit row solves the same equation as a contact row, so it gets the mapping of
`wbtc.compile.soft_contact`: ODE's ERP and CFM at `basicTimeStep` become the spring and damper they
stand for, re-expressed at MuJoCo's substep (CFM_s, ERP_s); the row gets R = CFM_s / h_s through
imp = diag / (diag + R) and the direct solref (−ERP_s·imp / h_s², −imp / h_s). stopERP 0 gives K = 0:
penetration is never corrected, only the velocity into the stop is stopped, as in ODE.

diag is MuJoCo's `diagApprox` of a limit row, the dof's `dof_invweight0` (its inverse inertia at the
reference pose, before the motor servos' armature exists). MuJoCo's impedance is at most 0.9999, so
R is at least 1e-4 × diag: for a gear of 4e-8 kg m² that is 2500, where the row's real A, with the
servo's armature on the gear, is near 100; the stop would give way like a spring. So a limited dof
whose inverse weight is above R / 1e-4 gets exactly that (the largest diag that still gives ODE's R).
MuJoCo also takes the dof's friction-loss rows' diag from `dof_invweight0`: on such a light limited
joint `staticFriction` is then that much harder too (closer to ODE's, a hard motor row).

Which stops are rows in a step is decided at the start of each basic step, as ODE does
(`wbtc.runtime.joint_stops`); a motor whose joint drives other links through an engaged stop gets
a servo gain for the links it then moves (`wbtc.runtime.motors`).

The parameters go into the compiled model only, not into the spec's MJCF (`wbtc compile`), which
cannot carry a dof's inverse weight; there the stops keep MuJoCo's default limit.
"""

from __future__ import annotations

import mujoco

from wbtc.compile.context import CompileContext
from wbtc.compile.soft_contact import MAX_IMP, Softness, row_terms
from wbtc.scene.model import Node

#: Webots' "use WorldInfo's value" for stopERP and stopCFM.
_WORLD = -1.0


def stop_softness(params: Node | None, world_erp: float, world_cfm: float) -> Softness:
    """The ERP and CFM of a joint axis's stops: its own stopERP/stopCFM where set, else WorldInfo's."""
    erp, cfm = world_erp, world_cfm
    if isinstance(params, Node):
        own_erp, own_cfm = params.get("stopERP"), params.get("stopCFM")
        if own_erp is not None and float(own_erp) != _WORLD:
            erp = float(own_erp)
        if own_cfm is not None and float(own_cfm) != _WORLD:
            cfm = float(own_cfm)
    return Softness(erp, cfm)


def record(ctx: CompileContext, joint: mujoco.MjsJoint, params: Node | None) -> None:
    """Remember a limited joint's stop softness until the model is compiled (see `apply`)."""
    softness = stop_softness(params, ctx.world_erp, ctx.world_cfm)
    ctx.joint_stops[joint.name] = (softness.erp, softness.cfm)


def apply(model: mujoco.MjModel, ctx: CompileContext) -> None:
    """Give every recorded joint's limit ODE's stop row (see the module docstring)."""
    basic, substep = ctx.table.basic_time_step / 1000.0, float(model.opt.timestep)
    for name, (erp, cfm) in ctx.joint_stops.items():
        joint = model.joint(name).id
        dof = int(model.jnt_dofadr[joint])
        terms = row_terms(Softness(erp, cfm), basic, substep)
        # The largest diag whose impedance MuJoCo can still represent gives R exactly (see above).
        diag = min(float(model.dof_invweight0[dof]), terms.r * MAX_IMP / (1.0 - MAX_IMP))
        model.dof_invweight0[dof] = diag
        solref, solimp = terms.parameters(diag)
        model.jnt_solref[joint] = solref
        model.jnt_solimp[joint] = solimp
