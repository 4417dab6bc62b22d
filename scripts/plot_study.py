#!/usr/bin/env python3
"""Draws a `washout study` (docs/validation.md): error against wall time, log-log, each point
labelled with its varied values; and, when d0 was varied, error against d0 with the observed
convergence order fitted (least squares of log error on log d0).

usage: plot_study.py STUDY.csv [OUT.png]   (default: study.png beside the CSV)
"""
import csv
import os
import sys

from study_fit import fit_order, number


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    path = sys.argv[1]
    out = sys.argv[2] if len(sys.argv) > 2 else os.path.join(os.path.dirname(path), "study.png")
    with open(path, newline="") as f:
        reader = csv.DictReader(f)
        header = reader.fieldnames or []
        rows = list(reader)
    varied = header[: header.index("status")]
    scores = ["error"] + [h for h in header if h.startswith("error_") and
                          not h.startswith("error_bound") and h not in ("error_metric", "error_name")]
    primary = next((r.get("error_name") for r in rows if r.get("error_name")), "error")

    def label_of(score):
        return primary if score == "error" else score[len("error_"):]
    ok = [r for r in rows if r["status"] == "ok"]
    if not any(number(r["error"]) for r in ok):
        sys.exit("no completed run with an error to plot (the scene declares no reference, "
                 "or every run failed)")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    with_d0 = "d0" in varied
    fig, axes = plt.subplots(1, 2 if with_d0 else 1, figsize=(12 if with_d0 else 6.5, 4.8))
    axes = list(axes) if with_d0 else [axes]
    metric = ok[0].get("error_metric", "") if ok else ""

    ax = axes[0]
    for score in scores:
        pts = [(number(r["wall_seconds_min"]), number(r[score]), r) for r in ok]
        pts = [(w, e, r) for w, e, r in pts if w and e]
        if not pts:
            continue
        ax.loglog([w for w, _, _ in pts], [e for _, e, _ in pts], "o-",
                  label=label_of(score) if len(scores) > 1 else None)
        for w, e, r in pts:
            ax.annotate(", ".join(f"{n}={r[n]}" for n in varied), (w, e),
                        textcoords="offset points", xytext=(4, 4), fontsize=7)
    for r in rows:
        if r["status"] != "ok":
            w = number(r["wall_seconds_min"])
            if w:
                ax.axvline(w, color="0.7", ls=":", lw=1)
                ax.annotate(r["status"], (w, ax.get_ylim()[0]), rotation=90, fontsize=7,
                            color="0.4", xytext=(2, 2), textcoords="offset points")
    ax.set_xlabel("wall time [s] (min over repeats)")
    ax.set_ylabel("error")
    ax.set_title(metric[:80], fontsize=8)
    ax.grid(True, which="both", alpha=0.3)
    if len(scores) > 1:
        ax.legend(fontsize=7)

    if with_d0:
        ax = axes[1]
        others = [n for n in varied if n != "d0"]
        for score in scores:
            groups = {}
            for r in ok:
                d, e = number(r["d0"]), number(r[score])
                if d and e:
                    groups.setdefault(tuple(r[n] for n in others), []).append((d, e))
            for key, pts in groups.items():
                pts.sort(reverse=True)
                label = label_of(score) + "".join(f", {n}={v}" for n, v in zip(others, key))
                fit = fit_order(pts)
                converging = fit is not None and fit[0] > 0 and pts[-1][1] < pts[0][1]
                if fit is not None:
                    label += f": order {fit[0]:.2f}" + ("" if converging else " (not converging)")
                    print(f"{label}  [" + "; ".join(f"d0={d:g}: {e:.4g}" for d, e in pts) + "]")
                line, = ax.loglog([d for d, _ in pts], [e for _, e in pts], "o", label=label)
                if fit is not None:
                    ds = [pts[0][0], pts[-1][0]]
                    ax.loglog(ds, [fit[1] * d ** fit[0] for d in ds], "-", color=line.get_color(),
                              alpha=0.6)
        ax.set_xlabel("d0 [m]")
        ax.set_ylabel("error")
        ax.invert_xaxis()  # finer to the right
        ax.set_title("error against resolution, fitted order", fontsize=9)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)

    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
