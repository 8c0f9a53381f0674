"""Drives `collide view`'s panel of up to five pucks in headless Chromium for
tests/suite/view_nbody.rs (issue 43, section 2): python3 view_nbody.py PAGE.html OUT_DIR
CASES.json prints one JSON object of what the page did, in one page load:

- `cases`: for each case of CASES.json (mode, masses, velocities, fin, positions, radii, e),
  typed into the panel: `#nball-state` and `#nball-command` as the page shows them (or its
  error), and whether its pictures hold NaN or Infinity;
- `cue`: the preset "cue ball onto two touching balls": the velocities table as the panel shows
  it, its state and command;
- `motion`: the cue ball's centre on screen at the impact (t = 0) and one step after, with the
  picture's velocity at that time (the step moves it along v');
- `bad`: a negative mass: the error, the field marked, the panel greyed, the state emptied;
- `arrow`: one step after the impact, the cue ball's (slow) arrow: its ends, and the puck's centre
  and radius on screen; `labels`: the boxes of the momenta chart's names (P, px, py);
- `phone`: the panel at 390x844 with five touching balls: its width against the window's; for
  them and for the cue ball's preset, each input's text against its box and the table of
  values' width against its box's.
Console messages and page errors are reported under `console`. Screenshots of the panel at
1280x800 and 390x844 are left in OUT_DIR."""
import json, os, sys, time

from playwright.sync_api import sync_playwright

from view_browser import CHROMIUM_FLAGS, wait_ready

# Fills the panel at once and solves (as typing does, one input event).
FILL = """c => {
  const $ = (id) => document.getElementById(id);
  $('nb-count').value = String(c.masses.length);
  for (const r of document.querySelectorAll('input[name="nb-mode"]')) r.checked = r.value === c.mode;
  $('nb-e').value = c.e || 'elastic';
  const lists = { m: c.masses, v: c.velocities, f: c.fin, x: c.positions, r: c.radii };
  for (const k in lists) (lists[k] || []).forEach((t, i) => { $('nb-' + k + (i + 1)).value = t; });
  $('nb-m1').dispatchEvent(new Event('input'));
}"""

READ = """() => ({ state: document.getElementById('nball-state').textContent,
  command: document.getElementById('nball-command').textContent,
  error: document.getElementById('nball-error').hidden ? null : document.getElementById('nball-error').textContent,
  bad: /NaN|Infinity/.test(['nball-svg', 'nball-momentum-svg'].map(id => document.getElementById(id).outerHTML).join('')) })"""

TABLES = """() => Object.fromEntries([...document.querySelectorAll('#nball-numbers table')].map(t =>
  [t.caption.textContent, [...t.tBodies[0].rows].map(r => [...r.cells].map(c => c.textContent))]))"""

PUCK = """() => { const c = document.getElementById('nb-puck-1');
  return { x: Number(c.getAttribute('cx')), y: Number(c.getAttribute('cy')), t: collideView.nbody.t }; }"""


# The cue ball's arrow after the impact: where its line starts and where its head's tip is,
# with the puck's centre and radius (screen units of the picture).
ARROW = """() => { const g = document.getElementById('nb-fin-1'), c = document.getElementById('nb-puck-1');
  const line = g.querySelector('line'), tip = g.querySelector('polygon').getAttribute('points').split(' ')[0].split(',').map(Number);
  return { from: [+line.getAttribute('x1'), +line.getAttribute('y1')], tip,
    centre: [+c.getAttribute('cx'), +c.getAttribute('cy')], r: +c.getAttribute('r'),
    map: JSON.parse(document.getElementById('nball-svg').dataset.map), fin: collideView.nbodyPicture().fin[0] }; }"""

LABELS = """() => [...document.querySelectorAll('#nball-momentum-svg text.label')].map(t => {
  const b = t.getBBox(); return [t.textContent, b.x, b.y, b.width, b.height]; })"""

# Each input of the pucks' table shown (its text wider than its box scrolls inside it), and the
# table of values' width against its box's.
FIT = """() => ({ inputs: [...document.querySelectorAll('#nb-rows input')].filter(i => i.offsetParent)
    .map(i => [i.id, i.value, i.scrollWidth, i.clientWidth]),
  numbers: [document.getElementById('nball-numbers').scrollWidth, document.getElementById('nball-numbers').clientWidth] })"""


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

        out["cases"] = []
        for c in cases:
            page.evaluate(FILL, c)
            out["cases"].append(page.evaluate(READ))

        # The preset of physics.md section 8, read from the panel.
        page.select_option("#nb-preset", "cue2")
        out["cue"] = {"tables": page.evaluate(TABLES), "read": page.evaluate(READ)}
        page.locator("#nball").scroll_into_view_if_needed()
        page.screenshot(path=os.path.join(out_dir, "nball-cue-before-1280.png"))

        # The time run to the impact, then one step after it (the buttons a user presses).
        page.evaluate("() => { const r = document.getElementById('nball-time'); r.value = '0'; r.dispatchEvent(new Event('input')); }")
        at_impact = page.evaluate(PUCK)
        page.click("#nball-step")
        after = page.evaluate(PUCK)
        out["motion"] = {"impact": at_impact, "after": after,
                         "map": json.loads(page.get_attribute("#nball-svg", "data-map")),
                         "fin": page.evaluate("() => collideView.nbodyPicture().fin[0]")}
        out["arrow"] = page.evaluate(ARROW)
        out["labels"] = page.evaluate(LABELS)
        page.screenshot(path=os.path.join(out_dir, "nball-cue-after-1280.png"))
        page.click("#nball-play")
        page.wait_for_timeout(300)
        page.click("#nball-play")
        out["played"] = page.evaluate(PUCK)

        # The rack of 1 + 2, for the picture.
        page.select_option("#nb-preset", "rack3")
        page.click("#nball-step")
        page.locator("#nball").scroll_into_view_if_needed()
        page.screenshot(path=os.path.join(out_dir, "nball-rack-1280.png"))

        # A bad input greys the panel with the module's message.
        page.fill("#nb-m2", "-1")
        out["bad"] = {"read": page.evaluate(READ),
                      "stale": page.evaluate("() => document.getElementById('nball-svg').closest('figure').classList.contains('stale')"),
                      "invalid": page.evaluate("() => document.getElementById('nb-m2').getAttribute('aria-invalid')")}

        # Five touching balls on a phone.
        page.select_option("#nb-preset", "cradle")
        page.set_viewport_size({"width": 390, "height": 844})
        page.wait_for_timeout(200)
        page.locator("#nball-form").scroll_into_view_if_needed()
        page.screenshot(path=os.path.join(out_dir, "nball-form-390.png"))
        page.locator("#nball-svg").scroll_into_view_if_needed()
        page.screenshot(path=os.path.join(out_dir, "nball-cradle-390.png"))
        out["phone"] = page.evaluate("""() => ({ window: window.innerWidth,
          page: document.documentElement.scrollWidth,
          panel: document.getElementById('nball').getBoundingClientRect().right,
          bad: /NaN|Infinity/.test(document.getElementById('nball').outerHTML) })""")
        out["phone"]["fit"] = [page.evaluate(FIT)]
        page.select_option("#nb-preset", "cue2")
        out["phone"]["fit"].append(page.evaluate(FIT))
        browser.close()
    out["seconds"] = time.time() - start
    print(json.dumps(out))


if __name__ == "__main__":
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    main()
