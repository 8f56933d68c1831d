"""Ctrl-C while the command line starts: its modules still loading (assur._start).

A ``sitecustomize`` on the subprocess's path sends the process SIGINT as numpy is
first looked for: a Ctrl-C during ``import assur`` at a point known in advance, not
after a guessed delay.
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
from pathlib import Path

import pytest

from assur import _start, cli

from .conftest import EXAMPLES

ROOT = Path(__file__).resolve().parent.parent
SLIDER = EXAMPLES / "slider_crank_exercise.toml"

CTRL_C_AT_NUMPY = """\
import os, signal, sys

class CtrlC:
    def find_spec(self, name, path=None, target=None):
        if name == "numpy":
            sys.meta_path.remove(self)
            os.kill(os.getpid(), signal.SIGINT)
        return None

sys.meta_path.insert(0, CtrlC())
"""

# the console script as pip writes it
SCRIPT = """\
#!{python}
import re
import sys
from assur.cli import main
if __name__ == '__main__':
    sys.argv[0] = re.sub(r'(-script\\.pyw|\\.exe)?$', '', sys.argv[0])
    sys.exit(main())
"""


def run(tmp_path: Path, *argv: str) -> subprocess.CompletedProcess[str]:
    """Run ``python ARGV`` with Ctrl-C sent as numpy is first imported."""
    if not hasattr(os, "kill") or sys.platform == "win32":
        pytest.skip("no SIGINT to send")
    hooks = tmp_path / "hooks"
    hooks.mkdir(exist_ok=True)
    (hooks / "sitecustomize.py").write_text(CTRL_C_AT_NUMPY, encoding="utf-8")
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(hooks), str(ROOT)]))
    return subprocess.run(
        [sys.executable, *argv],
        cwd=tmp_path,
        env=env,
        capture_output=True,
        text=True,
        timeout=120,
        check=False,
    )


def test_ctrl_c_while_python_m_assur_loads_is_one_line(tmp_path: Path):
    # it was a traceback of 7 to 46 lines ending in KeyboardInterrupt
    result = run(tmp_path, "-m", "assur", "forces", str(SLIDER), "--csv", "out.csv")
    assert (result.returncode, result.stderr) == (130, "assur: interrupted\n")
    assert result.stdout == ""
    assert not (tmp_path / "out.csv").exists()


@pytest.mark.parametrize("typed", ["absolute", "bin/assur", "./bin/assur"])
def test_ctrl_c_while_the_assur_script_loads_is_one_line(tmp_path: Path, typed: str):
    # the script named as the shell was given it: a relative name was not known
    script = tmp_path / "bin" / "assur"
    script.parent.mkdir()
    script.write_text(SCRIPT.format(python=sys.executable), encoding="utf-8")
    name = str(script) if typed == "absolute" else typed
    result = run(tmp_path, name, "forces", str(SLIDER), "--csv", "out.csv")
    assert (result.returncode, result.stderr) == (130, "assur: interrupted\n")
    assert not (tmp_path / "out.csv").exists()


def test_a_plain_import_keeps_python_s_ctrl_c(tmp_path: Path):
    # a program of the user's that imports assur gets its KeyboardInterrupt; the
    # package loads numpy with its first name used, here the analysis
    code = (
        "try:\n    import assur\n    assur.forces\nexcept KeyboardInterrupt:\n"
        "    print('caught')\n"
        "import signal; print(signal.getsignal(signal.SIGINT).__name__)\n"
    )
    result = run(tmp_path, "-c", code)
    assert result.returncode == 0, result.stderr
    assert result.stdout == "caught\ndefault_int_handler\n"
    script = tmp_path / "assur"  # a script of that name, not the console script's
    script.write_text(code, encoding="utf-8")
    result = run(tmp_path, str(script))
    assert result.stdout == "caught\ndefault_int_handler\n"


def test_the_command_line_takes_ctrl_c_back_once_loaded(capsys):
    # after the modules, Ctrl-C is a KeyboardInterrupt again, which main() catches
    # and which removes the outputs' temporary files (test_cli_robustness)
    before = signal.signal(signal.SIGINT, _start._interrupted)
    try:
        assert cli.main(["structure", str(SLIDER)]) == 0
        assert signal.getsignal(signal.SIGINT) is signal.default_int_handler
    finally:
        signal.signal(signal.SIGINT, before)
    capsys.readouterr()
