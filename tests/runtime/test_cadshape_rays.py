"""Infra-red DistanceSensors see through CadShapes (Webots' infra-red rays meet Shape nodes only); cameras see them."""

import shutil
from pathlib import Path

from tests.conftest import simulation_of
from wbtc.runtime.commands import apply_commands

MESHES = Path(__file__).parents[1] / "compile" / "fixtures" / "meshes"

#: An infra-red sensor at the origin looking along +x. cad_parts.obj's blue box spans x 0.1 to 0.3 (and
#: y -0.1 to 0.1, z 0 to 0.4), so its face is 0.1 m ahead; a plain white Shape wall stands 0.35 m ahead.
_WORLD = """#VRML_SIM R2023b utf8
WorldInfo {{ basicTimeStep 32 }}
Solid {{
  translation 0 0 -0.2
  children [ {cad} ]
  name "cad"
}}
Solid {{
  translation 0.4 0 0
  children [ Shape {{ appearance PBRAppearance {{ roughness 0 metalness 0 }} geometry Box {{ size 0.1 1 1 }} }} ]
  name "wall"
}}
Robot {{
  children [
    DistanceSensor {{
      name "ir"
      type "infra-red"
      lookupTable [ 0 1000 0  0.5 0 0 ]
    }}
  ]
  controller "<none>"
}}
"""


def _reading(tmp_path: Path, cad: str) -> float:
    for name in ("cad_parts.obj", "cad_parts.mtl"):
        shutil.copy(MESHES / name, tmp_path / name)
    sim = simulation_of(tmp_path, _WORLD.format(cad=cad), "ir.wbt")
    robot = sim.robots[0]
    apply_commands(sim, robot, [(0, "enable", 32)])
    sim.step()
    return float(robot.sensors[0].value)


def test_an_infra_red_ray_passes_a_cadshape_and_reads_the_wall_behind(tmp_path: Path) -> None:
    through = _reading(tmp_path, 'CadShape { url [ "cad_parts.obj" ] }')
    nothing = _reading(tmp_path, "")
    # The wall's face is 0.35 m ahead: 1000 x (1 - 0.35 / 0.5) = 300 on a white wall, with or without
    # the CadShape before it.
    assert abs(through - 300) < 5
    assert through == nothing


def test_the_same_box_as_a_shape_is_seen(tmp_path: Path) -> None:
    # The blue box written as a Shape (with the mesh as its geometry) stops the ray 0.1 m ahead.
    seen = _reading(tmp_path, 'Shape { geometry Mesh { url [ "cad_parts.obj" ] } }')
    assert seen > 700
