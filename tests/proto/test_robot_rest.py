"""Every robot of wbtc's library stands still at its default pose on a floor, as Webots' default puts it.

A robot left without a controller holds its joints; at Webots' default translation it rests where it
is. The robots listed in MOVES move in Webots too, from facts their headers give (Webots' own
default leaves them in the air or a few millimetres in the ground, or they tip onto a caster).
"""

import re
from pathlib import Path

import numpy as np
import pytest
from conftest import simulation_of

ROBOTS = Path(__file__).resolve().parents[2] / "protos" / "robots"

#: Robots whose default pose is not a resting pose in Webots either, and why (see each header).
MOVES = {
    "DARwInOP": "Webots' crouch puts the soles 16 mm into the floor and the robot rocks onto them",
    "RobotisOp2": "Webots' crouch puts the soles 16 mm into the floor and the robot rocks onto them",
    "Mavic2Pro": "its front legs start 4.75 mm in the ground and it tips back onto its body box",
    "Mir100UltrasonicSensor": "a part of the MiR100: alone its 8.5 g board is centred on its origin, half in "
                              "the floor, and is pushed out",
    "Pioneer3dx": "its caster is 7.9 mm above the floor: it tips back onto it",
    "Robotino3": "Webots' default puts its wheels 3.85 mm into the floor (about ODE's resting depth)",
    "Spot": "Webots' default leaves its feet 9.7 mm above the floor: it drops onto them and stands",
    "SpotLeg": "a leg of Spot, hidden in Webots: alone no Solid holds its hinges, which Webots (and wbtc) then "
               "leave unattached, so its links fall",
    "TiagoBase": "Webots' default puts it 3.5 mm into the floor (about ODE's resting depth)",
    "TiagoLite": "Webots' default puts it 3.5 mm into the floor (about ODE's resting depth)",
    "TiagoIron": "Webots' default puts it 3.5 mm into the floor (about ODE's resting depth), as TiagoLite",
    "TiagoSteel": "Webots' default puts it 3.5 mm into the floor (about ODE's resting depth), as TiagoLite",
    "TiagoTitanium": "Webots' default puts it 3.5 mm into the floor (about ODE's resting depth), as TiagoLite",
    "Tiago++": "Webots' default puts it 3.5 mm into the floor (about ODE's resting depth), as TiagoLite",
    "TiagoBody": "a part of TIAGo placed for its base's body slot: alone it falls",
    "TinkerbotsBase": "the 4 cm block is centred on its origin, half in the floor at Webots' default",
    "WallFollowingPioneer3dx": "its caster is 7.9 mm above the floor: it tips back onto it (as Pioneer3dx)",
    "Yamor": "its head plate starts 0.6 mm in the ground and it tips onto its body block",
    "Youbot": "Webots' default leaves its wheels 15 mm in the air",
}


def _robots() -> list[str]:
    names = []
    for path in sorted(ROBOTS.glob("*.proto")):
        if re.search(rf"PROTO\s+{re.escape(path.stem)}\s*\[", path.read_text(encoding="utf-8")):
            names.append(path.stem)
    return names


def test_the_list_of_moving_robots_names_library_robots():
    assert set(MOVES) <= set(_robots())


@pytest.mark.parametrize("name", [n for n in _robots() if n not in MOVES])
def test_a_library_robot_rests_at_its_default_pose(tmp_path: Path, name: str):
    text = (ROBOTS / f"{name}.proto").read_text(encoding="utf-8")
    controller = ' controller "<none>"' if re.search(r"field\s+SFString\s+controller\b", text) else ""
    world = (f"#VRML_SIM R2025a utf8\nWorldInfo {{ basicTimeStep 16 }}\nFloor {{ size 20 20 }}\n"
             f"DEF R {name} {{{controller} }}\n")
    sim = simulation_of(tmp_path, world)
    try:
        model, data = sim.model, sim.data
        top = [b for b in range(1, model.nbody) if model.body_parentid[b] == 0 and model.body(b).name != "floor"][0]
        start = data.xpos[top].copy()
        while sim.time < 1.0:
            sim.step()
        shift = data.xpos[top] - start
        # Moose started 38 cm inside the floor before its default became Webots' 0 0 0.38.
        assert abs(float(shift[2])) < 2e-3 and float(np.linalg.norm(shift[:2])) < 2e-3, shift
    finally:
        sim.close()
