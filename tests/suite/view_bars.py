"""Drives `collide view`'s page in headless Chromium for tests/suite/view_bars.rs (issue 43, PhET's
bars, the rail's starting positions and the live regions): python3 view_bars.py PAGE.html OUT_DIR
prints one JSON object of what the page did, at 1280x800:

- `bars`: the rail's momentum and energy bars and the plane's energy bars (each bar's value,
  width and the group's zero and reach), for the lecture's Fig. 1.3 and again with e = 2/3;
- `rail`: a car dragged on the rail at t = -1 (where the pointer let go and where the car is
  drawn after), the typed velocities, the state and the command shown;
- `said`: the texts of the live regions at every step of a drag of IN and after it ends;
- `latency`: a drag of a car and a drag of IN, each move timed from its event to the end of the
  frame that draws it, with the machine's load average.
Console messages and page errors are reported under `console`. Screenshots of the bars and the
rail are left in OUT_DIR."""
import json, os, sys, time

from playwright.sync_api import sync_playwright

from view_browser import AFTER_MOVE, CHROMIUM_FLAGS, COUNT_MOVES, FRAMES, Phases, wait_ready

# Each group of bars in `svg`: its zero line and reach (viewBox units), and each bar's value and
# drawn extent.
BARS = """svg => [...document.querySelectorAll(svg + ' g[data-zero]')].map(g => ({
    id: g.id, zero: +g.dataset.zero, reach: +g.dataset.reach,
    rows: [...g.querySelectorAll('rect.bar')].map(r => ({ name: r.previousElementSibling.textContent,
      value: r.dataset.value === '' ? null : Number(r.dataset.value),
      x: +r.getAttribute('x'), width: +r.getAttribute('width') })) }))"""

# A car's box on the screen (CSS pixels), and the rail's screen pixels per viewBox unit.
CAR = """i => { const r = document.querySelector('#rail-svg rect.car[data-body="' + i + '"]').getBoundingClientRect();
    const s = document.getElementById('rail-svg'); return { left: r.left, right: r.right, mid: r.top + r.height / 2,
      k: s.getBoundingClientRect().width / s.viewBox.baseVal.width, svgLeft: s.getBoundingClientRect().left }; }"""

# Every change of a live region's text, with the drag step it happened at.
WATCH = """() => { window.saidLog = []; window.dragStep = 0;
  for (const e of document.querySelectorAll('[aria-live]')) new MutationObserver(() =>
    saidLog.push([e.id, dragStep, e.textContent])).observe(e, { childList: true, subtree: true, characterData: true }); }"""


# Until the live region `id` no longer says `before` (its sentence said); fails after 5 s.
SAID = """([id, before]) => new Promise((done, fail) => {
  const t0 = performance.now(), e = document.getElementById(id);
  const look = () => {
    if (e.textContent !== before) done(e.textContent);
    else if (performance.now() - t0 > 5000) fail(new Error(id + ' said nothing new in 5 s'));
    else requestAnimationFrame(look);
  };
  look(); })"""


def load():
    return [float(x) for x in open("/proc/loadavg").read().split()[:3]]


def bars(page):
    return {"rail": page.evaluate(BARS, "#bars-svg"), "plane": page.evaluate(BARS, "#plane-bars-svg")}


def drag_car(page, body, dx, steps):
    """Car `body` dragged by `dx` screen pixels in `steps` moves; where it was grabbed and let go."""
    page.locator("#rail-svg").scroll_into_view_if_needed()
    page.evaluate(COUNT_MOVES, "rail-svg")
    car = page.evaluate(CAR, body)
    x, y = (car["left"] + car["right"]) / 2, car["mid"]
    page.mouse.move(x, y)
    page.mouse.down()
    first = page.evaluate("moves['rail-svg']")
    for i in range(1, steps + 1):
        page.mouse.move(x + dx * i / steps, y)
        # Each move drawn before the next (the page's redraw is queued in the next frame).
        page.evaluate(AFTER_MOVE, ["rail-svg", first + i])
    page.mouse.up()
    page.evaluate(FRAMES)
    return car


def latency_of(page, svg, start, moves):
    """Each move's event to the end of the frame that shows it, for a drag from `start` along
    `moves` (screen offsets)."""
    page.evaluate("""svg => { window.latency = [];
        document.getElementById(svg).addEventListener('pointermove', (ev) => {
          const t0 = ev.timeStamp; requestAnimationFrame(() => setTimeout(() => latency.push(performance.now() - t0), 0)); }); }""", svg)
    page.mouse.move(*start)
    page.mouse.down()
    for dx, dy in moves:
        page.mouse.move(start[0] + dx, start[1] + dy)
        page.wait_for_timeout(25)
    page.mouse.up()
    page.wait_for_timeout(100)
    return page.evaluate("latency")


def main():
    page_path, out_dir = sys.argv[1], sys.argv[2]
    chromium = os.environ.get("COLLIDE_CHROMIUM", "/usr/bin/chromium")
    console, out = [], {}
    started = time.time()
    phases = Phases()
    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path=chromium, headless=True, args=CHROMIUM_FLAGS)
        ctx = browser.new_context(viewport={"width": 1280, "height": 800}, device_scale_factor=1)
        page = ctx.new_page()
        page.on("console", lambda m: console.append([m.type, m.text]))
        page.on("pageerror", lambda e: console.append(["pageerror", str(e)]))
        page.goto("file://" + os.path.abspath(page_path))
        wait_ready(page)
        phases.done("launch and ready")
        out["bars"] = {"fig13": bars(page)}
        for sel in ("#bars-svg", "#plane-bars-svg"):
            page.locator(sel).screenshot(path=os.path.join(out_dir, "bars-%s.png" % sel[1:]))
        page.fill("#e", "2/3")
        page.evaluate(FRAMES)
        out["bars"]["two_thirds"] = bars(page)
        page.fill("#e", "elastic")
        phases.done("bars")
        # A car on the rail, dragged at t = -1 (as Reset leaves it): 120 px to the left.
        page.click("#dual-reset")
        car = drag_car(page, 1, -120, 8)
        out["rail"] = {"grabbed": car, "after": page.evaluate(CAR, 1),
                       "typed": [page.input_value("#v1"), page.input_value("#v2")],
                       "state": page.eval_on_selector("#state", "e => e.textContent"),
                       "command": page.eval_on_selector("#command", "e => e.textContent"),
                       "bars": bars(page)["rail"]}
        page.locator("#rail-svg").screenshot(path=os.path.join(out_dir, "rail-dragged.png"))
        phases.done("rail")
        # The live regions during a drag of IN (30 moves) and after it ends.
        # Typed, the result is said 700 ms after the last key (bars.js, sayLater): said before
        # the watch begins. The sentence changes (V1 was 86), which the wait sees.
        said = page.eval_on_selector("#case-said", "e => e.textContent")
        for f, v in [("v1", "60"), ("v2", "10")]:
            page.fill("#" + f, v)
        page.evaluate(SAID, ["case-said", said])
        page.evaluate(WATCH)
        page.locator("#plane-svg").scroll_into_view_if_needed()
        x, y = page.eval_on_selector("#plane-svg", """s => { const r = s.getBoundingClientRect(),
            c = s.querySelector('#point-in'), k = r.width / s.viewBox.baseVal.width;
            return [r.left + +c.getAttribute('cx') * k, r.top + +c.getAttribute('cy') * k]; }""")
        page.evaluate(COUNT_MOVES, "plane-svg")
        page.mouse.move(x, y)
        page.mouse.down()
        first = page.evaluate("moves['plane-svg']")
        for i in range(1, 31):
            # Move i - 1 drawn, then the step named.
            page.evaluate("([n, i]) => (%s)(['plane-svg', n]).then(() => { dragStep = i; })" % AFTER_MOVE,
                          [first + i - 1, i])
            page.mouse.move(x - 3 * i, y - 2 * i)
        page.evaluate("n => (%s)(['plane-svg', n]).then(() => { dragStep = 'up'; })" % AFTER_MOVE, first + 30)
        page.mouse.up()
        page.wait_for_timeout(1000)
        out["said"] = {"log": page.evaluate("saidLog"), "state": page.eval_on_selector("#state", "e => e.textContent"),
                       "live": page.evaluate("() => [...document.querySelectorAll('[aria-live]')].map(e => [e.id, e.querySelectorAll('table').length])")}
        phases.done("said")
        # Latency: a car dragged 80 moves, then IN 80 moves, with the load average before each.
        page.click("#dual-reset")
        page.locator("#rail-svg").scroll_into_view_if_needed()
        car = page.evaluate(CAR, 2)
        out["latency"] = {"car_load": load()}
        out["latency"]["car"] = latency_of(page, "rail-svg", ((car["left"] + car["right"]) / 2, car["mid"]),
                                           [(-(i % 40) * 2, 0) for i in range(1, 81)])
        for f, v in [("v1", "60"), ("v2", "10")]:
            page.fill("#" + f, v)
        page.locator("#plane-svg").scroll_into_view_if_needed()
        x, y = page.eval_on_selector("#plane-svg", """s => { const r = s.getBoundingClientRect(),
            c = s.querySelector('#point-in'), k = r.width / s.viewBox.baseVal.width;
            return [r.left + +c.getAttribute('cx') * k, r.top + +c.getAttribute('cy') * k]; }""")
        out["latency"]["in_load"] = load()
        out["latency"]["in"] = latency_of(page, "plane-svg", (x, y), [(-2 * i, -3 * (i % 40)) for i in range(1, 81)])
        out["latency"]["page_ms"] = page.evaluate("collideView.timings")
        phases.done("latency")
        ctx.close()
        browser.close()
    out["console"] = console
    out["seconds"] = time.time() - started
    json.dump(out, sys.stdout, allow_nan=False)


if __name__ == "__main__":
    main()
