"""The simulator side of the Supervisor API, driven directly (no controller process)."""

from pathlib import Path

import numpy as np
import pytest

from wbtc.compile.compiler import compile_scene
from wbtc.pipeline import load_world
from wbtc.runtime.scene_tree import TYPE_CODES
from wbtc.runtime.simulation import Simulation
from wbtc.runtime.supervisor import SupervisorError, SupervisorHub

FIXTURES = Path(__file__).parent / "fixtures"


@pytest.fixture
def hub():
    world = FIXTURES / "referee.wbt"
    scene, _ = load_world(world)
    sim = Simulation(compile_scene(scene), noise=False)
    referee = next(r for r in sim.robots if r.entry.name == "referee")
    yield SupervisorHub(sim, scene, world), referee
    sim.close()


def _field(hub, robot, def_name, name):
    node = hub.call(robot, "getFromDef", (def_name, -1))
    return node, hub.call(robot, "node.getField", (node["id"], name, False))


def test_nodes_have_webots_ids_types_and_parents(hub):
    hub, referee = hub
    assert hub.call(referee, "getRoot", ()) == {"id": 0, "def": "", "type": "Group", "base_type": "Group",
                                                "proto": False, "parent": -1}
    driver = hub.call(referee, "getFromDef", ("DRIVER", -1))
    assert (driver["type"], driver["base_type"], driver["proto"], driver["parent"]) == ("E-puck", "Robot", True, 0)
    arm = hub.call(referee, "getFromDef", ("BOX.ARM", -1))
    box = hub.call(referee, "getFromDef", ("BOX", -1))
    assert (arm["type"], arm["parent"]) == ("Pose", box["id"])
    assert hub.call(referee, "getFromDef", ("NOPE", -1)) is None
    assert hub.call(referee, "getFromId", (box["id"],)) == box
    assert hub.call(referee, "getSelf", ())["def"] == "REFEREE"


def test_translation_reads_live_and_writes_move_the_body(hub):
    hub, referee = hub
    box, translation = _field(hub, referee, "BOX", "translation")
    assert translation["type"] == TYPE_CODES["SFVec3f"] == 0x05 and translation["count"] == -1
    assert hub.call(referee, "field.get", (translation["id"], -1)) == pytest.approx([1, 1, 0.05], abs=1e-12)
    hub.queue(referee, "field.set", (translation["id"], -1, [0.5, -0.25, 0.05]))
    assert not hub.flush().rebuilt
    assert hub.call(referee, "field.get", (translation["id"], -1)) == pytest.approx([0.5, -0.25, 0.05], abs=1e-12)
    assert hub.call(referee, "node.getPosition", (box["id"],)) == pytest.approx([0.5, -0.25, 0.05], abs=1e-12)
    # The Pose child moves with it: 0.1 above the box.
    arm = hub.call(referee, "getFromDef", ("BOX.ARM", -1))
    assert hub.call(referee, "node.getPosition", (arm["id"],)) == pytest.approx([0.5, -0.25, 0.15], abs=1e-12)


def test_reset_physics_stops_a_thrown_ball(hub):
    hub, referee = hub
    sim = hub.sim
    ball, _ = _field(hub, referee, "BALL", "translation")
    hub.queue(referee, "node.setVelocity", (ball["id"], [1.0, 0.0, 0.0, 0.0, 0.0, 0.0]))
    hub.flush()
    for _ in range(10):
        sim.step()
    assert hub.call(referee, "node.getVelocity", (ball["id"],))[0] > 0.5
    hub.queue(referee, "node.resetPhysics", (ball["id"],))
    hub.flush()
    assert hub.call(referee, "node.getVelocity", (ball["id"],)) == pytest.approx([0.0] * 6, abs=1e-12)


def test_import_and_remove_a_robot_recompiles_and_keeps_the_rest(hub):
    hub, referee = hub
    sim = hub.sim
    for _ in range(20):
        sim.step()
    ball_before = sim.data.xpos[sim.model.body(sim.table.solids[id(hub.tree.from_def("BALL"))][0]).id].copy()
    root = hub.call(referee, "getRoot", ())
    children = hub.call(referee, "node.getField", (root["id"], "children", False))
    count = children["count"]
    hub.queue(referee, "field.importMFNode", (children["id"], -1, 'DEF NEW E-puck { translation 2 2 0 name "new" }'))
    assert hub.flush().rebuilt
    assert [r.entry.name for r in sim.robots] == ["driver", "referee", "new"]
    assert hub.call(referee, "field.getCount", (children["id"],)) == count + 1
    new = hub.call(referee, "getFromDef", ("NEW", -1))
    assert new["type"] == "E-puck"
    assert hub.call(referee, "node.getPosition", (new["id"],))[:2] == pytest.approx([2, 2], abs=1e-9)
    ball_after = sim.data.xpos[sim.model.body(sim.table.solids[id(hub.tree.from_def("BALL"))][0]).id]
    np.testing.assert_allclose(ball_after, ball_before, atol=1e-12)
    hub.queue(referee, "node.remove", (new["id"],))
    assert hub.flush().rebuilt
    assert [r.entry.name for r in sim.robots] == ["driver", "referee"]
    assert hub.call(referee, "getFromDef", ("NEW", -1)) is None


def test_proto_field_change_reexpands_the_instance(hub):
    hub, referee = hub
    driver = hub.call(referee, "getFromDef", ("DRIVER", -1))
    name = hub.call(referee, "node.getField", (driver["id"], "name", False))
    assert hub.call(referee, "field.get", (name["id"], -1)) == "driver"
    hub.queue(referee, "field.set", (name["id"], -1, "renamed"))
    assert hub.flush().rebuilt
    assert [r.entry.name for r in hub.sim.robots] == ["renamed", "referee"]
    assert hub.call(referee, "getFromDef", ("DRIVER", -1))["id"] == driver["id"]


def test_labels_quit_and_errors(hub):
    hub, referee = hub
    hub.queue(referee, "setLabel", (1, "Frame: 3th", 0.8, 0.1, 0.1, 0xFF0000, 0.2, "Arial"))
    hub.queue(referee, "simulationQuit", (3,))
    hub.flush()
    assert hub.sim.labels == {1: ("Frame: 3th", 0.8, 0.1, 0.1, 0xFF0000, 0.2, "Arial")}
    assert hub.quit_status == 3
    with pytest.raises(SupervisorError, match="does not exist"):
        hub.call(referee, "node.getPosition", (9999,))


def test_simulation_reset_restores_the_initial_state(hub):
    hub, referee = hub
    sim = hub.sim
    box, translation = _field(hub, referee, "BOX", "translation")
    hub.queue(referee, "field.set", (translation["id"], -1, [3.0, 3.0, 0.05]))
    hub.flush()
    driver_state = next(r for r in sim.robots if r.entry.name == "driver")
    tag, sensor = next(iter(driver_state.sensors.items()))
    sensor.enable(16, sim.time_ms)  # as the driver's controller would have
    for _ in range(30):
        sim.step()
    sim.rng.random(5)  # noise drawn during the run
    hub.queue(referee, "simulationReset", ())
    outcome = hub.flush()
    assert outcome.reset
    # No controller starts over (Webots' Reset/Reload matrix): each robot keeps its devices' settings,
    # their next samples moved back with the clock.
    assert outcome.restart == [] and outcome.keep_controllers
    assert sim.time_ms == 0.0
    kept = next(r for r in sim.robots if r.entry.name == "driver").sensors[tag]
    assert kept is not sensor and kept.period == 16 and kept.next_due == pytest.approx(16.0)
    assert hub.call(referee, "field.get", (translation["id"], -1)) == pytest.approx([1, 1, 0.05], abs=1e-12)
    driver = hub.call(referee, "getFromDef", ("DRIVER", -1))
    assert hub.call(referee, "node.getPosition", (driver["id"],))[:2] == pytest.approx([-3, -3], abs=1e-9)
    # The random numbers (sensor noise) start over too, as Webots resets its seeds.
    assert sim.rng.random() == np.random.default_rng(sim.seed).random()


def test_proto_internals_through_base_fields_and_proto_defs(hub):
    hub, referee = hub
    driver = hub.call(referee, "getFromDef", ("DRIVER", -1))
    # getField of a PROTO instance is an interface field; getBaseNodeField a field of the Robot it expands to.
    interface = hub.call(referee, "node.getField", (driver["id"], "controller", False))
    assert hub.call(referee, "field.get", (interface["id"], -1)) == "drive"
    assert hub.call(referee, "node.getField", (driver["id"], "children", False)) is None
    children = hub.call(referee, "node.getField", (driver["id"], "children", True))
    assert children["type"] == 0x19 and children["count"] > 5
    # A DEF inside the PROTO is hidden from getFromDef but reached from the instance (getFromProtoDef).
    assert hub.call(referee, "getFromDef", ("EPUCK_COLUMN", -1)) is None
    column = hub.call(referee, "getFromDef", ("EPUCK_COLUMN", driver["id"]))
    assert column is not None and column["def"] == "EPUCK_COLUMN"


def test_merged_sensors_report_their_own_pose_and_their_robots_velocity(hub):
    # The E-puck's ps0 has no body of its own (the compiler merges massless, non-colliding devices
    # into their robot's body, as Webots merges them into its rigid body); the supervisor still sees
    # it where its site is, turned like it, and moving with the robot.
    hub, referee = hub
    sim = hub.sim
    driver = hub.call(referee, "getFromDef", ("DRIVER", -1))
    robot_node = hub.tree.by_id[driver["id"]]
    ps0 = next(i for i, n in hub.tree.by_id.items()
               if n.get("name") == "ps0" and n.base_type == "DistanceSensor" and hub.tree.parent(n) is robot_node)
    assert "driver/ps0" not in [sim.model.body(b).name for b in range(sim.model.nbody)]
    site = sim.model.site("driver/ps0").id
    assert hub.call(referee, "node.getPosition", (ps0,)) == pytest.approx(sim.data.site_xpos[site], abs=1e-9)
    assert hub.call(referee, "node.getOrientation", (ps0,)) == pytest.approx(sim.data.site_xmat[site], abs=1e-9)
    hub.queue(referee, "node.setVelocity", (driver["id"], [0.25, 0.0, 0.0, 0.0, 0.0, 0.0]))
    hub.flush()
    assert hub.call(referee, "node.getVelocity", (ps0,))[:3] == pytest.approx([0.25, 0.0, 0.0], abs=1e-9)


def test_save_and_load_states_and_the_initial_one(hub, capsys):
    hub, referee = hub
    sim = hub.sim
    ball = hub.call(referee, "getFromDef", ("BALL", -1))
    root = hub.call(referee, "getRoot", ())
    body = sim.model.body("BALL").id
    hub.queue(referee, "node.setVelocity", (ball["id"], [1.0, 0.0, 0.0, 0.0, 0.0, 0.0]))
    hub.flush()
    for _ in range(5):
        sim.step()
    saved_pos, saved_vel = sim.data.xpos[body].copy(), hub.call(referee, "node.getVelocity", (ball["id"],))
    hub.queue(referee, "node.saveState", (ball["id"], "thrown"))
    hub.flush()
    for _ in range(20):
        sim.step()
    assert np.linalg.norm(sim.data.xpos[body] - saved_pos) > 0.1
    hub.queue(referee, "node.loadState", (ball["id"], "thrown"))
    hub.flush()
    assert sim.data.xpos[body] == pytest.approx(saved_pos, abs=1e-12)
    assert hub.call(referee, "node.getVelocity", (ball["id"],)) == pytest.approx(saved_vel, abs=1e-12)
    # "__init__" is the world as it started: the ball back at the centre, at rest.
    hub.queue(referee, "node.loadState", (root["id"], "__init__"))
    hub.flush()
    assert sim.data.xpos[body] == pytest.approx([0.0, 0.0, 0.05], abs=1e-9)
    assert hub.call(referee, "node.getVelocity", (ball["id"],)) == pytest.approx([0.0] * 6, abs=1e-12)
    hub.queue(referee, "node.loadState", (ball["id"], "never saved"))
    hub.flush()
    assert "[referee] Error: wb_supervisor_node_load_state(): no state named 'never saved' was saved." in \
        capsys.readouterr().err


def _arm_supervisor(tmp_path):
    """fixtures/arm.wbt with its robot made a supervisor and its joint named SHOULDER."""
    text = (FIXTURES / "arm.wbt").read_text(encoding="utf-8")
    text = text.replace("    HingeJoint {", "    DEF SHOULDER HingeJoint {").replace('  controller "hold"',
                                                                                   "  supervisor TRUE")
    world = tmp_path / "arm.wbt"
    world.write_text(text, encoding="utf-8")
    scene, _ = load_world(world)
    sim = Simulation(compile_scene(scene), noise=False)
    hub, arm = SupervisorHub(sim, scene, world), sim.robots[0]
    return sim, hub, arm, hub.call(arm, "getFromDef", ("SHOULDER", -1))


def test_set_joint_position_turns_the_joint_at_once(tmp_path):
    sim, hub, arm, shoulder = _arm_supervisor(tmp_path)
    hub.queue(arm, "node.setJointPosition", (shoulder["id"], 0.5, 1))
    hub.flush()
    joint = sim.model.joint(sim.table.robots[0].device("shoulder").joint)
    assert sim.data.qpos[joint.qposadr[0]] == 0.5
    # The 0.2 m arm (its centre of mass at its end) turned 0.5 rad about +y: the end went down.
    com = sim.data.xipos[joint.bodyid[0]]
    assert com == pytest.approx([0.2 * np.cos(0.5), 0.0, 1.0 - 0.2 * np.sin(0.5)], abs=1e-9)
    # Its motor now targets 0.5 rad, as Webots' joints make their motor do: the arm stays there.
    motor = next(iter(arm.motors.values()))
    assert motor.target == 0.5
    for _ in range(60):
        sim.step()
    assert sim.data.qpos[joint.qposadr[0]] == pytest.approx(0.5, abs=0.01)
    sim.close()


def test_loading_a_state_makes_motors_hold_the_loaded_positions(tmp_path):
    # Webots resets a joint's motor, then sets the joint's saved position, which sets the motor's target:
    # a motor in velocity control when the state was saved holds the saved position after loading it.
    sim, hub, arm, shoulder = _arm_supervisor(tmp_path)
    motor = next(iter(arm.motors.values()))
    motor.apply("setPosition", (float("inf"),))
    motor.apply("setVelocity", (1.0,))
    for _ in range(10):
        sim.step()
    root = hub.call(arm, "getRoot", ())
    hub.queue(arm, "node.saveState", (root["id"], "turning"))
    hub.flush()
    joint = sim.model.joint(sim.table.robots[0].device("shoulder").joint)
    saved = float(sim.data.qpos[joint.qposadr[0]])
    for _ in range(10):
        sim.step()
    hub.queue(arm, "node.loadState", (root["id"], "turning"))
    hub.flush()
    assert sim.data.qpos[joint.qposadr[0]] == pytest.approx(saved, abs=1e-12) and motor.target == saved
    for _ in range(30):
        sim.step()
    assert sim.data.qpos[joint.qposadr[0]] == pytest.approx(saved, abs=0.01)
    sim.close()


def test_world_save_writes_joint_positions_and_leaves_the_scene_alone(tmp_path):
    sim, hub, arm, shoulder = _arm_supervisor(tmp_path)
    hub.queue(arm, "node.setJointPosition", (shoulder["id"], 0.5, 1))
    hub.queue(arm, "worldSave", (str(tmp_path / "saved.wbt"),))
    hub.flush()
    joint = sim.model.joint(sim.table.robots[0].device("shoulder").joint)
    end_com = sim.data.xipos[joint.bodyid[0]].copy()
    sim.close()
    saved = (tmp_path / "saved.wbt").read_text(encoding="utf-8")
    assert saved.startswith("#VRML_SIM R2023b utf8\n# A fixed robot holding a horizontal 0.2 m arm")
    # The running scene still holds what the file said.
    params = hub.tree.by_id[shoulder["id"]].get("jointParameters")
    assert params.get("position") == 0.0
    # Loaded again, the saved world starts with the arm at 0.5 rad, where it was.
    scene2, _ = load_world(tmp_path / "saved.wbt")
    sim2 = Simulation(compile_scene(scene2), noise=False)
    joint2 = sim2.model.joint(sim2.table.robots[0].device("shoulder").joint)
    assert sim2.data.qpos[joint2.qposadr[0]] == pytest.approx(0.5, abs=1e-9)
    assert sim2.data.xipos[joint2.bodyid[0]] == pytest.approx(end_com, abs=1e-9)
    sim2.close()


def test_proto_chain_of_a_derived_proto(tmp_path, capsys):
    (tmp_path / "RedBox.proto").write_text("""#VRML_SIM R2025a utf8
EXTERNPROTO "webots://projects/objects/geometries/protos/SolidBox.proto"
PROTO RedBox [
  field SFVec3f translation 0 0 0.05
  field SFVec3f size 0.1 0.1 0.1
]
{
  SolidBox {
    translation IS translation
    size IS size
    name "red box"
  }
}
""", encoding="utf-8")
    world = tmp_path / "derived.wbt"
    world.write_text("""#VRML_SIM R2025a utf8
EXTERNPROTO "RedBox.proto"
WorldInfo { basicTimeStep 16 }
DEF RB RedBox { translation 1 0 0.05 }
DEF SUP Robot { supervisor TRUE }
""", encoding="utf-8")
    scene, _ = load_world(world)
    sim = Simulation(compile_scene(scene), noise=False)
    hub, sup = SupervisorHub(sim, scene, world), sim.robots[0]
    box = hub.call(sup, "getFromDef", ("RB", -1))["id"]
    assert hub.call(sup, "node.getProto", (box,)) == ["RedBox", "SolidBox"]
    assert hub.call(sup, "proto.getNumberOfParameters", (box, 1)) == 2
    own = hub.call(sup, "proto.getParameter", (box, 1, "translation"))
    assert own == hub.call(sup, "node.getField", (box, "translation", False))  # the same Field as getField
    assert hub.call(sup, "field.get", (own["id"], -1)) == [1.0, 0.0, 0.05]
    name = hub.call(sup, "proto.getParameter", (box, 2, "name"))
    assert hub.call(sup, "field.get", (name["id"], -1)) == "red box"
    by_index = hub.call(sup, "proto.getParameterByIndex", (box, 2, 0))
    assert by_index["name"] == "translation" and by_index["id"] != own["id"]
    assert hub.call(sup, "proto.getParameter", (box, 2, "nope")) is None
    hub.queue(sup, "field.set", (name["id"], -1, "renamed"))
    hub.flush()
    assert "is a read-only PROTO internal field" in capsys.readouterr().err
    assert hub.call(sup, "field.get", (name["id"], -1)) == "red box"
    assert hub.call(sup, "node.getProto", (hub.call(sup, "getSelf", ())["id"],)) == []
    sim.close()


_PROTO_ARM = """#VRML_SIM R2023b utf8
PROTO PendulumArm [
  field SFVec3f translation 0 0 1
]
{
  Robot {
    translation IS translation
    children [
      HingeJoint {
        jointParameters HingeJointParameters { axis 0 1 0 }
        endPoint Solid {
          translation 0.2 0 0
          children [ Shape { geometry DEF ARM Box { size 0.2 0.02 0.02 } } ]
          boundingObject USE ARM
          physics Physics { density -1 mass 1 }
        }
      }
    ]
    controller "<none>"
  }
}
"""


def test_world_save_writes_hidden_lines_of_a_proto_instance(tmp_path):
    (tmp_path / "PendulumArm.proto").write_text(_PROTO_ARM, encoding="utf-8")
    world = tmp_path / "pendulum.wbt"
    world.write_text('#VRML_SIM R2023b utf8\nEXTERNPROTO "PendulumArm.proto"\nWorldInfo { gravity 0 }\n'
                     'PendulumArm { }\nRobot { name "saver" supervisor TRUE controller "<none>" }\n',
                     encoding="utf-8")
    scene, _ = load_world(world)
    sim = Simulation(compile_scene(scene), noise=False)
    hub = SupervisorHub(sim, scene, world)
    hinge = next(j for j in range(sim.model.njnt) if sim.model.jnt_type[j] == 3)
    sim.data.qpos[sim.model.jnt_qposadr[hinge]] = 0.5
    sim.step()
    hub.queue(sim.robots[1], "worldSave", (str(tmp_path / "saved.wbt"),))
    hub.flush()
    sim.close()
    saved = (tmp_path / "saved.wbt").read_text(encoding="utf-8")
    # Webots' numbering: Solid 0 is the PROTO's Robot, Solid 1 the arm; joint 0 among Solid 0's children.
    assert "  hidden position_0_0 0.5\n" in saved
    assert "  hidden rotation_1 0 1 0 0.5\n" in saved
    assert "hidden translation_0" not in saved  # the interface exposes the root's translation
    scene2, _ = load_world(tmp_path / "saved.wbt")
    sim2 = Simulation(compile_scene(scene2), noise=False)
    assert sim2.data.qpos[sim2.model.jnt_qposadr[hinge]] == pytest.approx(0.5, abs=1e-12)
    sim2.close()


def test_reset_physics_stops_a_motor_slowing_down_under_its_acceleration(tmp_path):
    # Webots resets the motors of the joints it stops: a motor braking at its `acceleration` does not
    # pick the joint up again at the speed its ramp had reached.
    sim, hub, arm, shoulder = _arm_supervisor(tmp_path)
    motor = next(iter(arm.motors.values()))
    motor.apply("setAcceleration", (10.0,))
    motor.apply("setPosition", (float("inf"),))
    motor.apply("setVelocity", (5.0,))
    for _ in range(40):
        sim.step()
    motor.apply("setVelocity", (0.0,))
    sim.step()
    joint = sim.model.joint(sim.table.robots[0].device("shoulder").joint)
    assert abs(float(sim.data.qvel[joint.dofadr[0]])) > 3.0  # still braking from 5 rad/s at 10 rad/s²
    hub.queue(arm, "node.resetPhysics", (hub.call(arm, "getSelf", ())["id"],))
    hub.flush()
    sim.step()
    assert abs(float(sim.data.qvel[joint.dofadr[0]])) < 0.05
    sim.close()


def test_fields_by_index_follow_webots_node_definitions(tmp_path):
    # Solid.wrl: translation, rotation, children, name ... recognitionColors, translationStep, rotationStep and
    # the hidden velocities; the deprecated `scale` of old Solids is no field of an R2023b Solid.
    sim, hub, arm, shoulder = _arm_supervisor(tmp_path)
    end = hub.tree.by_id[shoulder["id"]].get("endPoint")
    names = [name for name, _ in hub.tree.field_names(end, 0)]
    assert names[:4] == ["translation", "rotation", "children", "name"]
    assert "scale" not in names
    assert names[names.index("recognitionColors"):] == ["recognitionColors", "translationStep", "rotationStep",
                                                        "linearVelocity", "angularVelocity"]
    assert len(names) == 17
    sim.close()


def test_actual_field_follows_is_links_out_to_the_world(tmp_path):
    from wbtc.runtime.scene_tree import actual_field

    (tmp_path / "Inner.proto").write_text('#VRML_SIM R2025a utf8\nPROTO Inner [\n  field SFFloat a 0.5\n'
                                          '  field SFFloat loose 0.5\n]\n{\n  Solid { translationStep IS a }\n}\n')
    (tmp_path / "Outer.proto").write_text('#VRML_SIM R2025a utf8\nEXTERNPROTO "Inner.proto"\nPROTO Outer [\n'
                                          '  field SFFloat b 0.25\n]\n{\n  Inner { a IS b }\n}\n')
    world = tmp_path / "links.wbt"
    world.write_text('#VRML_SIM R2025a utf8\nEXTERNPROTO "Outer.proto"\nDEF O Outer { }\n'
                     'Robot { supervisor TRUE controller "<none>" }\n')
    scene, _ = load_world(world)
    sim = Simulation(compile_scene(scene), noise=False)
    hub = SupervisorHub(sim, scene, world)
    tree = hub.tree
    node = next(n for n in tree.by_id.values() if getattr(n, "def_name", None) == "O")
    b = tree.field(node, "b", 1)
    assert actual_field(tree, b) is b  # a field written in the world is its own actual field
    assert actual_field(tree, tree.field(node, "a", 2)) is b  # Inner's a IS Outer's b
    assert actual_field(tree, tree.field(node, "translationStep", 0)) is b  # the Solid's, through a and b
    assert actual_field(tree, tree.field(node, "loose", 2)) is None  # linked to nothing
    sim.close()


def test_simulation_reset_keeps_written_fields_and_removals_and_drops_imports(hub):
    # Webots' Reset/Reload matrix, "Reset from Supervisor": Solids' poses come back, nodes added since
    # the start go, but other fields keep what a supervisor wrote and removed nodes stay removed.
    hub, referee = hub
    sim = hub.sim
    _, arm = _field(hub, referee, "ARM", "translation")  # a Pose: not reset
    _, box = _field(hub, referee, "BOX", "translation")  # a Solid: reset
    driver, args = _field(hub, referee, "DRIVER", "controllerArgs")
    ball = hub.call(referee, "getFromDef", ("BALL", -1))
    root = hub.call(referee, "getRoot", ())
    children = hub.call(referee, "node.getField", (root["id"], "children", False))
    count = children["count"]
    hub.queue(referee, "field.set", (arm["id"], -1, [0.0, 0.0, 0.3]))
    hub.queue(referee, "field.set", (box["id"], -1, [2.0, 2.0, 0.05]))
    hub.queue(referee, "field.set", (args["id"], 0, "1.0"))
    hub.queue(referee, "field.importMFNode", (children["id"], -1, 'DEF EXTRA Solid { translation 0 2 0.05 }'))
    hub.queue(referee, "node.remove", (ball["id"],))
    hub.flush()
    for _ in range(10):
        sim.step()
    assert hub.call(referee, "field.getCount", (children["id"],)) == count  # one in, one out
    hub.queue(referee, "simulationReset", ())
    assert hub.flush().reset
    assert sim.time_ms == 0.0
    assert hub.call(referee, "field.get", (box["id"], -1)) == pytest.approx([1, 1, 0.05])
    assert hub.call(referee, "field.get", (arm["id"], -1)) == pytest.approx([0, 0, 0.3])
    assert hub.call(referee, "field.get", (args["id"], 0)) == "1.0"
    assert hub.call(referee, "getFromDef", ("EXTRA", -1)) is None
    assert hub.call(referee, "getFromDef", ("BALL", -1)) is None
    assert hub.call(referee, "field.getCount", (children["id"],)) == count - 1
    assert next(r for r in sim.robots if r.entry.name == "driver").entry.controller_args[0] == "1.0"


def test_reset_button_resets_like_the_supervisor_and_restarts_every_controller(hub):
    # The window's reset key is Webots' Reset button: the same reset (fields a supervisor wrote are
    # kept, Solids go back), and every controller starts over.
    hub, referee = hub
    sim = hub.sim
    _, arm = _field(hub, referee, "ARM", "translation")
    _, box = _field(hub, referee, "BOX", "translation")
    hub.queue(referee, "field.set", (arm["id"], -1, [0.0, 0.0, 0.3]))
    hub.queue(referee, "field.set", (box["id"], -1, [2.0, 2.0, 0.05]))
    hub.flush()
    hub.take_changes()
    for _ in range(5):
        sim.step()
    hub.queue(None, "resetButton", ())
    hub.flush()
    changes = hub.take_changes()
    assert changes.reset and sim.time_ms == 0.0
    assert sorted(r.entry.name for r in changes.restart) == ["driver", "referee"]
    assert hub.call(referee, "field.get", (box["id"], -1)) == pytest.approx([1, 1, 0.05])
    assert hub.call(referee, "field.get", (arm["id"], -1)) == pytest.approx([0, 0, 0.3])


def test_a_proto_given_as_another_protos_parameter_is_rebuilt_where_the_body_takes_it(tmp_path):
    # Holder's body takes its `slot` by IS: the Group keeps its own copy of the parameter's list.
    (tmp_path / "Holder.proto").write_text("""#VRML_SIM R2025a utf8
PROTO Holder [ field MFNode slot [ ] ]
{ Solid { children [ Pose { translation 0 0 0.5 children [ Group { children IS slot } ] } ] } }
""", encoding="utf-8")
    (tmp_path / "Stick.proto").write_text("""#VRML_SIM R2025a utf8
PROTO Stick [ field SFFloat height 0.1 ]
{ Shape { geometry Cylinder { radius 0.01 height IS height } } }
""", encoding="utf-8")
    world = tmp_path / "nested.wbt"
    world.write_text("""#VRML_SIM R2025a utf8
EXTERNPROTO "Holder.proto"
EXTERNPROTO "Stick.proto"
WorldInfo { }
Holder { slot [ DEF STICK Stick { } ] }
DEF SUP Robot { supervisor TRUE }
""", encoding="utf-8")
    scene, _ = load_world(world)
    sim = Simulation(compile_scene(scene), noise=False)
    hub, sup = SupervisorHub(sim, scene, world), sim.robots[0]
    stick = hub.call(sup, "getFromDef", ("STICK", -1))["id"]
    height = hub.call(sup, "node.getField", (stick, "height", False))
    hub.queue(sup, "field.set", (height["id"], -1, 0.3))
    assert hub.flush().rebuilt
    cylinders = [g for g in range(hub.sim.model.ngeom) if hub.sim.model.geom_type[g] == 5]  # mjGEOM_CYLINDER
    assert [round(float(hub.sim.model.geom_size[g][1]), 6) for g in cylinders] == [0.15]  # half of 0.3
    assert hub.call(sup, "getFromDef", ("STICK", -1))["id"] == stick
    sim.close()


def test_a_plain_proto_keeps_its_inner_nodes_when_a_field_changes(tmp_path):
    # Webots regenerates template PROTOs only: the inner nodes of a plain one stay the same nodes.
    (tmp_path / "Arm.proto").write_text("""#VRML_SIM R2025a utf8
PROTO Arm [ field SFVec3f offset 0 0 0 ]
{ Solid { children [ DEF INNER Pose { translation IS offset children [ Shape { geometry Box { } } ] } ] } }
""", encoding="utf-8")
    world = tmp_path / "arm.wbt"
    world.write_text("""#VRML_SIM R2025a utf8
EXTERNPROTO "Arm.proto"
WorldInfo { }
DEF ARM Arm { offset 1 0 0 }
DEF SUP Robot { supervisor TRUE }
""", encoding="utf-8")
    scene, _ = load_world(world)
    sim = Simulation(compile_scene(scene), noise=False)
    hub, sup = SupervisorHub(sim, scene, world), sim.robots[0]
    arm = hub.call(sup, "getFromDef", ("ARM", -1))["id"]
    inner = hub.call(sup, "getFromDef", ("INNER", arm))["id"]
    translation = hub.call(sup, "node.getField", (inner, "translation", False))
    offset = hub.call(sup, "node.getField", (arm, "offset", False))
    old_root = hub.tree.by_id[arm]
    hub.queue(sup, "field.set", (offset["id"], -1, [0.0, 2.0, 0.0]))
    assert hub.flush().rebuilt
    # The replaced root's Python id is forgotten: a node made later at its address must not pass for it.
    assert id(old_root) not in hub.tree.ids and hub.tree.by_id[arm] is not old_root
    assert hub.call(sup, "getFromDef", ("INNER", arm))["id"] == inner
    assert hub.call(sup, "field.get", (translation["id"], -1)) == [0.0, 2.0, 0.0]
    assert hub.call(sup, "node.getPosition", (inner,)) == [0.0, 2.0, 0.0]
    sim.close()
