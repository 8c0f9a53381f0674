// collide view: the page's script. It draws and handles input only; every number comes from
// collide's Rust core, compiled to WebAssembly and embedded in this page (see docs/view.md).
// The script is in parts by job (src/view/page.rs runs them in order, inside one function whose
// scope they share): this one (the core, drawing helpers, the velocity plane, players, copy
// buttons), bars.js (the momentum and energy bars, the sentences said), two_body.js (the velocity plane and the dual panel), plane.js (two pucks in the
// plane), stack.js (the superball stack) and start.js.
  const $ = (id) => document.getElementById(id);
  const NS = "http://www.w3.org/2000/svg";
  const data = JSON.parse($("setup").textContent);
  const reduceMotion = window.matchMedia && window.matchMedia("(prefers-reduced-motion: reduce)").matches;

  // What tests and curious users can read: whether the core is running, how long each recompute
  // + redraw of a drag took (IN on the velocity plane; an arrow in the plane), and the last run +
  // redraw of the stack (milliseconds).
  const view = { ready: false, timings: [], planeTimings: [], lastUpdateMs: NaN, stackMs: NaN,
    time: () => ({ dual: dual.t, stack: stack.t }) };
  window.collideView = view;

  // ---------------------------------------------------------------- the core (WebAssembly)
  let core = null;

  async function loadCore() {
    if (typeof DecompressionStream !== "function") {
      throw new Error("this browser has no DecompressionStream: Chrome 80, Firefox 113, Safari 16.4 or newer is needed");
    }
    const raw = atob($("module").textContent.replace(/\s+/g, ""));
    const packed = new Uint8Array(raw.length);
    for (let i = 0; i < raw.length; i++) packed[i] = raw.charCodeAt(i);
    const inflated = new Blob([packed]).stream().pipeThrough(new DecompressionStream("deflate"));
    const bytes = await new Response(inflated).arrayBuffer();
    const { instance } = await WebAssembly.instantiate(bytes, {});
    const ex = instance.exports;
    const encoder = new TextEncoder();
    const decoder = new TextDecoder();
    return function ask(request) {
      const input = encoder.encode(JSON.stringify(request));
      const at = ex.alloc(input.length);
      new Uint8Array(ex.memory.buffer, at, input.length).set(input);
      const n = ex.call(at, input.length);
      return JSON.parse(decoder.decode(new Uint8Array(ex.memory.buffer, ex.answer(), n)));
    };
  }

  // ---------------------------------------------------------------- drawing helpers
  function el(parent, name, attrs, text) {
    const e = document.createElementNS(NS, name);
    if (attrs) for (const k in attrs) e.setAttribute(k, attrs[k]);
    if (text !== undefined) e.textContent = text;
    if (parent) parent.appendChild(e);
    return e;
  }
  function clear(node) {
    while (node.firstChild) node.removeChild(node.firstChild);
  }
  const r2 = (x) => Math.round(x * 100) / 100;
  const pts = (list) => list.map((p) => r2(p[0]) + "," + r2(p[1])).join(" ");
  const minus = (s) => s.replace(/-/g, "\u2212");

  // A number with `digits` significant digits, as people read it (the JSON keeps them all).
  function fmt(x, digits) {
    if (typeof x !== "number" || !isFinite(x)) return String(x);
    if (x === 0) return "0";
    const a = Math.abs(x);
    let s;
    if (a >= 1e7 || a < 1e-4) {
      s = x.toExponential(digits - 1).replace(/\.?0+e/, "e").replace("e+", "e");
    } else {
      s = String(Number(x.toPrecision(digits)));
    }
    return minus(s);
  }
  const short = (x) => fmt(x, 4);
  const num = (x) => fmt(x, 7);

  // A table of numbers in `box`: its caption, the head's cells and the rows (a row's header
  // first), as HTML for the names and text for the values.
  function numbersTable(box, caption, head, rows) {
    const t = document.createElement("table");
    t.createCaption().innerHTML = caption;
    const h = t.createTHead().insertRow();
    for (const x of head) { const th = document.createElement("th"); th.innerHTML = x; h.appendChild(th); }
    const body = t.createTBody();
    for (const r of rows) {
      const tr = body.insertRow();
      const th = document.createElement("th");
      th.scope = "row"; th.innerHTML = r[0]; tr.appendChild(th);
      for (const x of r.slice(1)) tr.insertCell().textContent = x;
    }
    box.appendChild(t);
  }

  // The element `id` drawn again by `draw(box)`: into a detached box, whose text is copied into
  // the live one where both hold the same elements (a table of numbers during a drag: only its
  // values change, and the browser has no new element to style), else its children replace
  // the live one's.
  function fillBox(id, draw) {
    const box = document.createElement("div");
    draw(box);
    const live = $(id);
    if (!sameText(live, box)) live.replaceChildren(...box.childNodes);
  }
  // Copies the text of `fresh` into `live` node by node while their elements and attributes
  // are the same; false where they differ.
  function sameText(live, fresh) {
    const a = live.childNodes, b = fresh.childNodes;
    if (a.length !== b.length) return false;
    for (let i = 0; i < a.length; i++) {
      const p = a[i], q = b[i];
      if (p.nodeType !== q.nodeType || p.nodeName !== q.nodeName) return false;
      if (p.nodeType === Node.TEXT_NODE) {
        if (p.data !== q.data) p.data = q.data;
        continue;
      }
      if (p.nodeType !== Node.ELEMENT_NODE || p.attributes.length !== q.attributes.length) return false;
      for (const at of q.attributes) if (p.getAttribute(at.name) !== at.value) return false;
      if (!sameText(p, q)) return false;
    }
    return true;
  }

  // About `n` round ticks from lo to hi.
  // Spans are taken by halves (hi/2 - lo/2): a box from -1e308 to 1e308 is 2e308 wide, which
  // binary64 cannot hold (the valid case M 1, 1e-308; V 0, 1e308 draws such a box).
  function ticks(lo, hi, n) {
    const half = hi / 2 - lo / 2;
    if (!(half > 0) || !isFinite(half)) return [];
    const raw = (half / n) * 2;
    const p = Math.pow(10, Math.floor(Math.log10(raw)));
    const step = [1, 2, 5, 10].map((k) => k * p).find((s) => s >= raw) || 10 * p;
    const out = [];
    const end = hi + 1e-9 * raw * n;
    for (let k = Math.ceil(lo / step); k * step <= end && out.length <= 40; k++) out.push(k * step === 0 ? 0 : k * step);
    return out.length > 40 || !out.every(isFinite) ? [] : out;
  }

  // The part of the line k1 x + k2 y = c inside the box [x0, x1] x [y0, y1].
  function clipLine(k1, k2, c, box) {
    const hits = [];
    const within = (v, lo, hi) => isFinite(v) && v >= lo - 2e-9 * (hi / 2 - lo / 2) && v <= hi + 2e-9 * (hi / 2 - lo / 2);
    if (k2 !== 0) {
      for (const x of [box.x0, box.x1]) {
        const y = (c - k1 * x) / k2;
        if (within(y, box.y0, box.y1)) hits.push([x, y]);
      }
    }
    if (k1 !== 0) {
      for (const y of [box.y0, box.y1]) {
        const x = (c - k2 * y) / k1;
        if (within(x, box.x0, box.x1)) hits.push([x, y]);
      }
    }
    hits.sort((a, b) => a[0] - b[0] || a[1] - b[1]);
    return hits.length >= 2 ? [hits[0], hits[hits.length - 1]] : null;
  }

  // Chart text at one readable size on every screen: a chart's `--k` is its viewBox units per
  // screen pixel, and page.css sizes its text in those units (11 px ticks), so that a phone,
  // which draws the 560-unit velocity plane 340 px wide, shows the same 11 px text as a desktop.
  // Returns whether a drawn chart's scale changed (its labels, placed by measure, are redrawn).
  const textScale = new Map();
  const shownWidth = new Map(); // each chart's width on screen when last measured (px)
  function scaleText(svg) {
    const w = svg.getBoundingClientRect().width;
    if (!(w > 0)) return false;
    shownWidth.set(svg, w);
    const k = Math.min(4, Math.max(0.5, svg.viewBox.baseVal.width / w));
    const old = textScale.get(svg);
    if (old !== undefined && Math.abs(old - k) < 0.02 * old) return false;
    textScale.set(svg, k);
    svg.style.setProperty("--k", k.toFixed(5));
    return old !== undefined;
  }
  const kOf = (svg) => textScale.get(svg.ownerSVGElement || svg) || 1;

  // A 2-D plot area: data box to screen, with grid and tick labels.
  // The map of a plot area: data box to screen.
  function axesMap(area, box) {
    // By halves, as in `ticks`: no difference of two huge numbers overflows.
    const sx = area.w / 2 / (box.x1 / 2 - box.x0 / 2);
    const sy = area.h / 2 / (box.y1 / 2 - box.y0 / 2);
    const X = (x) => area.x + (x / 2 - box.x0 / 2) * (2 * sx);
    const Y = (y) => area.y + (box.y1 / 2 - y / 2) * (2 * sy);
    return { X, Y, sx, sy };
  }
  function frameAxes(svg, area, box, labels) {
    const { X, Y, sx, sy } = axesMap(area, box);
    el(svg, "rect", { x: area.x, y: area.y, width: area.w, height: area.h, fill: "#fff", stroke: "#d1d5db" });
    const grid = el(svg, "g", { stroke: "#eef0f3", "stroke-width": 1 });
    const tickText = el(svg, "g", { class: "tick" });
    // Fewer ticks where the text is large against the picture (a phone).
    const k = kOf(svg);
    for (const t of ticks(box.x0, box.x1, area.w / k > 300 ? 6 : 4)) {
      el(grid, "line", { x1: r2(X(t)), x2: r2(X(t)), y1: area.y, y2: area.y + area.h });
      el(tickText, "text", { x: r2(X(t)), y: r2(area.y + area.h + 3 + 11 * k), "text-anchor": "middle" }, short(t));
    }
    for (const t of ticks(box.y0, box.y1, area.h / k > 300 ? 6 : 4)) {
      el(grid, "line", { x1: area.x, x2: area.x + area.w, y1: r2(Y(t)), y2: r2(Y(t)) });
      el(tickText, "text", { x: area.x - 5, y: r2(Y(t) + 4 * k), "text-anchor": "end" }, short(t));
    }
    const axes = el(svg, "g", { stroke: "#6b7280", "stroke-width": 1.2 });
    if (box.y0 <= 0 && box.y1 >= 0) el(axes, "line", { x1: area.x, x2: area.x + area.w, y1: r2(Y(0)), y2: r2(Y(0)) });
    if (box.x0 <= 0 && box.x1 >= 0) el(axes, "line", { x1: r2(X(0)), x2: r2(X(0)), y1: area.y, y2: area.y + area.h });
    if (labels) {
      // Each axis named at its far end: beside the axis line when it is in the picture.
      const across = box.y0 <= 0 && box.y1 >= 0 ? Y(0) - 6 : area.y + area.h - 6;
      const up = box.x0 <= 0 && box.x1 >= 0 ? X(0) + 7 : area.x + 6;
      const style = { class: "label", "font-style": "italic", "paint-order": "stroke", stroke: "#fff", "stroke-width": 4 };
      el(svg, "text", Object.assign({ x: area.x + area.w - 5, y: r2(across), "text-anchor": "end" }, style), labels[0]);
      el(svg, "text", Object.assign({ x: r2(up), y: area.y + 15, "text-anchor": "start" }, style), labels[1]);
    }
    return { X, Y, sx, sy };
  }

  // A core's answer in the page: its error shown in the element `box`, the input of its field
  // (`ids[field]`, else `fallback`) marked invalid, the outputs `cleared` emptied and the
  // pictures and tables `stale` greyed out and labelled as the last valid case (they would show
  // the last good case as if it were this one); no error clears the marks.
  function showError(answer, ids, fallback, box, cleared, stale) {
    for (const id of Object.values(ids)) $(id).removeAttribute("aria-invalid");
    markStale(stale || [], !answer.ok);
    if (answer.ok) {
      $(box).hidden = true;
      return;
    }
    $(ids[answer.field] || fallback).setAttribute("aria-invalid", "true");
    $(box).textContent = answer.error;
    $(box).hidden = false;
    for (const id of cleared) $(id).textContent = "";
  }

  // Greys out the outputs `ids` (a picture's figure, or the element) with a note on each that
  // they show the last valid case, or takes it away.
  function markStale(ids, on) {
    for (const id of ids) {
      const node = $(id).closest("figure") || $(id);
      node.classList.toggle("stale", on);
      const old = document.querySelector('.stale-note[data-for="' + id + '"]');
      if (!on) {
        if (old) old.remove();
      } else if (!old) {
        const note = document.createElement("p");
        note.className = "stale-note";
        note.dataset.for = id;
        note.textContent = "Last valid case (not the inputs above: see the error)";
        // Inside a figure or a table's box, else before the picture.
        if (node.tagName.toLowerCase() === "svg") node.parentNode.insertBefore(note, node);
        else node.insertBefore(note, node.firstChild);
      }
    }
  }

  // The box of an SVG text about as `getBBox` gives it, a little larger (a tenth of the font's
  // size more on each side, a fifth more after an italic): the advance of its glyphs across and
  // the font's ascent and descent, measured on a canvas in the font page.css gives its class
  // (`tick`, `label`, `title`, at the chart's `--k`). Reading `getBBox` after a change lays the
  // page out again: a forced layout per label at every step of a drag. Other texts are asked.
  const measure = document.createElement("canvas").getContext("2d");
  const SVG_FONT = 'system-ui, -apple-system, "Segoe UI", Roboto, Arial, sans-serif';
  const TEXT_CLASS = { tick: [400, 11], label: [600, 12.5], title: [400, 13] };
  function textBox(t) {
    const cls = (t.getAttribute("class") || "").split(" ").find((c) => TEXT_CLASS[c]);
    if (!measure || !cls) { const b = t.getBBox(); return { x: b.x, y: b.y, width: b.width, height: b.height }; }
    const [weight, size] = TEXT_CLASS[cls];
    const px = size * kOf(t), italic = t.getAttribute("font-style") === "italic";
    measure.font = (italic ? "italic " : "") + weight + " " + px + "px " + SVG_FONT;
    // SVG text collapses its spaces.
    const m = measure.measureText(t.textContent.replace(/\s+/g, " ").trim());
    const anchor = t.getAttribute("text-anchor");
    const x = Number(t.getAttribute("x")) - (anchor === "end" ? m.width : anchor === "middle" ? m.width / 2 : 0);
    const up = m.fontBoundingBoxAscent, down = m.fontBoundingBoxDescent;
    return { x: x - 0.1 * px, y: Number(t.getAttribute("y")) - up - 0.1 * px, width: m.width + (italic ? 0.4 : 0.2) * px, height: up + down + 0.2 * px };
  }

  // A chart's frame (grid, ticks, axis names: `draw(defs)`) drawn again unless `keep` and the
  // frame drawn last time had the same `key` (and text scale); what was drawn after the frame
  // is taken away either way. A drag that keeps a chart's scale then has fewer new elements
  // for the browser to style and lay out at each step.
  function chartFrame(svg, key, keep, draw) {
    const full = key + "|" + kOf(svg);
    const mark = svg.querySelector(":scope > defs.frame");
    if (keep && mark && mark.dataset.key === full) {
      while (mark.nextSibling) svg.removeChild(mark.nextSibling);
      return;
    }
    clear(svg);
    const defs = el(null, "defs", { class: "frame" });
    defs.dataset.key = full;
    draw(defs);
    svg.appendChild(defs);
  }

  // A text in `parent` at `attrs`, moved down a line at a time while it would overlap a box of
  // `placed` (measured, not estimated: `textBox`); its box is added to `placed`.
  function placeText(parent, placed, attrs, text) {
    const t = el(parent, "text", attrs, text);
    const hits = (b) => placed.some((q) => b.x < q.x + q.width && q.x < b.x + b.width && b.y < q.y + q.height && q.y < b.y + b.height);
    for (let k = 0; k < 12 && hits(textBox(t)); k++) t.setAttribute("y", r2(Number(t.getAttribute("y")) + 15));
    placed.push(textBox(t));
    return t;
  }
  // The boxes of the texts already in `svg` (axis names) that labels must not cover.
  const boxesOf = (svg) => [...svg.querySelectorAll("text.label")].map(textBox);

  // A drag redraws at each frame only what it moves in sight: a picture or table off screen (the
  // tables under the velocity plane, the rail, Space vs Space and the bars below it) waits, and
  // is drawn when it comes into view or when the drag ends (`drawWaiting`), so that the browser
  // styles, lays out and paints only what the drag changes on screen. `drawSeen(node, draw,
  // later, soon)` draws now unless `later` (a drag) and `node` is off screen; with `soon` too
  // (a part the pointer does not move: the tables, the bars beside a dragged car), a node in
  // sight is drawn after the frame, once the page is idle (`requestIdleCallback`), so that the
  // frame that follows the pointer draws only what it drags. A later call's drawing replaces a
  // waiting one (each draws the whole node from the last answer).
  const offScreen = new Set();
  const waiting = new Map();
  const watched = new WeakSet();
  const sight = typeof IntersectionObserver === "function" ? new IntersectionObserver((entries) => {
    for (const e of entries) {
      if (!e.isIntersecting) { offScreen.add(e.target); continue; }
      offScreen.delete(e.target);
      const draw = waiting.get(e.target);
      if (draw) { waiting.delete(e.target); draw(); }
    }
  }, { rootMargin: "100px" }) : null;
  const whenIdle = typeof requestIdleCallback === "function" ? (f) => requestIdleCallback(f, { timeout: 100 }) : (f) => setTimeout(f, 30);
  let idleQueued = false;
  function drawSeen(node, draw, later, soon) {
    if (sight && !watched.has(node)) { watched.add(node); sight.observe(node); }
    if (later && (soon || offScreen.has(node))) {
      waiting.set(node, draw);
      if (!offScreen.has(node) && !idleQueued) {
        idleQueued = true;
        whenIdle(() => {
          idleQueued = false;
          for (const [n, d] of [...waiting]) if (!offScreen.has(n)) { waiting.delete(n); d(); }
        });
      }
      return;
    }
    waiting.delete(node);
    draw();
  }
  function drawWaiting() {
    for (const [node, draw] of [...waiting]) { waiting.delete(node); draw(); }
  }

  // ---------------------------------------------------------------- the velocity plane
  // The data box of a velocity plane (lecture Figs. 1.3, 2.3): square, around the origin, the
  // pictures' IN, COM and FIN and their energy ellipses (with `zoom`, around the points only);
  // `more(p, add)` adds points of a picture.
  function fitVelocityPlane(pictures, zoom, more) {
    let x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity;
    const add = (p) => {
      if (!isFinite(p[0]) || !isFinite(p[1])) return;
      x0 = Math.min(x0, p[0]); x1 = Math.max(x1, p[0]);
      y0 = Math.min(y0, p[1]); y1 = Math.max(y1, p[1]);
    };
    if (!zoom) add([0, 0]);
    for (const p of pictures) {
      [p.in, p.com, p.fin].forEach(add);
      for (const k of zoom ? [] : ["in", "com", "fin"]) {
        const e = p.ellipses[k];
        const [q1, q2] = e.axes;
        const hx = Math.hypot(e.a * q1[0], e.b * q2[0]);
        const hy = Math.hypot(e.a * q1[1], e.b * q2[1]);
        add([hx, hy]); add([-hx, -hy]);
      }
      if (more) more(p, add);
    }
    // Half the side, by halves (a side of 2e308 overflows binary64), at most the largest double.
    let half = Math.max(x1 / 2 - x0 / 2, y1 / 2 - y0 / 2) * 1.12;
    half = half > 0 ? Math.min(half, Number.MAX_VALUE) : 1;
    const cx = x0 / 2 + x1 / 2, cy = y0 / 2 + y1 / 2;
    const P = { left: 62, top: 34, side: 470 };
    const s = P.side / 2 / half;
    const box = { x0: cx - half, x1: cx + half, y0: cy - half, y1: cy + half };
    return { box, s, ox: P.left - s * box.x0, oy: P.top + s * box.y1, area: { x: P.left, y: P.top, w: P.side, h: P.side } };
  }

  // The step a dragged point moves by (a drag snaps to it; an arrow key moves one): the power of
  // 10 at or above one screen unit of the map (`map.s` screen units per unit).
  const snapStep = (map) => Math.pow(10, Math.ceil(Math.log10(1 / map.s) - 1e-9));
  function snapText(x, step) {
    const decimals = Math.max(0, -Math.round(Math.log10(step)));
    const snapped = Math.round(x / step) * step;
    // Fixed point up to 20 decimals (toFixed takes at most 100); smaller steps in exponent form,
    // to the digits the step keeps.
    let t = decimals <= 20 && Math.abs(snapped) < 1e21 ? snapped.toFixed(decimals)
      : String(Number(snapped.toPrecision(Math.min(21, Math.max(1, Math.floor(Math.log10(Math.abs(snapped) / step)) + 1)))));
    if (/^-0(\.0*)?$/.test(t) || t === "-0") t = t.replace("-", "");
    return t;
  }

  // A typed quantity as a number and its unit ("1500 kg" -> [1500, "kg"]); NaN where the number
  // is not one (a fraction a/b is read).
  function splitUnit(text) {
    const m = /^\s*([+-]?[0-9.]+(?:[eE][+-]?[0-9]+)?(?:\/[0-9.]+)?)\s*(.*)$/.exec(text);
    return m ? [valueOf(m[1]), m[2].trim()] : [NaN, ""];
  }

  // A logarithmic mass slider (`range`, log10 of the mass) set to the typed mass, its range
  // widened to hold it; the typed text from the slider keeps the typed unit.
  function massToSlider(range, text) {
    const [v] = splitUnit(text);
    if (!(v > 0) || !isFinite(v)) return;
    const lg = Math.log10(v);
    if (lg < Number(range.min) || lg > Number(range.max)) {
      range.min = String(Math.floor(lg) - 2);
      range.max = String(Math.floor(lg) + 2);
    }
    range.value = String(lg);
  }
  function sliderToMass(range, text) {
    const unit = splitUnit(text)[1];
    return String(Number(Math.pow(10, Number(range.value)).toPrecision(3))) + (unit ? " " + unit : "");
  }

  // A rail's velocity plane (a picture of the core's) in `svg` at `map`: axes, the title, the
  // 45-degree line V1 = V2, the momentum line, the IN, COM and FIN energy ellipses and the points
  // with their coordinates. Options: `title`, `axes` (the axes' names), `under(g, X, Y)` draws
  // more beneath the points, in the clipped area, `more(point)` adds points, and element ids
  // start with `prefix` (a page may hold several planes). With `keep` (a drag, the map kept),
  // the frame (grid, ticks, axis names and title) drawn last time stays if it is the same, and
  // only what moves is drawn again: fewer new elements for the browser to style and lay out.
  function velocityPlane(svg, p, map, opts) {
    const prefix = opts.prefix || "";
    const X = (x) => map.ox + map.s * x;
    const Y = (y) => map.oy - map.s * y;
    const a = map.area;
    const axes = opts.axes || ["V\u2081", "V\u2082"];
    const key = [a.x, a.y, a.w, a.h, map.box.x0, map.box.x1, map.box.y0, map.box.y1, opts.title, axes.join(), prefix].join("|");
    chartFrame(svg, key, opts.keep, (defs) => {
      frameAxes(svg, a, map.box, axes);
      el(svg, "text", { x: a.x, y: 20, class: "title" }, opts.title);
      const clip = el(defs, "clipPath", { id: prefix + "plane-clip" });
      el(clip, "rect", { x: a.x, y: a.y, width: a.w, height: a.h });
    });
    const g = el(svg, "g", { "clip-path": "url(#" + prefix + "plane-clip)" });
    const b = map.box;
    // The 45-degree line V1 = V2 and the momentum line k1 V1 + k2 V2 = P.
    const diag = clipLine(1, -1, 0, b);
    if (diag) el(g, "line", { x1: r2(X(diag[0][0])), y1: r2(Y(diag[0][1])), x2: r2(X(diag[1][0])), y2: r2(Y(diag[1][1])), stroke: "#9ca3af", "stroke-dasharray": "6 5", "stroke-width": 1.3 });
    const line = clipLine(p.line[0], p.line[1], p.line[2], b);
    if (line) el(g, "line", { id: prefix + "momentum-line", x1: r2(X(line[0][0])), y1: r2(Y(line[0][1])), x2: r2(X(line[1][0])), y2: r2(Y(line[1][1])), stroke: "var(--p)", "stroke-width": 2 });
    // The energy ellipses, centred on the frame's origin.
    const ellipse = (e, colour, id, dash) => {
      const angle = Math.atan2(e.axes[0][1], e.axes[0][0]) * 180 / Math.PI;
      const attrs = { id: prefix + id, cx: r2(X(0)), cy: r2(Y(0)), rx: Math.max(0, e.a * map.s), ry: Math.max(0, e.b * map.s), fill: "none", stroke: colour, "stroke-width": 2.2 };
      if (angle !== 0) attrs.transform = "rotate(" + r2(-angle) + " " + r2(X(0)) + " " + r2(Y(0)) + ")";
      if (dash) attrs["stroke-dasharray"] = dash;
      el(g, "ellipse", attrs);
    };
    ellipse(p.ellipses.com, "var(--com)", "ellipse-com");
    ellipse(p.ellipses.in, "var(--in)", "ellipse-in");
    if (p.e !== 0 && p.e !== 1) ellipse(p.ellipses.fin, "var(--fin)", "ellipse-fin", "7 4");
    if (opts.under) opts.under(g, X, Y);
    // The points and their coordinates (the IN-FIN chord lies on the momentum line).
    const labels = el(svg, "g", {});
    // An axis's name that IN, COM or FIN would cover (a point at the end of an axis: IN on the
    // V1 axis at the ellipse's edge) goes to the other side of its axis line.
    const dots = [p.in, p.com, p.fin].map((v) => [X(v[0]), Y(v[1])]);
    const names = svg.querySelectorAll(":scope > text.label[font-style=italic]");
    names.forEach((t, i) => {
      if (!t.dataset.x) Object.assign(t.dataset, { x: t.getAttribute("x"), y: t.getAttribute("y"), anchor: t.getAttribute("text-anchor") });
      t.setAttribute("x", t.dataset.x); t.setAttribute("y", t.dataset.y); t.setAttribute("text-anchor", t.dataset.anchor);
      const b = textBox(t);
      if (!dots.some(([x, y]) => x + 9 > b.x && x - 9 < b.x + b.width && y + 9 > b.y && y - 9 < b.y + b.height)) return;
      if (i === 0) t.setAttribute("y", r2(Number(t.dataset.y) + 12 + 12.5 * kOf(svg)));
      else { t.setAttribute("x", r2(Number(t.dataset.x) - 14)); t.setAttribute("text-anchor", "end"); }
    });
    // Labels beside their points, moved down a line where they would overlap another or an
    // axis name.
    const placed = boxesOf(svg);
    const point = (v, colour, name, id, r) => {
      const sx = X(v[0]), sy = Y(v[1]);
      el(svg, "circle", { id: prefix + id, cx: r2(sx), cy: r2(sy), r, fill: colour, stroke: "#fff", "stroke-width": 2 });
      const text = name + " (" + short(v[0]) + ", " + short(v[1]) + ")";
      const right = sx < a.x + a.w - 150;
      placeText(labels, placed, {
        x: r2(sx + (right ? 10 : -10)), y: r2(sy - 9), "text-anchor": right ? "start" : "end",
        class: "label", fill: colour, "paint-order": "stroke", stroke: "#fff", "stroke-width": 4,
      }, text);
    };
    point(p.in, "var(--in)", "IN", "point-in", 7);
    point(p.com, "var(--com)", "COM", "point-com", 5);
    point(p.fin, "var(--fin)", "FIN", "point-fin", 5.5);
    if (opts.more) opts.more(point);
    // IN on top, to be grabbed.
    svg.appendChild(svg.querySelector("#" + prefix + "point-in"));
    svg.appendChild(labels);
  }

  // A finger on a handle (`.handle`) of `svg` drags it, and the page does not scroll: its
  // `touch-action: none` is not honoured on an SVG shape by every browser (Chromium's is not),
  // so the touch is also taken here. Elsewhere on the picture a finger scrolls the page.
  function holdHandles(svg) {
    svg.addEventListener("touchstart", (ev) => {
      if (ev.target.classList && ev.target.classList.contains("handle")) ev.preventDefault();
    }, { passive: false });
  }

  // A Play/Pause button: while playing, `advance(seconds)` is called once a frame with the time
  // since the last one. Returns `pause()`.
  function player(button, advance) {
    let playing = false, last = 0;
    const tick = (now) => {
      // A disabled button (its panel shows a refused input) stops the animation.
      if (button.disabled && playing) {
        playing = false;
        button.textContent = "Play";
        button.setAttribute("aria-pressed", "false");
      }
      if (!playing) return;
      advance(last ? (now - last) / 1000 : 0);
      last = now;
      requestAnimationFrame(tick);
    };
    const show = () => {
      button.textContent = playing ? "Pause" : "Play";
      button.setAttribute("aria-pressed", String(playing));
    };
    button.addEventListener("click", () => {
      playing = !playing;
      last = 0;
      show();
      if (playing) requestAnimationFrame(tick);
    });
    return { pause: () => { playing = false; show(); } };
  }

  // PhET's controls for an animation (the buttons `<prefix>-play`, `-back`, `-step`, `-reset`
  // and the select `-speed`) whose time `o.get()` runs from `o.start` to `o.end()`; `o.set(t)`
  // sets and draws it. Play runs `o.rate` time units a second times the speed, round and round;
  // a step moves the time by `o.step()` back or forward, paused, within the ends; Reset pauses at
  // the start at 1x: the state as typed, before anything moved.
  function animation(prefix, o) {
    const speed = $(prefix + "-speed");
    const play = player($(prefix + "-play"), (dt) => {
      const t = o.get() + dt * o.rate * Number(speed.value);
      o.set(t > o.end() ? o.start : t);
    });
    const stepBy = (k) => {
      play.pause();
      o.set(Math.min(o.end(), Math.max(o.start, o.get() + k * o.step())));
    };
    $(prefix + "-step").addEventListener("click", () => stepBy(1));
    $(prefix + "-back").addEventListener("click", () => stepBy(-1));
    $(prefix + "-reset").addEventListener("click", () => {
      play.pause();
      speed.value = "1";
      o.set(o.start);
    });
  }

  function valueOf(text) {
    const t = text.trim();
    if (t === "elastic") return 1;
    if (t === "inelastic") return 0;
    const parts = t.split("/");
    return parts.length === 2 ? Number(parts[0]) / Number(parts[1]) : Number(t);
  }
  // ---------------------------------------------------------------- back to the shell
  function setupCopy() {
    for (const b of document.querySelectorAll("button.copy")) {
      b.addEventListener("click", () => {
        const text = $(b.dataset.copy).textContent;
        const done = () => { b.textContent = "Copied"; setTimeout(() => { b.textContent = "Copy"; }, 1200); };
        const fallback = () => {
          const area = document.createElement("textarea");
          area.value = text;
          document.body.appendChild(area);
          area.select();
          try { document.execCommand("copy"); done(); } catch (e) { b.textContent = "Select it"; }
          area.remove();
        };
        if (navigator.clipboard && navigator.clipboard.writeText) navigator.clipboard.writeText(text).then(done, fallback);
        else fallback();
      });
    }
  }

