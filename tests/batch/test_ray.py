"""`wbtc batch --ray`: the same plan as Ray tasks on a local Ray instance the test starts."""

from pathlib import Path

import pytest
import ray
from batch_helpers import DRIVE, KILLER, make_plan

from wbtc.batch.runner import run_batch


@pytest.fixture(scope="module")
def local_ray():
    ray.init(num_cpus=2, include_dashboard=False, log_to_driver=False)
    yield
    ray.shutdown()


def test_plan_runs_as_ray_tasks(tmp_path, local_ray):
    plan = make_plan(tmp_path, "", DRIVE, output="out.jsonl")
    with plan.open("a", encoding="utf-8") as stream:
        stream.write('[args]\ne-puck = [["2"], ["4"]]\n')
    summary = run_batch(plan, ray="auto", progress=lambda text: None)
    assert summary.statuses == {"done": 2}
    local = run_batch(plan, output=tmp_path / "local.jsonl", progress=lambda text: None)
    scores = {row["args.e-puck"]: row["score"] for row in summary.rows}
    assert scores == pytest.approx({row["args.e-puck"]: row["score"] for row in local.rows}, abs=1e-9)
    assert [row["message"] for row in sorted(summary.rows, key=lambda r: r["run"])] == ["speed 2", "speed 4"]


@pytest.mark.parametrize(("mode", "status"), [("once", "done"), ("always", "failed")])
def test_a_ray_worker_dying_mid_run_is_retried_once(tmp_path, local_ray, mode, status):
    marker = tmp_path / "starts.log"
    plan = make_plan(tmp_path, "", KILLER)
    with plan.open("a", encoding="utf-8") as stream:
        stream.write(f'[args]\ne-puck = [["{marker}", "{mode}", "2"]]\n')
    summary = run_batch(plan, ray="auto", progress=lambda text: None)
    row = summary.rows[0]
    assert row["status"] == status
    assert Path(marker).read_text().count("start") == 2  # the first attempt and Ray's one retry
    if status == "failed":
        assert row["message"].startswith("its Ray worker died, on each of 2 attempts")
