"""Compiling a model with sphc: :func:`build` makes a program, :func:`check` only checks."""

from __future__ import annotations

import os
import shutil
import subprocess
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Optional, Union

from .errors import CompileError, Diagnostic, parse_diagnostics

__all__ = ["Program", "build", "check", "find_sphc", "program_name"]

PathLike = Union[str, "os.PathLike[str]"]

# sphc's options that build no program: check() runs --check; the others print.
_NOT_A_BUILD = {"o", "check", "dump", "to_sph", "emit_only", "help", "version"}


@dataclass(frozen=True)
class Program:
    """A program sphc built: ``path`` runs the model ``source``.

    ``stderr`` holds sphc's warnings and notes (``warnings``, parsed), ``stdout`` its
    report (``sphc: built ./beam (cpu)``).  ``Program.run(...)`` is :func:`sphc.run`.
    """

    path: Path
    source: Path
    target: str = "cpu"
    mpi: bool = False
    stdout: str = ""
    stderr: str = ""

    @property
    def name(self) -> str:
        """The program's file name."""
        return self.path.name

    @property
    def warnings(self) -> list[Diagnostic]:
        """sphc's ``file:line:col: warning: ...`` messages on the model."""
        return [d for d in parse_diagnostics(self.stderr) if d.kind == "warning"]

    def __fspath__(self) -> str:
        return str(self.path)

    def run(self, **kwargs: Any) -> "Any":
        """Runs the program: :func:`sphc.run` with this program."""
        from .run import run
        return run(self, **kwargs)


def find_sphc(sphc: Optional[PathLike] = None) -> str:
    """The sphc compiler: ``sphc`` if given, else ``$SPHC``, else ``sphc`` on PATH.

    Raises FileNotFoundError when none is found.
    """
    given = sphc or os.environ.get("SPHC")
    if given:
        path = shutil.which(str(given)) or (str(given) if os.path.isfile(given) else None)
        if path:
            return path
        raise FileNotFoundError(f"sphc not found at {given}")
    path = shutil.which("sphc")
    if not path:
        raise FileNotFoundError("sphc not found: pass sphc=PATH, set $SPHC or put sphc on "
                                "PATH (it is built as build/sphc; see README.md)")
    return path


def program_name(path: PathLike) -> str:
    """The name sphc gives the program of the model at ``path``: its file name without the
    extension, with characters other than letters, digits and ``. _ + -`` as ``_``."""
    base = os.path.basename(os.fspath(path))
    dot = base.rfind(".")
    stem = base[:dot] if dot > 0 else base
    return "".join(c if (c.isascii() and c.isalnum()) or c in "._+-" else "_" for c in stem)


def _flags(options: dict[str, Any]) -> list[str]:
    """sphc's flags for keyword options: ``strict=True`` is ``--strict``, ``cuda_arch="sm_90"``
    is ``--cuda-arch=sm_90``; False and None leave an option out."""
    flags = []
    for key, value in options.items():
        if value is None or value is False:
            continue
        flag = "--" + key.replace("_", "-")
        if isinstance(value, os.PathLike):
            value = os.fspath(value)
        flags.append(flag if value is True else f"{flag}={value}")
    return flags


def _sphc(sphc: Optional[PathLike], flags: list[str],
          path: PathLike) -> "subprocess.CompletedProcess[str]":
    """Runs sphc with ``flags`` on the model at ``path``; raises CompileError on failure."""
    model = Path(path)
    if not model.is_file():
        raise FileNotFoundError(f"no model at {model}")
    command = [find_sphc(sphc), *flags, str(model)]
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        raise CompileError(done.stderr, done.returncode, command)
    return done


def build(path: PathLike, out: Optional[PathLike] = None, target: str = "cpu",
          mpi: bool = False, *, sphc: Optional[PathLike] = None, **options: Any) -> Program:
    """Compiles the model at ``path`` (a ``.sph`` model or a SoliDualSPHysics ``.xml`` case)
    into a program.

    ``out`` is the program's path (default: named after the model, in the current folder,
    as sphc names it); ``target`` is ``"cpu"`` or ``"cuda"``; ``mpi`` builds for many
    processes.  Other keyword options are sphc's (README.md, "The compiler"), underscores
    for dashes: ``strict=True``, ``cuda_arch="sm_90"``, ``emit_c="gen"``,
    ``xml_elastic2d="sdsph"``, ``xml_fill="gencase"``.  ``sphc`` is the compiler (default:
    ``$SPHC``, else PATH).

    Raises :class:`~sphc.CompileError` with sphc's messages when the model is refused or
    does not build.
    """
    for key in options:
        if key in _NOT_A_BUILD:
            raise TypeError(f"build() builds a program; the option {key!r} does not "
                            "(sphc.check() checks a model)")
    exe = Path(out if out is not None else program_name(path)).absolute()
    flags = ["-o", str(exe), f"--target={target}", *(["--mpi"] if mpi else []), *_flags(options)]
    done = _sphc(sphc, flags, path)
    return Program(exe, Path(path).resolve(), target, mpi, done.stdout, done.stderr)


def check(path: PathLike, *, sphc: Optional[PathLike] = None, **options: Any) -> list[Diagnostic]:
    """Checks the model at ``path`` (``sphc --check``) without building anything; returns
    sphc's warnings.  Options as for :func:`build` (``strict=True`` makes warnings errors).

    Raises :class:`~sphc.CompileError` when the model is refused.
    """
    done = _sphc(sphc, ["--check", *_flags(options)], path)
    return [d for d in parse_diagnostics(done.stderr) if d.kind == "warning"]
