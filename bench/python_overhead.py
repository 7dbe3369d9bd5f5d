#!/usr/bin/python3
"""What a call from Python adds to the C++ work (docs/performance.md): tripack.build(n=N) timed
from Python against bench_analysis' BM_BuildBestForN/N (pipeline::build_best_for_n, the same
build) in one run, interleaved (C++, Python, C++, Python, ...) so a noisy neighbour hits both
alike. Prints the medians and their ratio.

Usage: /usr/bin/python3 bench/python_overhead.py BUILD_DIR [N] [REPS]
"""
import csv
import io
import os
import statistics
import subprocess
import sys
import time

build = os.path.abspath(sys.argv[1])
n = int(sys.argv[2]) if len(sys.argv) > 2 else 22
reps = int(sys.argv[3]) if len(sys.argv) > 3 else 7
sys.path.insert(0, os.path.join(build, "python"))
import tripack  # noqa: E402

CALLS = 10  # Python calls per repetition, timed one by one (the median of each repetition kept)


def cpp_ms():
    out = subprocess.run(
        [os.path.join(build, "bench", "bench_analysis"), f"--benchmark_filter=BM_BuildBestForN/{n}$",
         "--benchmark_format=csv", "--benchmark_min_time=1"],
        capture_output=True, text=True, check=True).stdout
    rows = list(csv.DictReader(io.StringIO(out[out.index("name,"):])))
    return float(rows[0]["real_time"])  # milliseconds (the benchmark's unit)


def python_ms():
    times = []
    for _ in range(CALLS):
        start = time.perf_counter()
        p = tripack.build(n=n)
        times.append((time.perf_counter() - start) * 1e3)
        assert p.certified
    return statistics.median(times)


tripack.build(n=n)  # the first call imports numpy and json once
cpp, python = [], []
for _ in range(reps):
    cpp.append(cpp_ms())
    python.append(python_ms())
c, p = statistics.median(cpp), statistics.median(python)
print(f"build n={n}: C++ {c:.3f} ms, Python {p:.3f} ms (medians of {reps}); "
      f"Python/C++ {p / c:.3f}, overhead {p - c:+.3f} ms")
