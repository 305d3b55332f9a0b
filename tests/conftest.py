"""Slow work that waits for nothing the tests do starts in the background as soon as the tests
are collected, and runs beside the rest of the suite.

A test module that defines ``start_in_background(session)`` has it called once when collection
ends (with the collected items in ``session.items``: it starts only what its selected tests
need), and ``stop_in_background()`` when the session ends (a run stopped early, by ``-x`` or
Ctrl-C, leaves nothing behind). Two modules do: ``tests/test_site.py`` (the site build, a third of
the suite's time, in a process of its own) and ``tests/test_docs.py`` (every documentation block,
each in a process of its own). Their tests then wait for the result and check it as before; the
work and every check are the same, only the suite's other tests no longer wait for it.
"""

from __future__ import annotations


def _modules(session):
    seen = {}
    for item in session.items:
        module = getattr(item, "module", None)
        if module is not None:
            seen.setdefault(id(module), module)
    return list(seen.values())


def pytest_collection_finish(session):
    if session.config.option.collectonly:
        return
    for module in _modules(session):
        start = getattr(module, "start_in_background", None)
        if start is not None:
            start(session)


def pytest_sessionfinish(session):
    for module in _modules(session):
        stop = getattr(module, "stop_in_background", None)
        if stop is not None:
            stop()
