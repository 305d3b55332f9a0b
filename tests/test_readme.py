"""The README starts with the two set-up commands that CI runs (its blocks run in test_docs.py)."""

import pathlib
import re

README = pathlib.Path(__file__).parent.parent / "README.md"


def test_readme_starts_with_the_two_commands():
    text = README.read_text()
    first = re.search(r"```bash\n(.*?)```", text, flags=re.S).group(1).strip().splitlines()
    assert first == [
        'pip install -e ".[all]" && geartrain demo --scene stage.glb',
        'pip install -e ".[test]" && pytest',
    ]
    ci = (README.parent / ".ci" / "run").read_text()
    assert 'pip install -q -e ".[test]"' in ci and "python3 -m pytest" in ci


def test_readme_says_the_tests_take_minutes_and_build_the_site():
    # a new user who runs the second command waits minutes: the README says so, and why
    text = README.read_text()
    intro = text[: text.index("## ")]
    assert "minutes" in intro and "site" in intro and "test_site.py" in intro
