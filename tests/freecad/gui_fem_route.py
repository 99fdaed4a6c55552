"""BisectMesh from the FEM workbench, in a real FreeCAD window (CTest: freecad.gui_fem_route).

FreeCAD is started as an Addon Manager install would start it: with the staged workbench as a
module folder (``freecad -M build/Mod/BisectMesh``), so that FreeCAD's own start-up reads its
package.xml and runs Init.py and InitGui.py, and with a fresh user configuration
(``-u <tmp>/user.cfg``) as on a first start. Run by hand from the repository root:

    QTWEBENGINE_CHROMIUM_FLAGS=--no-sandbox BISECTMESH_BUILD_MOD=$PWD/build/Mod/BisectMesh \
    BISECTMESH_ARTIFACTS=$PWD/build/test-artifacts xvfb-run -a -s "-screen 0 1400x900x24" \
    freecad -u /tmp/fem-route-user.cfg -M $PWD/build/Mod/BisectMesh tests/freecad/gui_fem_route.py

It checks that both commands exist before any workbench has been activated, then activates the
FEM workbench only and finds the BisectMesh toolbar and the Mesh menu entries there, runs both
commands from that toolbar on a part in an analysis, checks that a recompute marks a mesh object
instead of meshing it and that Re-mesh meshes it in the panel's worker with progress, checks that switching workbenches does not
duplicate the menu entries, that a toolbar the user deleted stays deleted, and that the
BisectMesh workbench still works alone. Screenshots: fem_route.png, fem_route_stale.png.
"""

import os
import sys
import time

import FreeCAD
import FreeCADGui
from PySide import QtCore, QtGui

HERE = os.path.dirname(os.path.abspath(globals().get("__file__", "tests/freecad/gui_fem_route.py")))
sys.path.insert(0, HERE)
from gui_harness import ARTIFACTS, BUILD_MOD, check, log, settle, widen_combo_view  # noqa: E402

MESH, REMESH, QUALITY = "BisectMesh_Mesh", "BisectMesh_Remesh", "BisectMesh_Quality"


def command_action(name):
    command = FreeCADGui.Command.get(name)
    actions = command.getAction() if command else []
    return actions[0] if actions else None


def visible_toolbar(title):
    for bar in FreeCADGui.getMainWindow().findChildren(QtGui.QToolBar):
        if bar.windowTitle() == title and bar.isVisible():
            return bar
    return None


def fem_mesh_menu_actions():
    """The actions of FEM's Mesh menu as the menu bar shows it, or None without that menu."""
    for action in FreeCADGui.getMainWindow().menuBar().actions():
        menu = action.menu()
        if menu is not None and menu.objectName() == "M&esh" and action.isVisible():
            return list(menu.actions())
    return None


def save_window(name):
    window = FreeCADGui.getMainWindow()
    settle(300)
    pixmap = QtGui.QGuiApplication.primaryScreen().grabWindow(window.winId())
    path = os.path.join(ARTIFACTS, name)
    pixmap.save(path)
    return path


def run():
    import bisectmesh

    # -- FreeCAD loaded the staged workbench through its package.xml ---------------------------
    check(os.path.abspath(bisectmesh.__file__).startswith(os.path.abspath(BUILD_MOD)),
          "bisectmesh loaded by FreeCAD's start-up from %s" % os.path.dirname(bisectmesh.__file__))
    check("BisectMeshWorkbench" in FreeCADGui.listWorkbenches(), "the BisectMesh workbench is registered")
    active = FreeCADGui.activeWorkbench().name()
    check(active != "BisectMeshWorkbench", "BisectMesh is not the active workbench (%s is)" % active)
    # -- the commands exist before any BisectMesh activation -------------------------------------
    for name in (MESH, REMESH, QUALITY):
        check(FreeCADGui.Command.get(name) is not None, "%s is registered at start-up" % name)

    from bisectmesh.gui import commands

    group = commands.fem_toolbar_group()
    check(group is not None and group.GetBool("Active", False), "a FEM custom toolbar group named BisectMesh")
    stored = [name for kind, name, _ in group.GetContents() if kind == "String" and name != "Name"]
    check(stored == list(commands.COMMANDS), "the group lists the commands in order: %s" % stored)

    # -- the FEM workbench, and only it ---------------------------------------------------------
    FreeCADGui.activateWorkbench("FemWorkbench")
    settle(500)
    check(FreeCADGui.activeWorkbench().name() == "FemWorkbench", "the FEM workbench is active")
    bar = visible_toolbar("BisectMesh")
    check(bar is not None, "the FEM workbench shows a BisectMesh toolbar")
    for name in (MESH, REMESH, QUALITY):
        check(command_action(name) in bar.actions(), "the toolbar holds %s" % name)
    actions = fem_mesh_menu_actions()
    check(actions is not None, "the FEM workbench has its Mesh menu")
    for name in (MESH, REMESH, QUALITY):
        check(actions.count(command_action(name)) == 1, "FEM's Mesh menu holds %s once" % name)

    # -- both commands run from the FEM toolbar -------------------------------------------------
    import FemGui
    import ObjectsFem
    import fc_helpers
    from bisectmesh.gui import mesh_panel, quality_panel

    doc = FreeCAD.newDocument("FemRoute")
    analysis = ObjectsFem.makeAnalysis(doc, "Analysis")
    FemGui.setActiveAnalysis(analysis)
    part = fc_helpers.box_minus_cylinder(doc)
    FreeCADGui.SendMsgToActiveView("ViewFit")
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(part)
    settle(300)
    check(command_action(MESH).isEnabled(), "Mesh with BisectMesh is enabled on the selected solid")
    command_action(MESH).trigger()
    settle(500)
    panel = mesh_panel.MeshPanel.open_panel
    check(panel is not None, "the toolbar button opened the mesh panel")
    # the README's picture (scripts/screenshots.sh copies it to docs/images/fem-route.png): the
    # FEM workbench, the panel after meshing, the mesh in the 3D view
    widen_combo_view(480)
    FreeCADGui.SendMsgToActiveView("ViewAxo")
    FreeCADGui.SendMsgToActiveView("ViewFit")
    panel.mesh_button.click()
    start = time.time()
    while panel.worker is not None and time.time() - start < 120:
        settle(100)
    check(panel.worker is None and panel.computed is not None, "the panel meshed the part in its worker")
    FreeCADGui.SendMsgToActiveView("ViewFit")
    save_window("fem_route.png")
    FreeCADGui.Control.closeDialog()
    settle(300)

    mesh = doc.addObject("Fem::FemMeshObject", "Mesh")
    mesh.FemMesh = bisectmesh.mesh_shape(part.Shape, elements=800, order=1)
    analysis.addObject(mesh)
    doc.recompute()
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(mesh)
    settle(300)
    check(command_action(QUALITY).isEnabled(), "Mesh quality is enabled on the selected FEM mesh")
    command_action(QUALITY).trigger()
    settle(500)
    check(quality_panel.QualityPanel.open_panel is not None, "the toolbar button opened the quality panel")
    FreeCADGui.Control.closeDialog()
    settle(300)

    # -- a recompute never meshes; Re-mesh does, in the worker thread, with progress ---------------

    obj = bisectmesh.make_mesh_object(doc, part, elements=30000, order=1, analysis=analysis)
    doc.recompute()
    check(obj.NeedsRemesh and obj.FemMesh.VolumeCount == 0, "a new mesh object: marked by the recompute, not meshed")
    check(obj.ViewObject.Proxy.getIcon().endswith("BisectMesh_MeshStale.svg"), "its tree icon is the stale one")
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(obj)
    settle(300)
    check(command_action(REMESH).isEnabled(), "Re-mesh is enabled on the selected mesh object")
    command_action(REMESH).trigger()
    panel = mesh_panel.MeshPanel.open_panel
    check(panel is not None and panel.worker is not None, "Re-mesh opened the panel, meshing in its worker")
    values, longest, last, start = [], 0.0, time.time(), time.time()
    while FreeCADGui.Control.activeDialog():
        if time.time() - start > 120:
            raise AssertionError("Re-mesh did not finish in 120 s")
        settle(20)
        now = time.time()
        longest, last = max(longest, now - last), now
        if not panel.closed:
            values.append(panel.progress.value())
    log("progress values seen: %d, from %s to %s; longest GUI gap %.2f s" % (
        len(values), values[:1], values[-1:], longest))
    check(not obj.NeedsRemesh and obj.FemMesh.VolumeCount > 15000, "the panel closed by itself with the object "
          "meshed: %d tetrahedra" % obj.FemMesh.VolumeCount)
    check(obj.ViewObject.Proxy.getIcon().endswith("BisectMesh_Mesh.svg"), "its tree icon is the plain one again")
    check(len(set(values)) >= 3, "the progress bar moved (%d distinct values)" % len(set(values)))
    check(longest < 1.0, "the window kept running: longest gap between event-loop turns %.2f s" % longest)
    tets = obj.FemMesh.VolumeCount
    obj.TargetElements = 60000
    start = time.time()
    doc.recompute()
    seconds = time.time() - start
    check(seconds < 0.5 and obj.FemMesh.VolumeCount == tets and obj.NeedsRemesh,
          "a changed parameter: the recompute took %.2f s, kept the mesh and marked it" % seconds)
    check(obj.ViewObject.Proxy.getIcon().endswith("BisectMesh_MeshStale.svg"), "and the icon says so")
    save_window("fem_route_stale.png")

    # -- switching workbenches leaves one entry each --------------------------------------------
    FreeCADGui.activateWorkbench("PartWorkbench")
    settle(300)
    check(visible_toolbar("BisectMesh") is None, "no BisectMesh toolbar in the Part workbench")
    FreeCADGui.activateWorkbench("FemWorkbench")
    settle(300)
    check(visible_toolbar("BisectMesh") is not None, "the toolbar is back in FEM")
    actions = fem_mesh_menu_actions()
    for name in (MESH, REMESH, QUALITY):
        check(actions.count(command_action(name)) == 1, "still once in FEM's Mesh menu: %s" % name)

    # -- a toolbar the user deleted stays deleted; the update keeps the user's Active ------------
    group.SetBool("Active", False)
    commands.install_fem_toolbar()
    check(not commands.fem_toolbar_group().GetBool("Active", True), "an update keeps Active off")
    toolbars = FreeCAD.ParamGet(commands.FEM_TOOLBARS)
    for name in toolbars.GetGroups():
        if toolbars.GetGroup(name).GetString("Name") == commands.TOOLBAR_NAME:
            toolbars.RemGroup(name)
    check(commands.install_fem_toolbar() is None and commands.fem_toolbar_group() is None,
          "a toolbar the user deleted is not added again")

    # -- the BisectMesh workbench alone ---------------------------------------------------------
    FreeCADGui.activateWorkbench("BisectMeshWorkbench")
    settle(300)
    bar = visible_toolbar("BisectMesh")
    check(bar is not None and command_action(MESH) in bar.actions(), "the BisectMesh workbench has its toolbar")
    FreeCAD.closeDocument(doc.Name)


def main():
    import traceback

    os.makedirs(ARTIFACTS, exist_ok=True)
    ok = False
    try:
        run()
        ok = True
    except Exception:
        log(traceback.format_exc())
    log("GUI-TESTS-OK" if ok else "GUI-TESTS-FAILED")
    sys.stdout.flush()
    os._exit(0 if ok else 1)


QtCore.QTimer.singleShot(1000, main)
