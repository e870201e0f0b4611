"""The reproduction report: page structure, files, CSV tables and Table II arithmetic."""

from __future__ import annotations

import math
import re
import time
from html.parser import HTMLParser
from pathlib import Path

import pandas as pd
import pytest

import rocking
from rocking.blocks.specimens import paper_data
from rocking.report import SECTIONS, ReportError, reproduce, section
from rocking.report.core import ordered_sections

FREQS = [0.5, 1.0, 1.5, 2.0, 2.5, 3.0, 3.3, 5.0]
AMPS = [3, 4, 5, 6, 8, 10, 12]


class _Links(HTMLParser):
    def __init__(self):
        super().__init__()
        self.refs: list[str] = []

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag == "img" and "src" in a:
            self.refs.append(a["src"])
        if tag == "a" and "href" in a:
            self.refs.append(a["href"])
        if tag in ("link", "script"):
            self.refs.append(a.get("href") or a.get("src") or "")


@pytest.fixture(scope="module")
def report(tmp_path_factory):
    out = tmp_path_factory.mktemp("report")
    t0 = time.perf_counter()
    index = reproduce(out, quick=True, progress=False)
    return out, index, time.perf_counter() - t0


def test_index_written(report):
    out, index, elapsed = report
    assert index == out / "index.html"
    assert index.is_file()
    assert elapsed < 60.0  # quick mode is meant for tests (< 30 s on 2 cores, with slack)


def test_page_references_only_existing_local_files(report):
    out, index, _ = report
    text = index.read_text(encoding="utf-8")
    parser = _Links()
    parser.feed(text)
    assert parser.refs, "the page should link its figures and CSV files"
    for ref in parser.refs:
        if ref.startswith("#"):
            anchor = ref[1:]
            assert f'id="{anchor}"' in text, ref
            continue
        assert not re.match(r"^[a-z]+:", ref), f"no network or absolute resources: {ref}"
        assert (out / ref).is_file(), f"missing file referenced by the page: {ref}"
    assert "<script" not in text.lower()


def test_page_header_and_sections(report):
    _, index, _ = report
    text = index.read_text(encoding="utf-8")
    assert "Peña" in text or "Pena" in text
    assert paper_data()["source"].split(".")[0] in text  # the full citation
    assert rocking.__version__ in text
    assert "Sign convention" in text
    assert "Contents" in text
    for sec in ordered_sections():
        assert f'id="{sec.id}"' in text
        assert sec.title.split(" — ")[0] in text
    for title in ("Table II", "Table IV", "Figure 7"):
        assert title in text
    assert 'class="error"' not in text


def test_every_figure_is_a_png(report):
    out, _, _ = report
    pngs = sorted(out.glob("*.png"))
    names = {p.name for p in pngs}
    assert {"table4_map.png", "table4_ratio.png", "figure7_theta.png"} <= names
    for p in pngs:
        assert p.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_table2_csv(report):
    out, _, _ = report
    df = pd.read_csv(out / "table2_parameters.csv")
    assert list(df["specimen"]) == [1, 2, 3, 4]
    data = paper_data()["specimens"]
    for _, row in df.iterrows():
        n = int(row["specimen"])
        geo = rocking.specimen(n, "geometric")
        for k in ("alpha", "mu", "p"):
            paper = data[str(n)]["theoretical"][k]
            ours = getattr(geo, k)
            assert row[f"{k}_paper_T"] == pytest.approx(paper)
            assert row[f"{k}_paper_E"] == pytest.approx(data[str(n)]["experimental"][k])
            assert row[f"{k}_ours"] == pytest.approx(ours, rel=1e-5)
            assert row[f"{k}_diff_pct"] == pytest.approx((ours - paper) / paper * 100, abs=1e-3)


def test_table2_known_values(report):
    """Independent arithmetic: specimen 1 alpha = atan(0.125/0.5); specimen 4 from Table I."""
    out, _, _ = report
    df = pd.read_csv(out / "table2_parameters.csv").set_index("specimen")
    assert df.loc[1, "alpha_ours"] == pytest.approx(math.atan(0.125 / 0.5), rel=1e-5)
    a4 = math.atan(0.08 / 0.2285)
    assert df.loc[4, "alpha_ours"] == pytest.approx(a4, rel=1e-5)
    R4 = math.hypot(0.08, 0.2285)
    assert df.loc[4, "p_ours"] == pytest.approx(math.sqrt(3 * 9.80665 / (4 * R4)), rel=1e-5)
    assert df.loc[4, "mu_ours"] == pytest.approx(1 - 1.5 * math.sin(a4) ** 2, rel=1e-5)
    ck = pd.read_csv(out / "table2_consistency.csv").set_index("specimen")
    # Eq 3 with the tabulated I_O of Table I
    M, I = 503.0, 179.0
    R1 = math.hypot(0.125, 0.5)
    assert ck.loc[1, "p_eq3_table1_IO"] == pytest.approx(math.sqrt(M * 9.80665 * R1 / I),
                                                         rel=1e-5)


def test_table4_csv(report):
    out, _, _ = report
    grid = pd.read_csv(out / "table4_grid.csv", keep_default_na=False)
    assert len(grid) == len(FREQS) * len(AMPS)
    assert sorted(set(grid["freq_hz"].astype(float))) == FREQS
    assert sorted(set(grid["amp_mm"].astype(int))) == AMPS
    assert not grid.duplicated(["freq_hz", "amp_mm"]).any()
    # measured column: exactly the tested cells of the paper
    meas = paper_data()["table4"]["rows"]
    n_tested = sum(len(r) for r in meas.values())
    assert (grid["measured"] != "").sum() == n_tested
    # outcome labels are consistent with the numeric columns
    for _, r in grid.iterrows():
        if r["ours"] == "OVT":
            assert str(r["ours_overturned"]) == "True"
        elif r["ours"] == "N-R":
            assert str(r["ours_uplifted"]) == "False"
        else:
            assert float(r["ours"]) == pytest.approx(float(r["ours_max_deg"]), abs=0.006)
    # physics sanity: no uplift where the nominal acceleration is below g tan(alpha)
    below = grid[grid["acc_ratio"].astype(float) < 1.0]
    assert (below["ours"] == "N-R").all()
    wide = pd.read_csv(out / "table4_ours_vs_measured.csv")
    assert wide.shape == (len(FREQS), 1 + len(AMPS))
    cells = pd.read_csv(out / "table4_measured_cells.csv")
    assert len(cells) == n_tested


def test_figure7_csv(report):
    out, _, _ = report
    df = pd.read_csv(out / "figure7_summary.csv").set_index("quantity")
    assert df.loc["max_abs_theta_deg", "paper_measured"] == pytest.approx(1.14)
    ours = df.loc["max_abs_theta_deg", "ours_experimental_params"]
    r = rocking.simulate(rocking.specimen(2, "experimental"),
                         rocking.motions.Sine(5.0, 0.005, 25.0))
    assert ours == pytest.approx(math.degrees(r.max_abs_theta), rel=1e-5)
    hist = pd.read_csv(out / "figure7_theta_history.csv")
    assert list(hist.columns) == ["t_s", "theta_deg"]
    assert hist["t_s"].iloc[-1] == pytest.approx(25.0)


def test_failing_section_is_reported_and_raises(tmp_path):
    @section("zz_boom", "A section that fails", order=999)
    def _boom(ctx):
        ctx.path("partial.txt").write_text("written before failing")
        raise ValueError("deliberate failure")

    try:
        with pytest.raises(ReportError) as ei:
            reproduce(tmp_path, quick=True, progress=False, only=["table2", "zz_boom"])
    finally:
        SECTIONS.pop("zz_boom", None)
    assert ei.value.failed.keys() == {"zz_boom"}
    assert isinstance(ei.value, RuntimeError)
    page = (tmp_path / "index.html").read_text(encoding="utf-8")
    assert 'class="error"' in page and "deliberate failure" in page
    assert "Table II" in page  # the other section still ran
    assert Path(ei.value.path) == tmp_path / "index.html"


def test_progress_lines_on_stderr(tmp_path, capsys):
    reproduce(tmp_path, quick=True, progress=True, only="table2")
    err = capsys.readouterr().err
    assert re.search(r"\[1/1\] Table II .* ok .* s", err)


def test_unknown_section_rejected(tmp_path):
    with pytest.raises(ValueError, match="unknown report section"):
        reproduce(tmp_path, only=["nope"], progress=False)
