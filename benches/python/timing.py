"""The timing both sweep benchmarks use: the best of a few runs of a call."""

import time


def best(call, runs=3):
    """The shortest time of `runs` calls (seconds) and the last call's result."""
    times, result = [], None
    for _ in range(runs):
        start = time.perf_counter()
        result = call()
        times.append(time.perf_counter() - start)
    return min(times), result
