"""The stability suite's report (scripts/stability.sh): one table per sweep and the stability map.

usage: /usr/bin/python3 scripts/stability_report.py OUT --report FILE.md [--mode quick|full]

OUT holds sweeps.txt (name, scene, what, tab-separated) and one `washout study` folder per sweep.
For every run: its status, the guard that stopped it (from its log), the wall time, and from its
HDF5 file the largest fluid speed in the last frame and the kinetic energy's growth over the
second half of the run (for the runs at rest: no drift, no spurious velocity, no energy gain).
The map (FILE with _map.png) shows stable and stopped points in the planes
(dt / dt_default, alpha), (E, eps) and (density ratio, d0).
"""
import argparse
import csv
import glob
import os
import re
import sys

import numpy as np

try:
    import h5py
except ImportError:  # the table still gets written, without the run-file figures
    h5py = None


def guard_message(log_path):
    """The line that says why the run stopped, or ''."""
    if not os.path.exists(log_path):
        return ""
    for line in open(log_path, errors="replace"):
        if "unstable at t =" in line or line.startswith("error:"):
            return line.strip()
    return ""


def run_figures(run_dir):
    """Largest fluid speed in the last frame, kinetic energy last / peak over the second half."""
    files = glob.glob(os.path.join(run_dir, "*.h5"))
    if not files or h5py is None:
        return None
    try:
        with h5py.File(files[0], "r") as f:
            frames = [f["frames"][k] for k in sorted(f["frames"])]
            times, energy, last_speed = [], [], 0.0
            for g in frames:
                fluid = g["kind"][()] == 0
                v = g["velocity"][()][fluid]
                s2 = (v ** 2).sum(axis=1)
                times.append(float(g.attrs["time"]))
                energy.append(0.5 * s2.sum())
                last_speed = float(np.sqrt(s2.max())) if len(s2) else 0.0
            times, energy = np.array(times), np.array(energy)
            half = times >= 0.5 * times[-1]
            growth = float(energy[-1] / max(energy[half].max(), 1e-300)) if half.any() else np.nan
            return {"end_time": times[-1], "last_speed": last_speed, "ke_last_over_peak": growth}
    except (OSError, KeyError, ValueError) as e:
        return {"error": str(e)}


def read_sweep(out, name):
    rows = []
    path = os.path.join(out, name, "study.csv")
    if not os.path.exists(path):
        return rows
    with open(path) as f:
        for k, row in enumerate(csv.DictReader(f)):
            run_dir = os.path.join(out, name, "run_%02d" % (k + 1))
            row["guard"] = guard_message(os.path.join(run_dir, "run.log"))
            row["figures"] = run_figures(run_dir)
            rows.append(row)
    return rows


FIXED = {"status", "exit_code", "particles", "fluid_particles", "steps", "wall_seconds_min",
         "wall_seconds_median", "repeats", "peak_rss_bytes", "ppe_iterations_per_step", "error",
         "error_bound", "error_name", "error_metric", "guard", "figures"}


def varied(row):
    return [k for k in row if k not in FIXED and not k.startswith("error")]


def table(rows):
    keys = varied(rows[0])
    head = keys + ["status", "particles", "steps", "wall [s]", "end t [s]", "last max |u| [m/s]",
                   "KE last / peak (2nd half)", "why it stopped"]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for r in rows:
        fig = r["figures"] or {}
        cells = [r[k] for k in keys] + [
            r["status"], r["particles"], r["steps"], "%.1f" % float(r["wall_seconds_min"] or 0),
            "%.3g" % fig["end_time"] if "end_time" in fig else "",
            "%.3g" % fig["last_speed"] if "last_speed" in fig else "",
            "%.2f" % fig["ke_last_over_peak"] if "ke_last_over_peak" in fig else "",
            re.sub(r"\|", "/", r["guard"])[:160]]
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines)


def draw_map(sweeps, path):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError as e:
        return "no map (%s)" % e
    planes = [("dt_alpha", "cfl", "alpha", lambda v: v / 0.2, "dt / dt_default (cfl / 0.2)", "alpha"),
              ("contact", "girder_young_modulus", "girder_restitution", None, "E [Pa]", "eps"),
              ("density", "girder_density", "d0", lambda v: v / 1000.0, "density ratio rho_b / rho_w",
               "d0 [m]")]
    present = [p for p in planes if sweeps.get(p[0])]
    if not present:
        return "no map (none of the map's sweeps ran)"
    fig, axes = plt.subplots(1, len(present), figsize=(5 * len(present), 4), squeeze=False)
    for ax, (name, kx, ky, fx, lx, ly) in zip(axes[0], present):
        for r in sweeps[name]:
            x, y = float(r[kx]), float(r[ky])
            x = fx(x) if fx else x
            ok = r["status"] == "ok"
            ax.plot(x, y, "o" if ok else "x", color="tab:green" if ok else "tab:red", ms=9, mew=2)
        ax.set_xscale("log")
        if name == "contact":
            pass
        ax.set_xlabel(lx)
        ax.set_ylabel(ly)
        ax.set_title(name + " (o stable, x stopped)")
        ax.grid(True, alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    return ""


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("out")
    ap.add_argument("--report", required=True)
    ap.add_argument("--mode", default="full")
    a = ap.parse_args()
    sweeps, order = {}, []
    for line in open(os.path.join(a.out, "sweeps.txt")):
        name, scene, what = line.rstrip("\n").split("\t")
        sweeps[name] = read_sweep(a.out, name)
        order.append((name, scene, what))
    map_path = os.path.splitext(a.report)[0] + "_map.png"
    note = draw_map(sweeps, map_path)
    total = sum(len(v) for v in sweeps.values())
    stable = sum(r["status"] == "ok" for v in sweeps.values() for r in v)
    out = ["# Stability suite (%s)" % a.mode, "",
           "Written by `bash scripts/stability.sh%s` (scripts/stability_report.py). "
           "%d runs, %d completed. Status `ok`: the run reached its end time; `unstable`: a guard "
           "stopped it (exit 2, its message in the last column); the frames written so far stay "
           "readable either way." % (" --quick" if a.mode == "quick" else "", total, stable), "",
           "![stability map](%s)" % os.path.basename(map_path) if not note else note, ""]
    for name, scene, what in order:
        out += ["## %s: %s" % (name, what), "", "Scene `%s`." % scene, ""]
        out += [table(sweeps[name]) if sweeps[name] else "(no runs)", ""]
    os.makedirs(os.path.dirname(os.path.abspath(a.report)), exist_ok=True)
    with open(a.report, "w") as f:
        f.write("\n".join(out))
    print("stability: %s (%d runs, %d completed)%s" % (a.report, total, stable,
                                                        "" if not note else "; " + note))
    if a.mode == "quick" and stable < total:
        sys.exit(1)


if __name__ == "__main__":
    main()
