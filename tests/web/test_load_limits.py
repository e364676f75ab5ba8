"""The web under load: time budget, cancellation on disconnect, light requests beside heavy ones.

A real server (uvicorn on 127.0.0.1, a free port, in a thread) with a short time budget, so that a
heavy request is stopped within the test's time.
"""

import socket
import threading
import time

import httpx
import pytest
import uvicorn

from bearinglab.web import create_app

BUDGET = 3.0
# 96 000 high-speed cases (under the case limit, _bounds.MAX_CASES): many seconds of work on this
# machine, far over the budget above
HEAVY = {"bearing": "B218", "axial_load": "1N:1600N:1N", "speed": "1rpm:60rpm:1rpm"}
LIGHT = {"bearing": "6205-2RS", "speed": "1797 rpm"}


@pytest.fixture(scope="module")
def server():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    app = create_app(light_workers=1, heavy_workers=2, time_budget=BUDGET)
    srv = uvicorn.Server(uvicorn.Config(app, host="127.0.0.1", port=port, log_level="warning"))
    thread = threading.Thread(target=srv.run, daemon=True)
    thread.start()
    deadline = time.monotonic() + 60
    while not srv.started:
        assert time.monotonic() < deadline and thread.is_alive(), "the server did not start"
        time.sleep(0.05)
    url = f"http://127.0.0.1:{port}"
    httpx.get(url + "/api/frequencies", params=LIGHT, timeout=60)  # the workers are up
    yield url, app
    srv.should_exit = True
    thread.join(10)


def test_a_request_over_its_budget_is_stopped_and_named(server):
    url, app = server
    before = set(app.state.server.heavy.pids())
    start = time.monotonic()
    r = httpx.get(url + "/api/high-speed", params=HEAVY, timeout=60)
    took = time.monotonic() - start
    assert r.status_code == 503
    assert r.json()["error"] == "limit" and f"time budget of {BUDGET:g} s" in r.json()["detail"]
    assert took < BUDGET + 3
    time.sleep(0.5)
    assert set(app.state.server.heavy.pids()) != before  # the worker was stopped and replaced
    assert httpx.get(url + "/api/frequencies", params=LIGHT, timeout=30).status_code == 200


def test_a_light_request_is_answered_while_heavy_ones_run(server):
    url, _ = server
    heavy = [threading.Thread(target=lambda: httpx.get(url + "/api/high-speed", params=HEAVY, timeout=60))
             for _ in range(4)]
    for t in heavy:
        t.start()
    time.sleep(0.5)
    times = []
    for _ in range(5):
        start = time.monotonic()
        r = httpx.get(url + "/api/frequencies", params=LIGHT, timeout=30)
        times.append(time.monotonic() - start)
        assert r.status_code == 200
    for t in heavy:
        t.join()
    assert max(times) < 1.5, times  # not held behind 4 heavy requests of seconds each


def test_a_client_that_goes_away_cancels_its_work(server):
    url, app = server
    time.sleep(0.5)
    before = set(app.state.server.heavy.pids())
    with pytest.raises(httpx.ReadTimeout):
        httpx.get(url + "/api/high-speed", params=HEAVY, timeout=0.8)
    deadline = time.monotonic() + 2.0  # well before the budget of 3 s would stop it
    while set(app.state.server.heavy.pids()) == before and time.monotonic() < deadline:
        time.sleep(0.1)
    assert set(app.state.server.heavy.pids()) != before


def test_a_worker_past_its_memory_bound_is_replaced():
    """Memory comes back: a worker whose peak memory passed the bound after a request is replaced (a
    bound of 1 MB, which every worker passes, replaces it after every request)."""
    from fastapi.testclient import TestClient

    with TestClient(create_app(light_workers=1, heavy_workers=1, memory_bound_mb=1)) as client:
        pool = client.app.state.server.light
        seen = []
        for _ in range(3):
            assert client.get("/api/frequencies", params=LIGHT).status_code == 200
            seen.append(tuple(pool.pids()))
        assert len(set(seen)) == 3, seen


def test_a_worker_that_died_is_replaced_and_no_request_sees_a_500():
    """A worker killed from outside (out of memory, an operator): the next requests are answered."""
    import os
    import signal

    from fastapi.testclient import TestClient

    with TestClient(create_app(light_workers=1, heavy_workers=1)) as client:
        assert client.get("/api/frequencies", params=LIGHT).status_code == 200
        (pid,) = client.app.state.server.light.pids()
        os.kill(pid, signal.SIGKILL)
        time.sleep(0.3)
        statuses = [client.get("/api/frequencies", params=LIGHT).status_code for _ in range(3)]
        assert 500 not in statuses and statuses[-1] == 200, statuses
        assert client.app.state.server.light.pids() != [pid]
