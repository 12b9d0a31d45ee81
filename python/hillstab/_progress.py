"""Progress of long calls (internal): the ``progress=`` argument of `floquet`, `chart`,
`System.points` and `System.chart`.

``progress`` is None or False (no report), a callable (called from Python as
``progress(done, total)``, done increasing up to total), or True (a bar from tqdm when it is
installed, else a line on stderr rewritten in place). The numbers equal those of a call
without progress to the bit:

- points (`floquet`, `System.points`) are split into chunks computed one after the other,
  each point being computed alone (any split gives the same numbers);
- a chart is computed by one call into the library, in a worker thread, while the calling
  thread counts the rows whose every status has been written and reports them (`watch`).
  A chart is not split: the library computes its rows differently with many rows than with
  few (whole rows on a thread each, or each row's points in chunks sharing the row's
  meshes), and the error estimates of the two ways may differ in their last bits.
"""
import math
import sys
import threading

import numpy as np


def chunks(total, size):
    """(start, stop) of consecutive chunks of at most `size` items covering range(total)."""
    size = max(1, int(size))
    return [(start, min(total, start + size)) for start in range(0, total, size)]


def chunk_size(chunk, total, least):
    """The items per progress step: `chunk` when given (a whole number >= 1), else about 1 %
    of the total and at least `least`."""
    if chunk is None:
        return max(least, int(math.ceil(total / 100.0)))
    if isinstance(chunk, bool) or int(chunk) != chunk or chunk < 1:
        raise ValueError("chunk: must be a whole number >= 1, got {!r}".format(chunk))
    return int(chunk)


class Progress:
    """Reports done/total to a callable, a tqdm bar or stderr; inactive for None/False."""

    def __init__(self, progress, total, unit):
        self.callback = None
        self.bar = None
        self.text = False
        self.total = int(total)
        self.unit = unit
        if progress is None or progress is False:
            return
        if progress is True:
            try:
                from tqdm.auto import tqdm
            except ImportError:
                self.text = True
            else:
                self.bar = tqdm(total=self.total, unit=" " + unit, desc="hillstab")
            return
        if not callable(progress):
            raise TypeError("progress: must be None, True/False or a callable progress(done, total), got {}".format(
                type(progress).__name__))
        self.callback = progress

    @property
    def active(self):
        """Whether the work is to be split and reported."""
        return self.callback is not None or self.bar is not None or self.text

    def update(self, done):
        """Report that `done` of the total are computed."""
        if self.callback is not None:
            self.callback(int(done), self.total)
        elif self.bar is not None:
            self.bar.update(int(done) - self.bar.n)
        elif self.text:
            sys.stderr.write("\rhillstab: {} of {} {}".format(int(done), self.total, self.unit))
            sys.stderr.flush()

    def close(self):
        if self.bar is not None:
            self.bar.close()
        elif self.text:
            sys.stderr.write("\n")
            sys.stderr.flush()


#: a status no point has (the rows still to come)
PENDING = -99


def watch(call, status, report, interval=0.05):
    """Run ``call()`` (a ctypes call into the library, which releases the GIL, and its check)
    in a worker thread while this thread reports the rows of `status` (2-D, rows first,
    C ints) whose every entry has been written. Returns call's result; re-raises its error
    (the library's message is read in the worker, whose thread it belongs to)."""
    status[...] = PENDING
    outcome = {}

    def work():
        try:
            outcome["value"] = call()
        except BaseException as error:  # noqa: B902 - handed to the calling thread
            outcome["error"] = error

    worker = threading.Thread(target=work, name="hillstab", daemon=True)
    worker.start()
    done = 0
    try:
        while worker.is_alive():
            worker.join(interval)
            rows = int(np.count_nonzero((status != PENDING).all(axis=1)))
            if rows > done and "error" not in outcome:
                done = rows
                report.update(done)
    finally:
        worker.join()
    if "error" in outcome:
        raise outcome["error"]
    if done < report.total:
        report.update(report.total)
    return outcome.get("value")
