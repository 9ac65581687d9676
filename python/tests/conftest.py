"""Shared fixtures: the finseg command line and the source tree, as CTest passes them
(python/CMakeLists.txt sets FINSEG_BINARY and FINSEG_SOURCE_DIR)."""

import csv
import os
import pathlib
import subprocess

import pytest

SOURCE_DIR = pathlib.Path(
    os.environ.get("FINSEG_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2])
)


@pytest.fixture(scope="session")
def finseg_cli():
    """Runs `finseg ARGS...`; returns the CompletedProcess (text)."""
    binary = os.environ.get("FINSEG_BINARY")
    if not binary:
        pytest.fail("FINSEG_BINARY is not set (run the tests through ctest)")

    def run(*args, cwd=None):
        return subprocess.run(
            [binary, *map(str, args)], cwd=cwd, capture_output=True, text=True, check=False
        )

    return run


@pytest.fixture(scope="session")
def source_dir():
    return SOURCE_DIR


def read_csv(path):
    """{column: [text cell, ...]} of a CSV file, cells as written."""
    with open(path, newline="", encoding="utf-8") as f:
        rows = list(csv.reader(f))
    return {name: [r[i] for r in rows[1:]] for i, name in enumerate(rows[0])}


def as_csv_cells(values):
    """Numbers formatted as finseg's CSV writer formats them (12 significant digits)."""
    return [f"{v:.12g}" for v in values]
