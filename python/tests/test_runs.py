"""Tables of runs from Python: `collide.sweep` in the plane, `collide.track(vary=...)` and
`collide.contact(vary=...)` against the command's CSV bit for bit (the same columns in the same
order, every number the binary64 the command prints, the `error` column's messages), and by hand.
"""

import csv
import io
import math
import random

import numpy as np
import polars
import pytest

import collide
from conftest import cli_error, run


def cli_runs(command, args):
    """The CSV of `collide COMMAND ARGS... --format csv` as {column: list of cells} in its order
    (numbers as float, an empty cell as NaN; the error column's cells as text or None)."""
    status, out, err = run(command, *args, "--format", "csv")
    assert status == 0, err
    rows = list(csv.reader(io.StringIO(out)))
    names, body = rows[0], rows[1:]
    table = {}
    for i, name in enumerate(names):
        cells = [r[i] for r in body]
        if name == "error":
            table[name] = [c or None for c in cells]
        else:
            table[name] = np.array([float(c) if c else math.nan for c in cells])
    return table


def same_bits(got, want):
    got = np.asarray(got, dtype=np.float64)
    return got.shape == want.shape and np.array_equal(got.view(np.int64), want.view(np.int64))


def assert_same_table(got, want, context):
    assert list(got) == list(want), (context, list(got), list(want))
    for name, cells in want.items():
        if name == "error":
            assert list(got[name]) == cells, (context, name)
        else:
            assert same_bits(got[name], cells), (context, name, got[name], cells)


def test_plane_sweeps_are_the_cli_table_bit_for_bit():
    rng = random.Random(8123)
    rows = failed = 0
    for _ in range(20):
        m = (rng.choice([1, 2.5, "1/3"]), rng.choice([1, 7, 1e-3]))
        v1 = (round(rng.uniform(-5, 5), 3), round(rng.uniform(-5, 5), 3))
        v2 = (0, round(rng.uniform(-1, 1), 3))
        words = ["-m", f"{m[0]},{m[1]!r}", "-v", f"({v1[0]!r},{v1[1]!r}),({v2[0]},{v2[1]!r})"]
        kwargs = {"m": m, "v": (v1, v2)}
        if rng.random() < 0.5:
            normal = f"{rng.randint(-80, 80)}deg"
            words += ["--normal", normal]
            kwargs["normal"] = normal
            vary = [f"normal_deg={rng.randint(-89, 0)}:{rng.randint(1, 89)}:{rng.randint(2, 6)}"]
        else:
            words += ["--radii", "1,1", "--impact-parameter", "0.5"]
            kwargs.update(radii=(1, 1), b=0.5)
            vary = [f"b=-2.5:2.5:{rng.randint(3, 8)}"]
        vary.append(rng.choice(["e=0:1:3", "v1x=-3,3", "m2=0.5,2"]))
        for spec in vary:
            words += ["--vary", spec]
        want = cli_runs("sweep", words)
        got = collide.sweep(**kwargs, vary=vary, to="numpy")
        assert_same_table(got, want, words)
        df = collide.sweep(**kwargs, vary=vary)
        assert isinstance(df, polars.DataFrame) and df.columns == list(want)
        rows += len(want["lost"])
        failed += sum(e is not None for e in want["error"])
    assert rows > 100 and failed > 0, (rows, failed)


def test_a_plane_sweep_by_hand():
    # Equal disks, body 2 at rest, elastic, line of impact n = (cos t, sin t): body 2 leaves
    # along n with the component of v1 on it, v2' = (v1.n) n = cos t (cos t, sin t), and body 1
    # with the rest, v1' = v1 - v2'; at t = 30 deg, v2' = (3/4, sqrt(3)/4), v1' = (1/4, -sqrt(3)/4).
    df = collide.sweep(m=(1, 1), v=((1, 0), (0, 0)), normal="(1,0)", vary="normal_deg=0,30,60", to="numpy")
    r3 = math.sqrt(3) / 4  # correctly rounded
    exact = {0: (0, 0, 1, 0), 30: (0.25, -r3, 0.75, r3), 60: (0.75, -r3, 0.25, r3)}
    for i, t in enumerate((0, 30, 60)):
        for name, x in zip(("fin1x", "fin1y", "fin2x", "fin2y"), exact[t]):
            # within 2 ulps of the exact value (the line's cos and sin are rounded once each)
            assert abs(df[name][i] - x) <= 2 * math.ulp(max(abs(x), 0.25)), (t, name, df[name][i], x)
    assert list(df["lost"]) == [0.0, 0.0, 0.0]
    assert df["error"] == [None, None, None]


def test_track_and_contact_tables_are_the_cli_tables():
    cases = [
        ("track", ["-m", "1,100", "-x", "1,2", "-v", "0,-1", "--left-wall", "0"],
         dict(m=(1, 100), x=(1, 2), v=(0, -1), left_wall=0), ["m2=1:10000:5", "x2=0.5,2"]),
        ("track", ["-m", "1,2,3", "-x", "0,2,4", "-v", "1,0,-1", "--right-wall", "6", "-e", "0.5"],
         dict(m=(1, 2, 3), x=(0, 2, 4), v=(1, 0, -1), right_wall=6, e=0.5), ["v1=0.5:2:4"]),
        ("contact", ["-m", "1,1", "-x", "0,1", "--sizes", "1,1", "-v", "1,0"],
         dict(m=(1, 1), x=(0, 1), sizes=(1, 1), v=(1, 0)), ["zeta=0:0.5:3", "m2=0.5,2"]),
    ]
    for command, words, kwargs, vary in cases:
        for spec in vary:
            words = words + ["--vary", spec]
        want = cli_runs(command, words)
        got = getattr(collide, command)(**kwargs, vary=vary, to="numpy")
        assert_same_table(got, want, words)


def test_counts_by_hand_and_as_integers():
    # Galperin's billiard: a light ball between a wall and a heavy one 100^N times its mass
    # collides floor(pi 10^N) times: 3, 31, 314.
    df = collide.track(m=(1, 100), x=(1, 2), v=(0, -1), left_wall=0, vary="m2=1,100,10000",
                       columns=["m2", "collisions"])
    assert isinstance(df, polars.DataFrame)
    assert df["collisions"].dtype == polars.Int64
    assert df["collisions"].to_list() == [3, 31, 314]
    pdf = collide.track(m=(1, 100), x=(1, 2), v=(0, -1), left_wall=0, vary="m2=1,100", to="pandas")
    assert list(pdf["collisions"]) == [3, 31]


def test_failed_runs_as_the_command_has_them():
    base = dict(m=(1, 100), x=(1, 2), v=(0, -1), left_wall=0)
    words = ["track", "-m", "1,100", "-x", "1,2", "-v", "0,-1", "--left-wall", "0", "--vary", "x2=0.5,2"]
    # Without the error column a failed run stops the table with the command's message ...
    with pytest.raises(collide.CollideError) as e:
        collide.track(**base, vary="x2=0.5,2", columns=["x2", "collisions"])
    assert str(e.value) == cli_error(*words, "--columns", "x2,collisions", "--format", "csv")
    # ... or is left out with skip_bad=True, as --skip-bad leaves it out.
    got = collide.track(**base, vary="x2=0.5,2", columns=["x2", "collisions"], skip_bad=True, to="numpy")
    assert list(got["x2"]) == [2.0] and list(got["collisions"]) == [31]
    # A run that failed has NaN for its summary and its message in the error column.
    got = collide.track(**base, vary="x2=0.5,2", to="numpy")
    assert math.isnan(got["collisions"][0]) and got["collisions"][1] == 31
    assert got["error"][0].startswith("bodies 1 and 2 overlap") and got["error"][1] is None


def test_vary_where_one_report_is_asked():
    # An empty vary= is a clear refusal, not a crash (it once reached an expect()).
    with pytest.raises(collide.CollideError, match="vary= names no parameter"):
        collide.track(m=(1, 100), x=(1, 2), v=(0, -1), left_wall=0, vary=[])
    with pytest.raises(collide.CollideError, match="vary=: solve gives one report"):
        collide.solve(m=(4, 1), v=(60, 10), vary="e=0:1:3")
    with pytest.raises(collide.CollideError, match="to='arrow': a table is a 'polars' or a 'pandas'"):
        collide.track(m=(1, 100), x=(1, 2), v=(0, -1), left_wall=0, vary="m2=1,100", to="arrow")
