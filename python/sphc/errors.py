"""The exceptions of the sphc module: a model that does not compile, and a run that ended
with one of the generated program's non-zero exit codes (README.md, "Exit codes")."""

from __future__ import annotations

import re
from typing import TYPE_CHECKING, NamedTuple, Optional

if TYPE_CHECKING:  # (no import cycle at run time)
    from .run import Run

__all__ = [
    "SphcError", "CompileError", "Diagnostic", "RunError", "ExpectationFailed",
    "BadOptions", "Unstable", "SetupFailed", "CudaError", "Stopped", "error_for",
]


class SphcError(Exception):
    """The base of every error this module raises for sphc or a generated program."""


class Diagnostic(NamedTuple):
    """One of sphc's ``file:line:col: kind: text`` messages."""

    file: str
    line: int
    column: int
    kind: str  # "error", "warning" or "note"
    text: str


_DIAGNOSTIC = re.compile(r"^(.+?):(\d+):(\d+): (error|warning|note): (.*)$")


def parse_diagnostics(text: str) -> list[Diagnostic]:
    """The ``file:line:col: kind: text`` lines of sphc's messages, in order (the quoted
    source lines and carets that follow each are left out)."""
    found = []
    for line in text.splitlines():
        m = _DIAGNOSTIC.match(line)
        if m:
            found.append(Diagnostic(m[1], int(m[2]), int(m[3]), m[4], m[5]))
    return found


class CompileError(SphcError):
    """sphc refused a model or failed to build it.

    ``message`` is sphc's standard error, whose ``file:line:col: error: ...`` lines (with
    the source line and a caret) say where; ``diagnostics`` holds those lines parsed.
    """

    def __init__(self, message: str, returncode: int, command: list[str]):
        self.message = message
        self.returncode = returncode
        self.command = command
        self.diagnostics = parse_diagnostics(message)
        super().__init__(message.rstrip() or f"sphc exited with {returncode}")


class RunError(SphcError):
    """A generated program exited with a status other than 0.

    ``returncode`` is its exit status (negative: the signal that killed it), ``message``
    its standard error (the lines that say why), ``run`` the :class:`~sphc.Run`, whose
    output folder keeps what the program wrote until then.
    """

    #: what the exit status means (README.md), for the message
    meaning = "the run failed"

    def __init__(self, run: "Run"):
        self.run = run
        self.returncode = run.returncode
        self.message = run.stderr
        what = (f"killed by signal {-run.returncode}" if run.returncode < 0
                else f"exited with {run.returncode}: {self.meaning}")
        text = run.stderr.strip()
        super().__init__(f"{run.program.name} {what}" + (f"\n{text}" if text else ""))


class ExpectationFailed(RunError):
    """Exit 1: the run finished, but an expectation the model declares failed (summary.json,
    "expectations", says which)."""

    meaning = "a declared expectation failed"


class BadOptions(RunError):
    """Exit 2: the program refused its command line."""

    meaning = "bad options"


class Unstable(RunError):
    """Exit 3: the stability monitor stopped the run; the last good output is kept."""

    meaning = "the run went unstable"


class SetupFailed(RunError):
    """Exit 4: the set-up or an output failed (a folder with another run's outputs without
    ``overwrite=True`` among them)."""

    meaning = "set-up or output failed"


class CudaError(RunError):
    """Exit 5: a CUDA call failed (CUDA target; the message names the call and the reason)."""

    meaning = "a CUDA call failed"


class Stopped(RunError):
    """Exit 6 or 7: stopped by a signal (SIGTERM, SIGINT), after writing a checkpoint to
    resume from (6, ``checkpoint`` true) or without one (7); the outputs up to then are
    kept and summary.json says ``"stopped"``."""

    meaning = "stopped by a signal"

    @property
    def checkpoint(self) -> bool:
        """Whether the program wrote a checkpoint that resumes the run (exit 6)."""
        return self.returncode == 6


_BY_CODE: dict[int, type[RunError]] = {
    1: ExpectationFailed, 2: BadOptions, 3: Unstable, 4: SetupFailed, 5: CudaError,
    6: Stopped, 7: Stopped,
}


def error_for(run: "Run") -> Optional[RunError]:
    """The exception for the exit status of ``run``, or None for 0."""
    if run.returncode == 0:
        return None
    return _BY_CODE.get(run.returncode, RunError)(run)
