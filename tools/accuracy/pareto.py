"""The Pareto front of (cost, error) points and the recommendation table:
for a target error, the cheapest measured setting that meets it."""

TARGETS = (0.10, 0.05, 0.02, 0.01)


def front(points, resolution=1e-3):
    """The points (cost, err, payload) no other point beats in both cost
    and error, sorted by cost (error then falls along the front). A point
    must improve on the error of every cheaper one by more than the
    relative resolution: equal errors up to round-off (exact models at
    their finite-strain residue) do not make a costlier point optimal."""
    best, out = float("inf"), []
    for p in sorted(points, key=lambda p: (p[0], p[1])):
        if p[1] < best * (1 - resolution):
            out.append(p)
            best = p[1]
    return out


def cheapest(points, target):
    """The point of least cost with err <= target, or None."""
    ok = [p for p in points if p[1] <= target]
    return min(ok, key=lambda p: p[0]) if ok else None
