"""The examples of the guide page docs/guide/python.md run as printed: every ```python block,
in order and in one namespace, prints exactly the ```text block after it (run in a scratch
directory beside the repository's data/, as from the repository's root)."""
import contextlib
import io
import os
import re

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
PAGE = os.path.join(ROOT, "docs", "guide", "python.md")


def examples():
    text = open(PAGE, encoding="utf-8").read()
    return re.findall(r"```python\n(.*?)```\s*```text\n(.*?)```", text, re.S)


def test_page_has_examples():
    assert len(examples()) >= 5


def test_examples_run_as_printed(tmp_path, monkeypatch):
    pytest.importorskip("matplotlib")
    os.symlink(os.path.join(ROOT, "data"), tmp_path / "data")
    monkeypatch.chdir(tmp_path)
    namespace = {}
    for code, expected in examples():
        printed = io.StringIO()
        with contextlib.redirect_stdout(printed):
            exec(compile(code, PAGE, "exec"), namespace)
        assert printed.getvalue() == expected, code
    assert (tmp_path / "chart.png").stat().st_size > 1000
    assert (tmp_path / "out" / "spring_amplitudes_points.dat").exists()
