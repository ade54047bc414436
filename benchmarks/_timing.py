"""The benchmarks' one timer: CPU time of this process, best of a few runs."""

from __future__ import annotations

import math
import time
from collections.abc import Callable


def best(f: Callable[[], object], reps: int) -> tuple[float, object]:
    """(best CPU seconds of ``reps`` calls of ``f``, the last result). The process's CPU
    time (``time.process_time``): the machine may be shared, and every side runs in one
    thread. The previous result is freed before the clock starts again."""
    t, res = math.inf, None
    for _ in range(reps):
        res = None
        t0 = time.process_time()
        res = f()
        t = min(t, time.process_time() - t0)
    return t, res
