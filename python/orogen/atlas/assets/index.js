// The index: filter the runs table by any text, experiment and status.
"use strict";
(function () {
  var table = document.getElementById("runs"), q = document.getElementById("filter");
  var exp = document.getElementById("f-experiment"), st = document.getElementById("f-status");
  var count = document.getElementById("count");
  var head = Array.from(table.tHead.rows[0].cells).map(function (c) { return c.textContent; });
  var ie = head.indexOf("experiment"), is = head.indexOf("status");
  function apply() {
    var text = q.value.trim().toLowerCase(), shown = 0, rows = table.tBodies[0].rows;
    Array.from(rows).forEach(function (r) {
      var ok = (!text || r.textContent.toLowerCase().indexOf(text) >= 0) &&
               (!exp.value || r.cells[ie].textContent === exp.value) &&
               (!st.value || r.cells[is].textContent === st.value);
      r.hidden = !ok;
      if (ok) shown++;
    });
    count.textContent = shown + " of " + rows.length + " runs";
  }
  [q, exp, st].forEach(function (e) { e.addEventListener("input", apply); });
  apply();
})();
