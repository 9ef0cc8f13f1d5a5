"""The shipped lesson controllers are the lessons' files, and every lesson has a world and a README line.

A shipped controller may differ from its lesson only in hunks that keep the lesson's line in a comment
("The lesson's line: `...`") with the corrected line under it.
"""

import difflib
import re

import pytest
from conftest import LESSONS
from lesson_runs import WORLDS

# lesson file -> shipped controller (worlds/controllers/<stem>/<stem>.py)
LESSON_FILES = sorted(p.relative_to(LESSONS).as_posix() for p in LESSONS.rglob("*.py"))
CORRECTED = {"workshop/ex03_avoid_obstacle_ps0.py", "workshop/ex04_avoid_multiple_ir.py",
             "workshop/ex05_obstacle_led.py", "workshop/ex10_distance_speed.py", "two_wheels/my_supervisor.py"}


def shipped(lesson: str):
    stem = lesson.rsplit("/", 1)[-1].removesuffix(".py")
    return WORLDS / "controllers" / stem / f"{stem}.py"


def test_every_lesson_is_covered():
    assert len(LESSON_FILES) == 16, LESSON_FILES


@pytest.mark.parametrize("lesson", LESSON_FILES)
def test_shipped_controller_is_the_lesson_file(lesson):
    original = (LESSONS / lesson).read_text(encoding="utf-8")
    ours = shipped(lesson).read_text(encoding="utf-8")
    if lesson not in CORRECTED:
        assert ours == original
        return
    a, b = original.splitlines(), ours.splitlines()
    hunks = [op for op in difflib.SequenceMatcher(a=a, b=b, autojunk=False).get_opcodes() if op[0] != "equal"]
    assert hunks
    for tag, i1, i2, j1, j2 in hunks:
        added = b[j1:j2]
        assert tag in ("replace", "insert"), f"{lesson}: lesson lines removed without a note: {a[i1:i2]}"
        assert "the lesson's line" in "\n".join(added).lower(), f"{lesson}: a change without the lesson's line: {added}"
        for line in a[i1:i2]:
            assert f"`{line.strip()}`" in ours, f"{lesson}: the lesson's line {line.strip()!r} is not quoted"
        # Only comments and as many code lines as the lesson had are added.
        code = [line for line in added if not line.strip().startswith("#")]
        assert len(code) == i2 - i1


@pytest.mark.parametrize("lesson", LESSON_FILES)
def test_a_world_runs_each_lesson_controller(lesson):
    stem = shipped(lesson).stem
    assert any(f'controller "{stem}"' in w.read_text(encoding="utf-8") for w in WORLDS.glob("*.wbt"))


def test_the_readme_lists_every_world_with_its_command():
    readme = (WORLDS / "README.md").read_text(encoding="utf-8")
    listed = set(re.findall(r"`wbtc run worlds/([\w-]+\.wbt)`", readme))
    assert listed == {w.name for w in WORLDS.glob("*.wbt")}
