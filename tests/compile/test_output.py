"""Writing MJCF: a Display's texture (pixels made in memory) goes out as a PNG asset that plain MuJoCo loads."""

from pathlib import Path

import mujoco
import numpy as np
from PIL import Image

from wbtc.compile.output import write_mjcf
from wbtc.pipeline import compile_world

WORLD = """#VRML_SIM R2025a utf8
WorldInfo { }
Robot {
  children [
    Display {
      width 4
      height 2
      children [
        Shape {
          appearance Appearance { texture ImageTexture { } }
          geometry Box { size 0.1 0.1 0.01 }
        }
      ]
    }
  ]
}
"""


def test_a_display_texture_is_written_as_a_png_that_mujoco_loads(tmp_path: Path) -> None:
    world = tmp_path / "display.wbt"
    world.write_text(WORLD, encoding="utf-8")
    result, _ = compile_world(world)
    written = write_mjcf(result.spec, tmp_path / "display.xml")
    pngs = [p for p in written if p.suffix == ".png"]
    assert len(pngs) == 1 and pngs[0].parent.name == "display_assets"
    # The display's initial pixels: its ImageTexture has no image, so opaque white (RGBA: the display's
    # alpha reaches the renderer), at the display's size.
    assert np.array_equal(np.asarray(Image.open(pngs[0])), np.full((2, 4, 4), 255, dtype=np.uint8))
    model = mujoco.MjModel.from_xml_path(str(tmp_path / "display.xml"))
    assert (model.ntex, int(model.tex_width[0]), int(model.tex_height[0])) == (1, 4, 2)


JOINTS = """#VRML_SIM R2025a utf8
WorldInfo { }
Robot {
  children [
    HingeJoint {
      endPoint Solid {
        name "kinematic arm"
        children [ Shape { geometry Box { size 0.1 0.01 0.01 } } ]
      }
    }
    SliderJoint {
      endPoint Solid {
        translation 0 0.1 0
        name "finger"
        boundingObject Box { size 0.01 0.02 0.03 }
        physics Physics {
          density -1
          mass 0.03
          centerOfMass [ 0 0.01 0.02 ]
          inertiaMatrix [ 7e-06 6e-06 1e-06, 0 0 -1e-06 ]
        }
      }
    }
  ]
  boundingObject Box { size 0.1 0.1 0.1 }
  physics Physics { }
}
"""


def test_written_models_load_in_plain_mujoco_with_their_masses(tmp_path: Path) -> None:
    # A Physics-less end point (wbtc gives it a tiny mass to carry its joint) and a youBot finger whose
    # inertia sits on the triangle inequality (A + B = C): both used to make files MuJoCo refused.
    world = tmp_path / "joints.wbt"
    world.write_text(JOINTS, encoding="utf-8")
    result, _ = compile_world(world)
    write_mjcf(result.spec, tmp_path / "joints.xml")
    loaded = mujoco.MjModel.from_xml_path(str(tmp_path / "joints.xml"))
    for name in ("robot/kinematic arm", "robot/finger"):
        assert loaded.body(name).mass[0] == result.model.body(name).mass[0]
        np.testing.assert_allclose(loaded.body(name).inertia, result.model.body(name).inertia, rtol=1e-4)
