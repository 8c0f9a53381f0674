  // ---------------------------------------------------------------- the two-body case
  const caseFields = ["m1", "m2", "v1", "v2", "e"];
  let caseAnswer = data.answers.solve; // the last good answer
  let caseState = null; // its JSON, parsed
  const plane = { map: null, keep: false, dragging: null, dragW: null, animation: 0 };

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
    // An input during a frame's animation wins: the animation would end on the case it began
    // with (its numbers, not these).
    cancelAnimationFrame(plane.animation);
    const answer = core(caseRequest());
    showCaseError(answer);
    if (!answer.ok) return answer;
    caseAnswer = answer;
    plane.keep = !!keepMap;
    renderCase();
    return answer;
  }

  function showCaseError(answer) {
    const ids = {};
    for (const f of caseFields.concat(["inertia", "reverse"])) ids[f] = f;
    showError(answer, ids, "m1", "case-error", ["state", "command", "scene", "case-said"],
      ["plane-svg", "case-numbers", "rail-svg", "newton-svg", "minkowski-svg", "space-svg", "bars-svg"]);
    if (!answer.ok) clearTimeout(sayTimers["case-said"]);
  }


  function renderCase() {
    caseState = JSON.parse(caseAnswer.state);
    const p = caseAnswer.picture;
    // (The plane is off screen while a car is dragged on the rail below it, and drawn after the
    // frame when it is not; the tables are drawn after the frame during any drag.)
    drawSeen($("plane-svg"), () => drawPlane(p), plane.dragging, dual.dragging >= 0);
    drawSeen($("case-numbers"), () => drawNumbers(p), plane.dragging, true);
    drawDual(p);
    $("state").textContent = caseAnswer.state;
    $("command").textContent = caseAnswer.command;
    $("scene").textContent = caseAnswer.scene;
    // Said once the drag or the typing ends (a drag's end says it at once).
    if (!plane.dragging) sayLater("case-said", caseSentence);
  }

  // The data box the plane shows: square, around the origin and everything drawn.
  function fitPlane(pictures) {
    return fitVelocityPlane(pictures, $("zoom").checked, (p, add) => {
      if (p.reverse) [p.reverse.in, p.reverse.fin].forEach(add);
      if ($("overlay").checked) for (const f of p.frames) [f.in, f.com, f.fin].forEach(add);
    });
  }

  function frameWords(name) {
    const f = caseAnswer.picture.frames.find((x) => x.name === name);
    return f ? f.label : "observer at " + name;
  }

  function drawPlane(p, frameLabel) {
    const svg = $("plane-svg");
    if (!plane.keep || !plane.map) plane.map = fitPlane([p]);
    const map = plane.map;
    svg.setAttribute("data-origin-x", map.ox);
    svg.setAttribute("data-origin-y", map.oy);
    svg.setAttribute("data-scale", map.s);
    svg.setAttribute("data-step", snapStep(map));
    svg.setAttribute("data-w", p.w);
    const m = p.inertia;
    const tensor = m[0][1] === 0 && m[1][0] === 0
      ? "diag(" + short(m[0][0]) + ", " + short(m[1][1]) + ")"
      : "[[" + m.map((r) => r.map(short).join(", ")).join("], [") + "]]";
    const title = "M = " + tensor + ",  e = " + (frameLabel ? short(p.e) : $("e").value.trim()) + ",  " + (frameLabel || frameWords(currentFrame())) + " frame";
    velocityPlane(svg, p, map, { title, keep: plane.keep, under: (g, X, Y) => {
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
    }, more: (point) => {
      if (p.reverse) {
        point(p.reverse.in, "var(--rev)", "IN\u2032", "point-rev-in", 0.1);
        point(p.reverse.fin, "var(--rev)", "FIN\u2032", "point-rev-fin", 0.1);
      }
    } });
    // Where a finger grabs IN (22 px around it, `touch-action: none`); elsewhere a finger
    // scrolls the page, and only a mouse or pen moves IN to where it presses.
    el(svg, "circle", { id: "in-handle", class: "handle", cx: r2(map.ox + map.s * p.in[0]), cy: r2(map.oy - map.s * p.in[1]), r: r2(22 * kOf(svg)), fill: "transparent" });
  }

  function drawNumbers(p) {
    fillBox("case-numbers", (box) => caseNumbers(box, p));
  }
  function caseNumbers(box, p) {
    const s = caseState;
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
        // The case as the fields are now (an input may have changed them during the shift).
        const now = core(caseRequest(name));
        showCaseError(now);
        if (now.ok) { caseAnswer = now; renderCase(); }
        return;
      }
      const s = u < 0.5 ? 2 * u * u : 1 - 2 * (1 - u) * (1 - u);
      const w = w0 + (w1 - w0) * s;
      const mid = core(caseRequest(String(w)));
      showCaseError(mid);
      if (mid.ok) {
        drawPlane(mid.picture, "observer at " + short(w));
        drawDual(mid.picture);
      }
      plane.animation = requestAnimationFrame(step);
    };
    plane.animation = requestAnimationFrame(step);
  }

  // The lab velocities (V1, V2) the frame on screen shows at the point (x, y), the frame's
  // velocity w kept. The lab and an observer do not move with the case: V = (x, y) + w. The
  // other frames do (COM, a body at rest before or after): there the case on screen depends
  // only on the relative velocity d = V1 - V2, the same in every frame, as IN = d c, where the
  // core gives c as IN for V = (1, 0) (COM: c = (M2, -M1) / M for masses M1, M2). The pointer
  // is taken along the 45-degree line (a change of frame) to that line: d = x - y, V = d c + w;
  // on the line, IN lands under the pointer. A drag keeps the w it began with (the typed values
  // snap to the step, and w would drift a little at every move).
  function labIn(x, y) {
    const f = currentFrame();
    const w = plane.dragging && plane.dragW !== null ? plane.dragW : caseAnswer.picture.w;
    if (f === "lab" || Number.isFinite(Number(f))) return [x + w, y + w];
    const unit = core(Object.assign(caseRequest(), { v1: "1", v2: "0", reverse: false }));
    if (!unit.ok) return [x + w, y + w];
    const c = unit.picture.in, d = x - y;
    return [c[0] * d + w, c[1] * d + w];
  }

  // Moves IN to a point of the plane (in the frame on screen), snapped to the step. `only` (0 or
  // 1, a car dragged on the rail) rewrites that body's velocity alone where the other's lab
  // velocity cannot change (the lab, an observer): its typed text stays as it was.
  function moveIn(x, y, only) {
    const t0 = performance.now();
    const map = plane.map;
    const step = snapStep(map);
    const v = labIn(x, y);
    // In the unit typed (`72 km/h` stays km/h: the core's velocities are in it).
    const unit = splitUnit($("v1").value)[1] || splitUnit($("v2").value)[1];
    const typed = (x) => snapText(x, step) + (unit ? " " + unit : "");
    const f = currentFrame();
    const one = (only === 0 || only === 1) && (f === "lab" || Number.isFinite(Number(f)));
    if (!one || only === 0) $("v1").value = typed(v[0]);
    if (!one || only === 1) $("v2").value = typed(v[1]);
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
    holdHandles(svg);
    svg.addEventListener("pointerdown", (ev) => {
      if (!core || ev.button !== 0) return;
      if (ev.pointerType === "touch" && ev.target.id !== "in-handle") return;
      cancelAnimationFrame(plane.animation);
      plane.dragging = true;
      plane.dragW = caseAnswer.picture.w;
      svg.setPointerCapture(ev.pointerId);
      svg.classList.add("dragging");
      svg.focus({ preventScroll: true });
      pending = ev;
      // A mouse moves IN to where it presses at once. A finger moves it from its first move:
      // the redraw would take its handle away before the browser sends the touch's start
      // (after this event), which then could not hold the page still.
      if (ev.pointerType !== "touch") flush();
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
      drawDual(caseAnswer.picture);
      drawWaiting();
      say("case-said", caseSentence());
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
        $(f).value = sliderToMass($(f + "-range"), $(f).value);
        solveCase(false);
      });
    }
    $("e-range").addEventListener("input", () => { $("e").value = String(Number($("e-range").value)); solveCase(false); });
    $("reverse").addEventListener("change", () => solveCase(false));
    $("overlay").addEventListener("change", () => solveCase(false));
    $("zoom").addEventListener("change", () => solveCase(false));
  }
  function syncSliders() {
    const tensor = $("inertia").value.trim() !== "";
    for (const f of ["m1", "m2"]) $(f).closest(".field").classList.toggle("unused", tensor);
    for (const f of ["m1", "m2"]) massToSlider($(f + "-range"), $(f).value);
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
  const dual = { t: -1, picture: null, dragging: -1, reach: 0, rail: null };

  function drawDual(p) {
    dual.picture = p;
    const v = p.in, f = p.fin;
    // A car dragged on the rail keeps the scale it was grabbed at; a drag of IN keeps it while
    // the world lines fit (and widens it by a quarter more when they do not), so that the
    // diagrams' frames stay; the drag's end fits it again.
    const need = Math.max(Math.abs(v[0]), Math.abs(v[1]), Math.abs(f[0]), Math.abs(f[1])) * 1.1 || 1;
    const reach = dual.dragging >= 0 && dual.reach ? dual.reach
      : plane.dragging && dual.reach ? (need <= dual.reach ? dual.reach : 1.25 * need) : need;
    dual.reach = reach;
    const x = (i, t) => (t < 0 ? v[i] * t : f[i] * t);
    const area = { x: 46, y: 16, w: 262, h: 244 };
    dual.map = { reach, x, map2: null, space: null, axes: {}, area };
    // Newton's or Minkowski's diagram: with the rail, off screen during a car's drag (drawn
    // after the frame when in sight); the diagram not chosen is drawn when it is.
    for (const id of ["newton-svg", "minkowski-svg"]) {
      const svg = $(id);
      if (svg.closest("[hidden]")) { clear(svg); continue; }
      drawSeen(svg, () => drawWorldLines(id, v, f, reach), plane.dragging, dual.dragging >= 0);
    }
    // Below, off screen during a drag of IN, and drawn after the frame beside a dragged car:
    // Space vs Space and the bars.
    drawSeen($("space-svg").closest(".row"), () => { drawSpace(p, v, f); drawRailBars(p); }, plane.dragging, true);
    drawDualTime();
  }

  // One space-time diagram (`newton-svg`: t across, x up; `minkowski-svg`: x across, t up) of
  // the world lines through IN and FIN in the box of half-width `reach`, and its time cursor.
  function drawWorldLines(id, v, f, reach) {
    const newton = id === "newton-svg";
    const svg = $(id);
    const { area, x } = dual.map;
    const tBox = [-1.1, 1.1];
    const colours = ["var(--body1)", "var(--body2)"];
    const box = newton ? { x0: tBox[0], x1: tBox[1], y0: -reach, y1: reach } : { x0: -reach, x1: reach, y0: tBox[0], y1: tBox[1] };
    const a = axesMap(area, box);
    chartFrame(svg, reach, plane.dragging, () => frameAxes(svg, area, box, newton ? ["t", "x"] : ["x", "t"]));
    const at = (t, xx) => (newton ? [a.X(t), a.Y(xx)] : [a.X(xx), a.Y(t)]);
    for (let i = 0; i < 2; i++) {
      el(svg, "polyline", { points: pts([at(-1, x(i, -1)), at(0, 0), at(1, x(i, 1))]), fill: "none", stroke: colours[i], "stroke-width": 2.2 });
    }
    const g = el(svg, "g", { class: "cursor" });
    g.dataset.newton = newton ? "1" : "0";
    dual.map.axes[id] = a;
    drawCursor(id);
  }

  // Space vs Space: x2 against x1, or scaled by M^(1/2); the path from IN to FIN and its dot at
  // the time shown.
  function drawSpace(p, v, f) {
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
    dual.map.map2 = map2;
    dual.map.space = a;
    placeSpaceDot();
  }
  function placeSpaceDot() {
    const { x, map2, space } = dual.map;
    if (!space) return;
    const sp = $("space-svg");
    let dot = sp.querySelector("#space-dot");
    const q = map2(x(0, dual.t), x(1, dual.t));
    if (!dot) dot = el(sp, "circle", { id: "space-dot", r: 5.5, fill: "var(--rev)", stroke: "#fff", "stroke-width": 1.5 });
    dot.setAttribute("cx", r2(space.X(q[0])));
    dot.setAttribute("cy", r2(space.Y(q[1])));
  }

  function drawDualTime() {
    const p = dual.picture;
    if (!p) return;
    const t = dual.t;
    const { reach, x } = dual.map;
    // (A diagram still waiting to be drawn places its cursor then.)
    for (const id of ["newton-svg", "minkowski-svg"]) if (!waiting.has($(id))) drawCursor(id);
    if (!waiting.has($("space-svg").closest(".row"))) placeSpaceDot();
    // The rail: drawn in the frame of a car's drag, after it during a drag of IN.
    drawSeen($("rail-svg"), () => drawRail(p, t, reach, x), plane.dragging, dual.dragging < 0);
    $("dual-time").value = String(t);
    $("dual-time-out").textContent = "t = " + minus(t.toFixed(3));
  }

  // The time cursor of a space-time diagram drawn at `dual.t` (a line across, the bodies' dots).
  function drawCursor(id) {
    const svg = $(id);
    const g = svg.querySelector(".cursor");
    const a = dual.map.axes[id];
    if (!g || !a) return;
    const t = dual.t, { x, area } = dual.map;
    const newton = g.dataset.newton === "1";
    const colours = ["var(--body1)", "var(--body2)"];
    clear(g);
    const { X, Y } = a;
    if (newton) el(g, "line", { x1: r2(X(t)), x2: r2(X(t)), y1: area.y, y2: area.y + area.h, stroke: "#111827", "stroke-opacity": 0.35 });
    else el(g, "line", { x1: area.x, x2: area.x + area.w, y1: r2(Y(t)), y2: r2(Y(t)), stroke: "#111827", "stroke-opacity": 0.35 });
    for (let i = 0; i < 2; i++) {
      const [cx, cy] = newton ? [X(t), Y(x(i, t))] : [X(x(i, t)), Y(t)];
      el(g, "circle", { cx: r2(cx), cy: r2(cy), r: 5, fill: colours[i], stroke: "#fff", "stroke-width": 1.5 });
    }
  }

  function drawRail(p, t, reach, x) {
    const svg = $("rail-svg");
    clear(svg);
    // The rail is 960 units long on a wide screen and shorter on a narrow one (down to 480), so
    // that its cars and text are not drawn tiny on a phone. (Its width as last measured:
    // measuring here would lay out the page again at every step of a drag.) The title has a row
    // of its own, above the cars' velocities.
    const shown = shownWidth.get(svg) || 0;
    const W = shown > 0 ? Math.round(Math.min(960, Math.max(480, shown * 1.4))) : svg.viewBox.baseVal.width;
    if (W !== svg.viewBox.baseVal.width) { svg.setAttribute("viewBox", "0 0 " + W + " 132"); scaleText(svg); }
    const L = 30, R = W - 30, car = 84, D = 22;
    const X = (u) => L + car + (u / reach + 1) * (R - L - 2 * car) / 2;
    dual.rail = { X, u: (sx) => ((sx - L - car) * 2 / (R - L - 2 * car) - 1) * reach };
    el(svg, "line", { x1: L, x2: R, y1: D + 86, y2: D + 86, stroke: "#6b7280", "stroke-width": 3 });
    for (const u of ticks(-reach, reach, (R - L) / kOf(svg) > 600 ? 8 : 4)) {
      el(svg, "line", { x1: r2(X(u)), x2: r2(X(u)), y1: D + 86, y2: D + 92, stroke: "#6b7280" });
      el(svg, "text", { x: r2(X(u)), y: D + 105, "text-anchor": "middle", class: "tick" }, short(u));
    }
    const m = p.inertia;
    // The cars meet at x = 0 at t = 0: the one on the left (body 2 when it catches body 1 from
    // behind, `p.left`) ends at its position, the other starts there.
    const onLeft = p.left === 2 ? 1 : 0;
    const bodies = [0, 1].map((i) => ({
      left: X(x(i, t)) - (i === onLeft ? car : 0), colour: "var(--body" + (i + 1) + ")", name: String(i + 1),
      mass: m[i][i], v: t < 0 ? p.in[i] : p.fin[i],
    }));
    for (const b of bodies) {
      el(svg, "rect", { x: r2(b.left), y: D + 46, width: car, height: 36, rx: 7, fill: b.colour, class: t < 0 ? "car handle" : "car", "data-body": b.name });
      // The wheels and the name are part of the car to a pointer (the car's rectangle takes it).
      el(svg, "circle", { cx: r2(b.left + 18), cy: D + 84, r: 6, fill: "#1f2937", "pointer-events": "none" });
      el(svg, "circle", { cx: r2(b.left + car - 18), cy: D + 84, r: 6, fill: "#1f2937", "pointer-events": "none" });
      el(svg, "text", { x: r2(b.left + car / 2), y: D + 69, "text-anchor": "middle", fill: "#fff", class: "label", "pointer-events": "none" }, "M" + (b.name === "1" ? "\u2081" : "\u2082") + " " + short(b.mass));
      const dir = b.v >= 0 ? 1 : -1;
      const cx = b.left + car / 2;
      if (b.v !== 0) {
        el(svg, "line", { x1: r2(cx - dir * 18), x2: r2(cx + dir * 18), y1: D + 30, y2: D + 30, stroke: b.colour, "stroke-width": 2.2 });
        el(svg, "polygon", { points: pts([[cx + dir * 24, D + 30], [cx + dir * 16, D + 25], [cx + dir * 16, D + 35]]), fill: b.colour });
      }
      el(svg, "text", { x: r2(cx), y: D + 18, "text-anchor": "middle", class: "tick" }, "V = " + short(b.v));
    }
    el(svg, "text", { x: L, y: 18, class: "title" }, t < 0 ? "before: IN" : t > 0 ? "after: FIN" : "the collision");
  }


  // PhET's starting positions: before the collision (t < 0 on screen) a car dragged along the
  // rail moves to where the pointer is. The cars meet at x = 0 at t = 0, so car i at x at time t
  // moves with V_i = x / t (in the frame on screen); the other body's velocity stays, and the
  // case is solved again as a drag of IN is (`moveIn`: the step, the unit, the frame). The rail
  // keeps its scale during the drag. Near t = 0 every position would need a huge velocity: a
  // car is dragged from t <= -0.1.
  function setupRailDrag() {
    const svg = $("rail-svg");
    let grab = 0, pending = null, queued = false;
    const railX = (ev) => { const r = svg.getBoundingClientRect(); return (ev.clientX - r.left) * svg.viewBox.baseVal.width / r.width; };
    const flush = () => {
      queued = false;
      if (!pending || dual.dragging < 0) return;
      const u = dual.rail.u(railX(pending) - grab);
      pending = null;
      const p = caseAnswer.picture, v = u / dual.t;
      if (!isFinite(v)) return;
      moveIn(dual.dragging === 0 ? v : p.in[0], dual.dragging === 1 ? v : p.in[1], dual.dragging);
    };
    holdHandles(svg);
    svg.addEventListener("pointerdown", (ev) => {
      const target = ev.target;
      if (!core || ev.button !== 0 || !target.classList || !target.classList.contains("car") || !(dual.t <= -0.1)) return;
      const i = Number(target.dataset.body) - 1;
      cancelAnimationFrame(plane.animation);
      dual.dragging = i;
      plane.dragging = true;
      plane.dragW = caseAnswer.picture.w;
      grab = railX(ev) - dual.rail.X(caseAnswer.picture.in[i] * dual.t);
      svg.setPointerCapture(ev.pointerId);
      svg.classList.add("dragging");
      ev.preventDefault();
    });
    svg.addEventListener("pointermove", (ev) => {
      if (dual.dragging < 0) return;
      pending = ev;
      if (!queued) { queued = true; requestAnimationFrame(flush); }
    });
    const end = (ev) => {
      if (dual.dragging < 0) return;
      if (ev.type === "pointerup") pending = ev;
      try {
        flush();
      } finally {
        dual.dragging = -1;
        plane.dragging = false;
        svg.classList.remove("dragging");
      }
      drawDual(caseAnswer.picture);
      drawWaiting();
      say("case-said", caseSentence());
    };
    svg.addEventListener("pointerup", end);
    svg.addEventListener("pointercancel", end);
  }

  function setupDual() {
    setupRailDrag();
    // Two units of time (t from -1 to 1) in four seconds at 1x, round and round; 40 steps.
    animation("dual", { start: -1, end: () => 1, rate: 0.5, step: () => 0.05, get: () => dual.t,
      set: (t) => { dual.t = t; drawDualTime(); } });
    $("dual-time").addEventListener("input", () => { dual.t = Number($("dual-time").value); drawDualTime(); });
    $("scaled").addEventListener("change", () => drawDual(caseAnswer.picture));
    // Newton's or Minkowski's diagram beside the velocity plane: both are drawn at every change,
    // the choice only shows one.
    for (const choice of document.querySelectorAll('input[name="spacetime"]')) {
      choice.addEventListener("change", () => {
        $("newton-figure").hidden = choice.value !== "newton";
        $("minkowski-figure").hidden = choice.value !== "minkowski";
        scaleText($(choice.value + "-svg"));
        if (dual.picture) drawDual(dual.picture);
      });
    }
  }

