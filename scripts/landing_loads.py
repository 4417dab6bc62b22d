#!/usr/bin/env python3
"""The landing-load study of docs/stability.md ("Landing loads", issue 15).

Runs the sinking box (scenes/sinking_box_2d.lua) and the 2D girder wash-out
(scenes/girder_washout_2d.lua) at fixed time steps and particle spacings, two runs at a time
with one thread each, and reads what the body report of each run stored in /bodies/NAME
(engine/cli/body_report.cpp, engine/cli/landing_load.cpp): the raw one-step peak of the fluid
load, its peak averaged over the report's load_window, and the fluid impulse of the first
landing. Writes OUT/landing_loads.csv, OUT/landing_loads.md (the table) and a plot.

  /usr/bin/python3 scripts/landing_loads.py [--washout PATH] [--out DIR] [--plot PNG]
                                            [--table-only] [--quick]

--table-only reads the runs already in OUT. Needs h5py and matplotlib.
"""
import argparse
import concurrent.futures as futures
import csv
import math
import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

# (scene file, body, end time [s], [(d0, dt), ...]): the box lands at about 0.25-0.27 s, the
# girder leaves its pier at about 0.64 s and falls off it by 1.3 s. The box gets the cross
# product; the girder at d0 = 0.005 m costs some minutes a run, so its d0 sweep takes two steps.
DTS = [0.00025, 0.0005, 0.00075, 0.001]
CASES = [
    ("sinking_box_2d", "box", 0.45,
     [(d0, dt) for d0 in (0.01, 0.0075, 0.005) for dt in DTS]),
    ("girder_washout_2d", "girder", 1.4,
     [(0.01, dt) for dt in DTS] + [(d0, dt) for d0 in (0.0075, 0.005) for dt in (0.0005, 0.001)]),
]
QUICK = [("sinking_box_2d", "box", 0.45, [(0.01, dt) for dt in DTS])]


def run_dir(out, scene, d0, dt):
    return out / f"{scene}_d0_{d0:g}_dt_{dt * 1e3:g}ms"


def run_one(washout, out, scene, end_time, d0, dt):
    d = run_dir(out, scene, d0, dt)
    d.mkdir(parents=True, exist_ok=True)
    cmd = [washout, "run", str(ROOT / "scenes" / f"{scene}.lua"), "--out", str(d), "--quiet",
           "--threads", "1", "--set", f"d0={d0}", "--set", f"dt={dt}",
           "--set", f"end_time={end_time}"]
    env = dict(os.environ, OMP_NUM_THREADS="1")
    with open(d / "run.log", "w") as log:
        rc = subprocess.call(cmd, stdout=log, stderr=subprocess.STDOUT, env=env)
    print(f"{scene} d0={d0} dt={dt}: exit {rc}", flush=True)
    return rc


def read_run(out, scene, body, d0, dt):
    import h5py
    d = run_dir(out, scene, d0, dt)
    files = sorted(d.glob("*.h5"))
    row = {"scene": scene, "d0": d0, "dt_ms": dt * 1e3, "status": "missing"}
    if not files:
        return row
    log = (d / "run.log").read_text(errors="replace") if (d / "run.log").exists() else ""
    row["status"] = "unstable" if "unstable" in log else "ok"
    with h5py.File(files[0], "r") as f:
        g = f[f"/bodies/{body}"]
        a = g.attrs
        if "load_window" not in a:
            row["status"] = "no report"
            return row
        w = float(a["weight"])
        mass = float(a["mass"])
        vertical = 1  # 2D: y is up
        row.update({
            "end_time": float(g["time"][-1]),
            "weight": w,
            "window_s": float(a["load_window"]),
            "raw_v_W": float(a["peak_force_vertical_one_step"]) / w,
            "raw_v_time": float(a["peak_force_vertical_one_step_time"]),
            "win_v_W": float(a["peak_force_vertical_windowed"]) / w,
            "win_v_time": float(a["peak_force_vertical_windowed_time"]),
            "raw_h_W": float(a["peak_force_horizontal_one_step"]) / w,
            "win_h_W": float(a["peak_force_horizontal_windowed"]) / w,
            "landing_time": float(a["landing_time"]),
            "J_fluid": float(a["landing_impulse_fluid"][vertical]),
            "J_contact": float(a["landing_impulse_contact"][vertical]),
            "Mv_landing": mass * float(a["landing_velocity"][vertical]),
            "spikes": int(a["load_spikes"]),
        })
    return row


def fmt(v, spec):
    return "" if v is None or (isinstance(v, float) and math.isnan(v)) else format(v, spec)


def write_table(rows, path):
    head = ("| scene | d0 [m] | dt [ms] | status | end t [s] | raw one-step peak F_v / W (t [s]) "
            "| windowed peak F_v / W (t [s]) | raw F_x / W | windowed F_x / W | landing t [s] "
            "| J_fluid,v [N s/m] | M v_landing [N s/m] | J_fluid / (M v) |")
    lines = [head, "|" + "---|" * (head.count("|") - 1)]
    for r in rows:
        if r["status"] in ("missing", "no report"):
            lines.append(f"| {r['scene']} | {r['d0']:g} | {r['dt_ms']:g} | {r['status']} |" + " |" * 9)
            continue
        ratio = r["J_fluid"] / r["Mv_landing"] if r["Mv_landing"] else float("nan")
        lines.append(
            f"| {r['scene']} | {r['d0']:g} | {r['dt_ms']:g} | {r['status']} | {r['end_time']:.3g} "
            f"| {r['raw_v_W']:.1f} ({r['raw_v_time']:.3f}) | {r['win_v_W']:.2f} ({r['win_v_time']:.3f}) "
            f"| {r['raw_h_W']:.2f} | {r['win_h_W']:.2f} | {fmt(r['landing_time'], '.3f')} "
            f"| {fmt(r['J_fluid'], '.3f')} | {fmt(r['Mv_landing'], '.3f')} | {fmt(ratio, '.2f')} |")
    path.write_text("\n".join(lines) + "\n")


def plot(rows, path):
    """Peaks against dt for each scene (raw one-step dashed, windowed solid, one colour per d0)
    and the sinking box's landing impulse against dt."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    scenes = [s for s in ("sinking_box_2d", "girder_washout_2d") if any(r["scene"] == s for r in rows)]
    fig, axes = plt.subplots(1, len(scenes) + 1, figsize=(5.5 * (len(scenes) + 1), 4.5), squeeze=False)
    colours = {0.01: "C0", 0.0075: "C1", 0.005: "C2"}

    def series(scene, d0, key):
        return sorted((r["dt_ms"], abs(r[key])) for r in rows
                      if r["scene"] == scene and r["d0"] == d0 and key in r and not math.isnan(r[key]))

    for ax, scene in zip(axes[0], scenes):
        for d0, colour in colours.items():
            raw, win = series(scene, d0, "raw_v_W"), series(scene, d0, "win_v_W")
            if not raw:
                continue
            ax.plot(*zip(*raw), "o--", color=colour, label=f"raw one-step, d0 = {d0:g} m")
            ax.plot(*zip(*win), "s-", color=colour, label=f"windowed, d0 = {d0:g} m")
            if d0 == 0.01 and len(raw) > 1:  # what a load stopped in one step would follow
                ref = raw[-1][1] * raw[-1][0]
                ax.plot([p[0] for p in raw], [ref / p[0] for p in raw], ":", color="grey",
                        label="1/dt through the raw point at the largest dt")
        bad = [r for r in rows if r["scene"] == scene and r["status"] == "unstable" and "raw_v_W" in r]
        for i, r in enumerate(bad):  # a guard stopped these: their peaks are the blow-up's
            ax.plot([r["dt_ms"]] * 2, [abs(r["raw_v_W"]), abs(r["win_v_W"])], "x", color="red",
                    ms=10, mew=2, label="run stopped unstable" if i == 0 else None)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("fixed time step dt [ms]")
        ax.set_ylabel("abs(peak vertical fluid load) / weight")
        ax.set_title(f"{scene}: peaks")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    ax = axes[0][-1]
    for d0, colour in colours.items():
        j = series("sinking_box_2d", d0, "J_fluid")
        mv = series("sinking_box_2d", d0, "Mv_landing")
        if j:
            ax.plot(*zip(*j), "s-", color=colour, label=f"abs(J_fluid), d0 = {d0:g} m")
            ax.plot(*zip(*mv), "^:", color=colour, label=f"M abs(v_landing), d0 = {d0:g} m")
    ax.set_xscale("log")
    ax.set_ylim(bottom=0)
    ax.set_xlabel("fixed time step dt [ms]")
    ax.set_ylabel("N s/m")
    ax.set_title("sinking_box_2d: landing impulse of the fluid")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=100)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--washout", default=os.environ.get("WASHOUT", str(ROOT / "build-perf/engine/cli/washout")))
    ap.add_argument("--out", default=str(ROOT / "runs/landing_loads"))
    ap.add_argument("--plot", default=None, help="PNG path (default OUT/landing_loads.png)")
    ap.add_argument("--table-only", action="store_true")
    ap.add_argument("--quick", action="store_true", help="the sinking box at d0 = 0.01 m only")
    ap.add_argument("--jobs", type=int, default=2)
    args = ap.parse_args()
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    cases = QUICK if args.quick else CASES
    if not args.table_only:
        with futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
            # The longest runs first (cost ~ end time / (d0^2 dt)), so the two workers end together.
            todo = sorted(((scene, end, d0, dt) for scene, _, end, points in cases for d0, dt in points),
                          key=lambda c: -c[1] / (c[2] ** 2 * c[3]))
            jobs = [pool.submit(run_one, args.washout, out, *c) for c in todo]
            for j in jobs:
                j.result()
    rows = [read_run(out, scene, body, d0, dt) for scene, body, _, points in cases for d0, dt in points]
    fields = ["scene", "d0", "dt_ms", "status", "end_time", "weight", "window_s", "raw_v_W",
              "raw_v_time", "win_v_W", "win_v_time", "raw_h_W", "win_h_W", "landing_time",
              "J_fluid", "J_contact", "Mv_landing", "spikes"]
    with open(out / "landing_loads.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields, restval="")
        w.writeheader()
        w.writerows(rows)
    write_table(rows, out / "landing_loads.md")
    plot(rows, Path(args.plot) if args.plot else out / "landing_loads.png")
    print((out / "landing_loads.md").read_text())
    return 0


if __name__ == "__main__":
    sys.exit(main())
