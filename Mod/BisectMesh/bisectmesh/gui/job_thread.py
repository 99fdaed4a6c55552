"""One function run off the GUI thread, its answer delivered on the GUI thread: the quality
panel's report and colours (at 10^6 elements the check and the per-node colours take seconds; the
window must not freeze for more than 0.5 s, issue 19). The C++ core releases the GIL while it
works, so the window keeps running meanwhile.
"""

from PySide import QtCore

# Jobs whose panel closed before they finished: kept referenced until they end (a QThread
# destroyed while its thread runs takes FreeCAD down with it).
_RUNNING = set()


class JobThread(QtCore.QThread):
    """Runs ``work()`` in its own thread; then calls ``done(result, error)`` on the GUI thread,
    error being None or the exception's text."""

    def __init__(self, work, done):
        super().__init__()
        self.work, self.done = work, done
        self.result = self.error = None
        self.finished.connect(self._finished)
        _RUNNING.add(self)
        self.start()

    def run(self):
        try:
            self.result = self.work()
        except Exception as err:  # shown by the panel; FreeCAD lives on
            self.error = str(err) or err.__class__.__name__

    def _finished(self):
        self.wait()  # finished comes just before the thread ends: let it end first
        _RUNNING.discard(self)
        done, self.done = self.done, None
        if done is not None:
            done(self.result, self.error)

    def forget(self):
        """The caller is gone: its answer is dropped when it comes."""
        self.done = None
