"""collide.solve against `collide solve --format json` and the lecture's numbers.

Each random case is typed to the command line independently of the module: floats as Python's
repr (`1e+16`, where the module writes Rust's `1e16`), fractions as `n/d`, units as text; the
report must be the command's JSON exactly (`to_dict()` equal to `json.loads` of stdout, and
`to_json()` its text).
"""

import json
import random
from fractions import Fraction

import pytest

import collide
from conftest import cli_error, cli_json, unwrapped


def cli_text(x):
    if isinstance(x, Fraction):
        return f"{x.numerator}/{x.denominator}"
    if isinstance(x, tuple):
        return "(" + ",".join(cli_text(c) for c in x) + ")"
    return x if isinstance(x, str) else repr(x)


def args(m, v, e, frame="lab", reverse=False, exact=False, plane=()):
    out = ["solve", "-m", ",".join(map(cli_text, m)), "-v", ",".join(map(cli_text, v))]
    if e is not None:
        out += ["-e", cli_text(e)]
    out += ["--frame", frame, *plane]
    return out + ["--reverse"] * reverse + ["--exact"] * exact


def test_lecture_case_a():
    """physics.md case A (Fig. 1.3): M = diag(4, 1), V_IN = (60, 10), elastic. The lecture's
    table: COM (50, 50), FIN (40, 90), KE 7,250 in and out, KE_COM 6,250, crunch 1,000,
    V_COM.M.V_IN = 12,500, V_FIN.M.V_IN = 10,500. All are integers well inside 2^53, and the
    impulse form computes each from integers exactly, so the comparison is exact (0 ulps)."""
    r = collide.solve(m=(4, 1), v=(60, 10), e=1)
    assert r.fin == [40.0, 90.0]
    assert r.com == [50.0, 50.0]
    assert r.v_com == 50.0
    assert (r.energy["in"], r.energy.fin, r.energy.com) == (7250.0, 7250.0, 6250.0)
    assert r.energy.crunch == 1000.0 and r.energy.lost == 0.0
    assert (r.forms.com_m_in, r.forms.fin_m_in) == (12500.0, 10500.0)
    assert r.in_ == [60.0, 10.0] and "in" in r and r["in"] == [60.0, 10.0]
    out, data = cli_json("solve", "-m", "4,1", "-v", "60,10")
    assert r.to_dict() == data
    assert r.to_json() == out


def test_lecture_case_b_exact():
    """physics.md case B (Fig. 2.3): M = diag(6, 1), V_IN = (3, -4), e = 2/3: P = 14,
    V_COM = 2, FIN = (1+e) V_COM - e V_IN = (10/3 - 2, 10/3 + 8/3) = (4/3, 6),
    KE_IN = (54 + 16)/2 = 35, KE_COM = V_COM P / 2 = 14, crunch = 21,
    KE_FIN = 14 + (4/9) 21 = 70/3 (the lecture's 23.33), lost = (5/9) 21 = 35/3. Exact:
    Fractions, equal."""
    r = collide.solve(m=(6, 1), v=(3, -4), e="2/3", exact=True)
    assert r.fin == [Fraction(4, 3), Fraction(6)]
    assert r.v_com == 2 and r.restitution == Fraction(2, 3)
    assert (r.energy["in"], r.energy.com, r.energy.crunch) == (35, 14, 21)
    assert (r.energy.fin, r.energy.lost) == (Fraction(70, 3), Fraction(35, 3))
    assert all(isinstance(x, Fraction) for x in r.fin + [r.energy.crunch])
    _, data = cli_json("solve", "-m", "6,1", "-v", "3,-4", "-e", "2/3", "--exact")
    assert r.to_dict() == data
    # Every number of the CLI's exact JSON, read as a Fraction, is the attribute's.
    for key, value in data["energy"].items():
        assert r.energy[key] == Fraction(value)
    assert r.inertia == [[6, 0], [0, 1]]


def number(rng):
    """A value as a user may type it: int, float of any scale, Fraction, text with a unit."""
    kind = rng.randrange(5)
    if kind == 0:
        return rng.randint(1, 10**6)
    if kind == 1:
        return 10 ** rng.uniform(-20, 20)
    if kind == 2:
        return Fraction(rng.randint(1, 1000), rng.randint(1, 1000))
    if kind == 3:
        return rng.uniform(0.01, 100)
    return f"{rng.randint(1, 100)} {rng.choice(['kg', 'g', 'ton', 'lb'])}"


def masses(rng):
    """Two masses, both with a unit or neither (the CLI refuses a mix)."""
    m = (number(rng), number(rng))
    while isinstance(m[0], str) != isinstance(m[1], str):
        m = masses(rng)
    return m


def velocity(rng, unit):
    x = rng.choice([rng.uniform(-100, 100), rng.randint(-50, 50), Fraction(rng.randint(-99, 99), 7)])
    return f"{cli_text(x)} {unit}" if unit else x


FRAMES = ["lab", "com", "rest-in:1", "rest-in:2", "rest-fin:1", "rest-fin:2"]
RESTITUTIONS = [None, 0, 1, "2/3", 0.25, Fraction(1, 3), "elastic", "inelastic", 1.5]


@pytest.mark.parametrize("exact", [False, True])
def test_random_cases_on_a_rail_are_the_cli_json(exact):
    rng = random.Random(44 + exact)
    for _ in range(40):
        m = masses(rng)
        # Units on every mass and velocity, or on none (the CLI refuses a mix).
        unit = rng.choice(["m/s", "mph", "km/h"]) if isinstance(m[0], str) else None
        v = (velocity(rng, unit), velocity(rng, unit))
        e = rng.choice(RESTITUTIONS)
        frame = rng.choice(FRAMES)
        reverse = rng.random() < 0.2 and e not in (0, "inelastic")
        if exact and any(isinstance(x, float) for x in (*m, *v)):
            # A float is its binary64 value; --exact reads the text, which is that value only
            # when it is short: give the float as its exact fraction on both sides.
            m = tuple(Fraction(x) if isinstance(x, float) else x for x in m)
            v = tuple(Fraction(x) if isinstance(x, float) else x for x in v)
        r = collide.solve(m=m, v=v, e=e, frame=frame, reverse=reverse, exact=exact)
        out, data = cli_json(*args(m, v, e, frame, reverse, exact))
        assert r.to_dict() == data, (m, v, e, frame, reverse)
        assert r.to_json() == out
        if exact:
            assert r.fin == [Fraction(x) for x in data["fin"]]


def vector(rng):
    kind = rng.randrange(3)
    if kind == 0:
        return (rng.randint(-9, 9), rng.randint(-9, 9))
    if kind == 1:
        return (rng.uniform(-5, 5), Fraction(rng.randint(-9, 9), 4))
    return f"{rng.randint(1, 9)} m/s @ {rng.randint(0, 359)}deg"


def test_random_cases_in_the_plane_are_the_cli_json():
    rng = random.Random(4402)
    for _ in range(40):
        m = masses(rng)
        v = (vector(rng), vector(rng))
        e = rng.choice([None, 0, 1, "2/3", 0.5])
        if rng.random() < 0.5:
            normal = rng.choice([f"{rng.randint(0, 359)}deg", (rng.randint(-3, 3), 1)])
            kw, plane = {"normal": normal}, ["--normal", cli_text(normal)]
        else:
            radii, b = (rng.randint(1, 5), rng.randint(1, 5)), rng.uniform(-2, 2)
            kw = {"radii": radii, "b": b}
            plane = ["--radii", ",".join(map(cli_text, radii)), "--impact-parameter", repr(b)]
        text = [cli_text(x) for x in v]
        cli = ["solve", "-m", ",".join(map(cli_text, m)), "-v", ",".join(text), *plane]
        cli += ["-e", cli_text(e)] if e is not None else []
        from conftest import run

        status, out, err = run(*cli, "--format", "json")
        if status != 0:
            with pytest.raises(collide.CollideError) as refused:
                collide.solve(m=m, v=v, e=e, **kw)
            assert str(refused.value) == cli_error(*cli)
            continue
        r = collide.solve(m=m, v=v, e=e, **kw)
        assert r.to_dict() == json.loads(out), cli
        assert r.dim == 2 and ('fin' not in r or len(r.fin) == 2)


def test_units_and_the_lecture_in_words():
    """A 4-ton SUV at 60 mph and a 1-ton VW at 10 mph: the CLI keeps the units typed."""
    r = collide.solve(m=("4 ton", "1 ton"), v=("60 mph", "10 mph"), e="2/3")
    _, data = cli_json("solve", "-m", "4 ton,1 ton", "-v", "60 mph,10 mph", "-e", "2/3")
    assert r.to_dict() == data
    # FIN = (1+e) V_COM - e V_IN with V_COM = 50: (250/3 - 40, 250/3 - 20/3) = (130/3, 230/3).
    assert r.fin == [float(Fraction(130, 3)), float(Fraction(230, 3))]


@pytest.mark.parametrize(
    "kwargs, cli",
    [
        ({"m": (-1, 1), "v": (1, 0)}, ["solve", "-m", "-1,1", "-v", "1,0"]),
        ({"m": (1, 1), "v": (1, 0), "e": -1}, ["solve", "-m", "1,1", "-v", "1,0", "-e", "-1"]),
        ({"m": ("4 parsec", 1), "v": (1, 0)}, ["solve", "-m", "4 parsec,1", "-v", "1,0"]),
        ({"m": (1, 1), "v": (1, 0), "frame": "moon"}, ["solve", "-m", "1,1", "-v", "1,0", "--frame", "moon"]),
        ({"m": ("x", 1), "v": (1, 0)}, ["solve", "-m", "x,1", "-v", "1,0"]),
        (
            {"m": (2, 1), "v": ("6 m/s @ 30deg", (0, 0)), "normal": "45deg", "exact": True},
            ["solve", "-m", "2,1", "-v", "6 m/s @ 30deg,(0,0)", "--normal", "45deg", "--exact"],
        ),
    ],
)
def test_refusals_carry_the_cli_message(kwargs, cli):
    with pytest.raises(collide.CollideError) as refused:
        collide.solve(**kwargs)
    assert str(refused.value) == cli_error(*cli)
    assert isinstance(refused.value, ValueError)


def test_refusals_of_python_values():
    """Values Python has and the command line cannot be typed: refused by the module, naming
    the keyword and the item."""
    for kwargs, words in [
        ({"m": (1, float("nan")), "v": (1, 0)}, "m[1]: NaN is not a number"),
        ({"m": (1, 1), "v": (float("inf"), 0)}, "v[0]: inf is not a number"),
        ({"m": (True, 1), "v": (1, 0)}, "m[0]: expected a number or text, got the bool True"),
        ({"m": (1, 1), "v": ((1, float("nan")), (0, 0))}, "v[0][1]: NaN is not a number"),
        ({"m": (1, 1), "v": (1, 0), "b": object()}, "b: expected a number or text, got <object"),
    ]:
        with pytest.raises(collide.CollideError) as refused:
            collide.solve(**kwargs)
        assert str(refused.value).startswith(words), str(refused.value)


@pytest.mark.parametrize(
    "kwargs, cli",
    [
        ({"m": (1, 1, 1), "v": (1, 0)}, ["-m", "1,1,1", "-v", "1,0"]),
        ({"m": (1, 1)}, ["-m", "1,1"]),
        ({"m": 4, "v": (1, 0)}, ["-m", "4", "-v", "1,0"]),
        ({"m": (1, 1), "v": ((1, 2, 3), (0, 0))}, ["-m", "1,1", "-v", "(1,2,3),(0,0)"]),
    ],
)
def test_refusals_of_shapes_are_the_cli_message(kwargs, cli):
    """A list of the wrong length is the command's to refuse (it takes N bodies and vectors in
    space): the same message."""
    with pytest.raises(collide.CollideError) as refused:
        collide.solve(**kwargs)
    assert unwrapped(str(refused.value)) == cli_error("solve", *cli, "--format", "json")


def test_display():
    r = collide.solve(m=(4, 1), v=(60, 10))
    html = r._repr_html_()
    assert "<table" in html and "<th style=\"text-align:left\">crunch</th>" in html
    assert "1000.0" in html
    assert repr(r).startswith("Report(restitution, inertia, in, com, fin")
    assert r.energy._repr_html_().count("<tr>") == 5
    with pytest.raises(AttributeError):
        r.no_such_key


def test_a_general_tensor_is_the_cli_json():
    """--inertia M11,M12;M21,M22 instead of the masses, in the COM frame, binary64 and exact."""
    for exact in (False, True):
        r = collide.solve(inertia="4,1;1,2", v=(60, 10), e="1/2", frame="com", exact=exact)
        cli = ["solve", "--inertia", "4,1;1,2", "-v", "60,10", "-e", "1/2", "--frame", "com"]
        out, data = cli_json(*cli, *["--exact"] * exact)
        assert r.to_dict() == data and r.to_json() == out
