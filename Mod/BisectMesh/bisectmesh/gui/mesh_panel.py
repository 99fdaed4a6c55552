"""The task panel of the "Mesh with BisectMesh" command (and of editing a BisectMesh object).

The user sets the element count or size, the size bounds and curvature, the order, the
resolution hints and the optimisation passes (the form: mesh_form.py; an edited object's mesh
regions are listed and used), and presses Mesh: the mesher runs in a worker thread
(mesh_worker.py) with a progress bar and a Stop button, and the panel then shows the counts, the
stage times and the quality of the mesh. OK keeps that mesh in a BisectMesh FEM mesh object
(created through FreeCADGui.doCommand, so that macros record it; the computed mesh is handed over
rather than computed again); Cancel leaves the document as it was.
"""

import FreeCAD
import FreeCADGui
from PySide import QtCore, QtGui

from .. import mesh_object
from .mesh_form import MeshForm, escape, size_for as _size_for  # noqa: F401  (_size_for: tests)
from .mesh_worker import MeshWorker

# The bar repaints at most this often. Each repaint recomposes the whole window when it holds an
# OpenGL 3D view; under software OpenGL (a VM, Xvfb) that is 20-50 ms of the GUI thread's time
# and of the cores the mesher runs on: a repaint per percent made meshing 2e5 tetra10 in a
# window 4.3 s where ten a second make it 4.0-4.2 s (gui_stall). Ten a second still move smoothly.
BAR_PERIOD_MS = 100

# the mesh object's property of each argument that the panel sets (regions are the object's own)
_PROPERTIES = (("order", "ElementOrder"), ("use_hints", "UseResolutionHints"), ("optimize", "OptimizePasses"),
               ("smooth", "SmoothPasses"), ("min_size", "MinSize"), ("max_size", "MaxSize"),
               ("curvature_elements", "CurvatureElements"), ("chord_deviation", "ChordDeviation"))


class MeshPanel(MeshForm):
    """Task panel: mesh ``part`` with BisectMesh; ``mesh_obj`` when editing an existing object."""

    open_panel = None  # the panel on screen, if any

    def __init__(self, part, mesh_obj=None):
        self.doc_name = part.Document.Name
        self.part_name = part.Name
        self.mesh_name = mesh_obj.Name if mesh_obj is not None else None
        self.editing = mesh_obj is not None  # opened by the object's setEdit
        self.worker = None
        self.computed = None  # (key, femmesh, result, arrays) of the last finished meshing
        self.result = None
        self.error = None
        self.closed = False
        self._accept_when_done = False
        self._pending_fraction = None  # the latest progress report, not yet on the bar
        self._bar_timer = QtCore.QTimer()
        self._bar_timer.setSingleShot(True)
        self._bar_timer.setInterval(BAR_PERIOD_MS)
        self._bar_timer.timeout.connect(self._show_progress)
        self.form = self._build(part)
        self.form.destroyed.connect(self._destroyed)
        if mesh_obj is not None:
            self._load(mesh_obj)
        MeshPanel.open_panel = self

    def _settings_changed(self, *_):
        if self.computed is not None and self.worker is None and self.computed[0] != self._key():
            self.status.setText("The settings changed since that mesh: press Mesh again (OK meshes with "
                                "the new settings).")

    # -- objects ---------------------------------------------------------------------------

    def _doc(self):
        return FreeCAD.listDocuments().get(self.doc_name)

    def _part(self):
        doc = self._doc()
        return doc.getObject(self.part_name) if doc else None

    def _mesh_obj(self):
        doc = self._doc()
        return doc.getObject(self.mesh_name) if doc and self.mesh_name else None

    # -- meshing ---------------------------------------------------------------------------

    def start(self):
        """Starts meshing in a worker thread (the Mesh button)."""
        if self.worker is not None or self.closed:
            return
        part = self._part()
        if part is None:
            self._fail("the Part object is gone (deleted, or its document closed)")
            return
        from .. import shape_mesher

        try:
            shape = mesh_object.part_shape(part).copy()  # the worker's own: the view may tessellate the other
            # read in the GUI thread: the view object may change meanwhile
            self.resolution = shape_mesher.view_resolution(part)
        except Exception as err:
            self._fail(str(err))
            return
        try:
            self.read_regions(self._mesh_obj())  # as they are now: the user may have edited them
        except ValueError as err:
            self._fail(str(err))
            return
        self.error = None
        self._running_key = self._key()
        self.worker = MeshWorker(self, shape, self.arguments(), self.resolution)
        self.worker.progressed.connect(self._progressed)
        # where the generator's share of the bar ends, and the FemMesh build's (the check follows)
        core, femmesh, _ = shape_mesher.progress_shares(self.worker.arguments["order"], check=True)
        self._stage_ends = ((core, "Generating the mesh\u2026 %p%"), (core + femmesh, "Building the FEM mesh\u2026 %p%"),
                            (2.0, "Checking the mesh\u2026 %p%"))
        self._set_running(True)
        self.progress.setValue(0)
        self.progress.setFormat("%p%")
        self.status.setText("Meshing %s\u2026" % escape(part.Label))
        self.worker.start()

    def accept_when_done(self):
        """Presses OK for the user once the running meshing has finished well (the Re-mesh
        command); Stop, Cancel or an error leave the panel open and the object as it was."""
        self._accept_when_done = self.worker is not None

    def stop(self):
        """Asks the running meshing to stop (the Stop button); it stops at its next progress report."""
        if self.worker is not None:
            self.worker.stop.set()
            self._accept_when_done = False
            self.stop_button.setEnabled(False)
            self.status.setText("Stopping\u2026")

    def _progressed(self, fraction):
        """A progress report: on the bar now if the bar has rested BAR_PERIOD_MS, else when it has."""
        if self.closed:
            return
        self._pending_fraction = fraction
        if not self._bar_timer.isActive():
            self._show_progress()

    def _show_progress(self):
        fraction, self._pending_fraction = self._pending_fraction, None
        if fraction is None or self.closed or self.worker is None:
            return
        self.progress.setValue(int(round(100 * min(max(fraction, 0.0), 1.0))))
        self.progress.setFormat(next(text for end, text in self._stage_ends if fraction < end))
        self._bar_timer.start()

    def _worker_done(self, worker):
        if worker is not self.worker:
            return
        self.worker = None
        self._bar_timer.stop()
        self._pending_fraction = None
        if self.closed:
            return
        self._set_running(False)
        self.progress.setFormat("%p%")
        if worker.cancelled:
            self._accept_when_done = False
            self.progress.setValue(0)
            self.status.setText("Meshing cancelled.")
            FreeCAD.Console.PrintMessage("BisectMesh: meshing of %s cancelled\n" % self.part_name)
            return
        if worker.error is not None:
            self._accept_when_done = False
            self.progress.setValue(0)
            self._fail(worker.error)
            return
        self.progress.setValue(100)
        self.computed = (self._running_key, worker.femmesh, worker.result, worker.arrays)
        self._show_result(worker.result)
        self.status.setText("Done. OK keeps this mesh; Mesh again with other settings, or Cancel.")
        FreeCAD.Console.PrintMessage("BisectMesh: %s meshed:\n%s\n" % (
            self.part_name, mesh_object.summary(worker.result)))
        if self._accept_when_done:
            self._accept_when_done = False
            if self._keep():
                self._close_dialog()

    def _fail(self, message):
        self.error = message
        self.status.setText("<span style='color:#b00000'><b>Could not mesh:</b> %s</span>" % escape(message))
        FreeCAD.Console.PrintError("BisectMesh: could not mesh %s: %s\n" % (self.part_name, message))

    # -- keeping the mesh ------------------------------------------------------------------

    def _keep(self):
        """Creates (or updates) the mesh object with the computed mesh; False after an error."""
        key, femmesh, result, arrays = self.computed
        doc, part = self._doc(), self._part()
        if doc is None or part is None:
            self._fail("the Part object is gone (deleted, or its document closed)")
            return False
        args = dict(key[0])
        doc_expr = "FreeCAD.getDocument(%r)" % self.doc_name
        doc.openTransaction("Mesh with BisectMesh")
        try:
            FreeCADGui.doCommand("import bisectmesh")
            obj = self._mesh_obj()
            if obj is None:
                call = ", ".join("%s=%r" % (k, args[k]) for k in ("elements", "size") + tuple(a for a, _ in _PROPERTIES)
                                 if not (k in ("elements", "size") and args[k] is None))
                FreeCADGui.doCommand("bisectmesh_mesh = bisectmesh.make_mesh_object(%s, %s.getObject(%r), %s)"
                                     % (doc_expr, doc_expr, self.part_name, call))
                import __main__

                obj = __main__.bisectmesh_mesh
                self.mesh_name = obj.Name
            else:
                expr = "%s.getObject(%r)" % (doc_expr, obj.Name)
                FreeCADGui.doCommand("%s.TargetElements = %r" % (expr, args["elements"] or 0))
                for arg, prop in _PROPERTIES:
                    value = args[arg] if arg != "order" else ("1st" if args["order"] == 1 else "2nd")
                    FreeCADGui.doCommand("%s.%s = %r" % (expr, prop, value))
                if args["size"] is not None:
                    FreeCADGui.doCommand("%s.ElementSize = %r" % (expr, args["size"]))
            # the mesh just computed: a macro meshes here with the line below, uncommented
            obj.Proxy.adopt(obj, femmesh, result, arrays=arrays)
            FreeCADGui.doCommand("# bisectmesh.remesh(%s.getObject(%r))  # meshed by the panel" % (doc_expr, obj.Name))
            FreeCADGui.doCommand("%s.recompute()" % doc_expr)
            FreeCADGui.doCommandGui("FreeCADGui.getDocument(%r).getObject(%r).Visibility = False"
                                    % (self.doc_name, self.part_name))
            FreeCADGui.doCommandGui("FreeCADGui.getDocument(%r).getObject(%r).Visibility = True"
                                    % (self.doc_name, obj.Name))
            doc.commitTransaction()
        except Exception as err:
            doc.abortTransaction()
            self._fail(str(err))
            return False
        return True

    # -- FreeCAD task panel interface ------------------------------------------------------

    def getStandardButtons(self):
        return int(QtGui.QDialogButtonBox.Ok | QtGui.QDialogButtonBox.Cancel)

    def accept(self):
        """OK: keeps the mesh on screen, or meshes first (the dialog closes when it is done)."""
        if self.worker is not None:
            self._accept_when_done = True
            self.status.setText("Meshing\u2026 the panel closes when the mesh is ready.")
            return False
        if self.computed is None or self.computed[0] != self._key():
            self.start()
            self._accept_when_done = self.worker is not None
            return False
        if not self._keep():
            return False
        self._finish()
        return True

    def reject(self):
        """Cancel: stops a running meshing; nothing is added to the document."""
        self._finish()
        return True

    def _close_dialog(self):
        self._finish()
        if not self._reset_edit():
            FreeCADGui.Control.closeDialog()

    def _reset_edit(self):
        if not self.editing:
            return False
        gui_doc = FreeCADGui.getDocument(self.doc_name) if self._doc() else None
        if gui_doc is not None and gui_doc.getInEdit():
            gui_doc.resetEdit()
            return True
        return False

    def _finish(self):
        if self.closed:
            return
        self.closed = True
        if self.worker is not None:
            self.worker.orphan()
        if MeshPanel.open_panel is self:
            MeshPanel.open_panel = None
        if self.editing:
            # leave edit mode (the view provider's unsetEdit closes the dialog)
            QtCore.QTimer.singleShot(0, self._reset_edit)

    def _destroyed(self, *_):
        # FreeCADGui.Control.closeDialog() deletes the widgets without calling reject()
        self._finish()


