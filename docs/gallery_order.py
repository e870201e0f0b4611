"""The order of the gallery's examples (``sphinx_gallery_conf["within_subsection_order"]``
in ``conf.py``): the end-to-end question first, then the paper, then the tools."""

from __future__ import annotations

ORDER = (
    "plot_is_my_statue_safe.py",
    "plot_paper_figure.py",
    "plot_overturning_spectrum.py",
    "plot_campaign_dask.py",
)


class GalleryOrder:
    """Sort key of sphinx-gallery: the files of :data:`ORDER` in that order, any other
    after them by name."""

    def __init__(self, src_dir: str):
        self.src_dir = src_dir

    def __call__(self, filename: str) -> tuple[int, str]:
        return (ORDER.index(filename) if filename in ORDER else len(ORDER), filename)

    def __repr__(self) -> str:
        return f"<{type(self).__name__}>"
