"""Scenes and output files: run a namelist scene as the command line does, read any
output file (text or binary) into numpy arrays by column name with the effective scene
of its header, and the nonlinear pendulum's `series` as arrays.
"""
import os
import re
import tempfile

import numpy as np

from . import _capi
from ._capi import lib, check

_OFFSET = re.compile(r"offset=\s*(\d+)")


class Output:
    """An output file of hillstab: its columns by name (``out["beta"]``, ``out.column("S")``,
    ``out.columns``), the data as a 2-D array (``out.data``, one row a point), the header
    lines (``out.header``, without ``#``) and the effective scene they repeat (``out.scene``,
    namelist text: write it to a file and run it to repeat the run)."""

    def __init__(self, path, header, columns, data):
        #: the file
        self.path = path
        #: its header lines, without the leading "# "
        self.header = header
        #: the column names of its "# columns:" line
        self.columns = columns
        #: its numbers, one row a point (a 2-D array, columns in file order)
        self.data = data

    @property
    def scene(self):
        """The effective scene of the header: its namelist groups, one a line."""
        lines, inside = [], False
        for line in self.header:
            text = line.strip()
            if text.startswith("&"):
                inside = True
            if inside:
                lines.append(text)
                if text.endswith("/"):
                    inside = False
        return "\n".join(lines) + "\n"

    def column(self, name):
        """The column called `name` (KeyError listing the columns when there is none)."""
        if name not in self.columns:
            raise KeyError("{}: no column '{}' (columns: {})".format(self.path, name, " ".join(self.columns)))
        return self.data[:, self.columns.index(name)]

    def __getitem__(self, name):
        return self.column(name)

    def __contains__(self, name):
        return name in self.columns

    def __repr__(self):
        return "<hillstab output {}: {} rows, columns {}>".format(self.path, self.data.shape[0], " ".join(self.columns))


def read_output(path):
    """Read an output file of hillstab (text or ``format = 'binary'``) into an `Output`.

    >>> out = read_output("out/default_chart.dat")
    >>> out["S"], out.scene
    """
    with open(path, "rb") as handle:
        raw = handle.read()
    header, columns, offset = [], None, None
    position = 0
    while position < len(raw) and raw[position:position + 1] == b"#":
        end = raw.find(b"\n", position)
        end = len(raw) if end < 0 else end
        line = raw[position:end].decode("utf-8", "replace")
        position = end + 1
        text = line[1:].strip() if len(line) > 1 and line[1] != " " else line[2:]
        header.append(text)
        if text.startswith("columns:"):
            columns = text[len("columns:"):].split()
        match = _OFFSET.search(text) if text.startswith("numpy:") else None
        if match:
            offset = int(match.group(1))
    if columns is None:
        raise ValueError("{}: no '# columns:' line: not an output file of hillstab".format(path))
    if offset is not None:
        data = np.frombuffer(raw, dtype="<f8", offset=offset).reshape(-1, len(columns)).copy()
    else:
        rows = []
        for line in raw[position:].decode("utf-8", "replace").splitlines():
            fields = line.split()
            if not fields or fields[0].startswith("#"):
                continue
            if fields == columns:
                continue  # names_line = .true.
            rows.append([float(x) for x in fields])
        data = np.array(rows, dtype=np.float64).reshape(-1, len(columns))
    return Output(path, header, columns, data)


def run_scene(path, quiet=True):
    """Run the namelist scene file `path` as ``hillstab path`` does and read its output:
    returns the `Output` of the file written (relative output paths are taken from the
    current directory). Bad input raises ValueError with the library's message naming the
    file, the group and the variable (nothing written); a file written with failed points
    raises PointsFailedError, whose ``path`` is that file."""
    written = _run(path, quiet)
    return read_output(written)


def _run(path, quiet):
    buffer = _capi.ctypes.create_string_buffer(8192)
    status = lib.hillstab_run_scene(os.fsencode(path), 1 if quiet else 0, buffer, len(buffer))
    written = buffer.value.decode("utf-8", "replace") or None
    check(status, path=written)
    return written


def namelist_value(value):
    """A Python value as namelist text: strings quoted, booleans .true./.false., numbers
    in their shortest exact form, sequences as comma lists."""
    if isinstance(value, str):
        return "'" + value.replace("'", "''") + "'"
    if isinstance(value, (bool, np.bool_)):
        return ".true." if value else ".false."
    if isinstance(value, (int, np.integer)):
        return str(int(value))
    if np.ndim(value) > 0:
        return ", ".join(namelist_value(v) for v in np.asarray(value).ravel().tolist())
    return repr(float(value))


def scene_text(groups):
    """Namelist text of groups given as {group: {variable: value}} (None values left out)."""
    lines = []
    for group, variables in groups.items():
        items = ", ".join("{} = {}".format(name, namelist_value(value))
                          for name, value in variables.items() if value is not None)
        lines.append("&{} {} /".format(group, items))
    return "\n".join(lines) + "\n"


def run_groups(groups, quiet=True):
    """Run a scene given as groups (`scene_text`) in a temporary directory; its `Output`."""
    with tempfile.TemporaryDirectory(prefix="hillstab_") as directory:
        groups = {name: dict(variables) for name, variables in groups.items()}
        groups["scene"]["output"] = os.path.join(directory, "run")
        path = os.path.join(directory, "scene.nml")
        with open(path, "w") as handle:
            handle.write(scene_text(groups))
        return run_scene(path, quiet)


class Series:
    """The nonlinear pendulum over time: arrays ``t`` (s), ``r`` (m), ``phi`` (rad), ``x``,
    ``z`` (m), ``energy`` (J/kg), ``vx``, ``vz`` (m/s), and the `Output` (``output``: its
    header reports max |φ|, the energy drift and the onset of the swing)."""

    def __init__(self, output):
        #: the file as read (header, scene, columns)
        self.output = output
        self.t = output["t"]
        self.r = output["r"]
        self.phi = output["phi"]
        self.x = output["x"]
        self.z = output["z"]
        self.energy = output["E"]
        self.vx = output["vx"]
        self.vz = output["vz"]

    def __repr__(self):
        return "<hillstab series: {} samples over {} s>".format(self.t.size, self.t[-1] if self.t.size else 0)


def series(alpha, beta, phi0=0.017, periods=50, duration=None, samples_per_period=100, r0=0.1, g=9.81,
           vx0=0.0, vz0=0.0, epsilon=0.0, tolerance=1e-10, model="elastic", quiet=True):
    """The nonlinear elastic pendulum of eq. (38) at (α, β) from φ(0) = phi0 (rad), as task
    ``series`` computes it (DOP853 to the relative tolerance, samples from its dense output
    at t = j T / samples_per_period over `periods` radial periods, or up to `duration`
    seconds). Returns a `Series` of arrays (t, r, phi, x, z, energy, vx, vz).

    >>> s = series(7.88, 3.95, phi0=0.017, periods=50)     # the paper's Fig. 4 (e)
    >>> abs(s.phi).max()
    """
    name = model if isinstance(model, str) else model.name
    scene = {"task": "series", "model": name, "tolerance": tolerance, "epsilon": epsilon}
    group = {"alpha": alpha, "beta": beta, "phi0": phi0, "samples_per_period": samples_per_period, "r0": r0,
             "g": g, "vx0": vx0, "vz0": vz0}
    if duration is None:
        group["periods"] = periods
    else:
        group["duration"] = duration
    return Series(run_groups({"scene": scene, "series": group}, quiet))
