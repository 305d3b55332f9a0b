"""Dask faults get a clear answer (issue 17 item 6): a wrong address, a port where no Dask
scheduler listens, a cluster that loses its last worker mid-search. From the CLI each is exit 2
with one line naming what happened, within ``--connect-timeout``; from the API
(``gears.search.engine.pairs``, ``trains.synthesize_gearbox``, the resolver
``gears.search.cluster.dask_client``) a GearError / TrainError.

The clusters are in-process ``LocalCluster``s (threads), so each case takes a second or two.
"""

from __future__ import annotations

import contextlib
import http.server
import socket
import threading
import time

import dask
import pytest
from distributed import Client, LocalCluster

from gears import GearError
from gears.search.cluster import dask_client
from gears.search.engine import pairs
from trains import TrainError, synthesize_gearbox
from trains.cli.app import main

SEARCH = ["search", "pairs", "--ratio", "2", "--module", "2", "--teeth", "14", "40"]


def _bad_input(capsys, argv, seconds: float) -> str:
    """Run ``argv``: exit 2 within ``seconds``, one line on stderr, nothing on stdout."""
    t0 = time.monotonic()
    code = main(argv)
    took = time.monotonic() - t0
    out, err = capsys.readouterr()
    assert code == 2, (code, out, err)
    assert out == "" and err.count("\n") == 1 and "Traceback" not in err, err
    assert took < seconds, f"took {took:.1f} s: {err}"
    return err


@contextlib.contextmanager
def _http_server():
    """A live port that is not a Dask scheduler: an HTTP server on the loopback address."""

    class Quiet(http.server.BaseHTTPRequestHandler):
        def log_message(self, *args):  # no request log on stderr
            pass

    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), Quiet)
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    try:
        yield f"tcp://127.0.0.1:{server.server_port}"
    finally:
        server.shutdown()
        server.server_close()


def _closed_port() -> str:
    """A loopback address where nothing listens (a port just released)."""
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    return f"tcp://127.0.0.1:{port}"


@contextlib.contextmanager
def _one_worker_cluster():
    with (
        LocalCluster(
            n_workers=1, threads_per_worker=1, processes=False, protocol="tcp",
            dashboard_address=None,
        ) as cluster,
        Client(cluster) as client,
    ):  # fmt: skip
        yield cluster, client


def test_unknown_scheme_is_exit_2(capsys):
    err = _bad_input(capsys, [*SEARCH, "--scheduler", "foo://127.0.0.1:1"], 10)
    assert "unknown address scheme 'foo'" in err and "tcp://host:8786" in err


def test_a_port_that_is_not_a_scheduler_is_exit_2_within_the_timeout(capsys):
    # before: the Dask client waited for ever on an HTTP server's port
    with _http_server() as address:
        argv = [*SEARCH, "--scheduler", address, "--connect-timeout", "1"]
        err = _bad_input(capsys, argv, 8)
    assert f"no Dask scheduler answered at '{address}' within 1 s (--connect-timeout)" in err


def test_nothing_listening_is_exit_2_within_the_timeout(capsys):
    # before: a fixed 30 s wait; now --connect-timeout bounds it
    address = _closed_port()
    err = _bad_input(capsys, [*SEARCH, "--scheduler", address, "--connect-timeout", "1"], 8)
    assert f"no Dask scheduler answered at '{address}'" in err


def test_connect_timeout_needs_a_scheduler(capsys):
    err = _bad_input(capsys, [*SEARCH, "--connect-timeout", "1"], 10)
    assert "--connect-timeout applies with --scheduler only" in err


def test_the_resolver_refuses_bad_addresses_with_gear_errors():
    with pytest.raises(GearError, match="unknown address scheme"):
        dask_client("foo://127.0.0.1:1")
    with _http_server() as address, pytest.raises(GearError, match=r"within 0\.5 s"):
        dask_client(address, timeout=0.5)
    with pytest.raises(GearError, match="no Dask scheduler answered"):
        dask_client(_closed_port(), timeout=0.5)
    with pytest.raises(GearError, match=r"timeouts\.connect"):
        dask_client(_closed_port(), timeout=float("nan"))
    with pytest.raises(GearError, match="unknown address scheme"):
        pairs(ratio=2, client="foo://127.0.0.1:1")
    with pytest.raises(TrainError, match="unknown address scheme"):
        synthesize_gearbox(37, 2, 3, client="foo://127.0.0.1:1", progress=False)


def test_losing_the_last_worker_mid_search_is_a_gear_error():
    # the only worker is closed after the first chunk comes back: the search stops with the
    # library's error (before: a FutureCancelledError traceback, exit 3 from the CLI)
    with _one_worker_cluster() as (cluster, client):
        done = []

        def kill_after_first(n, total):  # progress counts candidates, once per chunk
            done.append(n)
            if len(done) == 1:
                cluster.scale(0)

        kw = {"ratio": 2, "module": [1, 2, 3], "teeth": (12, 80), "shifts": (-0.5, 1, 0.1)}
        with (
            dask.config.set({"distributed.comm.timeouts.connect": 2}),
            pytest.raises(GearError, match=r"Dask cluster (lost work|has had no worker)"),
        ):
            pairs(**kw, client=client, chunk_size=2048, progress=kill_after_first)
        assert done and len(done) < 8  # it stopped, not finished (the space has 60+ chunks)


def test_a_cluster_without_workers_is_a_train_error():
    # synthesize_gearbox's stage searches wait for a worker no longer than the timeout
    with _one_worker_cluster() as (cluster, client):
        cluster.scale(0)
        t0 = time.monotonic()
        with (
            dask.config.set({"distributed.comm.timeouts.connect": 1}),
            pytest.raises(TrainError, match="no worker for 1 s"),
        ):
            synthesize_gearbox(37, 2, 3, client=client, progress=False)
        assert time.monotonic() - t0 < 10


def test_the_cli_reports_a_lost_worker_as_exit_2(capsys, monkeypatch):
    # the CLI's progress callback is where the test closes the worker, mid-search
    from trains.cli.gear_commands import search as command

    with _one_worker_cluster() as (cluster, _client):

        @contextlib.contextmanager
        def killing_bar(desc, total=None, delay=1.0, unit="block"):
            calls = []

            def update(n, total):
                calls.append(n)
                if len(calls) == 1:
                    cluster.scale(0)

            yield update

        monkeypatch.setattr(command, "progress_bar", killing_bar)
        # a space of many chunks of 65536 candidates (151 x 151 shifts per tooth pair)
        argv = [*SEARCH, "--module", "1", "2", "3", "--teeth", "12", "80", "--shifts", "-0.5",
                "1", "0.01", "--scheduler", cluster.scheduler_address, "--connect-timeout",
                "2"]  # fmt: skip
        err = _bad_input(capsys, argv, 30)
    assert "the Dask cluster lost work mid-run" in err or "has had no worker" in err, err


def test_parquet_without_pyarrow_is_exit_2_before_the_search(capsys, monkeypatch, tmp_path):
    # issue 16: the search used to run in full, then exit 2 and throw the table away
    import sys

    import gears.search.engine

    def no_search(*args, **kwargs):
        raise AssertionError("the search started")

    monkeypatch.setitem(sys.modules, "pyarrow", None)  # import pyarrow -> ImportError
    monkeypatch.setitem(sys.modules, "pyarrow.parquet", None)
    monkeypatch.setattr(gears.search.engine, "pairs", no_search)
    err = _bad_input(capsys, [*SEARCH, "-o", str(tmp_path / "r.parquet")], 10)
    assert "writing Parquet needs pyarrow" in err and "geartrain[parquet]" in err
    assert not (tmp_path / "r.parquet").exists()
