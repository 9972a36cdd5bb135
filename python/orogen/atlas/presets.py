"""Which examples/*.toml preset a run was started from: the preset whose every key the run's
resolved configuration has with the same value (keys that only set length, seed or display
excepted), the one with most keys when several fit; presets that are the same run (N(I) and
Experiment 3's mu_br = 2 mu_bp) are all named. A member of an ensemble is named by its plan."""
import glob
import os
import tomllib

from . import config_table

# Keys a user changes on a preset without making it another experiment.
_FREE = {"run.threads", "run.adapt_threads", "run.adapt_slice", "wedge.s_end", "wedge.outputs",
         "output.progress", "output.vtp", "output.checkpoint_every"}


def load(examples_dir):
    presets = []
    for path in sorted(glob.glob(os.path.join(examples_dir, "*.toml"))):
        with open(path, encoding="utf-8") as f:
            keys = config_table.flat(f.read())
        keys = {k: v for k, v in keys.items() if k not in _FREE}
        if keys:
            presets.append((os.path.basename(path)[:-5], keys))
    return presets


def match(presets, config):
    best, best_n = [], 0
    for name, keys in presets:
        if len(keys) >= best_n and all(config.get(k) == v for k, v in keys.items()):
            best, best_n = ([name] if len(keys) > best_n else best + [name]), len(keys)
    return " = ".join(best)


def ensemble_members(ensemble_dir):
    """{member name: its preset's name} from an ensemble's resolved plan, ensemble.toml."""
    try:
        with open(os.path.join(ensemble_dir, "ensemble.toml"), "rb") as f:
            plan = tomllib.load(f)
    except (OSError, tomllib.TOMLDecodeError):
        return {}
    return {m["name"]: os.path.basename(str(m["preset"])).removesuffix(".toml")
            for m in plan.get("member", []) if isinstance(m, dict) and "name" in m and m.get("preset")}
