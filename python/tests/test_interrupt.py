"""Ctrl-C during Scene.run stops the run at its next output, writes the output folder
with status "interrupted" and raises KeyboardInterrupt, as SIGINT stops `finseg run`;
the interpreter lives on."""

import json
import signal
import subprocess
import sys
import textwrap
import time


def test_sigint_stops_the_run_and_raises_keyboard_interrupt(tmp_path):
    child = textwrap.dedent(
        """
        import json, sys
        import finseg
        # Explicit steps of a 16-segment strip for 100 s of simulated time: hours, unless stopped.
        scene = finseg.cantilever(segments=16, tip_force=(0, 0, -1e-3), solver="explicit",
                                  t_end=100, output_interval=1e-3)
        print("running", flush=True)
        try:
            scene.run(out=sys.argv[1])
        except KeyboardInterrupt:
            print("interrupted", flush=True)
        """
    )
    out = tmp_path / "out"
    p = subprocess.Popen(
        [sys.executable, "-c", child, str(out)], stdout=subprocess.PIPE, text=True
    )
    assert p.stdout.readline().strip() == "running"
    time.sleep(1.0)  # the run is under way (the scene is read in milliseconds)
    p.send_signal(signal.SIGINT)
    rest, _ = p.communicate(timeout=60)
    assert p.returncode == 0
    assert rest.strip() == "interrupted"
    summary = json.loads((out / "summary.json").read_text())
    assert summary["status"] == "interrupted"
    # Stopped after some outputs, long before the 100 001 of the whole run.
    assert 1 <= summary["outputs"] < 100001
    last_t = float((out / "tip.csv").read_text().splitlines()[-1].split(",")[0])
    assert 0 <= last_t < 100
