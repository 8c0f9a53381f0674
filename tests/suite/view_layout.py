"""Drives `collide view`'s page in headless Chromium at a desktop's and a phone's size, for
tests/suite/view_layout.rs (issue 43): python3 view_layout.py PAGE.html OUT_DIR prints one JSON
object of what the page did. Each window is a fresh context of one browser:

- `wide`: at 1280x800 and 1600x1000, the boxes of the velocity plane and of Newton's and
  Minkowski's diagrams (side by side in one view), the Newton diagram's world lines read back at
  every step of a mouse drag of IN, a screenshot of every panel;
- `phone`: at 390x844 with touch, the page's width, the smallest chart text on screen, a one-finger
  swipe over the velocity plane and a one-finger drag of IN's handle (touch events sent as a
  phone's), screenshots;
- `focus`: at 1280x800 and 390x844, every control reached with Tab and its box against the
  sticky bar of links;
- `contrast`: the colours of every text on the page and the background under it;
- `extreme`, `units`, `stack`: the valid extreme case, a drag in km/h, a heavy ball on top;
- `latency`: a mouse drag of IN, each move timed from its event to the end of the frame that
  shows it;
- `controls`: PhET's step back and forward, speed and Reset of the dual panel and the stack.
Console messages and page errors of every context are reported under `console`."""
import json, os, sys, time

from playwright.sync_api import sync_playwright

from view_browser import AFTER_MOVE, CHROMIUM_FLAGS, COUNT_MOVES, FRAMES, STILL, Phases, wait_ready
PANELS = ["two-body", "dual", "stack", "plane", "shell"]

# The boxes of elements in CSS pixels of the window, and the bar of links' bottom edge.
BOX = """sel => { const r = document.querySelector(sel).getBoundingClientRect();
    return {left: r.left, top: r.top, right: r.right, bottom: r.bottom}; }"""

# What the Newton diagram draws: for each body its world line's points (screen units).
NEWTON = """() => [...document.querySelectorAll('#newton-svg polyline')].map(p =>
    p.getAttribute('points').split(' ').map(q => q.split(',').map(Number)))"""

# Every text on the page with its colour and the colour under it (WCAG contrast is computed by
# the test): HTML elements with text of their own, and SVG texts (on white, or on the shape they
# are drawn on: a car's name on the car).
COLOURS = """() => {
  const rgb = (c) => { const m = /rgba?\\(([^)]+)\\)/.exec(c); if (!m) return null;
    const v = m[1].split(/[ ,\\/]+/).filter(Boolean).map(Number); return v.length > 3 ? v : v.concat([1]); };
  const under = (e) => { for (let n = e; n; n = n.parentElement) { const b = rgb(getComputedStyle(n).backgroundColor);
    if (b && b[3] > 0) return b; } return [255, 255, 255, 1]; };
  const out = [];
  for (const e of document.querySelectorAll('body *')) {
    if (e.closest('svg, script, style, noscript, [hidden], details:not([open]) > :not(summary)')) continue;
    const own = [...e.childNodes].some(n => n.nodeType === 3 && n.textContent.trim());
    if (!own || e.disabled) continue;
    const r = e.getBoundingClientRect(); if (!(r.width > 0)) continue;
    const s = getComputedStyle(e);
    out.push({what: e.tagName.toLowerCase() + (e.id ? '#' + e.id : '') + ' ' + e.textContent.trim().slice(0, 30),
      fg: rgb(s.color), bg: under(e), px: parseFloat(s.fontSize), bold: Number(s.fontWeight) >= 700});
  }
  for (const t of document.querySelectorAll('svg.chart text')) {
    if (t.closest('[hidden]') || !t.textContent.trim()) continue;
    const s = getComputedStyle(t);
    let bg = [255, 255, 255, 1];
    const fg = rgb(s.fill);
    if (fg && fg[0] > 250 && fg[1] > 250 && fg[2] > 250) {
      for (let p = t.previousElementSibling; p; p = p.previousElementSibling) if (p.tagName === 'rect') { bg = rgb(getComputedStyle(p).fill); break; }
    }
    const k = t.ownerSVGElement.getBoundingClientRect().width / t.ownerSVGElement.viewBox.baseVal.width;
    out.push({what: 'svg ' + t.ownerSVGElement.id + ' ' + t.textContent.slice(0, 30), fg, bg,
      px: parseFloat(s.fontSize) * k, bold: Number(s.fontWeight) >= 700, opacity: Number(s.opacity)});
  }
  return out;
}"""

# The smallest text of the charts shown, in screen pixels (font size times the chart's scale).
SMALLEST_TEXT = """() => { let least = {px: Infinity, what: ''};
  for (const t of document.querySelectorAll('svg.chart text')) {
    const svg = t.ownerSVGElement; const w = svg.getBoundingClientRect().width;
    if (!(w > 0) || !t.textContent.trim()) continue;
    const px = parseFloat(getComputedStyle(t).fontSize) * w / svg.viewBox.baseVal.width;
    if (px < least.px) least = {px, what: svg.id + ': ' + t.textContent}; }
  return least; }"""

# Every NaN or Infinity in the pictures' attributes and texts.
NOT_FINITE = """() => { const bad = [];
  for (const e of document.querySelectorAll('svg *')) {
    for (const a of e.attributes) if (/NaN|Infinity/.test(a.value)) bad.push(e.tagName + ' ' + a.name + '=' + a.value);
    if (e.tagName === 'text' && /NaN|Infinity/.test(e.textContent)) bad.push('text ' + e.textContent); }
  return bad; }"""


def opened(browser, page_path, console, **options):
    ctx = browser.new_context(**options)
    page = ctx.new_page()
    tag = "%dx%d" % (options["viewport"]["width"], options["viewport"]["height"])
    page.on("console", lambda m: console.append([tag, m.type, m.text]))
    page.on("pageerror", lambda e: console.append([tag, "pageerror", str(e)]))
    page.goto("file://" + os.path.abspath(page_path))
    wait_ready(page)
    return ctx, page


def to(page, sel, block="center"):
    """`sel` scrolled to at once (`block` of the window), and a frame drawn there."""
    page.eval_on_selector(sel, "(s, b) => { s.scrollIntoView({block: b, behavior: 'instant'}); return %s; }" % FRAMES,
                          block)


CHARTS = ["plane-svg", "newton-svg", "rail-svg", "space-svg", "tower-svg", "lines-svg", "pucks-svg",
          "momentum-svg", "normal-svg"]


def shots(page, out_dir, tag):
    """The window at the start of each panel, at the velocity plane (with the diagram beside it
    on a wide screen), and each chart by itself. No text field has the focus here (the last
    click or drag left it on a picture or a radio button), so there is no caret to hide: the
    screenshots skip Playwright's style that hides it (caret="initial"), the same pixels."""
    assert page.evaluate("!document.activeElement || !document.activeElement.matches('input[type=text], input:not([type]), textarea')"), \
        "a text field has the focus: its caret would show"
    for part in PANELS:
        to(page, "#" + part, "start")
        page.screenshot(path=os.path.join(out_dir, "%s-%s.png" % (tag, part)), caret="initial")
    to(page, "#plane-svg")
    page.screenshot(path=os.path.join(out_dir, "%s-duo.png" % tag), caret="initial")
    for chart in CHARTS:
        to(page, "#" + chart)
        page.locator("#" + chart).screenshot(path=os.path.join(out_dir, "%s-chart-%s.png" % (tag, chart)),
                                             caret="initial")


def in_at(page):
    """IN's centre on the screen and the screen pixels per viewBox unit of the plane."""
    return page.eval_on_selector("#plane-svg", """s => { const r = s.getBoundingClientRect(),
        c = s.querySelector('#point-in'), k = r.width / s.viewBox.baseVal.width;
        return [r.left + +c.getAttribute('cx') * k, r.top + +c.getAttribute('cy') * k, k]; }""")


def state(page):
    return json.loads(page.eval_on_selector("#state", "e => e.textContent"))


def wide(browser, page_path, out_dir, console, w, h):
    ctx, page = opened(browser, page_path, console, viewport={"width": w, "height": h}, device_scale_factor=1)
    out = {"window": [w, h]}
    to(page, "#plane-svg")
    out["bar"] = page.evaluate(BOX, "nav.jump")["bottom"]
    out["plane"] = page.evaluate(BOX, "#plane-svg")
    out["newton"] = page.evaluate(BOX, "#newton-svg")
    page.check('input[name="spacetime"][value="minkowski"]')
    out["minkowski"] = page.evaluate(BOX, "#minkowski-svg")
    out["newton_hidden"] = page.eval_on_selector("#newton-figure", "f => f.hidden")
    page.check('input[name="spacetime"][value="newton"]')
    # IN dragged by the mouse: after each move (and its frame), IN and the Newton diagram.
    page.evaluate(COUNT_MOVES, "plane-svg")
    x, y, k = in_at(page)
    page.mouse.move(x, y)
    page.mouse.down()
    out["drag"] = []
    for i in range(1, 9):
        page.mouse.move(x - 6 * i, y - 9 * i)
        page.evaluate(AFTER_MOVE, ["plane-svg", i])
        s = state(page)
        out["drag"].append({"in": s["in"], "fin": s["fin"], "newton": page.evaluate(NEWTON)})
    page.mouse.up()
    shots(page, out_dir, "%dx%d" % (w, h))
    ctx.close()
    return out


def phone(browser, page_path, out_dir, console):
    ctx, page = opened(browser, page_path, console, viewport={"width": 390, "height": 844},
                       device_scale_factor=2, is_mobile=True, has_touch=True)
    out = {"width": page.evaluate("[document.documentElement.scrollWidth, innerWidth]")}
    cdp = ctx.new_cdp_session(page)

    def swipe(x0, y0, x1, y1, n=12):
        # Touch events as a phone sends them (through the compositor, which scrolls).
        cdp.send("Input.dispatchTouchEvent", {"type": "touchStart", "touchPoints": [{"x": x0, "y": y0}]})
        for i in range(1, n + 1):
            cdp.send("Input.dispatchTouchEvent", {"type": "touchMove", "touchPoints": [
                {"x": x0 + (x1 - x0) * i / n, "y": y0 + (y1 - y0) * i / n}]})
            page.wait_for_timeout(16)
        cdp.send("Input.dispatchTouchEvent", {"type": "touchEnd", "touchPoints": []})
        page.evaluate(STILL, "#plane-svg")

    to(page, "#plane-svg")
    page.evaluate(STILL, "#plane-svg")
    typed = lambda: [page.input_value("#v1"), page.input_value("#v2")]
    # A finger on IN's handle drags IN, and the page stays.
    x, y, k = in_at(page)
    m = page.eval_on_selector("#plane-svg", "s => ({s: +s.dataset.scale, step: +s.dataset.step})")
    before = {"scroll": page.evaluate("scrollY"), "typed": typed(), "state": state(page)["in"]}
    swipe(x, y, x - 40, y - 60)
    out["handle"] = {"before": before, "after": {"scroll": page.evaluate("scrollY"), "typed": typed(),
                     "state": state(page)["in"]}, "moved_px": [-40, -60], "k": k, "map": m}
    # A vertical swipe over the picture away from IN scrolls the page, and IN stays.
    r = page.evaluate(BOX, "#plane-svg")
    sx = r["left"] + 0.2 * (r["right"] - r["left"])
    before = {"scroll": page.evaluate("scrollY"), "typed": typed()}
    swipe(sx, r["top"] + 0.8 * (r["bottom"] - r["top"]), sx, r["top"] + 0.2 * (r["bottom"] - r["top"]))
    out["swipe"] = {"before": before, "after": {"scroll": page.evaluate("scrollY"), "typed": typed()}}
    # The smallest chart text of each panel, seen in turn.
    out["text"] = {"newton": page.evaluate(SMALLEST_TEXT)}
    page.check('input[name="spacetime"][value="minkowski"]')
    out["text"]["minkowski"] = page.evaluate(SMALLEST_TEXT)
    page.check('input[name="spacetime"][value="newton"]')
    out["width_after"] = page.evaluate("[document.documentElement.scrollWidth, innerWidth]")
    shots(page, out_dir, "390x844")
    ctx.close()
    return out


def focus(browser, page_path, console, w, h, mobile):
    """Every control reached with Tab: its box and the bar's bottom edge (reduced motion, so that
    the scroll to it is done when read)."""
    ctx, page = opened(browser, page_path, console, viewport={"width": w, "height": h},
                       is_mobile=mobile, has_touch=mobile, reduced_motion="reduce")
    page.evaluate("document.activeElement && document.activeElement.blur(); scrollTo(0, 0)")
    seen = []
    for _ in range(400):
        page.keyboard.press("Tab")
        f = page.evaluate("""() => { const e = document.activeElement; if (!e || e === document.body) return null;
            const r = e.getBoundingClientRect(), bar = document.querySelector('nav.jump').getBoundingClientRect();
            window.tabbed = window.tabbed || new Map();
            if (!tabbed.has(e)) tabbed.set(e, tabbed.size);
            return {n: tabbed.get(e), what: e.tagName.toLowerCase() + (e.id ? '#' + e.id : '') + (e.name ? '[' + e.name + '=' + e.value + ']' : '') + ' ' + (e.textContent || '').trim().slice(0, 20),
                    top: r.top, bottom: r.bottom, bar: bar.bottom, height: innerHeight, in_bar: !!e.closest('nav.jump')}; }""")
        if f is None:
            continue
        if seen and f["n"] == 0:
            break
        seen.append(f)
    ctx.close()
    return seen


def desktop_checks(browser, page_path, console, phases):
    ctx, page = opened(browser, page_path, console, viewport={"width": 1280, "height": 800}, device_scale_factor=1)
    phases.done("desktop: open")
    out = {"contrast": page.evaluate(COLOURS)}
    phases.done("desktop: contrast")
    # The valid extreme case of the brief.
    for f, v in [("m1", "1"), ("m2", "1e-308"), ("v1", "0"), ("v2", "1e308"), ("e", "0")]:
        page.fill("#" + f, v)
    out["extreme"] = {"bad": page.evaluate(NOT_FINITE), "state": page.eval_on_selector("#state", "e => e.textContent"),
                      "error": page.eval_on_selector("#case-error", "e => e.hidden ? '' : e.textContent")}
    phases.done("desktop: extreme")
    # A drag in km/h.
    for f, v in [("m1", "4"), ("m2", "1"), ("v1", "72 km/h"), ("v2", "10 km/h"), ("e", "elastic")]:
        page.fill("#" + f, v)
    to(page, "#plane-svg")
    x, y, k = in_at(page)
    page.mouse.move(x, y)
    page.mouse.down()
    page.mouse.move(x - 30, y - 50, steps=5)
    page.mouse.up()
    out["units"] = {"typed": [page.input_value("#v1"), page.input_value("#v2")],
                    "state": page.eval_on_selector("#state", "e => e.textContent"),
                    "error": page.eval_on_selector("#case-error", "e => e.hidden ? '' : e.textContent")}
    phases.done("desktop: units")
    # A heavy ball on a light one: 1 on 0.01, touching (0.01's top at 1.5, 1's bottom at 1.5).
    for f, v in [("t-masses", "0.01,1"), ("t-sizes", "0.5,1"), ("t-positions", "1.25,2"), ("t-velocities", "0,0")]:
        page.fill("#" + f, v)
        page.dispatch_event("#" + f, "change")
    out["stack"] = {"numbers": page.eval_on_selector("#stack-numbers", "e => e.textContent"),
                    "state": page.eval_on_selector("#track-state", "e => e.textContent"),
                    "command": page.eval_on_selector("#track-command", "e => e.textContent"),
                    "error": page.eval_on_selector("#track-error", "e => e.hidden ? '' : e.textContent")}
    phases.done("desktop: stack")
    # Drag latency: each mouse move's event to the end of the frame that draws it (a timeout
    # queued in the next animation frame runs after that frame's style, layout and paint).
    for f, v in [("v1", "60"), ("v2", "10")]:
        page.fill("#" + f, v)
    to(page, "#plane-svg")
    page.evaluate("""() => { window.latency = [];
        document.getElementById('plane-svg').addEventListener('pointermove', (ev) => {
          const t0 = ev.timeStamp; requestAnimationFrame(() => setTimeout(() => latency.push(performance.now() - t0), 0)); }); }""")
    x, y, k = in_at(page)
    page.mouse.move(x, y)
    page.mouse.down()
    for i in range(1, 121):
        page.mouse.move(x - 2 * i, y - 3 * (i % 40))
        page.wait_for_timeout(25)
    page.mouse.up()
    page.wait_for_timeout(100)
    out["latency"] = page.evaluate("latency")
    ctx.close()
    phases.done("desktop: latency")
    return out


def controls(browser, page_path, console):
    """PhET's controls of the two animations: steps, a timed play at 2x and at 1/4x, Reset."""
    ctx, page = opened(browser, page_path, console, viewport={"width": 1280, "height": 800}, device_scale_factor=1)
    time_of = lambda: page.evaluate("collideView.time()")
    out = {}
    for prefix in ("dual", "stack"):
        to(page, "#%s-play" % prefix)
        seen = {"start": time_of()[prefix]}
        for _ in range(3):
            page.click("#%s-step" % prefix)
        seen["three_steps"] = time_of()[prefix]
        page.click("#%s-back" % prefix)
        seen["one_back"] = time_of()[prefix]
        # Played for 600 ms of the page's clock at each speed: (time advanced, seconds).
        seen["rates"] = {}
        for speed in ("2", "0.25"):
            page.select_option("#%s-speed" % prefix, speed)
            seen["rates"][speed] = page.evaluate("""prefix => new Promise(done => {
                const t0 = collideView.time()[prefix], c0 = performance.now();
                document.getElementById(prefix + '-play').click();
                setTimeout(() => { document.getElementById(prefix + '-play').click();
                  done([collideView.time()[prefix] - t0, (performance.now() - c0) / 1000]); }, 600); })""", prefix)
        page.click("#%s-reset" % prefix)
        seen["reset"] = {"time": time_of()[prefix], "speed": page.input_value("#%s-speed" % prefix),
                         "pressed": page.get_attribute("#%s-play" % prefix, "aria-pressed")}
        out[prefix] = seen
    out["rail"] = page.eval_on_selector("#rail-svg", "s => [...s.querySelectorAll('text')].map(t => t.textContent)")
    out["until"] = json.loads(page.eval_on_selector("#track-state", "e => e.textContent"))["time"]
    ctx.close()
    return out


def main():
    page_path, out_dir = sys.argv[1], sys.argv[2]
    chromium = os.environ.get("COLLIDE_CHROMIUM", "/usr/bin/chromium")
    console = []
    started = time.time()
    phases = Phases()
    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path=chromium, headless=True, args=CHROMIUM_FLAGS)
        phases.done("launch")
        out = {"wide": []}
        for w, h in [(1280, 800), (1600, 1000)]:
            out["wide"].append(wide(browser, page_path, out_dir, console, w, h))
            phases.done("wide %dx%d" % (w, h))
        out["phone"] = phone(browser, page_path, out_dir, console)
        phases.done("phone")
        out["focus"] = {}
        for w, h, mobile in [(1280, 800, False), (390, 844, True)]:
            out["focus"]["%dx%d" % (w, h)] = focus(browser, page_path, console, w, h, mobile)
            phases.done("focus %dx%d" % (w, h))
        out.update(desktop_checks(browser, page_path, console, phases))
        out["controls"] = controls(browser, page_path, console)
        phases.done("controls")
        browser.close()
    out["console"] = console
    out["seconds"] = time.time() - started
    json.dump(out, sys.stdout, allow_nan=False)


if __name__ == "__main__":
    main()
