"""What the study plot and the validation report share: reading numbers from study.csv and the
observed convergence order (least squares of log error on log d0)."""
import math


def number(text):
    """A finite float from a CSV cell, or None (empty, 'nan', text)."""
    try:
        v = float(text)
        return v if math.isfinite(v) else None
    except (TypeError, ValueError):
        return None


def fit_order(points):
    """(p, c) of error = c d0^p fitted to (d0, error) points with positive values, or None
    with fewer than two such points."""
    pts = [(d, e) for d, e in points if d and e and d > 0 and e > 0]
    if len(pts) < 2:
        return None
    xs = [math.log(d) for d, _ in pts]
    ys = [math.log(e) for _, e in pts]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    sxx = sum((x - mx) ** 2 for x in xs)
    if sxx == 0:
        return None
    p = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx
    return p, math.exp(my - p * mx)
