"""The task panel of the "Mesh quality" command.

Two boxes: the report (validity with the list of problems, a table of the measures, histograms
of the minimum dihedral angle and of gamma) and the 3D view (colour by quality, mark the nodes
of poor elements, reset). The report, the histograms, the colours and the marks are computed in
job threads (job_thread.py), so that the window never freezes for long, even at 10^6 elements;
the calls then appear in the Python console and in macros as comments (a macro that uncomments
them computes the same, blocking), and the report is left in ``bisectmesh_report``. Resetting
goes through FreeCADGui.doCommandGui.
"""

import FreeCAD
import FreeCADGui
from PySide import QtCore, QtGui

from . import colouring, icon_path
from .colouring import SCALES
from .job_thread import JobThread

# Kinds of violation whose ids are node ids; the others carry element ids.
_NODE_KINDS = ("open_boundary", "duplicate_node", "unused_node", "non_finite_node")

_TABLE_ROWS = (  # (measure, row label, tooltip, format)
    ("dihedral_min", "dihedral min (\u00b0)", "Smallest dihedral angle of each element, in degrees; "
     "70.53\u00b0 for the regular tetrahedron, 0 for a flat one", "%.2f"),
    ("dihedral_max", "dihedral max (\u00b0)", "Largest dihedral angle of each element, in degrees; "
     "70.53\u00b0 for the regular tetrahedron, 180 for a flat one", "%.2f"),
    ("solid_angle_min", "solid angle min (sr)", "Smallest solid angle at a corner of each element "
     "(Van Oosterom\u2013Strackee), in steradians; 0.5513 for the regular tetrahedron", "%.4f"),
    ("gamma", "\u03b3", "Goodness \u03b3 = 374.123 V\u00b2/S\u00b3 (volume V, surface area S); "
     "1 for the regular tetrahedron", "%.4f"),
    ("alpha", "\u03b1", "Radius ratio \u03b1 = inradius / circumradius; 1/3 for the regular "
     "tetrahedron", "%.4f"),
)
_HISTOGRAM_WIDTH = 300
_VALID_DETAILS = ("no inverted or zero-volume elements, every face shared by at most two elements, "
                  "a closed boundary, no duplicate or unused nodes")
_COLOUR_MEASURES = ("gamma", "dihedral_min", "alpha", "solid_angle_min")
_MAX_LISTED = 500


class QualityPanel:
    """Task panel showing ``bisectmesh.quality`` of one FEM mesh object."""

    open_panel = None  # the panel on screen, if any (the command closes it before a new one)

    def __init__(self, obj):
        self.doc_name = obj.Document.Name
        self.obj_name = obj.Name
        self.report = None
        self.error = None
        self.job = None  # the report's JobThread while it runs
        self.view_jobs = {}  # "colour" or "mark": its JobThread while it runs
        self.form = [self._build_report_box(obj), self._build_view_box()]
        # FreeCADGui.Control.closeDialog() deletes the widgets without calling reject().
        self.form[0].destroyed.connect(self._close)
        QualityPanel.open_panel = self

    # -- widgets ---------------------------------------------------------------------------

    def _build_report_box(self, obj):
        box = QtGui.QWidget()
        box.setObjectName("BisectMeshQualityReport")
        box.setWindowTitle("Mesh quality")
        box.setWindowIcon(QtGui.QIcon(icon_path("BisectMesh_Quality.svg")))
        layout = QtGui.QVBoxLayout(box)

        self.label = obj.Label  # plain text, for the report view (the title is rich text)
        self.title = QtGui.QLabel("<b>%s</b>" % _escape(obj.Label))
        self.title.setWordWrap(True)
        layout.addWidget(self.title)

        self.validity = QtGui.QLabel("Computing\u2026")
        self.validity.setObjectName("validity")
        self.validity.setWordWrap(True)
        layout.addWidget(self.validity)

        self.violations = QtGui.QListWidget()
        self.violations.setObjectName("violations")
        self.violations.setMaximumHeight(110)
        self.violations.setWordWrap(True)
        self.violations.setToolTip("Double-click a problem to mark its nodes in the 3D view")
        self.violations.itemActivated.connect(self._show_violation)
        self.violations.hide()
        layout.addWidget(self.violations)

        self.table = QtGui.QTableWidget(len(_TABLE_ROWS), 3)
        self.table.setObjectName("measures")
        self.table.setHorizontalHeaderLabels(["min", "mean", "max"])
        self.table.setVerticalHeaderLabels([label for _, label, _, _ in _TABLE_ROWS])
        for row, (_, _, tooltip, _) in enumerate(_TABLE_ROWS):
            self.table.verticalHeaderItem(row).setToolTip(tooltip)
        self.table.setEditTriggers(QtGui.QAbstractItemView.NoEditTriggers)
        self.table.horizontalHeader().setSectionResizeMode(QtGui.QHeaderView.Stretch)
        self.table.verticalHeader().setSectionResizeMode(QtGui.QHeaderView.ResizeToContents)
        self.table.setVerticalScrollBarPolicy(QtCore.Qt.ScrollBarAlwaysOff)
        layout.addWidget(self.table)

        self.notes = QtGui.QLabel("")
        self.notes.setObjectName("notes")
        self.notes.setWordWrap(True)
        layout.addWidget(self.notes)

        self.histograms = QtGui.QLabel()
        self.histograms.setObjectName("histograms")
        self.histograms.setAlignment(QtCore.Qt.AlignCenter)
        layout.addWidget(self.histograms)
        return box

    def _build_view_box(self):
        box = QtGui.QWidget()
        box.setObjectName("BisectMeshQualityView")
        box.setWindowTitle("3D view")
        layout = QtGui.QGridLayout(box)

        layout.addWidget(QtGui.QLabel("Measure:"), 0, 0)
        self.measure = QtGui.QComboBox()
        self.measure.setObjectName("measure")
        for name in _COLOUR_MEASURES:
            self.measure.addItem(SCALES[name][0], name)
        self.measure.currentIndexChanged.connect(self._measure_changed)
        layout.addWidget(self.measure, 0, 1)

        self.colour = QtGui.QCheckBox("Colour by quality")
        self.colour.setObjectName("colour")
        self.colour.setToolTip("Colours every node by the worst quality of the elements that use it: "
                               "red poor, yellow fair, green good (1 = regular tetrahedron)")
        self.colour.toggled.connect(self._colour_toggled)
        layout.addWidget(self.colour, 1, 0, 1, 2)

        self.legend = QtGui.QLabel()
        layout.addWidget(self.legend, 2, 0, 1, 2)

        self.mark = QtGui.QCheckBox("Mark elements, dihedral below")
        self.mark.setObjectName("mark")
        self.mark.setToolTip("Shows the nodes of the flattest elements as points, inside the mesh too")
        self.mark.toggled.connect(self._mark_toggled)
        layout.addWidget(self.mark, 3, 0)
        self.threshold = QtGui.QDoubleSpinBox()
        self.threshold.setObjectName("threshold")
        self.threshold.setRange(0.0, 70.0)
        self.threshold.setDecimals(1)
        self.threshold.setSingleStep(5.0)
        self.threshold.setValue(10.0)
        self.threshold.setSuffix("\u00b0")
        self.threshold.valueChanged.connect(self._threshold_changed)
        layout.addWidget(self.threshold, 3, 1)

        self.reset = QtGui.QPushButton("Reset colours")
        self.reset.setObjectName("reset")
        self.reset.clicked.connect(self._reset_clicked)
        layout.addWidget(self.reset, 4, 0, 1, 2)
        self._set_legend()
        return box

    def _set_legend(self):
        # drawn from the colours themselves: matplotlib's first drawing would freeze the window
        rgb = colouring.legend_rgb(240, 14)
        self._legend_bytes = rgb.tobytes()  # QImage reads this buffer: keep it alive
        image = QtGui.QImage(self._legend_bytes, rgb.shape[1], rgb.shape[0], 3 * rgb.shape[1],
                             QtGui.QImage.Format_RGB888)
        self.legend.setPixmap(QtGui.QPixmap.fromImage(image))
        self.legend.setToolTip("poor \u2192 good")

    # -- FreeCAD task panel interface ------------------------------------------------------

    def getStandardButtons(self):
        return int(QtGui.QDialogButtonBox.Close)

    def accept(self):
        return self._close()

    def reject(self):
        return self._close()

    def _close(self, *_):
        for job in [self.job] + list(self.view_jobs.values()):
            if job is not None:
                job.forget()
        self.job, self.view_jobs = None, {}
        if QualityPanel.open_panel is self:
            QualityPanel.open_panel = None
        return True

    # -- actions ---------------------------------------------------------------------------

    def _object(self):
        doc = FreeCAD.listDocuments().get(self.doc_name)
        return doc.getObject(self.obj_name) if doc else None

    def _object_expr(self):
        return "FreeCAD.getDocument(%r).getObject(%r)" % (self.doc_name, self.obj_name)

    def compute(self):
        """Runs bisectmesh.quality in a job thread and shows the report when it comes; the console
        gets the call (as a comment: the panel computed it) and ``bisectmesh_report``."""
        obj = self._object()
        if obj is None:
            self._computed(None, "the mesh object is gone (deleted or its document closed)")
            return
        import bisectmesh

        # what the thread reads, taken here: the kept arrays of a BisectMesh object, or the
        # FemMesh itself (a reference: replacing the object's mesh meanwhile does not touch it)
        mesh = bisectmesh.mesh_arrays(obj) if _kept_arrays(obj) else obj.FemMesh
        self.validity.setText("Computing\u2026")

        def work():
            report = bisectmesh.quality(mesh)
            return report, _histograms(report)  # matplotlib's drawing too: 0.3 s and more

        self.job = JobThread(work, self._computed)

    def computing(self):
        """True while the report is being computed."""
        return self.job is not None

    def _computed(self, answer, error):
        self.job = None
        report, self._histogram_png = answer if answer is not None else (None, None)
        self.report, self.error = report, error
        if QualityPanel.open_panel is not self:
            return
        self._show_report()
        if report is not None:
            import __main__
            import bisectmesh

            __main__.bisectmesh_report = report
            FreeCADGui.doCommand("import bisectmesh")
            FreeCADGui.doCommand("# bisectmesh_report = bisectmesh.quality(%s)  # computed by the Mesh quality panel"
                                 % self._object_expr())
            FreeCAD.Console.PrintMessage(
                "Mesh quality of %s:\n%s\n" % (self.label, bisectmesh.format_report(report)))

    def _show_report(self):
        report = self.report
        if report is None:
            self.validity.setText("<span style='color:#b00000'><b>Could not compute the quality:</b> %s</span>"
                                  % _escape(self.error or "unknown error"))
            self.colour.setEnabled(False)
            self.mark.setEnabled(False)
            return
        obj = self._object()
        label = obj.Label if obj else self.obj_name
        skipped = report.get("skipped_volumes") or {}
        skipped_text = ("; skipped (not tetrahedra): " + ", ".join(
            "%d %s" % (n, k) for k, n in sorted(skipped.items()))) if skipped else ""
        self.title.setText("<b>%s</b><br>%d tetrahedra (order %d), %d nodes%s" % (
            _escape(label), report["tets"], report["order"], report["nodes"], _escape(skipped_text)))

        if report["valid"]:
            self.validity.setText("<span style='color:#007000'><b>\u2714 Valid mesh</b></span>")
            self.validity.setToolTip(_VALID_DETAILS)
            self.violations.hide()
        else:
            problems = report["violations"]
            self.validity.setText("<span style='color:#b00000'><b>\u2718 Not valid</b></span>: %d problem%s"
                                  % (len(problems), "" if len(problems) == 1 else "s"))
            self.validity.setToolTip("A valid mesh has " + _VALID_DETAILS)
            self.violations.clear()
            for problem in problems[:_MAX_LISTED]:
                item = QtGui.QListWidgetItem(problem["message"])
                item.setToolTip(problem["message"])
                item.setData(QtCore.Qt.UserRole, (problem["kind"], list(problem["ids"])))
                self.violations.addItem(item)
            if len(problems) > _MAX_LISTED:
                self.violations.addItem("\u2026 and %d more (see bisectmesh_report['violations'])"
                                        % (len(problems) - _MAX_LISTED))
            self.violations.show()

        for row, (name, _, _, fmt) in enumerate(_TABLE_ROWS):
            stats = report["measures"][name]
            for col, key in enumerate(("min", "mean", "max")):
                item = QtGui.QTableWidgetItem(fmt % stats[key])
                item.setTextAlignment(QtCore.Qt.AlignRight | QtCore.Qt.AlignVCenter)
                self.table.setItem(row, col, item)
        self.table.setFixedHeight(self.table.horizontalHeader().height()
                                  + sum(self.table.rowHeight(r) for r in range(self.table.rowCount())) + 4)
        self.notes.setText("%.2f%% of the elements have a dihedral angle below 10\u00b0; "
                           "mean of the element minimum solid angles %.4f sr."
                           % (report["pct_dihedral_below_10"], report["solid_angle_mean"]))
        self._show_histograms()

    def _show_histograms(self):
        png = getattr(self, "_histogram_png", None)
        if isinstance(png, bytes):
            pixmap = QtGui.QPixmap()
            pixmap.loadFromData(png)
            self.histograms.setPixmap(pixmap)
        else:
            self.histograms.setText("(no histograms: %s)" % _escape(str(png)))

    def _colour_toggled(self, checked):
        if checked:
            measure = self.measure.itemData(self.measure.currentIndex())
            self._in_view("colour", "bisectmesh.gui.colouring.colour_by_quality(%s, %r)" % (self._object_expr(), measure),
                          lambda mesh: colouring.colour_values(mesh, measure),
                          lambda obj, values: colouring.apply_colours(obj, *values))
        else:
            self._forget_view_job("colour")
            self._run_gui("%s.ViewObject.resetNodeColor()" % self._object_expr())

    def colouring_done(self):
        """True when no colouring or marking is being computed."""
        return not self.view_jobs

    def _measure_changed(self, _index):
        if self.colour.isChecked():
            self._colour_toggled(True)

    def _threshold_changed(self, _value):
        if self.mark.isChecked():
            self._mark_toggled(True)

    def _mark_toggled(self, checked):
        if checked:
            threshold = round(self.threshold.value(), 1)
            self._in_view("mark", "bisectmesh.gui.colouring.mark_poor_elements(%s, 'dihedral_min', %r)"
                          % (self._object_expr(), threshold),
                          lambda mesh: colouring.poor_element_nodes(mesh, "dihedral_min", threshold),
                          colouring.apply_marks)
        else:
            self._forget_view_job("mark")
            self._run_gui("%s.ViewObject.resetHighlightedNodes()" % self._object_expr())

    def _forget_view_job(self, kind):
        job = self.view_jobs.pop(kind, None)
        if job is not None:
            job.forget()

    def _in_view(self, kind, call, compute, apply):
        """``compute(mesh)`` in a job thread, then ``apply(obj, values)`` here; the console gets
        ``call`` as a comment (a macro replays it, blocking). A newer request of the same kind
        replaces a running one; unticking its box drops it."""
        obj = self._object()
        if obj is None:
            self.validity.setText("The mesh object is gone (deleted or its document closed).")
            return
        import bisectmesh

        self._forget_view_job(kind)
        mesh = bisectmesh.mesh_arrays(obj) if _kept_arrays(obj) else obj.FemMesh

        def done(values, error):
            if self.view_jobs.get(kind) is not job:  # replaced by a newer request, or dropped
                return
            del self.view_jobs[kind]
            target = self._object()
            if error is not None or target is None:
                FreeCAD.Console.PrintError("BisectMesh: %s\n" % (error or "the mesh object is gone"))
                return
            apply(target, values)
            FreeCADGui.doCommandGui("# %s  # applied by the Mesh quality panel" % call)

        job = self.view_jobs[kind] = JobThread(lambda: compute(mesh), done)

    def _reset_clicked(self):
        for kind in list(self.view_jobs):
            self._forget_view_job(kind)
        for box in (self.colour, self.mark):
            box.blockSignals(True)
            box.setChecked(False)
            box.blockSignals(False)
        self._run_gui("bisectmesh.gui.colouring.reset_colours(%s)" % self._object_expr())

    def _show_violation(self, item):
        data = item.data(QtCore.Qt.UserRole)
        obj = self._object()
        if not data or obj is None:
            return
        kind, ids = data
        if kind in _NODE_KINDS:
            nodes = ids
        else:
            nodes = sorted({n for eid in ids for n in _element_nodes(obj.FemMesh, eid)})
        if nodes:
            self._run_gui("%s.ViewObject.HighlightedNodes = %r" % (self._object_expr(), nodes))

    def _run_gui(self, command):
        if self._object() is None:
            self.validity.setText("The mesh object is gone (deleted or its document closed).")
            return
        QtGui.QApplication.setOverrideCursor(QtCore.Qt.WaitCursor)
        try:
            FreeCADGui.doCommandGui("import bisectmesh.gui.colouring")
            FreeCADGui.doCommandGui(command)
        except Exception as err:
            FreeCAD.Console.PrintError("BisectMesh: %s\n" % err)
        finally:
            QtGui.QApplication.restoreOverrideCursor()


def _histograms(report):
    """The histograms' PNG bytes, or the reason there are none (matplotlib missing, say)."""
    try:
        from .histograms import histogram_png

        return histogram_png(report, width_px=_HISTOGRAM_WIDTH)
    except Exception as err:
        return str(err) or err.__class__.__name__


def _kept_arrays(obj):
    kept = getattr(getattr(obj, "Proxy", None), "mesh_arrays", None)
    return callable(kept) and kept() is not None


def _element_nodes(femmesh, element_id):
    try:
        return femmesh.getElementNodes(element_id)
    except Exception:
        return ()


def _escape(text):
    return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")
