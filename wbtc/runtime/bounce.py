"""ODE's restitution (ContactProperties `bounce`, `bounceVelocity`) on MuJoCo's contact rows.

ODE (joints/contact.cpp) gives a contact's normal row the target speed max(ERP correction,
−bounce × v_n) when the incoming normal speed −v_n exceeds `bounceVelocity` (v_n: the bodies'
normal velocity at the start of the step, positive when they separate). MuJoCo has no restitution:
its normal row's reference acceleration a_ref (−B·v_n − K·imp·r) takes a contact to rest. So each
substep is split (wbtc.runtime.substeps): after `mj_step1` has made the contacts and their rows, a
landing contact's normal row gets a_ref = max(a_ref, (−bounce·v_n − v_n) / h), h the substep: the
velocity change that leaves it at `bounce` × its landing speed, as ODE's row is asked within its
step. Its regularisation R becomes ODE's, softCFM / basicTimeStep, so that all the rows of a landing
(a box's four corners) reach together the share of their targets that ODE's rows reach in Webots'
step (A / (A + R) for one row: 96.8 % for a 0.52 kg ball at 16 ms). wbtc's soft row at a substep has
a far larger R (ODE's for a step that short): a ball would leave at 1.88 instead of 2.0 m/s.

A contact bounces only in the substep it lands in (no deeper than −v_n·h: apart the substep
before). ODE makes its contacts again at every step, but wbtc's soft row lasts several substeps,
and a contact bounced at each of them would gain energy (a robot rocking on its base hopped higher
and higher, a dropped TouchSensor bounced back higher than it fell).

wbtc's cone is elliptic (wbtc.compile.world), so a contact's normal row is its first row.
"""

from __future__ import annotations

from collections.abc import Callable

import mujoco
import numpy as np

from wbtc.compile.bounce import BounceTable

Hook = Callable[[mujoco.MjModel, mujoco.MjData], None]


def bounce_hook(table: BounceTable | None, model: mujoco.MjModel) -> Hook | None:
    """The function that sets the approaching contacts' rows, or None when nothing in `model` bounces."""
    if table is None or len(table.geom_class) != model.ngeom or not np.isfinite(table.threshold):
        return None
    threshold = table.threshold
    classes, bounce, velocity = table.geom_class, table.bounce, table.velocity
    regularisation = table.regularisation

    def hook(model: mujoco.MjModel, data: mujoco.MjData) -> None:
        if not data.ncon:
            return
        contacts = data.contact
        # Cheap test first, as this runs at every substep (Python lists: NumPy's calls on a few values
        # cost more): no contact's normal row (its first, -1 when it has none: a false alarm at worst)
        # approaches fast enough to bounce.
        velocities = data.efc_vel.tolist()
        if not velocities or min(velocities[row] for row in contacts.efc_address.tolist()) > -threshold:
            return  # (no rows at all: every contact excluded, or a robot's own parts touching)
        rows = contacts.efc_address
        speed = data.efc_vel[rows]  # negative when the bodies approach
        first, second = classes[contacts.geom[:, 0]], classes[contacts.geom[:, 1]]
        # Landing: approaching fast enough, and no deeper than this substep's approach, so apart at the
        # substep before. ODE's contact lasts one step, wbtc's soft row several substeps: a contact
        # already being compressed must not bounce again at every substep.
        landing = ((rows >= 0) & (first >= 0) & (second >= 0) & (speed < -velocity[first, second])
                   & (contacts.dist >= speed * model.opt.timestep))
        if not landing.any():
            return
        rows, speed = rows[landing], speed[landing]
        first, second = first[landing], second[landing]
        # ODE's row of the landing: its R, softCFM / basicTimeStep (MuJoCo's R of the soft row at a
        # substep is ODE's for a step that short, far softer), so that the rows reach together the
        # share of their targets ODE's rows reach in Webots' step; then the bounce target.
        data.efc_R[rows] = regularisation[first, second]
        data.efc_D[rows] = 1.0 / data.efc_R[rows]
        mujoco.mj_island(model, data)  # the islands' copies of D, as mj_step1 made them
        mujoco.mj_projectConstraint(model, data)
        wanted = -(1.0 + bounce[first, second]) * speed / model.opt.timestep
        data.efc_aref[rows] = np.maximum(data.efc_aref[rows], wanted)

    return hook

