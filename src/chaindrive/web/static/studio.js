// chaindrive design studio: live update of the guided design (plain fetch, no framework).
"use strict";
(function () {
  const form = document.getElementById("design");
  if (!form) return;
  const $ = (id) => document.getElementById(id);
  let liveBusy = false, liveAgain = false, liveQuery = null, editAt = null, chartsCtl = null, chartsTimer = null;
  let mapBase = null, sliding = false;
  const plotConfig = { displaylogo: false, responsive: true, modeBarButtonsToRemove: ["sendDataToCloud"] };

  function params() {
    const p = new URLSearchParams();
    for (const el of form.elements) {
      if (el.name) p.set(el.name, el.value);
    }
    return p;
  }
  function text(el, value) { el.textContent = value == null ? "" : String(value); }
  function cell(tr, value, cls) {
    const td = document.createElement("td");
    text(td, value);
    if (cls) td.className = cls;
    tr.appendChild(td);
    return td;
  }
  function kvTable(id, rows) {
    const body = $(id).querySelector("tbody");
    body.replaceChildren();
    for (const [k, v] of rows) {
      const tr = document.createElement("tr");
      const th = document.createElement("th");
      text(th, k);
      tr.appendChild(th);
      cell(tr, v);
      body.appendChild(tr);
    }
  }
  function showErrors(errors) {
    for (const el of form.querySelectorAll(".msg")) el.textContent = "";
    for (const el of form.querySelectorAll("[aria-invalid]")) el.removeAttribute("aria-invalid");
    for (const f of form.querySelectorAll(".field.invalid")) f.classList.remove("invalid");
    for (const [name, message] of Object.entries(errors || {})) {
      const msg = $("err-" + name);
      const input = $(name);
      if (msg) msg.textContent = message;
      if (input) input.setAttribute("aria-invalid", "true");
      const f = $("field-" + name);
      if (f) f.classList.add("invalid");
    }
  }
  // after an invalid input the results on screen are those of the last valid inputs: say so
  function markStale(stale) {
    document.body.classList.toggle("has-errors", stale);
    const banner = $("stale-banner");
    if (banner) banner.hidden = !stale;
    const ov = $("overall");
    if (ov && stale) { text(ov, "stale: fix the marked field"); ov.className = "verdict stale-verdict"; }
  }
  function toggleTensioner() {
    $("tensioner-fields").hidden = $("tensioner").value !== "on";
    $("field-guide_end").hidden = $("guide").value === "";
  }

  function render(d) {
    showErrors(d.errors);
    const ok = !d.errors || Object.keys(d.errors).length === 0;
    markStale(!ok);
    if (d.query !== undefined) history.replaceState(null, "", "/" + (d.query ? "?" + d.query : ""));
    const ks = d.service_factor_table;
    if (ks) text($("ks-source"), "Service factor table: " + ks.driver + " × " + ks.character + " → K_s = " + ks.value + ". Source: " + ks.source);
    if (!d.duty) return;
    kvTable("duty-out", [
      ["power P", d.duty.power.join(" ")],
      ["driving speed", d.duty.speed_rpm + " rpm"],
      ["ratio", d.duty.ratio],
      ["load character", d.duty.load_character],
      ["service factor K_s", d.duty.service_factor + (d.duty.service_factor_source === "given" ? " (given)" : " (table)")],
      ["design power K_s P", d.duty.design_power.join(" ")],
    ]);
    const body = $("candidates").querySelector("tbody");
    body.replaceChildren();
    for (const c of d.candidates) {
      const tr = document.createElement("tr");
      tr.className = "candidate" + (c.chosen ? " chosen" : "");
      tr.dataset.chain = c.chain;
      tr.title = "choose " + c.chain;
      cell(tr, c.chain + (c.chosen ? "  ✓" : ""));
      cell(tr, c.pitch_text);
      cell(tr, c.rated);
      cell(tr, c.margin_text, c.margin >= 1 ? "pass" : "fail");
      cell(tr, c.safety_text);
      cell(tr, c.lubrication || "—");
      tr.addEventListener("click", () => { $("chain").value = c.chain; schedule(); });
      body.appendChild(tr);
    }
    text($("candidate-note"), "Chosen: " + d.chain.name + " (" + d.chain.family + "), pitch " + d.chain.pitch +
      ", breaking force " + d.chain.breaking_force + ". " + (d.candidate_note || "") +
      (d.advice || []).map((a) => " Advice, " + a.name + ": " + a.note + " [" + a.source + "].").join(""));
    const L = d.layout;
    const rows = [
      ["teeth z1 / z2", L.teeth_driving + " / " + L.teeth_driven],
      ["centre distance asked", L.centre_distance_given],
      ["chain length", L.links + " links (" + L.links_required + " required), " + L.chain_length],
    ];
    if (L.centre_distance_exact) rows.push(["exact centre distance for " + L.links + " links", L.centre_distance_exact]);
    rows.push(["chain speed", L.chain_speed]);
    if (d.life_years) rows.push(["chain life at " + d.duty.hours_per_day + " h/day", d.life_years + " years"]);
    kvTable("layout-out", rows);
    $("drawing").innerHTML = d.drawing || "";
    const lb = $("loads").querySelector("tbody");
    lb.replaceChildren();
    if (d.loads) {
      text($("loads-caption"), d.loads.caption);
      for (const [name, value, unit, basis] of d.loads.rows) {
        const tr = document.createElement("tr");
        cell(tr, name);
        cell(tr, value + " " + unit);
        cell(tr, basis, "source");
        lb.appendChild(tr);
      }
    }
    $("loads").hidden = !d.loads;
    const fb = $("fretting").querySelector("tbody");
    fb.replaceChildren();
    if (d.fretting) {
      text($("fretting-caption"), d.fretting.caption);
      for (const [name, value, unit] of d.fretting.rows) {
        const tr = document.createElement("tr");
        cell(tr, name);
        cell(tr, value + " " + unit);
        fb.appendChild(tr);
      }
    }
    $("fretting").hidden = !d.fretting;
    const cb = $("checks").querySelector("tbody");
    cb.replaceChildren();
    for (const c of d.checks || []) {
      const tr = document.createElement("tr");
      tr.className = "check " + (c.passed === true ? "pass" : c.passed === false ? "fail" : "info");
      cell(tr, c.passed === true ? "✔ pass" : c.passed === false ? "✘ FAIL" : "ℹ info", "verdict-cell");
      const name = cell(tr, c.name);
      if (c.note) { const s = document.createElement("div"); s.className = "hint"; text(s, c.note); name.appendChild(s); }
      cell(tr, c.value_text + " " + c.unit_text);
      cell(tr, c.limit_text);
      cell(tr, c.margin_text);
      cell(tr, c.source, "source");
      cb.appendChild(tr);
    }
    const ov = $("overall");
    if (d.checks) {
      text(ov, d.verdict || (d.passed ? "passes" : "a check fails"));
      ov.className = "verdict " + (d.passed ? "pass" : "fail");
    }
    const wl = $("warnings");
    wl.replaceChildren();
    for (const w of d.warnings || []) { const li = document.createElement("li"); text(li, w); wl.appendChild(li); }
    for (const a of document.querySelectorAll("#downloads a")) {
      if (d.downloads && d.downloads[a.dataset.name]) a.href = d.downloads[a.dataset.name];
    }
    $("simulate-link").href = "/expert/simulation?" + new URLSearchParams({ example: "studio", duration: "0.5 s", design: d.query || "" }).toString();
    $("resonance").hidden = !d.has_tensioner;
    text($("status"), "updated in " + d.elapsed_ms + " ms (server)");
  }

  // one live request at a time: an edit while one is on its way asks for one more, sent when it
  // has answered with the form as it is then (an aborted request would still cost the server its work)
  // (an edit fires "input" and "change": the form already asked for is not asked for again)
  async function update(force) {
    if (liveBusy) { liveAgain = true; return; }
    const query = params().toString();
    if (query === liveQuery && !force) return;
    liveBusy = true;
    liveAgain = false;
    liveQuery = query;
    const since = editAt;  // the edit this request answers (a later one starts its own)
    editAt = null;
    document.body.classList.add("busy");
    try {
      const r = await fetch("/api/design?" + query, { headers: { Accept: "application/json" } });
      const d = await r.json();
      if (!r.ok) liveQuery = null;  // asked again at the next edit (or retry)
      if (r.status === 503) { text($("status"), d.error); setTimeout(schedule, 1000); return; }
      if (!r.ok) { showErrors(d.field ? { [d.field]: d.error } : {}); markStale(true); text($("status"), d.error || ("error " + r.status)); return; }
      render(d);
      document.body.dataset.ready = "live";
      // once the new page is painted: the time from the edit (data-edit-ms) and the count of updates
      requestAnimationFrame(() => setTimeout(() => {
        if (since !== null) document.body.dataset.editMs = (performance.now() - since).toFixed(1);
        document.body.dataset.updates = String((parseInt(document.body.dataset.updates || "0", 10)) + 1);
      }, 0));
      if (!d.errors || Object.keys(d.errors).length === 0) scheduleCharts();
    } catch (e) {
      liveQuery = null;
      text($("status"), "the server did not answer: " + e);
    } finally {
      liveBusy = false;
      if (liveAgain) update();
      if (!liveBusy) document.body.classList.remove("busy");
    }
  }

  function plot(id, fig) {
    const el = $(id);
    if (!el) return;
    if (!fig) { el.hidden = true; return; }
    el.hidden = false;
    if (window.Plotly) window.Plotly.react(el, fig.data, fig.layout, plotConfig);
  }

  async function charts() {
    if (chartsCtl) chartsCtl.abort();
    chartsCtl = new AbortController();
    try {
      const r = await fetch("/api/design/charts?" + params().toString(), { signal: chartsCtl.signal });
      if (!r.ok) return;
      const d = await r.json();
      plot("plot-rating", d.rating);
      plot("plot-campbell", d.campbell);
      if (!sliding) {
        plot("plot-map", d.resonance_map);
        if (d.resonance_map) {
          const t = d.resonance_map.data[2];
          mapBase = { mass: t.y[0], stiffness: t.x[0] };
          $("slider-mass").value = 0;
          $("slider-stiffness").value = 0;
          text($("out-mass"), mapBase.mass.toPrecision(3) + " kg");
          text($("out-stiffness"), mapBase.stiffness.toPrecision(3) + " kN/m");
        }
      }
      document.body.dataset.charts = "ready";
      document.body.dataset.chartUpdates = String((parseInt(document.body.dataset.chartUpdates || "0", 10)) + 1);
    } catch (e) { /* aborted or offline: the live part is shown already */ }
  }

  function schedule() {  // at once when no request is on its way, else right after it
    if (editAt === null) editAt = performance.now();
    update();
  }
  function scheduleCharts() { clearTimeout(chartsTimer); chartsTimer = setTimeout(charts, 250); }

  function slide() {
    if (!mapBase) return;
    sliding = true;
    const m = mapBase.mass * Math.pow(10, parseFloat($("slider-mass").value));
    const c = mapBase.stiffness * Math.pow(10, parseFloat($("slider-stiffness").value));
    $("tensioner_mass").value = m.toPrecision(3) + " kg";
    $("tensioner_stiffness").value = c.toPrecision(3) + " kN/m";
    text($("out-mass"), m.toPrecision(3) + " kg");
    text($("out-stiffness"), c.toPrecision(3) + " kN/m");
    const el = $("plot-map");
    if (window.Plotly && el && el.data) window.Plotly.restyle(el, { x: [[c]], y: [[m]] }, [2]);
    schedule();
  }

  form.addEventListener("input", (e) => {
    if (e.target.id === "tensioner_mass" || e.target.id === "tensioner_stiffness") sliding = false;
    toggleTensioner();
    schedule();
  });
  form.addEventListener("change", (e) => {
    if (e.target && e.target.id === "extra_wheels") { form.submit(); return; }  // rows are drawn by the server
    toggleTensioner(); schedule();
  });
  for (const b of form.querySelectorAll("[data-extra]")) {
    b.addEventListener("click", () => {
      const count = $("extra_wheels");
      count.value = String(Number(count.value) + Number(b.dataset.extra));
      form.submit();
    });
  }
  form.addEventListener("submit", (e) => { e.preventDefault(); update(true); });
  $("slider-mass").addEventListener("input", slide);
  $("slider-stiffness").addEventListener("input", slide);
  $("project-file").addEventListener("change", async () => {
    const f = $("project-file").files[0];
    if (!f) return;
    const fd = new FormData();
    fd.append("file", f);
    const r = await fetch("/open", { method: "POST", body: fd, headers: { Accept: "application/json" } });
    const d = await r.json();
    if (r.ok) { window.location.assign("/" + (d.query ? "?" + d.query : "")); }
    else { text($("err-project"), d.error); }
  });
  toggleTensioner();
  update();
})();
