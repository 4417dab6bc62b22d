#!/usr/bin/python3
"""Plots a body's wash-out from washout run files: the centre of mass's horizontal (x) and
vertical position and the rotation angle against time, with the fluid force below, one column
per run (several runs side by side: e.g. the three water heights of scripts/washout_heights.sh).

    python3 scripts/plot_washout.py runs/girder_washout                  # -> runs/girder_washout/girder_washout.png
    python3 scripts/plot_washout.py RUN1 RUN2 RUN3 --out heights.png     # side by side

A RUN is a run file (.h5) or the folder `washout run --out` wrote it into. The series is
/bodies/NAME (docs/output.md); the wave arrival and the time the body leaves its support are
the attributes the run stored there (docs/output.md, "Body reports") and are drawn as dashed
and dotted lines. Needs h5py, numpy and matplotlib (Debian: python3-h5py python3-matplotlib).
"""
import argparse
import json
import math
import os
import sys

import h5py
import matplotlib

matplotlib.use("Agg")  # no display needed
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def find_run_file(path):
    if os.path.isdir(path):
        files = sorted(f for f in os.listdir(path) if f.endswith(".h5"))
        if not files:
            sys.exit(f"plot_washout: no .h5 run file in {path}")
        if len(files) > 1:
            sys.exit(f"plot_washout: several .h5 files in {path}: name one of {files}")
        return os.path.join(path, files[0])
    if not os.path.isfile(path):
        sys.exit(f"plot_washout: no such run file or folder: {path}")
    return path


def load(path, body):
    """The body's series and summary, and a label for the run."""
    with h5py.File(path, "r") as f:
        group = f"/bodies/{body}"
        if group not in f:
            names = list(f["/bodies"].keys()) if "/bodies" in f else []
            sys.exit(f"plot_washout: {path} has no body '{body}' (bodies: {names or 'none'})")
        g = f[group]
        if "time" not in g:
            sys.exit(f"plot_washout: {path}: body '{body}' has no rows (the run stopped at once)")
        dim = int(np.asarray(f.attrs["dim"]).ravel()[0])
        params = {}
        if "parameters" in f.attrs:
            text = f.attrs["parameters"]
            params = json.loads(text.decode() if isinstance(text, bytes) else text)
        run = {
            "dim": dim,
            "time": g["time"][:],
            "position": g["position"][:],
            "angle": g["angle"][:],
            "force_fluid": g["force_fluid"][:],
            "attrs": {k: np.asarray(v) for k, v in g.attrs.items()},
            "params": params,
        }
    label = os.path.basename(os.path.dirname(os.path.abspath(path))) or os.path.basename(path)
    height = run["params"].get("water_height")
    if height is not None:
        label = f"water height {float(height) * 1000:.0f} mm"
    d0 = run["params"].get("d0")
    if d0 is not None:
        label += f", d0 = {float(d0) * 1000:g} mm"
    run["label"] = label
    return run


def scalar(run, name):
    v = run["attrs"].get(name)
    if v is None or v.size == 0:
        return math.nan
    return float(v.ravel()[0])


def plot(runs, out, body):
    n = len(runs)
    fig, axes = plt.subplots(4, n, figsize=(4.6 * n + 0.6, 10), sharex="col", sharey="row",
                             squeeze=False)
    for c, run in enumerate(runs):
        t = run["time"]
        up = 1 if run["dim"] == 2 else 2
        x0 = run["position"][0]
        vertical = "y" if run["dim"] == 2 else "z"
        unit = "N/m" if run["dim"] == 2 else "N"
        ax = axes[:, c]
        ax[0].plot(t, run["position"][:, 0] - x0[0], color="C0")
        ax[1].plot(t, run["position"][:, up] - x0[up], color="C1")
        ax[2].plot(t, np.degrees(run["angle"] - run["angle"][0]), color="C2")
        ax[3].plot(t, run["force_fluid"][:, 0], color="C0", label="horizontal (x)")
        ax[3].plot(t, run["force_fluid"][:, up], color="C1", label=f"vertical ({vertical})")
        arrival, leave = scalar(run, "arrival_time"), scalar(run, "leave_time")
        for a in ax:
            if not math.isnan(arrival):
                a.axvline(arrival, color="0.4", ls="--", lw=0.8)
            if not math.isnan(leave):
                a.axvline(leave, color="0.4", ls=":", lw=1.0)
            a.grid(alpha=0.3)
        title = run["label"]
        lines = []
        if not math.isnan(arrival):
            lines.append(f"wave {arrival:.3f} s")
        if not math.isnan(leave):
            lines.append(f"off the pier {leave:.3f} s")
        if lines:
            title += "\n" + ", ".join(lines)
        ax[0].set_title(title, fontsize=10)
        ax[3].set_xlabel("time [s]")
        if c == 0:
            ax[0].set_ylabel("x displacement [m]")
            ax[1].set_ylabel(f"{vertical} displacement [m]")
            ax[2].set_ylabel("rotation [deg]")
            ax[3].set_ylabel(f"fluid force [{unit}]")
            ax[3].legend(fontsize=8, loc="upper right")
    fig.suptitle(f"{body}: centre of mass and rotation (dashed: wave arrives; dotted: leaves "
                 "the pier)", fontsize=11)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print(f"plot_washout: wrote {out}")


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("runs", nargs="+", help="run files (.h5) or the folders holding them")
    p.add_argument("--out", help="PNG to write (default: beside the first run file, "
                   "<run name>.png)")
    p.add_argument("--body", default="girder", help="body name (default: girder)")
    args = p.parse_args()
    files = [find_run_file(r) for r in args.runs]
    runs = [load(f, args.body) for f in files]
    out = args.out or os.path.splitext(files[0])[0] + ".png"
    plot(runs, out, args.body)


if __name__ == "__main__":
    main()
