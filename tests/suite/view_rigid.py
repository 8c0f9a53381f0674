"""Drives `collide view`'s rigid panel in headless Chromium for tests/suite/view_rigid.rs (issue
43, section 3): python3 view_rigid.py PAGE.html OUT_DIR CASES.json prints one JSON object of what
the page did, at 1280x800:

- `cases`: for each case of CASES.json (the panel's fields), the fields typed, then
  `#rigid-state` and `#rigid-command` as the page shows them (or its error);
- `hit`: the hit point dragged along the rod with the mouse: the field before and after, where
  the pointer let go (in the target's units, from the picture's map), and the state and command;
- `hand`: the numbers tables of the panel for a case derived by hand in the Rust test;
- `floor`: a spinning sphere on a rough floor: its tables, and its arrows against its outline;
- `extreme`: an extreme valid case: its state, and whether the pictures hold NaN or Infinity;
- `phone`: the panel at 390x844: its width against the window's (no sideways overflow).
Console messages and page errors are reported under `console`. Screenshots of the panel at
1280x800 and 390x844 are left in OUT_DIR."""
import json, os, sys, time

from playwright.sync_api import sync_playwright

from view_browser import CHROMIUM_FLAGS, wait_ready

FIELDS = ["m1", "m2", "v1", "target", "pivot", "hit_at", "ball", "spin", "e", "friction", "beta"]

# Fills the panel's fields at once and solves (as typing does, one input event).
FILL = """c => { for (const f of %s) document.getElementById('r-' + f).value = c[f] || '';
  document.getElementById('r-m1').dispatchEvent(new Event('input')); }""" % json.dumps(FIELDS)

READ = """() => ({ state: document.getElementById('rigid-state').textContent,
  command: document.getElementById('rigid-command').textContent,
  error: document.getElementById('rigid-error').hidden ? null : document.getElementById('rigid-error').textContent,
  hit_at: document.getElementById('r-hit_at').value })"""

# The numbers tables: caption -> rows of [header, cells...].
TABLES = """() => Object.fromEntries([...document.querySelectorAll('#rigid-numbers table')].map(t =>
  [t.caption.textContent, [...t.tBodies[0].rows].map(r => [...r.cells].map(c => c.textContent))]))"""

BAD = """() => { const svgs = ['rigid-svg', 'rigid-normal-svg'].map(id => document.getElementById(id).outerHTML).join('');
  return /NaN|Infinity/.test(svgs); }"""

# The ball's outline and its velocity arrows before and after: where each line starts and where
# its head's tip is (viewBox units).
ARROWS = """() => { const c = document.getElementById('rigid-body1');
  const get = id => { const g = document.getElementById(id), l = g.querySelector('line');
    return { from: [+l.getAttribute('x1'), +l.getAttribute('y1')],
      tip: g.querySelector('polygon').getAttribute('points').split(' ')[0].split(',').map(Number) }; };
  return { centre: [+c.getAttribute('cx'), +c.getAttribute('cy')], r: +c.getAttribute('r'),
    v1: get('rigid-v1'), v1_fin: get('rigid-v1-fin') }; }"""


def arrows(page):
    """The ball's arrows against its outline (issue 43: they start at the disk's edge)."""
    return page.evaluate(ARROWS)


def main():
    page_path, out_dir, cases_path = sys.argv[1], sys.argv[2], sys.argv[3]
    cases = json.load(open(cases_path))
    start = time.time()
    out = {"console": []}
    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path="/usr/bin/chromium", args=CHROMIUM_FLAGS)
        page = browser.new_page(viewport={"width": 1280, "height": 800})
        page.on("console", lambda m: out["console"].append(m.type + ": " + m.text))
        page.on("pageerror", lambda e: out["console"].append("pageerror: " + str(e)))
        page.goto("file://" + os.path.abspath(page_path))
        wait_ready(page)
        page.locator("#rigid").scroll_into_view_if_needed()
        page.screenshot(path=os.path.join(out_dir, "rigid-rod-1280.png"), full_page=False)
        page.locator("#rigid-svg").screenshot(path=os.path.join(out_dir, "rigid-svg-1280.png"))

        out["cases"] = []
        for c in cases:
            page.evaluate(FILL, c)
            out["cases"].append(page.evaluate(READ))

        # The hit point dragged on the free rod of the lecture's case, from the end toward the
        # centre: the drop point read back in the target's units from the picture's map.
        page.evaluate(FILL, {"m1": "1", "m2": "4", "v1": "3", "target": "rod 2", "hit_at": "end", "e": "elastic"})
        page.locator("#rigid-svg").scroll_into_view_if_needed()
        before = page.evaluate(READ)
        scale = page.evaluate("() => collideView.rigidScale")
        h = page.locator("#rigid-hit-handle").bounding_box()
        x, y = h["x"] + h["width"] / 2, h["y"] + h["height"] / 2
        page.mouse.move(x, y)
        page.mouse.down()
        for i in range(1, 9):
            page.mouse.move(x, y + 60 * i / 8)
            page.wait_for_timeout(30)
        page.mouse.up()
        page.wait_for_timeout(100)
        after = page.evaluate(READ)
        # The pointer's drop point in world units (the map kept during the drag: scale s).
        drop = page.evaluate("""([cx, cy]) => { const svg = document.getElementById('rigid-svg');
          const r = svg.getBoundingClientRect(), vb = svg.viewBox.baseVal;
          return { screen_y: (cy - r.top) * vb.height / r.height, units: vb.height / r.height }; }""", [x, y + 60])
        out["hit"] = {"before": before, "after": after, "dy_screen": 60, "drop": drop,
                      "scale_before": scale}
        page.locator("#rigid-svg").screenshot(path=os.path.join(out_dir, "rigid-hit-dragged.png"))

        # The hand-derived case (tests/suite/view_rigid.rs): m = 1 at 3 on the end of a free rod
        # of mass 2 and length 2, e = 1.
        page.evaluate(FILL, {"m1": "1", "m2": "2", "v1": "3", "target": "rod 2", "hit_at": "end", "e": "1"})
        out["hand"] = {"tables": page.evaluate(TABLES), "read": page.evaluate(READ),
                       "contact": page.evaluate("() => document.getElementById('rigid-contact').textContent")}

        # A rough floor, for the screenshot and a named contact.
        page.evaluate(FILL, {"m1": "1", "m2": "floor", "v1": "(7,-1)", "ball": "sphere 1", "friction": "1", "spin": "2"})
        out["floor"] = {"read": page.evaluate(READ), "tables": page.evaluate(TABLES),
                        "contact": page.evaluate("() => document.getElementById('rigid-contact').textContent"),
                        "arrows": arrows(page)}
        page.locator("#rigid").scroll_into_view_if_needed()
        page.screenshot(path=os.path.join(out_dir, "rigid-floor-1280.png"))

        # An extreme valid case: a ball of 1e-300 at 1e300 sticks (e = 0) to the end of a rod of
        # length 1e-100 (crunch 5e299, spins of 1e100).
        extreme = {"m1": "1e-300", "m2": "1", "v1": "1e300", "target": "rod 1e-100", "hit_at": "end", "e": "0"}
        page.evaluate(FILL, extreme)
        out["extreme"] = {"case": extreme, "read": page.evaluate(READ), "bad": page.evaluate(BAD)}
        page.locator("#rigid-svg").screenshot(path=os.path.join(out_dir, "rigid-extreme.png"))

        # A bad input greys the panel with the module's message.
        page.evaluate(FILL, {"m1": "1", "m2": "4", "v1": "3", "target": "rod 2", "hit_at": "5", "e": "1"})
        out["bad"] = {"read": page.evaluate(READ),
                      "stale": page.evaluate("() => document.getElementById('rigid-svg').closest('figure').classList.contains('stale')"),
                      "invalid": page.evaluate("() => document.getElementById('r-hit_at').getAttribute('aria-invalid')")}

        # The door on its hinge, then the phone.
        page.evaluate(FILL, {"m1": "50 g", "m2": "2 kg", "v1": "10 m/s", "target": "door 0.9 m", "pivot": "end", "hit_at": "0.6 m"})
        page.locator("#rigid").scroll_into_view_if_needed()
        page.screenshot(path=os.path.join(out_dir, "rigid-door-1280.png"))
        page.set_viewport_size({"width": 390, "height": 844})
        page.wait_for_timeout(200)
        page.locator("#rigid-svg").scroll_into_view_if_needed()
        page.screenshot(path=os.path.join(out_dir, "rigid-door-390.png"))
        page.locator("#rigid-normal-svg").scroll_into_view_if_needed()
        page.screenshot(path=os.path.join(out_dir, "rigid-normal-390.png"))
        out["phone"] = page.evaluate("""() => ({ window: window.innerWidth,
          page: document.documentElement.scrollWidth,
          panel: document.getElementById('rigid').getBoundingClientRect().right })""")
        browser.close()
    out["seconds"] = time.time() - start
    print(json.dumps(out))


if __name__ == "__main__":
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    main()
