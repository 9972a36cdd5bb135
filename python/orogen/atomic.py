"""Files written whole: a temporary name in the destination's folder, then a rename, so that a
reader (a viewer, the atlas, a killed script's next run) never sees half a file. The package's
one writer: charts, statistics, the atlas and the frames all write through it."""

import contextlib
import os
import shutil
import tempfile


def _umask_mode():
    mask = os.umask(0)
    os.umask(mask)
    return 0o666 & ~mask


@contextlib.contextmanager
def temporary_path(path, suffix=".tmp", ordinary_mode=True):
    """Yields a fresh temporary path beside `path` for a writer of its own (ffmpeg, savefig);
    renamed to `path` when the block ends normally, removed when it raises. The suffix keeps
    the extension for writers that choose the format by it; ordinary_mode=False leaves the
    file's permissions alone (a hard link shares them with its source)."""
    folder = os.path.dirname(os.path.abspath(path))
    os.makedirs(folder, exist_ok=True)
    fd, tmp = tempfile.mkstemp(prefix=".tmp-", suffix=suffix, dir=folder)
    os.close(fd)
    try:
        yield tmp
        if ordinary_mode:
            os.chmod(tmp, _umask_mode())  # mkstemp makes 0600; give the file ordinary permissions
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise


def write_atomically(path, write, binary=False, suffix=".tmp"):
    """Calls write(file) on a temporary file beside path, then renames it to path."""
    with temporary_path(path, suffix) as tmp:
        with open(tmp, "wb" if binary else "w", **({} if binary else {"encoding": "utf-8", "newline": ""})) as f:
            write(f)


def write_text(path, text):
    write_atomically(path, lambda f: f.write(text))


def save_figure(fig, path, fmt="png", dpi=110, metadata=None):
    """Writes a matplotlib figure (PNG at 110 dpi unless told otherwise) atomically, then closes it."""
    import matplotlib.pyplot as plt  # only the charts call this; they set the backend
    try:
        write_atomically(path, lambda f: fig.savefig(f, format=fmt, dpi=dpi, metadata=metadata), binary=True,
                         suffix="." + fmt)
    finally:
        plt.close(fig)


def place_file(src, dst):
    """dst becomes src's content: a hard link where the file system allows (instant, no space),
    else a copy; an up-to-date dst is left alone."""
    try:
        s, d = os.stat(src), os.stat(dst)
        if (s.st_ino == d.st_ino and s.st_dev == d.st_dev) or (s.st_size == d.st_size and s.st_mtime_ns <= d.st_mtime_ns):
            return
    except FileNotFoundError:
        pass
    with temporary_path(dst, ordinary_mode=False) as tmp:
        os.unlink(tmp)
        try:
            os.link(src, tmp)
        except OSError:
            shutil.copy2(src, tmp)
