"""``python -m bearinglab``: the command line, as the ``bearinglab`` console script runs it."""

from bearinglab.cli import run

__all__: list[str] = []

if __name__ == "__main__":
    run()
