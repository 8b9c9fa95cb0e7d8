"""Ctrl-C and SIGTERM: either signal to a Python process inside rotorsweep.run or rotorsweep.slider stops
the sweep within moments and is raised again (KeyboardInterrupt; SIGTERM as SystemExit(143), where nothing
else handles it), and with output= the finished members stay in OUTPUT.partial as the command line keeps
them, with no temporary or lock file left behind."""

import os
import signal
import subprocess
import sys
import time

import h5py
import pytest

LONG_SCENE = """
[model]
rows = 20
[drive]
g = [0.0011]
[sweep]
A = { from = 5.0, to = 8.0, count = 50 }
[initial]
replicas = 200
[schedule]
relax_periods = 20
average_periods = 20
"""

SCRIPT = """
import sys, rotorsweep
print("started", flush=True)
try:
    if sys.argv[1] == "run":
        rotorsweep.run(sys.argv[2], progress=False, output=sys.argv[3])
    else:
        rotorsweep.slider({"sweep": {"separation": {"from": 5e-3, "to": 13e-3, "count": 64}}}, progress=False,
                          output=sys.argv[3], threads=1)
except KeyboardInterrupt:
    print("interrupted", flush=True)
    sys.exit(130)
print("finished", flush=True)
"""


@pytest.mark.parametrize("command, number", [("run", signal.SIGINT), ("run", signal.SIGTERM),
                                             ("slider", signal.SIGTERM)])
def test_a_signal_stops_a_run_keeping_its_finished_members(tmp_path, command, number):
    scene = tmp_path / "long.toml"
    scene.write_text(LONG_SCENE)
    output = tmp_path / "long.h5"
    process = subprocess.Popen([sys.executable, "-c", SCRIPT, command, str(scene), str(output)],
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=os.environ.copy())
    assert process.stdout.readline().strip() == "started"
    time.sleep(1.5)  # inside the sweep
    sent = time.monotonic()
    process.send_signal(number)
    out, err = process.communicate(timeout=60)
    assert time.monotonic() - sent < 30, err
    assert process.returncode == 128 + number, err
    assert out.strip() == ("interrupted" if number == signal.SIGINT else "")
    assert sorted(tmp_path.iterdir()) == [output.with_name("long.h5.partial"), scene]
    with h5py.File(tmp_path / "long.h5.partial", "r") as f:
        assert not f.attrs["complete"]
        done = int(f["members/done"][:].sum())
        assert f.attrs["members_done"] == done < f["members/done"].shape[0]
    assert f"stopped: {done} of" in err and "--resume" in err
