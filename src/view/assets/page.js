// collide view: the page's script. It draws and handles input only; every number comes from
// collide's Rust core, compiled to WebAssembly and embedded in this page (see docs/view.md).
"use strict";
(function () {
  const $ = (id) => document.getElementById(id);
  const NS = "http://www.w3.org/2000/svg";
  const data = JSON.parse($("setup").textContent);
  const reduceMotion = window.matchMedia && window.matchMedia("(prefers-reduced-motion: reduce)").matches;

  // What tests and curious users can read: whether the core is running, how long each recompute
  // + redraw of a drag took, and the last run + redraw of the stack (milliseconds).
  const view = { ready: false, timings: [], lastUpdateMs: NaN, stackMs: NaN };
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

  // About `n` round ticks from lo to hi.
  function ticks(lo, hi, n) {
    const span = hi - lo;
    if (!(span > 0) || !isFinite(span)) return [];
    const raw = span / n;
    const p = Math.pow(10, Math.floor(Math.log10(raw)));
    const step = [1, 2, 5, 10].map((k) => k * p).find((s) => s >= raw) || 10 * p;
    const out = [];
    for (let k = Math.ceil(lo / step); k * step <= hi + 1e-9 * span; k++) out.push(k * step === 0 ? 0 : k * step);
    return out.length > 40 ? [] : out;
  }

  // The part of the line k1 x + k2 y = c inside the box [x0, x1] x [y0, y1].
  function clipLine(k1, k2, c, box) {
    const hits = [];
    const within = (v, lo, hi) => v >= lo - 1e-9 * (hi - lo) && v <= hi + 1e-9 * (hi - lo);
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

  // A 2-D plot area: data box to screen, with grid and tick labels.
  function frameAxes(svg, area, box, labels) {
    const sx = area.w / (box.x1 - box.x0);
    const sy = area.h / (box.y1 - box.y0);
    const X = (x) => area.x + (x - box.x0) * sx;
    const Y = (y) => area.y + (box.y1 - y) * sy;
    el(svg, "rect", { x: area.x, y: area.y, width: area.w, height: area.h, fill: "#fff", stroke: "#d1d5db" });
    const grid = el(svg, "g", { stroke: "#eef0f3", "stroke-width": 1 });
    const tickText = el(svg, "g", { class: "tick" });
    for (const t of ticks(box.x0, box.x1, area.w > 300 ? 6 : 4)) {
      el(grid, "line", { x1: r2(X(t)), x2: r2(X(t)), y1: area.y, y2: area.y + area.h });
      el(tickText, "text", { x: r2(X(t)), y: area.y + area.h + 14, "text-anchor": "middle" }, short(t));
    }
    for (const t of ticks(box.y0, box.y1, area.h > 300 ? 6 : 4)) {
      el(grid, "line", { x1: area.x, x2: area.x + area.w, y1: r2(Y(t)), y2: r2(Y(t)) });
      el(tickText, "text", { x: area.x - 5, y: r2(Y(t)) + 4, "text-anchor": "end" }, short(t));
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

  // ---------------------------------------------------------------- the two-body case
  const caseFields = ["m1", "m2", "v1", "v2", "e"];
  let caseAnswer = data.answers.solve; // the last good answer
  let caseState = null; // its JSON, parsed
  const plane = { map: null, keep: false, dragging: null, animation: 0 };

  function caseRequest(frame) {
    const r = { op: "solve" };
    const tensor = $("inertia").value.trim();
    if (tensor) r.inertia = tensor;
    for (const f of caseFields) {
      if (tensor && (f === "m1" || f === "m2")) continue;
      r[f] = $(f).value;
    }
    r.frame = frame === undefined ? currentFrame() : frame;
    r.reverse = $("reverse").checked;
    return r;
  }
  function currentFrame() {
    const checked = document.querySelector('input[name="frame"]:checked');
    return checked ? checked.value : "lab";
  }

  // Solves the case on screen and redraws; `keepMap` keeps the plane's scale (a drag).
  function solveCase(keepMap) {
    if (!core) return null;
    const answer = core(caseRequest());
    showCaseError(answer);
    if (!answer.ok) return answer;
    caseAnswer = answer;
    plane.keep = !!keepMap;
    renderCase();
    return answer;
  }

  function showCaseError(answer) {
    for (const f of caseFields.concat(["inertia", "reverse"])) $(f).removeAttribute("aria-invalid");
    const box = $("case-error");
    if (answer.ok) {
      box.hidden = true;
      return;
    }
    const field = $(answer.field) ? answer.field : "m1";
    $(field).setAttribute("aria-invalid", "true");
    box.textContent = answer.error;
    box.hidden = false;
    $("state").textContent = "";
    $("command").textContent = "";
    $("scene").textContent = "";
  }

  function renderCase() {
    caseState = JSON.parse(caseAnswer.state);
    drawPlane(caseAnswer.picture);
    drawNumbers(caseAnswer.picture);
    drawDual(caseAnswer.picture);
    $("state").textContent = caseAnswer.state;
    $("command").textContent = caseAnswer.command;
    $("scene").textContent = caseAnswer.scene;
  }

  // The data box the plane shows: square, around the origin and everything drawn.
  function fitPlane(pictures) {
    let x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity;
    const add = (p) => {
      if (!isFinite(p[0]) || !isFinite(p[1])) return;
      x0 = Math.min(x0, p[0]); x1 = Math.max(x1, p[0]);
      y0 = Math.min(y0, p[1]); y1 = Math.max(y1, p[1]);
    };
    const zoom = $("zoom").checked;
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
      if (p.reverse) [p.reverse.in, p.reverse.fin].forEach(add);
      if ($("overlay").checked) for (const f of p.frames) [f.in, f.com, f.fin].forEach(add);
    }
    let span = Math.max(x1 - x0, y1 - y0);
    span = span > 0 && isFinite(span) ? span * 1.12 : 2;
    const cx = (x0 + x1) / 2, cy = (y0 + y1) / 2;
    const P = { left: 62, top: 34, side: 470 };
    const s = P.side / span;
    const box = { x0: cx - span / 2, x1: cx + span / 2, y0: cy - span / 2, y1: cy + span / 2 };
    return { box, s, ox: P.left - s * box.x0, oy: P.top + s * box.y1, area: { x: P.left, y: P.top, w: P.side, h: P.side } };
  }

  // The step IN moves by (a drag snaps to it; an arrow key moves one): the power of 10 at or
  // above one screen unit of the plane.
  const snapStep = (map) => Math.pow(10, Math.ceil(Math.log10(1 / map.s) - 1e-9));
  function snapText(x, step) {
    const decimals = Math.max(0, -Math.round(Math.log10(step)));
    let t = (Math.round(x / step) * step).toFixed(decimals);
    if (/^-0(\.0*)?$/.test(t)) t = t.slice(1);
    return t;
  }

  function frameWords(name) {
    const f = caseAnswer.picture.frames.find((x) => x.name === name);
    return f ? f.label : "observer at " + name;
  }

  function drawPlane(p, frameLabel) {
    const svg = $("plane-svg");
    if (!plane.keep || !plane.map) plane.map = fitPlane([p]);
    const map = plane.map;
    const X = (x) => map.ox + map.s * x;
    const Y = (y) => map.oy - map.s * y;
    const S = (v) => [X(v[0]), Y(v[1])];
    clear(svg);
    svg.setAttribute("data-origin-x", map.ox);
    svg.setAttribute("data-origin-y", map.oy);
    svg.setAttribute("data-scale", map.s);
    svg.setAttribute("data-step", snapStep(map));
    svg.setAttribute("data-w", p.w);
    const a = map.area;
    frameAxes(svg, a, map.box, ["V\u2081", "V\u2082"]);
    const m = p.inertia;
    const tensor = m[0][1] === 0 && m[1][0] === 0
      ? "diag(" + short(m[0][0]) + ", " + short(m[1][1]) + ")"
      : "[[" + m.map((r) => r.map(short).join(", ")).join("], [") + "]]";
    el(svg, "text", { x: a.x, y: 20, class: "title" },
      "M = " + tensor + ",  e = " + (frameLabel ? short(p.e) : $("e").value.trim()) + ",  " + (frameLabel || frameWords(currentFrame())) + " frame");
    const defs = el(svg, "defs");
    const clip = el(defs, "clipPath", { id: "plane-clip" });
    el(clip, "rect", { x: a.x, y: a.y, width: a.w, height: a.h });
    const g = el(svg, "g", { "clip-path": "url(#plane-clip)" });
    const b = map.box;
    // The 45-degree line V1 = V2 and the momentum line k1 V1 + k2 V2 = P.
    const diag = clipLine(1, -1, 0, b);
    if (diag) el(g, "line", { x1: r2(X(diag[0][0])), y1: r2(Y(diag[0][1])), x2: r2(X(diag[1][0])), y2: r2(Y(diag[1][1])), stroke: "#9ca3af", "stroke-dasharray": "6 5", "stroke-width": 1.3 });
    const line = clipLine(p.line[0], p.line[1], p.line[2], b);
    if (line) el(g, "line", { id: "momentum-line", x1: r2(X(line[0][0])), y1: r2(Y(line[0][1])), x2: r2(X(line[1][0])), y2: r2(Y(line[1][1])), stroke: "var(--p)", "stroke-width": 2 });
    // The energy ellipses, centred on the frame's origin.
    const ellipse = (e, colour, id, dash) => {
      const angle = Math.atan2(e.axes[0][1], e.axes[0][0]) * 180 / Math.PI;
      const attrs = { id, cx: r2(X(0)), cy: r2(Y(0)), rx: Math.max(0, e.a * map.s), ry: Math.max(0, e.b * map.s), fill: "none", stroke: colour, "stroke-width": 2.2 };
      if (angle !== 0) attrs.transform = "rotate(" + r2(-angle) + " " + r2(X(0)) + " " + r2(Y(0)) + ")";
      if (dash) attrs["stroke-dasharray"] = dash;
      el(g, "ellipse", attrs);
    };
    ellipse(p.ellipses.com, "var(--com)", "ellipse-com");
    ellipse(p.ellipses.in, "var(--in)", "ellipse-in");
    if (p.e !== 0 && p.e !== 1) ellipse(p.ellipses.fin, "var(--fin)", "ellipse-fin", "7 4");
    // The other frames, faint (Fig. 2.5).
    if ($("overlay").checked) {
      const o = el(g, "g", { opacity: 0.45 });
      for (const f of p.frames) {
        if (Math.abs(f.w - p.w) <= 1e-12 * (Math.abs(f.w) + Math.abs(p.w))) continue;
        el(o, "line", { x1: r2(X(f.in[0])), y1: r2(Y(f.in[1])), x2: r2(X(f.fin[0])), y2: r2(Y(f.fin[1])), stroke: "#6b7280", "stroke-dasharray": "3 4" });
        for (const [v, c] of [[f.in, "var(--in)"], [f.com, "var(--com)"], [f.fin, "var(--fin)"]]) el(o, "circle", { cx: r2(X(v[0])), cy: r2(Y(v[1])), r: 3.5, fill: c });
        el(o, "text", { x: r2(X(f.com[0]) + 7), y: r2(Y(f.com[1]) + 4), class: "tick" }, f.name);
      }
    }
    // The time reverse: IN' = -FIN, FIN' = -IN.
    if (p.reverse) {
      const rv = p.reverse;
      el(g, "line", { x1: r2(X(rv.in[0])), y1: r2(Y(rv.in[1])), x2: r2(X(rv.fin[0])), y2: r2(Y(rv.fin[1])), stroke: "var(--rev)", "stroke-dasharray": "4 4", "stroke-width": 1.5 });
      for (const v of [rv.in, rv.fin]) el(g, "circle", { cx: r2(X(v[0])), cy: r2(Y(v[1])), r: 5, fill: "#fff", stroke: "var(--rev)", "stroke-width": 2 });
    }
    // The points and their coordinates (the IN-FIN chord lies on the momentum line).
    const labels = el(svg, "g", {});
    // Labels beside their points, moved down a line where they would overlap another.
    const placed = [];
    const point = (v, colour, name, id, r) => {
      const [sx, sy] = S(v);
      el(svg, "circle", { id, cx: r2(sx), cy: r2(sy), r, fill: colour, stroke: "#fff", "stroke-width": 2 });
      const text = name + " (" + short(v[0]) + ", " + short(v[1]) + ")";
      const right = sx < a.x + a.w - 150;
      const width = 7.2 * text.length;
      const x0 = right ? sx + 10 : sx - 10 - width;
      let y = sy - 9;
      while (placed.some((q) => Math.abs(q.y - y) < 14 && x0 < q.x1 && q.x0 < x0 + width)) y += 15;
      placed.push({ x0, x1: x0 + width, y });
      el(labels, "text", {
        x: r2(sx + (right ? 10 : -10)), y: r2(y), "text-anchor": right ? "start" : "end",
        class: "label", fill: colour, "paint-order": "stroke", stroke: "#fff", "stroke-width": 4,
      }, text);
    };
    point(p.in, "var(--in)", "IN", "point-in", 7);
    point(p.com, "var(--com)", "COM", "point-com", 5);
    point(p.fin, "var(--fin)", "FIN", "point-fin", 5.5);
    if (p.reverse) {
      point(p.reverse.in, "var(--rev)", "IN\u2032", "point-rev-in", 0.1);
      point(p.reverse.fin, "var(--rev)", "FIN\u2032", "point-rev-fin", 0.1);
    }
    // IN on top, to be grabbed.
    svg.appendChild(svg.querySelector("#point-in"));
    svg.appendChild(labels);
  }

  function drawNumbers(p) {
    const s = caseState;
    const box = $("case-numbers");
    clear(box);
    const table = (caption, head, rows) => {
      const t = document.createElement("table");
      const c = t.createCaption();
      c.innerHTML = caption;
      const h = t.createTHead().insertRow();
      for (const x of head) { const th = document.createElement("th"); th.innerHTML = x; h.appendChild(th); }
      const body = t.createTBody();
      for (const r of rows) {
        const tr = body.insertRow();
        r.forEach((x, i) => {
          const cell = i === 0 ? document.createElement("th") : tr.insertCell();
          if (i === 0) { cell.innerHTML = x; cell.scope = "row"; tr.appendChild(cell); } else { cell.textContent = typeof x === "number" ? num(x) : x; }
        });
      }
      box.appendChild(t);
    };
    table("Velocities", ["", "V<sub>1</sub>", "V<sub>2</sub>"], [
      ['<span class="c-in">IN</span>', s.in[0], s.in[1]],
      ['<span class="c-com">COM</span>', s.com[0], s.com[1]],
      ['<span class="c-fin">FIN</span>', s.fin[0], s.fin[1]],
    ]);
    const en = s.energy;
    const rows = [
      ['<span class="c-in">KE<sub>IN</sub></span>', en.in],
      ['<span class="c-com">KE<sub>COM</sub></span>', en.com],
      ['<span class="c-fin">KE<sub>FIN</sub></span>', en.fin],
      ["crunch = KE<sub>IN</sub> &minus; KE<sub>COM</sub>", en.crunch],
    ];
    if (en.lost !== undefined) rows.push(["lost = (1 &minus; e<sup>2</sup>) crunch", en.lost]);
    if (en.released !== undefined) rows.push(["released = (e<sup>2</sup> &minus; 1) crunch", en.released]);
    table("Energy" + (s.units ? " (" + s.units.energy + ")" : ""), ["", ""], rows);
    const f = s.forms;
    table("Quadratic forms", ["", ""], [
      ["V<sub>COM</sub>&middot;M&middot;V<sub>IN</sub>", f.com_m_in],
      ["V<sub>FIN</sub>&middot;M&middot;V<sub>IN</sub>", f.fin_m_in],
      ["V<sub>IN</sub>&middot;M&middot;V<sub>IN</sub>", f.in_m_in],
      ["V<sub>FIN</sub>&middot;M&middot;V<sub>FIN</sub>", f.fin_m_fin],
    ]);
    const [k1, k2, P] = p.line;
    const kind = p.e === 1 ? "elastic, ka-bong" : p.e === 0 ? "totally inelastic, ka-runch" : p.e > 1 ? "superelastic" : "ka-whump";
    const para = (html) => { const x = document.createElement("p"); x.innerHTML = html; box.appendChild(x); };
    para('<span class="c-p">Momentum line</span> <span class="num">' + num(k1) + " V<sub>1</sub> + " + num(k2) + " V<sub>2</sub> = " + num(P) + "</span>");
    para("V<sub>COM</sub> = <span class=\"num\">" + num(s.v_com) + "</span>; e = <span class=\"num\">" + num(s.restitution) + "</span> (" + kind + ")");
    if (s.frame) para("Seen from the " + frameWords(s.frame.name) + " frame: observer at w = <span class=\"num\">" + num(s.frame.w) + "</span>");
    if (!s.approaching) para("V<sub>1</sub> = V<sub>2</sub>: the bodies never meet, so FIN = IN.");
    else if (s.left === 2) para("V<sub>1</sub> &lt; V<sub>2</sub>: body 2 is behind (on the left) and catches body 1.");
    if (s.reverse) {
      para('<span class="c-rev">Time reverse</span>: IN&prime; = (<span class="num">' + num(s.reverse.in[0]) + ", " + num(s.reverse.in[1]) +
        "</span>), FIN&prime; = (<span class=\"num\">" + num(s.reverse.fin[0]) + ", " + num(s.reverse.fin[1]) + "</span>), e&prime; = 1/e = <span class=\"num\">" +
        num(s.reverse.restitution) + "</span>; " + (s.reverse.equals_original ? "the same collision again" : "not the original collision"));
    }
  }

  // Animates the 45-degree shift from the frame on screen to `name`: the core solves the case
  // seen by observers moving at velocities between the two frames' (each a frame of its own).
  function changeFrame(name) {
    if (!core) return;
    const from = caseAnswer.picture;
    const end = core(caseRequest(name));
    showCaseError(end);
    if (!end.ok) return;
    const w0 = from.w, w1 = end.picture.w;
    cancelAnimationFrame(plane.animation);
    if (reduceMotion || w0 === w1) {
      caseAnswer = end; plane.keep = false; renderCase();
      return;
    }
    plane.map = fitPlane([from, end.picture]);
    plane.keep = true;
    const duration = 700;
    let t0 = null;
    const step = (now) => {
      if (t0 === null) t0 = now;
      const u = Math.min(1, (now - t0) / duration);
      if (u >= 1) {
        caseAnswer = end; renderCase();
        return;
      }
      const s = u < 0.5 ? 2 * u * u : 1 - 2 * (1 - u) * (1 - u);
      const w = w0 + (w1 - w0) * s;
      const mid = core(caseRequest(String(w)));
      if (mid.ok) {
        drawPlane(mid.picture, "observer at " + short(w));
        drawDual(mid.picture);
      }
      plane.animation = requestAnimationFrame(step);
    };
    plane.animation = requestAnimationFrame(step);
  }

  // Moves IN to a point of the plane (in the frame on screen), snapped to the step.
  function moveIn(x, y) {
    const t0 = performance.now();
    const map = plane.map;
    const step = snapStep(map);
    const w = caseAnswer.picture.w;
    $("v1").value = snapText(x + w, step);
    $("v2").value = snapText(y + w, step);
    const answer = solveCase(true);
    const ms = performance.now() - t0;
    view.lastUpdateMs = ms;
    view.timings.push(ms);
    return answer;
  }

  function planePoint(ev) {
    const svg = $("plane-svg");
    const rect = svg.getBoundingClientRect();
    const vb = svg.viewBox.baseVal;
    const X = (ev.clientX - rect.left) * vb.width / rect.width;
    const Y = (ev.clientY - rect.top) * vb.height / rect.height;
    return [(X - plane.map.ox) / plane.map.s, (plane.map.oy - Y) / plane.map.s];
  }

  function setupDrag() {
    const svg = $("plane-svg");
    let pending = null, queued = false;
    const flush = () => {
      queued = false;
      if (pending && plane.dragging) { const [x, y] = planePoint(pending); pending = null; moveIn(x, y); }
    };
    svg.addEventListener("pointerdown", (ev) => {
      if (!core || ev.button !== 0) return;
      cancelAnimationFrame(plane.animation);
      plane.dragging = true;
      svg.setPointerCapture(ev.pointerId);
      svg.classList.add("dragging");
      svg.focus({ preventScroll: true });
      pending = ev;
      flush();
      ev.preventDefault();
    });
    svg.addEventListener("pointermove", (ev) => {
      if (!plane.dragging) return;
      pending = ev;
      if (!queued) { queued = true; requestAnimationFrame(flush); }
    });
    const end = (ev) => {
      if (!plane.dragging) return;
      if (ev.type === "pointerup") pending = ev;
      flush();
      plane.dragging = false;
      svg.classList.remove("dragging");
    };
    svg.addEventListener("pointerup", end);
    svg.addEventListener("pointercancel", end);
    svg.addEventListener("keydown", (ev) => {
      const d = { ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowDown: [0, -1], ArrowUp: [0, 1] }[ev.key];
      if (!d || !core) return;
      ev.preventDefault();
      const step = snapStep(plane.map) * (ev.shiftKey ? 10 : 1);
      const p = caseAnswer.picture;
      const x = p.in[0] + d[0] * step, y = p.in[1] + d[1] * step;
      const b = plane.map.box;
      if (x < b.x0 || x > b.x1 || y < b.y0 || y > b.y1) plane.map = fitPlane([p]);
      moveIn(x, y);
    });
  }

  // Sliders and typed values: the slider follows a typed value, a typed value follows the slider.
  function setupCaseInputs() {
    const c = data.setup.case;
    for (const f of caseFields) $(f).value = c[f];
    $("inertia").value = c.inertia || "";
    $("reverse").checked = !!c.reverse;
    buildFrames(c.frame);
    syncSliders();
    const typed = () => { syncSliders(); solveCase(false); };
    for (const f of caseFields.concat(["inertia"])) $(f).addEventListener("input", typed);
    for (const f of ["m1", "m2"]) {
      $(f + "-range").addEventListener("input", () => {
        $(f).value = String(Number(Math.pow(10, Number($(f + "-range").value)).toPrecision(3)));
        solveCase(false);
      });
    }
    $("e-range").addEventListener("input", () => { $("e").value = String(Number($("e-range").value)); solveCase(false); });
    $("reverse").addEventListener("change", () => solveCase(false));
    $("overlay").addEventListener("change", () => solveCase(false));
    $("zoom").addEventListener("change", () => solveCase(false));
  }
  function valueOf(text) {
    const t = text.trim();
    if (t === "elastic") return 1;
    if (t === "inelastic") return 0;
    const parts = t.split("/");
    return parts.length === 2 ? Number(parts[0]) / Number(parts[1]) : Number(t);
  }
  function syncSliders() {
    const tensor = $("inertia").value.trim() !== "";
    for (const f of ["m1", "m2"]) $(f).closest(".field").classList.toggle("unused", tensor);
    for (const f of ["m1", "m2"]) {
      const v = valueOf($(f).value);
      if (v > 0) $(f + "-range").value = String(Math.log10(v));
    }
    const e = valueOf($("e").value);
    if (e >= 0) $("e-range").value = String(e);
  }
  function buildFrames(selected) {
    const box = $("frame-choices");
    clear(box);
    const frames = data.answers.solve.picture.frames.map((f) => [f.name, f.label]);
    if (!frames.some((f) => f[0] === selected)) frames.push([selected, "observer at " + selected]);
    for (const [name, label] of frames) {
      const l = document.createElement("label");
      const i = document.createElement("input");
      i.type = "radio"; i.name = "frame"; i.value = name; i.checked = name === selected;
      i.addEventListener("change", () => { if (i.checked) changeFrame(name); });
      l.appendChild(i);
      l.appendChild(document.createTextNode(label === "COM" ? "COM" : label));
      box.appendChild(l);
    }
  }

  // ---------------------------------------------------------------- the dual panel
  const dual = { t: -1, picture: null };

  // A Play/Pause button: while playing, `advance(seconds)` is called once a frame with the time
  // since the last one.
  function player(button, advance) {
    let playing = false, last = 0;
    const tick = (now) => {
      if (!playing) return;
      advance(last ? (now - last) / 1000 : 0);
      last = now;
      requestAnimationFrame(tick);
    };
    button.addEventListener("click", () => {
      playing = !playing;
      last = 0;
      button.textContent = playing ? "Pause" : "Play";
      button.setAttribute("aria-pressed", String(playing));
      if (playing) requestAnimationFrame(tick);
    });
  }

  function drawDual(p) {
    dual.picture = p;
    const v = p.in, f = p.fin;
    const reach = Math.max(Math.abs(v[0]), Math.abs(v[1]), Math.abs(f[0]), Math.abs(f[1])) * 1.1 || 1;
    const tBox = [-1.1, 1.1];
    const x = (i, t) => (t < 0 ? v[i] * t : f[i] * t);
    const colours = ["var(--body1)", "var(--body2)"];
    const area = { x: 46, y: 16, w: 262, h: 244 };
    // Newton: t across, x up. Minkowski: x across, t up.
    for (const [id, newton] of [["newton-svg", true], ["minkowski-svg", false]]) {
      const svg = $(id);
      clear(svg);
      const box = newton ? { x0: tBox[0], x1: tBox[1], y0: -reach, y1: reach } : { x0: -reach, x1: reach, y0: tBox[0], y1: tBox[1] };
      const a = frameAxes(svg, area, box, newton ? ["t", "x"] : ["x", "t"]);
      const at = (t, xx) => (newton ? [a.X(t), a.Y(xx)] : [a.X(xx), a.Y(t)]);
      for (let i = 0; i < 2; i++) {
        el(svg, "polyline", { points: pts([at(-1, x(i, -1)), at(0, 0), at(1, x(i, 1))]), fill: "none", stroke: colours[i], "stroke-width": 2.2 });
      }
      const g = el(svg, "g", { class: "cursor" });
      g.dataset.newton = newton ? "1" : "0";
    }
    // Space vs Space: x2 against x1, or scaled by M^(1/2).
    const svg = $("space-svg");
    clear(svg);
    const scaled = $("scaled").checked;
    const S = p.sqrt_m;
    const map2 = (x1, x2) => (scaled ? [S[0][0] * x1 + S[0][1] * x2, S[1][0] * x1 + S[1][1] * x2] : [x1, x2]);
    const path = [map2(-v[0], -v[1]), [0, 0], map2(f[0], f[1])];
    let r = 0;
    for (const q of path) r = Math.max(r, Math.abs(q[0]), Math.abs(q[1]));
    r = r * 1.1 || 1;
    const sq = { x: 52, y: 16, w: 244, h: 244 };
    const diag = p.inertia[0][1] === 0;
    const a = frameAxes(svg, sq, { x0: -r, x1: r, y0: -r, y1: r },
      scaled ? (diag ? ["\u221aM\u2081 x\u2081", "\u221aM\u2082 x\u2082"] : ["(M\u00bd x)\u2081", "(M\u00bd x)\u2082"]) : ["x\u2081", "x\u2082"]);
    // The collision line x1 = x2 (through the origin along M^(1/2) (1, 1) when scaled).
    const d = map2(1, 1);
    const line = clipLine(d[1], -d[0], 0, { x0: -r, x1: r, y0: -r, y1: r });
    if (line) el(svg, "line", { x1: r2(a.X(line[0][0])), y1: r2(a.Y(line[0][1])), x2: r2(a.X(line[1][0])), y2: r2(a.Y(line[1][1])), stroke: "#9ca3af", "stroke-width": 1.6, "stroke-dasharray": "6 4" });
    el(svg, "polyline", { points: pts(path.map((q) => [a.X(q[0]), a.Y(q[1])])), fill: "none", stroke: "var(--rev)", "stroke-width": 2.2 });
    const note = !scaled ? "on the dashed line x\u2081 = x\u2082 the bodies meet"
      : p.e === 1 ? "e = 1: the path reflects in the dashed line" : "only e = 1 reflects the path in the line";
    el(svg, "text", { x: sq.x + 6, y: sq.y + sq.h - 8, class: "tick", "paint-order": "stroke", stroke: "#fff", "stroke-width": 3 }, note);
    dual.map = { reach, x, map2, space: a };
    drawDualTime();
  }

  function drawDualTime() {
    const p = dual.picture;
    if (!p) return;
    const t = dual.t;
    const { reach, x, map2, space } = dual.map;
    const colours = ["var(--body1)", "var(--body2)"];
    const area = { x: 46, y: 16, w: 262, h: 244 };
    for (const id of ["newton-svg", "minkowski-svg"]) {
      const svg = $(id);
      const g = svg.querySelector(".cursor");
      const newton = g.dataset.newton === "1";
      clear(g);
      const bx = newton ? { x0: -1.1, x1: 1.1, y0: -reach, y1: reach } : { x0: -reach, x1: reach, y0: -1.1, y1: 1.1 };
      const X = (u) => area.x + (u - bx.x0) * area.w / (bx.x1 - bx.x0);
      const Y = (u) => area.y + (bx.y1 - u) * area.h / (bx.y1 - bx.y0);
      if (newton) el(g, "line", { x1: r2(X(t)), x2: r2(X(t)), y1: area.y, y2: area.y + area.h, stroke: "#111827", "stroke-opacity": 0.35 });
      else el(g, "line", { x1: area.x, x2: area.x + area.w, y1: r2(Y(t)), y2: r2(Y(t)), stroke: "#111827", "stroke-opacity": 0.35 });
      for (let i = 0; i < 2; i++) {
        const [cx, cy] = newton ? [X(t), Y(x(i, t))] : [X(x(i, t)), Y(t)];
        el(g, "circle", { cx: r2(cx), cy: r2(cy), r: 5, fill: colours[i], stroke: "#fff", "stroke-width": 1.5 });
      }
    }
    const sp = $("space-svg");
    let dot = sp.querySelector("#space-dot");
    const q = map2(x(0, t), x(1, t));
    if (!dot) dot = el(sp, "circle", { id: "space-dot", r: 5.5, fill: "var(--rev)", stroke: "#fff", "stroke-width": 1.5 });
    dot.setAttribute("cx", r2(space.X(q[0])));
    dot.setAttribute("cy", r2(space.Y(q[1])));
    drawRail(p, t, reach, x);
    $("dual-time").value = String(t);
    $("dual-time-out").textContent = "t = " + minus(t.toFixed(3));
  }

  function drawRail(p, t, reach, x) {
    const svg = $("rail-svg");
    clear(svg);
    const L = 30, R = 930, car = 84;
    const X = (u) => L + car + (u + reach) * (R - L - 2 * car) / (2 * reach);
    el(svg, "line", { x1: L, x2: R, y1: 86, y2: 86, stroke: "#6b7280", "stroke-width": 3 });
    for (const u of ticks(-reach, reach, 8)) {
      el(svg, "line", { x1: r2(X(u)), x2: r2(X(u)), y1: 86, y2: 92, stroke: "#6b7280" });
      el(svg, "text", { x: r2(X(u)), y: 105, "text-anchor": "middle", class: "tick" }, short(u));
    }
    const m = p.inertia;
    const bodies = [
      { left: X(x(0, t)) - car, colour: "var(--body1)", name: "1", mass: m[0][0], v: t < 0 ? p.in[0] : p.fin[0] },
      { left: X(x(1, t)), colour: "var(--body2)", name: "2", mass: m[1][1], v: t < 0 ? p.in[1] : p.fin[1] },
    ];
    for (const b of bodies) {
      el(svg, "rect", { x: r2(b.left), y: 46, width: car, height: 36, rx: 7, fill: b.colour, "fill-opacity": 0.88 });
      el(svg, "circle", { cx: r2(b.left + 18), cy: 84, r: 6, fill: "#1f2937" });
      el(svg, "circle", { cx: r2(b.left + car - 18), cy: 84, r: 6, fill: "#1f2937" });
      el(svg, "text", { x: r2(b.left + car / 2), y: 69, "text-anchor": "middle", fill: "#fff", class: "label" }, "M" + (b.name === "1" ? "\u2081" : "\u2082") + " " + short(b.mass));
      const dir = b.v >= 0 ? 1 : -1;
      const cx = b.left + car / 2;
      if (b.v !== 0) {
        el(svg, "line", { x1: r2(cx - dir * 18), x2: r2(cx + dir * 18), y1: 30, y2: 30, stroke: b.colour, "stroke-width": 2.2 });
        el(svg, "polygon", { points: pts([[cx + dir * 24, 30], [cx + dir * 16, 25], [cx + dir * 16, 35]]), fill: b.colour });
      }
      el(svg, "text", { x: r2(cx), y: 18, "text-anchor": "middle", class: "tick" }, "V = " + short(b.v));
    }
    el(svg, "text", { x: L, y: 16, class: "title" }, t < 0 ? "before: IN" : t > 0 ? "after: FIN" : "the collision");
  }

  function setupDual() {
    // Two units of time (t from -1 to 1) in four seconds, round and round.
    player($("dual-play"), (dt) => {
      dual.t += dt / 2;
      if (dual.t > 1) dual.t = -1;
      drawDualTime();
    });
    $("dual-time").addEventListener("input", () => { dual.t = Number($("dual-time").value); drawDualTime(); });
    $("scaled").addEventListener("change", () => drawDual(caseAnswer.picture));
  }

  // ---------------------------------------------------------------- the superball stack
  const trackFields = [["masses", "t-masses"], ["sizes", "t-sizes"], ["positions", "t-positions"], ["velocities", "t-velocities"],
    ["e", "t-e"], ["e_wall", "t-e-wall"], ["gravity", "t-gravity"], ["left_wall", "t-floor"], ["until", "t-until"]];
  const presets = {
    2: { masses: "1,0.01", sizes: "1,0.5", positions: "1.5,2.25", velocities: "0,0", e: "elastic", e_wall: "", gravity: "9.81", left_wall: "0", until: "" },
    3: { masses: "1,0.01,0.0001", sizes: "1,0.5,0.25", positions: "1.5,2.25,2.625", velocities: "0,0,0", e: "elastic", e_wall: "", gravity: "9.81", left_wall: "0", until: "" },
    ball: { masses: "1", sizes: "0.2", positions: "1.1", velocities: "0", e: "elastic", e_wall: "0.5", gravity: "9.81", left_wall: "0", until: "" },
  };
  const ballColours = ["#2563eb", "#dc2626", "#059669", "#d97706", "#7c3aed", "#0891b2"];
  let stackAnswer = data.answers.track;
  let trackState = null;
  const stack = { t: 0 };

  function trackRequest() {
    const r = { op: "track", right_wall: data.setup.track.right_wall || "" };
    for (const [key, id] of trackFields) r[key] = $(id).value;
    return r;
  }
  function runStack() {
    if (!core) return;
    const t0 = performance.now();
    const answer = core(trackRequest());
    for (const [, id] of trackFields) $(id).removeAttribute("aria-invalid");
    const box = $("track-error");
    if (!answer.ok) {
      const f = trackFields.find((x) => x[0] === answer.field);
      $(f ? f[1] : "t-masses").setAttribute("aria-invalid", "true");
      box.textContent = answer.error;
      box.hidden = false;
      for (const id of ["track-state", "track-command", "track-scene"]) $(id).textContent = "";
      return;
    }
    box.hidden = true;
    stackAnswer = answer;
    stack.t = Math.min(stack.t, answer.until);
    renderStack();
    view.stackMs = performance.now() - t0;
  }
  function renderStack() {
    const a = stackAnswer;
    trackState = JSON.parse(a.state);
    $("track-state").textContent = a.state;
    $("track-command").textContent = a.command;
    $("track-scene").textContent = a.scene;
    $("stack-time").max = String(a.until);
    $("stack-time").step = String(a.until / 1000);
    drawStackLines();
    drawStackNumbers();
    drawStackTime();
  }

  function stackBox() {
    const a = stackAnswer;
    let lo = a.floor !== null ? a.floor : Infinity, hi = -Infinity;
    const n = a.masses.length;
    for (let i = 0; i < n; i++) {
      const half = a.sizes[i] / 2;
      const xs = a.x[i] && a.x[i].length ? a.x[i] : [trackState.x[i]];
      for (const x of xs) { lo = Math.min(lo, x - half); hi = Math.max(hi, x + half); }
    }
    if (a.ceiling !== null) hi = Math.max(hi, a.ceiling);
    if (!(hi > lo)) hi = lo + 1;
    return { lo, hi: hi + 0.04 * (hi - lo) };
  }

  // The positions at time t: the core's samples, joined by straight segments for drawing.
  function stackAt(t) {
    const a = stackAnswer;
    const n = a.masses.length;
    if (!a.t.length) return trackState.x.slice(0, n);
    let lo = 0, hi = a.t.length - 1;
    if (t >= a.t[hi]) return a.x.map((xs) => xs[hi]);
    while (hi - lo > 1) { const mid = (lo + hi) >> 1; if (a.t[mid] <= t) lo = mid; else hi = mid; }
    const u = a.t[hi] > a.t[lo] ? (t - a.t[lo]) / (a.t[hi] - a.t[lo]) : 0;
    return a.x.map((xs) => xs[lo] + (xs[hi] - xs[lo]) * u);
  }

  function drawStackLines() {
    const a = stackAnswer;
    const svg = $("lines-svg");
    clear(svg);
    const box = stackBox();
    const end = a.t.length ? a.t[a.t.length - 1] : trackState.time;
    const area = { x: 52, y: 16, w: 550, h: 372 };
    const ax = frameAxes(svg, area, { x0: 0, x1: Math.max(end, 1e-300), y0: box.lo, y1: box.hi }, ["t", "height"]);
    if (a.floor !== null) el(svg, "line", { x1: area.x, x2: area.x + area.w, y1: r2(ax.Y(a.floor)), y2: r2(ax.Y(a.floor)), stroke: "#374151", "stroke-width": 3 });
    if (!a.t.length) {
      el(svg, "text", { x: area.x + 10, y: area.y + 20, class: "title" }, a.events.length + " collisions: too many to animate; the numbers are the core's");
    }
    a.x.forEach((xs, i) => {
      if (!xs.length) return;
      el(svg, "polyline", { points: pts(xs.map((x, k) => [ax.X(a.t[k]), ax.Y(x)])), fill: "none", stroke: ballColours[i % ballColours.length], "stroke-width": 2 });
    });
    const dots = el(svg, "g", {});
    for (const ev of a.events) {
      const k = a.t.indexOf(ev.t);
      if (k < 0) continue;
      for (const m of ev.who.match(/\d+/g) || []) {
        const i = Number(m) - 1;
        if (a.x[i]) el(dots, "circle", { cx: r2(ax.X(ev.t)), cy: r2(ax.Y(a.x[i][k])), r: 3.2, fill: "#111827" });
      }
    }
    el(svg, "g", { class: "cursor" });
    stack.lines = ax;
    stack.area = area;
  }

  function drawStackTime() {
    const a = stackAnswer;
    const t = stack.t;
    const x = stackAt(t);
    const box = stackBox();
    // The tower: the balls at their heights, to scale (at least 3 units across).
    const svg = $("tower-svg");
    clear(svg);
    const top = 14, bottom = 400;
    const s = (bottom - top) / (box.hi - box.lo);
    const Y = (h) => bottom - (h - box.lo) * s;
    el(svg, "rect", { x: 0.5, y: 0.5, width: 199, height: 419, fill: "#fff", stroke: "none" });
    if (a.floor !== null) {
      el(svg, "rect", { x: 10, y: r2(Y(a.floor)), width: 180, height: 8, fill: "#374151" });
    }
    x.forEach((h, i) => {
      const r = Math.max(3, (a.sizes[i] / 2) * s);
      el(svg, "circle", { cx: 80, cy: r2(Y(h)), r: r2(Math.min(r, 70)), fill: ballColours[i % ballColours.length], stroke: "#fff", "stroke-width": 1 });
      el(svg, "text", { x: 156, y: r2(Y(h) + 4), "text-anchor": "middle", class: "tick" }, "m " + short(a.masses[i]));
    });
    // The cursor on the world lines.
    const lines = $("lines-svg").querySelector(".cursor");
    if (lines && stack.lines) {
      clear(lines);
      const ar = stack.area;
      el(lines, "line", { x1: r2(stack.lines.X(t)), x2: r2(stack.lines.X(t)), y1: ar.y, y2: ar.y + ar.h, stroke: "#111827", "stroke-opacity": 0.35 });
      x.forEach((h, i) => el(lines, "circle", { cx: r2(stack.lines.X(t)), cy: r2(stack.lines.Y(h)), r: 4.5, fill: ballColours[i % ballColours.length], stroke: "#fff" }));
    }
    $("stack-time").value = String(t);
    $("stack-time-out").textContent = "t = " + short(t);
  }

  function drawStackNumbers() {
    const a = stackAnswer, s = trackState;
    const box = $("stack-numbers");
    clear(box);
    const para = (html, cls) => { const p = document.createElement("p"); p.innerHTML = html; if (cls) p.className = cls; box.appendChild(p); };
    const amp = a.amplification;
    if (amp && a.masses.length > 1) {
      para("Velocity amplification: the top ball leaves at <span class=\"num\">" + num(amp.ratio) + "</span> &times; the bottom ball's impact speed", "big");
      para("(it leaves at " + num(amp.top_velocity) + "; the bottom ball hit the floor at " + num(amp.drop_speed) +
        "). For elastic balls, each much lighter than the one below, the limit is 2<sup>" + a.masses.length + "</sup> &minus; 1 = " + amp.limit + ".");
      if (a.gravity > 0) para("so it rises <span class=\"num\">" + num(amp.ratio * amp.ratio) + "</span> &times; as high above the collision as the stack fell");
    } else if (amp) {
      para("The ball rebounds at <span class=\"num\">" + num(amp.ratio) + "</span> &times; its impact speed", "big");
    }
    const stop = { done: "no collision can happen any more", until: "reached until", "max-collisions": "reached the cap on collisions", horizon: "the next collision is beyond binary64", zeno: "infinitely many collisions accumulate here (a Zeno sequence)" }[s.stop.reason] || s.stop.reason;
    para(s.collisions + " collisions (" + s.pair_collisions + " between balls, " + s.wall_collisions + " with the floor) by t = " + num(s.time) + ": " + stop);
    const t = document.createElement("table");
    t.createCaption().textContent = "At t = " + num(s.time);
    const h = t.createTHead().insertRow();
    for (const x of ["ball", "m", "height", "v"]) { const th = document.createElement("th"); th.textContent = x; h.appendChild(th); }
    const b = t.createTBody();
    s.x.forEach((x, i) => {
      const r = b.insertRow();
      const c0 = r.insertCell(); c0.innerHTML = '<span style="color:' + ballColours[i % ballColours.length] + '">&#9679;</span> ' + (i + 1);
      r.insertCell().textContent = num(a.masses[i]);
      r.insertCell().textContent = num(x);
      r.insertCell().textContent = num(s.v[i]);
    });
    box.appendChild(t);
    para("Energy " + num(s.energy.start) + " &rarr; " + num(s.energy.end) + "; momentum " + num(s.momentum.start) + " &rarr; " + num(s.momentum.end) + " (the floor and gravity change it)");
  }

  function setupStack() {
    const tr = data.setup.track;
    for (const [key, id] of trackFields) $(id).value = tr[key] || "";
    syncTrackSlider();
    for (const [, id] of trackFields) $(id).addEventListener("change", () => { syncTrackSlider(); runStack(); });
    $("t-e-range").addEventListener("input", () => { $("t-e").value = String(Number($("t-e-range").value)); runStack(); });
    $("preset").addEventListener("change", () => {
      const p = presets[$("preset").value];
      if (!p) return;
      for (const [key, id] of trackFields) $(id).value = p[key];
      syncTrackSlider();
      stack.t = 0;
      runStack();
    });
    // In real time (the track's time unit a second).
    player($("stack-play"), (dt) => {
      stack.t += dt;
      if (stack.t > stackAnswer.until) stack.t = 0;
      drawStackTime();
    });
    $("stack-time").addEventListener("input", () => { stack.t = Number($("stack-time").value); drawStackTime(); });
  }
  function syncTrackSlider() {
    const e = valueOf($("t-e").value);
    if (e >= 0 && e <= 1) $("t-e-range").value = String(e);
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

  // ---------------------------------------------------------------- start
  const controls = () => document.querySelectorAll("#case-form input, #track-form input, #track-form select, #plane-svg");
  function setEnabled(on) {
    for (const c of controls()) {
      if (c.tagName.toLowerCase() === "svg") c.setAttribute("aria-disabled", String(!on));
      else c.disabled = !on;
    }
  }

  setupCaseInputs();
  setupDrag();
  setupDual();
  setupStack();
  setupCopy();
  renderCase();
  renderStack();
  setEnabled(false);
  if (data.setup.focus === "stack" && !location.hash) $("stack").scrollIntoView();

  loadCore().then((ask) => {
    core = ask;
    // The core must give the very answers collide wrote into the page.
    for (const [op, request, written] of [["solve", Object.assign({ op: "solve" }, data.setup.case), data.answers.solve],
      ["track", Object.assign({ op: "track" }, data.setup.track), data.answers.track]]) {
      const again = core(request);
      if (JSON.stringify(again) !== JSON.stringify(written)) {
        console.error("collide view: the WebAssembly core and the collide binary disagree on the " + op + " request", again, written);
      }
    }
    setEnabled(true);
    view.ready = true;
    $("status").textContent = "Ready: collide's WebAssembly core computes every change you make.";
  }).catch((e) => {
    $("status").textContent = "The WebAssembly core could not start (" + e.message + "): the numbers shown are the ones collide wrote; nothing can be changed.";
    $("status").classList.add("bad");
    console.error("collide view:", e);
  });
})();
