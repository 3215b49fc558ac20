"""algkin.runtime.child: the one way work runs in a forked child: its answer, its error raised in
the parent as itself, its notes heard on the way, and no child left however the wait ends.

No test here waits on the machine's clock: the time left is what the test says."""

import multiprocessing
import os
import threading

import pytest

from algkin.errors import ComputationError, SceneError
from algkin.runtime.child import TimeUp, forked


def test_the_answer_and_the_notes_before_it():
    def work(tell):
        tell("loading")
        tell(("compiling", 2))
        return {"answer": [1, 2, 3]}

    heard = []
    with forked(work) as child:
        assert child.answer(heard=heard.append) == {"answer": [1, 2, 3]}
    assert heard == ["loading", ("compiling", 2)]
    assert multiprocessing.active_children() == []


def test_an_error_in_the_child_is_raised_as_itself():
    def work(tell):
        raise SceneError("fourbar.toml", "B", "can never assemble")

    with forked(work) as child, pytest.raises(SceneError, match="fourbar.toml: B: can never assemble"):
        child.answer()


class Stubborn(Exception):
    """An error that pickles but cannot be rebuilt (its constructor wants two arguments), nor be
    pickled whole (a lock among its attributes: distributed, once imported by an earlier test,
    installs tblib's pickling of every exception class, which rebuilds one without its constructor)."""

    def __init__(self, one, two):
        super().__init__(f"{one} and {two}")
        self.lock = threading.Lock()


def test_an_error_that_cannot_travel_is_named():
    def work(tell):
        raise Stubborn("this", "that")

    with forked(work) as child, pytest.raises(ComputationError, match="^Stubborn: this and that$"):
        child.answer()


def test_a_result_that_cannot_travel_is_an_error():
    with forked(lambda tell: threading.Lock()) as child, \
            pytest.raises(ComputationError, match="the result could not be sent back"):
        child.answer()


def test_a_child_that_dies_without_an_answer():
    with forked(lambda tell: os._exit(3)) as child, \
            pytest.raises(ComputationError, match=r"ended without an answer \(exit code 3\)"):
        child.answer()


def test_no_time_left_stops_the_child():
    # the child would wait forever; the time is up at the first look
    with forked(lambda tell: threading.Event().wait()) as child, pytest.raises(TimeUp):
        child.answer(left=lambda: 0.0)
    assert multiprocessing.active_children() == []


def test_an_answer_sent_in_time_is_taken_after_the_time_is_up():
    def left():
        for process in multiprocessing.active_children():
            process.join()  # the child has answered and ended before the time is found up
        return 0.0

    with forked(lambda tell: 42) as child:
        assert child.answer(left=left) == 42


def test_the_child_is_reaped_however_the_block_ends():
    with pytest.raises(KeyboardInterrupt), forked(lambda tell: threading.Event().wait()):
        raise KeyboardInterrupt  # as a signal's handler would, while the parent waits
    assert multiprocessing.active_children() == []
