  // ---------------------------------------------------------------- bars and what is said
  // PhET's momentum and energy bars: each body's value before and after, and their sum, as the
  // core answered them (the picture's `momentum` and `kinetic`, the plane's `ke_in` and
  // `ke_fin`, the report's energies): the page neither adds nor multiplies them.

  // Bars in `svg`: `groups` = [{title, id, rows: [{name, value, colour}]}], each group scaled to
  // its largest |value| (a zero line in the middle when a value is negative); each bar carries
  // its value in `data-value`, and its number beside it. A value the core could not give in
  // binary64 (null) is named, not drawn. The picture's height follows its rows.
  function drawBars(svg, groups) {
    clear(svg);
    const k = kOf(svg);
    const W = svg.viewBox.baseVal.width;
    const rowH = Math.max(18, 16 * k), nameW = 64 * k, valueW = 74 * k;
    const x0 = 8 + nameW, x1 = W - valueW - 8;
    let y = 0;
    for (const g of groups) {
      y += 22 * Math.max(1, k);
      el(svg, "text", { x: 6, y: r2(y - 6), class: "title" }, g.title);
      const shown = g.rows.map((r) => typeof r.value === "number" && isFinite(r.value));
      const big = g.rows.reduce((m, r, i) => (shown[i] ? Math.max(m, Math.abs(r.value)) : m), 0);
      const signed = g.rows.some((r, i) => shown[i] && r.value < 0);
      const zero = signed ? (x0 + x1) / 2 : x0;
      const reach = signed ? (x1 - x0) / 2 : x1 - x0;
      const top = y;
      const group = el(svg, "g", { id: g.id, "data-zero": r2(zero), "data-reach": r2(reach) });
      g.rows.forEach((r, i) => {
        const base = y + rowH / 2 + 4 * k;
        el(group, "text", { x: 6, y: r2(base), class: "tick" }, r.name);
        // |value| <= big: the ratio neither overflows nor loses the sign.
        const len = shown[i] && big > 0 ? (r.value / big) * reach : 0;
        el(group, "rect", { class: "bar", x: r2(Math.min(zero, zero + len)), y: r2(y + 3), width: r2(Math.abs(len)),
          height: r2(rowH - 6), fill: r.colour, "data-value": shown[i] ? String(r.value) : "" });
        el(group, "text", { x: r2(x1 + 5), y: r2(base), class: "tick" }, shown[i] ? short(r.value) : "beyond binary64");
        y += rowH;
      });
      el(svg, "line", { x1: r2(zero), x2: r2(zero), y1: r2(top), y2: r2(y), stroke: "#6b7280", "stroke-width": 1.2 });
    }
    svg.setAttribute("viewBox", "0 0 " + W + " " + Math.ceil(y + 8));
  }

  const sub = (i) => (i === 0 ? "\u2081" : "\u2082");

  // The rail's bars: each body's momentum P = M V and its kinetic energy before and after,
  // and the totals (the momentum line's P, the IN and FIN ellipses' energies).
  function drawRailBars(p) {
    const body = ["var(--body1)", "var(--body2)"];
    const rows = (name, values, total, totalName) => [0, 1]
      .map((i) => ({ name: name + sub(i), value: values[i], colour: body[i] }))
      .concat([{ name: totalName, value: total, colour: "var(--com)" }]);
    const m = p.momentum;
    const ke = p.kinetic;
    const energy = (phase, which) => (ke ? rows("KE", ke[phase], p.ellipses[phase].ke, "sum")
      : [{ name: "sum", value: p.ellipses[phase].ke, colour: "var(--com)" }])
      .map((r) => Object.assign(r, { name: r.name + " " + which }));
    drawBars($("bars-svg"), [
      { title: "Momentum P = M V: before, after", id: "bars-momentum",
        rows: rows("P", m.in, m.total, "sum").map((r) => Object.assign(r, { name: r.name + " IN" }))
          .concat(rows("P", m.fin, m.total, "sum").map((r) => Object.assign(r, { name: r.name + " FIN" }))) },
      { title: "Kinetic energy" + (ke ? "" : " (a tensor's is not split)"), id: "bars-energy",
        rows: energy("in", "IN").concat(energy("fin", "FIN")) },
    ]);
  }

  // The plane's bars: each puck's kinetic energy before and after, and the report's totals
  // (the momenta are the arrows of the momentum triangles).
  function drawPlaneBars(p, s) {
    const body = ["var(--body1)", "var(--body2)"];
    const phase = (values, total, which) => [0, 1]
      .map((i) => ({ name: "KE" + sub(i) + " " + which, value: values[i], colour: body[i] }))
      .concat([{ name: "sum " + which, value: total, colour: "var(--com)" }]);
    const after = p.ke_fin && s.energy && s.energy.fin !== undefined ? phase(p.ke_fin, s.energy.fin, "FIN") : [];
    const total = s.energy ? s.energy.in : null;
    drawBars($("plane-bars-svg"), [
      { title: "Kinetic energy: before, after" + (after.length ? "" : " (no collision)"), id: "plane-bars-energy",
        rows: phase(p.ke_in, total, "IN").concat(after) },
    ]);
  }

  // The live regions: one short sentence of the result, said once a drag or the typing has
  // ended (`sayLater`), not the tables at every step. `say(id, text)` says it now.
  const sayTimers = {};
  function say(id, text) {
    clearTimeout(sayTimers[id]);
    if ($(id).textContent !== text) $(id).textContent = text;
  }
  function sayLater(id, sentence) {
    clearTimeout(sayTimers[id]);
    sayTimers[id] = setTimeout(() => say(id, sentence()), 700);
  }
  const pairText = (v) => "(" + short(v[0]) + ", " + short(v[1]) + ")";
  // Nothing is said of the last valid case while an error stands (the error is said instead).
  function caseSentence() {
    const s = caseState;
    if (!s || !$("case-error").hidden) return "";
    const e = s.energy;
    return "IN " + pairText(s.in) + " gives FIN " + pairText(s.fin) + "; kinetic energy " + short(e.in) +
      " before, " + short(e.fin) + " after" + (e.lost ? " (" + short(e.lost) + " lost)." : ".");
  }
  function planeSentence() {
    const s = planeState, p = planeAnswer.picture;
    if (!s || !$("plane-error").hidden) return "";
    if (!p.fin) return "v\u2081 " + pairText(p.in[0]) + " and v\u2082 " + pairText(p.in[1]) + ": the pucks do not collide.";
    return "v\u2081 " + pairText(p.in[0]) + " and v\u2082 " + pairText(p.in[1]) + " give v\u2081\u2032 " + pairText(p.fin[0]) +
      " and v\u2082\u2032 " + pairText(p.fin[1]) + (s.energy ? "; kinetic energy " + short(s.energy.in) + " before, " + short(s.energy.fin) + " after." : ".");
  }
  // The rigid result: the ball's velocity before and after, the target's (or its spin), the
  // contact and the normal impulse.
  function rigidSentence() {
    const p = rigidAnswer.picture;
    if (!$("rigid-error").hidden) return "";
    if (!p) return "The bodies do not approach at the contact: no collision.";
    const [ball, target] = p.bodies;
    const moves = target.kind !== "floor" && target.kind !== "wall" && target.kind !== "ceiling";
    return "v\u2081 " + pairText(ball.v_in) + " gives v\u2081\u2032 " + pairText(ball.v_fin) +
      (moves ? ", the target " + pairText(target.v_fin) + " spinning at " + short(target.omega_fin) : ", spin " + short(ball.omega_fin)) +
      "; contact " + p.contact + ", normal impulse " + short(p.impulse_n) + ".";
  }
