"""The page shell and small HTML pieces shared by every page."""
import html
import json

esc = html.escape

# Set before the styles load, so a dark page never flashes light.
_THEME = ("<script>(function(){var t=null;try{t=localStorage.getItem('atlas-theme')}catch(e){}"
          "if(!t)t=matchMedia('(prefers-color-scheme: dark)').matches?'dark':'light';"
          "document.documentElement.dataset.theme=t})();</script>")


def page(title, body, up="", scripts=(), page_data=None):
    """A whole page; `up` leads from the page's folder to the site root ('' or '../')."""
    data = "<script>ATLAS.page=%s;</script>" % json_for_script(page_data) if page_data is not None else ""
    tags = "".join('<script src="%s%s"></script>' % (up, s) for s in scripts)
    return (
        '<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8">'
        '<meta name="viewport" content="width=device-width, initial-scale=1">'
        "<title>%s · Orogen atlas</title>%s"
        '<link rel="stylesheet" href="%sassets/uPlot.min.css"><link rel="stylesheet" href="%sassets/atlas.css">'
        '<script src="%sassets/uPlot.iife.min.js"></script><script src="%sassets/atlas.js"></script>%s</head>'
        '<body><header class="top"><a class="brand" href="%sindex.html">Orogen atlas</a>'
        '<nav><a href="%sindex.html">Runs</a><a href="%scompare.html">Compare</a></nav>'
        '<button id="theme" type="button" title="light or dark theme">◐ theme</button></header>'
        "<main>%s</main>%s</body></html>\n"
        % (esc(title), _THEME, up, up, up, up, data, up, up, up, body, tags))


def json_for_script(value):
    """JSON that is safe inside a <script> element."""
    return json.dumps(value, separators=(",", ":"), allow_nan=False).replace("</", "<\\/")


def fmt(value):
    if value is None or value == "":
        return ""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return "%.4g" % value
    return str(value)


def table(headers, rows, cls="sortable", attrs=""):
    """headers: [text]; rows: [[(html, sort key or None)]]; sortable by clicking a header."""
    head = "".join('<th scope="col">%s</th>' % esc(h) for h in headers)
    body = []
    for row in rows:
        cells = []
        for content, key in row:
            k = ' data-sort="%s"' % esc(str(key)) if key is not None else ""
            if isinstance(key, (int, float)) and not isinstance(key, bool):
                k += ' class="num"'  # numbers right-aligned, text left
            cells.append("<td%s>%s</td>" % (k, content))
        body.append("<tr>%s</tr>" % "".join(cells))
    return ('<div class="scroll"><table class="%s"%s><thead><tr>%s</tr></thead><tbody>%s</tbody></table></div>'
            % (cls, attrs, head, "".join(body)))


def cell(value):
    """(html, sort key) of a value: numbers sort as numbers."""
    key = value if isinstance(value, (int, float)) and not isinstance(value, bool) else None
    return (esc(fmt(value)), key)


def figure(src, title, fig, up=""):
    caption = esc(title) + (' <span class="fig">thesis %s</span>' % esc(fig) if fig else "")
    return ('<figure class="chart"><a href="%s%s"><img src="%s%s" alt="%s" loading="lazy"></a>'
            "<figcaption>%s</figcaption></figure>" % (up, esc(src), up, esc(src), esc(title), caption))


def markdown_tables(text):
    """A Markdown file of pipe tables and paragraphs (fits.md, cycles.md) as HTML."""
    out, rows = [], []

    def flush():
        if rows:
            head = rows[0]
            body = [r for r in rows[1:] if not all(set(c.strip()) <= set("-: ") for c in r)]
            out.append(table(head, [[(esc(c), None) for c in r] for r in body], cls="plain"))
            rows.clear()
    for line in text.splitlines():
        s = line.strip()
        if s.startswith("|"):
            rows.append([c.strip() for c in s.strip("|").split("|")])
            continue
        flush()
        if s.startswith("#"):
            out.append("<h4>%s</h4>" % esc(s.lstrip("# ")))
        elif s:
            out.append("<p>%s</p>" % esc(s))
    flush()
    return "".join(out)
