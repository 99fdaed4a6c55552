"""The widgets of the mesh panel (mesh_panel.py): the settings, the run row, the result.

:class:`MeshForm` builds them, reads them into the keyword arguments of mesh_object.mesh_part,
loads an existing mesh object's settings into them, and shows a result. The panel
(:class:`mesh_panel.MeshPanel`, a MeshForm) drives the meshing; the worker thread is in
mesh_worker.py. The defaults of a new mesh come from BisectMesh's preferences
(bisectmesh/preferences.py, Edit > Preferences > BisectMesh).
"""

from PySide import QtCore, QtGui

from . import icon_path
from .. import mesh_object, mesh_regions, preferences


class MeshForm:
    """The widgets, as attributes with object names (elements, size, order, ...) for the tests.
    Subclasses provide ``worker`` (None unless meshing), ``resolution`` and the slots ``start``,
    ``stop`` and ``_settings_changed``."""

    worker = None
    regions = ()  # the mesh regions of the edited object (mesh_regions.regions_of), read at start

    def _build(self, part):
        from .. import shape_mesher

        defaults = preferences.defaults()
        box = QtGui.QWidget()
        box.setObjectName("BisectMeshMeshPanel")
        box.setWindowTitle("Mesh with BisectMesh")
        box.setWindowIcon(QtGui.QIcon(icon_path("BisectMesh_Mesh.svg")))
        layout = QtGui.QVBoxLayout(box)

        shape = part.Shape
        solids = len(shape.Solids)
        self.title = QtGui.QLabel("<b>%s</b><br>%d solid%s, %d faces, volume %.4g mm\u00b3" % (
            escape(part.Label), solids, "" if solids == 1 else "s", len(shape.Faces), shape.Volume))
        self.title.setWordWrap(True)
        layout.addWidget(self.title)

        size_box = QtGui.QGroupBox("Mesh size")
        grid = QtGui.QGridLayout(size_box)
        self.by_count = QtGui.QRadioButton("Number of elements")
        self.by_count.setObjectName("by_count")
        self.by_count.setToolTip("The number of tetrahedra asked for; the mesh comes close to it")
        self.elements = _spin("elements", 10, 100000000, defaults["DefaultElements"])
        self.elements.setSingleStep(1000)
        self.elements.setGroupSeparatorShown(True)
        self.by_size = QtGui.QRadioButton("Element size")
        self.by_size.setObjectName("by_size")
        self.by_size.setToolTip("The nodal spacing: about the length of an element's edge")
        self.size = _length("size", 0.001, defaults["DefaultSize"] if defaults["UseElementSize"]
                            else size_for(shape.Volume, defaults["DefaultElements"]))
        (self.by_size if defaults["UseElementSize"] else self.by_count).setChecked(True)
        self.by_count.toggled.connect(self._mode_changed)
        grid.addWidget(self.by_count, 0, 0)
        grid.addWidget(self.elements, 0, 1)
        grid.addWidget(self.by_size, 1, 0)
        grid.addWidget(self.size, 1, 1)
        # bounds and curvature: 0 shows as "none"
        self.min_size = _length("min_size", 0.0, 0.0, "none", "The smallest element size anywhere (MinSize)")
        self.max_size = _length("max_size", 0.0, 0.0, "none", "The largest element size anywhere (MaxSize)")
        grid.addWidget(QtGui.QLabel("Smallest size:"), 2, 0)
        grid.addWidget(self.min_size, 2, 1)
        grid.addWidget(QtGui.QLabel("Largest size:"), 3, 0)
        grid.addWidget(self.max_size, 3, 1)
        self.curvature = _spin("curvature", 0, 10000, defaults["CurvatureElements"],
                               "Curved faces and edges get at least this many elements per full circle "
                               "(CurvatureElements; 0: no bound, else at least 3)")
        self.curvature.setSpecialValueText("no bound")
        grid.addWidget(QtGui.QLabel("Elements per circle:"), 4, 0)
        grid.addWidget(self.curvature, 4, 1)
        self.chord = _length("chord", 0.0, 0.0, "none", "Element edges on curved faces stay within this "
                             "distance of the surface (ChordDeviation)")
        grid.addWidget(QtGui.QLabel("Chord deviation:"), 5, 0)
        grid.addWidget(self.chord, 5, 1)
        self.regions_label = QtGui.QLabel("")
        self.regions_label.setObjectName("regions")
        self.regions_label.setWordWrap(True)
        self.regions_label.setToolTip("FEM mesh regions of this mesh object (MeshRegionList): a smaller "
                                      "size on chosen faces, edges, vertices or solids")
        grid.addWidget(self.regions_label, 6, 0, 1, 2)
        layout.addWidget(size_box)

        options = QtGui.QGroupBox("Options")
        form = QtGui.QFormLayout(options)
        self.order = QtGui.QComboBox()
        self.order.setObjectName("order")
        self.order.addItem("1st (tetra4)", "1st")
        self.order.addItem("2nd (tetra10)", "2nd")
        self.order.setCurrentIndex(0 if defaults["DefaultOrder"] == 1 else 1)
        self.order.setToolTip("2nd order puts the mid-edge nodes of boundary edges on the true surfaces")
        form.addRow("Element order:", self.order)
        self.resolution = shape_mesher.view_resolution(part)
        self.hints = QtGui.QCheckBox("Also follow the view resolution")
        self.hints.setObjectName("hints")
        self.hints.setChecked(False)
        self.hints.setToolTip(
            "The resolution hints (UseResolutionHints): curved faces are also followed as finely as "
            "%s is drawn (%s); a change of its view Deviation then marks the mesh as needing a re-mesh"
            % (part.Label, resolution_text(self.resolution)))
        form.addRow(self.hints)
        self.optimize = _spin("optimize", 0, 50, defaults["OptimizePasses"],
                              "Passes of global optimisation by local transformations")
        self.smooth = _spin("smooth", 0, 50, defaults["SmoothPasses"], "Passes of guarded nodal smoothing")
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
        for widget in (self.elements, self.size, self.optimize, self.smooth, self.min_size, self.max_size,
                       self.curvature, self.chord):
            widget.valueChanged.connect(self._settings_changed)
        self.order.currentIndexChanged.connect(self._settings_changed)
        self.hints.toggled.connect(self._settings_changed)
        self._mode_changed(True)
        return box

    def _load(self, obj):
        """The settings and the last result of an existing BisectMesh object; checks its inputs
        first, so that what the panel says about it is current (a view Deviation may have
        changed without a recompute)."""
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
        self.min_size.setValue(obj.MinSize.Value)
        self.max_size.setValue(obj.MaxSize.Value)
        self.curvature.setValue(obj.CurvatureElements)
        self.chord.setValue(obj.ChordDeviation.Value)
        try:
            self.read_regions(obj)
        except ValueError as err:
            self.regions_label.setText("<span style='color:#b00000'>%s</span>" % escape(err))
        mesh_object.check_inputs(obj)
        stored = mesh_object.stored_result(obj)
        if stored:
            self._show_result(stored)
            self.progress.setValue(100)
            self.progress.setFormat("last mesh")
            self.status.setText("The last mesh of %s; change the settings and press Mesh to mesh again."
                                % escape(obj.Label))
        if getattr(obj, "NeedsRemesh", False) and obj.MeshStatus:
            self.status.setText("<span style='color:#8a6d00'><b>Needs a re-mesh:</b> %s</span>"
                                % escape(obj.MeshStatus))

    def read_regions(self, obj):
        """Reads ``obj``'s mesh regions (None: no object, none); ValueError, naming the region,
        for one that cannot be used."""
        self.regions = ()
        text = "Mesh regions: none"
        try:
            if obj is not None:
                self.regions = tuple(mesh_regions.regions_of(obj))
                if self.regions:
                    text = "Mesh regions: " + "; ".join(mesh_regions.describe(self.regions))
        finally:
            self.regions_label.setText(text if obj is not None else "")
        return self.regions

    def _mode_changed(self, _checked):
        self.elements.setEnabled(self.by_count.isChecked() and self.worker is None)
        self.size.setEnabled(self.by_size.isChecked() and self.worker is None)

    def _set_running(self, running):
        for widget in (self.by_count, self.by_size, self.order, self.hints, self.optimize, self.smooth,
                       self.min_size, self.max_size, self.curvature, self.chord, self.mesh_button):
            widget.setEnabled(not running)
        self.stop_button.setEnabled(running)
        self._mode_changed(True)

    # -- the settings ----------------------------------------------------------------------

    def arguments(self):
        """The keyword arguments of mesh_object.mesh_part that the widgets (and the edited
        object's mesh regions) ask for."""
        by_count = self.by_count.isChecked()
        curvature = int(self.curvature.value())
        return {
            "elements": int(self.elements.value()) if by_count else None,
            "size": None if by_count else float(self.size.value()),
            "order": 1 if self.order.itemData(self.order.currentIndex()) == "1st" else 2,
            "use_hints": self.hints.isChecked(),
            "optimize": int(self.optimize.value()),
            "smooth": int(self.smooth.value()),
            "min_size": float(self.min_size.value()),
            "max_size": float(self.max_size.value()),
            "curvature_elements": curvature if curvature == 0 else max(3, curvature),
            "chord_deviation": float(self.chord.value()),
            "regions": [dict(r) for r in self.regions],
        }

    def _key(self):
        resolution = self.resolution if self.hints.isChecked() else None
        if isinstance(resolution, dict):
            resolution = tuple(sorted(resolution.items()))
        return tuple(sorted(self.arguments().items())), resolution

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
                    + escape("; ".join(result.get("violations", [])[:3])))
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



def _spin(name, low, high, value, tooltip=""):
    spin = QtGui.QSpinBox()
    spin.setObjectName(name)
    spin.setRange(low, high)
    spin.setValue(value)
    if tooltip:
        spin.setToolTip(tooltip)
    return spin


def _length(name, low, value, none_text="", tooltip=""):
    """A spin box in mm; ``none_text`` shown at 0."""
    spin = QtGui.QDoubleSpinBox()
    spin.setObjectName(name)
    spin.setRange(low, 1.0e6)
    spin.setDecimals(3)
    spin.setSuffix(" mm")
    spin.setValue(value)
    if none_text:
        spin.setSpecialValueText(none_text)
    if tooltip:
        spin.setToolTip(tooltip)
    return spin


def size_for(volume, elements):
    """The element size that asks for about ``elements`` tetrahedra in ``volume``, to the panel's
    three decimals (arguments.spacing_for: the one formula)."""
    from ..arguments import spacing_for

    if volume <= 0:
        return 1.0
    return round(spacing_for(volume, elements), 3)


def resolution_text(resolution):
    if isinstance(resolution, dict):
        return "deviation %g %%, angular deflection %g\u00b0" % (
            resolution.get("deviation", float("nan")), resolution.get("angular_deflection", float("nan")))
    if resolution is None:
        return "FreeCAD's default resolution"
    return "deflection %g mm" % resolution


def escape(text):
    return str(text).replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")
