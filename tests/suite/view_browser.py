"""Drives `collide view`'s page in headless Chromium for tests/suite/view.rs, which checks what it
reports: python3 view_browser.py PAGE.html PLAN.json prints one JSON object of what the page did.

The plan: `cases` (inputs to type: m1, m2, v1, v2, e, inertia), `drag` (a case, and a point of
the velocity plane to drag IN to), `keys` (arrow keys pressed on the plane), `frame` (a frame
to switch to, sampling the animation), `reverse`, `screenshot` (where to save a picture of the
plane, and points to probe for colours), `stack` (presets and inputs of the superball stack),
`plane` (two pucks: `cases` to type, an arrow `drag`, `keys`, a `screenshot` of the pucks),
`steps` (scripted actions and reads, for the hostile review's defects: see run_steps).
Needs Playwright for Python and a Chromium (COLLIDE_CHROMIUM, default /usr/bin/chromium); the
browser is launched with a fresh profile and no network use of its own."""
import collections, json, math, operator, os, struct, sys, tempfile, time, zlib

from playwright.sync_api import sync_playwright

CHROMIUM_FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                  "--disable-background-networking", "--disable-component-update", "--disable-sync"]


def png_pixels(data):
    """(width, height, rows of (r, g, b)) of an 8-bit RGB or RGBA, non-interlaced PNG."""
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    at, idat, width = 8, b"", 0
    while at < len(data):
        n, kind = struct.unpack(">I4s", data[at:at + 8])
        body = data[at + 8:at + 8 + n]
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            assert depth == 8 and colour in (2, 6) and interlace == 0, (depth, colour, interlace)
            channels = 3 if colour == 2 else 4
        elif kind == b"IDAT":
            idat += body
        at += 12 + n
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, prev, i = [], bytearray(stride), 0
    for _ in range(height):
        f, line = raw[i], bytearray(raw[i + 1:i + 1 + stride])
        i += 1 + stride
        # The filters of PNG (RFC 2083, 6.2-6.6), each byte from the one `channels` before it
        # (a), above it (b) and above that (c), modulo 256. Up needs no byte of its own row, so
        # it is done at once (map, in C); the others byte by byte.
        if f == 2:
            line = bytearray(map(MOD_256.__getitem__, map(operator.add, line, prev)))
        elif f == 1:
            for x in range(channels, stride):
                line[x] = (line[x] + line[x - channels]) & 255
        elif f == 3:
            for x in range(stride):
                a = line[x - channels] if x >= channels else 0
                line[x] = (line[x] + ((a + prev[x]) >> 1)) & 255
        elif f == 4:
            for x in range(stride):
                if x < channels:
                    # a = c = 0: the predictor is b.
                    line[x] = (line[x] + prev[x]) & 255
                    continue
                a, b, c = line[x - channels], prev[x], prev[x - channels]
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append([tuple(line[x:x + 3]) for x in range(0, stride, channels)])
        prev = line
    return width, height, rows


# n modulo 256 for the sums of two bytes.
MOD_256 = bytes(n & 255 for n in range(511))


def colour_counts(rows):
    """How many pixels there are of each colour, in one pass over the picture."""
    return collections.Counter(px for row in rows for px in row)


def count_near(counts, rgb, tol=40):
    """How many pixels are `near` `rgb`: `near` asked once per colour of `colour_counts`."""
    return sum(n for px, n in counts.items() if near(px, rgb, tol))


def near(rgb, target, tol=40):
    return all(abs(a - b) <= tol for a, b in zip(rgb, target))


def nearest(rows, at, rgb):
    """The distance from `at` (pixels) to the nearest pixel of colour `rgb` within 12 pixels, or None."""
    cx, cy = at
    h, w = len(rows), len(rows[0])
    best = None
    for y in range(max(0, int(cy) - 12), min(h, int(cy) + 13)):
        for x in range(max(0, int(cx) - 12), min(w, int(cx) + 13)):
            if near(rows[y][x], rgb):
                dist = ((x + 0.5 - cx) ** 2 + (y + 0.5 - cy) ** 2) ** 0.5
                best = dist if best is None else min(best, dist)
    return best


# Text fields typed in order, in one call: each focused, its value set and its `input` event
# dispatched (what page.fill does; the two-body case and the plane solve and redraw in that
# handler, at once). A field not shown, disabled or read-only fails, as page.fill would.
FILL = """pairs => { for (const [sel, value] of pairs) {
  const f = document.querySelector(sel);
  if (!f || f.disabled || f.readOnly || !f.getClientRects().length) throw new Error(sel + ' is not editable');
  f.focus();
  f.value = value;
  f.dispatchEvent(new Event('input', {bubbles: true})); } }"""


def drive_plane(page, plan):
    """The plane panel: cases typed, an arrow's tip dragged with the mouse, keys, a screenshot."""
    text = lambda sel: page.eval_on_selector(sel, "e => e.textContent")
    out = {}

    def set_case(case):
        line = "normal" if case.get("normal") else "disks" if case.get("r1") else "none"
        page.check('input[name="p-line"][value="%s"]' % line)
        page.evaluate(FILL, [["#p-" + field, case.get(field, "elastic" if field == "e" else "")]
                             for field in ("m1", "m2", "v1", "v2", "e", "normal", "r1", "r2", "b")
                             if field in case or field in ("m1", "m2", "v1", "v2", "e")])
        page.select_option("#p-frame", case.get("frame", "lab"))
        return {"state": text("#plane-state"), "command": text("#plane-command"), "scene": text("#plane-scene"),
                "error": page.eval_on_selector("#plane-error", "e => e.hidden ? '' : e.textContent")}

    def pucks_map():
        return page.eval_on_selector("#pucks-svg", """s => { const r = s.getBoundingClientRect();
            return Object.assign(JSON.parse(s.dataset.map), {left: r.left, top: r.top, width: r.width, vb: s.viewBox.baseVal.width}); }""")

    def screen(m, i, v):
        """The client point of velocity v drawn from body i's centre (v in the frame on screen)."""
        k = m["width"] / m["vb"]
        return m["left"] + (m["c"][i][0] + m["s"] * v[0]) * k, m["top"] + (m["c"][i][1] - m["s"] * v[1]) * k

    def centred():
        # At once: the page scrolls smoothly (CSS), and the map is read right after.
        page.eval_on_selector("#pucks-svg", "s => s.scrollIntoView({block: 'center', behavior: 'instant'})")

    out["cases"] = [set_case(c) for c in plan.get("cases", [])]
    if "drag" in plan:
        d = plan["drag"]
        before = set_case(d["case"])
        centred()
        m = pucks_map()
        state = json.loads(before["state"])
        i = d["body"]
        page.evaluate("collideView.planeTimings.length = 0")
        page.mouse.move(*screen(m, i, state["in"][i]))
        page.mouse.down()
        page.mouse.move(*screen(m, i, d["to"]), steps=d.get("steps", 30))
        page.mouse.up()
        out["drag"] = {"before": before["state"], "after": text("#plane-state"), "command": text("#plane-command"),
                       "map": m, "timings": page.evaluate("collideView.planeTimings")}
    if "keys" in plan:
        page.focus("#pucks-svg")
        m = pucks_map()
        for key in plan["keys"]:
            page.keyboard.press(key)
        out["keys"] = {"state": text("#plane-state"), "map": m}
    if "screenshot" in plan:
        sh = plan["screenshot"]
        seen = set_case(sh["case"])
        page.evaluate("document.activeElement && document.activeElement.blur()")
        centred()
        m = pucks_map()
        png = page.locator("#pucks-svg").screenshot(path=sh["path"])
        w, h, rows = png_pixels(png)
        k = w / m["vb"]
        every = colour_counts(rows)
        counts = {name: count_near(every, rgb) for name, rgb in sh["colours"].items()}
        probes = []
        for probe in sh["probes"]:
            c = m["c"][probe["body"]]
            if "velocity" in probe:
                at = (c[0] + m["s"] * probe["velocity"][0], c[1] - m["s"] * probe["velocity"][1])
            else:
                a = math.radians(probe["rim_deg"])
                r = m["radii"][probe["body"]]
                at = (c[0] + r * math.cos(a), c[1] - r * math.sin(a))
            probes.append(nearest(rows, (at[0] * k, at[1] * k), sh["colours"][probe["colour"]]))
        white = count_near(every, (255, 255, 255), 8)
        out["screenshot"] = {"width": w, "height": h, "counts": counts, "probes": probes, "white": white,
                             "map": m, "state": seen["state"], "error": seen["error"]}
    return out


# What an animation of the two-body case changes every frame: the velocity plane's data (its
# map and the frame's w, drawn between the two frames during a shift), the state and the dual
# panel's time.
SHOWN = """JSON.stringify([document.getElementById('plane-svg').dataset, document.getElementById('state').textContent,
  collideView.time()])"""

# Until SHOWN is the same over ten frames in a row, or `ms` milliseconds have passed.
SETTLED = """ms => new Promise(done => {
  const t0 = performance.now();
  let last = null, same = 0;
  const tick = () => {
    const now = %s;
    same = now === last ? same + 1 : 0;
    last = now;
    if (same >= 10 || performance.now() - t0 >= ms) done([same >= 10, performance.now() - t0]);
    else requestAnimationFrame(tick);
  };
  requestAnimationFrame(tick); })""" % SHOWN


def settled(page, ms):
    """Until the page is still (nothing of SHOWN changed over ten frames: no shift of a frame
    under way), or `ms` milliseconds have passed, as the fixed wait of `ms` did before."""
    still, waited = page.evaluate(SETTLED, ms)
    print("settled: %s after %.0f of %d ms" % ("still" if still else "not still", waited, ms), file=sys.stderr)


def run_steps(page, steps, errors):
    """Scripted checks in one page session: each step one action (`fill`, `select`, `check`,
    `uncheck`, `press` [selector, key, times], `drag_tip` {body, by (picture units), steps},
    `drag_in` {by, steps} (IN on the velocity plane), `hover` selector, `wait` milliseconds) and optionally `read` [name, JS function]: what the function returns, with
    the page errors seen so far, under `name` in the result. A `wait` (the plans wait out the
    700 ms shift of a frame change) ends when the page is still (`settled`), at most after
    its milliseconds, as before."""
    out = {}
    for step in steps:
        if "fill" in step:
            page.fill(step["fill"][0], step["fill"][1])
        if "select" in step:
            page.select_option(step["select"][0], step["select"][1])
        if "check" in step:
            page.check(step["check"])
        if "uncheck" in step:
            page.uncheck(step["uncheck"])
        if "press" in step:
            sel, key, times = step["press"]
            page.focus(sel)
            for _ in range(times):
                page.keyboard.press(key)
        if "drag_tip" in step:
            d = step["drag_tip"]
            page.eval_on_selector("#pucks-svg", "s => s.scrollIntoView({block: 'center', behavior: 'instant'})")
            # The picture still (no smooth scroll under way) before the mouse goes down.
            top, still = None, 0
            while still < 3:
                now = page.eval_on_selector("#pucks-svg", "s => s.getBoundingClientRect().top")
                still = still + 1 if now == top else 0
                top = now
                page.wait_for_timeout(30)
            at = page.eval_on_selector("#pucks-svg", """(s, i) => { const r = s.getBoundingClientRect(), t = s.querySelector('#tip-' + i)
                || s.querySelector('#in-' + i + ' polygon'), k = r.width / s.viewBox.baseVal.width;
                const b = t.getBBox(); return [r.left + (b.x + b.width / 2) * k, r.top + (b.y + b.height / 2) * k, k]; }""", d["body"])
            page.mouse.move(at[0], at[1])
            page.mouse.down()
            n = d.get("steps", 10)
            for k in range(1, n + 1):
                page.mouse.move(at[0] + d["by"][0] * at[2] * k / n, at[1] + d["by"][1] * at[2] * k / n)
                page.wait_for_timeout(20)
            page.mouse.up()
        if "drag_in" in step:
            # IN on the velocity plane dragged by `by` picture units, in `steps` moves.
            d = step["drag_in"]
            page.eval_on_selector("#plane-svg", "s => { s.scrollIntoView({block: 'center', behavior: 'instant'}); return %s; }"
                                  % FRAMES)
            at = page.eval_on_selector("#plane-svg", """s => { const r = s.getBoundingClientRect(),
                c = s.querySelector('#point-in'), k = r.width / s.viewBox.baseVal.width;
                return [r.left + +c.getAttribute('cx') * k, r.top + +c.getAttribute('cy') * k, k]; }""")
            page.mouse.move(at[0], at[1])
            page.mouse.down()
            n = d.get("steps", 10)
            for k in range(1, n + 1):
                page.mouse.move(at[0] + d["by"][0] * at[2] * k / n, at[1] + d["by"][1] * at[2] * k / n)
                page.wait_for_timeout(20)
            page.mouse.up()
        if "hover" in step:
            page.hover(step["hover"])
        if "wait" in step:
            settled(page, step["wait"])
        if "read" in step:
            name, js = step["read"]
            out[name] = {"value": page.evaluate(js), "errors": list(errors)}
    return out


# Two animation frames: the first runs in the next frame's update, before its observers (the
# page draws a picture that comes into sight in an IntersectionObserver); the second begins the
# frame after, when that one has been drawn.
FRAMES = "new Promise(done => requestAnimationFrame(() => requestAnimationFrame(done)))"

# Until the page is still: scrollY and the box of `sel` the same over five frames in a row (a
# scroll or a fling under way moves one of them every frame). Fails after 5 s.
STILL = """sel => new Promise((done, fail) => {
  const t0 = performance.now(), e = document.querySelector(sel);
  const at = () => { const r = e.getBoundingClientRect(); return [scrollX, scrollY, r.left, r.top, r.width, r.height].join(); };
  let last = at(), same = 0;
  const look = () => {
    const now = at();
    same = now === last ? same + 1 : 0;
    last = now;
    if (same >= 5) done(now);
    else if (performance.now() - t0 > 5000) fail(new Error(sel + ' still moving after 5 s'));
    else requestAnimationFrame(look);
  };
  requestAnimationFrame(look); })"""

# The pointer moves with the button down that the picture `id` receives, counted (once per
# picture; with the pointer captured, every move of a drag is the picture's).
COUNT_MOVES = """id => { window.moves = window.moves || {};
  if (id in moves) return; moves[id] = 0;
  document.getElementById(id).addEventListener('pointermove', (ev) => { if (ev.buttons & 1) moves[id]++; }); }"""

# After the n-th counted move of picture `id`: once the page has received it (its handler
# queues the redraw in the next animation frame), one frame more, which runs after that redraw.
# Fails if the move has not come in 5 s (a move merged into another, or lost).
AFTER_MOVE = """([id, n]) => new Promise((done, fail) => {
  const t0 = performance.now();
  const look = () => {
    if (moves[id] >= n) requestAnimationFrame(() => done(moves[id]));
    else if (performance.now() - t0 > 5000) fail(new Error(id + ': move ' + n + ' did not reach the page in 5 s'));
    else requestAnimationFrame(look);
  };
  look(); })"""


class Phases:
    """Where a driver's time goes: `done(name)` writes to stderr the seconds since the last
    phase (time.perf_counter), for profiling the drivers (the tests show stderr on failure)."""

    def __init__(self):
        self.last = time.perf_counter()

    def done(self, name):
        now = time.perf_counter()
        print("phase %-28s %7.3f s" % (name, now - self.last), file=sys.stderr)
        self.last = now


def wait_ready(page):
    """Until the page's core is ready. Polled with page.evaluate: Playwright's wait_for_function
    evaluates its predicate with eval() when it has to poll, which the page's
    Content-Security-Policy (no 'unsafe-eval') refuses, so it failed whenever the page was not
    ready at the first look."""
    deadline = time.time() + 30
    while not page.evaluate("() => !!(window.collideView && window.collideView.ready)"):
        if time.time() > deadline:
            raise TimeoutError("the page did not become ready in 30 s")
        time.sleep(0.02)


def main():
    page_path, plan_path = sys.argv[1], sys.argv[2]
    plan = json.load(open(plan_path))
    chromium = os.environ.get("COLLIDE_CHROMIUM", "/usr/bin/chromium")
    out = {"requests": [], "console": [], "errors": []}
    started = time.time()
    phases = Phases()
    with sync_playwright() as p, tempfile.TemporaryDirectory() as profile:
        ctx = p.chromium.launch_persistent_context(
            profile, executable_path=chromium, headless=True, args=CHROMIUM_FLAGS,
            viewport={"width": 1400, "height": 1000}, device_scale_factor=1)
        ctx.on("request", lambda r: out["requests"].append(r.url[:200]))
        page = ctx.new_page()
        page.on("console", lambda m: out["console"].append([m.type, m.text]))
        page.on("pageerror", lambda e: out["errors"].append(str(e)))
        page.goto("file://" + os.path.abspath(page_path))
        wait_ready(page)
        out["ready_s"] = time.time() - started
        phases.done("launch and ready")
        text = lambda sel: page.eval_on_selector(sel, "e => e.textContent")

        def set_case(case):
            page.evaluate(FILL, [["#" + field, case.get(field, "")] for field in ("inertia", "m1", "m2", "v1", "v2", "e")])
            return {"state": text("#state"), "command": text("#command"), "scene": text("#scene"),
                    "error": page.eval_on_selector("#case-error", "e => e.hidden ? '' : e.textContent")}

        out["cases"] = [set_case(c) for c in plan.get("cases", [])]
        phases.done("cases")

        def plane_map():
            return page.eval_on_selector("#plane-svg", """s => { const r = s.getBoundingClientRect();
                return {ox: +s.dataset.originX, oy: +s.dataset.originY, s: +s.dataset.scale, step: +s.dataset.step,
                        left: r.left, top: r.top, width: r.width, height: r.height, vb: s.viewBox.baseVal.width}; }""")

        def screen(m, v):
            k = m["width"] / m["vb"]
            return m["left"] + (m["ox"] + m["s"] * v[0]) * k, m["top"] + (m["oy"] - m["s"] * v[1]) * k

        if "drag" in plan:
            d = plan["drag"]
            before = set_case(d["case"])
            page.locator("#plane-svg").scroll_into_view_if_needed()
            m = plane_map()
            page.evaluate("collideView.timings.length = 0")
            page.mouse.move(*screen(m, d["from"]))
            page.mouse.down()
            page.mouse.move(*screen(m, d["to"]), steps=d.get("steps", 30))
            page.mouse.up()
            out["drag"] = {"before": before["state"], "after": text("#state"), "map": m,
                           "timings": page.evaluate("collideView.timings")}
            phases.done("drag")
        if "keys" in plan:
            page.focus("#plane-svg")
            for key in plan["keys"]:
                page.keyboard.press(key)
            out["keys"] = {"state": text("#state"), "map": plane_map()}
            phases.done("keys")
        if "frame" in plan:
            set_case(plan["frame"]["case"])
            out["frame"] = {"w": page.evaluate("""name => new Promise(done => {
                const seen = [], t0 = performance.now();
                document.querySelector('input[name="frame"][value="' + name + '"]').click();
                const look = () => { seen.push(+document.getElementById('plane-svg').dataset.w);
                    if (performance.now() - t0 < 1400) requestAnimationFrame(look); else done(seen); };
                requestAnimationFrame(look); })""", plan["frame"]["to"]),
                "state": text("#state"), "command": text("#command")}
            page.check('input[name="frame"][value="lab"]')
            settled(page, 900)
            phases.done("frame")
        if "reverse" in plan:
            set_case(plan["reverse"])
            page.check("#reverse")
            out["reverse"] = {"state": text("#state"), "command": text("#command")}
            page.uncheck("#reverse")
            phases.done("reverse")
        if "screenshot" in plan:
            sh = plan["screenshot"]
            set_case(sh["case"])
            plot = page.locator("#plane-svg")
            plot.scroll_into_view_if_needed()
            m = plane_map()
            png = plot.screenshot(path=sh["path"])
            page.screenshot(path=sh["page"], full_page=True)
            w, h, rows = png_pixels(png)
            k = w / m["vb"]
            counts, colours, every = {}, set(), colour_counts(rows)
            for name, rgb in sh["colours"].items():
                counts[name] = count_near(every, rgb)
            for row in rows[::3]:
                for px in row[::3]:
                    colours.add(px)
            probes = [nearest(rows, ((m["ox"] + m["s"] * probe["at"][0]) * k, (m["oy"] - m["s"] * probe["at"][1]) * k),
                              sh["colours"][probe["colour"]]) for probe in sh["probes"]]
            white = count_near(every, (255, 255, 255), 8)
            out["screenshot"] = {"width": w, "height": h, "counts": counts, "probes": probes,
                                 "colours": len(colours), "white": white}
            phases.done("screenshot")
        if "stack" in plan:
            out["stack"] = []
            for step in plan["stack"]:
                if "preset" in step:
                    page.select_option("#preset", step["preset"])
                for field, value in step.get("fill", {}).items():
                    page.fill("#" + field, value)
                    page.dispatch_event("#" + field, "change")
                ms = page.evaluate("collideView.stackMs")
                out["stack"].append({"ms": ms if ms == ms else None,
                                     "state": text("#track-state"), "command": text("#track-command"),
                                     "scene": text("#track-scene"), "numbers": text("#stack-numbers"),
                                     "error": page.eval_on_selector("#track-error", "e => e.hidden ? '' : e.textContent")})
            phases.done("stack")
        if "plane" in plan:
            out["plane"] = drive_plane(page, plan["plane"])
            phases.done("plane")
        if "steps" in plan:
            out["steps"] = run_steps(page, plan["steps"], out["errors"])
            phases.done("steps")
        out["seconds"] = time.time() - started
        ctx.close()
    json.dump(out, sys.stdout, allow_nan=False)


if __name__ == "__main__":
    main()
