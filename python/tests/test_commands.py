"""collide.solve's knowns and unknowns, rigid impacts, frames, plot, track, contact, pi and scenes
against the command line's `--format json` (issue 44).

Each function turns its keywords into the command's flags (`hit_at=` is `--hit-at`) and runs the
command's own parser and renderer, so the tests type every case to the binary independently:
the docs' example commands word for word, and random cases of each kind. Where the answer is
known by hand (a homework problem's unknowns), the tests check it exactly with Fractions.
"""

import json
import random
import re
import shlex
from fractions import Fraction
from pathlib import Path

import pytest

import collide
from conftest import ROOT, cli_error, run, unwrapped

COMMANDS = ("solve", "frames", "track", "contact", "pi", "scene")
SHORT = {"-m": "m", "-v": "v", "-e": "e", "-x": "x"}
# Measured wall-clock times: the only numbers two runs of one command do not share.
CLOCKS = {"seconds", "ns_per_collision", "run_seconds", "wall_seconds"}


def without_clocks(value):
    if isinstance(value, dict):
        return {k: without_clocks(v) for k, v in value.items() if k not in CLOCKS}
    if isinstance(value, list):
        return [without_clocks(v) for v in value]
    return value


def keywords(words):
    """A command line's words after `collide COMMAND` as (positional, keywords): `-m X` is
    `m=X`, `--hit-at X` is `hit_at=X`, a flag with no value `True`."""
    positional, kw = [], {}
    i = 0
    while i < len(words):
        w = words[i]
        if w in SHORT:
            kw[SHORT[w]] = words[i + 1]
            i += 2
        elif w.startswith("--"):
            name = w[2:].replace("-", "_")
            if i + 1 == len(words) or words[i + 1].startswith("--"):
                kw[name] = True
                i += 1
            else:
                kw[name] = words[i + 1]
                i += 2
        else:
            positional.append(w)
            i += 1
    return positional, kw


def doc_commands():
    """Every `$ collide COMMAND ...` example of the docs that prints one report: no table
    (`--vary`), no file written, one scene file, no usage error shown on purpose."""
    found = set()
    for page in [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]:
        for line in page.read_text().splitlines():
            m = re.match(r"^\$ collide (\w+) (.*)$", line.strip())
            if not m or m.group(1) not in COMMANDS:
                continue
            try:
                words = shlex.split(m.group(2))
            except ValueError:
                continue
            if any(w in ("--vary", "-o", "--plot", "--log", "--term") or "*" in w for w in words):
                continue
            if m.group(1) == "scene" and len(words) != 1:
                continue
            words = [w for i, w in enumerate(words) if w != "--format" and (i == 0 or words[i - 1] != "--format")]
            positional, _ = keywords(words)
            if m.group(1) not in ("pi", "scene") and positional:
                continue  # a usage error shown on purpose (`-m 4 1`): no keywords say it
            found.add((m.group(1), tuple(words)))
    return sorted(found)


DOCS = doc_commands()


def test_the_docs_have_examples_of_each_command():
    assert {c for c, _ in DOCS} == set(COMMANDS), DOCS
    assert len(DOCS) >= 60, len(DOCS)


def same_as_cli(command, words):
    """The module's report for `collide COMMAND WORDS...` equals the command's JSON (or its
    refusal the command's message)."""
    positional, kw = keywords(list(words))
    status, out, err = run(command, *words, "--format", "json")
    call = getattr(collide, command)
    if status == 2:
        with pytest.raises(collide.CollideError) as refused:
            call(*positional, **kw)
        assert unwrapped(str(refused.value)) == cli_error(command, *words, "--format", "json"), words
        return None
    r = call(*positional, **kw)
    assert r.status == status, (words, r.status, status)
    assert without_clocks(r.to_dict()) == without_clocks(json.loads(out)), words
    if without_clocks(json.loads(out)) == json.loads(out):
        assert r.to_json() == out
    return r


@pytest.mark.parametrize("command, words", DOCS, ids=lambda x: " ".join(x) if isinstance(x, tuple) else x)
def test_every_doc_example_is_the_cli_json(command, words):
    if command == "pi" and int(words[0]) > 6 and "--no-simulate" not in words:
        words = (*words, "--no-simulate")
    same_as_cli(command, words)


def homework(rng):
    """A collision on a rail with exact values: masses, velocities, e, and its finals by the
    impulse form FIN = (1 + e) V_COM - e V_IN, V_COM = (m1 v1 + m2 v2) / (m1 + m2)."""
    m1, m2 = Fraction(rng.randint(1, 20), rng.randint(1, 4)), Fraction(rng.randint(1, 20))
    v1, v2 = Fraction(rng.randint(1, 30)), Fraction(rng.randint(-30, 0), rng.randint(1, 3))
    e = Fraction(rng.randint(1, 9), 10)
    v_com = (m1 * v1 + m2 * v2) / (m1 + m2)
    f1, f2 = (1 + e) * v_com - e * v1, (1 + e) * v_com - e * v2
    return {"m1": m1, "m2": m2, "v1": v1, "v2": v2, "e": e, "f1": f1, "f2": f2}


def text(x):
    return x if isinstance(x, str) else f"{x.numerator}/{x.denominator}"


@pytest.mark.parametrize("unknowns", [("v1", "e"), ("m2", "f1"), ("m1", "v2"), ("f1", "f2"), ("v2", "f2"), ("m2", "e")])
def test_random_unknowns_are_the_cli_json_and_the_hand_values(unknowns):
    """Two of m1, m2, v1, v2, f1, f2, e as '?', the rest given: the report is the CLI's JSON,
    and `solved` holds the hidden values exactly (they were made by the impulse form)."""
    rng = random.Random(",".join(unknowns))  # a str seed is the same in every run
    solved = 0
    for _ in range(8):
        case = homework(rng)
        given = {k: ("?" if k in unknowns else v) for k, v in case.items()}
        kw = dict(
            m=(given["m1"], given["m2"]),
            v=(given["v1"], given["v2"]),
            fin=(given["f1"], given["f2"]),
            exact=True,
        )
        cli = ["solve", "-m", f"{text(given['m1'])},{text(given['m2'])}",
               "-v", f"{text(given['v1'])},{text(given['v2'])}",
               "--fin", f"{text(given['f1'])},{text(given['f2'])}", "--exact"]
        if "e" not in unknowns:
            kw["e"] = given["e"]
            cli += ["-e", text(given["e"])]
        status, out, err = run(*cli, "--format", "json")
        if status != 0:
            with pytest.raises(collide.CollideError) as refused:
                collide.solve(**kw)
            assert str(refused.value) == cli_error(*cli)
            continue
        r = collide.solve(**kw)
        assert r.to_dict() == json.loads(out) and r.to_json() == out, cli
        for name in unknowns:
            assert r.solved[name] == case[name], (name, r.solved.to_dict(), case)
        solved += 1
    assert solved == 8, solved


def test_knowns_by_hand():
    """The knowns of `collide solve --help`, each against the hand value (docs/homework.md):
    - 3 kg at 6 m/s hits 2 kg at rest with an impulse of 12 N s: f1 = 6 - 12/3 = 2,
      f2 = 12/2 = 6 m/s, e = (6 - 2) / 6 = 2/3;
    - 1 kg and 2 kg at rest part with 48 J released: momentum 0 gives f1 = -2 f2, and
      (1/2)(1)(4 f2^2) + (1/2)(2) f2^2 = 3 f2^2 = 48, so |f2| = 4, |f1| = 8 (two solutions);
    - 2 kg at 5 m/s, 3 kg at rest, separating at 2 m/s: f2 - f1 = 2 and 2 f1 + 3 f2 = 10,
      so f1 = 4/5, f2 = 14/5, e = 2/5."""
    r = collide.solve(m=("3 kg", "2 kg"), v=("6 m/s", "0 m/s"), impulse="12 N s", exact=True)
    assert r.fin == [2, 6] and r.restitution == Fraction(2, 3), r.to_dict()
    two = collide.solve(m=("1 kg", "2 kg"), v=(0, "0 m/s"), fin=("?", "?"), released="48 J")
    fins = sorted(tuple(s["fin"]) for s in two.to_dict()["solutions"])
    assert fins == [(-8.0, 4.0), (8.0, -4.0)]
    s = collide.solve(m=("2 kg", "3 kg"), v=("5 m/s", 0), separation_speed="2 m/s", exact=True)
    assert s.fin == [Fraction(4, 5), Fraction(14, 5)] and s.restitution == Fraction(2, 5)


def test_contradicting_givens_are_status_1_as_the_cli():
    """m = (4, 1), V_IN = (60, 10) elastic gives FIN = (40, 90); FIN = (40, 80) with e = 1
    contradicts momentum: the command exits 1 with `"consistent": false`, and so the report."""
    cli = ["solve", "-m", "4,1", "-v", "60,10", "--fin", "40,80", "-e", "1"]
    status, out, _ = run(*cli, "--format", "json")
    assert status == 1
    r = collide.solve(m=(4, 1), v=(60, 10), fin=(40, 80), e=1)
    assert r.status == 1 and r.consistent is False and r.to_dict() == json.loads(out)
    assert r._repr_svg_() is None


LONG = ["rod {}", "door {}", "box ({},2)"]
ROUND = ["disk {}", "ring {}", "sphere {}"]


def rigid_case(rng):
    """A random homework impact: a point hits a shape, free or pivoted, at a random place,
    maybe with friction and a law, or joining it."""
    size = rng.choice([1, 2, "1/2", 0.75])
    long = rng.random() < 0.6
    kw = {"m": (rng.choice([1, "1/3", 0.05]), rng.choice([1, 4, "2/3"])),
          "v": (rng.choice([3, "(3,-1)", 5]), 0),
          "target": rng.choice(LONG if long else ROUND).format(size)}
    if rng.random() < 0.5:
        kw["pivot"] = rng.choice(["end", "centre", (0, Fraction(-1, 4))] if long else ["centre", (0, Fraction(-1, 8))])
    if "pivot" in kw or rng.random() < 0.6:
        kw["hit_at"] = rng.choice(["end", Fraction(rng.randint(-4, 4), 8), 0.25] if long else [0, Fraction(1, 5), 0.25])
    if rng.random() < 0.2:
        kw["join"] = True
    else:
        if rng.random() < 0.3:
            kw["friction"] = rng.choice([0, Fraction(1, 2), 1])
            if rng.random() < 0.5:
                kw["law"] = rng.choice(["poisson", "newton", "stronge"])
        if rng.random() < 0.5:
            kw["e"] = rng.choice([0, "1/2", 1])
    kw["exact"] = long and rng.random() < 0.5
    return kw


def words_of(kw):
    """The command line a user types for `kw` (independently of the module)."""
    def value(x):
        if isinstance(x, tuple):
            return "(" + ",".join(value(c) for c in x) + ")"
        if isinstance(x, Fraction):
            return f"{x.numerator}/{x.denominator}"
        return str(x)

    out = []
    for k, x in kw.items():
        flag = {"m": "-m", "v": "-v", "e": "-e", "x": "-x"}.get(k, "--" + k.replace("_", "-"))
        if x is True:
            out.append(flag)
        elif x is False or x is None:
            continue
        elif isinstance(x, tuple) and k not in ("pivot", "normal"):
            out += [flag, ",".join(value(c) for c in x)]
        else:
            out += [flag, value(x)]
    return out


def test_random_rigid_impacts_are_the_cli_json():
    rng = random.Random(4421)
    solved = refused = 0
    for _ in range(60):
        kw = rigid_case(rng)
        words = words_of(kw)
        status, out, _ = run("solve", *words, "--format", "json")
        if status == 2:
            with pytest.raises(collide.CollideError) as e:
                collide.solve(**kw)
            assert unwrapped(str(e.value)) == cli_error("solve", *words, "--format", "json"), words
            refused += 1
            continue
        r = collide.solve(**kw)
        assert r.to_dict() == json.loads(out) and r.to_json() == out, words
        solved += 1
    assert solved >= 30 and refused >= 1, (solved, refused)


def test_rigid_exact_by_hand():
    """A unit point mass at 3 hits the end of a free rod of mass 4 and length 2 (docs/rigid.md):
    I = 4 * 2^2 / 12 = 4/3 about the centre, hit 1 from it: the rod's effective mass at its end
    is 1 / (1/4 + 1^2 / (4/3)) = 1, so the pair's is m_eff = 1 / (1/1 + 1/1) = 1/2, the
    elastic impulse J = (1 + e) m_eff 3 = 3, the ball stops (3 - J / 1 = 0) and the rod's
    centre moves at J / 4 = 3/4, spinning at -J * 1 / (4/3) = -9/4 (clockwise)."""
    r = collide.solve(m=(1, 4), v=(3, 0), target="rod 2", hit_at="end", exact=True)
    assert r.m_eff == Fraction(1, 2), r.to_dict()
    assert r.impulse.normal == 3 and r.fin[0].v == [0, 0] and r.fin[0].omega == 0
    assert r.fin[1].v == [Fraction(3, 4), 0] and r.fin[1].omega == Fraction(-9, 4)


def test_random_frames_are_the_cli_json():
    rng = random.Random(4422)
    for _ in range(20):
        kw = {"m": (rng.randint(1, 9), Fraction(rng.randint(1, 9), 2)),
              "v": (rng.randint(-20, 20), rng.uniform(-5, 5)),
              "e": rng.choice([0, "1/2", 1, None]),
              "reverse": rng.random() < 0.3, "exact": rng.random() < 0.3}
        if kw["exact"]:
            kw["v"] = (kw["v"][0], Fraction(kw["v"][1]))
        if rng.random() < 0.3:
            kw["frame"] = ["rest-in:1", "7"][: rng.randint(1, 2)]
        words = words_of({k: v for k, v in kw.items() if k != "frame"})
        for f in kw.get("frame", []):
            words += ["--frame", f]
        status, out, _ = run("frames", *words, "--format", "json")
        if status == 2:
            with pytest.raises(collide.CollideError) as e:
                collide.frames(**kw)
            assert unwrapped(str(e.value)) == cli_error("frames", *words, "--format", "json")
            continue
        r = collide.frames(**kw)
        assert r.to_dict() == json.loads(out), words


def test_random_tracks_and_contacts_are_the_cli_json():
    """Layouts of 1 to 4 bodies between walls: `collide track` and `collide contact`."""
    rng = random.Random(4423)
    for _ in range(12):
        n = rng.randint(1, 4)
        m = tuple(rng.choice([1, 2, 100, 0.5]) for _ in range(n))
        x = tuple(range(1, n + 1))
        v = tuple(rng.choice([0, -1, 1, 0.5]) for _ in range(n))
        kw = {"m": m, "x": x, "v": v, "left_wall": 0, "e": rng.choice([1, 0.5]), "until": 5}
        if rng.random() < 0.5:
            kw["right_wall"] = n + 1
        if rng.random() < 0.3:
            kw["gravity"] = 2
            kw.pop("right_wall", None)
        same_as_cli("track", words_of(kw))
        ckw = {"m": m, "x": tuple(2 * i for i in x), "v": v, "sizes": (1,) * n,
               "zeta": rng.choice([0, 0.2]), "until": 3}
        same_as_cli("contact", words_of(ckw))


def test_pi_counts_and_refusals():
    """pi N: the count spells pi to N digits after the point (3, 31, 314, 3141, 31415)."""
    for n in range(5):
        r = same_as_cli("pi", (str(n),))
        assert r.count == "31415"[: n + 1] and r.simulation.collisions == int(r.count)
    assert collide.pi(20, no_simulate=True).count == "314159265358979323846"
    with pytest.raises(collide.CollideError) as e:
        collide.pi(10001)
    assert unwrapped(str(e.value)) == cli_error("pi", "10001", "--format", "json")


@pytest.mark.parametrize("path", sorted(p.name for p in (ROOT / "scenarios").glob("*.toml")))
def test_every_scene_is_the_cli_json(path):
    """Every scene of scenarios/, by its full path on both sides (the report names it); a
    [sweep] scene, which writes a table, is refused by both with --format json."""
    full = str(ROOT / "scenarios" / path)
    r = same_as_cli("scene", (full,))
    assert r is None or r.scene == full


@pytest.mark.parametrize(
    "call, cli",
    [
        (lambda: collide.solve(m=(1, 1), v=(1, 0), foo=3), ["solve", "-m", "1,1", "-v", "1,0", "--foo", "3"]),
        (lambda: collide.solve(m=(1, 1)), ["solve", "-m", "1,1"]),
        (lambda: collide.solve(m=(1, 1), v=("?", "?"), fin=(1, "?")), ["solve", "-m", "1,1", "-v", "?,?", "--fin", "1,?"]),
        (lambda: collide.solve(m=(1, 2), v=(3, 0), target="rod -2"), ["solve", "-m", "1,2", "-v", "3,0", "--target", "rod -2"]),
        (lambda: collide.solve(m=(1, 2), v=(3, 0), target="rod 2", law="magic"), ["solve", "-m", "1,2", "-v", "3,0", "--target", "rod 2", "--law", "magic"]),
        (lambda: collide.track(m=(1, 2), x=(1,), v=(0, 0)), ["track", "-m", "1,2", "-x", "1", "-v", "0,0"]),
        (lambda: collide.contact(m=(1, 1), x=(0, 0.5), v=(1, 0), sizes=(1, 1)), ["contact", "-m", "1,1", "-x", "0,0.5", "-v", "1,0", "--sizes", "1,1"]),
        (lambda: collide.frames(m=(1, 1), v=((1, 0), (0, 0)), frame="moon"), ["frames", "-m", "1,1", "-v", "(1,0),(0,0)", "--frame", "moon"]),
        (lambda: collide.scene("no-such-scene.toml"), ["scene", "no-such-scene.toml"]),
    ],
)
def test_refusals_are_the_cli_message(call, cli):
    with pytest.raises(collide.CollideError) as e:
        call()
    assert unwrapped(str(e.value)) == cli_error(*cli, "--format", "json")


def test_what_the_module_does_not_write():
    for kw, words in [({"output": "x.svg"}, "output="), ({"format": "text"}, "format=")]:
        with pytest.raises(collide.CollideError) as e:
            collide.track(m=(1,), x=(1,), v=(0,), left_wall=0, **kw)
        assert str(e.value).startswith(words)
