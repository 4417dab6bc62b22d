#!/usr/bin/python3
"""Reads bench/run's output on stdin and fails (exit 1, saying which line and field) unless
every line is a JSON object of a known kind with that kind's fields, the STREAM and case
figures are positive numbers, and every case ran. ctest runs `bench/run --smoke` through it."""
import json
import sys

FIELDS = {
    "machine": ["mode", "cores", "threads", "load_average_start"],
    "stream": ["threads", "bytes_per_second", "array_bytes"],
    "case": ["case", "scene", "dim", "particles", "steps", "simulated_seconds", "wall_seconds",
             "seconds_per_step", "fluid_particle_steps_per_second", "particle_steps_per_second",
             "stage_share", "ppe", "peak_rss_bytes", "bytes_per_particle", "threads", "error",
             "errors"],
    "end": ["load_average_end", "failed"],
}
PPE = ["solver", "mean_iterations", "solves", "mean_unknowns", "mean_nonzeros", "setup_seconds",
       "solve_seconds", "spmv_bytes_per_second", "spmv_over_stream"]
POSITIVE = ["steps", "wall_seconds", "seconds_per_step", "particle_steps_per_second",
            "peak_rss_bytes", "bytes_per_particle", "threads"]


def check(lines):
    problems, kinds = [], []
    for n, line in enumerate(lines, 1):
        try:
            record = json.loads(line)
        except json.JSONDecodeError as e:
            problems.append(f"line {n}: not JSON ({e}): {line[:80]}")
            continue
        kind = record.get("kind")
        kinds.append(kind)
        if kind not in FIELDS:
            problems.append(f"line {n}: unknown kind {kind!r}")
            continue
        if record.get("failed") is True:
            problems.append(f"line {n}: {record.get('case', kind)} failed")
            continue
        for field in FIELDS[kind]:
            if field not in record:
                problems.append(f"line {n} ({kind}): no field {field!r}")
        if kind == "stream" and not record.get("bytes_per_second", 0) > 0:
            problems.append(f"line {n}: STREAM bandwidth is not positive")
        if kind == "case":
            name = record.get("case")
            for field in POSITIVE:
                value = record.get(field)
                if not isinstance(value, (int, float)) or value <= 0:
                    problems.append(f"line {n} ({name}): {field} = {value!r}, not a positive number")
            particles = record.get("particles", {})
            for field in ("fluid", "wall", "active_wall"):
                if field not in particles:
                    problems.append(f"line {n} ({name}): particles has no {field!r}")
            active, wall = particles.get("active_wall"), particles.get("wall")
            if not isinstance(active, (int, float)) or not 0 < active <= (wall or 0):
                problems.append(f"line {n} ({name}): active_wall = {active!r}, not in (0, wall]")
            ppe = record.get("ppe", {})
            for field in PPE:
                if field not in ppe:
                    problems.append(f"line {n} ({name}): ppe has no {field!r}")
            shares = record.get("stage_share", {})
            if not shares or abs(sum(shares.values()) - 1.0) > 1e-3:
                problems.append(f"line {n} ({name}): stage shares do not add up to 1")
            if name.startswith("mm_") and not (record.get("error") or {}).get("value"):
                problems.append(f"line {n} ({name}): the Martin & Moyce case has no front error")
    for kind in ("machine", "stream", "case", "end"):
        if kind not in kinds:
            problems.append(f"no line of kind {kind!r}")
    return problems


def main():
    lines = [line for line in sys.stdin.read().splitlines() if line.strip()]
    problems = check(lines)
    for p in problems:
        print("check_lines:", p)
    print(f"check_lines: {len(lines)} lines, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
