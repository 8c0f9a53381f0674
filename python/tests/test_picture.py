"""Report._repr_svg_ (Jupyter's picture of a report) and collide.plot against `collide plot`: the
same SVG text for the same case, and a valid SVG document."""

import random
import xml.etree.ElementTree as ET
from fractions import Fraction

import collide
from conftest import run
from test_commands import words_of

SVG = "{http://www.w3.org/2000/svg}svg"


def cli_svg(words):
    status, out, err = run("plot", *words)
    assert status == 0, err
    return out


def valid(svg):
    root = ET.fromstring(svg)
    assert root.tag == SVG, root.tag
    assert float(root.get("width")) > 0 and float(root.get("height")) > 0
    return root


def test_random_cases_draw_what_collide_plot_draws():
    """Cases on a rail (units, fractions, frames), in the plane, and rigid impacts: the picture
    of `collide.solve(...)` is `collide plot` of the same flags, byte for byte."""
    rng = random.Random(4441)
    drawn = 0
    for i in range(24):
        kind = i % 3
        if kind == 0:
            kw = {"m": (rng.randint(1, 9), Fraction(rng.randint(1, 9), 3)), "v": (rng.randint(-9, 30), rng.uniform(-9, 9)),
                  "e": rng.choice([0, "1/2", 1]), "frame": rng.choice(["lab", "com", "rest-in:2"])}
        elif kind == 1:
            kw = {"m": (1, rng.randint(1, 4)), "v": ((rng.randint(1, 5), rng.randint(-2, 2)), (0, 0)),
                  "normal": rng.choice(["30deg", (1, 1), "N30E"])}
        else:
            kw = {"m": (1, rng.choice([1, 4])), "v": (3, 0), "target": rng.choice(["rod 2", "door 1"]),
                  "hit_at": rng.choice(["end", "1/2"])}
        report = collide.solve(**kw, exact=kind == 0 and rng.random() < 0.5)
        svg = report._repr_svg_()
        assert svg == cli_svg(words_of(kw)), kw
        valid(svg)
        assert collide.plot(**kw) == svg
        drawn += 1
    assert drawn == 24


def test_case_a_picture_and_frames():
    """Lecture Fig. 1.3 (case A): the velocity plane of solve and of frames is collide plot's."""
    svg = collide.solve(m=(4, 1), v=(60, 10), e=1)._repr_svg_()
    assert svg == cli_svg(["-m", "4,1", "-v", "60,10", "-e", "1"])
    root = valid(svg)
    assert len(list(root.iter())) > 20
    assert collide.frames(m=(4, 1), v=(60, 10), e=1, frame="7")._repr_svg_() == svg
    assert collide.plot(m=(4, 1), v=(60, 10), kind="minkowski") == cli_svg(["-m", "4,1", "-v", "60,10", "--kind", "minkowski"])


def test_reports_collide_plot_does_not_draw_have_no_picture():
    """No picture rather than another case's: unknowns, knowns that change the collision, given
    values that contradict each other, tracks and counts."""
    assert collide.solve(m=(4, "?"), v=(60, 10), fin=(40, 90))._repr_svg_() is None
    assert collide.solve(m=("3 kg", "2 kg"), v=("6 m/s", "0 m/s"), impulse="12 N s")._repr_svg_() is None
    assert collide.solve(m=(4, 1), v=(60, 10), fin=(40, 80), e=1)._repr_svg_() is None
    assert collide.track(m=(1, 100), x=(1, 2), v=(0, -1), left_wall=0)._repr_svg_() is None
    assert collide.pi(2, no_simulate=True)._repr_svg_() is None
