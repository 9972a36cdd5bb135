"""A run's resolved config.toml as rows (key, value, doc) and as a flat {key: value} dict."""
import re
import tomllib

_SECTION = re.compile(r"^\[([^\]]+)\]\s*$")
_KEY = re.compile(r"^([A-Za-z0-9_]+)\s*=\s*(.*)$")


def rows(text):
    """[(section.key, value text, the comment above it)] in file order."""
    out, section, doc = [], "", []
    for line in text.splitlines():
        s = line.strip()
        if s.startswith("#"):
            doc.append(s.lstrip("#").strip())
        elif _SECTION.match(s):
            section, doc = _SECTION.match(s).group(1), []
        elif _KEY.match(s):
            m = _KEY.match(s)
            out.append(((section + "." if section else "") + m.group(1), m.group(2), " ".join(doc)))
            doc = []
        else:
            doc = []
    return out


def flat(text):
    """{section.key: value} parsed by tomllib ({} for a file that does not parse)."""
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError:
        return {}
    out = {}

    def walk(prefix, d):
        for k, v in d.items():
            if isinstance(v, dict):
                walk(prefix + k + ".", v)
            else:
                out[prefix + k] = v
    walk("", data)
    return out


def branch_of(text):
    """SOURCE:OUTPUT of a branch (its first line), or ''."""
    first = text.split("\n", 1)[0]
    m = re.match(r"# branch of (.*) \(orogen run --from\)", first)
    return m.group(1) if m else ""
