// Shared by every page: the data registry (data files call ATLAS.add), the theme switch,
// sortable tables, the series charts (uPlot) and the frame player.
"use strict";
var ATLAS = window.ATLAS || {};
window.ATLAS = ATLAS;
ATLAS.runs = {};
ATLAS.waiting = {};

// A run's data file is a script (file:// forbids fetch() of local files), loaded when needed.
ATLAS.add = function (data) {
  ATLAS.runs[data.slug] = data;
  (ATLAS.waiting[data.slug] || []).forEach(function (f) { f(data); });
  delete ATLAS.waiting[data.slug];
};
ATLAS.load = function (slug, up) {
  return new Promise(function (resolve, reject) {
    if (ATLAS.runs[slug]) return resolve(ATLAS.runs[slug]);
    var first = !ATLAS.waiting[slug];
    (ATLAS.waiting[slug] = ATLAS.waiting[slug] || []).push(resolve);
    if (!first) return;
    var s = document.createElement("script");
    s.src = (up || "") + "data/run_" + encodeURIComponent(slug) + ".js";
    s.onerror = function () { reject(new Error("missing data file " + s.src)); };
    document.head.appendChild(s);
  });
};

ATLAS.css = function (name) { return getComputedStyle(document.documentElement).getPropertyValue(name).trim(); };
ATLAS.palette = ["#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#17becf"];

// Charts drawn with uPlot; redrawn when the theme changes (their colours are the theme's).
ATLAS.plots = [];
ATLAS.plot = function (el, spec) {
  // spec: {title, fig, x: [..], xLabel, yLabel, series: [{label, values}]}
  var box = document.createElement("div");
  box.className = "plot";
  var h = document.createElement("h3");
  h.textContent = spec.title;
  if (spec.fig) {
    var f = document.createElement("span");
    f.className = "fig";
    f.textContent = " thesis " + spec.fig;
    h.appendChild(f);
  }
  box.appendChild(h);
  el.appendChild(box);
  var entry = { box: box, spec: spec, u: null };
  draw(entry);
  ATLAS.plots.push(entry);
  return entry;
};
function draw(entry) {
  var spec = entry.spec, fg = ATLAS.css("--fg"), line = ATLAS.css("--line");
  if (entry.u) entry.u.destroy();
  var axis = function (label) {
    return { label: label, stroke: fg, grid: { stroke: line, width: 1 }, ticks: { stroke: line, width: 1 } };
  };
  var width = Math.max(240, entry.box.clientWidth - 12);
  var opts = {
    width: width, height: Math.round(Math.min(320, width * 0.6)),
    scales: { x: { time: false } },
    axes: [axis(spec.xLabel), axis(spec.yLabel)],
    cursor: { drag: { x: true, y: true, uni: 30 } },
    series: [{ label: spec.xLabel }].concat(spec.series.map(function (s, i) {
      return { label: s.label, stroke: s.color || ATLAS.palette[i % ATLAS.palette.length], width: 1.5,
               spanGaps: true, dash: s.dash };
    })),
    hooks: spec.hooks || {}
  };
  entry.u = new uPlot(opts, [spec.x].concat(spec.series.map(function (s) { return s.values; })), entry.box);
}
window.addEventListener("resize", function () {
  ATLAS.plots.forEach(function (e) {
    if (!e.u) return;
    var w = Math.max(240, e.box.clientWidth - 12);
    e.u.setSize({ width: w, height: Math.round(Math.min(320, w * 0.6)) });
  });
});
ATLAS.clearPlots = function (el) {
  ATLAS.plots = ATLAS.plots.filter(function (e) {
    if (el.contains(e.box)) { e.u.destroy(); return false; }
    return true;
  });
  el.innerHTML = "";
};
ATLAS.unitLabel = function (name, unit) { return name + " [" + (unit || "-") + "]"; };

// Frames by x (S or time): one slider shows, for each image, its frame at the largest x not above the slider's.
ATLAS.player = function (sets, imgs, slider, label, button, xName) {
  // Runs of other time steps reach an output at slightly other S: values closer than a quarter
  // of the finest output spacing are one slider step, and every run shows its frame there.
  var xs = [], tol = Infinity;
  sets.forEach(function (frames) {
    frames.forEach(function (f, i) {
      if (f[0] === null) f[0] = i;
      xs.push(f[0]);
      if (i > 0 && f[0] > frames[i - 1][0]) tol = Math.min(tol, 0.25 * (f[0] - frames[i - 1][0]));
    });
  });
  if (!isFinite(tol)) tol = 1e-9;
  xs = xs.sort(function (a, b) { return a - b; }).filter(function (v, i, a) { return i === 0 || v - a[i - 1] > tol; });
  slider.min = 0; slider.max = Math.max(0, xs.length - 1); slider.value = 0;
  var p = { xs: xs, onshow: null }, timer = null, preloaded = false;
  function show(i) {
    var v = xs[i];
    sets.forEach(function (frames, k) {
      var pick = frames[0];
      frames.forEach(function (f) { if (f[0] <= v + tol) pick = f; });
      if (pick && imgs[k].getAttribute("src") !== pick[1]) imgs[k].setAttribute("src", pick[1]);
    });
    label.textContent = xs.length ? xName + " = " + Number(v).toFixed(2) : "no frames";
    if (p.onshow) p.onshow(v);
  }
  function stop() { clearInterval(timer); timer = null; button.textContent = "▶ play"; }
  p.show = show;
  p.stop = stop;
  p.play = function () {
    if (timer) return stop();
    if (!preloaded) {  // only when played: opening a page loads one frame per image
      sets.forEach(function (frames) { frames.forEach(function (f) { new Image().src = f[1]; }); });
      preloaded = true;
    }
    if (+slider.value >= xs.length - 1) slider.value = 0;
    button.textContent = "❚❚ pause";
    timer = setInterval(function () {
      var i = +slider.value + 1;
      if (i > xs.length - 1) return stop();
      slider.value = i; show(i);
    }, 120);
  };
  slider.oninput = function () { show(+slider.value); };
  button.onclick = p.play;
  show(0);
  return p;
};

// Tables: click a header to sort (numbers by their data-sort value).
function sortTable(table, col, th) {
  var body = table.tBodies[0], rows = Array.from(body.rows);
  var dir = th.getAttribute("aria-sort") === "ascending" ? -1 : 1;
  table.querySelectorAll("th").forEach(function (h) { h.removeAttribute("aria-sort"); });
  th.setAttribute("aria-sort", dir > 0 ? "ascending" : "descending");
  var key = function (r) {
    var c = r.cells[col];
    if (!c) return "";
    var s = c.getAttribute("data-sort");
    if (s !== null && s !== "" && !isNaN(+s)) return +s;
    var t = c.textContent.trim().toLowerCase();
    return t === "" ? null : t;
  };
  rows.sort(function (a, b) {
    var x = key(a), y = key(b);
    if (x === null || y === null) return (x === null) - (y === null);  // empty cells last, either way
    if (typeof x !== typeof y) return (typeof x === "number" ? -1 : 1) * dir;
    return (x < y ? -1 : x > y ? 1 : 0) * dir;
  });
  rows.forEach(function (r) { body.appendChild(r); });
}

document.addEventListener("DOMContentLoaded", function () {
  document.querySelectorAll("table.sortable").forEach(function (t) {
    t.querySelectorAll("thead th").forEach(function (th, i) {
      th.addEventListener("click", function () { sortTable(t, i, th); });
    });
  });
  var b = document.getElementById("theme");
  if (b) b.addEventListener("click", function () {
    var t = document.documentElement.dataset.theme === "dark" ? "light" : "dark";
    document.documentElement.dataset.theme = t;
    try { localStorage.setItem("atlas-theme", t); } catch (e) { /* private mode: this page only */ }
    ATLAS.plots.forEach(draw);
  });
});
