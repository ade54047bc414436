"""Cold start: what a fresh process pays before its first answers.

Each measurement runs in a new Python process with an empty environment: no writable
HOME (so no cache folder could help), byte-code writing off. It prints the time of
``import minkowski2d`` and of each first call after the import, as medians over
``--runs`` fresh processes. There is no just-in-time compilation anywhere: the
compiled core is loaded with the package.

Run: ``python benchmarks/bench_coldstart.py``
"""

from __future__ import annotations

import argparse
import json
import statistics
import subprocess
import sys

CHILD = r"""
import json, time
t0 = time.perf_counter()
import minkowski2d as mk
import numpy as np
out = {"import minkowski2d": time.perf_counter() - t0}


def first(label, fn, *args):
    t = time.perf_counter()
    fn(*args)
    out[label] = time.perf_counter() - t


def ngon(n, r, phase):
    th = np.linspace(0, 2 * np.pi, n, endpoint=False) + phase
    return np.c_[r * np.cos(th), r * np.sin(th)]


rng = np.random.default_rng(1)
A = [ngon(64, 1.0, p) + rng.uniform(-2, 2, 2) for p in rng.uniform(0, 1, 100)]
B = [ngon(64, 0.5, p) + rng.uniform(-2, 2, 2) for p in rng.uniform(0, 1, 100)]
P = [ngon(int(k), 1.0, 0.2) for k in rng.integers(3, 13, 1000)]
L = [(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)]
first("first minkowski_sum, two 200-gons", mk.minkowski_sum, ngon(200, 1, 0.1), ngon(200, 0.7, 0.3))
first("first intersects_many, 100 pairs of 64-gons", mk.intersects_many, A, B)
first("first distance_many, 100 pairs of 64-gons", mk.distance_many, A, B)
first("first 1,000-pair batch", mk.minkowski_sum_many, P, P[::-1])
first("first small general sum (L ⊕ L)", mk.minkowski_sum_general, L, L)
print(json.dumps(out))
"""


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--runs", type=int, default=5)
    args = ap.parse_args()
    env = {"HOME": "/nonexistent", "PATH": "/usr/bin:/bin", "PYTHONDONTWRITEBYTECODE": "1"}
    runs = []
    for _ in range(args.runs):
        res = subprocess.run(
            [sys.executable, "-c", CHILD], env=env, capture_output=True, text=True, check=True
        )
        runs.append(json.loads(res.stdout))
    print("| fresh process | median | target |")
    print("|---|---:|---|")
    for key in runs[0]:
        med = statistics.median(r[key] for r in runs)
        target = "≤ 300 ms" if key.startswith("import") else "≤ 50 ms"
        print(f"| {key} | {med * 1e3:.1f} ms | {target} |")
    print(f"\nmedians of {args.runs} fresh processes; python {sys.version.split()[0]}")


if __name__ == "__main__":
    main()
