"""The watchdog's thread is woken only when a computation's stop time is the new earliest."""

from __future__ import annotations

import threading

from app.admission import Ticket, Watchdog


def test_only_a_new_earliest_stop_wakes_the_thread() -> None:
    watchdog = Watchdog()
    watchdog._thread = threading.Thread(target=lambda: None)  # not started: nothing clears
    first, later, earlier = (Ticket(arrival=0.0, deadline=t) for t in (10.0, 20.0, 5.0))
    watchdog.watch(first, 10.0)
    assert watchdog._wake.is_set()  # the heap was empty
    watchdog._wake.clear()
    watchdog.watch(later, 20.0)
    assert not watchdog._wake.is_set()  # the thread already sleeps until 10
    watchdog.watch(earlier, 5.0)
    assert watchdog._wake.is_set()
    assert [entry[2] for entry in sorted(watchdog._heap)] == [earlier, first, later]
