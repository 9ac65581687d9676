"""The Python path and `finseg run` on the same scene give the same numbers, to the last
digit written; the generators write the same scene text as `finseg gen`."""

import json

import finseg
import pytest
from conftest import as_csv_cells, read_csv

# Mattiasson's elastica table (alpha = P L^2 / EI = 2): tip at 0.16064 L along x from the
# clamp and 0.49346 L down, L = 0.1 m (README, tests/test_validation_elastica.cpp).
ELASTICA_TIP_X_M = 0.083936
ELASTICA_TIP_Z_M = -0.049346


def test_cantilever_matches_cli_and_the_elastica(tmp_path, finseg_cli, source_dir):
    scene_file = source_dir / "examples/cantilever/alpha2.yaml"
    cli = finseg_cli("run", scene_file, "--out", tmp_path / "cli", "--quiet")
    assert cli.returncode == 0, cli.stderr
    result = finseg.load(str(scene_file)).run()
    tip = result.probes["tip"]
    assert list(tip) == ["load_scale", "x_m", "y_m", "z_m"]
    written = read_csv(tmp_path / "cli/tip.csv")
    assert list(written) == list(tip)
    for column, values in tip.items():
        assert as_csv_cells(values) == written[column], column
    # Both agree with the large-deflection elastica within the discretisation error.
    assert tip["x_m"][-1] == pytest.approx(ELASTICA_TIP_X_M, abs=1e-5)
    assert tip["z_m"][-1] == pytest.approx(ELASTICA_TIP_Z_M, abs=1e-5)
    cli_summary = json.loads((tmp_path / "cli/summary.json").read_text())
    assert result.summary["probes"] == cli_summary["probes"]
    assert result.summary["stats"]["newton_iterations"] == cli_summary["stats"]["newton_iterations"]


def test_output_folder_is_the_clis(tmp_path, finseg_cli, source_dir):
    """run(out=...) writes the files `finseg run` writes, with the same CSV bytes."""
    scene_file = source_dir / "examples/cantilever/alpha2.yaml"
    sets = ["discretisation.segments=16", "solver.load_steps=2"]
    args = [a for s in sets for a in ("--set", s)]
    cli = finseg_cli("run", scene_file, "--out", tmp_path / "cli", "--quiet", *args)
    assert cli.returncode == 0, cli.stderr
    scene = finseg.load(str(scene_file), set={"discretisation.segments": 16})
    result = scene.with_set(["solver.load_steps=2"]).run(out=str(tmp_path / "py"))
    assert result.out == str(tmp_path / "py")
    cli_files = sorted(p.name for p in (tmp_path / "cli").iterdir())
    py_files = sorted(p.name for p in (tmp_path / "py").iterdir())
    assert py_files == cli_files
    assert (tmp_path / "py/tip.csv").read_bytes() == (tmp_path / "cli/tip.csv").read_bytes()
    py_summary = json.loads((tmp_path / "py/summary.json").read_text())
    assert py_summary["overrides"] == sets
    assert py_summary == result.summary
    # The checkpoint's scene hash covers the overrides the same way.
    py_state = json.loads((tmp_path / "py/checkpoint.json").read_text())
    cli_state = json.loads((tmp_path / "cli/checkpoint.json").read_text())
    assert py_state["scene_hash"] == cli_state["scene_hash"]
    assert py_state["bodies"] == cli_state["bodies"]


@pytest.mark.parametrize("solver", ["implicit", "explicit"])
def test_solver_choice_matches_cli_set(tmp_path, finseg_cli, solver):
    """run(solver=...) is `finseg run --set solver.type=...`."""
    scene = finseg.cantilever(
        segments=8, tip_force=(0, 0, -1e-4), damping_time=1e-3, t_end=5e-4, output_interval=1e-4
    )
    scene.save(str(tmp_path / "c.yaml"))
    cli = finseg_cli(
        "run", "c.yaml", "--out", "cli", "--quiet", "--set", f"solver.type={solver}",
        cwd=tmp_path,
    )
    assert cli.returncode == 0, cli.stderr
    result = scene.run(solver=solver)
    assert result.summary["solver"]["type"] == solver
    assert result.abscissa == "t_s"
    written = read_csv(tmp_path / "cli/tip.csv")
    for column, values in result.probes["tip"].items():
        assert as_csv_cells(values) == written[column], column


def test_generators_write_the_clis_scene_text(finseg_cli):
    cli = finseg_cli("gen", "zigzag", "--fold-angle", "83", "--panels", "4", "--fixed-panels",
                     "1,4", "--no-contact", "--solver", "implicit", "--pull-speed", "0.02")
    assert cli.returncode == 0, cli.stderr
    scene = finseg.zigzag(fold_angle=83, panels=4, fixed_panels=[1, 4], contact=False,
                          solver="implicit", pull_speed=0.02)
    assert scene.yaml == cli.stdout
    cli = finseg_cli("gen", "cantilever", "--segments", "12", "--tip-moment", "0,1e-4,0",
                     "--gravity")
    assert cli.returncode == 0, cli.stderr
    scene = finseg.cantilever(segments=12, tip_moment=[0, 1e-4, 0], gravity=True)
    assert scene.yaml == cli.stdout
