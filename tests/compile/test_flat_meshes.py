"""Flat IndexedFaceSets (a floor drawn as faces, a single triangle): they compile and things rest on them.

MuJoCo collides meshes through their convex hull and refused both (coplanar vertices; fewer than 4
vertices), so a world Webots opens failed to compile. ODE collides the triangles themselves.
"""

from pathlib import Path

import pytest

from wbtc.runtime.launch import prepare

_WORLD = """#VRML_SIM R2023b utf8
WorldInfo {{ basicTimeStep 32 }}
Solid {{
  children [ DEF FACES Shape {{ geometry IndexedFaceSet {{ coord Coordinate {{ point [ {points} ] }}
                                                         coordIndex [ {index} ] }} }} ]
  boundingObject USE FACES
}}
Solid {{
  translation 0.2 0.2 0.3
  children [ DEF BALL Shape {{ geometry Sphere {{ radius 0.1 }} }} ]
  boundingObject USE BALL
  physics Physics {{ }}
}}
Shape {{ geometry IndexedFaceSet {{ coord Coordinate {{ point [ 0 0 1, 1 0 1, 0 1 1 ] }} coordIndex [ 0 1 2 -1 ] }} }}
"""


@pytest.mark.parametrize(("points", "index"), [
    ("0 0 0, 1 0 0, 1 1 0, 0 1 0", "0 1 2 3 -1"),  # a square
    ("0 0 0, 1 0 0, 0 1 0", "0 1 2 -1"),  # one triangle
])
def test_a_ball_rests_on_a_flat_face_set(tmp_path: Path, points: str, index: str) -> None:
    world = tmp_path / "flat.wbt"
    world.write_text(_WORLD.format(points=points, index=index))
    sim = prepare(world).sim
    for _ in range(60):
        sim.step()
    x, y, z = sim.data.qpos[:3]
    assert (x, y) == pytest.approx((0.2, 0.2), abs=1e-9)
    # On the faces (the hull's half thickness, 5e-5 of 1 m, above them), less MuJoCo's contact depth.
    assert z == pytest.approx(0.1, abs=1e-4)
    assert float(sim.data.qvel[2]) == pytest.approx(0.0, abs=1e-6)
