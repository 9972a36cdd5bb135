"""Files written whole: a temporary name in the same folder, then a rename, so a reader (or
a killed build) never sees half a page."""
import os
import shutil


def write_text(path, text):
    os.makedirs(os.path.dirname(path) or ".", exist_ok=True)
    tmp = "%s.tmp-%d" % (path, os.getpid())
    with open(tmp, "w", encoding="utf-8") as f:
        f.write(text)
    os.replace(tmp, path)


def place_file(src, dst):
    """dst becomes src's content: a hard link where the file system allows (instant, no space),
    else a copy; an up-to-date dst is left alone."""
    try:
        s, d = os.stat(src), os.stat(dst)
        if (s.st_ino == d.st_ino and s.st_dev == d.st_dev) or (s.st_size == d.st_size and s.st_mtime_ns <= d.st_mtime_ns):
            return
    except FileNotFoundError:
        pass
    os.makedirs(os.path.dirname(dst), exist_ok=True)
    tmp = "%s.tmp-%d" % (dst, os.getpid())
    try:
        os.link(src, tmp)
    except OSError:
        shutil.copy2(src, tmp)
    os.replace(tmp, dst)
