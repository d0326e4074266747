#!/usr/bin/env python3
"""Path synthesis, side by side in one run on the same targets: Linkage Lab's
`linkage synth path` against pylinkage's particle-swarm optimiser.

Ten targets lie on the coupler curve of a crank-rocker (A (0, 0), D (4, 0.5),
crank 1.2, coupler 3.6, rocker 3.0, coupler point (1.5, 1.1) from B along BC), at
crank angles 10 + 36 k degrees; untimed. Each side searches the same nine
parameters (both ground pivots, three lengths, the coupler point) and stops when
its largest miss of a target is at most 1e-3 of the targets' size (the diagonal of
their bounding box). The figure is the time to get there.

pylinkage builds the four-bar from its own parts (Ground, Crank, RRRDyad,
FixedDyad), simulates it with its own solver over 360 crank steps and is scored
by the largest distance from a target to that polyline (the same measure as
ours; the polyline's chords are within 1e-4 of the curve here). Its optimiser
is pylinkage.particle_swarm_optimization with its defaults (100 particles).

Not run by CI. Run from the repository root:

    pip install pylinkage
    cargo build --release -p linkage-cli
    python3 benches/path_vs_pylinkage.py [--seeds 5] [--peer-seconds 300]
"""

import argparse
import json
import math
import statistics
import subprocess
import tempfile
import time
from pathlib import Path

KNOWN = dict(a=(0.0, 0.0), d=(4.0, 0.5), crank=1.2, coupler=3.6, rocker=3.0, point=(1.5, 1.1))
GOAL = 1e-3


def coupler_point(theta, m=KNOWN):
    """P of the known four-bar at crank angle theta (C left of B->D)."""
    (ax, ay), (dx, dy) = m["a"], m["d"]
    bx, by = ax + m["crank"] * math.cos(theta), ay + m["crank"] * math.sin(theta)
    ex, ey = dx - bx, dy - by
    l2 = ex * ex + ey * ey
    along = (m["coupler"] ** 2 - m["rocker"] ** 2 + l2) / (2 * l2)
    h = math.sqrt(m["coupler"] ** 2 / l2 - along * along)
    cx, cy = bx + ex * along - ey * h, by + ey * along + ex * h
    ux, uy = (cx - bx) / m["coupler"], (cy - by) / m["coupler"]
    px, py = m["point"]
    return bx + ux * px - uy * py, by + uy * px + ux * py


def targets():
    return [coupler_point(math.radians(10 + 36 * k)) for k in range(10)]


def size(points):
    xs, ys = [p[0] for p in points], [p[1] for p in points]
    return math.hypot(max(xs) - min(xs), max(ys) - min(ys))


def ours(points, seed, binary):
    with tempfile.NamedTemporaryFile("w", suffix=".csv", delete=False) as f:
        f.write("x_m,y_m\n")
        for x, y in points:
            f.write(f"{x!r},{y!r}\n")
    started = time.perf_counter()
    out = subprocess.run(
        [binary, "synth", "path", "--points", f.name, "--tolerance", str(GOAL),
         "--solutions", "1", "--seed", str(seed)],
        check=True, capture_output=True, text=True,
    ).stdout
    wall = time.perf_counter() - started
    result = json.loads(out)
    best = result["designs"][0]["relative_error"]
    return wall, result["seconds"], best


class Reached(Exception):
    pass


def peer(points, seed, budget_s):
    """pylinkage's particle swarm on the same nine parameters; seconds to the goal
    (None if not reached within budget_s) and the best relative error seen."""
    import numpy as np
    import pylinkage as pl

    rng_state = np.random.get_state()
    np.random.seed(seed)
    s = size(points)
    cx = sum(p[0] for p in points) / len(points)
    cy = sum(p[1] for p in points) / len(points)
    targets_np = np.array(points)
    best = [math.inf]
    started = time.perf_counter()

    def build(v):
        ax, ay, dx, dy, a, b, c, px, py = v
        ground_a, ground_d = pl.Ground(ax, ay), pl.Ground(dx, dy)
        crank = pl.Crank(anchor=ground_a, radius=a)
        rocker = pl.RRRDyad(anchor1=crank.output, anchor2=ground_d, distance1=b, distance2=c)
        tracer = pl.FixedDyad(anchor1=crank.output, anchor2=rocker,
                              distance=math.hypot(px, py), angle=math.atan2(py, px))
        return pl.Linkage([ground_a, ground_d, crank, rocker, tracer])

    def miss(v):
        try:
            linkage = build(v)
            locus = np.array([step[-1] for step in linkage.step(iterations=360)], dtype=float)
        except Exception:
            return math.inf
        if locus.ndim != 2 or not np.all(np.isfinite(locus)):
            return math.inf
        s0, s1 = locus, np.roll(locus, -1, axis=0)
        seg = s1 - s0
        worst = 0.0
        for t in targets_np:
            along = np.clip(((t - s0) * seg).sum(1) / np.maximum((seg * seg).sum(1), 1e-300), 0, 1)
            d = np.hypot(*(s0 + seg * along[:, None] - t).T).min()
            worst = max(worst, d)
        return worst / s

    def score(linkage, params, init_pos):
        error = miss(params)
        best[0] = min(best[0], error)
        elapsed = time.perf_counter() - started
        if best[0] <= GOAL or elapsed > budget_s:
            raise Reached()
        return error

    known = [*KNOWN["a"], *KNOWN["d"], KNOWN["crank"], KNOWN["coupler"], KNOWN["rocker"], *KNOWN["point"]]
    check = miss(known)
    print(f"pylinkage's simulation of the known four-bar misses by {check:.1e} of the size")
    assert check < 1e-4, "the peer's model of the four-bar is wrong"
    started = time.perf_counter()
    lower = [cx - 1.5 * s, cy - 1.5 * s, cx - 1.5 * s, cy - 1.5 * s, 0.02 * s, 0.05 * s, 0.05 * s, -1.5 * s, -1.5 * s]
    upper = [cx + 1.5 * s, cy + 1.5 * s, cx + 1.5 * s, cy + 1.5 * s, 1.0 * s, 2.5 * s, 2.5 * s, 1.5 * s, 1.5 * s]
    try:
        pl.particle_swarm_optimization(
            score, build([0, 0, 1, 0, 0.3, 1, 1, 0, 0]), dimensions=9,
            bounds=(lower, upper), order_relation=min, iterations=100000, verbose=False,
        )
    except Reached:
        pass
    np.random.set_state(rng_state)
    elapsed = time.perf_counter() - started
    return (elapsed if best[0] <= GOAL else None), best[0]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", type=int, default=5)
    parser.add_argument("--peer-seconds", type=float, default=300.0)
    parser.add_argument("--peer-seeds", type=int, default=1)
    parser.add_argument("--binary", default="target/release/linkage")
    args = parser.parse_args()
    points = targets()
    print(f"10 targets, size {size(points):.4f} m, goal {GOAL} of the size")
    walls = []
    for seed in range(1, args.seeds + 1):
        wall, search_s, err = ours(points, seed, args.binary)
        walls.append(wall)
        print(f"linkage synth path seed {seed}: {wall:.3f} s wall ({search_s:.3f} s search), error {err:.2e}")
    print(f"ours: median {statistics.median(walls):.3f} s, worst {max(walls):.3f} s over {len(walls)} seeds")
    for seed in range(1, args.peer_seeds + 1):
        t, err = peer(points, seed, args.peer_seconds)
        shown = f"{t:.1f} s" if t is not None else f"not reached in {args.peer_seconds:.0f} s"
        print(f"pylinkage PSO seed {seed}: {shown}, best error {err:.2e}")
        if t is not None:
            print(f"speed-up against our median: {t / statistics.median(walls):.0f}x")
        else:
            print(f"speed-up against our median: more than {args.peer_seconds / statistics.median(walls):.0f}x")


if __name__ == "__main__":
    main()
