"""Plots of an mpdem run's outputs: `mpdem plot OUTPUT_DIR` (docs/output.md, "Plots").

Writes PNGs into OUTPUT_DIR/plots/ and prints the path of each on stdout:

    log_energy.png          energies of log.csv against time
    log_heat.png            stored heat and heat losses (only with [analysis] thermal = true)
    log_contacts.png        contacts and particles against time
    log_inlets_sinks.png    inlet and sink columns of log.csv (only with [[inlet]] / [[sink]])
    log_step.png            time step, iterations and evaluations per step, redone steps
    barrier_groups.png      force, moment (torque, power) of every barrier group against time
                            (barrier_groups_2.png, ... for groups 9-16, 17-24, ...)
    <name>.png              one per profile CSV: profile*.csv and cg_*.csv in OUTPUT_DIR, and in its
                            subfolders (<folder>_<name>.png), with every CSV of coarse_grain*/ folders

Standalone: the standard library, numpy and matplotlib only (it does not import the mpdem package,
so it runs without the engine module). The mpdem binary carries this file's text and runs it as
`python3 -c SCRIPT -- OUTPUT_DIR`; `python3 plot.py OUTPUT_DIR` does the same.
Exit status: 0 done (CSVs that are missing or empty are skipped with a note on stderr),
1 a plot failed, 2 bad input (no such folder, no log.csv) or numpy/matplotlib missing.
"""

import argparse
import csv
import math
import os
import sys
import warnings

# Run as `python3 -c SCRIPT`: do not let files in the working folder shadow numpy or matplotlib.
if sys.argv and sys.argv[0] == "-c" and sys.path and sys.path[0] == "":
    del sys.path[0]

PLOTS_FOLDER = "plots"
GROUPS_PER_FIGURE = 8  # barrier groups per barrier_groups PNG (one row each)
MARKER_BELOW = 60  # series with fewer points than this get markers (a few logged rows)
DECIMATE_BUCKETS = 1500  # series longer than twice this are drawn as their min/max envelope

# log.csv columns (docs/output.md, "log.csv"), by panel: (column, legend label).
ENERGY_PANELS = [
    ("kinetic and stored energy", [("kinetic", "kinetic"), ("rotational", "rotational"),
                                   ("elastic", "elastic (contacts)"), ("near_field", "near field")]),
    ("potential energy, barrier work and total",
     [("potential", "potential (gravity + electric)"), ("barrier_work", "work of moving barriers"),
      ("total_energy", "total")]),
    ("energy dissipated so far", [("damping_dissipated", "damping"), ("friction_dissipated", "friction")]),
]
HEAT_COLUMNS = [("thermal_energy", "stored heat (sum m c T)"), ("heat_to_barriers", "lost to barriers"),
                ("heat_convected", "convected to the air"), ("heat_radiated", "radiated")]
INLET_SUFFIXES = (".inserted", ".inserted_mass", ".shortfall")
SINK_SUFFIXES = (".removed", ".removed_mass", ".mass_rate")

# Units of profile columns, guessed from their names (the first match wins; None: not guessed),
# after the fields of src/analysis/coarse_grain.hpp (CgFields): "temperature" there is the
# granular temperature. A name that carries its unit ("vx [m/s]") is left as it is.
PROFILE_UNITS = [
    (("flux", "rate", "gradient", "per_"), None),
    (("number_density",), "1/m^3"),
    (("force_density",), "N/m^3"),
    (("momentum",), "kg/(m^2 s)"),
    (("solid_fraction", "fraction", "porosity", "count", "number", "coordination"), "-"),
    (("temperature",), "m^2/s^2"),
    (("density", "rho"), "kg/m^3"),
    (("stress", "pressure", "sigma"), "Pa"),
    (("angular", "omega", "spin"), "rad/s"),
    (("velocity", "speed"), "m/s"),
    (("mass",), "kg"),
    (("position", "height", "depth", "distance", "radius"), "m"),
]
PROFILE_SHORT_UNITS = {"x": "m", "y": "m", "z": "m", "r": "m", "s": "m", "vx": "m/s", "vy": "m/s", "vz": "m/s",
                       "v": "m/s", "u": "m/s", "ux": "m/s", "uy": "m/s", "uz": "m/s", "wx": "rad/s", "wy": "rad/s",
                       "wz": "rad/s", "nu": "-"}


class BadInput(Exception):
    """Bad command-line input: message on stderr, exit status 2."""


def note(text):
    print(f"note: {text}", file=sys.stderr)


def import_plotting():
    """numpy and matplotlib (Agg backend, no display), or None with a message when missing."""
    try:
        import numpy
        import matplotlib
    except ImportError as e:
        print(f"error: mpdem plot needs numpy and matplotlib in {sys.executable} ({e}); install them "
              "(Debian: apt install python3-matplotlib) or pick another interpreter (mpdem plot --python PATH)",
              file=sys.stderr)
        return None
    matplotlib.use("Agg")
    import matplotlib.pyplot as pyplot
    return numpy, pyplot


# ---------------------------------------------------------------------------------------------
# Reading the CSVs


class Table:
    """A CSV's columns by name (float arrays); rows with the wrong field count are dropped."""

    def __init__(self, np, path):
        self.path = path
        self.names = []
        self.columns = {}
        self.dropped = 0
        with open(path, newline="") as f:
            header = next(csv.reader([f.readline()]), None)
            if not header:
                return
            self.names = [h.strip() for h in header]
            body = f.tell()
            data = self._fast(np, f)
            if data is None:  # the careful way: row by row
                f.seek(body)
                rows = []
                for row in csv.reader(f):
                    if not row:
                        continue
                    if len(row) != len(self.names):  # a cut last line (interrupted run), or damage
                        self.dropped += 1
                        continue
                    rows.append([_number(v) for v in row])
                data = np.array(rows, dtype=float).reshape(len(rows), len(self.names))
        for i, name in enumerate(self.names):
            if name not in self.columns:  # the first of duplicate names
                self.columns[name] = data[:, i]

    def _fast(self, np, f):
        """All rows at once (numpy's C reader) when every one is complete and numeric, else None."""
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")  # "input contained no data"
                data = np.loadtxt(f, delimiter=",", dtype=float, ndmin=2, comments=None)
        except (ValueError, IndexError):
            data = None
        if data is None or data.shape[0] == 0 or data.shape[1] != len(self.names):
            return None
        return data

    def __len__(self):
        return len(next(iter(self.columns.values()))) if self.columns else 0

    def has(self, name):
        return name in self.columns

    def __getitem__(self, name):
        return self.columns[name]


def _number(text):
    try:
        return float(text)
    except ValueError:
        return math.nan


def read_table(np, path, what):
    """The Table of `path`, or None (with a note) when it is missing or holds no data row."""
    if not os.path.isfile(path):
        note(f"{path}: not present ({what}), skipped")
        return None
    table = Table(np, path)
    if not table.names:
        note(f"{path}: empty, skipped")
        return None
    if len(table) == 0:
        note(f"{path}: no data rows, skipped")
        return None
    if table.dropped:
        note(f"{path}: {table.dropped} incomplete row(s) ignored")
    return table


# ---------------------------------------------------------------------------------------------
# Drawing


class Plotter:
    def __init__(self, np, plt, out_dir):
        self.np = np
        self.plt = plt
        self.out_dir = out_dir
        self.plots_dir = os.path.join(out_dir, PLOTS_FOLDER)
        self.written = []
        self.failed = 0
        self.stdout_closed = False
        self.title = os.path.basename(os.path.normpath(os.path.abspath(out_dir)))

    def figure(self, rows, cols=1, width=10.0, row_height=2.8, sharex=True):
        size = (max(width, 10.0), 1.0 + row_height * rows)
        try:  # constrained layout leaves room for the figure's title (matplotlib >= 3.5)
            return self.plt.subplots(rows, cols, figsize=size, sharex=sharex, squeeze=False, layout="constrained")
        except TypeError:
            return self.plt.subplots(rows, cols, figsize=size, sharex=sharex, squeeze=False, constrained_layout=True)

    def save(self, fig, name, suptitle):
        fig.suptitle(f"{suptitle}  ({self.title})")
        os.makedirs(self.plots_dir, exist_ok=True)
        path = os.path.join(self.plots_dir, name)
        tmp = f"{path}.tmp-{os.getpid()}"
        try:
            fig.savefig(tmp, dpi=110, format="png")
            os.replace(tmp, path)
        finally:
            self.plt.close(fig)
            if os.path.exists(tmp):
                os.remove(tmp)
        self.written.append(path)
        self.report(path)

    def report(self, path):
        if self.stdout_closed:
            return
        try:
            print(path, flush=True)
        except BrokenPipeError:  # stdout's reader is gone (`mpdem plot DIR | head -1`): go on drawing, quietly
            self.stdout_closed = True
            devnull = os.open(os.devnull, os.O_WRONLY)
            os.dup2(devnull, sys.stdout.fileno())
            os.close(devnull)

    def line(self, ax, x, y, label, **kw):
        if len(x) < MARKER_BELOW:
            kw.setdefault("marker", ".")
        x, y = self.decimate(x, y)
        ax.plot(x, y, label=label, **kw)

    def decimate(self, x, y):
        """Long series (millions of logged rows): the smallest and the largest value of each of
        DECIMATE_BUCKETS stretches, in order - the curve's envelope as drawn, at a fraction of the cost."""
        np = self.np
        n = len(y)
        if n <= 2 * DECIMATE_BUCKETS or not np.isfinite(y).all():
            return x, y
        k = n // DECIMATE_BUCKETS
        m = (n // k) * k
        blocks = y[:m].reshape(-1, k)
        base = np.arange(0, m, k)
        lo, hi = base + blocks.argmin(axis=1), base + blocks.argmax(axis=1)
        keep = np.concatenate([np.minimum(lo, hi), np.maximum(lo, hi), np.arange(m, n)])
        keep = np.unique(keep)  # sorted
        return x[keep], y[keep]

    @staticmethod
    def finish_axes(ax, ylabel, title=None, legend=True):
        ax.set_ylabel(ylabel)
        if title:
            ax.set_title(title, fontsize="medium")
        ax.grid(True, alpha=0.3)
        if legend and ax.get_legend_handles_labels()[0]:
            ax.legend(fontsize="small", loc="best")

    def attempt(self, what, fn, *args):
        """Runs one plot; a failure is reported and counted, the other plots go on."""
        try:
            fn(*args)
        except Exception as e:  # noqa: BLE001 - one broken file must not stop the other plots
            self.failed += 1
            print(f"error: {what}: {type(e).__name__}: {e}", file=sys.stderr)
            self.plt.close("all")


# ---------------------------------------------------------------------------------------------
# log.csv


def plot_log(p, log):
    t = log["time"] if log.has("time") else log["step"] if log.has("step") else p.np.arange(len(log), dtype=float)
    t_label = "time t (s)" if log.has("time") else "step" if log.has("step") else "row"
    p.attempt("log_energy.png", plot_log_energy, p, log, t, t_label)
    p.attempt("log_heat.png", plot_log_heat, p, log, t, t_label)
    p.attempt("log_contacts.png", plot_log_contacts, p, log, t, t_label)
    p.attempt("log_inlets_sinks.png", plot_log_inlets_sinks, p, log, t, t_label)
    p.attempt("log_step.png", plot_log_step, p, log, t, t_label)


def plot_log_energy(p, log, t, t_label):
    panels = []
    for title, cols in ENERGY_PANELS:
        present = [(c, label) for c, label in cols if log.has(c)]
        if present:
            panels.append((title, present))
    if not panels:
        note(f"{log.path}: no energy columns, log_energy.png skipped")
        return
    fig, axes = p.figure(len(panels))
    for ax, (title, cols) in zip(axes[:, 0], panels):
        for c, label in cols:
            p.line(ax, t, log[c], label, **({"color": "black", "linestyle": "--"} if c == "total_energy" else {}))
        if title == "energy dissipated so far" and len(cols) == 2:
            p.line(ax, t, log[cols[0][0]] + log[cols[1][0]], "damping + friction", color="black", linestyle="--")
        p.finish_axes(ax, "energy (J)", title)
    axes[-1, 0].set_xlabel(t_label)
    p.save(fig, "log_energy.png", "Energies (log.csv)")


def plot_log_heat(p, log, t, t_label):
    cols = [(c, label) for c, label in HEAT_COLUMNS if log.has(c)]
    if not cols:
        return  # no thermal analysis: nothing to say
    fig, axes = p.figure(2 if log.has("thermal_energy") and len(cols) > 1 else 1)
    ax_stored, ax_lost = axes[0, 0], axes[-1, 0]
    if log.has("thermal_energy"):
        stored = log["thermal_energy"]
        p.line(ax_stored, t, stored, "stored heat (sum m c T)")
        losses = [c for c, _ in cols if c != "thermal_energy"]
        if losses:
            p.line(ax_stored, t, stored + sum(log[c] for c in losses), "stored + lost (constant)", color="black",
                   linestyle="--")
        p.finish_axes(ax_stored, "heat (J)", "stored heat")
    lost = [(c, label) for c, label in cols if c != "thermal_energy"]
    if lost:
        for c, label in lost:
            p.line(ax_lost, t, log[c], label)
        p.finish_axes(ax_lost, "heat (J)", "heat lost so far")
    axes[-1, 0].set_xlabel(t_label)
    p.save(fig, "log_heat.png", "Heat (log.csv, thermal analysis)")


def plot_log_contacts(p, log, t, t_label):
    contacts = [(c, label) for c, label in [("contacts_pp", "particle-particle"), ("contacts_pb", "particle-barrier")]
                if log.has(c)]
    counts = [(c, label) for c, label in [("particles", "in the domain"), ("removed", "removed (left the domain)")]
              if log.has(c)]
    panels = [x for x in [("contacts", contacts), ("particles", counts)] if x[1]]
    if not panels:
        note(f"{log.path}: no contact or particle columns, log_contacts.png skipped")
        return
    fig, axes = p.figure(len(panels))
    for ax, (title, cols) in zip(axes[:, 0], panels):
        for c, label in cols:
            p.line(ax, t, log[c], label)
        p.finish_axes(ax, f"number of {title} (-)", f"number of {title}")
    axes[-1, 0].set_xlabel(t_label)
    p.save(fig, "log_contacts.png", "Contacts and particles (log.csv)")


def plot_log_inlets_sinks(p, log, t, t_label):
    def named(suffix):
        return [(n, n[: -len(suffix)]) for n in log.names if n.endswith(suffix) and len(n) > len(suffix)]

    inserted, inserted_mass, shortfall = (named(s) for s in INLET_SUFFIXES)
    removed, removed_mass, mass_rate = (named(s) for s in SINK_SUFFIXES)
    panels = []
    if inserted_mass or removed_mass:
        panels.append(("mass inserted by inlets / removed by sinks so far", "mass (kg)",
                       [(c, f"{n} inserted") for c, n in inserted_mass] + [(c, f"{n} removed") for c, n in removed_mass]))
    if inserted or removed:
        panels.append(("particles inserted / removed so far", "number of particles (-)",
                       [(c, f"{n} inserted") for c, n in inserted] + [(c, f"{n} removed") for c, n in removed]))
    if mass_rate:
        panels.append(("mass flow rate into the sinks (over each logging interval)", "mass flow rate (kg/s)",
                       [(c, n) for c, n in mass_rate]))
    if shortfall:
        panels.append(("inlet shortfall (due but no room in the region)", "shortfall (kg or particles)",
                       [(c, n) for c, n in shortfall]))
    if not panels:
        return  # no [[inlet]] or [[sink]]
    fig, axes = p.figure(len(panels))
    for ax, (title, ylabel, cols) in zip(axes[:, 0], panels):
        for c, label in cols:
            p.line(ax, t, log[c], label)
        p.finish_axes(ax, ylabel, title)
    axes[-1, 0].set_xlabel(t_label)
    p.save(fig, "log_inlets_sinks.png", "Inlets and sinks (log.csv)")


def plot_log_step(p, log, t, t_label):
    np = p.np
    panels = []
    if log.has("dt"):
        panels.append("dt")
    per_step = [(c, label) for c, label in [("iterations", "fixed-point iterations (trapezoidal)"),
                                             ("evaluations", "interaction evaluations")] if log.has(c)]
    # Verlet logs iterations = 0: leave that column out then.
    per_step = [(c, label) for c, label in per_step if c != "iterations" or np.nanmax(log[c]) > 0]
    if per_step:
        panels.append("per_step")
    if log.has("redone_steps") and np.nanmax(log["redone_steps"]) > 0:
        panels.append("redone")
    if not panels:
        note(f"{log.path}: no dt, iterations or evaluations columns, log_step.png skipped")
        return
    fig, axes = p.figure(len(panels))
    for ax, what in zip(axes[:, 0], panels):
        if what == "dt":
            dt = log["dt"]
            p.line(ax, t, dt, "dt")
            finite = dt[np.isfinite(dt) & (dt > 0)]
            title = "time step (of the logged steps)"
            if len(finite) and finite.max() > 20 * finite.min():
                ax.set_yscale("log")
            elif len(finite) and finite.max() - finite.min() <= 1e-9 * finite.max():
                # constant up to the round-off of t + dt: no ticks in the 16th digit
                ax.set_ylim(0, 1.25 * finite.max())
                title = f"time step (constant: {finite.max():.6g} s)"
            p.finish_axes(ax, "time step dt (s)", title, legend=False)
        elif what == "per_step":
            for c, label in per_step:
                p.line(ax, t, log[c], label)
            p.finish_axes(ax, "per step (-)", "iterations and evaluations (of the logged steps)")
        else:
            p.line(ax, t, log["redone_steps"], "redone steps")
            p.finish_axes(ax, "steps redone so far (-)", "steps rejected and redone with a smaller dt",
                          legend=False)
    axes[-1, 0].set_xlabel(t_label)
    p.save(fig, "log_step.png", "Time step (log.csv)")


# ---------------------------------------------------------------------------------------------
# barrier_groups.csv


def plot_barrier_groups(p, table):
    np = p.np
    if not table.has("time"):
        note(f"{table.path}: no 'time' column, skipped")
        return
    t = table["time"]
    groups = []  # in column order
    for name in table.names[1:]:
        if "." in name:
            g = name.rsplit(".", 1)[0]
            if g not in groups:
                groups.append(g)
    if not groups:
        note(f"{table.path}: no group columns, skipped")
        return
    chunks = [groups[i:i + GROUPS_PER_FIGURE] for i in range(0, len(groups), GROUPS_PER_FIGURE)]
    for k, chunk in enumerate(chunks):
        name = "barrier_groups.png" if k == 0 else f"barrier_groups_{k + 1}.png"
        p.attempt(name, plot_barrier_group_chunk, p, np, table, t, chunk, name, k, len(chunks))


def plot_barrier_group_chunk(p, np, table, t, groups, name, k, n_chunks):
    def col(g, c):
        key = f"{g}.{c}"
        return table[key] if table.has(key) else None

    # Panels per row: force, moment, and the drive's torque and power when some group has them.
    has_torque = any(col(g, "torque") is not None for g in groups)
    has_power = any(col(g, "power") is not None for g in groups)
    ncols = 2 + has_torque + has_power
    fig, axes = p.figure(len(groups), ncols, width=4.2 * ncols, row_height=2.6)
    for row, g in enumerate(groups):
        area = col(g, "area")
        area_text = ""
        if area is not None and np.isfinite(area).any():
            lo, hi = np.nanmin(area), np.nanmax(area)
            area_text = f", area {hi:.4g} m^2" if lo == hi else f", area {lo:.4g} .. {hi:.4g} m^2"
        ax = axes[row, 0]
        comps = [(c, col(g, c)) for c in ("fx", "fy", "fz")]
        for c, y in comps:
            if y is not None:
                p.line(ax, t, y, f"F{c[1]}")
        if all(y is not None for _, y in comps):
            p.line(ax, t, np.sqrt(sum(y * y for _, y in comps)), "|F|", color="black", linestyle="--")
        p.finish_axes(ax, "force (N)", f"'{g}': force of the particles{area_text}")
        ax = axes[row, 1]
        for c in ("mx", "my", "mz"):
            y = col(g, c)
            if y is not None:
                p.line(ax, t, y, f"M{c[1]}")
        p.finish_axes(ax, "moment (N m)", f"'{g}': moment about the origin")
        c_idx = 2
        for shown, column, color, unit, title in (
                (has_torque, "torque", "tab:purple", "torque (N m)", "torque about its rotation axis"),
                (has_power, "power", "tab:red", "power (W)", "power put into the particles")):
            if not shown:
                continue
            ax = axes[row, c_idx]
            y = col(g, column)
            if y is not None:
                p.line(ax, t, y, column, color=color)
                p.finish_axes(ax, unit, f"'{g}': {title}", legend=False)
            else:
                ax.set_axis_off()
            c_idx += 1
    for c in range(ncols):
        axes[-1, c].set_xlabel("time t (s)")
        axes[-1, c].xaxis.set_tick_params(labelbottom=True)
    part = f", part {k + 1} of {n_chunks}" if n_chunks > 1 else ""
    p.save(fig, name, f"Loads on the barrier groups (barrier_groups.csv{part})")


# ---------------------------------------------------------------------------------------------
# Profiles (coarse-grained fields along an axis)


def profile_files(out_dir):
    """(path, png name) of every profile CSV: profile*.csv and cg_*.csv in the folder and its
    subfolders (one level), and every CSV in a coarse_grain* subfolder."""
    found = []

    def is_profile(name):
        low = name.lower()
        return low.endswith(".csv") and (low.startswith("profile") or low.startswith("cg_"))

    for entry in sorted(os.listdir(out_dir)):
        path = os.path.join(out_dir, entry)
        if os.path.isfile(path) and is_profile(entry):
            found.append((path, os.path.splitext(entry)[0] + ".png"))
        elif os.path.isdir(path) and entry != PLOTS_FOLDER and not entry.startswith("particles"):
            cg_folder = entry.lower().startswith("coarse_grain")
            for sub in sorted(os.listdir(path)):
                sub_path = os.path.join(path, sub)
                if os.path.isfile(sub_path) and (is_profile(sub) or (cg_folder and sub.lower().endswith(".csv"))):
                    found.append((sub_path, f"{entry}_{os.path.splitext(sub)[0]}.png"))
    return found


def profile_unit(name):
    low = name.lower().strip()
    if "[" in low or "(" in low:
        return None  # the name carries its unit
    if low in PROFILE_SHORT_UNITS:
        return PROFILE_SHORT_UNITS[low]
    for keys, unit in PROFILE_UNITS:
        if any(k in low for k in keys):
            return unit
    return None


def with_unit(name):
    unit = profile_unit(name)
    return f"{name} ({unit})" if unit else name


def plot_profile(p, table, png):
    np = p.np
    names = [n for n in table.names if n != "time"]
    if len(names) < 2:
        note(f"{table.path}: needs a position column and at least one more, skipped")
        return
    rows = np.ones(len(table), dtype=bool)
    when = ""
    if table.has("time"):
        times = table["time"]
        finite = times[np.isfinite(times)]
        if len(finite):
            last = finite.max()
            rows = times == last
            when = f" at t = {last:.6g} s" + (" (the last of several times)" if len(np.unique(finite)) > 1 else "")
    pos_name = names[0]
    x = table[pos_name][rows]
    order = np.argsort(x, kind="stable")
    x = x[order]
    fields = [n for n in names[1:] if np.isfinite(table[n][rows]).any()]
    if not fields:
        note(f"{table.path}: no numeric values besides '{pos_name}', skipped")
        return
    ncols = 1 if len(fields) == 1 else 2 if len(fields) <= 4 else 3
    nrows = math.ceil(len(fields) / ncols)
    fig, axes = p.figure(nrows, ncols, width=4.6 * ncols, row_height=2.8, sharex=False)
    for i, name in enumerate(fields):
        ax = axes[i // ncols, i % ncols]
        p.line(ax, x, table[name][rows][order], name)
        p.finish_axes(ax, with_unit(name), name, legend=False)
        ax.set_xlabel(f"position along the axis: {with_unit(pos_name) if profile_unit(pos_name) else pos_name + ' (m)'}")
    for j in range(len(fields), nrows * ncols):
        axes[j // ncols, j % ncols].set_axis_off()
    rel = os.path.relpath(table.path, p.out_dir)
    p.save(fig, png, f"Profile {rel}{when}")


# ---------------------------------------------------------------------------------------------


def main(argv):
    parser = argparse.ArgumentParser(
        prog="mpdem plot",
        description="Plot an mpdem run's outputs (log.csv, barrier_groups.csv, profile CSVs) into OUTPUT_DIR/plots/ "
        "as PNGs; prints the path of each.")
    parser.add_argument("output_dir", metavar="OUTPUT_DIR", help="the run's output folder")
    args = parser.parse_args(argv)
    out_dir = args.output_dir
    try:
        if not os.path.isdir(out_dir):
            raise BadInput(f"{out_dir}: no such folder" if not os.path.exists(out_dir) else f"{out_dir}: not a folder")
        if not os.path.isfile(os.path.join(out_dir, "log.csv")):
            raise BadInput(f"{out_dir}: no log.csv (not an mpdem output folder?)")
    except BadInput as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    plotting = import_plotting()
    if plotting is None:
        return 2
    np, plt = plotting
    plt.rcParams.update({"axes.formatter.useoffset": False, "axes.formatter.limits": (-3, 4)})
    p = Plotter(np, plt, out_dir)
    try:
        log = read_table(np, os.path.join(out_dir, "log.csv"), "no log")
        if log is not None:
            plot_log(p, log)
        groups = read_table(np, os.path.join(out_dir, "barrier_groups.csv"),
                            "a scene without barriers, or barrier_log_every = 0")
        if groups is not None:
            plot_barrier_groups(p, groups)
        for path, png in profile_files(out_dir):
            table = read_table(np, path, "profile")
            if table is not None:
                p.attempt(png, plot_profile, p, table, png)
    except OSError as e:
        print(f"error: {e}", file=sys.stderr)
        return 1
    if p.failed:
        print(f"error: {p.failed} plot(s) failed; {len(p.written)} written", file=sys.stderr)
        return 1
    if not p.written:
        note(f"{out_dir}: nothing to plot")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
