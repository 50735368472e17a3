"""sphc from Python: build a model into a program, run it, read its outputs.

>>> import sphc
>>> program = sphc.build("cases/beam2d.sph")               # sphc cases/beam2d.sph
>>> run = sphc.run(program, out="beam_out", end=0.01)       # ./beam2d --out beam_out --end 0.01
>>> results = run.load()                                    # or sphc.load("beam_out")
>>> results.measurements["tip"]["uz"].abs().max()

The compiler is found through ``build(..., sphc=PATH)``, ``$SPHC`` or PATH.  See
docs/python.md in the sphc repository.
"""

from .build import Program, build, check, find_sphc, program_name
from .errors import (BadOptions, CompileError, CudaError, Diagnostic, ExpectationFailed,
                     RunError, SetupFailed, SphcError, Stopped, Unstable)
from .results import Frame, Results, load, read_frame
from .run import Run, run

__version__ = "0.1.0"

__all__ = [
    "build", "check", "run", "load", "read_frame", "find_sphc", "program_name",
    "Program", "Run", "Results", "Frame", "Diagnostic",
    "SphcError", "CompileError", "RunError", "ExpectationFailed", "BadOptions", "Unstable",
    "SetupFailed", "CudaError", "Stopped",
]
