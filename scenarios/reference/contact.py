#!/usr/bin/env python3
"""Independent reference numbers for the `[contact]` scenes (not run by the tests).

Integrates the same contact laws with SciPy's Radau IIA (order 5, implicit) and, where the
stiffness allows it in minutes, DOP853 (order 8, explicit), at rtol 1e-13, restarting at every
contact opening and closing found by SciPy's event location, and prints the final velocities of
both and their largest difference. Nothing is shared with collide's code.

    pip install scipy   # once
    python3 scenarios/reference/contact.py
"""
import math

from scipy.integrate import solve_ivp


def run(m, x, s, v, k, c, wall=None, law="linear", method="Radau", t_end=50.0, rtol=1e-13):
    """m, x, s, v: masses, centres, sizes, velocities; k, c: pair law; wall: (L, R, kw, cw)."""
    n = len(m)
    left, right, kw, cw = wall or (None, None, k, c)
    slots = []  # (kind, index, k, c)
    if left is not None:
        slots.append(("L", 0, kw, cw))
    slots += [("P", i, k, c) for i in range(n - 1)]
    if right is not None:
        slots.append(("R", n - 1, kw, cw))

    # The state holds displacements u from the initial positions x (not positions), so that an
    # overlap that starts at 0 grows from 0 in full precision: with positions near 1, a middle
    # ball's first 1e-20 of motion rounded away, its overlap read 0 at both ends of a step, and
    # its contact opened and closed at t = 0 for ever.
    base = {}
    for kind, i, _, _ in slots:
        if kind == "P":
            base[(kind, i)] = (s[i] + s[i + 1]) / 2 - (x[i + 1] - x[i])
        elif kind == "L":
            base[(kind, i)] = left - (x[0] - s[0] / 2)
        else:
            base[(kind, i)] = x[n - 1] + s[n - 1] / 2 - right

    def overlap(slot, y):
        kind, i, _, _ = slot
        u, v = y[:n], y[n:]
        d0 = base[(kind, i)]
        if kind == "P":
            return d0 + (u[i] - u[i + 1]), v[i] - v[i + 1]
        if kind == "L":
            return d0 - u[0], -v[0]
        return d0 + u[n - 1], v[n - 1]

    def force(slot, d, rate):
        _, _, kk, cc = slot
        if law == "linear":
            return kk * d + cc * rate
        return kk * max(d, 0.0) ** 1.5 * (1 + cc * rate)

    def rhs(active):
        def f(t, y):
            a = [0.0] * n
            for j, slot in enumerate(slots):
                if not active[j]:
                    continue
                d, rate = overlap(slot, y)
                F = force(slot, d, rate)
                kind, i, _, _ = slot
                if kind == "P":
                    a[i] -= F / m[i]
                    a[i + 1] += F / m[i + 1]
                elif kind == "L":
                    a[0] += F / m[0]
                else:
                    a[n - 1] -= F / m[n - 1]
            return list(y[n:]) + a

        return f

    def gate(j, closing):
        def g(t, y):
            d, rate = overlap(slots[j], y)
            if not closing:
                return d
            if law == "linear":
                return min(d, d + slots[j][3] / slots[j][2] * rate)
            return min(d, d * (1 + slots[j][3] * rate))

        g.terminal = True
        g.direction = -1 if closing else 1
        return g

    y = [0.0] * n + list(v)
    t = 0.0
    # A contact pushes at the start if the bodies overlap, or touch and close (touching at rest,
    # the cradle's middle ball, is not yet a contact: its opening is found as an event).
    active = [overlap(sl, y)[0] > 0 or (overlap(sl, y)[0] == 0 and overlap(sl, y)[1] > 0)
              for sl in slots]
    events = 0
    while t < t_end:
        if not any(active):
            # Free flight to the next opening, exactly.
            waits = []
            for j, sl in enumerate(slots):
                d, rate = overlap(sl, y)
                if rate > 0:
                    waits.append((-d / rate, j))
            if not waits:
                break
            w, j = min(waits)
            y = [y[i] + y[n + i] * w for i in range(n)] + y[n:]
            t += w
            active[j] = True
            continue
        evs = [gate(j, active[j]) for j in range(len(slots))]
        sol = solve_ivp(rhs(active), (t, t_end), y, method=method, rtol=rtol,
                        atol=1e-16, events=evs, dense_output=False)
        t, y = sol.t[-1], list(sol.y[:, -1])
        hit = [j for j, te in enumerate(sol.t_events) if len(te)]
        if not hit:
            break
        for j in hit:
            active[j] = not active[j]
        events += 1
    return y[n:], t


SCENES = {
    "contact-backstop-1e2, 1e4": [
        (f"wall k {kw:g}", dict(m=[1, 1], x=[0, 1], s=[1, 1], v=[1, 0], k=1, c=0.4,
                                wall=(None, 1.5, kw, 2 * math.sqrt(kw * 1.0))))
        for kw in (1e2, 1e4)
    ],
    "contact-cradle-linear": [("", dict(m=[1, 1, 1], x=[0, 1, 2], s=[1, 1, 1], v=[1, 0, 0],
                                         k=1, c=0))],
    "contact-cradle-hertz": [("", dict(m=[1, 1, 1], x=[0, 1, 2], s=[1, 1, 1], v=[1, 0, 0],
                                        k=1, c=0, law="hertz"))],
    "contact-superball": [("", dict(m=[1, 0.1], x=[0.5, 1.5], s=[1, 1], v=[-1, -1], k=1, c=0,
                                     wall=(0, None, 1e6, 0)))],
}

if __name__ == "__main__":
    for name, cases in SCENES.items():
        for label, case in cases:
            a, ta = run(**case, method="Radau")
            line = f"{name} {label}: v = {[f'{q:.15g}' for q in a]} (Radau), t = {ta:.12g}"
            wall = case.get("wall")
            if wall is None or wall[2] <= 1e4:
                b, _ = run(**case, method="DOP853")
                diff = max(abs(p - q) for p, q in zip(a, b))
                line += f"; DOP853 {[f'{q:.15g}' for q in b]}, differ by {diff:.1e}"
            print(line, flush=True)
