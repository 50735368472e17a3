"""Fixtures of the sphc module's tests: the compiler, a folder for the runs, and the pulse in
a strip of tests/physics/wave2d.sph (2400 particles, under a second), built and run once."""

from __future__ import annotations

from pathlib import Path

import pytest

import sphc

ROOT = Path(__file__).resolve().parents[2]
WAVE = ROOT / "tests" / "physics" / "wave2d.sph"


@pytest.fixture(scope="session")
def compiler() -> str:
    """sphc: $SPHC, PATH, or the build tree's."""
    try:
        return sphc.find_sphc()
    except FileNotFoundError:
        built = ROOT / "build" / "sphc"
        if built.is_file():
            return str(built)
        pytest.skip("sphc not found: set $SPHC, put it on PATH or build it (./scripts/build)")


@pytest.fixture(scope="session")
def work(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return tmp_path_factory.mktemp("runs")


@pytest.fixture(scope="session")
def wave(compiler: str, work: Path) -> sphc.Program:
    return sphc.build(WAVE, out=work / "wave2d", sphc=compiler)


class Lines(list):
    """The lines a run passed on (run's ``echo``)."""

    def __call__(self, line: str) -> None:
        self.append(line)


@pytest.fixture(scope="session")
def wave_run(wave: sphc.Program, work: Path) -> tuple[sphc.Run, Lines]:
    """wave2d to its end (7.5 ms, an output every 50 us), a frame every millisecond."""
    lines = Lines()
    return sphc.run(wave, out=work / "wave_out", frames=1e-3, echo=lines), lines
