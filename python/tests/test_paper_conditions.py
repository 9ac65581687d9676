"""The paper's four zigzag conditions (examples/zigzag/, Table 1) from Python give the
command line's curves and deployment peaks exactly (about 0.6 s each in Release)."""

import json

import finseg
import pytest
from conftest import as_csv_cells, read_csv

CONDITIONS = [
    "condition1-80deg-plain",
    "condition2-80deg-taped",
    "condition3-83deg-plain",
    "condition4-83deg-taped",
]


@pytest.mark.parametrize("name", CONDITIONS)
def test_condition_matches_cli(name, tmp_path, finseg_cli, source_dir):
    scene_file = source_dir / f"examples/zigzag/{name}.yaml"
    cli = finseg_cli("run", scene_file, "--out", tmp_path / "cli", "--quiet")
    assert cli.returncode == 0, cli.stderr
    result = finseg.load(str(scene_file)).run()
    gauge = result.probes["gauge"]
    written = read_csv(tmp_path / "cli/gauge.csv")
    assert list(gauge) == list(written)
    for column, values in gauge.items():
        assert as_csv_cells(values) == written[column], column
    cli_summary = json.loads((tmp_path / "cli/summary.json").read_text())
    ours = result.summary["probes"]["gauge"]
    theirs = cli_summary["probes"]["gauge"]
    for key in ["deployment_peak_force_N", "deployment_peak_displacement_m", "peak_force_N"]:
        assert ours[key] == theirs[key], key
    assert result.summary["phases"] == cli_summary["phases"]
