"""Types hostile tokens into every text input of `collide view`'s page in headless Chromium, for
tests/suite/view_tokens.rs: python3 view_tokens.py PAGE.html TOKENS.json prints one JSON object,
for each input and token what the page showed: its panel's error message, whether the panel is
greyed (an element marked stale), whether any SVG holds NaN or Infinity, the state JSON and the
command the panel shows, and the page and console errors so far; then the input's own value typed
back, and whether the panel's error went away. Needs what view_browser.py needs."""
import json, os, sys, tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from view_browser import CHROMIUM_FLAGS, wait_ready  # noqa: E402
from playwright.sync_api import sync_playwright  # noqa: E402

# Each panel: its text inputs, its error, state and command elements.
PANELS = {
    "two-body": (["m1", "m2", "v1", "v2", "e", "inertia"], "case-error", "state", "command"),
    "stack": (["t-masses", "t-sizes", "t-positions", "t-velocities", "t-e", "t-e-wall",
               "t-gravity", "t-floor", "t-until"], "track-error", "track-state", "track-command"),
    "plane": (["p-m1", "p-m2", "p-v1", "p-v2", "p-e", "p-r1", "p-r2", "p-b", "p-normal"],
              "plane-error", "plane-state", "plane-command"),
}

LOOK = """([panel, error, state, command]) => {
    const p = document.getElementById(panel), e = document.getElementById(error);
    const svgs = [...document.querySelectorAll('svg')].map((s) => s.outerHTML).join('');
    return {error: e.hidden ? '' : e.textContent, stale: p.querySelectorAll('.stale').length,
            svg_bad: (svgs.match(/NaN|Infinity/g) || []).length,
            state: document.getElementById(state).textContent,
            command: document.getElementById(command).textContent};
}"""


def main():
    page_path, tokens_path = sys.argv[1], sys.argv[2]
    tokens = json.load(open(tokens_path))
    out = {"console": [], "errors": [], "seen": []}
    with sync_playwright() as p, tempfile.TemporaryDirectory() as profile:
        ctx = p.chromium.launch_persistent_context(
            profile, executable_path=os.environ.get("COLLIDE_CHROMIUM", "/usr/bin/chromium"),
            headless=True, args=CHROMIUM_FLAGS, viewport={"width": 1400, "height": 1000})
        page = ctx.new_page()
        page.on("console", lambda m: out["console"].append([m.type, m.text]))
        page.on("pageerror", lambda e: out["errors"].append(str(e)))
        page.goto("file://" + os.path.abspath(page_path))
        wait_ready(page)
        for panel, (inputs, error, state, command) in PANELS.items():
            for field in inputs:
                if field == "p-normal":
                    page.check('#plane input[value="normal"]')
                sel = "#" + field
                own = page.eval_on_selector(sel, "e => e.value")
                for token in tokens:
                    page.fill(sel, token)
                    page.dispatch_event(sel, "change")
                    page.wait_for_timeout(30)
                    seen = page.evaluate(LOOK, [panel, error, state, command])
                    seen.update({"field": field, "token": token,
                                 "errors": len(out["errors"]),
                                 "console_errors": sum(1 for c in out["console"] if c[0] == "error")})
                    page.fill(sel, own)
                    page.dispatch_event(sel, "change")
                    page.wait_for_timeout(30)
                    back = page.evaluate(LOOK, [panel, error, state, command])
                    seen["back"] = {"error": back["error"], "stale": back["stale"],
                                    "svg_bad": back["svg_bad"]}
                    out["seen"].append(seen)
        ctx.close()
    json.dump(out, sys.stdout, allow_nan=False)


if __name__ == "__main__":
    main()
