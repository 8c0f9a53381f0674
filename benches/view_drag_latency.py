"""The drag latency of every drag on `collide view`'s page (docs/benchmarks.md, "The page: drag
latency"): python3 benches/view_drag_latency.py PAGE.html RUNS [DRAG,...]

In headless Chromium at 1280x800, one page load a run, each drag of 121 moves 25 ms apart: IN on
the velocity plane, a car on the rail (at t = -1), v1's tip in the plane, v1's tip and the hit
point on the rigid panel's rod, its spin slider (a ball on a rough floor) and the N-ball panel's
time slider (its pucks have no handle). Each move is timed from its pointermove's time stamp to
a timeout queued in the next animation frame (after that frame's style, layout and paint). One
line a drag and run: the median, the 95th percentile and the largest, with the load average
(1 minute) before it. Needs Playwright for Python and /usr/bin/chromium; not run by the tests."""
import os, sys
from playwright.sync_api import sync_playwright
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "suite"))
from view_browser import CHROMIUM_FLAGS, wait_ready

N = 121
HOOK = """id => { window.latency = []; const e = document.getElementById(id);
  window.hooked = window.hooked || new Set(); if (hooked.has(id)) return; hooked.add(id);
  e.addEventListener('pointermove', (ev) => { if (!(ev.buttons & 1)) return; const t0 = ev.timeStamp;
    requestAnimationFrame(() => setTimeout(() => latency.push(performance.now() - t0), 0)); }); }"""
CENTRE = """sel => { const r = document.querySelector(sel).getBoundingClientRect(); return [r.left + r.width / 2, r.top + r.height / 2]; }"""

def load():
    return open("/proc/loadavg").read().split()[0]

def drag(page, hook_id, start, moves):
    page.evaluate(HOOK, hook_id)
    page.mouse.move(*start)
    page.mouse.down()
    for dx, dy in moves:
        page.mouse.move(start[0] + dx, start[1] + dy)
        page.wait_for_timeout(25)
    page.mouse.up()
    page.wait_for_timeout(150)
    return page.evaluate("latency")

def in_plane(page):
    for f, v in [("v1", "60"), ("v2", "10")]: page.fill("#" + f, v)
    page.locator("#plane-svg").scroll_into_view_if_needed()
    page.wait_for_timeout(200)
    s = page.evaluate(CENTRE, "#point-in")
    return drag(page, "plane-svg", s, [(-2 * (i % 60), -3 * (i % 40)) for i in range(1, N + 1)])

def car(page):
    page.click("#dual-reset")
    page.locator("#rail-svg").scroll_into_view_if_needed()
    page.wait_for_timeout(200)
    s = page.evaluate(CENTRE, '#rail-svg rect.car[data-body="2"]')
    return drag(page, "rail-svg", s, [(-(i % 40) * 2, 0) for i in range(1, N + 1)])

def pucks(page):
    page.locator("#pucks-svg").scroll_into_view_if_needed()
    page.wait_for_timeout(200)
    s = page.evaluate(CENTRE, "#tip-1")
    return drag(page, "pucks-svg", s, [(-(i % 30), (i % 20)) for i in range(1, N + 1)])

def rigid_v1(page):
    page.select_option("#r-preset", "rod")
    page.locator("#rigid-svg").scroll_into_view_if_needed()
    page.wait_for_timeout(200)
    s = page.evaluate(CENTRE, "#rigid-v1-handle")
    return drag(page, "rigid-svg", s, [(-(i % 30), (i % 20) - 10) for i in range(1, N + 1)])

def rigid_hit(page):
    page.select_option("#r-preset", "rod")
    page.locator("#rigid-svg").scroll_into_view_if_needed()
    page.wait_for_timeout(200)
    s = page.evaluate(CENTRE, "#rigid-hit-handle")
    return drag(page, "rigid-svg", s, [(0, 2 + (i % 40)) for i in range(1, N + 1)])

def slider(page, sel, pre=None):
    if pre: pre(page)
    page.locator(sel).scroll_into_view_if_needed()
    page.wait_for_timeout(200)
    box = page.locator(sel).bounding_box()
    # The thumb where the value is: press it at its place.
    frac = page.evaluate("""sel => { const r = document.querySelector(sel); return (r.value - r.min) / (r.max - r.min); }""", sel)
    x0 = box["x"] + 8 + frac * (box["width"] - 16)
    s = (x0, box["y"] + box["height"] / 2)
    span = box["width"] - 16
    return drag(page, sel[1:], s, [(((i % 40) / 40.0 - frac) * span * 0.9, 0) for i in range(1, N + 1)])

def rigid_spin(page):
    return slider(page, "#r-spin-range", lambda p: (p.select_option("#r-preset", "floor"), p.wait_for_timeout(100)))

def nbody_time(page):
    return slider(page, "#nball-time")

ALL = {"in": in_plane, "car": car, "pucks": pucks, "rigid-v1": rigid_v1, "rigid-hit": rigid_hit,
       "rigid-spin": rigid_spin, "nbody-time": nbody_time}

def main():
    path, runs = sys.argv[1], int(sys.argv[2])
    which = sys.argv[3].split(",") if len(sys.argv) > 3 else list(ALL)
    res = {w: [] for w in which}
    with sync_playwright() as p:
        b = p.chromium.launch(executable_path="/usr/bin/chromium", headless=True, args=CHROMIUM_FLAGS)
        for r in range(runs):
            ctx = b.new_context(viewport={"width": 1280, "height": 800}, device_scale_factor=1)
            page = ctx.new_page()
            errs = []
            page.on("pageerror", lambda e: errs.append(str(e)))
            page.goto("file://" + os.path.abspath(path))
            wait_ready(page)
            for w in which:
                l0 = load()
                ms = sorted(ALL[w](page))
                med, p95 = ms[len(ms) // 2], ms[min(len(ms) - 1, int(len(ms) * 0.95))]
                res[w].append((med, p95))
                print("run %d %-10s n=%3d median %5.1f p95 %5.1f max %5.1f load %s" % (r + 1, w, len(ms), med, p95, ms[-1], l0), flush=True)
            if errs: print("ERRORS", errs)
            ctx.close()
        b.close()


if __name__ == "__main__":
    main()
