"""What sessions print goes to Python's streams: Printf to sys.stdout, log lines to
sys.stderr, so that notebooks and pytest's capture see them."""

import geomesh
from conftest import SQUARE


def test_run_prints_to_sys_stdout(write_script, capsys):
    # Printf shows from verbosity 3 (direct output) on, as in the reference.
    geomesh.run(write_script('Printf("hello %g", 42);\n'), dim=0, verbosity=3)
    captured = capsys.readouterr()
    assert "hello 42" in captured.out
    assert "hello 42" not in captured.err


def test_run_logs_to_sys_stderr_at_verbosity_5(write_script, capsys):
    geomesh.run(write_script(SQUARE), dim=2, verbosity=5)
    captured = capsys.readouterr()
    assert "Meshing" in captured.err
    assert "Meshing" not in captured.out


def test_run_at_verbosity_0_logs_nothing(write_script, capsys):
    geomesh.run(write_script(SQUARE), dim=2, verbosity=0)
    assert capsys.readouterr().err == ""


def test_the_api_session_logs_to_sys_stderr(capsys):
    geomesh.finalize()
    geomesh.initialize()
    geo = geomesh.model.geo
    geo.addPoint(0, 0, 0, 0.5)
    geo.addPoint(1, 0, 0, 0.5)
    geo.addLine(1, 2)
    geo.synchronize()
    geomesh.option.setNumber("General.Verbosity", 5)
    geomesh.model.mesh.generate(1)
    assert "Meshing" in capsys.readouterr().err
    geomesh.option.setNumber("General.Verbosity", 0)
    geomesh.model.mesh.generate(1)
    assert capsys.readouterr().err == ""
    geomesh.finalize()
