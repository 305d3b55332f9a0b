"""Layer 11, command line: the ``geartrain`` entry point.

Each sub-command is a module of :mod:`trains.cli.gear_commands` or
:mod:`trains.cli.train_commands` (or :mod:`trains.cli.demo`) exposing ``HELP`` (one line),
``add_arguments(parser)`` and ``run(args) -> int`` (0 every check passes, 1 a check fails); its
docstring is the user's description in ``geartrain CMD --help`` (plain text, with an
``Examples:`` block that a test runs). An optional ``NAMES`` mapping translates the library's
names in error messages (``x1``, ``split='keep'``) into the command's options (``--shift X1``,
``--split keep``). The modules are discovered (names starting with ``_`` are helpers), so adding
a command is adding a file.

The command modules import the library inside ``run()`` only: they sit at the top of the
layering, and building the parser (``geartrain --help``) must not pay for numpy or scipy.

Exit status (:func:`main`): 0 every check passes; 1 the design fails a check (the report is
printed and names it; files asked for are still written); 2 bad input, one line on stderr
naming the option, file or field, and nothing on stdout; 3 an internal error (a bug), with its
traceback.
"""

from __future__ import annotations

import argparse
import contextlib
import importlib
import io
import os
import pathlib
import pkgutil
import sys
import traceback

from trains.cli._common import BAD_INPUT, INTERNAL_ERROR, translate, wrap

EPILOG = """\
exit status (every command):
  0  every check passes
  1  the design fails a check (the report names the failed checks; mesh and profile print them
     on stderr and take --no-check); files asked for are still written
  2  bad input (one line on stderr naming the option, file or field; nothing on stdout)
  3  an internal error, a bug: the traceback is printed (please report it)

Examples:
    geartrain demo
    geartrain pair 12 24 --module 3 --shift 0.6 0.36
    geartrain synthesize --ratio 7 --planets 3

Run 'geartrain COMMAND --help' for a command's options."""


class HelpFormatter(argparse.RawDescriptionHelpFormatter, argparse.ArgumentDefaultsHelpFormatter):
    """Keeps the descriptions' line breaks and shows every option's default (not the ``None``
    and ``False`` of optional values and switches, whose help says what they do)."""

    def _get_help_string(self, action: argparse.Action) -> str:
        if action.default is None or action.default is False or "(default" in (action.help or ""):
            return action.help or ""
        return super()._get_help_string(action)


def _use_formatter(parser: argparse.ArgumentParser) -> None:
    """``parser`` and the parsers of its own sub-commands (``search pairs``) format their help
    with :class:`HelpFormatter`."""
    parser.formatter_class = HelpFormatter
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for nested in action.choices.values():
                _use_formatter(nested)


class UsageError(Exception):
    """An argparse usage error, reported as one line with exit status 2."""


class Parser(argparse.ArgumentParser):
    """An ``ArgumentParser`` whose usage errors raise :class:`UsageError` (one line, exit 2)
    instead of printing the usage and exiting."""

    def error(self, message: str):
        raise UsageError(f"{self.prog}: error: {message} (see '{self.prog} --help')")


class _Version(argparse.Action):
    """``--version``: the installed distribution's version, looked up only when asked (the
    metadata import would slow every ``--help``)."""

    def __init__(
        self, option_strings, dest=argparse.SUPPRESS, default=argparse.SUPPRESS, help=None
    ):
        super().__init__(option_strings, dest, nargs=0, default=default, help=help)

    def __call__(self, parser, namespace, values, option_string=None):
        from importlib.metadata import PackageNotFoundError, version

        try:
            v = version("geartrain")
        except PackageNotFoundError:  # pragma: no cover - running from a bare source tree
            v = "unknown"
        print(f"geartrain {v}")
        parser.exit()


def build_parser() -> argparse.ArgumentParser:
    """The ``geartrain`` parser with every sub-command of :mod:`trains.cli.gear_commands` and
    :mod:`trains.cli.train_commands`."""
    parser = Parser(
        prog="geartrain",
        description="Involute gear geometry, tooth profiles and gear-train solving.",
        epilog=EPILOG,
        formatter_class=HelpFormatter,
    )
    parser.add_argument("--version", action=_Version, help="show the version and exit")
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    found = {"demo": "trains.cli.demo"}
    for package in ("gear_commands", "train_commands"):  # read from disk: nothing imported
        for info in pkgutil.iter_modules([str(pathlib.Path(__file__).parent / package)]):
            if not info.name.startswith("_"):
                found[info.name] = f"trains.cli.{package}.{info.name}"
    for name in sorted(found):
        module = importlib.import_module(found[name])
        p = sub.add_parser(
            name, help=module.HELP, description=module.__doc__, epilog=EPILOG.split("\n\n")[0],
            formatter_class=HelpFormatter,
        )  # fmt: skip
        module.add_arguments(p)
        _use_formatter(p)
        p.set_defaults(run=module.run, names=getattr(module, "NAMES", {}))
    return parser


def main(argv: list[str] | None = None) -> int:
    """Run ``geartrain`` with ``argv`` (default ``sys.argv[1:]``); return the exit status.

    The command's report is collected and printed only when the command finishes, wrapped at
    the terminal width, so an error never follows half a report.
    """
    try:
        args = build_parser().parse_args(argv)
    except UsageError as exc:
        print(str(exc).replace("\n", " "), file=sys.stderr)
        return BAD_INPUT
    except SystemExit as exc:  # --help, --version
        return int(exc.code or 0) if not isinstance(exc.code, str) else BAD_INPUT
    from gears.errors import GearError
    from trains.errors import TrainError

    prog = f"geartrain {args.command}"
    out = io.StringIO()
    try:
        with contextlib.redirect_stdout(out):
            status = int(args.run(args) or 0)
    except (GearError, TrainError) as exc:
        message = translate(" ".join(str(exc).split()), args.names)
        print(f"{prog}: error: {message}", file=sys.stderr)
        return BAD_INPUT
    except OSError as exc:  # a file that cannot be read or written
        where = f": {exc.filename}" if exc.filename else ""
        print(f"{prog}: error: {exc.strerror or exc}{where}", file=sys.stderr)
        return BAD_INPUT
    except MemoryError as exc:  # a request too large for this machine
        print(
            f"{prog}: error: not enough memory for this request ({exc}); ask for less work "
            "(fewer teeth to search, a coarser --tolerance)", file=sys.stderr,
        )  # fmt: skip
        return BAD_INPUT
    except KeyboardInterrupt:
        print(f"{prog}: interrupted", file=sys.stderr)
        return 130
    except Exception:
        traceback.print_exc()
        print(f"{prog}: internal error (a bug in geartrain; please report it)", file=sys.stderr)
        return INTERNAL_ERROR
    text = out.getvalue()
    try:
        if text:
            sys.stdout.write(wrap(text.rstrip("\n")) + "\n")
        sys.stdout.flush()
    except BrokenPipeError:  # `geartrain ... | head`: the reader has gone, which is no error
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
    return status


if __name__ == "__main__":
    sys.exit(main())
