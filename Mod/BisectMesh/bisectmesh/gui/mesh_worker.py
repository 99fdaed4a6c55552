"""The mesh panel's worker thread: mesh_object.mesh_part with its check off the GUI
thread (the C++ releases the GIL while it works, so the window stays alive)."""

import threading

from PySide import QtCore

from .. import mesh_object

# Workers whose panel closed before they finished: kept referenced until they stop, because a
# QThread object destroyed while its thread runs takes FreeCAD down with it.
ORPHANS = set()


class MeshWorker(QtCore.QThread):
    """Runs mesh_object.mesh_part, the check included, off the GUI thread. Its signals reach
    the panel through queued connections, i.e. in the GUI thread; when it ends it calls the
    panel's ``_worker_done(worker)`` there."""

    progressed = QtCore.Signal(float)

    def __init__(self, panel, shape, arguments, resolution):
        super().__init__()
        self.panel = panel
        self.shape = shape
        self.arguments = dict(arguments)
        self.resolution = resolution
        self.stop = threading.Event()
        self.femmesh = self.result = self.error = self.arrays = None
        self.cancelled = False
        self.finished.connect(self._done)

    def run(self):
        import bisectmesh

        try:
            # the check of the mesh is part of the bar and of Stop (mesh_part's check)
            report = {}
            self.femmesh, self.result = mesh_object.mesh_part(
                None, shape=self.shape, resolution=self.resolution, progress=self._progress, check=True,
                report=report, **self.arguments)
            self.arrays = report["arrays"]
        except bisectmesh.core().Cancelled:
            self.cancelled = True
        except Exception as err:  # shown in the panel and the report view; FreeCAD lives on
            self.error = str(err) or err.__class__.__name__

    def _progress(self, fraction):
        self.progressed.emit(float(fraction))
        return not self.stop.is_set()

    def orphan(self):
        """The panel closed: stop, and stay referenced until the thread has ended."""
        self.stop.set()
        ORPHANS.add(self)

    def _done(self):
        self.wait()  # finished is emitted just before the thread ends: let it end first
        panel, self.panel = self.panel, None
        ORPHANS.discard(self)
        if panel is not None:
            panel._worker_done(self)
