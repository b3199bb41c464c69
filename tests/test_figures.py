"""Figures a reader can trust: the check of sailmujoco.figures finds a legend over data, an axis
without a unit and text off the canvas; the colour scale of a heat map is not one cell's; a
robot's moment is in N m; the study and command figures pass the check (the smoke studies'
figures are checked as the other study tests run them: the check warns and pytest's config makes
that warning an error)."""

import warnings

import numpy as np
import pandas as pd
import pytest

from sailmujoco import figures


def _line_figure(**legend):
    plt = figures.pyplot()
    fig, ax = plt.subplots(figsize=(5, 4))
    x = np.linspace(0.0, 10.0, 200)
    ax.plot(x, np.full_like(x, 5.0), label="flat line at 5")  # crosses the middle of the axes
    ax.set_xlim(0, 10)
    ax.set_ylim(0, 10)
    ax.set_xlabel("time [s]")
    ax.set_ylabel("speed [m/s]")
    return plt, fig, ax


def test_a_legend_over_the_data_is_found_and_one_below_is_not():
    plt, fig, ax = _line_figure()
    ax.legend(loc="center left")
    found = figures.problems(fig)
    plt.close(fig)
    assert len(found) == 1 and "legend (flat line at 5) over" in found[0]

    plt, fig, ax = _line_figure()
    figures.legend_below(fig, ax)
    assert figures.problems(fig) == []
    plt.close(fig)


def test_an_axis_without_unit_and_text_off_the_canvas_are_found():
    plt, fig, ax = _line_figure()
    ax.set_xlabel("time")
    fig.text(1.05, 0.5, "a note off the right edge")
    found = figures.problems(fig)
    plt.close(fig)
    assert any("x label 'time' names no unit" in p for p in found)
    assert any("'a note off the right edge' outside the canvas" in p for p in found)
    assert not any("y label" in p for p in found)


def test_a_boxed_note_over_the_data_is_found():
    plt, fig, ax = _line_figure()
    ax.text(5.0, 5.0, "note on the line", ha="center", va="center", bbox=dict(facecolor="white"))
    found = figures.problems(fig)
    plt.close(fig)
    assert len(found) == 1 and "text 'note on the line' over" in found[0]


def test_robust_limits_leave_one_outlier_out_and_say_so():
    # 0..28 and one cell at -1000: the 2nd percentile of 30 values is the 2nd smallest (0), the
    # 98th the 2nd largest (27); both ends lie beyond, so both ends are clipped
    values = np.append(np.arange(29.0), -1000.0)
    assert figures.robust_limits(values) == (0.0, 27.0, "both")
    # no outlier (full span 29 <= twice the robust span 27): the full range, nothing clipped
    assert figures.robust_limits(np.arange(30.0)) == (0.0, 29.0, "neither")
    assert figures.robust_limits([np.nan, 1.0, 3.0]) == (1.0, 3.0, "neither")
    # a 2 x 2 smoke grid has too few cells to call one an outlier
    assert figures.robust_limits([0.01, 0.01, 0.02, 0.3]) == (0.01, 0.3, "neither")


def test_moments_are_in_newton_metres_below_a_kilonewton_metre():
    assert figures.moment_unit(130.0) == (1.0, "N m")  # the 15 kg robot's righting moment
    assert figures.moment_unit(-5.2e4) == (1e3, "kN m")  # the yacht's


def _captured(monkeypatch):
    saved = []

    def keep(fig, path, dpi=None):
        saved.append((path, fig))
        assert figures.problems(fig) == [], path
    monkeypatch.setattr(figures, "save", keep)
    return saved


def test_the_robots_righting_curve_is_in_newton_metres(monkeypatch, tmp_path):
    from sailmujoco.boat.catalogue import get_boat
    from sailmujoco.cli.health import plot_righting_curve

    saved = _captured(monkeypatch)
    plot_righting_curve(get_boat("saoud_robot"), tmp_path / "r.png")
    (_, fig), = saved
    ax = fig.axes[0]
    assert ax.get_ylabel() == "righting moment [N m]"
    # m g GM sin(phi) of a 15 kg robot with GM_t 1 m is at most ~150 N m: the axis stays below 1000
    assert 50.0 < ax.get_ylim()[1] < 1000.0


def test_polar_figures_say_where_the_wind_comes_from(monkeypatch, tmp_path):
    from sailmujoco.design import polar, polar_compare

    frame = pd.DataFrame({"tws": [2.0] * 4 + [4.0] * 4, "twa": [45.0, 90.0, 135.0, 180.0] * 2,
                          "speed": [0.3, 0.5, 0.4, 0.35, 0.6, 0.9, 0.8, 0.7]})
    saved = _captured(monkeypatch)
    polar.plot_polar(frame, tmp_path / "p.png", "robot")
    polar_compare.plot_comparison({"saoud": frame, "best": frame.assign(speed=frame["speed"] * 1.1)},
                          tmp_path / "c.png", "robot")
    texts = [t.get_text() for t in saved[0][1].axes[0].texts]
    assert any("true wind\nfrom 0°" in t for t in texts)
    assert len(saved) == 2


def test_the_saoud_fig3_fig4_figures_pass_the_check(tmp_path):
    from sailmujoco.studies import saoud_fig3_fig4

    from sailmujoco import sweep
    from sailmujoco.study import run_study

    with warnings.catch_warnings():
        warnings.simplefilter("error", figures.FigureWarning)
        run_study(saoud_fig3_fig4.STUDY, tmp_path, sweep.Engine("serial"), smoke=True, progress=False)
    assert (tmp_path / "fig3.png").stat().st_size > 10_000


def test_save_warns_about_a_problem(tmp_path):
    plt, fig, ax = _line_figure()
    ax.set_ylabel("speed")
    with pytest.warns(figures.FigureWarning, match="y label 'speed' names no unit"):
        figures.save(fig, tmp_path / "f.png")
    assert (tmp_path / "f.png").exists()
