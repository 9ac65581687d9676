"""FOLD crease patterns from Python: read and checked as `finseg pattern check` does
(docs/fold.md); refusals are InputErrors."""

import json

import finseg
import numpy as np
import pytest


def test_zigzag_pattern_reads_back(tmp_path, finseg_cli):
    cli = finseg_cli("pattern", "zigzag", "--length", "0.48", "--width", "0.04", "--panels", "6",
                     "--out", "z.fold", cwd=tmp_path)
    assert cli.returncode == 0, cli.stderr
    p = finseg.read_fold(str(tmp_path / "z.fold"))
    flat = p["vertices_flat_m"]
    # The flat strip is 480 x 40 mm; 6 panels have 5 creases, each a mountain or a valley.
    assert np.ptp(flat[:, 0]) == pytest.approx(0.48, abs=1e-12)
    assert np.ptp(flat[:, 1]) == pytest.approx(0.04, abs=1e-12)
    assert sum(a in "MV" for a in p["edges_assignment"]) == 5
    assert len(p["faces_vertices"]) == 6
    assert p["vertices_folded_m"].shape == (len(flat), 3)
    assert p["edges_vertices"].shape == (len(p["edges_assignment"]), 2)


def test_unitless_pattern_needs_a_unit(tmp_path):
    square = {
        "file_spec": 1.1,
        "vertices_coords": [[0, 0], [1, 0], [1, 1], [0, 1]],
        "faces_vertices": [[0, 1, 2, 3]],
    }
    path = tmp_path / "square.fold"
    path.write_text(json.dumps(square))
    with pytest.raises(finseg.InputError) as e:
        finseg.read_fold(str(path))
    assert e.value.file == str(path)
    p = finseg.read_fold(str(path), unit="mm")
    assert np.ptp(p["vertices_flat_m"][:, 0]) == pytest.approx(1e-3)
    assert finseg.read_fold(str(path), unit=0.2)["vertices_flat_m"].max() == pytest.approx(0.2)
    with pytest.raises(finseg.InputError):
        finseg.read_fold(str(path), unit="furlong")
