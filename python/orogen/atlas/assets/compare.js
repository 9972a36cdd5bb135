// The compare page: 2-4 runs from the menus, one slider over S for their animations, one
// chart of a chosen series of each. The choice lives in the URL (#slug,slug,...).
"use strict";
(function () {
  var cat = ATLAS.catalog || [];
  var picks = Array.from(document.querySelectorAll("select.pick"));
  var anim = document.getElementById("anim"), column = document.getElementById("column");
  var slider = document.getElementById("slider"), at = document.getElementById("at");
  var play = document.getElementById("play"), panels = document.getElementById("panels");
  var overlay = document.getElementById("overlay");
  var player = null, marker = null;

  picks.forEach(function (sel, k) {
    sel.add(new Option(k < 2 ? "(pick a run)" : "(none)", ""));
    cat.forEach(function (r) { sel.add(new Option(r.name + " · " + r.experiment, r.slug)); });
  });
  var wanted = decodeURIComponent(location.hash.slice(1)).split(",").filter(Boolean);
  if (wanted.length < 2) {  // fill up to two from the catalog
    cat.forEach(function (r) { if (wanted.length < 2 && wanted.indexOf(r.slug) < 0) wanted.push(r.slug); });
  }
  wanted.slice(0, 4).forEach(function (slug, k) { picks[k].value = slug; });

  function chosen() {
    var out = [];
    picks.forEach(function (p) { if (p.value && out.indexOf(p.value) < 0) out.push(p.value); });
    return out;
  }
  function fill(sel, values, keep) {
    var old = sel.value;
    sel.innerHTML = "";
    values.forEach(function (v) { sel.add(new Option(v[1], v[0])); });
    if (values.some(function (v) { return v[0] === old; })) sel.value = old;
    else if (keep && values.some(function (v) { return v[0] === keep; })) sel.value = keep;
  }

  function update() {
    var slugs = chosen();
    history.replaceState(null, "", "#" + slugs.join(","));
    Promise.all(slugs.map(function (s) { return ATLAS.load(s); })).then(function (runs) {
      var folders = [];
      runs.forEach(function (r) {
        Object.keys(r.frames).forEach(function (f) {
          if (!folders.some(function (x) { return x[0] === f; })) folders.push([f, r.frames[f].title]);
        });
      });
      fill(anim, folders, "frames");
      var cols = [];
      runs.forEach(function (r) {
        if (!r.series || !r.series.columns) return;
        r.series.columns.forEach(function (c) {
          if (c !== r.x && c !== "step" && !cols.some(function (x) { return x[0] === c; })) cols.push([c, c]);
        });
      });
      fill(column, cols, "H");
      drawPanels(runs);
      drawOverlay(runs);
    });
  }

  function drawPanels(runs) {
    if (player) player.stop();
    panels.innerHTML = "";
    var sets = [], imgs = [];
    runs.forEach(function (r) {
      var fig = document.createElement("figure");
      var set = r.frames[anim.value];
      fig.innerHTML = '<div class="frame"><img alt=""></div><figcaption><a></a> <span class="muted"></span></figcaption>';
      var a = fig.querySelector("a");
      a.href = "runs/" + r.slug + ".html";
      a.textContent = r.name;
      fig.querySelector(".muted").textContent = set ? set.title : "(no such animation)";
      panels.appendChild(fig);
      if (set) { sets.push(set.frames.map(function (f) { return [f[0], f[1]]; })); imgs.push(fig.querySelector("img")); }
      else fig.querySelector(".frame").remove();
    });
    var x = runs.length ? runs[0].x : "S";
    player = ATLAS.player(sets, imgs, slider, at, play, x);
    player.onshow = function (v) { marker = v; ATLAS.plots.forEach(function (e) { if (e.u) e.u.redraw(false); }); };
  }

  function drawOverlay(runs) {
    ATLAS.clearPlots(overlay);
    var c = column.value;
    var have = runs.filter(function (r) { return r.series && r.series.data && r.series.data[c]; });
    if (!have.length) return;
    var xs = [];
    have.forEach(function (r) { r.series.data[r.x].forEach(function (v) { if (v !== null) xs.push(v); }); });
    xs = Array.from(new Set(xs)).sort(function (a, b) { return a - b; });
    var index = new Map(xs.map(function (v, i) { return [v, i]; }));
    var series = have.map(function (r) {
      var ys = new Array(xs.length).fill(null), rx = r.series.data[r.x], ry = r.series.data[c];
      rx.forEach(function (v, i) { if (v !== null) ys[index.get(v)] = ry[i]; });
      return { label: r.name, values: ys };
    });
    var u = have[0].series.units || {}, x = have[0].x;
    ATLAS.plot(overlay, {
      title: c + " of each run", x: xs, xLabel: ATLAS.unitLabel(x, u[x]), yLabel: ATLAS.unitLabel(c, u[c]),
      series: series,
      hooks: { draw: [function (plot) {  // the slider's S as a vertical line
        if (marker === null) return;
        var ctx = plot.ctx, px = plot.valToPos(marker, "x", true);
        ctx.save(); ctx.strokeStyle = ATLAS.css("--accent"); ctx.lineWidth = 2;
        ctx.beginPath(); ctx.moveTo(px, plot.bbox.top); ctx.lineTo(px, plot.bbox.top + plot.bbox.height); ctx.stroke();
        ctx.restore();
      }] }
    });
  }

  picks.forEach(function (p) { p.addEventListener("change", update); });
  anim.addEventListener("change", function () {
    drawPanels(chosen().map(function (s) { return ATLAS.runs[s]; }));
  });
  column.addEventListener("change", function () { drawOverlay(chosen().map(function (s) { return ATLAS.runs[s]; })); });
  update();
})();
