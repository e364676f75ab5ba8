"""``bearinglab serve`` and the command line's JSON adapter (``cli.run_json``) the web API runs on."""

import json
import socket
import subprocess
import sys

import pytest
import uvicorn

from bearinglab import cli
from bearinglab.cli import serve as serve_cli


@pytest.fixture
def bound_port():
    """A port of 127.0.0.1 this test holds (bound and listening), closed when the test ends."""
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as sock:
        sock.bind(("127.0.0.1", 0))
        sock.listen()
        yield sock.getsockname()[1]


@pytest.fixture
def no_bind_check(monkeypatch):
    """These tests are about the arguments uvicorn gets: a port another program holds is no concern."""
    monkeypatch.setattr(serve_cli, "_check_bindable", lambda host, port: None)


def test_serve_is_a_command_and_listens_on_localhost_by_default(monkeypatch, capsys, no_bind_check):
    calls = []
    monkeypatch.setattr(uvicorn, "run", lambda app, **kw: calls.append((app, kw)))
    assert cli.main(["serve"]) == 0
    ((app, kw),) = calls
    assert kw["host"] == "127.0.0.1" and kw["port"] == 8000
    assert {route.path for route in app.routes} >= {"/", "/api/high-speed", "/api/catalog/search"}
    assert "http://127.0.0.1:8000/" in capsys.readouterr().out


def test_serve_takes_host_and_port(monkeypatch, capsys, no_bind_check):
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


def test_serve_on_a_port_in_use_is_one_line_and_exit_2(monkeypatch, capsys, bound_port):
    calls = []
    monkeypatch.setattr(uvicorn, "run", lambda app, **kw: calls.append(kw))
    assert cli.main(["serve", "--port", str(bound_port)]) == 2
    out, err = capsys.readouterr()
    assert out == "" and calls == []  # no banner, no server
    assert err == f"bearinglab: error: port: {bound_port} is already in use on 127.0.0.1\n"


@pytest.mark.parametrize("host", ["256.1.1.1"])
def test_serve_on_an_address_it_cannot_have_is_one_line_and_exit_2(monkeypatch, capsys, host):
    calls = []
    monkeypatch.setattr(uvicorn, "run", lambda app, **kw: calls.append(kw))
    assert cli.main(["serve", "--host", host, "--port", "8765"]) == 2
    out, err = capsys.readouterr()
    assert out == "" and calls == []
    assert err.startswith(f"bearinglab: error: host: cannot listen on '{host}' (")
    assert err.count("\n") == 1


def test_serve_checks_the_port_it_is_given_on_a_free_port(monkeypatch, capsys):
    # the check closes its socket: the server can bind the same port right after
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        port = probe.getsockname()[1]
    seen = []

    def run(app, host, port, **kw):
        with socket.socket() as sock:
            sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
            sock.bind((host, port))
            sock.listen()
            seen.append(port)

    monkeypatch.setattr(uvicorn, "run", run)
    assert cli.main(["serve", "--port", str(port)]) == 0
    assert seen == [port] and f"http://127.0.0.1:{port}/" in capsys.readouterr().out


def test_serve_startup_failure_of_uvicorn_is_exit_2_not_3(monkeypatch, capsys, no_bind_check):
    # a port taken between the check and uvicorn's bind: uvicorn exits 3, our code for a solver
    def run(app, **kw):
        raise SystemExit(3)

    monkeypatch.setattr(uvicorn, "run", run)
    assert cli.main(["serve", "--port", "8765"]) == 2
    assert capsys.readouterr().err.endswith(
        "bearinglab: error: serve: the server could not start on 127.0.0.1:8765\n"
    )


def test_the_command_line_does_not_import_the_web_framework():
    code = "import sys, bearinglab, bearinglab.cli; print(any(m.split('.')[0] in ('fastapi', 'uvicorn', 'starlette') for m in sys.modules))"
    out = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=True
    ).stdout
    assert out.strip() == "False"


def test_the_web_does_not_import_the_command_line():
    # issue 22: the web answers through the typed layer; neither the server nor a worker's warm-up and
    # calculations (life, the high-speed figure, a posted runout error set) load bearinglab.cli
    code = (
        "import importlib, sys\n"
        "import bearinglab.web.app, bearinglab.web.api, bearinglab.web.page, bearinglab.web.workers as w\n"
        "from bearinglab import calculations\n"
        "for m in w._CALCULATION_MODULES: importlib.import_module(m)\n"
        "calculations.run(calculations.parse('life', {'bearing': '6205-2RS', 'radial_load': '2 kN', "
        "'speed': '3000 rpm'}))\n"
        "calculations.figure_svg(calculations.parse('high-speed', {'bearing': 'B218', "
        "'axial_load': '10 kN, 20 kN', 'speed': '6000 rpm'}))\n"
        "print(sorted(m for m in sys.modules if m == 'bearinglab.cli' or m.startswith('bearinglab.cli.')))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "[]"


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
