"""groups/SLUG.html: a sweep or an ensemble: its results table (run names linked to their
pages), and for an ensemble the chapter-5 statistics (Table 5.1, envelopes) where computed."""
import os

from . import csv_series, figures
from .discover import slug as slug_of
from .markup import cell, esc, figure, markdown_tables, page, table


def _results(group_dir, rel, kind, known):
    path = os.path.join(group_dir, "results.csv")
    if not os.path.isfile(path):
        return "<p class=\"muted\">No results.csv yet.</p>"
    t = csv_series.read(path)
    sub = "runs" if kind == "sweep" else "members"
    headers = [c + (" [%s]" % t["units"][c] if t["units"].get(c) not in (None, "", "-") else "") for c in t["columns"]]
    rows = []
    for r in t["rows"]:
        row = []
        for i, c in enumerate(t["columns"]):
            v = r[i] if i < len(r) else ""
            if i == 0:
                s = slug_of(os.path.join(rel, sub, v))
                row.append(('<a href="../runs/%s.html">%s</a>' % (esc(s), esc(v)) if s in known else esc(v), v))
            else:
                n = csv_series.number(v)
                row.append(cell(n) if n is not None else (esc(v), None))
        rows.append(row)
    return table(headers, rows)


def _aggregate(group_dir, site_dir, place):
    """Table 5.1 (fits.md), cycles and the ensemble charts of aggregate/ and aggregate/GROUP/."""
    base = os.path.join(group_dir, "aggregate")
    if not os.path.isdir(base):
        return ""
    parts = []
    for here, dirs, files in sorted(os.walk(base)):
        dirs.sort()
        sub = os.path.relpath(here, base)
        if os.path.basename(here) == "charts":
            continue
        head = "" if sub == "." else " — " + sub
        if "fits.md" in files:
            with open(os.path.join(here, "fits.md"), encoding="utf-8") as f:
                parts.append("<h3>Fits and trends%s <span class=\"fig\">thesis Table 5.1</span></h3>%s"
                             % (esc(head), markdown_tables(f.read())))
        if "cycles.md" in files:
            with open(os.path.join(here, "cycles.md"), encoding="utf-8") as f:
                parts.append("<h3>Thrust cycles%s</h3>%s" % (esc(head), markdown_tables(f.read())))
        charts = os.path.join(here, "charts")
        if os.path.isdir(charts):
            figs = []
            for name in sorted(os.listdir(charts)):
                if name.endswith(".png") and not name.startswith("."):
                    dst = os.path.join(site_dir, os.path.relpath(os.path.join(charts, name), group_dir))
                    place(os.path.join(charts, name), dst)
                    title, fig = figures.chart(name)
                    figs.append(figure(os.path.relpath(dst, os.path.dirname(site_dir)), title, fig))
            parts.append("<h3>Charts%s</h3><div class=\"charts\">%s</div>" % (esc(head), "".join(figs)))
    if not parts:
        return ""
    return "<h2>Statistics <span class=\"muted\">(aggregate/)</span></h2>" + "".join(parts)


# The exhumation figures shown per member on a group page (all are on the member's page).
EXHUMATION_HEADLINE = ("charts/exhumation/spacetime_max_depth.png", "charts/exhumation/spacetime_surface_age.png",
                       "charts/exhumation/flux.png")


def _exhumation(rel, infos):
    """The members' key exhumation figures side by side, where `orogen analyze` and the charts ran."""
    parts = []
    for slug, info in infos:
        if info["group"] != rel:
            continue
        have = {c[0]: c for c in info["charts"]}
        figs = [figure("../runs/%s/%s" % (slug, path), "%s: %s" % (info["name"], have[path][1]), have[path][2])
                for path in EXHUMATION_HEADLINE if path in have]
        if figs:
            parts.append("<div class=\"charts\">%s</div>" % "".join(figs))
    if not parts:
        return ""
    return ("<h2>Exhumation</h2><p class=\"muted\">Each member's maximum depth and surface age in space and "
            "time and its flux balance; every exhumation figure is on the member's page.</p>" + "".join(parts))


def build(group_dir, rel, kind, site, known, place, infos=()):
    slug = slug_of(rel)
    site_dir = os.path.join(site, "groups", slug)
    body = ("<h1>%s <span class=\"muted\">%s</span></h1>" % (esc(rel), kind)
            + "<h2>Results</h2>" + _results(group_dir, rel, kind, known)
            + (_aggregate(group_dir, site_dir, place) if kind == "ensemble" else "")
            + _exhumation(rel, infos))
    links = []
    for name in ("results.csv", "results.md", "members.csv"):
        if os.path.isfile(os.path.join(group_dir, name)):
            place(os.path.join(group_dir, name), os.path.join(site_dir, name))
            links.append('<a href="%s/%s">%s</a>' % (esc(slug), name, name))
    if links:
        body += "<p>Files: %s</p>" % " · ".join(links)
    return page(rel, body, up="../", page_data={"kind": kind})
