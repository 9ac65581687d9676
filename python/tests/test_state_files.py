"""State files (docs/state-file.md) from Python: written and read back bit for bit, the
same as `finseg run`'s checkpoint, and a run started from one continues from its poses."""

import json

import finseg
import numpy as np
from conftest import as_csv_cells, read_csv


def test_state_round_trip_is_exact(tmp_path):
    scene = finseg.cantilever(segments=8, tip_force=(0, 0, -1e-3))
    state = scene.run().state
    state.save(str(tmp_path / "end.json"))
    back = scene.read_state(str(tmp_path / "end.json"))
    for name in ["p_W", "R_WB", "v_W", "w_W", "drive_s"]:
        assert np.array_equal(getattr(back, name), getattr(state, name)), name
    assert back.t == state.t
    assert back.load_scale == state.load_scale
    assert back.scene_hash == state.scene_hash
    assert back.body_names == state.body_names
    # Rotations stay rotations: R^T R = I to round-off.
    R = back.R_WB
    assert np.allclose(np.einsum("nji,njk->nik", R, R), np.eye(3), atol=1e-12)


def test_cli_checkpoint_reads_as_the_python_final_state(tmp_path, finseg_cli):
    scene = finseg.cantilever(segments=8, tip_force=(0, 0, -1e-3))
    scene.save(str(tmp_path / "c.yaml"))
    cli = finseg_cli("run", "c.yaml", "--out", "cli", "--quiet", cwd=tmp_path)
    assert cli.returncode == 0, cli.stderr
    from_cli = scene.read_state(str(tmp_path / "cli/checkpoint.json"))
    ours = scene.run().state
    assert np.array_equal(from_cli.p_W, ours.p_W)
    assert np.array_equal(from_cli.R_WB, ours.R_WB)
    # The hash of a generated scene is the hash of the same text read from a file.
    assert from_cli.scene_hash == ours.scene_hash


def test_run_from_an_equilibrium_stays_there(tmp_path):
    """Starting the same static load from its own equilibrium converges at once to it."""
    scene = finseg.cantilever(segments=8, tip_force=(0, 0, -1e-3))
    end = scene.run().state
    again = scene.run(state=end)
    assert np.allclose(again.state.p_W, end.p_W, atol=1e-12)
    tip = again.probes["tip"]
    assert np.allclose(tip["z_m"], tip["z_m"][-1], atol=1e-12)


def test_run_from_a_state_is_the_command_lines_run_from_its_file(tmp_path, finseg_cli):
    """`Scene.run(state=...)` starts a fresh run as `finseg run --state FILE` does: time from 0,
    the drive from where its point is. Both read the same file here, so the probes agree to the
    last digit the CSV keeps."""
    strip = finseg.zigzag(segments_per_panel=4, pull_travel=0.004, pull_step=0.001)
    strip.save(str(tmp_path / "s.yaml"))
    dynamic = finseg.cantilever(segments=8, tip_force=(0, 0, -1e-3)).with_set(
        {"solver.type": "implicit", "solver.t_end": 0.02, "solver.output_interval": 0.005}
    )
    dynamic.save(str(tmp_path / "d.yaml"))
    for name, scene, probe in [("s", strip, "gauge"), ("d", dynamic, "tip")]:
        first = scene.run(out=str(tmp_path / (name + "1")))
        assert first.status == "ok"
        cli = finseg_cli(
            "run", name + ".yaml", "--out", name + "2", "--quiet", "--state",
            name + "1/checkpoint.json", *(["--set", "solver.type=implicit", "--set",
            "solver.t_end=0.02", "--set", "solver.output_interval=0.005"] if name == "d" else []),
            cwd=tmp_path,
        )
        assert cli.returncode == 0, cli.stderr
        ours = scene.run(state=scene.read_state(str(tmp_path / (name + "1/checkpoint.json"))))
        theirs = read_csv(tmp_path / (name + "2") / (probe + ".csv"))
        columns = ours.probes[probe]
        assert list(columns) == list(theirs)
        for column, cells in theirs.items():
            assert as_csv_cells(columns[column]) == cells, column
        # A fresh run: its abscissa starts at 0 and the run moves on from the state.
        assert columns[ours.abscissa][0] == 0
        assert ours.summary["stats"]["steps"] > 0


def test_state_file_keys_are_documented(tmp_path):
    finseg.cantilever(segments=4).initial_state().save(str(tmp_path / "s.json"))
    j = json.loads((tmp_path / "s.json").read_text())
    assert j["format"] == "finseg-state"
    assert j["version"] == 1
    assert len(j["bodies"]) == j["model"]["bodies"]
