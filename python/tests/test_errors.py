"""Bad input raises finseg.InputError (a ValueError naming file, field and message) where
`finseg` exits 2; a diverging run raises finseg.DivergenceError (exit 3) with what it
recorded. The interpreter survives every one."""

import finseg
import pytest


def test_input_error_is_a_value_error_with_file_field_message(source_dir):
    scene = str(source_dir / "examples/cantilever/alpha2.yaml")
    with pytest.raises(finseg.InputError) as e:
        finseg.load(scene, set={"material.youngs_modulus": -1})
    assert isinstance(e.value, ValueError)
    assert e.value.file == scene
    assert e.value.field == "material.youngs_modulus"
    assert e.value.message
    assert str(e.value) == f"{e.value.file}: {e.value.field}: {e.value.message}"


def test_same_message_as_the_cli(tmp_path, finseg_cli, source_dir):
    scene = str(source_dir / "examples/cantilever/alpha2.yaml")
    cli = finseg_cli("run", scene, "--out", tmp_path / "o", "--set", "solver.type=magic")
    assert cli.returncode == 2
    with pytest.raises(finseg.InputError) as e:
        finseg.load(scene).run(solver="magic")
    assert f"finseg: error: {e.value}\n" == cli.stderr


@pytest.mark.parametrize(
    "call, field",
    [
        (lambda: finseg.load("/nonexistent/scene.yaml"), "file"),
        (lambda: finseg.parse("a: [1, 2"), "line 1"),
        (lambda: finseg.parse("title: x\nunknown_section: 1\n"), "unknown_section"),
        (lambda: finseg.zigzag(fold_angle="80"), "fold_angle"),
        (lambda: finseg.zigzag(panels=2.5), "panels"),
        (lambda: finseg.zigzag(colour="red"), "colour"),
        (lambda: finseg.zigzag(panels=1), "panels"),
        (lambda: finseg.zigzag(pressing_time=10), "pressing_time"),
        (lambda: finseg.zigzag(pull_speed=0), "pull_speed"),
        (lambda: finseg.cantilever(tip_force=(0, 0)), "tip_force"),
        (lambda: finseg.cantilever(gravity=1), "gravity"),
        (lambda: finseg.cantilever(solver="quick"), "solver"),
        (lambda: finseg.cantilever().with_set({"no.such.key": 1}), "no"),
        (lambda: finseg.cantilever().with_set(["missing_equals_sign"]), "'missing_equals_sign'"),
        (lambda: finseg.cantilever().with_set(42), "set"),
        (lambda: finseg.cantilever().run(threads=-1), "threads"),
    ],
)
def test_bad_input_raises_input_error(call, field):
    with pytest.raises(finseg.InputError) as e:
        call()
    assert e.value.field.startswith(field), str(e.value)


def test_unknown_option_lists_the_allowed_ones():
    with pytest.raises(finseg.InputError) as e:
        finseg.zigzag(fold_angel=83)
    assert "fold_angle" in e.value.message


def test_state_of_another_model_is_refused(tmp_path):
    small = finseg.cantilever(segments=4)
    big = finseg.cantilever(segments=8)
    with pytest.raises(finseg.InputError):
        big.run(state=small.initial_state())
    small.initial_state().save(str(tmp_path / "s.json"))
    with pytest.raises(finseg.InputError) as e:
        big.read_state(str(tmp_path / "s.json"))
    assert e.value.file == str(tmp_path / "s.json")


def test_divergence_raises_with_what_was_recorded(tmp_path, finseg_cli):
    # A far too large explicit step (as tests/test_cli_run.cpp's DivergingRunKeepsWhatItRecorded).
    options = dict(segments=8, tip_force=(0, 0, -1e-3), solver="explicit", t_end=0.2, dt=2e-3,
                   output_interval=2e-3)
    scene = finseg.cantilever(**options)
    with pytest.raises(finseg.DivergenceError) as e:
        scene.run(out=str(tmp_path / "py"))
    assert "diverged" in str(e.value)
    result = e.value.result
    assert result.status == "diverged"
    t = result.probes["tip"]["t_s"]
    assert 2 <= len(t) < 101
    assert t[-1] < 0.2
    assert (tmp_path / "py/summary.json").exists()
    scene.save(str(tmp_path / "c.yaml"))
    cli = finseg_cli("run", "c.yaml", "--out", "cli", "--quiet", cwd=tmp_path)
    assert cli.returncode == 3
    assert (tmp_path / "py/tip.csv").read_bytes() == (tmp_path / "cli/tip.csv").read_bytes()


def test_unwritable_output_folder_is_refused_before_the_run(tmp_path):
    blocker = tmp_path / "file"
    blocker.write_text("not a folder")
    with pytest.raises((finseg.InputError, finseg.OutputError)):
        finseg.cantilever(segments=4).run(out=str(blocker / "out"))
