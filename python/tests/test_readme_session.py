"""The README's Python session runs as printed (it needs matplotlib, which the module
itself does not: skipped without it)."""

import os
import re

import pytest


def test_readme_session_runs(tmp_path, source_dir, monkeypatch):
    pytest.importorskip("matplotlib")
    monkeypatch.setenv("MPLBACKEND", "Agg")
    text = (source_dir / "README.md").read_text(encoding="utf-8")
    section = text[text.index("## From Python") :]
    code = re.search(r"```python\n(.*?)```", section, re.S).group(1)
    os.symlink(source_dir / "examples", tmp_path / "examples")
    monkeypatch.chdir(tmp_path)
    exec(compile(code, "README.md", "exec"), {})
    assert (tmp_path / "conditions.png").stat().st_size > 10000
