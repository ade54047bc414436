"""Building the CGAL peer drivers (Debian's libcgal-dev) for the benchmarks: one place.

Each driver is one C++ file next to this module, built once into ``build/`` and rebuilt
when its source is newer. Without g++ or libcgal-dev the CGAL columns are skipped, and
the reason is printed.
"""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def build_driver(name: str, header: str = "minkowski_sum_2.h") -> str | None:
    """Path of ``build/<name>`` built from ``benchmarks/<name>.cpp``; None (and why) if
    it cannot be built here. ``header`` is a CGAL header the driver needs."""
    src = Path(__file__).with_name(f"{name}.cpp")
    exe = ROOT / "build" / name
    if exe.exists() and exe.stat().st_mtime >= src.stat().st_mtime:
        return str(exe)
    if shutil.which("g++") is None:
        print("CGAL: skipped (no g++)")
        return None
    if not Path("/usr/include/CGAL", header).exists():
        print("CGAL: skipped (libcgal-dev is not installed: apt-get install -y libcgal-dev)")
        return None
    exe.parent.mkdir(exist_ok=True)
    print(f"CGAL: building build/{name} (g++ -O2, a minute or two) ...", flush=True)
    cmd = ["g++", "-O2", "-std=c++17", str(src), "-o", str(exe), "-lgmp", "-lmpfr"]
    res = subprocess.run(cmd, capture_output=True, text=True)
    if res.returncode:
        print("CGAL: skipped (build failed):", res.stderr[-500:])
        return None
    return str(exe)
