"""Every study's report.md opens the same way: the title, a "Summary" of at most 200 words, the
study's main table, then the explanations under their own headings.

The studies that simulate nothing or little (Saoud Figs. 3-4 and Fig. 7) run here in smoke mode;
:func:`layout_problems` is the check, so a study's own smoke test can apply it to its report too.
"""

import pytest
from sailmujoco.studies import saoud_fig3_fig4, saoud_fig7
from sailmujoco.studies.kit import SUMMARY_WORDS

from sailmujoco import sweep
from sailmujoco.study import run_study


def summary_words(text: str) -> int:
    """Words of prose in the "## Summary" section (its table rows left out)."""
    lines = text.split("## Summary\n", 1)[1].split("\n## ", 1)[0].splitlines()
    return len(" ".join(line for line in lines if not line.startswith("|")).split())


def layout_problems(text: str) -> list[str]:
    """What keeps a report from opening with title, summary and main table (empty: none)."""
    lines = text.splitlines()
    if not lines or not lines[0].startswith("# "):
        return ["the first line is not a '# ' title"]
    headings = [line for line in lines[1:] if line.startswith("#")]
    if not headings or headings[0] != "## Summary":
        return [f"the first heading after the title is {headings[:1]}, not '## Summary'"]
    problems = []
    section = text.split("## Summary\n", 1)[1].split("\n## ", 1)[0]
    table = [line for line in section.splitlines() if line.startswith("|")]
    if len(table) < 3:  # header, rule, at least one row
        problems.append("no table in the Summary section, before the next '## ' heading")
    prose = section.split("\n|", 1)[0].strip()
    if not prose:
        problems.append("no summary text before the table")
    if summary_words(text) > SUMMARY_WORDS:
        problems.append(f"summary of {summary_words(text)} words, more than {SUMMARY_WORDS}")
    if "\n## " not in text.split("## Summary\n", 1)[1]:
        problems.append("no explanations after the summary")
    return problems


GOOD = ("# A study\n\n## Summary\n\nOurs is 1.5 m/s, the paper's 1.6 m/s.\n\n"
        "| quantity | paper | ours |\n|---|---|---|\n| speed | 1.6 | 1.5 |\n\n"
        "## Scenario\n\nHow it runs.\n")


def test_layout_check_accepts_the_layout_and_rejects_each_departure():
    assert layout_problems(GOOD) == []
    long = GOOD.replace("Ours is", "word " * (SUMMARY_WORDS - 7) + "Ours is")  # 201 words
    assert summary_words(long) == SUMMARY_WORDS + 1
    assert layout_problems(long) == [f"summary of {SUMMARY_WORDS + 1} words, more than {SUMMARY_WORDS}"]
    assert layout_problems(GOOD.replace("# A study", "A study")) == ["the first line is not a '# ' title"]
    assert layout_problems(GOOD.replace("## Summary", "## Results"))[0].startswith("the first heading")
    no_table = "\n".join(line for line in GOOD.splitlines() if not line.startswith("|"))
    assert layout_problems(no_table) == ["no table in the Summary section, before the next '## ' heading"]
    # the table under a heading of its own is not the summary's table
    moved = GOOD.replace("| quantity", "## Table\n\n| quantity")
    assert "no table in the Summary section, before the next '## ' heading" in layout_problems(moved)


@pytest.fixture(scope="module")
def reports(tmp_path_factory):
    """report.md of the cheap studies' smoke passes."""
    texts = {}
    with sweep.Engine("serial") as engine:
        for study in (saoud_fig3_fig4.STUDY, saoud_fig7.STUDY):
            out = tmp_path_factory.mktemp(study.name)
            run_study(study, out, engine, smoke=True, progress=False)
            texts[study.name] = (out / "report.md").read_text()
    return texts


@pytest.mark.parametrize("name", ["saoud_fig3_fig4", "saoud_fig7"])
def test_report_opens_with_title_summary_and_main_table(reports, name):
    text = reports[name]
    assert layout_problems(text) == []
    section = text.split("## Summary\n", 1)[1].split("\n## ", 1)[0]
    assert "| paper | ours |" in section  # the paper-vs-ours comparison is the main table
