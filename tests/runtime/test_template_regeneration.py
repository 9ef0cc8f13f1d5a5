"""A template PROTO changed by a supervisor: its `context.id`, when Webots regenerates it, what that invalidates."""

from pathlib import Path

import pytest

from wbtc.compile.compiler import compile_scene
from wbtc.pipeline import load_world
from wbtc.runtime.simulation import Simulation
from wbtc.runtime.supervisor import SupervisorError, SupervisorHub

WORLD = Path(__file__).parent / "fixtures" / "regeneration" / "regeneration.wbt"


@pytest.fixture
def hub():
    scene, _ = load_world(WORLD)
    sim = Simulation(compile_scene(scene), noise=False)
    referee = next(r for r in sim.robots if r.entry.name == "referee")
    yield SupervisorHub(sim, scene, WORLD), referee
    sim.close()


def _set(hub, referee, def_name: str, field: str, value) -> dict:
    node = hub.call(referee, "getFromDef", (def_name, -1))
    ref = hub.call(referee, "node.getField", (node["id"], field, False))
    hub.queue(referee, "field.set", (ref["id"], -1, value))
    return node


def test_context_id_is_the_node_id_webots_numbers_in_file_order(hub):
    hub, referee = hub
    # Root 0, WorldInfo 1, Viewpoint 2, PLAIN 3 (its Solid) with its Shape and Sphere, then FIRST 6
    # (its Robot) with its Shape and Box, then SECOND 9: their templates got these ids as context.id.
    first = hub.call(referee, "getFromDef", ("FIRST", -1))
    second = hub.call(referee, "getFromDef", ("SECOND", -1))
    assert (first["id"], second["id"]) == (6, 9)
    assert sorted(r.entry.name for r in hub.sim.robots) == ["referee", "robot 6", "robot 9"]
    assert [hub.call(referee, "getFromId", (i,))["type"] for i in (1, 2, 3)] == ["WorldInfo", "Viewpoint", "Plain"]


def test_a_field_the_template_reads_regenerates_the_robot_and_restarts_its_controller(hub):
    hub, referee = hub
    first = _set(hub, referee, "FIRST", "size", 0.2)
    outcome = hub.flush()
    assert outcome.rebuilt
    assert [r.entry.name for r in outcome.restart] == ["robot 6"]  # the same id, so the same name
    assert hub.call(referee, "getFromDef", ("FIRST", -1))["id"] == first["id"]


def test_a_field_only_passed_by_is_does_not_regenerate(hub):
    hub, referee = hub
    body = hub.call(referee, "getFromDef", ("BODY", hub.call(referee, "getFromDef", ("FIRST", -1))["id"]))
    _set(hub, referee, "FIRST", "label", "changed")
    outcome = hub.flush()
    assert outcome.rebuilt and outcome.restart == []
    assert hub.call(referee, "node.getField", (body["id"], "geometry", False)) is not None


def test_a_regeneration_drops_its_old_internal_nodes_and_every_internal_field_reference(hub):
    hub, referee = hub
    first = hub.call(referee, "getFromDef", ("FIRST", -1))
    plain = hub.call(referee, "getFromDef", ("PLAIN", -1))
    body = hub.call(referee, "getFromDef", ("BODY", first["id"]))
    other = hub.call(referee, "node.getField", (plain["id"], "children", True))  # PLAIN's internal Solid field
    own = hub.call(referee, "node.getField", (plain["id"], "translation", False))
    _set(hub, referee, "FIRST", "size", 0.2)
    hub.flush()
    # Webots deletes the old BODY; the controller library forgets every PROTO-internal field.
    with pytest.raises(SupervisorError, match=f"id {body['id']} does not exist"):
        hub.call(referee, "node.getField", (body["id"], "geometry", False))
    assert other["id"] in hub.tree.dead_fields and own["id"] not in hub.tree.dead_fields
    again = hub.call(referee, "node.getField", (plain["id"], "children", True))
    assert again is not None and again["id"] != other["id"]
    new_body = hub.call(referee, "getFromDef", ("BODY", first["id"]))
    assert new_body is not None and new_body["id"] != body["id"]
