"""runs/SLUG.html: one run, and data/run_SLUG.js, the data its scripts draw."""
import os

from . import figures
from .discover import slug as group_slug
from .markup import esc, figure, fmt, page, table

# Raw files that stay in the run folder (large, or pointing at other files beside them).
IN_PLACE = {"analysis.h5", "snapshots.h5", "snapshots.xmf", "run.pvd", "packing.h5"}


def files_to_place(info):
    """[(path in the run folder)] copied or linked into the site: frames, animations, charts, small raw files."""
    out = []
    for folder, idx in info["frames"].items():
        out += ["%s/frame_%06d.png" % (folder, k) for k in idx]
    for _, gif, mp4 in info["animations"]:
        out += [f for f in (gif, mp4) if f]
    out += [c[0] for c in info["charts"]]
    out += [f for f in info["raw"] if f not in IN_PLACE]
    return out


def data(slug, info, series):
    """The run's data file content: frames by S (or time) and the series."""
    xcol = "S" if series and "S" in series["columns"] else "time"
    xs = series["data"].get(xcol, []) if series else []
    frames = {}
    for folder, idx in info["frames"].items():
        title, fig = figures.animation(folder)
        frames[folder] = {"title": title, "fig": fig,
                          "frames": [[xs[k] if k < len(xs) else None, "runs/%s/%s/frame_%06d.png" % (slug, folder, k)]
                                     for k in idx]}
    return {"slug": slug, "name": info["rel"], "experiment": info["experiment"], "x": xcol, "frames": frames,
            "series": series}


def build(slug, info, run_dir, site):
    up = "../"
    files = "runs/%s/" % slug
    parts = ["<h1>%s</h1>" % esc(info["rel"])]
    facts = [("experiment", info["experiment"]), ("preset", info["preset"]), ("status", info["status"]),
             ("wall time [s]", round(info["wall_s"], 1) if info["wall_s"] is not None else None),
             ("branch of", info["branch"])]
    facts += list(info["params"].items())
    facts += [(k, v) for k, v in info["results"].items()]
    dl = "".join("<div><dt>%s</dt><dd>%s</dd></div>" % (esc(k), esc(fmt(v))) for k, v in facts if v not in (None, ""))
    if info["group"]:
        dl += '<div><dt>part of</dt><dd><a href="%sgroups/%s.html">%s</a></dd></div>' % (
            up, esc(group_slug(info["group"])), esc(info["group"]))
    parts.append('<dl class="facts">%s</dl>' % dl)
    parts.append('<p><a href="%scompare.html#%s">Compare this run with others</a></p>' % (up, esc(slug)))
    if info["animations"]:
        parts.append("<h2>Animations</h2><p class=\"muted\">Drag the slider or play; the label gives the "
                     "output's S. The GIF and MP4 are the same frames.</p><div class=\"players\">")
        for folder, gif, mp4 in info["animations"]:
            title, fig = figures.animation(folder)
            links = " ".join('<a href="%s%s%s">%s</a>' % (up, files, esc(f), f.rsplit(".", 1)[1].upper())
                             for f in (gif, mp4) if f)
            parts.append('<figure class="player" data-frames="%s"><div class="frame"><img alt="%s"></div>'
                         '<div class="player-controls"><button type="button" class="play">▶ play</button>'
                         '<input type="range" min="0" max="0" value="0" aria-label="output"><span class="at"></span>'
                         "</div><figcaption>%s%s %s</figcaption></figure>"
                         % (esc(folder), esc(title), esc(title),
                            ' <span class="fig">thesis %s</span>' % esc(fig) if fig else "", links))
        parts.append("</div>")
    parts.append('<h2>Series</h2><p class="muted">Drag across a chart to zoom, double-click to reset; the '
                 'values under the cursor are in the legend.</p><div id="plots" class="plots"></div>')
    if info["charts"]:
        by_folder = {}
        for path, title, fig in info["charts"]:
            by_folder.setdefault(os.path.dirname(path), []).append(figure(files + path, title, fig, up))
        for folder, figs in by_folder.items():
            heading = "Exhumation figures" if folder.endswith("exhumation") else "Charts"
            parts.append("<h2>%s</h2><div class=\"charts\">%s</div>" % (heading, "".join(figs)))
    raw = []
    for f in info["raw"]:
        href = os.path.relpath(os.path.join(run_dir, f), os.path.join(site, "runs")) if f in IN_PLACE else files + f
        where = ' <span class="muted">(in the run folder)</span>' if f in IN_PLACE else ""
        raw.append('<li><a href="%s">%s</a>%s</li>' % (esc(href if f in IN_PLACE else up + href), esc(f), where))
    parts.append("<h2>Files</h2><ul class=\"files\">%s</ul>" % "".join(raw))
    rows = [[("<code>%s</code>" % esc(k), k), (esc(v), None), ('<span class="muted">%s</span>' % esc(d), None)]
            for k, v, d in info["config_rows"]]
    parts.append("<details><summary><h2>Configuration</h2> (resolved: every key)</summary>%s</details>"
                 % table(["key", "value", "meaning"], rows, cls="plain config"))
    return page(info["rel"], "".join(parts), up=up, scripts=["data/run_%s.js" % slug, "assets/run.js"],
                page_data={"kind": "run", "slug": slug})


