#!/usr/bin/env python3
"""The table of `collide sweep -m 4,1 -v 60,10 --vary v1=-100:100:10000 --vary e=0:1:1000`
made with NumPy, for comparison (issue 5). Not used by the tests; needs `pip install numpy`.

    python3 benches/sweep_numpy.py [ROWS_OUT]     # writes CSV to ROWS_OUT (default /dev/null)

It uses the textbook formulas (vectorised), and writes every number with repr-equivalent
'%.17g' formatting, as collide writes shortest round-trip numbers. Prints rows per second for the
computation alone and for computation plus CSV writing.
"""
import sys
import time

import numpy as np

out = sys.argv[1] if len(sys.argv) > 1 else "/dev/null"
m1, m2, v2 = 4.0, 1.0, 10.0
v1 = np.linspace(-100.0, 100.0, 10000)
e = np.linspace(0.0, 1.0, 1000)
V1, E = np.meshgrid(v1, e, indexing="ij")  # last varies fastest, as in collide
V1, E = V1.ravel(), E.ravel()
n = V1.size

t = time.perf_counter()
mt = m1 + m2
vcom = (m1 * V1 + m2 * v2) / mt
fin1 = (1 + E) * vcom - E * V1
fin2 = (1 + E) * vcom - E * v2
ke_in = 0.5 * m1 * V1 * V1 + 0.5 * m2 * v2 * v2
mu = m1 * m2 / mt
crunch = 0.5 * mu * (V1 - v2) ** 2
ke_fin = 0.5 * mt * vcom * vcom + E * E * crunch
lost = (1 - E * E) * crunch
compute = time.perf_counter() - t
print(f"numpy compute only:         {n / compute / 1e6:6.2f} M rows/s")

table = np.column_stack([np.full(n, m1), np.full(n, m2), V1, np.full(n, v2), E,
                         fin1, fin2, vcom, ke_in, ke_fin, crunch, lost])
t = time.perf_counter()
np.savetxt(out, table, delimiter=",", fmt="%.17g",
           header="m1,m2,v1,v2,e,fin1,fin2,v_com,ke_in,ke_fin,crunch,lost", comments="")
write = time.perf_counter() - t
print(f"numpy compute + CSV:        {n / (compute + write) / 1e6:6.2f} M rows/s ({n} rows)")
