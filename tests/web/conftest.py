"""One web application (with its worker processes) for the web tests of a session."""

import pytest
from fastapi.testclient import TestClient

from bearinglab.web import create_app


@pytest.fixture(scope="session")
def client():
    with TestClient(create_app(light_workers=2, heavy_workers=2)) as c:
        yield c
