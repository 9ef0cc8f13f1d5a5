"""`wbtc check` resolves library PROTOs that a world names without EXTERNPROTO lines."""

from __future__ import annotations

import json

from typer.testing import CliRunner

from wbtc.cli import app

WORLD = """#VRML_SIM R2023b utf8
WorldInfo {
}
Viewpoint {
  orientation -0.5 0.5 0.7 1.9
  position 0 -2 2
}
RectangleArena {
  floorSize 2 2
}
WoodenBox {
  translation 0.5 0.5 0.05
  size 0.1 0.1 0.1
}
WoodenBox {
  translation -0.5 0.5 0.05
  size 0.1 0.1 0.1
}
E-puck {
  controller "<none>"
}
"""

runner = CliRunner()


def test_check_resolves_library_protos_without_externproto(tmp_path) -> None:
    world = tmp_path / "arena.wbt"
    world.write_text(WORLD)
    result = runner.invoke(app, ["check", "--json", "--strict", str(world)])
    assert result.exit_code == 0, result.output
    report = json.loads(result.stdout)
    assert report["protos"] == [
        {"name": "E-puck", "count": 1, "source": "wbtc:E-puck"},
        {"name": "RectangleArena", "count": 1, "source": "wbtc:RectangleArena"},
        {"name": "WoodenBox", "count": 2, "source": "wbtc:WoodenBox"},
    ]
    [robot] = report["robots"]
    assert robot["name"] == "e-puck" and robot["controller"] == "<none>"
    assert {"name": "ps0", "type": "DistanceSensor"} in robot["devices"]
    assert report["warnings"] == []


def test_check_human_report_names_library_sources(tmp_path) -> None:
    world = tmp_path / "arena.wbt"
    world.write_text(WORLD)
    result = runner.invoke(app, ["check", str(world)])
    assert result.exit_code == 0, result.output
    lines = result.stdout.splitlines()
    assert "  RectangleArena x1  (wbtc:RectangleArena)" in lines
    assert "  E-puck x1  (wbtc:E-puck)" in lines
    assert "  WoodenBox x2  (wbtc:WoodenBox)" in lines
