"""Scenes and output files: run a namelist scene as the command line does, read any
output file (text or binary) into numpy arrays by column name with the effective scene
of its header, and the nonlinear pendulum's `series` as arrays.
"""
import math
import os
import re
import tempfile

import numpy as np

from . import _capi
from ._capi import lib, check

_OFFSET = re.compile(r"offset=\s*(\d+)")


def _group(header, name):
    """The header's namelist line of group `name` (``&chart ... /``), or None."""
    for line in header:
        text = line.strip()
        if re.match(r"&{}\b".format(name), text, re.I):
            return text
    return None


def _variable(group, name, kind=str):
    """A variable of a namelist line: a quoted string, or a number converted by `kind`; None
    when absent."""
    if group is None:
        return None
    match = re.search(r"(?:^|[\s,&])" + name + r"\s*=\s*('(?:[^']|'')*'|[^,/\s]+)", group, re.I)
    if not match:
        return None
    value = match.group(1)
    if value.startswith("'"):
        return value[1:-1].replace("''", "'")
    return kind(value)


def grid_values(first, last, count, scale="linear"):
    """The values of a grid axis as the library computes them (``grid_value``): first, then
    first + (last − first) i/(count − 1), the last exactly `last`; with ``scale="log"``
    (``&chart alpha_scale = 'log'``) geometric, 10 to the power log10(first) + (log10(last) −
    log10(first)) i/(count − 1), both ends exact."""
    geometric = str(scale).strip().lower() == "log"
    values = np.empty(count)
    for i in range(count):
        if count <= 1:
            values[i] = first
        elif i == count - 1:
            values[i] = last
        elif geometric and i == 0:
            values[i] = first
        elif geometric:
            low, high = math.log10(first), math.log10(last)
            values[i] = math.pow(10.0, low + (high - low) * float(i) / float(count - 1))
        else:
            values[i] = first + (last - first) * float(i) / float(count - 1)
    return values


class Output:
    """An output file of hillstab: its columns by name (``out["beta"]``, ``out.column("S")``,
    ``out.columns``), the data as a 2-D array (``out.data``, one row a point), the header
    lines (``out.header``, without ``#``) and the effective scene they repeat (``out.scene``,
    namelist text: write it to a file and run it to repeat the run).

    A chart (task ``chart``, or ``lyapunov`` over a chart) is a grid as well: ``out.grid("S")``
    is a column as a 2-D array ``[i_alpha, i_beta]`` and ``out.axes`` the coordinate vectors
    (alpha, beta) — the shape of `chart`'s and `System.chart`'s results; a chart of a spring
    in SI units (``&physical``) has the axes (a, omega). ``out.is_grid``, ``out.grid_shape``,
    ``out.axis_names`` and ``out.axis_scales`` (``"log"`` for ``&chart alpha_scale = 'log'``)
    tell. ``out.to_pandas()`` gives a long table (pandas needed)."""

    def __init__(self, path, header, columns, data):
        #: the file
        self.path = path
        #: its header lines, without the leading "# "
        self.header = header
        #: the column names of its "# columns:" line
        self.columns = columns
        #: its numbers, one row a point (a 2-D array, columns in file order)
        self.data = data
        self._grid = self._find_grid()

    def _find_grid(self):
        """(axis names, counts, ends) of a chart's grid from the header's scene, or None."""
        scene = _group(self.header, "scene")
        task = (_variable(scene, "task") or "").lower()
        over = (_variable(_group(self.header, "lyapunov"), "over") or "").lower()
        if not (task == "chart" or (task == "lyapunov" and over == "chart")):
            return None
        chart = _group(self.header, "chart")
        physical = _group(self.header, "physical")
        if chart is not None and _variable(chart, "n_alpha", int) is not None:
            names, group = ("alpha", "beta"), chart
            equation = _group(self.header, "equation") or _group(self.header, "equations")
            if equation is not None and _variable(equation, "alpha") and _variable(equation, "beta"):
                # an equation's axes are its parameters, and the columns are named after them
                names = (_variable(equation, "alpha"), _variable(equation, "beta"))
            keys = ("alpha_min", "alpha_max", "n_alpha", "beta_min", "beta_max", "n_beta")
        elif physical is not None and _variable(physical, "n_a", int) is not None:
            names, group = ("a", "omega"), physical
            keys = ("a_min", "a_max", "n_a", "omega_min", "omega_max", "n_omega")
        else:
            return None
        values = [_variable(group, key, int if key.startswith("n_") else float) for key in keys]
        if any(v is None for v in values):
            return None
        first0, last0, count0, first1, last1, count1 = values
        # a log axis is named in the header (&chart alpha_scale = 'log'); linear is not
        scales = tuple((_variable(group, key) or "linear").lower() if group is chart else "linear"
                       for key in ("alpha_scale", "beta_scale"))
        return names, (count0, count1), ((first0, last0), (first1, last1)), scales

    @property
    def is_grid(self):
        """True for a chart: the rows are the points of a grid, first axis outer."""
        return self._grid is not None

    @property
    def grid_shape(self):
        """(n_alpha, n_beta) of a chart (n_a, n_omega with ``&physical``), else None."""
        return self._grid[1] if self._grid else None

    @property
    def axis_names(self):
        """("alpha", "beta") of a chart (("a", "omega") with ``&physical``; an equation's two
        parameters, as its columns are named), else None."""
        return self._grid[0] if self._grid else None

    def _check_grid(self):
        if self._grid is None:
            raise ValueError("{}: not a chart (no grid in its header: task {})".format(
                self.path, _variable(_group(self.header, "scene"), "task")))
        rows = self.data.shape[0]
        n0, n1 = self._grid[1]
        if rows != n0 * n1:
            raise ValueError("{}: {} rows, not the {} x {} points of its grid (a file cut short?)".format(
                self.path, rows, n0, n1))

    @property
    def axes(self):
        """The coordinate vectors of a chart's grid, (alpha, beta) (or (a, omega)): from the
        file's columns when it has them, else computed from the header's grid as the library
        computes them. ValueError for a file that is not a chart."""
        self._check_grid()
        names, (n0, n1), ends, scales = self._grid
        result = []
        for k, name in enumerate(names):
            if name in self.columns:
                column = self.column(name)
                result.append((column[::n1] if k == 0 else column[:n1]).copy())
            else:
                result.append(grid_values(ends[k][0], ends[k][1], (n0, n1)[k], scales[k]))
        return tuple(result)

    @property
    def axis_scales(self):
        """("linear", "linear") of a chart, "log" for an axis of geometric values (``&chart
        alpha_scale = 'log'``: plot it with ``set_xscale("log")``), else None."""
        return self._grid[3] if self._grid else None

    def grid(self, name):
        """The column `name` of a chart as a 2-D array [i_alpha, i_beta] (the shape of
        `chart`'s results; a copy). ValueError for a file that is not a chart, KeyError for
        a column it does not have."""
        self._check_grid()
        return self.column(name).reshape(self._grid[1]).copy()

    def to_pandas(self):
        """The file as a pandas DataFrame, one row a point and one column a column of the
        file (a long table; pandas is not a requirement of hillstab: ImportError without it)."""
        try:
            import pandas
        except ImportError:
            raise ImportError("Output.to_pandas needs pandas (pip install pandas)") from None
        return pandas.DataFrame(self.data, columns=list(self.columns))

    def __repr__(self):
        shape = " (grid {} x {})".format(*self._grid[1]) if self._grid else ""
        return "<hillstab output {}: {} rows{}, columns {}>".format(self.path, self.data.shape[0], shape,
                                                                     " ".join(self.columns))

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


def read_output(path):
    """Read an output file of hillstab (text or ``format = 'binary'``) into an `Output`:
    columns by name as flat arrays (one entry a row of the file), and for a chart the same
    as 2-D arrays ``[i_alpha, i_beta]`` with the axes (``grid``, ``axes``).

    >>> out = read_output("out/default_exact_chart.dat")
    >>> out["S"], out.scene
    >>> out.grid("S").shape, out.axes        # (600, 600), (alpha, beta)
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
