  // ---------------------------------------------------------------- up to five pucks
  // The inputs (ids "nb-" + list letter + puck: nb-m3, nb-v1, nb-f2 (v' to explode), nb-x4 and
  // nb-r4 (a touching ball's centre and radius)), the mode, e, and what the core answers
  // (src/view/nbody.rs): `collide solve`'s JSON and command, and each puck's velocity and
  // momentum before and after from the solved outcome. The pucks move along their paths as the
  // time runs from -1 to 1 (the impact at 0): the page only draws them there.
  const nbLists = ["m", "v", "f", "x", "r"];
  const nbColours = ["var(--body1)", "var(--body2)", "#7c3aed", "#b45309", "#0f766e"];
  const nbTints = ["#dbeafe", "#fee2e2", "#ede9fe", "#fef3c7", "#ccfbf1"];
  const nbPresets = {
    // physics.md section 8: the published -0.76 and 2.63 m/s (scenarios/contacts-cue-two-balls.toml).
    cue2: { mode: "contacts", e: "elastic", m: ["1", "1", "1"], v: ["(3.8,0)", "0", "0"], x: ["(0,0)", "(1.732,1)", "(1.732,-1)"], r: ["1", "1", "1"] },
    // The first two rows of scenarios/contacts-rack.toml and its cue ball.
    rack3: { mode: "contacts", e: "elastic", m: ["1", "1", "1", "1"], v: ["(2,0)", "0", "0", "0"], x: ["(0,0)", "(2,0)", "(3.7320508,-1)", "(3.7320508,1)"], r: ["1", "1", "1", "1"] },
    cradle: { mode: "contacts", e: "elastic", m: ["1", "1", "1", "1", "1"], v: ["(1,0)", "0", "0", "0", "0"], x: ["(0,0)", "(2,0)", "(4,0)", "(6,0)", "(8,0)"], r: ["1", "1", "1", "1", "1"] },
    stick3: { mode: "stick", m: ["1", "2", "3"], v: ["(1,0)", "(0,1)", "(-1,-1)"] },
    // docs/plane.md's three-piece explosion.
    explode3: { mode: "explode", m: ["1 kg", "2 kg", "3 kg"], v: ["0", "0", "0"], f: ["(2,0) m/s", "(0,1) m/s", "?"] },
  };
  let nbAnswer = data.answers.nbody; // the last good answer
  let nbState = JSON.parse(nbAnswer.state);
  const nb = { t: -1, map: null, mode: data.setup.nbody.mode };
  view.nbody = nb;
  view.nbodyPicture = () => nbAnswer.picture;

  const nbCount = () => Number($("nb-count").value);
  function nbMode() {
    const checked = document.querySelector('input[name="nb-mode"]:checked');
    return checked ? checked.value : "stick";
  }

  function nbRequest() {
    const n = nbCount(), mode = nbMode();
    const list = (k) => Array.from({ length: n }, (_, i) => $("nb-" + k + (i + 1)).value);
    const r = { op: "nbody", mode, masses: list("m"), velocities: list("v") };
    if (mode === "explode") r.fin = list("f");
    if (mode === "contacts") { r.positions = list("x"); r.radii = list("r"); r.e = $("nb-e").value; }
    return r;
  }

  // Shows the rows of the count and the columns of the mode.
  function showNbFields() {
    const n = nbCount();
    for (let i = 1; i <= 5; i++) $("nb-row" + i).hidden = i > n;
    $("nball-form").dataset.mode = nbMode();
  }

  function solveNb() {
    if (!core) return null;
    showNbFields();
    const answer = core(nbRequest());
    const ids = { mode: "nb-count", count: "nb-count", e: "nb-e" };
    for (const k of nbLists) for (let i = 1; i <= 5; i++) ids[k + i] = "nb-" + k + i;
    showError(answer, ids, "nb-m1", "nball-error", ["nball-state", "nball-command", "nball-said"],
      ["nball-svg", "nball-numbers", "nball-momentum-svg"]);
    $("nball-play").disabled = !answer.ok;
    if (!answer.ok) { clearTimeout(sayTimers["nball-said"]); return answer; }
    nbAnswer = answer;
    nb.mode = nbMode();
    nb.map = null;
    renderNb();
    sayLater("nball-said", nbSentence);
    return answer;
  }

  function renderNb() {
    nbState = JSON.parse(nbAnswer.state);
    drawNbPucks(nbAnswer.picture);
    drawNbMomentum(nbAnswer.picture);
    drawNbNumbers(nbAnswer.picture);
    $("nball-state").textContent = nbAnswer.state;
    $("nball-command").textContent = nbAnswer.command;
  }

  // One sentence of the result for the live region (not the tables).
  function nbSentence() {
    const s = nbState;
    if (!s || !$("nball-error").hidden) return "";
    const e = s.energy;
    return s.fin.length + " pucks leave at " + s.fin.map(pairText).join(", ") + "; kinetic energy " + short(e.in) +
      " before, " + short(e.fin) + " after.";
  }

  // The picture's map: where each puck is at the impact (touching balls at their centres; points
  // all at one place), the time scale `tau` (a puck moves tau v in a unit of time: the fastest
  // two and a half radii, or a unit), the world box of every path, the velocity arrows' scale.
  function fitNb(p) {
    const W = 560, H = 460, top = 30, margin = 24;
    const n = p.masses.length;
    const centres = p.positions || p.masses.map(() => [0, 0]);
    const speeds = p.in.concat(p.fin).map((v) => Math.hypot(v[0], v[1])).filter((x) => isFinite(x) && x > 0);
    const fastest = speeds.length ? Math.max(...speeds) : 1;
    const rmax = p.radii ? Math.max(...p.radii) : 1;
    const tau = (p.radii ? 2.5 * rmax : 1) / fastest;
    let x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity;
    const add = (q, r) => {
      if (!isFinite(q[0]) || !isFinite(q[1])) return;
      x0 = Math.min(x0, q[0] - r); x1 = Math.max(x1, q[0] + r);
      y0 = Math.min(y0, q[1] - r); y1 = Math.max(y1, q[1] + r);
    };
    for (let i = 0; i < n; i++) {
      const c = centres[i], r = p.radii ? p.radii[i] : 0;
      add(c, r);
      add([c[0] - tau * p.in[i][0], c[1] - tau * p.in[i][1]], r);
      add([c[0] + tau * p.fin[i][0], c[1] + tau * p.fin[i][1]], r);
    }
    // By halves, as elsewhere: no span overflows.
    let half = Math.max(x1 / 2 - x0 / 2, y1 / 2 - y0 / 2);
    half = half > 0 && isFinite(half) ? half : 1;
    const cx = x0 / 2 + x1 / 2, cy = y0 / 2 + y1 / 2;
    const s = Math.min((W - 2 * margin) / 2, (H - top - 2 * margin) / 2) / half;
    const X = (x) => W / 2 + s * (x - cx);
    const Y = (y) => top + (H - top) / 2 - s * (y - cy);
    // Points drawn as disks of a size by mass (their area), touching balls to scale.
    const mmax = Math.max(...p.masses);
    const radius = (i) => p.radii ? Math.max(3, s * p.radii[i]) : 5 + 9 * Math.sqrt(p.masses[i] / mmax);
    return { W, H, centres, tau, X, Y, s, radius, k: 90 / fastest };
  }

  // Where puck i is at time t: along v before the impact, along v' after.
  function nbAt(p, m, i, t) {
    const v = t < 0 ? p.in[i] : p.fin[i];
    return [m.centres[i][0] + m.tau * t * v[0], m.centres[i][1] + m.tau * t * v[1]];
  }

  function drawNbPucks(p) {
    const svg = $("nball-svg");
    if (!nb.map) nb.map = fitNb(p);
    const m = nb.map, n = p.masses.length, t = nb.t;
    clear(svg);
    svg.setAttribute("data-map", JSON.stringify({ tau: m.tau, s: m.s, k: m.k, t }));
    const unit = p.velocity_unit ? " " + p.velocity_unit : "";
    el(svg, "text", { x: 12, y: 20, class: "title" }, n + " pucks " + { stick: "stick", explode: "explode", contacts: "touching" }[nb.mode] +
      ", t = " + fmt(t, 3) + (t < 0 ? " (before)" : t > 0 ? " (after)" : " (impact)"));
    const S = (q) => [m.X(q[0]), m.Y(q[1])];
    const paths = el(svg, "g", { fill: "none", "stroke-width": 1.3, "stroke-dasharray": "2 4" });
    for (let i = 0; i < n; i++) {
      const a = S(nbAt(p, m, i, -1)), c = S(m.centres[i]), b = S(nbAt(p, m, i, 1));
      el(paths, "polyline", { points: pts([a, c, b]), stroke: nbColours[i] });
      // The impact: each puck's outline where it is at t = 0.
      el(svg, "circle", { cx: r2(c[0]), cy: r2(c[1]), r: r2(m.radius(i)), fill: "none", stroke: nbColours[i], "stroke-opacity": 0.45, "stroke-dasharray": "3 3" });
    }
    for (let i = 0; i < n; i++) {
      const c = S(nbAt(p, m, i, t));
      el(svg, "circle", { id: "nb-puck-" + (i + 1), cx: r2(c[0]), cy: r2(c[1]), r: r2(m.radius(i)), fill: nbTints[i], "fill-opacity": 0.9, stroke: nbColours[i], "stroke-width": 2.2 });
      el(svg, "text", { x: r2(c[0]), y: r2(c[1] + 4 * kOf(svg)), "text-anchor": "middle", class: "tick", fill: "#111827" }, String(i + 1));
    }
    for (let i = 0; i < n; i++) {
      const v = t < 0 ? p.in[i] : p.fin[i];
      const c = S(nbAt(p, m, i, t));
      // An arrow whose tip would be inside its disk (a slow puck: the cue ball after the break)
      // starts at the disk's edge instead, its length (the velocity, in the one scale) the same.
      const d = [m.k * v[0], -m.k * v[1]], len = Math.hypot(d[0], d[1]), r = m.radius(i);
      const from = len > 0 && len < r ? [c[0] + d[0] / len * r, c[1] + d[1] / len * r] : c;
      arrow(svg, from, [from[0] + d[0], from[1] + d[1]], nbColours[i], t < 0 ? { id: "nb-in-" + (i + 1), width: 2.6 } : { id: "nb-fin-" + (i + 1), dash: "7 4", width: 2.4 });
    }
    el(svg, "text", { x: 12, y: m.H - 10, class: "tick" }, "v" + unit + ": solid before, dashed after");
  }

  // The momenta tip to tail, before (solid) and after (dashed), both ending at P.
  function drawNbMomentum(p) {
    const svg = $("nball-momentum-svg");
    clear(svg);
    if (!p.momenta) {
      el(svg, "text", { x: 20, y: 40, class: "label" }, "A momentum is beyond binary64: not drawn (see the JSON).");
      return;
    }
    p = p.momenta;
    const chain = (ps) => ps.reduce((acc, q) => { const last = acc[acc.length - 1]; acc.push([last[0] + q[0], last[1] + q[1]]); return acc; }, [[0, 0]]);
    const before = chain(p.p_in), after = chain(p.p_fin);
    let x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity;
    for (const q of before.concat(after, [p.p_total])) {
      if (!isFinite(q[0]) || !isFinite(q[1])) continue;
      x0 = Math.min(x0, q[0]); x1 = Math.max(x1, q[0]); y0 = Math.min(y0, q[1]); y1 = Math.max(y1, q[1]);
    }
    let span = Math.max(x1 / 2 - x0 / 2, y1 / 2 - y0 / 2) * 2.4;
    span = span > 0 && isFinite(span) ? span : 2;
    const cx = x0 / 2 + x1 / 2, cy = y0 / 2 + y1 / 2;
    const ax = frameAxes(svg, { x: 58, y: 30, w: 380, h: 380 }, { x0: cx - span / 2, x1: cx + span / 2, y0: cy - span / 2, y1: cy + span / 2 }, ["px", "py"]);
    const S = (q) => [ax.X(q[0]), ax.Y(q[1])];
    el(svg, "text", { x: 58, y: 20, class: "title" }, "momenta: P = (" + short(p.p_total[0]) + ", " + short(p.p_total[1]) + ") before and after");
    for (let i = 0; i < p.p_in.length; i++) {
      arrow(svg, S(before[i]), S(before[i + 1]), nbColours[i], { id: "nb-p-in-" + (i + 1), width: 2.4 });
      arrow(svg, S(after[i]), S(after[i + 1]), nbColours[i], { id: "nb-p-fin-" + (i + 1), dash: "7 4", width: 2.2 });
    }
    // P on top, thin, where both chains end.
    arrow(svg, S([0, 0]), S(p.p_total), "var(--com)", { id: "nb-momentum-total", width: 1.6 });
    // P's name beside its tip, moved down a line while it would cover an axis's name (px).
    const end = S(p.p_total);
    placeText(svg, boxesOf(svg), { x: r2(end[0] + 8), y: r2(end[1] - 8), class: "label", fill: "var(--com)", "paint-order": "stroke", stroke: "#fff", "stroke-width": 4 }, "P");
  }

  function drawNbNumbers(p) {
    fillBox("nball-numbers", (box) => nbNumbers(box, p));
  }
  function nbNumbers(box, p) {
    const s = nbState;
    const cell = (x) => (typeof x === "number" ? num(x) : String(x));
    const pair = (v) => "(" + cell(v[0]) + ", " + cell(v[1]) + ")";
    const unit = s.units ? " (" + s.units.velocity + ")" : "";
    const name = (i) => '<span class="c-n' + (i + 1) + '">' + (i + 1) + "</span>";
    numbersTable(box, "Velocities" + unit, ["puck", "IN", "FIN", "|FIN| @ angle"], s.in.map((v, i) => [name(i), pair(v), pair(s.fin[i]),
      s.fin_speed[i] === 0 ? "0" : cell(s.fin_speed[i]) + (s.fin_angle_deg[i] === null ? "" : " @ " + cell(s.fin_angle_deg[i]) + "\u00b0")]));
    if (s.contacts) {
      numbersTable(box, "Contacts (impulse along n from a to b)", ["a-b", "n at", "impulse"],
        s.contacts.map((c) => [c.pair.join("-"), cell(c.normal_angle_deg) + "\u00b0", cell(c.impulse)]));
    }
    const en = s.energy;
    const rows = [["KE<sub>IN</sub>", cell(en.in)], ["KE<sub>FIN</sub>", cell(en.fin)]];
    if (en.lost !== undefined) rows.push(["lost", cell(en.lost)]);
    if (en.released !== undefined) rows.push(["released", cell(en.released)]);
    numbersTable(box, "Energy" + (s.units ? " (" + s.units.energy + ")" : ""), ["", ""], rows);
    const para = document.createElement("p");
    para.innerHTML = '<span class="c-com">V<sub>COM</sub></span> = <span class="num">' + pair(s.v_com) + "</span>";
    box.appendChild(para);
  }

  function fillNb(c) {
    $("nb-count").value = String(c.m.length);
    for (const r of document.querySelectorAll('input[name="nb-mode"]')) r.checked = r.value === c.mode;
    $("nb-e").value = c.e || "elastic";
    for (let i = 0; i < 5; i++) {
      for (const k of nbLists) {
        const given = c[k] && c[k][i];
        // Keep a value to come back to in another mode or count.
        if (given !== undefined) $("nb-" + k + (i + 1)).value = given;
        else if (!$("nb-" + k + (i + 1)).value) $("nb-" + k + (i + 1)).value = { m: "1", v: "0", f: "?", x: "(" + 2 * i + ",0)", r: "1" }[k];
      }
    }
    showNbFields();
  }

  function setNbTime(t) {
    nb.t = Math.max(-1, Math.min(1, t));
    $("nball-time").value = String(nb.t);
    drawNbPucks(nbAnswer.picture);
  }

  // The table's five rows: a puck's mass, velocity, v' (explode), centre and radius (contacts),
  // each input named for a screen reader.
  function nbRows() {
    const what = { m: "the mass of puck #", v: "the velocity of puck # before", f: "the velocity of puck # after (? for the one momentum gives)",
      x: "the centre of ball #", r: "the radius of ball #" };
    const column = { f: "nb-explode", x: "nb-contacts", r: "nb-contacts" };
    for (let i = 1; i <= 5; i++) {
      const tr = $("nb-rows").insertRow();
      tr.id = "nb-row" + i;
      const th = document.createElement("th");
      th.scope = "row"; th.className = "c-n" + i; th.textContent = String(i);
      tr.appendChild(th);
      for (const k of nbLists) {
        const td = tr.insertCell();
        if (column[k]) td.className = column[k];
        const input = document.createElement("input");
        Object.assign(input, { id: "nb-" + k + i, type: "text", spellcheck: false });
        input.setAttribute("aria-label", (k === "f" ? "v" + i + "\u2032" : (k === "r" ? "R" : k) + i) + ", " + what[k].replace("#", i));
        td.appendChild(input);
      }
    }
  }

  function setupNb() {
    nbRows();
    const c = data.setup.nbody;
    fillNb({ mode: c.mode, e: c.e, m: c.masses, v: c.velocities, f: c.fin, x: c.positions, r: c.radii });
    const typed = () => { $("nb-preset").value = ""; solveNb(); };
    for (const k of nbLists) for (let i = 1; i <= 5; i++) $("nb-" + k + i).addEventListener("input", typed);
    $("nb-e").addEventListener("input", typed);
    $("nb-count").addEventListener("change", typed);
    for (const r of document.querySelectorAll('input[name="nb-mode"]')) r.addEventListener("change", typed);
    $("nb-preset").addEventListener("change", () => {
      const p = nbPresets[$("nb-preset").value];
      if (!p) return;
      fillNb(p);
      solveNb();
      setNbTime(-1);
    });
    $("nball-time").addEventListener("input", () => setNbTime(Number($("nball-time").value)));
    animation("nball", { start: -1, rate: 0.5, end: () => 1, step: () => 0.1, get: () => nb.t, set: setNbTime });
  }
