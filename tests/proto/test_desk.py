"""wbtc's Desk: its top's upper face is at 0.71 m, where Webots' Desk bounds it and Webots' worlds rest things."""

from pathlib import Path

import mujoco
from conftest import simulation_of

# The Desk and Book of a Webots world (cyberbotics' webots-cloud-simulation-examples, robotino_example.wbt),
# as Webots saved them: the book lying on the desk, its centre 0.72 m high.
WORLD = """#VRML_SIM R2025a utf8
WorldInfo { basicTimeStep 16 }
Desk {
  translation -1.2162 2.14753 0
  rotation 0 0 1 -1.5707953071795862
}
Book {
  translation -1.22 2.14 0.72
  rotation 0.5199881374825417 0.6776611791705899 0.5199881374825417 -1.950445307179586
}
"""


def _book_on_desk(sim) -> list[float]:
    model, data = sim.model, sim.data
    book = model.body("book").id
    desk = model.body("desk").id
    return [float(data.contact[i].dist) for i in range(data.ncon)
            if {int(model.geom_bodyid[g]) for g in data.contact[i].geom} == {book, desk}]


def test_a_book_where_webots_left_it_rests_on_the_desk_top(tmp_path: Path):
    sim = simulation_of(tmp_path, WORLD)
    try:
        mujoco.mj_forward(sim.model, sim.data)
        start = _book_on_desk(sim)
        assert start and max(abs(d) for d in start) < 1e-4  # touching, neither above nor inside (was 1 cm in)
        z0 = float(sim.data.body("book").xpos[2])
        for _ in range(62):  # 1 s
            sim.step()
        assert abs(float(sim.data.body("book").xpos[2]) - z0) < 5e-4
    finally:
        sim.close()
