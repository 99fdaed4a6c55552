"""The task panel of the "Mesh with BisectMesh" command (and of editing a BisectMesh object).

The user sets the element count or size, the order, the resolution hints and the optimisation
passes, and presses Mesh: the mesher runs in a worker thread (it releases the GIL while the C++
works, so the window stays alive) with a progress bar and a Stop button, and the panel then shows
the counts, the stage times and the quality of the mesh. OK keeps that mesh in a BisectMesh FEM
mesh object (created through FreeCADGui.doCommand, so that macros record it; the computed mesh is
handed over rather than computed again); Cancel leaves the document as it was.
"""

import threading

import FreeCAD
import FreeCADGui
from PySide import QtCore, QtGui

from . import icon_path
from .. import mesh_object

_DEFAULT_ELEMENTS = mesh_object.DEFAULT_ELEMENTS

# Workers whose panel closed before they finished: kept referenced until they stop, because a
# QThread object destroyed while its thread runs takes FreeCAD down with it.
_ORPHANS = set()


class _MeshWorker(QtCore.QThread):
    """Runs mesh_object.mesh_part and bisectmesh.quality off the GUI thread. Its signals reach
    the panel through queued connections, i.e. in the GUI thread."""

    progressed = QtCore.Signal(float)
    stage = QtCore.Signal(str)

    def __init__(self, panel, shape, arguments, resolution):
        super().__init__()
        self.panel = panel
        self.shape = shape
        self.arguments = dict(arguments)
        self.resolution = resolution
        self.stop = threading.Event()
        self.femmesh = self.result = self.error = None
        self.cancelled = False
        self.finished.connect(self._done)

    def run(self):
        import bisectmesh

        try:
            femmesh, result = mesh_object.mesh_part(None, shape=self.shape, resolution=self.resolution,
                                                    progress=self._progress, **self.arguments)
            self.stage.emit("Checking the mesh\u2026")
            check = bisectmesh.quality(femmesh)
            result["quality"] = {k: v for k, v in check.items()
                                 if k not in ("measures", "violations", "per_element", "skipped_volumes")}
            result["violations"] = [v["message"] for v in check["violations"][:20]]
            self.femmesh, self.result = femmesh, result
        except bisectmesh.core().Cancelled:
            self.cancelled = True
        except Exception as err:  # shown in the panel and the report view; FreeCAD lives on
            self.error = str(err) or err.__class__.__name__

    def _progress(self, fraction):
        self.progressed.emit(float(fraction))
        return not self.stop.is_set()

    def _done(self):
        self.wait()  # finished is emitted just before the thread ends: let it end first
        panel, self.panel = self.panel, None
        _ORPHANS.discard(self)
        if panel is not None:
            panel._worker_done(self)


class MeshPanel:
    """Task panel: mesh ``part`` with BisectMesh; ``mesh_obj`` when editing an existing object."""

    open_panel = None  # the panel on screen, if any

    def __init__(self, part, mesh_obj=None):
        self.doc_name = part.Document.Name
        self.part_name = part.Name
        self.mesh_name = mesh_obj.Name if mesh_obj is not None else None
        self.editing = mesh_obj is not None  # opened by the object's setEdit
        self.worker = None
        self.computed = None  # (key, femmesh, result) of the last finished meshing
        self.result = None
        self.error = None
        self.closed = False
        self._accept_when_done = False
        self.form = self._build(part)
        self.form.destroyed.connect(self._destroyed)
        if mesh_obj is not None:
            self._load(mesh_obj)
        MeshPanel.open_panel = self

    # -- widgets ---------------------------------------------------------------------------

    def _build(self, part):
        from .. import shape_mesher

        box = QtGui.QWidget()
        box.setObjectName("BisectMeshMeshPanel")
        box.setWindowTitle("Mesh with BisectMesh")
        box.setWindowIcon(QtGui.QIcon(icon_path("BisectMesh_Mesh.svg")))
        layout = QtGui.QVBoxLayout(box)

        shape = part.Shape
        solids = len(shape.Solids)
        self.title = QtGui.QLabel("<b>%s</b><br>%d solid%s, %d faces, volume %.4g mm\u00b3" % (
            _escape(part.Label), solids, "" if solids == 1 else "s", len(shape.Faces), shape.Volume))
        self.title.setWordWrap(True)
        layout.addWidget(self.title)

        size_box = QtGui.QGroupBox("Mesh size")
        grid = QtGui.QGridLayout(size_box)
        self.by_count = QtGui.QRadioButton("Number of elements")
        self.by_count.setObjectName("by_count")
        self.by_count.setToolTip("The number of tetrahedra asked for; the mesh comes close to it")
        self.elements = QtGui.QSpinBox()
        self.elements.setObjectName("elements")
        self.elements.setRange(10, 100000000)
        self.elements.setSingleStep(1000)
        self.elements.setGroupSeparatorShown(True)
        self.elements.setValue(_DEFAULT_ELEMENTS)
        self.by_size = QtGui.QRadioButton("Element size")
        self.by_size.setObjectName("by_size")
        self.by_size.setToolTip("The nodal spacing: about the length of an element's edge")
        self.size = QtGui.QDoubleSpinBox()
        self.size.setObjectName("size")
        self.size.setRange(0.001, 1.0e6)
        self.size.setDecimals(3)
        self.size.setSuffix(" mm")
        self.size.setValue(_size_for(shape.Volume, _DEFAULT_ELEMENTS))
        self.by_count.setChecked(True)
        self.by_count.toggled.connect(self._mode_changed)
        grid.addWidget(self.by_count, 0, 0)
        grid.addWidget(self.elements, 0, 1)
        grid.addWidget(self.by_size, 1, 0)
        grid.addWidget(self.size, 1, 1)
        layout.addWidget(size_box)

        options = QtGui.QGroupBox("Options")
        form = QtGui.QFormLayout(options)
        self.order = QtGui.QComboBox()
        self.order.setObjectName("order")
        self.order.addItem("1st (tetra4)", "1st")
        self.order.addItem("2nd (tetra10)", "2nd")
        self.order.setCurrentIndex(1)
        self.order.setToolTip("2nd order puts the mid-edge nodes of boundary edges on the true surfaces")
        form.addRow("Element order:", self.order)
        self.resolution = shape_mesher.view_resolution(part)
        self.hints = QtGui.QCheckBox("Grade from the view resolution")
        self.hints.setObjectName("hints")
        self.hints.setChecked(True)
        self.hints.setToolTip(
            "Curved faces are followed as finely as %s is drawn (%s), and the volume mesh is "
            "graded from that fine boundary; off: FreeCAD's default resolution and a uniform "
            "spacing" % (part.Label, _resolution_text(self.resolution)))
        form.addRow(self.hints)
        self.optimize = QtGui.QSpinBox()
        self.optimize.setObjectName("optimize")
        self.optimize.setRange(0, 50)
        self.optimize.setValue(3)
        self.optimize.setToolTip("Passes of global optimisation by local transformations")
        self.smooth = QtGui.QSpinBox()
        self.smooth.setObjectName("smooth")
        self.smooth.setRange(0, 50)
        self.smooth.setValue(3)
        self.smooth.setToolTip("Passes of guarded nodal smoothing")
        passes = QtGui.QHBoxLayout()
        passes.addWidget(self.optimize, 1)
        passes.addWidget(QtGui.QLabel("smoothing:"))
        passes.addWidget(self.smooth, 1)
        form.addRow("Optimisation passes:", passes)
        layout.addWidget(options)

        run = QtGui.QHBoxLayout()
        self.mesh_button = QtGui.QPushButton(QtGui.QIcon(icon_path("BisectMesh_Mesh.svg")), "Mesh")
        self.mesh_button.setObjectName("mesh")
        self.mesh_button.setToolTip("Mesh now, and show the result here; OK keeps it")
        self.mesh_button.clicked.connect(self.start)
        self.stop_button = QtGui.QPushButton("Stop")
        self.stop_button.setObjectName("stop")
        self.stop_button.setToolTip("Cancel the meshing that is running")
        self.stop_button.setEnabled(False)
        self.stop_button.clicked.connect(self.stop)
        self.progress = QtGui.QProgressBar()
        self.progress.setObjectName("progress")
        self.progress.setRange(0, 100)
        self.progress.setValue(0)
        run.addWidget(self.mesh_button)
        run.addWidget(self.progress, 1)
        run.addWidget(self.stop_button)
        layout.addLayout(run)
        self.status = QtGui.QLabel("Press Mesh to see the mesh's counts and quality before keeping it.")
        self.status.setObjectName("status")
        self.status.setWordWrap(True)
        self.status.setTextInteractionFlags(QtCore.Qt.TextSelectableByMouse)
        layout.addWidget(self.status)

        results = QtGui.QGroupBox("Result")
        rl = QtGui.QVBoxLayout(results)
        self.counts = QtGui.QLabel("")
        self.counts.setObjectName("counts")
        self.counts.setWordWrap(True)
        rl.addWidget(self.counts)
        self.times = QtGui.QLabel("")
        self.times.setObjectName("times")
        rl.addWidget(self.times)
        self.quality = QtGui.QLabel("")
        self.quality.setObjectName("quality")
        self.quality.setWordWrap(True)
        rl.addWidget(self.quality)
        self.results_box = results
        results.hide()
        layout.addWidget(results)
        layout.addStretch(1)
        for widget in (self.elements, self.size, self.optimize, self.smooth):
            widget.valueChanged.connect(self._settings_changed)
        self.order.currentIndexChanged.connect(self._settings_changed)
        self.hints.toggled.connect(self._settings_changed)
        self._mode_changed(True)
        return box

    def _load(self, obj):
        """The settings and the last result of an existing BisectMesh object."""
        if obj.TargetElements > 0:
            self.elements.setValue(obj.TargetElements)
            self.by_count.setChecked(True)
        else:
            self.size.setValue(obj.ElementSize.Value)
            self.by_size.setChecked(True)
        self.order.setCurrentIndex(0 if obj.ElementOrder == "1st" else 1)
        self.hints.setChecked(obj.UseResolutionHints)
        self.optimize.setValue(obj.OptimizePasses)
        self.smooth.setValue(obj.SmoothPasses)
        stored = mesh_object.stored_result(obj)
        if stored:
            self._show_result(stored)
            self.progress.setValue(100)
            self.progress.setFormat("last mesh")
            self.status.setText("The last mesh of %s; change the settings and press Mesh to mesh again."
                                % _escape(obj.Label))
        if getattr(obj, "NeedsRemesh", False) and obj.MeshStatus:
            self.status.setText("<span style='color:#8a6d00'><b>Needs a re-mesh:</b> %s</span>"
                                % _escape(obj.MeshStatus))

    def _mode_changed(self, _checked):
        self.elements.setEnabled(self.by_count.isChecked() and self.worker is None)
        self.size.setEnabled(self.by_size.isChecked() and self.worker is None)

    def _settings_changed(self, *_):
        if self.computed is not None and self.worker is None and self.computed[0] != self._key():
            self.status.setText("The settings changed since that mesh: press Mesh again (OK meshes with "
                                "the new settings).")

    def _set_running(self, running):
        for widget in (self.by_count, self.by_size, self.order, self.hints, self.optimize, self.smooth,
                       self.mesh_button):
            widget.setEnabled(not running)
        self.stop_button.setEnabled(running)
        self._mode_changed(True)

    # -- the settings ----------------------------------------------------------------------

    def arguments(self):
        """The keyword arguments of mesh_object.mesh_part that the widgets ask for."""
        by_count = self.by_count.isChecked()
        return {
            "elements": int(self.elements.value()) if by_count else None,
            "size": None if by_count else float(self.size.value()),
            "order": 1 if self.order.itemData(self.order.currentIndex()) == "1st" else 2,
            "use_hints": self.hints.isChecked(),
            "optimize": int(self.optimize.value()),
            "smooth": int(self.smooth.value()),
        }

    def _key(self):
        resolution = self.resolution if self.hints.isChecked() else None
        if isinstance(resolution, dict):
            resolution = tuple(sorted(resolution.items()))
        return tuple(sorted(self.arguments().items())), resolution

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
        self.error = None
        self._running_key = self._key()
        self.worker = _MeshWorker(self, shape, self.arguments(), self.resolution)
        self.worker.progressed.connect(self._progressed)
        self.worker.stage.connect(self._stage)
        self._set_running(True)
        self.progress.setValue(0)
        self.progress.setFormat("%p%")
        self.status.setText("Meshing %s\u2026" % _escape(part.Label))
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
        if self.closed:
            return
        self.progress.setValue(int(round(100 * min(max(fraction, 0.0), 1.0))))
        if fraction >= 1.0:
            self.progress.setFormat("Building the FEM mesh\u2026")

    def _stage(self, text):
        if not self.closed:
            self.progress.setFormat(text)

    def _worker_done(self, worker):
        if worker is not self.worker:
            return
        self.worker = None
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
        self.computed = (self._running_key, worker.femmesh, worker.result)
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
        self.status.setText("<span style='color:#b00000'><b>Could not mesh:</b> %s</span>" % _escape(message))
        FreeCAD.Console.PrintError("BisectMesh: could not mesh %s: %s\n" % (self.part_name, message))

    def _show_result(self, result):
        self.result = result
        order = result.get("order", 2)
        text = "<b>%d tetrahedra</b> (%s), %d nodes" % (
            result["tets"], "tetra10" if order == 2 else "tetra4", result["nodes"])
        if "convex_cells" in result:
            text += ", %d convex cells" % result["convex_cells"]
        text += "; %.2f s in all" % result["seconds"]
        self.counts.setText(text)
        times = result.get("times") or {}
        cells = ["<td>%s</td><td align='right'>%.3f s</td>" % (label, times[key])
                 for key, label in mesh_object.STAGES if key in times]
        rows = "".join("<tr>%s</tr>" % "<td width='16'></td>".join(cells[i:i + 2])
                       for i in range(0, len(cells), 2))
        self.times.setText("<b>Stage times</b> (generator)<table cellspacing='2'>%s</table>" % rows
                           if rows else "")
        q = result.get("quality") or {}
        text = ""
        if q.get("valid") is True:
            text = "<span style='color:#007000'><b>\u2714 Valid mesh</b></span>"
        elif q.get("valid") is False:
            text = ("<span style='color:#b00000'><b>\u2718 Not valid</b></span>: "
                    + _escape("; ".join(result.get("violations", [])[:3])))
        if "dihedral_min" in q:
            rows = (("dihedral angles", "%.2f\u00b0 .. %.2f\u00b0" % (q["dihedral_min"], q["dihedral_max"])),
                    ("below 10\u00b0", "%.2f%% of the elements" % q["pct_dihedral_below_10"]),
                    ("min solid angle", "%.4f sr" % q["solid_angle_min"]),
                    ("\u03b3 min, mean", "%.4f, %.4f" % (q["gamma_min"], q["gamma_mean"])),
                    ("\u03b1 mean", "%.4f" % q["alpha_mean"]))
            text += "<table cellspacing='2'>%s</table>" % "".join(
                "<tr><td>%s&nbsp;&nbsp;</td><td>%s</td></tr>" % row for row in rows)
        self.quality.setText(text)
        self.results_box.show()

    # -- keeping the mesh ------------------------------------------------------------------

    def _keep(self):
        """Creates (or updates) the mesh object with the computed mesh; False after an error."""
        key, femmesh, result = self.computed
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
                call = ", ".join("%s=%r" % (k, args[k]) for k in
                                 ("elements", "size", "order", "use_hints", "optimize", "smooth")
                                 if not (k in ("elements", "size") and args[k] is None))
                FreeCADGui.doCommand("bisectmesh_mesh = bisectmesh.make_mesh_object(%s, %s.getObject(%r), %s)"
                                     % (doc_expr, doc_expr, self.part_name, call))
                import __main__

                obj = __main__.bisectmesh_mesh
                self.mesh_name = obj.Name
            else:
                expr = "%s.getObject(%r)" % (doc_expr, obj.Name)
                for prop, value in (("TargetElements", args["elements"] or 0),
                                    ("ElementOrder", "1st" if args["order"] == 1 else "2nd"),
                                    ("UseResolutionHints", args["use_hints"]),
                                    ("OptimizePasses", args["optimize"]),
                                    ("SmoothPasses", args["smooth"])):
                    FreeCADGui.doCommand("%s.%s = %r" % (expr, prop, value))
                if args["size"] is not None:
                    FreeCADGui.doCommand("%s.ElementSize = %r" % (expr, args["size"]))
            # the mesh just computed: a macro meshes here with the line below, uncommented
            obj.Proxy.adopt(obj, femmesh, result)
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
            self.worker.stop.set()
            _ORPHANS.add(self.worker)
        if MeshPanel.open_panel is self:
            MeshPanel.open_panel = None
        if self.editing:
            # leave edit mode (the view provider's unsetEdit closes the dialog)
            QtCore.QTimer.singleShot(0, self._reset_edit)

    def _destroyed(self, *_):
        # FreeCADGui.Control.closeDialog() deletes the widgets without calling reject()
        self._finish()


def _size_for(volume, elements):
    """The element size that asks for about ``elements`` tetrahedra in ``volume``, to the panel's
    three decimals (arguments.spacing_for: the one formula)."""
    from ..arguments import spacing_for

    if volume <= 0:
        return 1.0
    return round(spacing_for(volume, elements), 3)


def _resolution_text(resolution):
    if isinstance(resolution, dict):
        return "deviation %g %%, angular deflection %g\u00b0" % (
            resolution.get("deviation", float("nan")), resolution.get("angular_deflection", float("nan")))
    if resolution is None:
        return "FreeCAD's default resolution"
    return "deflection %g mm" % resolution


def _escape(text):
    return str(text).replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")
