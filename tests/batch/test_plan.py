"""Batch plans: combinations, ranges, and every mistake named at its plan line before anything runs."""

from pathlib import Path

import pytest

from wbtc.batch.plan import read_plan
from wbtc.errors import WbtcError

REPO = Path(__file__).resolve().parents[2]
WORLD = REPO / "worlds" / "epuck_obstacles.wbt"


def _plan(tmp_path: Path, text: str) -> Path:
    (tmp_path / "subs").mkdir(exist_ok=True)
    for name in ("a.py", "b.py"):
        (tmp_path / "subs" / name).write_text("pass\n", encoding="utf-8")
    (tmp_path / "grader.py").write_text("def grade(result):\n    return 1\n\ndef two(a, b):\n    return 0\n",
                                        encoding="utf-8")
    path = tmp_path / "plan.toml"
    path.write_text(f'world = "{WORLD}"\n' + text, encoding="utf-8")
    return path


def test_every_combination_is_one_job(tmp_path):
    plan = read_plan(_plan(tmp_path, """duration = 2
seeds = {start = 1, stop = 4}
[controllers]
e-puck = "subs/"
[args]
e-puck = [["1"], ["2", "x"]]
[fields]
"box 1.size" = [[0.1, 0.1, 0.1]]
"WorldInfo.basicTimeStep" = {start = 8, stop = 16, num = 3}
"""))
    jobs = plan.jobs()
    assert len(jobs) == 2 * 2 * 1 * 3 * 3
    assert plan.robots == ["e-puck"]
    first, last = jobs[0], jobs[-1]
    assert first.params == {"world": str(WORLD), "controller.e-puck": "subs/a.py", "args.e-puck": "1",
                            "field.box 1.size": "[0.1, 0.1, 0.1]", "field.WorldInfo.basicTimeStep": "8", "seed": "1"}
    assert last.params["controller.e-puck"] == "subs/b.py" and last.args == {"e-puck": ["2", "x"]}
    assert last.fields["WorldInfo.basicTimeStep"] == 16 and last.seed == 3 and last.duration == 2.0
    assert len({job.key for job in jobs}) == len(jobs)


@pytest.mark.parametrize(("text", "line", "message"), [
    ("durration = 3\n", 2, "unknown plan key 'durration'"),
    ("[controllers]\nthymio = \"subs/\"\n", 3, "epuck_obstacles.wbt has no robot named 'thymio' (robots: e-puck)"),
    ("[controllers]\ne-puck = \"nothing/\"\n", 3, "no controller file at 'nothing/'"),
    ("[fields]\n\"BOX.size\" = [[1, 1, 1]]\n", 3,
     "epuck_obstacles.wbt: 'BOX.size': no node with DEF name, Solid name or top-level type 'BOX' in the world"),
    ("[fields]\n\"e-puck.colour\" = [1]\n", 3, "epuck_obstacles.wbt: 'e-puck.colour': E-puck 'e-puck' has no field"),
    ("[fields]\n\"e-puck.translation\" = [[0, 0]]\n", 3, "is a SFVec3f field: [0, 0] does not fit it"),
    ("[fields]\n\"e-puck.translation\" = [0, 0, 0]\n", 3, "is a SFVec3f field: 0 does not fit it"),
    ("grader = \"grader.py:missing\"\n", 2, "grader.py has no function 'missing'"),
    ("grader = \"grader.py:two\"\n", 2, "the grader two() must take one argument (the run's result)"),
    ("grader = \"nope.py:grade\"\n", 2, "the grader file does not exist: nope.py"),
    ("output = \"results.xlsx\"\n", 2, "the output table must be a .csv, .jsonl or .parquet file"),
    ("seeds = [1.5]\n", 2, "seeds must be integers"),
    ("timeout = -1\n", 2, "'timeout' must be a positive number, not -1"),
    ("physics_step = 0\n", 2, "'physics_step' must be a positive number, not 0"),
    ("ode_contacts = \"yes\"\n", 2, "'ode_contacts' must be true or false, not 'yes'"),
])
def test_mistakes_name_their_line(tmp_path, text, line, message):
    path = _plan(tmp_path, text)
    with pytest.raises(WbtcError) as caught:
        read_plan(path)
    diagnostic = caught.value.diagnostics[0]
    assert diagnostic.span.file == str(path) and diagnostic.span.line == line
    assert message in diagnostic.message


def test_unknown_world_names_the_world_line(tmp_path):
    path = tmp_path / "plan.toml"
    path.write_text('duration = 1\nworlds = ["a.wbt"]\n', encoding="utf-8")
    with pytest.raises(WbtcError) as caught:
        read_plan(path)
    assert str(caught.value.diagnostics[0]) == f"{path}:2:1: error: no such world file: a.wbt"


def test_invalid_toml_names_the_line(tmp_path):
    path = tmp_path / "plan.toml"
    path.write_text('duration = 1\nworld = \n', encoding="utf-8")
    with pytest.raises(WbtcError) as caught:
        read_plan(path)
    assert caught.value.diagnostics[0].span.line == 2
    assert caught.value.diagnostics[0].message.startswith("the plan is not valid TOML")


def test_physics_options_reach_every_job_and_its_run(tmp_path, monkeypatch):
    plan = read_plan(_plan(tmp_path, "seeds = [1, 2]\nphysics_step = 1000\node_contacts = true\n"))
    jobs = plan.jobs()
    assert [(j.physics_step, j.ode_contacts) for j in jobs] == [(1000.0, True), (1000.0, True)]
    assert read_plan(_plan(tmp_path, "")).jobs()[0].physics_step == 2.0  # `wbtc run`'s defaults
    assert read_plan(_plan(tmp_path, "")).jobs()[0].ode_contacts is False
    import wbtc.api
    from wbtc.batch import worker

    seen = {}

    def fake_run(world, **options):  # noqa: ANN001, ANN003, ANN202
        seen.update(options)
        raise wbtc.api.WbtcError("stopped here")

    monkeypatch.setattr(wbtc.api, "run", fake_run)
    assert worker._run(jobs[0]).status == "error"
    assert (seen["physics_step"], seen["ode_contacts"], seen["seed"]) == (1000.0, True, 1)
