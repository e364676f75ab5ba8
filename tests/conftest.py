"""Test configuration.

Hypothesis explores new random examples on every local run (and remembers failures in .hypothesis/).
Under CI (the environment variable CI is set, as the CI runner does) it runs derandomized: the same
examples every time, so a CI result depends on the code only. Failures that random exploration finds
locally are added to the tests as explicit @example cases.
"""

import os

from hypothesis import settings

settings.register_profile("ci", derandomize=True, database=None)
if os.environ.get("CI"):
    settings.load_profile("ci")
