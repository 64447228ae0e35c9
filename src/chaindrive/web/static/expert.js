// chaindrive expert pages: plots from the JSON block, the simulation job with progress.
"use strict";
(function () {
  const $ = (id) => document.getElementById(id);
  const cfg = { displaylogo: false, responsive: true };
  const data = $("plot-data");
  if (data && window.Plotly) {
    const figs = JSON.parse(data.textContent);
    figs.forEach((f, i) => window.Plotly.newPlot($("plot-" + (i + 1)), f.data, f.layout, cfg));
  }
  const form = $("expert-form");
  // results shown for other inputs than those in the form are marked stale at once
  const result = $("result");
  if (form && result) {
    const initial = new URLSearchParams(new FormData(form)).toString();
    form.addEventListener("input", () => {
      const stale = new URLSearchParams(new FormData(form)).toString() !== initial;
      result.classList.toggle("stale", stale);
      $("stale").hidden = !stale;
    });
  }
  if (!form || !form.action.endsWith("/expert/simulation")) return;
  function text(el, v) { el.textContent = v == null ? "" : String(v); }
  form.addEventListener("submit", async (e) => {
    e.preventDefault();
    for (const m of form.querySelectorAll(".msg")) m.textContent = "";
    const body = new URLSearchParams(new FormData(form));
    history.replaceState(null, "", "/expert/simulation?" + body.toString());
    const r = await fetch("/api/jobs/simulate", { method: "POST", body: body,
      headers: { "Content-Type": "application/x-www-form-urlencoded" } });
    const d = await r.json();
    if (!r.ok) {
      for (const [k, v] of Object.entries(d.errors || {})) { const m = $("err-" + k); if (m) text(m, v); }
      if (!d.errors) text($("err-example"), d.error);
      return;
    }
    $("job").hidden = false;
    $("job-results").replaceChildren();
    poll(d.job);
  });
  async function poll(id) {
    const r = await fetch("/api/jobs/" + encodeURIComponent(id));
    const j = await r.json();
    $("job-bar").style.width = Math.round(100 * (j.progress || 0)) + "%";
    const note = j.error || (j.message === j.state ? "" : j.message);
    text($("job-message"), j.state + (note ? ": " + note : "") + " (" + j.elapsed + " s)");
    if (j.state === "queued" || j.state === "running") { setTimeout(() => poll(id), 400); return; }
    if (j.state !== "done") return;
    const out = $("job-results");
    for (const name of ["simulation.gif", "simulation.png", "frame.png"]) {
      if (!j.files.includes(name)) continue;
      const fig = document.createElement("figure");
      const img = document.createElement("img");
      img.src = "/api/jobs/" + encodeURIComponent(id) + "/files/" + name;
      img.alt = name;
      img.className = "sim";
      const cap = document.createElement("figcaption");
      text(cap, name === "simulation.gif" ? "animation" : name === "frame.png" ? "the drive at the last instant" : "tensions, speeds and contact forces");
      fig.append(img, cap);
      out.appendChild(fig);
    }
    const rows = j.result && j.result.rows;
    if (rows) {
      const t = document.createElement("table");
      t.className = "kv";
      t.id = "sim-summary";
      for (const [label, value, unit] of rows) {
        const tr = t.insertRow();
        const th = document.createElement("th"); th.scope = "row"; text(th, label); tr.appendChild(th);
        const td = tr.insertCell(); td.className = "numcell"; text(td, value);
        const tu = tr.insertCell(); text(tu, unit);
      }
      out.appendChild(t);
    }
    const a = document.createElement("a");
    a.href = "/api/jobs/" + encodeURIComponent(id) + "/files/simulation.json";
    a.className = "button secondary";
    text(a, "simulation.json");
    out.appendChild(a);
    document.body.dataset.job = "done";
  }
})();
