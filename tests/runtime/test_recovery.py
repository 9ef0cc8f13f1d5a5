"""Bodies started or set deep inside others leave at ODE's speed on MuJoCo's default contact (wbtc.runtime.recovery)."""

from pathlib import Path

from wbtc.runtime import recovery
from wbtc.runtime.launch import prepare
from wbtc.runtime.poses import set_local_pose

#: A 0.1 m box (1 kg) started with its centre 2 cm above the floor: 3 cm inside it.
_WORLD = """#VRML_SIM R2023b utf8
WorldInfo {{
  basicTimeStep 32
  contactProperties [ {laws} ]
}}
Solid {{
  children [ Shape {{ geometry DEF FLOOR Plane {{ size 10 10 }} }} ]
  boundingObject USE FLOOR
}}
DEF BOX Solid {{
  translation 0 0 {height}
  children [ DEF BOX_SHAPE Shape {{ geometry Box {{ size 0.1 0.1 0.1 }} }} ]
  boundingObject USE BOX_SHAPE
  physics Physics {{ }}
}}
"""


def _simulation(tmp_path: Path, height: float = 0.02, laws: str = ""):  # noqa: ANN202
    world = tmp_path / "inside.wbt"
    world.write_text(_WORLD.format(height=height, laws=laws))
    return prepare(world).sim


def _rise(sim, steps: int) -> tuple[list[float], list[float]]:  # noqa: ANN001
    """The box's height and vertical speed after each of `steps` basic steps."""
    heights, speeds = [], []
    for _ in range(steps):
        sim.step()
        heights.append(float(sim.data.qpos[2]))
        speeds.append(float(sim.data.qvel[2]))
    return heights, speeds


def test_a_box_started_in_the_floor_rises_at_odes_speed_without_a_hop(tmp_path: Path) -> None:
    heights, speeds = _rise(_simulation(tmp_path), 32)
    # ODE takes softERP (0.2) of the depth out per 32 ms step: 0.8^n x 3 cm deep after n steps, at
    # 0.1875 m/s at most. MuJoCo's own spring threw the box up at 1.17 m/s, to 9.6 cm (4.6 cm above
    # where it rests).
    assert max(speeds) < 0.1875
    assert max(heights) < 0.0501
    for n in (1, 2, 5, 10):
        assert abs(heights[n - 1] - (0.05 - 0.03 * 0.8**n)) < 5e-4, n
    assert abs(heights[-1] - 0.05) < 1e-3


def test_the_rate_is_the_contact_properties_soft_erp(tmp_path: Path) -> None:
    heights, _ = _rise(_simulation(tmp_path, laws="ContactProperties { softERP 0.5 }"), 3)
    # Half the depth out per step, within 1 mm: the substeps reach the faster speed from rest (0.8 mm
    # behind after the first step, 0.3 mm after the third), where ODE's row reaches it at once.
    for n in (1, 2, 3):
        assert abs(heights[n - 1] - (0.05 - 0.03 * 0.5**n)) < 1e-3, n
    assert heights[2] > 0.05 - 0.03 * 0.8**3 + 0.005  # well out of reach of the default 0.2


def test_a_resting_box_keeps_mujocos_contact(tmp_path: Path) -> None:
    sim = _simulation(tmp_path, height=0.05)
    _rise(sim, 10)
    assert sim.data.ncon and -recovery.DEEP < float(sim.data.contact.dist.min()) < 0
    assert not sim.per_model[3].pairs


def test_an_impact_keeps_mujocos_contact(tmp_path: Path) -> None:
    # Dropped from 0.5 m, the box lands at 3.1 m/s and MuJoCo's contact lets it 3 mm in (at a step's
    # end): an impact, not a placed overlap, so no pair is tracked and MuJoCo's row sends it back up.
    sim = _simulation(tmp_path, height=0.55)
    deepest, pairs = 0.0, 0
    for _ in range(20):
        sim.step()
        if sim.data.ncon:
            deepest = min(deepest, float(sim.data.contact.dist.min()))
        pairs += len(sim.per_model[3].pairs)
    assert deepest < -2 * recovery.DEEP
    assert pairs == 0


def test_a_box_a_supervisor_sets_inside_the_floor_rises_at_odes_speed(tmp_path: Path) -> None:
    sim = _simulation(tmp_path, height=0.05)
    _rise(sim, 10)
    box = next(node for node in sim.result.scene.nodes if node.def_name == "BOX")
    assert set_local_pose(sim, box, [0.0, 0.0, 0.02], None)
    assert sim.moved
    heights, speeds = _rise(sim, 2)
    assert not sim.moved
    assert max(speeds) < 0.1875
    assert abs(heights[1] - (0.05 - 0.03 * 0.8**2)) < 5e-4


_GRIPPER = """#VRML_SIM R2025a utf8
WorldInfo { basicTimeStep 16 }
Robot {
  children [ Robotiq3fGripper { translation 0 0 0.5 } ]
  controller "<none>"
  selfCollision TRUE
}
"""


def test_a_finger_hinged_inside_its_palm_is_held_by_its_motor(tmp_path: Path) -> None:
    # Webots' Robotiq 3F has its scissor fingers' proximal boxes 2 to 3.5 cm inside the palm's box, a pair
    # Webots collides (selfCollision TRUE). ODE's row is a spring (softCFM 0.001) the 100 N.m motors
    # hold against; MuJoCo's stiff row, asked for ODE's speed with any force, opened them: to 1.90 rad
    # here (0.33 on a corpus world's UR5e), 0.091 with ODE's softness.
    world = tmp_path / "gripper.wbt"
    world.write_text(_GRIPPER)
    sim = prepare(world).sim
    model = sim.model
    fingers = [model.joint(f"robot/finger_{n}_link_1").qposadr[0] for n in (1, 2)]
    sim.step()
    assert sim.per_model[3].pairs  # the palm and the two fingers, placed inside each other
    while sim.time < 1.0:
        sim.step()
    for address in fingers:
        assert abs(float(sim.data.qpos[address]) - 0.0495) < 0.05
    assert float(sim.data.contact.dist.min()) < -0.03  # still inside: the motor holds, as in Webots
