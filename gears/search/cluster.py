"""Layer 3, scheduling primitives: the Dask client and its results, the kept heap of a worker, the
progress bar.

What a search on a cluster needs besides its own chunks: the client resolved from an address
(asked first, never a hang), finished results gathered as they come with a lost cluster told as
a GearError, a worker's heap kept while a task runs. :func:`gears.search.pairs` and
``trains.synthesize_gearbox`` both use them.
"""

from __future__ import annotations

import contextlib
import os
import sys
import threading
import time
from collections.abc import Callable
from concurrent.futures import CancelledError, ThreadPoolExecutor

from gears.errors import GearError
from gears.geometry import check_real

__all__ = [
    "check_workers",
    "dask_client",
    "dask_results",
    "dask_timeout",
    "in_kept_heap",
    "kept_heap",
    "progress_callback",
]


def dask_timeout(timeout=None) -> float:
    """Seconds to wait for a Dask scheduler to answer, and for a worker when a cluster has none:
    ``timeout`` (a finite number > 0), or Dask's own setting
    ``distributed.comm.timeouts.connect`` (``dask.config.set(...)``; the CLI's
    ``--connect-timeout`` sets it)."""
    if timeout is None:
        import dask
        from dask.utils import parse_timedelta

        timeout = parse_timedelta(dask.config.get("distributed.comm.timeouts.connect"), "s")
    return check_real("distributed.comm.timeouts.connect", timeout, 0.0)


def _check_scheduler(address: str, seconds: float) -> None:
    """A GearError unless a Dask scheduler answers at ``address`` within ``seconds``: an unknown
    scheme, nothing listening, and a port where something else listens (an HTTP server, which
    would keep a Dask client waiting for ever) are told apart."""
    import asyncio

    from distributed.comm import connect
    from distributed.comm.addressing import parse_address, parse_host_port
    from distributed.comm.registry import get_backend

    try:
        scheme, location = parse_address(address)
        get_backend(scheme)
    except (ValueError, TypeError) as exc:
        raise GearError(
            f"Dask scheduler address {address!r}: {exc}; an address reads tcp://host:8786"
        ) from None
    if scheme in ("tcp", "tls"):  # a malformed port is bad input, not a server's answer
        port = location.rpartition(":")[2] if ":" in location else ""
        try:
            parse_host_port(location)
            ok = port.isdigit() and 0 < int(port) < 65536
        except (ValueError, TypeError):
            ok = False
        if not ok:
            raise GearError(
                f"Dask scheduler address {address!r}: the port {port!r} is not a port number "
                "(1 ... 65535); an address reads tcp://host:8786"
            )

    async def identity():
        comm = await connect(address, timeout=seconds)
        try:
            await comm.write({"op": "identity"})
            return await comm.read()
        finally:
            comm.abort()

    def ask():  # in a thread of its own, so that it also runs under a live event loop (Jupyter)
        return asyncio.run(asyncio.wait_for(identity(), seconds))

    wait = f"within {seconds:g} s (distributed.comm.timeouts.connect)"
    with ThreadPoolExecutor(1, thread_name_prefix="gears.dask_probe") as pool:
        try:
            reply = pool.submit(ask).result()
        except TimeoutError:  # asyncio's is the same class
            raise GearError(
                f"no Dask scheduler answered at {address!r} {wait}: nothing listens there, or "
                "something that is not a Dask scheduler does; check the address and the port"
            ) from None
        except OSError as exc:
            raise GearError(
                f"no Dask scheduler answered at {address!r} {wait}: {exc}; check the address "
                "and that the scheduler runs"
            ) from None
        except Exception as exc:  # a reply that is no Dask message
            raise GearError(
                f"{address!r} answered, but not as a Dask scheduler ({type(exc).__name__}); "
                "check the port (a scheduler listens on 8786 by default, its dashboard on 8787)"
            ) from None
    if not (isinstance(reply, dict) and reply.get("type") == "Scheduler"):
        kind = reply.get("type") if isinstance(reply, dict) else type(reply).__name__
        raise GearError(f"{address!r} answered as a {kind}, not as a Dask scheduler")


def dask_client(client, timeout: float | None = None):
    """The Dask client to use: the given one, one at this address, the active one, or None
    (``client=False``: local threads even with an active client).

    An address is asked first, within ``timeout`` seconds (default: Dask's
    ``distributed.comm.timeouts.connect``, see :func:`dask_timeout`): an unknown scheme
    (``foo://``), an address where nothing listens or where something else than a Dask
    scheduler answers (an HTTP server) is a GearError saying which, never a hang.
    """
    if client is False:
        return None
    if isinstance(client, str):
        try:
            from distributed import Client
        except ImportError:
            raise GearError("client='address' needs dask: pip install 'geartrain[scale]'") from None
        seconds = dask_timeout(timeout)
        _check_scheduler(client, seconds)
        try:
            opened = Client(client, timeout=seconds)
        except (OSError, TimeoutError) as exc:
            raise GearError(
                f"the Dask scheduler at {client!r} did not take a client: {exc}"
            ) from None
        try:
            check_workers(opened)
        except BaseException:
            opened.close()
            raise
        return opened
    if client is not None:
        if not hasattr(client, "submit"):
            raise GearError(f"client must be a dask.distributed.Client or an address; "
                            f"got {client!r}")  # fmt: skip
        check_workers(client)
        return client
    if "distributed" in sys.modules:  # an active client implies distributed is imported
        try:
            from distributed import get_client

            return get_client()
        except (ValueError, ImportError):
            return None
    return None


def check_workers(client) -> None:
    """A GearError unless every worker of ``client`` has this version of geartrain: a worker
    without it (or with another) would fail every task with a traceback from deep in Dask.
    Asked of each worker through :func:`importlib.metadata.version`, which every worker has."""
    import importlib.metadata

    try:  # this process's version, as gears.__version__ gives it
        __version__ = importlib.metadata.version("geartrain")
    except importlib.metadata.PackageNotFoundError:  # pragma: no cover - a bare source tree
        __version__ = None
    try:
        found = client.run(importlib.metadata.version, "geartrain", on_error="return")
    except (OSError, TimeoutError) as exc:
        raise GearError(f"the Dask cluster could not be asked for its versions: {exc}") from None
    # a worker that left meanwhile answers with a connection error: not a missing library
    missing = sorted(w for w, v in found.items()
                     if isinstance(v, importlib.metadata.PackageNotFoundError))  # fmt: skip
    other = sorted(f"{w} has {v}" for w, v in found.items() if isinstance(v, str)
                   and __version__ is not None and v != __version__)  # fmt: skip
    if missing or other:
        what = []
        if missing:
            what.append(f"{len(missing)} without geartrain ({', '.join(missing[:3])}"
                        f"{', ...' if len(missing) > 3 else ''})")  # fmt: skip
        if other:
            what.append(f"{len(other)} with another version ({', '.join(other[:3])})")
        raise GearError(
            f"of the Dask cluster's {len(found)} workers, {' and '.join(what)}: every worker "
            f"needs geartrain {__version__} (pip install 'geartrain[scale]=={__version__}' "
            "where the workers run)"
        )


_HEAP = {"lock": None, "active": 0}


@contextlib.contextmanager
def kept_heap():
    """Keep freed memory in this process's heap while the block runs, then give it back.

    Dask's nannies start workers with ``MALLOC_TRIM_THRESHOLD_=65536``: glibc then returns each
    free block over 64 kB to the system at once and maps each allocation over 128 kB afresh, so
    every numpy temporary of a chunk costs page faults (a gearbox sizing chunk ran 1.6-3x
    slower on a worker than in the client, docs/performance.md). Inside, the thresholds are
    raised (``mallopt``: trim 1 GiB, mmap 32 MiB); when the last such block of the process ends
    they are set back to the environment's values and the heap is trimmed (``malloc_trim``),
    so between tasks the worker's memory is as it asked. Does nothing without that setting or
    where the C library is not glibc.
    """
    trim = os.environ.get("MALLOC_TRIM_THRESHOLD_")
    libc = _glibc() if trim is not None else None
    if libc is None:
        yield
        return
    if _HEAP["lock"] is None:
        _HEAP["lock"] = threading.Lock()
    with _HEAP["lock"]:
        if _HEAP["active"] == 0:
            libc.mallopt(_M_TRIM_THRESHOLD, 1 << 30)
            libc.mallopt(_M_MMAP_THRESHOLD, 1 << 25)
        _HEAP["active"] += 1
    try:
        yield
    finally:
        with _HEAP["lock"]:
            _HEAP["active"] -= 1
            if _HEAP["active"] == 0:
                libc.mallopt(_M_TRIM_THRESHOLD, int(trim))
                mmap = os.environ.get("MALLOC_MMAP_THRESHOLD_", str(128 * 1024))
                libc.mallopt(_M_MMAP_THRESHOLD, int(mmap))
                libc.malloc_trim(0)


_M_TRIM_THRESHOLD, _M_MMAP_THRESHOLD = -1, -3  # glibc's mallopt parameters


def _glibc():
    """The C library when it is glibc (it has mallopt and malloc_trim), else None."""
    import ctypes
    import ctypes.util

    if not sys.platform.startswith("linux"):
        return None
    try:
        libc = ctypes.CDLL(ctypes.util.find_library("c") or "libc.so.6")
        libc.mallopt  # noqa: B018 - glibc has both
        libc.malloc_trim  # noqa: B018
    except (OSError, AttributeError):
        return None
    return libc


def in_kept_heap(fn: Callable, *args):
    """``fn(*args)`` inside :func:`kept_heap` (a Dask task that runs numpy on large blocks)."""
    with kept_heap():
        return fn(*args)


def dask_results(client, pending: set, timeout: float | None = None):
    """``(future, result)`` of each future of ``pending`` as it finishes; the caller may add
    futures to ``pending`` meanwhile.

    A cluster that fails under the work is a GearError saying what happened, not a Dask
    traceback: a worker lost with its task or with data the work needs (``KilledWorker``, a
    cancelled future), a lost connection to the scheduler, or a cluster left without workers
    for ``timeout`` seconds (default :func:`dask_timeout`). An error raised by the task itself
    reaches the caller unchanged. On any exception (Ctrl-C too) the futures still pending are
    cancelled, so no task of the search stays on the scheduler.
    """
    seconds = dask_timeout(timeout)
    try:
        yield from _results(client, pending, seconds)
    except BaseException:  # an error, Ctrl-C (KeyboardInterrupt), a closed generator
        # no task of this search stays on the scheduler
        with contextlib.suppress(Exception):
            client.cancel(list(pending))
        raise


def _results(client, pending: set, seconds: float):
    from distributed import wait
    from distributed.scheduler import KilledWorker

    lost = (CancelledError, KilledWorker, OSError)
    idle_since = None
    while pending:
        try:
            with client.as_current():  # wait() asks for the current client: this one, even
                done, _ = wait(  # when it is not the default (set_as_default=False)
                    list(pending), timeout=min(seconds, 1.0), return_when="FIRST_COMPLETED"
                )
        except TimeoutError:
            if _workers(client):
                idle_since = None
            elif idle_since is None:
                idle_since = time.monotonic()
            elif time.monotonic() - idle_since > seconds:
                raise GearError(
                    f"the Dask cluster has had no worker for {seconds:g} s "
                    "(distributed.comm.timeouts.connect) with work left: its workers died or "
                    "left; start workers, or run without client= (local threads)"
                ) from None
            continue
        except lost as exc:
            raise _lost_work(exc) from None
        done = list(done)
        pending.difference_update(done)
        try:  # every finished result in one round trip (one per future cost 5-10 ms each)
            results = client.gather(done)
        except lost as exc:
            raise _lost_work(exc) from None
        yield from zip(done, results, strict=True)


def _lost_work(exc: BaseException) -> GearError:
    return GearError(
        f"the Dask cluster lost work mid-run ({type(exc).__name__}): a worker died or left "
        "with tasks or data the work needs, or the scheduler went away; check the cluster and "
        "run again"
    )


def _workers(client) -> int:
    """Workers the scheduler knows of now (0 when it cannot be asked)."""
    try:
        return len(client.nthreads())
    except (OSError, TimeoutError, CancelledError):
        return 0


def progress_callback(
    progress, desc: str = "pair search", unit: str = "candidate"
) -> Callable[..., None] | None:
    """``progress`` as a callback ``(done, total)`` or None: a user's callable is returned as
    it is; None shows a tqdm bar on a terminal (the units done, their rate per second and the
    time left) and nothing otherwise; True always; False nothing."""
    if progress is False:
        return None
    if callable(progress):
        return lambda done, total: progress(done, total)
    if progress is None and not sys.stderr.isatty():
        return None
    if progress not in (None, True):
        raise GearError(f"progress = {progress!r}; valid are None, True, False or a callable")
    from tqdm import tqdm

    state = {}

    def update(done: int, total: int) -> None:
        if "bar" not in state:
            state["bar"] = tqdm(total=total, desc=desc, unit=unit, unit_scale=True, leave=False,
                                file=sys.stderr)  # fmt: skip
        bar = state["bar"]
        bar.total = total
        bar.update(done - bar.n)  # update(), not n =: tqdm's rate and time left follow it
        bar.refresh()
        if done >= total:
            bar.close()

    return update


def _announce_dashboard(client, progress) -> None:
    """Print the Dask dashboard's address on stderr above the progress bar (when the bar is
    shown and the cluster has a dashboard)."""
    if callable(progress):
        return
    link = getattr(client, "dashboard_link", None)
    if link:
        print(f"Dask dashboard: {link}", file=sys.stderr)
