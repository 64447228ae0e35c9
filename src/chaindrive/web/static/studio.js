// chaindrive design studio: live update of the guided design (plain fetch, no framework).
"use strict";
(function () {
  const form = document.getElementById("design");
  if (!form) return;
  const $ = (id) => document.getElementById(id);
  let liveBusy = false, liveAgain = false, liveQuery = null, editAt = null, chartsCtl = null, chartsTimer = null;
  let mapBase = null, sliding = false;
  // what each part of the page shows now (its data as JSON): an edit redraws only the parts it changed
  const shown = {};
  function changed(part, value) {
    const key = JSON.stringify(value === undefined ? null : value);
    if (shown[part] === key) return false;
    shown[part] = key;
    return true;
  }
  const plotConfig = { displaylogo: false, responsive: true, modeBarButtonsToRemove: ["sendDataToCloud"] };

  function params() {
    const p = new URLSearchParams();
    for (const el of form.elements) {
      if (el.name) p.set(el.name, el.value);
    }
    return p;
  }
  function text(el, value) { el.textContent = value == null ? "" : String(value); }
  // the rows of a table body as data: each row {cls, cells: [[text, class, tag], ...], title, chain, hint};
  // rows and cells already there are reused and only texts and classes that differ are written
  // (fewer new nodes: less style and layout work for the browser after each edit)
  function setClass(el, cls) {  // as a new element with that class (none: no class attribute)
    if (cls) { if (el.className !== cls) el.className = cls; } else if (el.hasAttribute("class")) el.removeAttribute("class");
  }
  function fillRows(body, rows) {
    while (body.rows.length > rows.length) body.deleteRow(-1);
    rows.forEach((row, i) => {
      let tr = body.rows[i];
      if (!tr) { tr = document.createElement("tr"); body.appendChild(tr); }
      setClass(tr, row.cls);
      if (row.title !== undefined && tr.title !== row.title) tr.title = row.title;
      if (row.chain !== undefined) tr.dataset.chain = row.chain;
      while (tr.cells.length > row.cells.length) tr.deleteCell(-1);
      row.cells.forEach(([value, cls, tag], j) => {
        let td = tr.cells[j];
        const want = (tag || "td").toUpperCase();
        if (!td || td.tagName !== want) {
          const fresh = document.createElement(want);
          if (td) tr.replaceChild(fresh, td); else tr.appendChild(fresh);
          td = fresh;
        }
        const hint = j === row.hintAt ? row.hint : undefined;
        const str = value == null ? "" : String(value);
        if (hint) {
          if (td.firstChild === null || td.firstChild.nodeType !== Node.TEXT_NODE || td.firstChild.data !== str
              || td.childNodes.length !== 2 || td.lastChild.textContent !== hint) {
            const s = document.createElement("div");
            s.className = "hint";
            text(s, hint);
            td.replaceChildren(document.createTextNode(str), s);
          }
        } else if (td.childNodes.length > 1 || td.textContent !== str) {
          td.textContent = str;
        }
        setClass(td, cls);
      });
    });
  }
  function kvTable(id, rows) {
    fillRows($(id).querySelector("tbody"), rows.map(([k, v]) => ({ cells: [[k, "", "th"], [v]] })));
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
    const ks = d.service_factor_table;
    if (ks && changed("ks", ks)) text($("ks-source"), "Service factor table: " + ks.driver + " × " + ks.character + " → K_s = " + ks.value + ". Source: " + ks.source);
    if (!d.duty) return;
    if (changed("duty", d.duty)) kvTable("duty-out", [
      ["power P", d.duty.power.join(" ")],
      ["driving speed", d.duty.speed_rpm + " rpm"],
      ["ratio", d.duty.ratio],
      ["load character", d.duty.load_character],
      ["service factor K_s", d.duty.service_factor + (d.duty.service_factor_source === "given" ? " (given)" : " (table)")],
      ["design power K_s P", d.duty.design_power.join(" ")],
    ]);
    if (changed("candidates", d.candidates)) {
      fillRows($("candidates").querySelector("tbody"), d.candidates.map((c) => ({
        cls: "candidate" + (c.chosen ? " chosen" : ""), chain: c.chain, title: "choose " + c.chain,
        cells: [[c.chain + (c.chosen ? "  ✓" : "")], [c.pitch_text], [c.rated],
                [c.margin_text, c.margin >= 1 ? "pass" : "fail"], [c.safety_text], [c.lubrication || "—"]],
      })));
    }
    if (changed("note", [d.chain, d.candidate_note, d.advice])) text($("candidate-note"), "Chosen: " + d.chain.name + " (" + d.chain.family + "), pitch " + d.chain.pitch +
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
    if (changed("layout", rows)) kvTable("layout-out", rows);
    if (changed("drawing", d.drawing)) $("drawing").innerHTML = d.drawing || "";
    if (changed("loads", d.loads)) {
      text($("loads-caption"), d.loads ? d.loads.caption : "");
      fillRows($("loads").querySelector("tbody"), d.loads ? d.loads.rows.map(([name, value, unit, basis]) => ({
        cells: [[name], [value + " " + unit], [basis, "source"]] })) : []);
      $("loads").hidden = !d.loads;
    }
    if (changed("fretting", d.fretting)) {
      text($("fretting-caption"), d.fretting ? d.fretting.caption : "");
      fillRows($("fretting").querySelector("tbody"), d.fretting ? d.fretting.rows.map(([name, value, unit]) => ({
        cells: [[name], [value + " " + unit]] })) : []);
      $("fretting").hidden = !d.fretting;
    }
    if (changed("checks", d.checks)) {
      fillRows($("checks").querySelector("tbody"), (d.checks || []).map((c) => ({
        cls: "check " + (c.passed === true ? "pass" : c.passed === false ? "fail" : "info"), hintAt: 1, hint: c.note,
        cells: [[c.passed === true ? "✔ pass" : c.passed === false ? "✘ FAIL" : "ℹ info", "verdict-cell"], [c.name],
                [c.value_text + " " + c.unit_text], [c.limit_text], [c.margin_text], [c.source, "source"]],
      })));
    }
    const ov = $("overall");
    if (d.checks) {
      text(ov, d.verdict || (d.passed ? "passes" : "a check fails"));
      ov.className = "verdict " + (d.passed ? "pass" : "fail");
    }
    if (changed("warnings", d.warnings)) {
      const wl = $("warnings");
      wl.replaceChildren();
      for (const w of d.warnings || []) { const li = document.createElement("li"); text(li, w); wl.appendChild(li); }
    }
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
      // once the new page is painted: the time from the edit (data-edit-ms) and the count of updates;
      // then the address bar (the link that reproduces the design; Chromium looks at the icon again
      // after each history entry: work the answer on screen need not wait for)
      requestAnimationFrame(() => setTimeout(() => {
        if (since !== null) document.body.dataset.editMs = (performance.now() - since).toFixed(1);
        document.body.dataset.updates = String((parseInt(document.body.dataset.updates || "0", 10)) + 1);
        if (d.query !== undefined) history.replaceState(null, "", "/" + (d.query ? "?" + d.query : ""));
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
    if (!fig) { el.hidden = true; delete shown["plot " + id]; return; }
    el.hidden = false;
    // the same figure as on screen (e.g. the rating chart after a centre-distance edit): not drawn again
    if (window.Plotly && changed("plot " + id, fig)) window.Plotly.react(el, fig.data, fig.layout, plotConfig);
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
    delete shown["plot plot-map"];  // the map on screen is no longer the server's figure
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
  $("candidates").addEventListener("click", (e) => {  // a candidate's row chooses its chain
    const tr = e.target.closest("tr.candidate");
    if (tr) { $("chain").value = tr.dataset.chain; schedule(); }
  });
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
