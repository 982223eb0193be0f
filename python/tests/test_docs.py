"""The `python` code blocks of docs/python.md and docs/scale-out.md, each page run as one
script from the source folder: the documented examples work as written."""
import os
import re
import subprocess
import sys

import pytest

from conftest import SOURCE_DIR

BLOCK = re.compile(r"^```python\n(.*?)^```", re.S | re.M)


@pytest.mark.parametrize("page", ["python.md", "scale-out.md"])
def test_documented_examples_run(page):
    blocks = BLOCK.findall((SOURCE_DIR / "docs" / page).read_text())
    assert len(blocks) >= 1
    script = "\n".join(blocks)
    completed = subprocess.run([sys.executable, "-c", script], cwd=SOURCE_DIR, env=os.environ,
                               capture_output=True, text=True, timeout=600, check=False)
    assert completed.returncode == 0, completed.stderr
    assert completed.stdout.strip()
