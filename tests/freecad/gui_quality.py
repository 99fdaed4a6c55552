"""The "Mesh quality" command in a real FreeCAD window (not part of the default CTest run).

Run it under Xvfb from the repository root after building:

    QTWEBENGINE_CHROMIUM_FLAGS=--no-sandbox BISECTMESH_BUILD_MOD=/work/build-lead/Mod/BisectMesh \
    BISECTMESH_ARTIFACTS=/work/build-lead/test-artifacts \
    xvfb-run -a -s "-screen 0 1400x900x24" freecad tests/freecad/gui_quality.py

It registers the staged workbench, meshes a box minus a cylinder with FreeCAD's Gmsh mesher,
checks that the command is inactive (and says why) without a selection, runs it on the
selected mesh, checks the panel's widgets, colours the mesh, marks poor elements, resets, and
opens the panel on a hand-made invalid mesh. It prints GUI-TESTS-OK or GUI-TESTS-FAILED, writes
the same verdict and its log to $BISECTMESH_ARTIFACTS/gui_quality.log, and leaves screenshots
there: quality_panel.png (the window), quality_colours.png and quality_marked.png (3D view),
quality_invalid_panel.png.
"""

import os
import sys

import FreeCAD
import FreeCADGui
from PySide import QtGui

HERE = os.path.dirname(os.path.abspath(globals().get("__file__", "tests/freecad/gui_quality.py")))
sys.path.insert(0, HERE)
from gui_harness import ARTIFACTS, check, command_state, log, settle, start, widen_combo_view  # noqa: E402

COMMAND = "BisectMesh_Quality"


def wait_for(condition, what, timeout=120):
    """The panel computes in job threads: turns the event loop until ``condition()``."""
    import time

    start_time = time.time()
    while not condition():
        check(time.time() - start_time < timeout, "waiting for %s" % what)
        settle(50)


def save_view(name):
    view = FreeCADGui.ActiveDocument.ActiveView
    view.viewIsometric()
    FreeCADGui.SendMsgToActiveView("ViewFit")
    settle(200)
    view.saveImage(os.path.join(ARTIFACTS, name), 900, 650, "White")


def run():
    import fc_helpers
    from bisectmesh.gui import quality_panel

    check(FreeCADGui.activeWorkbench().name() == "BisectMeshWorkbench", "workbench active")
    check(FreeCADGui.getMainWindow().findChild(QtGui.QToolBar, "BisectMesh") is not None, "toolbar BisectMesh")

    doc = FreeCAD.newDocument("GuiQuality")
    part = fc_helpers.box_minus_cylinder(doc)
    mesh = fc_helpers.gmsh_mesh(doc, part, order=2, size=2.5)
    part.ViewObject.Visibility = False
    FreeCADGui.Selection.clearSelection()
    settle()

    active, tooltip = command_state(COMMAND)
    check(not active, "command inactive without a selection")
    check("Select a FEM mesh object" in tooltip, "tooltip says why: %r" % tooltip.split("\n")[0])
    FreeCADGui.Selection.addSelection(part)
    check(not command_state(COMMAND)[0], "command inactive with a Part object selected")
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(mesh)
    active, tooltip = command_state(COMMAND)
    check(active, "command active with a FEM mesh selected")

    widen_combo_view(440)
    FreeCADGui.runCommand("BisectMesh_Quality")
    settle(100)
    panel = quality_panel.QualityPanel.open_panel
    check(panel is not None and FreeCADGui.Control.activeDialog(), "task panel open")
    wait_for(lambda: not panel.computing(), "the report")
    report = panel.report
    check(report is not None and report["valid"] is True, "report valid: %s" % (report and report["valid"]))
    check(report["order"] == 2 and report["tets"] == mesh.FemMesh.VolumeCount, "report counts")
    check("Valid" in panel.validity.text(), "validity label: %s" % panel.validity.text()[:60])
    check(panel.violations.isHidden(), "no violation list on a valid mesh")
    check(panel.table.item(3, 0) is not None and float(panel.table.item(3, 0).text()) > 0, "table filled")
    pixmap = panel.histograms.pixmap()
    check(pixmap is not None and not pixmap.isNull() and pixmap.height() > 200, "histogram picture shown")

    # the report view gets plain text: the mesh's label, never the panel's rich-text title
    report_views = [w for w in FreeCADGui.getMainWindow().findChildren(QtGui.QTextEdit)
                    if w.metaObject().className().endswith("ReportOutput")]
    if not report_views:
        log("skip  report view not found: its text is not checked")
    else:
        text = report_views[0].toPlainText()
        # (the report view may put a time stamp before each line)
        line = [l for l in text.splitlines() if "Mesh quality of " in l]
        check(line and line[-1].endswith("Mesh quality of %s:" % mesh.Label) and "<b>" not in text and "<br>" not in text,
              "the report view's line is plain text: %r" % (line[-1:] or text[-300:]))

    console = FreeCADGui.getMainWindow().findChild(QtGui.QPlainTextEdit, "Python console")
    if console is None:
        log("skip  Python console not found: the recorded commands are not checked")
    else:
        check("bisectmesh_report = bisectmesh.quality(" in console.toPlainText(),
              "the quality call went through the console (macro recording)")

    panel.colour.setChecked(True)
    wait_for(panel.colouring_done, "the colours")
    settle()
    save_view("quality_colours.png")
    panel.measure.setCurrentIndex(1)  # recolour by minimum dihedral angle
    panel.threshold.setValue(25.0)  # the Gmsh mesh has no element below 10 degrees
    panel.mark.setChecked(True)
    wait_for(panel.colouring_done, "the marks")
    settle()
    save_view("quality_marked.png")
    FreeCADGui.getMainWindow().grab().save(os.path.join(ARTIFACTS, "quality_panel.png"))
    panel.reset.click()
    settle()
    check(not panel.colour.isChecked() and not panel.mark.isChecked(), "reset unticks the boxes")
    save_view("quality_reset.png")

    # A hand-made mesh with one element turned inside out.
    femmesh = mesh.FemMesh.copy()
    bad = sorted(femmesh.Volumes)[10]
    import Fem

    broken = Fem.FemMesh()
    for nid, point in femmesh.Nodes.items():
        broken.addNode(point.x, point.y, point.z, nid)
    for vid in femmesh.Volumes:
        element = list(femmesh.getElementNodes(vid))
        if vid == bad:
            element[0], element[1] = element[1], element[0]
            # the mid-nodes follow: edge 12 becomes 02 and 03 becomes 13
            element[5], element[6] = element[6], element[5]
            element[7], element[8] = element[8], element[7]
        broken.addVolume(element, vid)
    obj = doc.addObject("Fem::FemMeshObject", "Broken")
    obj.FemMesh = broken
    doc.recompute()
    mesh.ViewObject.Visibility = False
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(obj)
    FreeCADGui.runCommand("BisectMesh_Quality")
    settle(100)
    panel = quality_panel.QualityPanel.open_panel
    wait_for(lambda: not panel.computing(), "the report")
    check(panel.report["valid"] is False, "hand-made mesh reported invalid")
    kinds = [(v["kind"], v["ids"]) for v in panel.report["violations"]]
    check(("inverted_tet", [bad]) in kinds, "inverted element %d named: %s" % (bad, kinds[:3]))
    check(panel.violations.isVisible() and panel.violations.count() == len(kinds), "violation list shown")
    panel.violations.itemActivated.emit(panel.violations.item(0))
    settle()
    FreeCADGui.getMainWindow().grab().save(os.path.join(ARTIFACTS, "quality_invalid_panel.png"))
    FreeCADGui.Control.closeDialog()
    settle()
    check(quality_panel.QualityPanel.open_panel is None, "panel closed")


start("gui_quality", run)
