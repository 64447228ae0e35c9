// The studio's 3-D view: fetch the figure of the design and draw it with plotly (mesh3d);
// a click on a part shows its numbers (each trace's meta: vertices per copy, texts per copy).
(function () {
  "use strict";
  var box = document.getElementById("view3d");
  var status = document.getElementById("view3d-status");
  var info = document.getElementById("view3d-part");
  if (!box) { return; }
  fetch("/api/view3d?" + box.dataset.query, {headers: {"Accept": "application/json"}})
    .then(function (r) { return r.json().then(function (body) { return {ok: r.ok, body: body}; }); })
    .then(function (res) {
      if (!res.ok) { status.textContent = "error: " + (res.body.error || res.body.detail || "the model failed"); return; }
      var s = res.body.summary;
      status.textContent = s.parts + " parts (" + s.distinct_shapes + " distinct solids), " + s.links + " links";
      return Plotly.newPlot(box, res.body.figure.data, res.body.figure.layout, {responsive: true, displaylogo: false})
        .then(function () {
          box.setAttribute("data-ready", "1");
          box.on("plotly_click", function (ev) {
            var pt = ev.points && ev.points[0];
            if (!pt) { return; }
            var meta = pt.data.meta;
            var copy = Math.floor(pt.pointNumber / meta.verts);
            var text = meta.parts[copy] || pt.data.name;
            info.textContent = text.replace(/<br>/g, "\n").replace(/<\/?b>/g, "");
          });
        });
    })
    .catch(function (e) { status.textContent = "error: " + e; });
})();
