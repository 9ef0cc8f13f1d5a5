"""Webots' hinge-chain skip: bodies linked through hinges with one anchor never collide (wbtc.compile.hinge_chains)."""

from pathlib import Path

import mujoco
from conftest import simulation_of

# A shoulder of two hinges about one point (the anchor 0 0 0.5 in both joints' frames): the arm box
# overlaps the base box, two bodies up. `second` sets the second hinge's anchor.
WORLD = """#VRML_SIM R2025a utf8
WorldInfo {{ gravity 0 }}
Robot {{
  selfCollision TRUE
  children [
    DEF BASE Solid {{
      children [
        HingeJoint {{
          jointParameters HingeJointParameters {{ axis 1 0 0 anchor 0 0 0.5 }}
          endPoint DEF YOKE Solid {{
            children [
              HingeJoint {{
                jointParameters HingeJointParameters {{ axis 0 1 0 anchor {second} }}
                endPoint DEF ARM Solid {{
                  translation 0 0 0.35
                  children [ Shape {{ geometry DEF ARM_BOX Box {{ size 0.1 0.1 0.3 }} }} ]
                  boundingObject USE ARM_BOX
                  physics Physics {{ mass 1 }}
                  name "arm"
                }}
              }}
            ]
            physics Physics {{ mass 0.1 }}
            name "yoke"
          }}
        }}
      ]
      boundingObject Box {{ size 0.3 0.3 0.5 }}
      physics Physics {{ mass 5 }}
      name "base"
    }}
  ]
  physics Physics {{ mass 1 }}
}}
"""


def _arm_touches_base(tmp_path: Path, second: str) -> bool:
    sim = simulation_of(tmp_path, WORLD.format(second=second))
    try:
        model, data = sim.model, sim.data
        mujoco.mj_forward(model, data)
        arm, base = model.body("robot/ARM").id, model.body("robot/BASE").id
        touching = {frozenset(int(model.geom_bodyid[g]) for g in data.contact[i].geom) for i in range(data.ncon)}
        return frozenset((arm, base)) in touching
    finally:
        sim.close()


def test_two_hinges_about_one_anchor_spare_the_outer_link_and_the_base(tmp_path: Path):
    # The arm box spans z 0.2 to 0.5, the base box -0.25 to 0.25: 5 cm deep. Webots skips the pair
    # (both hinges' anchors are 0 0 0.5), and so does wbtc.
    assert not _arm_touches_base(tmp_path, "0 0 0.5")


def test_hinges_with_different_anchors_collide(tmp_path: Path):
    # A second hinge about another point ends Webots' climb: the arm and the base collide.
    assert _arm_touches_base(tmp_path, "0 0 0.4")
