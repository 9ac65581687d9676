"""finseg from Python: build a scene from a generator or a scene file, change parameters,
run any solver, get the probes as numpy arrays (docs/python.md).

    import finseg
    scene = finseg.zigzag(fold_angle=83)
    result = scene.run()
    gauge = result.probes["gauge"]   # {"pull_displacement_m": array, "force_N": array, ...}
"""

from ._errors import DivergenceError, InputError, OutputError
from ._finseg import (
    Result,
    Scene,
    State,
    __version__,
    cantilever,
    git_revision,
    load,
    parse,
    read_fold,
    zigzag,
)

__all__ = [
    "DivergenceError",
    "InputError",
    "OutputError",
    "Result",
    "Scene",
    "State",
    "cantilever",
    "git_revision",
    "load",
    "parse",
    "read_fold",
    "zigzag",
]
