"""Reading a run's output folder as the runtime writes it (README.md, "The generated
program"): energies.csv and measure_<name>.csv (a header of column names, then a row per
output time, ``time`` first), summary.json, and each body's particle frames, listed with
their times in particles/<body>.pvd (``.vtu`` files, or ``.pvtu`` files of one ``.vtu``
piece per process for a run on many processes)."""

from __future__ import annotations

import json
import os
import xml.etree.ElementTree as ET
from functools import cached_property
from pathlib import Path
from typing import Any, NamedTuple, Union

import meshio
import numpy as np
import pandas as pd

__all__ = ["Frame", "Results", "load"]


class Frame(NamedTuple):
    """A body's particle file at one output time (an entry of its ``.pvd`` list)."""

    time: float
    path: Path


def _csv(path: Path) -> pd.DataFrame:
    """A CSV time series of the runtime: its columns as written, ``time`` as the index, each
    number read to the double nearest its text (``%.10g``)."""
    return pd.read_csv(path, index_col="time", dtype=np.float64, float_precision="round_trip")


class Results:
    """The outputs of a run in the folder ``out``, each read when first asked for.

    ``energies``: energies.csv as a DataFrame indexed by time (columns
    ``<body>_strain``, ``<body>_kinetic``, ..., ``total``); ``measurements``: each
    measurement plane's ``measure_<name>.csv`` by name (columns ``ux uy uz fx fy fz``);
    ``summary``: summary.json; ``frames(body)`` and ``frame(body, k)``: the particle files.
    """

    def __init__(self, out: Union[str, "os.PathLike[str]"]):
        self.out = Path(out)
        if not self.out.is_dir():
            raise FileNotFoundError(f"no output folder {self.out}")

    def __repr__(self) -> str:
        return f"Results({str(self.out)!r})"

    @cached_property
    def energies(self) -> pd.DataFrame:
        """energies.csv: a row per output time, indexed by ``time``."""
        return _csv(self.out / "energies.csv")

    @cached_property
    def measurements(self) -> dict[str, pd.DataFrame]:
        """The measurement planes' series by name (``measure_<name>.csv``), each indexed by
        ``time`` with the columns ``ux uy uz`` (mean displacement) and ``fx fy fz``
        (force)."""
        return {path.name[len("measure_"):-len(".csv")]: _csv(path)
                for path in sorted(self.out.glob("measure_*.csv"))}

    @cached_property
    def summary(self) -> dict[str, Any]:
        """summary.json (a value that was not finite is None)."""
        with open(self.out / "summary.json", encoding="utf-8") as f:
            return json.load(f)

    @property
    def bodies(self) -> list[str]:
        """The names of the bodies that have particle frames, in the model's order where
        summary.json lists them."""
        listed = {path.stem for path in (self.out / "particles").glob("*.pvd")}
        try:
            ordered = [b["name"] for b in self.summary.get("bodies", [])]
        except (OSError, ValueError):
            ordered = []
        return [b for b in ordered if b in listed] + sorted(listed - set(ordered))

    def frames(self, body: str) -> list[Frame]:
        """The particle files of ``body`` with their times, in the order of its ``.pvd``
        list (particles/<body>.pvd)."""
        pvd = self.out / "particles" / f"{body}.pvd"
        if not pvd.is_file():
            raise KeyError(f"no frames of a body {body!r} in {self.out} "
                           f"(bodies: {', '.join(self.bodies) or 'none'})")
        root = ET.parse(pvd).getroot()
        return [Frame(float(d.get("timestep", "nan")), pvd.parent / d.get("file", ""))
                for d in root.iter("DataSet")]

    def frame(self, body: str, k: int = -1) -> meshio.Mesh:
        """Frame ``k`` of ``body`` (negative counts from the last) as a meshio Mesh: the
        particles' current positions as points, one ``vertex`` cell each, their fields
        (``displacement``, ``velocity``, ``cauchy_stress``, ``sigma_vm``, ``J``,
        ``strain_energy``, a law's state, ...) as ``point_data``, and the time as
        ``field_data["TimeValue"]``."""
        return read_frame(self.frames(body)[k].path)


def read_frame(path: Union[str, "os.PathLike[str]"]) -> meshio.Mesh:
    """A particle file: a ``.vtu`` file, or a ``.pvtu`` file whose pieces (one per process)
    are joined into one Mesh, its particles in the order of their ``global_id`` (the same
    on any number of processes)."""
    path = Path(path)
    if path.suffix != ".pvtu":
        return _read_vtu(path)
    pieces = [_read_vtu(path.parent / piece.get("Source", ""))
              for piece in ET.parse(path).getroot().iter("Piece")]
    if not pieces:
        raise ValueError(f"{path} lists no pieces")
    points = np.concatenate([p.points for p in pieces])
    point_data = {name: np.concatenate([p.point_data[name] for p in pieces])
                  for name in pieces[0].point_data}
    if "global_id" in point_data:
        order = np.argsort(point_data["global_id"], kind="stable")
        points = points[order]
        point_data = {name: x[order] for name, x in point_data.items()}
    return _particles(points, point_data, pieces[0].field_data)


def _particles(points: np.ndarray, point_data: dict[str, np.ndarray],
               field_data: dict[str, np.ndarray]) -> meshio.Mesh:
    """A Mesh of particles: a ``vertex`` cell each."""
    cells = [("vertex", np.arange(len(points), dtype=np.int64).reshape(-1, 1))]
    return meshio.Mesh(points, cells, point_data=point_data, field_data=field_data)


_VTK_TYPES = {"Float64": "f8", "Float32": "f4", "Int64": "i8", "Int32": "i4", "UInt64": "u8",
              "UInt32": "u4", "UInt8": "u1", "Int8": "i1"}


def _read_vtu(path: Path) -> meshio.Mesh:
    """A ``.vtu`` file of particles as the runtime writes it (runtime/io/vtu.c): an XML
    header, then every array as a raw block in ``<AppendedData>`` (a byte count of the
    file's ``header_type``, then the values), at its DataArray's ``offset`` after the
    leading ``_``; one VTK_VERTEX cell per particle.  Other .vtu files go to meshio."""
    raw = path.read_bytes()
    at = raw.find(b'<AppendedData encoding="raw">')
    if at < 0 or b"compressor=" in raw[:at]:
        return meshio.read(path, file_format="vtu")
    data = raw.index(b"_", at) + 1
    root = ET.fromstring(raw[:at] + b"</VTKFile>")
    order = "<" if root.get("byte_order", "LittleEndian") == "LittleEndian" else ">"
    count = np.dtype(order + _VTK_TYPES[root.get("header_type", "UInt32")])

    def values(array: ET.Element) -> np.ndarray:
        dtype = np.dtype(order + _VTK_TYPES[array.get("type", "Float64")])
        if array.get("format") == "ascii":
            x = np.array((array.text or "").split(), dtype=dtype)
        else:
            start = data + int(array.get("offset", "0"))
            nbytes = int(np.frombuffer(raw, count, 1, start)[0])
            x = np.frombuffer(raw, dtype, nbytes // dtype.itemsize, start + count.itemsize)
        ncomp = int(array.get("NumberOfComponents", "1"))
        return (x.reshape(-1, ncomp) if ncomp > 1 else x).astype(dtype.newbyteorder("="))

    piece = root.find("UnstructuredGrid/Piece")
    types = piece.find("Cells/DataArray[@Name='types']") if piece is not None else None
    if piece is None or types is None or np.any(values(types) != 1):  # (not particles)
        return meshio.read(path, file_format="vtu")
    points = values(piece.find("Points/DataArray"))
    point_data = {a.get("Name", ""): values(a) for a in piece.iterfind("PointData/DataArray")}
    field_data = {a.get("Name", ""): values(a)
                  for a in root.iterfind("UnstructuredGrid/FieldData/DataArray")}
    return _particles(points, point_data, field_data)


def load(out: Union[str, "os.PathLike[str]"]) -> Results:
    """The outputs of a run in the folder ``out`` (what ``--out`` named; by default
    ``<model>_out``)."""
    return Results(out)
