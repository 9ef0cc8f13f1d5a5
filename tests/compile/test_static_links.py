"""A body hinged to the static environment touches no static geometry; the links beyond it still do (Webots)."""

from pathlib import Path

import mujoco

from wbtc.pipeline import compile_world

#: A static base (no Physics) on a static floor, an arm link hinged to the base and sunk 1 cm into both,
#: a second link hinged to the first, also sunk 1 cm into the floor, and a pad with Physics fixed to the
#: static base (an ODE body of its own in Webots) sunk 1 cm into the first link's top.
_WORLD = """#VRML_SIM R2023b utf8
WorldInfo { }
Solid {
  children [ Shape { geometry DEF FLOOR Plane { size 4 4 } } ]
  name "floor"
  boundingObject USE FLOOR
}
Robot {
  translation 0 0 0.1
  children [
    Shape { geometry DEF BASE Box { size 0.2 0.2 0.2 } }
    Solid {
      translation 0.19 0 0.11
      children [ Shape { geometry DEF PAD Box { size 0.1 0.1 0.06 } } ]
      name "pad"
      boundingObject USE PAD
      physics Physics { }
    }
    HingeJoint {
      jointParameters HingeJointParameters { axis 0 1 0 anchor 0.1 0 0 }
      endPoint Solid {
        translation 0.19 0 -0.01
        children [
          Shape { geometry DEF LINK Box { size 0.2 0.1 0.2 } }
          HingeJoint {
            jointParameters HingeJointParameters { axis 0 1 0 anchor 0.1 0 0 }
            endPoint Solid {
              translation 0.2 0 0
              children [ Shape { geometry DEF TIP Box { size 0.2 0.1 0.2 } } ]
              name "tip"
              boundingObject USE TIP
              physics Physics { }
            }
          }
        ]
        name "link"
        boundingObject USE LINK
        physics Physics { }
      }
    }
  ]
  boundingObject USE BASE
  selfCollision TRUE
  controller "<none>"
}
"""


def _touching(tmp_path: Path) -> set[frozenset[str]]:
    world = tmp_path / "arm.wbt"
    world.write_text(_WORLD)
    model = compile_world(world)[0].model
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    names = [model.body(int(model.geom_bodyid[g])).name for g in range(model.ngeom)]
    return {frozenset((names[c.geom[0]], names[c.geom[1]])) for c in data.contact[:data.ncon]}


def test_the_link_hinged_to_the_static_base_touches_neither_the_base_nor_the_floor(tmp_path: Path) -> None:
    touching = _touching(tmp_path)
    # Webots: ODE's dAreConnectedExcluding(link, 0) is true, so the link skips every static geom; the
    # tip, hinged to the link (a body), still rests on the floor, and the pad, which has Physics, still
    # touches the link.
    assert touching == {frozenset(("floor", "robot/tip")), frozenset(("robot/pad", "robot/link"))}
