"""Folding runs from Python (docs/folding.md): Scene.run(fold=True) is `finseg run --fold`,
the coarse cut included, and its state deploys as the command line's checkpoint does."""

import finseg
import numpy as np
import pytest
from conftest import as_csv_cells, read_csv

QUIET = ["--set", "outputs.vtk=false", "--set", "outputs.html=false", "--set", "outputs.plot=false"]
SETS = {"folding.coarse_subdivisions": 1, "outputs.vtk": False, "outputs.html": False,
        "outputs.plot": False}


def test_fold_and_deploy_as_the_command_line(tmp_path, finseg_cli):
    gen = finseg_cli("gen", "cone", "--top", "open", "--base", "open", "--pleats", "3",
                     "--axial-folds", "1", "--subdivisions", "2", "--fold-to-gathered", "0.9",
                     "--out", "c.yaml", cwd=tmp_path)
    assert gen.returncode == 0, gen.stderr
    cli = finseg_cli("run", "c.yaml", "--fold", "--out", "cli", "--quiet", "--set",
                     "folding.coarse_subdivisions=1", *QUIET, cwd=tmp_path)
    assert cli.returncode == 0, cli.stderr
    scene = finseg.load(str(tmp_path / "c.yaml")).with_set(SETS)
    folded = scene.run(fold=True, out=str(tmp_path / "py"))
    from_cli = scene.read_state(str(tmp_path / "cli/checkpoint.json"))
    assert np.array_equal(folded.state.p_W, from_cli.p_W)
    assert np.array_equal(folded.state.R_WB, from_cli.R_WB)
    # The coarse cut's fold (3 pleats, 1 fold: 14 segments) is reported beside the fine run's.
    assert [s["segments"] for s in folded.summary["stages"]] == [14]
    assert folded.summary["stages"][0]["stats"]["newton_iterations"] > 0

    # Deployed from the fold: the command line from its checkpoint, Python from the State.
    pull = ["--set", "solver.t_end=0.05"]
    cli = finseg_cli("run", "c.yaml", "--state", "cli/checkpoint.json", "--out", "dep",
                     "--quiet", *pull, *QUIET, cwd=tmp_path)
    assert cli.returncode == 0, cli.stderr
    deployed = finseg.load(str(tmp_path / "c.yaml")).with_set({"solver.t_end": 0.05}).run(
        state=folded.state)
    theirs = read_csv(tmp_path / "dep/top.csv")
    for column, cells in theirs.items():
        assert as_csv_cells(deployed.probes["top"][column]) == cells, column


def test_fold_from_a_state_as_the_command_line(tmp_path, finseg_cli):
    """A fold started from a state (a second fold from the first's end) keeps the state's
    history and velocities, as `finseg run --fold --state FILE` does."""
    gen = finseg_cli("gen", "cone", "--fan-fold", "--pleats", "3",
                     "--axial-folds", "1", "--subdivisions", "1", "--fold-fraction", "0.3",
                     "--out", "c.yaml", cwd=tmp_path)  # an implicit (dynamic) fold
    assert gen.returncode == 0, gen.stderr
    for args in (["--out", "f1"], ["--state", "f1/checkpoint.json", "--out", "f2"]):
        cli = finseg_cli("run", "c.yaml", "--fold", "--quiet", *args, *QUIET, cwd=tmp_path)
        assert cli.returncode == 0, cli.stderr
    scene = finseg.load(str(tmp_path / "c.yaml"))
    first = scene.read_state(str(tmp_path / "f1/checkpoint.json"))
    assert np.abs(first.w_W).max() > 0  # it ends moving: the velocities count
    again = scene.run(fold=True, state=first).state
    from_cli = scene.read_state(str(tmp_path / "f2/checkpoint.json"))
    assert np.array_equal(again.p_W, from_cli.p_W)
    assert np.array_equal(again.R_WB, from_cli.R_WB)


def test_fold_refuses_a_solver(tmp_path, finseg_cli):
    gen = finseg_cli("gen", "cone", "--top", "open", "--base", "open", "--pleats", "3",
                     "--axial-folds", "1", "--subdivisions", "1", "--fold-to-gathered", "0.5",
                     "--out", "c.yaml", cwd=tmp_path)
    assert gen.returncode == 0, gen.stderr
    with pytest.raises(finseg.InputError) as e:
        finseg.load(str(tmp_path / "c.yaml")).run(fold=True, solver="implicit")
    assert e.value.field == "solver"
    # A scene without a folding: section says so, as --fold does.
    with pytest.raises(finseg.InputError) as e:
        finseg.cantilever(segments=4).run(fold=True)
    assert e.value.field == "folding"
