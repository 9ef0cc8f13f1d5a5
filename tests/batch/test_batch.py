"""`wbtc batch` on the local pool: the grading example, tables, resume, limits, dying workers."""

import csv
import json
import subprocess
import sys
from pathlib import Path

import pytest
from batch_helpers import DRIVE, KILLER, REPO, make_plan

from wbtc.batch.runner import run_batch

EXAMPLE = REPO / "examples" / "grading"

#: The grading example's 20 submissions: (run status, controller status, exit code, score).
EXPECTED = {
    "01_reference": ("done", "running", 0, 10), "02_lesson_verbatim": ("done", "running", 0, 0),
    "03_syntax_error": ("done", "crashed", 1, 0), "04_infinite_loop": ("timeout", "killed", -9, 0),
    "05_exception": ("done", "crashed", 1, 0), "06_exit_3": ("done", "crashed", 3, 0),
    "07_threshold_150": ("done", "running", 0, 10), "08_threshold_1000": ("done", "running", 0, 7),
    "09_slow": ("done", "running", 0, 10), "10_max_speed": ("done", "running", 0, 10),
    "11_too_fast": ("done", "running", 0, 10), "12_timestep_32": ("done", "running", 0, 10),
    "13_wrong_turns": ("done", "running", 0, 10), "14_no_sensors": ("done", "running", 0, 7),
    "15_spin": ("done", "running", 0, 0), "16_backwards": ("done", "running", 0, 7),
    "17_missing_sensor": ("done", "crashed", 1, 0), "18_import_error": ("done", "crashed", 1, 0),
    "19_chatty": ("done", "running", 0, 10), "20_quits_early": ("done", "exited", 0, 7),
}


def _rows(path: Path) -> list[dict]:
    with path.open(encoding="utf-8", newline="") as stream:
        return list(csv.DictReader(stream))


def test_grading_example_grades_all_twenty(tmp_path):
    table = tmp_path / "grades.csv"
    done = subprocess.run([sys.executable, "-m", "wbtc.cli", "batch", str(EXAMPLE / "plan.toml"), "-o", str(table),
                           "--workers", "2"], capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stderr
    assert done.stdout.startswith("20 runs in ") and "19 done, 1 timeout; results in" in done.stdout
    assert done.stderr.count("/20 runs") == 20 and " left; run " in done.stderr
    rows = {Path(r["controller.e-puck"]).stem: r for r in _rows(table)}
    got = {name: (r["status"], r["e-puck.status"], int(r["e-puck.exit_code"]), float(r["score"]))
           for name, r in rows.items()}
    assert got == EXPECTED
    assert rows["03_syntax_error"]["message"] == ("the controller crashed (exit code 1): "
                                                  "SyntaxError: '(' was never closed")
    assert rows["04_infinite_loop"]["end_reason"] == "wall-clock timeout (10 s)"
    assert rows["04_infinite_loop"]["message"] == "wall-clock timeout (10 s); no grade"
    assert rows["08_threshold_1000"]["message"].startswith("touched an obstacle at t = ")


@pytest.mark.parametrize("suffix", [".csv", ".jsonl", ".parquet"])
def test_tables_and_resume(tmp_path, suffix):
    plan = make_plan(tmp_path, "", DRIVE, output=f"out{suffix}")
    with plan.open("a", encoding="utf-8") as stream:
        stream.write('[args]\ne-puck = [["2"], ["4"], ["6"]]\n')
    first = run_batch(plan, workers=2, progress=lambda text: None)
    assert first.total == 3 and first.statuses == {"done": 3}
    rows = _read(tmp_path / f"out{suffix}")
    assert sorted(str(r["args.e-puck"]) for r in rows) == ["2", "4", "6"]
    by_speed = {str(r["args.e-puck"]): r for r in rows}
    assert by_speed["2"]["message"] == "speed 2"
    assert float(by_speed["6"]["score"]) > float(by_speed["4"]["score"]) > float(by_speed["2"]["score"]) > 1.0
    # An interrupted batch: the last row is lost; --resume runs only that one.
    _drop_last_row(tmp_path / f"out{suffix}", rows)
    again = run_batch(plan, workers=2, resume=True, progress=lambda text: None)
    assert (again.total, again.skipped, again.statuses) == (3, 2, {"done": 1})
    assert sorted(str(r["args.e-puck"]) for r in _read(tmp_path / f"out{suffix}")) == ["2", "4", "6"]


def _read(path: Path) -> list[dict]:
    if path.suffix == ".csv":
        return _rows(path)
    if path.suffix == ".jsonl":
        return [json.loads(line) for line in path.read_text(encoding="utf-8").splitlines()]
    import pyarrow.parquet as pq

    return pq.read_table(path).to_pylist()


def _drop_last_row(path: Path, rows: list[dict]) -> None:
    if path.suffix == ".parquet":
        import pyarrow as pa
        import pyarrow.parquet as pq

        pq.write_table(pa.Table.from_pylist(rows[:-1], schema=pq.read_schema(path)), path)
        return
    lines = path.read_text(encoding="utf-8").splitlines(keepends=True)
    path.write_text("".join(lines[:-1]), encoding="utf-8")


def test_existing_table_needs_resume(tmp_path):
    plan = make_plan(tmp_path, "", DRIVE)
    (tmp_path / "out.csv").write_text("run\n", encoding="utf-8")
    done = subprocess.run([sys.executable, "-m", "wbtc.cli", "batch", str(plan)], capture_output=True, text=True)
    assert done.returncode == 1 and "Traceback" not in done.stderr
    assert "out.csv exists: pass --resume to finish that batch, or remove the file first" in done.stderr


def test_a_table_into_a_missing_folder_is_refused_before_any_run(tmp_path):
    # It raised FileNotFoundError (a traceback) when the table was first opened.
    plan = make_plan(tmp_path, "", DRIVE)
    missing = tmp_path / "missing" / "out.csv"
    done = subprocess.run([sys.executable, "-m", "wbtc.cli", "batch", str(plan), "-o", str(missing)],
                          capture_output=True, text=True)
    assert done.returncode == 1 and "Traceback" not in done.stderr
    assert done.stderr.strip() == f"error: cannot write the results table {missing}: no such folder {missing.parent}"


def test_memory_limit_stops_a_greedy_controller(tmp_path):
    greedy = "from controller import Robot\nrobot = Robot()\nrobot.step(32)\nblock = bytearray(900 * 2**20)\n"
    plan = make_plan(tmp_path, "memory_mb = 600", greedy)
    summary = run_batch(plan, workers=1, progress=lambda text: None)
    row = summary.rows[0]
    assert row["status"] == "done" and row["e-puck.status"] == "crashed" and row["e-puck.exit_code"] == 1


def test_a_grader_that_raises_names_its_line(tmp_path, capsys):
    plan = make_plan(tmp_path, "", "from controller import Robot\nwhile True:\n    pass\n")
    plan.write_text(plan.read_text(encoding="utf-8").replace("timeout = 30", "timeout = 1"), encoding="utf-8")
    summary = run_batch(plan, workers=1, progress=lambda text: None)
    row = summary.rows[0]
    assert row["status"] == "timeout" and row["score"] is None
    assert row["message"] == f"wall-clock timeout (1 s); {plan}:5:1: the grader raised ValueError: no result"
    assert capsys.readouterr().err == f"wbtc batch: {plan}:5:1: the grader raised ValueError: no result\n"


@pytest.mark.parametrize(("mode", "status", "starts"), [("once", "done", 2), ("always", "failed", 2)])
def test_a_dying_worker_is_retried_once(tmp_path, mode, status, starts):
    marker = tmp_path / "starts.log"
    plan = make_plan(tmp_path, "", KILLER)
    with plan.open("a", encoding="utf-8") as stream:
        stream.write(f'[args]\ne-puck = [["{marker}", "{mode}", "1"]]\n')
    summary = run_batch(plan, workers=1, progress=lambda text: None)
    row = summary.rows[0]
    assert (row["status"], row["attempts"]) == (status, 2)
    assert marker.read_text().count("start") == starts
    if status == "failed":
        assert row["message"].startswith("its worker process died (exit status -9), on each of 2 attempts; ")


FORK_PROBE = """
import sys
from pathlib import Path
import wbtc.batch.pool as pool
from wbtc.batch.runner import run_batch

kinds = []
adopt = pool.LocalPool._adopt
pool.LocalPool._adopt = lambda self, worker: kinds.append(type(worker).__name__) or adopt(self, worker)
summary = run_batch(Path(sys.argv[1]), workers=2, progress=lambda text: None)
print(sorted(kinds), summary.statuses, sorted(row["message"] for row in summary.rows))
"""


def test_a_small_scheduler_forks_its_warm_workers(tmp_path):
    # A scheduler of its own (as `wbtc batch` is) forks its first workers once it has loaded the
    # plan's world: each run is still its own process and reads the same.
    plan = make_plan(tmp_path, "", DRIVE)
    with plan.open("a", encoding="utf-8") as stream:
        stream.write('[args]\ne-puck = [["2"], ["4"], ["3"]]\n')
    done = subprocess.run([sys.executable, "-c", FORK_PROBE, str(plan)], capture_output=True, text=True,
                          cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "['ForkedWorker', 'ForkedWorker'] {'done': 3} ['speed 2', 'speed 3', 'speed 4']"
