"""Types hostile tokens into every text input of `collide view`'s page in headless Chromium, for
tests/suite/view_tokens.rs: python3 view_tokens.py PAGE.html TOKENS.json prints one JSON object,
for each input and token what the page showed: its panel's error message, whether the panel is
greyed (an element marked stale), whether any SVG holds NaN or Infinity, the state JSON and the
command the panel shows, and the page and console errors so far; then the input's own value typed
back, and whether the panel's error went away. Needs what view_browser.py needs."""
import json, os, sys, tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from view_browser import CHROMIUM_FLAGS, Phases, wait_ready  # noqa: E402
from playwright.sync_api import sync_playwright  # noqa: E402

# Each panel: its text inputs, its error, state and command elements.
PANELS = {
    "two-body": (["m1", "m2", "v1", "v2", "e", "inertia"], "case-error", "state", "command"),
    "stack": (["t-masses", "t-sizes", "t-positions", "t-velocities", "t-e", "t-e-wall",
               "t-gravity", "t-floor", "t-until"], "track-error", "track-state", "track-command"),
    "plane": (["p-m1", "p-m2", "p-v1", "p-v2", "p-e", "p-r1", "p-r2", "p-b", "p-normal"],
              "plane-error", "plane-state", "plane-command"),
}

# One step of a field: the value set as typed (focused, the value put in, its `input` event, then
# its `change` event: the two-body case and the plane solve on `input`, the stack on `change`;
# each handler redraws synchronously, so the page is read right after), and what the panel then
# shows. The pictures are searched for NaN and Infinity node by node (every tag and attribute
# name, attribute value, text and comment of every SVG: what their outerHTML would hold, without
# serialising them).
STEP = """([sel, value, panel, error, state, command]) => {
    const f = document.querySelector(sel);
    if (!f || f.disabled || f.readOnly || !f.getClientRects().length) throw new Error(sel + ' is not editable');
    f.focus();
    f.value = value;
    f.dispatchEvent(new Event('input', {bubbles: true}));
    f.dispatchEvent(new Event('change', {bubbles: true}));
    const p = document.getElementById(panel), e = document.getElementById(error);
    const bad = /NaN|Infinity/g, count = (t) => (t.match(bad) || []).length;
    let svg_bad = 0;
    for (const s of document.querySelectorAll('svg')) {
        const walk = document.createTreeWalker(s, NodeFilter.SHOW_ELEMENT | NodeFilter.SHOW_TEXT | NodeFilter.SHOW_COMMENT | NodeFilter.SHOW_CDATA_SECTION);
        for (let n = s; n; n = walk.nextNode()) {
            if (n.nodeType !== 1) { svg_bad += count(n.data); continue; }
            svg_bad += count(n.tagName);
            for (const a of n.attributes) svg_bad += count(a.name) + count(a.value);
        }
    }
    return {error: e.hidden ? '' : e.textContent, stale: p.querySelectorAll('.stale').length, svg_bad,
            state: document.getElementById(state).textContent,
            command: document.getElementById(command).textContent};
}"""


def main():
    page_path, tokens_path = sys.argv[1], sys.argv[2]
    tokens = json.load(open(tokens_path))
    out = {"console": [], "errors": [], "seen": []}
    phases = Phases()
    with sync_playwright() as p, tempfile.TemporaryDirectory() as profile:
        ctx = p.chromium.launch_persistent_context(
            profile, executable_path=os.environ.get("COLLIDE_CHROMIUM", "/usr/bin/chromium"),
            headless=True, args=CHROMIUM_FLAGS, viewport={"width": 1400, "height": 1000})
        page = ctx.new_page()
        page.on("console", lambda m: out["console"].append([m.type, m.text]))
        page.on("pageerror", lambda e: out["errors"].append(str(e)))
        page.goto("file://" + os.path.abspath(page_path))
        wait_ready(page)
        phases.done("launch and ready")
        for panel, (inputs, error, state, command) in PANELS.items():
            for field in inputs:
                if field == "p-normal":
                    page.check('#plane input[value="normal"]')
                sel = "#" + field
                own = page.eval_on_selector(sel, "e => e.value")
                for token in tokens:
                    seen = page.evaluate(STEP, [sel, token, panel, error, state, command])
                    seen.update({"field": field, "token": token,
                                 "errors": len(out["errors"]),
                                 "console_errors": sum(1 for c in out["console"] if c[0] == "error")})
                    back = page.evaluate(STEP, [sel, own, panel, error, state, command])
                    seen["back"] = {"error": back["error"], "stale": back["stale"],
                                    "svg_bad": back["svg_bad"]}
                    out["seen"].append(seen)
            phases.done(panel)
        ctx.close()
    json.dump(out, sys.stdout, allow_nan=False)


if __name__ == "__main__":
    main()
