"""The sweep runner: same records on the local pool and on a Dask LocalCluster, time limits, resume."""

from __future__ import annotations

import json
import time

import pytest
from experiments.sweep import case_key, load_records, run_sweep, task_reference


def toy_task(case: dict) -> dict:
    """A toy task: squares x, hangs forever on "hang", divides by zero on "fail"."""
    if case.get("hang"):
        while True:
            time.sleep(60)
    if case.get("fail"):
        return {"y": 1 / 0}
    return {"y": case["x"] ** 2}


TOY = task_reference(toy_task)
CASES = [{"x": 3}, {"x": -2}, {"x": 0}, {"hang": True}, {"fail": True}]
LIMIT = 3.0  # seconds; a case process starts in well under a second, so only the hanging case reaches it


def summary(records: list[dict]) -> list[tuple]:
    """What must not depend on where the cases ran (everything but wall times)."""
    return [(r["key"], r["status"], r["result"], r["case"]) for r in records]


def check_toy_records(records: list[dict]) -> None:
    by_case = {json.dumps(r["case"], sort_keys=True): r for r in records}
    assert [by_case[json.dumps({"x": x})]["result"] for x in (3, -2, 0)] == [{"y": 9}, {"y": 4}, {"y": 0}]
    hung = by_case[json.dumps({"hang": True})]
    assert hung["status"] == "timeout" and hung["result"] is None
    assert LIMIT <= hung["seconds"] < LIMIT + 10  # killed at the limit, not left running
    failed = by_case[json.dumps({"fail": True})]
    assert failed["status"] == "error" and "ZeroDivisionError" in failed["error"]
    assert [r["key"] for r in records] == sorted(case_key(TOY, c) for c in CASES)


def test_pool_and_dask_local_give_the_same_records(tmp_path):
    pooled = run_sweep(toy_task, CASES, out=tmp_path / "pool.jsonl", time_limit=LIMIT, workers=2,
                       progress=False)
    check_toy_records(pooled)
    dasked = run_sweep(toy_task, CASES, out=tmp_path / "dask.jsonl", time_limit=LIMIT, dask_local=True,
                       progress=False)
    assert summary(dasked) == summary(pooled)


def test_resume_skips_finished_cases(tmp_path):
    out = tmp_path / "records.jsonl"
    first = run_sweep(toy_task, CASES, out=out, time_limit=LIMIT, workers=2, progress=False)
    assert len(out.read_text().splitlines()) == 5
    # Rerun with one case more: only the new case and the error case run again (2 new lines); the timeout
    # was recorded under the same limit, so it is finished.
    again = run_sweep(toy_task, [*CASES, {"x": 5}], out=out, time_limit=LIMIT, workers=2, progress=False)
    lines = [json.loads(line) for line in out.read_text().splitlines()]
    assert sorted(json.dumps(r["case"]) for r in lines[5:]) == sorted(['{"fail": true}', '{"x": 5}'])
    assert summary([r for r in again if r["case"] != {"x": 5}]) == summary(first)
    assert len(load_records(out)) == 6


def test_a_longer_limit_reruns_timeouts_and_fresh_reruns_all(tmp_path):
    out = tmp_path / "records.jsonl"
    run_sweep(toy_task, [{"hang": True}], out=out, time_limit=1.0, progress=False)
    run_sweep(toy_task, [{"hang": True}], out=out, time_limit=2.0, progress=False)  # 1 s < 2 s: runs again
    assert [r["time_limit"] for r in map(json.loads, out.read_text().splitlines())] == [1.0, 2.0]
    run_sweep(toy_task, [{"x": 1}], out=out, time_limit=2.0, fresh=True, progress=False)
    assert [r["case"] for r in map(json.loads, out.read_text().splitlines())] == [{"x": 1}]


def test_case_key_ignores_dict_order_and_bad_tasks_are_refused():
    assert case_key(TOY, {"a": 1, "b": 2.5}) == case_key(TOY, {"b": 2.5, "a": 1})
    assert case_key(TOY, {"a": 1}) != case_key(TOY, {"a": 2})
    with pytest.raises(ValueError, match="top-level"):
        task_reference(lambda case: case)
    with pytest.raises(ValueError, match="duplicate"):
        run_sweep(toy_task, [{"x": 1}, {"x": 1}], progress=False)
