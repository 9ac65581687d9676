"""The errors of finseg as Python exceptions (raised by the C++ core, docs/python.md)."""


class InputError(ValueError):
    """Bad input, as `finseg` exits 2 for: names the file (or "<python>"), the field and
    what is allowed."""

    def __init__(self, file, field, message):
        super().__init__(f"{file}: {field}: {message}")
        self.file = file
        self.field = field
        self.message = message


class DivergenceError(RuntimeError):
    """The simulation diverged (`finseg run` exits 3); `result` holds what was recorded
    up to the last good output (a finseg.Result), when there is one."""

    def __init__(self, message, result=None):
        super().__init__(message)
        self.message = message
        self.result = result


class OutputError(OSError):
    """An output could not be written (disk full, permissions; `finseg` exits 4)."""
