"""collide.sweep against `collide sweep --format csv`, bit for bit: the same grid (`--vary`), the
same columns in the same order, every value the binary64 the command prints (its shortest
round-trip text read back with float()).
"""

import random
import sys

import numpy as np
import pandas
import polars
import pytest

import collide
from conftest import cli_error, run, unwrapped

RAIL_COLUMNS = [c for c in collide.COLUMNS if c not in ("error",)]


def cli_table(args):
    """The CSV `collide sweep ARGS...` prints, as {column: float64 array} in its order."""
    status, out, err = run("sweep", *args, "--format", "csv")
    assert status == 0, err
    lines = out.strip().split("\n")
    names = lines[0].split(",")
    rows = [[float(x) for x in line.split(",")] for line in lines[1:]]
    values = np.array(rows, dtype=np.float64).reshape(len(rows), len(names))
    return {n: values[:, i] for i, n in enumerate(names)}


def same_bits(a, b):
    return a.dtype == np.float64 and a.shape == b.shape and np.array_equal(a.view(np.int64), b.view(np.int64))


def vary_spec(rng, name):
    kind = rng.randrange(3)
    if name in ("m1", "m2"):
        lo, hi = 10 ** rng.uniform(-8, 0), 10 ** rng.uniform(0, 8)
    elif name == "e":
        lo, hi = 0, rng.choice([1, 1.5])
    else:
        lo, hi = rng.uniform(-100, 0), rng.uniform(0, 100)
    if kind == 0:
        return f"{name}={lo!r}:{hi!r}:{rng.randint(1, 9)}"
    if kind == 1 and name in ("m1", "m2"):
        return f"{name}={lo!r}:{hi!r}:{rng.randint(2, 9)}:log"
    return f"{name}=" + ",".join(repr(rng.uniform(lo, hi) if name != "e" else rng.uniform(0, 1)) for _ in range(rng.randint(1, 4)))


def test_random_sweeps_are_the_cli_table_bit_for_bit():
    rng = random.Random(4431)
    rows = 0
    for _ in range(25):
        names = rng.sample(["m1", "m2", "v1", "v2", "e"], rng.randint(1, 3))
        vary = [vary_spec(rng, n) for n in names]
        m, v = (rng.choice([4, 0.5, "1/3"]), rng.choice([1, 1e6])), (rng.uniform(-50, 50), rng.choice([0, 10]))
        columns = rng.sample(RAIL_COLUMNS, rng.randint(1, 8)) if rng.random() < 0.5 else None
        args = ["-m", f"{m[0]},{m[1]!r}", "-v", f"{v[0]!r},{v[1]}"]
        for spec in vary:
            args += ["--vary", spec]
        args += ["--columns", ",".join(columns)] if columns else []
        expected = cli_table(args)
        df = collide.sweep(m=m, v=v, vary=vary, columns=columns)
        assert isinstance(df, polars.DataFrame)
        assert df.columns == list(expected), (df.columns, list(expected))
        for name, want in expected.items():
            assert same_bits(df[name].to_numpy(), want), (args, name)
        rows += len(df)
    assert rows > 100, rows


def test_one_vary_as_text_and_the_lecture_by_hand():
    """Fig. 1.3's case at e = 0, 1/2, 1: FIN = (1 + e) V_COM - e V_IN with V_COM = 50:
    (50, 50), (45, 70), (40, 90); crunch 1,000 and lost (1 - e^2) 1,000: 1,000, 750, 0."""
    out = collide.sweep(m=(4, 1), v=(60, 10), vary="e=0:1:3", to="numpy")
    assert list(out) == ["m1", "m2", "v1", "v2", "e", "fin1", "fin2", "v_com", "ke_in", "ke_fin", "crunch", "lost"]
    assert out["fin1"].tolist() == [50, 45, 40] and out["fin2"].tolist() == [50, 70, 90]
    assert out["lost"].tolist() == [1000, 750, 0] and set(out["crunch"]) == {1000}
    assert all(isinstance(a, np.ndarray) and a.dtype == np.float64 for a in out.values())


def test_pandas_and_the_shard_and_a_tensor():
    args = ["--inertia", "4,1;1,2", "-v", "60,10", "--vary", "e=0:1:7", "--vary", "v2=-5,0,5", "--shard", "2/3"]
    expected = cli_table([*args, "--header", "always"])
    df = collide.sweep(inertia="4,1;1,2", v=(60, 10), vary=["e=0:1:7", "v2=-5,0,5"], shard="2/3", to="pandas")
    assert isinstance(df, pandas.DataFrame) and list(df.columns) == list(expected)
    for name, want in expected.items():
        assert same_bits(df[name].to_numpy(), want), name
    assert len(df) == 7


def test_bad_rows_as_the_cli():
    """v1 = 1e154 on unit masses: KE_IN = 5e307 fits binary64; with m1 = 1e10 it does not."""
    args = ["-m", "1,1", "-v", "1e154,0", "--vary", "m1=1,1e10,1"]
    with pytest.raises(collide.CollideError) as e:
        collide.sweep(m=(1, 1), v=(1e154, 0), vary="m1=1,1e10,1")
    cli = cli_error("sweep", *args, "--format", "csv")
    assert cli.endswith(" (--skip-bad reports bad rows and goes on)")
    assert unwrapped(str(e.value)) == cli.replace("(--skip-bad reports", "(skip_bad=True leaves").replace(
        "rows and goes on)", "rows out and goes on)"
    )
    kept = collide.sweep(m=(1, 1), v=(1e154, 0), vary="m1=1,1e10,1", skip_bad=True, to="numpy")
    expected = cli_table([*args, "--skip-bad"])
    assert kept["m1"].tolist() == [1.0, 1.0] and all(same_bits(kept[k], expected[k]) for k in expected)


@pytest.mark.parametrize(
    "kwargs, args",
    [
        ({"vary": "q=1:2:3"}, ["--vary", "q=1:2:3"]),
        ({"vary": "m1=-1,1"}, ["--vary", "m1=-1,1"]),
        ({"vary": ["e=0:1:3"], "columns": ["fin1", "nope"]}, ["--vary", "e=0:1:3", "--columns", "fin1,nope"]),
        ({"vary": "e=0:1:1000", "max_rows": 10}, ["--vary", "e=0:1:1000", "--max-rows", "10"]),
    ],
)
def test_refusals_are_the_cli_message(kwargs, args):
    with pytest.raises(collide.CollideError) as e:
        collide.sweep(m=(4, 1), v=(60, 10), **kwargs)
    assert unwrapped(str(e.value)) == cli_error("sweep", "-m", "4,1", "-v", "60,10", *args, "--format", "csv")


def test_what_it_needs_and_refuses(monkeypatch):
    with pytest.raises(collide.CollideError, match="to='arrow': a table is a 'polars' or a 'pandas'"):
        collide.sweep(m=(4, 1), v=(60, 10), vary="e=0:1:3", to="arrow")
    # Polars or pandas missing: a clear ImportError (sys.modules[name] = None makes the import fail).
    for name in ("polars", "pandas"):
        monkeypatch.setitem(sys.modules, name, None)
        with pytest.raises(ImportError, match=f"collide.sweep\\(to='{name}'\\) needs {name}.*pip install {name}"):
            collide.sweep(m=(4, 1), v=(60, 10), vary="e=0:1:3", to=name)
