"""Ctrl-C and SIGTERM during `wbtc run` (wbtc.runtime.interrupt), sent as a terminal sends them: to the group."""

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

WORLD = """#VRML_SIM R2023b utf8
WorldInfo {{
  basicTimeStep 16
}}
Robot {{
  name "r"
  controller "{controller}"
}}
"""

#: Steps until told to stop, then says how it ended: Webots' controllers clean up after step() returns -1.
POLITE = '''import os
from controller import Robot
robot = Robot()
print("pid", os.getpid(), flush=True)
while robot.step(16) != -1:
    if robot.getTime() > 0.5:
        print("stepping", flush=True)
print("ended at", round(robot.getTime(), 3), flush=True)
'''

#: Never steps again after its first step: only a second signal can end the run.
STUCK = '''import os
from controller import Robot
robot = Robot()
print("pid", os.getpid(), flush=True)
robot.step(16)
print("stepping", flush=True)
while True:
    pass
'''


def _start(tmp_path: Path, controller: str, source: str, *args: str) -> subprocess.Popen[str]:
    (tmp_path / f"{controller}.py").write_text(source, encoding="utf-8")
    world = tmp_path / "w.wbt"
    world.write_text(WORLD.format(controller=controller), encoding="utf-8")
    # A session of its own, so that the signal goes to the run and its controllers as a terminal's would.
    return subprocess.Popen([sys.executable, "-m", "wbtc.cli", "run", str(world), "--headless", "--realtime",
                             "--trace", str(tmp_path / "t.csv"), *args], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, start_new_session=True)


def _wait_for(run: subprocess.Popen[str], marker: str) -> list[str]:
    assert run.stdout is not None
    lines = []
    deadline = time.monotonic() + 60
    while time.monotonic() < deadline:
        line = run.stdout.readline()
        assert line, "".join(lines)
        lines.append(line)
        if marker in line:
            return lines
    raise AssertionError("".join(lines))


def _pid(lines: list[str]) -> int:
    return int(next(line for line in lines if " pid " in line).split()[-1])


def _alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    return not Path(f"/proc/{pid}/stat").read_text().split()[2] == "Z"


def test_ctrl_c_ends_the_run_after_the_step_as_webots_quitting_does(tmp_path):
    run = _start(tmp_path, "polite", POLITE)
    _wait_for(run, "stepping")
    os.killpg(run.pid, signal.SIGINT)
    out, err = run.communicate(timeout=30)
    assert run.returncode == 130, err
    assert "wbtc: Ctrl-C: the run ends after this step (again to stop at once)" in err
    assert "Traceback" not in err + out
    # The controller saw step() return -1 and ended by itself, as when Webots quits.
    assert "[r] ended at" in out
    assert "ended: interrupted (Ctrl-C)" in out and "(polite: running, exit code 0)" in out
    simulated = float(out.split("ended at")[1].split()[0])
    assert simulated > 0.5
    rows = (tmp_path / "t.csv").read_text(encoding="utf-8").splitlines()
    assert len({row.count(",") for row in rows}) == 1  # every row complete, the header's columns
    assert float(rows[-1].split(",")[0]) >= simulated - 0.016


def test_sigterm_ends_it_the_same_way_with_the_shells_code(tmp_path):
    run = _start(tmp_path, "polite", POLITE)
    _wait_for(run, "stepping")
    os.kill(run.pid, signal.SIGTERM)  # as `kill PID` or `timeout` send it: to wbtc alone
    out, err = run.communicate(timeout=30)
    assert run.returncode == 143, err
    assert "wbtc: SIGTERM: the run ends after this step" in err
    assert "ended: interrupted (SIGTERM)" in out and "[r] ended at" in out


def test_a_second_ctrl_c_stops_a_stuck_controller_at_once_and_keeps_no_trace(tmp_path):
    run = _start(tmp_path, "stuck", STUCK)
    pid = _pid(_wait_for(run, "stepping"))
    os.killpg(run.pid, signal.SIGINT)
    time.sleep(0.5)
    assert run.poll() is None  # the first one waits for the step the controller never asks for
    assert _alive(pid)  # the controller ignores the terminal's Ctrl-C: wbtc ends it
    os.killpg(run.pid, signal.SIGINT)
    out, err = run.communicate(timeout=30)
    assert run.returncode == 130, err
    assert "wbtc run: stopped at once; no video, page or trace of this run was kept" in err
    assert "Traceback" not in err
    assert not (tmp_path / "t.csv").exists()
    assert not _alive(pid)


def test_an_interrupted_wait_for_an_extern_controller_leaves_no_socket_file(tmp_path):
    (tmp_path / "w.wbt").write_text(WORLD.format(controller="<extern>"), encoding="utf-8")
    run = subprocess.Popen([sys.executable, "-m", "wbtc.cli", "run", str(tmp_path / "w.wbt"), "--headless"],
                           stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, start_new_session=True)
    assert run.stderr is not None
    line = ""
    while "WBTC_CONTROLLER_URL=" not in line:
        line = run.stderr.readline()
        assert line
    socket_file = Path(line.split("WBTC_CONTROLLER_URL=unix:")[1].split()[0])
    assert socket_file.exists()
    os.killpg(run.pid, signal.SIGTERM)
    _, err = run.communicate(timeout=30)
    assert run.returncode == 143, err
    assert "stopped at once" in err and "Traceback" not in err
    assert not socket_file.exists()
