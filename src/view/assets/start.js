  // ---------------------------------------------------------------- start
  const controls = () => document.querySelectorAll("#case-form input, #plane-form input, #plane-form select, #plane input[name=\"p-key\"], #track-form input, #track-form select, #rigid-form input, #rigid-form select, #nball-form input, #nball-form select, #nball-time, #plane-svg, #pucks-svg, #rigid-svg");
  function setEnabled(on) {
    for (const c of controls()) {
      if (c.tagName.toLowerCase() === "svg") c.setAttribute("aria-disabled", String(!on));
      else c.disabled = !on;
    }
  }

  // With JavaScript on, the page draws everything: the status says the core is loading.
  $("status").classList.remove("bad");
  $("status").textContent = "Showing the numbers collide wrote into this page; loading its WebAssembly core\u2026";
  setupCaseInputs();
  setupDrag();
  setupDual();
  setupPlane();
  setupStack();
  setupRigid();
  setupNb();
  setupCopy();
  for (const svg of document.querySelectorAll("svg.chart")) scaleText(svg);
  renderCase();
  renderPlane();
  renderStack();
  renderRigid();
  renderNb();
  setEnabled(false);
  // A picture drawn at another width (a phone turned, a window resized): its text keeps its
  // size, and the pictures are drawn again around it.
  if (typeof ResizeObserver === "function") {
    const seen = new ResizeObserver((entries) => {
      let changed = false;
      for (const e of entries) changed = scaleText(e.target) || changed;
      if (changed) { renderCase(); renderPlane(); renderStack(); renderRigid(); renderNb(); }
    });
    for (const svg of document.querySelectorAll("svg.chart")) seen.observe(svg);
  }
  if ((data.setup.focus === "stack" || data.setup.focus === "plane") && !location.hash) $(data.setup.focus).scrollIntoView();

  loadCore().then((ask) => {
    core = ask;
    // The core must give the very answers collide wrote into the page.
    for (const [op, request, written] of [["solve", Object.assign({ op: "solve" }, data.setup.case), data.answers.solve],
      ["plane", Object.assign({ op: "plane" }, data.setup.plane), data.answers.plane],
      ["track", Object.assign({ op: "track" }, data.setup.track), data.answers.track],
      ["rigid", Object.assign({ op: "rigid" }, data.setup.rigid), data.answers.rigid],
      ["nbody", Object.assign({ op: "nbody" }, data.setup.nbody), data.answers.nbody]]) {
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
