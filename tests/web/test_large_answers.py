"""A large answer goes out in pieces (``web.app._PIECE``) and arrives whole: the same bytes as the command line's
JSON, with its length declared."""

import json

from bearinglab.cli import main
from bearinglab.web import app as web_app


def test_a_map_larger_than_a_piece_arrives_whole(client, capsys):
    query = {"bearing": "B218", "axial_load": "1kN:60kN:1kN", "speed": "1000rpm:10000rpm:1000rpm"}
    r = client.get("/api/high-speed", params=query)
    assert r.status_code == 200
    assert len(r.content) > 2 * web_app._PIECE  # three pieces
    assert int(r.headers["content-length"]) == len(r.content)
    doc = r.json()
    assert main(["high-speed", "-b", "B218", "-F", query["axial_load"], "-n", query["speed"], "--json"]) == 0
    assert doc == json.loads(capsys.readouterr().out)  # the command line's document, to the last digit
