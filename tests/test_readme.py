"""The README's code does what the README says: the five-line example runs as a plain script,
prints the task's metrics and writes its figure; the controller file of "Bring your controller"
loads by its path and sails; the documented video command writes into results/, not over the
tracked docs/video_frame.png; the README stays a short page."""

import ast
import os
import re
import subprocess
import sys
from pathlib import Path

import numpy as np

README = Path(__file__).resolve().parents[1] / "README.md"


def _block(heading: str, language: str) -> str:
    text = README.read_text(encoding="utf-8")
    section = text[text.index(heading):]
    return re.search(rf"```{language}\n(.*?)```", section, re.S).group(1)


def test_five_line_example_runs_as_a_script_and_writes_its_figure(tmp_path):
    code = _block("## Five lines", "python")
    assert len(code.strip().splitlines()) == 5
    figure = re.search(r'savefig\("([^"]+)"\)', code).group(1)
    # smoke length: 3 s of the 60 s episode (the code is otherwise run exactly as printed)
    assert "time_limit=60" in code
    script = tmp_path / "example.py"
    script.write_text(code.replace("time_limit=60", "time_limit=3"))
    env = {k: v for k, v in os.environ.items() if k != "MPLBACKEND"}
    done = subprocess.run([sys.executable, str(script)], cwd=tmp_path, check=True, env=env, timeout=120,
                          capture_output=True, text=True)
    metrics = ast.literal_eval(done.stdout.strip().splitlines()[-1])  # the printed metrics dict
    assert {"roll_amplitude", "mean_surge"} <= set(metrics)
    assert 0.0 < metrics["mean_surge"] < 15.0  # m/s: the yacht sails, below any speed it can reach
    png = (tmp_path / figure).read_bytes()
    assert png[:8] == b"\x89PNG\r\n\x1a\n" and len(png) > 10_000


def test_documented_video_command_writes_into_results():
    command = _block("## Videos", "bash")
    video = command.split("sailmujoco video", 1)[1].split("\n\n")[0]
    outputs = re.findall(r"--(?:out|still) (\S+)", video)
    assert len(outputs) == 2
    assert all(path.startswith("results/") for path in outputs), outputs
    assert "docs/" not in command


def test_own_controller_file_loads_by_its_path_and_holds_its_heading(tmp_path, monkeypatch):
    """The README's my_ctrl.py, written as printed, named "my_ctrl.py:make": the robot keeps the
    ordered heading (north) within a few degrees under its proportional rudder."""
    from sailmujoco import suite, sweep

    section = README.read_text(encoding="utf-8").split("## Bring your controller", 1)[1]
    code = re.search(r"```python\n(# my_ctrl.py\n.*?)```", section, re.S).group(1)
    (tmp_path / "my_ctrl.py").write_text(code)
    monkeypatch.chdir(tmp_path)
    env = suite.load("saoud_robot", "heading_hold", seed=0, time_limit=20)
    log = suite.rollout(env, sweep.make_controller("my_ctrl.py:make", env, gain=2.0))
    assert len(log) > 150 and env.task.desired_heading == 0.0
    error = np.angle(np.exp(1j * log["heading"].iloc[-50:].to_numpy()))  # wrapped to (-pi, pi]
    assert np.abs(error).max() < 0.1  # rad


def test_readme_is_a_short_page():
    """At most 1,500 words, counted as whitespace-separated tokens of the whole file."""
    assert len(README.read_text(encoding="utf-8").split()) <= 1500


NUMBER = re.compile(r"(?<![\w.])[-−+]?\d+(?:\.\d+)?(?:e[-+]?\d+)?")


def _prose_numbers(text: str) -> set[float]:
    """The numbers of a Markdown page's prose and tables: code, inline code and link targets
    left out (they are names, paths and arguments, not findings)."""
    text = re.sub(r"```.*?```", "", text, flags=re.S)
    text = re.sub(r"`[^`]*`", "", text)
    text = re.sub(r"\]\([^)]*\)", "]", text)
    return {abs(float(match.replace("−", "-"))) for match in NUMBER.findall(text)}


def test_every_number_of_the_readme_is_in_the_results_or_the_benchmarks():
    """The README cites, it does not measure: each number in its prose and tables appears in
    docs/results.md (taken from the studies' reports), docs/performance.md (the benchmarks'
    output) or docs/papers.md; the Python version of the quick start aside."""
    docs = README.parent / "docs"
    cited = set().union(*(_prose_numbers((docs / page).read_text(encoding="utf-8"))
                          for page in ("results.md", "performance.md", "papers.md")))
    readme = README.read_text(encoding="utf-8").replace("Python 3.11", "Python")
    assert _prose_numbers(readme) - cited == set()


def test_every_relative_link_of_the_readme_and_the_docs_resolves():
    pages = [README, *sorted((README.parent / "docs").glob("*.md"))]
    broken = [(page.name, target) for page in pages
              for target in re.findall(r"\]\(([^)#]+)\)", page.read_text(encoding="utf-8"))
              if not target.startswith(("http://", "https://")) and not (page.parent / target).exists()]
    assert broken == []
