"""Track: its devices, the belt's travelled distance, and the surface velocity that drives a tracked robot."""

import math
from pathlib import Path

import pytest

from wbtc.compile.track_belt import belt_path, plate_pose
from wbtc.pipeline import compile_world
from wbtc.runtime import commands
from wbtc.runtime.rebuild import swap_model
from wbtc.runtime.simulation import Simulation

_TRACK = """
    Track {{
      translation 0 {y} 0
      children [
        TrackWheel {{
          position -0.1 0
          radius 0.03
          children [
            Shape {{
              geometry Cylinder {{
                height 0.02
                radius 0.03
              }}
            }}
          ]
        }}
      ]
      name "{side} track"
      boundingObject Box {{
        size 0.26 0.04 0.06
      }}
      physics Physics {{
      }}
      device [
        PositionSensor {{
          name "{side} sensor"
        }}
        LinearMotor {{
          name "{side} motor"
        }}
        Brake {{
          name "{side} brake"
        }}
      ]
    }}"""

#: A 2 kg box between two 0.26 × 0.04 × 0.06 m tracks (1000 kg/m³: 0.624 kg each) on a floor, 20 ms steps.
WORLD = """#VRML_SIM R2023b utf8
WorldInfo {
  basicTimeStep 20
}
Solid {
  children [
    Shape {
      geometry Plane {
        size 10 10
      }
    }
  ]
  boundingObject Plane {
    size 10 10
  }
}
Robot {
  translation 0 0 0.03
  children [
    Shape {
      geometry Box {
        size 0.2 0.1 0.04
      }
    }
""" + _TRACK.format(y=0.07, side="left") + _TRACK.format(y=-0.07, side="right") + """
  ]
  boundingObject Box {
    size 0.2 0.1 0.04
  }
  physics Physics {
    density -1
    mass 2
  }
  controller "<none>"
}
"""


def _sim(tmp_path: Path, world: str = WORLD) -> Simulation:
    path = tmp_path / "tracked.wbt"
    path.write_text(world, encoding="utf-8")
    result, _ = compile_world(path)
    return Simulation(result, noise=False)


def _device(sim: Simulation, name: str):
    robot = sim.robots[0]
    tag = next(tag for tag, d in enumerate(robot.entry.devices) if d.name == name)
    return tag, robot.motors.get(tag) or robot.sensors.get(tag)


def test_the_devices_of_a_track_field_are_the_robots_in_webots_order(tmp_path):
    sim = _sim(tmp_path)
    robot = sim.robots[0]
    # A Track's devices come when the Track is met, in its `device` field's order.
    assert [d.name for d in robot.entry.devices] == ["left sensor", "left motor", "left brake",
                                                     "right sensor", "right motor", "right brake"]
    infos = {info["name"]: info for info in commands.device_infos(robot.entry)}
    assert infos["left motor"]["type"] == "LinearMotor"
    assert infos["left motor"]["sensor"] == 0 and infos["left motor"]["brake"] == 2
    assert infos["right sensor"]["motor"] == 4 and infos["right brake"]["sensor"] == 3
    sim.close()


def test_a_velocity_drives_the_robot_forward_at_the_belt_speed(tmp_path):
    sim = _sim(tmp_path)
    for side in ("left", "right"):
        motor = _device(sim, f"{side} motor")[1]
        motor.apply("setPosition", (math.inf,))
        motor.apply("setVelocity", (0.1,))
    sensor = _device(sim, "left sensor")[1]
    sensor.enable(20, sim.time_ms)
    for _ in range(10):
        sim.step()
    start = float(sim.data.xpos[sim.robots[0].body][0])
    for _ in range(50):
        sim.step()
    # The belt travels 0.1 m/s × 1.2 s; the robot goes 0.1 m in the last second, straight ahead.
    assert sensor.value == pytest.approx(0.12, abs=1e-12)
    assert float(sim.data.xpos[sim.robots[0].body][0]) - start == pytest.approx(0.1, abs=0.001)
    assert abs(float(sim.data.xpos[sim.robots[0].body][1])) < 1e-4
    sim.close()


def test_opposite_belts_turn_the_robot_clockwise(tmp_path):
    sim = _sim(tmp_path)
    for side, v in (("left", 0.1), ("right", -0.1)):
        motor = _device(sim, f"{side} motor")[1]
        motor.apply("setPosition", (math.inf,))
        motor.apply("setVelocity", (v,))
    for _ in range(25):
        sim.step()
    mat = sim.data.xmat[sim.robots[0].body].reshape(3, 3)
    # Left belt forward, right belt back: a turn to the right (negative yaw), on the spot.
    assert math.atan2(mat[1, 0], mat[0, 0]) < -0.1
    assert abs(float(sim.data.xpos[sim.robots[0].body][0])) < 0.005
    sim.close()


def test_position_control_moves_the_belt_with_webots_pid(tmp_path):
    sim = _sim(tmp_path)
    motor = _device(sim, "left motor")[1]
    motor.apply("setPosition", (0.05,))
    for _ in range(3):
        sim.step()
    # P = 10 on the belt's own position each 20 ms step: x ← x + 0.02 · 10 · (0.05 − x).
    expected = 0.0
    for _ in range(3):
        expected += 0.2 * (0.05 - expected)
    assert motor.belt.position == pytest.approx(expected, abs=1e-15)
    sim.close()


def test_a_force_gives_a_belt_speed_of_force_times_step_over_mass_and_the_brake_slows_it(tmp_path):
    sim = _sim(tmp_path)
    motor = _device(sim, "left motor")[1]
    brake_tag = _device(sim, "left brake")[0]
    motor.apply("setForce", (5.0,))
    sim.step()
    # Webots' rule: v = F · basicTimeStep / m, m the whole rigid robot (2 + 2 × 0.624 kg).
    mass = 2.0 + 2 * 0.26 * 0.04 * 0.06 * 1000
    assert motor.belt.mass == pytest.approx(mass)
    assert motor.belt.velocity == pytest.approx(5.0 * 0.02 / mass)
    commands._brake(sim, sim.robots[0].entry.devices[brake_tag], 100.0)
    previous = motor.belt.velocity
    sim.step()
    assert motor.belt.velocity == pytest.approx((5.0 - 100.0 * previous) * 0.02 / mass)
    sim.close()


def test_track_wheels_turn_with_the_belt(tmp_path):
    sim = _sim(tmp_path)
    motor = _device(sim, "left motor")[1]
    motor.apply("setPosition", (math.inf,))
    motor.apply("setVelocity", (0.03,))
    for _ in range(10):
        sim.step()
    # 0.03 m/s × 0.2 s over a 0.03 m radius: 0.2 rad about the Track's y axis.
    assert motor.belt.angles[0] == pytest.approx(0.2)
    sim.close()


CONVEYOR = """#VRML_SIM R2023b utf8
WorldInfo {
  basicTimeStep 16
}
Robot {
  children [
    Track {
      boundingObject Box {
        size 2 0.4 0.1
      }
      physics Physics {
      }
      device [
        LinearMotor {
          name "belt"
        }
      ]
    }
  ]
  controller "<none>"
}
Solid {
  translation 0 0 0.1
  boundingObject Box {
    size 0.1 0.1 0.1
  }
  physics Physics {
  }
}
"""


def test_a_static_track_carries_what_lies_on_it_along_its_x_axis(tmp_path):
    sim = _sim(tmp_path, CONVEYOR)
    motor = _device(sim, "belt")[1]
    motor.apply("setPosition", (math.inf,))
    motor.apply("setVelocity", (0.2,))
    box = sim.model.nbody - 1
    for _ in range(20):
        sim.step()
    start = float(sim.data.xpos[box][0])
    for _ in range(50):
        sim.step()
    # The belt's top runs forward: the box goes +x at the belt's 0.2 m/s (0.8 s).
    assert float(sim.data.xpos[box][0]) - start == pytest.approx(0.16, abs=0.002)
    sim.close()


def test_the_belt_path_runs_clockwise_round_two_wheels():
    path = belt_path([(-0.15, 0.0, 0.0575, True), (0.165, 0.0, 0.0575, True)])
    assert path.length == pytest.approx(2 * 0.315 + 2 * math.pi * 0.0575)
    # It starts on top of the first wheel going +x, and is halfway round the second wheel pointing down.
    assert path.at(0.0) == pytest.approx((-0.15, 0.0575, 0.0))
    assert path.at(0.315 + math.pi * 0.0575 / 2) == pytest.approx((0.165 + 0.0575, 0.0, -math.pi / 2))
    assert path.at(path.length + 0.1) == pytest.approx(path.at(0.1))


def test_a_concave_belt_wraps_an_outer_wheel_the_other_way():
    # The Track reference page's concave example: the middle wheel is outside the belt.
    wheels = [(-0.4, 0.0, 0.2, True), (0.0, 0.14, 0.1, False), (0.4, 0.0, 0.2, True)]
    path = belt_path(wheels)
    for first, second in zip(path.segments, path.segments[1:] + path.segments[:1], strict=True):
        assert first.end == pytest.approx(second.start)  # a closed path
    outer = next(s for s in path.segments if s.centre == (0.0, 0.14))
    assert outer.turn == 1.0
    # The belt dips under the outer wheel: its lowest point there is the wheel's bottom.
    u, v, _ = path.at(path.segments[0].length + outer.length / 2)  # the arc after the first run
    assert (u, v) == pytest.approx((0.0, 0.04), abs=1e-9)


PLATES = """#VRML_SIM R2023b utf8
WorldInfo {
  basicTimeStep 10
}
Robot {
  children [
    Track {
      children [
        TrackWheel {
          position -0.2 0
          radius 0.05
        }
        TrackWheel {
          position 0.2 0
          radius 0.05
        }
      ]
      boundingObject Box {
        size 0.5 0.1 0.1
      }
      physics Physics {
      }
      device [
        LinearMotor {
          name "belt"
        }
      ]
      animatedGeometry Shape {
        geometry Box {
          size 0.02 0.01 0.05
        }
      }
      geometriesCount 8
    }
  ]
  controller "<none>"
}
"""


def test_belt_plates_ride_round_the_path_with_the_belt(tmp_path):
    sim = _sim(tmp_path, PLATES)
    belt = _device(sim, "belt")[1].belt
    path = belt.entry.path
    assert len(belt.plates) == 8 and path.length == pytest.approx(0.8 + 2 * math.pi * 0.05)
    model = sim.model
    spacing = path.length / 8
    assert model.body_pos[belt.plates[1]] == pytest.approx(plate_pose(path, spacing)[0])
    motor = _device(sim, "belt")[1]
    motor.apply("setPosition", (math.inf,))
    motor.apply("setVelocity", (0.1,))
    for _ in range(10):
        sim.step()
    # 0.1 m/s for 0.1 s: every plate 1 cm further along (the first one on the top run, going +x).
    assert belt.position == pytest.approx(0.01)
    assert model.body_pos[belt.plates[0]] == pytest.approx([-0.2 + 0.01, 0.0, 0.05])
    for i, body in enumerate(belt.plates):
        assert model.body_pos[body] == pytest.approx(plate_pose(path, 0.01 + i * spacing)[0])
    sim.close()


def test_a_recompile_keeps_the_belts_travel(tmp_path):
    sim = _sim(tmp_path, PLATES)
    motor = _device(sim, "belt")[1]
    motor.apply("setPosition", (math.inf,))
    motor.apply("setVelocity", (0.1,))
    for _ in range(10):
        sim.step()
    result, _ = compile_world(tmp_path / "tracked.wbt")
    swap_model(sim, result, by_name=True)
    motor = _device(sim, "belt")[1]
    belt = motor.belt
    # The new belt goes on from 1 cm, its plates where they were, its motor still at 0.1 m/s.
    assert belt.position == pytest.approx(0.01)
    assert sim.model.body_pos[belt.plates[0]] == pytest.approx([-0.2 + 0.01, 0.0, 0.05])
    sim.step()
    assert belt.position == pytest.approx(0.011)
    sim.close()


@pytest.mark.parametrize(("rotation", "least", "most"), [("0 0", 0.0, 0.03), ("1.5708 1.5708", 0.09, 0.11)])
def test_belts_drive_on_a_floor_with_asymmetric_friction(tmp_path, rotation, least, most):
    # Both contact rules act in the same substep: the floor's friction is 0.002 along its x axis and 2
    # across it (Webots' formula for two aligned directions of [0.001 1]). Belts pushing along the
    # slippery direction barely move the robot; turned a quarter, the same belts drive it at their speed.
    world = WORLD.replace("WorldInfo {", "WorldInfo {\n  contactProperties [ ContactProperties { "
                          f"coulombFriction [ 0.001 1 ] frictionRotation {rotation} }} ]")
    sim = _sim(tmp_path, world)
    assert sim.table.asymmetric_friction is not None
    for side in ("left", "right"):
        motor = _device(sim, f"{side} motor")[1]
        motor.apply("setPosition", (math.inf,))
        motor.apply("setVelocity", (0.1,))
    for _ in range(10):
        sim.step()
    start = float(sim.data.xpos[sim.robots[0].body][0])
    for _ in range(50):
        sim.step()
    assert least <= float(sim.data.xpos[sim.robots[0].body][0]) - start <= most
    sim.close()
