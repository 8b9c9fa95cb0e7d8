"""Ctrl-C: SIGINT to a Python process inside rotorsweep.run stops the sweep within moments,
raises KeyboardInterrupt, and leaves no output file behind."""

import os
import signal
import subprocess
import sys
import time

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
    rotorsweep.run(sys.argv[1], progress=False, output=sys.argv[2])
except KeyboardInterrupt:
    print("interrupted", flush=True)
    sys.exit(130)
print("finished", flush=True)
"""


def test_sigint_stops_a_run_cleanly(tmp_path):
    scene = tmp_path / "long.toml"
    scene.write_text(LONG_SCENE)
    output = tmp_path / "long.h5"
    process = subprocess.Popen([sys.executable, "-c", SCRIPT, str(scene), str(output)],
                               stdout=subprocess.PIPE, text=True, env=os.environ.copy())
    assert process.stdout.readline().strip() == "started"
    time.sleep(1.0)  # inside the sweep
    sent = time.monotonic()
    process.send_signal(signal.SIGINT)
    out, _ = process.communicate(timeout=30)
    assert time.monotonic() - sent < 10
    assert process.returncode == 130
    assert out.strip() == "interrupted"
    assert list(tmp_path.iterdir()) == [scene]
