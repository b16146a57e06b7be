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


def best_on_fresh(make, call, runs=3):
    """The shortest time of `runs` calls of `call` (seconds), each on a freshly made
    argument (`make()`, not timed), and the last call's result: OpenCascade's booleans may
    change their arguments (they raise the tolerances of the sub-shapes they cut), so a
    second boolean on the same shape is not the user's first."""
    times, result = [], None
    for _ in range(runs):
        argument = make()
        start = time.perf_counter()
        result = call(argument)
        times.append(time.perf_counter() - start)
    return min(times), result
