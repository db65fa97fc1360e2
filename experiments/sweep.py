"""The sweep runner shared by the experiments.

A sweep is one task function and a list of independent cases. A case is a JSON-serializable dict of
parameters; the task is a top-level function ``task(case: dict) -> dict`` whose result is JSON-serializable
(numpy scalars and arrays are converted). The task is named by reference, ``"package.module:function"``, so
that a fresh process anywhere (a local case process, a Dask worker's case process) can import it.

Every case runs in its own child process (``python -c``, a new session) that is killed with its process group
when it exceeds the case time limit; the case is then recorded with status ``"timeout"``, so one hung case
never stalls the sweep. A plain subprocess rather than ``multiprocessing.Process`` because Dask worker
processes are daemonic by default (``distributed.worker.daemon``), and daemonic processes may not start
multiprocessing children.

Where the cases run:
  - default: ``workers`` case processes at a time on this machine (threads of this process drive them, so the
    case processes are the process pool; a second pool layer would only double the processes);
  - ``scheduler="tcp://HOST:PORT"``: a Dask distributed cluster; each case is one Dask task that starts the
    limited case process on its worker (workers must be able to import ``experiments``: start them from the
    repository root with ``PYTHONPATH=src:.`` or with the package installed);
  - ``dask_local=True``: a Dask LocalCluster on 127.0.0.1 (processes, 2 workers, one thread each).
The results are the same either way: one record per case, sorted by the case key.

Records are appended to a JSONL file as cases finish, keyed by a stable hash of (task, case). A rerun skips
the cases already recorded as ``"ok"``, and the ``"timeout"`` cases whose recorded limit is at least the
current one; ``"error"`` cases run again (an error usually means code that is being fixed).

Record fields: key, task, case, status ("ok" | "timeout" | "error"), seconds (wall time of the case process,
interpreter start included), time_limit, result (the task's dict, or None), error (text, or None).
"""

from __future__ import annotations

import argparse
import csv
import hashlib
import importlib
import json
import os
import signal
import subprocess
import sys
import tempfile
import threading
import time
import traceback
from collections.abc import Callable, Iterable
from concurrent.futures import ThreadPoolExecutor, as_completed
from pathlib import Path
from typing import Any

from experiments.outputs import add_out_option

TaskRef = str
Record = dict[str, Any]

# The child reads its payload from stdin; the parent's import path comes first so that the task module
# resolves the same way in the case process as in the process that named it.
_CHILD_BOOT = (
    "import json, sys\n"
    "payload = json.loads(sys.stdin.read())\n"
    "sys.path[:0] = [p for p in payload['sys_path'] if p not in sys.path]\n"
    "from experiments.sweep import child_main\n"
    "child_main(payload)\n"
)

_running: set[subprocess.Popen] = set()
_running_lock = threading.Lock()


def to_jsonable(value: Any) -> Any:
    """``json.dumps`` default hook: numpy scalars and arrays to Python numbers and lists, paths to strings."""
    if hasattr(value, "tolist"):
        return value.tolist()
    if isinstance(value, Path):
        return str(value)
    raise TypeError(f"not JSON-serializable: {type(value).__name__}")


def canonical_json(value: Any) -> str:
    """Key-sorted compact JSON: the same text for equal values, whatever the dict insertion order."""
    return json.dumps(value, sort_keys=True, separators=(",", ":"), default=to_jsonable)


def case_key(task_ref: TaskRef, case: dict[str, Any]) -> str:
    """Stable 16-hex-digit key of a case of a task (sha256 of their canonical JSON)."""
    text = canonical_json({"task": task_ref, "case": case})
    return hashlib.sha256(text.encode()).hexdigest()[:16]


def task_reference(task: TaskRef | Callable[[dict], dict]) -> TaskRef:
    """``"module:function"`` for a top-level function (or such a string, checked for its shape).

    A function of a script run as ``__main__`` is named by the module the script was run as (``python -m``).
    """
    if isinstance(task, str):
        module, _, name = task.partition(":")
        if not module or not name:
            raise ValueError(f"task reference must be 'module:function', got {task!r}")
        return task
    module, name = task.__module__, task.__qualname__
    if "<locals>" in name or "<lambda>" in name:
        raise ValueError(f"task {name} must be a top-level function (the case process imports it by name)")
    if module == "__main__":
        module = _main_module_name()
    return f"{module}:{name}"


def _main_module_name() -> str:
    """The importable name of the ``__main__`` module: the one it was run as (``python -m``), or, for a
    script, its dotted path below the first ``sys.path`` entry that contains it."""
    main = sys.modules["__main__"]
    spec = getattr(main, "__spec__", None)
    if spec is not None:
        return spec.name
    script = Path(getattr(main, "__file__", "")).resolve()
    for entry in sys.path:
        root = Path(entry or ".").resolve()
        if script.is_relative_to(root) and script != root:
            return ".".join(script.relative_to(root).with_suffix("").parts)
    raise ValueError("cannot name the task of this script by module: pass it as 'module:function'")


def resolve_task(task_ref: TaskRef) -> Callable[[dict], dict]:
    """Import the function named by ``"module:function"``."""
    module, _, name = task_ref.partition(":")
    obj: Any = importlib.import_module(module)
    for part in name.split("."):
        obj = getattr(obj, part)
    return obj


def child_main(payload: dict[str, Any]) -> None:
    """Entry of a case process: run the task on the case, write {"status", "result"|"error"} atomically."""
    try:
        result = resolve_task(payload["task"])(dict(payload["case"]))
        text = json.dumps({"status": "ok", "result": result}, default=to_jsonable)
    except Exception:
        text = json.dumps({"status": "error", "error": traceback.format_exc(limit=-8)})
    path = Path(payload["result_path"])
    tmp = path.with_suffix(".tmp")
    tmp.write_text(text)
    os.replace(tmp, path)


def _child_env() -> dict[str, str]:
    env = dict(os.environ)
    for var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
        env.setdefault(var, "1")  # the pool already uses every core; one thread per case process
    env.setdefault("PYTHONHASHSEED", "0")
    return env


def _kill_group(proc: subprocess.Popen) -> None:
    try:
        os.killpg(proc.pid, signal.SIGKILL)  # the case process leads its own session: kill what it started
    except ProcessLookupError:
        pass
    proc.wait()


def run_case_limited(task_ref: TaskRef, case: dict[str, Any], time_limit: float,
                     sys_path: Iterable[str] = ()) -> Record:
    """Run one case in a child process killed after ``time_limit`` seconds; return its record.

    The child imports with this process's ``sys.path`` followed by ``sys_path`` (the submitting process's
    path, so that its task modules resolve on a local Dask worker too).
    Never raises for a failing case: a task exception or a crashed child is recorded as status "error".
    """
    record: Record = {"key": case_key(task_ref, case), "task": task_ref, "case": case,
                      "time_limit": time_limit, "result": None, "error": None}
    search_path = list(sys.path) + [p for p in sys_path if p not in sys.path]
    with tempfile.TemporaryDirectory(prefix="sweep-case-") as tmp:
        result_path = Path(tmp) / "result.json"
        payload = json.dumps({"task": task_ref, "case": case, "result_path": str(result_path),
                              "sys_path": search_path}, default=to_jsonable)
        start = time.perf_counter()
        with open(Path(tmp) / "stderr.txt", "w+b") as err:
            proc = subprocess.Popen([sys.executable, "-c", _CHILD_BOOT], stdin=subprocess.PIPE,
                                    stdout=subprocess.DEVNULL, stderr=err, env=_child_env(),
                                    start_new_session=True)
            with _running_lock:
                _running.add(proc)
            try:
                proc.communicate(payload.encode(), timeout=time_limit)
                timed_out = False
            except subprocess.TimeoutExpired:
                _kill_group(proc)
                timed_out = True
            finally:
                with _running_lock:
                    _running.discard(proc)
            record["seconds"] = round(time.perf_counter() - start, 3)
            err.seek(0)
            stderr_tail = err.read()[-2000:].decode(errors="replace")
        if timed_out:
            record["status"] = "timeout"
        elif result_path.exists():
            outcome = json.loads(result_path.read_text())
            record["status"] = outcome["status"]
            record["result"] = outcome.get("result")
            record["error"] = outcome.get("error")
        else:
            record["status"] = "error"
            record["error"] = f"case process exited with code {proc.returncode}\n{stderr_tail}"
    return record


def kill_running_cases() -> None:
    """Kill every case process this process started that is still running (used on interrupt)."""
    with _running_lock:
        procs = list(_running)
    for proc in procs:
        _kill_group(proc)


def load_records(path: Path | None) -> dict[str, Record]:
    """Records of a JSONL file by key (the last record of a key wins; a truncated last line is ignored)."""
    records: dict[str, Record] = {}
    if path is None or not Path(path).exists():
        return records
    with open(path) as f:
        for line in f:
            try:
                rec = json.loads(line)
            except json.JSONDecodeError:
                continue  # a line cut by an interrupted run
            records[rec["key"]] = rec
    return records


def error_summary(record: Record) -> str:
    """One line for a failed case: the exception line of its traceback (or the exit message), at most 200
    characters; empty for a case without an error."""
    lines = (record.get("error") or "").strip().splitlines()
    return lines[-1][:200] if lines else ""


def is_finished(record: Record, time_limit: float) -> bool:
    """Whether a recorded case need not run again under ``time_limit`` (see the module docstring)."""
    if record["status"] == "ok":
        return True
    return record["status"] == "timeout" and record["time_limit"] >= time_limit


class Progress:
    """done/total, timeouts, errors, elapsed and eta on stderr, at most once a second (and at the end)."""

    def __init__(self, name: str, total: int, cached: int, enabled: bool) -> None:
        self.name, self.total, self.cached, self.enabled = name, total, cached, enabled
        self.done, self.timeouts, self.errors = 0, 0, 0
        self.start = self.last = time.monotonic()

    def update(self, record: Record) -> None:
        self.done += 1
        self.timeouts += record["status"] == "timeout"
        self.errors += record["status"] == "error"
        now = time.monotonic()
        if self.enabled and (now - self.last >= 1.0 or self.cached + self.done == self.total):
            self.last = now
            elapsed = now - self.start
            eta = elapsed / self.done * (self.total - self.cached - self.done)
            print(f"[{self.name}] {self.cached + self.done}/{self.total} done ({self.cached} cached, "
                  f"{self.timeouts} timeout, {self.errors} error), elapsed {_hms(elapsed)}, eta {_hms(eta)}",
                  file=sys.stderr, flush=True)


def _hms(seconds: float) -> str:
    s = int(round(seconds))
    return f"{s // 3600}:{s // 60 % 60:02d}:{s % 60:02d}"


def _run_local(task_ref: TaskRef, todo: list[dict], time_limit: float, workers: int,
               on_record: Callable[[Record], None]) -> None:
    with ThreadPoolExecutor(max_workers=workers) as pool:
        futures = [pool.submit(run_case_limited, task_ref, case, time_limit) for case in todo]
        try:
            for fut in as_completed(futures):
                on_record(fut.result())
        except BaseException:
            for fut in futures:
                fut.cancel()
            kill_running_cases()
            raise


def _run_dask(task_ref: TaskRef, todo: list[dict], time_limit: float, client: Any,
              on_record: Callable[[Record], None]) -> None:
    from distributed import as_completed as dask_as_completed

    futures = [client.submit(run_case_limited, task_ref, case, time_limit, list(sys.path),
                             key=f"sweep-case-{case_key(task_ref, case)}") for case in todo]
    for fut in dask_as_completed(futures):
        on_record(fut.result())
        fut.release()


def run_sweep(task: TaskRef | Callable[[dict], dict], cases: list[dict[str, Any]], *, out: Path | None = None,
              time_limit: float = 60.0, workers: int | None = None, scheduler: str | None = None,
              dask_local: bool = False, fresh: bool = False, progress: bool = True,
              name: str | None = None) -> list[Record]:
    """Run every case of ``task`` (each limited to ``time_limit`` s) and return their records sorted by key.

    out:        JSONL file of records (appended as cases finish; finished cases are skipped on a rerun);
                None keeps nothing. ``fresh`` empties it first.
    workers:    concurrent case processes for the local pool (default: the number of CPUs).
    scheduler:  ``tcp://HOST:PORT`` of a Dask scheduler; ``dask_local``: start a LocalCluster on 127.0.0.1
                with ``workers`` (default 2) single-threaded worker processes.
    Raises ValueError for duplicate cases or a task that cannot be named by reference.
    """
    if scheduler and dask_local:
        raise ValueError("give either scheduler or dask_local, not both")
    task_ref = task_reference(task)
    keyed: dict[str, dict] = {}
    for case in cases:
        key = case_key(task_ref, case)
        if key in keyed:
            raise ValueError(f"duplicate case {canonical_json(case)}")
        keyed[key] = case
    out = Path(out) if out is not None else None
    if out is not None and fresh:
        out.unlink(missing_ok=True)
    done = {k: r for k, r in load_records(out).items() if k in keyed and is_finished(r, time_limit)}
    todo = [case for key, case in keyed.items() if key not in done]
    bar = Progress(name or task_ref, len(keyed), len(done), progress)
    if out is not None:
        out.parent.mkdir(parents=True, exist_ok=True)
    sink = open(out, "a") if out is not None else None  # closed in the finally below

    def on_record(record: Record) -> None:
        if sink is not None:
            sink.write(json.dumps(record, sort_keys=True, default=to_jsonable) + "\n")
            sink.flush()
        done[record["key"]] = record
        bar.update(record)

    try:
        if todo and (scheduler or dask_local):
            _with_dask_client(scheduler, workers, lambda client: _run_dask(task_ref, todo, time_limit, client,
                                                                           on_record))
        elif todo:
            _run_local(task_ref, todo, time_limit, workers or os.cpu_count() or 1, on_record)
    finally:
        if sink is not None:
            sink.close()
    return [done[k] for k in sorted(done)]


def _with_dask_client(scheduler: str | None, workers: int | None, body: Callable[[Any], None]) -> None:
    from distributed import Client, LocalCluster

    if scheduler:
        with Client(scheduler) as client:
            body(client)
        return
    with LocalCluster(n_workers=workers or 2, threads_per_worker=1, processes=True, host="127.0.0.1",
                      dashboard_address=None) as cluster, Client(cluster) as client:
        body(client)


def add_sweep_arguments(parser: argparse.ArgumentParser) -> None:
    """The common experiment options: --quick --seed --workers --scheduler/--dask-local --out --fresh
    --time-limit (default: the experiment's, see ``sweep_from_args``)."""
    parser.add_argument("--quick", action="store_true", help="a small sweep (minutes on 2 cores)")
    parser.add_argument("--seed", type=int, default=0, help="seed of every random choice (default 0)")
    parser.add_argument("--workers", type=int, default=None,
                        help="concurrent case processes (default: CPUs; 2 with --dask-local)")
    where = parser.add_mutually_exclusive_group()
    where.add_argument("--scheduler", metavar="tcp://HOST:PORT", help="run on this Dask scheduler")
    where.add_argument("--dask-local", action="store_true", help="run on a Dask LocalCluster on 127.0.0.1")
    add_out_option(parser)
    parser.add_argument("--fresh", action="store_true", help="forget the recorded cases and run all again")
    parser.add_argument("--time-limit", type=float, default=None,
                        help="seconds per case before it is killed and recorded as timeout")


def sweep_from_args(args: argparse.Namespace, task: TaskRef | Callable[[dict], dict], cases: list[dict],
                    name: str, time_limit: float) -> list[Record]:
    """Run a sweep with the options of ``add_sweep_arguments`` (``time_limit`` unless --time-limit is given);
    records go to OUT/cache/NAME[_quick].jsonl."""
    cache = Path(args.out) / "cache" / f"{output_stem(name, args.quick)}.jsonl"
    return run_sweep(task, cases, out=cache, time_limit=args.time_limit or time_limit, workers=args.workers,
                     scheduler=args.scheduler, dask_local=args.dask_local, fresh=args.fresh, name=name)


def output_stem(name: str, quick: bool) -> str:
    """File stem of an experiment's outputs: quick runs get their own files, never overwriting full ones."""
    return f"{name}_quick" if quick else name


def write_csv(path: Path, rows: list[dict[str, Any]], columns: list[str]) -> None:
    """Write ``rows`` (dicts; missing keys empty) as CSV with exactly ``columns``, atomically."""
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = path.with_suffix(path.suffix + ".tmp")
    with open(tmp, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=columns, extrasaction="ignore")
        writer.writeheader()
        writer.writerows(rows)
    os.replace(tmp, path)
