"""A lidar's own shapes are cast once and reused while they stay put: the same ranges, one batch per scan."""

from pathlib import Path

import mujoco
import numpy as np
import pytest

from wbtc.pipeline import compile_world
from wbtc.runtime.lidar import Lidar
from wbtc.runtime.simulation import Simulation
from wbtc.runtime.visible_rays import VisibleRays

# A robot with Physics (its own weld group) carrying a lidar inside a housing cylinder (met from
# inside: invisible), a post within `near` in front of it (clipped), and a turret on a hinge below
# the lidar with a fin the rays meet beyond `near`; walls and a free box around.
WORLD = """#VRML_SIM R2023b utf8
WorldInfo { basicTimeStep 16 }
Solid { translation 1.5 0 0.25 children [ Shape { geometry Box { size 0.1 4 0.5 } } ]
        boundingObject Box { size 0.1 4 0.5 } name "east" }
Solid { translation 0 1.2 0.25 children [ Shape { geometry Box { size 4 0.1 0.5 } } ]
        boundingObject Box { size 4 0.1 0.5 } name "north" }
Solid { translation -0.6 -0.5 0.1 children [ Shape { geometry Box { size 0.2 0.2 0.2 } } ]
        boundingObject Box { size 0.2 0.2 0.2 } physics Physics { } name "box" }
Robot {
  translation 0 0 0.05
  children [
    Shape { geometry Box { size 0.2 0.2 0.1 } }
    Lidar {
      translation 0 0 0.1
      children [
        Shape { geometry Cylinder { radius 0.03 height 0.02 } }
        Pose { translation 0.03 0.01 0 children [ Shape { geometry Box { size 0.01 0.01 0.05 } } ] }
        HingeJoint {
          jointParameters HingeJointParameters { axis 0 0 1 }
          device [ RotationalMotor { name "turret" } ]
          endPoint Solid {
            children [ Pose { translation -0.15 0 0 children [ Shape { geometry Box { size 0.02 0.1 0.05 } } ] } ]
            physics Physics { }
          }
        }
      ]
      horizontalResolution 90
      fieldOfView 6.28
      numberOfLayers 1
      near 0.05
      minRange 0.06
      maxRange 3
    }
  ]
  boundingObject Box { size 0.2 0.2 0.1 }
  physics Physics { }
  controller "<none>"
}
"""


@pytest.fixture
def sim(tmp_path: Path) -> Simulation:
    (tmp_path / "world.wbt").write_text(WORLD, encoding="utf-8")
    result, _ = compile_world(tmp_path / "world.wbt")
    return Simulation(result, seed=1, noise=False)


def lidar_of(sim: Simulation) -> Lidar:
    return next(s for s in sim.robots[0].sensors.values() if isinstance(s, Lidar))


def test_own_shapes_are_the_robot_housing_post_and_turret_not_the_world(sim):
    lidar = lidar_of(sim)
    lidar.sample(sim)
    model = sim.model
    robot = model.site_bodyid[lidar.site]
    bodies = sorted(int(model.geom_bodyid[g]) for g in lidar.caster._own)
    turret = [b for b in bodies if b != model.body_weldid[robot]]
    # The robot's box, the housing and the post are welded to the robot; the fin is on the turret.
    assert len(bodies) == 4 and len(turret) == 1
    assert model.body_parentid[turret[0]] == robot and model.body_jntnum[turret[0]] == 1
    assert lidar.caster._others and 0 not in {int(model.body_weldid[model.geom_bodyid[g]]) for g in lidar.caster._own}


def test_ranges_match_casting_at_everything_while_the_robot_drives_and_the_turret_turns(sim):
    lidar = lidar_of(sim)
    plain = VisibleRays(lidar.near)
    model, data = sim.model, sim.data
    free = model.jnt_qposadr[model.body_jntadr[model.site_bodyid[lidar.site]]]
    hinge = next(j for j in range(model.njnt) if model.jnt_type[j] == mujoco.mjtJoint.mjJNT_HINGE)
    limit = np.full(len(lidar.rays), lidar.max_range)
    every = np.arange(len(lidar.rays))
    seen_fin = full_casts = 0
    for k in range(60):
        data.qpos[free:free + 2] += (0.01, -0.005)  # drive
        if 20 <= k < 30:
            data.qpos[model.jnt_qposadr[hinge]] += 0.3  # the turret turns, then stays
        mujoco.mj_forward(model, data)
        pos, mat = lidar.frame(sim)
        own = lidar.caster.cast(sim, pos, mat, every, limit)
        everything = plain.cast(sim, pos, lidar.rays @ mat.T, limit)
        # Same rays, same shapes: equal but for the last bit of a distance cast in another batch.
        assert np.array_equal(np.isinf(own), np.isinf(everything)), k
        assert np.allclose(own, everything, rtol=0, atol=1e-12), k
        seen_fin += int(np.sum(np.abs(own - 0.14) < 0.02))
        full_casts += lidar.caster._dist is None
    assert seen_fin > 0  # the turret's fin, 0.14 m away, is seen (and is what the turn moves)
    # Casts at everything: the first scan and the ten scans the turret turned; driving moves no own shape.
    assert full_casts == 11


def test_a_still_scan_casts_one_batch_at_the_world(sim, monkeypatch):
    lidar = lidar_of(sim)
    calls = []
    cast = VisibleRays._multi_ray
    monkeypatch.setattr(VisibleRays, "_multi_ray", lambda self, *a: calls.append(len(a[3])) or cast(self, *a))
    lidar.sample(sim)  # new model: everything is cast
    lidar.sample(sim)  # still: the own shapes are cast once, then the world
    calls.clear()
    lidar.sample(sim)
    assert calls == [90]  # one batch of every ray; the housing and the post no longer cost a second
