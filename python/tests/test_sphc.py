"""The sphc module against real runs: sphc builds the models of tests/, the programs run,
and what the module reads is checked against the files read independently."""

from __future__ import annotations

import csv
import os
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

import sphc
from sphc.build import _flags
from sphc.run import program_flags

from conftest import ROOT, WAVE


def read_csv(path: Path) -> tuple[list[str], np.ndarray]:
    """A CSV file's header and rows, read with the csv module and float()."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return rows[0], np.array([[float(x) for x in row] for row in rows[1:]])


# ------------------------------------------------------------------ options and names

def test_program_flags() -> None:
    assert program_flags({"every": 1e-3, "no_stencil": True, "quiet": False,
                          "threads": None, "restart": Path("o/checkpoint.bin")}) == \
        ["--every", "0.001", "--no-stencil", "--restart", "o/checkpoint.bin"]
    assert _flags({"strict": True, "cuda_arch": "sm_90", "emit_c": None}) == \
        ["--strict", "--cuda-arch=sm_90"]


def test_program_name() -> None:
    assert sphc.program_name("cases/my-beam.sph") == "my-beam"
    assert sphc.program_name("a b(1).v2.sph") == "a_b_1_.v2"
    assert sphc.program_name("Case_Def.xml") == "Case_Def"


def test_missing_compiler() -> None:
    with pytest.raises(FileNotFoundError, match="sphc not found"):
        sphc.build(WAVE, sphc="/nonexistent/sphc")


def test_build_refuses_options_that_build_nothing(compiler: str) -> None:
    with pytest.raises(TypeError, match="check"):
        sphc.build(WAVE, sphc=compiler, check=True)


# ------------------------------------------------------------------ building

def test_build(wave: sphc.Program) -> None:
    assert wave.path.is_file() and os.access(wave.path, os.X_OK)
    assert wave.name == "wave2d" and wave.source == WAVE
    assert "sphc: built" in wave.stdout
    assert wave.warnings == []


def test_check(compiler: str) -> None:
    assert sphc.check(WAVE, sphc=compiler) == []


def test_compile_error(compiler: str, tmp_path: Path) -> None:
    """A misspelt parameter: CompileError with sphc's file:line:col message."""
    text = WAVE.read_text()
    lines = text.splitlines()
    line = next(k for k, s in enumerate(lines, 1) if "bulk 3.25e6" in s)
    column = lines[line - 1].index("bulk 3.25e6") + 1
    bad = tmp_path / "bad.sph"
    bad.write_text(text.replace("bulk 3.25e6", "bulkk 3.25e6"))
    with pytest.raises(sphc.CompileError) as caught:
        sphc.build(bad, out=tmp_path / "bad", sphc=compiler)
    where = f"{bad}:{line}:{column}: error: "
    assert where in str(caught.value)
    assert "bulkk" in caught.value.message
    first = caught.value.diagnostics[0]
    assert (first.file, first.line, first.column, first.kind) == (str(bad), line, column, "error")
    assert not (tmp_path / "bad").exists()
    with pytest.raises(sphc.CompileError, match=where):
        sphc.check(bad, sphc=compiler)


# ------------------------------------------------------------------ a run and its outputs

def test_run(wave_run) -> None:
    run, lines = wave_run
    assert run.ok and run.returncode == 0
    assert run.out.is_dir() and run.args[1:3] == ["--out", str(run.out)]
    assert any("ParaView" in line for line in lines)  # passed on as it came
    assert "ParaView" in run.stdout


def test_energies(wave_run) -> None:
    run, _ = wave_run
    energies = run.load().energies
    header, rows = read_csv(run.out / "energies.csv")
    assert header[0] == "time" and energies.index.name == "time"
    assert list(energies.columns) == header[1:] == \
        ["strip_strain", "strip_kinetic", "strip_viscous", "total"]
    assert np.array_equal(energies.index.to_numpy(), rows[:, 0])
    assert np.array_equal(energies.to_numpy(), rows[:, 1:])
    assert len(energies) == 151  # t = 0 and every 50 us to 7.5 ms
    assert energies["total"].iloc[0] > 0


def test_measurements(wave_run) -> None:
    run, _ = wave_run
    results = run.load()
    assert sorted(results.measurements) == ["first", "second"]
    for name, series in results.measurements.items():
        header, rows = read_csv(run.out / f"measure_{name}.csv")
        assert header == ["time", "ux", "uy", "uz", "fx", "fy", "fz"]
        assert list(series.columns) == header[1:]
        assert np.array_equal(series.index.to_numpy(), rows[:, 0])
        assert np.array_equal(series.to_numpy(), rows[:, 1:])
        assert series.index.equals(results.energies.index)
    # the pulse passes the first plane before the second
    first, second = (results.measurements[n]["ux"].abs().idxmax() for n in ("first", "second"))
    assert 0 < first < second


def test_summary(wave_run) -> None:
    summary = wave_run[0].load().summary
    assert summary["model"] == "wave2d" and summary["status"] == "finished"
    assert summary["stability"]["verdict"] == "stable"
    assert summary["particles"] == 2400
    assert summary["time"] == pytest.approx(7.5e-3)
    assert [b["name"] for b in summary["bodies"]] == ["strip"]


def test_frames(wave_run) -> None:
    run, _ = wave_run
    results = run.load()
    assert results.bodies == ["strip"]
    frames = results.frames("strip")
    assert [f.time for f in frames] == pytest.approx([1e-3 * k for k in range(8)])
    assert all(f.path.is_file() and f.path.parent == run.out / "particles" for f in frames)
    first, last = results.frame("strip", 0), results.frame("strip")
    assert last.field_data["TimeValue"][0] == pytest.approx(frames[-1].time)
    assert len(last.points) == len(last.cells_dict["vertex"]) == 2400
    assert {"displacement", "velocity", "cauchy_stress", "sigma_vm", "J",
            "strain_energy"} <= set(last.point_data)
    assert last.point_data["cauchy_stress"].shape == (2400, 6)
    assert np.all(first.point_data["displacement"] == 0)
    assert np.all(first.point_data["J"] == 1)
    # current position = reference position + displacement, the body in the plane y = 0
    moved = last.points - first.points
    assert np.allclose(moved, last.point_data["displacement"], rtol=0, atol=1e-15)
    assert np.all(last.points[:, 1] == 0)
    assert np.abs(last.point_data["displacement"][:, 0]).max() > 0
    with pytest.raises(KeyError, match="strip"):
        results.frames("nobody")


def test_load(wave_run) -> None:
    run, _ = wave_run
    results = sphc.load(run.out)
    assert results.energies.equals(run.load().energies)
    with pytest.raises(FileNotFoundError):
        sphc.load(run.out / "nothing")


# ------------------------------------------------------------------ exit codes

def test_used_folder(wave: sphc.Program, tmp_path: Path) -> None:
    """A folder with another run's outputs: refused (4) unless overwrite=True."""
    out = tmp_path / "out"
    sphc.run(wave, out=out, end=1e-3, echo=False)
    with pytest.raises(sphc.SetupFailed, match="holds the outputs of an earlier run") as caught:
        sphc.run(wave, out=out, end=1e-3, echo=False)
    assert caught.value.returncode == 4
    run = sphc.run(wave, out=out, end=5e-4, overwrite=True, echo=False)
    assert run.load().energies.index[-1] == pytest.approx(5e-4)


def test_bad_options(wave: sphc.Program, tmp_path: Path) -> None:
    with pytest.raises(sphc.BadOptions, match="invalid value '-1' for --end") as caught:
        sphc.run(wave, out=tmp_path / "out", end=-1, echo=False)
    assert caught.value.returncode == 2
    assert caught.value.run.returncode == 2
    run = sphc.run(wave, out=tmp_path / "out", threads=0, echo=False, check=False)
    assert run.returncode == 2 and not run.ok
    with pytest.raises(sphc.BadOptions, match="--threads"):
        run.check()


def test_expectation_failed(compiler: str, work: Path) -> None:
    """The coarse beam for a twelfth of its period: it has no period to compare (exit 1)."""
    program = sphc.build(ROOT / "tests" / "physics" / "beam2d_coarse.sph",
                         out=work / "beam2d_coarse", sphc=compiler)
    with pytest.raises(sphc.ExpectationFailed) as caught:
        sphc.run(program, out=work / "beam_out", end=0.02, every=2e-3, echo=False)
    error = caught.value
    assert error.returncode == 1
    assert "expect period tip.uz = 0.2553 within 3%: no period" in error.message
    assert "(FAILED)" in str(error)
    results = error.run.load()
    failed = [x["kind"] for x in results.summary["expectations"] if not x["pass"]]
    assert "period" in failed
    assert results.summary["status"] == "finished"
    assert results.measurements["tip"].index[-1] == pytest.approx(0.02)


def test_unstable(compiler: str, work: Path) -> None:
    """A fixed time step five times the stable one: the monitor stops the run (exit 3)."""
    program = sphc.build(ROOT / "tests" / "stability" / "unstable_dt.sph",
                         out=work / "unstable_dt", sphc=compiler)
    with pytest.raises(sphc.Unstable, match="the run went unstable at step") as caught:
        sphc.run(program, out=work / "unstable_out", echo=False)
    assert caught.value.returncode == 3
    results = caught.value.run.load()
    assert results.summary["status"] == "unstable"
    assert results.summary["stability"]["verdict"] == "unstable"
    assert [f.time for f in results.frames("block")] == [0.0]  # the last good output


# ------------------------------------------------------------------ many processes

def test_processes(compiler: str, wave_run, work: Path) -> None:
    """wave2d on two MPI processes: the same energies as on one, to round-off, and each
    frame's pieces joined into one mesh."""
    mpirun = os.environ.get("MPIRUN", "mpirun")
    if not shutil.which(mpirun):
        pytest.skip("no mpirun")
    version = subprocess.run([mpirun, "--version"], capture_output=True, text=True).stdout
    if "Open MPI" in version or "OpenRTE" in version:  # (more processes than cores)
        mpirun = [mpirun, "--oversubscribe"]
    try:
        program = sphc.build(WAVE, out=work / "wave2d_mpi", mpi=True, sphc=compiler)
    except sphc.CompileError as error:
        if "without MPI" in error.message:
            pytest.skip("sphc was built without MPI")
        raise
    env = {"OMP_NUM_THREADS": "1", "OMPI_ALLOW_RUN_AS_ROOT": "1",
           "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1"}
    run = sphc.run(program, processes=2, mpirun=mpirun, out=work / "wave_mpi_out", end=2e-3,
                   frames=1e-3, env=env, echo=False)
    results, serial = run.load(), wave_run[0].load()
    assert results.summary["processes"]["count"] == 2
    energies = results.energies
    assert np.allclose(energies, serial.energies.loc[energies.index], rtol=1e-9, atol=1e-18)
    frames = results.frames("strip")
    assert [f.path.suffix for f in frames] == [".pvtu"] * 3
    mesh = results.frame("strip")
    assert len(mesh.points) == 2400
    assert np.array_equal(mesh.point_data["global_id"], np.arange(2400))
