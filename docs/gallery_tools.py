"""Helpers of the gallery (``sphinx_gallery_conf`` in ``conf.py``, named there by string
so that the configuration stays picklable).

* :class:`GalleryOrder`: the order of the examples (``within_subsection_order``): the
  end-to-end question first, then the paper, then the tools.
* :func:`figure_scraper`: an image scraper for the figures that ``rocking``'s plotting
  functions return. They build a :class:`matplotlib.figure.Figure` without touching
  pyplot's state (so that a library call never leaks figures), which the stock matplotlib
  scraper (``plt.get_fignums()``) does not see: this one saves every new ``Figure`` bound
  to a top-level name of the example after each code block (it runs before the
  matplotlib scraper, which then saves and closes the pyplot figures).
"""

from __future__ import annotations

ORDER = (
    "plot_is_my_statue_safe.py",
    "plot_paper_figure.py",
    "plot_overturning_spectrum.py",
    "plot_campaign_dask.py",
)


class GalleryOrder:
    """Sort key: the files of :data:`ORDER` in that order, any other after them by name."""

    def __init__(self, src_dir: str):
        self.src_dir = src_dir

    def __call__(self, filename: str) -> tuple[int, str]:
        return (ORDER.index(filename) if filename in ORDER else len(ORDER), filename)

    def __repr__(self) -> str:
        return f"<{type(self).__name__}>"


_SEEN: dict[str, list] = {}      # example file -> the Figures already saved (kept alive)


def figure_scraper(block, block_vars, gallery_conf, **kwargs):
    """Save the new pyplot-less Figures of the example's globals (see the module doc)."""
    from matplotlib.figure import Figure
    from sphinx_gallery.scrapers import figure_rst

    src = str(block_vars.get("src_file", ""))
    seen = _SEEN.setdefault(src, [])
    paths = []
    for value in list(block_vars["example_globals"].values()):
        if not isinstance(value, Figure) or any(value is s for s in seen):
            continue
        seen.append(value)
        # a pyplot figure (it has a manager until the matplotlib scraper, which runs
        # after this one, saves and closes it) is that scraper's
        if getattr(value.canvas, "manager", None) is None:
            path = next(block_vars["image_path_iterator"])
            value.savefig(path, dpi=100, bbox_inches="tight")
            paths.append(path)
    return figure_rst(paths, gallery_conf["src_dir"])


def _get_sg_image_scraper():
    """sphinx-gallery's hook for ``image_scrapers = ("gallery_tools", ...)``."""
    return figure_scraper
