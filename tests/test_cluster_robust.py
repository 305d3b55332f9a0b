"""The cluster keeps its promises (issue 26, "The cluster"): a malformed address is bad input
naming its port; workers without geartrain (or with another version) are found before any work;
a client opened from an address is closed; Ctrl-C leaves no task on the scheduler; a scheduler
lost mid-run is one line from the CLI; estimate counts the connection; the ``[all]`` extra
installs pandas, which the docs use to read the Parquet output.

The clusters are in-process ``LocalCluster``s on the loopback address (as tests/test_cli_dask.py).
"""

from __future__ import annotations

import contextlib
import time
import tomllib
from pathlib import Path

import pytest
from distributed import Client, LocalCluster

from gears import GearError
from gears.search.cluster import check_workers, dask_client
from gears.search.engine import estimate, pairs
from trains import TrainError, synthesize_gearbox
from trains.cli.app import main

SEARCH = {"ratio": 2, "module": 2, "teeth": (14, 40)}


@contextlib.contextmanager
def _cluster(workers: int = 1):
    with (
        LocalCluster(
            n_workers=workers, threads_per_worker=1, processes=False, protocol="tcp",
            dashboard_address=None,
        ) as cluster,
        Client(cluster) as client,
    ):  # fmt: skip
        yield cluster, client


def _wait_until(condition, seconds: float = 10.0) -> bool:
    t0 = time.monotonic()
    while time.monotonic() - t0 < seconds:
        if condition():
            return True
        time.sleep(0.05)
    return condition()


def test_a_malformed_port_is_bad_input_naming_it(capsys):
    # it was "answered, but not as a Dask scheduler"
    with pytest.raises(GearError, match=r"the port '18786x' is not a port number"):
        dask_client("tcp://127.0.0.1:18786x")
    with pytest.raises(GearError, match=r"the port '99999' is not a port number"):
        dask_client("127.0.0.1:99999")
    code = main(["search", "pairs", "--ratio", "2", "--module", "2", "--teeth", "14", "40",
                 "--scheduler", "127.0.0.1:18786x"])  # fmt: skip
    err = capsys.readouterr().err
    assert code == 2 and err.count("\n") == 1 and "'18786x'" in err


class _Workers:
    """A stand-in client whose workers answer the version question as given."""

    def __init__(self, answers: dict):
        self.answers = answers

    def run(self, fn, *args, on_error="raise"):
        return dict(self.answers)


def test_workers_without_geartrain_or_with_another_version_are_named():
    import importlib.metadata

    from gears import __version__

    missing = importlib.metadata.PackageNotFoundError("geartrain")
    with pytest.raises(GearError, match=r"2 workers, 1 without geartrain \(tcp://a:1\).*needs "
                                        rf"geartrain {__version__}"):  # fmt: skip
        check_workers(_Workers({"tcp://a:1": missing, "tcp://b:2": __version__}))
    with pytest.raises(GearError, match=r"1 with another version \(tcp://b:2 has 0\.0\.1\)"):
        check_workers(_Workers({"tcp://b:2": "0.0.1"}))
    check_workers(_Workers({"tcp://b:2": __version__}))  # agrees: silent


def test_a_real_cluster_has_this_version_and_address_clients_are_closed():
    with _cluster() as (cluster, client):
        check_workers(client)  # the workers run this process's geartrain
        before = len(cluster.scheduler.clients)
        address = cluster.scheduler_address
        for _ in range(2):
            r = pairs(**SEARCH, client=address, progress=False)
            assert len(r) > 0
        synthesize_gearbox(12, 2, z_max=60, client=address, progress=False)
        e = estimate(**SEARCH, client=address, sample=256)
        # every client opened from the address was closed (one more per call before)
        assert _wait_until(lambda: len(cluster.scheduler.clients) == before)
        assert e.connect_seconds > 0.0 and "to connect" in str(e)
        assert e.cluster_seconds(1) == pytest.approx(e.connect_seconds + e.worker_seconds)


def test_ctrl_c_leaves_no_task_on_the_scheduler():
    with _cluster() as (cluster, client):
        calls = []

        def interrupt(done, total):
            calls.append(done)
            raise KeyboardInterrupt

        with pytest.raises(KeyboardInterrupt) as info:
            pairs(ratio=2, module=[1, 2, 3], teeth=(12, 80), shifts=(-0.5, 1, 0.1),
                  client=client, chunk_size=2048, progress=interrupt)  # fmt: skip
        assert calls
        # the traceback is kept (as a notebook keeps sys.last_traceback), and with it every
        # future the search held: their tasks are cancelled all the same
        assert info.traceback is not None
        assert _wait_until(lambda: not cluster.scheduler.tasks), len(cluster.scheduler.tasks)


#: a worker whose environment has no geartrain: its version lookup finds no distribution
_NO_GEARTRAIN = """
import importlib.metadata as m, sys
found = m.version
def version(name):
    if name == "geartrain":
        raise m.PackageNotFoundError(name)
    return found(name)
m.version = version
from distributed.cli.dask_worker import main
sys.exit(main())
"""


@contextlib.contextmanager
def _scheduler_and_worker_processes(worker_code: str | None = None):
    """A Dask scheduler and one worker as processes of their own on the loopback address (a
    scheduler that can be killed as a real one dies); ``worker_code`` runs the worker instead
    of ``python -m distributed.cli.dask_worker``."""
    import os
    import socket
    import subprocess
    import sys

    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    address = f"tcp://127.0.0.1:{port}"
    root = str(Path(__file__).parents[1])
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([root, os.environ.get("PYTHONPATH", "")])}
    quiet = {"env": env, "stdout": subprocess.DEVNULL, "stderr": subprocess.DEVNULL}
    scheduler = subprocess.Popen([sys.executable, "-m", "distributed.cli.dask_scheduler", "--host",
                                  "127.0.0.1", "--port", str(port), "--dashboard-address", ":0",
                                  "--no-show"], **quiet)  # fmt: skip
    run = ["-c", worker_code] if worker_code else ["-m", "distributed.cli.dask_worker"]
    worker = subprocess.Popen([sys.executable, *run, address, "--nthreads", "1",
                               "--no-dashboard", "--no-nanny"], **quiet)  # fmt: skip
    try:
        with Client(address, timeout=30) as probe:
            probe.wait_for_workers(1, timeout=30)
        yield address, scheduler
    finally:
        for p in (worker, scheduler):
            p.kill()
            p.wait(10)


def test_a_scheduler_killed_mid_run_is_one_line():
    # the CLI printed a 23-line Dask traceback (its log of the failed reconnections) before its
    # one-line message. The command runs as a process of its own, as a user runs it (under
    # pytest Dask's log would go to pytest's handler), and the scheduler is killed (SIGKILL)
    # while the search runs (a space of 60+ chunks, several seconds on one worker thread): as
    # soon as the scheduler holds the search's first tasks, not after a fixed wait (on a quiet
    # machine the search could end before it)
    import os
    import subprocess
    import sys

    with _scheduler_and_worker_processes() as (address, scheduler):
        root = str(Path(__file__).parents[1])
        env = {**os.environ, "PYTHONPATH": root}
        argv = ["search", "pairs", "--ratio", "2", "--module", "1", "2", "3", "--teeth", "12",
                "80", "--shifts", "-0.5", "1", "0.005", "--scheduler", address,
                "--connect-timeout", "2"]  # fmt: skip
        run = "import sys; from trains.cli.app import main; sys.exit(main(sys.argv[1:]))"
        cli = subprocess.Popen([sys.executable, "-c", run, *argv], env=env, text=True,
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE)  # fmt: skip
        with Client(address, timeout=30) as probe:
            deadline = time.monotonic() + 60.0
            while time.monotonic() < deadline and cli.poll() is None:
                if probe.run_on_scheduler(lambda dask_scheduler: len(dask_scheduler.tasks)):
                    break  # the search's chunks are on the scheduler
                time.sleep(0.05)
        scheduler.kill()
        out, err = cli.communicate(timeout=60)
    assert cli.returncode == 2, (out, err)
    assert err.count("\n") == 1 and "Traceback" not in err, err
    assert "the Dask cluster lost work mid-run" in err or "scheduler" in err


def test_a_worker_without_geartrain_is_named_before_any_work(capsys):
    # issue 26: a 57-line traceback ending in "a bug in geartrain" (pair search) or "workers
    # died" (gearbox search); now one GearError / TrainError naming the worker, before any work
    with _scheduler_and_worker_processes(_NO_GEARTRAIN) as (address, _):
        with pytest.raises(GearError, match=r"1 workers, 1 without geartrain \(tcp://"):
            pairs(**SEARCH, client=address, progress=False)
        with pytest.raises(TrainError, match="without geartrain"):
            synthesize_gearbox(12, 2, z_max=60, client=address, progress=False)
        code = main(["search", "pairs", "--ratio", "2", "--module", "2", "--teeth", "14", "40",
                     "--scheduler", address])  # fmt: skip
    err = capsys.readouterr().err
    assert code == 2 and err.count("\n") == 1 and "without geartrain" in err, err


def test_the_all_extra_reads_parquet_with_pandas():
    # docs/search.md reads the Parquet output with pandas: [all] must install it
    meta = tomllib.loads((Path(__file__).parents[1] / "pyproject.toml").read_text())
    extras = meta["project"]["optional-dependencies"]
    reqs = []
    for item in extras["all"]:  # "geartrain[mesh,plot,...]": the extras it gathers
        for extra in item.split("[")[1].rstrip("]").split(","):
            reqs += extras[extra]
    names = {req.split(">")[0].split("=")[0].split("[")[0].strip() for req in reqs}
    assert "pandas" in names and "pyarrow" in names


def test_the_cluster_errors_are_train_errors_for_the_gearbox():
    with pytest.raises(TrainError, match="18786x"):
        synthesize_gearbox(12, 2, client="tcp://127.0.0.1:18786x", progress=False)
