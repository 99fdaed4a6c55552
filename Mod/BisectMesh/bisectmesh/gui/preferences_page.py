"""Edit > Preferences > BisectMesh: the defaults of new mesh objects and of the task panel.

FreeCAD 0.20 takes a Python class as a preferences page (``FreeCADGui.addPreferencePage(class,
"BisectMesh")``): it makes one each time the dialog opens, shows its ``form`` and calls
``loadSettings`` then, on OK or Apply, ``saveSettings``. The values live in
``User parameter:BaseApp/Preferences/Mod/BisectMesh`` (bisectmesh/preferences.py reads them, with
or without the GUI).
"""

from PySide import QtGui

from .. import preferences

GROUP = "BisectMesh"  # the page's entry in the preferences dialog


class PreferencesPage:
    """The page; its widgets have object names (by_count, elements, ...) for the tests."""

    def __init__(self):
        self.form = QtGui.QWidget()
        self.form.setObjectName("BisectMeshPreferences")
        self.form.setWindowTitle("BisectMesh")
        layout = QtGui.QVBoxLayout(self.form)

        size_box = QtGui.QGroupBox("Mesh size of a new mesh")
        grid = QtGui.QGridLayout(size_box)
        self.by_count = QtGui.QRadioButton("Number of elements")
        self.by_count.setObjectName("by_count")
        self.elements = _spin("elements", 10, 100000000, "The number of tetrahedra asked for")
        self.elements.setSingleStep(1000)
        self.by_size = QtGui.QRadioButton("Element size")
        self.by_size.setObjectName("by_size")
        self.size = QtGui.QDoubleSpinBox()
        self.size.setObjectName("size")
        self.size.setRange(0.001, 1.0e6)
        self.size.setDecimals(3)
        self.size.setSuffix(" mm")
        self.size.setToolTip("The nodal spacing: about the length of an element's edge")
        grid.addWidget(self.by_count, 0, 0)
        grid.addWidget(self.elements, 0, 1)
        grid.addWidget(self.by_size, 1, 0)
        grid.addWidget(self.size, 1, 1)
        layout.addWidget(size_box)

        options = QtGui.QGroupBox("Meshing")
        form = QtGui.QFormLayout(options)
        self.order = QtGui.QComboBox()
        self.order.setObjectName("order")
        self.order.addItem("1st (tetra4)", 1)
        self.order.addItem("2nd (tetra10)", 2)
        form.addRow("Element order:", self.order)
        self.curvature = _spin("curvature", 0, 10000, "Curved faces and edges get at least this many elements "
                               "per full circle; 0: no bound")
        self.curvature.setSpecialValueText("no bound")
        form.addRow("Elements per full circle:", self.curvature)
        self.optimize = _spin("optimize", 0, 100, "Passes of global optimisation by local transformations")
        self.smooth = _spin("smooth", 0, 100, "Passes of guarded nodal smoothing")
        passes = QtGui.QHBoxLayout()
        passes.addWidget(self.optimize, 1)
        passes.addWidget(QtGui.QLabel("smoothing:"))
        passes.addWidget(self.smooth, 1)
        form.addRow("Optimisation passes:", passes)
        self.threads = _spin("threads", 0, 1024, "Threads of the generator; the mesh is the same for any "
                             "count. 0: one per core")
        self.threads.setSpecialValueText("one per core")
        form.addRow("Threads:", self.threads)
        layout.addWidget(options)
        note = QtGui.QLabel("New mesh objects and the task panel start from these values; a mesh "
                            "object keeps its own once made (its properties).")
        note.setWordWrap(True)
        layout.addWidget(note)
        layout.addStretch(1)
        self.by_count.toggled.connect(self._mode_changed)

    def _mode_changed(self, _checked=None):
        self.elements.setEnabled(self.by_count.isChecked())
        self.size.setEnabled(self.by_size.isChecked())

    def loadSettings(self):
        values = preferences.defaults()
        (self.by_size if values["UseElementSize"] else self.by_count).setChecked(True)
        self.elements.setValue(values["DefaultElements"])
        self.size.setValue(values["DefaultSize"])
        self.order.setCurrentIndex(0 if values["DefaultOrder"] == 1 else 1)
        self.curvature.setValue(values["CurvatureElements"])
        self.optimize.setValue(values["OptimizePasses"])
        self.smooth.setValue(values["SmoothPasses"])
        self.threads.setValue(values["Threads"])
        self._mode_changed()

    def saveSettings(self):
        curvature = int(self.curvature.value())
        preferences.write({
            "UseElementSize": self.by_size.isChecked(),
            "DefaultElements": int(self.elements.value()),
            "DefaultSize": float(self.size.value()),
            "DefaultOrder": int(self.order.itemData(self.order.currentIndex())),
            "CurvatureElements": curvature if curvature == 0 else max(3, curvature),
            "OptimizePasses": int(self.optimize.value()),
            "SmoothPasses": int(self.smooth.value()),
            "Threads": int(self.threads.value()),
        })


def _spin(name, low, high, tooltip):
    spin = QtGui.QSpinBox()
    spin.setObjectName(name)
    spin.setRange(low, high)
    spin.setToolTip(tooltip)
    return spin


class _CurrentPage:
    """What the dialog is given: it makes the page of the bisectmesh package imported now. The
    dialog keeps every class it was given for the session, and two copies of the workbench (the
    user's Mod folder and another, or a reloaded package) would each add a tab; this one class,
    added once, always builds the page from the code that is loaded."""

    def __init__(self):
        import importlib

        page = importlib.import_module(__name__).PreferencesPage()
        self.form = page.form
        self.loadSettings = page.loadSettings
        self.saveSettings = page.saveSettings


_REGISTERED = "_bisectmesh_preferences_page"  # FreeCADGui's attribute: set once the page is added


def register():
    """Adds the page to the preferences dialog once per session, whichever copy asks."""
    import os

    import FreeCADGui

    if getattr(FreeCADGui, _REGISTERED, False):
        return
    from . import icon_path

    # the dialog takes the group's icon by name: preferences-bisectmesh(.svg) in an icon path
    icon = icon_path("preferences-bisectmesh.svg")
    if icon:
        FreeCADGui.addIconPath(os.path.dirname(icon))
    FreeCADGui.addPreferencePage(_CurrentPage, GROUP)
    setattr(FreeCADGui, _REGISTERED, True)
