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
    // After a bad input the tower, the world lines and the numbers are the last valid run's:
    // greyed and labelled, and Play disabled (it would animate that run as if it were this).
    markStale(["tower-svg", "lines-svg", "stack-numbers"], !answer.ok);
    for (const b of ["play", "back", "step", "reset"]) $("stack-" + b).disabled = !answer.ok;
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
      // Harter's limit 2^n - 1 is for balls each lighter than the one below; a heavy ball on
      // top is not amplified, and the top ball may leave downward (then it does not rise).
      const start = (i) => (a.x[i] && a.x[i].length ? a.x[i][0] : trackState.x[i]);
      const up = a.masses.map((m, i) => i).sort((i, j) => start(i) - start(j));
      const lighterUp = up.every((i, k) => k === 0 || a.masses[i] < a.masses[up[k - 1]]);
      const rises = amp.top_velocity > 0;
      para(rises ? "Velocity amplification: the top ball leaves at <span class=\"num\">" + num(amp.ratio) + "</span> &times; the bottom ball's impact speed"
        : "No amplification: the top ball leaves the collision downward, at <span class=\"num\">" + num(amp.ratio) + "</span> &times; the bottom ball's impact speed", "big");
      const limit = "the limit is 2<sup>" + a.masses.length + "</sup> &minus; 1 = " + amp.limit;
      para("(it leaves at " + num(amp.top_velocity) + "; the bottom ball hit the floor at " + num(amp.drop_speed) + "). " +
        (lighterUp ? "For elastic balls, each much lighter than the one below, " + limit + "."
          : "A heavier ball is above a lighter one here; " + limit + " only for elastic balls each much lighter than the one below."));
      if (a.gravity > 0 && rises) para("so it rises <span class=\"num\">" + num(amp.ratio * amp.ratio) + "</span> &times; as high above the collision as the stack fell");
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
    // In real time at 1x (the track's time unit a second); 100 steps to the end.
    animation("stack", { start: 0, end: () => stackAnswer.until, rate: 1, step: () => stackAnswer.until / 100,
      get: () => stack.t, set: (t) => { stack.t = t; drawStackTime(); } });
    $("stack-time").addEventListener("input", () => { stack.t = Number($("stack-time").value); drawStackTime(); });
  }
  function syncTrackSlider() {
    const e = valueOf($("t-e").value);
    if (e >= 0 && e <= 1) $("t-e-range").value = String(e);
  }

