#!/usr/bin/env python3
"""Writes docs/validation.md from the study.csv of each validation case and checks the
documented bounds (each scene's washout.validation{bound = ...}). Called by
scripts/validate.sh; exits 1 if a run did not complete or an error exceeds its bound.

usage: validation_report.py OUT.md MODE CASE_DIR... (MODE: quick or full; each CASE_DIR holds
       study.csv and case.txt: "name|dim|scene|what")
"""
import csv
import os
import sys

from study_fit import fit_order, number


def fmt(v, spec=".3g"):
    return "" if v is None else format(v, spec)


def main():
    out_path, mode, case_dirs = sys.argv[1], sys.argv[2], sys.argv[3:]
    lines, failures, not_converging = [], [], []
    for case_dir in case_dirs:
        with open(os.path.join(case_dir, "case.txt")) as f:
            name, dim, scene, what = f.read().strip().split("|", 3)
        csv_path = os.path.join(case_dir, "study.csv")
        if not os.path.exists(csv_path):
            failures.append(f"{name}: no study.csv (the study did not run)")
            continue
        with open(csv_path, newline="") as f:
            reader = csv.DictReader(f)
            header = reader.fieldnames
            rows = list(reader)
        scores = [("error", "error_bound")] + [
            (h, "error_bound_" + h[len("error_"):]) for h in header
            if h.startswith("error_") and not h.startswith("error_bound")
            and h not in ("error_metric", "error_name")]
        metric = next((r["error_metric"] for r in rows if r.get("error_metric")), "")
        primary_name = next((r["error_name"] for r in rows if r.get("error_name")), "error")
        primary = f"{primary_name}: {metric.split(';')[0]}"
        for column, bound_column in scores:
            label = primary_name if column == "error" else column[len("error_"):]
            pts = [(number(r["d0"]), number(r[column])) for r in rows if r["status"] == "ok"]
            fit = fit_order(pts)
            p = fit[0] if fit else None
            ok_pts = sorted([x for x in pts if x[0] and x[1] is not None], reverse=True)
            converging = (p is not None and p > 0 and ok_pts[-1][1] < ok_pts[0][1])
            if p is not None and not converging:
                not_converging.append(
                    f"{name} ({label}): " + "; ".join(f"d0 = {d:g}: {e:.3g}" for d, e in ok_pts))
            for k, r in enumerate(rows):
                err, bound = number(r[column]), number(r[bound_column])
                if r["status"] != "ok" and column == "error":
                    failures.append(f"{name} at d0 = {r['d0']}: run {r['status']}")
                if err is not None and bound is not None and err > bound:
                    failures.append(f"{name} ({label}) at d0 = {r['d0']}: error {err:.4g} > bound {bound:.4g}")
                order_cell = ""
                if k == len(rows) - 1 and p is not None:
                    order_cell = f"{p:.2f}" + ("" if converging else " **not converging**")
                lines.append(
                    f"| {name} | {label if column != 'error' else primary} | {dim} | {r['d0']} | "
                    f"{fmt(number(r['particles']), '.0f')} | {r['status']} | {fmt(err, '.4g')} | "
                    f"{fmt(bound, '.3g')} | {fmt(number(r['wall_seconds_min']), '.1f')} | "
                    f"{fmt(number(r['peak_rss_bytes']) and number(r['peak_rss_bytes']) / 2**20, '.0f')} | "
                    f"{order_cell} |")
        lines.append(f"| | *{what}; plot: [images/validation/{name}.png](images/validation/{name}.png)* "
                     f"| | | | | | | | | |")

    with open(out_path, "w") as out:
        out.write(f"""# Validation report

Written by `bash scripts/validate.sh{' --quick' if mode == 'quick' else ''}` (mode **{mode}**);
run it again to refresh every figure here. How scenes score themselves and how `washout study`
works: [study.md](study.md). Reference data and their sources:
[validation/reference/README.md](../validation/reference/README.md).

Errors are against experiments or analytic solutions, never against the code's own earlier
output. Each case's error is defined by its scene (`washout.validation{{...}}`); the bound is the
scene's `bound` (what the engine reaches now with a margin, to catch regressions; an empty bound
is reported but not required). Wall time is the whole `washout run` child on this machine
(2 cores, shared with other work while measured: treat it as indicative). The observed order
is the least-squares slope of log(error) on log(d0) over the case's completed runs; a case is
**not converging** when that slope is not positive or its finest error is not below its
coarsest.

How far the references can be trusted (validation/reference/README.md): Martin & Moyce's front
is their Table 2 as transcribed by two codes that agree within 0.02 in Z (an instantaneous
release's toe takes a lead over it in the first 0.15 s, after which the surge runs at their
speed, `front_speed`: docs/method.md, the twenty-third session); Lobovsky's front is a
figure-data file of the experiment (medium-high), the gauges and the sensor-1 statistics are
the released measurements (high; sensor 1 is a 2.5-97.5 % band over repeated runs at each
instant, decimated to every 5th sample here: the scatter of the runs' impact times smooths its
peak, and an incompressible model's peak changes with the step, so the impact is held to its
impulse, docs/method.md, the twenty-third session); SPHERIC Test 2 is one run of the
experiment as released (high), about 1 kHz, its pressures with the sensors' zero offsets (about
1 % of rho g H) and the same single-run impact peaks (reported, not bounded). Hydrostatics,
Poiseuille and Archimedes are exact.

| case | error (metric) | dim | d0 [m] | particles | status | error | bound | wall [s] | peak memory [MB] | observed order |
|---|---|---|---|---|---|---|---|---|---|---|
""")
        out.write("\n".join(lines) + "\n\n")
        out.write("## Not converging\n\n")
        out.write("".join(f"- {n}\n" for n in not_converging) or "None.\n")
        out.write("\n## Checks\n\n")
        out.write("".join(f"- FAILED: {f}\n" for f in failures) or
                  "Every run completed and every bounded error is within its bound.\n")
    for f in failures:
        print("FAILED:", f, file=sys.stderr)
    for n in not_converging:
        print("not converging:", n)
    print(f"wrote {out_path}")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
