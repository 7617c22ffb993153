"""A matplotlib figure written as a PNG atomically, for the plotting scripts (plot_*.py): the
figure goes to a temporary file beside the target, which is then renamed over it, so a reader
sees the old picture or the whole new one, never a part."""
import os
import tempfile


def save(fig, path, dpi=110):
    """Writes `fig` to `path` (a PNG) atomically and closes the figure."""
    import matplotlib.pyplot as plt  # after the script chose its backend

    folder = os.path.dirname(os.path.abspath(path))
    fd, tmp = tempfile.mkstemp(prefix=".plot-", suffix=".png", dir=folder)
    try:
        os.close(fd)
        # mkstemp makes the file private; a plot is as readable as any file the user writes.
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(tmp, 0o666 & ~umask)
        fig.savefig(tmp, dpi=dpi, format="png")
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise
    finally:
        plt.close(fig)
