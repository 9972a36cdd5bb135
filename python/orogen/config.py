"""Configurations from a TOML file, a dict, or both, through the CLI's own strict checks.

A dict is nested ({"wedge": {"s_end": 2}}) or dotted ({"wedge.s_end": 2}); each key becomes the
`--set section.key=value` of `orogen run`, so the same mistakes raise the same message, here as
orogen.ConfigError (a ValueError) naming where, the key, the value and what is allowed.
"""

import json
import math
from pathlib import Path

from ._engine import _orogen

ConfigError = _orogen.ConfigError


def _literal(value):
    """A TOML literal of a Python value (what `--set key=VALUE` takes)."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        if math.isnan(value):
            return "nan"
        if math.isinf(value):
            return "inf" if value > 0 else "-inf"
        return repr(value)  # round-trips the double exactly
    if isinstance(value, (str, Path)):
        return json.dumps(str(value))  # a TOML basic string
    raise ConfigError(f"config error in the dict: value {value!r} of type {type(value).__name__}: "
                      "expected a bool, int, float or string")


def overrides(settings):
    """["section.key=value", ...] from a nested or dotted dict."""
    out = []
    for key, value in (settings or {}).items():
        if isinstance(value, dict):
            out += [f"{key}.{item}" for item in overrides(value)]
        else:
            out.append(f"{key}={_literal(value)}")
    return out


def split(config):
    """(TOML file or None, dict) from what run() and Simulation() accept as `config`."""
    if config is None:
        return None, {}
    if isinstance(config, (str, Path)):
        return Path(config), {}
    if isinstance(config, dict):
        return None, config
    raise TypeError(f"config: expected a TOML file path, a dict or None, got {type(config).__name__}")


def load_config(config=None, set=None):
    """The checked configuration (an _orogen.Config): `config` a TOML path, a dict or None (the
    defaults), `set` a dict of further keys that win, as --set does. Raises ConfigError."""
    file, settings = split(config)
    return _orogen.Config.load(file, overrides(settings) + overrides(set))


def resolved_toml(config=None, set=None):
    """The resolved configuration as the text config.toml would hold."""
    return load_config(config, set).to_toml()
