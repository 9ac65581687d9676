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


def test_readme_fold_session_runs(tmp_path, finseg_cli, monkeypatch, capsys, source_dir):
    """The README's fold-once-deploy-many session, on the cone its text generates."""
    text = (source_dir / "README.md").read_text(encoding="utf-8")
    section = text[text.index("## From Python") :]
    command = " ".join(re.search(r"`finseg (gen cone [^`]*)`", section).group(1).split())
    gen = finseg_cli(*command.split(), cwd=tmp_path)
    assert gen.returncode == 0, gen.stderr
    code = re.findall(r"```python\n(.*?)```", section, re.S)[1]
    monkeypatch.chdir(tmp_path)
    exec(compile(code, "README.md", "exec"), {"finseg": __import__("finseg")})
    lines = capsys.readouterr().out.split("\n")[:3]
    assert [int(line.split()[0]) for line in lines] == [10, 20, 40]
    assert all(float(line.split()[1]) > 0 for line in lines)
