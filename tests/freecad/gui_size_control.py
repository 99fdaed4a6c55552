"""Size control in a real FreeCAD window (CTest: freecad.gui_size_control).

Run it under Xvfb from the repository root after building:

    QTWEBENGINE_CHROMIUM_FLAGS=--no-sandbox BISECTMESH_BUILD_MOD=$PWD/build/Mod/BisectMesh \
    BISECTMESH_ARTIFACTS=$PWD/build/test-artifacts \
    xvfb-run -a -s "-screen 0 1400x900x24" freecad tests/freecad/gui_size_control.py

It sets BisectMesh's defaults on its page of Edit > Preferences (the dialog itself, OK pressed)
and checks that they are stored and that the mesh panel starts from them; changes a Part's view
Deviation and checks that its mesh object with UseResolutionHints is marked within the watch's second
(no recompute), and one without is not; adds a FEM mesh region with the Mesh region command (FEM's
panel for it opens), checks that it shows under the mesh
and in the panel, re-meshes with the Re-mesh command and measures smaller elements on the
region's face; and sets MaxSize in the object's panel. Screenshots: preferences_page.png,
mesh_panel_regions.png. The user's BisectMesh preferences are restored at the end.
"""

import os
import sys
import time

import FreeCAD
import FreeCADGui
from PySide import QtCore, QtGui

HERE = os.path.dirname(os.path.abspath(globals().get("__file__", "tests/freecad/gui_size_control.py")))
sys.path.insert(0, HERE)
from gui_harness import ARTIFACTS, check, dialog_button, log, select, settle, start, widen_combo_view  # noqa: E402


def wait_for(condition, timeout, what):
    begin = time.time()
    while not condition():
        if time.time() - begin > timeout:
            raise AssertionError("timed out after %d s waiting for %s" % (timeout, what))
        settle(50)
    return time.time() - begin


def set_preferences_in_the_dialog(values):
    """Opens Edit > Preferences on BisectMesh's page, sets ``values`` ({object name: value}) in its
    widgets and presses OK. Returns what was seen."""
    seen = {}
    begin = time.time()

    def fill():
        dialog = QtGui.QApplication.activeModalWidget()
        pages = dialog.findChildren(QtGui.QWidget, "BisectMeshPreferences") if dialog else []
        seen["pages"] = len(pages)
        page = next((p for p in pages if p.isVisible()), pages[0] if pages else None)
        seen["page"] = page is not None and page.isVisible()
        if not seen["page"] and time.time() - begin < 15:
            # a loaded machine shows the dialog, then its page, later: look again
            QtCore.QTimer.singleShot(250, fill)
            return
        try:
            if page is None:
                if dialog is not None:
                    dialog.reject()
                return
            seen["loaded"] = page.findChild(QtGui.QSpinBox, "elements").value()
            for name, value in values.items():
                widget = page.findChild(QtGui.QWidget, name)
                if isinstance(widget, QtGui.QComboBox):
                    widget.setCurrentIndex(value)
                elif isinstance(widget, QtGui.QAbstractButton):
                    widget.setChecked(value)
                else:
                    widget.setValue(value)
            settle(200)
            pixmap = QtGui.QGuiApplication.primaryScreen().grabWindow(dialog.winId())
            pixmap.save(os.path.join(ARTIFACTS, "preferences_page.png"))
            box = dialog.findChild(QtGui.QDialogButtonBox)
            box.button(QtGui.QDialogButtonBox.Ok).click()
            seen["ok"] = True
        except Exception as err:
            seen["error"] = repr(err)
        finally:
            if dialog is not None and dialog.isVisible():
                dialog.reject()  # never leave a modal dialog open

    QtCore.QTimer.singleShot(500, fill)
    FreeCADGui.showPreferences("BisectMesh")  # modal: returns once the dialog is closed
    return seen


def run():
    import numpy as np

    import bisectmesh
    import fc_helpers
    from bisectmesh import mesh_regions, preferences
    from bisectmesh.gui import mesh_panel
    from test_mesh_regions import face_named, mean_edge_length

    group = FreeCAD.ParamGet(preferences.PATH)
    saved = list(group.GetContents() or [])
    setters = {"Integer": "SetInt", "Boolean": "SetBool", "Float": "SetFloat", "String": "SetString",
               "Unsigned Long": "SetUnsigned"}
    for kind, name, _ in preferences.BUILT_IN:
        getattr(group, "Rem" + kind)(name)
    try:
        # -- Edit > Preferences > BisectMesh --------------------------------------------------
        seen = set_preferences_in_the_dialog({"elements": 2345, "order": 0, "curvature": 24, "optimize": 2,
                                              "smooth": 1, "threads": 1})
        check(seen.get("page"), "the preferences dialog shows BisectMesh's page: %s" % seen)
        check(seen.get("pages") == 1, "one BisectMesh page, however many copies of the workbench FreeCAD found "
              "(an installed copy older than this one adds its own: reinstall it): %s" % seen)
        check(seen.get("loaded") == preferences.DEFAULT_ELEMENTS, "it loaded the default count, %s" % seen.get("loaded"))
        check(seen.get("ok") and "error" not in seen, "values set and OK pressed: %s" % seen)
        values = preferences.defaults()
        check((values["DefaultElements"], values["DefaultOrder"], values["CurvatureElements"], values["OptimizePasses"],
               values["SmoothPasses"], values["Threads"]) == (2345, 1, 24, 2, 1, 1),
              "stored in %s: %s" % (preferences.PATH, values))

        doc = FreeCAD.newDocument("GuiSizeControl")
        part = fc_helpers.box_minus_cylinder(doc)
        FreeCADGui.SendMsgToActiveView("ViewFit")
        widen_combo_view(480)
        select(part)
        FreeCADGui.runCommand("BisectMesh_Mesh")
        settle(300)
        panel = mesh_panel.MeshPanel.open_panel
        check(panel is not None, "the mesh panel is open")
        check((panel.elements.value(), panel.order.currentIndex(), panel.curvature.value(), panel.optimize.value(),
               panel.smooth.value()) == (2345, 0, 24, 2, 1), "the panel starts from the preferences")
        check(not panel.hints.isChecked(), "resolution hints off by default")
        dialog_button(QtGui.QDialogButtonBox.Cancel).click()
        settle(300)
        obj = bisectmesh.make_mesh_object(doc, part)
        check((obj.TargetElements, obj.ElementOrder, obj.CurvatureElements) == (2345, "1st", 24),
              "make_mesh_object takes the preferences")
        doc.removeObject(obj.Name)

        # -- the view's Deviation marks the mesh at once, with UseResolutionHints only ---------
        hinted = bisectmesh.make_mesh_object(doc, part, elements=800, order=1, use_hints=True, name="Hinted")
        plain = bisectmesh.make_mesh_object(doc, part, elements=800, order=1, name="Plain")
        bisectmesh.remesh(hinted)
        bisectmesh.remesh(plain)
        doc.recompute()
        check(not hinted.NeedsRemesh and not plain.NeedsRemesh, "both meshes current")
        deviation = part.ViewObject.Deviation
        settle(1500)  # the watch has seen the Deviation the meshes were made with
        part.ViewObject.Deviation = deviation / 2
        seconds = wait_for(lambda: hinted.NeedsRemesh, 5, "the mesh to be marked")
        check(hinted.NeedsRemesh and "view resolution" in hinted.MeshStatus,
              "with UseResolutionHints, a new Deviation marks the mesh, no recompute, within %.1f s: %r"
              % (seconds, hinted.MeshStatus))
        check(hinted.ViewObject.Proxy.getIcon().endswith("BisectMesh_MeshStale.svg"), "its icon is the stale one")
        check(not plain.NeedsRemesh, "without, it does not")
        part.ViewObject.Deviation = deviation
        wait_for(lambda: not hinted.NeedsRemesh, 5, "the mesh to be current again")
        check(not hinted.NeedsRemesh, "the Deviation it was meshed with: current again")
        for obj in (hinted, plain):
            doc.removeObject(obj.Name)

        # -- a FEM mesh region, the panel, Re-mesh ----------------------------------------------
        hole_name, hole = face_named(part.Shape, "Cylinder")
        obj = bisectmesh.make_mesh_object(doc, part, size=2.0, order=1, curvature_elements=12)
        bisectmesh.remesh(obj)
        # the Mesh region command: FEM's region object and FEM's own task panel for it
        select(obj)
        check(FreeCADGui.Command.get("BisectMesh_MeshRegion").isActive(), "Mesh region is active on the mesh")
        FreeCADGui.runCommand("BisectMesh_MeshRegion")
        settle(500)
        regions = list(obj.MeshRegionList)
        check(len(regions) == 1 and mesh_regions.is_mesh_region(regions[0]), "the command added a region to the mesh")
        check(FreeCADGui.Control.activeDialog(), "and opened FEM's mesh region panel")
        dialog_button(QtGui.QDialogButtonBox.Cancel).click()
        settle(300)
        region = regions[0]
        region.CharacteristicLength = 0.5
        region.References = [(part, (hole_name,))]
        doc.recompute()
        check(obj.NeedsRemesh and "mesh region" in obj.MeshStatus, "a new region marks the mesh: %r" % obj.MeshStatus)
        check(obj.ViewObject.Proxy.claimChildren() == [region], "the region shows under the mesh in the tree")
        select(obj)
        FreeCADGui.runCommand("BisectMesh_Remesh")
        settle(200)
        panel = mesh_panel.MeshPanel.open_panel
        check(panel is not None and "0.5 mm on 1 face" in panel.regions_label.text(),
              "the panel lists the region: %r" % (panel.regions_label.text() if panel else None))
        path = os.path.join(ARTIFACTS, "mesh_panel_regions.png")
        QtGui.QGuiApplication.primaryScreen().grabWindow(FreeCADGui.getMainWindow().winId()).save(path)
        wait_for(lambda: mesh_panel.MeshPanel.open_panel is None, 300, "Re-mesh to finish")
        settle(300)
        check(not obj.NeedsRemesh, "Re-mesh made the mesh current")
        fine, _ = mean_edge_length(obj.FemMesh, hole)
        far = [mean_edge_length(obj.FemMesh, f)[0] for f in part.Shape.Faces if f.distToShape(hole)[0] > 1.0]
        elsewhere = float(np.mean(far))
        check(fine < 0.75 and elsewhere > 2 * fine,
              "smaller elements on the region's face: mean edge %.3f mm there, %.3f mm on the far faces"
              % (fine, elsewhere))
        check(mesh_regions.regions_of(obj)[0]["size"] == 0.5, "the region is read from the object")

        # -- MaxSize from the object's panel -----------------------------------------------------
        FreeCADGui.ActiveDocument.setEdit(obj.Name, 0)
        settle(300)
        panel = mesh_panel.MeshPanel.open_panel
        check(panel is not None and panel.max_size.value() == 0.0, "the object's panel: no MaxSize")
        panel.max_size.setValue(1.5)
        panel.curvature.setValue(36)
        dialog_button(QtGui.QDialogButtonBox.Ok).click()  # meshes, then keeps
        wait_for(lambda: mesh_panel.MeshPanel.open_panel is None, 300, "OK to mesh and close")
        settle(300)
        check(abs(obj.MaxSize.Value - 1.5) < 1e-9 and obj.CurvatureElements == 36 and not obj.NeedsRemesh,
              "MaxSize %.3g and CurvatureElements %d kept, the mesh current" % (obj.MaxSize.Value,
                                                                                 obj.CurvatureElements))
        FreeCAD.closeDocument(doc.Name)
    finally:
        for kind, name, _ in preferences.BUILT_IN:
            getattr(group, "Rem" + kind)(name)
        for kind, name, value in saved:
            getattr(group, setters[kind])(name, value)
        # the dialog's OK wrote user.cfg, and the harness leaves by os._exit: write it again
        FreeCAD.saveParameter()
    log("preferences restored")


start("gui_size_control", run)
