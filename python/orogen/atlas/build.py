"""Builds or updates the site: run pages only for runs whose files changed since the last
build (manifest.json), then the index, compare page, catalog and group pages, which are cheap."""
import json
import os
import shutil
import time

from . import discover, manifest, page_compare, page_group, page_index, page_run, presets, run_info
from ..atomic import place_file, write_text
from .markup import json_for_script

HERE = os.path.dirname(os.path.abspath(__file__))
EXAMPLES = os.path.join(os.path.dirname(os.path.dirname(HERE)), "examples")
ASSETS = [("assets", n) for n in ("atlas.css", "atlas.js", "index.js", "run.js", "compare.js")] + \
         [("vendor", n) for n in ("uPlot.iife.min.js", "uPlot.min.css", "uPlot.LICENSE")]


def _unique_slugs(runs):
    seen, out = set(), []
    for _, rel, _ in runs:
        s, k = discover.slug(rel), 2
        while s in seen:
            s, k = "%s-%d" % (discover.slug(rel), k), k + 1
        seen.add(s)
        out.append(s)
    return out


def build(root, site, log=print):
    t0 = time.monotonic()
    os.makedirs(site, exist_ok=True)
    for sub, name in ASSETS:
        place_file(os.path.join(HERE, sub, name), os.path.join(site, "assets", name))
    runs, groups = discover.find(root, site)
    old = manifest.load(site)
    new = {"runs": {}}
    preset_list = presets.load(EXAMPLES)
    member_presets = {rel: presets.ensemble_members(path) for path, rel, kind in groups if kind == "ensemble"}
    infos, rebuilt = [], 0
    for (run_dir, rel, group), slug in zip(runs, _unique_slugs(runs)):
        sig = manifest.signature(run_dir)
        prev = old.get("runs", {}).get(slug)
        page_path = os.path.join(site, "runs", slug + ".html")
        if prev and prev.get("signature") == sig and os.path.isfile(page_path):
            info = prev["info"]
        else:
            try:  # a run being written or damaged is skipped, said, and tried again next time
                info = run_info.read(run_dir, rel, group, preset_list)
                series = run_info.series(run_dir)
            except (OSError, ValueError) as e:
                log("atlas: skipped %s: %s" % (run_dir, e))
                continue
            info["preset"] = member_presets.get(group, {}).get(os.path.basename(run_dir)) or info["preset"]
            for f in page_run.files_to_place(info):
                place_file(os.path.join(run_dir, f), os.path.join(site, "runs", slug, f))
            data = page_run.data(slug, info, series)
            write_text(os.path.join(site, "data", "run_%s.js" % slug),
                       "ATLAS.add(%s);\n" % json_for_script(data))
            write_text(page_path, page_run.build(slug, info, run_dir, site))
            rebuilt += 1
        new["runs"][slug] = {"signature": sig, "dir": run_dir,
                             "info": {k: v for k, v in info.items() if k != "config_rows"} | {"config_rows": []}}
        infos.append((slug, info))
    _remove_gone(site, old, new)
    known = {slug for slug, _ in infos}
    group_rows = []
    for group_dir, rel, kind in groups:
        slug = discover.slug(rel)
        write_text(os.path.join(site, "groups", slug + ".html"),
                   page_group.build(group_dir, rel, kind, site, known, place_file, infos))
        group_rows.append((slug, rel, kind, sum(1 for _, i in infos if i["group"] == rel)))
    _remove_gone_groups(site, {slug for slug, _, _, _ in group_rows})
    catalog = [{"slug": s, "name": i["rel"], "experiment": i["experiment"], "status": i["status"],
                "frames": list(i["frames"])} for s, i in infos]
    write_text(os.path.join(site, "data", "catalog.js"), "ATLAS.catalog = %s;\n" % json_for_script(catalog))
    write_text(os.path.join(site, "index.html"), page_index.build(infos, group_rows))
    write_text(os.path.join(site, "compare.html"), page_compare.build())
    write_text(os.path.join(site, manifest.NAME), json.dumps(new, indent=0, allow_nan=False))
    log("atlas: %d runs (%d pages rebuilt), %d sweeps/ensembles, in %.1f s: %s"
        % (len(infos), rebuilt, len(groups), time.monotonic() - t0, os.path.join(site, "index.html")))
    if not runs:
        log("atlas: no run folder under %s (a run folder holds config.toml beside series.csv or snapshots.h5; "
            "symbolic links to folders are followed)" % root)
    return 0


def _remove_gone(site, old, new):
    """A run folder that is gone takes its page, data and files with it."""
    for slug in set(old.get("runs", {})) - set(new["runs"]):
        for path in (os.path.join(site, "runs", slug + ".html"), os.path.join(site, "data", "run_%s.js" % slug)):
            if os.path.isfile(path):
                os.remove(path)
        shutil.rmtree(os.path.join(site, "runs", slug), ignore_errors=True)


def _remove_gone_groups(site, kept):
    folder = os.path.join(site, "groups")
    if not os.path.isdir(folder):
        return
    for name in os.listdir(folder):
        slug = name[:-5] if name.endswith(".html") else name
        if slug not in kept:
            path = os.path.join(folder, name)
            shutil.rmtree(path) if os.path.isdir(path) else os.remove(path)
