// A run page: its frame players and its series as charts, from data/run_SLUG.js.
"use strict";
(function () {
  var data = ATLAS.runs[ATLAS.page.slug];
  if (!data) throw new Error("no data for run " + ATLAS.page.slug);
  var xName = data.x;

  document.querySelectorAll("figure.player").forEach(function (fig) {
    var set = data.frames[fig.getAttribute("data-frames")];
    ATLAS.player([set.frames.map(function (f) { return [f[0], "../" + f[1]]; })], [fig.querySelector("img")],
                 fig.querySelector("input[type=range]"), fig.querySelector(".at"), fig.querySelector(".play"), xName);
  });

  var s = data.series;
  if (!s || !s.columns) return;
  var units = s.units || {};
  // Wedge series by what they measure (thesis figures); anything else by its unit.
  var groups = [
    { title: "Height and peak position", cols: ["H", "T"], fig: "Figs 4.6, 4.9, 4.11" },
    { title: "Fronts", cols: ["Dp", "Mp", "Dr", "Mr"], fig: "Fig 5.14" },
    { title: "Tapers", cols: ["alpha", "beta", "alpha_fit", "beta_fit"], fig: "Figs 4.7, 4.12" },
    { title: "Basal contacts at the Coulomb limit", cols: ["slip_pro", "slip_retro"] },
    { title: "Discs", cols: ["n_active", "n_discs", "n_eroded", "n_left", "n_entered"] },
    { title: "Active region", cols: ["window_pro", "window_retro"] }
  ];
  var used = { step: 1, time: 1 };
  used[xName] = 1;
  groups = groups.map(function (g) {
    g.cols = g.cols.filter(function (c) { return s.columns.indexOf(c) >= 0; });
    g.cols.forEach(function (c) { used[c] = 1; });
    return g;
  }).filter(function (g) { return g.cols.length; });
  var byUnit = {};
  s.columns.forEach(function (c) {
    if (used[c]) return;
    var u = units[c] || "-";
    (byUnit[u] = byUnit[u] || []).push(c);
  });
  Object.keys(byUnit).forEach(function (u) { groups.push({ title: byUnit[u].join(", "), cols: byUnit[u] }); });

  var el = document.getElementById("plots");
  groups.forEach(function (g) {
    var gu = Array.from(new Set(g.cols.map(function (c) { return units[c] || "-"; })));
    ATLAS.plot(el, {
      title: g.title, fig: g.fig, x: s.data[xName], xLabel: ATLAS.unitLabel(xName, units[xName]),
      yLabel: (gu.length === 1 && g.cols.length <= 4 ? g.cols.join(", ") + " " : "") + "[" + gu.join(", ") + "]",
      series: g.cols.map(function (c) {
        return { label: c + " [" + (units[c] || "-") + "]", values: s.data[c], dash: /_fit$/.test(c) ? [6, 4] : undefined };
      })
    });
  });
})();
