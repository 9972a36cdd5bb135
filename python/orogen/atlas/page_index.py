"""index.html: every run in one sortable, filterable table, and the sweeps and ensembles."""
from .markup import cell, esc, page, table
from .run_info import PARAMS, RESULTS


def build(runs, groups):
    """runs: [(slug, info)], groups: [(slug, rel, kind, n_runs)]."""
    params = [label for label, _ in PARAMS if any(label in i["params"] for _, i in runs)]
    results = [label for label, _, _ in RESULTS if any(label in i["results"] for _, i in runs)]
    # The run's path names its sweep or ensemble; results before parameters, as a reader scans.
    headers = ["run", "experiment", "preset", "status", "wall time [s]"] + results + params
    rows = []
    for slug, i in runs:
        row = [('<a href="runs/%s.html">%s</a>' % (esc(slug), esc(i["rel"])), i["rel"]),
               cell(i["experiment"]), cell(i["preset"] or ("branch" if i["branch"] else "")),
               ('<span class="status %s">%s</span>' % (esc(i["status"]), esc(i["status"])), i["status"]),
               cell(round(i["wall_s"], 1) if i["wall_s"] is not None else None)]
        row += [cell(i["results"].get(r)) for r in results]
        row += [cell(i["params"].get(p)) for p in params]
        rows.append(row)
    experiments = sorted({i["experiment"] for _, i in runs})
    statuses = sorted({i["status"] for _, i in runs})
    options = lambda values: "".join('<option value="%s">%s</option>' % (esc(v), esc(v)) for v in values)  # noqa: E731
    controls = ('<div class="controls"><input id="filter" type="search" placeholder="filter runs (any text)" '
                'aria-label="filter runs"><select id="f-experiment" aria-label="experiment"><option value="">'
                'every experiment</option>%s</select><select id="f-status" aria-label="status"><option value="">'
                'every status</option>%s</select><span id="count"></span></div>'
                % (options(experiments), options(statuses)))
    group_list = ""
    if groups:
        items = "".join('<li><a href="groups/%s.html">%s</a> <span class="muted">%s, %d runs</span></li>'
                        % (esc(slug), esc(rel), esc(kind), n) for slug, rel, kind, n in groups)
        group_list = "<section><h2>Sweeps and ensembles</h2><ul class=\"groups\">%s</ul></section>" % items
    body = ("<h1>Runs <span class=\"muted\">%d</span></h1>%s%s%s"
            '<p class="muted">Click a header to sort; H, b and the tapers are from <code>summary.csv</code> '
            "(H and S at the end, b of H = a S<sup>b</sup> and the mean tapers over the last three quarters). "
            'Lengths in h0. <a href="compare.html">Compare runs side by side</a>.</p>'
            % (len(runs), controls, table(headers, rows, attrs=' id="runs"'), group_list))
    return page("Runs", body, scripts=["assets/index.js"], page_data={"kind": "index"})


