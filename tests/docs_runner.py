"""Runs one documentation block in the process it is given (see test_docs.py).

Run by ``runpy.run_path`` in a fresh process with ``BLOCK`` (id, lang, code, root), ``WORKDIR``
and ``CONN`` (a pipe) in its globals; sends back ``error`` (a traceback or None), ``prints``
(last line of an expression statement -> what it printed or showed) and ``status`` (the CLI
exit codes)."""

import ast
import io
import os
import pathlib
import re
import shlex
import sys
import traceback


def run(block: dict, workdir: str, conn) -> None:
    # what a block prints is recorded below and sent back; the process's own output goes nowhere
    # (the block processes inherit the terminal of pytest, outside its capture)
    quiet = os.open(os.devnull, os.O_WRONLY)
    os.dup2(quiet, 1)
    os.dup2(quiet, 2)
    os.chdir(workdir)
    os.environ["MPLBACKEND"] = "Agg"
    root = pathlib.Path(block["root"])
    result = {"error": None, "prints": {}, "status": []}
    try:
        if block["lang"] == "python":
            # every expression statement reports what it shows, keyed by its last line (where its
            # comment is): a print call what it printed, any other expression its str() (as a
            # notebook cell would show it); the first time a line runs counts
            tree = ast.parse(block["code"])

            def record(line, text):
                result["prints"].setdefault(line, text)

            def show(line, value):
                if value is not None:
                    record(line, str(value))
                return value

            def printed(line, *args, **kwargs):
                if "file" not in kwargs:
                    buf = io.StringIO()
                    print(*args, **kwargs, file=buf)
                    record(line, buf.getvalue())
                print(*args, **kwargs)

            class Recorder(ast.NodeTransformer):
                def visit_Expr(self, node):
                    self.generic_visit(node)
                    v = node.value
                    if (
                        isinstance(v, ast.Call)
                        and isinstance(v.func, ast.Name)
                        and v.func.id == "print"
                    ):
                        call = ast.Call(
                            ast.Name("__printed__", ast.Load()),
                            [ast.Constant(node.end_lineno), *v.args],
                            v.keywords,
                        )
                    else:
                        call = ast.Call(
                            ast.Name("__show__", ast.Load()), [ast.Constant(node.end_lineno), v], []
                        )
                    return ast.copy_location(ast.Expr(call), node)

            tree = ast.fix_missing_locations(Recorder().visit(tree))
            env = {"__name__": "__main__", "__printed__": printed, "__show__": show}
            exec(compile(tree, f"<{block['id']}>", "exec"), env)
        elif block["lang"] == "bash":
            from trains.cli.app import main

            os.symlink(root / "examples", pathlib.Path.cwd() / "examples")
            for line in block["code"].splitlines():
                command, _, comment = line.partition("#")
                argv = shlex.split(command)
                if not argv:
                    continue
                if argv[0] != "geartrain":
                    raise AssertionError(f"a bash block line that is not a geartrain call: {line}")
                want = re.match(r"\s*exit (\d)", comment)
                result["status"].append((line, main(argv[1:]), int(want[1]) if want else None))
        else:  # toml: a train file
            from trains import read_train

            path = pathlib.Path.cwd() / "block.toml"
            path.write_text(block["code"])
            read_train(path)
    except BaseException:  # everything goes back to the test, which decides
        result["error"] = traceback.format_exc()
    sys.stdout.flush()
    conn.send(result)
    conn.close()


if __name__ == "__docs_block__":  # not when pytest imports it for doctests
    run(BLOCK, WORKDIR, CONN)  # noqa: F821 (the globals run_path was given)
