"""Running a generated program: :func:`run` starts it with its options, passes its lines on
as they come and maps its exit status to an exception (README.md, "Exit codes")."""

from __future__ import annotations

import os
import shlex
import subprocess
import sys
import threading
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import IO, Any, Callable, Mapping, Optional, Sequence, Union

from .build import PathLike, Program
from .errors import error_for
from .results import Results

__all__ = ["Run", "run", "program_flags"]

Echo = Union[bool, Callable[[str], None]]


@dataclass
class Run:
    """A finished run of a program: its command line (``args``), output folder (``out``),
    exit status (``returncode``), standard output and error, and wall time in seconds."""

    program: Path
    out: Path
    args: list[str]
    returncode: int
    stdout: str = ""
    stderr: str = ""
    wall_time: float = 0.0
    _results: Optional[Results] = field(default=None, repr=False, compare=False)

    @property
    def ok(self) -> bool:
        """Whether the program exited with 0."""
        return self.returncode == 0

    def check(self) -> "Run":
        """Raises the exception for the exit status (:class:`~sphc.Unstable` for 3, ...);
        returns the run when it is 0."""
        error = error_for(self)
        if error is not None:
            raise error
        return self

    def load(self) -> Results:
        """The run's outputs (:func:`sphc.load` of ``out``), read once."""
        if self._results is None:
            self._results = Results(self.out)
        return self._results


def program_flags(options: Mapping[str, Any]) -> list[str]:
    """A generated program's flags for keyword options (README.md, "The generated
    program"): ``every=1e-3`` is ``--every 0.001``, ``no_stencil=True`` is
    ``--no-stencil``; False and None leave an option out."""
    flags: list[str] = []
    for key, value in options.items():
        if value is None or value is False:
            continue
        flags.append("--" + key.replace("_", "-"))
        if value is not True:
            flags.append(os.fspath(value) if isinstance(value, os.PathLike) else str(value))
    return flags


def _sinks(echo: Echo) -> tuple[Callable[[str], None], Callable[[str], None]]:
    """Where the program's standard output and error lines go as they come."""
    if callable(echo):
        def call(line: str) -> None:
            echo(line.rstrip("\n"))
        return call, call
    if not echo:
        return _ignore, _ignore
    return _writer("stdout"), _writer("stderr")


def _ignore(line: str) -> None:
    pass


def _writer(name: str) -> Callable[[str], None]:
    """Writes a line to sys.stdout or sys.stderr, as they are when it comes."""
    def write(line: str) -> None:
        stream = getattr(sys, name)
        stream.write(line)
        stream.flush()
    return write


def _pump(stream: IO[str], lines: list[str], sink: Callable[[str], None]) -> None:
    for line in stream:
        lines.append(line)
        sink(line)


def _stop(proc: "subprocess.Popen[str]") -> None:
    """Stops a program still running: SIGTERM, after which it ends after the step under way
    and writes summary.json "stopped" (and its checkpoint if it takes them), then SIGKILL
    if it has not ended within 30 s."""
    if proc.poll() is not None:
        return
    proc.terminate()
    try:
        proc.wait(timeout=30)
    except subprocess.TimeoutExpired:
        proc.kill()
        proc.wait()


def run(program: Union[Program, PathLike], out: Optional[PathLike] = None,
        threads: Optional[int] = None, end: Optional[float] = None, *,
        processes: Optional[int] = None, mpirun: Union[str, Sequence[str], None] = None,
        echo: Echo = True, check: bool = True, env: Optional[Mapping[str, str]] = None,
        **options: Any) -> Run:
    """Runs a program built by :func:`sphc.build` (or the path of one).

    ``out`` is the output folder (``--out``; default ``<program>_out`` in the current
    folder, or the folder of a ``restart`` checkpoint); ``threads`` and ``end`` are
    ``--threads`` and ``--end``.  Other keyword options are the program's, underscores for
    dashes (README.md, "The generated program"): ``every=1e-3``, ``frames=0.01``,
    ``overwrite=True``, ``quiet=True``, ``progress=5``, ``profile=True``,
    ``checkpoint=0.1``, ``restart="out/checkpoint.bin"``, ``no_stencil=True``, ...

    ``processes`` runs it on that many MPI processes (a program built with ``mpi=True``)
    through ``mpirun``: a command, or a list of its words with flags such as
    ``["mpirun", "--oversubscribe"]`` (default ``$MPIRUN``, else ``mpirun``).  ``echo``
    passes the program's lines on as they come: True to this process's standard output
    and error, False nowhere (they are kept in the Run either way), or a function called
    with each line.  ``env`` adds environment variables (``OMP_WAIT_POLICY``, ...).

    With ``check`` (the default) an exit status other than 0 raises its exception, which
    carries the program's message and the Run: :class:`~sphc.ExpectationFailed` (1),
    :class:`~sphc.BadOptions` (2), :class:`~sphc.Unstable` (3),
    :class:`~sphc.SetupFailed` (4), :class:`~sphc.CudaError` (5), :class:`~sphc.Stopped`
    (6, 7) or :class:`~sphc.RunError`; without, the Run is returned whatever its status
    (``Run.check()`` raises it later).  An interrupted call (KeyboardInterrupt) stops the
    program with SIGTERM, which ends it after the step under way, and is raised again.
    """
    exe = Path(program.path if isinstance(program, Program) else program).absolute()
    if out is None:
        restart = options.get("restart")
        out = Path(restart).parent if restart else Path(f"{exe.name}_out")
    out = Path(out).absolute()
    args = [str(exe), "--out", str(out),
            *program_flags({"threads": threads, "end": end, **options})]
    if processes is not None:
        launcher = mpirun or os.environ.get("MPIRUN") or "mpirun"
        launcher = shlex.split(launcher) if isinstance(launcher, str) else list(launcher)
        args = [*launcher, "-np", str(processes), *args]
    environment = {**os.environ, **(env or {})}
    out_sink, err_sink = _sinks(echo)
    out_lines: list[str] = []
    err_lines: list[str] = []
    start = time.monotonic()
    # (a session of its own: a terminal's Ctrl-C reaches this process alone, which stops
    # the program with one SIGTERM, as _stop says, rather than two signals)
    proc = subprocess.Popen(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            encoding="utf-8", errors="replace", bufsize=1, env=environment,
                            start_new_session=True)
    errors = threading.Thread(target=_pump, args=(proc.stderr, err_lines, err_sink), daemon=True)
    errors.start()
    try:
        assert proc.stdout is not None
        _pump(proc.stdout, out_lines, out_sink)
        proc.wait()
    except BaseException:
        _stop(proc)
        raise
    finally:
        errors.join()
        for stream in (proc.stdout, proc.stderr):
            if stream:
                stream.close()
    result = Run(exe, out, args, proc.returncode, "".join(out_lines), "".join(err_lines),
                 time.monotonic() - start)
    return result.check() if check else result
