"""collide.solve_many against `collide batch` and `collide sweep`: the same rows, bit for bit.

The CLI prints each binary64 as its shortest round-trip text, so reading its CSV back with
float() gives the bits it computed; the arrays must hold exactly those bits (NaN only in bad
rows, -0.0 kept apart from 0.0).
"""

import csv
import io
import random
import threading

import numpy as np
import pytest

import collide
from conftest import run, unwrapped

INPUTS = ["m1", "m2", "v1", "v2", "e"]
ALL = [c for c in collide.COLUMNS if c not in ("m11", "m12", "m22")]


def same_bits(a, b):
    a, b = np.asarray(a, dtype=np.float64), np.asarray(b, dtype=np.float64)
    return a.shape == b.shape and a.view(np.uint64).tolist() == b.view(np.uint64).tolist()


def read_csv(text):
    rows = list(csv.DictReader(io.StringIO(text)))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]} if rows else {}


def test_lecture_rows():
    """Case A at e = 1 and e = 0 (physics.md): FIN (40, 90) and (50, 50); KE_IN 7,250, crunch
    1,000 in both; KE_FIN 7,250 elastic and KE_COM = 6,250 stuck, lost 0 and 1,000. Integers:
    exact in binary64, compared exactly."""
    out = collide.solve_many(4, 1, 60, 10, np.array([1.0, 0.0]))
    assert out["fin1"].tolist() == [40.0, 50.0] and out["fin2"].tolist() == [90.0, 50.0]
    assert out["ke_in"].tolist() == [7250.0, 7250.0]
    assert out["ke_fin"].tolist() == [7250.0, 6250.0]
    assert out["crunch"].tolist() == [1000.0, 1000.0]
    assert out["lost"].tolist() == [0.0, 1000.0]
    assert out["error"].tolist() == [None, None]
    assert list(out) == ["m1", "m2", "v1", "v2", "e", "fin1", "fin2", "v_com", "ke_in",
                         "ke_fin", "crunch", "lost", "error"]
    # e omitted: elastic, as the CLI without -e.
    assert collide.solve_many(4, 1, 60, 10)["fin2"].tolist() == 90.0


def extreme_rows(rng, n):
    """Rows of every scale: mass ratios to 1e16 and beyond, relative velocities 1e-12 of the
    common one, signed zeros, restitutions in [0, 1.5]; some beyond binary64 (KE of 1e400)."""
    rows = []
    for _ in range(n):
        m1 = 10 ** rng.uniform(-30, 30)
        m2 = m1 * 10 ** rng.choice([0, rng.uniform(-16, 16), 16, -16])
        v = rng.uniform(-1e3, 1e3)
        v1 = v * 10 ** rng.uniform(-5, 150)
        v2 = rng.choice([v1 * (1 - 1e-12), -v1, 0.0, -0.0, rng.uniform(-1e3, 1e3)])
        e = rng.choice([0.0, 1.0, 0.5, rng.uniform(0, 1.5), 2 / 3])
        rows.append((m1, m2, v1, v2, e))
    return rows


def test_random_rows_are_collide_batch_bit_for_bit():
    rng = random.Random(4444)
    rows = extreme_rows(rng, 3000)
    # Bad rows: a mass 0 or negative, a negative e, NaN and infinity, typed as collide prints
    # these numbers (a message quotes the typed text; for a float, collide's own).
    bad = {100: "0,1,1,0,1", 200: "-1,1,1,0,1", 300: "1,1,1,0,-0.5", 400: "NaN,1,1,0,1",
           500: "1,1,inf,0,1"}
    lines = [",".join(map(repr, r)) for r in rows]
    for i, line in bad.items():
        lines[i] = line
        rows[i] = tuple(map(float, line.split(",")))
    text = "m1,m2,v1,v2,e\n" + "".join(line + "\n" for line in lines)
    status, out, err = run("batch", "--skip-bad", "--columns", ",".join(ALL), "-", stdin=text)
    assert status == 0, err
    cli = read_csv(out)
    columns = np.array(rows).T
    ours = collide.solve_many(*columns, columns=ALL)
    good = np.array([x is None for x in ours["error"]])
    assert good.sum() == len(cli["fin1"]) and good.sum() < len(rows)
    for name in ALL:
        assert same_bits(ours[name][good], cli[name]), name
        assert np.isnan(ours[name][~good]).all(), name
    # The bad rows' messages are the ones --skip-bad prints ("skipped line N: ..."), line 1
    # being the header.
    skipped = {}
    for line in unwrapped(err).splitlines():
        if line.startswith("skipped line "):
            place, message = line[len("skipped line "):].split(": ", 1)
            skipped[int(place) - 2] = message
    assert skipped == {i: m for i, m in enumerate(ours["error"]) if m is not None}
    for i in bad:
        assert i in skipped


def test_sweeps_are_collide_sweep_bit_for_bit():
    """Grids of masses (log steps), velocities and restitutions (exact decimal steps): the
    sweep's CSV gives each row's inputs, and solve_many of those inputs gives its outputs."""
    for vary in (
        ["--vary", "m1=1e-8:1e8:17:log", "--vary", "v1=-3:3:7", "--vary", "e=0:1:11"],
        ["--vary", "m2=1e-16:1e16:33:log", "--vary", "v2=60:60.000000000001:5"],
    ):
        status, out, err = run("sweep", "-m", "4,1", "-v", "60,10", *vary, "--columns",
                               ",".join(ALL))
        assert status == 0, err
        cli = read_csv(out)
        ours = collide.solve_many(*(cli[k] for k in INPUTS), columns=ALL)
        for name in ALL:
            assert same_bits(ours[name], cli[name]), name


def test_broadcasting_like_numpy():
    m1 = np.array([[1.0], [2.0], [4.0]])
    v1 = np.linspace(-1.0, 1.0, 4)
    out = collide.solve_many(m1, 1.0, v1, 0.0, 0.5)
    assert out["fin1"].shape == (3, 4) == out["error"].shape
    # Each entry is the row of its broadcast inputs, and a list works as well as an array.
    one = collide.solve_many([2.0], 1.0, [v1[3]], 0.0, 0.5)
    assert same_bits(out["fin1"][1, 3], one["fin1"][0])
    assert same_bits(out["m1"], np.broadcast_to(m1, (3, 4)))
    # Strided and integer inputs are read as float64 like NumPy's asarray.
    ints = collide.solve_many(np.arange(1, 9)[::2], 1, 3, 0)
    assert ints["m1"].tolist() == [1.0, 3.0, 5.0, 7.0]
    with pytest.raises(collide.CollideError, match="do not broadcast"):
        collide.solve_many(np.ones(3), np.ones(4), 1.0, 0.0)
    with pytest.raises(collide.CollideError, match="'fin3' is not a column"):
        collide.solve_many(1.0, 1.0, 1.0, 0.0, columns=["fin3"])
    assert collide.solve_many(np.ones(0), 1.0, 1.0, 0.0)["fin1"].shape == (0,)


def test_the_gil_is_released():
    """While solve_many solves 4 million rows, another Python thread keeps running: had the
    call held the GIL, the counter would not move until it returned."""
    n = 4_000_000
    m1 = np.full(n, 4.0)
    count, done = [0], threading.Event()

    def solve():
        collide.solve_many(m1, 1.0, 60.0, 10.0, columns=["fin1"])
        done.set()

    t = threading.Thread(target=solve)
    t.start()
    while not done.is_set():
        count[0] += 1
    t.join()
    assert count[0] > 1000, count[0]
