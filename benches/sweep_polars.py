#!/usr/bin/env python3
"""The 1,000 x 1,000 sweep of issue 16 made with NumPy and written with Polars (`write_csv`, a
multi-threaded Rust CSV writer), to compare with

    collide sweep -m 4,1 -v 60,10 --vary v1=-100:100:1000 --vary e=0:1:1000 -o /dev/null

Not used by the tests. Install: `pip install numpy polars`. Run:

    python3 benches/sweep_polars.py [ROWS_OUT]     # CSV to ROWS_OUT (default /dev/null)

The same 1 M rows and 12 columns (textbook formulas, vectorised); Polars writes shortest
round-trip floats as collide does. Prints the wall time of computing and of writing, and the
process's peak memory; time the whole process with `/usr/bin/time -f "%e s %M KB"` to compare
with collide's.
"""
import resource
import sys
import time

import numpy as np
import polars as pl

out = sys.argv[1] if len(sys.argv) > 1 else "/dev/null"
start = time.perf_counter()
m1, m2, v2 = 4.0, 1.0, 10.0
v1 = np.linspace(-100.0, 100.0, 1000)
e = np.linspace(0.0, 1.0, 1000)
V1, E = np.meshgrid(v1, e, indexing="ij")  # the last parameter varies fastest, as in collide
V1, E = V1.ravel(), E.ravel()
n = V1.size
mt = m1 + m2
vcom = (m1 * V1 + m2 * v2) / mt
fin1 = (1 + E) * vcom - E * V1
fin2 = (1 + E) * vcom - E * v2
mu = m1 * m2 / mt
crunch = 0.5 * mu * (V1 - v2) ** 2
ke_in = 0.5 * mt * vcom * vcom + crunch
ke_fin = 0.5 * mt * vcom * vcom + E * E * crunch
lost = (1 - E * E) * crunch
table = pl.DataFrame({
    "m1": np.full(n, m1), "m2": np.full(n, m2), "v1": V1, "v2": np.full(n, v2), "e": E,
    "fin1": fin1, "fin2": fin2, "v_com": vcom, "ke_in": ke_in, "ke_fin": ke_fin,
    "crunch": crunch, "lost": lost,
})
computed = time.perf_counter()
table.write_csv(out)
written = time.perf_counter()
peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
print(f"polars: {n} rows; compute {computed - start:.3f} s, write_csv {written - computed:.3f} s, "
      f"peak {peak:.0f} MB", file=sys.stderr)
