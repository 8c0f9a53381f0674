  // ---------------------------------------------------------------- rigid bodies
  // The inputs (ids "r-" + name, `collide solve`'s homework flags) and what the core answers
  // (src/view/rigid.rs): the bodies at the instant of impact with their velocities and spins
  // before and after, the contact's normal and tangent, and the velocity plane of the contact
  // points along the normal. Every number drawn or shown is the core's (the picture's values
  // are the state's, each rounded once from the exact outcome).
  const rigidFields = ["m1", "m2", "v1", "target", "pivot", "hit_at", "ball", "spin", "e", "friction", "beta"];
  const rigidPresets = {
    rod: { m1: "1", m2: "4", v1: "3", target: "rod 2", hit_at: "end", e: "elastic" },
    door: { m1: "50 g", m2: "2 kg", v1: "10 m/s", target: "door 0.9 m", pivot: "end", hit_at: "0.6 m", e: "elastic" },
    floor: { m1: "1", m2: "floor", v1: "(7,-1)", ball: "sphere 1", friction: "1", e: "elastic" },
    garwin: { m1: "1", m2: "floor", v1: "(3,-1)", ball: "sphere 1", beta: "1", e: "elastic" },
  };
  const contactWords = {
    smooth: "no friction, the impulse is normal",
    stick: "the slip stopped and the contact held",
    slip: "it slid throughout, P_t = \u03bc P_n",
    reverse: "the slip stopped, then reversed",
    joined: "one rigid body after",
  };
  let rigidAnswer = data.answers.rigid; // the last good answer
  // The picture's map (kept while a handle is dragged), what is dragged ("v1", "hit" or null).
  const rigidView = { map: null, keep: false, dragging: null, sliding: false, timings: [] };
  view.rigidTimings = rigidView.timings;

  function rigidRequest() {
    const r = { op: "rigid", v2: "", law: "" };
    for (const f of rigidFields) r[f] = $("r-" + f).value;
    return r;
  }

  // Solves the case on screen and redraws; `keepMap` keeps the picture's scales (a drag).
  function solveRigid(keepMap) {
    if (!core) return null;
    const answer = core(rigidRequest());
    const ids = {};
    for (const f of rigidFields) ids[f] = "r-" + f;
    showError(answer, ids, "r-m1", "rigid-error", ["rigid-state", "rigid-command", "rigid-said"],
      ["rigid-svg", "rigid-numbers", "rigid-normal-svg"]);
    if (!answer.ok) { clearTimeout(sayTimers["rigid-said"]); return answer; }
    rigidAnswer = answer;
    rigidView.keep = !!keepMap;
    renderRigid();
    if (!rigidView.dragging) sayLater("rigid-said", rigidSentence);
    return answer;
  }

  function renderRigid() {
    const a = rigidAnswer, p = a.picture;
    drawRigid(p);
    // During a drag (a handle, or a slider until it is let go), the tables and the velocity
    // plane along n are drawn after the frame, or once in sight.
    const later = !!rigidView.dragging || rigidView.sliding;
    drawSeen($("rigid-numbers"), () => drawRigidNumbers(p), later, true);
    drawSeen($("rigid-normal-figure"), () => drawRigidPlane(p), later, true);
    syncRigidSliders(a.picture);
    $("rigid-state").textContent = a.state;
    $("rigid-command").textContent = a.command;
  }

  // The extent of a body along y from its centre, and whether it is drawn as a line (a wall,
  // floor or ceiling through the contact point).
  function halfHeight(b) {
    if (b.kind === "rod") return b.sizes[0] / 2;
    if (b.kind === "box") return b.sizes[1] / 2;
    if (b.sizes.length) return b.sizes[0];
    return 0;
  }
  const immovable = (b) => b.kind === "floor" || b.kind === "wall" || b.kind === "ceiling";
  const round = (b) => b.kind === "disk" || b.kind === "ring" || b.kind === "sphere" || b.kind === "shell";
  // A round body's radius on screen at map `m` (as its outline is drawn), else 0.
  const drawnRadius = (b, m) => (round(b) ? Math.min(b.sizes[0] * m.s, 2000) : 0);

  // A body's velocity arrow `v` on screen at map `m`: from its centre, or from a round body's
  // edge in the direction of `v` (from the centre it would run inside the outline), as the
  // N-body panel draws a slow puck's; its length `k |v|` either way. Returns [from, tip].
  function velocityArrow(m, b, v) {
    const c = [m.X(b.position[0]), m.Y(b.position[1])];
    const d = [m.k * v[0], -m.k * v[1]], len = Math.hypot(d[0], d[1]), r = drawnRadius(b, m);
    const from = len > 0 && r > 0 ? [c[0] + d[0] / len * r, c[1] + d[1] / len * r] : c;
    return [from, [from[0] + d[0], from[1] + d[1]]];
  }
  // The velocity whose arrow `velocityArrow` draws with its tip at the screen point `q` (a
  // round body's: along the centre to `q`, as long as `q` is beyond the edge).
  function arrowVelocity(m, b, q) {
    const c = [m.X(b.position[0]), m.Y(b.position[1])];
    const w = [q[0] - c[0], q[1] - c[1]], dist = Math.hypot(w[0], w[1]), r = drawnRadius(b, m);
    const f = r > 0 && dist > 0 ? Math.max(0, dist - r) / dist : 1;
    return [f * w[0] / m.k, -f * w[1] / m.k];
  }

  // World to screen: the bodies and the contact fitted in the picture (spans taken by halves:
  // sizes near the largest double do not overflow), and the one scale `k` of every velocity
  // arrow (the longest about 120 units).
  function fitRigid(p) {
    let x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity;
    const add = (q) => {
      if (!isFinite(q[0]) || !isFinite(q[1])) return;
      x0 = Math.min(x0, q[0]); x1 = Math.max(x1, q[0]);
      y0 = Math.min(y0, q[1]); y1 = Math.max(y1, q[1]);
    };
    add(p.point);
    for (const b of p.bodies) {
      if (immovable(b)) continue;
      const h = halfHeight(b);
      const w = b.kind === "box" ? b.sizes[0] / 2 : b.kind === "rod" ? 0 : h;
      add([b.position[0] - w, b.position[1] - h]);
      add([b.position[0] + w, b.position[1] + h]);
      if (b.pivot) add(b.pivot);
    }
    let half = Math.max(x1 / 2 - x0 / 2, y1 / 2 - y0 / 2) * 1.5;
    if (!(half > 0) || !isFinite(half)) half = Math.max(Math.abs(p.point[0]), Math.abs(p.point[1]), 1);
    half = Math.min(half, Number.MAX_VALUE);
    const cx = x0 / 2 + x1 / 2, cy = y0 / 2 + y1 / 2;
    const area = { x: 40, y: 40, w: 480, h: 380 };
    const s = Math.min(area.w, area.h) / 2 / half;
    let vmax = 0;
    for (const b of p.bodies) for (const v of [b.v_in, b.v_fin]) vmax = Math.max(vmax, Math.hypot(v[0] / 2, v[1] / 2) * 2);
    const k = vmax > 0 && isFinite(vmax) ? 120 / vmax : 1;
    let wmax = 0;
    for (const b of p.bodies) wmax = Math.max(wmax, Math.abs(b.omega_in), Math.abs(b.omega_fin));
    return { s, k, wmax: isFinite(wmax) ? wmax : Number.MAX_VALUE, X: (x) => area.x + area.w / 2 + s * (x - cx), Y: (y) => area.y + area.h / 2 - s * (y - cy), area };
  }

  // A spin as an arc about `c` (screen) of radius r, its sweep the spin's share of the largest
  // (270 degrees), counterclockwise for a positive spin, with an arrowhead at its end.
  function spinArc(parent, c, r, omega, wmax, colour, dash, id) {
    if (!(wmax > 0) || omega === 0) return;
    const sweep = Math.sign(omega) * Math.max(20, 270 * Math.abs(omega) / wmax) * Math.PI / 180;
    const start = Math.PI / 2;
    const at = (t) => [c[0] + r * Math.cos(t), c[1] - r * Math.sin(t)];
    const a = at(start), b = at(start + sweep);
    const large = Math.abs(sweep) > Math.PI ? 1 : 0;
    const sweepFlag = sweep > 0 ? 0 : 1;
    const attrs = { id, d: "M " + r2(a[0]) + " " + r2(a[1]) + " A " + r2(r) + " " + r2(r) + " 0 " + large + " " + sweepFlag + " " + r2(b[0]) + " " + r2(b[1]), fill: "none", stroke: colour, "stroke-width": 2 };
    if (dash) attrs["stroke-dasharray"] = dash;
    el(parent, "path", attrs);
    // The head, along the arc's direction at its end.
    const t = start + sweep, d = Math.sign(sweep);
    const u = [-Math.sin(t) * d, -Math.cos(t) * d];
    const n = [Math.cos(t), -Math.sin(t)];
    const size = 8;
    el(parent, "polygon", { points: pts([b, [b[0] - size * u[0] + size * 0.45 * n[0], b[1] - size * u[1] + size * 0.45 * n[1]], [b[0] - size * u[0] - size * 0.45 * n[0], b[1] - size * u[1] - size * 0.45 * n[1]]]), fill: colour });
  }

  function drawRigid(p) {
    const svg = $("rigid-svg");
    clear(svg);
    if (!p) {
      el(svg, "text", { x: 40, y: 60, class: "label" }, "The bodies do not approach at the contact: no collision.");
      return;
    }
    if (!rigidView.keep || !rigidView.map) rigidView.map = fitRigid(p);
    // Screen units per unit of length (the tests read a drag back with it).
    view.rigidScale = rigidView.map.s;
    const m = rigidView.map;
    const { X, Y } = m;
    const S = (q) => [X(q[0]), Y(q[1])];
    const colours = ["var(--body1)", "var(--body2)"];
    const g = el(svg, "g", {});
    // The bodies.
    p.bodies.forEach((b, i) => {
      const c = S(b.position);
      const id = "rigid-body" + (i + 1);
      if (b.kind === "floor" || b.kind === "ceiling") {
        const y = Y(p.point[1]);
        el(g, "line", { id, x1: 10, y1: r2(y), x2: 550, y2: r2(y), stroke: "#374151", "stroke-width": 3 });
        const dy = b.kind === "floor" ? 8 : -8;
        for (let x = 20; x < 550; x += 16) el(g, "line", { x1: x, y1: r2(y), x2: x - 8, y2: r2(y + dy), stroke: "#6b7280", "stroke-width": 1 });
      } else if (b.kind === "wall") {
        const x = X(p.point[0]);
        el(g, "line", { id, x1: r2(x), y1: 10, x2: r2(x), y2: 450, stroke: "#374151", "stroke-width": 3 });
      } else if (b.kind === "rod") {
        const h = b.sizes[0] / 2 * m.s;
        el(g, "line", { id, x1: r2(c[0]), y1: r2(c[1] - h), x2: r2(c[0]), y2: r2(c[1] + h), stroke: colours[i], "stroke-width": 7, "stroke-linecap": "round" });
      } else if (b.kind === "box") {
        const w = b.sizes[0] / 2 * m.s, h = b.sizes[1] / 2 * m.s;
        el(g, "rect", { id, x: r2(c[0] - w), y: r2(c[1] - h), width: r2(2 * w), height: r2(2 * h), fill: "none", stroke: colours[i], "stroke-width": 3 });
      } else if (b.kind === "point") {
        el(g, "circle", { id, cx: r2(c[0]), cy: r2(c[1]), r: 7, fill: colours[i] });
      } else {
        el(g, "circle", { id, cx: r2(c[0]), cy: r2(c[1]), r: r2(Math.min(b.sizes[0] * m.s, 2000)), fill: "none", stroke: colours[i], "stroke-width": 3 });
      }
      if (b.pivot) {
        const q = S(b.pivot);
        el(g, "circle", { id: "rigid-pivot" + (i + 1), cx: r2(q[0]), cy: r2(q[1]), r: 5, fill: "#fff", stroke: "#111827", "stroke-width": 2 });
      }
    });
    // The contact's normal and tangent, 50 units each from the contact point.
    const c = S(p.point);
    const tipN = [c[0] + 40 * p.normal[0], c[1] - 40 * p.normal[1]];
    const tipT = [c[0] + 40 * p.tangent[0], c[1] - 40 * p.tangent[1]];
    arrow(g, c, tipN, "#4b5563", { id: "rigid-normal", width: 1.5 });
    arrow(g, c, tipT, "#4b5563", { id: "rigid-tangent", width: 1.5, dash: "3 3" });
    const labels = el(svg, "g", {});
    const placed = [];
    placeText(labels, placed, { x: r2(tipN[0] + 4), y: r2(tipN[1] + 14), class: "label", fill: "#374151" }, "n");
    placeText(labels, placed, { x: r2(tipT[0] + 4), y: r2(tipT[1] - 4), class: "label", fill: "#374151" }, "t");
    // Velocity arrows (solid before, dashed after) from each centre, or a round body's edge,
    // and spin arcs.
    const sub = ["\u2081", "\u2082"];
    p.bodies.forEach((b, i) => {
      if (immovable(b)) return;
      const q = S(b.position);
      const tip = (v) => velocityArrow(m, b, v)[1];
      arrow(g, ...velocityArrow(m, b, b.v_in), colours[i], { id: "rigid-v" + (i + 1) });
      arrow(g, ...velocityArrow(m, b, b.v_fin), colours[i], { id: "rigid-v" + (i + 1) + "-fin", dash: "6 4" });
      const r = b.kind === "point" ? 16 : Math.max(16, Math.min(60, halfHeight(b) * m.s * (b.kind === "rod" ? 0.25 : 0.6)));
      spinArc(g, q, r, b.omega_in, m.wmax, colours[i], null, "rigid-spin" + (i + 1));
      spinArc(g, q, r + 8, b.omega_fin, m.wmax, colours[i], "5 3", "rigid-spin" + (i + 1) + "-fin");
      // The spins' names beside their arcs (their values are in the table).
      if (b.omega_in !== 0) placeText(labels, placed, { x: r2(q[0] - r - 28), y: r2(q[1] - r), class: "label", fill: colours[i], "paint-order": "stroke", stroke: "#fff", "stroke-width": 4 }, "\u03c9" + sub[i]);
      if (b.omega_fin !== 0) placeText(labels, placed, { x: r2(q[0] - r - 36), y: r2(q[1] + r + 14), class: "label", fill: colours[i], "paint-order": "stroke", stroke: "#fff", "stroke-width": 4 }, "\u03c9" + sub[i] + "\u2032");
      if (b.v_in[0] !== 0 || b.v_in[1] !== 0) placeText(labels, placed, { x: r2(tip(b.v_in)[0] + 6), y: r2(tip(b.v_in)[1] - 6), class: "label", fill: colours[i], "paint-order": "stroke", stroke: "#fff", "stroke-width": 4 }, "v" + sub[i]);
      if (b.v_fin[0] !== 0 || b.v_fin[1] !== 0) placeText(labels, placed, { x: r2(tip(b.v_fin)[0] + 6), y: r2(tip(b.v_fin)[1] + 14), class: "label", fill: colours[i], "paint-order": "stroke", stroke: "#fff", "stroke-width": 4 }, "v" + sub[i] + "\u2032");
    });
    // The handles: v1's tip, and the hit point on a movable target.
    const tip1 = velocityArrow(m, p.bodies[0], p.bodies[0].v_in)[1];
    el(svg, "circle", { id: "rigid-v1-handle", class: "handle", cx: r2(tip1[0]), cy: r2(tip1[1]), r: 11, fill: "transparent", stroke: "var(--body1)", "stroke-opacity": 0.5 });
    if (!immovable(p.bodies[1])) el(svg, "circle", { id: "rigid-hit-handle", class: "handle", cx: r2(c[0]), cy: r2(c[1]), r: 12, fill: "transparent", stroke: "var(--com)", "stroke-width": 3 });
    placeText(labels, placed, { x: 12, y: 450, class: "label", fill: "#111827" }, "contact: " + p.contact);
    svg.appendChild(labels);
  }

  function drawRigidNumbers(p) {
    fillBox("rigid-numbers", (box) => rigidNumbers(box, p));
  }
  function rigidNumbers(box, p) {
    const para = (html) => { const x = document.createElement("p"); x.innerHTML = html; box.appendChild(x); };
    if (!p) { para("The bodies do not approach at the contact: no collision (see the JSON)."); return; }
    const cell = (x) => (x === null || x === undefined ? "immovable" : num(x));
    const pair = (v) => "(" + num(v[0]) + ", " + num(v[1]) + ")";
    const table = (caption, head, rows) => numbersTable(box, caption, head, rows);
    const unit = p.velocity_unit ? " (SI: m/s, rad/s, N s)" : "";
    para('<b id="rigid-contact">contact ' + p.contact + "</b>: " + (contactWords[p.contact] || ""));
    if (p.paradox) para('<span class="error">' + p.paradox + "</span>");
    table("Impulse on body 2" + unit, ["", "value"], [
      ["P", pair(p.impulse)], ["P<sub>n</sub>", num(p.impulse_n)], ["P<sub>t</sub>", num(p.impulse_t)]]);
    const rows = [];
    p.bodies.forEach((b, i) => {
      if (immovable(b)) return;
      const c = '<span class="c-' + (i + 1) + '">';
      rows.push([c + "v<sub>" + (i + 1) + "</sub></span>", pair(b.v_in), pair(b.v_fin)]);
      rows.push([c + "&omega;<sub>" + (i + 1) + "</sub></span>", num(b.omega_in), num(b.omega_fin)]);
    });
    table("Velocities and spins" + unit, ["", "IN", "FIN"], rows);
    table("Along the normal: the contact points", ["", "v<sub>1n</sub>", "v<sub>2n</sub>"], [
      ["m<sub>eff</sub>", cell(p.masses[0]), cell(p.masses[1])],
      ['<span class="c-in">IN</span>', num(p.in[0]), num(p.in[1])],
      ['<span class="c-com">COM</span>', num(p.com), num(p.com)],
      ['<span class="c-fin">FIN</span>', num(p.fin[0]), num(p.fin[1])],
      ["e along n", num(p.e_along)]]);
  }

  // The lecture's velocity plane of the contact points along n, with the effective masses (a
  // wall, a floor or a pivot that holds body 2 along n has none: said instead).
  function drawRigidPlane(p) {
    const svg = $("rigid-normal-svg");
    clear(svg);
    const np = p && p.normal_plane;
    $("rigid-normal-figure").hidden = !np;
    if (!np) return;
    const map = fitVelocityPlane([np], false);
    velocityPlane(svg, np, map, {
      prefix: "r-", axes: ["v\u2081\u2099", "v\u2082\u2099"],
      title: "along n: m_eff = (" + short(p.masses[0]) + ", " + short(p.masses[1]) + "), e along n = " + short(p.e_along),
    });
  }

  // The sliders follow the case: the hit point's range spans the target from its pivot (or
  // centre), the spin's and e's take the typed values.
  function syncRigidSliders(p) {
    const e = valueOf($("r-e").value === "elastic" ? "1" : $("r-e").value);
    if (isFinite(e)) $("r-e-range").value = String(e);
    const w = splitUnit($("r-spin").value)[0];
    if (isFinite(w)) $("r-spin-range").value = String(w);
    const t = p && p.bodies[1];
    const range = $("r-hit_at-range");
    const fixed = t && immovable(t);
    range.disabled = !t || fixed || !core;
    // Said where it is disabled: a floor, wall or ceiling is hit where the ball is.
    const why = fixed ? "hit point (slider off: a " + t.kind + " is hit where the ball meets it; the hit point is along a rod, door or box)" : "hit point along the target (slider)";
    range.setAttribute("aria-label", why);
    range.title = fixed ? "No hit point on a " + t.kind + ": it is hit where the ball meets it" : "";
    if (!t || fixed) return;
    const ref = t.pivot ? t.pivot[1] : t.position[1];
    const h = halfHeight(t);
    range.min = String(t.position[1] - h - ref);
    range.max = String(t.position[1] + h - ref);
    range.step = String((2 * h) / 200 || 0.01);
    range.value = String(p.point[1] - ref);
  }

  // The hit point at the world height `y`: `--hit-at` from the pivot (or the centre), snapped to
  // the step, in the typed unit.
  function moveHit(y, step) {
    const t = rigidAnswer.picture.bodies[1];
    const ref = t.pivot ? t.pivot[1] : t.position[1];
    const unit = splitUnit($("r-hit_at").value)[1];
    $("r-hit_at").value = snapText(y - ref, step) + (unit && unit !== "end" ? " " + unit : (rigidAnswer.picture.velocity_unit ? " m" : ""));
    return solveRigid(true);
  }

  // v1's tip at the velocity `v`, snapped to the step, in the typed unit.
  function moveV1(v, step) {
    const t0 = performance.now();
    const unit = rigidAnswer.picture.velocity_unit;
    $("r-v1").value = "(" + snapText(v[0], step) + "," + snapText(v[1], step) + ")" + (unit ? " " + unit : "");
    const answer = solveRigid(true);
    rigidView.timings.push(performance.now() - t0);
    return answer;
  }

  function rigidPoint(ev) {
    const svg = $("rigid-svg");
    const rect = svg.getBoundingClientRect();
    const vb = svg.viewBox.baseVal;
    return [(ev.clientX - rect.left) * vb.width / rect.width, (ev.clientY - rect.top) * vb.height / rect.height];
  }

  function setupRigidDrag() {
    const svg = $("rigid-svg");
    let pending = null, queued = false;
    const world = (q) => {
      const m = rigidView.map;
      return [(q[0] - m.X(0)) / m.s, (m.Y(0) - q[1]) / m.s];
    };
    const flush = () => {
      queued = false;
      if (!pending || !rigidView.dragging) return;
      const q = rigidPoint(pending);
      pending = null;
      const m = rigidView.map, p = rigidAnswer.picture;
      if (rigidView.dragging === "v1") {
        moveV1(arrowVelocity(m, p.bodies[0], q), snapStep({ s: m.k }));
      } else {
        moveHit(world(q)[1], snapStep({ s: m.s }));
      }
    };
    holdHandles(svg);
    svg.addEventListener("pointerdown", (ev) => {
      if (!core || ev.button !== 0 || !rigidAnswer.picture) return;
      if (ev.pointerType === "touch" && !ev.target.classList.contains("handle")) return;
      const q = rigidPoint(ev);
      const m = rigidView.map, p = rigidAnswer.picture, b = p.bodies[0];
      const tip = velocityArrow(m, b, b.v_in)[1];
      const hit = [m.X(p.point[0]), m.Y(p.point[1])];
      const dTip = Math.hypot(tip[0] - q[0], tip[1] - q[1]);
      const dHit = immovable(p.bodies[1]) ? Infinity : Math.hypot(hit[0] - q[0], hit[1] - q[1]);
      svg.focus({ preventScroll: true });
      if (Math.min(dTip, dHit) > 30) return;
      rigidView.dragging = dTip <= dHit ? "v1" : "hit";
      svg.setPointerCapture(ev.pointerId);
      svg.classList.add("dragging");
      ev.preventDefault();
    });
    svg.addEventListener("pointermove", (ev) => {
      if (!rigidView.dragging) return;
      pending = ev;
      if (!queued) { queued = true; requestAnimationFrame(flush); }
    });
    const end = (ev) => {
      if (!rigidView.dragging) return;
      if (ev.type === "pointerup") pending = ev;
      try {
        flush();
      } finally {
        rigidView.dragging = null;
        svg.classList.remove("dragging");
      }
      // Fitted again once the drag ends; the result said once.
      rigidView.keep = false;
      if (rigidAnswer.picture) renderRigid();
      say("rigid-said", rigidSentence());
    };
    svg.addEventListener("pointerup", end);
    svg.addEventListener("pointercancel", end);
    svg.addEventListener("keydown", (ev) => {
      const d = { ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowDown: [0, -1], ArrowUp: [0, 1] }[ev.key];
      if (!core || !d || !rigidAnswer.picture) return;
      ev.preventDefault();
      const step = snapStep({ s: rigidView.map.k }) * (ev.shiftKey ? 10 : 1);
      const v = rigidAnswer.picture.bodies[0].v_in;
      moveV1([v[0] + d[0] * step, v[1] + d[1] * step], step);
    });
  }

  function fillRigid(values) {
    for (const f of rigidFields) $("r-" + f).value = values[f] || "";
  }

  function setupRigid() {
    fillRigid(data.setup.rigid);
    const typed = () => { $("r-preset").value = ""; solveRigid(false); };
    for (const f of rigidFields) $("r-" + f).addEventListener("input", typed);
    const slide = (f) => { rigidView.sliding = true; try { f(); } finally { rigidView.sliding = false; } };
    $("r-e-range").addEventListener("input", () => slide(() => { $("r-e").value = String(Number($("r-e-range").value)); solveRigid(true); }));
    $("r-spin-range").addEventListener("input", () => slide(() => { $("r-spin").value = String(Number($("r-spin-range").value)); solveRigid(true); }));
    $("r-hit_at-range").addEventListener("input", () => slide(() => {
      const unit = splitUnit($("r-hit_at").value)[1];
      $("r-hit_at").value = String(Number(Number($("r-hit_at-range").value).toPrecision(3))) + (unit && unit !== "end" ? " " + unit : (rigidAnswer.picture && rigidAnswer.picture.velocity_unit ? " m" : ""));
      solveRigid(true);
    }));
    // A slider let go: fitted again and drawn whole.
    for (const id of ["r-e-range", "r-spin-range", "r-hit_at-range"]) $(id).addEventListener("change", () => { rigidView.keep = false; if (rigidAnswer.picture) renderRigid(); });
    $("r-preset").addEventListener("change", () => {
      const p = rigidPresets[$("r-preset").value];
      if (!p) return;
      fillRigid(p);
      solveRigid(false);
    });
    setupRigidDrag();
  }
