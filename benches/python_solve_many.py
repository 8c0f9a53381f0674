"""collide.solve_many against the same columns as NumPy array expressions (the impulse form in
float64), side by side: time and peak memory on ROWS rows (default 10 million), and the error of
each against exact rational arithmetic on a sample of extreme rows (mass ratios of 1e16 and
beyond, relative velocities 1e-12 of the common one).

Run (after `pip install ./python`):  python3 benches/python_solve_many.py [ROWS]
Each side runs in its own process, so that its peak resident memory is its own.
"""

import json
import math
import os
import random
import resource
import subprocess
import sys
import time
from fractions import Fraction

import numpy as np

import collide

COLUMNS = ["fin1", "fin2", "v_com", "ke_in", "ke_fin", "crunch", "lost"]


def numpy_columns(m1, m2, v1, v2, e):
    """The impulse form as a NumPy user writes it: J = (1 + e) mu (v1 - v2), FIN = V -+ J/m,
    crunch = mu (v1 - v2)^2 / 2, lost = (1 - e^2) crunch, KE_FIN = KE_IN - lost. On Fractions
    the same expressions are the exact values."""
    mt = m1 + m2
    mu = m1 * m2 / mt
    dv = v1 - v2
    j = (1 + e) * mu * dv
    ke_in = (m1 * v1 * v1 + m2 * v2 * v2) / 2
    crunch = mu * dv * dv / 2
    lost = (1 - e * e) * crunch
    return {
        "fin1": v1 - j / m1,
        "fin2": v2 + j / m2,
        "v_com": (m1 * v1 + m2 * v2) / mt,
        "ke_in": ke_in,
        "ke_fin": ke_in - lost,
        "crunch": crunch,
        "lost": lost,
    }


def collide_columns(m1, m2, v1, v2, e):
    out = collide.solve_many(m1, m2, v1, v2, e, columns=COLUMNS)
    del out["error"]
    return out


def inputs(n, seed=2026):
    rng = np.random.default_rng(seed)
    m1 = 10 ** rng.uniform(-3, 3, n)
    m2 = m1 * 10 ** rng.uniform(-6, 6, n)
    v1 = rng.uniform(-100, 100, n)
    v2 = rng.uniform(-100, 100, n)
    e = rng.uniform(0, 1, n)
    return m1, m2, v1, v2, e


def timed(side, n):
    """Runs one side on n rows (in this process): seconds and peak RSS in MB."""
    args = inputs(n)
    base = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    f = collide_columns if side == "collide" else numpy_columns
    best, cpu = math.inf, math.inf
    for _ in range(3):
        t, c = time.perf_counter(), time.process_time()
        out = f(*args)
        best, cpu = min(best, time.perf_counter() - t), min(cpu, time.process_time() - c)
        del out
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    return {"seconds": best, "cpu": cpu, "peak_mb": peak / 1024, "inputs_mb": base / 1024}


def extreme_rows(seed=44):
    """Rows where digits are lost: mass ratios of 1e16 (and 1e-16, 1e30), relative velocities
    1e-12 of the common one, e near 1, and ordinary rows."""
    rng = random.Random(seed)
    rows = []
    for _ in range(2000):
        m1 = 10 ** rng.uniform(-10, 10)
        m2 = m1 * rng.choice([1e16, 1e-16, 1e30, 1.0, 10 ** rng.uniform(-3, 3)])
        v = rng.uniform(1, 1e3) * rng.choice([1, -1])
        v2 = v * (1 + rng.choice([1e-12, -1e-12, 1e-9, 0.5, -2.0]))
        e = rng.choice([1.0, 0.0, 0.5, 1 - 2**-40, rng.uniform(0, 1)])
        rows.append((m1, m2, v, v2, e))
    return rows


def exact(*row):
    return numpy_columns(*map(Fraction, row))


def ulp(x):
    """2^(floor(log2 |x|) - 52): docs/accuracy.md's ulp of a scale."""
    if x == 0:
        return 2.0**-1074
    return 2.0 ** (math.frexp(float(abs(x)))[1] - 1 - 52)


def errors():
    """Worst error of each side per column, in ulps of docs/accuracy.md's scale: velocities in
    ulps of max(|V1|, |V2|, |V_COM|, |FIN1|, |FIN2|), energies of themselves (a lost that
    should be 0 compared in ulps of KE_IN)."""
    rows = extreme_rows()
    cols = [np.array(c) for c in zip(*rows)]
    sides = {"collide": collide_columns(*cols), "numpy": numpy_columns(*cols)}
    worst = {s: {c: 0.0 for c in COLUMNS} for s in sides}
    for i, row in enumerate(rows):
        x = exact(*row)
        vscale = ulp(max(abs(row[2]), abs(row[3]), *(abs(x[c]) for c in ("v_com", "fin1", "fin2"))))
        for c in COLUMNS:
            scale = vscale if c in ("fin1", "fin2", "v_com") else ulp(x[c] or x["ke_in"])
            for s, out in sides.items():
                got = out[c][i]
                err = math.inf if not math.isfinite(got) else float(abs(Fraction(got) - x[c]) / Fraction(scale))
                worst[s][c] = max(worst[s][c], err)
    return worst


def main():
    if len(sys.argv) > 2 and sys.argv[1] == "--side":
        print(json.dumps(timed(sys.argv[2], int(sys.argv[3]))))
        return
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 10_000_000
    print(f"{n:,} rows, columns {' '.join(COLUMNS)}; best of 3; {os.cpu_count()} CPUs")
    for side in ("collide", "numpy"):
        out = subprocess.run([sys.executable, __file__, "--side", side, str(n)],
                             capture_output=True, text=True, check=True).stdout
        r = json.loads(out)
        print(f"  {side:8} {r['seconds']:7.3f} s  {r['seconds'] / n * 1e9:6.1f} ns/row  "
              f"CPU (all threads) {r['cpu']:7.3f} s  peak RSS {r['peak_mb']:6.0f} MB "
              f"(inputs made: {r['inputs_mb']:.0f} MB)")
    print("worst error against exact rationals, 2,000 extreme rows (ulps; collide states 1):")
    worst = errors()
    print("  column   " + "".join(f"{s:>14}" for s in worst))
    for c in COLUMNS:
        print(f"  {c:8} " + "".join(f"{worst[s][c]:14.3g}" for s in worst))


if __name__ == "__main__":
    main()
