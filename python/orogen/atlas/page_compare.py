"""compare.html: two to four runs one above the other, their animations on one slider of S,
their series overlaid. The menus come from data/catalog.js; a run's data file loads when picked."""
from .markup import page


def build():
    pickers = "".join('<select class="pick" id="pick%d" aria-label="run %d"></select>' % (k, k + 1) for k in range(4))
    body = ('<h1>Compare runs</h1><p class="muted">Pick two to four runs; one slider plays their animations '
            "together: each shows its frame at the same S (or time, for runs without S), one above the other. "
            "Cross-sections drawn together (<code>orogen sections RUN1 RUN2 ...</code>) share one x-range, "
            "exaggeration and colour scale, so that they line up. The URL keeps the choice, to share it.</p>"
            '<div class="controls">%s</div>'
            '<div class="controls"><label>animation <select id="anim"></select></label>'
            '<button type="button" id="play">▶ play</button>'
            '<input type="range" id="slider" min="0" max="0" value="0" aria-label="S">'
            '<span id="at" class="at"></span></div>'
            '<div id="panels" class="panels"></div>'
            '<h2>Series overlaid</h2><div class="controls"><label>series <select id="column"></select></label></div>'
            '<div id="overlay" class="plots"></div>' % pickers)
    return page("Compare", body, scripts=["data/catalog.js", "assets/compare.js"], page_data={"kind": "compare"})
