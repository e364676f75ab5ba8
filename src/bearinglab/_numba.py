"""What the compiled kernels share: the lock that keeps two parallel numba launches apart.

numba's default (workqueue) threading layer aborts the process on concurrent launches of parallel kernels,
so every kernel that runs over threads (:mod:`bearinglab.quasistatic._compiled`,
:mod:`bearinglab.stand._compiled`) takes this one lock. Kept in its own base module so that the kernels of
different packages share it without importing each other. This module does not import numba.

Names
-----
LOCK    the one lock of every parallel compiled kernel
"""

from __future__ import annotations

import threading

__all__ = ["LOCK"]

#: Held while a parallel compiled kernel runs: numba's workqueue layer does not allow concurrent launches.
LOCK = threading.Lock()
