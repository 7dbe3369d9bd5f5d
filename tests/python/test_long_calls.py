# Long calls: Ctrl-C ends them, other Python threads run meanwhile, and a failing progress
# callback stops them (docs/python.md, "Long calls").
import os
import signal
import threading
import time

import pytest

import tripack


def test_keyboard_interrupt_ends_a_search_within_a_second():
    sent = {}

    def interrupt():
        sent["at"] = time.monotonic()
        os.kill(os.getpid(), signal.SIGINT)  # as Ctrl-C: Python's handler, then the call's check

    timer = threading.Timer(2.0, interrupt)
    timer.start()
    started = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        tripack.search(80, seconds=60, threads=2)
    ended = time.monotonic()
    timer.join()
    assert ended - started < 30  # it did not run its 60 s
    assert ended - sent["at"] < 1.0, ended - sent["at"]
    # The module is usable afterwards.
    assert tripack.build("four-delta", k=2).certified


def test_other_threads_run_during_a_long_call():
    ticks = []
    stop = threading.Event()

    def count():
        while not stop.is_set():
            ticks.append(time.monotonic())
            time.sleep(0.01)

    counter = threading.Thread(target=count)
    counter.start()
    started = time.monotonic()
    tripack.search(30, seconds=1.5, builder_starts=False)
    ended = time.monotonic()
    stop.set()
    counter.join()
    during = [t for t in ticks if started < t < ended]
    # Sleeping 10 ms a tick, the thread ticks close to 150 times in 1.5 s when the call releases
    # the GIL (a loaded machine, fewer); a call that held it would let it tick none while it ran.
    assert len(during) >= 10, len(during)


def test_an_exception_in_the_progress_callback_stops_the_call():
    class Enough(Exception):
        pass

    calls = []

    def progress(report):
        calls.append(report)
        raise Enough()

    started = time.monotonic()
    with pytest.raises(Enough):
        tripack.billiards(40, runs=200, threads=2, progress=progress)
    assert time.monotonic() - started < 10 and len(calls) == 1
