  // ---------------------------------------------------------------- two pucks in the plane
  // The inputs (ids "p-" + name) and what the core answers (src/view/plane.rs): the pucks with
  // their velocity arrows, the momentum triangles and the velocity plane of the normal parts.
  const planeFields = ["m1", "m2", "v1", "v2", "e", "normal", "r1", "r2", "b"];
  const planeColours = ["var(--body1)", "var(--body2)"];
  const planeTints = ["#dbeafe", "#fee2e2"];
  const planePresets = {
    disks: { m1: "1", m2: "1", v1: "(1,0)", v2: "(0,0)", e: "elastic", line: "disks", r1: "1", r2: "1", b: "1" },
    rule: { m1: "1", m2: "1", v1: "(4,0)", v2: "(0,0)", e: "elastic", line: "normal", normal: "30deg" },
    stick: { m1: "1500 kg", m2: "2500 kg", v1: "25 m/s @ E", v2: "20 m/s @ N", e: "0", line: "none" },
    deflect: { m1: "2", m2: "1", v1: "(1,0)", v2: "(0,0)", e: "elastic", line: "normal", normal: "30deg" },
    whump: { m1: "6", m2: "1", v1: "(3,2)", v2: "(-4,-1)", e: "2/3", line: "normal", normal: "0deg" },
  };
  let planeAnswer = data.answers.plane; // the last good answer
  let planeState = null; // its JSON, parsed
  // The pucks' map (kept while an arrow is dragged), the arrow being dragged, the one the keys move.
  // The last move of an arrow the core refused, `{i, v}` (v in the frame on screen), else null.
  const pucks = { map: null, keep: false, dragging: -1, selected: 0, pending: null };

  function lineMode() {
    const checked = document.querySelector('input[name="p-line"]:checked');
    return checked ? checked.value : "none";
  }

  function planeRequest() {
    const r = { op: "plane" };
    for (const f of ["m1", "m2", "v1", "v2", "e"]) r[f] = $("p-" + f).value;
    const mode = lineMode();
    r.line = mode;
    if (mode === "normal") r.normal = $("p-normal").value;
    if (mode === "disks") for (const f of ["r1", "r2", "b"]) r[f] = $("p-" + f).value;
    r.frame = $("p-frame").value;
    r.reverse = $("p-reverse").checked;
    r.exact = $("p-exact").checked;
    return r;
  }

  // Solves the pucks on screen and redraws; `keepMap` keeps the pucks' scale (a drag).
  function solvePlane(keepMap) {
    if (!core) return null;
    const answer = core(planeRequest());
    showPlaneError(answer);
    if (!answer.ok) return answer;
    planeAnswer = answer;
    pucks.keep = !!keepMap;
    renderPlane();
    return answer;
  }

  function showPlaneError(answer) {
    const ids = {};
    for (const f of planeFields.concat(["frame", "reverse", "exact"])) ids[f] = "p-" + f;
    showError(answer, ids, "p-m1", "plane-error", ["plane-state", "plane-command", "plane-scene", "plane-said"],
      ["pucks-svg", "plane-numbers", "momentum-svg", "normal-svg", "plane-bars-svg"]);
    if (!answer.ok) clearTimeout(sayTimers["plane-said"]);
  }


  function renderPlane() {
    const a = planeAnswer;
    planeState = JSON.parse(a.state);
    drawPucks(a.picture);
    // During a drag, what the pointer does not move is drawn after the frame (or once in sight).
    const later = pucks.dragging >= 0, p = a.picture, s = planeState;
    drawSeen($("momentum-svg"), () => drawMomentum(p), later, true);
    drawSeen($("normal-svg"), () => drawNormalParts(p), later, true);
    drawSeen($("plane-numbers"), () => drawPlaneNumbers(p), later, true);
    drawSeen($("plane-bars-svg"), () => drawPlaneBars(p, s), later, true);
    syncPlaneSliders(a.picture);
    if (pucks.dragging < 0) sayLater("plane-said", planeSentence);
    $("plane-state").textContent = a.state;
    $("plane-command").textContent = a.command;
    $("plane-scene").textContent = a.scene;
  }

  // An arrow from `a` to `b` (screen), its head filled.
  function arrow(parent, a, b, colour, attrs) {
    const g = el(parent, "g", attrs.id ? { id: attrs.id } : {});
    const dx = b[0] - a[0], dy = b[1] - a[1];
    const len = Math.hypot(dx, dy);
    if (len < 0.5) return g;
    const ux = dx / len, uy = dy / len;
    const size = Math.min(11, len / 2);
    const line = { x1: r2(a[0]), y1: r2(a[1]), x2: r2(b[0] - ux * size * 0.6), y2: r2(b[1] - uy * size * 0.6), stroke: colour, "stroke-width": attrs.width || 2.4 };
    if (attrs.dash) line["stroke-dasharray"] = attrs.dash;
    el(g, "line", line);
    el(g, "polygon", { points: pts([b, [b[0] - size * ux - size * 0.45 * uy, b[1] - size * uy + size * 0.45 * ux], [b[0] - size * ux + size * 0.45 * uy, b[1] - size * uy - size * 0.45 * ux]]), fill: colour });
    return g;
  }

  // Where the pucks sit (at the instant of impact, along the line of impact) and the one scale
  // of every velocity arrow (screen units per velocity unit): the longest about 180 units, every
  // tip inside the picture.
  function fitPucks(p) {
    const W = 560, H = 460, C = [280, 250];
    let d = p.normal;
    if (!d) {
      // No line of impact: along the relative velocity.
      const r = [p.in[0][0] - p.in[1][0], p.in[0][1] - p.in[1][1]];
      const len = Math.hypot(r[0], r[1]);
      d = len > 0 ? [r[0] / len, r[1] / len] : [1, 0];
    }
    let radii, gap;
    if (p.radii) {
      const k = 130 / (p.radii[0] + p.radii[1]);
      gap = [p.radii[0] * k, p.radii[1] * k];
      radii = gap.map((r) => Math.max(3, r));
    } else {
      // Points meet at one place: drawn apart along the line, so each keeps its arrows.
      gap = [22, 22];
      radii = [7, 7];
    }
    const c = [[C[0] - gap[0] * d[0], C[1] + gap[0] * d[1]], [C[0] + gap[1] * d[0], C[1] - gap[1] * d[1]]];
    const vs = [[0, p.in[0]], [1, p.in[1]]];
    if (p.fin) vs.push([0, p.fin[0]], [1, p.fin[1]]);
    if (p.fin && $("p-reverse").checked) vs.push([0, p.fin[0].map((x) => -x)], [1, p.fin[1].map((x) => -x)]);
    let s = Infinity;
    const margin = 26;
    for (const [i, v] of vs) {
      const m = Math.hypot(v[0], v[1]);
      if (!(m > 0) || !isFinite(m)) continue;
      s = Math.min(s, 180 / m);
      const [x, y] = c[i];
      if (v[0] > 0) s = Math.min(s, (W - margin - x) / v[0]);
      if (v[0] < 0) s = Math.min(s, (margin - x) / v[0]);
      if (v[1] > 0) s = Math.min(s, (y - margin) / v[1]);
      if (v[1] < 0) s = Math.min(s, (y - (H - margin)) / v[1]);
    }
    if (!(s > 0) || !isFinite(s)) s = 180;
    return { W, H, C, d, c, radii, s };
  }

  // Whether every arrow's tip (IN, FIN, and the reverse's) is inside the picture at map `m`.
  function pucksFit(m, p) {
    const vs = [[0, p.in[0]], [1, p.in[1]]];
    if (p.fin) vs.push([0, p.fin[0]], [1, p.fin[1]]);
    if (p.fin && $("p-reverse").checked) vs.push([0, p.fin[0].map((x) => -x)], [1, p.fin[1].map((x) => -x)]);
    return vs.every(([i, v]) => {
      const x = m.c[i][0] + m.s * v[0], y = m.c[i][1] - m.s * v[1];
      return x > 10 && x < m.W - 10 && y > 10 && y < m.H - 10;
    });
  }

  function drawPucks(p) {
    const svg = $("pucks-svg");
    // The scale kept while an arrow is dragged (or after a move, while every tip fits).
    if (!pucks.keep || !pucks.map || (pucks.dragging < 0 && !pucksFit(pucks.map, p))) pucks.map = fitPucks(p);
    const m = pucks.map;
    const step = snapStep(m);
    // For tests and the curious: where the pucks are drawn (their centres and radii in the
    // picture's units), the velocity scale, the step a drag snaps to, the frame's velocity.
    svg.setAttribute("data-map", JSON.stringify({ c: m.c, radii: m.radii, s: m.s, step, w: p.w }));
    clear(svg);
    const tip = (i, v) => [m.c[i][0] + m.s * v[0], m.c[i][1] - m.s * v[1]];
    const unit = p.velocity_unit ? " " + p.velocity_unit : "";
    const massUnit = planeState && planeState.units && planeState.units.mass ? " " + planeState.units.mass : "";
    el(svg, "text", { x: 12, y: 20, class: "title" },
      "m\u2081 = " + short(p.masses[0]) + massUnit + ", m\u2082 = " + short(p.masses[1]) + massUnit + (p.e === null ? "" : ", e = " + short(p.e)) +
      ", " + $("p-frame").selectedOptions[0].textContent + " frame");
    el(svg, "text", { x: 12, y: m.H - 10, class: "tick" }, "solid: before (IN), dashed: after (FIN); arrows in one velocity scale");
    // Labels beside their points (the arrows' tips), moved down a line where they would overlap another.
    const placed = [];
    const label = (at, text, colour) => {
      const right = at[0] < m.W - 170;
      const width = 7 * text.length;
      const x0 = right ? at[0] + 10 : at[0] - 10 - width;
      let y = at[1] - 8;
      while (placed.some((q) => Math.abs(q.y - y) < 14 && x0 < q.x1 && q.x0 < x0 + width)) y += 15;
      placed.push({ x0, x1: x0 + width, y });
      el(svg, "text", { x: r2(right ? at[0] + 10 : at[0] - 10), y: r2(y), "text-anchor": right ? "start" : "end", class: "label", fill: colour, "paint-order": "stroke", stroke: "#fff", "stroke-width": 4 }, text);
    };
    const d = m.d;
    const far = (k) => [m.C[0] + k * d[0], m.C[1] - k * d[1]];
    if (p.normal) {
      // The line of impact through the point of contact, and the tangent plane across it.
      const a = far(-700), b = far(700);
      el(svg, "line", { id: "line-of-impact", x1: r2(a[0]), y1: r2(a[1]), x2: r2(b[0]), y2: r2(b[1]), stroke: "#6b7280", "stroke-width": 1.6, "stroke-dasharray": "8 5" });
      const t1 = [m.C[0] - 700 * d[1], m.C[1] - 700 * d[0]], t2 = [m.C[0] + 700 * d[1], m.C[1] + 700 * d[0]];
      el(svg, "line", { x1: r2(t1[0]), y1: r2(t1[1]), x2: r2(t2[0]), y2: r2(t2[1]), stroke: "#d1d5db", "stroke-width": 1, "stroke-dasharray": "2 4" });
      const at = far(-190);
      label([Math.min(Math.max(at[0], 30), m.W - 30), Math.min(Math.max(at[1], 40), m.H - 30)], "n at " + short(p.normal_deg) + "\u00b0", "#4b5563");
    }
    // The pucks: disks of their radii (to scale), or points.
    for (let i = 0; i < 2; i++) {
      const [x, y] = m.c[i];
      el(svg, "circle", { id: "puck-" + (i + 1), cx: r2(x), cy: r2(y), r: r2(m.radii[i]), fill: planeTints[i], "fill-opacity": 0.9, stroke: planeColours[i], "stroke-width": 2.2 });
      const name = (p.radii ? "" : "point ") + (i + 1);
      const inside = m.radii[i] >= 16;
      el(svg, "text", { x: r2(inside ? x : x + (i ? 10 : -10)), y: r2(y + 20), "text-anchor": inside ? "middle" : i ? "start" : "end", class: "tick", fill: "#374151" }, name);
    }
    if (p.radii && p.b !== null) {
      // Body 1's path relative to body 2, and body 2's centre at the impact parameter b from it.
      const rel = [p.in[0][0] - p.in[1][0], p.in[0][1] - p.in[1][1]];
      const len = Math.hypot(rel[0], rel[1]);
      if (len > 0) {
        const u = [rel[0] / len, -rel[1] / len];
        const c1 = m.c[0], c2 = m.c[1];
        el(svg, "line", { x1: r2(c1[0] - 700 * u[0]), y1: r2(c1[1] - 700 * u[1]), x2: r2(c1[0] + 700 * u[0]), y2: r2(c1[1] + 700 * u[1]), stroke: "#a78bfa", "stroke-width": 1.2, "stroke-dasharray": "3 4" });
        const k = (c2[0] - c1[0]) * u[0] + (c2[1] - c1[1]) * u[1];
        const foot = [c1[0] + k * u[0], c1[1] + k * u[1]];
        el(svg, "line", { id: "impact-parameter", x1: r2(c2[0]), y1: r2(c2[1]), x2: r2(foot[0]), y2: r2(foot[1]), stroke: "var(--rev)", "stroke-width": 1.6 });
        el(svg, "text", { x: r2((c2[0] + foot[0]) / 2 + 6), y: r2((c2[1] + foot[1]) / 2 + 4), class: "label", fill: "var(--rev)", "paint-order": "stroke", stroke: "#fff", "stroke-width": 4 }, "b = " + short(p.b));
      }
    }
    const vec = (v) => "(" + short(v[0]) + ", " + short(v[1]) + ")";
    const names = [["v\u2081", "v\u2081\u2032"], ["v\u2082", "v\u2082\u2032"]];
    if (p.fin) {
      for (let i = 0; i < 2; i++) {
        const to = tip(i, p.fin[i]);
        arrow(svg, m.c[i], to, planeColours[i], { id: "fin-" + (i + 1), dash: "7 4", width: 2.2 });
        label(to, names[i][1] + " " + vec(p.fin[i]), planeColours[i]);
      }
      if ($("p-reverse").checked) {
        // The time reverse: IN' = -FIN (FIN' = -IN, the IN arrows turned round).
        for (let i = 0; i < 2; i++) {
          const back = [-p.fin[i][0], -p.fin[i][1]];
          const to = tip(i, back);
          arrow(svg, m.c[i], to, "var(--rev)", { id: "rev-" + (i + 1), dash: "2 3", width: 2 });
          label(to, names[i][0] + " rev. = \u2212" + names[i][1] + " " + vec(back), "var(--rev)");
        }
      }
    } else {
      el(svg, "text", { x: 12, y: 40, class: "label", fill: "var(--bad)" }, "They do not approach along n: no collision, no FIN.");
    }
    for (let i = 0; i < 2; i++) {
      const to = tip(i, p.in[i]);
      arrow(svg, m.c[i], to, planeColours[i], { id: "in-" + (i + 1), width: 3.2 });
      label(to, names[i][0] + " " + vec(p.in[i]) + unit, planeColours[i]);
    }
    // The handles to drag, on top; the keys move the selected one (ringed while focused).
    const fixed = [0, 1].filter((i) => !draggable(i));
    if (fixed.length) {
      el(svg, "text", { id: "drag-note", x: 12, y: m.H - 26, class: "tick" },
        (fixed.length === 2 ? "v\u2081 and v\u2082 move" : "v" + (fixed[0] ? "\u2082" : "\u2081") + " moves") +
        " with this frame: type it, or drag it in another frame");
    }
    for (let i = 0; i < 2; i++) {
      if (!draggable(i)) continue;
      const [x, y] = tip(i, p.in[i]);
      if (i === pucks.selected) el(svg, "circle", { class: "tip-ring", cx: r2(x), cy: r2(y), r: 12, fill: "none", stroke: "#111827", "stroke-width": 1.5, "stroke-dasharray": "3 3" });
      el(svg, "circle", { id: "tip-" + (i + 1), class: "tip", cx: r2(x), cy: r2(y), r: 7, fill: planeColours[i], stroke: "#fff", "stroke-width": 2 });
      // Where a finger grabs the tip (22 px around it, `touch-action: none`); elsewhere a
      // finger scrolls the page.
      el(svg, "circle", { class: "handle", "data-body": i, cx: r2(x), cy: r2(y), r: r2(22 * kOf(svg)), fill: "transparent" });
    }
  }

  // Momentum as vectors: p1 + p2 = P before (solid) and p1' + p2' = P after (dashed), tip to
  // tail, with the impulse J on body 2 joining p1' to p1 (Axiom 1 in the plane).
  function drawMomentum(p) {
    const svg = $("momentum-svg");
    clear(svg);
    const P = p.p_total;
    const points = [[0, 0], p.p_in[0], P];
    if (p.p_fin) points.push(p.p_fin[0]);
    let x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity;
    for (const q of points) {
      if (!isFinite(q[0]) || !isFinite(q[1])) continue;
      x0 = Math.min(x0, q[0]); x1 = Math.max(x1, q[0]); y0 = Math.min(y0, q[1]); y1 = Math.max(y1, q[1]);
    }
    let span = Math.max(x1 - x0, y1 - y0);
    span = span > 0 && isFinite(span) ? span * 1.2 : 2;
    const cx = (x0 + x1) / 2, cy = (y0 + y1) / 2;
    const area = { x: 58, y: 30, w: 380, h: 380 };
    const ax = frameAxes(svg, area, { x0: cx - span / 2, x1: cx + span / 2, y0: cy - span / 2, y1: cy + span / 2 }, ["px", "py"]);
    const S = (q) => [ax.X(q[0]), ax.Y(q[1])];
    const g = el(svg, "g", {});
    const names = [["p\u2081", "p\u2081\u2032"], ["p\u2082", "p\u2082\u2032"]];
    // Labels placed last, each clear of the axis names and the labels before it (P first); an
    // arrow of zero length gets none (p2 = 0 would sit on P).
    const notes = [];
    const note = (q, text, colour, dy, from, to) => {
      if (from && to && Math.hypot(to[0] - from[0], to[1] - from[1]) < 0.5) return;
      notes.push([q, text, colour, dy]);
    };
    const mid = (a, b) => [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2];
    arrow(g, S([0, 0]), S(P), "var(--com)", { id: "momentum-total", width: 3 });
    note(S(P), "P", "var(--com)", -6);
    if (p.p_fin) {
      arrow(g, S([0, 0]), S(p.p_fin[0]), planeColours[0], { dash: "7 4" });
      arrow(g, S(p.p_fin[0]), S(P), planeColours[1], { dash: "7 4" });
      note(mid(S([0, 0]), S(p.p_fin[0])), names[0][1], planeColours[0], 14, S([0, 0]), S(p.p_fin[0]));
      note(mid(S(p.p_fin[0]), S(P)), names[1][1], planeColours[1], 14, S(p.p_fin[0]), S(P));
      arrow(g, S(p.p_fin[0]), S(p.p_in[0]), "var(--rev)", { id: "momentum-impulse", width: 1.8, dash: "2 3" });
      note(mid(S(p.p_fin[0]), S(p.p_in[0])), "J", "var(--rev)", -4, S(p.p_fin[0]), S(p.p_in[0]));
    }
    arrow(g, S([0, 0]), S(p.p_in[0]), planeColours[0], {});
    arrow(g, S(p.p_in[0]), S(P), planeColours[1], {});
    note(mid(S([0, 0]), S(p.p_in[0])), names[0][0], planeColours[0], -6, S([0, 0]), S(p.p_in[0]));
    note(mid(S(p.p_in[0]), S(P)), names[1][0], planeColours[1], -6, S(p.p_in[0]), S(P));
    const placed = boxesOf(svg);
    for (const [q, text, colour, dy] of notes) {
      placeText(g, placed, { x: r2(q[0] + 6), y: r2(q[1] + dy), class: "label", fill: colour, "paint-order": "stroke", stroke: "#fff", "stroke-width": 4 }, text);
    }
  }

  // The lecture's velocity plane of the normal parts (v1.n, v2.n), |n| = 1: along the line of
  // impact the pucks collide as on a rail, with the same masses and e.
  function drawNormalParts(p) {
    const svg = $("normal-svg");
    clear(svg);
    const np = p.normal_parts;
    // Without a line of impact (or a collision) there is no rail to draw.
    $("normal-figure").hidden = !np;
    if (!np) return;
    const map = fitVelocityPlane([np], $("p-zoom").checked, (q, add) => { if (q.reverse) [q.reverse.in, q.reverse.fin].forEach(add); });
    velocityPlane(svg, np, map, {
      prefix: "n-", axes: ["v\u2081\u00b7n", "v\u2082\u00b7n"],
      title: "along n: M = diag(" + short(p.masses[0]) + ", " + short(p.masses[1]) + "), e = " + short(np.e),
      under: (g, X, Y) => {
        // The time reverse: IN' = -FIN, FIN' = -IN, on the same momentum line through -P.
        if (!np.reverse) return;
        const rv = np.reverse;
        el(g, "line", { x1: r2(X(rv.in[0])), y1: r2(Y(rv.in[1])), x2: r2(X(rv.fin[0])), y2: r2(Y(rv.fin[1])), stroke: "var(--rev)", "stroke-dasharray": "4 4", "stroke-width": 1.5 });
      },
      more: (point) => {
        if (!np.reverse) return;
        point(np.reverse.in, "var(--rev)", "IN\u2032", "point-rev-in", 4);
        point(np.reverse.fin, "var(--rev)", "FIN\u2032", "point-rev-fin", 4);
      },
    });
  }

  function drawPlaneNumbers(p) {
    fillBox("plane-numbers", (box) => planeNumbers(box, p));
  }
  function planeNumbers(box, p) {
    const s = planeState;
    const cell = (x) => (typeof x === "number" ? num(x) : String(x));
    const pair = (v) => "(" + cell(v[0]) + ", " + cell(v[1]) + ")";
    const polar = (speed, angle) => (speed === 0 ? "0" : num(speed) + (angle === null || angle === undefined ? "" : " @ " + num(angle) + "\u00b0"));
    const table = (caption, head, rows) => numbersTable(box, caption, head, rows);
    const para = (html) => { const x = document.createElement("p"); x.innerHTML = html; box.appendChild(x); };
    const unit = s.units ? " (" + s.units.velocity + ")" : "";
    const rows = [
      ['<span class="c-1">v<sub>1</sub></span>', pair(s.in[0]), polar(p.in_polar[0][0], p.in_polar[0][1])],
      ['<span class="c-2">v<sub>2</sub></span>', pair(s.in[1]), polar(p.in_polar[1][0], p.in_polar[1][1])],
    ];
    if (s.fin) {
      rows.push(['<span class="c-1">v<sub>1</sub>&prime;</span>', pair(s.fin[0]), polar(s.fin_speed[0], s.fin_angle_deg[0])]);
      rows.push(['<span class="c-2">v<sub>2</sub>&prime;</span>', pair(s.fin[1]), polar(s.fin_speed[1], s.fin_angle_deg[1])]);
      rows.push(['<span class="c-com">V<sub>COM</sub></span>', pair(s.v_com), polar(p.v_com_polar[0], p.v_com_polar[1])]);
    }
    table("Velocities" + unit, ["", "components", "speed @ angle"], rows);
    if (s.fin && s.impulse) {
      // A momentum, in the mass unit times the velocity unit (collide solve's "kg m/s").
      const u = s.units ? " (" + (s.units.mass || "mass unit") + " " + (s.units.velocity || "velocity unit") + ")" : "";
      table("Impulse" + u, ["", "components", ""], [['<span class="c-rev">J</span> on body 2', pair(s.impulse), "m\u2082 (v\u2082\u2032 \u2212 v\u2082)"]]);
    }
    if (!s.fin) {
      para("The pucks do not approach along the line of impact (n&middot;(v<sub>1</sub> &minus; v<sub>2</sub>) &le; 0): they do not collide.");
      return;
    }
    const en = s.energy;
    const energy = [
      ["KE<sub>IN</sub>", cell(en.in)],
      ["KE<sub>FIN</sub>", cell(en.fin)],
      ['<span class="c-com">KE<sub>COM</sub></span> = &frac12; M |V<sub>COM</sub>|<sup>2</sup>', cell(en.com)],
      [p.normal ? "crunch = &frac12; &mu; (n&middot;(v<sub>1</sub> &minus; v<sub>2</sub>))<sup>2</sup>" : "crunch = KE<sub>IN</sub> &minus; KE<sub>COM</sub>", cell(en.crunch)],
    ];
    if (en.lost !== undefined) energy.push(["lost", cell(en.lost)]);
    if (en.released !== undefined) energy.push(["released", cell(en.released)]);
    table("Energy" + (s.units ? " (" + s.units.energy + ")" : ""), ["", ""], energy);
    if (s.normal_parts) {
      table("Along the line of impact (|n| = 1)", ["", "v<sub>1</sub>&middot;n", "v<sub>2</sub>&middot;n"], [
        ["IN", cell(s.normal_parts.in[0]), cell(s.normal_parts.in[1])],
        ["FIN", cell(s.normal_parts.fin[0]), cell(s.normal_parts.fin[1])],
      ]);
    }
    const angles = [];
    if (s.angle_between_deg !== undefined && s.angle_between_deg !== null) angles.push("between v<sub>1</sub>&prime; and v<sub>2</sub>&prime; <span class=\"num\">" + num(s.angle_between_deg) + "&deg;</span>");
    // As collide solve's text: no "turned" for a body at rest before or after (its JSON says 0).
    const moving = (v) => Number(v[0]) !== 0 || Number(v[1]) !== 0;
    if (s.turned_deg) s.turned_deg.forEach((a, i) => { if (a !== null && moving(s.in[i]) && moving(s.fin[i])) angles.push("body " + (i + 1) + " turned <span class=\"num\">" + num(a) + "&deg;</span>"); });
    if (angles.length) para("Angles: " + angles.join("; "));
    if (p.normal) {
      let line = "Line of impact n = (<span class=\"num\">" + num(p.normal[0]) + ", " + num(p.normal[1]) + "</span>) at <span class=\"num\">" + num(p.normal_deg) + "&deg;</span>";
      if (p.radii) line += "; sin &phi; = b / (R<sub>1</sub> + R<sub>2</sub>) = <span class=\"num\">" + num(p.b / (p.radii[0] + p.radii[1])) + "</span>, &phi; = <span class=\"num\">" + num(p.phi_deg) + "&deg;</span> from v<sub>1</sub> &minus; v<sub>2</sub>";
      para(line);
    }
    if (s.reverse) {
      para('<span class="c-rev">Time reverse</span>: IN&prime; = &minus;FIN = ' + pair(s.reverse.in[0]) + ", " + pair(s.reverse.in[1]) +
        "; FIN&prime; = &minus;IN; e&prime; = " + (typeof s.reverse.restitution === "number"
          ? "1/e = " + cell(s.reverse.restitution) + (s.reverse.restitution > 1 ? ": an explosion, not a collision" : "")
          : "undefined: 1/e with e = 0, the stuck bodies fly apart"));
    }
  }

  // Whether body i's arrow can be dragged in the frame on screen: not where the frame moves with
  // a velocity that depends on it (body i initially at rest: its arrow is always 0; a body
  // finally at rest: FIN depends on both INs, and may not give every on-screen value).
  function draggable(i) {
    const f = $("p-frame").value;
    return f !== "rest-in:" + (i + 1) && !f.startsWith("rest-fin:");
  }

  // The lab velocity of body i that the frame on screen shows as `u`: the frame's velocity w
  // does not depend on v_i (the lab, an observer, the other body initially at rest: v_i = u + w),
  // or, in the COM frame, u = v_i - (m_i v_i + m_j v_j) / M = (m_j / M) (v_i - v_j), so
  // v_i = v_j + (M / m_j) u (body j's lab velocity unchanged).
  function labVelocity(i, u) {
    const p = planeAnswer.picture;
    if ($("p-frame").value !== "com") return [u[0] + p.w[0], u[1] + p.w[1]];
    const j = 1 - i, k = (p.masses[0] + p.masses[1]) / p.masses[j];
    return [p.in[j][0] + p.w[0] + k * u[0], p.in[j][1] + p.w[1] + k * u[1]];
  }

  // Moves the tip of body i's IN arrow to `v` (a velocity in the frame on screen), snapped to
  // the step; the typed velocity keeps the case's unit. A move the core refuses is kept, so the
  // keys go on from it, not from the last valid case.
  function moveTip(i, v) {
    if (!draggable(i)) return null;
    const t0 = performance.now();
    const step = snapStep(pucks.map);
    const lab = labVelocity(i, v);
    const unit = planeAnswer.picture.velocity_unit;
    $("p-v" + (i + 1)).value = "(" + snapText(lab[0], step) + "," + snapText(lab[1], step) + ")" + (unit ? " " + unit : "");
    const answer = solvePlane(true);
    pucks.pending = answer && !answer.ok ? { i, v } : null;
    const ms = performance.now() - t0;
    view.lastUpdateMs = ms;
    view.planeTimings.push(ms);
    return answer;
  }

  // A pointer's place in the pucks' picture (its viewBox units).
  function pucksPoint(ev) {
    const svg = $("pucks-svg");
    const rect = svg.getBoundingClientRect();
    const vb = svg.viewBox.baseVal;
    return [(ev.clientX - rect.left) * vb.width / rect.width, (ev.clientY - rect.top) * vb.height / rect.height];
  }
  const tipVelocity = (i, q) => [(q[0] - pucks.map.c[i][0]) / pucks.map.s, (pucks.map.c[i][1] - q[1]) / pucks.map.s];

  function selectTip(i) {
    pucks.selected = i;
    const radio = document.querySelector('input[name="p-key"][value="' + i + '"]');
    if (radio) radio.checked = true;
    drawPucks(planeAnswer.picture);
  }

  function setupPucksDrag() {
    const svg = $("pucks-svg");
    let pending = null, queued = false;
    const flush = () => {
      queued = false;
      if (pending && pucks.dragging >= 0) {
        const q = pucksPoint(pending);
        pending = null;
        moveTip(pucks.dragging, tipVelocity(pucks.dragging, q));
      }
    };
    holdHandles(svg);
    svg.addEventListener("pointerdown", (ev) => {
      if (!core || ev.button !== 0) return;
      // A finger drags only from a tip's handle (it scrolls the page elsewhere).
      if (ev.pointerType === "touch" && !ev.target.classList.contains("handle")) return;
      const q = pucksPoint(ev);
      const p = planeAnswer.picture, m = pucks.map;
      // The nearer tip of the two IN arrows, within reach.
      let best = -1, dist = 36;
      for (let i = 0; i < 2; i++) {
        if (!draggable(i)) continue;
        const d = Math.hypot(m.c[i][0] + m.s * p.in[i][0] - q[0], m.c[i][1] - m.s * p.in[i][1] - q[1]);
        if (d < dist) { best = i; dist = d; }
      }
      svg.focus({ preventScroll: true });
      if (best < 0) return;
      pucks.dragging = best;
      pucks.selected = best;
      svg.setPointerCapture(ev.pointerId);
      svg.classList.add("dragging");
      ev.preventDefault();
    });
    svg.addEventListener("pointermove", (ev) => {
      if (pucks.dragging < 0) return;
      pending = ev;
      if (!queued) { queued = true; requestAnimationFrame(flush); }
    });
    const end = (ev) => {
      if (pucks.dragging < 0) return;
      if (ev.type === "pointerup") pending = ev;
      try {
        flush();
      } finally {
        pucks.dragging = -1;
        svg.classList.remove("dragging");
      }
      drawWaiting();
      say("plane-said", planeSentence());
      // Rescaled once the drag ends if an arrow left the picture.
      if (!pucksFit(pucks.map, planeAnswer.picture)) drawPucks(planeAnswer.picture);
    };
    svg.addEventListener("pointerup", end);
    svg.addEventListener("pointercancel", end);
    svg.addEventListener("keydown", (ev) => {
      if (!core) return;
      if (ev.key === "1" || ev.key === "2") {
        ev.preventDefault();
        selectTip(Number(ev.key) - 1);
        return;
      }
      const d = { ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowDown: [0, -1], ArrowUp: [0, 1] }[ev.key];
      if (!d) return;
      ev.preventDefault();
      const i = pucks.selected;
      if (!draggable(i)) return;
      const step = snapStep(pucks.map) * (ev.shiftKey ? 10 : 1);
      // From where the last key put the arrow, if the core refused it (so the keys can go past
      // a refused value); else from the case on screen.
      const v = pucks.pending && pucks.pending.i === i ? pucks.pending.v : planeAnswer.picture.in[i];
      const next = [v[0] + d[0] * step, v[1] + d[1] * step];
      moveTip(i, next);
    });
    for (const r of document.querySelectorAll('input[name="p-key"]')) r.addEventListener("change", () => { if (r.checked) selectTip(Number(r.value)); });
  }

  // Shows the fields of the chosen line of impact.
  function showLineFields() {
    const mode = lineMode();
    $("p-normal-field").hidden = mode !== "normal";
    $("p-disks-field").hidden = mode !== "disks";
  }

  // The sliders follow the core's answer (an angle typed as N30E or (1,1) included).
  function syncPlaneSliders(p) {
    for (const f of ["m1", "m2"]) massToSlider($("p-" + f + "-range"), $("p-" + f).value);
    const e = valueOf($("p-e").value);
    if (e >= 0) $("p-e-range").value = String(e);
    if (p.normal_deg !== null) $("p-normal-range").value = String(Math.round(p.normal_deg));
    // Radii and b typed with units (2.5 cm) are read in theirs (the same unit for all three).
    const sum = splitUnit($("p-r1").value)[0] + splitUnit($("p-r2").value)[0];
    if (sum > 0) {
      const range = $("p-b-range");
      range.min = String(-sum); range.max = String(sum); range.step = String(sum / 200);
      const b = splitUnit($("p-b").value)[0];
      if (isFinite(b)) range.value = String(b);
    }
  }

  function fillPlane(values) {
    for (const f of planeFields) $("p-" + f).value = values[f] || "";
    const mode = values.line || (values.normal ? "normal" : values.r1 || values.r2 || values.b ? "disks" : "none");
    for (const r of document.querySelectorAll('input[name="p-line"]')) r.checked = r.value === mode;
    // Keep a line of impact to come back to in the other mode.
    if (!$("p-normal").value) $("p-normal").value = "30deg";
    if (!$("p-r1").value && !$("p-r2").value && !$("p-b").value) { $("p-r1").value = "1"; $("p-r2").value = "1"; $("p-b").value = "1"; }
    showLineFields();
  }

  function setupPlane() {
    const c = data.setup.plane;
    fillPlane(c);
    const frames = [["lab", "lab (Earth)"], ["rest-in:1", "body 1 initially at rest"], ["rest-in:2", "body 2 initially at rest"], ["com", "COM"], ["rest-fin:1", "body 1 finally at rest"], ["rest-fin:2", "body 2 finally at rest"]];
    if (!frames.some((f) => f[0] === c.frame)) frames.push([c.frame, "observer at " + c.frame]);
    for (const [value, text] of frames) {
      const o = document.createElement("option");
      o.value = value; o.textContent = text; o.selected = value === c.frame;
      $("p-frame").appendChild(o);
    }
    $("p-reverse").checked = !!c.reverse;
    $("p-exact").checked = !!c.exact;
    // A typed value leaves the preset: the menu no longer names it.
    const typed = () => { pucks.pending = null; $("p-preset").value = ""; solvePlane(false); };
    for (const f of planeFields) $("p-" + f).addEventListener("input", typed);
    for (const f of ["m1", "m2"]) {
      $("p-" + f + "-range").addEventListener("input", () => {
        $("p-" + f).value = sliderToMass($("p-" + f + "-range"), $("p-" + f).value);
        solvePlane(false);
      });
    }
    $("p-e-range").addEventListener("input", () => { $("p-e").value = String(Number($("p-e-range").value)); solvePlane(false); });
    $("p-normal-range").addEventListener("input", () => { $("p-normal").value = $("p-normal-range").value + "deg"; solvePlane(false); });
    $("p-b-range").addEventListener("input", () => {
      const unit = splitUnit($("p-b").value)[1] || splitUnit($("p-r1").value)[1];
      $("p-b").value = String(Number(Number($("p-b-range").value).toPrecision(3))) + (unit ? " " + unit : "");
      solvePlane(false);
    });
    for (const r of document.querySelectorAll('input[name="p-line"]')) r.addEventListener("change", () => { showLineFields(); solvePlane(false); });
    for (const id of ["p-frame", "p-reverse", "p-exact"]) $(id).addEventListener("change", typed);
    $("p-zoom").addEventListener("change", () => drawNormalParts(planeAnswer.picture));
    $("p-preset").addEventListener("change", () => {
      const p = planePresets[$("p-preset").value];
      if (!p) return;
      fillPlane(p);
      solvePlane(false);
    });
    setupPucksDrag();
  }
