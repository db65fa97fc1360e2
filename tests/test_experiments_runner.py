"""The experiments' one runner (``python -m experiments NAME [ARGS]``) and their common ``--out DIR``."""

from __future__ import annotations

import csv
import subprocess
import sys
from pathlib import Path

import experiments.__main__ as runner
from experiments import fv_maximum_principle

EXPERIMENTS = Path(runner.__file__).parent


def rows_without_seconds(path: Path) -> list[dict[str, str]]:
    with path.open() as f:
        return [{k: v for k, v in r.items() if k != "seconds"} for r in csv.DictReader(f)]


def test_the_list_has_every_script_of_the_package(capsys):
    scripts = {p.stem for p in EXPERIMENTS.glob("*.py")
               if not p.stem.startswith("_") and runner.SCRIPT_GUARD in p.read_text()}
    assert "fv_maximum_principle" in scripts and "sweep" not in scripts  # a library, not a script
    assert runner.main([]) == 0
    listed = capsys.readouterr().out
    for name, doc in runner.runnable().items():
        assert f"  {name}  " in listed and doc.split()[0] in listed
    assert set(runner.runnable()) == scripts


def test_unknown_experiment_is_exit_2_naming_the_choices(capsys):
    assert runner.main(["no_such_study"]) == 2
    err = capsys.readouterr().err
    assert "unknown experiment 'no_such_study'" in err and "fv_maximum_principle" in err


def test_runner_and_module_write_the_same_results_into_out(tmp_path):
    via_runner, via_module = tmp_path / "runner", tmp_path / "module"
    argv = [sys.executable, "-m", "experiments", "fv_maximum_principle", "--quick", "--out", str(via_runner)]
    done = subprocess.run(argv, capture_output=True, text=True, cwd=EXPERIMENTS.parent, timeout=300)
    assert done.returncode == 0, done.stderr
    assert fv_maximum_principle.main(["--quick", "--out", str(via_module)]) == 0
    names = sorted(p.name for p in via_runner.iterdir())
    assert names == sorted(p.name for p in via_module.iterdir()) == \
        ["fv_maximum_principle_quick.csv", "fv_maximum_principle_quick.png"]
    csv_name = "fv_maximum_principle_quick.csv"
    assert rows_without_seconds(via_runner / csv_name) == rows_without_seconds(via_module / csv_name)


def test_option_errors_keep_the_experiments_exit_code(tmp_path):
    done = subprocess.run([sys.executable, "-m", "experiments", "fv_maximum_principle", "--bogus"],
                          capture_output=True, text=True, cwd=EXPERIMENTS.parent, timeout=120)
    assert done.returncode == 2 and "--bogus" in done.stderr and "Traceback" not in done.stderr
