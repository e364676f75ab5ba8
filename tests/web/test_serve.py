"""``bearinglab serve`` and the command line's JSON adapter (``cli.run_json``) the web API runs on."""

import json
import subprocess
import sys

import uvicorn

from bearinglab import cli


def test_serve_is_a_command_and_listens_on_localhost_by_default(monkeypatch, capsys):
    calls = []
    monkeypatch.setattr(uvicorn, "run", lambda app, **kw: calls.append((app, kw)))
    assert cli.main(["serve"]) == 0
    ((app, kw),) = calls
    assert kw["host"] == "127.0.0.1" and kw["port"] == 8000
    assert {route.path for route in app.routes} >= {"/", "/api/{endpoint}"}
    assert "http://127.0.0.1:8000/" in capsys.readouterr().out


def test_serve_takes_host_and_port(monkeypatch, capsys):
    calls = []
    monkeypatch.setattr(uvicorn, "run", lambda app, **kw: calls.append(kw))
    assert cli.main(["serve", "--host", "0.0.0.0", "--port", "8123"]) == 0
    assert calls == [{"host": "0.0.0.0", "port": 8123, "log_level": "warning"}]


def test_serve_rejects_a_bad_port(capsys):
    assert cli.main(["serve", "--port", "70000"]) == 2
    assert (
        capsys.readouterr().err.strip()
        == "bearinglab: error: port must be in [0, 65535], got 70000"
    )


def test_the_command_line_does_not_import_the_web_framework():
    code = "import sys, bearinglab, bearinglab.cli; print(any(m.split('.')[0] in ('fastapi', 'uvicorn', 'starlette') for m in sys.modules))"
    out = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=True
    ).stdout
    assert out.strip() == "False"


def test_run_json_gives_the_document_the_command_prints(capsys):
    argv = ["axial-angle", "--bearing", "4-1006095", "--axial-load", "2 kgf"]
    run = cli.run_json(argv)
    assert cli.main([*argv, "--json"]) == 0
    assert run == (0, json.loads(capsys.readouterr().out), "")


def test_run_json_gives_the_error_line_without_printing(capsys):
    run = cli.run_json(["axial-angle", "--bearing", "4-1006095", "--axial-load", "2 m"])
    assert run.exit_code == 2 and run.document is None
    assert run.error.startswith("axial-load: ") and "force" in run.error
    assert capsys.readouterr() == ("", "")
